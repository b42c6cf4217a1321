// SPDX-License-Identifier: MIT
//! The four evaluation forms of σⁿₖ agree (docs/math.md §1), including near the integers and far
//! from zero, for n up to 4096.

use hi_curve::{Form, Sigma};

/// The grid of the issue: dense in [0, 1), plus points near the integers and far away.
fn grid() -> Vec<f64> {
    let mut ts: Vec<f64> = (0..997).map(|i| i as f64 / 997.0 + 1e-4).collect();
    ts.extend([0.0, 1.0 - 1e-12, -1e-15, 1e6 + 0.5, 1.0, 0.5, -0.25, 3.0 + 1e-9, -7.75]);
    ts
}

/// Basis indices to test for size n: all of them for small n, a spread otherwise.
fn indices(n: usize) -> Vec<usize> {
    if n <= 16 { (0..n).collect() } else { vec![0, 1, 2, n / 3, n / 2, n - 2, n - 1] }
}

fn max_disagreement(n: usize, form: Form) -> f64 {
    let sigma = Sigma::new(n);
    let mut worst = 0.0f64;
    for k in indices(n) {
        for t in grid() {
            let a = sigma.eval(k, t);
            let b = sigma.eval_form(form, k, t);
            worst = worst.max((a - b).abs());
        }
    }
    worst
}

const SIZES: [usize; 14] = [1, 2, 3, 4, 5, 6, 7, 8, 16, 63, 64, 255, 1024, 4096];

#[test]
fn closed_form_recurrence_and_cosine_sum_agree_to_1e13() {
    for n in SIZES {
        for form in [Form::Recurrence, Form::CosineSum] {
            let e = max_disagreement(n, form);
            println!("n={n:5} {form:?}: {e:.2e}");
            assert!(e <= 1e-13, "n = {n}, {form:?}: {e:e}");
        }
    }
}

/// The Chebyshev form (§3.9) loses accuracy as n grows: φₖ = cos(π(t − k/n)) is rounded to a
/// double, and Uₙ₋₁ has slope up to n³/3 near φ = ±1, so the error is about n²·ε/3 next to a
/// node (measured on this grid: 3e-13 at n = 64, 4e-12 at n = 256, 5e-11 at n = 1024, 5e-10 at
/// n = 4096). Near t ≡ 0 (mod 1), s = cos(πt) also drops the low bits of t (cos is flat there),
/// which costs up to |σ′|·√ε/π ≈ n·1e-9.
#[test]
fn chebyshev_form_error_growth() {
    for n in SIZES {
        let sigma = Sigma::new(n);
        let (mut interior, mut near_integers) = (0.0f64, 0.0f64);
        for k in indices(n) {
            for i in 0..4000 {
                let t = 0.05 + 0.9 * (i as f64 + 0.5) / 4000.0;
                interior = interior.max((sigma.eval(k, t) - sigma.chebyshev(k, t)).abs());
            }
            for t in [1.0 - 1e-12, -1e-15, 1e6 + 0.5, 3.0 + 1e-9, 1e-4, 0.999] {
                near_integers = near_integers.max((sigma.eval(k, t) - sigma.chebyshev(k, t)).abs());
            }
        }
        println!(
            "n = {n:5}: Chebyshev form vs closed form: {interior:.1e} for t in [0.05, 0.95], {near_integers:.1e} near integers"
        );
        let eps = f64::EPSILON;
        if n <= 256 {
            assert!(interior <= 1e-11, "n = {n}: {interior:e}");
        }
        assert!(interior <= (n * n) as f64 * eps / 3.0 + 1e-14, "n = {n}: {interior:e}");
        assert!(near_integers <= 2e-9 * n as f64, "n = {n}: {near_integers:e}");
    }
}
