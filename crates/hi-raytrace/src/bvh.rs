// SPDX-License-Identifier: MIT
//! The bounding volume hierarchy every object uses to find candidate primitives along a ray
//! (Hardy 2005, §5.6: "a bounding volume hierarchy … can also be used"): an `obvhs` BVH over
//! f32 boxes, with f64 geometry on both sides of it.
//!
//! The f64 boxes are rounded outward to f32 and padded by a small fraction of the size of the
//! whole object, which covers the error of the f32 traversal: before traversal the ray's origin is
//! moved (in f64) to where it enters the object's box, so the f32 origin is near the object and
//! its rounding is relative to the object's size, not to the camera's distance.

use std::time::Duration;

use glam::{DVec3, Vec3A};
use hi_bezier::Aabb;
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb as F32Aabb;
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::builder::build_cwbvh;
use obvhs::ray::{Ray as BvhRay, RayHit};

use crate::ray::Ray;

/// Boxes are padded by this fraction of the object's size (its box diagonal plus its largest
/// coordinate magnitude).
const PAD: f64 = 1e-6;

/// A BVH over f64 boxes of primitives.
#[derive(Clone)]
pub(crate) struct Bvh {
    bvh: CwBvh,
    /// The box of all primitives (f64, padded).
    lo: DVec3,
    hi: DVec3,
}

impl std::fmt::Debug for Bvh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Bvh")
            .field("n_primitives", &self.bvh.primitive_indices.len())
            .field("lo", &self.lo)
            .field("hi", &self.hi)
            .finish()
    }
}

/// f32 below (or at) `x`.
fn down(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x { f.next_down() } else { f }
}

/// f32 above (or at) `x`.
fn up(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) < x { f.next_up() } else { f }
}

impl Bvh {
    /// The BVH over the boxes, given in f64; `boxes` must not be empty.
    pub(crate) fn build(boxes: &[Aabb<DVec3>]) -> Self {
        let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        for b in boxes {
            lo = lo.min(b.min);
            hi = hi.max(b.max);
        }
        let size = (hi - lo).length() + lo.abs().max(hi.abs()).max_element();
        let pad = PAD * size;
        let f32_boxes: Vec<F32Aabb> = boxes
            .iter()
            .map(|bb| {
                let (a, b) = (bb.min - pad, bb.max + pad);
                F32Aabb::new(
                    Vec3A::new(down(a.x), down(a.y), down(a.z)),
                    Vec3A::new(up(b.x), up(b.y), up(b.z)),
                )
            })
            .collect();
        // obvhs's medium build (wider search when pairing nodes, and reinsertion): a little more
        // time to build than its fast build, for a tree that millions of rays traverse faster.
        let params = BvhBuildParams::medium_build();
        let bvh = build_cwbvh(&f32_boxes, params, &mut Duration::default());
        Bvh { bvh, lo: lo - 2.0 * pad, hi: hi + 2.0 * pad }
    }

    /// The f64 box of everything, padded.
    pub(crate) fn bounds(&self) -> Aabb<DVec3> {
        Aabb { min: self.lo, max: self.hi }
    }

    /// Calls `test(primitive, t_max)` for the primitives whose boxes the ray may meet, nearest
    /// boxes first as far as the traversal orders them, where `t_max` is the nearest hit so far
    /// (or the ray's `t_max`); `test` returns the parameter of its hit, if any, below `t_max`.
    /// Returns the nearest hit parameter and what `test` attached to it.
    pub(crate) fn traverse<T>(
        &self,
        ray: &Ray,
        mut test: impl FnMut(usize, f64) -> Option<(f64, T)>,
    ) -> Option<(f64, T)> {
        let (t0, t1) = slab(ray, self.lo, self.hi, ray.t_min, ray.t_max)?;
        let (bray, shift) = f32_ray(ray, t0, t1);
        let mut best: Option<(f64, T)> = None;
        let indices = &self.bvh.primitive_indices;
        let mut hit = RayHit::none();
        self.bvh.ray_traverse(bray, &mut hit, |_, id| {
            let t_max = best.as_ref().map_or(ray.t_max, |b| b.0);
            match test(indices[id] as usize, t_max) {
                Some((t, data)) if t < t_max => {
                    best = Some((t, data));
                    up(t - shift).next_up()
                }
                _ => f32::INFINITY,
            }
        });
        best
    }

    /// Whether `test(primitive)` holds for any primitive whose box the ray may meet: the
    /// any-hit query of shadow rays, which stops at the first primitive that reports a hit
    /// instead of looking for the nearest.
    pub(crate) fn any(&self, ray: &Ray, mut test: impl FnMut(usize) -> bool) -> bool {
        let Some((t0, t1)) = slab(ray, self.lo, self.hi, ray.t_min, ray.t_max) else {
            return false;
        };
        let (bray, _) = f32_ray(ray, t0, t1);
        let indices = &self.bvh.primitive_indices;
        // The traversal stops at the first primitive given a distance inside the ray.
        !self.bvh.ray_traverse_miss(bray, |_, id| {
            if test(indices[id] as usize) { 0.0 } else { f32::INFINITY }
        })
    }
}

/// How far (in the ray's parameter) before the object's box the f32 ray starts: obvhs's wide
/// BVH culls a box that the ray leaves before the parameter 10⁻⁴ (its `EPSILON`), so the
/// traversal must start well before anything it has to find.
const LEAD: f64 = 1e-3;

/// The f32 ray of the traversal over [t0, t1] of `ray`, started [`LEAD`] before it enters the
/// object's box (at t0), so that f32 rounding scales with the object, not with the camera
/// distance; and the parameter of `ray` where the f32 ray starts (its t = 0).
fn f32_ray(ray: &Ray, t0: f64, t1: f64) -> (BvhRay, f64) {
    let start = t0 - LEAD;
    let (o, d) = (ray.point_at(start), ray.dir);
    // obvhs's wide BVH misses every box for a direction with a component exactly 0 (a ray
    // along an axis); 10⁻³⁰ in its place moves the ray by 10⁻³⁰·t, far inside the boxes' pad.
    let component = |x: f64| {
        let x = x as f32;
        if x == 0.0 { 1e-30f32.copysign(x) } else { x }
    };
    let f32_ray = BvhRay::new(
        Vec3A::new(o.x as f32, o.y as f32, o.z as f32),
        Vec3A::new(component(d.x), component(d.y), component(d.z)),
        0.0,
        up(t1 - start),
    );
    (f32_ray, start)
}

/// The parameter range [t0, t1] ∩ [`t_min`, `t_max`] where the ray is inside the box, by the
/// slab method in f64, widened by a relative 1e-12 against rounding; `None` if empty.
pub(crate) fn slab(ray: &Ray, lo: DVec3, hi: DVec3, t_min: f64, t_max: f64) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (t_min, t_max);
    for i in 0..3 {
        let (o, d) = (ray.origin[i], ray.dir[i]);
        if d == 0.0 {
            if o < lo[i] || o > hi[i] {
                return None;
            }
            continue;
        }
        let inv = 1.0 / d;
        let (mut a, mut b) = ((lo[i] - o) * inv, (hi[i] - o) * inv);
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        let slack = 1e-12 * (a.abs().max(b.abs()) + (hi[i] - lo[i]).abs() * inv.abs());
        t0 = t0.max(a - slack);
        t1 = t1.min(b + slack);
        if t0 > t1 {
            return None;
        }
    }
    Some((t0, t1))
}
