// SPDX-License-Identifier: MIT
//! The B-spline surface fit of Hardy 2005, §4.4 (Watt & Watt's curve network): the surface
//! passes through every data point and contains every U-curve; knot insertion keeps curves;
//! the exact Bézier patches agree with the B-spline; Adini's patches keep the network and are
//! exact where the twist estimate is; closed directions are periodic; bad input is an error.
//!
//! Expected values come from the data, from `hi_curve`'s independent B-spline evaluator, from
//! Boehm's insertion formula written out here, from finite differences, or from algebra.

use glam::DVec3;
use hi_compare::Error;
use hi_compare::bspline::BSplineCurve;
use hi_compare::bspline_fit::{
    BSplineFit, BSplineFitOptions, BSplineSurface, EndCondition, Parameters, insert_knots,
};
use hi_curve::Error as CurveError;
use hi_testkit::proptest_config;
use proptest::prelude::*;

/// A bumpy open surface cut into `n_slices` slices of different lengths and uneven spacing.
fn bumpy_slices(n_slices: usize) -> Vec<Vec<DVec3>> {
    (0..n_slices)
        .map(|s| {
            let y = s as f64 * 0.8 + 0.1 * (s as f64).sin();
            let n = 5 + (s * 3) % 4;
            (0..n)
                .map(|k| {
                    let t = k as f64 / (n - 1) as f64;
                    let x = 4.0 * t + 0.15 * (3.0 * t + s as f64).sin();
                    let z = 0.6 * (1.3 * x).sin() * (0.9 * y).cos() + 0.1 * x;
                    DVec3::new(x, y + 0.05 * x, z)
                })
                .collect()
        })
        .collect()
}

/// Slices of a torus-like closed tube: closed slices (circles), and the slices go round.
fn tube_slices(n_slices: usize, n_points: usize) -> Vec<Vec<DVec3>> {
    (0..n_slices)
        .map(|s| {
            let a = std::f64::consts::TAU * s as f64 / n_slices as f64;
            let r = 0.5 + 0.1 * (2.0 * a).cos();
            (0..n_points)
                .map(|k| {
                    let b =
                        std::f64::consts::TAU * (k as f64 + 0.2 * (s % 2) as f64) / n_points as f64;
                    let rho = 2.0 + r * b.cos();
                    DVec3::new(rho * a.cos(), rho * a.sin(), r * b.sin())
                })
                .collect()
        })
        .collect()
}

fn size(slices: &[Vec<DVec3>]) -> f64 {
    slices.iter().flatten().fold(0.0f64, |m, p| m.max(p.length())).max(1.0)
}

/// Largest distance of a data point from the surface at its parameters.
fn interpolation_error(fit: &BSplineFit) -> f64 {
    let mut worst = 0.0f64;
    for (s, slice) in fit.slices().iter().enumerate() {
        for (k, x) in slice.iter().enumerate() {
            let p = fit.surface().eval(fit.u_params()[s][k], fit.v_params()[s]);
            worst = worst.max(p.distance(*x));
        }
    }
    worst
}

fn options(closed_u: bool, closed_v: bool) -> BSplineFitOptions {
    BSplineFitOptions { closed_u, closed_v, ..BSplineFitOptions::default() }
}

#[test]
fn every_data_point_is_on_the_surface() {
    let open = bumpy_slices(6);
    for end in [EndCondition::Natural, EndCondition::NotAKnot, EndCondition::Coincident] {
        let opts = BSplineFitOptions { end_u: end, end_v: end, ..BSplineFitOptions::default() };
        let fit = BSplineFit::try_new(open.clone(), &opts).unwrap();
        let err = interpolation_error(&fit);
        assert!(err < 1e-12 * size(&open), "{end:?}: {err:e}");
    }
    let tube = tube_slices(7, 9);
    for (cu, cv) in [(true, true), (true, false), (false, true)] {
        let fit = BSplineFit::try_new(tube.clone(), &options(cu, cv)).unwrap();
        let err = interpolation_error(&fit);
        assert!(err < 1e-12 * size(&tube), "closed ({cu}, {cv}): {err:e}");
    }
}

