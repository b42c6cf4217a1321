// SPDX-License-Identifier: MIT
//! The spherical geometry image of algorithm 2 (§5.3): rays from a centre, one per texel of a
//! latitude–longitude grid that covers the sphere twice, so the image is periodic both ways.
//!
//! Texel (i, j) looks along d(u, v) = (sin 2πu cos 2πv, sin 2πu sin 2πv, cos 2πu) at
//! u = i/rows, v = j/cols: u runs from the north pole over the south pole and back (a full
//! meridian circle), v around the axis — the parameterisation of the exact harmonic sphere
//! (docs/math.md §3), under which the harmonic surface covers the object once for u ∈ [0, ½].
//! Since d(1 − u, v + ½) = d(u, v), the rows past the south pole repeat the first half with v
//! turned by ½; for an even number of columns they are copied exactly.
//!
//! Along each ray the surface is found as in the thesis: a kd-tree holds the points'
//! directions from the centre (unit vectors), the points within a small angle of the ray are
//! gathered — the angle grows until enough are found — and their distances from the centre are
//! averaged with weights that fall off with the angle. Beyond the thesis:
//! - **several shells.** When the distances of the gathered points split into groups (a gap
//!   larger than [`SphericalOptions::shell_gap`] of the object's radius) the ray meets the
//!   surface more than once: the object is not star-shaped about the centre there. The texel is
//!   flagged in [`SphericalImage::non_star`] and takes the outermost group (the surface seen
//!   from outside), and [`SphericalImage::non_star_fraction`] says how much of the image this
//!   concerns;
//! - **holes.** A ray with too few points within [`SphericalOptions::max_angle`] is a hole,
//!   flagged in [`SphericalImage::holes`] and filled by averaging the distances of its
//!   neighbours, pass by pass, from the edge of the hole inwards.

use std::f64::consts::TAU;
use std::num::NonZero;

use glam::DVec3;
use hi_par::*;
use hi_surface::ParamRange;
use kiddo::{ImmutableKdTree, SquaredEuclidean};

use crate::image::{GeometryImage, check_resolution};
use crate::{Error, NonFiniteInput};

/// The settings of [`spherical_image`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SphericalOptions {
    /// How texels map to ray directions. Default [`Layout::Sphere`].
    pub layout: Layout,
    /// Rows of the image (samples of u over a full meridian circle); even, so that both poles
    /// are texels. Default 128.
    pub rows: usize,
    /// Columns (samples of v around the axis). Default 128.
    pub cols: usize,
    /// The centre of the rays; `None` for the mean of the points.
    pub centre: Option<DVec3>,
    /// At most this many points, the nearest in direction, are averaged per texel. Default 8.
    pub neighbours: usize,
    /// A texel needs at least this many points within [`SphericalOptions::max_angle`]; fewer
    /// make it a hole. Default 3 (the thesis: "3 points or more").
    pub min_neighbours: usize,
    /// The widest search angle about a ray, in radians. Default 0.2 (about 11°).
    pub max_angle: f64,
    /// Distances along one ray that differ by more than this fraction of the object's radius
    /// belong to different shells. Default 0.05.
    pub shell_gap: f64,
}

impl Default for SphericalOptions {
    fn default() -> Self {
        Self {
            layout: Layout::Sphere,
            rows: 128,
            cols: 128,
            centre: None,
            neighbours: 8,
            min_neighbours: 3,
            max_angle: 0.2,
            shell_gap: 0.05,
        }
    }
}

/// A spherical geometry image with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub struct SphericalImage {
    /// The image: texel (i, j) = centre + r·d(i/rows, j/cols).
    pub image: GeometryImage,
    /// The centre of the rays.
    pub centre: DVec3,
    /// The distance r of each texel from the centre, row-major.
    pub radii: Vec<f64>,
    /// Texels whose ray found several shells (row-major).
    pub non_star: Vec<bool>,
    /// Texels whose ray found too few points, filled from their neighbours (row-major).
    pub holes: Vec<bool>,
    /// The fraction of the rays (each direction counted once) that met several shells.
    pub non_star_fraction: f64,
    /// The fraction of the rays that found too few points.
    pub hole_fraction: f64,
}

