// SPDX-License-Identifier: MIT
//! Rational Bézier curves and conics (§2.5, figure 2.8) against analytic truths: radii and
//! angles of circular arcs, the conic type from an implicit conic fitted through sample points,
//! the chord sagitta of a flattened circle, and derivatives by finite differences.

mod common;

use std::f64::consts::{FRAC_PI_2, PI};

use common::central;
use glam::DVec2;
use hi_bezier::{BezierCurve, ConicType, Error, ParamRange, RationalBezierCurve};

/// Figure 2.8: x₀ = (0, 1), x₁ = (2, 1), x₂ = (2, −1), x₃ = (0, −1), weights 1, ⅓, ⅓, 1.
fn figure_2_8() -> RationalBezierCurve<DVec2> {
    RationalBezierCurve::new(
        vec![
            DVec2::new(0.0, 1.0),
            DVec2::new(2.0, 1.0),
            DVec2::new(2.0, -1.0),
            DVec2::new(0.0, -1.0),
        ],
        vec![1.0, 1.0 / 3.0, 1.0 / 3.0, 1.0],
    )
}

#[test]
fn figure_2_8_is_the_right_half_of_the_unit_circle() {
    let c = figure_2_8();
    let mut last_angle = FRAC_PI_2;
    for k in 0..=1000 {
        let t = k as f64 / 1000.0;
        let p = c.eval(t);
        assert!((p.length() - 1.0).abs() <= 1e-15, "t={t}: |p| − 1 = {}", p.length() - 1.0);
        assert!(p.x >= -1e-16, "right half");
        let angle = p.y.atan2(p.x);
        assert!(angle <= last_angle + 1e-15, "clockwise, monotone");
        last_angle = angle;
    }
    assert!((c.eval(0.5) - DVec2::X).length() < 1e-15);
    assert!((last_angle + FRAC_PI_2).abs() < 1e-15, "ends at (0, −1)");
}

#[test]
fn circular_arcs_are_exact() {
    let centers = [DVec2::ZERO, DVec2::new(3.0, -2.0)];
    for &center in &centers {
        for &radius in &[1.0, 0.25, 7.0] {
            for &(start, sweep) in
                &[(0.0, FRAC_PI_2), (1.0, 3.0), (-0.5, -2.5), (2.0, 0.1), (0.3, 3.1)]
            {
                let arc = RationalBezierCurve::circle_arc(center, radius, start, sweep).unwrap();
                assert_eq!(arc.conic_type(), Some(ConicType::Ellipse));
                assert!((arc.conic_shape_factor().unwrap() - (0.5 * sweep).cos()).abs() < 1e-15);
                let tol = 2e-16 * (radius + center.length()) * 4.0;
                for k in 0..=200 {
                    let t = k as f64 / 200.0;
                    let p = arc.eval(t) - center;
                    assert!(
                        (p.length() - radius).abs() <= tol.max(1e-15 * radius),
                        "r={radius} t={t}"
                    );
                    // The angle runs monotonically from start to start + sweep.
                    let theta = start + (p.y.atan2(p.x) - start + PI).rem_euclid(2.0 * PI) - PI;
                    let along = (theta - start) / sweep;
                    assert!((-1e-12..=1.0 + 1e-12).contains(&along), "angle within the sweep");
                }
                let p0 = arc.eval(0.0) - center;
                let p1 = arc.eval(1.0) - center;
                assert!((p0 - radius * DVec2::from_angle(start)).length() < 1e-14 * radius);
                assert!(
                    (p1 - radius * DVec2::from_angle(start + sweep)).length()
                        < 1e-14 * (radius + 1.0)
                );
            }
        }
    }
}

#[test]
fn unit_arcs_to_1e_15() {
    for &sweep in &[0.1, 1.0, FRAC_PI_2, 2.5, 3.1] {
        let arc = RationalBezierCurve::circle_arc(DVec2::ZERO, 1.0, 0.2, sweep).unwrap();
        for k in 0..=1000 {
            let d = arc.eval(k as f64 / 1000.0).length() - 1.0;
            assert!(d.abs() <= 1e-15, "sweep {sweep}: {d}");
        }
    }
}

