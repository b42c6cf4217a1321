// SPDX-License-Identifier: MIT
//! Bézier patches in a BVH (Hardy 2005, §5.6 and §5.7: "the convex hull property … a bounding
//! volume hierarchy … the majority of the algorithms presented rely on Newton's method,
//! subdivision and the convex hull property").
//!
//! At build time each patch is subdivided (de Casteljau) until its pieces are flat: every control
//! point lies within a fraction [`BezierOptions::flatness`] of the piece's size from the bilinear
//! patch of its corners. The control boxes of the pieces (which hold them, by the convex hull
//! property) go into a BVH. A ray then runs Newton's method in (u, v, t) on the exact patch,
//! S(u, v) − (o + t·d) = 0, from the centre of each piece whose box it meets; a root that lands
//! outside the piece (or no convergence) sends the piece back to subdivision at ray time, a few
//! levels deep, with Newton from each sub-piece the ray meets.

use glam::DVec3;
use hi_bezier::{Aabb, BezierPatch, ParamRange, ParamWindow, SmallPatch};
use hi_surface::bezier::{SurfaceBezier, patch_color};

use crate::bvh::{Bvh, slab};
use crate::error::{Error, check_positive};
use crate::ray::{Ray, gamma};

/// How Bézier patches are prepared and intersected.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BezierOptions {
    /// A piece is flat when its control points lie within this fraction of its diagonal from the
    /// bilinear patch of its corners.
    pub flatness: f64,
    /// Most subdivision levels at build time (each level splits a piece in four).
    pub max_depth: u32,
    /// Extra subdivision levels at ray time for a piece where Newton's method fails.
    pub max_ray_depth: u32,
    /// Newton stops when |S(u, v) − (o + t·d)| is below this fraction of the size of the object.
    pub tolerance: f64,
}

impl Default for BezierOptions {
    /// `flatness = 0.05`, `max_depth = 6`, `max_ray_depth = 4`, `tolerance = 1e-11`.
    fn default() -> Self {
        BezierOptions { flatness: 0.05, max_depth: 6, max_ray_depth: 4, tolerance: 1e-11 }
    }
}

/// A flat piece of a patch: the patch and its parameter window.
#[derive(Clone, Copy, Debug)]
struct Piece {
    patch: usize,
    u: [f64; 2],
    v: [f64; 2],
}

/// Bézier patches ready for ray tracing: flat pieces in a BVH, Newton on the exact patches.
#[derive(Clone, Debug)]
pub struct BezierObject {
    patches: Vec<BezierPatch<DVec3>>,
    /// Global (u, v) window of each patch (for a harmonic surface's patches), else [0, 1]².
    windows: Vec<ParamWindow>,
    colors: Vec<[f32; 3]>,
    pieces: Vec<Piece>,
    /// Control boxes of the pieces.
    boxes: Vec<Aabb<DVec3>>,
    /// Control nets of the pieces of at most [`SmallPatch::MAX_POINTS`] points (their children's nets, at
    /// ray time, are split from these).
    nets: Vec<Option<SmallPatch<DVec3>>>,
    /// Normal cones of the pieces (`None` where a normal is undefined or the cone is too wide).
    cones: Vec<Option<Cone>>,
    bvh: Bvh,
    options: BezierOptions,
    /// The absolute Newton tolerance.
    tolerance: f64,
    /// Bound on the coordinates, for the evaluation error.
    magnitude: f64,
}

impl BezierObject {
    /// The patches, coloured one colour each by [`patch_color`], with their own parameters.
    ///
    /// # Errors
    ///
    /// [`Error::EmptyScene`] for no patches, [`Error::InvalidValue`] or [`Error::NonFinite`] for
    /// bad options.
    pub fn try_new(
        patches: Vec<BezierPatch<DVec3>>,
        options: &BezierOptions,
    ) -> Result<Self, Error> {
        let windows = vec![ParamWindow::UNIT; patches.len()];
        Self::build(patches, windows, options)
    }

