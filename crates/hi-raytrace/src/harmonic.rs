// SPDX-License-Identifier: MIT
//! Direct ray tracing of harmonic tensor-product surfaces with interval methods (Hardy 2005,
//! §5.6: "Interval Root Finding — Bisection", "Interval Root Finding — Newton-Raphson",
//! "Raytracing Harmonic Surfaces").
//!
//! The ray o + t·d meets the surface where f(u, v, t) = p(u, v) − (o + t·d) = 0.
//!
//! **Enclosures.** p is a trigonometric polynomial, p(u, v) = Σₐ Σᵦ [Aₐᵦ cos 2πau cos 2πβv +
//! Bₐᵦ cos 2πau sin 2πβv + Cₐᵦ sin 2πau cos 2πβv + Dₐᵦ sin 2πau sin 2πβv] (its 2-D spectrum). The
//! parameter square is cut into cells (32 × 32 by default). For each cell, the spectrum is
//! evaluated in interval arithmetic (`hi-interval`'s rigorous sin and cos) over the whole cell,
//! giving bounds of |p|'s first and second partial derivatives there, per coordinate. Inside a
//! cell, a sub-box U × V with centre c and half-widths hᵤ, hᵥ is then enclosed by the Taylor form
//! p(c) ± (|pᵤ(c)|hᵤ + |pᵥ(c)|hᵥ + ½(Mᵤᵤhᵤ² + 2Mᵤᵥhᵤhᵥ + Mᵥᵥhᵥ²)), intersected with the
//! mean-value form p(c) ± (Mᵤhᵤ + Mᵥhᵥ) (Theorem 5.4), where p(c), pᵤ(c), pᵥ(c) are evaluated in
//! f64 and widened by an a-priori bound of their rounding error. These boxes shrink
//! quadratically with the sub-box, much faster than a naive interval evaluation of the sum, and
//! cost one point evaluation each.
//!
//! **Candidate cells.** The cells' enclosures go into a BVH; a ray does interval work only in
//! the cells whose boxes it meets, nearest first, and stops at the nearest proven hit.
//!
//! **Bisection** ([`IntervalMethod::Bisection`]): a (u, v) box whose enclosure misses the ray is
//! discarded; otherwise t is narrowed to where the ray is inside the enclosure (so the box is a
//! (u, v, t) box on which 0 ∈ F), and the box is halved along its spatially larger side, nearer
//! half first, until its enclosure is smaller than the distance tolerance.
//!
//! **Interval Newton** ([`IntervalMethod::Krawczyk`]): on each (u, v, t) box X, the Krawczyk
//! operator K(X, y, Y) = y − Y f(y) + (I − Y F′(X))(X − y) with y the centre, Y = m(F′(X))⁻¹ and
//! F′ = [pᵤ, pᵥ, −d]. K ∩ X = ∅ discards X; K ⊂ int X proves a unique root in X, and iterating
//! X ← K ∩ X narrows it quadratically; otherwise X ← K ∩ X is bisected. A box narrower than the
//! parameter tolerance that is neither excluded nor proven (a tangent ray, a pole of the
//! parametrisation) counts as a hit.

use glam::DVec3;
use hi_bezier::Aabb;
use hi_interval::Interval;
use hi_mesh::{ColorLegend, ColorMap};
use hi_surface::{CurvatureQuantity, HarmonicSurface};

use crate::bvh::{Bvh, slab};
use crate::error::{Error, check_positive};
use crate::ray::{Ray, gamma};

/// How far past its cell (as a fraction of the cell's width) a cell's derivative bounds hold.
const CELL_MARGIN: f64 = 0.05;

/// Krawczyk boxes are inflated by this fraction of their radius before each step (ε-inflation),
/// so that K ⊂ int X can hold when the root sits on a face of the box.
const INFLATION: f64 = 0.1;

/// The root finder of [`HarmonicObject`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum IntervalMethod {
    /// Interval Newton: the Krawczyk operator, with bisection where it cannot decide (§5.6).
    #[default]
    Krawczyk,
    /// Interval bisection alone (§5.6).
    Bisection,
}

/// How a harmonic surface is intersected.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct HarmonicOptions {
    /// The root finder.
    pub method: IntervalMethod,
    /// Number of parameter cells along u and v whose enclosures go into the BVH.
    pub cells: (usize, usize),
    /// Bisection stops when the enclosure of a box is smaller than this fraction of the size of
    /// the surface (the error of a bisection hit).
    pub distance_tolerance: f64,
    /// Boxes narrower than this in u and v are not split further.
    pub parameter_tolerance: f64,
    /// Most boxes examined per ray and cell (a cap that guarantees termination).
    pub max_boxes: usize,
}

