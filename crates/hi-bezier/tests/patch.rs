// SPDX-License-Identifier: MIT
//! Tensor-product and rational patches (§4.3, figure 4.2) against the explicit double
//! Bernstein sum, finite differences, exact quadric surfaces (sphere octant, cylinder) and
//! dense sampling.

mod common;

use std::f64::consts::FRAC_PI_2;

use common::bernstein;
use glam::{DVec2, DVec3};
use hi_bezier::{
    Aabb, BezierPatch, Error, ParamRange, ParamWindow, RationalBezierCurve, RationalBezierPatch,
    SmallPatch,
};

/// A bumpy patch of degree (3, 4).
fn bumpy() -> BezierPatch<DVec3> {
    BezierPatch::try_from_fn(3, 4, |j, k| {
        DVec3::new(
            j as f64 + 0.1 * k as f64,
            k as f64 - 0.2 * j as f64,
            ((j * 5 + k * 3) % 4) as f64 * 0.5,
        )
    })
    .unwrap()
}

/// Σⱼ Σₖ Bᵐⱼ(u)·Bⁿₖ(v)·xⱼₖ, explicitly.
fn double_sum(p: &BezierPatch<DVec3>, u: f64, v: f64) -> DVec3 {
    let (m, n) = (p.degree_u(), p.degree_v());
    let mut res = DVec3::ZERO;
    for j in 0..=m {
        for k in 0..=n {
            res += p.control_point(j, k).unwrap() * (bernstein(m, j, u) * bernstein(n, k, v));
        }
    }
    res
}

fn params() -> Vec<(f64, f64)> {
    let mut res = vec![];
    for a in 0..=6 {
        for b in 0..=6 {
            res.push((a as f64 / 6.0, b as f64 / 6.0));
        }
    }
    res
}

#[test]
fn evaluation_equals_the_double_sum() {
    let p = bumpy();
    for (u, v) in params() {
        assert!((p.eval(u, v) - double_sum(&p, u, v)).length() < 1e-13, "({u}, {v})");
    }
    // Corners interpolate, boundaries are the Bézier curves of the boundary rows and columns.
    assert_eq!(p.eval(0.0, 0.0), p.control_point(0, 0).unwrap());
    assert_eq!(p.eval(1.0, 1.0), p.control_point(3, 4).unwrap());
    let first_row = hi_bezier::BezierCurve::new(p.rows()[0].clone());
    assert_eq!(p.curve_at_u(0.0), first_row);
    for &t in &[0.2, 0.7] {
        assert!((p.curve_at_u(0.4).eval(t) - p.eval(0.4, t)).length() < 1e-14);
        assert!((p.curve_at_v(0.4).eval(t) - p.eval(t, 0.4)).length() < 1e-14);
    }
}

#[test]
fn partials_match_finite_differences() {
    let p = bumpy();
    let h = 1e-5;
    for &(u, v) in &[(0.3, 0.6), (0.5, 0.5), (0.85, 0.1)] {
        let f = |a: f64, b: f64| p.eval(a, b);
        let pu = (f(u + h, v) - f(u - h, v)) / (2.0 * h);
        let pv = (f(u, v + h) - f(u, v - h)) / (2.0 * h);
        let puv =
            (f(u + h, v + h) - f(u + h, v - h) - f(u - h, v + h) + f(u - h, v - h)) / (4.0 * h * h);
        let puu = (f(u + h, v) - 2.0 * f(u, v) + f(u - h, v)) / (h * h);
        assert!((p.eval_deriv(u, v, 1, 0) - pu).length() < 1e-8);
        assert!((p.eval_deriv(u, v, 0, 1) - pv).length() < 1e-8);
        assert!((p.eval_deriv(u, v, 1, 1) - puv).length() < 1e-4);
        assert!((p.eval_deriv(u, v, 2, 0) - puu).length() < 1e-3);
        // Third order in u from second-order partials.
        let p3 = (p.eval_deriv(u + h, v, 2, 1) - p.eval_deriv(u - h, v, 2, 1)) / (2.0 * h);
        assert!((p.eval_deriv(u, v, 3, 1) - p3).length() < 1e-6);
    }
    assert_eq!(p.eval_deriv(0.5, 0.5, 4, 0), DVec3::ZERO);
    assert_eq!(p.eval_deriv(0.5, 0.5, 0, 5), DVec3::ZERO);
}

