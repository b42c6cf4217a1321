// SPDX-License-Identifier: MIT
//! Enclosures of the transcendental functions (Hardy 2005, §5.6, "Transcendental Functions":
//! the case analysis of cos([xₗ, xᵤ]) by the extrema the interval crosses).
//!
//! # What is relied on
//!
//! Point values come from the platform `libm` through `f64::sin`, `cos`, `exp`, `ln` and `atan`
//! (glibc on Linux, where Rust's std links it). glibc documents errors below 1 ulp for these
//! functions over the whole double range, including its exact Payne–Hanek reduction of huge
//! arguments for sin and cos. Every point value is therefore widened by [`LIBM_ULPS`] = 2 ulps on
//! each side, which covers any error below 2 ulps. The peer test `tests/peer_mpmath.rs` checks
//! the resulting enclosures against mpmath's `iv` at 160 bits on 10⁵ cases per function, including
//! huge arguments and arguments next to multiples of π/2.
//!
//! # sin and cos
//!
//! For a wide argument (width ≥ 2π as computed, or an infinite end) the range is `[−1, 1]`.
//! Otherwise the computed width is below `TAU`, the double below 2π, so the true width is below
//! 2π too: the arc from xₗ to xᵤ winds less than once, and which extrema it crosses follows from the
//! quadrants of its ends, read from the signs of the (rigorously enclosed) sin and cos values at
//! the ends. This needs no reduction by π of our own and is exact for any magnitude: it relies
//! only on the signs being right, which holds whenever libm's relative error is below 1, because
//! sin and cos of a nonzero double are never 0. As a second guard, an end whose sin (cos) value
//! is below 2⁻⁵⁰ in magnitude is treated as possibly lying on either side of the multiple of π
//! (of π/2): the extremum at that multiple is added to the range. That costs nothing (the
//! function is within 2⁻¹⁰⁰ of the extremum there) and keeps the result true even if libm's
//! reduction were off by up to 2⁻⁵⁰ near multiples of π/2.

use crate::Interval;
use crate::round::{ulps_down, ulps_up};

/// Ulps by which every libm point value is widened on each side (libm error bound: below 1 ulp,
/// with a factor 2 of margin).
pub const LIBM_ULPS: u32 = 2;

/// Below this magnitude the sign of a computed sin or cos value is not trusted (see the module
/// docs).
const SIGN_GUARD: f64 = 8.881_784_197_001_252e-16; // 2^-50

/// Enclosure of a libm value `v` (true value within 2 ulps), clamped to `[lo_clamp, hi_clamp]`.
fn widen(v: f64, lo_clamp: f64, hi_clamp: f64) -> (f64, f64) {
    (ulps_down(v, LIBM_ULPS).max(lo_clamp), ulps_up(v, LIBM_ULPS).min(hi_clamp))
}

/// What is known about one end of a sin/cos argument.
struct End {
    /// Enclosure of sin at the end.
    sin: (f64, f64),
    /// Enclosure of cos at the end.
    cos: (f64, f64),
    /// Quadrant 0..4 of the angle (quadrant q is [qπ/2, (q+1)π/2) mod 2π).
    quadrant: u8,
    /// The end may lie on either side of the angle `near * π/2` (mod 2π), or `None`.
    near: Option<u8>,
}

fn end(x: f64) -> End {
    if x == 0.0 {
        return End { sin: (-0.0, 0.0), cos: (1.0, 1.0), quadrant: 0, near: None };
    }
    let (s, c) = x.sin_cos();
    let sin = widen(s, -1.0, 1.0);
    let cos = widen(c, -1.0, 1.0);
    // Near a multiple of π: the sign of sin is not trusted, cos's sign is (|cos| ≈ 1).
    if s.abs() < SIGN_GUARD {
        let q = if c > 0.0 { 0 } else { 2 };
        return End { sin, cos, quadrant: q, near: Some(q) };
    }
    if c.abs() < SIGN_GUARD {
        let q = if s > 0.0 { 1 } else { 3 };
        return End { sin, cos, quadrant: q, near: Some(q) };
    }
    let quadrant = match (s > 0.0, c > 0.0) {
        (true, true) => 0,
        (true, false) => 1,
        (false, false) => 2,
        (false, true) => 3,
    };
    End { sin, cos, quadrant, near: None }
}