impl Default for HarmonicOptions {
    /// Krawczyk, 32 × 32 cells, distance tolerance 1e-7, parameter tolerance 1e-10, at most
    /// 4096 boxes per ray and cell.
    fn default() -> Self {
        HarmonicOptions {
            method: IntervalMethod::Krawczyk,
            cells: (32, 32),
            distance_tolerance: 1e-7,
            parameter_tolerance: 1e-10,
            max_boxes: 4096,
        }
    }
}

/// How an object is coloured.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SurfaceColor {
    /// One colour, linear RGB.
    Uniform([f32; 3]),
    /// Curvature (K, H or κ₁ + κ₂) at each hit through a colour map (§5.9); the map's range is
    /// taken from the curvature on a 64 × 64 grid of the surface.
    Curvature {
        /// Which curvature.
        quantity: CurvatureQuantity,
        /// The colour map.
        map: ColorMap,
    },
}

/// Bounds of a cell: the parameter window, the enclosure of p, and per-coordinate bounds of the
/// first and second partial derivatives of p over the cell.
#[derive(Clone, Copy, Debug)]
struct Cell {
    u: [f64; 2],
    v: [f64; 2],
    /// The cell widened by [`CELL_MARGIN`] of its width on each side: the derivative bounds
    /// hold there, so Krawczyk boxes may be inflated a little past the cell.
    ext_u: [f64; 2],
    ext_v: [f64; 2],
    /// |pᵤ|, |pᵥ| bounds per coordinate.
    d1: [DVec3; 2],
    /// |pᵤᵤ|, |pᵤᵥ|, |pᵥᵥ| bounds per coordinate.
    d2: [DVec3; 3],
}

/// A harmonic surface ready for interval ray tracing.
#[derive(Clone, Debug)]
pub struct HarmonicObject {
    surface: HarmonicSurface<DVec3>,
    /// A-priori bounds of the rounding error of p, pᵤ, pᵥ evaluated in f64.
    eval_err: [f64; 3],
    cells: Vec<Cell>,
    bvh: Bvh,
    options: HarmonicOptions,
    /// Size of the surface (box diagonal plus largest coordinate).
    scale: f64,
    color: [f32; 3],
    curvature: Option<(CurvatureQuantity, ColorLegend)>,
}

/// A hit on a harmonic surface.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct HarmonicHit {
    /// Ray parameter.
    pub t: f64,
    /// Surface parameter u.
    pub u: f64,
    /// Surface parameter v.
    pub v: f64,
    /// Error bound of the hit point o + t·d, per coordinate.
    pub error: DVec3,
    /// Whether the root was proven unique in its final box (Krawczyk's test); bisection hits
    /// and undecided boxes report `false`.
    pub proven: bool,
}

impl HarmonicObject {
    /// The surface, prepared: its spectrum, the cell bounds and their BVH.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidValue`] or [`Error::NonFinite`] for a bad setting (tolerances must be
    /// positive, cells between 1 and 1024 per direction, `max_boxes` at least 1).
    pub fn try_new(
        surface: HarmonicSurface<DVec3>,
        options: &HarmonicOptions,
    ) -> Result<Self, Error> {
        check_positive("distance tolerance", options.distance_tolerance)?;
        check_positive("parameter tolerance", options.parameter_tolerance)?;
        for c in [options.cells.0, options.cells.1] {
            if !(1..=1024).contains(&c) {
                return Err(Error::InvalidValue {
                    what: "number of cells",
                    value: c as f64,
                    expected: "1 to 1024 per direction",
                });
            }
        }
        if options.max_boxes == 0 {
            return Err(Error::InvalidValue {
                what: "max_boxes",
                value: 0.0,
                expected: "at least 1",
            });
        }
        // A-priori bounds of the rounding error of p, pᵤ, pᵥ evaluated in f64.
        let eval_err = [(0, 0), (1, 0), (0, 1)].map(|(p, q)| surface.eval_error_bound(p, q));
        let mut obj = HarmonicObject {
            surface,
            eval_err,
            cells: Vec::new(),
            bvh: Bvh::build(&[Aabb { min: DVec3::ZERO, max: DVec3::ZERO }]),
            options: *options,
            scale: 1.0,
            color: [0.8, 0.8, 0.8],
            curvature: None,
        };
        let (nu, nv) = options.cells;
        let mut boxes = Vec::with_capacity(nu * nv);
        for i in 0..nu {
            for j in 0..nv {
                let u = [i as f64 / nu as f64, (i + 1) as f64 / nu as f64];
                let v = [j as f64 / nv as f64, (j + 1) as f64 / nv as f64];
                let (cell, lo, hi) = obj.cell(u, v);
                obj.cells.push(cell);
                boxes.push(Aabb { min: lo, max: hi });
            }
        }
        obj.bvh = Bvh::build(&boxes);
        let Aabb { min: lo, max: hi } = obj.bvh.bounds();
        obj.scale = (hi - lo).length() + lo.abs().max(hi.abs()).max_element();
        Ok(obj)
    }

