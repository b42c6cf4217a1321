// SPDX-License-Identifier: MIT
//! The Bézier forms of §5.7 (`hi_curve::bezier`): the thesis's cubic scheme against the numbers
//! of docs/math.md §4, partition of unity, interpolation of the data, the Hermite scheme's tolerance
//! and C1 joins, and the guaranteed bounds against dense sampling.

use glam::{DVec2, DVec3};
use hi_bezier::BezierCurve;
use hi_curve::bezier::{BasisPieces, BezierScheme, HermiteDegree};
use hi_curve::{Error, HarmonicCurve, Sigma};
use hi_testkit::proptest_config;
use proptest::prelude::*;

/// max over k and a dense t grid of |σₖ(t) − approximation|.
fn basis_error(p: &BasisPieces, samples: usize) -> f64 {
    let sigma = Sigma::new(p.n());
    let mut worst: f64 = 0.0;
    for i in 0..samples {
        let t = (i as f64 + 0.5) / samples as f64;
        for k in 0..p.n() {
            worst = worst.max((sigma.eval(k, t) - p.eval(k, t)).abs());
        }
    }
    worst
}

/// Solves the 4×4 system Σⱼ B³ⱼ(i/3)·cⱼ = fᵢ by Gaussian elimination with partial pivoting
/// (a different method from the closed-form inverse in the library).
fn solve_bernstein(f: [f64; 4]) -> [f64; 4] {
    let bern = |j: usize, s: f64| {
        let c = [1.0, 3.0, 3.0, 1.0][j];
        c * s.powi(j as i32) * (1.0 - s).powi(3 - j as i32)
    };
    let mut m = [[0.0; 5]; 4];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().take(4).enumerate() {
            *x = bern(j, i as f64 / 3.0);
        }
        row[4] = f[i];
    }
    for col in 0..4 {
        let piv = (col..4).max_by(|&a, &b| m[a][col].abs().total_cmp(&m[b][col].abs())).unwrap();
        m.swap(col, piv);
        for r in 0..4 {
            if r != col {
                let factor = m[r][col] / m[col][col];
                let pivot_row = m[col];
                for (x, p) in m[r].iter_mut().zip(pivot_row).skip(col) {
                    *x -= factor * p;
                }
            }
        }
    }
    [0, 1, 2, 3].map(|i| m[i][4] / m[i][i])
}

#[test]
fn thesis_cubic_control_values_solve_the_bernstein_system() {
    for n in [2usize, 3, 5, 8] {
        let p = BasisPieces::thesis_cubic(n).expect("n ≥ 1");
        let sigma = Sigma::new(n);
        for a in 0..n {
            for k in 0..n {
                let f =
                    [0, 1, 2, 3].map(|i| sigma.eval(k, (a as f64 + f64::from(i) / 3.0) / n as f64));
                let want = solve_bernstein(f);
                for (j, (&got, want)) in p.control(a, k).iter().zip(want).enumerate() {
                    assert!((got - want).abs() < 1e-13, "n {n} a {a} k {k} j {j}: {got} vs {want}");
                }
            }
        }
    }
}

#[test]
fn thesis_cubic_basis_error_is_the_plateau_of_math_md() {
    // docs/math.md §4, computed there independently: max over k, t of |σₖ − Bézier|.
    let table = [
        (2, 5.48e-3),
        (3, 6.21e-3),
        (4, 3.92e-3),
        (5, 7.04e-3),
        (6, 4.88e-3),
        (7, 6.68e-3),
        (8, 5.43e-3),
        (10, 5.70e-3),
        (12, 5.85e-3),
        (16, 6.00e-3),
        (32, 6.15e-3),
        (64, 6.19e-3),
    ];
    for (n, want) in table {
        let p = BasisPieces::thesis_cubic(n).expect("n ≥ 1");
        let got = basis_error(&p, 400 * n);
        assert!((got - want).abs() < 0.01 * want + 5e-6, "n = {n}: {got:e}, docs/math.md {want:e}");
        assert!(got < 7.5e-3, "n = {n}: the docs/math.md bound 7.5e-3");
    }
}

