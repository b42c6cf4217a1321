// SPDX-License-Identifier: MIT
//! Point clouds too large to work on point by point, summarised: one point per occupied cell of
//! a grid of cubes, the mean of the points in it (and of their normals, where the scan has
//! them), so that what is built on the summary costs what the grid holds rather than what the
//! scanner delivered. A scanner's 10⁶–10⁷ points sample the surface far more densely than a
//! geometry image of 512² texels can hold; the cell is chosen from the detail wanted
//! ([`cell_for_count`]: the cell at which about so many cells are occupied), and averaging within
//! a cell also takes the scanner's noise down by about the square root of the points in it.
//!
//! Before either, a point listed more than once is taken once ([`merge_duplicates`]): the
//! vertices of a mesh written triangle by triangle repeat each point several times.
//!
//! These steps cost O(n log n) in the n points (a sort of the points' cell keys) and hold O(n)
//! extra memory (a key and an index per point, 16 bytes); the result does not depend on the
//! number of threads (each cell's points are summed in the order the scan lists them).

use glam::DVec3;

use crate::{Error, NonFiniteInput};
use hi_par::*;

/// A point cloud summarised on a grid ([`summarise`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// One point per occupied cell: the mean of the scan's points in it, in the order of the
    /// cells' keys (z, then y, then x).
    pub points: Vec<DVec3>,
    /// The mean of the unit normals of the points in each cell, normalised (zero where they
    /// cancel), when the scan has normals.
    pub normals: Option<Vec<DVec3>>,
    /// How many scan points each summary point stands for.
    pub counts: Vec<u32>,
    /// The cell's side.
    pub cell: f64,
}

/// The most cells along an axis (keys pack three 21-bit coordinates).
const AXIS_CELLS: f64 = (1u64 << 21) as f64;

/// The cell key of each point on a grid of side `cell` from `origin`.
fn keys(points: &[DVec3], origin: DVec3, cell: f64) -> Vec<u64> {
    points
        .par_iter()
        .map(|p| {
            let c = ((*p - origin) / cell).floor();
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "0 ≤ c < 2²¹, checked by the caller's extent"
            )]
            let [x, y, z] = c.to_array().map(|v| v.clamp(0.0, AXIS_CELLS - 1.0) as u64);
            (z << 42) | (y << 21) | x
        })
        .collect()
}

/// Checks the points and a cell side, and returns the grid's origin.
fn grid_origin(points: &[DVec3], cell: f64) -> Result<DVec3, Error> {
    if let Some(k) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinite { what: NonFiniteInput::Point(k) });
    }
    if points.is_empty() {
        return Err(Error::TooFewPoints { found: 0, needed: 1 });
    }
    let (lo, hi) = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    if !(cell.is_finite() && cell > 0.0) || (hi - lo).max_element() / cell >= AXIS_CELLS - 1.0 {
        return Err(Error::InvalidOption {
            name: "summary cell",
            value: cell,
            expected: "positive, and at least 2⁻²¹ of the points' extent",
        });
    }
    Ok(lo)
}

/// The number of cells of side `cell` that hold at least one of `points`.
///
/// # Errors
///
/// As [`summarise`].
pub fn occupied_cells(points: &[DVec3], cell: f64) -> Result<usize, Error> {
    let origin = grid_origin(points, cell)?;
    let mut k = keys(points, origin, cell);
    k.par_sort_unstable();
    k.dedup();
    Ok(k.len())
}

/// The most points [`cell_for_count`] looks at, unless the target is over a quarter of them
/// (an even subsample of larger clouds: a cell several times their spacing is occupied alike).
const ESTIMATE_POINTS: usize = 200_000;

