// SPDX-License-Identifier: MIT
//! Points in one, two and three dimensions: the coordinates a curve interpolates.

use std::fmt::Debug;
use std::ops::{Add, AddAssign, Mul, Neg, Sub};

use glam::{DVec2, DVec3};

/// A point (or vector) that a curve can interpolate: `f64`, [`DVec2`] or [`DVec3`].
///
/// The harmonic curve X(t) = Σₖ σₖ(t)·xₖ only needs the points to form a real vector space;
/// this trait gives the generic code that, plus access to the coordinates (for the FFT, which
/// runs per coordinate) and a Euclidean norm (for curvature, arc length and errors).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ControlPoint;
///
/// let p = DVec2::new(3.0, 4.0);
/// assert_eq!(p.norm(), 5.0);
/// assert_eq!(DVec2::from_coords(|i| p.coord(i) * 2.0), DVec2::new(6.0, 8.0));
/// assert_eq!(<DVec2 as ControlPoint>::DIM, 2);
/// ```
pub trait ControlPoint:
    Copy
    + Debug
    + PartialEq
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<f64, Output = Self>
    + AddAssign
{
    /// Number of coordinates.
    const DIM: usize;
    /// The origin.
    const ZERO: Self;

    /// Coordinate `i` (0 ≤ i < `DIM`).
    ///
    /// # Panics
    ///
    /// Panics if `i >= DIM`.
    fn coord(&self, i: usize) -> f64;

    /// Builds a point from its coordinates, `f(0)`, …, `f(DIM − 1)`.
    fn from_coords(f: impl FnMut(usize) -> f64) -> Self;

    /// Euclidean inner product.
    fn dot(self, other: Self) -> f64;

    /// Euclidean length.
    fn norm(self) -> f64 {
        self.dot(self).sqrt()
    }

    /// True if every coordinate is finite (neither NaN nor ±∞).
    fn is_finite(self) -> bool;
}

impl ControlPoint for f64 {
    const DIM: usize = 1;
    const ZERO: Self = 0.0;

    fn coord(&self, i: usize) -> f64 {
        assert!(i == 0, "f64 has one coordinate, asked for coordinate {i}");
        *self
    }

    fn from_coords(mut f: impl FnMut(usize) -> f64) -> Self {
        f(0)
    }

    fn dot(self, other: Self) -> f64 {
        self * other
    }

    fn norm(self) -> f64 {
        self.abs()
    }

    fn is_finite(self) -> bool {
        f64::is_finite(self)
    }
}

impl ControlPoint for DVec2 {
    const DIM: usize = 2;
    const ZERO: Self = DVec2::ZERO;

    fn coord(&self, i: usize) -> f64 {
        self[i]
    }

    fn from_coords(mut f: impl FnMut(usize) -> f64) -> Self {
        let x = f(0);
        DVec2::new(x, f(1))
    }

    fn dot(self, other: Self) -> f64 {
        DVec2::dot(self, other)
    }

    fn is_finite(self) -> bool {
        DVec2::is_finite(self)
    }
}

impl ControlPoint for DVec3 {
    const DIM: usize = 3;
    const ZERO: Self = DVec3::ZERO;

    fn coord(&self, i: usize) -> f64 {
        self[i]
    }

    fn from_coords(mut f: impl FnMut(usize) -> f64) -> Self {
        let x = f(0);
        let y = f(1);
        DVec3::new(x, y, f(2))
    }

    fn dot(self, other: Self) -> f64 {
        DVec3::dot(self, other)
    }

    fn is_finite(self) -> bool {
        DVec3::is_finite(self)
    }
}

/// Checks that `points` is non-empty and finite; the check every constructor runs.
pub(crate) fn check_points<P: ControlPoint>(points: &[P]) -> Result<(), crate::Error> {
    if points.is_empty() {
        return Err(crate::Error::Empty);
    }
    match points.iter().position(|p| !p.is_finite()) {
        Some(index) => Err(crate::Error::NonFinitePoint { index }),
        None => Ok(()),
    }
}

/// Checks that a parameter is finite.
pub(crate) fn check_param(name: &'static str, value: f64) -> Result<(), crate::Error> {
    if value.is_finite() { Ok(()) } else { Err(crate::Error::NonFiniteParameter { name, value }) }
}
