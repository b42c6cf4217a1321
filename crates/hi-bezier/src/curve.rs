// SPDX-License-Identifier: MIT
//! Bézier curves of any degree (Hardy 2005, §2.5, eq. 2.1): q(t) = Σᵢ Bⁿᵢ(t)·Pᵢ, evaluated by
//! de Casteljau's method (eq. 2.6), with derivatives (eq. 2.3, 2.4), degree elevation and
//! curvature.

use glam::DVec2;

use crate::bernstein::falling_factorial;
use crate::error::check_points;
use crate::{ControlPoint, Error};

/// A Bézier curve of degree n with control points P₀, …, Pₙ, over t ∈ [0, 1].
///
/// Split, subsegments and flattening live in `subdivide.rs` and `flatten.rs`, bounding boxes in
/// `bounds.rs`; they are all methods of this type.
///
/// # Examples
///
/// ```
/// use hi_bezier::BezierCurve;
///
/// let c = BezierCurve::try_new(vec![0.0, 1.0, 0.0, 3.0]).unwrap();
/// assert_eq!(c.eval(0.0), 0.0);
/// assert_eq!(c.eval(1.0), 3.0);
/// // Eq. 2.4: q′(0) = n(P₁ − P₀), q′(1) = n(Pₙ − Pₙ₋₁).
/// assert_eq!(c.eval_deriv(0.0, 1), 3.0);
/// assert_eq!(c.eval_deriv(1.0, 1), 9.0);
/// assert!(BezierCurve::<f64>::try_new(vec![]).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierCurve<P> {
    // Invariant: at least one control point, all finite.
    control: Vec<P>,
}

impl<P: ControlPoint> BezierCurve<P> {
    /// The curve with these control points (degree = number of points − 1).
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no points, [`Error::NonFinitePoint`] for a NaN or infinite
    /// coordinate.
    pub fn try_new(control: Vec<P>) -> Result<Self, Error> {
        check_points(&control)?;
        Ok(Self { control })
    }

    /// The curve with these control points.
    ///
    /// # Panics
    ///
    /// Panics on empty or non-finite input; see [`BezierCurve::try_new`].
    #[must_use]
    pub fn new(control: Vec<P>) -> Self {
        Self::try_new(control).unwrap_or_else(|e| panic!("{e}"))
    }

    /// Wraps points already known to be valid (non-empty, finite up to overflow in arithmetic
    /// on valid input).
    pub(crate) fn from_vec_unchecked(control: Vec<P>) -> Self {
        debug_assert!(!control.is_empty(), "a Bézier curve needs a control point");
        Self { control }
    }

    /// The control points P₀, …, Pₙ.
    #[must_use]
    pub fn control_points(&self) -> &[P] {
        &self.control
    }

    /// Takes the control points out of the curve.
    #[must_use]
    pub fn into_control_points(self) -> Vec<P> {
        self.control
    }