/// The direction of texel (i, j): d(i/rows, j/cols), exactly ±z on the pole rows.
#[must_use]
pub fn ray_direction(i: usize, j: usize, rows: usize, cols: usize) -> DVec3 {
    let i = i % rows;
    // The poles exactly, whatever the column.
    if i == 0 {
        return DVec3::Z;
    }
    if 2 * i == rows {
        return DVec3::NEG_Z;
    }
    let (su, cu) = (TAU * i as f64 / rows as f64).sin_cos();
    let (sv, cv) = (TAU * (j % cols) as f64 / cols as f64).sin_cos();
    DVec3::new(su * cv, su * sv, cu)
}

/// How the texels of a ray-cast geometry image map to directions from the centre.
///
/// All three make the image periodic in both directions, as harmonic interpolation needs:
///
/// | layout | texel (i, j) looks along | covers the sphere | seams |
/// |---|---|---|---|
/// | [`Layout::Sphere`] | d(i/rows, j/cols), latitude–longitude doubled over the poles | twice; u ∈ [0, ½] once | none; poles crowded |
/// | [`Layout::Octahedron`] | the octahedral square of Praun and Hoppe (2003) at texel centres, wrapped around as it is | once | at the square's edges |
/// | [`Layout::FlatOctahedron`] | the same square, extended across its edges by its own symmetry and sampled along its diagonals | twice; u ∈ [0, ½] once | none |
///
/// The plain octahedral image is what §5.3 (figures 5.18, 5.19) calls the octahedron
/// geometry image: wrapping the square around joins texels that are far apart on the object,
/// and smoothing or interpolation across that join leaves seams. The flattened octahedron
/// (figure 5.20) avoids them: the square's map to the sphere is invariant under half-turns
/// about the midpoints of its edges, so it extends to the whole plane with the periods
/// (2, 2) and (2, −2); the image samples one such period along the diagonals,
/// (s, t) = (a − b + ½, a + b + ½) for a = 2i/rows, b = 2j/cols, and neighbouring texels are
/// neighbours on the object everywhere.
///
/// In every layout ∂d/∂u × ∂d/∂v points away from the centre, so the harmonic surface of a
/// star-shaped object has outward normals pᵤ × pᵥ (and a mesh of it with default
/// [`hi_surface::MeshOptions`] is wound outwards); for the flattened octahedron this is why
/// s and t run as they do.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Layout {
    /// Latitude–longitude rays over a doubled meridian (algorithm 2 as in the thesis).
    #[default]
    Sphere,
    /// The octahedral square, wrapped as it is (seams at its edges).
    Octahedron,
    /// The octahedral square extended by its symmetry (seamless).
    FlatOctahedron,
}

impl Layout {
    /// The direction of texel (i, j) of a `rows × cols` image (a unit vector).
    #[must_use]
    pub fn direction(self, i: usize, j: usize, rows: usize, cols: usize) -> DVec3 {
        let (i, j) = (i % rows, j % cols);
        match self {
            Self::Sphere => ray_direction(i, j, rows, cols),
            Self::Octahedron => octahedral_direction(
                -1.0 + (2 * i + 1) as f64 / rows as f64,
                -1.0 + (2 * j + 1) as f64 / cols as f64,
            ),
            Self::FlatOctahedron => {
                let (a, b) = (2.0 * i as f64 / rows as f64, 2.0 * j as f64 / cols as f64);
                octahedral_direction(a - b + 0.5, a + b + 0.5)
            }
        }
    }