/// The side of the grid cell at which about `target` cells hold points of `points` (within
/// about 10 %, for points on a surface). The count of occupied cells of a surface falls as the
/// square of the side; two measured counts fix the local exponent and a third corrects it. On
/// clouds of more than 200 000 points and four times the target, the counts are taken on an
/// even subsample of that size, and one count of the whole cloud corrects the last.
///
/// # Errors
///
/// [`Error::TooFewPoints`] for fewer than `target` points (or none); [`Error::NonFinite`] for a
/// non-finite point; [`Error::Degenerate`] when all points coincide.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::cloud::{cell_for_count, occupied_cells};
///
/// // 250 000 points on a unit square: about 10 000 cells of side 0.01 hold points.
/// let points: Vec<DVec3> =
///     (0..250_000).map(|k| DVec3::new((k % 500) as f64 / 500.0, (k / 500) as f64 / 500.0, 0.0)).collect();
/// let cell = cell_for_count(&points, 10_000).unwrap();
/// let count = occupied_cells(&points, cell).unwrap() as f64;
/// assert!((count / 10_000.0 - 1.0).abs() < 0.1, "{count}");
/// ```
pub fn cell_for_count(points: &[DVec3], target: usize) -> Result<f64, Error> {
    if points.len() < target.max(1) {
        return Err(Error::TooFewPoints { found: points.len(), needed: target.max(1) });
    }
    // Cells larger than the subsample's spacing are occupied as the whole cloud's are.
    let step = points.len().div_ceil(ESTIMATE_POINTS.max(4 * target));
    let sample: Vec<DVec3> = points.iter().step_by(step).copied().collect();
    let target = target as f64;
    let diagonal = crate::distance::bounding_diagonal(&sample);
    if diagonal.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Err(Error::Degenerate { what: "all points coincide" });
    }
    let count = |cell: f64| occupied_cells(&sample, cell).map(|c| c as f64);
    // Start where a surface spread over the bounding box would give the target.
    let mut h0 = diagonal / target.sqrt();
    let mut n0 = count(h0)?;
    let mut h1 = h0 * (n0 / target).sqrt();
    for _ in 0..3 {
        let n1 = count(h1)?;
        if (n1 / target - 1.0).abs() < 0.05 || h1 == h0 {
            break;
        }
        // The local exponent n ∝ h^(−a), a between 1 (a curve) and 3 (a volume).
        let a = if n1 != n0 { ((n1 / n0).ln() / (h0 / h1).ln()).clamp(1.0, 3.0) } else { 2.0 };
        let next = h1 * (n1 / target).powf(1.0 / a);
        (h0, n0, h1) = (h1, n1, next);
    }
    if step > 1 {
        // Near the sample's own spacing its cells empty faster than the cloud's: one step on
        // the whole cloud corrects that (as a surface's count falls, as the square).
        let n = occupied_cells(points, h1)? as f64;
        h1 *= (n / target).sqrt();
    }
    Ok(h1)
}

/// The summary of `points` (with their `normals`, one per point, if given) on a grid of cubes
/// of side `cell`: see the module documentation.
///
/// # Errors
///
/// [`Error::TooFewPoints`] for no points; [`Error::NonFinite`] for a non-finite point;
/// [`Error::InvalidOption`] for a cell that is not positive and finite, or so small that the
/// points' extent spans more than 2²¹ cells, or a normal count other than the point count.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::cloud::summarise;
///
/// // Four points in two cells of side 1: their means.
/// let points = [DVec3::ZERO, DVec3::splat(0.5), DVec3::new(1.25, 0.0, 0.0), DVec3::new(1.5, 0.25, 0.0)];
/// let s = summarise(&points, None, 1.0).unwrap();
/// assert_eq!(s.points, vec![DVec3::splat(0.25), DVec3::new(1.375, 0.125, 0.0)]);
/// assert_eq!(s.counts, vec![2, 2]);
/// ```
pub fn summarise(points: &[DVec3], normals: Option<&[DVec3]>, cell: f64) -> Result<Summary, Error> {
    crate::error::check_points(points, normals)?;
    let origin = grid_origin(points, cell)?;
    // Each point's cell key beside its index, sorted: a cell's points stay in the scan's order
    // (ties are broken by the index), so the sums do not depend on threads.
    let mut order: Vec<(u64, u32)> = keys(points, origin, cell)
        .into_iter()
        .zip(0..u32::try_from(points.len()).unwrap_or(u32::MAX))
        .collect();
    order.par_sort_unstable();
    let mut out_points = Vec::new();
    let mut out_normals = normals.map(|_| Vec::new());
    let mut counts = Vec::new();
    let mut start = 0;
    while start < order.len() {
        let key = order[start].0;
        let mut end = start + 1;
        while end < order.len() && order[end].0 == key {
            end += 1;
        }
        let members = &order[start..end];
        let sum: DVec3 = members.iter().map(|&(_, i)| points[i as usize]).sum();
        out_points.push(sum / members.len() as f64);
        if let (Some(out), Some(given)) = (out_normals.as_mut(), normals) {
            let n: DVec3 =
                members.iter().map(|&(_, i)| given[i as usize].normalize_or_zero()).sum::<DVec3>();
            out.push(n.normalize_or_zero());
        }
        counts.push(u32::try_from(members.len()).unwrap_or(u32::MAX));
        start = end;
    }
    Ok(Summary { points: out_points, normals: out_normals, counts, cell })
}

