// SPDX-License-Identifier: MIT
//! Harmonic surfaces as Bézier patches (§5.7, `hi_surface::bezier`): the thesis's patches
//! interpolate the surface at 4×4 nodes per patch and pass through the data, the Hermite
//! patches are C1 and within the tolerance, and no measured deviation exceeds its bound.

use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_surface::{Error, HarmonicSurface, torus};
use hi_testkit::proptest_config;
use proptest::prelude::*;

/// A bumpy m×n closed surface: a torus with a deterministic ripple.
fn bumpy(m: usize, n: usize, seed: f64) -> HarmonicSurface<DVec3> {
    let rows = (0..m)
        .map(|j| {
            (0..n)
                .map(|k| {
                    let (u, v) = (j as f64 / m as f64, k as f64 / n as f64);
                    let (tu, tv) = (std::f64::consts::TAU * u, std::f64::consts::TAU * v);
                    let r = 1.0 + 0.3 * (3.0 * tu + seed).sin() * (2.0 * tv).cos();
                    DVec3::new(
                        (3.0 + r * tv.cos()) * tu.cos(),
                        (3.0 + r * tv.cos()) * tu.sin(),
                        r * tv.sin(),
                    )
                })
                .collect()
        })
        .collect();
    HarmonicSurface::new(rows)
}

#[test]
fn thesis_cubic_patches_interpolate_the_surface_at_sixteen_nodes_each() {
    let s = bumpy(5, 6, 0.3);
    let b = s
        .to_bezier(BezierScheme::ThesisCubic, hi_curve::bezier::DEFAULT_TOLERANCE)
        .expect("converts");
    assert_eq!(b.report.patches, 30, "m×n patches");
    assert_eq!(b.report.degree, (3, 3), "bicubic");
    for a in 0..5 {
        for c in 0..6 {
            let patch = &b.patches[a * 6 + c];
            for i in 0..4 {
                for j in 0..4 {
                    let (s0, t0) = (f64::from(i) / 3.0, f64::from(j) / 3.0);
                    let (u, v) = ((a as f64 + s0) / 5.0, (c as f64 + t0) / 6.0);
                    let d = (patch.eval(s0, t0) - s.eval(u, v)).length();
                    assert!(d < 1e-12, "patch ({a}, {c}) node ({i}, {j}): {d:e}");
                }
            }
        }
    }
    // The data points are patch corners.
    for j in 0..5 {
        for k in 0..6 {
            let d = (b.eval(j as f64 / 5.0, k as f64 / 6.0) - s.point(j, k)).length();
            assert!(d < 1e-13, "point ({j}, {k}): {d:e}");
        }
    }
    assert!(b.report.max_normal_jump > 1e-4, "the thesis patches are C0 only: {:?}", b.report);
    assert!(b.report.max_deviation <= b.report.bound, "{:?}", b.report);
}

#[test]
fn thesis_cubic_patches_are_affine_invariant() {
    let s = bumpy(4, 4, 1.0);
    let shift = DVec3::new(1.5, -2.0, 0.25);
    let moved = HarmonicSurface::new(
        s.rows().into_iter().map(|r| r.into_iter().map(|p| 2.0 * p + shift).collect()).collect(),
    );
    let (b0, b1) = (
        s.to_bezier(BezierScheme::ThesisCubic, hi_curve::bezier::DEFAULT_TOLERANCE)
            .expect("converts"),
        moved
            .to_bezier(BezierScheme::ThesisCubic, hi_curve::bezier::DEFAULT_TOLERANCE)
            .expect("converts"),
    );
    for (p, q) in b0.patches.iter().zip(&b1.patches) {
        for (x, y) in p.control_points().iter().zip(q.control_points()) {
            assert!((2.0 * *x + shift - *y).length() < 1e-12, "control points move with the grid");
        }
    }
}

#[test]
fn hermite_patches_are_c1_and_within_the_tolerance() {
    let s = bumpy(6, 8, 0.7);
    for (degree, tol) in [(HermiteDegree::Cubic, 1e-3), (HermiteDegree::Quintic, 1e-5)] {
        let b = s
            .to_bezier(BezierScheme::Hermite(degree), hi_curve::bezier::Tolerance::Absolute(tol))
            .expect("converts");
        let r = b.report;
        assert!(r.bound <= tol, "{degree:?}: {r:?}");
        assert!(r.max_deviation <= r.bound, "{degree:?}: {r:?}");
        assert!(r.max_normal_jump < 1e-7, "{degree:?}: C1 {r:?}");
        let (nu, nv) = (b.u_breaks.len() - 1, b.v_breaks.len() - 1);
        assert_eq!(nu % 6, 0, "the data grid lines are patch edges");
        assert_eq!(nv % 8, 0, "the data grid lines are patch edges");
        // ∂p/∂u across every u-edge, from both patches, in surface parameters.
        let hu = 1.0 / nu as f64;
        for a in 0..nu {
            for c in 0..nv {
                let (left, right) = (&b.patches[a * nv + c], &b.patches[((a + 1) % nu) * nv + c]);
                for x in [0.0, 0.3, 1.0] {
                    let (_, lu, _) = left.eval_with_partials(1.0, x);
                    let (_, ru, _) = right.eval_with_partials(0.0, x);
                    assert!(
                        (lu - ru).length() / hu < 1e-8 * s.deriv_bound(1, 0),
                        "{degree:?} C1 at ({a}, {c})"
                    );
                }
            }
        }
        for j in 0..6 {
            for k in 0..8 {
                let d = (b.eval(j as f64 / 6.0, k as f64 / 8.0) - s.point(j, k)).length();
                assert!(d < 1e-12, "{degree:?}: data point ({j}, {k}) off by {d:e}");
            }
        }
    }
}

