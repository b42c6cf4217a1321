// SPDX-License-Identifier: MIT
//! Rational Bézier curves (Hardy 2005, §2.5 "Rational Bézier Curves"):
//! q(t) = Σᵢ wᵢ·Bⁿᵢ(t)·Pᵢ / Σᵢ wᵢ·Bⁿᵢ(t), the projection of a Bézier curve in homogeneous
//! coordinates (wᵢPᵢ, wᵢ).

use crate::bernstein::binomial;
use crate::bounds::Aabb;
use crate::curve::with_scratch;
use crate::error::{check_points, check_weights};
use crate::flatten::{check_tolerance, distance_to_segment};
use crate::subdivide::subsegment_points;
use crate::{BezierCurve, ControlPoint, Error, ParamRange};

/// A rational Bézier curve of degree n: control points P₀, …, Pₙ with positive weights
/// w₀, …, wₙ, over t ∈ [0, 1].
///
/// Positive weights keep the denominator Σᵢ wᵢBⁿᵢ(t) positive on [0, 1] and every curve point a
/// convex combination of the control points, so the convex hull property, the bounding boxes
/// and the flattening guarantee of polynomial curves carry over. Conics and circular arcs are
/// built in `conic.rs` ([`RationalBezierCurve::conic`], [`RationalBezierCurve::circle_arc`]).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_bezier::RationalBezierCurve;
///
/// // Figure 2.8: the right half of the unit circle as a rational cubic.
/// let points = vec![
///     DVec2::new(0.0, 1.0),
///     DVec2::new(2.0, 1.0),
///     DVec2::new(2.0, -1.0),
///     DVec2::new(0.0, -1.0),
/// ];
/// let half = RationalBezierCurve::try_new(points, vec![1.0, 1.0 / 3.0, 1.0 / 3.0, 1.0]).unwrap();
/// for i in 0..=20 {
///     assert!((half.eval(i as f64 / 20.0).length() - 1.0).abs() < 1e-15);
/// }
/// assert!((half.eval(0.5) - DVec2::X).length() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBezierCurve<P> {
    // Invariant: points non-empty and finite; weights.len() == points.len(), all positive and
    // finite.
    points: Vec<P>,
    weights: Vec<f64>,
}

impl<P: ControlPoint> RationalBezierCurve<P> {
    /// The rational curve with these control points and weights.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no points, [`Error::NonFinitePoint`] for a non-finite coordinate,
    /// [`Error::WeightCount`] unless there is one weight per point, [`Error::InvalidWeight`]
    /// for a weight that is not positive and finite.
    pub fn try_new(points: Vec<P>, weights: Vec<f64>) -> Result<Self, Error> {
        check_points(&points)?;
        check_weights(points.len(), &weights)?;
        Ok(Self { points, weights })
    }

    /// The rational curve with these control points and weights.
    ///
    /// # Panics
    ///
    /// Panics on invalid input; see [`RationalBezierCurve::try_new`].
    #[must_use]
    pub fn new(points: Vec<P>, weights: Vec<f64>) -> Self {
        Self::try_new(points, weights).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The polynomial curve as a rational one with unit weights.
    #[must_use]
    pub fn from_polynomial(curve: &BezierCurve<P>) -> Self {
        let points = curve.control_points().to_vec();
        let weights = vec![1.0; points.len()];
        Self { points, weights }
    }

    /// Builds from homogeneous control points (wᵢPᵢ, wᵢ).
    fn from_homogeneous(hp: Vec<P>, w: Vec<f64>) -> Self {
        let points = hp.into_iter().zip(&w).map(|(p, &wi)| p * (1.0 / wi)).collect();
        Self { points, weights: w }
    }

    /// The control points P₀, …, Pₙ.
    #[must_use]
    pub fn control_points(&self) -> &[P] {
        &self.points
    }

    /// The weights w₀, …, wₙ.
    #[must_use]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The degree n.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The homogeneous form: the polynomial curves A(t) = Σ wᵢBⁿᵢ(t)Pᵢ and W(t) = Σ wᵢBⁿᵢ(t),
    /// with q = A/W.
    #[must_use]
    pub fn homogeneous(&self) -> (BezierCurve<P>, BezierCurve<f64>) {
        let a = self.points.iter().zip(&self.weights).map(|(&p, &w)| p * w).collect();
        (BezierCurve::from_vec_unchecked(a), BezierCurve::from_vec_unchecked(self.weights.clone()))
    }

    /// q(t) by the rational de Casteljau algorithm: each step is
    /// wʳᵢ = (1 − t)wʳ⁻¹ᵢ + t·wʳ⁻¹ᵢ₊₁ and pʳᵢ = ((1 − t)wʳ⁻¹ᵢpʳ⁻¹ᵢ + t·wʳ⁻¹ᵢ₊₁pʳ⁻¹ᵢ₊₁)/wʳᵢ, a
    /// convex combination of points for t ∈ [0, 1] (more accurate than dividing A(t) by W(t)).
    ///
    /// Outside [0, 1] the denominator may vanish, giving non-finite coordinates.
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        with_scratch(&self.points, |p| {
            with_scratch(&self.weights, |w| rational_de_casteljau(p, w, t).0)
        })
    }

