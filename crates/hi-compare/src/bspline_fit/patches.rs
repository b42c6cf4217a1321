// SPDX-License-Identifier: MIT
//! Bicubic Bézier patches from a B-spline surface (Hardy 2005, §4.4, after Watt & Watt): the
//! grid of patches, and Watt & Watt's construction of it from the curve network with the
//! interior control points from twist vectors estimated by Adini's method.
//!
//! See [`BSplineSurface::to_adini_patches`] for the construction and what is exact.

use glam::DVec3;
use hi_bezier::BezierPatch;

use super::axis::Axis;
use super::surface::BSplineSurface;

/// A grid of bicubic Bézier patches covering a parameter rectangle: patch (i, l) covers
/// [Uᵢ, Uᵢ₊₁] × [Vₗ, Vₗ₊₁] of the breakpoints, at its own parameters
/// (u, v) = ((U − Uᵢ)/(Uᵢ₊₁ − Uᵢ), (V − Vₗ)/(Vₗ₊₁ − Vₗ)) ∈ [0, 1]².
///
/// Made by [`BSplineSurface::to_bezier_patches`] (exact) or
/// [`BSplineSurface::to_adini_patches`] (Watt & Watt's construction, §4.4).
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPatchGrid {
    u_breaks: Vec<f64>,
    v_breaks: Vec<f64>,
    closed_u: bool,
    closed_v: bool,
    // Invariant: (u_breaks.len() − 1) × (v_breaks.len() − 1) bicubic patches, row-major.
    patches: Vec<BezierPatch<DVec3>>,
}

impl BezierPatchGrid {
    pub(crate) fn from_parts(
        u_breaks: Vec<f64>,
        v_breaks: Vec<f64>,
        closed_u: bool,
        closed_v: bool,
        patches: Vec<BezierPatch<DVec3>>,
    ) -> Self {
        debug_assert_eq!(patches.len(), (u_breaks.len() - 1) * (v_breaks.len() - 1), "grid");
        Self { u_breaks, v_breaks, closed_u, closed_v, patches }
    }

    /// The number of patches along u.
    #[must_use]
    pub fn n_u(&self) -> usize {
        self.u_breaks.len() - 1
    }

    /// The number of patches along v.
    #[must_use]
    pub fn n_v(&self) -> usize {
        self.v_breaks.len() - 1
    }

    /// The breakpoints U₀ < … < Uₙ along u (n = [`Self::n_u`]).
    #[must_use]
    pub fn u_breaks(&self) -> &[f64] {
        &self.u_breaks
    }

    /// The breakpoints V₀ < … < Vₙ along v (n = [`Self::n_v`]).
    #[must_use]
    pub fn v_breaks(&self) -> &[f64] {
        &self.v_breaks
    }

    /// Patch (i, l), `None` out of range.
    #[must_use]
    pub fn patch(&self, i: usize, l: usize) -> Option<&BezierPatch<DVec3>> {
        (i < self.n_u() && l < self.n_v()).then(|| &self.patches[i * self.n_v() + l])
    }

    /// All patches, row-major: patch (i, l) is at i·[`Self::n_v`] + l.
    #[must_use]
    pub fn patches(&self) -> &[BezierPatch<DVec3>] {
        &self.patches
    }

    /// The point at surface parameters (U, V): the patch holding them at its own parameters
    /// (closed directions wrap around; open ones extrapolate the end patches).
    #[must_use]
    pub fn eval(&self, u: f64, v: f64) -> DVec3 {
        let (i, s) = locate(&self.u_breaks, self.closed_u, u);
        let (l, t) = locate(&self.v_breaks, self.closed_v, v);
        self.patches[i * self.n_v() + l].eval(s, t)
    }
}

/// The piece holding x and the local parameter in it.
fn locate(breaks: &[f64], closed: bool, x: f64) -> (usize, f64) {
    let (a, b) = (breaks[0], breaks[breaks.len() - 1]);
    let x = if closed {
        let w = a + (x - a).rem_euclid(b - a);
        if w >= b { a } else { w }
    } else {
        x
    };
    let n = breaks.len() - 1;
    let i = breaks.partition_point(|&k| k <= x).saturating_sub(1).min(n - 1);
    (i, (x - breaks[i]) / (breaks[i + 1] - breaks[i]))
}

