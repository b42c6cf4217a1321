// SPDX-License-Identifier: MIT
//! The error type of `hi-bezier`.

use std::fmt;

/// Everything that can be wrong with the input of a `hi-bezier` function; `Display` gives one
/// line naming the problem.
///
/// # Examples
///
/// ```
/// use hi_bezier::{BezierPatch, Error};
///
/// let ragged = BezierPatch::try_new(vec![vec![0.0, 1.0], vec![2.0]]);
/// assert_eq!(ragged, Err(Error::RaggedGrid { row: 1, expected: 2, found: 1 }));
/// assert_eq!(
///     ragged.unwrap_err().to_string(),
///     "control grid row 1 has 1 entries, expected 2 (every row must have the same length)"
/// );
/// ```
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// No control points (or no segments) were given.
    Empty,
    /// Control point `index` has a NaN or infinite coordinate.
    NonFinitePoint {
        /// Index of the first offending point (row-major for grids).
        index: usize,
    },
    /// A row of a control grid (or of a weight grid) differs in length from the first row.
    RaggedGrid {
        /// Index of the first offending row.
        row: usize,
        /// Length of the first row.
        expected: usize,
        /// Length of the offending row.
        found: usize,
    },
    /// The number of weights (for grids: of weight rows) differs from the number of control
    /// points (of control rows).
    WeightCount {
        /// Number of control points (or rows).
        expected: usize,
        /// Number of weights (or weight rows).
        found: usize,
    },
    /// A weight is zero, negative, NaN or infinite; rational curves need positive weights.
    InvalidWeight {
        /// Index of the first offending weight (row-major for grids).
        index: usize,
        /// Its value.
        value: f64,
    },
    /// The number of control points of a triangular patch is not (n+1)(n+2)/2 for any degree n.
    TriangularCount {
        /// Number of points given.
        found: usize,
    },
    /// A scalar argument is outside the range an operation accepts.
    InvalidArgument {
        /// Name of the argument.
        name: &'static str,
        /// Its value.
        value: f64,
        /// The accepted range, in words.
        expected: &'static str,
    },
    /// A flattening or bounding tolerance is not a finite number at least `minimum` (the floor
    /// below which rounding errors of the coordinates would dominate).
    InvalidTolerance {
        /// The tolerance given.
        value: f64,
        /// The smallest tolerance accepted for this input.
        minimum: f64,
    },
    /// An operation needs more points than were given.
    TooFewPoints {
        /// Number of points needed.
        needed: usize,
        /// Number of points given.
        found: usize,
    },
    /// Two inputs that must have matching lengths do not.
    LengthMismatch {
        /// Which input has the wrong length.
        what: &'static str,
        /// Length it must have.
        expected: usize,
        /// Length it has.
        found: usize,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Empty => write!(f, "no control points given: at least one is needed"),
            Error::NonFinitePoint { index } => {
                write!(f, "control point {index} has a non-finite coordinate (NaN or infinity)")
            }
            Error::RaggedGrid { row, expected, found } => write!(
                f,
                "control grid row {row} has {found} entries, expected {expected} (every row must \
                 have the same length)"
            ),
            Error::WeightCount { expected, found } => {
                write!(f, "{found} weights given for {expected} control points: need one each")
            }
            Error::InvalidWeight { index, value } => {
                write!(f, "weight {index} is {value}: weights must be positive and finite")
            }
            Error::TriangularCount { found } => write!(
                f,
                "{found} control points cannot form a triangular patch: need (n+1)(n+2)/2 for a \
                 degree n"
            ),
            Error::InvalidArgument { name, value, expected } => {
                write!(f, "argument `{name}` is {value}: expected {expected}")
            }
            Error::InvalidTolerance { value, minimum } => write!(
                f,
                "tolerance {value} is invalid: expected a finite number of at least {minimum:e}"
            ),
            Error::TooFewPoints { needed, found } => {
                write!(f, "{found} points given: at least {needed} are needed")
            }
            Error::LengthMismatch { what, expected, found } => {
                write!(f, "{what} has length {found}, expected {expected}")
            }
        }
    }
}

impl std::error::Error for Error {}

/// Checks that `points` is non-empty and finite; the check every constructor runs.
pub(crate) fn check_points<P: crate::ControlPoint>(points: &[P]) -> Result<(), Error> {
    if points.is_empty() {
        return Err(Error::Empty);
    }
    match points.iter().position(|p| !p.is_finite()) {
        Some(index) => Err(Error::NonFinitePoint { index }),
        None => Ok(()),
    }
}

/// Checks that there is one weight per point and every weight is positive and finite.
pub(crate) fn check_weights(n_points: usize, weights: &[f64]) -> Result<(), Error> {
    if weights.len() != n_points {
        return Err(Error::WeightCount { expected: n_points, found: weights.len() });
    }
    match weights.iter().position(|w| !(w.is_finite() && *w > 0.0)) {
        Some(index) => Err(Error::InvalidWeight { index, value: weights[index] }),
        None => Ok(()),
    }
}

/// Checks that a scalar argument is finite.
pub(crate) fn check_finite(name: &'static str, value: f64) -> Result<(), Error> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidArgument { name, value, expected: "a finite number" })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_message_is_one_line() {
        let all = [
            Error::Empty,
            Error::NonFinitePoint { index: 3 },
            Error::RaggedGrid { row: 1, expected: 3, found: 2 },
            Error::WeightCount { expected: 3, found: 2 },
            Error::InvalidWeight { index: 0, value: -1.0 },
            Error::TriangularCount { found: 4 },
            Error::InvalidArgument { name: "radius", value: -1.0, expected: "a positive number" },
            Error::InvalidTolerance { value: 0.0, minimum: 1e-10 },
            Error::TooFewPoints { needed: 2, found: 1 },
            Error::LengthMismatch { what: "tangents", expected: 3, found: 2 },
        ];
        for e in all {
            let text = e.to_string();
            assert!(!text.contains('\n') && !text.is_empty(), "{text:?}");
        }
    }

    #[test]
    fn weight_checks() {
        assert_eq!(check_weights(2, &[1.0]), Err(Error::WeightCount { expected: 2, found: 1 }));
        assert_eq!(
            check_weights(2, &[1.0, 0.0]),
            Err(Error::InvalidWeight { index: 1, value: 0.0 })
        );
        assert!(matches!(
            check_weights(1, &[f64::NAN]),
            Err(Error::InvalidWeight { index: 0, .. })
        ));
        assert_eq!(check_weights(2, &[1.0, 2.0]), Ok(()));
    }
}