    /// The patches of a harmonic surface (§5.7), coloured by [`patch_color`]; hits report the
    /// surface's (u, v).
    ///
    /// # Errors
    ///
    /// As [`BezierObject::try_new`].
    pub fn try_from_surface(
        surface: &SurfaceBezier<DVec3>,
        options: &BezierOptions,
    ) -> Result<Self, Error> {
        let windows = (0..surface.patches.len()).map(|i| surface.window(i)).collect();
        Self::build(surface.patches.clone(), windows, options)
    }

    fn build(
        patches: Vec<BezierPatch<DVec3>>,
        windows: Vec<ParamWindow>,
        options: &BezierOptions,
    ) -> Result<Self, Error> {
        if patches.is_empty() {
            return Err(Error::EmptyScene);
        }
        check_positive("Bézier flatness", options.flatness)?;
        check_positive("Bézier tolerance", options.tolerance)?;
        if options.max_depth > 12 || options.max_ray_depth > 12 {
            return Err(Error::InvalidValue {
                what: "Bézier subdivision depth",
                value: f64::from(options.max_depth.max(options.max_ray_depth)),
                expected: "at most 12",
            });
        }
        let mut pieces = Vec::new();
        let mut boxes = Vec::new();
        let mut nets = Vec::new();
        let mut magnitude: f64 = 0.0;
        for (i, patch) in patches.iter().enumerate() {
            for p in patch.control_points() {
                magnitude = magnitude.max(p.abs().max_element());
            }
            split_flat(
                patch,
                i,
                [0.0, 1.0],
                [0.0, 1.0],
                0,
                options,
                &mut pieces,
                &mut boxes,
                &mut nets,
            );
        }
        let bvh = Bvh::build(&boxes);
        let cones = pieces.iter().map(|p| normal_cone(&patches[p.patch], p.u, p.v)).collect();
        let Aabb { min: lo, max: hi } = bvh.bounds();
        let tolerance = options.tolerance * ((hi - lo).length() + magnitude);
        let colors = (0..patches.len()).map(patch_color).collect();
        Ok(BezierObject {
            patches,
            windows,
            colors,
            pieces,
            boxes,
            nets,
            cones,
            bvh,
            options: *options,
            tolerance,
            magnitude,
        })
    }

    /// The same patches with one colour (linear RGB) for all of them.
    #[must_use]
    pub fn with_uniform_color(mut self, color: [f32; 3]) -> Self {
        self.colors = vec![color; self.patches.len()];
        self
    }

    /// Number of patches.
    #[must_use]
    pub fn n_patches(&self) -> usize {
        self.patches.len()
    }

    /// Number of flat pieces in the BVH.
    #[must_use]
    pub fn n_pieces(&self) -> usize {
        self.pieces.len()
    }

    /// The box of the patches (padded).
    #[must_use]
    pub fn bounds(&self) -> Aabb<DVec3> {
        self.bvh.bounds()
    }

    /// The nearest hit: (patch, local u, local v, t).
    #[must_use]
    pub fn intersect(&self, ray: &Ray) -> Option<BezierHit> {
        self.bvh
            .traverse(ray, |i, t_max| {
                let r = ray.with_t_max(t_max);
                self.intersect_piece(
                    &r,
                    self.pieces[i],
                    self.nets[i].as_ref(),
                    Some((self.boxes[i], self.cones[i])),
                    0,
                )
                .map(|h| (h.t, h))
            })
            .map(|(_, h)| h)
    }

    /// Whether the patches meet the ray in [`Ray::t_min`], [`Ray::t_max`] (a shadow ray's
    /// any-hit query: the BVH stops at the first piece hit).
    #[must_use]
    pub fn occluded(&self, ray: &Ray) -> bool {
        self.bvh.any(ray, |i| {
            self.intersect_piece(
                ray,
                self.pieces[i],
                self.nets[i].as_ref(),
                Some((self.boxes[i], self.cones[i])),
                0,
            )
            .is_some_and(|h| h.t < ray.t_max)
        })
    }