#[test]
fn the_surface_contains_every_u_curve_and_the_v_curves_are_its_knot_lines() {
    let slices = bumpy_slices(5);
    let fit = BSplineFit::try_new(slices.clone(), &BSplineFitOptions::default()).unwrap();
    let surface = fit.surface();
    let scale = size(&slices);
    // U-curves evaluated by hi-curve's own B-spline code, on their own knots and merged.
    for (s, (own, merged)) in fit.u_curves().iter().zip(fit.merged_u_curves()).enumerate() {
        assert!(merged.knots().len() >= own.knots().len(), "merging only adds knots");
        for step in 0..=50 {
            let u = step as f64 / 50.0;
            let d = surface.eval(u, fit.v_params()[s]).distance(own.eval(u));
            assert!(d < 1e-12 * scale, "slice {s}, u = {u}: {d:e}");
            assert!(merged.eval(u).distance(own.eval(u)) < 1e-12 * scale, "knot insertion");
        }
    }
    // The merged knots are the union of the slices' knots.
    let knots = fit.u_knots();
    for curve in fit.u_curves() {
        assert!(curve.knots().iter().all(|k| knots.contains(k)), "union");
    }
    // The V-curves pass through the U-curves at the U-knots, at the slice parameters.
    let v_curves = fit.v_curves();
    assert_eq!(v_curves.len(), knots.len());
    for (curve, &u) in v_curves.iter().zip(&knots) {
        for (s, own) in fit.u_curves().iter().enumerate() {
            let d = curve.eval(fit.v_params()[s]).distance(own.eval(u));
            assert!(d < 1e-12 * scale, "V-curve at u = {u}, slice {s}: {d:e}");
        }
        for step in 0..=20 {
            let v = step as f64 / 20.0;
            assert!(curve.eval(v).distance(surface.eval(u, v)) < 1e-12 * scale, "iso-curve");
        }
    }
}

#[test]
fn partial_derivatives_match_difference_quotients() {
    let fit = BSplineFit::try_new(bumpy_slices(5), &BSplineFitOptions::default()).unwrap();
    let s = fit.surface();
    let h = 1e-5;
    for (u, v) in [(0.13, 0.4), (0.52, 0.77), (0.9, 0.05)] {
        for (a, b) in [(1, 0), (0, 1), (1, 1), (2, 0), (0, 2), (2, 1)] {
            let exact = s.eval_deriv(u, v, a, b);
            let fd = if a > 0 {
                (s.eval_deriv(u + h, v, a - 1, b) - s.eval_deriv(u - h, v, a - 1, b)) / (2.0 * h)
            } else {
                (s.eval_deriv(u, v + h, a, b - 1) - s.eval_deriv(u, v - h, a, b - 1)) / (2.0 * h)
            };
            assert!(exact.distance(fd) < 1e-4 * (1.0 + exact.length()), "({a}, {b}) at ({u}, {v})");
        }
        assert_eq!(s.eval_deriv(u, v, 4, 0), DVec3::ZERO);
    }
}

#[test]
fn closed_directions_are_periodic_and_c2_across_the_seam() {
    let fit = BSplineFit::try_new(tube_slices(6, 8), &options(true, true)).unwrap();
    let s = fit.surface();
    for (u, v) in [(0.1, 0.2), (0.55, 0.9), (0.0, 0.0)] {
        assert!(s.eval(u + 1.0, v).distance(s.eval(u, v)) < 1e-12, "u period");
        assert!(s.eval(u, v - 2.0).distance(s.eval(u, v)) < 1e-12, "v period");
    }
    // Across the seam u = 0: both sides of every derivative up to the second agree.
    let eps = 1e-9;
    for (a, b) in [(0, 0), (1, 0), (2, 0), (1, 1)] {
        let left = s.eval_deriv(1.0 - eps, 0.3, a, b);
        let right = s.eval_deriv(eps, 0.3, a, b);
        assert!(left.distance(right) < 1e-6 * (1.0 + left.length()), "order ({a}, {b})");
    }
}

