// SPDX-License-Identifier: MIT
//! Chaikin's corner cutting and the 4-point scheme (Hardy 2005, §4.5, figures 4.6 and 4.7)
//! against analytic truths: Chaikin's limit is the uniform quadratic B-spline, the 4-point
//! scheme interpolates and reproduces cubics.

use glam::{DVec2, DVec3};
use hi_compare::corner_cutting::{ChaikinCurve, FourPointCurve, chaikin_step, four_point_step};
use hi_curve::ParamCurve;

/// The uniform quadratic B-spline basis function on [0, 3] (Cox–de Boor, written out).
fn quadratic_basis(x: f64) -> f64 {
    if (0.0..1.0).contains(&x) {
        0.5 * x * x
    } else if (1.0..2.0).contains(&x) {
        0.5 * (-2.0 * x * x + 6.0 * x - 3.0)
    } else if (2.0..3.0).contains(&x) {
        0.5 * (3.0 - x) * (3.0 - x)
    } else {
        0.0
    }
}

/// Σᵢ cᵢ·N(u − i + 2): the uniform quadratic B-spline with controls c, segment j on [j, j+1]
/// (cyclic controls when `closed`).
fn bspline(controls: &[DVec2], closed: bool, u: f64) -> DVec2 {
    let n = controls.len() as i64;
    let mut res = DVec2::ZERO;
    for i in -3..n + 3 {
        let c = if closed {
            controls[i.rem_euclid(n) as usize]
        } else if (0..n).contains(&i) {
            controls[i as usize]
        } else {
            continue;
        };
        res += c * quadratic_basis(u - i as f64 + 2.0);
    }
    res
}

fn heptagon() -> Vec<DVec2> {
    // The seven irregular points of the thesis's figures 4.6/4.7 are not given numerically;
    // any irregular heptagon will do.
    vec![
        DVec2::new(0.0, 3.0),
        DVec2::new(-2.0, 0.5),
        DVec2::new(-1.0, -2.0),
        DVec2::new(1.5, -2.5),
        DVec2::new(3.0, -0.5),
        DVec2::new(2.0, 1.0),
        DVec2::new(2.5, 2.5),
    ]
}

/// The open polygon with doubled ends, whose B-spline is open Chaikin's limit.
fn doubled_ends(points: &[DVec2]) -> Vec<DVec2> {
    let mut res = vec![points[0]];
    res.extend_from_slice(points);
    res.push(points[points.len() - 1]);
    res
}

#[test]
fn chaikin_step_counts_and_known_values() {
    let triangle = [DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(0.0, 4.0)];
    let step = chaikin_step(&triangle, true);
    let expected = [(1.0, 0.0), (3.0, 0.0), (3.0, 1.0), (1.0, 3.0), (0.0, 3.0), (0.0, 1.0)];
    assert_eq!(step, expected.map(|(x, y)| DVec2::new(x, y)));
    let open = chaikin_step(&triangle, false);
    assert_eq!(open.len(), 6);
    assert_eq!((open[0], open[5]), (triangle[0], triangle[2]));
    for closed in [true, false] {
        let polygons = ChaikinCurve::new(heptagon(), closed).refine(5).unwrap();
        for (k, polygon) in polygons.iter().enumerate() {
            assert_eq!(polygon.len(), 7 << k, "closed = {closed}, step {k}");
        }
    }
}

#[test]
fn chaikin_limit_is_the_uniform_quadratic_bspline() {
    let points = heptagon();
    let closed = ChaikinCurve::new(points.clone(), true);
    let open = ChaikinCurve::new(points.clone(), false);
    let augmented = doubled_ends(&points);
    for i in 0..=700 {
        let t = i as f64 / 700.0;
        let u = 7.0 * t;
        assert!((closed.eval(t) - bspline(&points, true, u)).length() < 1e-14, "t = {t}");
        if i < 700 {
            assert!((open.eval(t) - bspline(&augmented, false, u)).length() < 1e-14, "t = {t}");
        }
    }
    assert_eq!(open.eval(0.0), points[0]);
    assert!((open.eval(1.0) - points[6]).length() < 1e-15);
    assert_eq!(closed.eval(0.0), (points[0] + points[1]) / 2.0);
    assert!(closed.is_periodic() && !open.is_periodic());
    // C¹ at the joins, and derivatives consistent with finite differences.
    let h = 1e-7;
    for curve in [&closed, &open] {
        for j in 1..7 {
            let t = j as f64 / 7.0;
            let left = curve.eval_deriv(t - 1e-12, 1);
            assert!((left - curve.eval_deriv(t, 1)).length() < 1e-9, "join {j}");
        }
        for t in [0.13, 0.5, 0.77] {
            let fd = (curve.eval(t + h) - curve.eval(t - h)) / (2.0 * h);
            assert!((fd - curve.eval_deriv(t, 1)).length() < 1e-6, "t = {t}");
            let fd2 = (curve.eval_deriv(t + h, 1) - curve.eval_deriv(t - h, 1)) / (2.0 * h);
            assert!((fd2 - curve.eval_deriv(t, 2)).length() < 1e-5, "t = {t}");
            assert_eq!(curve.eval_deriv(t, 3), DVec2::ZERO);
        }
    }
}

