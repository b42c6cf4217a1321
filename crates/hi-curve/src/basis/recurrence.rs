// SPDX-License-Identifier: MIT
//! The division-free recurrence of §3.6 for σⁿₖ.
//!
//! ς₁(d) = 1 and ςⱼ(d) = sin(jπd)/sin(πd) = cos((j−1)πd) + cos(πd)·ςⱼ₋₁(d), so
//! σⁿ(d) = ςₙ(d)/n for odd n and cos(πd)·ςₙ(d)/n for even n. No division by sin(πd), so no
//! special case at the nodes. |cos(πd)| ≤ 1 keeps the recurrence stable: rounding errors add
//! up, they are not amplified.

use crate::sinpi::{cos_pi, for_each_multiple, node_offset};

/// σⁿₖ(t) for 0 ≤ k < n by the recurrence.
pub(super) fn eval(n: usize, k: usize, t: f64) -> f64 {
    let d = node_offset(t, k, n);
    let c1 = cos_pi(d);
    let mut varsigma = 1.0; // ς₁
    // Step j uses cos((j−1)πd), j = 2..=n, i.e. multiples 1..=n−1.
    for_each_multiple(d, n - 1, |_, cos_jd, _| {
        varsigma = cos_jd + c1 * varsigma;
    });
    let nf = n as f64;
    if n % 2 == 1 { varsigma / nf } else { c1 * varsigma / nf }
}
