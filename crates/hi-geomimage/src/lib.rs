// SPDX-License-Identifier: MIT
//! Geometry images and surface fitting from scans (Hardy 2005, §5.3, §5.4, §5.8).
//!
//! This crate turns a scan (a mesh or bare points, read and repaired by `hi-scan`) into a
//! geometry image (spherical or octahedral layout), the geometry image into a harmonic
//! surface, and that surface into a closed mesh or cubic Bézier patches, with smoothing,
//! regularisation and reduction that report their effect and a fit error measured both ways.
//! Where the thesis's rays fail (a shape that is not star-shaped) it goes past them: a mesh is
//! parameterised over the sphere, points are shrink-wrapped. It builds on `hi-surface` and
//! `hi-scan`.
//!
//! | what | thesis | where |
//! |---|---|---|
//! | spherical parameterisation of a genus-0 mesh, geometry images sampled from it | beyond §5.3 | [`sphereparam`] |
//! | parameterisation of a genus-1 mesh over the flat torus (tree–cotree cohomology basis, harmonic one-forms, reduced period basis, stretch relaxation), geometry images sampled from it with no cut | beyond §5.3 | [`torusparam`] |
//! | parameterisation of an open disc-like mesh over the unit square (Tutte–Floater), whole-sample images and their mirror doubling into periodic ones | beyond §5.3 | [`discparam`] |
//! | shrink-wrapping a point set: the zero set of its signed distance, parameterised, projected onto local quadric patches | beyond §5.3 | [`shrinkwrap`] |
//! | spectral regularisation to the scan's noise (discrepancy principle, GCV) | beyond §5.4 | [`regularise`] |
//! | the parameter domains: the sphere in its layouts, the torus, the open sheet | §5.3, beyond | [`Domain`] |
//! | the mesh of a fitted surface over every domain: closed and outward, or an open sheet | §5.3 | [`layout_mesh`] |
//! | geometry images and their harmonic surfaces | §5.3 | [`GeometryImage`] |
//! | ray-cast geometry images (algorithm 2): spherical, octahedral and flattened octahedral layouts, with star-shape and hole diagnostics | §5.3 | [`spherical`], [`Layout`] |
//! | periodic smoothing (box, Gaussian), Theorem 5.3 resampling with the reduction error | §5.4 | [`Smoothing`], [`GeometryImage::smoothed`], [`GeometryImage::resampled`] |
//! | algorithm 1: cross-sections, a harmonic curve per contour, insertion, rotation alignment, the reversed traversal; with failure diagnostics | §5.3, figures 5.7–5.9 | [`sections`], [`fit_sections`] |
//! | the fitting pipeline, timed stage by stage, with diagnostics and errors | §5.3, §5.8, Table 5.1 | [`fit()`] |
//! | fit quality: scan-to-surface distances, two-sided Hausdorff distance to the scan mesh | | [`distance`] |
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
//! | `parallel` | yes | every stage of a fit on all cores (rayon), and `hi-surface`'s parallel grids; without it one thread computes the surface |
//! | `serde` | no | `Serialize` and `Deserialize` for scans, options, geometry images (`{"rows": [[t₀₀, …], …]}`, read back through [`GeometryImage::try_new`]) and reports; a report's per-point distances are left out, so it stays small |

pub mod contours;
pub mod discparam;
pub mod distance;
pub mod domain;
mod error;
mod filter;
pub mod fit;
mod flat;
mod image;
mod laplace;
pub mod layout_mesh;
pub mod regularise;
pub mod sections;
#[cfg(feature = "serde")]
mod serde_impls;
pub mod shrinkwrap;
pub mod sphereparam;
pub mod spherical;
pub mod torusparam;

pub use domain::Domain;
pub use error::{Error, NonFiniteInput};
pub use filter::Smoothing;
pub use fit::{
    ErrorMeasure, Fit, FitErrors, FitOptions, FitReport, MeshSource, Method, RowPoints,
    SourceImage, Stage, StageKind, fit,
};
pub use flat::{FlatImage, FlatQuality, FlatReport, RoundsEnd};
pub use image::{GeometryImage, MAX_TEXELS};
pub use sections::{SectionFit, SectionOptions, fit_given_sections, fit_sections};
pub use spherical::Layout;

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
