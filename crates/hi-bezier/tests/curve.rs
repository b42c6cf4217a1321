// SPDX-License-Identifier: MIT
//! Bézier curves (§2.5) against analytic truths: the explicit Bernstein sum, eq. 2.4, the
//! power-basis derivative, Theorem 2.2, degree elevation, closed-form extrema, the curvature of
//! a parabola, and flattening checked by dense sampling.

mod common;

use common::{
    bezier_sum, central, dist_to_curve, dist_to_polyline, power_coefficients, power_deriv,
    wiggly_points,
};
use glam::{DVec2, DVec3};
use hi_bezier::{BezierCurve, Error, FlatnessTest, ParamRange, convex_hull_2d, polygon_area};

fn cubic() -> BezierCurve<DVec2> {
    BezierCurve::new(vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 3.0),
        DVec2::new(4.0, 3.0),
        DVec2::new(5.0, -1.0),
    ])
}

fn space_curve() -> BezierCurve<DVec3> {
    BezierCurve::new(vec![
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 2.0, -1.0),
        DVec3::new(2.0, -1.0, 3.0),
        DVec3::new(4.0, 1.0, 0.5),
        DVec3::new(3.0, 3.0, 2.0),
        DVec3::new(5.0, 0.0, 1.0),
    ])
}

#[test]
fn de_casteljau_equals_the_bernstein_sum() {
    for m in [1usize, 2, 4, 9, 16] {
        let pts = wiggly_points(m, m as u64);
        let c = BezierCurve::new(pts.clone());
        for k in 0..=40 {
            let t = k as f64 / 40.0;
            assert!((c.eval(t) - bezier_sum(&pts, t)).length() < 1e-12, "m={m} t={t}");
        }
    }
    let sc = space_curve();
    assert!((sc.eval(0.3) - bezier_sum(sc.control_points(), 0.3)).length() < 1e-14);
}

#[test]
fn interpolates_the_end_points() {
    let c = space_curve();
    assert_eq!(c.eval(0.0), c.control_points()[0]);
    assert_eq!(c.eval(1.0), c.control_points()[5]);
}

#[test]
fn end_derivatives_eq_2_4() {
    for c in [cubic(), BezierCurve::new(wiggly_points(7, 3))] {
        let p = c.control_points();
        let n = c.degree();
        let nf = n as f64;
        assert!((c.eval_deriv(0.0, 1) - nf * (p[1] - p[0])).length() < 1e-13);
        assert!((c.eval_deriv(1.0, 1) - nf * (p[n] - p[n - 1])).length() < 1e-13);
        // Second derivative at 0: n(n − 1)(P₂ − 2P₁ + P₀).
        let d2 = nf * (nf - 1.0) * (p[2] - 2.0 * p[1] + p[0]);
        assert!((c.eval_deriv(0.0, 2) - d2).length() < 1e-12);
    }
}

#[test]
fn hodograph_equals_the_power_basis_derivative() {
    let c = space_curve();
    let a = power_coefficients(c.control_points());
    for order in 0..=6 {
        let d = c.deriv_n(order);
        assert_eq!(d.degree(), 5usize.saturating_sub(order));
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            let e = power_deriv(&a, order, t);
            let scale = 1.0 + e.length();
            assert!((c.eval_deriv(t, order) - e).length() < 1e-11 * scale, "k={order} t={t}");
            assert!((d.eval(t) - e).length() < 1e-11 * scale, "deriv_n({order})");
        }
    }
    // The hodograph of eq. 2.3 has control points n(Pᵢ₊₁ − Pᵢ).
    let h = c.deriv();
    let p = c.control_points();
    for (i, q) in h.control_points().iter().enumerate() {
        assert!((*q - 5.0 * (p[i + 1] - p[i])).length() < 1e-14);
    }
}

