// SPDX-License-Identifier: MIT
//! sin(πx) and cos(πx) with exact argument reduction, for the basis and spectral evaluations.
//!
//! The harmonic basis is evaluated at arguments such as n·t for large n and t far from zero.
//! Multiplying by π first and calling `sin` loses the low bits of the argument. Here the
//! argument is reduced in units of π instead: x − 2·round(x/2) is exact in floating point, so
//! the only rounding left is the final multiplication by π of a number in [−¼, ¼].
//! Products j·x are carried as an unevaluated sum hi + lo (the "two-product" of Dekker,
//! computed with one fused multiply–add), so that j·x mod 2 keeps every bit of x.

use std::f64::consts::PI;

/// Splits `a·b` into `hi + lo` with `hi = fl(a·b)` and `lo` the exact rounding error.
#[inline]
pub(crate) fn two_product(a: f64, b: f64) -> (f64, f64) {
    let hi = a * b;
    let lo = a.mul_add(b, -hi);
    (hi, lo)
}

/// Reduces `x` to `x − 2·round(x/2)` ∈ [−1, 1]; exact for every finite `x`.
#[inline]
pub(crate) fn reduce_mod2(x: f64) -> f64 {
    x - 2.0 * (0.5 * x).round()
}

/// Returns (sin(π(hi + lo)), cos(π(hi + lo))), where `lo` is small against `hi`.
///
/// `hi` is reduced modulo 2 exactly, then to a quarter period with a quadrant index, before
/// `lo` is added; so large `hi` loses nothing.
#[inline]
pub(crate) fn sin_cos_pi2(hi: f64, lo: f64) -> (f64, f64) {
    let r = reduce_mod2(hi); // exact, in [−1, 1]
    let quadrant = (2.0 * r).round(); // in {−2, −1, 0, 1, 2}
    let q = (r - 0.5 * quadrant) + lo; // r − quadrant/2 is exact (Sterbenz)
    let (s, c) = (PI * q).sin_cos();
    match (quadrant as i64).rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// Returns (sin(πx), cos(πx)) with exact argument reduction.
#[inline]
pub(crate) fn sin_cos_pi(x: f64) -> (f64, f64) {
    sin_cos_pi2(x, 0.0)
}

/// Returns cos(πx) with exact argument reduction.
#[inline]
pub(crate) fn cos_pi(x: f64) -> f64 {
    sin_cos_pi(x).1
}

/// Returns (sin(π·j·x), cos(π·j·x)) for an integer-valued `j`, keeping every bit of j·x.
#[inline]
pub(crate) fn sin_cos_pi_mul(j: f64, x: f64) -> (f64, f64) {
    let (hi, lo) = two_product(j, x);
    sin_cos_pi2(hi, lo)
}

/// Reduces a parameter of a 1-periodic function to `t − round(t)` ∈ [−½, ½]; exact.
#[inline]
pub(crate) fn reduce_period(t: f64) -> f64 {
    t - t.round()
}

/// n·t modulo n, split as an integer and a fraction, for measuring distances to the nodes k/n.
///
/// With r = t − round(t) (exact) and n·r = hi + lo (an exact two-product), the integer part
/// round(hi) is kept as an integer and the fraction (hi − round(hi)) + lo carries every
/// remaining bit. The distance to node k in units of 1/n is then u = j + frac with the integer
/// j = round(hi) − k reduced modulo n exactly, so u has a relative error of one rounding
/// wherever it lies, and is exact to the last bit near the node.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NodeFrame {
    n: i64,
    whole: i64,
    /// (hi − round(hi)) + lo, in about [−½, ½].
    pub(crate) frac: f64,
}

impl NodeFrame {
    #[inline]
    pub(crate) fn new(t: f64, n: usize) -> Self {
        let r = reduce_period(t);
        let (hi, lo) = two_product(n as f64, r);
        let whole = hi.round();
        Self { n: n as i64, whole: whole as i64, frac: (hi - whole) + lo }
    }

    /// (j, d): u = j + frac is the offset from node k in units of 1/n, with the integer j
    /// reduced into (−n/2, n/2], and d = u/n the offset t − k/n modulo 1, in about [−½, ½].
    #[inline]
    pub(crate) fn offset(&self, k: usize) -> (i64, f64) {
        let mut j = (self.whole - k as i64).rem_euclid(self.n);
        if 2 * j > self.n {
            j -= self.n;
        }
        (j, (j as f64 + self.frac) / self.n as f64)
    }
}