    /// The derivative of order `order` at t, from the quotient rule on q = A/W:
    /// q⁽ᵏ⁾ = (A⁽ᵏ⁾ − Σⱼ₌₁ᵏ C(k, j)·W⁽ʲ⁾·q⁽ᵏ⁻ʲ⁾) / W.
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        self.eval_derivs(t, order)[order]
    }

    /// q(t), q′(t), …, q⁽ᵏ⁾(t) for k = `max_order` (k + 1 values).
    #[must_use]
    pub fn eval_derivs(&self, t: f64, max_order: usize) -> Vec<P> {
        let (a, w) = self.homogeneous();
        let w_derivs: Vec<f64> = (0..=max_order).map(|j| w.eval_deriv(t, j)).collect();
        let mut res = Vec::with_capacity(max_order + 1);
        res.push(self.eval(t));
        for k in 1..=max_order {
            let mut num = a.eval_deriv(t, k);
            for j in 1..=k {
                num = num - res[k - j] * (binomial(k, j) * w_derivs[j]);
            }
            res.push(num * (1.0 / w_derivs[0]));
        }
        res
    }

    /// Splits at t₀ ∈ [0, 1] into q(t₀·t) and q(t₀ + (1 − t₀)·t), both rational of degree n
    /// (Theorem 2.2 on the homogeneous curve).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidArgument`] unless 0 ≤ t₀ ≤ 1 (outside, the weights of a piece can be
    /// zero or negative).
    pub fn split(&self, t0: f64) -> Result<(Self, Self), Error> {
        check_unit("t0", t0)?;
        Ok(self.split_unchecked(t0))
    }

    /// The split of [`RationalBezierCurve::split`] for a t₀ known to lie in [0, 1].
    fn split_unchecked(&self, t0: f64) -> (Self, Self) {
        let mut p = self.points.clone();
        let mut w = self.weights.clone();
        let n = p.len();
        let (mut lp, mut lw) = (vec![p[0]], vec![w[0]]);
        let (mut rp, mut rw) = (vec![p[n - 1]; n], vec![w[n - 1]; n]);
        for level in 1..n {
            for i in 0..n - level {
                rational_step(&mut p, &mut w, i, t0);
            }
            lp.push(p[0]);
            lw.push(w[0]);
            rp[n - 1 - level] = p[n - 1 - level];
            rw[n - 1 - level] = w[n - 1 - level];
        }
        (Self { points: lp, weights: lw }, Self { points: rp, weights: rw })
    }

    /// The piece over `range` = [t₀, t₁] ⊆ [0, 1] (t₀ > t₁ reverses it), reparametrised to
    /// [0, 1].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidArgument`] unless both ends lie in [0, 1].
    pub fn subsegment(&self, range: ParamRange) -> Result<Self, Error> {
        let (t0, t1) = (range.start, range.end);
        check_unit("start", t0)?;
        check_unit("end", t1)?;
        let (a, w) = self.homogeneous();
        let hp = subsegment_points(a.control_points(), t0, t1);
        let hw = subsegment_points(w.control_points(), t0, t1);
        Ok(Self::from_homogeneous(hp, hw))
    }

    /// The same curve with degree n + 1 (elevation of the homogeneous curve).
    #[must_use]
    pub fn elevate(&self) -> Self {
        let (a, w) = self.homogeneous();
        let a = a.elevate().into_control_points();
        let w = w.elevate().into_control_points();
        Self::from_homogeneous(a, w)
    }

    /// The curve traversed backwards, r(t) = q(1 − t).
    #[must_use]
    pub fn reverse(&self) -> Self {
        let mut res = self.clone();
        res.points.reverse();
        res.weights.reverse();
        res
    }

    /// The same curve with w₀ = wₙ = 1 (the standard form), by the reparametrisation
    /// t ↦ t/(c(1 − t) + t) that multiplies wᵢ by cⁱ, c = (w₀/wₙ)^(1/n), followed by dividing
    /// all weights by w₀. For a conic the middle weight is then its shape factor.
    #[must_use]
    pub fn to_standard_form(&self) -> Self {
        let n = self.degree();
        if n == 0 {
            return Self { points: self.points.clone(), weights: vec![1.0] };
        }
        let w0 = self.weights[0];
        let c = (w0 / self.weights[n]).powf(1.0 / n as f64);
        let weights: Vec<f64> = self
            .weights
            .iter()
            .enumerate()
            .map(|(i, &w)| if i == 0 || i == n { 1.0 } else { w * c.powi(i as i32) / w0 })
            .collect();
        Self { points: self.points.clone(), weights }
    }

    /// The unsigned curvature |q′ × q″|/|q′|³ in any dimension (Lagrange's identity), `None`
    /// where the speed vanishes.
    #[must_use]
    pub fn curvature(&self, t: f64) -> Option<f64> {
        let d = self.eval_derivs(t, 2);
        let (d1, d2) = (d[1], d[2]);
        let speed = d1.norm();
        let scale = self.control_bounding_box().size().norm() * self.degree() as f64;
        if speed.is_nan() || speed <= 1e-12 * scale {
            return None;
        }
        let cross2 = (d1.dot(d1) * d2.dot(d2) - d1.dot(d2).powi(2)).max(0.0);
        Some(cross2.sqrt() / speed.powi(3))
    }

    /// The box of the control points, which holds the curve over [0, 1] (positive weights).
    #[must_use]
    pub fn control_bounding_box(&self) -> Aabb<P> {
        Aabb::of_nonempty(&self.points)
    }

    /// The tight box of the curve over [0, 1].
    ///
    /// Each coordinate x = Aₓ/W is extreme at t = 0, t = 1 or a root of the numerator of its
    /// derivative, Aₓ′·W − Aₓ·W′, a polynomial of degree 2n − 1 formed exactly in Bernstein form
    /// (products of Bernstein polynomials) and solved by [`BezierCurve::roots`]; the box is that
    /// of the curve points there, exact to rounding.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::f64::consts::PI;
    ///
    /// use glam::DVec2;
    /// use hi_bezier::RationalBezierCurve;
    ///
    /// // The arc from 30° to 150° of the unit circle peaks at (0, 1).
    /// let arc = RationalBezierCurve::circle_arc(DVec2::ZERO, 1.0, PI / 6.0, 2.0 * PI / 3.0).unwrap();
    /// let b = arc.bounding_box();
    /// assert!((b.max.y - 1.0).abs() < 1e-15 && (b.min.y - 0.5).abs() < 1e-15);
    /// ```
    #[must_use]
    pub fn bounding_box(&self) -> Aabb<P> {
        let n = self.degree();
        let mut res = Aabb::from_point(self.points[0]).including(self.points[n]);
        if n < 2 {
            return res;
        }
        let (a, w) = self.homogeneous();
        let (da, dw) = (a.deriv(), w.deriv());
        let w_coeffs = w.control_points();
        let dw_coeffs = dw.control_points();
        for coord in 0..P::DIM {
            let ax: Vec<f64> = a.control_points().iter().map(|p| p.coord(coord)).collect();
            let dax: Vec<f64> = da.control_points().iter().map(|p| p.coord(coord)).collect();
            let first = bernstein_product(&dax, w_coeffs);
            let second = bernstein_product(&ax, dw_coeffs);
            let numerator = first.iter().zip(&second).map(|(x, y)| x - y).collect();
            for t in BezierCurve::from_vec_unchecked(numerator).roots() {
                res = res.including(self.eval(t));
            }
        }
        res
    }

    /// A polyline through curve points within `tolerance` of the curve, both ways, by halving
    /// until every piece's control points lie within `tolerance` of its chord (the convex hull
    /// test, valid for positive weights).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidTolerance`] unless `tolerance` is finite and at least 1e-10 times the
    /// largest coordinate magnitude.
    pub fn flatten(&self, tolerance: f64) -> Result<Vec<P>, Error> {
        check_tolerance(tolerance, &self.points)?;
        let n = self.degree();
        let mut out = vec![self.points[0]];
        let mut stack = vec![(self.clone(), 0u32)];
        while let Some((piece, depth)) = stack.pop() {
            let (a, b) = (piece.points[0], piece.points[n]);
            let flat = piece.points.iter().all(|&p| distance_to_segment(p, a, b) <= tolerance);
            if flat || depth >= 32 {
                out.push(b);
            } else {
                let (left, right) = piece.split_unchecked(0.5);
                stack.push((right, depth + 1));
                stack.push((left, depth + 1));
            }
        }
        Ok(out)
    }
}

