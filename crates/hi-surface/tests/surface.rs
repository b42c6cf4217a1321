// SPDX-License-Identifier: MIT
//! Harmonic surfaces: the identities of docs/math.md §3 and §2 on random grids, exact sphere and
//! torus, derivatives against finite differences, fast grid paths against the direct sum.

use std::f64::consts::PI;

use glam::{DMat3, DVec3};
use hi_interval::Interval;
use hi_surface::{Axis, Error, HarmonicSurface, sphere, torus};
use hi_testkit::proptest_config;
use proptest::prelude::*;

fn grid(max: usize) -> impl Strategy<Value = Vec<Vec<DVec3>>> {
    (1..max, 1..max).prop_flat_map(|(m, n)| {
        prop::collection::vec(
            prop::collection::vec(
                (-5.0..5.0f64, -5.0..5.0f64, -5.0..5.0f64)
                    .prop_map(|(x, y, z)| DVec3::new(x, y, z)),
                n,
            ),
            m,
        )
    })
}

proptest! {
    #![proptest_config(proptest_config(96))]

    /// The interval enclosure of every partial derivative up to order 2 over a parameter box
    /// holds the derivative evaluated in f64 at points of the box, up to the f64 rounding
    /// bound, and is no wider than the first-order Taylor bound from the spectrum allows.
    #[test]
    fn derivative_enclosures_hold_the_surface(
        g in grid(9),
        u0 in 0.0..1.0f64,
        v0 in 0.0..1.0f64,
        hu in 1e-4..0.05f64,
        hv in 1e-4..0.05f64,
    ) {
        let s = HarmonicSurface::new(g);
        let (u, v) = (Interval::new(u0, u0 + hu), Interval::new(v0, v0 + hv));
        for (p, q) in [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)] {
            let e = s.enclose_deriv(u, v, p, q);
            let err = s.eval_error_bound(p, q);
            for i in 0..=4 {
                for j in 0..=4 {
                    let (uu, vv) = (u0 + hu * i as f64 / 4.0, v0 + hv * j as f64 / 4.0);
                    let d = s.eval_deriv(uu.min(u.hi()), vv.min(v.hi()), p, q).to_array();
                    for k in 0..3 {
                        prop_assert!(
                            d[k] >= e[k].lo() - err && d[k] <= e[k].hi() + err,
                            "order ({p}, {q}) coordinate {k}: {} outside {:?} ± {err}", d[k], e[k]
                        );
                    }
                }
            }
            // Taylor: the derivative moves by at most M₁·h over the box, in each direction.
            let slope = s.deriv_bound(p + 1, q) * hu + s.deriv_bound(p, q + 1) * hv;
            let scale = s.deriv_bound(p, q);
            for (k, x) in e.iter().enumerate() {
                prop_assert!(
                    x.width() <= 4.0 * slope + 1e-9 * (1.0 + scale),
                    "order ({p}, {q}) coordinate {k}: width {} against slope bound {slope}",
                    x.width()
                );
            }
        }
    }

    /// p(j/m, k/n) = xⱼₖ.
    #[test]
    fn interpolates(g in grid(12)) {
        let s = HarmonicSurface::new(g.clone());
        let (m, n) = (s.m(), s.n());
        for (j, row) in g.iter().enumerate() {
            for (k, x) in row.iter().enumerate() {
                let p = s.eval(j as f64 / m as f64, k as f64 / n as f64);
                prop_assert!((p - *x).length() < 1e-13 * (1.0 + x.length()) * (m * n) as f64);
            }
        }
    }

    /// The weights σᵐⱼ(u)σⁿₖ(v) sum to 1, so affine maps commute with the surface.
    #[test]
    fn affine_invariance(g in grid(10), a in prop::array::uniform9(-2.0..2.0f64),
                         b in prop::array::uniform3(-3.0..3.0f64), u in -1.0..2.0f64, v in -1.0..2.0f64) {
        let mat = DMat3::from_cols_array(&a);
        let shift = DVec3::from_array(b);
        let image: Vec<Vec<DVec3>> = g.iter().map(|r| r.iter().map(|x| mat * *x + shift).collect()).collect();
        let lhs = HarmonicSurface::new(image).eval(u, v);
        let rhs = mat * HarmonicSurface::new(g).eval(u, v) + shift;
        prop_assert!((lhs - rhs).length() < 1e-11 * 100.0);
        // Translating a constant: the weights form a partition of unity.
    }

    /// The spectral path equals the direct sum, and insertion on both axes keeps the surface.
    #[test]
    fn spectral_path_and_insertion(g in grid(9), extra_u in 1usize..6, extra_v in 1usize..6,
                                   u in 0.0..1.0f64, v in 0.0..1.0f64) {
        let s = HarmonicSurface::new(g);
        let direct = s.eval(u, v);
        prop_assert!((s.eval_deriv(u, v, 0, 0) - direct).length() < 1e-12 * 50.0);
        let bigger = s.insert(s.m() + extra_u, s.n() + extra_v).unwrap();
        prop_assert!((bigger.eval(u, v) - direct).length() < 1e-12 * 50.0);
        let d = s.eval_deriv(u, v, 1, 1);
        prop_assert!((bigger.eval_deriv(u, v, 1, 1) - d).length() < 1e-10 * (1.0 + d.length()));
    }

    /// Derivatives of any order against central differences of the next lower order.
    #[test]
    fn derivatives_match_finite_differences(g in grid(8), u in 0.0..1.0f64, v in 0.0..1.0f64,
                                            p in 0usize..3, q in 0usize..3) {
        let s = HarmonicSurface::new(g);
        let h = 1e-5;
        let du = (s.eval_deriv(u + h, v, p, q) - s.eval_deriv(u - h, v, p, q)) / (2.0 * h);
        let dv = (s.eval_deriv(u, v + h, p, q) - s.eval_deriv(u, v - h, p, q)) / (2.0 * h);
        let exact_u = s.eval_deriv(u, v, p + 1, q);
        let exact_v = s.eval_deriv(u, v, p, q + 1);
        let scale = (2.0 * PI * 5.0f64).powi((p + q + 3) as i32) * 10.0;
        prop_assert!((du - exact_u).length() < 1e-8 * scale, "{du} vs {exact_u}");
        prop_assert!((dv - exact_v).length() < 1e-8 * scale, "{dv} vs {exact_v}");
    }

    /// Exact rotation per axis for every size, Theorem 5.1 exact for odd sizes.
    #[test]
    fn rotation_per_axis(g in grid(8), o in -1.0..1.0f64, u in 0.0..1.0f64, v in 0.0..1.0f64) {
        let s = HarmonicSurface::new(g);
        let ru = s.rotate(Axis::U, o).unwrap();
        let rv = s.rotate(Axis::V, o).unwrap();
        prop_assert!((ru.eval(u, v) - s.eval(u + o, v)).length() < 1e-11 * 50.0);
        prop_assert!((rv.eval(u, v) - s.eval(u, v + o)).length() < 1e-11 * 50.0);
        if s.m() % 2 == 1 {
            let t = s.rotate_theorem_5_1(Axis::U, o).unwrap();
            prop_assert!((t.eval(u, v) - s.eval(u + o, v)).length() < 1e-11 * 50.0);
        }
    }
}

