// SPDX-License-Identifier: MIT
//! Analytic truths of the cubic Hermite family (Hardy 2005, §2.6–2.8): Catmull-Rom passes
//! through its points with tangent (x_{i+1} − x_{i−1})/2 per unit segment, TCB with
//! T = C = B = 0 is Catmull-Rom, Bessel-Overhauser tangents are those of the parabola through
//! three points, and the Bézier chains reproduce the curves.

use glam::{DVec2, DVec3};
use hi_compare::cardinal::{Closure, HermiteSpline, Tcb, chord_length_parameters};
use hi_curve::ParamCurve;
use hi_testkit::proptest_config;
use proptest::prelude::*;

fn points_3d(min: usize, max: usize) -> impl Strategy<Value = Vec<DVec3>> {
    prop::collection::vec(
        (-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y, z)| DVec3::new(x, y, z)),
        min..max,
    )
}

fn closure() -> impl Strategy<Value = Closure> {
    prop_oneof![Just(Closure::Open), Just(Closure::Closed)]
}

fn tcb() -> impl Strategy<Value = Tcb> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64).prop_map(|(t, c, b)| Tcb::new(t, c, b))
}

fn close(a: DVec3, b: DVec3, scale: f64) -> bool {
    (a - b).length() <= 1e-12 * (1.0 + scale)
}

#[test]
fn bessel_tangent_is_the_parabola_slope() {
    // Points on the parabola y = x² at unequal x: with parameters x, the Bessel tangent at the
    // middle point is the parabola's own derivative (1, 2x).
    let xs = [0.0, 0.3, 1.0, 1.2, 2.0];
    let pts: Vec<DVec2> = xs.iter().map(|&x| DVec2::new(x, x * x)).collect();
    let curve =
        HermiteSpline::bessel_overhauser_with_params(pts, xs.to_vec(), Closure::Open).unwrap();
    // t = x/2, so dX/dt = 2·(1, 2x).
    for (i, &x) in xs.iter().enumerate().skip(1).take(3) {
        let d = curve.leaving_tangents()[i];
        assert!((d - DVec2::new(2.0, 4.0 * x)).length() < 1e-13, "x = {x}: {d}");
        assert_eq!(curve.arriving_tangents()[i], d);
    }
}

#[test]
fn bessel_on_uniform_parameters_is_catmull_rom() {
    let pts = vec![DVec2::ZERO, DVec2::new(2.0, 1.0), DVec2::new(3.0, -1.0), DVec2::new(5.0, 0.0)];
    for closure in [Closure::Open, Closure::Closed] {
        let n_seg = if closure == Closure::Open { 3.0 } else { 4.0 };
        let params = (0..4).map(|i| i as f64 / n_seg).collect();
        let bo =
            HermiteSpline::bessel_overhauser_with_params(pts.clone(), params, closure).unwrap();
        let cr = HermiteSpline::catmull_rom(pts.clone(), closure).unwrap();
        for i in 0..=40 {
            let t = i as f64 / 40.0;
            assert!((bo.eval(t) - cr.eval(t)).length() < 1e-14, "{closure:?} t = {t}");
        }
    }
}

#[test]
fn tcb_controls_act_as_documented() {
    let pts = vec![DVec2::ZERO, DVec2::new(1.0, 1.0), DVec2::new(3.0, 1.0), DVec2::new(4.0, 3.0)];
    // Tension 1: the curve stops at every point.
    let tight =
        HermiteSpline::kochanek_bartels(pts.clone(), Closure::Open, Tcb::new(1.0, 0.0, 0.0))
            .unwrap();
    assert!(tight.eval_deriv(1.0 / 3.0, 1).length() < 1e-15);
    // Continuity ≠ 0: a corner, the arriving and leaving tangents differ.
    let corner =
        HermiteSpline::kochanek_bartels(pts.clone(), Closure::Open, Tcb::new(0.0, -1.0, 0.0))
            .unwrap();
    assert!((corner.arriving_tangents()[1] - DVec2::new(3.0, 3.0)).length() < 1e-14); // v₋½
    assert!((corner.leaving_tangents()[1] - DVec2::new(6.0, 0.0)).length() < 1e-14); // v₊½
    // Bias 1: the tangent of the previous chord only, Bias −1: the next.
    let back = HermiteSpline::kochanek_bartels(pts.clone(), Closure::Open, Tcb::new(0.0, 0.0, 1.0))
        .unwrap();
    assert!((back.leaving_tangents()[1] - (pts[1] - pts[0]) * 3.0).length() < 1e-14);
    // Per-point keys: a key only changes the tangents at its own point.
    let keys = [Tcb::CATMULL_ROM, Tcb::new(0.5, 0.2, -0.3), Tcb::CATMULL_ROM, Tcb::CATMULL_ROM];
    let mixed =
        HermiteSpline::kochanek_bartels_per_point(pts.clone(), Closure::Open, &keys).unwrap();
    let cr = HermiteSpline::catmull_rom(pts, Closure::Open).unwrap();
    for i in [0, 2, 3] {
        assert_eq!(mixed.leaving_tangents()[i], cr.leaving_tangents()[i]);
    }
    assert_ne!(mixed.leaving_tangents()[1], cr.leaving_tangents()[1]);
}

