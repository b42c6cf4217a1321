// SPDX-License-Identifier: MIT
//! [`Scalar`]: the arithmetic shared by `f64` and [`Interval`], so a formula written once gives
//! both a value and its interval extension (Hardy 2005, §5.6: "we can thus create interval
//! extensions for polynomial functions, and functions such as σ").

use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

use crate::Interval;

/// A number type with the operations the harmonic formulas use: `f64` (values) and [`Interval`]
/// (inclusion-monotonic interval extensions, §5.6).
///
/// Constants must enter through [`Scalar::from_f64`] (exact doubles), [`Scalar::ratio`] or
/// [`Scalar::pi`], so that an interval evaluation encloses the real formula, not the
/// floating-point one: `S::from_f64(0.1)` is the double nearest 0.1, while `S::ratio(1.0, 10.0)`
/// encloses 1/10.
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, Scalar};
/// // Written once: f(t) = sin(πt)·cos(πt).
/// fn f<S: Scalar>(t: S) -> S {
///     let a = S::pi() * t;
///     a.sin() * a.cos()
/// }
/// let t = 0.3;
/// let value = f(t);
/// let enclosure = f(Interval::new(0.25, 0.35));
/// assert!(enclosure.contains(value));
/// ```
pub trait Scalar:
    Copy
    + Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The exact double `x` (a point interval for [`Interval`]).
    fn from_f64(x: f64) -> Self;
    /// The rational `p/q` (enclosed for [`Interval`]).
    fn ratio(p: f64, q: f64) -> Self;
    /// π (enclosed for [`Interval`]).
    fn pi() -> Self;
    /// Zero.
    fn zero() -> Self {
        Self::from_f64(0.0)
    }
    /// One.
    fn one() -> Self {
        Self::from_f64(1.0)
    }
    /// Square x².
    #[must_use]
    fn sqr(self) -> Self;
    /// Integer power xⁿ.
    #[must_use]
    fn powi(self, n: i32) -> Self;
    /// Square root.
    #[must_use]
    fn sqrt(self) -> Self;
    /// Sine.
    #[must_use]
    fn sin(self) -> Self;
    /// Cosine.
    #[must_use]
    fn cos(self) -> Self;
    /// Exponential.
    #[must_use]
    fn exp(self) -> Self;
    /// Natural logarithm.
    #[must_use]
    fn ln(self) -> Self;
    /// Arc tangent.
    #[must_use]
    fn atan(self) -> Self;
    /// Absolute value.
    #[must_use]
    fn abs(self) -> Self;
    /// A representative double: the value itself, or the midpoint of an interval.
    fn to_mid(self) -> f64;
}

impl Scalar for f64 {
    fn from_f64(x: f64) -> Self {
        x
    }
    fn ratio(p: f64, q: f64) -> Self {
        p / q
    }
    fn pi() -> Self {
        std::f64::consts::PI
    }
    fn sqr(self) -> Self {
        self * self
    }
    fn powi(self, n: i32) -> Self {
        f64::powi(self, n)
    }
    fn sqrt(self) -> Self {
        f64::sqrt(self)
    }
    fn sin(self) -> Self {
        f64::sin(self)
    }
    fn cos(self) -> Self {
        f64::cos(self)
    }
    fn exp(self) -> Self {
        f64::exp(self)
    }
    fn ln(self) -> Self {
        f64::ln(self)
    }
    fn atan(self) -> Self {
        f64::atan(self)
    }
    fn abs(self) -> Self {
        f64::abs(self)
    }
    fn to_mid(self) -> f64 {
        self
    }
}

impl Scalar for Interval {
    fn from_f64(x: f64) -> Self {
        Self::point(x)
    }
    fn ratio(p: f64, q: f64) -> Self {
        Self::ratio(p, q)
    }
    fn pi() -> Self {
        Self::PI
    }
    fn sqr(self) -> Self {
        Self::sqr(self)
    }
    fn powi(self, n: i32) -> Self {
        Self::powi(self, n)
    }
    fn sqrt(self) -> Self {
        Self::sqrt(self)
    }
    fn sin(self) -> Self {
        Self::sin(self)
    }
    fn cos(self) -> Self {
        Self::cos(self)
    }
    fn exp(self) -> Self {
        Self::exp(self)
    }
    fn ln(self) -> Self {
        Self::ln(self)
    }
    fn atan(self) -> Self {
        Self::atan(self)
    }
    fn abs(self) -> Self {
        Self::abs(self)
    }
    fn to_mid(self) -> f64 {
        self.mid()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly<S: Scalar>(x: S) -> S {
        // (x − 1)(x − 2) written expanded, so the interval version overestimates.
        x.sqr() - S::from_f64(3.0) * x + S::from_f64(2.0)
    }

    #[test]
    fn one_formula_two_types() {
        for i in 0..50 {
            let t = -1.0 + 0.1 * f64::from(i);
            let x = Interval::new(t, t + 0.1);
            let enc = poly(x);
            for j in 0..=10 {
                let s = t + 0.01 * f64::from(j);
                if x.contains(s) {
                    assert!(enc.contains(poly(s)), "t = {s}");
                }
            }
        }
        assert!(<Interval as Scalar>::ratio(1.0, 10.0).contains(0.1), "1/10 enclosed");
    }
}