    /// The same object coloured by `color`.
    ///
    /// # Errors
    ///
    /// [`Error::Surface`] for an invalid colour map.
    pub fn with_color(mut self, color: SurfaceColor) -> Result<Self, Error> {
        match color {
            SurfaceColor::Uniform(c) => {
                self.color = c;
                self.curvature = None;
            }
            SurfaceColor::Curvature { quantity, map } => {
                const N: usize = 64;
                let values: Vec<f64> = (0..N * N)
                    .map(|i| {
                        let (u, v) =
                            (((i / N) as f64 + 0.5) / N as f64, ((i % N) as f64 + 0.5) / N as f64);
                        self.surface.curvature(u, v).map_or(f64::NAN, |c| quantity.of(&c))
                    })
                    .collect();
                let legend = map.try_apply(&values)?.legend;
                self.curvature = Some((quantity, legend));
            }
        }
        Ok(self)
    }

    /// The surface.
    #[must_use]
    pub fn surface(&self) -> &HarmonicSurface<DVec3> {
        &self.surface
    }

    /// The options.
    #[must_use]
    pub fn options(&self) -> &HarmonicOptions {
        &self.options
    }

    /// The box of the surface (the union of the cell enclosures, padded).
    #[must_use]
    pub fn bounds(&self) -> Aabb<DVec3> {
        self.bvh.bounds()
    }

    /// The legend of the curvature colours, if coloured by curvature.
    #[must_use]
    pub fn legend(&self) -> Option<&ColorLegend> {
        self.curvature.as_ref().map(|(_, l)| l)
    }

    /// p, pᵤ, pᵥ at (u, v) in f64, from the spectrum
    /// ([`HarmonicSurface::eval_with_partials`], which allocates nothing).
    #[must_use]
    pub fn eval_with_partials(&self, u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
        self.surface.eval_with_partials(u, v)
    }

    /// An enclosure of ∂ᵖ⁺ᑫp/∂uᵖ∂vᑫ over U × V in interval arithmetic, per coordinate
    /// ([`HarmonicSurface::enclose_deriv`]).
    fn enclose_deriv(&self, u: [f64; 2], v: [f64; 2], p: usize, q: usize) -> [Interval; 3] {
        let e =
            self.surface.enclose_deriv(Interval::new(u[0], u[1]), Interval::new(v[0], v[1]), p, q);
        [e[0], e[1], e[2]]
    }

    /// The bounds of one cell and the box of its enclosure.
    fn cell(&self, u: [f64; 2], v: [f64; 2]) -> (Cell, DVec3, DVec3) {
        let mag = |x: [Interval; 3]| DVec3::new(x[0].mag(), x[1].mag(), x[2].mag());
        let (mu, mv) = (CELL_MARGIN * (u[1] - u[0]), CELL_MARGIN * (v[1] - v[0]));
        let (eu, ev) = ([u[0] - mu, u[1] + mu], [v[0] - mv, v[1] + mv]);
        let d1 = [mag(self.enclose_deriv(eu, ev, 1, 0)), mag(self.enclose_deriv(eu, ev, 0, 1))];
        let d2 = [
            mag(self.enclose_deriv(eu, ev, 2, 0)),
            mag(self.enclose_deriv(eu, ev, 1, 1)),
            mag(self.enclose_deriv(eu, ev, 0, 2)),
        ];
        let cell = Cell { u, v, ext_u: eu, ext_v: ev, d1, d2 };
        let naive = self.enclose_deriv(u, v, 0, 0);
        let e = self.enclosure(&cell, u, v);
        let lo = DVec3::new(naive[0].lo(), naive[1].lo(), naive[2].lo()).max(e.center - e.radius);
        let hi = DVec3::new(naive[0].hi(), naive[1].hi(), naive[2].hi()).min(e.center + e.radius);
        (cell, lo, hi)
    }

