// SPDX-License-Identifier: MIT
//! Directed rounding without a rounding mode: error-free transformations (Hardy 2005, §5.6,
//! "if we use the correct rounding on a computer").
//!
//! Rust computes in round-to-nearest only. Each function here computes the nearest result `r`
//! and then decides, exactly, on which side of `r` the true result lies, using the classical
//! error-free transformations: `TwoSum` (Knuth) for sums, and the exact error of a product
//! (`TwoProduct`: one fused multiply-add where the CPU target has FMA, else Dekker's product with
//! Veltkamp's split) for products, for the remainder of a quotient and for the residual of a
//! square root. The result is stepped one ulp (`f64::next_down`/`f64::next_up`) only when the
//! true value is on the far side, so the bounds are the correctly rounded ones. Where an error
//! term could underflow (results or operands below about 2⁻⁹⁵⁶) the error is not exact, and the
//! functions step one ulp unconditionally, which is still a valid bound.
//!
//! Infinite arguments follow the interval conventions of IEEE 1788: `0 · ∞ = 0` in products of
//! endpoints, and an overflowed finite result rounds down to `f64::MAX` (up to `+∞`).

/// Below this magnitude the fma error terms may underflow, so exactness is not decided.
const TINY: f64 = 1.0e-288; // about 2^-956

/// Below 2⁹⁹⁵ in magnitude Veltkamp's split (a multiplication by 2²⁷ + 1) cannot overflow.
const SPLIT_MAX: f64 = 6.69e299; // about 2^995

