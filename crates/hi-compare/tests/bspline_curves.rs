// SPDX-License-Identifier: MIT
//! Analytic truths of the B-spline family (Hardy 2005, §2.9–2.12): the basis is a partition of
//! unity with local support and the uniform cubic values 1/6, 2/3, 1/6; a clamped B-spline of
//! degree p with p + 1 control points is their Bézier curve; the NURBS circle has radius 1
//! exactly; interpolating splines pass through their points, periodic ones are C² at the seam;
//! and every `to_bezier` reproduces its curve.

use glam::{DVec2, DVec3};
use hi_bezier::BezierCurve;
use hi_compare::ParamRange;
use hi_compare::bspline::{BSplineBasis, BSplineCurve};
use hi_compare::bspline_interp::{EndCondition, InterpolatingSpline, Parameters};
use hi_compare::nurbs::NurbsCurve;
use hi_curve::ParamCurve;
use hi_testkit::proptest_config;
use proptest::prelude::*;

fn points_2d(min: usize, max: usize) -> impl Strategy<Value = Vec<DVec2>> {
    prop::collection::vec(
        (-10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y)| DVec2::new(x, y)),
        min..max,
    )
}

/// A clamped knot vector of degree p for m control points with random interior knots (some
/// repeated up to p times) in [0, 1].
fn clamped_knots(p: usize, m: usize, raw: &[f64]) -> Vec<f64> {
    let mut interior: Vec<f64> =
        raw.iter().take(m - p - 1).map(|u| (u * 8.0).round() / 8.0).collect();
    interior.sort_by(f64::total_cmp);
    // Cap multiplicities at p.
    let mut capped: Vec<f64> = Vec::new();
    for u in interior {
        let run = capped.iter().rev().take_while(|&&v| v == u).count();
        if run < p && u > 0.0 && u < 1.0 {
            capped.push(u);
        }
    }
    while capped.len() < m - p - 1 {
        // Fill up with distinct knots between the last one and 1.
        let last = capped.last().copied().unwrap_or(0.0);
        capped.push(last + (1.0 - last) / 2.0);
    }
    let mut knots = vec![0.0; p + 1];
    knots.extend(capped);
    knots.extend(std::iter::repeat_n(1.0, p + 1));
    knots
}

#[test]
fn uniform_cubic_known_values() {
    // §2.9: at a knot the non-zero uniform cubic functions are 1/6, 2/3, 1/6.
    let basis = BSplineBasis::uniform(3, 10);
    for knot in 3..=10 {
        let u = knot as f64;
        let values = basis.eval_all(u);
        let nonzero: Vec<f64> = values.iter().copied().filter(|v| *v != 0.0).collect();
        assert_eq!(nonzero.len(), 3, "u = {u}: {values:?}");
        for (got, expected) in nonzero.iter().zip([1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0]) {
            assert!((got - expected).abs() < 1e-15, "u = {u}: {got}");
        }
    }
    // Mid-interval: B(½) = 1/48, 23/48, 23/48, 1/48.
    let mid: Vec<f64> = basis.eval_all(5.5).into_iter().filter(|v| *v != 0.0).collect();
    for (got, expected) in mid.iter().zip([1.0, 23.0, 23.0, 1.0].map(|v| v / 48.0)) {
        assert!((got - expected).abs() < 1e-15, "{got}");
    }
    // The closed uniform cubic: x₀ weighs 2/3 at t = 0, its neighbours 1/6.
    let curve = BSplineCurve::try_uniform_closed(3, vec![0.0; 7]).unwrap();
    let w = curve.basis_values(0.0);
    assert!((w[0] - 2.0 / 3.0).abs() < 1e-15 && (w[1] - 1.0 / 6.0).abs() < 1e-15);
    assert!((w[6] - 1.0 / 6.0).abs() < 1e-15 && w[2..6].iter().all(|v| *v == 0.0));
}

#[test]
fn clamped_with_p_plus_one_points_is_bezier() {
    for p in 1..=9 {
        let control: Vec<DVec3> = (0..=p)
            .map(|i| DVec3::new(i as f64, ((i * 7) % 5) as f64 - 2.0, ((i * 3) % 4) as f64))
            .collect();
        let bspline = BSplineCurve::try_clamped(p, control.clone()).unwrap();
        let bezier = BezierCurve::new(control);
        for i in 0..=50 {
            let t = i as f64 / 50.0;
            let err = (bspline.eval(t) - bezier.eval(t)).length();
            assert!(err < 1e-13, "p = {p}, t = {t}: {err:e}");
        }
        assert_eq!(bspline.to_bezier().segments().len(), 1);
    }
}

