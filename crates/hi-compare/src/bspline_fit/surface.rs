// SPDX-License-Identifier: MIT
//! The bicubic tensor-product B-spline surface of Hardy 2005, §4.4,
//! p(u, v) = Σᵢ Σₗ Nᵢ(u)·Mₗ(v)·xᵢₗ, each direction open or closed; its partial derivatives,
//! iso-parameter curves, exact Bézier patches and triangle meshes; and knot insertion on the
//! cubic B-spline curves of `hi_curve`.

use crate::bspline::BSplineCurve;
use glam::{DVec2, DVec3};
use hi_bezier::BezierPatch;
use hi_curve::Error as CurveError;

use super::axis::{Axis, DEGREE};
use super::patches::BezierPatchGrid;
use hi_mesh::TriangleMesh;

use crate::{Error, ParamRange, ParamWindow};

/// A bicubic tensor-product B-spline surface (§4.4):
///
/// p(u, v) = Σᵢ Σₗ Nᵢ(u)·Mₗ(v)·xᵢₗ,
///
/// where Nᵢ and Mₗ are the cubic B-splines (§2.9–2.10) of the u and v knots. Each direction is
/// open or closed, with the knot conventions of `hi_curve`'s `BSplineCurve`: an open direction
/// with n control points has n + 4 non-decreasing knots and the domain [u₃, uₙ]; a closed one
/// has n + 1 breakpoints τ₀ < … < τₙ, period τₙ − τ₀, and control point i's B-spline is centred
/// at τᵢ. Parameters are in knot units (the fitted surfaces of [`crate::bspline_fit`] have
/// the domain [0, 1]²). A closed direction is periodic; an open one extrapolates its end
/// pieces outside the domain.
///
/// Control point xᵢₗ is row i (the u direction), column l (the v direction), as in
/// [`BezierPatch`].
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_compare::BSplineSurface;
///
/// // Clamped knots and a 4×4 net: the bicubic Bézier patch on that net.
/// let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
/// let net: Vec<Vec<DVec3>> = (0..4)
///     .map(|i| (0..4).map(|l| DVec3::new(i as f64, l as f64, (i * l) as f64 / 9.0)).collect())
///     .collect();
/// let s = BSplineSurface::try_new(knots.clone(), false, knots, false, net).unwrap();
/// // x = 3u, y = 3v, z = u·v exactly (the net is that of the bilinear function).
/// let p = s.eval(0.25, 0.5);
/// assert!((p - DVec3::new(0.75, 1.5, 0.125)).length() < 1e-15);
/// assert!((s.eval_deriv(0.25, 0.5, 1, 1) - DVec3::Z).length() < 1e-14);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineSurface {
    u: Axis,
    v: Axis,
    // Invariant: u.n_control × v.n_control finite points, row-major (u index first).
    control: Vec<DVec3>,
}

impl BSplineSurface {
    /// The surface with these knots (or breakpoints, for a closed direction) and control net,
    /// `control[i][l]` with i along u and l along v.
    ///
    /// # Errors
    ///
    /// [`Error::EmptyGrid`] for no control points, [`Error::RaggedGrid`] for rows of unequal
    /// length, [`hi_curve::Error::NonFinitePoint`] for a non-finite control point,
    /// [`hi_curve::Error::NonFiniteParameter`] for a non-finite knot and [`hi_curve::Error::InvalidCount`] when the
    /// knots do not fit the net (see [`BSplineSurface`]), decrease, repeat a value more than
    /// 3 times inside the domain, or leave the domain empty; also fewer than 4 control points
    /// along an open direction or 3 along a closed one.
    pub fn try_new(
        u_knots: Vec<f64>,
        closed_u: bool,
        v_knots: Vec<f64>,
        closed_v: bool,
        control: Vec<Vec<DVec3>>,
    ) -> Result<Self, Error> {
        let n_v = control.first().map_or(0, Vec::len);
        if n_v == 0 {
            return Err(Error::EmptyGrid);
        }
        if let Some((row, r)) = control.iter().enumerate().find(|(_, r)| r.len() != n_v) {
            return Err(Error::RaggedGrid { row, len: r.len(), expected: n_v });
        }
        for (row, r) in control.iter().enumerate() {
            if let Some(col) = r.iter().position(|p| !p.is_finite()) {
                return Err(Error::NonFiniteGridPoint { row, col });
            }
        }
        let u = Axis::try_new(u_knots, control.len(), closed_u, "u knot")?;
        let v = Axis::try_new(v_knots, n_v, closed_v, "v knot")?;
        Ok(Self { u, v, control: control.concat() })
    }

    pub(crate) fn from_parts(u: Axis, v: Axis, control: Vec<DVec3>) -> Self {
        debug_assert_eq!(control.len(), u.n_control * v.n_control, "the net fits the axes");
        Self { u, v, control }
    }