#[test]
fn full_circle_from_arcs() {
    for n_arcs in [3usize, 4, 7] {
        let arcs = RationalBezierCurve::circle(DVec2::new(1.0, 1.0), 2.0, n_arcs).unwrap();
        assert_eq!(arcs.len(), n_arcs);
        for (i, arc) in arcs.iter().enumerate() {
            let next = &arcs[(i + 1) % n_arcs];
            // C0 and G1 (here even C1: equal speeds) at every join, including the closing one.
            assert!((arc.eval(1.0) - next.eval(0.0)).length() < 1e-14);
            let (a, b) = (arc.eval_deriv(1.0, 1), next.eval_deriv(0.0, 1));
            assert!(a.normalize().perp_dot(b.normalize()).abs() < 1e-14);
            assert!((a - b).length() < 1e-13 * a.length());
        }
        // The arc angles add up to the whole turn.
        let total: f64 = arcs
            .iter()
            .map(|a| {
                let u = a.eval(0.0) - DVec2::ONE;
                let v = a.eval(1.0) - DVec2::ONE;
                u.angle_to(v)
            })
            .sum();
        assert!((total - 2.0 * PI).abs() < 1e-13);
    }
}

#[test]
fn arc_derivatives_and_curvature() {
    let (center, r) = (DVec2::new(-1.0, 2.0), 1.5);
    let arc = RationalBezierCurve::circle_arc(center, r, 0.4, 2.0).unwrap();
    for k in 1..20 {
        let t = k as f64 / 20.0;
        let p = arc.eval(t);
        let d = arc.eval_derivs(t, 3);
        assert_eq!(d[0], p);
        // Tangent ⊥ radius; derivatives agree with central differences.
        assert!(d[1].dot(p - center).abs() < 1e-12 * d[1].length());
        let fd1 = central(|s| arc.eval(s), t, 1e-6);
        assert!((d[1] - fd1).length() < 1e-7 * (1.0 + fd1.length()));
        let fd2 = central(|s| arc.eval_deriv(s, 1), t, 1e-6);
        assert!((d[2] - fd2).length() < 1e-6 * (1.0 + fd2.length()));
        let fd3 = central(|s| arc.eval_deriv(s, 2), t, 1e-5);
        assert!((d[3] - fd3).length() < 1e-4 * (1.0 + fd3.length()));
        assert!((arc.curvature(t).unwrap() - 1.0 / r).abs() < 1e-13, "κ = 1/R");
    }
}

/// The coefficients (A, B, C, D, E, F) of the conic Ax² + Bxy + Cy² + Dx + Ey + F = 0 through
/// five points: the generalized cross product of the five rows [x², xy, y², x, y, 1].
fn fit_conic(p: &[DVec2; 5]) -> [f64; 6] {
    let rows: Vec<[f64; 6]> =
        p.iter().map(|q| [q.x * q.x, q.x * q.y, q.y * q.y, q.x, q.y, 1.0]).collect();
    let mut res = [0.0; 6];
    for (col, slot) in res.iter_mut().enumerate() {
        let minor: Vec<Vec<f64>> =
            rows.iter().map(|r| (0..6).filter(|&c| c != col).map(|c| r[c]).collect()).collect();
        let sign = if col % 2 == 0 { 1.0 } else { -1.0 };
        *slot = sign * det(minor);
    }
    res
}