/// Ranges of (sin, cos) over X, by the quadrant analysis of §5.6.
fn sin_cos_range(x: Interval) -> (Interval, Interval) {
    if x.is_empty() {
        return (Interval::EMPTY, Interval::EMPTY);
    }
    let (lo, hi) = (x.lo(), x.hi());
    if !lo.is_finite() || !hi.is_finite() || hi - lo >= std::f64::consts::TAU {
        return (Interval::UNIT, Interval::UNIT);
    }
    let a = end(lo);
    let b = end(hi);
    // Angles k·π/2 (k = 0..4) whose extremum lies in [lo, hi]: crossed quadrant boundaries.
    let mut crossed = [false; 4];
    let steps = (4 + b.quadrant - a.quadrant) % 4;
    // Same quadrant: either a short arc (< π/2) or almost a full turn (> 3π/2).
    let steps = if steps == 0 && hi - lo > 3.0 { 4 } else { steps };
    for i in 1..=steps {
        crossed[usize::from((a.quadrant + i) % 4)] = true;
    }
    for e in [&a, &b] {
        if let Some(k) = e.near {
            crossed[usize::from(k)] = true;
        }
    }
    let mut s = (a.sin.0.min(b.sin.0), a.sin.1.max(b.sin.1));
    let mut c = (a.cos.0.min(b.cos.0), a.cos.1.max(b.cos.1));
    if crossed[0] {
        c.1 = 1.0;
    }
    if crossed[1] {
        s.1 = 1.0;
    }
    if crossed[2] {
        c.0 = -1.0;
    }
    if crossed[3] {
        s.0 = -1.0;
    }
    (Interval::new(s.0, s.1), Interval::new(c.0, c.1))
}

impl Interval {
    /// Enclosure of {sin x : x ∈ X} (§5.6, the case analysis by the extrema crossed).
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// let s = Interval::new(1.0, 2.0).sin(); // crosses π/2
    /// assert_eq!(s.hi(), 1.0);
    /// assert!(s.contains(1f64.sin()));
    /// assert_eq!(Interval::new(0.0, 7.0).sin(), Interval::UNIT);
    /// ```
    #[must_use]
    pub fn sin(self) -> Self {
        sin_cos_range(self).0
    }

    /// Enclosure of {cos x : x ∈ X} (§5.6).
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// let c = Interval::new(3.0, 3.5).cos(); // crosses π
    /// assert_eq!(c.lo(), -1.0);
    /// assert!(Interval::point(1e300).cos().width() < 1e-15);
    /// ```
    #[must_use]
    pub fn cos(self) -> Self {
        sin_cos_range(self).1
    }

    /// Enclosures of sin and cos together (one quadrant analysis for both).
    #[must_use]
    pub fn sin_cos(self) -> (Self, Self) {
        sin_cos_range(self)
    }

    /// Enclosure of {eˣ : x ∈ X}; exp is increasing.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// let e = Interval::new(0.0, 1.0).exp();
    /// assert_eq!(e.lo(), 1.0);
    /// assert!(e.contains(std::f64::consts::E));
    /// ```
    #[must_use]
    pub fn exp(self) -> Self {
        if self.is_empty() {
            return self;
        }
        let lo = if self.lo() == 0.0 { 1.0 } else { widen(self.lo().exp(), 0.0, f64::MAX).0 };
        let hi = if self.hi() == 0.0 { 1.0 } else { widen(self.hi().exp(), 0.0, f64::INFINITY).1 };
        Self::new(lo, hi)
    }