#[test]
fn open_uniform_cubic_spans_p_to_m() {
    // §2.9: m control points, knots 0..m+3, the curve runs over u ∈ [3, m] in m − 3 pieces and
    // starts at (x₀ + 4x₁ + x₂)/6.
    let control: Vec<f64> = vec![0.0, 6.0, 12.0, 0.0, 6.0, 3.0];
    let curve = BSplineCurve::try_uniform_open(3, control).unwrap();
    assert_eq!(curve.domain(), ParamRange::new(3.0, 6.0));
    assert!((curve.eval(0.0) - (0.0 + 24.0 + 12.0) / 6.0).abs() < 1e-14);
    assert_eq!(curve.to_bezier().segments().len(), 3);
}

#[test]
fn knot_of_multiplicity_p_interpolates_a_control_point() {
    // Knot ½ with multiplicity 3 in a cubic: the curve passes through x₃ there (C⁰ joint).
    let control = vec![0.0, 1.0, 3.0, 7.0, 2.0, 5.0, 4.0];
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0];
    let curve = BSplineCurve::try_new(3, knots, control).unwrap();
    assert!((curve.eval(0.5) - 7.0).abs() < 1e-14);
    assert_eq!(curve.breakpoints(), vec![0.0, 0.5, 1.0]);
}

#[test]
fn nurbs_circle_is_exact() {
    let center = DVec2::new(0.5, -2.0);
    let circle = NurbsCurve::circle(center, 1.0);
    for i in 0..=400 {
        let t = i as f64 / 400.0;
        let p = circle.eval(t);
        assert!(((p - center).length() - 1.0).abs() < 2e-16 * 4.0, "t = {t}");
        // Curvature 1 from the quotient-rule derivatives.
        let k = circle.curvature(t).unwrap();
        assert!((k - 1.0).abs() < 1e-13, "t = {t}: κ = {k}");
    }
    // The quadrant points at the knots.
    for (t, q) in [(0.0, DVec2::X), (0.25, DVec2::Y), (0.5, -DVec2::X), (0.75, -DVec2::Y)] {
        assert!((circle.eval(t) - center - q).length() < 1e-15, "t = {t}");
    }
    // Four exact rational quadratic segments: each a quarter of the circle.
    let segments = circle.to_rational_bezier();
    assert_eq!(segments.len(), 4);
    let breaks = circle.breakpoints();
    for (i, seg) in segments.iter().enumerate() {
        for j in 0..=20 {
            let v = j as f64 / 20.0;
            let t = breaks[i] + v * (breaks[i + 1] - breaks[i]);
            assert!((seg.eval(v) - circle.eval(t)).length() < 1e-15, "segment {i}, v = {v}");
        }
    }
    let (num, den) = circle.to_homogeneous_bezier();
    let t = 0.6;
    let (i, v) = num.locate(t);
    assert_eq!(i, 2);
    assert!(
        (num.segments()[i].eval(v) / den.segments()[i].eval(v) - circle.eval(t)).length() < 1e-15
    );
}

#[test]
fn nurbs_with_unit_weights_is_the_bspline() {
    let control: Vec<DVec2> = (0..6).map(|i| DVec2::new(i as f64, (i % 3) as f64)).collect();
    let knots = vec![0.0, 0.0, 0.0, 0.3, 0.4, 0.8, 1.0, 1.0, 1.0];
    let nurbs = NurbsCurve::try_new(2, knots.clone(), control.clone(), vec![1.0; 6]).unwrap();
    let bspline = BSplineCurve::try_new(2, knots, control).unwrap();
    for i in 0..=40 {
        let t = i as f64 / 40.0;
        for order in 0..=3 {
            let err = (nurbs.eval_deriv(t, order) - bspline.eval_deriv(t, order)).length();
            assert!(err < 1e-10 * (1.0 + bspline.eval_deriv(t, order).length()), "{t} {order}");
        }
    }
    // A closed NURBS is periodic.
    let closed = NurbsCurve::try_new_periodic(
        2,
        vec![0.0, 0.25, 0.5, 0.75, 1.0],
        vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y],
        vec![1.0, 2.0, 1.0, 2.0],
    )
    .unwrap();
    assert!(closed.is_periodic());
    assert!((closed.eval(0.1) - closed.eval(1.1)).length() < 1e-15);
    let sum: f64 = closed.basis_values(0.37).iter().sum();
    assert!((sum - 1.0).abs() < 1e-15);
}