/// Determinant by Gaussian elimination with partial pivoting.
fn det(mut m: Vec<Vec<f64>>) -> f64 {
    let n = m.len();
    let mut d = 1.0;
    for i in 0..n {
        let piv = (i..n).max_by(|&a, &b| m[a][i].abs().total_cmp(&m[b][i].abs())).unwrap();
        if m[piv][i] == 0.0 {
            return 0.0;
        }
        if piv != i {
            m.swap(piv, i);
            d = -d;
        }
        d *= m[i][i];
        let pivot_row = m[i].clone();
        for row in m.iter_mut().skip(i + 1) {
            let f = row[i] / pivot_row[i];
            for (x, p) in row.iter_mut().zip(&pivot_row).skip(i) {
                *x -= f * p;
            }
        }
    }
    d
}

#[test]
fn conic_type_by_weight_matches_the_implicit_discriminant() {
    let (p0, p1, p2) = (DVec2::new(-1.0, 0.0), DVec2::new(0.3, 2.0), DVec2::new(1.5, 0.2));
    for &w in &[0.2, 0.7, 0.999, 1.0, 1.001, 1.5, 4.0] {
        let c = RationalBezierCurve::conic(p0, p1, p2, w).unwrap();
        let pts = [0.05, 0.3, 0.5, 0.65, 0.9].map(|t| c.eval(t));
        let [a, b, cc, ..] = fit_conic(&pts);
        // B² − 4AC < 0: ellipse; = 0: parabola; > 0: hyperbola (normalised by the scale).
        let disc = (b * b - 4.0 * a * cc) / (a.abs() + b.abs() + cc.abs()).powi(2);
        let expected = if w < 1.0 {
            ConicType::Ellipse
        } else if w > 1.0 {
            ConicType::Hyperbola
        } else {
            ConicType::Parabola
        };
        assert_eq!(c.conic_type(), Some(expected));
        match expected {
            ConicType::Ellipse => assert!(disc < -1e-6, "w={w}: {disc}"),
            ConicType::Hyperbola => assert!(disc > 1e-6, "w={w}: {disc}"),
            ConicType::Parabola => assert!(disc.abs() < 1e-9, "w={w}: {disc}"),
        }
        // Every other sample lies on the fitted conic.
        let coef = fit_conic(&pts);
        for k in 0..=10 {
            let q = c.eval(k as f64 / 10.0);
            let v = coef[0] * q.x * q.x
                + coef[1] * q.x * q.y
                + coef[2] * q.y * q.y
                + coef[3] * q.x
                + coef[4] * q.y
                + coef[5];
            let scale: f64 = coef.iter().map(|x| x.abs()).sum();
            assert!(v.abs() < 1e-10 * scale, "w={w}: not a conic");
        }
    }
    // w = 1 is the polynomial quadratic.
    let par = RationalBezierCurve::conic(p0, p1, p2, 1.0).unwrap();
    let poly = BezierCurve::new(vec![p0, p1, p2]);
    assert!((par.eval(0.37) - poly.eval(0.37)).length() < 1e-15);
}

#[test]
fn conic_type_is_invariant_under_weight_scaling() {
    // Weights (a, a·k·w, a·k²): the reparametrisation family of the same conic.
    let c = RationalBezierCurve::new(
        vec![DVec2::X, DVec2::ONE, DVec2::Y],
        vec![3.0, 3.0 * 2.0 * 0.5, 3.0 * 4.0],
    );
    assert!((c.conic_shape_factor().unwrap() - 0.5).abs() < 1e-15);
    let s = c.to_standard_form();
    assert!((s.weights()[1] - 0.5).abs() < 1e-15);
    assert_eq!(s.conic_type(), Some(ConicType::Ellipse));
}

#[test]
fn split_subsegment_and_elevation_reproduce() {
    let c = figure_2_8();
    let (a, b) = c.split(0.3).unwrap();
    let s = c.subsegment(ParamRange::new(0.2, 0.9)).unwrap();
    let e = c.elevate();
    assert_eq!(e.degree(), 4);
    for k in 0..=20 {
        let t = k as f64 / 20.0;
        assert!((a.eval(t) - c.eval(0.3 * t)).length() < 1e-15);
        assert!((b.eval(t) - c.eval(0.3 + 0.7 * t)).length() < 1e-15);
        assert!((s.eval(t) - c.eval(0.2 + 0.7 * t)).length() < 1e-15);
        assert!((e.eval(t) - c.eval(t)).length() < 1e-15);
        assert!((c.reverse().eval(t) - c.eval(1.0 - t)).length() < 1e-15);
    }
    assert!(a.weights().iter().chain(b.weights()).all(|&w| w > 0.0));
}