#[test]
fn exact_bezier_patches_agree_with_the_bspline() {
    let cases = [
        (bumpy_slices(6), options(false, false)),
        (tube_slices(6, 7), options(true, true)),
        (tube_slices(5, 6), options(true, false)),
    ];
    for (slices, opts) in cases {
        let fit = BSplineFit::try_new(slices.clone(), &opts).unwrap();
        let s = fit.surface();
        let patches = s.to_bezier_patches();
        assert_eq!(patches.n_u(), s.u_breakpoints().len() - 1);
        assert_eq!(patches.n_v(), s.v_breakpoints().len() - 1);
        let mut worst = 0.0f64;
        for i in 0..=97 {
            for l in 0..=89 {
                let (u, v) = (i as f64 / 97.0, l as f64 / 89.0);
                worst = worst.max(patches.eval(u, v).distance(s.eval(u, v)));
            }
        }
        assert!(worst < 1e-12 * size(&slices), "{worst:e}");
        // Neighbouring patches share their boundary control points (C⁰ at least).
        for i in 0..patches.n_u() - 1 {
            let (a, b) = (patches.patch(i, 0).unwrap(), patches.patch(i + 1, 0).unwrap());
            for k in 0..4 {
                let d = a.control_point(3, k).unwrap().distance(b.control_point(0, k).unwrap());
                assert!(d < 1e-12 * size(&slices), "shared boundary");
            }
        }
    }
}

/// Largest distance between corresponding control points of two patch grids.
fn patch_distance(a: &hi_compare::BezierPatchGrid, b: &hi_compare::BezierPatchGrid) -> f64 {
    a.patches()
        .iter()
        .zip(b.patches())
        .flat_map(|(p, q)| {
            p.control_points().iter().zip(q.control_points()).map(|(x, y)| x.distance(*y))
        })
        .fold(0.0, f64::max)
}

#[test]
fn adini_patches_keep_the_network_and_approximate_the_surface() {
    let slices = bumpy_slices(6);
    let fit = BSplineFit::try_new(slices.clone(), &BSplineFitOptions::default()).unwrap();
    let s = fit.surface();
    let (exact, adini) = (s.to_bezier_patches(), s.to_adini_patches());
    let scale = size(&slices);
    let mut interior = 0.0f64;
    for (p, q) in exact.patches().iter().zip(adini.patches()) {
        for j in 0..4 {
            for k in 0..4 {
                let d = p.control_point(j, k).unwrap().distance(q.control_point(j, k).unwrap());
                if (1..=2).contains(&j) && (1..=2).contains(&k) {
                    interior = interior.max(d);
                } else {
                    assert!(d < 1e-12 * scale, "boundary point ({j}, {k}) moved by {d:e}");
                }
            }
        }
    }
    // The corners interpolate the network nodes, the data among them.
    for (i, &u) in adini.u_breaks().iter().enumerate() {
        for (l, &v) in adini.v_breaks().iter().enumerate() {
            let d = adini.eval(u, v).distance(s.eval(u, v));
            assert!(d < 1e-12 * scale, "node ({i}, {l})");
        }
    }
    // The surface deviation, measured (the interiors are estimates, not exact).
    let mut deviation = 0.0f64;
    for i in 0..=60 {
        for l in 0..=60 {
            let (u, v) = (i as f64 / 60.0, l as f64 / 60.0);
            deviation = deviation.max(adini.eval(u, v).distance(s.eval(u, v)));
        }
    }
    eprintln!(
        "Adini patches, bumpy surface of 6 slices: interior control points off by {interior:.3e}, \
         surface by {deviation:.3e} (size {scale:.2})"
    );
    assert!(deviation > 1e-8 && deviation < 0.02 * scale, "deviation {deviation:e}");
}

#[test]
fn adini_deviation_shrinks_with_the_knot_spacing() {
    // A smooth surface sampled on finer and finer grids: the twist estimate is O(h²), the
    // interior points O(h⁴) (h the spacing).
    let sample = |n: usize| -> f64 {
        let slices: Vec<Vec<DVec3>> = (0..n)
            .map(|s| {
                let v = s as f64 / (n - 1) as f64;
                (0..n)
                    .map(|k| {
                        let u = k as f64 / (n - 1) as f64;
                        DVec3::new(u, v, (2.0 * u).sin() * (1.5 * v).cos() + u * u * v)
                    })
                    .collect()
            })
            .collect();
        let opts = BSplineFitOptions {
            u_params: Parameters::Uniform,
            v_params: Parameters::Uniform,
            ..BSplineFitOptions::default()
        };
        let fit = BSplineFit::try_new(slices, &opts).unwrap();
        let s = fit.surface();
        patch_distance(&s.to_bezier_patches(), &s.to_adini_patches())
    };
    let (coarse, fine) = (sample(9), sample(17));
    eprintln!("Adini interior points off by {coarse:.3e} (h = 1/8), {fine:.3e} (h = 1/16)");
    assert!(fine < coarse / 8.0, "{coarse:e} → {fine:e}");
}