#[test]
fn first_partials_are_the_thesis_difference_formulas() {
    // ∂p/∂u = m·Σ Bᵐ⁻¹ⱼ(u)Bⁿₖ(v)(xⱼ₊₁,ₖ − xⱼₖ) (§4.3), summed explicitly.
    let p = bumpy();
    let (m, n) = (3, 4);
    let (u, v) = (0.35, 0.8);
    let mut pu = DVec3::ZERO;
    for j in 0..m {
        for k in 0..=n {
            let d = p.control_point(j + 1, k).unwrap() - p.control_point(j, k).unwrap();
            pu += d * (m as f64 * bernstein(m - 1, j, u) * bernstein(n, k, v));
        }
    }
    assert!((p.eval_deriv(u, v, 1, 0) - pu).length() < 1e-13);
    assert_eq!(p.deriv_patch(1, 0).degree_u(), 2);
}

#[test]
fn one_pass_partials_agree() {
    let line =
        BezierPatch::try_from_fn(0, 2, |_, k| DVec3::new(k as f64, (k * k) as f64, 1.0)).unwrap();
    for p in [bumpy(), bumpy().transpose(), line.clone(), line.transpose()] {
        for (u, v) in params() {
            let (q, pu, pv) = p.eval_with_partials(u, v);
            assert!((q - p.eval(u, v)).length() < 1e-14);
            assert!((pu - p.eval_deriv(u, v, 1, 0)).length() < 1e-12);
            assert!((pv - p.eval_deriv(u, v, 0, 1)).length() < 1e-12);
        }
    }
}

#[test]
fn split_and_subpatch_reproduce() {
    let p = bumpy();
    let (a, b) = p.split_u(0.3);
    let (c, d) = p.split_v(0.6);
    let s = p.subpatch(ParamWindow::new(ParamRange::new(0.2, 0.7), ParamRange::new(0.9, 0.4)));
    for (u, v) in params() {
        assert!((a.eval(u, v) - p.eval(0.3 * u, v)).length() < 1e-13);
        assert!((b.eval(u, v) - p.eval(0.3 + 0.7 * u, v)).length() < 1e-13);
        assert!((c.eval(u, v) - p.eval(u, 0.6 * v)).length() < 1e-13);
        assert!((d.eval(u, v) - p.eval(u, 0.6 + 0.4 * v)).length() < 1e-13);
        assert!((s.eval(u, v) - p.eval(0.2 + 0.5 * u, 0.9 - 0.5 * v)).length() < 1e-13);
    }
}

#[test]
fn elevation_per_direction_preserves() {
    let p = bumpy();
    let eu = p.elevate_u(2);
    let ev = p.elevate_v(3);
    assert_eq!((eu.degree_u(), eu.degree_v()), (5, 4));
    assert_eq!((ev.degree_u(), ev.degree_v()), (3, 7));
    for (u, v) in params() {
        assert!((eu.eval(u, v) - p.eval(u, v)).length() < 1e-13);
        assert!((ev.eval(u, v) - p.eval(u, v)).length() < 1e-13);
    }
}

#[test]
fn bounding_box_by_subdivision_is_tight_to_the_accuracy() {
    let p = bumpy();
    let accuracy = 1e-6;
    let b = p.bounding_box(accuracy).unwrap();
    assert!(p.control_bounding_box().contains_box(&b, 0.0));
    let mut sampled: Option<Aabb<DVec3>> = None;
    let n = 300;
    for a in 0..=n {
        for c in 0..=n {
            let q = p.eval(a as f64 / n as f64, c as f64 / n as f64);
            assert!(b.contains_box(&Aabb::from_point(q), 1e-12), "sample outside the box");
            sampled = Some(sampled.map_or(Aabb::from_point(q), |s| s.including(q)));
        }
    }
    let s = sampled.unwrap();
    // The sampled box misses the true extremes by at most O(h²) ≈ 1e-4 here.
    assert!((b.max - s.max).max_element() < accuracy + 1e-4, "{:?} vs {:?}", b.max, s.max);
    assert!((s.min - b.min).max_element() < accuracy + 1e-4, "{:?} vs {:?}", b.min, s.min);
    assert!(matches!(p.bounding_box(0.0), Err(Error::InvalidTolerance { .. })));
}

