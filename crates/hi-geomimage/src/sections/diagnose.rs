// SPDX-License-Identifier: MIT
//! The measurements that tell a failed algorithm-1 fit (figures 5.8, 5.9) from a good one:
//! self-crossings of a closed polygon in the plane of a section, and how far a harmonic
//! contour strays from the chords between its points.

use std::num::NonZero;

use glam::{DVec2, DVec3};
use hi_curve::HarmonicCurve;
use kiddo::{ImmutableKdTree, SquaredEuclidean};

use crate::Error;

/// The number of proper crossings between non-adjacent edges of the closed polygon
/// p₀ p₁ … pₙ₋₁ p₀. Touching and collinear overlaps are not counted, so a simple polygon (and
/// a polygon whose points all coincide) has none.
///
/// Edges are swept in order of their least x, and only edges whose x ranges overlap are tested
/// (sweep and prune), so a simple curve costs about O(n log n + n·√n).
pub(super) fn crossings(p: &[DVec2]) -> usize {
    let n = p.len();
    if n < 4 {
        return 0;
    }
    let edges: Vec<(usize, f64, f64)> = (0..n)
        .map(|k| {
            let (a, b) = (p[k], p[(k + 1) % n]);
            (k, a.x.min(b.x), a.x.max(b.x))
        })
        .collect();
    let mut sorted = edges;
    sorted.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
    let mut count = 0;
    for (s, &(i, _, x_max)) in sorted.iter().enumerate() {
        for &(j, x_min, _) in &sorted[s + 1..] {
            if x_min > x_max {
                break;
            }
            let adjacent = (i + 1) % n == j || (j + 1) % n == i;
            if !adjacent && properly_cross(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]) {
                count += 1;
            }
        }
    }
    count
}

/// The fraction of the points of the closed polygon p₀ p₁ … pₙ₋₁ whose nearest other point is
/// strictly nearer than both their neighbours in the polygon: 0 when the order follows a
/// well-sampled curve, large when it jumps across the section (a scrambled order, or points
/// that form a band rather than a curve).
pub(super) fn misordered(p: &[DVec2]) -> Result<f64, Error> {
    let n = p.len();
    if n < 4 {
        return Ok(0.0);
    }
    let tree: ImmutableKdTree<f64, 2> =
        ImmutableKdTree::new_from_slice(&p.iter().map(|q| q.to_array()).collect::<Vec<_>>())
            .map_err(|_| Error::Degenerate {
                what: "the points of a section do not form a kd-tree",
            })?;
    let two = NonZero::new(2).unwrap_or(NonZero::<usize>::MIN);
    let count = (0..n)
        .filter(|&k| {
            let near =
                tree.query(&p[k].to_array()).nearest_n::<SquaredEuclidean<f64>>(two).execute();
            let nearest = near
                .iter()
                .map(|q| q.distance)
                .fold(f64::INFINITY, |a, d| if d > 0.0 { a.min(d) } else { a });
            let adjacent = p[k]
                .distance_squared(p[(k + n - 1) % n])
                .min(p[k].distance_squared(p[(k + 1) % n]));
            // Squared distances; a point's own entry (distance 0) and exact duplicates are skipped.
            nearest < adjacent * (1.0 - 1e-9)
        })
        .count();
    Ok(count as f64 / n as f64)
}

/// Whether segments ab and cd cross at a single point inside both.
fn properly_cross(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let side = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let (d1, d2) = (side(a, b, c), side(a, b, d));
    let (d3, d4) = (side(c, d, a), side(c, d, b));
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

/// Samples of a contour curve per interval between neighbouring points.
pub(super) const SAMPLES_PER_SPAN: usize = 8;

/// The contour curve sampled [`SAMPLES_PER_SPAN`] times per span (by FFT), with the largest
/// distance of a sample from the chord xₖxₖ₊₁ of its span: how far the harmonic curve
/// wanders off the polygon of its points (oscillation between unevenly spaced points).
pub(super) fn dense_and_overshoot(
    curve: &HarmonicCurve<DVec3>,
) -> Result<(Vec<DVec3>, f64), Error> {
    let n = curve.n();
    let dense = curve.sample_uniform(SAMPLES_PER_SPAN * n).map_err(Error::from)?;
    let x = curve.points();
    let mut worst = 0.0_f64;
    for (s, q) in dense.iter().enumerate() {
        let k = s / SAMPLES_PER_SPAN;
        worst = worst.max(distance_to_segment(*q, x[k], x[(k + 1) % n]));
        if s % SAMPLES_PER_SPAN == 0 && k > 0 {
            // The first sample of a span is also the last of the one before.
            worst = worst.max(distance_to_segment(*q, x[k - 1], x[k]));
        }
    }
    Ok((dense, worst))
}

fn distance_to_segment(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 { ((p - a).dot(ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
    p.distance(a + ab * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bow_tie_crosses_once_and_a_square_never() {
        let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
        assert_eq!(crossings(&square), 0);
        let bow_tie = [DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ONE];
        assert_eq!(crossings(&bow_tie), 1);
        // A pentagram visits the vertices of a pentagon two at a time: 5 crossings.
        let star: Vec<DVec2> = (0..5)
            .map(|k| {
                let a = std::f64::consts::TAU * (2 * k) as f64 / 5.0;
                DVec2::new(a.cos(), a.sin())
            })
            .collect();
        assert_eq!(crossings(&star), 5);
        assert_eq!(crossings(&[DVec2::ONE; 6]), 0);
    }

    #[test]
    fn an_order_that_jumps_across_is_misordered() {
        // Twelve points round a circle: in order, none is misordered; every other one swapped
        // with its opposite, each point's nearest neighbour is away from it in the order.
        let circle: Vec<DVec2> = (0..12)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / 12.0;
                DVec2::new(a.cos(), a.sin())
            })
            .collect();
        assert_eq!(misordered(&circle).unwrap(), 0.0);
        let jumping: Vec<DVec2> =
            (0..12).map(|k| circle[if k % 2 == 0 { k } else { (k + 6) % 12 }]).collect();
        assert_eq!(misordered(&jumping).unwrap(), 1.0);
    }

    #[test]
    fn the_curve_through_a_square_overshoots_by_its_sagitta() {
        // The harmonic curve through a square's corners is its circumcircle (docs/math.md §3): it
        // bulges 1 − cos 45° beyond each side.
        let c = HarmonicCurve::new(vec![DVec3::X, DVec3::Y, -DVec3::X, -DVec3::Y]);
        let (dense, over) = dense_and_overshoot(&c).unwrap();
        assert_eq!(dense.len(), 4 * SAMPLES_PER_SPAN);
        assert!((over - (1.0 - 0.5f64.sqrt())).abs() < 1e-12, "{over}");
    }
}