/// A node of the curve network along one direction: its index among the breakpoints, its
/// parameter unrolled across the seam of a closed direction.
fn neighbour(axis: &Axis, breaks: &[f64], i: isize) -> (usize, f64) {
    let n = breaks.len() - 1;
    if axis.closed {
        let period = breaks[n] - breaks[0];
        let k = i.rem_euclid(n as isize) as usize;
        (k, breaks[k] + i.div_euclid(n as isize) as f64 * period)
    } else {
        let k = i.clamp(0, n as isize) as usize;
        (k, breaks[k])
    }
}

impl BSplineSurface {
    /// Adini's estimate of the twist `p_UV` at every node (Uᵢ, Vⱼ) of the knot lines, from the
    /// network's points and cross-derivatives (see [`BSplineSurface::to_adini_patches`]); indexed
    /// `[i][j]` over the breakpoints (the last one left out along a closed direction).
    #[must_use]
    pub fn adini_twists(&self) -> Vec<Vec<DVec3>> {
        let (ub, vb) = (self.u_breakpoints(), self.v_breakpoints());
        let (ua, va) = (self.u_axis(), self.v_axis());
        let n_i = if ua.closed { ub.len() - 1 } else { ub.len() };
        let n_j = if va.closed { vb.len() - 1 } else { vb.len() };
        let p = |u: f64, v: f64| self.eval(u, v);
        let pu = |u: f64, v: f64| self.eval_deriv(u, v, 1, 0);
        let pv = |u: f64, v: f64| self.eval_deriv(u, v, 0, 1);
        (0..n_i)
            .map(|i| {
                let (_, u) = neighbour(ua, &ub, i as isize);
                let (_, um) = neighbour(ua, &ub, i as isize - 1);
                let (_, up) = neighbour(ua, &ub, i as isize + 1);
                (0..n_j)
                    .map(|j| {
                        let (_, v) = neighbour(va, &vb, j as isize);
                        let (_, vm) = neighbour(va, &vb, j as isize - 1);
                        let (_, vp) = neighbour(va, &vb, j as isize + 1);
                        let (du, dv) = (up - um, vp - vm);
                        (pv(up, v) - pv(um, v)) / du + (pu(u, vp) - pu(u, vm)) / dv
                            - (p(up, vp) - p(um, vp) - p(up, vm) + p(um, vm)) / (du * dv)
                    })
                    .collect()
            })
            .collect()
    }