#[test]
fn sphere_and_torus_curvature() {
    let r = 1.5;
    let s = sphere(r);
    for (u, v) in [(0.1, 0.2), (0.25, 0.9), (0.4, 0.5)] {
        // p(u, v) = r(sin 2πu cos 2πv, sin 2πu sin 2πv, cos 2πu).
        let (su, cu) = (2.0 * PI * u).sin_cos();
        let (sv, cv) = (2.0 * PI * v).sin_cos();
        assert!((s.eval(u, v) - r * DVec3::new(su * cv, su * sv, cu)).length() < 1e-14);
        let c = s.curvature(u, v).unwrap();
        assert!((c.gaussian - 1.0 / (r * r)).abs() < 1e-12, "K = {}", c.gaussian);
        assert!((c.mean + 1.0 / r).abs() < 1e-12 && (c.k1_plus_k2 + 2.0 / r).abs() < 1e-12);
        assert!((c.k1 - c.k2).abs() < 1e-6, "umbilic: κ₁ = κ₂");
    }
    // Poles: p_v = 0.
    assert!(s.normal(0.0, 0.3).is_none() && s.curvature(0.5, 0.1).is_none());

    let (big_r, r) = (3.0, 1.0);
    let t = torus(big_r, r);
    for (u, v) in [(0.05, 0.2), (0.3, 0.7), (0.6, 0.1), (0.9, 0.45)] {
        let theta = 2.0 * PI * u;
        let c = t.curvature(u, v).unwrap();
        let k = theta.sin() / (r * (big_r + r * theta.sin()));
        let h = (big_r + 2.0 * r * theta.sin()) / (2.0 * r * (big_r + r * theta.sin()));
        assert!((c.gaussian - k).abs() < 1e-12, "K {} vs {k}", c.gaussian);
        assert!((c.mean.abs() - h).abs() < 1e-12, "H {} vs {h}", c.mean);
        // Principal curvatures of a torus: 1/r (around the tube) and sin θ/(R + r sin θ).
        let mut ks = [c.k1.abs(), c.k2.abs()];
        ks.sort_by(f64::total_cmp);
        let mut expected = [1.0 / r, (theta.sin() / (big_r + r * theta.sin())).abs()];
        expected.sort_by(f64::total_cmp);
        assert!((ks[0] - expected[0]).abs() < 1e-11 && (ks[1] - expected[1]).abs() < 1e-11);
        // The principal directions are orthonormal and tangent.
        assert!(c.dir1.dot(c.dir2).abs() < 1e-12 && c.dir1.dot(c.normal).abs() < 1e-12);
    }
}