    pub(crate) fn u_axis(&self) -> &Axis {
        &self.u
    }

    pub(crate) fn v_axis(&self) -> &Axis {
        &self.v
    }

    /// The degrees (3, 3).
    #[must_use]
    pub fn degree(&self) -> (usize, usize) {
        (DEGREE, DEGREE)
    }

    /// The u knots as given (the breakpoints τ₀, …, τₙ when closed).
    #[must_use]
    pub fn u_knots(&self) -> &[f64] {
        &self.u.knots
    }

    /// The v knots as given (the breakpoints when closed).
    #[must_use]
    pub fn v_knots(&self) -> &[f64] {
        &self.v.knots
    }

    /// True when the u direction is closed (periodic).
    #[must_use]
    pub fn is_closed_u(&self) -> bool {
        self.u.closed
    }

    /// True when the v direction is closed (periodic).
    #[must_use]
    pub fn is_closed_v(&self) -> bool {
        self.v.closed
    }

    /// The number of control points along u and along v.
    #[must_use]
    pub fn n_control(&self) -> (usize, usize) {
        (self.u.n_control, self.v.n_control)
    }

    /// Control point xᵢₗ, `None` out of range.
    #[must_use]
    pub fn control_point(&self, i: usize, l: usize) -> Option<DVec3> {
        (i < self.u.n_control && l < self.v.n_control)
            .then(|| self.control[i * self.v.n_control + l])
    }

    /// The control net, row i along u.
    #[must_use]
    pub fn control_rows(&self) -> Vec<Vec<DVec3>> {
        self.control.chunks(self.v.n_control).map(<[DVec3]>::to_vec).collect()
    }

    /// The parameter domain [u₀, u₁] × [v₀, v₁].
    #[must_use]
    pub fn domain(&self) -> ParamWindow {
        ParamWindow::new(self.u.domain(), self.v.domain())
    }

    /// The distinct u knots of the domain, increasing: the u ends of the polynomial pieces
    /// (and of the Bézier patches).
    #[must_use]
    pub fn u_breakpoints(&self) -> Vec<f64> {
        self.u.breakpoints()
    }

    /// The distinct v knots of the domain, increasing.
    #[must_use]
    pub fn v_breakpoints(&self) -> Vec<f64> {
        self.v.breakpoints()
    }

    /// p(u, v), by de Boor's algorithm in both directions.
    #[must_use]
    pub fn eval(&self, u: f64, v: f64) -> DVec3 {
        self.eval_deriv(u, v, 0, 0)
    }

    /// The partial derivative ∂^(a+b) p/∂uᵃ∂vᵇ at (u, v), exact (zero above order 3 in either
    /// direction inside a piece). At a knot the piece on the right is used (on the left at the
    /// end of an open direction).
    #[must_use]
    pub fn eval_deriv(&self, u: f64, v: f64, order_u: usize, order_v: usize) -> DVec3 {
        let (u, _) = self.u.wrap(u);
        let (v, _) = self.v.wrap(v);
        let (ju, jv) = (self.u.span(u), self.v.span(v));
        let (iu, iv) = (self.u.active(ju), self.v.active(jv));
        let n_v = self.v.n_control;
        // Along v in each of the four active rows, then along u.
        let rows: [DVec3; 4] = std::array::from_fn(|a| {
            let d = iv.map(|l| self.control[iu[a] * n_v + l]);
            self.v.eval_span(jv, d, v, order_v)
        });
        self.u.eval_span(ju, rows, u, order_u)
    }

    /// The curve v ↦ p(u, v) at this u, as a cubic B-spline on the v knots (closed when v is):
    /// a V-curve of the curve network of §4.4.
    ///
    /// # Panics
    ///
    /// Does not panic: the curve's knots and (finite) control points are those of the surface.
    #[must_use]
    pub fn iso_u(&self, u: f64) -> BSplineCurve<DVec3> {
        let (u, _) = self.u.wrap(u);
        let ju = self.u.span(u);
        let iu = self.u.active(ju);
        let n_v = self.v.n_control;
        let control: Vec<DVec3> = (0..n_v)
            .map(|l| self.u.eval_span(ju, iu.map(|i| self.control[i * n_v + l]), u, 0))
            .collect();
        curve_on(&self.v, control)
    }

    /// The curve u ↦ p(u, v) at this v, as a cubic B-spline on the u knots: a U-curve of the
    /// curve network of §4.4.
    ///
    /// # Panics
    ///
    /// Does not panic: the curve's knots and (finite) control points are those of the surface.
    #[must_use]
    pub fn iso_v(&self, v: f64) -> BSplineCurve<DVec3> {
        let (v, _) = self.v.wrap(v);
        let jv = self.v.span(v);
        let iv = self.v.active(jv);
        let n_v = self.v.n_control;
        let control: Vec<DVec3> = (0..self.u.n_control)
            .map(|i| self.v.eval_span(jv, iv.map(|l| self.control[i * n_v + l]), v, 0))
            .collect();
        curve_on(&self.u, control)
    }

