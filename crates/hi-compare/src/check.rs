// SPDX-License-Identifier: MIT
//! Input checks shared by the comparison curves.

use hi_curve::ControlPoint;
use hi_curve::Error as CurveError;

use crate::Error;

/// Largest number of samples a curve gives in one call (2²⁸, as in `hi-curve`).
pub(crate) const MAX_SAMPLES: usize = 1 << 28;

/// [`hi_curve::Error::Empty`] for no points, [`hi_curve::Error::NonFinitePoint`] for the first point with a NaN or
/// infinite coordinate.
pub(crate) fn check_points<P: ControlPoint>(points: &[P]) -> Result<(), Error> {
    if points.is_empty() {
        return Err(Error::Curve(CurveError::Empty));
    }
    match points.iter().position(|p| !p.is_finite()) {
        Some(index) => Err(Error::Curve(CurveError::NonFinitePoint { index })),
        None => Ok(()),
    }
}

/// [`hi_curve::Error::NonFiniteParameter`] unless `value` is finite.
pub(crate) fn check_param(name: &'static str, value: f64) -> Result<(), Error> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::Curve(CurveError::NonFiniteParameter { name, value }))
    }
}

/// [`hi_curve::Error::InvalidCount`] unless 1 ≤ `value` ≤ [`MAX_SAMPLES`].
pub(crate) fn check_count(what: &'static str, value: usize) -> Result<(), Error> {
    if (1..=MAX_SAMPLES).contains(&value) {
        Ok(())
    } else {
        Err(Error::Curve(CurveError::InvalidCount { what, value, expected: "between 1 and 2^28" }))
    }
}

/// The largest distance of a point from `centroid` (at least the least positive f64): the
/// size that relative tolerances scale with.
pub(crate) fn spread<P: ControlPoint>(points: &[P], centroid: P) -> f64 {
    points.iter().map(|p| (*p - centroid).norm()).fold(f64::MIN_POSITIVE, f64::max)
}
