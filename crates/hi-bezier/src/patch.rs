// SPDX-License-Identifier: MIT
//! Tensor-product Bézier patches of any degree (Hardy 2005, §4.3 "Tensor Product Bézier
//! Surfaces", figure 4.2): p(u, v) = Σⱼ Σₖ Bᵐⱼ(u)·Bⁿₖ(v)·xⱼₖ, with partial derivatives, normals,
//! subdivision, degree elevation and bounding boxes.

use glam::DVec3;

use crate::bernstein::{Bernstein, falling_factorial};
use crate::bounds::{Aabb, grid_max};
use crate::curve::{
    SMALL, de_casteljau, de_casteljau_with_deriv, elevate_once, forward_differences, with_scratch,
};
use crate::error::check_points;
use crate::flatten::check_tolerance;
use crate::subdivide::{split_points, subsegment_on_stack, subsegment_points};
use crate::{BezierCurve, ControlPoint, Error, ParamWindow};

/// A tensor-product Bézier patch of degree (m, n) with an (m + 1) × (n + 1) control grid xⱼₖ,
/// over (u, v) ∈ [0, 1]²; u runs over the first (row) index j, v over the second (column)
/// index k.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_bezier::BezierPatch;
///
/// // A bilinear patch (degree (1, 1)) is the hyperbolic paraboloid through its corners.
/// let patch = BezierPatch::new(vec![
///     vec![DVec3::ZERO, DVec3::Y],
///     vec![DVec3::X, DVec3::new(1.0, 1.0, 1.0)],
/// ]);
/// assert_eq!((patch.degree_u(), patch.degree_v()), (1, 1));
/// let p = patch.eval(0.25, 0.5);
/// assert!((p - DVec3::new(0.25, 0.5, 0.125)).length() < 1e-15); // z = u·v
/// assert!((patch.eval_deriv(0.25, 0.5, 1, 0) - DVec3::new(1.0, 0.0, 0.5)).length() < 1e-15);
/// assert!(patch.normal(0.25, 0.5).is_some());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPatch<P> {
    // Invariant: n_rows ≥ 1, n_cols ≥ 1, points.len() == n_rows·n_cols (row-major), all finite.
    n_rows: usize,
    n_cols: usize,
    points: Vec<P>,
}

impl<P: ControlPoint> BezierPatch<P> {
    /// The patch with these control rows: `rows[j][k]` = xⱼₖ, j along u, k along v.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no rows or an empty first row, [`Error::RaggedGrid`] if a row's
    /// length differs from the first's, [`Error::NonFinitePoint`] for a non-finite coordinate
    /// (row-major index).
    pub fn try_new(rows: Vec<Vec<P>>) -> Result<Self, Error> {
        let (n_rows, n_cols) = grid_shape(&rows)?;
        let points: Vec<P> = rows.into_iter().flatten().collect();
        check_points(&points)?;
        Ok(Self { n_rows, n_cols, points })
    }