    /// The same surface as bicubic Bézier patches, one per pair of non-empty knot intervals
    /// (§4.4, after Watt & Watt): every knot inserted until its multiplicity is 3 in both
    /// directions, here by blossoming each piece. Exact: the patches agree with the B-spline
    /// to rounding, and neighbouring patches meet with the surface's C² continuity.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_compare::BSplineSurface;
    ///
    /// let knots = vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0];
    /// let net: Vec<Vec<DVec3>> = (0..5)
    ///     .map(|i| (0..5).map(|l| DVec3::new(i as f64, l as f64, ((i + 2 * l) % 3) as f64)).collect())
    ///     .collect();
    /// let s = BSplineSurface::try_new(knots.clone(), false, knots, false, net).unwrap();
    /// let patches = s.to_bezier_patches();
    /// assert_eq!((patches.n_u(), patches.n_v()), (2, 2));
    /// assert!((patches.eval(0.7, 0.2) - s.eval(0.7, 0.2)).length() < 1e-14);
    /// ```
    #[must_use]
    pub fn to_bezier_patches(&self) -> BezierPatchGrid {
        let n_v = self.v.n_control;
        let mut patches = Vec::new();
        for ju in self.u.spans() {
            let iu = self.u.active(ju);
            for jv in self.v.spans() {
                let iv = self.v.active(jv);
                // Bézier points along v in each active row, then along u in each column.
                let rows: [[DVec3; 4]; 4] = std::array::from_fn(|a| {
                    self.v.bezier_span(jv, iv.map(|l| self.control[iu[a] * n_v + l]))
                });
                let columns: [[DVec3; 4]; 4] = std::array::from_fn(|b| {
                    self.u.bezier_span(ju, std::array::from_fn(|a| rows[a][b]))
                });
                let net: Vec<Vec<DVec3>> =
                    (0..4).map(|c| (0..4).map(|b| columns[b][c]).collect()).collect();
                patches.push(BezierPatch::new(net));
            }
        }
        BezierPatchGrid::from_parts(
            self.u.breakpoints(),
            self.v.breakpoints(),
            self.u.closed,
            self.v.closed,
            patches,
        )
    }