/// The distinct points of `points`, each once, in the order they first appear, with the
/// mean of their normals (as [`summarise`] averages a cell's) and how many times each was
/// listed: a mesh's vertices written triangle by triangle (an STL file, a mesh whose seams
/// repeat their vertices) list most points several times, and a neighbourhood of k points
/// would hold fewer than k distinct ones. The [`Summary::cell`] is 0. Points equal as numbers
/// are one point (−0 and +0 alike).
///
/// # Errors
///
/// [`Error::NonFinite`] for a non-finite point; [`Error::InvalidOption`] for a normal count
/// other than the point count.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::cloud::merge_duplicates;
///
/// let points = [DVec3::X, DVec3::Y, DVec3::X, DVec3::new(-0.0, 1.0, 0.0)];
/// let merged = merge_duplicates(&points, None).unwrap();
/// assert_eq!(merged.points, vec![DVec3::X, DVec3::Y]);
/// assert_eq!(merged.counts, vec![2, 2]);
/// ```
pub fn merge_duplicates(points: &[DVec3], normals: Option<&[DVec3]>) -> Result<Summary, Error> {
    crate::error::check_points(points, normals)?;
    // +0.0 turns −0 into +0.
    let key = |p: DVec3| (p + DVec3::ZERO).to_array().map(f64::to_bits);
    // (the point's bits, its index), sorted.
    type Keyed = ([u64; 3], u32);
    let mut order: Vec<Keyed> = points
        .par_iter()
        .map(|p| key(*p))
        .zip(0..u32::try_from(points.len()).unwrap_or(u32::MAX))
        .collect();
    order.par_sort_unstable();
    // (first index, members) of each distinct point, then in the order of first appearance.
    let mut groups: Vec<(u32, &[Keyed])> =
        order.chunk_by(|a, b| a.0 == b.0).map(|members| (members[0].1, members)).collect();
    groups.sort_unstable_by_key(|g| g.0);
    let out_points = groups.iter().map(|&(first, _)| points[first as usize]).collect();
    let out_normals = normals.map(|given| {
        groups
            .iter()
            .map(|(_, members)| {
                members
                    .iter()
                    .map(|&(_, i)| given[i as usize].normalize_or_zero())
                    .sum::<DVec3>()
                    .normalize_or_zero()
            })
            .collect()
    });
    let counts = groups
        .iter()
        .map(|(_, members)| u32::try_from(members.len()).unwrap_or(u32::MAX))
        .collect();
    Ok(Summary { points: out_points, normals: out_normals, counts, cell: 0.0 })
}

/// The indices of `points` ordered cell by cell on a grid of about 256 cells along the longest
/// side of their bounding box (in the scan's order within a cell): nearest-point and
/// closest-point queries made in this order find their answers near the last ones, in cache.
/// Empty for no points or a non-finite one.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::cloud::spatial_order;
///
/// let points = [DVec3::ZERO, DVec3::splat(10.0), DVec3::splat(0.01)];
/// assert_eq!(spatial_order(&points), vec![0, 2, 1]);
/// ```
#[must_use]
pub fn spatial_order(points: &[DVec3]) -> Vec<u32> {
    let (lo, hi) = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let cell = (hi - lo).max_element() / 256.0;
    if !(cell.is_finite() && cell > 0.0) {
        return (0..u32::try_from(points.len()).unwrap_or(0)).collect();
    }
    let mut order: Vec<(u64, u32)> = keys(points, lo, cell)
        .into_iter()
        .zip(0..u32::try_from(points.len()).unwrap_or(u32::MAX))
        .collect();
    order.par_sort_unstable();
    order.into_iter().map(|(_, i)| i).collect()
}
