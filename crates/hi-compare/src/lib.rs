// SPDX-License-Identifier: MIT
//! The curves and surfaces the thesis compares harmonic interpolation against (A. Hardy,
//! *Harmonic interpolation for smooth curves and surfaces*, 2005, chapter 2; §4.4 for the
//! B-spline surface fit; §4.5 for curve subdivision), and the measures it compares them by.
//!
//! Every curve here implements [`ParamCurve`] over t ∈ [0, 1] (1-periodic when closed), so
//! curvature, torsion, arc length and the fairness measures are computed the same way for all
//! of them and for the harmonic curves of `hi-curve`; the piecewise polynomial ones convert to
//! [`hi_bezier::PiecewiseBezier`].
//!
//! | what | where |
//! |---|---|
//! | Lagrange interpolation (Neville), §2.3 | [`lagrange`] |
//! | Catmull-Rom, Bessel-Overhauser, Kochanek–Bartels (TCB), §2.6–2.8 | [`cardinal`] |
//! | uniform and non-uniform B-splines, §2.9–2.10 | [`bspline`] |
//! | NURBS and rational conics, §2.11 | [`nurbs`] |
//! | open and periodic B-spline interpolation, §2.12 | [`bspline_interp`] |
//! | METAPOST (Hobby) curves, §2.14 | [`hobby`] |
//! | Chaikin and the 4-point scheme, §4.5 | [`corner_cutting`] |
//! | every kind by name, for tools and figures | [`CurveKind`], [`AnyCurve`] |
//! | fairness: max \|κ\|, monotone pieces of κ, bending energy, confinement, §2.1 | [`fairness`] |
//! | bicubic B-spline surfaces through slices of data (§4.4, Watt & Watt's curve network), exact and Adini Bézier patches | [`bspline_fit`], [`BSplineFit`], [`BSplineSurface`] |
//!
//! # Examples
//!
//! ```
//! use glam::DVec2;
//! use hi_compare::{AnyCurve, CurveKind};
//! use hi_curve::ParamCurve;
//!
//! // The thesis's comparison in one loop: every closed interpolating kind through a square
//! // passes through its corners at t = k/4.
//! let square = vec![DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
//! for kind in [CurveKind::Harmonic, CurveKind::CatmullRom, CurveKind::HobbyClosed] {
//!     let curve: AnyCurve<DVec2> = kind.build(square.clone())?;
//!     for (k, p) in square.iter().enumerate() {
//!         assert!((curve.eval(k as f64 / 4.0) - *p).length() < 1e-12, "{kind:?} at {k}");
//!     }
//! }
//! # Ok::<(), hi_compare::Error>(())
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
//! - `serde`: `Serialize` and `Deserialize` for the comparison curves, their options and the
//!   fairness measures. A curve is written as the data its constructor takes and read back
//!   through that constructor (an invalid file is an error, never an invalid curve):
//!   [`bspline::BSplineCurve`] `{"degree", "knots", "control", "closed"}` (the breakpoints of
//!   one period when closed), [`nurbs::NurbsCurve`] the same plus `"weights"`,
//!   [`lagrange::LagrangeCurve`] `{"points", "params"}`, [`corner_cutting::ChaikinCurve`]
//!   `{"points", "closed"}`, [`corner_cutting::FourPointCurve`] the same plus `"weight"`,
//!   [`bspline_interp::InterpolatingSpline`] `{"points", "params", "end"}` (`end` null when
//!   periodic), [`AnyCurve`] `{"kind", "points"}`. Results that come out of a solve
//!   (the Hobby curve, the Hermite splines, the §4.4 surface fit) have no `serde` form: keep
//!   their inputs, or their Bézier form through `hi-bezier`'s `serde`.

pub mod bspline;
pub mod bspline_fit;
pub mod bspline_interp;
pub mod cardinal;
mod check;
pub mod corner_cutting;
mod error;
pub mod fairness;
pub mod hobby;
pub mod kind;
pub mod lagrange;
pub mod nurbs;
#[cfg(feature = "serde")]
mod serde_impls;

pub use bspline_fit::{BSplineFit, BSplineSurface, BezierPatchGrid};
pub use error::Error;
pub use hi_curve::{ControlPoint, ParamCurve, ParamRange, ParamWindow, PlaneCurve, SpaceCurve};
pub use kind::{AnyCurve, CurveKind};

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