/// The offset d = t − k/n modulo 1, in about [−½, ½], to a relative error of one rounding
/// (see [`NodeFrame`]).
#[inline]
pub(crate) fn node_offset(t: f64, k: usize, n: usize) -> f64 {
    NodeFrame::new(t, n).offset(k).1
}

/// wᵖ for a derivative order p of any size (`powi` takes an `i32`).
#[inline]
pub(crate) fn pow_order(w: f64, order: usize) -> f64 {
    match i32::try_from(order) {
        Ok(p) => w.powi(p),
        Err(_) => w.powf(order as f64),
    }
}

/// Rotates (sin θ, cos θ) to (sin(θ + pπ/2), cos(θ + pπ/2)).
#[inline]
pub(crate) fn quarter_turns(sin: f64, cos: f64, p: usize) -> (f64, f64) {
    match p % 4 {
        0 => (sin, cos),
        1 => (cos, -sin),
        2 => (-sin, -cos),
        _ => (-cos, sin),
    }
}

/// Calls `f(j, cos πjx, sin πjx)` for j = 1..=m.
///
/// The values come from the rotation e^{iπ(j+1)x} = e^{iπjx}·e^{iπx}, re-anchored with an
/// exactly reduced `sin_cos` every 16 steps, so the error stays within a few ulps for any m.
#[inline]
pub(crate) fn for_each_multiple(x: f64, m: usize, mut f: impl FnMut(usize, f64, f64)) {
    const ANCHOR: usize = 16;
    let (s1, c1) = sin_cos_pi(x);
    let (mut s, mut c) = (0.0, 1.0);
    for j in 1..=m {
        if j % ANCHOR == 0 {
            (s, c) = sin_cos_pi_mul(j as f64, x);
        } else {
            (s, c) = (s * c1 + c * s1, c * c1 - s * s1);
        }
        f(j, c, s);
    }
}

/// Calls `f(j, cos 2πjt, sin 2πjt)` for j = 1..=m (see [`for_each_multiple`]).
#[inline]
pub(crate) fn for_each_harmonic(t: f64, m: usize, f: impl FnMut(usize, f64, f64)) {
    for_each_multiple(2.0 * reduce_period(t), m, f);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reduction_is_exact_far_from_zero() {
        // sin(π(10⁶ + ½)) = 1 exactly; the naive formula is off by about 1e-10.
        assert_eq!(sin_cos_pi(1e6 + 0.5).0, 1.0);
        assert_eq!(cos_pi(1e6 + 1.0), -1.0);
        assert_eq!(sin_cos_pi(-3.0).0, 0.0);
        let (s, c) = sin_cos_pi(0.25);
        assert!(
            (s - 0.5f64.sqrt()).abs() <= 2e-16 && (c - 0.5f64.sqrt()).abs() <= 2e-16,
            "{s} {c}"
        );
    }

    #[test]
    fn quadrants_agree_with_std() {
        for i in -400..=400 {
            let x = i as f64 * 0.013_7;
            let (s, c) = sin_cos_pi(x);
            assert!((s - (PI * x).sin()).abs() < 1e-14, "sin at {x}");
            assert!((c - (PI * x).cos()).abs() < 1e-14, "cos at {x}");
        }
    }

    #[test]
    fn harmonics_match_direct_evaluation() {
        let t = 0.123_456_789;
        let mut worst = 0.0f64;
        for_each_harmonic(t, 5000, |j, c, s| {
            let (s2, c2) = sin_cos_pi_mul(2.0 * j as f64, t);
            worst = worst.max((c - c2).abs()).max((s - s2).abs());
        });
        assert!(worst < 1e-14, "worst {worst}");
    }

    #[test]
    fn node_offset_is_exact_at_nodes() {
        for n in [3usize, 4, 7, 1000, 4095] {
            for k in 0..n.min(50) {
                let t = k as f64 / n as f64;
                assert!(node_offset(t, k, n).abs() <= 1.2e-16, "n={n} k={k}");
            }
        }
        assert!((node_offset(1e6 + 0.5, 0, 4).abs() - 0.5).abs() < 1e-16);
        // Near node 251 of n = 268, from t = fl(252/268): one step of 1/n, off only by the
        // rounding of 252/268 (at most 2⁻⁵⁴, times n).
        let d = node_offset(252.0 / 268.0, 251, 268);
        assert!((d * 268.0 - 1.0).abs() <= 268.0 * 2f64.powi(-54) * 1.01, "{d}");
    }
}
