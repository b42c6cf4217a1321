// SPDX-License-Identifier: MIT
//! Non-uniform interpolation (§3.10, docs/math.md §5): both readings, on random and awkward nodes.

use std::f64::consts::PI;

use glam::DVec2;
use hi_curve::{Error, HarmonicCurve, NonUniformCurve, NonUniformVariant, chord_length_params};
use hi_testkit::proptest_config;
use proptest::prelude::*;

fn distinct_params(n: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::btree_set(0u32..100_000, n)
        .prop_map(|s| s.into_iter().map(|v| v as f64 / 100_000.0).collect())
}

fn points_and_params(max_n: usize) -> impl Strategy<Value = (Vec<DVec2>, Vec<f64>)> {
    (1..max_n).prop_flat_map(|n| {
        (
            prop::collection::vec(
                (-5.0..5.0f64, -5.0..5.0f64).prop_map(|(x, y)| DVec2::new(x, y)),
                n,
            ),
            distinct_params(n),
        )
    })
}

fn uniform(n: usize) -> Vec<f64> {
    (0..n).map(|k| k as f64 / n as f64).collect()
}

proptest! {
    #![proptest_config(proptest_config(128))]

    /// The nodes variant passes through xₖ at tₖ, for any distinct nodes.
    #[test]
    fn nodes_variant_interpolates((pts, params) in points_and_params(24)) {
        let curve = NonUniformCurve::try_with_params(pts.clone(), params.clone(), NonUniformVariant::Nodes).unwrap();
        for (p, t) in pts.iter().zip(&params) {
            prop_assert!((curve.eval(*t) - *p).length() < 1e-12 * curve.condition().max(1.0));
            // Also next to the node, where the barycentric form divides by a small sine.
            prop_assert!((curve.eval(*t + 1e-13) - *p).length() < 1e-9 * curve.condition().max(1.0));
        }
    }

    /// The cardinal functions sum to 1, so the curve commutes with translations and scalings.
    #[test]
    fn nodes_variant_is_affine_invariant((pts, params) in points_and_params(16), t in 0.0..1.0f64,
                                         shift in (-9.0..9.0f64, -9.0..9.0f64)) {
        let shift = DVec2::new(shift.0, shift.1);
        let moved: Vec<DVec2> = pts.iter().map(|p| 2.0 * *p + shift).collect();
        let a = NonUniformCurve::try_with_params(pts, params.clone(), NonUniformVariant::Nodes).unwrap();
        let b = NonUniformCurve::try_with_params(moved, params, NonUniformVariant::Nodes).unwrap();
        let scale = a.condition().max(1.0) * 20.0;
        prop_assert!((b.eval(t) - (2.0 * a.eval(t) + shift)).length() < 1e-11 * scale);
    }

    /// With tₖ = k/n the nodes variant is the uniform harmonic curve, odd and even n.
    #[test]
    fn nodes_variant_with_uniform_nodes_is_harmonic(pts in prop::collection::vec((-5.0..5.0f64, -5.0..5.0f64).prop_map(|(x, y)| DVec2::new(x, y)), 1..40),
                                                    t in -1.0..2.0f64) {
        let n = pts.len();
        let nu = NonUniformCurve::try_with_params(pts.clone(), uniform(n), NonUniformVariant::Nodes).unwrap();
        let h = HarmonicCurve::new(pts);
        prop_assert!((nu.eval(t) - h.eval(t)).length() < 1e-12 * 10.0);
        prop_assert!((nu.eval_deriv(t, 1) - h.eval_deriv(t, 1)).length() < 1e-11 * 10.0 * n as f64);
    }

    /// The thesis's formula interpolates at k/(n−1), and with tⱼ = j/n it is the uniform
    /// harmonic curve at (n−1)t/n (exact for odd n, the real part for even n with m = ⌊n/2⌋).
    #[test]
    fn thesis_variant_readings(pts in prop::collection::vec((-5.0..5.0f64, -5.0..5.0f64).prop_map(|(x, y)| DVec2::new(x, y)), 2..20),
                               t in 0.0..1.0f64) {
        let n = pts.len();
        let curve = NonUniformCurve::try_with_params(pts.clone(), uniform(n), NonUniformVariant::Thesis).unwrap();
        for (k, p) in pts.iter().enumerate() {
            prop_assert!((curve.eval(k as f64 / (n - 1) as f64) - *p).length() < 1e-11);
        }
        let h = HarmonicCurve::new(pts);
        let s = (n - 1) as f64 * t / n as f64;
        prop_assert!((curve.eval(t) - h.eval(s)).length() < 1e-11, "n={n}");
    }
}