    /// The enclosure of p over the sub-box (`u`, `v`) of `cell`, with the values at its centre.
    fn enclosure(&self, cell: &Cell, u: [f64; 2], v: [f64; 2]) -> Enclosure {
        let (uc, vc) = (0.5 * (u[0] + u[1]), 0.5 * (v[0] + v[1]));
        // Half-widths, rounded up so that they cover the box.
        let hu = ((u[1] - uc).max(uc - u[0])).next_up();
        let hv = ((v[1] - vc).max(vc - v[0])).next_up();
        let (p, pu, pv) = self.eval_with_partials(uc, vc);
        let [e0, e1, _] = self.eval_err;
        let mean_value = cell.d1[0] * hu + cell.d1[1] * hv;
        let taylor = (pu.abs() + DVec3::splat(e1)) * hu
            + (pv.abs() + DVec3::splat(e1)) * hv
            + (cell.d2[0] * (hu * hu) + cell.d2[1] * (2.0 * hu * hv) + cell.d2[2] * (hv * hv))
                * 0.5;
        let radius =
            (mean_value.min(taylor) + DVec3::splat(e0) + p.abs() * gamma(2)) * (1.0 + gamma(4));
        Enclosure { center: p, radius, pu, pv, hu, hv }
    }

    /// The nearest hit of `ray` in [`Ray::t_min`], [`Ray::t_max`].
    #[must_use]
    pub fn intersect(&self, ray: &Ray) -> Option<HarmonicHit> {
        self.bvh
            .traverse(ray, |i, t_max| {
                self.intersect_cell(ray, &self.cells[i], t_max).map(|h| (h.t, h))
            })
            .map(|(_, h)| h)
    }

    /// Whether the surface meets the ray in [`Ray::t_min`], [`Ray::t_max`] (a shadow ray's
    /// any-hit query: the BVH of cells stops at the first cell with a hit, proven or, past
    /// the box cap, unproven as in [`HarmonicObject::intersect`]).
    #[must_use]
    pub fn occluded(&self, ray: &Ray) -> bool {
        self.bvh.any(ray, |i| {
            self.intersect_cell(ray, &self.cells[i], ray.t_max).is_some_and(|h| h.t < ray.t_max)
        })
    }

    /// The nearest hit in one cell below `t_max`.
    fn intersect_cell(&self, ray: &Ray, cell: &Cell, t_max: f64) -> Option<HarmonicHit> {
        let root = self.node(ray, cell, cell.u, cell.v, t_max)?;
        // The search stack of this thread, kept between rays: no allocation per ray once it
        // has grown to the deepest search (taken, so that a nested search gets its own).
        let mut stack = SEARCH_STACK.take();
        stack.clear();
        stack.push(root);
        let best = self.search(ray, cell, t_max, &mut stack);
        SEARCH_STACK.set(stack);
        best
    }