#[test]
fn plane_has_zero_curvature() {
    // Any grid in the plane z = 2x − y + 1 gives a planar surface (affine invariance).
    let g: Vec<Vec<DVec3>> = (0..5)
        .map(|j| {
            (0..6)
                .map(|k| {
                    let (x, y) =
                        ((j * j) as f64 * 0.3 - k as f64, (k * j) as f64 * 0.2 + 0.1 * k as f64);
                    DVec3::new(x, y, 2.0 * x - y + 1.0)
                })
                .collect()
        })
        .collect();
    let s = HarmonicSurface::new(g);
    for (u, v) in [(0.13, 0.7), (0.5, 0.5), (0.81, 0.02)] {
        if let Some(c) = s.curvature(u, v) {
            assert!(
                c.gaussian.abs() < 1e-9 && c.mean.abs() < 1e-9,
                "K {} H {}",
                c.gaussian,
                c.mean
            );
            assert!(c.normal.cross(DVec3::new(2.0, -1.0, -1.0).normalize()).length() < 1e-9);
        }
    }
}

#[test]
fn fast_grids_equal_direct_evaluation() {
    let g: Vec<Vec<DVec3>> = (0..7)
        .map(|j| {
            (0..10)
                .map(|k| {
                    DVec3::new(
                        (j as f64).sin() + k as f64,
                        (k * j) as f64 * 0.1,
                        (j + 2 * k) as f64,
                    )
                    .cos()
                })
                .collect()
        })
        .collect();
    let s = HarmonicSurface::new(g);
    let (n_u, n_v) = (23, 40);
    let us: Vec<f64> = (0..n_u).map(|i| i as f64 / n_u as f64).collect();
    let vs: Vec<f64> = (0..n_v).map(|l| l as f64 / n_v as f64).collect();
    let direct = hi_surface::testing::sample_params_direct(&s, &us, &vs).unwrap();
    let separable = s.sample_params(&us, &vs, 0, 0).unwrap();
    let fft = s.sample_uniform(n_u, n_v, 0, 0).unwrap();
    let scale = s.points().iter().map(|p| p.length()).fold(1.0, f64::max);
    for ((a, b), c) in direct.values.iter().zip(&separable.values).zip(&fft.values) {
        assert!((*a - *b).length() < 1e-12 * scale && (*a - *c).length() < 1e-12 * scale);
    }
    // Derivatives on grids against pointwise spectral derivatives.
    let fft_uv = s.sample_uniform(n_u, n_v, 1, 2).unwrap();
    let sep_uv = s.sample_params(&us, &vs, 1, 2).unwrap();
    for i in [0, 5, 22] {
        for l in [0, 17, 39] {
            let exact = s.eval_deriv(us[i], vs[l], 1, 2);
            let tol = 1e-12 * scale * (2.0 * PI * 5.0f64).powi(3);
            assert!(
                (fft_uv.get(i, l) - exact).length() < tol
                    && (sep_uv.get(i, l) - exact).length() < tol
            );
        }
    }
}

#[test]
fn subdivision_keeps_the_surface() {
    let t = torus(2.0, 0.7);
    let sub = t.subdivide(2).unwrap();
    assert_eq!((sub.m(), sub.n()), (16, 16));
    assert_eq!(sub.point(4, 8), t.point(1, 2));
    for (u, v) in [(0.1, 0.3), (0.77, 0.5)] {
        assert!((sub.eval(u, v) - t.eval(u, v)).length() < 1e-13);
    }
}

#[test]
fn reduction_reports_its_error() {
    let g: Vec<Vec<DVec3>> = (0..9)
        .map(|j| {
            (0..5).map(|k| DVec3::new(j as f64, k as f64, ((j * 7 + k * 3) % 5) as f64)).collect()
        })
        .collect();
    let s = HarmonicSurface::new(g);
    let (r, err) = s.resample(Axis::U, 5).unwrap();
    assert_eq!(r.m(), 5);
    assert!(err.max_deviation > 0.1 && err.upper_bound >= err.max_deviation);
    let dense = (0..200)
        .flat_map(|i| (0..50).map(move |l| (i as f64 / 200.0, l as f64 / 50.0)))
        .map(|(u, v)| (s.eval(u, v) - r.eval(u, v)).length())
        .fold(0.0, f64::max);
    assert!(dense <= err.upper_bound * (1.0 + 1e-12), "dense {dense} > bound {}", err.upper_bound);
}

