// SPDX-License-Identifier: MIT
//! The error type of `hi-compare`.

use std::fmt;

/// Everything that can be wrong with the input of a `hi-compare` function; `Display` gives one
/// line naming the problem.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A construction needs more points than were given.
    TooFewPoints {
        /// What needs them.
        what: &'static str,
        /// How many it needs.
        needed: usize,
        /// How many there are.
        got: usize,
    },
    /// A knot vector is not a valid one (not non-decreasing, wrong length, or too many
    /// repeated knots).
    InvalidKnots {
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A rational weight is not finite and positive.
    InvalidWeight {
        /// Index of the weight.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// Node parameters that must increase decrease somewhere: parameter `index` is smaller
    /// than parameter `index − 1`.
    ParametersNotIncreasing {
        /// Index of the first parameter smaller than its predecessor.
        index: usize,
    },
    /// A result overflows the range of `f64` (finite input whose coordinates are too large, or
    /// a conversion whose coefficients grow too fast).
    Overflow {
        /// What overflows.
        what: &'static str,
    },
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
    NonFiniteGridPoint {
        /// Row index (the u direction).
        row: usize,
        /// Column index (the v direction).
        col: usize,
    },
    /// A value is out of its range: a mesh normal not of unit length, a colour component
    /// outside [0, 1], a colour-map bound.
    InvalidValue {
        /// What the value is.
        what: &'static str,
        /// Its index, for an element of a list (a vertex).
        index: Option<usize>,
        /// The value.
        value: f64,
        /// The accepted range, in words.
        expected: &'static str,
    },
    /// Too few slices for a B-spline surface fit ([`crate::bspline_fit`]).
    TooFewSlices {
        /// The least number of slices.
        needed: usize,
        /// The number given.
        got: usize,
    },
    /// A slice has too few points for its U-curve ([`crate::bspline_fit`]).
    TooFewSlicePoints {
        /// Index of the slice.
        slice: usize,
        /// The least number of points.
        needed: usize,
        /// Its number of points.
        got: usize,
    },
    /// A point of a slice has a NaN or infinite coordinate.
    NonFiniteSlicePoint {
        /// Index of the slice.
        slice: usize,
        /// Index of the point in the slice.
        point: usize,
    },
    /// A slice has a different number of points from the given u parameters.
    SliceLengthMismatch {
        /// Index of the slice.
        slice: usize,
        /// Its number of points.
        len: usize,
        /// The number of given u parameters.
        expected: usize,
    },
    /// Two consecutive points of a slice are equal: a zero chord length.
    CoincidentSlicePoints {
        /// Index of the slice.
        slice: usize,
        /// Index of the first point.
        first: usize,
        /// Index of the second point.
        second: usize,
    },
    /// Two consecutive slices have a zero (averaged) chord length between them.
    CoincidentSlices {
        /// Index of the first slice.
        first: usize,
        /// Index of the second slice.
        second: usize,
    },
    /// No curve kind has this name ([`crate::CurveKind`]'s `FromStr`).
    UnknownKind {
        /// The name given.
        name: String,
    },
    /// The curve of this kind is not piecewise polynomial, so it has no Bézier form
    /// ([`crate::AnyCurve::to_bezier`]).
    NotPolynomial {
        /// The kind.
        kind: crate::CurveKind,
    },
    /// An input `hi-curve` checks for every curve (no points, a non-finite point or
    /// parameter, a count out of range, parameters that do not match the points, coincident
    /// points or nodes, a singular system, an argument out of bounds), or an error of the
    /// harmonic curves of `hi-curve` (a [`crate::CurveKind::Harmonic`] or
    /// [`crate::CurveKind::Trig`] curve): the one description of those errors, shared.
    Curve(hi_curve::Error),
    /// An error from `hi-mesh` (a triangle mesh of a B-spline surface).
    Mesh(hi_mesh::Error),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::TooFewPoints { what, needed, got } => {
                write!(f, "{what} needs at least {}, got {got}", plural(*needed, "point"))
            }
            Error::InvalidKnots { reason } => write!(f, "invalid knot vector: {reason}"),
            Error::InvalidWeight { index, value } => {
                write!(
                    f,
                    "weight {index} = {value} is invalid: weights must be finite and positive"
                )
            }
            Error::ParametersNotIncreasing { index } => write!(
                f,
                "parameter {index} is smaller than parameter {}: the parameters must increase",
                index.saturating_sub(1)
            ),
            Error::Overflow { what } => {
                write!(f, "the {what} overflows the range of floating-point numbers")
            }
            Error::EmptyGrid => {
                write!(f, "the grid is empty: at least one row of one point is needed")
            }
            Error::RaggedGrid { row, len, expected } => write!(
                f,
                "row {row} of the grid has {len} points, row 0 has {expected}: the grid must be rectangular"
            ),
            Error::NonFiniteGridPoint { row, col } => {
                write!(f, "grid point ({row}, {col}) has a non-finite coordinate (NaN or infinity)")
            }
            Error::InvalidValue { what, index: Some(i), value, expected } => {
                write!(f, "{what} {i} = {value} is invalid: expected {expected}")
            }
            Error::InvalidValue { what, index: None, value, expected } => {
                write!(f, "{what} = {value} is invalid: expected {expected}")
            }
            Error::TooFewSlices { needed, got } => {
                write!(f, "the B-spline surface fit needs at least {needed} slices, {got} given")
            }
            Error::TooFewSlicePoints { slice, needed, got } => {
                write!(f, "slice {slice} has {got} points: its U-curve needs at least {needed}")
            }
            Error::NonFiniteSlicePoint { slice, point } => write!(
                f,
                "slice {slice}, point {point} has a non-finite coordinate (NaN or infinity)"
            ),
            Error::SliceLengthMismatch { slice, len, expected } => write!(
                f,
                "slice {slice} has {len} points but {expected} u parameters are given: with given \
                 parameters every slice needs one point per parameter"
            ),
            Error::CoincidentSlicePoints { slice, first, second } => {
                write!(f, "slice {slice}: points {first} and {second} coincide (zero chord length)")
            }
            Error::CoincidentSlices { first, second } => {
                write!(f, "slices {first} and {second} coincide (zero chord length between them)")
            }
            Error::UnknownKind { name } => {
                write!(f, "unknown curve kind '{name}': expected one of ")?;
                for (i, kind) in crate::CurveKind::ALL.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    f.write_str(kind.name())?;
                }
                Ok(())
            }
            Error::NotPolynomial { kind } => {
                let polynomial: Vec<&str> = crate::CurveKind::ALL
                    .iter()
                    .filter(|k| k.is_polynomial())
                    .map(|k| k.name())
                    .collect();
                write!(
                    f,
                    "the {kind} curve is not piecewise polynomial, so it has no Bézier form \
                     (the kinds that have one: {})",
                    polynomial.join(", ")
                )
            }
            Error::Curve(e) => write!(f, "{e}"),
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

/// "1 point", "2 points".
fn plural(count: usize, noun: &str) -> String {
    if count == 1 { format!("1 {noun}") } else { format!("{count} {noun}s") }
}
