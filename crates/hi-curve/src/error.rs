// SPDX-License-Identifier: MIT
//! The error type of `hi-curve`.

use std::fmt;

/// Everything that can be wrong with the input of a `hi-curve` function.
///
/// Each variant names what is wrong and where, so that a command-line tool can print it as one
/// readable line.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// No points were given.
    Empty,
    /// Point `index` has a NaN or infinite coordinate.
    NonFinitePoint {
        /// Index of the first offending point.
        index: usize,
    },
    /// A scalar argument is NaN or infinite.
    NonFiniteParameter {
        /// Name of the argument.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// The basis size n must be at least 1.
    ZeroBasisSize,
    /// A basis index k must satisfy k < n.
    IndexOutOfRange {
        /// The index given.
        k: usize,
        /// The basis size.
        n: usize,
    },
    /// A count (of samples, points or levels) is out of the range an operation accepts.
    InvalidCount {
        /// Which count.
        what: &'static str,
        /// Its value.
        value: usize,
        /// The range it must lie in, in words.
        expected: &'static str,
    },
    /// The number of parameters differs from the number of points.
    ParameterCountMismatch {
        /// Number of points.
        points: usize,
        /// Number of parameters.
        params: usize,
    },
    /// A node parameter lies outside [0, 1).
    NodeOutOfRange {
        /// Index of the parameter.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// Two node parameters coincide (modulo 1), so no curve can pass through both points.
    ParametersNotDistinct {
        /// Index of the first parameter.
        first: usize,
        /// Index of the second parameter.
        second: usize,
    },
    /// All points coincide, so chord-length parameters are undefined.
    ZeroLengthPolygon,
    /// Two consecutive points coincide, so their chord-length parameters coincide too.
    CoincidentPoints {
        /// Index of the first point.
        first: usize,
        /// Index of the next point (cyclically).
        second: usize,
    },
    /// A linear system of the construction is singular to working precision.
    Singular {
        /// Which system.
        what: &'static str,
    },
    /// A scalar argument is outside the range a construction accepts.
    ParameterOutOfBounds {
        /// Name of the argument.
        name: &'static str,
        /// Its value.
        value: f64,
        /// The accepted range, in words.
        expected: &'static str,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Empty => write!(f, "no points given: at least one point is needed"),
            Error::NonFinitePoint { index } => {
                write!(f, "point {index} has a non-finite coordinate (NaN or infinity)")
            }
            Error::NonFiniteParameter { name, value } => {
                write!(f, "{name} = {value} is not a finite number")
            }
            Error::ZeroBasisSize => write!(f, "the basis size n must be at least 1, got 0"),
            Error::IndexOutOfRange { k, n } => {
                write!(f, "basis index k = {k} is out of range for n = {n} (need k < n)")
            }
            Error::InvalidCount { what, value, expected } => {
                write!(f, "{what} = {value} is invalid: expected {expected}")
            }
            Error::ParameterCountMismatch { points, params } => write!(
                f,
                "{} given for {}: one parameter per point is needed",
                plural(*params, "parameter"),
                plural(*points, "point")
            ),
            Error::NodeOutOfRange { index, value } => {
                write!(f, "node parameter {index} = {value} is outside [0, 1)")
            }
            Error::ParametersNotDistinct { first, second } => write!(
                f,
                "parameters {first} and {second} coincide (modulo 1): the nodes must be distinct"
            ),
            Error::ZeroLengthPolygon => {
                write!(f, "all points coincide: chord-length parameters are undefined")
            }
            Error::CoincidentPoints { first, second } => write!(
                f,
                "points {first} and {second} coincide, so their chord-length parameters do too"
            ),
            Error::Singular { what } => write!(f, "the {what} is singular to working precision"),

            Error::ParameterOutOfBounds { name, value, expected } => {
                write!(f, "{name} = {value} is out of range: expected {expected}")
            }
        }
    }
}

impl std::error::Error for Error {}

/// "1 point", "2 points".
fn plural(count: usize, noun: &str) -> String {
    if count == 1 { format!("1 {noun}") } else { format!("{count} {noun}s") }
}