/// The rounding error `a·b − fl(a·b)` of a product `p = fl(a·b)`, exact when `|p| ≥ TINY` and
/// `p` is finite: one fused multiply-add where the target has FMA, else Dekker's
/// `TwoProduct` with Veltkamp's split (a libm `fma` call is far slower than 17 flops).
#[inline]
fn product_error(a: f64, b: f64, p: f64) -> f64 {
    // Dekker's partial products must not overflow either: keep |p| well below MAX.
    if cfg!(target_feature = "fma")
        || a.abs() > SPLIT_MAX
        || b.abs() > SPLIT_MAX
        || p.abs() > 1.0e306
    {
        return a.mul_add(b, -p);
    }
    let split = |x: f64| {
        let c = 134_217_729.0 * x; // 2^27 + 1
        let hi = c - (c - x);
        (hi, x - hi)
    };
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

/// `a + b` rounded toward −∞.
#[inline]
pub(crate) fn add_down(a: f64, b: f64) -> f64 {
    let s = a + b;
    if !s.is_finite() {
        // Overflow of finite arguments: the true sum is finite, so the lower bound is ±MAX or -inf.
        return if s == f64::INFINITY && a.is_finite() && b.is_finite() { f64::MAX } else { s };
    }
    let bb = s - a;
    let err = (a - (s - bb)) + (b - bb);
    if err < 0.0 { s.next_down() } else { s }
}

/// `a + b` rounded toward +∞.
#[inline]
pub(crate) fn add_up(a: f64, b: f64) -> f64 {
    -add_down(-a, -b)
}

/// `a − b` rounded toward −∞.
#[inline]
pub(crate) fn sub_down(a: f64, b: f64) -> f64 {
    add_down(a, -b)
}

/// `a − b` rounded toward +∞.
#[inline]
pub(crate) fn sub_up(a: f64, b: f64) -> f64 {
    add_up(a, -b)
}

/// `a · b` rounded toward −∞, with `0 · ∞ = 0`.
#[inline]
pub(crate) fn mul_down(a: f64, b: f64) -> f64 {
    if a == 0.0 || b == 0.0 {
        return 0.0;
    }
    let p = a * b;
    if !p.is_finite() {
        return if p == f64::INFINITY && a.is_finite() && b.is_finite() { f64::MAX } else { p };
    }
    if p.abs() < TINY {
        return p.next_down();
    }
    let err = product_error(a, b, p);
    if err < 0.0 { p.next_down() } else { p }
}

/// `a · b` rounded toward +∞, with `0 · ∞ = 0`.
#[inline]
pub(crate) fn mul_up(a: f64, b: f64) -> f64 {
    -mul_down(-a, b)
}

/// `a / b` rounded toward −∞, for `b ≠ 0`; `x/∞ = 0`.
#[inline]
pub(crate) fn div_down(a: f64, b: f64) -> f64 {
    if a == 0.0 {
        return 0.0;
    }
    let q = a / b;
    if !q.is_finite() {
        if q.is_nan() {
            // ∞/∞ has no value; −∞ is a valid lower bound whatever the limit.
            return f64::NEG_INFINITY;
        }
        return if q == f64::INFINITY && a.is_finite() && b.is_finite() { f64::MAX } else { q };
    }
    if b.is_infinite() {
        // A finite numerator over an infinite endpoint: the limit is exactly 0.
        return 0.0;
    }
    if q.abs() < TINY || a.abs() < TINY {
        return q.next_down();
    }
    // a = q·b + r exactly, so a/b = q + r/b; q·b = p + e exactly and a − p is exact (Sterbenz).
    let p = q * b;
    if !p.is_finite() {
        return q.next_down(); // q·b overflowed next to MAX: the error is unknown.
    }
    let r = (a - p) - product_error(q, b, p);
    if (r < 0.0) != (b < 0.0) && r != 0.0 { q.next_down() } else { q }
}

/// `a / b` rounded toward +∞, for `b ≠ 0`.
#[inline]
pub(crate) fn div_up(a: f64, b: f64) -> f64 {
    -div_down(-a, b)
}

/// `√a` rounded toward −∞, for `a ≥ 0`.
#[inline]
pub(crate) fn sqrt_down(a: f64) -> f64 {
    if a == 0.0 || a == f64::INFINITY {
        return a.abs();
    }
    let s = a.sqrt();
    if a < TINY {
        // The residual a − s² may underflow: not exact.
        return s.next_down().max(0.0);
    }
    let p = s * s;
    if !p.is_finite() {
        return s.next_down();
    }
    let r = (a - p) - product_error(s, s, p);
    if r < 0.0 { s.next_down() } else { s }
}

/// `√a` rounded toward +∞, for `a ≥ 0`.
#[inline]
pub(crate) fn sqrt_up(a: f64) -> f64 {
    if a == 0.0 || a == f64::INFINITY {
        return a.abs();
    }
    let s = a.sqrt();
    if a < TINY {
        return s.next_up();
    }
    let p = s * s;
    if !p.is_finite() {
        return s.next_up();
    }
    let r = (a - p) - product_error(s, s, p);
    if r > 0.0 { s.next_up() } else { s }
}

/// Steps `x` down by `n` ulps.
#[inline]
pub(crate) fn ulps_down(mut x: f64, n: u32) -> f64 {
    for _ in 0..n {
        x = x.next_down();
    }
    x
}

/// Steps `x` up by `n` ulps.
#[inline]
pub(crate) fn ulps_up(mut x: f64, n: u32) -> f64 {
    for _ in 0..n {
        x = x.next_up();
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_round_in_the_right_direction() {
        // 1 + 2^-60 is not representable: nearest is 1.
        let t = 2f64.powi(-60);
        assert_eq!(add_down(1.0, t), 1.0);
        assert_eq!(add_up(1.0, t), 1.0f64.next_up());
        assert_eq!(add_down(1.0, -t), 1.0f64.next_down());
        assert_eq!(add_up(1.0, -t), 1.0);
        assert_eq!(add_down(0.5, 0.25), 0.75);
        assert_eq!(add_up(0.5, 0.25), 0.75);
        assert_eq!(add_down(f64::MAX, f64::MAX), f64::MAX);
        assert_eq!(add_up(f64::MAX, f64::MAX), f64::INFINITY);
    }

    #[test]
    fn products_quotients_roots() {
        // 0.1 · 3: the true product of the two doubles is above their rounded product?
        // Decide with exact rational arithmetic on integers: 3 = 3, 0.1 = m·2^e.
        let p = 0.1f64 * 3.0;
        assert!(mul_down(0.1, 3.0) <= p && p <= mul_up(0.1, 3.0), "product bracket");
        assert_eq!(mul_up(0.1, 3.0).next_down(), mul_down(0.1, 3.0), "inexact: 1 ulp apart");
        assert_eq!(mul_down(1.5, 2.0), 3.0);
        assert_eq!(mul_up(1.5, 2.0), 3.0);
        assert_eq!(mul_down(0.0, f64::INFINITY), 0.0);
        assert_eq!(div_down(1.0, 4.0), 0.25);
        assert_eq!(div_up(1.0, 4.0), 0.25);
        assert_eq!(div_up(1.0, 3.0).next_down(), div_down(1.0, 3.0), "1/3 inexact");
        assert_eq!(div_down(1.0, f64::INFINITY), 0.0);
        assert_eq!(sqrt_down(4.0), 2.0);
        assert_eq!(sqrt_up(4.0), 2.0);
        assert_eq!(sqrt_up(2.0).next_down(), sqrt_down(2.0), "√2 inexact");
        assert!(sqrt_down(2.0) * sqrt_down(2.0) < 2.0, "lower root squared is below 2");
    }
}