#[test]
fn the_thesis_cubic_keeps_the_partition_of_unity_and_the_quintic_nearly() {
    for n in [3usize, 4, 5, 8, 13] {
        let cubic = BasisPieces::thesis_cubic(n).expect("n ≥ 1");
        let quintic = BasisPieces::thesis_quintic(n).expect("n ≥ 3");
        let quintic_error = basis_error(&quintic, 400 * n);
        for (p, tol) in [(cubic, 1e-13), (quintic, 2.0 * n as f64 * quintic_error)] {
            for a in 0..p.n_pieces() {
                for j in 0..=p.degree() {
                    let sum: f64 = (0..n).map(|k| p.control(a, k)[j]).sum();
                    assert!(
                        (sum - 1.0).abs() <= tol,
                        "n {n} degree {} piece {a}: {sum}",
                        p.degree()
                    );
                }
            }
        }
    }
}

#[test]
fn the_quintic_pieces_are_exact_hermite_data_at_the_zeros_of_sigma_prime() {
    for n in [3usize, 6, 9] {
        let p = BasisPieces::thesis_quintic(n).expect("n ≥ 3");
        let sigma = Sigma::new(n);
        let own = p.sigma_breaks();
        assert_eq!(
            own.len() - 1,
            if n % 2 == 1 { 2 * (n - 1) } else { 2 * n },
            "n = {n}: pieces of σ"
        );
        for (i, &b) in own.iter().enumerate().take(own.len() - 1) {
            if i % 2 == 0 {
                // A zero of σ′: found independently by the sign of σ′ either side.
                let (l, r) = (sigma.deriv(0, b - 1e-7, 1), sigma.deriv(0, b + 1e-7, 1));
                assert!(l * r < 0.0, "n {n}: σ′ does not change sign at {b}");
            }
            assert!((p.eval(0, b) - sigma.eval(0, b)).abs() < 1e-13, "n {n}: value at {b}");
        }
    }
}

#[test]
fn the_thesis_cubic_has_a_derivative_jump_of_about_twelve_percent() {
    // docs/math.md §4: the derivative jumps at the knots by about 12% of max|σ′| for all n.
    for n in [5usize, 8, 16] {
        let p = BasisPieces::thesis_cubic(n).expect("n");
        let sigma = Sigma::new(n);
        let max_d = (0..10_000)
            .map(|i| sigma.deriv(0, i as f64 / 10_000.0, 1).abs())
            .fold(0.0_f64, f64::max);
        let mut worst: f64 = 0.0;
        for a in 0..n {
            let (left, right) = (a, (a + 1) % n);
            for k in 0..n {
                // d/dt at the end of piece `left` and the start of piece `right`, width 1/n.
                let l = BezierCurve::new(p.control(left, k).to_vec()).eval_deriv(1.0, 1) * n as f64;
                let r =
                    BezierCurve::new(p.control(right, k).to_vec()).eval_deriv(0.0, 1) * n as f64;
                worst = worst.max((l - r).abs());
            }
        }
        let rel = worst / max_d;
        assert!((0.08..0.16).contains(&rel), "n = {n}: jump {rel} of max|σ′|");
    }
}

#[test]
fn the_thesis_quintic_is_far_closer_than_the_cubic() {
    for n in [3usize, 4, 5, 7, 8, 16] {
        let quintic = BasisPieces::thesis_quintic(n).expect("n ≥ 3");
        let err = basis_error(&quintic, 400 * n);
        let cubic = basis_error(&BasisPieces::thesis_cubic(n).expect("n"), 400 * n);
        // Measured: 1.5e-4 (n = 3) to 4.3e-4 (n = 4), a plateau like the cubic's, 9–25× lower.
        assert!(err < cubic / 5.0 && err < 5e-4, "n = {n}: quintic {err:e}, cubic {cubic:e}");
        assert!(quintic.n_pieces() >= quintic.sigma_breaks().len() - 1, "n = {n}: merged");
    }
}

#[test]
fn the_thesis_quintic_is_smooth_and_its_pieces_are_not_slivers() {
    for n in [3usize, 4, 5, 6, 9, 16] {
        let points = random_points(40 + n as u64, n);
        let b = HarmonicCurve::new(points)
            .to_bezier(BezierScheme::ThesisQuintic, hi_curve::bezier::DEFAULT_TOLERANCE)
            .expect("n ≥ 3");
        // Hermite data of the true σₖ on both sides of every break: C2, so the tangent turns
        // continuously.
        assert!(b.report.max_tangent_jump < 1e-9, "n = {n}: {:?}", b.report);
        let widths = b.spline.breaks().windows(2).map(|w| w[1] - w[0]);
        let narrowest = widths.fold(f64::INFINITY, f64::min);
        // Shifted breaks may truly lie close together (1.6e-5 apart at n = 16), but none is a
        // rounding copy of another (those differ by about 1e-12).
        assert!(narrowest > 1e-8, "n = {n}: a sliver piece of width {narrowest:e}");
    }
}