    /// The nearest hit in `piece`. If the ray is transversal to the piece's normal cone it meets
    /// the piece at most once, and Newton from the centre finds that root; otherwise (a grazing
    /// ray, which may cross the piece twice), or if Newton fails, the sub-pieces are searched.
    ///
    /// `net` is the piece's control net, if it has at most [`SmallPatch::MAX_POINTS`] points. `known` holds
    /// its control box and normal cone when they were computed at build time; a sub-piece's
    /// are computed here, the cone only once the ray meets the box and only where it decides
    /// something (most sub-pieces' boxes are missed, and the cone costs 25 evaluations).
    fn intersect_piece(
        &self,
        ray: &Ray,
        piece: Piece,
        net: Option<&SmallPatch<DVec3>>,
        known: Option<(Aabb<DVec3>, Option<Cone>)>,
        depth: u32,
    ) -> Option<BezierHit> {
        let patch = &self.patches[piece.patch];
        let Aabb { min: lo, max: hi } = match (known, net) {
            (Some(k), _) => k.0,
            (None, Some(net)) => net.control_bounding_box(),
            (None, None) => patch.subpatch_bounds(ParamWindow::new(
                ParamRange::new(piece.u[0], piece.u[1]),
                ParamRange::new(piece.v[0], piece.v[1]),
            )),
        };
        let pad = self.tolerance * 4.0;
        let (t0, t1) = slab(ray, lo - pad, hi + pad, ray.t_min, ray.t_max)?;
        let first = self.newton(ray, piece, 0.5 * (t0 + t1));
        let at_bottom = depth >= self.options.max_ray_depth;
        // Whether the ray is transversal to the piece's normals: asked only where it decides
        // something (a root found, or none inside, above the deepest level).
        let transversal = || {
            let cone = known.map_or_else(|| normal_cone(patch, piece.u, piece.v), |k| k.1);
            let dir = ray.dir.normalize();
            cone.is_some_and(|c| c.axis.dot(dir).abs() > c.sin_half)
        };
        let mut best = None;
        match first {
            Newton::Hit(h) if at_bottom || transversal() => return Some(h),
            Newton::Hit(h) => best = Some(h),
            Newton::Outside if at_bottom || transversal() => return None,
            Newton::Failed if at_bottom => return None,
            Newton::Outside | Newton::Failed => {}
        }
        let (um, vm) = (0.5 * (piece.u[0] + piece.u[1]), 0.5 * (piece.v[0] + piece.v[1]));
        let nets = net.map(SmallPatch::quarters);
        for (i, (u, v)) in [
            ([piece.u[0], um], [piece.v[0], vm]),
            ([um, piece.u[1]], [piece.v[0], vm]),
            ([piece.u[0], um], [vm, piece.v[1]]),
            ([um, piece.u[1]], [vm, piece.v[1]]),
        ]
        .into_iter()
        .enumerate()
        {
            let t_max = best.map_or(ray.t_max, |b| b.t);
            let sub = Piece { patch: piece.patch, u, v };
            if let Some(h) = self.intersect_piece(
                &ray.with_t_max(t_max),
                sub,
                nets.as_ref().map(|n| &n[i]),
                None,
                depth + 1,
            ) {
                best = Some(h);
            }
        }
        best
    }

