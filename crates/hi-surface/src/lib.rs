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
//! | triangle meshes over a parameter window: welded or split seams, poles, normals (§5.5), coloured by curvature (§5.9) | [`HarmonicSurface::to_mesh`], [`MeshOptions`] |
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
//! # References
//!
//! Sections cited as "`docs/math.md` §N" are those of the repository's page of
//! [formulas](https://github.com/harmonic-interpolation/harmonic/blob/main/docs/math.md), each
//! checked numerically; "`docs/peers.md` §N", of its page of
//! [peer programs](https://github.com/harmonic-interpolation/harmonic/blob/main/docs/peers.md)
//! that the tests compare against.
//!
//! # Feature flags
//!
//! | feature | default | adds |
//! |---|---|---|
//! | `parallel` | yes | grids, meshes and 2-D FFTs computed on all cores (rayon); without it they run on one thread with the same results |
//! | `serde` | no | `Serialize` and `Deserialize` for surfaces, options and reports; a [`HarmonicSurface`] is `{"rows": [[x₀₀, …], …]}`, the grid it interpolates, read back through [`HarmonicSurface::try_new`] (which rebuilds its spectrum) |

pub mod bezier;
mod error;
mod examples;
mod fft2;
mod geometry;
mod grid;
mod mesh;
mod parametric;
mod resample;
#[cfg(feature = "serde")]
mod serde_impls;
mod spectrum;
mod surface;
#[cfg(feature = "testing")]
pub mod testing;

pub use error::Error;
pub use examples::{sphere, torus};
pub use geometry::{Curvature, CurvatureQuantity, FundamentalForms, SurfaceDerivs};
pub use grid::GridSamples;
pub use hi_bezier::{ParamRange, ParamWindow};
pub use mesh::{CurvatureColoring, MeshOptions, Seam};
pub use parametric::{
    CurvatureComparison, ParametricSurface, compare_curvature, test_surface, test_surfaces,
};
pub use resample::Axis;
pub use surface::HarmonicSurface;

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
