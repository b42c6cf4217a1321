// SPDX-License-Identifier: MIT
//! Harmonic tensor-product surfaces (A. Hardy, *Harmonic interpolation for smooth curves and
//! surfaces*, 2005, §5.1, §5.2, §5.9).
//!
//! Given an m×n grid of points xⱼₖ, the harmonic surface
//!
//! p(u, v) = Σⱼ Σₖ σᵐⱼ(u)·σⁿₖ(v)·xⱼₖ
//!
//! is smooth, 1-periodic in both parameters and passes through xⱼₖ at (j/m, k/n). It builds
//! on the curve basis of `hi-curve`.
//!
//! | what | where |
//! |---|---|
//! | the surface, derivatives of any order | [`HarmonicSurface`] |
//! | normal, fundamental forms, K, H, κ₁ + κ₂, principal curvatures | [`Curvature`], [`HarmonicSurface::curvature`] |
//! | fast grids: separable basis matrices, 2-D FFT | [`HarmonicSurface::sample_params`], [`HarmonicSurface::sample_uniform`] |
//! | Theorems 5.1 and 5.3 per axis, subdivision (§5.2) | [`HarmonicSurface::resample`], [`HarmonicSurface::rotate`], [`HarmonicSurface::subdivide`] |
//! | the exact sphere and torus | [`sphere`], [`torus`] |
//! | the thirteen test surfaces of §5.9 and their curvature comparison | [`test_surfaces`], [`compare_curvature`] |
//! | triangle meshes over a parameter window: welded or split seams, poles, normals (§5.5) | [`TriangleMesh`], [`MeshOptions`] |
//! | curvature colours, blue → purple as in §5.9, with a legend | [`ColorMap`], [`ColorLegend`] |
//! | OBJ and glTF 2.0 (`.gltf`, `.glb`) files, read-back checks | [`export`] |
//! | bicubic B-spline surfaces through slices of data (§4.4, Watt & Watt's curve network), exact and Adini Bézier patches | [`bspline_fit`], [`BSplineSurface`] |
//! | subdivision surfaces of §4.5 on polygon meshes (Loop, butterfly, √3, Catmull-Clark, Doo-Sabin) | [`subdivision`] |
//! | Bézier patches (§5.7): the thesis's cubic and quintic schemes, C1 Hermite patches to a tolerance | [`bezier`] |
//!
//! # Examples
//!
//! ```
//! use hi_surface::torus;
//!
//! let t = torus(2.0, 0.5);
//! let p = t.eval(0.25, 0.0); // θ = π/2, v = 0: the outermost point on the x axis
//! assert!((p - glam::DVec3::new(2.5, 0.0, 0.0)).length() < 1e-14);
//! ```
//!
//! # Feature flags
//!
//! None: the crate has no optional features.

pub mod bezier;
pub mod bspline_fit;
mod colormap;
mod error;
mod examples;
pub mod export;
mod fft2;
mod geometry;
mod grid;
mod mesh;
mod parametric;
mod resample;
mod spectrum;
pub mod subdivision;
mod surface;

pub use bspline_fit::{BSplineFit, BSplineSurface, BezierPatchGrid};
pub use colormap::{
    ColorLegend, ColorMap, ColorMapping, ColorScale, CurvatureQuantity, HIGH_SRGB, LOW_SRGB,
    NEGATIVE_SRGB, NEUTRAL_SRGB, Palette, linear_to_srgb, linear_to_srgb_rgb, srgb_to_linear,
    srgb_to_linear_rgb,
};
pub use error::Error;
pub use examples::{sphere, torus};
pub use geometry::{Curvature, FundamentalForms, SurfaceDerivs};
pub use grid::GridSamples;
pub use mesh::{CurvatureColoring, MeshOptions, Seam, TriangleMesh};
pub use parametric::{
    CurvatureComparison, ParametricSurface, compare_curvature, test_surface, test_surfaces,
};
pub use resample::Axis;
pub use subdivision::{MeshError, PolyMesh};
pub use surface::HarmonicSurface;