#[test]
fn normals() {
    // A flat patch in z = 0 with u along x and v along y has normal +z.
    let flat = BezierPatch::try_from_fn(2, 3, |j, k| {
        DVec3::new(j as f64, k as f64 + 0.1 * (j * j) as f64, 0.0)
    })
    .unwrap();
    for (u, v) in params() {
        assert!((flat.normal(u, v).unwrap() - DVec3::Z).length() < 1e-15);
    }
    let p = bumpy();
    for &(u, v) in &[(0.2, 0.2), (0.5, 0.9)] {
        let nrm = p.normal(u, v).unwrap();
        assert!((nrm.length() - 1.0).abs() < 1e-15);
        assert!(nrm.dot(p.eval_deriv(u, v, 1, 0)).abs() < 1e-13);
        assert!(nrm.dot(p.eval_deriv(u, v, 0, 1)).abs() < 1e-13);
    }
}

fn quarter() -> RationalBezierCurve<DVec2> {
    RationalBezierCurve::circle_arc(DVec2::ZERO, 1.0, 0.0, FRAC_PI_2).unwrap()
}

#[test]
fn sphere_octant_is_exact() {
    let octant = RationalBezierPatch::revolve(&quarter(), &quarter());
    assert_eq!((octant.degree_u(), octant.degree_v()), (2, 2));
    for (u, v) in params() {
        let p = octant.eval(u, v);
        assert!((p.length() - 1.0).abs() <= 2e-16 * 4.0, "({u}, {v}): {}", p.length() - 1.0);
        assert!(p.min_element() >= -1e-16, "first octant");
        if let Some(nrm) = octant.normal(u, v) {
            assert!((nrm.dot(p).abs() - 1.0).abs() < 1e-12, "normal ∥ radius");
        } else {
            assert!(u == 1.0, "only the pole row is degenerate, got ({u}, {v})");
        }
    }
    // Corners: (1, 0, 0), (0, 1, 0) at the equator and the pole (0, 0, 1).
    assert!((octant.eval(0.0, 0.0) - DVec3::X).length() < 1e-15);
    assert!((octant.eval(0.0, 1.0) - DVec3::Y).length() < 1e-15);
    assert!((octant.eval(1.0, 0.3) - DVec3::Z).length() < 1e-15);
    // Partials against finite differences.
    let h = 1e-6;
    let (u, v) = (0.4, 0.7);
    let pu = (octant.eval(u + h, v) - octant.eval(u - h, v)) / (2.0 * h);
    let pv = (octant.eval(u, v + h) - octant.eval(u, v - h)) / (2.0 * h);
    assert!((octant.eval_deriv(u, v, 1, 0) - pu).length() < 1e-8);
    assert!((octant.eval_deriv(u, v, 0, 1) - pv).length() < 1e-8);
    let pv2 = (octant.eval_deriv(u, v + h, 1, 1) - octant.eval_deriv(u, v - h, 1, 1)) / (2.0 * h);
    assert!((octant.eval_deriv(u, v, 1, 2) - pv2).length() < 1e-6);
}

#[test]
fn cylinder_patch_is_exact() {
    // Profile: the vertical segment from (r, z) = (2, 0) to (2, 3).
    let profile =
        RationalBezierCurve::new(vec![DVec2::new(2.0, 0.0), DVec2::new(2.0, 3.0)], vec![1.0, 1.0]);
    let cyl = RationalBezierPatch::revolve(&profile, &quarter());
    for (u, v) in params() {
        let p = cyl.eval(u, v);
        assert!((p.truncate().length() - 2.0).abs() < 1e-15);
        assert!((p.z - 3.0 * u).abs() < 1e-15);
        let nrm = cyl.normal(u, v).unwrap();
        assert!((nrm.z).abs() < 1e-14 && (nrm.truncate().length() - 1.0).abs() < 1e-14);
    }
}

