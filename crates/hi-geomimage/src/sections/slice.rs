// SPDX-License-Identifier: MIT
//! Steps 1–4 of algorithm 1 (§5.3): the slicing axis, the cross-sections (equal slabs, or the
//! thesis's recursive subdivision with its termination criterion), and the order of the points
//! of each cross-section along its contour (polar angle, or nearest neighbours).

use glam::{DMat3, DVec2, DVec3};

use super::{ContourOrder, SliceAxis};
use crate::Error;

/// The fewest points a cross-section may have: a harmonic curve through fewer is a point or a
/// segment traversed twice.
pub(super) const MIN_SLICE_POINTS: usize = 3;

/// The recursive subdivision of step 3 stops at slabs this many times thinner than the object.
const MAX_DEPTH: u32 = 24;

/// The slicing frame: a unit axis and two unit vectors spanning the planes of the sections, so
/// that (e₁, e₂, a) is right-handed.
#[derive(Clone, Copy, Debug)]
pub(super) struct Frame {
    pub(super) axis: DVec3,
    pub(super) e1: DVec3,
    pub(super) e2: DVec3,
}

impl Frame {
    pub(super) fn new(axis: DVec3) -> Self {
        let (e1, e2) = axis.any_orthonormal_pair();
        // any_orthonormal_pair gives a right-handed (e1, e2, axis).
        Self { axis, e1, e2 }
    }

    pub(super) fn height(&self, p: DVec3) -> f64 {
        p.dot(self.axis)
    }

    pub(super) fn plane(&self, p: DVec3) -> DVec2 {
        DVec2::new(p.dot(self.e1), p.dot(self.e2))
    }
}

/// The unit axis of `choice` for `points` (finite, at least one).
pub(super) fn axis_of(choice: SliceAxis, points: &[DVec3]) -> Result<DVec3, Error> {
    match choice {
        SliceAxis::X => Ok(DVec3::X),
        SliceAxis::Y => Ok(DVec3::Y),
        SliceAxis::Z => Ok(DVec3::Z),
        SliceAxis::Principal => principal_axis(points),
    }
}

/// The direction of largest variance (power iteration on the covariance matrix), with its
/// largest coordinate positive so that the choice is deterministic.
fn principal_axis(points: &[DVec3]) -> Result<DVec3, Error> {
    let n = points.len() as f64;
    let mean = points.iter().copied().sum::<DVec3>() / n;
    let mut cov = DMat3::ZERO;
    for p in points {
        let d = *p - mean;
        cov += DMat3::from_cols(d * d.x, d * d.y, d * d.z);
    }
    cov *= 1.0 / n;
    // Start from the longest column: it has a component along the principal direction.
    let cols = [cov.x_axis, cov.y_axis, cov.z_axis];
    let mut v =
        cols.into_iter().max_by(|a, b| a.length().total_cmp(&b.length())).unwrap_or(DVec3::Z);
    if v.length() <= 0.0 {
        return Err(Error::Degenerate { what: "all points coincide: no principal axis" });
    }
    for _ in 0..200 {
        v = (cov * v).normalize_or_zero();
        if v == DVec3::ZERO {
            return Err(Error::Degenerate { what: "all points coincide: no principal axis" });
        }
    }
    let largest = if v.x.abs() >= v.y.abs() && v.x.abs() >= v.z.abs() {
        v.x
    } else if v.y.abs() >= v.z.abs() {
        v.y
    } else {
        v.z
    };
    Ok(if largest < 0.0 { -v } else { v })
}

/// One cross-section: the indices of its points and its slab of heights.
#[derive(Clone, Debug)]
pub(super) struct Slab {
    pub(super) from: f64,
    pub(super) to: f64,
    pub(super) members: Vec<usize>,
}