#[test]
fn the_thesis_quintic_needs_zeros_of_sigma_prime() {
    assert_eq!(BasisPieces::thesis_quintic(0), Err(Error::ZeroBasisSize));
    for n in [1, 2] {
        assert!(
            matches!(BasisPieces::thesis_quintic(n), Err(Error::InvalidCount { value, .. }) if value == n),
            "n = {n}"
        );
    }
}

fn random_points(seed: u64, n: usize) -> Vec<DVec3> {
    // A small deterministic generator (SplitMix64) for reproducible point sets.
    let mut s = seed;
    let mut next = move || {
        s = s.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = s;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..n).map(|_| DVec3::new(next(), next(), next())).collect()
}

#[test]
fn every_scheme_passes_through_the_data_points() {
    for n in [3usize, 4, 7, 10] {
        let points = random_points(n as u64, n);
        let curve = HarmonicCurve::new(points.clone());
        for scheme in [
            BezierScheme::ThesisCubic,
            BezierScheme::ThesisQuintic,
            BezierScheme::Hermite(HermiteDegree::Cubic),
            BezierScheme::Hermite(HermiteDegree::Quintic),
        ] {
            let b = curve
                .to_bezier(scheme, hi_curve::bezier::Tolerance::Absolute(1e-5))
                .expect("converts");
            // The quintic interpolates each σₖ at its own breaks only: within its bound.
            let tol = if scheme == BezierScheme::ThesisQuintic { b.report.bound } else { 1e-13 };
            for (k, &x) in points.iter().enumerate() {
                let t = k as f64 / n as f64;
                let d = (b.spline.eval(t) - x).length();
                assert!(d <= tol, "{} n {n} point {k}: off by {d:e}", scheme.name());
            }
        }
    }
}

#[test]
fn measured_deviation_never_exceeds_the_bound() {
    for n in [3usize, 5, 8, 16] {
        let curve = HarmonicCurve::new(random_points(100 + n as u64, n));
        for scheme in [
            BezierScheme::ThesisCubic,
            BezierScheme::ThesisQuintic,
            BezierScheme::Hermite(HermiteDegree::Cubic),
            BezierScheme::Hermite(HermiteDegree::Quintic),
        ] {
            let r = curve
                .to_bezier(scheme, hi_curve::bezier::Tolerance::Absolute(1e-4))
                .expect("converts")
                .report;
            // A denser check than the report's own sample.
            let b = curve
                .to_bezier(scheme, hi_curve::bezier::Tolerance::Absolute(1e-4))
                .expect("converts")
                .spline;
            let dense = (0..20_000)
                .map(|i| {
                    let t = (i as f64 + 0.37) / 20_000.0;
                    (b.eval(t) - curve.eval(t)).length()
                })
                .fold(0.0_f64, f64::max);
            assert!(r.max_deviation <= r.bound, "{} n {n}: {r:?}", scheme.name());
            assert!(
                dense <= r.bound,
                "{} n {n}: dense {dense:e} > bound {:e}",
                scheme.name(),
                r.bound
            );
            assert!(r.rms_deviation <= r.max_deviation, "{} n {n}", scheme.name());
        }
    }
}

