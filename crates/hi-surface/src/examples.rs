// SPDX-License-Identifier: MIT
//! Surfaces that harmonic interpolation reproduces exactly (docs/math.md §3).

use std::f64::consts::FRAC_PI_2;

use glam::{DQuat, DVec3};

use crate::HarmonicSurface;

/// The 4×4 grid xⱼₖ = R𝑧(πk/2)·dⱼ of a profile dⱼ (j = 0..3) turned about the z axis.
fn revolve(profile: [DVec3; 4]) -> HarmonicSurface<DVec3> {
    let grid = profile
        .iter()
        .map(|d| (0..4).map(|k| DQuat::from_rotation_z(FRAC_PI_2 * k as f64) * *d).collect())
        .collect();
    HarmonicSurface::new(grid)
}

/// The exact sphere of radius `r` from a 4×4 grid (docs/math.md §3):
/// p(u, v) = r·(sin 2πu·cos 2πv, sin 2πu·sin 2πv, cos 2πu).
///
/// The profile is the diamond (0, 0, r), (r, 0, 0), (0, 0, −r), (−r, 0, 0), so four grid points
/// coincide at each pole. u ∈ [0, ½] covers the sphere once (u ∈ [0, 1] twice). At the poles
/// (u = 0, ½) pᵥ = 0 and the normal is undefined.
///
/// # Examples
///
/// ```
/// let s = hi_surface::sphere(2.0);
/// let c = s.curvature(0.2, 0.7).unwrap();
/// assert!((c.gaussian - 0.25).abs() < 1e-12);
/// assert!((c.mean + 0.5).abs() < 1e-12); // pᵤ × pᵥ points outward: H = −1/r
/// assert!(s.normal(0.0, 0.3).is_none()); // a pole
/// ```
#[must_use]
pub fn sphere(r: f64) -> HarmonicSurface<DVec3> {
    revolve([
        DVec3::new(0.0, 0.0, r),
        DVec3::new(r, 0.0, 0.0),
        DVec3::new(0.0, 0.0, -r),
        DVec3::new(-r, 0.0, 0.0),
    ])
}

/// The exact torus with tube radius `r` around a circle of radius `big_r` (docs/math.md §3):
/// p(u, v) = ((R + r sin θ) cos 2πv, (R + r sin θ) sin 2πv, r cos θ) with θ = 2πu.
///
/// K = sin θ/(r(R + r sin θ)) and |H| = (R + 2r sin θ)/(2r(R + r sin θ)).
///
/// # Examples
///
/// ```
/// let t = hi_surface::torus(3.0, 1.0);
/// let c = t.curvature(0.25, 0.1).unwrap(); // θ = π/2: the outer equator
/// assert!((c.gaussian - 1.0 / 4.0).abs() < 1e-12);
/// ```
#[must_use]
pub fn torus(big_r: f64, r: f64) -> HarmonicSurface<DVec3> {
    revolve([
        DVec3::new(big_r, 0.0, r),
        DVec3::new(big_r + r, 0.0, 0.0),
        DVec3::new(big_r, 0.0, -r),
        DVec3::new(big_r - r, 0.0, 0.0),
    ])
}