#[test]
fn hodograph_by_finite_differences() {
    let c = BezierCurve::new(wiggly_points(9, 11));
    for k in 1..10 {
        let t = k as f64 / 10.0;
        let fd = central(|s| c.eval(s), t, 1e-6);
        assert!((c.deriv().eval(t) - fd).length() < 1e-6 * (1.0 + fd.length()), "t={t}");
        let fd2 = central(|s| c.eval_deriv(s, 1), t, 1e-6);
        assert!((c.eval_deriv(t, 2) - fd2).length() < 1e-5 * (1.0 + fd2.length()), "t={t}");
    }
}

#[test]
fn split_reproduces_both_halves_theorem_2_2() {
    let c = BezierCurve::new(wiggly_points(8, 5));
    for &t0 in &[0.0, 0.1, 0.3, 0.5, 0.77, 1.0] {
        let (q1, q2) = c.split(t0);
        assert_eq!((q1.degree(), q2.degree()), (7, 7));
        for k in 0..=20 {
            let t = k as f64 / 20.0;
            assert!((q1.eval(t) - c.eval(t0 * t)).length() < 1e-13, "q₁ t₀={t0} t={t}");
            assert!((q2.eval(t) - c.eval(t0 + (1.0 - t0) * t)).length() < 1e-13, "q₂ t₀={t0}");
        }
    }
    // The new control points are the edges of de Casteljau's triangle (eq. 2.6).
    let levels = c.de_casteljau_levels(0.3);
    let (q1, q2) = c.split(0.3);
    for r in 0..=7 {
        assert_eq!(q1.control_points()[r], levels[r][0]);
        assert_eq!(q2.control_points()[7 - r], levels[r][levels[r].len() - 1]);
    }
}

#[test]
fn split_outside_extrapolates() {
    let c = cubic();
    let (q1, _) = c.split(1.5);
    assert!((q1.eval(0.9) - c.eval(1.35)).length() < 1e-12);
}

#[test]
fn subsegment_reproduces() {
    let c = space_curve();
    for &(t0, t1) in &[(0.2, 0.6), (0.0, 0.3), (0.9, 0.1), (-0.2, 1.3)] {
        let s = c.subsegment(ParamRange::new(t0, t1));
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            assert!((s.eval(t) - c.eval(t0 + (t1 - t0) * t)).length() < 1e-12, "[{t0}, {t1}]");
        }
    }
}

#[test]
fn degree_elevation_preserves_the_curve() {
    let c = space_curve();
    for times in [1usize, 2, 5, 20] {
        let e = c.elevate_by(times);
        assert_eq!(e.degree(), 5 + times);
        for k in 0..=30 {
            let t = k as f64 / 30.0;
            assert!((e.eval(t) - c.eval(t)).length() < 1e-13, "times={times} t={t}");
        }
    }
    assert_eq!(c.elevate(), c.elevate_by(1));
    // Elevated control polygons converge to the curve: Qᵢ → q(i/(n + r)).
    let e = c.elevate_by(400);
    let m = e.degree() as f64;
    let worst = e
        .control_points()
        .iter()
        .enumerate()
        .map(|(i, q)| (*q - c.eval(i as f64 / m)).length())
        .fold(0.0, f64::max);
    assert!(worst < 0.1, "{worst}");
}