    /// The depth-first search of [`HarmonicObject::intersect_cell`] from the boxes on `stack`.
    fn search(
        &self,
        ray: &Ray,
        cell: &Cell,
        t_max: f64,
        stack: &mut Vec<Node>,
    ) -> Option<HarmonicHit> {
        let mut best: Option<HarmonicHit> = None;
        let mut n_boxes = 0;
        let dist_tol = self.options.distance_tolerance * self.scale;
        let par_tol = self.options.parameter_tolerance;
        while let Some(mut node) = stack.pop() {
            let limit = best.map_or(t_max, |b| b.t);
            if node.t[0] > limit {
                continue;
            }
            n_boxes += 1;
            if n_boxes > self.options.max_boxes {
                // The cap: where no root was found, the nearest box still open counts as an
                // unproven hit (its enclosure meets the ray; typically a pole, where a whole
                // interval of v maps to one point and boxes cannot be excluded).
                if best.is_none() {
                    best = Some(node.unproven_hit(ray, node.t[0]));
                }
                break;
            }
            // A box reaching the nearest hit so far may hold that same root (a surface that
            // covers itself twice, like the sphere grid): an unproven hit there is no better.
            let reaches_limit = node.t[1] >= limit;
            node.t[1] = node.t[1].min(limit);
            let narrow = (node.u[1] - node.u[0]).max(node.v[1] - node.v[0]) <= par_tol;
            match self.options.method {
                IntervalMethod::Bisection => {
                    let extent = (node.enc.radius * 2.0).max_element();
                    if extent <= dist_tol || narrow {
                        best = Some(node.unproven_hit(ray, 0.5 * (node.t[0] + node.t[1])));
                        continue;
                    }
                }
                IntervalMethod::Krawczyk => match self.krawczyk(ray, cell, &node, limit) {
                    Newton::Excluded => continue,
                    Newton::Unique(hit) => {
                        best = Some(hit);
                        continue;
                    }
                    Newton::Undecided(contracted) => {
                        if narrow && reaches_limit {
                            continue;
                        }
                        if narrow {
                            best = Some(node.unproven_hit(ray, 0.5 * (node.t[0] + node.t[1])));
                            continue;
                        }
                        if let Some((u, v)) = contracted {
                            if let Some(n) = self.node(ray, cell, u, v, limit) {
                                node = n;
                            } else {
                                continue;
                            }
                        }
                    }
                },
            }
            // Split along the side that is larger in space.
            let split_u =
                (node.enc.pu * node.enc.hu).length() >= (node.enc.pv * node.enc.hv).length();
            let (a, b) = if split_u {
                let m = 0.5 * (node.u[0] + node.u[1]);
                (([node.u[0], m], node.v), ([m, node.u[1]], node.v))
            } else {
                let m = 0.5 * (node.v[0] + node.v[1]);
                ((node.u, [node.v[0], m]), (node.u, [m, node.v[1]]))
            };
            let na = self.node(ray, cell, a.0, a.1, limit);
            let nb = self.node(ray, cell, b.0, b.1, limit);
            match (na, nb) {
                (Some(x), Some(y)) => {
                    let (near, far) = if x.t[0] <= y.t[0] { (x, y) } else { (y, x) };
                    stack.push(far);
                    stack.push(near);
                }
                (Some(x), None) | (None, Some(x)) => stack.push(x),
                (None, None) => {}
            }
        }
        best
    }

    /// The box (`u`, `v`) of `cell` with its enclosure and the t range where the ray is inside
    /// it, or `None` if the ray misses the enclosure below `t_max`.
    fn node(&self, ray: &Ray, cell: &Cell, u: [f64; 2], v: [f64; 2], t_max: f64) -> Option<Node> {
        let enc = self.enclosure(cell, u, v);
        let (t0, t1) =
            slab(ray, enc.center - enc.radius, enc.center + enc.radius, ray.t_min, t_max)?;
        Some(Node { u, v, t: [t0, t1], enc })
    }

    /// One Krawczyk test on the (u, v, t) box of `node`, iterated while it proves a root.
    fn krawczyk(&self, ray: &Ray, cell: &Cell, node: &Node, t_max: f64) -> Newton {
        let mut x = [
            Interval::new(node.u[0], node.u[1]),
            Interval::new(node.v[0], node.v[1]),
            Interval::new(node.t[0], node.t[1]),
        ];
        let mut proven = false;
        let t_range = Interval::new(ray.t_min, t_max);
        for _ in 0..40 {
            // ε-inflation, within the window where the cell's bounds hold.
            let grow = |i: Interval, lo: f64, hi: f64| {
                let r = INFLATION * i.rad() + 4.0 * f64::EPSILON * i.mag();
                Interval::new((i.lo() - r).max(lo), (i.hi() + r).min(hi))
            };
            let xi = [
                grow(x[0], cell.ext_u[0], cell.ext_u[1]),
                grow(x[1], cell.ext_v[0], cell.ext_v[1]),
                grow(x[2], ray.t_min, t_max),
            ];
            let y = [xi[0].mid(), xi[1].mid(), xi[2].mid()];
            let Some(k_box) = self.krawczyk_box(ray, cell, &xi, &y) else {
                break;
            };
            let interior = (0..3).all(|i| k_box[i].is_interior(xi[i]));

            let next = [
                k_box[0].intersection(xi[0]),
                k_box[1].intersection(xi[1]),
                k_box[2].intersection(xi[2]).intersection(t_range),
            ];
            if next.iter().any(|i| i.is_empty()) {
                // No root in the inflated box, so none in the box.
                return Newton::Excluded;
            }
            proven = proven || interior;
            let shrunk = (0..3).any(|i| next[i].width() < 0.5 * x[i].width());
            let done = next[0].width().max(next[1].width()) <= self.options.parameter_tolerance
                && next[2].width() <= 1e-3 * self.options.distance_tolerance * self.scale;
            if !proven && !shrunk {
                break;
            }
            let stalled = next == x;
            x = next;
            if proven && (done || stalled) {
                break;
            }
        }
        if proven {
            let enc = self.enclosure(cell, [x[0].lo(), x[0].hi()], [x[1].lo(), x[1].hi()]);
            let t = x[2].mid();
            let error = enc.radius.min(ray.dir.abs() * x[2].rad().max(f64::EPSILON * t.abs()))
                + ray.dir.abs() * (t.abs() * gamma(2));
            return Newton::Unique(HarmonicHit {
                t,
                u: x[0].mid(),
                v: x[1].mid(),
                error,
                proven: true,
            });
        }
        // Not decided: the roots in the node's box lie in x ∩ box.
        let u = x[0].intersection(Interval::new(node.u[0], node.u[1]));
        let v = x[1].intersection(Interval::new(node.v[0], node.v[1]));
        if u.is_empty() || v.is_empty() {
            return Newton::Excluded;
        }
        let (u, v) = ([u.lo(), u.hi()], [v.lo(), v.hi()]);
        let same = u == node.u && v == node.v;
        Newton::Undecided(if same { None } else { Some((u, v)) })
    }