    /// The u range [u₀, u₁] over which the harmonic surface covers the object once (v runs
    /// over [0, 1]).
    #[must_use]
    pub const fn covering_window(self) -> ParamRange {
        match self {
            Self::Sphere | Self::FlatOctahedron => ParamRange::new(0.0, 0.5),
            Self::Octahedron => ParamRange::UNIT,
        }
    }

    /// For the doubled layouts with an even number of rows and columns: the texel of the
    /// first half of the rows (i ≤ rows/2) that looks along the same direction as texel
    /// (i, j) — (rows − i, j + cols/2) on the sphere, (rows − i, cols/2 − j) on the flattened
    /// octahedron. `None` for the plain octahedron or odd sizes.
    pub(crate) fn mirror(
        self,
        rows: usize,
        cols: usize,
    ) -> Option<impl Fn(usize, usize) -> (usize, usize)> {
        let doubled = matches!(self, Self::Sphere | Self::FlatOctahedron);
        (doubled && rows.is_multiple_of(2) && cols.is_multiple_of(2)).then_some(
            move |i: usize, j: usize| match self {
                Self::FlatOctahedron => ((rows - i) % rows, (cols + cols / 2 - j % cols) % cols),
                _ => ((rows - i) % rows, (j + cols / 2) % cols),
            },
        )
    }
}

/// The unit direction of point (s, t) of the octahedral square [−1, 1]² (Praun and Hoppe
/// 2003), extended to the whole plane by half-turns about the midpoints of the square's
/// edges: the upper half of the octahedron |x| + |y| + |z| = 1 is the diamond |s| + |t| ≤ 1,
/// the lower half the four corner triangles folded over its edges.
#[must_use]
pub fn octahedral_direction(s: f64, t: f64) -> DVec3 {
    let wrap = |x: f64| (x + 1.0).rem_euclid(4.0) - 1.0;
    let (mut s, mut t) = (wrap(s), wrap(t));
    if s > 1.0 {
        (s, t) = (2.0 - s, -t); // the half-turn about (1, 0)
    }
    t = wrap(t);
    if t > 1.0 {
        (s, t) = (-s, 2.0 - t); // the half-turn about (0, 1)
    }
    let z = 1.0 - s.abs() - t.abs();
    let (x, y) =
        if z >= 0.0 { (s, t) } else { ((1.0 - t.abs()).copysign(s), (1.0 - s.abs()).copysign(t)) };
    DVec3::new(x, y, z).normalize()
}

/// What one ray found.
#[derive(Clone, Copy, Debug)]
enum Hit {
    /// The distance along the ray, and whether several shells were seen.
    Found(f64, bool),
    Hole,
}

/// The rays of algorithm 2: the points' directions from the centre in a kd-tree, and the
/// search for the points about one ray with a growing angle (shared by [`spherical_image`] and
/// [`crate::contours::contour_image`]).
pub(crate) struct Caster {
    tree: ImmutableKdTree<f64, 3>,
    /// Distance from the centre of each point in the tree.
    pub(crate) distances: Vec<f64>,
    /// The index in the input of each point in the tree.
    pub(crate) index: Vec<usize>,
    pub(crate) centre: DVec3,
    pub(crate) radius_max: f64,
    /// Distances that differ by more than this belong to different shells.
    pub(crate) gap: f64,
    first: f64,
    max_angle: f64,
    k: NonZero<usize>,
    min_neighbours: usize,
}