    /// The patch with these control rows.
    ///
    /// # Panics
    ///
    /// Panics on invalid input; see [`BezierPatch::try_new`].
    #[must_use]
    pub fn new(rows: Vec<Vec<P>>) -> Self {
        Self::try_new(rows).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The patch of degree (m, n) with xⱼₖ = f(j, k).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinitePoint`] if `f` returns a non-finite point.
    pub fn try_from_fn(
        degree_u: usize,
        degree_v: usize,
        mut f: impl FnMut(usize, usize) -> P,
    ) -> Result<Self, Error> {
        let (n_rows, n_cols) = (degree_u + 1, degree_v + 1);
        let points: Vec<P> = (0..n_rows)
            .flat_map(|j| (0..n_cols).map(move |k| (j, k)))
            .map(|(j, k)| f(j, k))
            .collect();
        check_points(&points)?;
        Ok(Self { n_rows, n_cols, points })
    }

    /// Wraps a valid row-major grid.
    pub(crate) fn from_parts(n_rows: usize, n_cols: usize, points: Vec<P>) -> Self {
        debug_assert!(n_rows * n_cols == points.len() && !points.is_empty(), "grid shape");
        Self { n_rows, n_cols, points }
    }

    /// The degree m in u (number of rows − 1).
    #[must_use]
    pub fn degree_u(&self) -> usize {
        self.n_rows - 1
    }

    /// The degree n in v (number of columns − 1).
    #[must_use]
    pub fn degree_v(&self) -> usize {
        self.n_cols - 1
    }

    /// The control points, row-major: xⱼₖ at index j·(n + 1) + k.
    #[must_use]
    pub fn control_points(&self) -> &[P] {
        &self.points
    }

    /// The control point xⱼₖ, or `None` outside the grid.
    #[must_use]
    pub fn control_point(&self, j: usize, k: usize) -> Option<P> {
        (j < self.n_rows && k < self.n_cols).then(|| self.points[j * self.n_cols + k])
    }

    /// The control rows xⱼ₀, …, xⱼₙ, one per j.
    #[must_use]
    pub fn rows(&self) -> Vec<Vec<P>> {
        self.points.chunks(self.n_cols).map(<[P]>::to_vec).collect()
    }

    /// p(u, v) by de Casteljau's algorithm along each row (in v), then along the resulting
    /// column (in u).
    #[must_use]
    pub fn eval(&self, u: f64, v: f64) -> P {
        let (n_rows, n_cols) = (self.n_rows, self.n_cols);
        if n_rows <= SMALL && n_cols <= SMALL {
            let mut row = [P::ZERO; SMALL];
            let mut column = [P::ZERO; SMALL];
            for (slot, r) in column.iter_mut().zip(self.points.chunks(n_cols)) {
                row[..n_cols].copy_from_slice(r);
                *slot = de_casteljau(&mut row[..n_cols], v);
            }
            de_casteljau(&mut column[..n_rows], u)
        } else {
            let mut column: Vec<P> =
                self.points.chunks(n_cols).map(|r| de_casteljau(&mut r.to_vec(), v)).collect();
            de_casteljau(&mut column, u)
        }
    }

    /// p(u, v) with its first partials (p, ∂p/∂u, ∂p/∂v) in one pass, allocating nothing for
    /// degrees up to 15: p = Σⱼ Bᵐⱼ(u)·Σₖ Bⁿₖ(v)·xⱼₖ and its partials with the Bernstein values
    /// and derivatives of each parameter computed once (§4.3), in (m + 1)(n + 1) steps (the
    /// bicubic patches of §5.7 by loops the compiler unrolls). Beyond degree 15, de Casteljau:
    /// the rows reduced in v to their values and v-derivatives, then both columns in u. Cheaper
    /// than three calls of [`BezierPatch::eval_deriv`].
    #[must_use]
    pub fn eval_with_partials(&self, u: f64, v: f64) -> (P, P, P) {
        let (m, n) = (self.degree_u(), self.degree_v());
        if m == 3 && n == 3 {
            if let Some(sums) = self.bernstein_sums::<4>(u, v) {
                return sums;
            }
        } else if let Some(sums) = self.bernstein_sums::<SMALL>(u, v) {
            return sums;
        }
        let mut values = Vec::with_capacity(self.n_rows);
        let mut v_derivs = Vec::with_capacity(self.n_rows);
        for r in self.points.chunks(self.n_cols) {
            let (p, dv) = with_scratch(r, |w| de_casteljau_with_deriv(w, v));
            values.push(p);
            v_derivs.push(dv);
        }
        let (p, pu) = with_scratch(&values, |w| de_casteljau_with_deriv(w, u));
        let pv = with_scratch(&v_derivs, |w| de_casteljau(w, u));
        (p, pu, pv)
    }

    /// [`BezierPatch::eval_with_partials`] by the Bernstein sums, with the basis in arrays of
    /// `N` (so both degrees below `N`; `None` otherwise).
    fn bernstein_sums<const N: usize>(&self, u: f64, v: f64) -> Option<(P, P, P)> {
        let (m, n) = (self.degree_u(), self.degree_v());
        let (bu, dbu) = Bernstein::new(m).values_with_derivatives::<N>(u)?;
        let (bv, dbv) = Bernstein::new(n).values_with_derivatives::<N>(v)?;
        let (mut s, mut su, mut sv) = (P::ZERO, P::ZERO, P::ZERO);
        for (j, row) in self.points.chunks(n + 1).enumerate() {
            let (mut r, mut rv) = (P::ZERO, P::ZERO);
            for (k, x) in row.iter().enumerate() {
                r += *x * bv[k];
                rv += *x * dbv[k];
            }
            s += r * bu[j];
            su += r * dbu[j];
            sv += rv * bu[j];
        }
        Some((s, su, sv))
    }

    /// p at every (uᵢ, vⱼ) of a tensor grid of parameters, row-major (`us.len()` rows of
    /// `vs.len()` points): p(uᵢ, vⱼ) = Σᵣ Bᵐᵣ(uᵢ)·Σ꜀ Bⁿ꜀(vⱼ)·xᵣ꜀ (§4.3) with the Bernstein
    /// values of each parameter computed once. For U·V points this costs
    /// O((m + 1)(n + 1)V + (m + 1)UV), against O(UV(m + 1)(n + 1)) for as many calls of
    /// [`BezierPatch::eval`]; the two agree to rounding for parameters in [0, 1].
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_bezier::BezierPatch;
    ///
    /// let patch = BezierPatch::new(vec![
    ///     vec![DVec2::new(0.0, 0.0), DVec2::new(0.0, 1.0), DVec2::new(0.0, 3.0)],
    ///     vec![DVec2::new(2.0, 0.0), DVec2::new(2.0, 1.0), DVec2::new(2.0, 3.0)],
    /// ]);
    /// let (us, vs) = ([0.0, 0.5, 1.0], [0.25, 0.75]);
    /// let grid = patch.eval_grid(&us, &vs);
    /// assert_eq!(grid.len(), 6);
    /// for (i, &u) in us.iter().enumerate() {
    ///     for (j, &v) in vs.iter().enumerate() {
    ///         assert!((grid[i * vs.len() + j] - patch.eval(u, v)).length() < 1e-15);
    ///     }
    /// }
    /// ```
    #[must_use]
    pub fn eval_grid(&self, us: &[f64], vs: &[f64]) -> Vec<P> {
        let (bu, bv) = (Bernstein::new(self.degree_u()), Bernstein::new(self.degree_v()));
        // rows[r][j] = Σ꜀ Bⁿ꜀(vⱼ)·x_rc.
        let mut weights = Vec::new();
        let mut rows = vec![P::ZERO; self.n_rows * vs.len()];
        for (j, &v) in vs.iter().enumerate() {
            bv.values_into(v, &mut weights);
            for (r, row) in self.points.chunks(self.n_cols).enumerate() {
                rows[r * vs.len() + j] =
                    row.iter().zip(&weights).fold(P::ZERO, |acc, (x, w)| acc + *x * *w);
            }
        }
        let mut out = vec![P::ZERO; us.len() * vs.len()];
        for (i, &u) in us.iter().enumerate() {
            bu.values_into(u, &mut weights);
            let line = &mut out[i * vs.len()..(i + 1) * vs.len()];
            for (r, w) in weights.iter().enumerate() {
                for (o, x) in line.iter_mut().zip(&rows[r * vs.len()..(r + 1) * vs.len()]) {
                    *o += *x * *w;
                }
            }
        }
        out
    }

    /// The partial derivative ∂ᵃ⁺ᵇp/∂uᵃ∂vᵇ at (u, v) for a = `order_u`, b = `order_v`
    /// (0, 0 is p itself); zero beyond the degrees.
    ///
    /// Differences the grid (∂p/∂u = m·Σ Bᵐ⁻¹ⱼ(u)Bⁿₖ(v)(xⱼ₊₁,ₖ − xⱼₖ), §4.3) and evaluates.
    #[must_use]
    pub fn eval_deriv(&self, u: f64, v: f64, order_u: usize, order_v: usize) -> P {
        if order_u > self.degree_u() || order_v > self.degree_v() {
            return P::ZERO;
        }
        self.deriv_patch(order_u, order_v).eval(u, v)
    }

    /// The patch ∂ᵃ⁺ᵇp/∂uᵃ∂vᵇ of degree (m − a, n − b) (clamped to 0 with a zero grid beyond
    /// the degree).
    #[must_use]
    pub fn deriv_patch(&self, order_u: usize, order_v: usize) -> Self {
        let (m, n) = (self.degree_u(), self.degree_v());
        if order_u > m || order_v > n {
            return Self { n_rows: 1, n_cols: 1, points: vec![P::ZERO] };
        }
        let scale = falling_factorial(m, order_u) * falling_factorial(n, order_v);
        let rows: Vec<Vec<P>> = self
            .points
            .chunks(self.n_cols)
            .map(|r| {
                let mut r = r.to_vec();
                forward_differences(&mut r, order_v);
                r.truncate(n + 1 - order_v);
                r
            })
            .collect();
        let n_cols = n + 1 - order_v;
        let mut res = map_columns(&rows.concat(), self.n_rows, n_cols, |c| {
            let mut c = c.to_vec();
            forward_differences(&mut c, order_u);
            c.truncate(m + 1 - order_u);
            c
        });
        for p in &mut res.points {
            *p = *p * scale;
        }
        res
    }

    /// The curve v ↦ p(u, v) at fixed u, a Bézier curve of degree n.
    #[must_use]
    pub fn curve_at_u(&self, u: f64) -> BezierCurve<P> {
        let control = (0..self.n_cols)
            .map(|k| {
                let mut column: Vec<P> =
                    (0..self.n_rows).map(|j| self.points[j * self.n_cols + k]).collect();
                de_casteljau(&mut column, u)
            })
            .collect();
        BezierCurve::from_vec_unchecked(control)
    }

    /// The curve u ↦ p(u, v) at fixed v, a Bézier curve of degree m.
    #[must_use]
    pub fn curve_at_v(&self, v: f64) -> BezierCurve<P> {
        let control =
            self.points.chunks(self.n_cols).map(|r| de_casteljau(&mut r.to_vec(), v)).collect();
        BezierCurve::from_vec_unchecked(control)
    }

    /// Splits at u = t into the patches over [0, t] and [t, 1] in u (Theorem 2.2 on every
    /// column), both of the same degrees and reparametrised to [0, 1]².
    #[must_use]
    pub fn split_u(&self, t: f64) -> (Self, Self) {
        let mut left = Vec::with_capacity(self.points.len());
        let mut right = Vec::with_capacity(self.points.len());
        for k in 0..self.n_cols {
            let column: Vec<P> =
                (0..self.n_rows).map(|j| self.points[j * self.n_cols + k]).collect();
            let (a, b) = split_points(&column, t);
            left.push(a);
            right.push(b);
        }
        (from_columns(&left), from_columns(&right))
    }

    /// Splits at v = t into the patches over [0, t] and [t, 1] in v.
    #[must_use]
    pub fn split_v(&self, t: f64) -> (Self, Self) {
        let mut left = Vec::with_capacity(self.points.len());
        let mut right = Vec::with_capacity(self.points.len());
        for r in self.points.chunks(self.n_cols) {
            let (a, b) = split_points(r, t);
            left.extend(a);
            right.extend(b);
        }
        (
            Self::from_parts(self.n_rows, self.n_cols, left),
            Self::from_parts(self.n_rows, self.n_cols, right),
        )
    }

    /// The piece over `window` = [u₀, u₁] × [v₀, v₁], reparametrised to [0, 1]² (blossoming
    /// along each direction, as [`BezierCurve::subsegment`]).
    #[must_use]
    pub fn subpatch(&self, window: ParamWindow) -> Self {
        let ([u0, u1], [v0, v1]) = ends(window);
        let rows: Vec<P> =
            self.points.chunks(self.n_cols).flat_map(|r| subsegment_points(r, v0, v1)).collect();
        map_columns(&rows, self.n_rows, self.n_cols, |c| subsegment_points(c, u0, u1))
    }

    /// The box of the control points of [`BezierPatch::subpatch`] (which holds the piece over
    /// `window`), computed with the same arithmetic but without allocating for degrees below 16
    /// in both directions.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_bezier::{BezierPatch, ParamRange, ParamWindow};
    ///
    /// let rows = (0..4)
    ///     .map(|j| (0..3).map(|k| DVec3::new(j as f64, k as f64, (j * k) as f64)).collect())
    ///     .collect();
    /// let p = BezierPatch::new(rows);
    /// let window = ParamWindow::new(ParamRange::new(0.2, 0.7), ParamRange::new(0.1, 0.4));
    /// let expected = p.subpatch(window).control_bounding_box();
    /// assert_eq!(p.subpatch_bounds(window), expected);
    /// ```
    #[must_use]
    pub fn subpatch_bounds(&self, window: ParamWindow) -> Aabb<P> {
        let (n_rows, n_cols) = (self.n_rows, self.n_cols);
        if n_rows <= 4 && n_cols <= 4 {
            self.subpatch_bounds_on_stack::<4>(window)
        } else if n_rows <= SMALL && n_cols <= SMALL {
            self.subpatch_bounds_on_stack::<SMALL>(window)
        } else {
            self.subpatch(window).control_bounding_box()
        }
    }

    /// [`BezierPatch::subpatch_bounds`] with scratch arrays of `N` × `N` points on the stack
    /// (both degrees below `N`).
    fn subpatch_bounds_on_stack<const N: usize>(&self, window: ParamWindow) -> Aabb<P> {
        let (n_rows, n_cols) = (self.n_rows, self.n_cols);
        let ([u0, u1], [v0, v1]) = ends(window);
        // Each row cut to [v0, v1], then each column of the result to [u0, u1].
        let mut rows = [[P::ZERO; N]; N];
        for (row, r) in rows.iter_mut().zip(self.points.chunks(n_cols)) {
            subsegment_on_stack::<P, N>(r, v0, v1, &mut row[..n_cols]);
        }
        let mut bounds = Aabb::from_point(self.points[0]);
        let (mut column, mut cut) = ([P::ZERO; N], [P::ZERO; N]);
        for k in 0..n_cols {
            for (slot, row) in column.iter_mut().zip(&rows[..n_rows]) {
                *slot = row[k];
            }
            subsegment_on_stack::<P, N>(&column[..n_rows], u0, u1, &mut cut[..n_rows]);
            let first = if k == 0 { Aabb::from_point(cut[0]) } else { bounds };
            bounds = cut[..n_rows].iter().fold(first, |b, &p| b.including(p));
        }
        bounds
    }

    /// The same surface with degree m + `times` in u.
    #[must_use]
    pub fn elevate_u(&self, times: usize) -> Self {
        map_columns(&self.points, self.n_rows, self.n_cols, |c| {
            let mut c = c.to_vec();
            for _ in 0..times {
                c = elevate_once(&c);
            }
            c
        })
    }

    /// The same surface with degree n + `times` in v.
    #[must_use]
    pub fn elevate_v(&self, times: usize) -> Self {
        let n_cols = self.n_cols + times;
        let points = self
            .points
            .chunks(self.n_cols)
            .flat_map(|r| {
                let mut r = r.to_vec();
                for _ in 0..times {
                    r = elevate_once(&r);
                }
                r
            })
            .collect();
        Self::from_parts(self.n_rows, n_cols, points)
    }

    /// The patch with u and v exchanged: q(u, v) = p(v, u).
    #[must_use]
    pub fn transpose(&self) -> Self {
        let points = (0..self.n_cols)
            .flat_map(|k| (0..self.n_rows).map(move |j| (j, k)))
            .map(|(j, k)| self.points[j * self.n_cols + k])
            .collect();
        Self::from_parts(self.n_cols, self.n_rows, points)
    }

    /// The box of the control points, which holds the patch (convex hull property, §4.3).
    #[must_use]
    pub fn control_bounding_box(&self) -> Aabb<P> {
        Aabb::of_nonempty(&self.points)
    }

    /// A box holding the patch over [0, 1]² and at most `accuracy` larger than its tight box on
    /// every side.
    ///
    /// Method: control-point hull + subdivision, per coordinate and side. The corner
    /// coefficients of a subpatch are values of the surface and its extreme coefficient bounds
    /// it (convex hull property); subpatches are split in four until their bound is within
    /// `accuracy` of the best surface value found. Every degree works; the cost grows as the
    /// accuracy shrinks (about log₄(1/accuracy) levels near each extreme).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidTolerance`] unless `accuracy` is finite and at least 1e-10 times the
    /// largest coordinate magnitude.
    pub fn bounding_box(&self, accuracy: f64) -> Result<Aabb<P>, Error> {
        check_tolerance(accuracy, &self.points)?;
        let mut lo = Vec::with_capacity(P::DIM);
        let mut hi = Vec::with_capacity(P::DIM);
        for i in 0..P::DIM {
            let grid: Vec<f64> = self.points.iter().map(|p| p.coord(i)).collect();
            hi.push(grid_max(&grid, self.n_rows, self.n_cols, accuracy));
            let neg: Vec<f64> = grid.iter().map(|x| -x).collect();
            lo.push(-grid_max(&neg, self.n_rows, self.n_cols, accuracy));
        }
        Ok(Aabb { min: P::from_coords(|i| lo[i]), max: P::from_coords(|i| hi[i]) })
    }
}

impl BezierPatch<DVec3> {
    /// The unit normal (∂p/∂u × ∂p/∂v)/|∂p/∂u × ∂p/∂v| (§4.3); `None` where the patch is
    /// degenerate, i.e. |∂p/∂u × ∂p/∂v| ≤ 1e-10·max(|∂p/∂u|, |∂p/∂v|)², as at a collapsed edge
    /// or corner.
    #[must_use]
    pub fn normal(&self, u: f64, v: f64) -> Option<DVec3> {
        let (_, pu, pv) = self.eval_with_partials(u, v);
        unit_normal(pu, pv)
    }
}

/// The unit normal of two tangents, `None` when they are (nearly) parallel or zero.
pub(crate) fn unit_normal(pu: DVec3, pv: DVec3) -> Option<DVec3> {
    let cross = pu.cross(pv);
    let len = cross.length();
    let scale = pu.length_squared().max(pv.length_squared());
    (len > 1e-10 * scale).then(|| cross / len)
}

/// Checks that rows form a non-empty rectangle; returns (rows, columns).
pub(crate) fn grid_shape<T>(rows: &[Vec<T>]) -> Result<(usize, usize), Error> {
    let n_cols = rows.first().map_or(0, Vec::len);
    if n_cols == 0 {
        return Err(Error::Empty);
    }
    if let Some((row, r)) = rows.iter().enumerate().find(|(_, r)| r.len() != n_cols) {
        return Err(Error::RaggedGrid { row, expected: n_cols, found: r.len() });
    }
    Ok((rows.len(), n_cols))
}

/// Applies `f` to every column of a row-major grid; every result must have the same length.
/// The ends of a window's two ranges, `([u₀, u₁], [v₀, v₁])`.
fn ends(window: ParamWindow) -> ([f64; 2], [f64; 2]) {
    ([window.u.start, window.u.end], [window.v.start, window.v.end])
}

fn map_columns<P: ControlPoint>(
    points: &[P],
    n_rows: usize,
    n_cols: usize,
    mut f: impl FnMut(&[P]) -> Vec<P>,
) -> BezierPatch<P> {
    let columns: Vec<Vec<P>> = (0..n_cols)
        .map(|k| {
            let column: Vec<P> = (0..n_rows).map(|j| points[j * n_cols + k]).collect();
            f(&column)
        })
        .collect();
    from_columns(&columns)
}

/// The patch whose columns (u direction) are `columns`.
fn from_columns<P: ControlPoint>(columns: &[Vec<P>]) -> BezierPatch<P> {
    let n_cols = columns.len();
    let n_rows = columns[0].len();
    let points = (0..n_rows).flat_map(|j| columns.iter().map(move |c| c[j])).collect();
    BezierPatch::from_parts(n_rows, n_cols, points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation() {
        assert_eq!(BezierPatch::<f64>::try_new(vec![]), Err(Error::Empty));
        assert_eq!(BezierPatch::<f64>::try_new(vec![vec![]]), Err(Error::Empty));
        assert_eq!(
            BezierPatch::try_new(vec![vec![1.0, 2.0], vec![3.0, f64::NAN]]),
            Err(Error::NonFinitePoint { index: 3 })
        );
        assert!(
            BezierPatch::try_from_fn(1, 1, |j, _| if j == 1 { f64::INFINITY } else { 0.0 })
                .is_err()
        );
    }

    #[test]
    fn shape_accessors() {
        let p = BezierPatch::try_from_fn(2, 3, |j, k| (10 * j + k) as f64).unwrap();
        assert_eq!(p.control_point(2, 3), Some(23.0));
        assert_eq!(p.control_point(3, 0), None);
        let t = p.transpose();
        assert_eq!((t.degree_u(), t.degree_v()), (3, 2));
        assert_eq!(t.control_point(3, 2), Some(23.0));
        assert!((t.eval(0.3, 0.8) - p.eval(0.8, 0.3)).abs() < 1e-13);
        assert_eq!(p.rows()[1], vec![10.0, 11.0, 12.0, 13.0]);
        assert_eq!(p.eval_deriv(0.5, 0.5, 3, 0), 0.0);
    }

    #[test]
    fn degenerate_normal() {
        // All of row 1 collapsed to one point: ∂p/∂v = 0 along u = 1.
        let p = BezierPatch::new(vec![vec![DVec3::ZERO, DVec3::X], vec![DVec3::Z, DVec3::Z]]);
        assert_eq!(p.normal(1.0, 0.5), None);
        assert!(p.normal(0.5, 0.5).is_some());
    }
}