#[test]
fn adini_is_exact_for_translational_and_bilinear_surfaces() {
    let us = [0.0, 0.15, 0.4, 0.55, 0.8, 1.0];
    let vs = [0.0, 0.3, 0.45, 0.7, 1.0];
    let opts = BSplineFitOptions {
        u_params: Parameters::Given(us.to_vec()),
        v_params: Parameters::Given(vs.to_vec()),
        ..BSplineFitOptions::default()
    };
    let translational = |u: f64, v: f64| DVec3::new(u, v, (3.0 * u).sin() + (2.0 * v).cos());
    let (a, b, c, d) = (DVec3::new(1.0, 0.0, 0.5), DVec3::X, DVec3::Y, DVec3::new(0.3, -0.2, 2.0));
    let bilinear = |u: f64, v: f64| a + b * u + c * v + d * (u * v);
    for (name, f) in
        [("translational", &translational as &dyn Fn(f64, f64) -> DVec3), ("bilinear", &bilinear)]
    {
        let slices: Vec<Vec<DVec3>> =
            vs.iter().map(|&v| us.iter().map(|&u| f(u, v)).collect()).collect();
        let fit = BSplineFit::try_new(slices, &opts).unwrap();
        let s = fit.surface();
        let d = patch_distance(&s.to_bezier_patches(), &s.to_adini_patches());
        assert!(d < 1e-12, "{name}: {d:e}");
    }
    // Natural splines reproduce linear data, so the bilinear surface is reproduced exactly,
    // twist d everywhere.
    let slices: Vec<Vec<DVec3>> =
        vs.iter().map(|&v| us.iter().map(|&u| bilinear(u, v)).collect()).collect();
    let fit = BSplineFit::try_new(slices, &opts).unwrap();
    for (u, v) in [(0.1, 0.9), (0.33, 0.5), (0.77, 0.21)] {
        assert!(fit.surface().eval(u, v).distance(bilinear(u, v)) < 1e-13, "bilinear");
        assert!(fit.surface().eval_deriv(u, v, 1, 1).distance(d) < 1e-12, "twist");
    }
    for row in fit.surface().adini_twists() {
        for t in row {
            assert!(t.distance(d) < 1e-12, "Adini twist {t} vs {d}");
        }
    }
}

#[test]
fn knot_insertion_leaves_curves_unchanged() {
    let control: Vec<DVec3> = (0..7)
        .map(|i| DVec3::new(i as f64, ((i * i) % 5) as f64, (i as f64 * 0.7).sin()))
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.2, 0.5, 0.6, 1.0, 1.0, 1.0, 1.0];
    let curve = BSplineCurve::try_new(3, knots.clone(), control.clone()).unwrap();
    let finer = insert_knots(&curve, &[0.1, 0.5, 0.75, 0.75]).unwrap();
    assert_eq!(finer.control_points().len(), 11);
    assert_eq!(
        finer.knots(),
        &[0.0, 0.0, 0.0, 0.0, 0.1, 0.2, 0.5, 0.5, 0.6, 0.75, 0.75, 1.0, 1.0, 1.0, 1.0]
    );
    for step in 0..=200 {
        let t = step as f64 / 200.0;
        assert!(finer.eval(t).distance(curve.eval(t)) < 1e-13, "t = {t}");
    }
    // One insertion by Boehm's formula, written out: ū = 0.3 in [u₄, u₅) = [0.2, 0.5), p = 3:
    // Qᵢ = (1 − αᵢ)Pᵢ₋₁ + αᵢPᵢ for i = 2, 3, 4, αᵢ = (ū − uᵢ)/(uᵢ₊₃ − uᵢ).
    let ubar = 0.3;
    let once = insert_knots(&curve, &[ubar]).unwrap();
    let mut boehm = control[..2].to_vec();
    for i in 2..=4 {
        let alpha = (ubar - knots[i]) / (knots[i + 3] - knots[i]);
        boehm.push(control[i - 1] * (1.0 - alpha) + control[i] * alpha);
    }
    boehm.extend_from_slice(&control[4..]);
    for (q, b) in once.control_points().iter().zip(&boehm) {
        assert!(q.distance(*b) < 1e-14, "Boehm");
    }
    // Closed curves: breakpoints inserted anywhere in the period, the seam included.
    let closed = BSplineCurve::try_new_periodic(
        3,
        vec![0.0, 0.2, 0.45, 0.6, 0.9, 1.0],
        control[..5].to_vec(),
    )
    .unwrap();
    let finer = insert_knots(&closed, &[0.0, 0.05, 0.5, 0.95]).unwrap();
    assert_eq!(finer.control_points().len(), 9);
    for step in 0..=200 {
        let t = step as f64 / 200.0;
        assert!(finer.eval(t).distance(closed.eval(t)) < 1e-13, "closed, t = {t}");
    }
    // Errors, not panics.
    assert!(matches!(insert_knots(&curve, &[1.5]), Err(Error::InvalidValue { .. })));
    assert!(matches!(
        insert_knots(&curve, &[f64::NAN]),
        Err(Error::Curve(CurveError::NonFiniteParameter { .. }))
    ));
    assert!(matches!(
        insert_knots(&curve, &[0.5, 0.5, 0.5]),
        Err(Error::Curve(CurveError::InvalidCount { .. }))
    ));
    assert!(matches!(insert_knots(&closed, &[1.0]), Err(Error::InvalidValue { .. })));
    let quadratic =
        BSplineCurve::try_new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], control[..3].to_vec())
            .unwrap();
    assert!(matches!(
        insert_knots(&quadratic, &[0.5]),
        Err(Error::Curve(CurveError::InvalidCount { .. }))
    ));
}