impl Caster {
    /// Checks `options` (see [`spherical_image`]'s errors) and builds the tree.
    pub(crate) fn new(points: &[DVec3], options: &SphericalOptions) -> Result<Self, Error> {
        let &SphericalOptions {
            layout,
            rows,
            cols,
            centre,
            neighbours,
            min_neighbours,
            max_angle,
            shell_gap,
        } = options;
        check_resolution(rows, cols)?;
        if rows % 2 != 0 && layout != Layout::Octahedron {
            return Err(Error::InvalidResolution {
                rows,
                cols,
                expected: "an even number of rows (both poles are texels)",
            });
        }
        if !(max_angle > 0.0 && max_angle <= std::f64::consts::PI) {
            return Err(Error::InvalidOption {
                name: "max_angle",
                value: max_angle,
                expected: "0 < angle ≤ π radians",
            });
        }
        if !(shell_gap > 0.0 && shell_gap <= 1.0) {
            return Err(Error::InvalidOption {
                name: "shell_gap",
                value: shell_gap,
                expected: "0 < gap ≤ 1",
            });
        }
        if neighbours == 0 || min_neighbours == 0 || min_neighbours > neighbours {
            return Err(Error::InvalidOption {
                name: "min_neighbours",
                value: min_neighbours as f64,
                expected: "1 ≤ min_neighbours ≤ neighbours",
            });
        }
        if let Some(k) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinite { what: NonFiniteInput::Point(k) });
        }
        let centre = match centre {
            Some(c) if !c.is_finite() => {
                return Err(Error::NonFinite { what: NonFiniteInput::Centre });
            }
            Some(c) => c,
            None if points.is_empty() => {
                return Err(Error::TooFewPoints { found: 0, needed: min_neighbours });
            }
            None => points.iter().copied().sum::<DVec3>() / points.len() as f64,
        };
        let radius_max = points.iter().map(|p| (*p - centre).length()).fold(0.0, f64::max);
        // Directions and distances of the points that are not at the centre.
        let mut directions: Vec<[f64; 3]> = Vec::with_capacity(points.len());
        let mut distances = Vec::with_capacity(points.len());
        let mut index = Vec::with_capacity(points.len());
        for (t, p) in points.iter().enumerate() {
            let r = (*p - centre).length();
            if r > 1e-12 * radius_max {
                directions.push(((*p - centre) / r).to_array());
                distances.push(r);
                index.push(t);
            }
        }
        if directions.len() < min_neighbours {
            return Err(Error::TooFewPoints { found: directions.len(), needed: min_neighbours });
        }
        let tree: ImmutableKdTree<f64, 3> =
            ImmutableKdTree::new_from_slice(&directions).map_err(|_| Error::Degenerate {
                what: "the point directions do not form a kd-tree",
            })?;
        // Half the larger angular texel spacing: the first search angle.
        let first = 0.5 * TAU / rows.min(cols) as f64;
        let gap = shell_gap * radius_max;
        let k = NonZero::new(neighbours).unwrap_or(NonZero::<usize>::MIN);
        Ok(Self {
            tree,
            distances,
            index,
            centre,
            radius_max,
            gap,
            first,
            max_angle,
            k,
            min_neighbours,
        })
    }

    /// The points about the ray along the unit vector `d`: the nearest (at most `neighbours`)
    /// within the first angle that holds `min_neighbours` of them, as (squared chord, index in
    /// the tree), with the squared chord of that angle; `None` if even the widest angle holds
    /// too few (a hole).
    pub(crate) fn gather(&self, d: DVec3) -> Option<(f64, Vec<(f64, usize)>)> {
        let q = d.to_array();
        let mut angle = self.first.min(self.max_angle);
        loop {
            let chord2 = 2.0 - 2.0 * angle.cos();
            let found = self
                .tree
                .query(&q)
                .nearest_n::<SquaredEuclidean<f64>>(self.k)
                .within(chord2)
                .execute();
            if found.len() >= self.min_neighbours {
                return Some((
                    chord2,
                    found.iter().map(|f| (f.distance, f.item as usize)).collect(),
                ));
            }
            if angle >= self.max_angle {
                return None;
            }
            angle = (angle * 1.5).min(self.max_angle);
        }
    }
}
/// Builds the spherical geometry image of `points` (algorithm 2 of §5.3).
///
/// # Errors
///
/// [`Error::InvalidResolution`] for fewer than 2 or an odd number of rows, fewer than 2
/// columns or too many texels; [`Error::InvalidOption`] for a search angle outside (0, π],
/// a shell gap outside (0, 1], `neighbours` or `min_neighbours` of 0 or
/// `min_neighbours > neighbours`; [`Error::NonFinite`] for a non-finite point or centre;
/// [`Error::TooFewPoints`] for fewer than `min_neighbours` points away from the centre.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::spherical::{SphericalOptions, spherical_image};
///
/// // Points on a sphere of radius 2 about (1, 0, 0).
/// let points: Vec<DVec3> = (0..4000)
///     .map(|k| {
///         let z = 1.0 - (2 * k + 1) as f64 / 4000.0;
///         let phi = k as f64 * 2.399_963_229_728_653; // the golden angle
///         let s = (1.0 - z * z).sqrt();
///         DVec3::new(1.0 + 2.0 * s * phi.cos(), 2.0 * s * phi.sin(), 2.0 * z)
///     })
///     .collect();
/// let options = SphericalOptions { rows: 32, cols: 32, ..SphericalOptions::default() };
/// let result = spherical_image(&points, &options).unwrap();
/// assert!((result.centre - DVec3::X).length() < 1e-3);
/// assert!(result.radii.iter().all(|r| (r - 2.0).abs() < 1e-3));
/// assert_eq!(result.non_star_fraction, 0.0);
/// ```
pub fn spherical_image(
    points: &[DVec3],
    options: &SphericalOptions,
) -> Result<SphericalImage, Error> {
    let &SphericalOptions { layout, rows, cols, .. } = options;
    let caster = Caster::new(points, options)?;
    let centre = caster.centre;
    let radius_max = caster.radius_max;
    let cast = |d: DVec3| -> Hit {
        match caster.gather(d) {
            Some((chord2, found)) => {
                let (r, several) = estimate(
                    &found
                        .iter()
                        .map(|&(c2, item)| (c2, caster.distances[item]))
                        .collect::<Vec<_>>(),
                    chord2,
                    caster.gap,
                );
                Hit::Found(r, several)
            }
            None => Hit::Hole,
        }
    };
    // Half the rows by casting; with an even number of columns the rest are copies (the
    // layout's half-turn symmetry). The plain octahedron has no such symmetry.
    let mirror = layout.mirror(rows, cols);
    let cast_rows = if mirror.is_some() { rows / 2 + 1 } else { rows };
    let mut hits: Vec<Hit> = (0..cast_rows * cols)
        .into_par_iter()
        .map(|t| cast(layout.direction(t / cols, t % cols, rows, cols)))
        .collect();
    if let Some(mirror) = &mirror {
        complete_by_symmetry(&mut hits, rows, cols, mirror);
    }
    // Each direction once: the first half of the rows for the doubled layouts (the poles of
    // the spherical layout once each), every texel for the plain octahedron.
    let distinct: Vec<usize> = match layout {
        Layout::Sphere => (0..=rows / 2)
            .flat_map(|i| {
                let n = if i == 0 || i == rows / 2 { 1 } else { cols };
                (0..n).map(move |j| i * cols + j)
            })
            .collect(),
        Layout::FlatOctahedron => (0..rows / 2 * cols).collect(),
        Layout::Octahedron => (0..rows * cols).collect(),
    };
    let count = |f: &dyn Fn(&Hit) -> bool| {
        distinct.iter().filter(|&&t| f(&hits[t])).count() as f64 / distinct.len() as f64
    };
    let non_star_fraction = count(&|h| matches!(h, Hit::Found(_, true)));
    let hole_fraction = count(&|h| matches!(h, Hit::Hole));
    let holes: Vec<bool> = hits.iter().map(|h| matches!(h, Hit::Hole)).collect();
    let non_star: Vec<bool> = hits.iter().map(|h| matches!(h, Hit::Found(_, true))).collect();
    let mut radii: Vec<Option<f64>> = hits
        .iter()
        .map(|h| match h {
            Hit::Found(r, _) => Some(*r),
            Hit::Hole => None,
        })
        .collect();
    fill_holes(&mut radii, rows, cols);
    let radii: Vec<f64> = radii.into_iter().map(|r| r.unwrap_or(radius_max)).collect();
    let mut texels: Vec<DVec3> = (0..cast_rows * cols)
        .map(|t| centre + radii[t] * layout.direction(t / cols, t % cols, rows, cols))
        .collect();
    if let Some(mirror) = &mirror {
        complete_by_symmetry(&mut texels, rows, cols, mirror);
    }
    Ok(SphericalImage {
        image: GeometryImage::try_new(rows, cols, texels)?,
        centre,
        radii,
        non_star,
        holes,
        non_star_fraction,
        hole_fraction,
    })
}

