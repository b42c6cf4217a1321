// SPDX-License-Identifier: MIT
//! The closed interval `[lo, hi]` of `f64` and its outward-rounded arithmetic (Hardy 2005, §5.6,
//! "Interval arithmetic": the operational definitions of `X + Y`, `X − Y`, `X · Y`, `1/X`, `X/Y`).
//!
//! Every operation returns an interval that contains the exact real result for every choice of
//! real arguments in the operands (the inclusion property). Bounds are the correctly rounded
//! ones for `+ − × ÷ √` and `sqr` (see `round.rs`); `powi` rounds once per multiplication.
//!
//! Conventions (those of IEEE 1788, the interval standard): intervals are sets of reals, so an
//! endpoint may be infinite but never a member; `[+∞, +∞]` is not an interval; there is one empty
//! interval. Zeros are compared by value: `-0.0` and `+0.0` are the same endpoint, and results
//! carry `-0.0` as a lower and `+0.0` as an upper zero bound. A NaN anywhere gives the empty
//! interval, never a panic.

use std::fmt;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

use crate::round::{
    add_down, add_up, div_down, div_up, mul_down, mul_up, sqrt_down, sqrt_up, sub_down, sub_up,
};

/// A closed interval of real numbers with `f64` endpoints (Hardy 2005, §5.6: X = [xₗ, xᵤ]).
///
/// # Examples
///
/// ```
/// use hi_interval::Interval;
/// let x = Interval::new(1.0, 2.0);
/// let y = Interval::new(-1.0, 0.5);
/// let p = x * y; // [min of the corner products, max of them]
/// assert_eq!((p.lo(), p.hi()), (-2.0, 1.0));
/// // 0.1 is not a double: the enclosure of 1/10 has two neighbouring endpoints around it.
/// let tenth = Interval::point(1.0) / Interval::point(10.0);
/// assert_eq!(tenth.lo().next_up(), tenth.hi());
/// assert!(tenth.contains(0.1));
/// ```
#[derive(Clone, Copy, PartialEq)]
pub struct Interval {
    // Invariant: either lo <= hi, lo < +inf, hi > -inf (a non-empty interval), or
    // lo = +inf, hi = -inf (the empty interval). Never NaN. A zero lo is -0.0, a zero hi is +0.0.
    lo: f64,
    hi: f64,
}

impl fmt::Debug for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_empty() {
            write!(f, "[empty]")
        } else {
            write!(f, "[{:e}, {:e}]", self.lo, self.hi)
        }
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}

impl Default for Interval {
    /// The point interval `[0, 0]`.
    fn default() -> Self {
        Self::ZERO
    }
}

impl From<f64> for Interval {
    /// The point interval `[x, x]` (see [`Interval::point`]).
    fn from(x: f64) -> Self {
        Self::point(x)
    }
}

/// Normalises zero endpoints: -0.0 below, +0.0 above.
#[inline]
fn lo0(x: f64) -> f64 {
    if x == 0.0 { -0.0 } else { x }
}

#[inline]
fn hi0(x: f64) -> f64 {
    if x == 0.0 { 0.0 } else { x }
}

impl Interval {
    /// The empty interval ∅ (Hardy 2005, §5.6: the result of a bisection step with no root).
    pub const EMPTY: Self = Self { lo: f64::INFINITY, hi: f64::NEG_INFINITY };
    /// The whole real line `[−∞, +∞]`.
    pub const ENTIRE: Self = Self { lo: f64::NEG_INFINITY, hi: f64::INFINITY };
    /// `[0, 0]`.
    pub const ZERO: Self = Self { lo: -0.0, hi: 0.0 };
    /// `[1, 1]`.
    pub const ONE: Self = Self { lo: 1.0, hi: 1.0 };
    /// `[−1, 1]`, the range of sin and cos.
    pub const UNIT: Self = Self { lo: -1.0, hi: 1.0 };
    /// The tightest double interval containing π.
    pub const PI: Self =
        Self { lo: std::f64::consts::PI, hi: 3.141_592_653_589_793_6 /* next_up(PI) */ };

