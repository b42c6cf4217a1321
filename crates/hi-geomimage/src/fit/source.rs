// SPDX-License-Identifier: MIT
//! The geometry image a fit's surface started from, with its diagnostics.

use hi_scan::repair::Repair;

use crate::GeometryImage;
use crate::contours::ContourImage;
use crate::flat::FlatQuality;
use crate::shrinkwrap::ShrinkWrapImage;
use crate::sphereparam::ParamQuality;
use crate::spherical::SphericalImage;

/// The geometry image a fit started from, with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub enum SourceImage {
    /// Algorithm 2's image.
    Radial(SphericalImage),
    /// §5.8's image of contours.
    Contours(ContourImage),
    /// The image of a parameterisation of a part of the scan's mesh (over the sphere, the
    /// torus or the square).
    Mesh(MeshSource),
    /// A surface wrapped onto the points: a part of the zero set of their signed distance,
    /// parameterised, or the radial image where that zero set gave nothing, projected onto
    /// them.
    ShrinkWrap(ShrinkWrapImage),
}

/// What the parameterisation of a part of a mesh did.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshSource {
    /// The image.
    pub image: GeometryImage,
    /// What was repaired to make the part the surface its domain needs.
    pub repair: Repair,
    /// The share of the scan's triangle area in the part.
    pub area_kept: f64,
    /// The quality of the map.
    pub quality: MapQuality,
    /// Texels that fell in closed holes (row-major).
    pub filled: Vec<bool>,
    /// The fraction of the distinct texels that fell in closed holes.
    pub filled_fraction: f64,
}

impl SourceImage {
    /// The image, before smoothing and reduction.
    #[must_use]
    pub const fn image(&self) -> &GeometryImage {
        match self {
            Self::Radial(s) => &s.image,
            Self::Contours(c) => &c.image,
            Self::Mesh(m) => &m.image,
            Self::ShrinkWrap(w) => &w.image,
        }
    }

    /// The fraction of the rays that met several shells (0 for a mesh parameterisation, which
    /// casts no rays).
    #[must_use]
    pub const fn non_star_fraction(&self) -> f64 {
        match self {
            Self::Radial(s) => s.non_star_fraction,
            Self::Contours(c) => c.non_star_fraction,
            Self::Mesh(_) => 0.0,
            Self::ShrinkWrap(w) => w.non_star_fraction,
        }
    }

    /// Whether the surface follows the outermost shell the rays from the centre met, so that
    /// [`SourceImage::non_star_fraction`] is the share of directions where it cannot reach the
    /// scan's inner shells: the ray methods, and a shrink-wrap that started from the rays. A
    /// mesh parameterisation and a shrink-wrap started from the zero set of the signed
    /// distance follow the scan's surface itself, whatever the rays met
    /// ([`super::FitErrors::unreached_fraction`] says what they missed).
    #[must_use]
    pub const fn follows_outer_shell(&self) -> bool {
        match self {
            Self::Radial(_) | Self::Contours(_) => true,
            Self::Mesh(_) => false,
            Self::ShrinkWrap(w) => !w.implicit_start,
        }
    }

    /// The fraction of the image with no scan data, filled: rays that found too few points,
    /// or texels on closed holes of a mesh.
    #[must_use]
    pub const fn hole_fraction(&self) -> f64 {
        match self {
            Self::Radial(s) => s.hole_fraction,
            Self::Contours(c) => c.hole_fraction,
            Self::Mesh(m) => m.filled_fraction,
            Self::ShrinkWrap(w) => w.filled_fraction,
        }
    }

    /// Which texels were filled rather than measured (row-major), if known.
    #[must_use]
    pub fn filled(&self) -> Option<&[bool]> {
        match self {
            Self::Radial(s) => Some(&s.holes),
            Self::Contours(_) => None,
            Self::Mesh(m) => Some(&m.filled),
            Self::ShrinkWrap(w) => Some(&w.filled),
        }
    }
}

/// The quality of a parameterisation: over the sphere, or flat (the torus and the square).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum MapQuality {
    /// A spherical parameterisation's.
    Sphere(ParamQuality),
    /// A flat parameterisation's.
    Flat(FlatQuality),
}

impl MapQuality {
    /// The L² stretch efficiency of Praun and Hoppe, in (0, 1], higher is better.
    #[must_use]
    pub const fn stretch_efficiency(&self) -> f64 {
        match self {
            Self::Sphere(q) => q.stretch_efficiency,
            Self::Flat(q) => q.stretch_efficiency,
        }
    }

    /// The ratio of the largest to the smallest density of the image on the surface.
    #[must_use]
    pub const fn area_ratio(&self) -> f64 {
        match self {
            Self::Sphere(q) => q.area_ratio,
            Self::Flat(q) => q.area_ratio,
        }
    }
}
