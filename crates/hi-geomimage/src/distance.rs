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

use crate::par::*;
use glam::DVec3;
use hi_surface::HarmonicSurface;
use kiddo::{ImmutableKdTree, SquaredEuclidean};

use crate::{Error, NonFiniteInput};

/// Distances from a set of points to a surface or mesh, with their summary.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Distances {
    /// The distance of each point, in the order given (not written by `serde`: a report stays
    /// small; read back, it is empty).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub per_point: Vec<f64>,
    /// The mean distance.
    pub mean: f64,
    /// The root mean square distance.
    pub rms: f64,
    /// The largest distance.
    pub max: f64,
    /// The length of the reference bounding-box diagonal the relative numbers divide by.
    pub diagonal: f64,
}

impl Distances {
    /// The summary of `per_point`, relative numbers against `diagonal`.
    pub(crate) fn from_values(per_point: Vec<f64>, diagonal: f64) -> Self {
        let n = per_point.len().max(1) as f64;
        let mean = per_point.iter().sum::<f64>() / n;
        let rms = (per_point.iter().map(|d| d * d).sum::<f64>() / n).sqrt();
        let max = per_point.iter().copied().fold(0.0, f64::max);
        Self { per_point, mean, rms, max, diagonal }
    }

    /// Mean, RMS and maximum divided by the diagonal.
    #[must_use]
    pub fn relative(&self) -> [f64; 3] {
        let d = if self.diagonal > 0.0 { self.diagonal } else { 1.0 };
        [self.mean / d, self.rms / d, self.max / d]
    }
}

/// The diagonal of the bounding box of `points` (0 for none).
#[must_use]
pub fn bounding_diagonal(points: &[DVec3]) -> f64 {
    let Some(first) = points.first() else { return 0.0 };
    let (lo, hi) = points.iter().fold((*first, *first), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    (hi - lo).length()
}

/// The point of triangle (a, b, c) closest to p (Ericson, *Real-Time Collision Detection*,
/// §5.1.5).
#[must_use]
pub fn closest_point_on_triangle(p: DVec3, a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return a + ab * (d1 / (d1 - d3));
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return a + ac * (d2 / (d2 - d6));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    let denom = va + vb + vc;
    if denom.abs() < f64::MIN_POSITIVE {
        // A degenerate (zero-area) triangle: the nearest of its corners.
        return [a, b, c]
            .into_iter()
            .min_by(|x, y| x.distance_squared(p).total_cmp(&y.distance_squared(p)))
            .unwrap_or(a);
    }
    a + ab * (vb / denom) + ac * (vc / denom)
}

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

/// The distance from each of `queries` to the nearest of `points` (a kd-tree), in parallel.
///
/// # Errors
///
/// [`Error::NonFinite`] for a non-finite point; [`Error::TooFewPoints`] for no points.
pub fn nearest_point_distances(queries: &[DVec3], points: &[DVec3]) -> Result<Vec<f64>, Error> {
    check_points(points, NonFiniteInput::Point)?;
    check_points(queries, NonFiniteInput::Query)?;
    if points.is_empty() {
        return Err(Error::TooFewPoints { found: 0, needed: 1 });
    }
    let tree: ImmutableKdTree<f64, 3> =
        ImmutableKdTree::new_from_slice(&points.iter().map(|p| p.to_array()).collect::<Vec<_>>())
            .map_err(|_| Error::Degenerate { what: "the points do not form a kd-tree" })?;
    Ok(queries
        .par_iter()
        .with_min_len(256)
        .map(|q| {
            tree.query(&q.to_array())
                .nearest_one::<SquaredEuclidean<f64>>()
                .execute()
                .distance
                .sqrt()
        })
        .collect())
}

/// The distance from each of `points` to the triangle mesh (`vertices`, `triangles`), exact
/// (closest point on every triangle that could be nearest); relative numbers are against the
/// mesh's bounding box.
///
/// # Errors
///
/// [`Error::NonFinite`] for a non-finite point or vertex; [`Error::TooFewPoints`] for a mesh
/// with no triangle; [`Error::InvalidOption`] for a triangle index out of range.
pub fn distances_to_mesh(
    points: &[DVec3],
    vertices: &[DVec3],
    triangles: &[[u32; 3]],
) -> Result<Distances, Error> {
    check_points(points, NonFiniteInput::Point)?;
    check_points(vertices, NonFiniteInput::Vertex)?;
    if triangles.is_empty() {
        return Err(Error::TooFewPoints { found: 0, needed: 1 });
    }
    if let Some(t) = triangles.iter().flatten().find(|&&k| k as usize >= vertices.len()) {
        return Err(Error::InvalidOption {
            name: "triangle index",
            value: f64::from(*t),
            expected: "below the vertex count",
        });
    }
    let corners = |t: &[u32; 3]| t.map(|k| vertices[k as usize]);
    let centroids: Vec<[f64; 3]> =
        triangles.iter().map(|t| (corners(t).iter().sum::<DVec3>() / 3.0).to_array()).collect();
    // Every point of a triangle lies within `reach` of its centroid.
    let reach = triangles
        .iter()
        .zip(&centroids)
        .map(|(t, c)| {
            corners(t).iter().map(|p| p.distance(DVec3::from_array(*c))).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max);
    let tree: ImmutableKdTree<f64, 3> = ImmutableKdTree::new_from_slice(&centroids)
        .map_err(|_| Error::Degenerate { what: "the triangle centroids do not form a kd-tree" })?;
    let per_point = points
        .par_iter()
        .map(|p| {
            let q = p.to_array();
            let nearest = tree.query(&q).nearest_one::<SquaredEuclidean<f64>>().execute();
            let [a, b, c] = corners(&triangles[nearest.item as usize]);
            let first = closest_point_on_triangle(*p, a, b, c).distance(*p);
            // A nearer triangle has its centroid within first + reach of p.
            let r = first + reach;
            tree.query(&q)
                .within::<SquaredEuclidean<f64>>(r * r)
                .unsorted()
                .execute()
                .iter()
                .map(|n| {
                    let [a, b, c] = corners(&triangles[n.item as usize]);
                    closest_point_on_triangle(*p, a, b, c).distance(*p)
                })
                .fold(first, f64::min)
        })
        .collect();
    Ok(Distances::from_values(per_point, bounding_diagonal(vertices)))
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