#[test]
fn open_end_conditions_hold() {
    let pts = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 2.0),
        DVec2::new(3.0, 2.5),
        DVec2::new(4.0, 0.0),
        DVec2::new(6.0, 1.0),
        DVec2::new(7.0, 3.0),
    ];
    for params in [Parameters::Uniform, Parameters::ChordLength] {
        let natural =
            InterpolatingSpline::try_open(pts.clone(), params.clone(), EndCondition::Natural)
                .unwrap();
        assert!(natural.eval_deriv(0.0, 2).length() < 1e-11);
        assert!(natural.eval_deriv(1.0, 2).length() < 1e-11);
        let thesis =
            InterpolatingSpline::try_open(pts.clone(), params.clone(), EndCondition::Coincident)
                .unwrap();
        assert!(thesis.eval_deriv(0.0, 1).length() < 1e-12);
        assert!(thesis.eval_deriv(1.0, 1).length() < 1e-12);
        let c = thesis.spline().control_points();
        assert!((c[0] - c[1]).length() < 1e-14 && (c[6] - c[7]).length() < 1e-14, "eq. 2.9");
        let nak =
            InterpolatingSpline::try_open(pts.clone(), params.clone(), EndCondition::NotAKnot)
                .unwrap();
        for t in [nak.params()[1], nak.params()[4]] {
            let jump = (nak.eval_deriv(t + 1e-12, 3) - nak.eval_deriv(t - 1e-12, 3)).length();
            assert!(jump < 1e-8 * nak.eval_deriv(t, 3).length().max(1.0), "t = {t}: {jump:e}");
        }
    }
}

#[test]
fn not_a_knot_reproduces_cubics_and_natural_lines() {
    let f = |t: f64| DVec2::new(t, 2.0 * t * t * t - t * t + 0.5);
    let ts = [0.0, 0.1, 0.35, 0.5, 0.8, 1.0];
    let pts: Vec<DVec2> = ts.iter().map(|&t| f(t)).collect();
    let nak =
        InterpolatingSpline::try_open(pts, Parameters::Given(ts.to_vec()), EndCondition::NotAKnot)
            .unwrap();
    for i in 0..=30 {
        let t = i as f64 / 30.0;
        assert!((nak.eval(t) - f(t)).length() < 1e-14, "t = {t}");
    }
    let line: Vec<DVec2> = (0..5).map(|i| DVec2::new(i as f64, 2.0 * i as f64 - 1.0)).collect();
    let natural =
        InterpolatingSpline::try_open(line, Parameters::Uniform, EndCondition::Natural).unwrap();
    assert!((natural.eval(0.3) - DVec2::new(1.2, 1.4)).length() < 1e-14);
}

