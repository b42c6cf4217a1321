// SPDX-License-Identifier: MIT
//! Harmonic tensor-product surfaces (Hardy 2005, §5.1, §5.2, §5.9).
//!
//! This crate will hold `HarmonicSurface`, the surface p(u,v) = Σⱼ Σₖ σᵐⱼ(u) σⁿₖ(v) xⱼₖ over an
//! m×n grid of points, with its derivatives, fundamental forms, Gaussian and mean curvature, the
//! exact sphere and torus, meshing, and glTF/OBJ export. It builds on `hi-curve`.
//!
//! Nothing is implemented yet.