#[test]
fn tight_box_of_a_cubic_matches_closed_form_extrema() {
    // Each coordinate's derivative is a quadratic a·t² + b·t + c; solve it by the formula.
    let c = cubic();
    let a = power_coefficients(c.control_points());
    let mut lo = c.eval(0.0).min(c.eval(1.0));
    let mut hi = c.eval(0.0).max(c.eval(1.0));
    for axis in 0..2 {
        let (c1, c2, c3) = (a[1][axis], a[2][axis], a[3][axis]);
        // d/dt = c1 + 2c2·t + 3c3·t².
        let (qa, qb, qc) = (3.0 * c3, 2.0 * c2, c1);
        let disc = qb * qb - 4.0 * qa * qc;
        let mut roots = vec![];
        if qa.abs() < 1e-300 {
            roots.push(-qc / qb);
        } else if disc >= 0.0 {
            roots.push((-qb + disc.sqrt()) / (2.0 * qa));
            roots.push((-qb - disc.sqrt()) / (2.0 * qa));
        }
        for t in roots.into_iter().filter(|t| (0.0..=1.0).contains(t)) {
            let v = bezier_sum(c.control_points(), t)[axis];
            lo[axis] = lo[axis].min(v);
            hi[axis] = hi[axis].max(v);
        }
    }
    let b = c.bounding_box();
    assert!((b.min - lo).length() < 1e-14, "{:?} vs {lo}", b.min);
    assert!((b.max - hi).length() < 1e-14, "{:?} vs {hi}", b.max);
    let control = c.control_bounding_box();
    assert!(control.contains_box(&b, 0.0));
    assert!(control.max.y > b.max.y + 0.5, "the control box is loose here");
}

#[test]
fn tight_box_by_dense_sampling_any_degree() {
    for (m, seed) in [(3usize, 1u64), (6, 2), (10, 3), (15, 4)] {
        let c = BezierCurve::new(wiggly_points(m, seed));
        let b = c.bounding_box();
        let n_samples = 20_000;
        let (mut lo, mut hi) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
        for k in 0..=n_samples {
            let p = c.eval(k as f64 / n_samples as f64);
            assert!(b.contains_box(&hi_bezier::Aabb::from_point(p), 1e-12), "sample outside box");
            lo = lo.min(p);
            hi = hi.max(p);
        }
        // The sampled extremes miss the true ones by at most ~|q″|·h²/8.
        assert!((b.min - lo).abs().max_element() < 1e-6, "m={m}: {:?} vs {lo}", b.min);
        assert!((b.max - hi).abs().max_element() < 1e-6, "m={m}: {:?} vs {hi}", b.max);
    }
}

#[test]
fn flatten_respects_the_tolerance_both_ways() {
    let curves: Vec<BezierCurve<DVec2>> = vec![
        cubic(),
        BezierCurve::new(wiggly_points(3, 7)),
        BezierCurve::new(wiggly_points(6, 8)),
        BezierCurve::new(wiggly_points(9, 9)),
        // A cusp: P₁ = P₂ on the far side.
        BezierCurve::new(vec![DVec2::ZERO, DVec2::new(2.0, 1.0), DVec2::new(0.0, 1.0), DVec2::X]),
    ];
    for c in &curves {
        for tol in [0.3, 1e-2, 1e-4] {
            let poly = c.flatten(tol).unwrap();
            assert_eq!(poly[0], c.eval(0.0));
            assert_eq!(*poly.last().unwrap(), c.eval(1.0));
            // Every curve point is within tol of the polyline.
            let worst = (0..=20_000)
                .map(|k| dist_to_polyline(c.eval(k as f64 / 20_000.0), &poly))
                .fold(0.0, f64::max);
            assert!(worst <= tol * (1.0 + 1e-9), "curve→polyline {worst} > {tol}");
            // Every polyline point is within tol of the curve.
            let f = |t| c.eval(t);
            for w in poly.windows(2) {
                for j in 0..=8 {
                    let x = w[0].lerp(w[1], j as f64 / 8.0);
                    let d = dist_to_curve(x, &f, 4000);
                    assert!(d <= tol * (1.0 + 1e-6) + 1e-12, "polyline→curve {d} > {tol}");
                }
            }
        }
    }
}

#[test]
fn flatten_in_3d_and_1d() {
    let c = space_curve();
    let poly = c.flatten(1e-3).unwrap();
    let worst = (0..=10_000)
        .map(|k| dist_to_polyline(c.eval(k as f64 / 10_000.0), &poly))
        .fold(0.0, f64::max);
    assert!(worst <= 1e-3);
    // In 1-D the polyline must contain the extremes to within the tolerance.
    let scalar = BezierCurve::new(vec![0.0, 3.0, -2.0, 1.0]);
    let poly = scalar.flatten(1e-3).unwrap();
    let b = scalar.bounding_box();
    let max = poly.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert!(b.max - max <= 1e-3 && max <= b.max);
}

