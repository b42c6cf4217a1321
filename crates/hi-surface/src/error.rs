// SPDX-License-Identifier: MIT
//! The error type of `hi-surface`.

use std::fmt;

use hi_bezier::ParamWindow;

/// Everything that can be wrong with the input of a `hi-surface` function; `Display` gives one
/// line naming the problem.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// The grid has no rows, or its first row is empty.
    EmptyGrid,
    /// A row of the grid has a different length from the first.
    RaggedGrid {
        /// Index of the offending row.
        row: usize,
        /// Its length.
        len: usize,
        /// The length of row 0.
        expected: usize,
    },
    /// Grid point (row, column) has a NaN or infinite coordinate.
    NonFinitePoint {
        /// Row index (the u direction).
        row: usize,
        /// Column index (the v direction).
        col: usize,
    },
    /// A scalar argument is NaN or infinite.
    NonFiniteParameter {
        /// Name of the argument.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A count (of samples, points or levels) is out of range.
    InvalidCount {
        /// Which count.
        what: &'static str,
        /// Its value.
        value: usize,
        /// The accepted range, in words.
        expected: &'static str,
    },
    /// A parameter window is empty or not finite.
    InvalidWindow {
        /// The window as given.
        window: ParamWindow,
    },
    /// An error from the curve layer (per-axis operations).
    Curve(hi_curve::Error),
    /// A value is out of its range (a tolerance, a colour).
    InvalidValue {
        /// What the value is.
        what: &'static str,
        /// Its index, for an element of a list.
        index: Option<usize>,
        /// The value.
        value: f64,
        /// The accepted range, in words.
        expected: &'static str,
    },
    /// An error from the mesh layer (`hi-mesh`): a colour map's bounds, a mesh file.
    Mesh(hi_mesh::Error),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::EmptyGrid => {
                write!(f, "the grid is empty: at least one row of one point is needed")
            }
            Error::RaggedGrid { row, len, expected } => write!(
                f,
                "row {row} of the grid has {len} points, row 0 has {expected}: the grid must be rectangular"
            ),
            Error::NonFinitePoint { row, col } => {
                write!(f, "grid point ({row}, {col}) has a non-finite coordinate (NaN or infinity)")
            }
            Error::NonFiniteParameter { name, value } => {
                write!(f, "{name} = {value} is not a finite number")
            }
            Error::InvalidCount { what, value, expected } => {
                write!(f, "{what} = {value} is invalid: expected {expected}")
            }
            Error::InvalidWindow { window } => write!(
                f,
                "window u ∈ [{}, {}], v ∈ [{}, {}] is invalid: bounds must be finite with u0 < u1 and v0 < v1",
                window.u.start, window.u.end, window.v.start, window.v.end
            ),
            Error::Curve(e) => write!(f, "{e}"),
            Error::InvalidValue { what, index: Some(i), value, expected } => {
                write!(f, "{what} {i} = {value} is invalid: expected {expected}")
            }
            Error::InvalidValue { what, index: None, value, expected } => {
                write!(f, "{what} = {value} is invalid: expected {expected}")
            }
            Error::Mesh(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Curve(e) => Some(e),
            Error::Mesh(e) => Some(e),
            _ => None,
        }
    }
}

impl From<hi_curve::Error> for Error {
    fn from(e: hi_curve::Error) -> Self {
        Error::Curve(e)
    }
}

impl From<hi_mesh::Error> for Error {
    fn from(e: hi_mesh::Error) -> Self {
        Error::Mesh(e)
    }
}
