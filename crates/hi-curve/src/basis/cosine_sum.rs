// SPDX-License-Identifier: MIT
//! The cosine sums of eq. 3.28 (odd n) and 3.29 (even n), and derivatives of any order.
//!
//! n = 2m+1: σ(d) = (1/n)·[1 + 2·Σⱼ₌₁ᵐ cos(2πjd)]
//! n = 2m:   σ(d) = (1/n)·[1 + cos(nπd) + 2·Σⱼ₌₁ᵐ⁻¹ cos(2πjd)]
//!
//! (The extracted thesis text drops the leading "1 +"; docs/math.md §1.) Differentiating term by
//! term with dᵖ/ddᵖ cos(ωd) = ωᵖ·cos(ωd + pπ/2) gives every derivative (eq. 5.4 for p = 1).

use std::f64::consts::PI;

use crate::sinpi::{NodeFrame, for_each_multiple, pow_order, quarter_turns, sin_cos_pi};

/// dᵖσⁿₖ/dtᵖ(t) for 0 ≤ k < n.
pub(super) fn eval_deriv(n: usize, k: usize, t: f64, order: usize) -> f64 {
    let frame = NodeFrame::new(t, n);
    let (j_whole, d) = frame.offset(k);
    let nf = n as f64;
    let m = n / 2;
    let mut sum = if order == 0 { 1.0 } else { 0.0 };
    if n.is_multiple_of(2) {
        // The Nyquist term cos(nπd) = cos(π(j + frac)) = (−1)ʲ·cos(π·frac), differentiated.
        let (s, c) = sin_cos_pi(frame.frac);
        let (s, c) = if j_whole % 2 == 0 { (s, c) } else { (-s, -c) };
        let (_, cp) = quarter_turns(s, c, order);
        sum += pow_order(PI * nf, order) * cp;
    }
    let n_pairs = if n % 2 == 1 { m } else { m.saturating_sub(1) };
    // cos(2πjd) = cos(πj·(2d)); 2d is exact.
    for_each_multiple(2.0 * d, n_pairs, |j, c, s| {
        let (_, cp) = quarter_turns(s, c, order);
        sum += 2.0 * pow_order(2.0 * PI * j as f64, order) * cp;
    });
    sum / nf
}
