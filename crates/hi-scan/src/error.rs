// SPDX-License-Identifier: MIT
//! The error type of `hi-scan`.

use std::fmt;

use crate::scan::{Location, ScanFormat};

/// Everything that can be wrong with the input of a `hi-scan` function; `Display` gives one
/// line naming the problem.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A scan could not be read: the format, where, and what is wrong
    /// ([`crate::scan::read_scan`], [`crate::scan::parse_scan`]).
    Read {
        /// The format being read, if known.
        format: Option<ScanFormat>,
        /// Where the problem is.
        location: Location,
        /// What is wrong, in a few words.
        message: String,
    },
    /// Too few points to build anything.
    TooFewPoints {
        /// Points given (finite ones).
        found: usize,
        /// Points needed.
        needed: usize,
    },
    /// A point or other input has a NaN or infinite coordinate.
    NonFinite {
        /// Which input.
        what: NonFiniteInput,
    },
    /// An option is out of its range.
    InvalidOption {
        /// Which option.
        name: &'static str,
        /// Its value.
        value: f64,
        /// The accepted range, in words.
        expected: &'static str,
    },
    /// The input is degenerate (all points on a line, a tree that cannot be built, …).
    Degenerate {
        /// What is degenerate, in words.
        what: &'static str,
    },
    /// A mesh cannot be made what is asked for (one-sided, of the wrong genus, no usable
    /// triangle).
    Topology {
        /// What is wrong, in words.
        what: String,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Read { format, location, message } => {
                if let Some(format) = format {
                    write!(f, "{format}")?;
                    match location {
                        Location::Line(n) => write!(f, ", line {n}")?,
                        Location::Byte(b) => write!(f, ", byte {b}")?,
                        Location::None => {}
                    }
                    f.write_str(": ")?;
                }
                f.write_str(message)
            }
            Self::TooFewPoints { found, needed } => {
                write!(f, "too few points: {found} given, at least {needed} needed")
            }
            Self::NonFinite { what } => write!(f, "{what} has a NaN or infinite coordinate"),
            Self::InvalidOption { name, value, expected } => {
                write!(f, "option {name} = {value} is out of range: {expected}")
            }
            Self::Degenerate { what } => write!(f, "degenerate input: {what}"),
            Self::Topology { what } => write!(f, "{what}"),
        }
    }
}

impl std::error::Error for Error {}

/// The input of [`Error::NonFinite`]: which point, vertex or value has a NaN or infinite
/// coordinate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum NonFiniteInput {
    /// Point k of a point set.
    Point(usize),
    /// Vertex k of a mesh.
    Vertex(usize),
    /// Query point k of a distance computation.
    Query(usize),
    /// The origin of a sampled grid.
    GridOrigin,
    /// Value k of a sampled grid.
    GridValue(usize),
}

impl fmt::Display for NonFiniteInput {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Point(k) => write!(f, "point {k}"),
            Self::Vertex(k) => write!(f, "vertex {k}"),
            Self::Query(k) => write!(f, "query {k}"),
            Self::GridOrigin => f.write_str("the grid's origin"),
            Self::GridValue(k) => write!(f, "grid value {k}"),
        }
    }
}

/// Checks a point set and its normals, if it has them: one normal per point
/// ([`Error::InvalidOption`] naming the count), every point finite ([`Error::NonFinite`] naming
/// the first that is not).
pub(crate) fn check_points(
    points: &[glam::DVec3],
    normals: Option<&[glam::DVec3]>,
) -> Result<(), Error> {
    if let Some(n) = normals
        && n.len() != points.len()
    {
        return Err(Error::InvalidOption {
            name: "normals",
            value: n.len() as f64,
            expected: "one normal per point",
        });
    }
    match points.iter().position(|p| !p.is_finite()) {
        Some(k) => Err(Error::NonFinite { what: NonFiniteInput::Point(k) }),
        None => Ok(()),
    }
}
