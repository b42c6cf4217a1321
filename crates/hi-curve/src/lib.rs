// SPDX-License-Identifier: MIT
//! Harmonic interpolating curves (A. Hardy, *Harmonic interpolation for smooth curves and
//! surfaces*, 2005, chapters 3 and 5).
//!
//! Given points x₀, …, xₙ₋₁ (in one, two or three dimensions), the harmonic curve
//!
//! X(t) = Σₖ σⁿₖ(t)·xₖ,  t ∈ [0, 1),
//!
//! is smooth, 1-periodic and passes through xₖ at t = k/n, with no linear system to solve. The
//! basis σⁿₖ is the periodic Dirichlet kernel for odd n and Hardy's real kernel for even n
//! ([`Sigma`]); the curve is a trigonometric polynomial of degree ⌊n/2⌋, so it also has an
//! exact Fourier representation ([`Fourier`]) that gives fast spectral paths (FFT sampling,
//! insertion, subdivision).
//!
//! | what | where |
//! |---|---|
//! | basis σⁿₖ in four forms, derivatives, complex kernel | [`Sigma`], [`Form`] |
//! | the curve, derivatives, curvature, torsion, Frenet frame, arc length | [`HarmonicCurve`] |
//! | Fourier coefficients and uniform sampling by FFT | [`Fourier`] |
//! | rotation (Thm 5.1 and an exact one), insertion/reduction (Thm 5.3), subdivision (§5.2) | [`HarmonicCurve`] methods |
//! | trigonometric interpolation of §2.13 | [`TrigonometricCurve`] |
//! | non-uniform interpolation (§3.10): the thesis formula and true node interpolation | [`NonUniformCurve`] |
//! | Bézier forms (§5.7): the thesis cubic and quintic schemes, C1 Hermite pieces to a tolerance, deviation measured and bounded | [`bezier`] |
//!
//! # Examples
//!
//! ```
//! use glam::DVec2;
//! use hi_curve::{HarmonicCurve, ParamCurve};
//!
//! // The harmonic curve through the vertices of a square is its circumcircle (docs/math.md §3).
//! let square = vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
//! let curve = HarmonicCurve::new(square);
//! for i in 0..100 {
//!     let t = i as f64 / 100.0;
//!     assert!((curve.eval(t).length() - 1.0).abs() < 1e-14);
//!     assert!((curve.curvature(t).unwrap() - 1.0).abs() < 1e-12);
//! }
//! assert!((curve.eval(0.25) - DVec2::Y).length() < 1e-15); // passes through x₁ at t = 1/4
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
//! - `serde`: `Serialize` and `Deserialize` for the curves, the basis and the small value types.
//!   A curve is written as the data it interpolates and read back through its checked
//!   constructor, which rebuilds its spectrum: [`HarmonicCurve`] and [`TrigonometricCurve`]
//!   are `{"points": [x₀, …]}`, [`NonUniformCurve`] `{"points", "params", "variant"}`,
//!   [`Fourier`] `{"cos": [a₀, …], "sin": [b₀, …]}`, [`Sigma`] `{"n": n}`. The results of
//!   [`HarmonicCurve::to_bezier`] ([`bezier::CurveBezier`], [`bezier::BezierSpline`],
//!   [`bezier::BasisPieces`]) are written only: read a spline back as the
//!   [`hi_bezier::PiecewiseBezier`] of its segments. Points are numbers or glam vectors.

mod basis;
pub mod bezier;

mod curve;
mod differential;
mod error;
mod fourier;
mod nonuniform;
mod point;
mod resample;
#[cfg(feature = "serde")]
mod serde_impls;
mod sinpi;
#[cfg(feature = "testing")]
pub mod testing;
mod trigonometric;

pub use basis::{Form, Sigma};
pub use curve::HarmonicCurve;
pub use differential::{FrenetFrame, ParamCurve, PlaneCurve, SpaceCurve};
pub use error::Error;
pub use fourier::Fourier;
pub use hi_bezier::{ControlPoint, ParamRange, ParamWindow};
pub use nonuniform::{NonUniformCurve, NonUniformVariant, chord_length_params};
pub use resample::ReductionDeviation;
pub use trigonometric::TrigonometricCurve;

/// The Rust examples of the project README, run as doctests so they stay true.
#[doc = include_str!("../../../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

/// Default accuracy for methods that take an `accuracy` argument (arc length), as in kurbo.
pub const DEFAULT_ACCURACY: f64 = 1e-9;

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