/// Completes a doubled image from its first rows/2 + 1 rows: the rest are copies of their
/// mirror texels, and within the two rows that map to themselves (0 and rows/2) the second
/// texel of each mirrored pair is made a copy of the first, so the symmetry holds exactly.
pub(crate) fn complete_by_symmetry<T: Copy>(
    values: &mut Vec<T>,
    rows: usize,
    cols: usize,
    mirror: &impl Fn(usize, usize) -> (usize, usize),
) {
    for i in [0, rows / 2] {
        for j in 0..cols {
            let (a, b) = mirror(i, j);
            if a == i && b < j {
                values[i * cols + j] = values[a * cols + b];
            }
        }
    }
    for i in rows / 2 + 1..rows {
        for j in 0..cols {
            let (a, b) = mirror(i, j);
            values.push(values[a * cols + b]);
        }
    }
}

/// The groups of `distances` (sorted) separated by gaps larger than `gap`.
pub(crate) fn shells(distances: &[f64], gap: f64) -> Vec<Vec<f64>> {
    let mut sorted = distances.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mut groups: Vec<Vec<f64>> = Vec::new();
    for r in sorted {
        match groups.last_mut() {
            Some(g) if r - g.last().copied().unwrap_or(r) <= gap => g.push(r),
            _ => groups.push(vec![r]),
        }
    }
    groups
}