#[test]
fn thesis_variant_does_not_pass_through_the_points_at_their_params() {
    // docs/math.md §5: the tⱼ act as frequencies; at t = tₖ the curve misses xₖ by O(1).
    let pts = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(3.0, 1.0),
        DVec2::new(4.0, 4.0),
        DVec2::new(1.0, 5.0),
        DVec2::new(-1.0, 2.0),
    ];
    let curve = NonUniformCurve::try_new(pts.clone(), NonUniformVariant::Thesis).unwrap();
    let miss = pts
        .iter()
        .zip(curve.params())
        .map(|(p, t)| (curve.eval(*t) - *p).length())
        .fold(0.0, f64::max);
    assert!(miss > 0.1, "{miss}");
    for (p, t) in pts.iter().zip(curve.interpolation_params()) {
        assert!((curve.eval(t) - *p).length() < 1e-12);
    }
    assert!(curve.matrix_condition().unwrap() >= 1.0);
}

#[test]
fn even_nodes_that_defeat_the_harmonic_space_still_work() {
    // n = 2 at t = 1/4, 3/4: the even harmonic space span{1, cos 2πt} cannot interpolate there
    // (cos 2πt is 0 at both), but the nodes variant's top term is sin(π(nt − Σtⱼ)) =
    // sin(π(2t − 1)), so its space is span{1, sin 2πt}, which can.
    let pts = vec![DVec2::new(1.0, 0.0), DVec2::new(-1.0, 2.0)];
    let curve =
        NonUniformCurve::try_with_params(pts.clone(), vec![0.25, 0.75], NonUniformVariant::Nodes)
            .unwrap();
    assert!((curve.eval(0.25) - pts[0]).length() < 1e-15);
    assert!((curve.eval(0.75) - pts[1]).length() < 1e-15);
    // Here Σtⱼ = 1, so the top term is sin(2πt): X(t) = (x₀ + x₁)/2 + (x₀ − x₁)/2·sin 2πt.
    let t = 0.1;
    let expected = (pts[0] + pts[1]) / 2.0 + (pts[0] - pts[1]) / 2.0 * (2.0 * PI * t).sin();
    assert!((curve.eval(t) - expected).length() < 1e-15);
}

#[test]
fn condition_is_the_lebesgue_constant() {
    // Uniform odd nodes: Λ of the Dirichlet kernel interpolant; Λ₃ = 5/3 (at t = 1/6 etc.).
    let pts = vec![DVec2::ZERO; 3];
    let c = NonUniformCurve::try_with_params(pts, uniform(3), NonUniformVariant::Nodes).unwrap();
    assert!((c.condition() - 5.0 / 3.0).abs() < 1e-12, "{}", c.condition());
    // Clustered nodes are ill-conditioned.
    let pts = vec![DVec2::ZERO; 7];
    let clustered = vec![0.0, 0.01, 0.02, 0.03, 0.5, 0.6, 0.7];
    let c = NonUniformCurve::try_with_params(pts, clustered, NonUniformVariant::Nodes).unwrap();
    assert!(c.condition() > 100.0, "{}", c.condition());
}

#[test]
fn chord_length_parameters() {
    let pts = vec![DVec2::ZERO, DVec2::X, DVec2::new(1.0, 1.0), DVec2::Y];
    assert_eq!(chord_length_params(&pts).unwrap(), vec![0.0, 0.25, 0.5, 0.75]);
    let curve = NonUniformCurve::try_new(pts.clone(), NonUniformVariant::Nodes).unwrap();
    assert_eq!(curve.params(), &[0.0, 0.25, 0.5, 0.75]);
    assert!((curve.eval(0.5) - pts[2]).length() < 1e-15);
}

#[test]
fn bad_parameters_are_rejected() {
    let pts = vec![DVec2::ZERO, DVec2::X, DVec2::Y];
    let v = NonUniformVariant::Nodes;
    assert_eq!(
        NonUniformCurve::try_with_params(pts.clone(), vec![0.0, 0.5], v).unwrap_err(),
        Error::ParameterCountMismatch { points: 3, params: 2 }
    );
    assert_eq!(
        NonUniformCurve::try_with_params(pts.clone(), vec![0.0, 0.5, 1.0], v).unwrap_err(),
        Error::NodeOutOfRange { index: 2, value: 1.0 }
    );
    assert!(matches!(
        NonUniformCurve::try_with_params(pts.clone(), vec![0.0, f64::NAN, 0.2], v),
        Err(Error::NodeOutOfRange { index: 1, .. })
    ));
    assert_eq!(
        NonUniformCurve::try_with_params(
            pts.clone(),
            vec![0.3, 0.5, 0.3],
            NonUniformVariant::Thesis
        )
        .unwrap_err(),
        Error::ParametersNotDistinct { first: 0, second: 2 }
    );
    assert_eq!(chord_length_params(&[DVec2::X, DVec2::X]).unwrap_err(), Error::ZeroLengthPolygon);
    assert_eq!(
        chord_length_params(&[DVec2::ZERO, DVec2::X, DVec2::X]).unwrap_err(),
        Error::CoincidentPoints { first: 1, second: 2 }
    );
    assert_eq!(NonUniformCurve::<DVec2>::try_new(vec![], v).unwrap_err(), Error::Empty);
    assert_eq!(
        Error::ParameterCountMismatch { points: 2, params: 1 }.to_string(),
        "1 parameter given for 2 points: one parameter per point is needed"
    );
}