/// `k` slabs of equal thickness between the lowest and highest point (steps 2–3 with a fixed
/// number of sections). Every slab must hold at least [`MIN_SLICE_POINTS`] points.
pub(super) fn equal_slabs(heights: &[f64], lo: f64, hi: f64, k: usize) -> Result<Vec<Slab>, Error> {
    let width = (hi - lo) / k as f64;
    let mut slabs: Vec<Slab> = (0..k)
        .map(|i| Slab {
            from: lo + i as f64 * width,
            to: if i + 1 == k { hi } else { lo + (i + 1) as f64 * width },
            members: Vec::new(),
        })
        .collect();
    for (idx, h) in heights.iter().enumerate() {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "(h − lo)/width lies in [0, k] for lo ≤ h ≤ hi"
        )]
        let i = (((h - lo) / width).floor().max(0.0) as usize).min(k - 1);
        slabs[i].members.push(idx);
    }
    check_slabs(&slabs)?;
    Ok(slabs)
}

/// The recursive subdivision of step 3: a slab is halved until "the vertical distance between
/// any two points in the cross section is less than the horizontal distance" — its points'
/// spread along the axis is at most the median distance between neighbours along its contour —
/// or it has too few points to halve. Empty halves are dropped. The object is always cut at
/// least once, so there are at least two sections.
pub(super) fn recursive_slabs(
    points: &[DVec3],
    heights: &[f64],
    frame: &Frame,
    order: ContourOrder,
    lo: f64,
    hi: f64,
) -> Result<Vec<Slab>, Error> {
    let all: Vec<usize> = (0..points.len()).collect();
    let mut slabs = Vec::new();
    let mid = 0.5 * (lo + hi);
    let (below, above): (Vec<usize>, Vec<usize>) = all.iter().partition(|&&i| heights[i] < mid);
    for (from, to, members) in [(lo, mid, below), (mid, hi, above)] {
        subdivide(points, heights, frame, order, Slab { from, to, members }, 1, &mut slabs);
    }
    check_slabs(&slabs)?;
    Ok(slabs)
}

fn subdivide(
    points: &[DVec3],
    heights: &[f64],
    frame: &Frame,
    order: ContourOrder,
    slab: Slab,
    depth: u32,
    out: &mut Vec<Slab>,
) {
    if slab.members.is_empty() {
        return;
    }
    let (h_min, h_max) =
        slab.members.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &i| {
            (a.min(heights[i]), b.max(heights[i]))
        });
    let spread = h_max - h_min;
    let done = depth >= MAX_DEPTH
        || slab.members.len() < 2 * MIN_SLICE_POINTS
        || spread <= median_spacing(points, frame, order, &slab.members);
    if done {
        out.push(slab);
        return;
    }
    let mid = 0.5 * (slab.from + slab.to);
    let (below, above): (Vec<usize>, Vec<usize>) =
        slab.members.iter().partition(|&&i| heights[i] < mid);
    subdivide(
        points,
        heights,
        frame,
        order,
        Slab { from: slab.from, to: mid, members: below },
        depth + 1,
        out,
    );
    subdivide(
        points,
        heights,
        frame,
        order,
        Slab { from: mid, to: slab.to, members: above },
        depth + 1,
        out,
    );
}

/// The median horizontal distance between consecutive points of the ordered contour.
fn median_spacing(points: &[DVec3], frame: &Frame, order: ContourOrder, members: &[usize]) -> f64 {
    let plane: Vec<DVec2> = members.iter().map(|&i| frame.plane(points[i])).collect();
    let ordered = order_contour(&plane, order);
    let n = ordered.len();
    let mut gaps: Vec<f64> =
        (0..n).map(|k| plane[ordered[k]].distance(plane[ordered[(k + 1) % n]])).collect();
    gaps.sort_by(f64::total_cmp);
    gaps.get(n / 2).copied().unwrap_or(0.0)
}