/// The distance along a ray from the gathered points `(chord², distance)`: the outermost
/// shell's distances averaged with weights (1 − chord²/limit)² + ε, which fall to nearly 0 at
/// the edge of the search cone; and whether the points form several shells.
fn estimate(found: &[(f64, f64)], limit: f64, gap: f64) -> (f64, bool) {
    let groups = shells(&found.iter().map(|f| f.1).collect::<Vec<_>>(), gap);
    let outer_min = groups.last().and_then(|g| g.first().copied()).unwrap_or(0.0);
    let (mut sum, mut weight) = (0.0, 0.0);
    for &(c2, r) in found {
        if r >= outer_min {
            let w = (1.0 - c2 / limit).max(0.0).powi(2) + 1e-3;
            sum += w * r;
            weight += w;
        }
    }
    (sum / weight, groups.len() > 1)
}

/// Fills the holes of a periodic image pass by pass: a hole with known 4-neighbours takes
/// their mean.
fn fill_holes(radii: &mut [Option<f64>], rows: usize, cols: usize) {
    if radii.iter().all(Option::is_none) {
        return;
    }
    while radii.iter().any(Option::is_none) {
        let before = radii.to_vec();
        for t in 0..rows * cols {
            if before[t].is_some() {
                continue;
            }
            let (i, j) = (t / cols, t % cols);
            let around = [
                ((i + rows - 1) % rows, j),
                ((i + 1) % rows, j),
                (i, (j + cols - 1) % cols),
                (i, (j + 1) % cols),
            ];
            let known: Vec<f64> =
                around.iter().filter_map(|&(a, b)| before[a * cols + b]).collect();
            if !known.is_empty() {
                radii[t] = Some(known.iter().sum::<f64>() / known.len() as f64);
            }
        }
    }
}
