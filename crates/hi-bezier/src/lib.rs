// SPDX-License-Identifier: MIT
//! Bézier curves and patches: the polynomial foundation of the `harmonic` workspace
//! (Hardy 2005, §2.5 and §4.3).
//!
//! This crate holds the [`ControlPoint`] trait every `hi-*` crate uses for points, and the
//! Bézier toolbox of the thesis's background chapters, in any degree and for points in one, two
//! or three dimensions (`f64`, [`glam::DVec2`], [`glam::DVec3`]). Harmonic curves and surfaces
//! convert themselves into these types (§5.7), so that other software can read them.
//!
//! It is a foundation crate: it depends on no other `hi-*` crate.
//!
//! | what | thesis | where |
//! |---|---|---|
//! | Bernstein polynomials Bⁿᵢ and their derivatives of any order | eq. 2.2, 2.3 | [`Bernstein`] (`bernstein.rs`) |
//! | Bézier curve: de Casteljau, derivatives, hodograph, elevation, curvature | eq. 2.1–2.6, fig. 2.6 | [`BezierCurve`] (`curve.rs`) |
//! | split at any t, subsegment [t₀, t₁] | Thm 2.2, fig. 2.7 | [`BezierCurve::split`], [`BezierCurve::subsegment`] (`subdivide.rs`) |
//! | flatness tests and polylines to a tolerance | eq. 2.7 | [`BezierCurve::flatten`], [`FlatnessTest`] (`flatten.rs`) |
//! | bounding boxes: control box, tight box | convex hull property | [`Aabb`], [`BezierCurve::bounding_box`] (`bounds.rs`) |
//! | roots of a 1-D Bézier polynomial in [0, 1] | | [`BezierCurve::roots`] (`roots.rs`) |
//! | plane convex hull and polygon area | fig. 2.4 | [`convex_hull_2d`], [`polygon_area`] (`hull.rs`) |
//! | rational curves: rational de Casteljau, derivatives, split, tight box, flattening | §2.5 rational | [`RationalBezierCurve`] (`rational.rs`) |
//! | conics, exact circular and elliptic arcs, full circles | fig. 2.8 | [`RationalBezierCurve::conic`], [`RationalBezierCurve::circle_arc`], [`ConicType`] (`conic.rs`) |
//! | piecewise curves, C1 and G1 chains | eq. 2.5, fig. 2.5 | [`PiecewiseBezier`] (`piecewise.rs`) |
//! | continuity at joins (C0 gap, C1 mismatch, G1 angle) | def. 2.5, 2.6 | [`Join`], [`PiecewiseBezier::joins`] (`continuity.rs`) |
//! | tensor-product patches: partials, normals, evaluation on parameter grids, split, elevation, boxes (subdivision) | §4.3, fig. 4.2 | [`BezierPatch`] (`patch.rs`) |
//! | rational patches, exact surfaces of revolution | §4.3 rational | [`RationalBezierPatch`] (`rational_patch.rs`) |
//! | triangular patches: barycentric de Casteljau, directional derivatives | §4.3, fig. 4.4 | [`TriangularPatch`] (`triangle.rs`) |
//!
//! Constructors validate their input (`try_new` returns an [`Error`], `new` panics with its
//! message); methods on valid objects never panic. Parameters outside [0, 1] extrapolate the
//! polynomial, except where a rational piece would lose its positive weights (those methods
//! return an error).
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
//! // Theorem 2.2: the halves are Bézier curves of the same degree.
//! let (left, _) = c.split(0.5);
//! assert!((left.eval(1.0) - c.eval(0.5)).length() < 1e-15);
//! // A polyline within 1e-3 of the curve.
//! assert!(c.flatten(1e-3).unwrap().len() > 2);
//! ```
//!
//! # Feature flags
//!
//! - `serde`: `Serialize` and `Deserialize` for the curves, patches, boxes and small value
//!   types. Curves and patches are written as their control data and read back through their
//!   checked constructors, so a file cannot make a value that breaks an invariant (an empty
//!   curve, a ragged patch, a non-positive weight): that is an error naming what is wrong.
//!
//!   | type | form |
//!   |---|---|
//!   | [`BezierCurve`] | `{"control": [p₀, …]}` |
//!   | [`PiecewiseBezier`] | `{"segments": [curve, …]}` |
//!   | [`RationalBezierCurve`] | `{"points": [p₀, …], "weights": [w₀, …]}` |
//!   | [`BezierPatch`] | `{"rows": [[x₀₀, …], …]}`, row j along u |
//!   | [`RationalBezierPatch`] | `{"rows": […], "weights": [[w₀₀, …], …]}` |
//!   | [`TriangularPatch`] | `{"points": […]}` in the order of [`TriangularPatch::new`] |
//!   | [`Aabb`] | `{"min": p, "max": p}` |
//!
//!   A point is what its type writes: a number for `f64`, `[x, y]` or `[x, y, z]` for glam's
//!   vectors (this feature turns on glam's `serde`).

mod bernstein;
mod bounds;
mod conic;
mod continuity;
mod curve;
mod error;
mod flatten;
mod hull;
mod patch;
mod piecewise;
mod point;
mod rational;
mod rational_patch;
mod roots;
#[cfg(feature = "serde")]
mod serde_impls;
mod small_patch;
mod subdivide;
mod triangle;
mod window;

pub use bernstein::Bernstein;
pub use bounds::Aabb;
pub use conic::ConicType;
pub use continuity::Join;
pub use curve::BezierCurve;
pub use error::Error;
pub use flatten::FlatnessTest;
pub use hull::{convex_hull_2d, polygon_area};
pub use patch::BezierPatch;
pub use piecewise::PiecewiseBezier;
pub use point::ControlPoint;
pub use rational::RationalBezierCurve;
pub use rational_patch::RationalBezierPatch;
pub use small_patch::SmallPatch;
pub use triangle::TriangularPatch;
pub use window::{ParamRange, ParamWindow};

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