    /// The interval `[lo, hi]` (§5.6: X = { x | xₗ ≤ x ≤ xᵤ }).
    ///
    /// Returns [`Interval::EMPTY`] when `lo > hi`, when either bound is NaN, or when the set
    /// `{ x ∈ ℝ | lo ≤ x ≤ hi }` is empty (`lo = +∞` or `hi = −∞`). Never panics.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert_eq!(Interval::new(0.0, 1.0).width(), 1.0);
    /// assert!(Interval::new(2.0, 1.0).is_empty());
    /// assert!(Interval::new(f64::NAN, 1.0).is_empty());
    /// ```
    #[must_use]
    #[inline]
    pub fn new(lo: f64, hi: f64) -> Self {
        if lo <= hi && lo < f64::INFINITY && hi > f64::NEG_INFINITY {
            Self { lo: lo0(lo), hi: hi0(hi) }
        } else {
            Self::EMPTY
        }
    }

    /// `[lo, hi]`, or an error when the bounds do not describe a non-empty interval.
    ///
    /// # Errors
    ///
    /// [`crate::Error::InvalidBounds`] when `lo > hi`, a bound is NaN, `lo = +∞` or `hi = −∞`.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert!(Interval::try_new(0.0, 1.0).is_ok());
    /// assert!(Interval::try_new(1.0, 0.0).is_err());
    /// ```
    pub fn try_new(lo: f64, hi: f64) -> Result<Self, crate::Error> {
        let res = Self::new(lo, hi);
        if res.is_empty() { Err(crate::Error::InvalidBounds { lo, hi }) } else { Ok(res) }
    }

    /// The point interval `[x, x]`; empty for NaN and ±∞ (which are not reals).
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert_eq!(Interval::point(2.5).width(), 0.0);
    /// assert!(Interval::point(f64::INFINITY).is_empty());
    /// ```
    #[must_use]
    #[inline]
    pub fn point(x: f64) -> Self {
        if x.is_finite() { Self { lo: lo0(x), hi: hi0(x) } } else { Self::EMPTY }
    }

    /// The tightest interval containing the rational `p/q`; empty when `q = 0` or either is NaN.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// let third = Interval::ratio(1.0, 3.0);
    /// assert!(third.lo() < third.hi() && third.lo().next_up() == third.hi());
    /// ```
    #[must_use]
    pub fn ratio(p: f64, q: f64) -> Self {
        Self::point(p) / Self::point(q)
    }

    /// Lower bound xₗ (`+∞` for the empty interval).
    #[must_use]
    #[inline]
    pub fn lo(self) -> f64 {
        self.lo
    }

    /// Upper bound xᵤ (`−∞` for the empty interval).
    #[must_use]
    #[inline]
    pub fn hi(self) -> f64 {
        self.hi
    }

    /// Is this the empty interval?
    #[must_use]
    #[inline]
    pub fn is_empty(self) -> bool {
        self.lo > self.hi
    }

    /// Is this `[−∞, +∞]`?
    #[must_use]
    pub fn is_entire(self) -> bool {
        self.lo == f64::NEG_INFINITY && self.hi == f64::INFINITY
    }