    /// A triangle mesh of the surface over its domain: an (`n_u` + 1)×(`n_v` + 1) grid of
    /// samples (`n_u`×`n_v` for closed directions, whose seam is welded), two triangles per
    /// quad wound counter-clockwise about pᵤ × pᵥ, normals pᵤ × pᵥ/|pᵤ × pᵥ| (where that
    /// vanishes, the area-weighted normals of the triangles around the vertex; failing that,
    /// +z), UVs the parameters scaled to [0, 1]. Write it with [`hi_mesh::export`].
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::InvalidCount`] if `n_u` or `n_v` is 0 (below 3 for a closed direction) or the
    /// grid has 2³² vertices or more.
    pub fn to_mesh(&self, n_u: usize, n_v: usize) -> Result<TriangleMesh, Error> {
        for (count, closed, what) in
            [(n_u, self.u.closed, "mesh quads along u"), (n_v, self.v.closed, "mesh quads along v")]
        {
            let least = if closed { 3 } else { 1 };
            if count < least {
                return Err(Error::Curve(CurveError::InvalidCount {
                    what,
                    value: count,
                    expected: if closed { "at least 3 (closed direction)" } else { "at least 1" },
                }));
            }
        }
        let rows = if self.u.closed { n_u } else { n_u + 1 };
        let cols = if self.v.closed { n_v } else { n_v + 1 };
        if rows.checked_mul(cols).is_none_or(|n| n >= u32::MAX as usize / 2) {
            return Err(Error::Curve(CurveError::InvalidCount {
                what: "mesh vertices",
                value: rows.saturating_mul(cols),
                expected: "fewer than 2^31",
            }));
        }
        let ParamWindow {
            u: ParamRange { start: u0, end: u1 },
            v: ParamRange { start: v0, end: v1 },
        } = self.domain();
        let mut positions = Vec::with_capacity(rows * cols);
        let mut normals = Vec::with_capacity(rows * cols);
        let mut uvs = Vec::with_capacity(rows * cols);
        let mut degenerate = Vec::new();
        let scale = self.control.iter().fold(0.0f64, |m, p| m.max(p.length())).max(1e-300);
        for r in 0..rows {
            let s = r as f64 / n_u as f64;
            let u = u0 + s * (u1 - u0);
            for c in 0..cols {
                let t = c as f64 / n_v as f64;
                let v = v0 + t * (v1 - v0);
                positions.push(self.eval(u, v));
                let n = self.eval_deriv(u, v, 1, 0).cross(self.eval_deriv(u, v, 0, 1));
                let tiny = 1e-10 * scale * scale * (u1 - u0).recip() * (v1 - v0).recip();
                if n.length() > tiny {
                    normals.push(n.normalize());
                } else {
                    degenerate.push(normals.len());
                    normals.push(DVec3::ZERO);
                }
                uvs.push(DVec2::new(s, t));
            }
        }
        let index = |r: usize, c: usize| ((r % rows) * cols + c % cols) as u32;
        let mut triangles = Vec::with_capacity(2 * n_u * n_v);
        for r in 0..n_u {
            for c in 0..n_v {
                let (a, b, d, e) =
                    (index(r, c), index(r + 1, c), index(r + 1, c + 1), index(r, c + 1));
                triangles.push([a, b, d]);
                triangles.push([a, d, e]);
            }
        }
        if !degenerate.is_empty() {
            let mut sums = vec![DVec3::ZERO; positions.len()];
            for t in &triangles {
                let [a, b, c] = t.map(|k| positions[k as usize]);
                let area_normal = (b - a).cross(c - a);
                for &k in t {
                    sums[k as usize] += area_normal;
                }
            }
            for k in degenerate {
                normals[k] = sums[k].try_normalize().unwrap_or(DVec3::Z);
            }
        }
        Ok(TriangleMesh::try_new(positions, normals, uvs, triangles)?)
    }
}

/// The cubic B-spline curve along `axis` with these control points.
fn curve_on(axis: &Axis, control: Vec<DVec3>) -> BSplineCurve<DVec3> {
    let res = if axis.closed {
        BSplineCurve::try_new_periodic(DEGREE, axis.knots.clone(), control)
    } else {
        BSplineCurve::try_new(DEGREE, axis.knots.clone(), control)
    };
    res.expect("the knots and control points of a valid surface make a valid curve")
}

/// The same cubic B-spline curve with more knots (§4.4, step 3 of Watt & Watt's algorithm):
/// knot insertion (Boehm 1980) of every value of `new_knots`, each once (repeat a value to
/// insert it more than once). The curve is unchanged; its knot vector is the union, with
/// multiplicities added. Open curves take values inside their domain [u₃, uₘ]; closed ones
/// take breakpoints in [τ₀, τₙ).
///
/// # Errors
///
/// [`hi_curve::Error::InvalidCount`] unless the curve is cubic, or if a knot would then be repeated more
/// than 3 times; [`hi_curve::Error::NonFiniteParameter`] for a non-finite knot and
/// [`Error::InvalidValue`] for one outside the domain.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_compare::bspline::BSplineCurve;
/// use hi_compare::bspline_fit::insert_knots;
///
/// let control = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::new(2.0, 1.0, 1.0)];
/// let curve = BSplineCurve::try_new(3, vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0], control).unwrap();
/// let finer = insert_knots(&curve, &[0.3, 0.5]).unwrap();
/// assert_eq!(finer.control_points().len(), 6);
/// assert!((finer.eval(0.4) - curve.eval(0.4)).length() < 1e-15);
/// ```
pub fn insert_knots(
    curve: &BSplineCurve<DVec3>,
    new_knots: &[f64],
) -> Result<BSplineCurve<DVec3>, Error> {
    if curve.degree() != DEGREE {
        return Err(Error::Curve(CurveError::InvalidCount {
            what: "degree of the curve",
            value: curve.degree(),
            expected: "3 (cubic)",
        }));
    }
    let closed = curve.is_closed();
    let control = curve.control_points();
    let coarse = Axis::try_new(curve.knots().to_vec(), control.len(), closed, "knot")?;
    let ParamRange { start: a, end: b } = coarse.domain();
    let mut knots = curve.knots().to_vec();
    for &k in new_knots {
        if !k.is_finite() {
            return Err(Error::Curve(CurveError::NonFiniteParameter {
                name: "inserted knot",
                value: k,
            }));
        }
        let inside = if closed { a <= k && k < b } else { a <= k && k <= b };
        if !inside {
            return Err(Error::InvalidValue {
                what: "inserted knot",
                index: None,
                value: k,
                expected: if closed {
                    "in [τ₀, τₙ)"
                } else {
                    "inside the domain [u₃, uₘ]"
                },
            });
        }
        // After the last copy of k (before τₙ when closed).
        let at = if closed {
            knots[..knots.len() - 1].partition_point(|&x| x <= k)
        } else {
            knots.partition_point(|&x| x <= k).min(knots.len() - DEGREE - 1)
        };
        knots.insert(at, k);
    }
    let n = control.len() + new_knots.len();
    let fine = Axis::try_new(knots, n, closed, "knot")?;
    let refined = coarse.refine(control, &fine);
    Ok(curve_on(&fine, refined))
}
