// SPDX-License-Identifier: MIT
//! The parameter domain of a geometry image: which surface the doubly periodic grid stands for.
//! A tensor-product harmonic surface (§5.1) is periodic in u and in v, so it is a torus; the
//! thesis makes it a sphere by doubling (§5.3: the latitude–longitude image over a doubled
//! meridian, the flattened octahedron), and the same doubling by reflection makes it an open
//! sheet:
//!
//! | domain | the image | the object once | what it fits |
//! |---|---|---|---|
//! | [`Domain::Sphere`] | a [`Layout`] of the sphere | [`Layout::covering_window`] | a closed surface of genus 0 |
//! | [`Domain::Torus`] | the flat torus R²/Z², texel (i, j) at (i/rows, j/cols), nothing doubled | the whole period | a closed surface of genus 1: a ring, a mug, a knot, with no cut and no seam |
//! | [`Domain::Sheet`] | the unit square sampled whole-sample (R × C texels, its first and last rows and columns on the sheet's rim), mirrored into a 2(R − 1) × 2(C − 1) image | u, v ∈ [0, ½] | an open sheet (a disc): a terrain, a face mask, a range image |
//!
//! The sheet's mirror image is even across both of its edges, so the harmonic surface's
//! derivative across the rim vanishes there: the rim is where the sheet ends, approached
//! perpendicularly in the parameter (the thesis's own doubling trick, as in its flattened
//! octahedron, §5.3).

use hi_surface::{ParamRange, ParamWindow};

use crate::spherical::Layout;

/// The parameter domain of a geometry image; see the module documentation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Domain {
    /// The sphere in a layout: a closed surface of genus 0.
    Sphere(Layout),
    /// The flat torus: a closed surface of genus 1.
    Torus,
    /// The unit square mirrored: an open sheet with one rim.
    Sheet,
}

impl From<Layout> for Domain {
    fn from(layout: Layout) -> Self {
        Self::Sphere(layout)
    }
}

impl Domain {
    /// Its name in reports: "sphere", "torus", "sheet".
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Sphere(_) => "sphere",
            Self::Torus => "torus",
            Self::Sheet => "sheet",
        }
    }

    /// The window of (u, v) over which the harmonic surface covers the object once: the
    /// layout's [`Layout::covering_window`] by the whole of v on the sphere, the unit square on
    /// the torus, [0, ½]² on the sheet.
    #[must_use]
    pub const fn covering_window(self) -> ParamWindow {
        match self {
            Self::Sphere(layout) => ParamWindow::new(layout.covering_window(), ParamRange::UNIT),
            Self::Torus => ParamWindow::new(ParamRange::UNIT, ParamRange::UNIT),
            Self::Sheet => ParamWindow::new(ParamRange::new(0.0, 0.5), ParamRange::new(0.0, 0.5)),
        }
    }

    /// Whether the surface is closed (a sphere or a torus), not an open sheet.
    #[must_use]
    pub const fn is_closed(self) -> bool {
        !matches!(self, Self::Sheet)
    }

    /// For each texel of a `rows × cols` image, the row-major index of the texel that stands
    /// for the same point of the object and comes first (itself, unless the layout is
    /// doubled): a texel and its representative always hold the same point.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_geomimage::domain::Domain;
    ///
    /// // A 6 × 4 sheet image mirrors a 4 × 3 square: row 4 is row 2 again, column 3 column 1.
    /// let owner = Domain::Sheet.owners(6, 4);
    /// assert_eq!(owner[4 * 4 + 3], 2 * 4 + 1);
    /// assert_eq!(Domain::Torus.owners(6, 4)[17], 17);
    /// ```
    #[must_use]
    pub fn owners(self, rows: usize, cols: usize) -> Vec<usize> {
        match self {
            Self::Sphere(layout) => {
                let mirror = layout.mirror(rows, cols);
                (0..rows * cols)
                    .map(|t| {
                        mirror.as_ref().map_or(t, |m| {
                            let (a, b) = m(t / cols, t % cols);
                            t.min(a * cols + b)
                        })
                    })
                    .collect()
            }
            Self::Torus => (0..rows * cols).collect(),
            Self::Sheet => {
                let fold = |i: usize, n: usize| if 2 * i <= n { i } else { n - i };
                (0..rows * cols)
                    .map(|t| fold(t / cols, rows) * cols + fold(t % cols, cols))
                    .collect()
            }
        }
    }

    /// How many distinct points of the object a `rows × cols` image holds (each point once).
    #[must_use]
    pub fn distinct_texels(self, rows: usize, cols: usize) -> usize {
        match self {
            Self::Sphere(Layout::Octahedron) | Self::Torus => rows * cols,
            Self::Sphere(_) => rows / 2 * cols,
            Self::Sheet => (rows / 2 + 1) * (cols / 2 + 1),
        }
    }
}