    /// The degree n.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.control.len() - 1
    }

    /// q(t) by de Casteljau's algorithm (eq. 2.6), stable for every t (extrapolates outside
    /// [0, 1]).
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        with_scratch(&self.control, |work| de_casteljau(work, t))
    }

    /// Every level of de Casteljau's scheme at t (figure 2.6): row r holds pʳ₀(t), …, pʳₙ₋ᵣ(t),
    /// so row 0 is the control polygon and row n is the single point q(t).
    #[must_use]
    pub fn de_casteljau_levels(&self, t: f64) -> Vec<Vec<P>> {
        let mut rows = vec![self.control.clone()];
        while rows.last().is_some_and(|r| r.len() > 1) {
            let prev = &rows[rows.len() - 1];
            let next = prev.windows(2).map(|w| lerp(w[0], w[1], t)).collect();
            rows.push(next);
        }
        rows
    }

    /// The derivative of order `order` at t (order 0 is q(t)); the zero point for order > n.
    ///
    /// Differences the control points `order` times (eq. 2.3) and evaluates the resulting
    /// curve of degree n − order, so it costs O(n²) and no powers of t are formed.
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        let n = self.degree();
        if order > n {
            return P::ZERO;
        }
        let mut work = self.control.clone();
        forward_differences(&mut work, order);
        de_casteljau(&mut work[..=n - order], t) * falling_factorial(n, order)
    }

    /// The hodograph q′ as a Bézier curve of degree n − 1 with control points n·(Pᵢ₊₁ − Pᵢ)
    /// (eq. 2.3); the constant zero curve (degree 0) for n = 0.
    #[must_use]
    #[doc(alias = "hodograph")]
    pub fn deriv(&self) -> Self {
        self.deriv_n(1)
    }

    /// The derivative of order `order` as a Bézier curve of degree max(n − order, 0).
    #[must_use]
    pub fn deriv_n(&self, order: usize) -> Self {
        let n = self.degree();
        if order > n {
            return Self { control: vec![P::ZERO] };
        }
        let mut work = self.control.clone();
        forward_differences(&mut work, order);
        work.truncate(n + 1 - order);
        let scale = falling_factorial(n, order);
        for p in &mut work {
            *p = *p * scale;
        }
        Self { control: work }
    }

    /// The same curve written with degree n + 1:
    /// Qᵢ = (i/(n+1))·Pᵢ₋₁ + (1 − i/(n+1))·Pᵢ, i = 0, …, n + 1.
    #[must_use]
    pub fn elevate(&self) -> Self {
        Self { control: elevate_once(&self.control) }
    }

    /// The same curve written with degree n + `times` (elevation repeated `times` times).
    #[must_use]
    pub fn elevate_by(&self, times: usize) -> Self {
        let mut control = self.control.clone();
        for _ in 0..times {
            control = elevate_once(&control);
        }
        Self { control }
    }

    /// The same point set traversed backwards: r(t) = q(1 − t).
    #[must_use]
    pub fn reverse(&self) -> Self {
        let mut control = self.control.clone();
        control.reverse();
        Self { control }
    }

    /// The curve with every control point mapped by `f` (exact for affine maps, by affine
    /// invariance).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinitePoint`] if `f` produces a non-finite point.
    pub fn try_map<Q: ControlPoint>(&self, f: impl FnMut(P) -> Q) -> Result<BezierCurve<Q>, Error> {
        BezierCurve::try_new(self.control.iter().copied().map(f).collect())
    }

    /// The length of the control polygon Σ|Pᵢ₊₁ − Pᵢ|, an upper bound of the arc length.
    #[must_use]
    pub fn control_polygon_length(&self) -> f64 {
        self.control.windows(2).map(|w| (w[1] - w[0]).norm()).sum()
    }

    /// The unsigned curvature κ(t) = |q′ × q″| / |q′|³ in any dimension, computed as
    /// √(|q′|²|q″|² − (q′·q″)²) / |q′|³ (Lagrange's identity); `None` where the speed |q′(t)|
    /// vanishes (relative to the size of the control polygon), as at a cusp.
    #[must_use]
    pub fn curvature(&self, t: f64) -> Option<f64> {
        let d1 = self.eval_deriv(t, 1);
        let d2 = self.eval_deriv(t, 2);
        let speed = d1.norm();
        if self.is_singular_speed(speed) {
            return None;
        }
        let cross2 = (d1.dot(d1) * d2.dot(d2) - d1.dot(d2).powi(2)).max(0.0);
        Some(cross2.sqrt() / speed.powi(3))
    }

    /// True if `speed` is zero relative to the largest speed the control polygon allows.
    fn is_singular_speed(&self, speed: f64) -> bool {
        let scale = self.degree() as f64
            * self.control.windows(2).map(|w| (w[1] - w[0]).norm()).fold(0.0, f64::max);
        speed.is_nan() || speed <= 1e-12 * scale
    }
}

impl BezierCurve<DVec2> {
    /// The signed curvature κ(t) = (x′y″ − y′x″) / |q′|³ of a plane curve, positive where the
    /// curve turns counter-clockwise; `None` where the speed vanishes.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_bezier::BezierCurve;
    ///
    /// // At t = 0, κ = (n − 1)/n · ((P₁ − P₀) × (P₂ − P₁)) / |P₁ − P₀|³.
    /// let c = BezierCurve::new(vec![DVec2::ZERO, DVec2::X, DVec2::ONE]);
    /// assert!((c.signed_curvature(0.0).unwrap() - 0.5).abs() < 1e-15);
    /// ```
    #[must_use]
    pub fn signed_curvature(&self, t: f64) -> Option<f64> {
        let d1 = self.eval_deriv(t, 1);
        let d2 = self.eval_deriv(t, 2);
        let speed = d1.length();
        if self.is_singular_speed(speed) {
            return None;
        }
        Some(d1.perp_dot(d2) / speed.powi(3))
    }
}

/// (1 − t)·a + t·b.
#[inline]
pub(crate) fn lerp<P: ControlPoint>(a: P, b: P, t: f64) -> P {
    a * (1.0 - t) + b * t
}

/// Control polygons up to this length are evaluated in a stack buffer.
pub(crate) const SMALL: usize = 16;