    /// Are both bounds finite (and the interval non-empty)?
    #[must_use]
    pub fn is_bounded(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    /// Is this a single point `[x, x]`?
    #[must_use]
    #[inline]
    pub fn is_point(self) -> bool {
        self.lo == self.hi
    }

    /// Does the interval contain the real `x`? (False for NaN and ±∞.)
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert!(Interval::new(-1.0, 0.0).contains(0.0));
    /// assert!(!Interval::ENTIRE.contains(f64::INFINITY));
    /// ```
    #[must_use]
    #[inline]
    pub fn contains(self, x: f64) -> bool {
        x.is_finite() && self.lo <= x && x <= self.hi
    }

    /// Is `self` a subset of `other`? (The empty set is a subset of everything.)
    #[must_use]
    #[inline]
    pub fn is_subset(self, other: Self) -> bool {
        self.is_empty() || (other.lo <= self.lo && self.hi <= other.hi)
    }

    /// Is `self` inside the interior of `other`? (Krawczyk's test K(X) ⊂ int X, §5.6.)
    ///
    /// An infinite endpoint of `other` counts as open, so everything is interior to ENTIRE.
    #[must_use]
    #[inline]
    pub fn is_interior(self, other: Self) -> bool {
        self.is_empty()
            || ((other.lo < self.lo || other.lo == f64::NEG_INFINITY)
                && (self.hi < other.hi || other.hi == f64::INFINITY))
    }

    /// Do the two intervals share a point?
    #[must_use]
    #[inline]
    pub fn overlaps(self, other: Self) -> bool {
        !self.intersection(other).is_empty()
    }

    /// Is every point of `self` strictly below every point of `other`?
    #[must_use]
    pub fn precedes_strictly(self, other: Self) -> bool {
        !self.is_empty() && !other.is_empty() && self.hi < other.lo
    }

    /// Midpoint m(X) = (xₗ + xᵤ)/2 (§5.6), a double inside X.
    ///
    /// Unbounded intervals give `0` for ENTIRE and `±f64::MAX` for half-lines; the empty interval
    /// gives NaN (the only NaN this crate returns, documented so callers can test for it).
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert_eq!(Interval::new(1.0, 2.0).mid(), 1.5);
    /// assert!(Interval::new(f64::MAX, f64::MAX).mid().is_finite());
    /// ```
    #[must_use]
    #[inline]
    pub fn mid(self) -> f64 {
        if self.is_empty() {
            return f64::NAN;
        }
        match (self.lo.is_finite(), self.hi.is_finite()) {
            (false, false) => 0.0,
            (false, true) => -f64::MAX,
            (true, false) => f64::MAX,
            (true, true) => {
                let m = 0.5 * self.lo + 0.5 * self.hi;
                // Both halves are exact unless subnormal; clamp for safety.
                m.clamp(self.lo, self.hi)
            }
        }
    }

    /// Width w(X) = xᵤ − xₗ (§5.6), rounded up; `0` for the empty interval.
    #[must_use]
    #[inline]
    pub fn width(self) -> f64 {
        if self.is_empty() { 0.0 } else { sub_up(self.hi, self.lo) }
    }

    /// Radius: the smallest `r` with X ⊆ [m − r, m + r] for `m = self.mid()`, rounded up.
    #[must_use]
    #[inline]
    pub fn rad(self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let m = self.mid();
        sub_up(m, self.lo).max(sub_up(self.hi, m))
    }

    /// Magnitude |X| = max(|xₗ|, |xᵤ|) (§5.6, the interval vector norm's building block);
    /// `0` for the empty interval.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert_eq!(Interval::new(-3.0, 2.0).mag(), 3.0);
    /// ```
    #[must_use]
    #[inline]
    pub fn mag(self) -> f64 {
        if self.is_empty() { 0.0 } else { self.lo.abs().max(self.hi.abs()) }
    }

    /// Mignitude ⟨X⟩ = min{|x| : x ∈ X}; `0` when X contains 0 or is empty.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert_eq!(Interval::new(-3.0, -2.0).mig(), 2.0);
    /// assert_eq!(Interval::new(-3.0, 2.0).mig(), 0.0);
    /// ```
    #[must_use]
    #[inline]
    pub fn mig(self) -> f64 {
        if self.is_empty() || (self.lo <= 0.0 && 0.0 <= self.hi) {
            0.0
        } else {
            self.lo.abs().min(self.hi.abs())
        }
    }

    /// Convex hull X ∪ Y (the smallest interval containing both).
    #[must_use]
    #[inline]
    pub fn hull(self, other: Self) -> Self {
        if self.is_empty() {
            return other;
        }
        if other.is_empty() {
            return self;
        }
        Self { lo: self.lo.min(other.lo), hi: self.hi.max(other.hi) }
    }

    /// Intersection X ∩ Y (§5.6: the interval Newton step Xₙ₊₁ = K(Xₙ, …) ∩ Xₙ).
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// let a = Interval::new(0.0, 2.0);
    /// assert_eq!(a.intersection(Interval::new(1.0, 3.0)), Interval::new(1.0, 2.0));
    /// assert!(a.intersection(Interval::new(3.0, 4.0)).is_empty());
    /// ```
    #[must_use]
    #[inline]
    pub fn intersection(self, other: Self) -> Self {
        let lo = self.lo.max(other.lo);
        let hi = self.hi.min(other.hi);
        if lo <= hi { Self { lo: lo0(lo), hi: hi0(hi) } } else { Self::EMPTY }
    }

    /// Splits at the midpoint into two halves, [xₗ, m] and [m, xᵤ] (the bisection step of §5.6).
    #[must_use]
    pub fn bisect(self) -> (Self, Self) {
        let m = self.mid();
        (Self::new(self.lo, m), Self::new(m, self.hi))
    }

    /// Widens both ends by `eps` (absolute), rounding outward (ε-inflation before a Krawczyk test).
    #[must_use]
    pub fn inflate(self, eps: f64) -> Self {
        if self.is_empty() || eps.is_nan() {
            return self;
        }
        Self::new(sub_down(self.lo, eps), add_up(self.hi, eps))
    }

    /// Absolute value {|x| : x ∈ X} = [⟨X⟩, |X|].
    #[must_use]
    #[inline]
    pub fn abs(self) -> Self {
        if self.is_empty() { self } else { Self { lo: lo0(self.mig()), hi: self.mag() } }
    }

    /// Pointwise minimum {min(x, y)}: `[min(xₗ, yₗ), min(xᵤ, yᵤ)]`.
    #[must_use]
    #[inline]
    pub fn min(self, other: Self) -> Self {
        if self.is_empty() || other.is_empty() {
            return Self::EMPTY;
        }
        Self::new(self.lo.min(other.lo), self.hi.min(other.hi))
    }

    /// Pointwise maximum {max(x, y)}: `[max(xₗ, yₗ), max(xᵤ, yᵤ)]`.
    #[must_use]
    #[inline]
    pub fn max(self, other: Self) -> Self {
        if self.is_empty() || other.is_empty() {
            return Self::EMPTY;
        }
        Self::new(self.lo.max(other.lo), self.hi.max(other.hi))
    }

    /// Square {x² : x ∈ X}, tighter than `X · X` when X contains 0 (§5.6, polynomial extensions).
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// let x = Interval::new(-1.0, 2.0);
    /// assert_eq!(x.sqr(), Interval::new(0.0, 4.0));
    /// assert_eq!(x * x, Interval::new(-2.0, 4.0));
    /// ```
    #[must_use]
    pub fn sqr(self) -> Self {
        if self.is_empty() {
            return self;
        }
        let (m, big) = (self.mig(), self.mag());
        Self::new(mul_down(m, m), mul_up(big, big))
    }

    /// Integer power {xⁿ : x ∈ X} (`X⁰ = [1, 1]`; negative `n` divide, as in [`Interval::div_extended`]).
    ///
    /// Computed by binary powering of the endpoint magnitudes with directed rounding, so the
    /// bounds can be several ulps wide for large |n|.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert_eq!(Interval::new(-2.0, 1.0).powi(3), Interval::new(-8.0, 1.0));
    /// assert_eq!(Interval::new(-2.0, 1.0).powi(2), Interval::new(0.0, 4.0));
    /// assert_eq!(Interval::new(2.0, 4.0).powi(-1), Interval::new(0.25, 0.5));
    /// ```
    #[must_use]
    pub fn powi(self, n: i32) -> Self {
        if self.is_empty() {
            return self;
        }
        if n == 0 {
            return Self::ONE;
        }
        let k = n.unsigned_abs();
        if n > 0 {
            self.pow_unsigned(k)
        } else if self.contains(0.0) {
            // 1/Xᵏ: the zero of Xᵏ is dropped by the division (see `div_extended`).
            Self::ONE / self.pow_unsigned(k)
        } else {
            // (1/X)ᵏ keeps a tiny result where Xᵏ would overflow.
            self.recip().pow_unsigned(k)
        }
    }

    /// Xᵏ for k ≥ 1 by binary powering of the endpoint magnitudes.
    fn pow_unsigned(self, k: u32) -> Self {
        if self.is_empty() {
            return self;
        }
        if k.is_multiple_of(2) {
            Self::new(pow_down(self.mig(), k), pow_up(self.mag(), k))
        } else {
            let lo = if self.lo >= 0.0 { pow_down(self.lo, k) } else { -pow_up(-self.lo, k) };
            let hi = if self.hi >= 0.0 { pow_up(self.hi, k) } else { -pow_down(-self.hi, k) };
            Self::new(lo, hi)
        }
    }

    /// Square root {√x : x ∈ X, x ≥ 0}: the part of X below 0 is outside the domain and ignored;
    /// empty when X < 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert_eq!(Interval::new(-1.0, 4.0).sqrt(), Interval::new(0.0, 2.0));
    /// assert!(Interval::new(-2.0, -1.0).sqrt().is_empty());
    /// ```
    #[must_use]
    pub fn sqrt(self) -> Self {
        if self.is_empty() || self.hi < 0.0 {
            return Self::EMPTY;
        }
        Self::new(sqrt_down(self.lo.max(0.0)), sqrt_up(self.hi))
    }

    /// Reciprocal 1/X = [1/xᵤ, 1/xₗ] for 0 ∉ X (§5.6); for 0 ∈ X the hull of
    /// [`Interval::div_extended`].
    #[must_use]
    pub fn recip(self) -> Self {
        Self::ONE / self
    }

    /// Extended division X/Y as a pair of intervals, so that division by an interval containing 0
    /// loses nothing (the Newton step of §5.6 splits on it).
    ///
    /// The union of the two parts is {x/y : x ∈ X, y ∈ Y, y ≠ 0} (closed). The second part is
    /// empty unless 0 lies strictly inside Y and 0 ∉ X. Y = [0, 0] gives two empty parts, and 0 ∈ X
    /// with 0 ∈ Y gives the whole line.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// let (a, b) = Interval::new(1.0, 2.0).div_extended(Interval::new(-1.0, 4.0));
    /// assert_eq!(a, Interval::new(f64::NEG_INFINITY, -1.0));
    /// assert_eq!(b, Interval::new(0.25, f64::INFINITY));
    /// ```
    #[must_use]
    pub fn div_extended(self, other: Self) -> (Self, Self) {
        if self.is_empty() || other.is_empty() {
            return (Self::EMPTY, Self::EMPTY);
        }
        let (x, y) = (self, other);
        if !(y.lo <= 0.0 && 0.0 <= y.hi) {
            return (x / y, Self::EMPTY);
        }
        if y.lo == 0.0 && y.hi == 0.0 {
            return (Self::EMPTY, Self::EMPTY);
        }
        if x.lo <= 0.0 && 0.0 <= x.hi {
            return (Self::ENTIRE, Self::EMPTY);
        }
        let neg_inf = f64::NEG_INFINITY;
        let inf = f64::INFINITY;
        if x.lo > 0.0 {
            match (y.lo == 0.0, y.hi == 0.0) {
                (true, _) => (Self::new(div_down(x.lo, y.hi), inf), Self::EMPTY),
                (_, true) => (Self::new(neg_inf, div_up(x.lo, y.lo)), Self::EMPTY),
                _ => (Self::new(neg_inf, div_up(x.lo, y.lo)), Self::new(div_down(x.lo, y.hi), inf)),
            }
        } else {
            match (y.lo == 0.0, y.hi == 0.0) {
                (true, _) => (Self::new(neg_inf, div_up(x.hi, y.hi)), Self::EMPTY),
                (_, true) => (Self::new(div_down(x.hi, y.lo), inf), Self::EMPTY),
                _ => (Self::new(neg_inf, div_up(x.hi, y.hi)), Self::new(div_down(x.hi, y.lo), inf)),
            }
        }
    }
}

/// xᵏ for x ≥ 0, rounded down (binary powering; each factor is a lower bound, all ≥ 0).
fn pow_down(x: f64, mut k: u32) -> f64 {
    let (mut base, mut acc) = (x, 1.0);
    while k > 0 {
        if k & 1 == 1 {
            acc = mul_down(acc, base);
        }
        k >>= 1;
        if k > 0 {
            base = mul_down(base, base);
        }
    }
    acc.max(0.0)
}

/// xᵏ for x ≥ 0, rounded up.
fn pow_up(x: f64, mut k: u32) -> f64 {
    let (mut base, mut acc) = (x, 1.0);
    while k > 0 {
        if k & 1 == 1 {
            acc = mul_up(acc, base);
        }
        k >>= 1;
        if k > 0 {
            base = mul_up(base, base);
        }
    }
    acc
}

impl Neg for Interval {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        if self.is_empty() { self } else { Self { lo: lo0(-self.hi), hi: hi0(-self.lo) } }
    }
}