/// The Bernstein coefficients of the product of two polynomials in Bernstein form of degrees
/// m and n: hₖ = Σᵢ₊ⱼ₌ₖ C(m, i)C(n, j)/C(m + n, k)·fᵢgⱼ.
fn bernstein_product(f: &[f64], g: &[f64]) -> Vec<f64> {
    let (m, n) = (f.len() - 1, g.len() - 1);
    let mut h = vec![0.0; m + n + 1];
    for (i, fi) in f.iter().enumerate() {
        for (j, gj) in g.iter().enumerate() {
            h[i + j] += binomial(m, i) * binomial(n, j) / binomial(m + n, i + j) * fi * gj;
        }
    }
    h
}

/// The rational de Casteljau algorithm in place; returns the point and its weight.
pub(crate) fn rational_de_casteljau<P: ControlPoint>(
    p: &mut [P],
    w: &mut [f64],
    t: f64,
) -> (P, f64) {
    let n = p.len();
    for level in 1..n {
        for i in 0..n - level {
            rational_step(p, w, i, t);
        }
    }
    (p[0], w[0])
}

/// One rational de Casteljau step on entry i.
#[inline]
fn rational_step<P: ControlPoint>(p: &mut [P], w: &mut [f64], i: usize, t: f64) {
    let a = (1.0 - t) * w[i];
    let b = t * w[i + 1];
    let wn = a + b;
    p[i] = (p[i] * a + p[i + 1] * b) * (1.0 / wn);
    w[i] = wn;
}