#[test]
fn rational_patch_split_reproduces() {
    let octant = RationalBezierPatch::revolve(&quarter(), &quarter());
    let (a, b) = octant.split_u(0.4).unwrap();
    let (c, d) = octant.split_v(0.25).unwrap();
    for (u, v) in params() {
        assert!((a.eval(u, v) - octant.eval(0.4 * u, v)).length() < 1e-15);
        assert!((b.eval(u, v) - octant.eval(0.4 + 0.6 * u, v)).length() < 1e-15);
        assert!((c.eval(u, v) - octant.eval(u, 0.25 * v)).length() < 1e-15);
        assert!((d.eval(u, v) - octant.eval(u, 0.25 + 0.75 * v)).length() < 1e-15);
    }
    assert!(octant.split_v(2.0).is_err());
    assert!(octant.control_bounding_box().contains(DVec3::new(0.5, 0.5, 0.5)));
}

#[test]
fn validation() {
    assert_eq!(
        BezierPatch::try_new(vec![vec![DVec3::ZERO, DVec3::X], vec![DVec3::Y]]),
        Err(Error::RaggedGrid { row: 1, expected: 2, found: 1 })
    );
    assert_eq!(BezierPatch::<DVec3>::try_new(vec![]), Err(Error::Empty));
    assert_eq!(
        RationalBezierPatch::try_new(vec![vec![DVec3::ZERO]], vec![vec![-1.0]]),
        Err(Error::InvalidWeight { index: 0, value: -1.0 })
    );
}

#[test]
fn small_patches_split_into_the_subpatches_of_their_quarters() {
    // A 4 × 3 net (rows ≠ columns, to catch a transposed index) and a bicubic one; the
    // quarters come from halving on the stack, the subpatches from `BezierPatch::subpatch`.
    let windows = [
        ((0.0, 0.5), (0.0, 0.5)),
        ((0.5, 1.0), (0.0, 0.5)),
        ((0.0, 0.5), (0.5, 1.0)),
        ((0.5, 1.0), (0.5, 1.0)),
    ];
    for cols in [3, 4] {
        let p = BezierPatch::try_from_fn(3, cols - 1, |j, k| {
            DVec3::new(j as f64, (k * k) as f64, ((j * 4 + k) as f64).cos())
        })
        .unwrap();
        let small = SmallPatch::try_from_patch(&p).expect("at most 16 points fit");
        assert_eq!((small.degree_u(), small.degree_v()), (3, cols - 1));
        assert_eq!(small.control_points(), p.control_points());
        assert_eq!(small.control_bounding_box(), p.control_bounding_box());
        for (quarter, ((u0, u1), (v0, v1))) in small.quarters().iter().zip(windows) {
            let sub =
                p.subpatch(ParamWindow::new(ParamRange::new(u0, u1), ParamRange::new(v0, v1)));
            for (a, b) in quarter.control_points().iter().zip(sub.control_points()) {
                assert!((*a - *b).length() < 1e-14, "{a} {b}");
            }
        }
    }
    // A biquartic patch (25 points) does not fit.
    let big = BezierPatch::try_from_fn(4, 4, |j, k| DVec3::new(j as f64, k as f64, 0.0)).unwrap();
    assert!(SmallPatch::try_from_patch(&big).is_none());
}

#[test]
fn partials_agree_with_de_casteljau_at_every_degree() {
    // The Bernstein sums (degrees up to 15, the bicubic case unrolled) and de Casteljau beyond
    // against `eval` and `eval_deriv` (de Casteljau on the hodograph patches).
    for (m, n) in [(3, 3), (3, 2), (1, 4), (15, 2), (16, 3)] {
        let p = BezierPatch::try_from_fn(m, n, |j, k| {
            DVec3::new(j as f64, (k * k) as f64, ((j * 7 + k) as f64).sin())
        })
        .unwrap();
        for (u, v) in [(0.0, 0.0), (0.3, 0.7), (1.0, 0.5), (0.9, 1.0), (-0.2, 1.1)] {
            let (s, su, sv) = p.eval_with_partials(u, v);
            let scale = 1.0 + (m + n) as f64;
            assert!((s - p.eval(u, v)).length() < 1e-12 * scale, "({m}, {n}) at {u}, {v}");
            assert!((su - p.eval_deriv(u, v, 1, 0)).length() < 1e-11 * scale, "({m}, {n}) ∂u");
            assert!((sv - p.eval_deriv(u, v, 0, 1)).length() < 1e-11 * scale, "({m}, {n}) ∂v");
        }
    }
}
