// SPDX-License-Identifier: MIT
//! Bézier curves and patches: the polynomial foundation of the `harmonic` workspace.
//!
//! This crate will hold Bernstein polynomials of any degree, `BezierCurve` of any degree in one
//! to three dimensions (de Casteljau evaluation, hodograph, split, degree elevation, adaptive
//! flattening, bounds), rational Bézier curves and exact conics, and tensor-product and
//! triangular patches (Hardy 2005, §2.3 and §4.2). Harmonic curves and surfaces convert
//! themselves into these types (§5.7).
//!
//! It is a foundation crate: it depends on no other `hi-*` crate. Nothing is implemented yet.
