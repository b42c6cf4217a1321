// SPDX-License-Identifier: MIT
//! Geometry images: a rectangular, doubly periodic grid of points (Gu, Gortler and Hoppe
//! 2002), the input of a harmonic tensor-product surface (§5.3).

use glam::DVec3;
use hi_surface::HarmonicSurface;

use crate::{Error, NonFiniteInput};

/// The largest number of texels an image may have (2²⁶, a 8192×8192 image).
pub const MAX_TEXELS: usize = 1 << 26;

/// A geometry image: `rows × cols` points; row i samples u = i/rows and column j samples
/// v = j/cols of a doubly periodic parameterisation, so the harmonic surface through the
/// texels (§5.1) is closed in both directions.
#[derive(Clone, Debug, PartialEq)]
pub struct GeometryImage {
    rows: usize,
    cols: usize,
    texels: Vec<DVec3>,
}

impl GeometryImage {
    /// An image from its texels in row-major order (`texels[i·cols + j]`).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidResolution`] if a side is 0, the texel count is not `rows·cols` or
    /// exceeds [`MAX_TEXELS`]; [`Error::NonFinite`] for a texel with a NaN or infinite
    /// coordinate.
    pub fn try_new(rows: usize, cols: usize, texels: Vec<DVec3>) -> Result<Self, Error> {
        check_resolution(rows, cols)?;
        if texels.len() != rows * cols {
            return Err(Error::InvalidResolution {
                rows,
                cols,
                expected: "the texel count must be rows × cols",
            });
        }
        if let Some(k) = texels.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinite {
                what: NonFiniteInput::Texel { row: k / cols, col: k % cols },
            });
        }
        Ok(Self { rows, cols, texels })
    }

    /// Rows: samples of u.
    #[must_use]
    pub const fn rows(&self) -> usize {
        self.rows
    }

    /// Columns: samples of v.
    #[must_use]
    pub const fn cols(&self) -> usize {
        self.cols
    }

    /// The texel at row `i`, column `j`, both taken modulo the image size (the image is
    /// periodic).
    #[must_use]
    pub fn get(&self, i: usize, j: usize) -> DVec3 {
        self.texels[(i % self.rows) * self.cols + j % self.cols]
    }

    /// All texels, row-major.
    #[must_use]
    pub fn texels(&self) -> &[DVec3] {
        &self.texels
    }

    /// The harmonic surface through the texels: p(i/rows, j/cols) = texel (i, j) (§5.1, no
    /// linear system).
    ///
    /// # Errors
    ///
    /// Never for a valid image; the surface layer's error is passed on.
    pub fn surface(&self) -> Result<HarmonicSurface<DVec3>, Error> {
        Ok(HarmonicSurface::try_from_flat(self.rows, self.cols, self.texels.clone())?)
    }

    /// An image from the points of a harmonic surface's grid.
    ///
    /// # Errors
    ///
    /// As [`GeometryImage::try_new`].
    pub fn try_from_surface(surface: &HarmonicSurface<DVec3>) -> Result<Self, Error> {
        Self::try_new(surface.m(), surface.n(), surface.points().to_vec())
    }
}

/// Checks an image size.
pub(crate) fn check_resolution(rows: usize, cols: usize) -> Result<(), Error> {
    if rows < 2 || cols < 2 || rows.checked_mul(cols).is_none_or(|t| t > MAX_TEXELS) {
        return Err(Error::InvalidResolution {
            rows,
            cols,
            expected: "each side at least 2 and at most 2²⁶ texels in all",
        });
    }
    Ok(())
}
