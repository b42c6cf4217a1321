// SPDX-License-Identifier: MIT
//! Closed form of σⁿₖ (eq. 3.13 for odd n, eq. 3.26 for even n) with exact argument reduction.

use crate::sinpi::{NodeFrame, sin_cos_pi};

/// Below this |d| the kernel equals 1 to double precision for any n < 2³², and the quotient
/// would underflow.
const TINY: f64 = 1e-150;

/// σⁿₖ(t) for 0 ≤ k < n: sin(π·u)/(n·sin(πd)), times cos(πd) for even n, where
/// u = n(t − k/n) = j + frac and d = u/n come exactly reduced from `NodeFrame`.
pub(super) fn eval(n: usize, k: usize, t: f64) -> f64 {
    let frame = NodeFrame::new(t, n);
    let (j, d) = frame.offset(k);
    if d.abs() < TINY {
        return 1.0;
    }
    let s_frac = sin_cos_pi(frame.frac).0;
    let num = if j % 2 == 0 { s_frac } else { -s_frac };
    let nf = n as f64;
    let (s, c) = sin_cos_pi(d);
    let ratio = num / (nf * s);
    if n % 2 == 1 { ratio } else { c * ratio }
}

/// σⁿ₀(t), …, σⁿₙ₋₁(t) into `out` (length n).
pub(super) fn eval_all(n: usize, t: f64, out: &mut [f64]) {
    debug_assert_eq!(out.len(), n, "output length must be n");
    for_each_value(n, t, |k, v| out[k] = v);
}

/// Calls `f(k, σⁿₖ(t))` for k = 0, …, n−1, in O(n) with one sine per function.
///
/// The numerators share one sine: with n·t = j + frac for node k (see `NodeFrame`),
/// sin(nπ(t − k/n)) = sin(π(j + frac)) = (−1)ʲ·sin(π·frac).
pub(crate) fn for_each_value(n: usize, t: f64, mut f: impl FnMut(usize, f64)) {
    let frame = NodeFrame::new(t, n);
    let numerator = sin_cos_pi(frame.frac).0;
    let nf = n as f64;
    let even = n.is_multiple_of(2);
    for k in 0..n {
        let (j, d) = frame.offset(k);
        if d.abs() < TINY {
            f(k, 1.0);
            continue;
        }
        let num = if j % 2 == 0 { numerator } else { -numerator };
        let (s, c) = sin_cos_pi(d);
        let ratio = num / (nf * s);
        f(k, if even { c * ratio } else { ratio });
    }
}