    /// Newton's method in (u, v, t) from the centre of `piece`, accepted if it converges inside
    /// the piece (to 1e-9 of its width) with t in range.
    fn newton(&self, ray: &Ray, piece: Piece, t_start: f64) -> Newton {
        let patch = &self.patches[piece.patch];
        let (wu, wv) = (piece.u[1] - piece.u[0], piece.v[1] - piece.v[0]);
        let (mut u, mut v, mut t) =
            (0.5 * (piece.u[0] + piece.u[1]), 0.5 * (piece.v[0] + piece.v[1]), t_start);
        // Iterations after the residual first fell below the tolerance: Newton converges
        // quadratically there, so these bring it to rounding level, and the hit's error bound
        // (which offsets shadow rays) can be that small.
        let mut polish = 0;
        let mut last = f64::INFINITY;
        for _ in 0..32 {
            let (s, su, sv) = patch.eval_with_partials(u, v);
            let f = s - ray.point_at(t);
            let residual = f.length();
            if residual <= self.tolerance {
                polish += 1;
            }
            if residual <= self.tolerance
                && (polish > 3 || residual >= 0.5 * last || residual == 0.0)
            {
                let slack_u = 1e-9 * wu;
                let slack_v = 1e-9 * wv;
                let inside = u >= piece.u[0] - slack_u
                    && u <= piece.u[1] + slack_u
                    && v >= piece.v[0] - slack_v
                    && v <= piece.v[1] + slack_v;
                if !inside || t < ray.t_min || t > ray.t_max {
                    return Newton::Outside;
                }
                let error = DVec3::splat(f.length())
                    + DVec3::splat(gamma(64) * self.magnitude)
                    + ray.dir.abs() * (t.abs() * gamma(2));
                return Newton::Hit(BezierHit {
                    patch: piece.patch,
                    u: u.clamp(0.0, 1.0),
                    v: v.clamp(0.0, 1.0),
                    t,
                    point: s,
                    error,
                    tangents: (su, sv),
                });
            }
            last = residual;
            // J·(du, dv, dt) = −F with J = [S_u, S_v, −d], by Cramer's rule.
            let nd = -ray.dir;
            let det = su.dot(sv.cross(nd));
            if det == 0.0 || !det.is_finite() {
                return Newton::Failed;
            }
            let rhs = -f;
            let du = rhs.dot(sv.cross(nd)) / det;
            let dv = su.dot(rhs.cross(nd)) / det;
            let dt = su.dot(sv.cross(rhs)) / det;
            u += du;
            v += dv;
            t += dt;
            // Far outside the piece: this piece's Newton has failed.
            if u < piece.u[0] - wu
                || u > piece.u[1] + wu
                || v < piece.v[0] - wv
                || v > piece.v[1] + wv
            {
                return Newton::Outside;
            }
        }
        Newton::Failed
    }

    /// Shading data of a hit: point, error, normal (geometric = shading), global (u, v), colour.
    pub(crate) fn surface_at(&self, h: &BezierHit) -> (DVec3, DVec3, DVec3, (f64, f64), [f32; 3]) {
        let (su, sv) = h.tangents;
        let patch = &self.patches[h.patch];
        let normal = su.cross(sv).try_normalize().unwrap_or_else(|| {
            // A collapsed edge or corner: the normal a little inside the patch.
            let (u, v) = (0.5 + 0.999 * (h.u - 0.5), 0.5 + 0.999 * (h.v - 0.5));
            let (_, a, b) = patch.eval_with_partials(u, v);
            a.cross(b).try_normalize().unwrap_or(DVec3::Z)
        });
        let uv = self.windows[h.patch].lerp(h.u, h.v);
        (h.point, h.error, normal, uv, self.colors[h.patch])
    }
}

/// What Newton's method found from the centre of a piece.
enum Newton {
    /// A root inside the piece.
    Hit(BezierHit),
    /// A root outside the piece, or the iteration left it.
    Outside,
    /// No convergence (or a singular Jacobian).
    Failed,
}

/// A cone holding the unit normals of a piece: its axis and the sine of its half-angle.
#[derive(Clone, Copy, Debug)]
struct Cone {
    axis: DVec3,
    sin_half: f64,
}