#[test]
fn bad_input_is_an_error_naming_the_problem() {
    let ok = bumpy_slices(3);
    let fit = |slices: Vec<Vec<DVec3>>, opts: &BSplineFitOptions| BSplineFit::try_new(slices, opts);
    let default = BSplineFitOptions::default();
    assert_eq!(fit(vec![], &default), Err(Error::TooFewSlices { needed: 2, got: 0 }));
    assert_eq!(fit(ok[..1].to_vec(), &default), Err(Error::TooFewSlices { needed: 2, got: 1 }));
    assert_eq!(
        fit(ok[..2].to_vec(), &options(false, true)),
        Err(Error::TooFewSlices { needed: 3, got: 2 })
    );
    let mut short = ok.clone();
    short[1].truncate(1);
    assert_eq!(fit(short, &default), Err(Error::TooFewSlicePoints { slice: 1, needed: 2, got: 1 }));
    let mut two = ok.clone();
    two[2].truncate(2);
    assert_eq!(
        fit(two, &options(true, false)),
        Err(Error::TooFewSlicePoints { slice: 2, needed: 3, got: 2 })
    );
    let mut nan = ok.clone();
    nan[2][3].y = f64::NAN;
    let err = fit(nan, &default).unwrap_err();
    assert_eq!(err, Error::NonFiniteSlicePoint { slice: 2, point: 3 });
    assert!(err.to_string().contains("slice 2, point 3"), "{err}");
    let mut inf = ok.clone();
    inf[0][0].z = f64::INFINITY;
    assert_eq!(fit(inf, &default), Err(Error::NonFiniteSlicePoint { slice: 0, point: 0 }));
    let mut dup = ok.clone();
    dup[1][3] = dup[1][2];
    assert_eq!(
        fit(dup, &default),
        Err(Error::CoincidentSlicePoints { slice: 1, first: 2, second: 3 })
    );
    let mut closing = tube_slices(4, 5);
    let first = closing[3][0];
    closing[3].push(first);
    assert_eq!(
        fit(closing, &options(true, true)),
        Err(Error::CoincidentSlicePoints { slice: 3, first: 5, second: 0 })
    );
    let same = vec![ok[0].clone(), ok[0].clone(), ok[1].clone()];
    assert_eq!(fit(same, &default), Err(Error::CoincidentSlices { first: 0, second: 1 }));
    let given = BSplineFitOptions {
        u_params: Parameters::Given(vec![0.0, 0.5, 1.0, 1.5, 2.0]),
        ..BSplineFitOptions::default()
    };
    let err = fit(ok.clone(), &given).unwrap_err();
    assert!(matches!(err, Error::SliceLengthMismatch { slice: 1, len: 8, expected: 5 }), "{err}");
    let bad_v = BSplineFitOptions {
        v_params: Parameters::Given(vec![0.0, 0.5, 0.5]),
        ..BSplineFitOptions::default()
    };
    assert!(
        matches!(
            fit(ok.clone(), &bad_v),
            Err(Error::Curve(CurveError::ParametersNotDistinct { .. })
                | Error::ParametersNotIncreasing { .. })
        ),
        "repeated v parameter"
    );
    let not_a_knot =
        BSplineFitOptions { end_v: EndCondition::NotAKnot, ..BSplineFitOptions::default() };
    assert_eq!(fit(ok, &not_a_knot), Err(Error::TooFewSlices { needed: 4, got: 3 }));
    // The surface constructor.
    let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let net = vec![vec![DVec3::ZERO; 4]; 4];
    assert!(
        BSplineSurface::try_new(knots.clone(), false, knots.clone(), false, net.clone()).is_ok()
    );
    assert_eq!(
        BSplineSurface::try_new(knots.clone(), false, knots.clone(), false, vec![]),
        Err(Error::EmptyGrid)
    );
    let mut ragged = net.clone();
    ragged[2].pop();
    assert!(matches!(
        BSplineSurface::try_new(knots.clone(), false, knots.clone(), false, ragged),
        Err(Error::RaggedGrid { row: 2, len: 3, expected: 4 })
    ));
    let mut bad = net.clone();
    bad[1][2] = DVec3::NAN;
    assert_eq!(
        BSplineSurface::try_new(knots.clone(), false, knots.clone(), false, bad),
        Err(Error::NonFiniteGridPoint { row: 1, col: 2 })
    );
    assert!(matches!(
        BSplineSurface::try_new(knots[1..].to_vec(), false, knots, false, net),
        Err(Error::Curve(CurveError::InvalidCount { .. }))
    ));
}