#[test]
fn flattened_circle_has_sagitta_within_tolerance() {
    // A chord of length L in a circle of radius R lies at most R − √(R² − L²/4) from the arc.
    let r = 2.0;
    for tol in [1e-1, 1e-3, 1e-6] {
        let mut n_segments = 0;
        for arc in RationalBezierCurve::circle(DVec2::ZERO, r, 4).unwrap() {
            let poly = arc.flatten(tol).unwrap();
            n_segments += poly.len() - 1;
            for w in poly.windows(2) {
                assert!((w[0].length() - r).abs() < 1e-14, "vertices on the circle");
                let half = 0.5 * (w[1] - w[0]).length();
                let sagitta = r - (r * r - half * half).sqrt();
                assert!(sagitta <= tol * (1.0 + 1e-9), "{sagitta} > {tol}");
            }
        }
        // Optimal count is π/acos(1 − tol/R); halving at most doubles it (and a bit more).
        let optimal = PI / (1.0 - tol / r).acos();
        assert!((n_segments as f64) < 4.0 * optimal + 8.0, "tol={tol}: {n_segments} vs {optimal}");
    }
}

#[test]
fn validation() {
    assert_eq!(
        RationalBezierCurve::try_new(vec![DVec2::ZERO, DVec2::X], vec![1.0, f64::INFINITY]),
        Err(Error::InvalidWeight { index: 1, value: f64::INFINITY })
    );
    assert!(matches!(
        RationalBezierCurve::circle_arc(DVec2::ZERO, 1.0, 0.0, -PI),
        Err(Error::InvalidArgument { name: "sweep", .. })
    ));
    assert!(RationalBezierCurve::circle_arc(DVec2::ZERO, f64::NAN, 0.0, 1.0).is_err());
    assert!(RationalBezierCurve::circle_arc(DVec2::new(f64::NAN, 0.0), 1.0, 0.0, 1.0).is_err());
}

#[test]
fn tight_box_of_arcs_is_analytic() {
    // The box of an arc holds its end points and every axis direction θ = kπ/2 it passes.
    for &(start, sweep) in &[(0.3, 2.5), (-1.0, -2.0), (2.0, 1.0), (0.0, 3.0)] {
        let (center, r) = (DVec2::new(1.0, -2.0), 1.5);
        let arc = RationalBezierCurve::circle_arc(center, r, start, sweep).unwrap();
        let mut lo = (center + r * DVec2::from_angle(start))
            .min(center + r * DVec2::from_angle(start + sweep));
        let mut hi = (center + r * DVec2::from_angle(start))
            .max(center + r * DVec2::from_angle(start + sweep));
        let (a, b) = if sweep > 0.0 { (start, start + sweep) } else { (start + sweep, start) };
        for k in -8..8 {
            let theta = k as f64 * FRAC_PI_2;
            if a < theta && theta < b {
                let p = center + r * DVec2::from_angle(theta);
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
        let bb = arc.bounding_box();
        assert!(
            (bb.min - lo).length() < 1e-14 && (bb.max - hi).length() < 1e-14,
            "{bb:?} vs [{lo}, {hi}]"
        );
        assert!(arc.control_bounding_box().contains_box(&bb, 1e-15));
    }
    // Figure 2.8: the right half of the unit circle has the box [0, 1] × [−1, 1].
    let b = figure_2_8().bounding_box();
    assert!((b.min - DVec2::new(0.0, -1.0)).length() < 1e-15);
    assert!((b.max - DVec2::new(1.0, 1.0)).length() < 1e-15);
}
