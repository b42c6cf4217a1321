// SPDX-License-Identifier: MIT
//! Bézier curves and patches: the polynomial foundation of the `harmonic` workspace
//! (Hardy 2005, §2.3–2.5 and §4.2).
//!
//! This crate holds the [`ControlPoint`] trait every `hi-*` crate uses for points, Bézier curves
//! of any degree ([`BezierCurve`]) and piecewise Bézier curves ([`PiecewiseBezier`]).
//! Harmonic curves and surfaces convert themselves into these types (§5.7), so that other
//! software can read them.
//!
//! It is a foundation crate: it depends on no other `hi-*` crate.
//!
//! # Examples
//!
//! ```
//! use glam::DVec2;
//! use hi_bezier::BezierCurve;
//!
//! let c = BezierCurve::new(vec![DVec2::ZERO, DVec2::new(1.0, 2.0), DVec2::new(3.0, 0.0)]);
//! assert_eq!(c.degree(), 2);
//! // B(½) = ¼·P₀ + ½·P₁ + ¼·P₂.
//! assert!((c.eval(0.5) - DVec2::new(1.25, 1.0)).length() < 1e-15);
//! ```
//!
//! # Feature flags
//!
//! None: the crate has no optional features.

mod curve;
mod error;
mod piecewise;
mod point;

pub use curve::BezierCurve;
pub use error::Error;
pub use piecewise::PiecewiseBezier;
pub use point::ControlPoint;