/// The normal cone of the piece (`u`, `v`) of `patch`, from its normals on a 5 × 5 grid, the
/// half-angle widened by half and by 0.05 rad for the normals between the samples; `None` where
/// a normal is undefined or the cone reaches a half-angle of 80°.
fn normal_cone(patch: &BezierPatch<DVec3>, u: [f64; 2], v: [f64; 2]) -> Option<Cone> {
    let mut normals = [DVec3::ZERO; 25];
    for (i, n) in normals.iter_mut().enumerate() {
        let s = u[0] + (u[1] - u[0]) * (i / 5) as f64 / 4.0;
        let t = v[0] + (v[1] - v[0]) * (i % 5) as f64 / 4.0;
        let (_, su, sv) = patch.eval_with_partials(s, t);
        *n = su.cross(sv).try_normalize()?;
    }
    let axis = normals.iter().copied().sum::<DVec3>().try_normalize()?;
    // The widest angle from the axis: acos of the smallest cosine (acos decreases).
    let cos = normals.iter().map(|n| n.dot(axis).clamp(-1.0, 1.0)).fold(1.0, f64::min);
    let half = cos.acos();
    let widened = 1.5 * half + 0.05;
    (widened < 80f64.to_radians()).then(|| Cone { axis, sin_half: widened.sin() })
}

/// A hit on a Bézier patch.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BezierHit {
    /// Index of the patch.
    pub patch: usize,
    /// Local parameter u in [0, 1].
    pub u: f64,
    /// Local parameter v in [0, 1].
    pub v: f64,
    /// Ray parameter.
    pub t: f64,
    /// The point S(u, v).
    pub point: DVec3,
    /// Error bound of `point`, per coordinate.
    pub error: DVec3,
    /// (Sᵤ, Sᵥ) at the hit.
    pub tangents: (DVec3, DVec3),
}

/// Splits `patch` over the window (`u`, `v`) until flat, collecting the pieces and their control
/// nets.
#[expect(clippy::too_many_arguments, reason = "a private recursive helper")]
fn split_flat(
    patch: &BezierPatch<DVec3>,
    index: usize,
    u: [f64; 2],
    v: [f64; 2],
    depth: u32,
    options: &BezierOptions,
    pieces: &mut Vec<Piece>,
    boxes: &mut Vec<Aabb<DVec3>>,
    nets: &mut Vec<Option<SmallPatch<DVec3>>>,
) {
    let sub =
        patch.subpatch(ParamWindow::new(ParamRange::new(u[0], u[1]), ParamRange::new(v[0], v[1])));
    if depth >= options.max_depth || is_flat(&sub, options.flatness) {
        pieces.push(Piece { patch: index, u, v });
        boxes.push(sub.control_bounding_box());
        nets.push(SmallPatch::try_from_patch(&sub));
        return;
    }
    let (um, vm) = (0.5 * (u[0] + u[1]), 0.5 * (v[0] + v[1]));
    for (a, b) in [
        ([u[0], um], [v[0], vm]),
        ([um, u[1]], [v[0], vm]),
        ([u[0], um], [vm, v[1]]),
        ([um, u[1]], [vm, v[1]]),
    ] {
        split_flat(patch, index, a, b, depth + 1, options, pieces, boxes, nets);
    }
}

/// Whether every control point lies within `flatness`·diagonal of the bilinear patch of the
/// corners at its Greville parameters.
fn is_flat(p: &BezierPatch<DVec3>, flatness: f64) -> bool {
    let (m, n) = (p.degree_u(), p.degree_v());
    let pts = p.control_points();
    let at = |j: usize, k: usize| pts[j * (n + 1) + k];
    let (c00, c01, c10, c11) = (at(0, 0), at(0, n), at(m, 0), at(m, n));
    let bb = p.control_bounding_box();
    let diag = (bb.max - bb.min).length();
    let limit = flatness * diag;
    for j in 0..=m {
        let s = if m == 0 { 0.0 } else { j as f64 / m as f64 };
        for k in 0..=n {
            let t = if n == 0 { 0.0 } else { k as f64 / n as f64 };
            let bilinear =
                (c00 * (1.0 - t) + c01 * t) * (1.0 - s) + (c10 * (1.0 - t) + c11 * t) * s;
            if (at(j, k) - bilinear).length() > limit {
                return false;
            }
        }
    }
    true
}
