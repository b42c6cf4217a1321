// SPDX-License-Identifier: MIT
//! The error type of `hi-bezier`.

use std::fmt;

/// Everything that can be wrong with the input of a `hi-bezier` function; `Display` gives one
/// line naming the problem.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// No control points (or no segments) were given.
    Empty,
    /// Control point `index` has a NaN or infinite coordinate.
    NonFinitePoint {
        /// Index of the first offending point.
        index: usize,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Empty => write!(f, "no control points given: at least one is needed"),
            Error::NonFinitePoint { index } => {
                write!(f, "control point {index} has a non-finite coordinate (NaN or infinity)")
            }
        }
    }
}

impl std::error::Error for Error {}
