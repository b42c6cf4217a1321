// SPDX-License-Identifier: MIT
//! How well a fitted surface matches its scan: distances from every scan point to the surface,
//! and from the surface to the scan's mesh, summarised as mean, RMS and maximum, absolute and
//! relative to the diagonal of the scan's bounding box (the usual Metro-style measures).
//!
//! The harmonic surface is sampled on a uniform grid `oversample` times finer than its own
//! (by FFT, Theorem 5.3) and triangulated; a point's distance is its distance to the nearest
//! of those triangles around the closest samples. The triangulation is within
//! h²·max|p″|/8 of the surface (h the sample spacing), far below scan noise at the default
//! 4× oversampling.

use std::num::NonZero;

use glam::DVec3;
use hi_par::*;
use hi_surface::HarmonicSurface;
use kiddo::{ImmutableKdTree, SquaredEuclidean};

use crate::{Error, NonFiniteInput};
use hi_scan::distance::distances_to_mesh;
use hi_scan::distance::{Distances, bounding_diagonal, closest_point_on_triangle};

fn check_points(points: &[DVec3], what: fn(usize) -> NonFiniteInput) -> Result<(), Error> {
    if let Some(k) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinite { what: what(k) });
    }
    Ok(())
}

/// The distance from each of `points` to the harmonic surface, sampled `oversample` times
/// finer than its grid and triangulated (see the module documentation); relative numbers
/// are against the bounding box of `points`.
///
/// # Errors
///
/// [`Error::NonFinite`] for a non-finite point; [`Error::InvalidOption`] for `oversample` 0
/// or a sample grid over 2²⁶ points; errors of the surface layer are passed on.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::distance::distances_to_surface;
///
/// let sphere = hi_surface::sphere(1.0); // the exact unit sphere
/// let points = [DVec3::new(0.0, 0.0, 2.0), DVec3::new(0.3, 0.0, 0.0)];
/// let d = distances_to_surface(&sphere, &points, 8).unwrap();
/// assert!((d.per_point[0] - 1.0).abs() < 1e-3);
/// assert!((d.per_point[1] - 0.7).abs() < 1e-2);
/// ```
pub fn distances_to_surface(
    surface: &HarmonicSurface<DVec3>,
    points: &[DVec3],
    oversample: usize,
) -> Result<Distances, Error> {
    check_points(points, NonFiniteInput::Point)?;
    let grid = SampleGrid::of(surface, oversample)?;
    grid.distances(points)
}

/// A periodic grid of surface samples, triangulated quad by quad.
struct SampleGrid {
    rows: usize,
    cols: usize,
    samples: Vec<DVec3>,
}

impl SampleGrid {
    /// The surface sampled `oversample` times finer than its grid (by FFT).
    fn of(surface: &HarmonicSurface<DVec3>, oversample: usize) -> Result<Self, Error> {
        let (rows, cols) = (surface.m().max(2) * oversample, surface.n().max(2) * oversample);
        if oversample == 0 || rows.saturating_mul(cols) > crate::MAX_TEXELS {
            return Err(Error::InvalidOption {
                name: "oversample",
                value: oversample as f64,
                expected: "at least 1, and at most 2²⁶ samples in all",
            });
        }
        let samples = surface.sample_uniform(rows, cols, 0, 0)?.values;
        Ok(Self { rows, cols, samples })
    }

    /// The distance from each of `points` to the triangulated samples.
    fn distances(&self, points: &[DVec3]) -> Result<Distances, Error> {
        let tree: ImmutableKdTree<f64, 3> = ImmutableKdTree::new_from_slice(
            &self.samples.iter().map(|p| p.to_array()).collect::<Vec<_>>(),
        )
        .map_err(|_| Error::Degenerate { what: "the surface samples do not form a kd-tree" })?;
        let k = NonZero::new(4).unwrap_or(NonZero::<usize>::MIN);
        let per_point = points
            .par_iter()
            .map(|p| {
                let near =
                    tree.query(&p.to_array()).nearest_n::<SquaredEuclidean<f64>>(k).execute();
                near.iter()
                    .map(|n| self.distance_around(n.item as usize, *p))
                    .fold(f64::INFINITY, f64::min)
            })
            .collect();
        Ok(Distances::from_values(per_point, bounding_diagonal(points)))
    }

    fn at(&self, i: usize, j: usize) -> DVec3 {
        self.samples[(i % self.rows) * self.cols + j % self.cols]
    }

    /// The distance from p to the eight triangles of the four quads around sample t.
    fn distance_around(&self, t: usize, p: DVec3) -> f64 {
        let (i, j) = (t / self.cols + self.rows, t % self.cols + self.cols);
        let mut best = f64::INFINITY;
        for (di, dj) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
            let (a, b) = (i + 1 - di, j + 1 - dj); // the quad's corner (a−1…a, b−1…b)
            let q = [self.at(a - 1, b - 1), self.at(a, b - 1), self.at(a, b), self.at(a - 1, b)];
            for (x, y, z) in [(q[0], q[1], q[2]), (q[0], q[2], q[3])] {
                best = best.min(closest_point_on_triangle(p, x, y, z).distance(p));
            }
        }
        best
    }
}

/// Both ways between a fitted surface and the scan mesh it came from.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Hausdorff {
    /// From each scan vertex to the surface.
    pub scan_to_surface: Distances,
    /// From each surface sample (the grid `oversample` times finer) to the mesh.
    pub surface_to_scan: Distances,
}

impl Hausdorff {
    /// The two-sided Hausdorff distance: the larger of the two maxima.
    #[must_use]
    pub fn distance(&self) -> f64 {
        self.scan_to_surface.max.max(self.surface_to_scan.max)
    }
}

/// The two-sided distances between a harmonic surface and a triangle mesh: scan vertices to
/// the surface, and surface samples (`oversample` times finer than its grid) to the mesh.
///
/// # Errors
///
/// As [`distances_to_surface`] and [`distances_to_mesh`].
pub fn hausdorff(
    surface: &HarmonicSurface<DVec3>,
    vertices: &[DVec3],
    triangles: &[[u32; 3]],
    oversample: usize,
) -> Result<Hausdorff, Error> {
    check_points(vertices, NonFiniteInput::Vertex)?;
    // One sampling of the surface serves both directions.
    let grid = SampleGrid::of(surface, oversample)?;
    let scan_to_surface = grid.distances(vertices)?;
    let surface_to_scan = distances_to_mesh(&grid.samples, vertices, triangles)?;
    Ok(Hausdorff { scan_to_surface, surface_to_scan })
}