pub(super) fn check_slabs(slabs: &[Slab]) -> Result<(), Error> {
    if let Some((i, s)) = slabs.iter().enumerate().find(|(_, s)| s.members.len() < MIN_SLICE_POINTS)
    {
        return Err(Error::SparseSlice {
            slice: i,
            n_slices: slabs.len(),
            from: s.from,
            to: s.to,
            found: s.members.len(),
            needed: MIN_SLICE_POINTS,
        });
    }
    Ok(())
}

/// The order of `plane` (points of one section, in its plane) along its contour (step 4),
/// counter-clockwise in (e₁, e₂), starting from the point of least polar angle about the
/// centroid.
///
/// - [`ContourOrder::Angular`]: by polar angle about the centroid (ties by distance), the
///   thesis's "ordering may be achieved using polar coordinates". Right for a section that is
///   star-shaped about its centroid; any other section is scrambled.
/// - [`ContourOrder::NearestNeighbour`]: from that first point, always on to the nearest point
///   not yet visited (the thesis's "nearest neighbour algorithm"), then reversed if the
///   polygon turns clockwise.
pub(super) fn order_contour(plane: &[DVec2], order: ContourOrder) -> Vec<usize> {
    let n = plane.len();
    if n == 0 {
        return Vec::new();
    }
    let centroid = plane.iter().copied().sum::<DVec2>() / n as f64;
    let polar: Vec<(f64, f64)> = plane
        .iter()
        .map(|p| {
            let d = *p - centroid;
            (d.y.atan2(d.x), d.length())
        })
        .collect();
    let mut by_angle: Vec<usize> = (0..n).collect();
    by_angle.sort_by(|&a, &b| {
        polar[a].0.total_cmp(&polar[b].0).then(polar[a].1.total_cmp(&polar[b].1)).then(a.cmp(&b))
    });
    match order {
        ContourOrder::Angular => by_angle,
        ContourOrder::NearestNeighbour => {
            let mut visited = vec![false; n];
            let mut chain = Vec::with_capacity(n);
            let mut current = by_angle[0];
            visited[current] = true;
            chain.push(current);
            for _ in 1..n {
                let here = plane[current];
                let mut best = (f64::INFINITY, usize::MAX);
                for (i, p) in plane.iter().enumerate() {
                    if !visited[i] {
                        let d = p.distance_squared(here);
                        if d < best.0 {
                            best = (d, i);
                        }
                    }
                }
                current = best.1;
                visited[current] = true;
                chain.push(current);
            }
            if signed_area(plane, &chain) < 0.0 {
                chain[1..].reverse();
            }
            chain
        }
    }
}

/// Twice the signed area of the polygon `plane[order[0]], plane[order[1]], …` (shoelace).
pub(super) fn signed_area(plane: &[DVec2], order: &[usize]) -> f64 {
    let n = order.len();
    (0..n).map(|k| plane[order[k]].perp_dot(plane[order[(k + 1) % n]])).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_orders_go_counter_clockwise_round_a_square() {
        // A square's corners, shuffled: both orders give 0, 1, 2, 3 from the corner at −135°.
        let plane = [
            DVec2::new(1.0, 1.0),
            DVec2::new(-1.0, -1.0),
            DVec2::new(-1.0, 1.0),
            DVec2::new(1.0, -1.0),
        ];
        for order in [ContourOrder::Angular, ContourOrder::NearestNeighbour] {
            assert_eq!(order_contour(&plane, order), vec![1, 3, 0, 2], "{order:?}");
        }
    }

    #[test]
    fn the_principal_axis_of_a_long_box_is_its_length() {
        let points: Vec<DVec3> = (0..27)
            .map(|i| {
                DVec3::new(
                    (i % 3) as f64 - 1.0,
                    5.0 * ((i / 3 % 3) as f64 - 1.0),
                    (i / 9) as f64 - 1.0,
                )
            })
            .collect();
        let a = principal_axis(&points).unwrap();
        assert!((a - DVec3::Y).length() < 1e-12, "{a}");
        assert!(principal_axis(&[DVec3::ONE; 4]).is_err());
    }
}
