// SPDX-License-Identifier: MIT
//! Property tests on random input: the identities of §2.5 and §4.3 (partition of unity,
//! de Casteljau = Bernstein sum, Theorem 2.2, degree elevation, convex hull property, exact
//! circular arcs, flattening tolerance, patch subdivision, affine invariance of triangles).

mod common;

use common::{bezier_sum, dist_to_polyline};
use glam::{DVec2, DVec3};
use hi_bezier::{
    Aabb, Bernstein, BezierCurve, BezierPatch, ParamRange, RationalBezierCurve, TriangularPatch,
    convex_hull_2d, polygon_area,
};
use hi_testkit::proptest_config;
use proptest::prelude::*;

fn point2() -> impl Strategy<Value = DVec2> {
    (-10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y)| DVec2::new(x, y))
}

fn point3() -> impl Strategy<Value = DVec3> {
    (-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn curve2(max_points: usize) -> impl Strategy<Value = BezierCurve<DVec2>> {
    prop::collection::vec(point2(), 1..max_points).prop_map(BezierCurve::new)
}

proptest! {
    #![proptest_config(proptest_config(256))]

    /// Σᵢ Bⁿᵢ(t) = 1 and every Bⁿᵢ(t) ≥ 0 on [0, 1].
    #[test]
    fn bernstein_partition_of_unity(n in 0usize..200, t in 0.0..=1.0f64) {
        let row = Bernstein::new(n).values(t);
        prop_assert!(row.iter().all(|&v| v >= 0.0));
        prop_assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-13);
    }

    /// de Casteljau's algorithm (eq. 2.6) equals the Bernstein sum (eq. 2.1).
    #[test]
    fn de_casteljau_is_the_bernstein_sum(c in curve2(12), t in 0.0..=1.0f64) {
        let e = bezier_sum(c.control_points(), t);
        prop_assert!((c.eval(t) - e).length() < 1e-11, "{} vs {}", c.eval(t), e);
    }

    /// Theorem 2.2: both halves reproduce the curve after reparametrisation.
    #[test]
    fn split_reproduces(c in curve2(12), t0 in 0.0..=1.0f64, s in 0.0..=1.0f64) {
        let (a, b) = c.split(t0);
        prop_assert!((a.eval(s) - c.eval(t0 * s)).length() < 1e-11);
        prop_assert!((b.eval(s) - c.eval(t0 + (1.0 - t0) * s)).length() < 1e-11);
    }

    /// Subsegments reproduce the curve between their ends.
    #[test]
    fn subsegment_reproduces(c in curve2(10), t0 in 0.0..=1.0f64, t1 in 0.0..=1.0f64, s in 0.0..=1.0f64) {
        let r = c.subsegment(ParamRange::new(t0, t1));
        prop_assert!((r.eval(s) - c.eval(t0 + (t1 - t0) * s)).length() < 1e-10);
    }

    /// Degree elevation does not change the curve.
    #[test]
    fn elevation_preserves(c in curve2(10), times in 0usize..6, t in 0.0..=1.0f64) {
        prop_assert!((c.elevate_by(times).eval(t) - c.eval(t)).length() < 1e-11);
    }

    /// The derivative agrees with a central difference of the curve.
    #[test]
    fn derivative_by_differences(c in curve2(8), t in 0.05..0.95f64) {
        let h = 1e-6;
        let fd = (c.eval(t + h) - c.eval(t - h)) / (2.0 * h);
        let scale = 1.0 + c.control_polygon_length() * c.degree() as f64;
        prop_assert!((c.eval_deriv(t, 1) - fd).length() < 1e-7 * scale);
    }

    /// Convex hull property: curve points lie in the control hull and the control box, and
    /// the tight box lies in the control box and holds the curve.
    #[test]
    fn hulls_and_boxes_hold_the_curve(c in curve2(9), t in 0.0..=1.0f64) {
        let p = c.eval(t);
        let hull = c.control_hull();
        if hull.len() >= 3 {
            prop_assert!(polygon_area(&hull) > 0.0);
            for i in 0..hull.len() {
                let (a, b) = (hull[i], hull[(i + 1) % hull.len()]);
                prop_assert!((b - a).perp_dot(p - a) >= -1e-9 * (1.0 + (b - a).length()));
            }
        }
        let tight = c.bounding_box();
        prop_assert!(c.control_bounding_box().contains_box(&tight, 1e-12));
        prop_assert!(tight.contains_box(&Aabb::from_point(p), 1e-11));
    }

    /// The hull of random points holds them all and its vertices are input points.
    #[test]
    fn convex_hull_holds_its_points(pts in prop::collection::vec(point2(), 0..40)) {
        let hull = convex_hull_2d(&pts);
        for v in &hull {
            prop_assert!(pts.contains(v));
        }
        if hull.len() >= 3 {
            for &p in &pts {
                for i in 0..hull.len() {
                    let (a, b) = (hull[i], hull[(i + 1) % hull.len()]);
                    prop_assert!((b - a).perp_dot(p - a) >= -1e-9);
                }
            }
        }
    }

    /// Flattening stays within the tolerance (checked on 2000 samples of the curve).
    #[test]
    fn flatten_within_tolerance(c in curve2(7), tol in 1e-4..1.0f64) {
        let poly = c.flatten(tol).unwrap();
        for k in 0..=2000 {
            let d = dist_to_polyline(c.eval(k as f64 / 2000.0), &poly);
            prop_assert!(d <= tol * (1.0 + 1e-9) + 1e-12, "{d} > {tol}");
        }
    }

    /// Circular arcs of any centre, radius and sweep lie on their circle.
    #[test]
    fn arcs_lie_on_their_circle(center in point2(), radius in 0.01..100.0f64,
                                start in -10.0..10.0f64, sweep in -3.1..3.1f64, t in 0.0..=1.0f64) {
        let arc = RationalBezierCurve::circle_arc(center, radius, start, sweep).unwrap();
        let d = (arc.eval(t) - center).length();
        prop_assert!((d - radius).abs() <= 1e-15 * 8.0 * (radius + center.length()), "{d} vs {radius}");
    }

    /// Patch splits in u and v reproduce the patch.
    #[test]
    fn patch_split_reproduces(grid in prop::collection::vec(point3(), 12), t in 0.0..=1.0f64,
                              u in 0.0..=1.0f64, v in 0.0..=1.0f64) {
        let rows: Vec<Vec<DVec3>> = grid.chunks(4).map(<[DVec3]>::to_vec).collect();
        let p = BezierPatch::new(rows);
        let (a, b) = p.split_u(t);
        let (c, d) = p.split_v(t);
        prop_assert!((a.eval(u, v) - p.eval(t * u, v)).length() < 1e-11);
        prop_assert!((b.eval(u, v) - p.eval(t + (1.0 - t) * u, v)).length() < 1e-11);
        prop_assert!((c.eval(u, v) - p.eval(u, t * v)).length() < 1e-11);
        prop_assert!((d.eval(u, v) - p.eval(u, t + (1.0 - t) * v)).length() < 1e-11);
    }

    /// Triangular patches are affine invariant: mapping the net maps the surface.
    #[test]
    fn triangle_affine_invariance(net in prop::collection::vec(point3(), 10), shift in point3(),
                                  scale in 0.1..3.0f64, u in 0.0..=1.0f64, v in 0.0..=1.0f64) {
        let (u, v) = if u + v > 1.0 { (1.0 - u, 1.0 - v) } else { (u, v) };
        let t = TriangularPatch::new(net.clone());
        let mapped = TriangularPatch::new(net.iter().map(|p| *p * scale + shift).collect());
        prop_assert!((mapped.eval(u, v) - (t.eval(u, v) * scale + shift)).length() < 1e-11);
    }

    /// The tight box is tight: its sides are within O(h²) of the extremes of dense samples.
    #[test]
    fn tight_box_is_tight(c in curve2(12)) {
        let b = c.bounding_box();
        let n_samples = 4000;
        let (mut lo, mut hi) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
        for k in 0..=n_samples {
            let p = c.eval(k as f64 / n_samples as f64);
            lo = lo.min(p);
            hi = hi.max(p);
        }
        let n = c.degree() as f64;
        // |q″| ≤ n(n − 1)·max|Δ²P| ≤ n²·40 for coordinates in ±10; a sampled extreme misses
        // the true one by at most |q″|·h²/8.
        let slack = n * n * 40.0 / (8.0 * (n_samples * n_samples) as f64) + 1e-12;
        let sampled = Aabb { min: lo, max: hi };
        prop_assert!(b.contains_box(&sampled, 1e-12));
        prop_assert!((lo - b.min).max_element() <= slack && (b.max - hi).max_element() <= slack,
                     "{b:?} vs [{lo}, {hi}]");
    }

    /// Roots of a product of linear factors with separated roots in (0, 1) are all found.
    #[test]
    fn roots_of_separated_factors(mut roots in prop::collection::vec(0.01..0.99f64, 1..7)) {
        roots.sort_by(f64::total_cmp);
        roots.dedup_by(|a, b| (*a - *b).abs() < 0.02);
        // Power basis of Π(t − rⱼ), then Bernstein coefficients cᵢ = Σⱼ C(i, j)/C(n, j)·aⱼ.
        let mut a = vec![1.0];
        for &r in &roots {
            let mut next = vec![0.0; a.len() + 1];
            for (k, &ak) in a.iter().enumerate() {
                next[k + 1] += ak;
                next[k] -= r * ak;
            }
            a = next;
        }
        let n = a.len() - 1;
        let c: Vec<f64> = (0..=n)
            .map(|i| (0..=i).map(|j| common::binomial(i as u64, j as u64)
                / common::binomial(n as u64, j as u64) * a[j]).sum())
            .collect();
        let found = BezierCurve::new(c).roots();
        prop_assert_eq!(found.len(), roots.len(), "{:?} vs {:?}", found, roots);
        for (f, r) in found.iter().zip(&roots) {
            prop_assert!((f - r).abs() < 1e-9, "{} vs {}", f, r);
        }
    }

    /// The subdivision box of a patch holds dense samples and is within the accuracy of them.
    #[test]
    fn patch_box_holds_the_patch(grid in prop::collection::vec(point3(), 12)) {
        let rows: Vec<Vec<DVec3>> = grid.chunks(3).map(<[DVec3]>::to_vec).collect();
        let p = BezierPatch::new(rows);
        let accuracy = 1e-4;
        let b = p.bounding_box(accuracy).unwrap();
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        let m = 60;
        for i in 0..=m {
            for j in 0..=m {
                let q = p.eval(i as f64 / m as f64, j as f64 / m as f64);
                lo = lo.min(q);
                hi = hi.max(q);
            }
        }
        let sampled = Aabb { min: lo, max: hi };
        prop_assert!(b.contains_box(&sampled, 1e-12));
        // Sampling error: |∂²p| ≤ 9·40 per direction, h = 1/60.
        let slack = accuracy + 2.0 * 9.0 * 40.0 / (8.0 * (m * m) as f64);
        prop_assert!((lo - b.min).max_element() <= slack && (b.max - hi).max_element() <= slack);
    }
}
