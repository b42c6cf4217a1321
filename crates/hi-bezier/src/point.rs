// SPDX-License-Identifier: MIT
//! Points in one, two and three dimensions: the coordinates of control points.

use std::fmt::Debug;
use std::ops::{Add, AddAssign, Mul, Neg, Sub};

use glam::{DVec2, DVec3};

/// A point (or vector) that curves and patches are made of: `f64`, [`DVec2`] or [`DVec3`].
///
/// Bézier and harmonic curves are affine combinations of their points, so the code only needs
/// the points to form a real vector space; this trait gives the generic code that, plus access
/// to the coordinates (for FFTs and bounding boxes, which run per coordinate) and a Euclidean
/// norm (for curvature, arc length and errors). Every `hi-*` crate uses this one trait.
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_bezier::ControlPoint;
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