/// Runs `f` on a mutable copy of `points`, on the stack when it is short.
#[inline]
pub(crate) fn with_scratch<P: ControlPoint, R>(points: &[P], f: impl FnOnce(&mut [P]) -> R) -> R {
    if points.len() <= SMALL {
        let mut buf = [P::ZERO; SMALL];
        let work = &mut buf[..points.len()];
        work.copy_from_slice(points);
        f(work)
    } else {
        f(&mut points.to_vec())
    }
}

/// de Casteljau's scheme in place, returning q(t) and q′(t) = n·(pⁿ⁻¹₁ − pⁿ⁻¹₀) (zero for
/// n = 0). `work` must not be empty.
pub(crate) fn de_casteljau_with_deriv<P: ControlPoint>(work: &mut [P], t: f64) -> (P, P) {
    let len = work.len();
    if len == 1 {
        return (work[0], P::ZERO);
    }
    for level in 1..len - 1 {
        for i in 0..len - level {
            work[i] = lerp(work[i], work[i + 1], t);
        }
    }
    (lerp(work[0], work[1], t), (work[1] - work[0]) * (len - 1) as f64)
}

/// de Casteljau's scheme (eq. 2.6) in place; returns pⁿ₀(t). `work` must not be empty.
pub(crate) fn de_casteljau<P: ControlPoint>(work: &mut [P], t: f64) -> P {
    let n = work.len();
    for level in 1..n {
        for i in 0..n - level {
            work[i] = lerp(work[i], work[i + 1], t);
        }
    }
    work[0]
}

/// Replaces `work[..len − k]` by the k-th forward differences Δᵏ Pᵢ (unscaled).
pub(crate) fn forward_differences<P: ControlPoint>(work: &mut [P], k: usize) {
    let len = work.len();
    for level in 1..=k.min(len.saturating_sub(1)) {
        for i in 0..len - level {
            work[i] = work[i + 1] - work[i];
        }
    }
}

/// One degree elevation of a control polygon.
pub(crate) fn elevate_once<P: ControlPoint>(control: &[P]) -> Vec<P> {
    let n = control.len() - 1;
    let m = (n + 1) as f64;
    let mut out = Vec::with_capacity(n + 2);
    out.push(control[0]);
    for i in 1..=n {
        let a = i as f64 / m;
        out.push(control[i - 1] * a + control[i] * (1.0 - a));
    }
    out.push(control[n]);
    out
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;

    #[test]
    fn derivative_of_low_degrees() {
        let c = BezierCurve::new(vec![2.0]);
        assert_eq!(c.eval_deriv(0.3, 1), 0.0);
        assert_eq!(c.deriv(), BezierCurve::new(vec![0.0]));
        let line = BezierCurve::new(vec![1.0, 4.0]);
        assert_eq!(line.eval_deriv(0.7, 1), 3.0);
        assert_eq!(line.eval_deriv(0.7, 2), 0.0);
        assert_eq!(line.deriv_n(5).degree(), 0);
    }

    #[test]
    fn levels_end_in_the_point() {
        let c = BezierCurve::new(vec![DVec2::ZERO, DVec2::Y, DVec2::ONE, DVec2::X]);
        let levels = c.de_casteljau_levels(0.3);
        assert_eq!(levels.len(), 4);
        assert_eq!(levels[0], c.control_points());
        assert!((levels[3][0] - c.eval(0.3)).length() < 1e-15);
    }

    #[test]
    fn curvature_of_a_cusp_is_none() {
        // P₀ = P₁ = P₂ gives q′(0) = 0.
        let c = BezierCurve::new(vec![DVec3::ZERO, DVec3::ZERO, DVec3::ZERO, DVec3::X]);
        assert_eq!(c.curvature(0.0), None);
        assert!(c.curvature(0.5).is_some());
        let point = BezierCurve::new(vec![DVec2::ONE]);
        assert_eq!(point.signed_curvature(0.5), None);
    }

    #[test]
    fn reverse_and_map() {
        let c = BezierCurve::new(vec![0.0, 1.0, 5.0]);
        assert!((c.reverse().eval(0.2) - c.eval(0.8)).abs() < 1e-15);
        let m = c.try_map(|x| DVec2::new(x, 2.0 * x)).unwrap();
        assert!((m.eval(0.4) - DVec2::new(c.eval(0.4), 2.0 * c.eval(0.4))).length() < 1e-15);
        assert!(c.try_map(|x| x / 0.0).is_err());
        assert_eq!(c.control_polygon_length(), 5.0);
    }
}