#[test]
fn the_thesis_quintic_patches_stay_within_their_bound() {
    let s = torus(2.0, 1.0);
    let b = s
        .to_bezier(BezierScheme::ThesisQuintic, hi_curve::bezier::DEFAULT_TOLERANCE)
        .expect("converts");
    assert_eq!(b.report.degree, (5, 5), "biquintic");
    assert!(b.report.max_deviation <= b.report.bound, "{:?}", b.report);
    let cubic = s
        .to_bezier(BezierScheme::ThesisCubic, hi_curve::bezier::DEFAULT_TOLERANCE)
        .expect("converts");
    assert!(b.report.max_deviation < cubic.report.max_deviation, "closer than the cubic");
}

#[test]
fn patches_tessellate_with_one_colour_each_and_write_obj_free_form() {
    let s = torus(2.0, 1.0);
    let b = s
        .to_bezier(BezierScheme::ThesisCubic, hi_curve::bezier::DEFAULT_TOLERANCE)
        .expect("converts");
    let mesh = b.to_triangle_mesh(6).expect("mesh");
    assert_eq!(mesh.n_vertices(), 16 * 49, "(k + 1)² vertices per patch");
    assert_eq!(mesh.n_triangles(), 16 * 72, "2k² triangles per patch");
    let colors = mesh.colors().expect("coloured");
    let mut distinct: Vec<[u32; 3]> = colors.chunks(49).map(|c| c[0].map(f32::to_bits)).collect();
    assert!(colors.chunks(49).all(|c| c.iter().all(|x| *x == c[0])), "one colour per patch");
    distinct.sort_unstable();
    distinct.dedup();
    assert_eq!(distinct.len(), 16, "every patch its own colour");
    for (p, uv) in mesh.positions().iter().zip(mesh.uvs()) {
        assert!((*p - b.eval(uv.x, uv.y)).length() < 1e-12, "UVs are the surface parameters");
    }
    assert!(b.to_triangle_mesh(0).is_err(), "k = 0");

    let mut obj = Vec::new();
    b.write_obj(&mut obj).expect("writes");
    let text = String::from_utf8(obj).expect("UTF-8");
    let vertices: Vec<DVec3> = text
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let c: Vec<f64> = l.split_whitespace().map(|x| x.parse().expect("number")).collect();
            DVec3::new(c[0], c[1], c[2])
        })
        .collect();
    assert_eq!(vertices.len(), 16 * 16, "16 control points per patch");
    assert_eq!(text.matches("cstype bezier").count(), 16, "one surface per patch");
    // Read back patch 5 from its `surf` line (u fastest) and compare with the patch.
    let surf: Vec<usize> = text
        .lines()
        .filter(|l| l.starts_with("surf "))
        .nth(5)
        .expect("patch 5")
        .split_whitespace()
        .skip(5)
        .map(|i| i.parse().expect("index"))
        .collect();
    let rows = b.patches[5].rows();
    for (n, &i) in surf.iter().enumerate() {
        let (iu, iv) = (n % 4, n / 4);
        assert_eq!(vertices[i - 1], rows[iu][iv], "control point ({iu}, {iv})");
    }
}

#[test]
fn bad_tolerances_and_small_grids_are_errors() {
    let s = torus(2.0, 1.0);
    let hermite = BezierScheme::Hermite(HermiteDegree::Cubic);
    assert!(matches!(
        s.to_bezier(hermite, hi_curve::bezier::Tolerance::Absolute(-1.0)),
        Err(Error::InvalidValue { .. })
    ));
    assert!(matches!(
        s.to_bezier(hermite, hi_curve::bezier::Tolerance::Absolute(f64::INFINITY)),
        Err(Error::NonFiniteParameter { .. })
    ));
    let small = bumpy(2, 5, 0.0);
    assert!(matches!(
        small.to_bezier(BezierScheme::ThesisQuintic, hi_curve::bezier::DEFAULT_TOLERANCE),
        Err(Error::Curve(_))
    ));
    assert!(matches!(
        s.to_bezier(hermite, hi_curve::bezier::Tolerance::Absolute(1e-300)),
        Err(Error::InvalidCount { .. })
    ));
}

proptest! {
    #![proptest_config(proptest_config(12))]

    #[test]
    fn hermite_bounds_hold_on_random_surfaces(
        m in 3usize..7,
        n in 3usize..7,
        seed in 0.0f64..6.0,
        exp in 2i32..5,
    ) {
        let s = bumpy(m, n, seed);
        let tol = 10f64.powi(-exp);
        let b = s.to_bezier(BezierScheme::Hermite(HermiteDegree::Cubic), hi_curve::bezier::Tolerance::Absolute(tol)).unwrap();
        prop_assert!(b.report.bound <= tol);
        prop_assert!(b.report.max_deviation <= b.report.bound);
    }
}
