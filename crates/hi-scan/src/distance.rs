// SPDX-License-Identifier: MIT
//! Distances between point sets and triangle meshes, summarised as mean, RMS and maximum,
//! absolute and relative to the diagonal of a bounding box (the usual Metro-style measures):
//! the closest point on a triangle (Ericson), nearest points by kd-tree, and exact distances
//! to a mesh.

use glam::DVec3;
use hi_par::*;
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
    pub fn from_values(per_point: Vec<f64>, diagonal: f64) -> Self {
        let n = per_point.len().max(1) as f64;
        let mean = per_point.iter().sum::<f64>() / n;
        let rms = (per_point.iter().map(|d| d * d).sum::<f64>() / n).sqrt();
        let max = per_point.iter().copied().fold(0.0, f64::max);
        Self { per_point, mean, rms, max, diagonal }
    }

    /// The summary of `values` alone (mean, RMS, maximum; [`Distances::per_point`] left empty),
    /// relative numbers against `diagonal`: for a summary that need not hold every distance.
    pub fn summary_of(values: impl IntoIterator<Item = f64>, diagonal: f64) -> Self {
        let (mut n, mut sum, mut squares, mut max) = (0usize, 0.0, 0.0, 0.0f64);
        for d in values {
            n += 1;
            sum += d;
            squares += d * d;
            max = max.max(d);
        }
        let n = n.max(1) as f64;
        Self { per_point: Vec::new(), mean: sum / n, rms: (squares / n).sqrt(), max, diagonal }
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

/// The points as `[x, y, z]` arrays, without a copy (glam's `DVec3` is three `f64` in that
/// order).
pub(crate) fn as_arrays(points: &[DVec3]) -> &[[f64; 3]] {
    bytemuck::cast_slice(points)
}

fn check_points(points: &[DVec3], what: fn(usize) -> NonFiniteInput) -> Result<(), Error> {
    if let Some(k) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinite { what: what(k) });
    }
    Ok(())
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
    let tree: ImmutableKdTree<f64, 3> = ImmutableKdTree::new_from_slice(as_arrays(points))
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
/// (the closest point of the closest triangle, found by the bounding-volume hierarchy of
/// [`crate::closest::TriangleBvh`]); relative numbers are against the mesh's bounding box.
///
/// # Errors
///
/// [`Error::NonFinite`] for a non-finite point or vertex; [`Error::TooFewPoints`] for a mesh
/// with no triangle; [`Error::InvalidOption`] for a triangle index out of range.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::distance::distances_to_mesh;
///
/// // A unit right triangle in z = 0: a point above its interior, one beyond its corner.
/// let v = [DVec3::ZERO, DVec3::X, DVec3::Y];
/// let points = [DVec3::new(0.2, 0.2, 0.5), DVec3::new(2.0, 0.0, 0.0)];
/// let d = distances_to_mesh(&points, &v, &[[0, 1, 2]])?;
/// assert_eq!(d.per_point, [0.5, 1.0]);
/// # Ok::<(), hi_scan::Error>(())
/// ```
pub fn distances_to_mesh(
    points: &[DVec3],
    vertices: &[DVec3],
    triangles: &[[u32; 3]],
) -> Result<Distances, Error> {
    check_points(points, NonFiniteInput::Point)?;
    let bvh = crate::closest::TriangleBvh::try_new(vertices, triangles)?;
    Ok(Distances::from_values(bvh.distances(points), bounding_diagonal(vertices)))
}
