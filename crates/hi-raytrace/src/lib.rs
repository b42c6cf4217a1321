// SPDX-License-Identifier: MIT
//! Ray tracing of harmonic surfaces (Hardy 2005, §5.5, §5.6).
//!
//! This crate will hold a small renderer: interval Newton and bisection ray tracing of harmonic
//! surfaces, Bézier patches in a bounding volume hierarchy, triangle meshes, shading, and
//! curvature colour maps. It builds on `hi-surface`.
//!
//! Nothing is implemented yet.