    /// Bicubic Bézier patches by Watt & Watt's construction (§4.4): the boundary control
    /// points from the Bézier segments of the curve network (the knot lines, exact), the four
    /// interior ones from the corner twists of [`BSplineSurface::adini_twists`] by
    /// x₁₁ = pᵤᵥ/9 + x₁₀ + x₀₁ − x₀₀ and its mirror images. The patches interpolate the
    /// network exactly; their interiors approximate the surface (exact for translational and
    /// bilinear surfaces). Compare
    /// [`BSplineSurface::to_bezier_patches`], the exact conversion.
    ///
    /// # The construction
    ///
    /// For a bicubic patch on x₀₀, …, x₃₃ over [0, 1]², pᵤ(0, 0) = 3(x₁₀ − x₀₀),
    /// pᵥ(0, 0) = 3(x₀₁ − x₀₀) and pᵤᵥ(0, 0) = 9(x₀₀ − x₀₁ − x₁₀ + x₁₁), so
    ///
    /// x₁₁ = pᵤᵥ(0, 0)/9 + x₁₀ + x₀₁ − x₀₀,
    ///
    /// and likewise at the other corners. The twelve boundary points come from the Bézier
    /// segments of the network curves (the knot lines u = Uᵢ and v = Vⱼ); the four interior ones
    /// need the twist pᵤᵥ at the corners. Adini's method estimates the twist of the whole surface
    /// at a node (Uᵢ, Vⱼ) from the network alone (surface-level derivatives written with
    /// capital subscripts):
    ///
    /// ```text
    /// p_UV(Uᵢ, Vⱼ) ≈ [p_V(Uᵢ₊₁, Vⱼ) − p_V(Uᵢ₋₁, Vⱼ)]/(Uᵢ₊₁ − Uᵢ₋₁)
    ///              + [p_U(Uᵢ, Vⱼ₊₁) − p_U(Uᵢ, Vⱼ₋₁)]/(Vⱼ₊₁ − Vⱼ₋₁)
    ///              − [p(Uᵢ₊₁, Vⱼ₊₁) − p(Uᵢ₋₁, Vⱼ₊₁) − p(Uᵢ₊₁, Vⱼ₋₁) + p(Uᵢ₋₁, Vⱼ₋₁)]
    ///                /((Uᵢ₊₁ − Uᵢ₋₁)(Vⱼ₊₁ − Vⱼ₋₁)),
    /// ```
    ///
    /// and the patch over [Uᵢ, Uᵢ₊₁] × [Vⱼ, Vⱼ₊₁] (u = (U − Uᵢ)/(Uᵢ₊₁ − Uᵢ), likewise v) has, by
    /// the chain rule, pᵤᵥ = (Uᵢ₊₁ − Uᵢ)(Vⱼ₊₁ − Vⱼ)·`p_UV`. At the edge of an open direction the
    /// missing neighbour is the node itself (one-sided differences); a closed direction wraps
    /// around.
    ///
    /// # What is exact
    ///
    /// The boundary curves are exact (they are iso-parameter curves of the surface), so Adini
    /// patches interpolate the network and meet their neighbours with C⁰ continuity. For a
    /// product term a(U)·b(V) the error of the estimate is (a′ − δa)(b′ − δb), where δ is the
    /// divided difference used above: the twist, and so the patch, is exact where the surface is
    /// translational (a(U) + b(V)) or bilinear, and wherever one factor's divided difference is its
    /// derivative. In general the interior points are off by O(h⁴) in the knot spacing h
    /// (measured in `tests/bspline_fit.rs`: on a smooth surface sampled with h = 1/8 and 1/16
    /// they are off by 1.1e-5 and 6.4e-7, a factor 16; on a bumpy surface of six uneven slices
    /// about 6 units across, the patches leave the B-spline by up to 7e-4).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_compare::bspline_fit::{BSplineFit, BSplineFitOptions};
    ///
    /// // Slices of the translational surface z = sin x + cos y: Adini's twist (zero) is exact.
    /// let slices: Vec<Vec<DVec3>> = (0..5)
    ///     .map(|j| (0..6).map(|i| {
    ///         let (x, y) = (i as f64 * 0.4, j as f64 * 0.5);
    ///         DVec3::new(x, y, x.sin() + y.cos())
    ///     }).collect())
    ///     .collect();
    /// let fit = BSplineFit::try_new(slices, &BSplineFitOptions::default()).unwrap();
    /// let (exact, adini) = (fit.surface().to_bezier_patches(), fit.surface().to_adini_patches());
    /// for (a, b) in exact.patches().iter().zip(adini.patches()) {
    ///     for (x, y) in a.control_points().iter().zip(b.control_points()) {
    ///         assert!((*x - *y).length() < 1e-12);
    ///     }
    /// }
    /// ```
    #[must_use]
    pub fn to_adini_patches(&self) -> BezierPatchGrid {
        let exact = self.to_bezier_patches();
        let twists = self.adini_twists();
        let (ub, vb) = (exact.u_breaks().to_vec(), exact.v_breaks().to_vec());
        let (n_u, n_v) = (exact.n_u(), exact.n_v());
        let (ua, va) = (self.u_axis(), self.v_axis());
        let twist = |i: usize, j: usize| {
            let (i, _) = neighbour(ua, &ub, i as isize);
            let (j, _) = neighbour(va, &vb, j as isize);
            let i = if ua.closed { i % n_u } else { i };
            let j = if va.closed { j % n_v } else { j };
            twists[i][j]
        };
        let mut patches = Vec::with_capacity(n_u * n_v);
        for i in 0..n_u {
            for j in 0..n_v {
                let scale = (ub[i + 1] - ub[i]) * (vb[j + 1] - vb[j]) / 9.0;
                let mut x = exact.patches[i * n_v + j].rows();
                x[1][1] = twist(i, j) * scale + x[1][0] + x[0][1] - x[0][0];
                x[2][1] = x[3][1] - x[3][0] + x[2][0] - twist(i + 1, j) * scale;
                x[1][2] = x[1][3] - x[0][3] + x[0][2] - twist(i, j + 1) * scale;
                x[2][2] = x[2][3] + x[3][2] - x[3][3] + twist(i + 1, j + 1) * scale;
                patches.push(BezierPatch::new(x));
            }
        }
        BezierPatchGrid::from_parts(ub, vb, ua.closed, va.closed, patches)
    }
}
