// SPDX-License-Identifier: MIT
//! Input checks shared by the constructors of this crate. The point trait itself,
//! [`ControlPoint`], lives in the foundation crate `hi-bezier` and is re-exported here.

use crate::ControlPoint;

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