#[test]
fn midpoint_flatness_is_eq_2_7() {
    let c = cubic();
    let p = c.control_points();
    let expected = (bezier_sum(p, 0.5) - 0.5 * (p[0] + p[3])).length();
    assert!((c.midpoint_flatness() - expected).abs() < 1e-14);
    let coarse = c.flatten_with(0.5, FlatnessTest::Midpoint).unwrap();
    assert!(coarse.len() >= 2);
    assert!(c.hull_flatness() >= expected, "the hull bound dominates the midpoint distance");
}

#[test]
fn flatten_rejects_bad_tolerances() {
    let c = cubic();
    for tol in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e-14] {
        assert!(matches!(c.flatten(tol), Err(Error::InvalidTolerance { .. })), "{tol}");
    }
}

#[test]
fn curvature_of_the_parabola() {
    // x(t) = 2t − 1, y(t) = x²: κ(x) = 2/(1 + 4x²)^{3/2}, counter-clockwise (positive).
    let c =
        BezierCurve::new(vec![DVec2::new(-1.0, 1.0), DVec2::new(0.0, -1.0), DVec2::new(1.0, 1.0)]);
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        let x = 2.0 * t - 1.0;
        let e = 2.0 / (1.0 + 4.0 * x * x).powf(1.5);
        assert!((c.signed_curvature(t).unwrap() - e).abs() < 1e-14, "t={t}");
        assert!((c.curvature(t).unwrap() - e).abs() < 1e-14);
    }
}

#[test]
fn end_curvature_in_space() {
    // κ(0) = (n − 1)/n · |(P₁ − P₀) × (P₂ − P₁)| / |P₁ − P₀|³.
    let c = space_curve();
    let p = c.control_points();
    let n = 5.0;
    let e =
        (n - 1.0) / n * (p[1] - p[0]).cross(p[2] - p[1]).length() / (p[1] - p[0]).length().powi(3);
    assert!((c.curvature(0.0).unwrap() - e).abs() < 1e-13);
}

#[test]
fn control_hull_holds_the_curve() {
    let c = BezierCurve::new(wiggly_points(7, 21));
    let hull = c.control_hull();
    assert!(polygon_area(&hull) > 0.0, "counter-clockwise");
    for k in 0..=200 {
        let p = c.eval(k as f64 / 200.0);
        for i in 0..hull.len() {
            let (a, b) = (hull[i], hull[(i + 1) % hull.len()]);
            assert!((b - a).perp_dot(p - a) >= -1e-12, "outside edge {i}");
        }
    }
}

#[test]
fn hull_of_a_regular_polygon_with_inner_points() {
    let m = 12;
    let mut pts: Vec<DVec2> = (0..m)
        .map(|k| DVec2::from_angle(2.0 * std::f64::consts::PI * k as f64 / m as f64) * 3.0)
        .collect();
    pts.extend([DVec2::ZERO, DVec2::new(1.0, 1.0), DVec2::new(-2.0, 0.5)]);
    pts.reverse();
    let hull = convex_hull_2d(&pts);
    assert_eq!(hull.len(), m);
    // Area of the regular m-gon of circumradius R: (m/2)·R²·sin(2π/m).
    let e = 0.5 * m as f64 * 9.0 * (2.0 * std::f64::consts::PI / m as f64).sin();
    assert!((polygon_area(&hull) - e).abs() < 1e-12);
}

#[test]
fn validation() {
    assert_eq!(BezierCurve::<DVec2>::try_new(vec![]), Err(Error::Empty));
    assert_eq!(
        BezierCurve::try_new(vec![DVec2::ZERO, DVec2::new(f64::NAN, 0.0)]),
        Err(Error::NonFinitePoint { index: 1 })
    );
}