    /// The Krawczyk box K = y − Y·f(y) + (I − Y·F′(X))·(X − y) of the inflated box `xi` with
    /// midpoint `y` (Y the inverse of F′ at y), in midpoint–radius form (S. M. Rump, *Fast
    /// and parallel interval arithmetic*, BIT 39, 1999): every quantity is a centre c and a
    /// radius r, products with the point matrix Y are taken in f64, and their rounding is
    /// covered by a priori bounds, |fl(Σⱼ₌₁ⁿ aⱼbⱼ) − Σⱼ aⱼbⱼ| ≤ γₙ·Σⱼ|aⱼbⱼ| (N. J. Higham,
    /// *Accuracy and stability of numerical algorithms*, §3.1), taken with room to spare, plus
    /// an absolute 10⁻³⁰⁰ per quantity for underflow. (I − Y·F′(X))·(X − y) lies in
    /// [−|M|·ρ, |M|·ρ] with |M| ≤ |Mᶜ| + Mʳ (centre and radius) and X − y ⊆ [−ρ, ρ]. Plain f64
    /// products replace the 48 directed-rounding interval products of a step, which took three
    /// quarters of a render's time. `None` where F′(X) is empty or singular at y.
    fn krawczyk_box(
        &self,
        ray: &Ray,
        cell: &Cell,
        xi: &[Interval; 3],
        y: &[f64; 3],
    ) -> Option<[Interval; 3]> {
        const UNDERFLOW: f64 = 1e-300;
        let [e0, e1, _] = self.eval_err;
        let (p, pu, pv) = self.eval_with_partials(y[0], y[1]);
        let (hu, hv) = (xi[0].rad().next_up(), xi[1].rad().next_up());
        // f(y) = p(y) − o − t·d: the evaluation error of p and the rounding of the sum.
        let mut f_c = [0.0; 3];
        let mut f_r = [0.0; 3];
        for k in 0..3 {
            let td = y[2] * ray.dir[k];
            f_c[k] = p[k] - ray.origin[k] - td;
            let size = p[k].abs() + ray.origin[k].abs() + td.abs();
            f_r[k] = e0 + gamma(2) * p[k].abs() + gamma(4) * size + UNDERFLOW;
        }
        // F′(X) = [pᵤ(X), pᵥ(X), −d], each entry as centre and radius.
        let ru = cell.d2[0] * hu + cell.d2[1] * hv + DVec3::splat(e1);
        let rv = cell.d2[1] * hu + cell.d2[2] * hv + DVec3::splat(e1);
        let mut j_c = [[0.0; 3]; 3];
        let mut j_r = [[0.0; 3]; 3];
        for k in 0..3 {
            let (au, av) = (cell.d1[0][k], cell.d1[1][k]);
            let ju =
                Interval::new(pu[k] - ru[k], pu[k] + ru[k]).intersection(Interval::new(-au, au));
            let jv =
                Interval::new(pv[k] - rv[k], pv[k] + rv[k]).intersection(Interval::new(-av, av));
            if ju.is_empty() || jv.is_empty() {
                return None;
            }
            j_c[k] = [ju.mid(), jv.mid(), -ray.dir[k]];
            j_r[k] = [ju.rad(), jv.rad(), 0.0];
        }
        let yinv = inverse3([pu, pv, -ray.dir])?;
        // X − y ⊆ [−ρ, ρ] (y is the midpoint of X; `rad` rounds up).
        let rho = [xi[0].rad(), xi[1].rad(), xi[2].rad()];
        let mut k_box = [Interval::ZERO; 3];
        for (i, row) in yinv.iter().enumerate() {
            // Centre y − Y·f_c, with the magnitudes its rounding bound needs; radius |Y|·f_r.
            let mut c = y[i];
            let mut size = y[i].abs();
            let mut r = 0.0;
            for j in 0..3 {
                let t = row[j] * f_c[j];
                c -= t;
                size += t.abs();
                r += row[j].abs() * f_r[j];
            }
            for l in 0..3 {
                // M_il = δ_il − Σⱼ Y_ij·F′_jl.
                let mut m_c = if i == l { 1.0 } else { 0.0 };
                let mut m_size = m_c;
                let mut m_r = 0.0;
                for j in 0..3 {
                    let t = row[j] * j_c[j][l];
                    m_c -= t;
                    m_size += t.abs();
                    m_r += row[j].abs() * j_r[j][l];
                }
                let m_mag = m_c.abs() + m_r + gamma(8) * (m_size + m_r) + UNDERFLOW;
                r += m_mag * rho[l];
            }
            // The rounding of the centre, of the radius's own sums, and of c ± radius.
            let radius = (r + gamma(8) * size) * (1.0 + gamma(32)) + UNDERFLOW;
            let radius = radius + gamma(2) * (c.abs() + radius);
            k_box[i] = Interval::new(c - radius, c + radius);
        }
        Some(k_box)
    }

