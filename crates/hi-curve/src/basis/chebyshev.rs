// SPDX-License-Identifier: MIT
//! The Chebyshev form of §3.9: σⁿₖ through the Chebyshev polynomial of the second kind.
//!
//! With s = cos(πt) for t ∈ [0, 1] and φₖ(s) = s·cos(πk/n) + √(1−s²)·sin(πk/n), which equals
//! cos(π(t − k/n)) there, and Uₙ₋₁(cos θ) = sin(nθ)/sin(θ):
//! σⁿₖ = Uₙ₋₁(φₖ)/n for odd n and φₖ·Uₙ₋₁(φₖ)/n (= T₁(φₖ)·Uₙ₋₁(φₖ)/n) for even n.

use crate::sinpi::{cos_pi, sin_cos_pi};

/// σⁿₖ(t) for 0 ≤ k < n by the Chebyshev form.
pub(super) fn eval(n: usize, k: usize, t: f64) -> f64 {
    // √(1−s²) = sin(πt) holds only for t ∈ [0, 1]: take t modulo 1 first.
    let t01 = t - t.floor();
    let s = cos_pi(t01);
    let root = (1.0 - s * s).max(0.0).sqrt();
    let (sk, ck) = sin_cos_pi(k as f64 / n as f64);
    let phi = s * ck + root * sk;
    let u = chebyshev_u(n - 1, phi);
    let nf = n as f64;
    if n % 2 == 1 { u / nf } else { phi * u / nf }
}

/// Uₚ(x) by the three-term recurrence U₀ = 1, U₁ = 2x, Uⱼ₊₁ = 2x·Uⱼ − Uⱼ₋₁.
fn chebyshev_u(p: usize, x: f64) -> f64 {
    let (mut prev, mut cur) = (1.0, 2.0 * x);
    if p == 0 {
        return prev;
    }
    for _ in 1..p {
        (prev, cur) = (cur, 2.0 * x * cur - prev);
    }
    cur
}

#[cfg(test)]
mod tests {
    use super::chebyshev_u;

    #[test]
    fn u_polynomials() {
        // U₂(x) = 4x² − 1, U₃(x) = 8x³ − 4x, Uₚ(1) = p + 1.
        assert_eq!(chebyshev_u(2, 0.5), 0.0);
        assert_eq!(chebyshev_u(3, 0.5), -1.0);
        assert_eq!(chebyshev_u(9, 1.0), 10.0);
    }
}
