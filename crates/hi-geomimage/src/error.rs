// SPDX-License-Identifier: MIT
//! The error type of `hi-geomimage`.

use std::fmt;

/// Everything that can be wrong with the input of a `hi-geomimage` function; `Display` gives
/// one line naming the problem.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// An error from the scan layer (`hi-scan`): a scan that could not be read, a mesh that
    /// could not be repaired, points with no surface.
    Scan(hi_scan::Error),
    /// Too few points to build anything.
    TooFewPoints {
        /// Points given (finite ones).
        found: usize,
        /// Points needed.
        needed: usize,
    },
    /// A point, centre or other input has a NaN or infinite coordinate.
    NonFinite {
        /// Which input.
        what: NonFiniteInput,
    },
    /// An image size is out of range.
    InvalidResolution {
        /// Rows (the u direction) asked for.
        rows: usize,
        /// Columns (the v direction) asked for.
        cols: usize,
        /// The accepted range, in words.
        expected: &'static str,
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
    /// All points coincide with the centre, so they have no direction from it.
    Degenerate {
        /// What is degenerate, in words.
        what: &'static str,
    },
    /// A cross-section of algorithm 1 (§5.3) holds too few points for a contour.
    SparseSlice {
        /// The section, from the lowest (0).
        slice: usize,
        /// Sections in all.
        n_slices: usize,
        /// The lower end of its slab of heights along the slicing axis.
        from: f64,
        /// The upper end.
        to: f64,
        /// Points in it.
        found: usize,
        /// Points needed.
        needed: usize,
    },
    /// A mesh is not what a spherical parameterisation needs (one-sided, of genus above 0,
    /// no usable triangle), or the parameterisation failed.
    Topology {
        /// What is wrong, in words.
        what: String,
    },
    /// Most of a geometry image had no data and would be guesswork.
    MostlyHoles {
        /// The fraction of the image filled rather than measured.
        fraction: f64,
    },
    /// An error from the surface layer.
    Surface(hi_surface::Error),
    /// An error from the curve layer (`hi-curve`): a section's harmonic curve.
    Curve(hi_curve::Error),
    /// An error from the mesh layer (`hi-mesh`): a mesh, a colour map, a mesh file.
    Mesh(hi_mesh::Error),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Scan(e) => write!(f, "{e}"),
            Self::TooFewPoints { found, needed } => {
                write!(f, "too few points: {found} given, at least {needed} needed")
            }
            Self::NonFinite { what } => write!(f, "{what} has a NaN or infinite coordinate"),
            Self::InvalidResolution { rows, cols, expected } => {
                write!(f, "image resolution {rows}x{cols} is out of range: {expected}")
            }
            Self::InvalidOption { name, value, expected } => {
                write!(f, "option {name} = {value} is out of range: {expected}")
            }
            Self::Degenerate { what } => write!(f, "degenerate input: {what}"),
            Self::SparseSlice { slice, n_slices, from, to, found, needed } => write!(
                f,
                "section {slice} of {n_slices} (heights {from:.6} to {to:.6} along the axis) has {found} points, at least {needed} needed: use fewer sections"
            ),
            Self::Topology { what } => write!(f, "{what}"),
            Self::MostlyHoles { fraction } => write!(
                f,
                "{:.0} % of the geometry image found no scan data (too few points, or points not around the centre): nothing to fit",
                100.0 * fraction
            ),
            Self::Surface(e) => write!(f, "{e}"),
            Self::Curve(e) => write!(f, "{e}"),
            Self::Mesh(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Scan(e) => Some(e),
            Self::Surface(e) => Some(e),
            Self::Curve(e) => Some(e),
            Self::Mesh(e) => Some(e),
            _ => None,
        }
    }
}

impl From<hi_scan::Error> for Error {
    fn from(e: hi_scan::Error) -> Self {
        Self::Scan(e)
    }
}

impl From<hi_surface::Error> for Error {
    fn from(e: hi_surface::Error) -> Self {
        Self::Surface(e)
    }
}

impl From<hi_mesh::Error> for Error {
    fn from(e: hi_mesh::Error) -> Self {
        Self::Mesh(e)
    }
}

impl From<hi_curve::Error> for Error {
    fn from(e: hi_curve::Error) -> Self {
        Self::Curve(e)
    }
}

/// The input of [`Error::NonFinite`]: which point, texel or value has a NaN or infinite
/// coordinate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum NonFiniteInput {
    /// Point k of the scan.
    Point(usize),
    /// A point of one of algorithm 1's sections.
    SectionPoint {
        /// The section, from the lowest (0).
        section: usize,
        /// The point within it.
        point: usize,
    },
    /// The centre given for a radial geometry image.
    Centre,
    /// Vertex k of a mesh.
    Vertex(usize),
    /// Query point k of a distance computation.
    Query(usize),
    /// A texel of a geometry image.
    Texel {
        /// Its row.
        row: usize,
        /// Its column.
        col: usize,
    },
    /// The origin of a sampled grid.
    GridOrigin,
    /// Value k of a sampled grid.
    GridValue(usize),
}

impl fmt::Display for NonFiniteInput {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Point(k) => write!(f, "point {k}"),
            Self::SectionPoint { section, point } => write!(f, "section {section}, point {point}"),
            Self::Centre => f.write_str("the centre"),
            Self::Vertex(k) => write!(f, "vertex {k}"),
            Self::Query(k) => write!(f, "query {k}"),
            Self::Texel { row, col } => write!(f, "texel ({row}, {col})"),
            Self::GridOrigin => f.write_str("the grid's origin"),
            Self::GridValue(k) => write!(f, "grid value {k}"),
        }
    }
}
