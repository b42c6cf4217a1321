// SPDX-License-Identifier: MIT
//! The Bernstein basis (eq. 2.2, 2.3) against its closed form, the binomial theorem and the
//! power basis.

mod common;

use common::{bernstein, binomial, power_deriv};
use hi_bezier::Bernstein;

#[test]
fn partition_of_unity() {
    // Σᵢ Bⁿᵢ(t) = (t + (1 − t))ⁿ = 1 (§2.5, the binomial theorem).
    for n in [0usize, 1, 2, 3, 7, 20, 100, 1000] {
        let b = Bernstein::new(n);
        for k in 0..=50 {
            let t = k as f64 / 50.0;
            let sum: f64 = b.values(t).iter().sum();
            assert!((sum - 1.0).abs() < 1e-13, "n={n} t={t}: {sum}");
        }
        // Outside [0, 1] the identity still holds, with the rounding of growing terms.
        let sum: f64 = b.values(1.5).iter().sum();
        if n <= 20 {
            let scale: f64 = b.values(1.5).iter().map(|v| v.abs()).sum();
            assert!((sum - 1.0).abs() < 1e-13 * scale, "n={n}: {sum}");
        }
    }
}

#[test]
fn known_values() {
    let cubic = Bernstein::new(3);
    let t: f64 = 0.3;
    let s = 1.0 - t;
    let expected = [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t];
    for (i, e) in expected.iter().enumerate() {
        assert!((cubic.eval(i, t) - e).abs() < 1e-16, "B³{i}(0.3)");
    }
    // Bⁿᵢ(i/n) against C(n, i)·tⁱ·(1 − t)ⁿ⁻ⁱ with an exact integer binomial.
    for n in [5usize, 12, 30] {
        let b = Bernstein::new(n);
        for i in 0..=n {
            for &t in &[0.0, 0.1, i as f64 / n as f64, 0.5, 0.9, 1.0] {
                let e = bernstein(n, i, t);
                assert!(
                    (b.eval(i, t) - e).abs() <= 1e-14 * e.max(1e-300) + 1e-300,
                    "n={n} i={i} t={t}"
                );
            }
        }
    }
    // End values: Bⁿᵢ(0) = δᵢ₀, Bⁿᵢ(1) = δᵢₙ.
    let b = Bernstein::new(6);
    for i in 0..=6 {
        assert_eq!(b.eval(i, 0.0), if i == 0 { 1.0 } else { 0.0 });
        assert_eq!(b.eval(i, 1.0), if i == 6 { 1.0 } else { 0.0 });
    }
}

#[test]
fn symmetry() {
    let b = Bernstein::new(9);
    for i in 0..=9 {
        for &t in &[0.05, 0.4, 0.77] {
            assert!((b.eval(i, t) - b.eval(9 - i, 1.0 - t)).abs() < 1e-15);
        }
    }
}

#[test]
fn derivatives_match_the_power_basis() {
    // Bⁿᵢ(t) = Σₗ C(n, i)·C(n − i, l)·(−1)ˡ·tⁱ⁺ˡ: differentiate the power series instead.
    for n in [1usize, 2, 3, 6, 10] {
        let b = Bernstein::new(n);
        for i in 0..=n {
            let mut a = vec![0.0; n + 1];
            for l in 0..=n - i {
                let sign = if l % 2 == 0 { 1.0 } else { -1.0 };
                a[i + l] = binomial(n as u64, i as u64) * binomial((n - i) as u64, l as u64) * sign;
            }
            for order in 0..=n + 1 {
                for &t in &[0.0, 0.25, 0.6, 1.0] {
                    let e = power_deriv(&a, order, t);
                    let got = b.eval_deriv(i, t, order);
                    let scale = 1.0 + e.abs() + (n as f64).powi(order as i32);
                    assert!(
                        (got - e).abs() < 1e-12 * scale,
                        "n={n} i={i} k={order} t={t}: {got} vs {e}"
                    );
                    let row = b.derivs(t, order);
                    assert!((row[i] - got).abs() < 1e-12 * scale, "derivs row");
                }
            }
        }
    }
}

#[test]
fn derivative_rows_sum_to_zero() {
    // d/dt Σᵢ Bⁿᵢ = d/dt 1 = 0 for every order ≥ 1.
    let b = Bernstein::new(8);
    for order in 1..=9 {
        let sum: f64 = b.derivs(0.35, order).iter().sum();
        assert!(sum.abs() < 1e-9, "order {order}: {sum}");
    }
}

#[test]
fn first_derivative_by_finite_differences() {
    let b = Bernstein::new(7);
    let h = 1e-6;
    for i in 0..=7 {
        let t = 0.43;
        let fd = (b.eval(i, t + h) - b.eval(i, t - h)) / (2.0 * h);
        assert!((b.eval_deriv(i, t, 1) - fd).abs() < 1e-8, "i={i}");
    }
}