    /// Shading data of a hit: point, unit normal pᵤ × pᵥ (a nearby one at a pole), colour.
    pub(crate) fn surface_at(&self, ray: &Ray, h: &HarmonicHit) -> (DVec3, DVec3, [f32; 3]) {
        let point = ray.point_at(h.t);
        let normal = self.normal_at(h.u, h.v);
        let color = match &self.curvature {
            None => self.color,
            Some((quantity, legend)) => {
                let value = self.surface.curvature(h.u, h.v).map_or(f64::NAN, |c| quantity.of(&c));
                legend.linear_at(value)
            }
        };
        (point, normal, color)
    }

    /// The unit normal pᵤ × pᵥ at (u, v); at a pole, the normal a little way off it.
    fn normal_at(&self, u: f64, v: f64) -> DVec3 {
        let (_, pu, pv) = self.eval_with_partials(u, v);
        let n = pu.cross(pv);
        if n.length() > 1e-10 * self.scale * self.scale {
            return n.normalize();
        }
        for du in [1e-6, -1e-6] {
            let (_, pu, pv) = self.eval_with_partials(u + du, v);
            if let Some(n) = pu.cross(pv).try_normalize() {
                return n;
            }
        }
        DVec3::Z
    }
}

std::thread_local! {
    /// Each thread's stack of open boxes for [`HarmonicObject::intersect_cell`].
    static SEARCH_STACK: std::cell::Cell<Vec<Node>> = const { std::cell::Cell::new(Vec::new()) };
}

/// A box of the search: (u, v) window, t range, enclosure.
#[derive(Clone, Copy, Debug)]
struct Node {
    u: [f64; 2],
    v: [f64; 2],
    t: [f64; 2],
    enc: Enclosure,
}

impl Node {
    /// An unproven hit at `t` in this box: its (u, v) centre, the error the whole enclosure
    /// and the rounding of the ray's point at t.
    fn unproven_hit(&self, ray: &Ray, t: f64) -> HarmonicHit {
        let extent = (self.enc.radius * 2.0).max_element();
        HarmonicHit {
            t,
            u: 0.5 * (self.u[0] + self.u[1]),
            v: 0.5 * (self.v[0] + self.v[1]),
            error: DVec3::splat(2.0 * extent) + ray.dir.abs() * (t.abs() * gamma(2)),
            proven: false,
        }
    }
}

/// The enclosure of p over a (u, v) box: centre ± radius per coordinate, with pᵤ and pᵥ at the
/// centre and the half-widths.
#[derive(Clone, Copy, Debug)]
struct Enclosure {
    center: DVec3,
    radius: DVec3,
    pu: DVec3,
    pv: DVec3,
    hu: f64,
    hv: f64,
}

/// What a Krawczyk step decided.
enum Newton {
    /// No root in the box.
    Excluded,
    /// A unique root, narrowed.
    Unique(HarmonicHit),
    /// Not decided; the contracted (u, v) box if it shrank.
    Undecided(Option<([f64; 2], [f64; 2])>),
}