    /// Enclosure of {ln x : x ∈ X, x > 0}: the part of X at or below 0 is outside the domain and
    /// ignored (so `[0, 1]` gives `[−∞, 0]`); empty when X ≤ 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// assert_eq!(Interval::new(1.0, 1.0).ln(), Interval::ZERO);
    /// assert!(Interval::new(1.0, 3.0).ln().contains(1.0));
    /// assert!(Interval::new(-1.0, 0.0).ln().is_empty());
    /// ```
    #[must_use]
    pub fn ln(self) -> Self {
        if self.is_empty() || self.hi() <= 0.0 {
            return Self::EMPTY;
        }
        let ln_bounds = |v: f64| -> (f64, f64) {
            if v == 1.0 {
                (0.0, 0.0)
            } else if v == f64::INFINITY {
                (f64::MAX, f64::INFINITY)
            } else {
                widen(v.ln(), f64::NEG_INFINITY, f64::INFINITY)
            }
        };
        let lo = if self.lo() <= 0.0 { f64::NEG_INFINITY } else { ln_bounds(self.lo()).0 };
        Self::new(lo, ln_bounds(self.hi()).1)
    }

    /// Enclosure of {atan x : x ∈ X}; atan is increasing with range (−π/2, π/2).
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_interval::Interval;
    /// let a = Interval::new(0.0, 1.0).atan();
    /// assert!(a.contains(std::f64::consts::FRAC_PI_4));
    /// ```
    #[must_use]
    pub fn atan(self) -> Self {
        if self.is_empty() {
            return self;
        }
        let half_pi_up = std::f64::consts::FRAC_PI_2.next_up();
        let f = |v: f64| -> (f64, f64) {
            if v == 0.0 {
                (0.0, 0.0)
            } else if v == f64::INFINITY {
                (std::f64::consts::FRAC_PI_2, half_pi_up)
            } else if v == f64::NEG_INFINITY {
                (-half_pi_up, -std::f64::consts::FRAC_PI_2)
            } else {
                widen(v.atan(), -half_pi_up, half_pi_up)
            }
        };
        Self::new(f(self.lo()).0, f(self.hi()).1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sin_cos_of_points_are_narrow() {
        for x in [0.1, 1.0, 3.0, -2.5, 1e6, 1e22, 1e300, -5e-300] {
            let (s, c) = Interval::point(x).sin_cos();
            assert!(s.contains(x.sin()) && c.contains(x.cos()), "x = {x}");
            assert!(s.width() <= 8.0 * f64::EPSILON && c.width() <= 8.0 * f64::EPSILON, "x = {x}");
        }
        assert_eq!(Interval::ZERO.sin(), Interval::ZERO);
        assert_eq!(Interval::ZERO.cos(), Interval::ONE);
    }

    #[test]
    fn extrema_by_quadrant() {
        use std::f64::consts::{FRAC_PI_2, PI};
        // Crossing each extremum exactly once.
        assert_eq!(Interval::new(1.0, 2.0).sin().hi(), 1.0);
        assert_eq!(Interval::new(-0.5, 0.5).cos().hi(), 1.0);
        assert_eq!(Interval::new(3.0, 3.3).cos().lo(), -1.0);
        assert_eq!(Interval::new(4.5, 4.9).sin().lo(), -1.0);
        // Monotone pieces keep the end values.
        let s = Interval::new(0.1, 1.5).sin();
        assert!(s.hi() < 1.0 && s.lo() < 0.1f64.sin() && s.lo() > 0.09, "{s}");
        // Almost a full turn in one quadrant: all four extrema.
        let wide = Interval::new(0.1, 0.1 + 2.0 * PI - 0.01);
        assert_eq!(wide.sin(), Interval::UNIT);
        assert_eq!(wide.cos(), Interval::UNIT);
        // Ends right at the largest double below π/2: the maximum is past the interval; the
        // guard may add it (sin is within 1e-32 of 1 there), the result must still hold sin.
        let s = Interval::new(1.0, FRAC_PI_2).sin();
        assert!(s.contains(FRAC_PI_2.sin()) && s.hi() >= FRAC_PI_2.sin(), "{s}");
    }
}