proptest! {
    #![proptest_config(proptest_config(128))]

    /// Partition of unity, non-negativity and local support (§2.9–2.10) on random clamped
    /// knot vectors with repeated knots, of every degree up to 5.
    #[test]
    fn basis_partition_of_unity_and_local_support(
        p in 1usize..=5, extra in 0usize..6, raw in prop::collection::vec(0.0..1.0f64, 12),
        u in 0.0..=1.0f64,
    ) {
        let m = p + 1 + extra;
        let knots = clamped_knots(p, m, &raw);
        let basis = BSplineBasis::try_new(p, knots.clone()).unwrap();
        let values = basis.eval_all(u);
        let sum: f64 = values.iter().sum();
        prop_assert!((sum - 1.0).abs() < 1e-14, "sum {sum}");
        for (i, v) in values.iter().enumerate() {
            prop_assert!(*v >= 0.0);
            if u < knots[i] || u > knots[i + p + 1] {
                prop_assert!(*v == 0.0, "N{i} = {v} outside its support at u = {u}");
            }
        }
        prop_assert!(values.iter().filter(|v| **v != 0.0).count() <= p + 1);
        // The curve's weights are the same functions.
        let curve = BSplineCurve::try_new(p, knots, vec![0.0; m]).unwrap();
        for (a, b) in curve.basis_values(u).iter().zip(&values) {
            prop_assert!((a - b).abs() < 1e-14);
        }
    }

    /// The Bézier chain of any B-spline is the same curve (breakpoint map), open or closed.
    #[test]
    fn bspline_to_bezier_reproduces(
        p in 1usize..=5, pts in points_2d(6, 14), raw in prop::collection::vec(0.0..1.0f64, 12),
        v in 0.0..=1.0f64, closed in any::<bool>(),
    ) {
        let m = pts.len();
        let curve = if closed {
            let mut breaks: Vec<f64> = raw.iter().take(m - 1).copied().collect();
            breaks.sort_by(f64::total_cmp);
            breaks.dedup();
            prop_assume!(breaks.len() == m - 1 && breaks.windows(2).all(|w| w[1] - w[0] > 1e-3));
            let mut all = vec![0.0];
            all.extend(breaks.iter().map(|b| 0.001 + 0.998 * b));
            all.push(1.0);
            BSplineCurve::try_new_periodic(p, all, pts).unwrap()
        } else {
            BSplineCurve::try_new(p, clamped_knots(p, m, &raw), pts).unwrap()
        };
        let chain = curve.to_bezier();
        let breaks = curve.breakpoints();
        prop_assert_eq!(chain.segments().len() + 1, breaks.len());
        for (i, seg) in chain.segments().iter().enumerate() {
            let t = breaks[i] + v * (breaks[i + 1] - breaks[i]);
            let err = (seg.eval(v) - curve.eval(t)).length();
            let size = 1.0 + curve.eval(t).length();
            prop_assert!(err < 1e-12 * size, "segment {} err {:e}", i, err);
        }
    }

    /// Closed B-splines of degree p are 1-periodic and C^{p−1} at the seam.
    #[test]
    fn closed_bspline_is_smooth_at_the_seam(p in 1usize..=5, pts in points_2d(3, 12)) {
        let curve = BSplineCurve::try_uniform_closed(p, pts).unwrap();
        for order in 0..p {
            let a = curve.eval_deriv(1.0 - 1e-13, order);
            let b = curve.eval_deriv(0.0, order);
            let size = b.length().max(curve.eval_deriv(0.5, order).length()).max(1.0);
            prop_assert!((a - b).length() < 1e-6 * size, "order {}: {:?} vs {:?}", order, a, b);
        }
        prop_assert!((curve.eval(0.3) - curve.eval(-0.7)).length() < 1e-12);
    }

    /// Interpolating splines pass through their points (§2.11), and `to_bezier` reproduces.
    #[test]
    fn interpolation_passes_through_points(
        pts in points_2d(4, 30), chord in any::<bool>(), end in 0usize..4, v in 0.0..=1.0f64,
    ) {
        let params = if chord { Parameters::ChordLength } else { Parameters::Uniform };
        let curve = match end {
            0 => InterpolatingSpline::try_periodic(pts.clone(), params),
            1 => InterpolatingSpline::try_open(pts.clone(), params, EndCondition::Coincident),
            2 => InterpolatingSpline::try_open(pts.clone(), params, EndCondition::Natural),
            _ => InterpolatingSpline::try_open(pts.clone(), params, EndCondition::NotAKnot),
        };
        // Random points may repeat only with probability zero.
        let curve = curve.unwrap();
        let scale = curve.scale().max(1.0);
        for (p, &t) in pts.iter().zip(curve.params()) {
            prop_assert!((curve.eval(t) - *p).length() < 1e-12 * scale, "t = {}", t);
        }
        if end == 0 {
            // C² at the seam and 1-periodic.
            for order in 0..=2 {
                let a = curve.eval_deriv(1.0 - 1e-14, order);
                let b = curve.eval_deriv(0.0, order);
                let size = curve.eval_deriv(0.0, order).length().max(1.0);
                prop_assert!((a - b).length() < 1e-8 * size, "order {}", order);
            }
        } else {
            prop_assert!((curve.eval(1.0) - pts[pts.len() - 1]).length() < 1e-12 * scale);
        }
        let chain = curve.to_bezier();
        let breaks = curve.breakpoints();
        for (i, seg) in chain.segments().iter().enumerate() {
            let t = breaks[i] + v * (breaks[i + 1] - breaks[i]);
            prop_assert!((seg.eval(v) - curve.eval(t)).length() < 1e-12 * scale);
        }
        if !chord {
            // Uniform parameters: the chain has the curve's own parameter.
            prop_assert!((chain.eval(v) - curve.eval(v)).length() < 1e-12 * scale);
        }
    }

    /// The NURBS circle has radius exactly 1 (to rounding) at every parameter.
    #[test]
    fn nurbs_circle_radius(t in -0.5..1.5f64, cx in -5.0..5.0f64, cy in -5.0..5.0f64) {
        let c = DVec2::new(cx, cy);
        let circle = NurbsCurve::circle(c, 1.0);
        if (0.0..=1.0).contains(&t) {
            prop_assert!(((circle.eval(t) - c).length() - 1.0).abs() < 1e-14);
        }
        // Derivatives: the velocity is tangent (orthogonal to the radius).
        let d1 = circle.eval_deriv(t.clamp(0.0, 1.0), 1);
        let r = circle.eval(t.clamp(0.0, 1.0)) - c;
        prop_assert!(d1.dot(r).abs() < 1e-12 * d1.length());
    }
}