/// The inverse of the 3 × 3 matrix with columns `c`, as rows; `None` if singular.
fn inverse3(c: [DVec3; 3]) -> Option<[[f64; 3]; 3]> {
    let det = c[0].dot(c[1].cross(c[2]));
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let r0 = c[1].cross(c[2]) / det;
    let r1 = c[2].cross(c[0]) / det;
    let r2 = c[0].cross(c[1]) / det;
    Some([r0.to_array(), r1.to_array(), r2.to_array()])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_krawczyk_box_holds_the_newton_map() {
        // For every x in X, x − Y·f(x) lies in K(X) (the mean value theorem): sampled on boxes
        // of several sizes in a few cells, with rays through and beside the surface there.
        let s = hi_surface::torus(2.0, 0.5);
        let obj = HarmonicObject::try_new(s.clone(), &HarmonicOptions::default()).unwrap();
        let mut checked = 0;
        for (c, shrink) in [(37, 1.0), (200, 0.25), (555, 0.01), (901, 1e-5)] {
            let cell = obj.cells[c];
            let (uc, vc) = (0.5 * (cell.u[0] + cell.u[1]), 0.5 * (cell.v[0] + cell.v[1]));
            let (hu, hv) =
                (0.5 * shrink * (cell.u[1] - cell.u[0]), 0.5 * shrink * (cell.v[1] - cell.v[0]));
            let target = s.eval(uc, vc);
            for (origin, miss) in
                [(DVec3::new(0.3, -6.0, 4.0), 0.0), (DVec3::new(-5.0, 1.0, 2.0), 0.05)]
            {
                let ray = Ray::new(origin, target + DVec3::splat(miss) - origin);
                let t = (target - origin).dot(ray.dir) / ray.dir.length_squared();
                let xi = [
                    Interval::new(uc - hu, uc + hu),
                    Interval::new(vc - hv, vc + hv),
                    Interval::new(t * (1.0 - 0.1 * shrink), t * (1.0 + 0.1 * shrink)),
                ];
                let y = [xi[0].mid(), xi[1].mid(), xi[2].mid()];
                let k = obj.krawczyk_box(&ray, &cell, &xi, &y).expect("regular");
                let (_, pu, pv) = obj.eval_with_partials(y[0], y[1]);
                let yinv = inverse3([pu, pv, -ray.dir]).expect("regular");
                for a in 0..=6 {
                    for b in 0..=6 {
                        for q in 0..=2 {
                            let x = [
                                xi[0].lo() + (xi[0].hi() - xi[0].lo()) * f64::from(a) / 6.0,
                                xi[1].lo() + (xi[1].hi() - xi[1].lo()) * f64::from(b) / 6.0,
                                xi[2].lo() + (xi[2].hi() - xi[2].lo()) * f64::from(q) / 2.0,
                            ];
                            let f = s.eval(x[0], x[1]) - ray.point_at(x[2]);
                            for (i, row) in yinv.iter().enumerate() {
                                let z = x[i] - (row[0] * f.x + row[1] * f.y + row[2] * f.z);
                                let slack = 1e-14 * (x[i].abs() + 1.0);
                                assert!(
                                    k[i].lo() - slack <= z && z <= k[i].hi() + slack,
                                    "cell {c}, shrink {shrink}: {z} outside {:?}",
                                    k[i]
                                );
                                checked += 1;
                            }
                        }
                    }
                }
            }
        }
        assert_eq!(checked, 4 * 2 * 49 * 3 * 3);
    }

    #[test]
    fn cell_enclosures_hold_the_surface() {
        let s = hi_surface::torus(2.0, 0.5);
        let obj = HarmonicObject::try_new(s.clone(), &HarmonicOptions::default()).unwrap();
        let cell = obj.cells[37];
        for i in 0..=10 {
            for j in 0..=10 {
                let u = cell.u[0] + (cell.u[1] - cell.u[0]) * i as f64 / 10.0;
                let v = cell.v[0] + (cell.v[1] - cell.v[0]) * j as f64 / 10.0;
                let sub_u = [cell.u[0], 0.5 * (cell.u[0] + cell.u[1])];
                let e = obj.enclosure(&cell, cell.u, cell.v);
                let p = s.eval(u, v);
                assert!(((p - e.center).abs() - e.radius).max_element() <= 0.0, "cell ({u}, {v})");
                if u <= sub_u[1] {
                    let e = obj.enclosure(&cell, sub_u, cell.v);
                    assert!(((p - e.center).abs() - e.radius).max_element() <= 0.0, "sub-box");
                }
            }
        }
    }
}
