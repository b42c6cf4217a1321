// SPDX-License-Identifier: MIT
//! The curves the thesis compares harmonic interpolation against (Hardy 2005, chapter 2,
//! §4.5 for curve subdivision), and the measures it compares them by.
//!
//! Every curve here implements [`ParamCurve`](crate::ParamCurve) over t ∈ [0, 1] (1-periodic
//! when closed), so curvature, torsion, arc length and the fairness measures are computed the
//! same way for all of them; the piecewise polynomial ones convert to
//! [`hi_bezier::PiecewiseBezier`].

pub mod bspline;
pub mod bspline_interp;
pub mod cardinal;
pub mod corner_cutting;
pub mod fairness;
pub mod hobby;
pub mod kind;
pub mod lagrange;
pub mod nurbs;

pub use kind::{AnyCurve, CurveKind, KindError};