#[test]
fn chord_length_parameters_open_and_closed() {
    let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
    assert_eq!(
        chord_length_parameters(&square, Closure::Open).unwrap(),
        vec![0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
    );
    assert_eq!(
        chord_length_parameters(&square, Closure::Closed).unwrap(),
        vec![0.0, 0.25, 0.5, 0.75]
    );
    // Closed Bessel-Overhauser of a square on chord-length = uniform = Catmull-Rom.
    let bo = HermiteSpline::bessel_overhauser(square.to_vec(), Closure::Closed).unwrap();
    let cr = HermiteSpline::catmull_rom(square.to_vec(), Closure::Closed).unwrap();
    assert!((bo.eval(0.3) - cr.eval(0.3)).length() < 1e-15);
}

proptest! {
    #![proptest_config(proptest_config(128))]

    /// Catmull-Rom (§2.6) passes through xᵢ at t = i/s with tangent (x_{i+1} − x_{i−1})/2 per
    /// unit segment; the ends of an open one have the end secant (reflected phantom point).
    #[test]
    fn catmull_rom_interpolates_with_central_tangents(
        pts in points_3d(3, 20), closure in closure(),
    ) {
        let n = pts.len();
        let curve = HermiteSpline::catmull_rom(pts.clone(), closure).unwrap();
        let s = if closure == Closure::Open { n - 1 } else { n };
        let scale = curve.scale();
        for i in 0..n {
            let t = i as f64 / s as f64;
            prop_assert!(close(curve.eval(t), pts[i], scale));
            let (prev, next) = match closure {
                Closure::Closed => (pts[(i + n - 1) % n], pts[(i + 1) % n]),
                Closure::Open if i == 0 => (pts[0] * 2.0 - pts[1], pts[1]),
                Closure::Open if i == n - 1 => (pts[n - 2], pts[n - 1] * 2.0 - pts[n - 2]),
                Closure::Open => (pts[i - 1], pts[i + 1]),
            };
            let per_segment = curve.eval_deriv(t, 1) / s as f64;
            prop_assert!(close(per_segment, (next - prev) / 2.0, scale), "i = {}", i);
        }
        if closure == Closure::Closed {
            prop_assert!(close(curve.eval(0.37), curve.eval(1.37), scale));
            // C¹ at the seam.
            let jump = curve.eval_deriv(1.0 - 1e-15, 1) - curve.eval_deriv(0.0, 1);
            prop_assert!(jump.length() < 1e-9 * (1.0 + scale * s as f64));
        }
    }

    /// TCB with T = C = B = 0 is Catmull-Rom (§2.8).
    #[test]
    fn tcb_zero_is_catmull_rom(pts in points_3d(2, 20), closure in closure(), t in -0.2..1.2f64) {
        prop_assume!(closure == Closure::Open || pts.len() >= 3);
        let cr = HermiteSpline::catmull_rom(pts.clone(), closure).unwrap();
        let tcb = HermiteSpline::kochanek_bartels(pts, closure, Tcb::new(0.0, 0.0, 0.0)).unwrap();
        for order in 0..=3 {
            let (a, b) = (cr.eval_deriv(t, order), tcb.eval_deriv(t, order));
            prop_assert!(close(a, b, cr.scale() * 1e3));
        }
    }

    /// Every member of the family interpolates, and its Bézier chain is the same curve.
    #[test]
    fn hermite_splines_interpolate_and_convert(
        pts in points_3d(3, 16), closure in closure(), key in tcb(), kind in 0usize..3,
        v in 0.0..=1.0f64,
    ) {
        let curve = match kind {
            0 => HermiteSpline::catmull_rom(pts.clone(), closure),
            1 => HermiteSpline::bessel_overhauser(pts.clone(), closure),
            _ => HermiteSpline::kochanek_bartels(pts.clone(), closure, key),
        }
        .unwrap();
        let scale = curve.scale();
        let breaks = curve.breakpoints();
        for (i, p) in pts.iter().enumerate() {
            prop_assert!(close(curve.eval(breaks[i]), *p, scale));
        }
        let chain = curve.to_bezier();
        prop_assert_eq!(chain.segments().len() + 1, breaks.len());
        for (i, seg) in chain.segments().iter().enumerate() {
            let t = breaks[i] + v * (breaks[i + 1] - breaks[i]);
            prop_assert!(close(seg.eval(v), curve.eval(t), scale));
        }
        if kind != 1 {
            // Uniform parameters: the chain has the curve's own parameter.
            prop_assert!(close(chain.eval(v), curve.eval(v), scale));
        }
        // Derivatives above the degree vanish inside a piece.
        prop_assert_eq!(curve.eval_deriv(0.5 * (breaks[0] + breaks[1]), 4), DVec3::ZERO);
    }
}
