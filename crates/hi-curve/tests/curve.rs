// SPDX-License-Identifier: MIT
//! Harmonic curves: differential geometry against independent computations, reduction error,
//! trigonometric interpolation, and input errors.

use std::f64::consts::PI;

use glam::{DVec2, DVec3};
use hi_curve::{Error, HarmonicCurve, ParamCurve, PlaneCurve, SpaceCurve, TrigonometricCurve};

/// A deterministic irregular 3-D point set.
fn knot(n: usize) -> Vec<DVec3> {
    (0..n)
        .map(|k| {
            let a = 2.0 * PI * k as f64 / n as f64;
            DVec3::new(
                (2.0 * a).sin() + 0.3 * (k as f64).cos(),
                a.cos() - 0.2 * (3.0 * a).sin(),
                (5.0 * a).cos() + 0.1 * k as f64,
            )
        })
        .collect()
}

#[test]
fn frenet_frame_satisfies_the_frenet_serret_equations() {
    // dT/ds = κN and dB/ds = −τN, checked by central differences of the frame: a different
    // computation from the closed formulas of κ and τ.
    for n in [7usize, 8] {
        let curve = HarmonicCurve::new(knot(n));
        for t in [0.1, 0.37, 0.62] {
            let h = 1e-6;
            let f = curve.frenet_frame(t).unwrap();
            let (fp, fm) = (curve.frenet_frame(t + h).unwrap(), curve.frenet_frame(t - h).unwrap());
            let ds = curve.eval_deriv(t, 1).length() * 2.0 * h;
            let dt_ds = (fp.tangent - fm.tangent) / ds;
            let db_ds = (fp.binormal.unwrap() - fm.binormal.unwrap()) / ds;
            let tol = 1e-6 * (1.0 + f.curvature + f.torsion.abs());
            assert!((dt_ds - f.curvature * f.normal).length() < tol, "n={n} t={t}: dT/ds");
            assert!((db_ds + f.torsion * f.normal).length() < tol, "n={n} t={t}: dB/ds");
            assert!(
                (f.curvature - curve.curvature(t).unwrap()).abs() < 1e-12 * f.curvature.max(1.0)
            );
        }
    }
}

#[test]
fn planar_curve_in_space_has_zero_torsion() {
    // A regular heptagon in a tilted plane: a circle of radius 2, κ = 1/2, τ = 0.
    let (u, v) = (DVec3::new(1.0, 1.0, 0.0).normalize(), DVec3::new(-1.0, 1.0, 2.0).normalize());
    let pts: Vec<DVec3> = (0..7)
        .map(|k| {
            2.0 * (u * (2.0 * PI * k as f64 / 7.0).cos() + v * (2.0 * PI * k as f64 / 7.0).sin())
        })
        .collect();
    let curve = HarmonicCurve::new(pts);
    for t in [0.0, 0.2, 0.9] {
        let f = curve.frenet_frame(t).unwrap();
        assert!((f.curvature - 0.5).abs() < 1e-12, "{}", f.curvature);
        assert!(f.torsion.abs() < 1e-11, "{}", f.torsion);
        // The principal normal points at the centre.
        assert!((f.normal + curve.eval(t) / 2.0).length() < 1e-12);
    }
}

#[test]
fn arclen_agrees_with_gauss_quadrature() {
    // The FFT trapezoid rule and adaptive Gauss–Legendre on |X′| are different methods.
    for n in [3usize, 4, 9, 16] {
        let curve = HarmonicCurve::new(knot(n));
        let fast = curve.arclen(1e-12);
        let gauss = curve.arclen_range(0.0, 1.0, 1e-12);
        assert!((fast - gauss).abs() < 1e-9, "n={n}: {fast} vs {gauss}");
    }
}

#[test]
fn signed_curvature_changes_sign_with_orientation() {
    let pts = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(3.0, 1.0),
        DVec2::new(4.0, 4.0),
        DVec2::new(1.0, 5.0),
        DVec2::new(-1.0, 2.0),
    ];
    let ccw = HarmonicCurve::new(pts.clone());
    let mut rev = pts;
    rev.reverse();
    let cw = HarmonicCurve::new(rev);
    for t in [0.05, 0.3, 0.77] {
        // The reversed curve is X(−t + c); its curvature at the same point has the opposite sign.
        let k1 = ccw.signed_curvature(t).unwrap();
        let k2 = cw.signed_curvature(0.8 - t).unwrap();
        assert!((k1 + k2).abs() < 1e-12 * k1.abs().max(1.0), "{k1} vs {k2}");
        assert!((ccw.eval(t) - cw.eval(0.8 - t)).length() < 1e-12);
    }
}

#[test]
fn cusp_has_no_curvature() {
    // The astroid (cos³ 2πt, sin³ 2πt) has cusps (X′ = 0) at t = k/4. It is a trigonometric
    // polynomial of degree 3 ≤ ⌊9/2⌋, so the harmonic curve through 9 samples is the astroid.
    let n = 9;
    let pts: Vec<DVec2> = (0..n)
        .map(|k| DVec2::from_angle(2.0 * PI * k as f64 / n as f64))
        .map(|p| DVec2::new(p.x.powi(3), p.y.powi(3)))
        .collect();
    let curve = HarmonicCurve::new(pts);
    assert!(
        (curve.eval(0.1) - DVec2::new((0.2 * PI).cos().powi(3), (0.2 * PI).sin().powi(3))).length()
            < 1e-14
    );
    assert_eq!(curve.curvature(0.0), None);
    assert_eq!(curve.signed_curvature(0.25), None);
    assert!(curve.curvature(0.1).is_some());
}