/// Checks that a split parameter lies in [0, 1].
fn check_unit(name: &'static str, t: f64) -> Result<(), Error> {
    if (0.0..=1.0).contains(&t) {
        Ok(())
    } else {
        Err(Error::InvalidArgument { name, value: t, expected: "a number in [0, 1]" })
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;

    #[test]
    fn validation() {
        assert_eq!(
            RationalBezierCurve::try_new(vec![0.0, 1.0], vec![1.0]),
            Err(Error::WeightCount { expected: 2, found: 1 })
        );
        assert_eq!(
            RationalBezierCurve::try_new(vec![0.0, 1.0], vec![1.0, -2.0]),
            Err(Error::InvalidWeight { index: 1, value: -2.0 })
        );
        assert_eq!(RationalBezierCurve::<f64>::try_new(vec![], vec![]), Err(Error::Empty));
        let c = RationalBezierCurve::new(vec![0.0, 1.0], vec![1.0, 2.0]);
        assert!(c.split(1.5).is_err());
        assert!(c.subsegment(ParamRange::new(0.0, f64::NAN)).is_err());
    }

    #[test]
    fn unit_weights_are_polynomial() {
        let poly = BezierCurve::new(vec![DVec2::ZERO, DVec2::Y, DVec2::ONE, DVec2::X]);
        let rat = RationalBezierCurve::from_polynomial(&poly);
        for i in 0..=10 {
            let t = i as f64 / 10.0;
            assert!((rat.eval(t) - poly.eval(t)).length() < 1e-15);
            assert!((rat.eval_deriv(t, 1) - poly.eval_deriv(t, 1)).length() < 1e-13);
            assert!((rat.eval_deriv(t, 2) - poly.eval_deriv(t, 2)).length() < 1e-12);
        }
    }

    #[test]
    fn standard_form_keeps_the_points() {
        let c = RationalBezierCurve::new(
            vec![DVec2::ZERO, DVec2::Y, DVec2::ONE, DVec2::X],
            vec![2.0, 0.5, 3.0, 5.0],
        );
        let s = c.to_standard_form();
        assert_eq!((s.weights()[0], s.weights()[3]), (1.0, 1.0));
        // Same point set: every sample of s lies on c (check by nearest sample).
        for i in 0..=20 {
            let p = s.eval(i as f64 / 20.0);
            let d = (0..=4000)
                .map(|j| (c.eval(j as f64 / 4000.0) - p).length())
                .fold(f64::INFINITY, f64::min);
            assert!(d < 2e-3, "{d}");
        }
    }
}
