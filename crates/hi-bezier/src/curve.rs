// SPDX-License-Identifier: MIT
//! Bézier curves of any degree (Hardy 2005, §2.3, eq. 2.2): B(t) = Σᵢ Bⁿᵢ(t)·Pᵢ.

use crate::{ControlPoint, Error};

/// A Bézier curve of degree n with control points P₀, …, Pₙ, over t ∈ [0, 1].
///
/// # Examples
///
/// ```
/// use hi_bezier::BezierCurve;
///
/// let c = BezierCurve::try_new(vec![0.0, 1.0, 0.0, 3.0]).unwrap();
/// assert_eq!(c.eval(0.0), 0.0);
/// assert_eq!(c.eval(1.0), 3.0);
/// assert!(BezierCurve::<f64>::try_new(vec![]).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierCurve<P> {
    // Invariant: at least one control point, all finite.
    control: Vec<P>,
}

impl<P: ControlPoint> BezierCurve<P> {
    /// The curve with these control points (degree = number of points − 1).
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no points, [`Error::NonFinitePoint`] for a NaN or infinite
    /// coordinate.
    pub fn try_new(control: Vec<P>) -> Result<Self, Error> {
        if control.is_empty() {
            return Err(Error::Empty);
        }
        if let Some(index) = control.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        Ok(Self { control })
    }

    /// The curve with these control points.
    ///
    /// # Panics
    ///
    /// Panics on empty or non-finite input; see [`BezierCurve::try_new`].
    #[must_use]
    pub fn new(control: Vec<P>) -> Self {
        Self::try_new(control).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The control points P₀, …, Pₙ.
    #[must_use]
    pub fn control_points(&self) -> &[P] {
        &self.control
    }

    /// The degree n.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.control.len() - 1
    }

    /// B(t) by de Casteljau's algorithm (§2.3.2), stable for every t (extrapolates outside
    /// [0, 1]).
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        let mut work = self.control.clone();
        let n = work.len();
        for level in 1..n {
            for i in 0..n - level {
                work[i] = work[i] * (1.0 - t) + work[i + 1] * t;
            }
        }
        work[0]
    }
}