#[test]
fn reduction_reports_its_error() {
    // Band-limited data: resample(resample(x, 6), 11) reduced back to 6 points loses nothing
    // but the even Nyquist sine, so the error is tiny (docs/math.md §2).
    let base = HarmonicCurve::new(knot(7)).resample(6).unwrap().0;
    let up = base.resample(11).unwrap().0;
    let (down, err) = up.resample(6).unwrap();
    assert!(err.max_deviation < 1e-13, "{err:?}");
    for t in [0.1, 0.5] {
        assert!((down.eval(t) - base.eval(t)).length() < 1e-13);
    }
    // Random data: an O(1) error, checked against a dense direct evaluation of |X − Y|.
    let curve = HarmonicCurve::new(knot(15));
    let (reduced, err) = curve.resample(8).unwrap();
    let dense = (0..20_000)
        .map(|i| {
            let t = i as f64 / 20_000.0;
            (curve.eval(t) - reduced.eval(t)).length()
        })
        .fold(0.0, f64::max);
    assert!(err.max_deviation > 0.1, "{err:?}");
    assert!(dense <= err.upper_bound * (1.0 + 1e-12), "dense {dense} > bound {}", err.upper_bound);
    assert!(
        (dense - err.max_deviation).abs() <= 0.02 * dense,
        "dense {dense} vs grid {}",
        err.max_deviation
    );
    // The reduced curve still passes through its samples of the original.
    for (j, p) in reduced.points().iter().enumerate() {
        assert!((*p - curve.eval(j as f64 / 8.0)).length() < 1e-13);
    }
}

#[test]
fn trigonometric_interpolation_differs_from_harmonic() {
    let square = vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
    let trig = TrigonometricCurve::try_new(square.clone()).unwrap();
    // q(t) = Re Σ cₖ e^{2πikt} with c = DFT/n: for the square, x(t) = Re(c₁e^{2πit} + c₃e^{6πit}),
    // c₁ = (1 − i)/2·… computed by hand: x coordinates 1, 0, −1, 0 give c₁ = c₃ = 1/2.
    let t = 0.1;
    let x_expected = 0.5 * (2.0 * PI * t).cos() + 0.5 * (6.0 * PI * t).cos();
    assert!((trig.eval(t).x - x_expected).abs() < 1e-15, "{} vs {x_expected}", trig.eval(t).x);
    for (k, p) in square.iter().enumerate() {
        assert!((trig.eval(k as f64 / 4.0) - *p).length() < 1e-15);
    }
}

#[test]
fn bad_input_is_rejected_with_a_clear_error() {
    assert_eq!(HarmonicCurve::<f64>::try_new(vec![]), Err(Error::Empty));
    let e = HarmonicCurve::try_new(vec![DVec2::ZERO, DVec2::new(f64::NAN, 0.0)]).unwrap_err();
    assert_eq!(e, Error::NonFinitePoint { index: 1 });
    assert_eq!(e.to_string(), "point 1 has a non-finite coordinate (NaN or infinity)");
    let curve = HarmonicCurve::new(vec![1.0, 2.0, 3.0]);
    assert!(matches!(curve.sample_uniform(0), Err(Error::InvalidCount { .. })));
    assert!(matches!(curve.resample(0), Err(Error::InvalidCount { .. })));
    assert!(matches!(
        curve.rotate(f64::INFINITY),
        Err(Error::NonFiniteParameter { name: "offset", .. })
    ));
    assert!(matches!(curve.subdivide(40), Err(Error::InvalidCount { .. })));
    assert!(matches!(curve.subdivide(200), Err(Error::InvalidCount { .. })));
    assert!(TrigonometricCurve::<f64>::try_new(vec![]).is_err());
}

#[test]
fn one_and_two_points() {
    // n = 1: a constant curve. n = 2: a segment traversed back and forth, x₀ + (x₁−x₀)(1−cos 2πt)/2.
    let one = HarmonicCurve::new(vec![DVec2::new(3.0, 4.0)]);
    assert_eq!(one.eval(0.3), DVec2::new(3.0, 4.0));
    assert_eq!(one.curvature(0.3), None);
    let two = HarmonicCurve::new(vec![DVec2::ZERO, DVec2::new(2.0, 0.0)]);
    for t in [0.1, 0.25, 0.8] {
        let expected = DVec2::new(1.0 - (2.0 * PI * t).cos(), 0.0);
        assert!((two.eval(t) - expected).length() < 1e-15);
    }
}

#[test]
fn collinear_points_have_zero_curvature() {
    // X(t) = a + f(t)·d, a line traversed back and forth: κ = 0 wherever X′ ≠ 0. Rounding
    // leaves about ε·|X″|/|X′|², which grows near the turning points.
    let (a, d) = (DVec3::new(1.0, -2.0, 0.5), DVec3::new(0.3, 0.4, 1.2));
    let pts: Vec<DVec3> = [0.0, 2.0, 1.5, -1.0, 0.25].iter().map(|s| a + *s * d).collect();
    let curve = HarmonicCurve::new(pts);
    for t in [0.05, 0.33, 0.61, 0.9] {
        let kappa = curve.curvature(t).unwrap();
        let noise = f64::EPSILON * curve.eval_deriv(t, 2).length()
            / curve.eval_deriv(t, 1).length_squared();
        assert!(kappa < 16.0 * noise, "t = {t}: κ = {kappa:e}, rounding level {noise:e}");
    }
}
