// SPDX-License-Identifier: MIT
//! Rays, hit records and error-bounded ray origins (Hardy 2005, §5.6: "the intersection point
//! between the parametric surface … and a ray given by p(t) = o + td").
//!
//! A secondary ray (a shadow ray) leaves a hit point p whose computed position is only known to
//! lie in a box p ± e. Its origin is pushed off the surface along the normal n by
//! d = |n|·e (pbrt-v4's `OffsetRayOrigin`), to the side the new ray travels, and each coordinate is
//! then rounded one more ulp away from the surface, so the new ray cannot meet the surface it
//! leaves (no "shadow acne").

use glam::DVec3;

/// A ray o + t·d for t in [`Ray::t_min`], [`Ray::t_max`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Ray {
    /// The origin o.
    pub origin: DVec3,
    /// The direction d (unit length for camera and shadow rays).
    pub dir: DVec3,
    /// The least parameter counted as a hit.
    pub t_min: f64,
    /// The greatest parameter counted as a hit.
    pub t_max: f64,
}

impl Ray {
    /// The ray from `origin` along `dir` for t ≥ 0.
    #[must_use]
    pub fn new(origin: DVec3, dir: DVec3) -> Self {
        Ray { origin, dir, t_min: 0.0, t_max: f64::INFINITY }
    }

    /// The point o + t·d.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_raytrace::Ray;
    /// let r = Ray::new(DVec3::ZERO, DVec3::X);
    /// assert_eq!(r.point_at(2.0), DVec3::new(2.0, 0.0, 0.0));
    /// ```
    #[must_use]
    pub fn point_at(&self, t: f64) -> DVec3 {
        self.origin + self.dir * t
    }

    /// The same ray limited to t ≤ `t_max`.
    #[must_use]
    pub fn with_t_max(mut self, t_max: f64) -> Self {
        self.t_max = t_max;
        self
    }
}

/// Where a ray met an object, and what is needed to shade it.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Hit {
    /// The ray parameter of the hit.
    pub t: f64,
    /// The hit point.
    pub point: DVec3,
    /// A bound of the error of `point`, per coordinate (the true intersection lies in
    /// `point` ± `error`).
    pub error: DVec3,
    /// The unit normal of the surface itself (the triangle's plane for meshes), for offsetting
    /// secondary rays.
    pub geometric_normal: DVec3,
    /// The unit normal for shading (interpolated for meshes).
    pub shading_normal: DVec3,
    /// Surface parameters (u, v) of the hit: the surface's own for harmonic surfaces, the
    /// global (u, v) of the patch for Bézier patches, the barycentric (b₁, b₂) for triangles.
    pub uv: (f64, f64),
    /// The surface colour at the hit, linear RGB.
    pub color: [f32; 3],
    /// Index of the object in its scene.
    pub object: usize,
}

/// γₙ = n·u/(1 − n·u) with u = 2⁻⁵³: the bound of the relative error of n rounded operations
/// (Higham; pbrt-v4 `gamma`).
#[must_use]
pub(crate) fn gamma(n: u32) -> f64 {
    let nu = f64::from(n) * f64::EPSILON * 0.5;
    nu / (1.0 - nu)
}

/// The origin of a ray leaving `point` (known to ± `error`) in direction `dir`, pushed off the
/// surface with normal `normal` to the side of `dir` (pbrt-v4 `OffsetRayOrigin`).
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_raytrace::offset_ray_origin;
/// let o = offset_ray_origin(DVec3::ZERO, DVec3::splat(1e-9), DVec3::Z, DVec3::new(0.3, 0.0, 1.0));
/// assert!(o.z > 1e-9); // above the error box, on the side the ray goes
/// let below = offset_ray_origin(DVec3::ZERO, DVec3::splat(1e-9), DVec3::Z, -DVec3::Z);
/// assert!(below.z < -1e-9);
/// ```
#[must_use]
pub fn offset_ray_origin(point: DVec3, error: DVec3, normal: DVec3, dir: DVec3) -> DVec3 {
    let d = normal.abs().dot(error.abs());
    let mut offset = normal * d;
    if dir.dot(normal) < 0.0 {
        offset = -offset;
    }
    let mut po = point + offset;
    for i in 0..3 {
        if offset[i] > 0.0 {
            po[i] = po[i].next_up();
        } else if offset[i] < 0.0 {
            po[i] = po[i].next_down();
        }
    }
    po
}