#[test]
fn bad_grids_are_rejected() {
    assert_eq!(HarmonicSurface::<DVec3>::try_new(vec![]), Err(Error::EmptyGrid));
    assert_eq!(HarmonicSurface::<DVec3>::try_new(vec![vec![]]), Err(Error::EmptyGrid));
    assert_eq!(
        HarmonicSurface::try_new(vec![vec![DVec3::ZERO; 3], vec![DVec3::ZERO; 2]]),
        Err(Error::RaggedGrid { row: 1, len: 2, expected: 3 })
    );
    let e = HarmonicSurface::try_new(vec![vec![DVec3::ZERO, DVec3::new(0.0, f64::NAN, 0.0)]])
        .unwrap_err();
    assert_eq!(e, Error::NonFinitePoint { row: 0, col: 1 });
    assert_eq!(e.to_string(), "grid point (0, 1) has a non-finite coordinate (NaN or infinity)");
    let s = sphere(1.0);
    assert!(s.sample_uniform(0, 4, 0, 0).is_err());
    assert!(s.sample_params(&[0.1, f64::NAN], &[0.2], 0, 0).is_err());
    assert!(s.rotate(Axis::U, f64::INFINITY).is_err());
}

/// The FFT grid against the separable basis sums (a different method) for odd and even grids,
/// folding and growing sample counts on either axis, and mixed derivative orders.
#[test]
fn uniform_fft_grid_equals_separable_sums_for_every_size() {
    for (m, n) in [(2, 3), (3, 2), (4, 4), (5, 8), (8, 5), (6, 7)] {
        let g: Vec<Vec<DVec3>> = (0..m)
            .map(|j| {
                (0..n)
                    .map(|k| {
                        let (a, b) = (j as f64, k as f64);
                        DVec3::new((1.3 * a + b).sin(), (a * b * 0.7).cos(), 0.3 * a - b)
                    })
                    .collect()
            })
            .collect();
        let s = HarmonicSurface::new(g);
        let scale = s.points().iter().map(|p| p.length()).fold(1.0, f64::max);
        for (n_u, n_v) in [(m, n), (m + 1, n + 1), (2 * m, 3 * n), (m - 1, 4 * n), (3 * m, n - 1)] {
            let us: Vec<f64> = (0..n_u).map(|i| i as f64 / n_u as f64).collect();
            let vs: Vec<f64> = (0..n_v).map(|l| l as f64 / n_v as f64).collect();
            for (p, q) in [(0, 0), (1, 0), (0, 1), (2, 1), (1, 3)] {
                let fft = s.sample_uniform(n_u, n_v, p, q).unwrap();
                let sums = s.sample_params(&us, &vs, p, q).unwrap();
                let tol = 1e-12 * scale * (2.0 * PI * (m.max(n) as f64)).powi((p + q) as i32);
                for (a, b) in fft.values.iter().zip(&sums.values) {
                    assert!(
                        (*a - *b).length() < tol,
                        "{m}×{n} → {n_u}×{n_v}, order ({p}, {q}): {a} vs {b}"
                    );
                }
            }
        }
    }
}

/// The one-pass (p, pᵤ, pᵥ) of the spectrum, on a grid small enough for its stack row and on
/// one too large for it (degree ≥ 64 in v), against the general derivative and the direct sum.
#[test]
fn eval_with_partials_matches_the_derivatives() {
    for (m, n) in [(6usize, 9usize), (11, 140)] {
        let grid: Vec<Vec<DVec3>> = (0..m)
            .map(|j| {
                (0..n)
                    .map(|k| {
                        let (a, b) = (j as f64, k as f64);
                        DVec3::new(
                            (0.7 * a + 0.3 * b).sin(),
                            (1.1 * a).cos() + 0.01 * b,
                            (a * b).sin(),
                        )
                    })
                    .collect()
            })
            .collect();
        let s = HarmonicSurface::try_new(grid).expect("finite grid");
        for (u, v) in [(0.1, 0.2), (0.77, 0.31), (0.5, 0.0), (-3.25, 7.9)] {
            let (p, pu, pv) = s.eval_with_partials(u, v);
            assert!((p - s.eval(u, v)).length() < 1e-11, "p at {m}×{n}");
            assert!((pu - s.eval_deriv(u, v, 1, 0)).length() < 1e-9, "pu at {m}×{n}");
            assert!((pv - s.eval_deriv(u, v, 0, 1)).length() < 1e-9, "pv at {m}×{n}");
        }
    }
}