#[test]
fn the_hermite_scheme_is_c1_and_meets_the_tolerance() {
    let curve = HarmonicCurve::new(random_points(7, 9));
    for tol in [1e-2, 1e-4, 1e-7] {
        for degree in [HermiteDegree::Cubic, HermiteDegree::Quintic] {
            let b = curve
                .to_bezier(
                    BezierScheme::Hermite(degree),
                    hi_curve::bezier::Tolerance::Absolute(tol),
                )
                .expect("converts");
            assert!(b.report.bound <= tol, "{degree:?} tol {tol}: bound {:e}", b.report.bound);
            assert!(b.report.max_tangent_jump < 1e-9, "{degree:?}: C1");
            // The derivative on both sides of every join is the curve's own.
            for &t in &b.spline.breaks()[1..b.spline.breaks().len() - 1] {
                let (left, right) = (b.spline.eval_deriv(t - 1e-13, 1), b.spline.eval_deriv(t, 1));
                let scale = curve.eval_deriv(t, 1).length().max(1.0);
                assert!((left - right).length() < 1e-6 * scale, "{degree:?} join at {t}");
            }
        }
    }
    let coarse = curve
        .to_bezier(
            BezierScheme::Hermite(HermiteDegree::Cubic),
            hi_curve::bezier::Tolerance::Absolute(1e-2),
        )
        .unwrap();
    let fine = curve
        .to_bezier(
            BezierScheme::Hermite(HermiteDegree::Cubic),
            hi_curve::bezier::Tolerance::Absolute(1e-7),
        )
        .unwrap();
    let quintic = curve
        .to_bezier(
            BezierScheme::Hermite(HermiteDegree::Quintic),
            hi_curve::bezier::Tolerance::Absolute(1e-7),
        )
        .unwrap();
    assert!(fine.report.pieces > coarse.report.pieces, "a finer tolerance needs more pieces");
    assert!(quintic.report.pieces < fine.report.pieces, "quintic pieces are longer");
}

#[test]
fn the_thesis_cubic_on_a_curve_has_a_c0_plateau_and_a_tangent_jump() {
    // A regular 7-gon: the harmonic curve is the circle.
    let n = 7;
    let points: Vec<DVec2> = (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            DVec2::new(a.cos(), a.sin())
        })
        .collect();
    let curve = HarmonicCurve::new(points);
    let r = curve
        .to_bezier(BezierScheme::ThesisCubic, hi_curve::bezier::DEFAULT_TOLERANCE)
        .expect("converts")
        .report;
    assert_eq!((r.pieces, r.degree), (7, 3), "n cubic pieces");
    assert!(r.max_tangent_jump > 1e-4, "C0 only: {r:?}");
    // The basis error of docs/math.md §4 (below 7.5e-3 per σₖ) bounds the curve's, as the
    // approximated basis sums to one: ≤ 7.5e-3·Σ‖xₖ − c‖ = 7.5e-3·7 here.
    assert!(r.max_deviation > 0.0 && r.max_deviation < 7.5e-3 * 7.0, "{r:?}");
    assert!(r.max_deviation <= r.bound, "{r:?}");
}

#[test]
fn bad_tolerances_and_counts_are_errors() {
    let curve = HarmonicCurve::new(random_points(1, 5));
    let scheme = BezierScheme::Hermite(HermiteDegree::Cubic);
    assert!(matches!(
        curve.to_bezier(scheme, hi_curve::bezier::Tolerance::Absolute(0.0)),
        Err(Error::ParameterOutOfBounds { .. })
    ));
    assert!(matches!(
        curve.to_bezier(scheme, hi_curve::bezier::Tolerance::Absolute(f64::NAN)),
        Err(Error::NonFiniteParameter { .. })
    ));
    assert!(matches!(
        BasisPieces::thesis_cubic(5).unwrap().apply(&random_points(2, 4)),
        Err(Error::InvalidCount { value: 4, .. })
    ));
    let mut bad = random_points(3, 5);
    bad[2].y = f64::INFINITY;
    assert_eq!(
        BasisPieces::thesis_cubic(5).unwrap().apply(&bad),
        Err(Error::NonFinitePoint { index: 2 })
    );
    for scheme in [BezierScheme::ThesisCubic, BezierScheme::Hermite(HermiteDegree::Quintic)] {
        assert_eq!(BezierScheme::from_name(scheme.name()), Some(scheme), "names round-trip");
    }
}

proptest! {
    #![proptest_config(proptest_config(48))]

    #[test]
    fn hermite_bounds_hold_on_random_curves(seed in 0u64..1_000_000, n in 2usize..24, exp in 2i32..8) {
        let curve = HarmonicCurve::new(random_points(seed, n));
        let tol = 10f64.powi(-exp);
        let b = curve.to_bezier(BezierScheme::Hermite(HermiteDegree::Cubic), hi_curve::bezier::Tolerance::Absolute(tol)).unwrap();
        prop_assert!(b.report.bound <= tol);
        prop_assert!(b.report.max_deviation <= b.report.bound);
    }
}
