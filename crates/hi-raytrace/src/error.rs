// SPDX-License-Identifier: MIT
//! The error type of `hi-raytrace` (Hardy 2005, §5.5, §5.6): what is wrong with a scene, a camera
//! or the render settings, in one line.

use std::fmt;

/// Everything that can be wrong with the input of a `hi-raytrace` function; `Display` gives one
/// line naming the problem.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// The image has no pixels.
    ZeroSizeImage {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
    },
    /// The camera cannot form an image: eye at the target, up along the view, or a field of
    /// view outside (0, π).
    DegenerateCamera {
        /// What is wrong, in words.
        reason: &'static str,
    },
    /// A number is NaN or infinite.
    NonFinite {
        /// What the number is.
        what: &'static str,
    },
    /// The scene has no objects.
    EmptyScene,
    /// A setting or value is out of its range.
    InvalidValue {
        /// What the value is.
        what: &'static str,
        /// The value.
        value: f64,
        /// The accepted range, in words.
        expected: &'static str,
    },
    /// An error from the surface layer (Bézier conversion, meshing, colour maps).
    Surface(hi_surface::Error),
    /// An error from the mesh layer (`hi-mesh`): a mesh, a colour map, a mesh file.
    Mesh(hi_mesh::Error),
    /// The pixels of a [`crate::Rendering`] do not fill its width × height, so it has no
    /// image to encode.
    PixelCount {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
        /// The number of pixels it holds.
        pixels: usize,
    },
    /// The PNG image could not be encoded or written: the kind of the I/O error (out of memory
    /// for the encoder's limits, invalid data for any other encoder failure).
    WriteImage {
        /// What went wrong.
        kind: std::io::ErrorKind,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::ZeroSizeImage { width, height } => {
                write!(f, "image size {width}x{height} has no pixels")
            }
            Error::DegenerateCamera { reason } => write!(f, "degenerate camera: {reason}"),
            Error::NonFinite { what } => write!(f, "{what} is not finite"),
            Error::EmptyScene => f.write_str("the scene has no objects"),
            Error::InvalidValue { what, value, expected } => {
                write!(f, "{what} is {value}, expected {expected}")
            }
            Error::Surface(e) => write!(f, "{e}"),
            Error::Mesh(e) => write!(f, "{e}"),
            Error::PixelCount { width, height, pixels } => {
                write!(f, "the image has {pixels} pixels, not the {width}x{height} its size needs")
            }
            Error::WriteImage { kind } => write!(f, "cannot write the image: {kind}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Surface(e) => Some(e),
            Error::Mesh(e) => Some(e),
            _ => None,
        }
    }
}

impl From<hi_surface::Error> for Error {
    fn from(e: hi_surface::Error) -> Self {
        Error::Surface(e)
    }
}

/// `Ok(())` if every coordinate of `v` is finite, else [`Error::NonFinite`] naming `what`.
pub(crate) fn check_finite(what: &'static str, v: glam::DVec3) -> Result<(), Error> {
    if v.is_finite() { Ok(()) } else { Err(Error::NonFinite { what }) }
}

/// `Ok(())` if `x` is finite, else [`Error::NonFinite`] naming `what`.
pub(crate) fn check_finite_scalar(what: &'static str, x: f64) -> Result<(), Error> {
    if x.is_finite() { Ok(()) } else { Err(Error::NonFinite { what }) }
}

/// `Ok(x)` if `x` is finite and positive, else an error naming `what`.
pub(crate) fn check_positive(what: &'static str, x: f64) -> Result<f64, Error> {
    check_finite_scalar(what, x)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(Error::InvalidValue { what, value: x, expected: "a positive number" })
    }
}

impl From<hi_mesh::Error> for Error {
    fn from(e: hi_mesh::Error) -> Self {
        Error::Mesh(e)
    }
}