impl Add for Interval {
    type Output = Self;
    /// X + Y = [xₗ + yₗ, xᵤ + yᵤ] (§5.6), rounded outward.
    #[inline]
    fn add(self, y: Self) -> Self {
        if self.is_empty() || y.is_empty() {
            return Self::EMPTY;
        }
        Self::new(add_down(self.lo, y.lo), add_up(self.hi, y.hi))
    }
}

impl Sub for Interval {
    type Output = Self;
    /// X − Y = [xₗ − yᵤ, xᵤ − yₗ] (§5.6), rounded outward.
    #[inline]
    fn sub(self, y: Self) -> Self {
        if self.is_empty() || y.is_empty() {
            return Self::EMPTY;
        }
        Self::new(sub_down(self.lo, y.hi), sub_up(self.hi, y.lo))
    }
}

impl Mul for Interval {
    type Output = Self;
    /// X · Y = [min of the four corner products, max of them] (§5.6), rounded outward.
    #[inline]
    fn mul(self, y: Self) -> Self {
        if self.is_empty() || y.is_empty() {
            return Self::EMPTY;
        }
        let (a, b, c, d) = (self.lo, self.hi, y.lo, y.hi);
        // The classical sign cases pick the extreme corners, so most need two products.
        let (lo, hi) = if a >= 0.0 {
            if c >= 0.0 {
                (mul_down(a, c), mul_up(b, d))
            } else if d <= 0.0 {
                (mul_down(b, c), mul_up(a, d))
            } else {
                (mul_down(b, c), mul_up(b, d))
            }
        } else if b <= 0.0 {
            if c >= 0.0 {
                (mul_down(a, d), mul_up(b, c))
            } else if d <= 0.0 {
                (mul_down(b, d), mul_up(a, c))
            } else {
                (mul_down(a, d), mul_up(a, c))
            }
        } else if c >= 0.0 {
            (mul_down(a, d), mul_up(b, d))
        } else if d <= 0.0 {
            (mul_down(b, c), mul_up(a, c))
        } else {
            (mul_down(a, d).min(mul_down(b, c)), mul_up(a, c).max(mul_up(b, d)))
        };
        Self::new(lo, hi)
    }
}

