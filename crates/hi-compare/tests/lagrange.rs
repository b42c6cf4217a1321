// SPDX-License-Identifier: MIT
//! Analytic truths of Lagrange interpolation (Hardy 2005, §2.4): the basis is cardinal and a
//! partition of unity, polynomials of degree below n are reproduced exactly (with their
//! derivatives), and the Bézier form is the same polynomial.

use glam::DVec2;
use hi_compare::lagrange::{LagrangeBasis, LagrangeCurve};
use hi_testkit::proptest_config;
use proptest::prelude::*;

/// The r-th derivative of Σ cₖ uᵏ, Σₖ≥ᵣ cₖ·k!/(k − r)!·uᵏ⁻ʳ by Horner's rule.
fn poly(coeffs: &[f64], u: f64, order: usize) -> f64 {
    let mut res = 0.0;
    for (k, c) in coeffs.iter().enumerate().rev() {
        if k < order {
            break;
        }
        let falling: f64 = (0..order).map(|j| (k - j) as f64).product();
        res = res * u + c * falling;
    }
    res
}

#[test]
fn example_2_1_interpolates_at_integer_nodes() {
    // Example 2.1 (figure 2.2), nodes 0, 1, 2, 3.
    let pts = vec![
        DVec2::new(1.0, 1.0),
        DVec2::new(2.0, 3.0),
        DVec2::new(4.0, 1.0),
        DVec2::new(3.0, 0.0),
    ];
    let curve = LagrangeCurve::try_with_params(pts.clone(), vec![0.0, 1.0, 2.0, 3.0]).unwrap();
    for (i, p) in pts.iter().enumerate() {
        assert!((curve.eval(i as f64 / 3.0) - *p).length() < 1e-14);
    }
    assert_eq!(curve.degree(), 3);
    // Figure 2.1: the basis is cardinal and sums to one, and overshoots below zero.
    let basis = curve.basis();
    for j in 0..4 {
        for k in 0..4 {
            assert_eq!(basis.eval(k, j as f64), if j == k { 1.0 } else { 0.0 });
        }
    }
    assert!(basis.eval(0, 1.5) < 0.0);
}

#[test]
fn to_bezier_of_moderate_degree() {
    // Runge's function at 12 uniform nodes: the Bézier form agrees to 1e-12 (see the
    // conditioning note of to_bezier).
    let n = 12;
    let pts: Vec<f64> = (0..n)
        .map(|i| {
            let x = -1.0 + 2.0 * i as f64 / (n - 1) as f64;
            1.0 / (1.0 + 25.0 * x * x)
        })
        .collect();
    let curve = LagrangeCurve::try_new(pts).unwrap();
    let chain = curve.to_bezier().unwrap();
    assert_eq!(chain.segments()[0].degree(), n - 1);
    for i in 0..=100 {
        let t = i as f64 / 100.0;
        assert!((chain.eval(t) - curve.eval(t)).abs() < 1e-12, "t = {t}");
    }
}

#[test]
fn to_bezier_of_huge_degree_overflows_cleanly() {
    let pts: Vec<f64> = (0..1200).map(|i| if i % 2 == 0 { 1.0 } else { -1.0 }).collect();
    let curve = LagrangeCurve::try_new(pts).unwrap();
    assert!(matches!(curve.to_bezier(), Err(hi_compare::Error::Overflow { .. })));
}

proptest! {
    #![proptest_config(proptest_config(256))]

    /// Lagrange interpolation reproduces every polynomial of degree < n (§2.4), with its
    /// derivatives, on random distinct nodes.
    #[test]
    fn reproduces_polynomials(
        coeffs in prop::collection::vec(-3.0..3.0f64, 1..7), extra in 0usize..3,
        gaps in prop::collection::vec(0.05..0.6f64, 10), start in -1.0..0.0f64,
        t in 0.0..=1.0f64,
    ) {
        let n = (coeffs.len() + extra).max(2);
        // Nodes from −1 ≤ start, separated by at least 0.05.
        let nodes: Vec<f64> =
            (0..n).map(|i| start + gaps[..i].iter().sum::<f64>()).collect();
        let values: Vec<f64> = nodes.iter().map(|&u| poly(&coeffs, u, 0)).collect();
        let curve = LagrangeCurve::try_with_params(values, nodes.clone()).unwrap();
        let (a, b) = (nodes[0], nodes[n - 1]);
        let u = a + t * (b - a);
        for order in 0..=n {
            let expected = poly(&coeffs, u, order) * (b - a).powi(order as i32);
            let got = curve.eval_deriv(t, order);
            let tol = 1e-9 * (1.0 + expected.abs()) * 10f64.powi(order as i32);
            prop_assert!((got - expected).abs() < tol, "order {}: {} vs {}", order, got, expected);
        }
        // The Bézier form is the same polynomial.
        let chain = curve.to_bezier().unwrap();
        prop_assert!((chain.eval(t) - curve.eval(t)).abs() < 1e-10 * (1.0 + curve.eval(t).abs()));
    }

    /// The basis is cardinal and a partition of unity (theorem 2.1: affine invariance).
    #[test]
    fn basis_is_cardinal_partition_of_unity(
        n in 1usize..12, u in -1.0..2.0f64,
    ) {
        let nodes: Vec<f64> = (0..n).map(|i| i as f64 / n as f64).collect();
        let basis = LagrangeBasis::try_new(nodes.clone()).unwrap();
        let values = basis.eval_all(u);
        let sum: f64 = values.iter().sum();
        // Far outside the nodes the Lₖ are large and of both signs: relative to Σ|Lₖ|.
        let size: f64 = values.iter().map(|v| v.abs()).sum();
        prop_assert!((sum - 1.0).abs() < 1e-14 * size.max(1.0), "sum {}", sum);
        for (j, &node) in nodes.iter().enumerate() {
            for k in 0..n {
                let expected = if j == k { 1.0 } else { 0.0 };
                prop_assert!((basis.eval(k, node) - expected).abs() < 1e-12);
            }
        }
    }
}