#[test]
fn meshes_sample_the_surface() {
    let fit = BSplineFit::try_new(bumpy_slices(4), &BSplineFitOptions::default()).unwrap();
    let mesh = fit.surface().to_mesh(10, 6).unwrap();
    assert_eq!((mesh.n_vertices(), mesh.n_triangles()), (11 * 7, 2 * 10 * 6));
    assert!(mesh.positions()[0].distance(fit.slices()[0][0]) < 1e-12, "corner = data corner");
    let tube = BSplineFit::try_new(tube_slices(5, 6), &options(true, true)).unwrap();
    let mesh = tube.surface().to_mesh(12, 8).unwrap();
    assert_eq!((mesh.n_vertices(), mesh.n_triangles()), (12 * 8, 2 * 12 * 8), "welded seams");
    assert!(matches!(
        tube.surface().to_mesh(2, 8),
        Err(Error::Curve(CurveError::InvalidCount { .. }))
    ));
    assert!(matches!(
        fit.surface().to_mesh(0, 8),
        Err(Error::Curve(CurveError::InvalidCount { .. }))
    ));
}

proptest! {
    #![proptest_config(proptest_config(48))]

    /// Random slices of random lengths over a jittered grid: the fit interpolates every point
    /// and its exact Bézier patches agree with it.
    #[test]
    fn random_slices_are_interpolated(
        heights in prop::collection::vec(prop::collection::vec(-2.0f64..2.0, 2..8), 2..6),
        jitter in -0.3f64..0.3,
        closed_u in any::<bool>(),
    ) {
        let slices: Vec<Vec<DVec3>> = heights
            .iter()
            .enumerate()
            .map(|(s, row)| {
                let n = row.len().max(3);
                (0..n)
                    .map(|k| {
                        let z = row[k % row.len()];
                        if closed_u {
                            let a = std::f64::consts::TAU * k as f64 / n as f64;
                            DVec3::new(a.cos() * (1.0 + 0.2 * z), a.sin(), s as f64 + 0.1 * z)
                        } else {
                            DVec3::new(k as f64 + jitter * (s as f64).sin(), s as f64, z)
                        }
                    })
                    .collect()
            })
            .collect();
        let fit = BSplineFit::try_new(slices.clone(), &options(closed_u, false)).unwrap();
        let scale = size(&slices);
        prop_assert!(interpolation_error(&fit) < 1e-10 * scale);
        let patches = fit.surface().to_bezier_patches();
        for i in 0..=13 {
            for l in 0..=11 {
                let (u, v) = (i as f64 / 13.0, l as f64 / 11.0);
                let d = patches.eval(u, v).distance(fit.surface().eval(u, v));
                prop_assert!(d < 1e-11 * scale, "({u}, {v}): {d:e}");
            }
        }
    }
}