#[test]
fn chaikin_polygons_touch_the_limit_at_their_edge_midpoints() {
    let points = heptagon();
    for closed in [true, false] {
        let curve = ChaikinCurve::new(points.clone(), closed);
        for (k, polygon) in curve.refine(6).unwrap().iter().enumerate() {
            let polygon = if closed { polygon.clone() } else { doubled_ends(polygon) };
            let n_edges = if closed { polygon.len() } else { polygon.len() - 1 };
            let denominator = (7usize << k) as f64;
            for m in 0..n_edges {
                let mid = (polygon[m] + polygon[(m + 1) % polygon.len()]) / 2.0;
                let on_curve = curve.eval(m as f64 / denominator);
                assert!((mid - on_curve).length() < 1e-14, "closed = {closed}, k = {k}, m = {m}");
            }
        }
    }
}

#[test]
fn chaikin_polygons_converge_quadratically() {
    // The vertices of Pᵏ approach the limit like 4⁻ᵏ (the B-spline's control polygon of
    // the refined knots).
    let curve = ChaikinCurve::new(heptagon(), true);
    let polygons = curve.refine(7).unwrap();
    let mut last = f64::INFINITY;
    for (k, polygon) in polygons.iter().enumerate().skip(1) {
        let n = polygon.len();
        // Vertex m of Pᵏ is the control point of the quadratic segment through the limit
        // points at (m − ½)/(7·2ᵏ) and (m + ½)/(7·2ᵏ): its distance to the curve at m/(7·2ᵏ).
        let worst = (0..n)
            .map(|m| (polygon[m] - curve.eval((m as f64 - 0.5) / n as f64)).length())
            .fold(0.0, f64::max);
        assert!(worst < last / 3.5, "step {k}: {worst} after {last}");
        last = worst;
    }
}

#[test]
fn four_point_is_interpolatory() {
    for closed in [true, false] {
        for w in [0.0, 1.0 / 32.0, 1.0 / 16.0, 0.1, 0.125] {
            let scheme = FourPointCurve::try_with_weight(heptagon(), closed, w).unwrap();
            let polygons = scheme.refine(5).unwrap();
            for k in 0..5 {
                let (old, new) = (&polygons[k], &polygons[k + 1]);
                let expected = if closed { 2 * old.len() } else { 2 * old.len() - 1 };
                assert_eq!(new.len(), expected, "closed = {closed}, w = {w}, step {k}");
                for (i, p) in old.iter().enumerate() {
                    assert_eq!(new[2 * i], *p, "closed = {closed}, w = {w}, step {k}, point {i}");
                }
            }
        }
    }
}

#[test]
fn four_point_reproduces_uniformly_sampled_cubics() {
    let cubic = |t: f64| {
        DVec2::new(0.1 * t * t * t - t * t + 2.0 * t - 1.0, -0.05 * t * t * t + 0.3 * t * t + t)
    };
    for n in [4usize, 5, 9] {
        let points: Vec<DVec2> = (0..n).map(|i| cubic(i as f64)).collect();
        let scheme = FourPointCurve::new(points, false);
        let polygons = scheme.refine(6).unwrap();
        for (k, polygon) in polygons.iter().enumerate() {
            assert_eq!(polygon.len(), ((n - 1) << k) + 1);
            for (i, p) in polygon.iter().enumerate() {
                // parameter() maps to [0, 1]; the cubic was sampled at 0, 1, …, n − 1.
                let t = scheme.parameter(k, i) * (n - 1) as f64;
                assert!((*p - cubic(t)).length() < 1e-12, "n = {n}, step {k}, point {i}");
            }
        }
    }
    // Three points: the quadratic end rule reproduces quadratics.
    let quadratic = |t: f64| t * t - 3.0 * t;
    let scheme = FourPointCurve::new(vec![quadratic(0.0), quadratic(1.0), quadratic(2.0)], false);
    for (i, x) in scheme.refine(4).unwrap()[4].iter().enumerate() {
        assert!((x - quadratic(i as f64 / 16.0)).abs() < 1e-13, "point {i}");
    }
    // Two points, or w = 0: linear interpolation.
    let line = FourPointCurve::new(vec![DVec3::ZERO, DVec3::new(1.0, 2.0, 3.0)], false);
    for (i, p) in line.refine(3).unwrap()[3].iter().enumerate() {
        assert!((*p - DVec3::new(1.0, 2.0, 3.0) * (i as f64 / 8.0)).length() < 1e-15);
    }
    assert_eq!(
        four_point_step(&[0.0, 1.0, 4.0, 9.0], true, 0.0),
        vec![0.0, 0.5, 1.0, 2.5, 4.0, 6.5, 9.0, 4.5]
    );
}

#[test]
fn four_point_closed_keeps_the_symmetry_of_a_regular_polygon() {
    let n = 6;
    let hexagon: Vec<DVec2> =
        (0..n).map(|k| DVec2::from_angle(std::f64::consts::TAU * k as f64 / n as f64)).collect();
    let scheme = FourPointCurve::new(hexagon, true);
    let polygons = scheme.refine(6).unwrap();
    let fine = &polygons[6];
    // Rotating by a sixth of a turn permutes the points.
    let shift = fine.len() / n;
    let rotation = DVec2::from_angle(std::f64::consts::TAU / n as f64);
    for i in 0..fine.len() {
        let rotated = rotation.rotate(fine[i]);
        assert!((rotated - fine[(i + shift) % fine.len()]).length() < 1e-14, "point {i}");
    }
    // The limit of a regular polygon stays close to its circumcircle.
    let radii = fine.iter().map(|p| p.length());
    let (lo, hi) = radii.fold((f64::INFINITY, 0.0f64), |(lo, hi), r| (lo.min(r), hi.max(r)));
    assert!(lo > 0.97 && hi < 1.0 + 1e-12, "radii in [{lo}, {hi}]");
    assert_eq!(scheme.parameter(1, 3), 0.25);
    assert_eq!(scheme.weight(), 1.0 / 16.0);
}
