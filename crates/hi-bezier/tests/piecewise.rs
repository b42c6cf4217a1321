// SPDX-License-Identifier: MIT
//! Piecewise Bézier curves (§2.5, eq. 2.5, figure 2.5): C1 and G1 chains checked by one-sided
//! difference quotients across the joins, Hermite interpolation, and chain flattening.

mod common;

use common::dist_to_polyline;
use glam::DVec2;
use hi_bezier::{BezierCurve, PiecewiseBezier};

/// A stand-in for figure 2.5 (the thesis's coordinates are not recoverable): a first cubic and
/// two tails (R₂, R₃).
fn figure_2_5_data() -> (BezierCurve<DVec2>, Vec<Vec<DVec2>>) {
    let first = BezierCurve::new(vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(0.5, 1.5),
        DVec2::new(2.0, 2.0),
        DVec2::new(3.0, 1.0),
    ]);
    let tails = vec![
        vec![DVec2::new(4.5, -1.5), DVec2::new(6.0, 0.0)],
        vec![DVec2::new(8.0, 2.0), DVec2::new(9.0, 0.5)],
    ];
    (first, tails)
}

/// One-sided derivatives of Q(u) in the global parameter at the join u, by difference quotients
/// of the chain's own evaluation.
fn one_sided(chain: &PiecewiseBezier<DVec2>, u: f64) -> (DVec2, DVec2) {
    let h = 1e-7;
    let left = (chain.eval(u) - chain.eval(u - h)) / h;
    let right = (chain.eval(u + h) - chain.eval(u)) / h;
    (left, right)
}

#[test]
fn figure_2_5a_c1_chain() {
    let (first, tails) = figure_2_5_data();
    let chain = PiecewiseBezier::c1_chain(first, &tails).unwrap();
    assert_eq!(chain.segments().len(), 3);
    assert!(chain.is_c1(1e-14), "{:?}", chain.joins());
    for (k, join) in chain.joins().iter().enumerate() {
        assert_eq!(join.index, k);
        assert!(join.angle.unwrap() < 1e-7);
        assert!((join.speed_ratio.unwrap() - 1.0).abs() < 1e-14);
        // Eq. 2.5: Qₙ − Qₙ₋₁ = R₁ − R₀.
        let q = chain.segments()[k].control_points();
        let r = chain.segments()[k + 1].control_points();
        assert!(((q[3] - q[2]) - (r[1] - r[0])).length() < 1e-15);
        // The global derivative is continuous: compare one-sided difference quotients.
        let (left, right) = one_sided(&chain, (k + 1) as f64 / 3.0);
        assert!((left - right).length() < 1e-5 * left.length(), "join {k}: {left} vs {right}");
    }
}

#[test]
fn figure_2_5b_g1_chain_with_s_0_6() {
    let (first, tails) = figure_2_5_data();
    let s = 0.6;
    let chain = PiecewiseBezier::g1_chain(first, &tails, s).unwrap();
    assert!(chain.is_c0(1e-15));
    assert!(chain.is_g1(1e-15, 1e-12), "{:?}", chain.joins());
    assert!(!chain.is_c1(1e-3), "G1 with s ≠ 1 is not C1");
    for (k, join) in chain.joins().iter().enumerate() {
        // §2.5: Qₙ − Qₙ₋₁ = s(R₁ − R₀).
        let q = chain.segments()[k].control_points();
        let r = chain.segments()[k + 1].control_points();
        assert!(((q[3] - q[2]) - s * (r[1] - r[0])).length() < 1e-14);
        assert!((join.speed_ratio.unwrap() - s).abs() < 1e-14);
        // Same direction, speeds in ratio s: measured by difference quotients.
        let (left, right) = one_sided(&chain, (k + 1) as f64 / 3.0);
        assert!(left.normalize().perp_dot(right.normalize()).abs() < 1e-5);
        assert!((left.length() / right.length() - s).abs() < 1e-5);
        assert!(join.tangent_mismatch > 0.1);
    }
}

#[test]
fn hermite_chain_interpolates_points_and_tangents() {
    let pts: Vec<DVec2> = (0..6).map(|k| DVec2::new(k as f64, (k as f64).sin())).collect();
    let tangents: Vec<DVec2> = (0..6).map(|k| DVec2::new(1.0, (k as f64).cos())).collect();
    let chain = PiecewiseBezier::c1_hermite(&pts, &tangents).unwrap();
    let s = 5.0;
    for k in 0..6 {
        let u = k as f64 / s;
        assert!((chain.eval(u) - pts[k]).length() < 1e-15);
        // dQ/du = s·dq/dt, and dq/dt = Tₖ.
        assert!((chain.eval_deriv(u, 1) / s - tangents[k]).length() < 1e-13, "k={k}");
    }
    assert!(chain.is_c1(1e-14));
}

#[test]
fn closed_chain_closing_join() {
    // Hermite through the four vertices of a square with tangents of a circle, closed up.
    let pts = [DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y, DVec2::X];
    let tangents = [DVec2::Y, -DVec2::X, -DVec2::Y, DVec2::X, DVec2::Y].map(|t| t * 1.6);
    let chain = PiecewiseBezier::c1_hermite(&pts, &tangents).unwrap();
    let closing = chain.closing_join();
    assert_eq!(closing.index, 3);
    assert!(closing.gap < 1e-15 && closing.tangent_mismatch < 1e-15);
}

#[test]
fn chain_flatten_and_box() {
    let (first, tails) = figure_2_5_data();
    let chain = PiecewiseBezier::g1_chain(first, &tails, 0.6).unwrap();
    let tol = 1e-3;
    let poly = chain.flatten(tol).unwrap();
    let worst = (0..=30_000)
        .map(|k| dist_to_polyline(chain.eval(k as f64 / 30_000.0), &poly))
        .fold(0.0, f64::max);
    assert!(worst <= tol);
    let b = chain.bounding_box();
    for k in 0..=3000 {
        let p = chain.eval(k as f64 / 3000.0);
        assert!(b.contains_box(&hi_bezier::Aabb::from_point(p), 1e-12));
    }
    // A gap is bridged by a polyline edge.
    let gap = PiecewiseBezier::new(vec![
        BezierCurve::new(vec![DVec2::ZERO, DVec2::X]),
        BezierCurve::new(vec![DVec2::Y, DVec2::ONE]),
    ]);
    assert!(!gap.is_c0(0.5));
    assert_eq!(gap.flatten(0.1).unwrap(), vec![DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ONE]);
}