impl Div for Interval {
    type Output = Self;
    /// X / Y = X · (1/Y) (§5.6) for 0 ∉ Y, computed from the corners with one rounding each.
    ///
    /// When 0 ∈ Y the result is the hull of [`Interval::div_extended`]: the whole line when 0 lies
    /// strictly inside Y (or in both X and Y), a half-line when 0 is an endpoint of Y, and empty
    /// for Y = [0, 0].
    fn div(self, y: Self) -> Self {
        if self.is_empty() || y.is_empty() {
            return Self::EMPTY;
        }
        if y.lo <= 0.0 && 0.0 <= y.hi {
            let (p, q) = self.div_extended(y);
            return p.hull(q);
        }
        let (a, b, c, d) = (self.lo, self.hi, y.lo, y.hi);
        let lo = div_down(a, c).min(div_down(a, d)).min(div_down(b, c)).min(div_down(b, d));
        let hi = div_up(a, c).max(div_up(a, d)).max(div_up(b, c)).max(div_up(b, d));
        Self::new(lo, hi)
    }
}

macro_rules! scalar_ops {
    ($($tr:ident $f:ident $atr:ident $af:ident),*) => {$(
        impl $tr<f64> for Interval {
            type Output = Self;
            /// The operation with the point interval `[x, x]` (empty when `x` is not finite).
            fn $f(self, x: f64) -> Self {
                $tr::$f(self, Self::point(x))
            }
        }
        impl $tr<Interval> for f64 {
            type Output = Interval;
            /// The operation with the point interval `[self, self]`.
            fn $f(self, x: Interval) -> Interval {
                $tr::$f(Interval::point(self), x)
            }
        }
        impl $atr for Interval {
            fn $af(&mut self, x: Self) {
                *self = $tr::$f(*self, x);
            }
        }
    )*};
}

