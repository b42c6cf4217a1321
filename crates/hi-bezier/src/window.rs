// SPDX-License-Identifier: MIT
//! Parameter ranges and windows: the one vocabulary every crate of the workspace uses for a
//! piece of a curve's parameter line ([`ParamRange`]) or of a surface's parameter plane
//! ([`ParamWindow`]).

/// The parameters from `start` to `end`: a curve's domain, the piece of it to cut out, one
/// side of a patch's window.
///
/// It is plain data: `start > end` is allowed where a method says what it means (a reversed
/// piece in [`BezierCurve::subsegment`](crate::BezierCurve::subsegment)); methods that need
/// an increasing, finite range check it and say so.
///
/// # Examples
///
/// ```
/// use hi_bezier::ParamRange;
/// let r = ParamRange::new(0.25, 0.75);
/// assert_eq!(r.width(), 0.5);
/// assert_eq!(r.lerp(0.5), 0.5);
/// assert!(r.contains(0.25) && !r.contains(0.8));
/// assert_eq!(ParamRange::UNIT, ParamRange::new(0.0, 1.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ParamRange {
    /// The first parameter.
    pub start: f64,
    /// The last parameter.
    pub end: f64,
}

impl ParamRange {
    /// [0, 1]: the whole of a Bézier curve, or one period of a harmonic curve.
    pub const UNIT: Self = Self { start: 0.0, end: 1.0 };

    /// The range from `start` to `end`.
    #[must_use]
    pub const fn new(start: f64, end: f64) -> Self {
        Self { start, end }
    }

    /// `end − start`.
    #[must_use]
    pub fn width(self) -> f64 {
        self.end - self.start
    }

    /// The parameter a fraction `s` of the way from `start` to `end`: start + s·(end − start).
    #[must_use]
    pub fn lerp(self, s: f64) -> f64 {
        self.start + s * (self.end - self.start)
    }

    /// Whether `start ≤ t ≤ end` (false for NaN).
    #[must_use]
    pub fn contains(self, t: f64) -> bool {
        self.start <= t && t <= self.end
    }

    /// Whether both ends are finite and `start < end`.
    #[must_use]
    pub fn is_increasing(self) -> bool {
        self.start.is_finite() && self.end.is_finite() && self.start < self.end
    }
}

/// A rectangle `u × v` of a surface's parameter plane: the window of a patch, the piece of a
/// surface to mesh or to cut out.
///
/// # Examples
///
/// ```
/// use hi_bezier::{ParamRange, ParamWindow};
/// let w = ParamWindow::new(ParamRange::new(0.0, 0.5), ParamRange::UNIT);
/// assert_eq!(w.lerp(0.5, 0.5), (0.25, 0.5));
/// assert!(w.contains(0.5, 1.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ParamWindow {
    /// The range of the first parameter, u.
    pub u: ParamRange,
    /// The range of the second parameter, v.
    pub v: ParamRange,
}

impl ParamWindow {
    /// [0, 1]²: the whole of a Bézier patch, or one period of a harmonic surface.
    pub const UNIT: Self = Self { u: ParamRange::UNIT, v: ParamRange::UNIT };

    /// The window `u × v`.
    #[must_use]
    pub const fn new(u: ParamRange, v: ParamRange) -> Self {
        Self { u, v }
    }

    /// The point a fraction `(s, r)` of the way across: (u.lerp(s), v.lerp(r)).
    #[must_use]
    pub fn lerp(self, s: f64, r: f64) -> (f64, f64) {
        (self.u.lerp(s), self.v.lerp(r))
    }

    /// Whether (u, v) lies in the window, edges included.
    #[must_use]
    pub fn contains(self, u: f64, v: f64) -> bool {
        self.u.contains(u) && self.v.contains(v)
    }
}