scalar_ops!(Add add AddAssign add_assign, Sub sub SubAssign sub_assign);

impl Mul<f64> for Interval {
    type Output = Self;
    /// The product with the point interval `[x, x]` (empty when `x` is not finite): the same
    /// bounds as `X · [x, x]`, with the two corner products picked by the sign of `x` alone.
    #[inline]
    fn mul(self, x: f64) -> Self {
        if self.is_empty() || !x.is_finite() {
            return Self::EMPTY;
        }
        if x >= 0.0 {
            Self::new(mul_down(self.lo, x), mul_up(self.hi, x))
        } else {
            Self::new(mul_down(self.hi, x), mul_up(self.lo, x))
        }
    }
}

impl Mul<Interval> for f64 {
    type Output = Interval;
    /// The product of the point interval `[self, self]` with `x`.
    #[inline]
    fn mul(self, x: Interval) -> Interval {
        x * self
    }
}

impl MulAssign for Interval {
    #[inline]
    fn mul_assign(&mut self, x: Self) {
        *self = *self * x;
    }
}

impl Div<f64> for Interval {
    type Output = Self;
    /// Division by the point interval `[x, x]`.
    fn div(self, x: f64) -> Self {
        self / Self::point(x)
    }
}

impl Div<Interval> for f64 {
    type Output = Interval;
    /// The point interval `[self, self]` divided by `x`.
    fn div(self, x: Interval) -> Interval {
        Interval::point(self) / x
    }
}

impl std::iter::Sum for Interval {
    fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
        iter.fold(Self::ZERO, |a, b| a + b)
    }
}

#[cfg(test)]
mod tests;
