// SPDX-License-Identifier: MIT
//! Non-uniform rational B-splines (Hardy 2005, §2.12): X(u) = Σᵢ Rᵢ,ₚ(u)·xᵢ with
//! Rᵢ,ₚ = wᵢNᵢ,ₚ / Σⱼ wⱼNⱼ,ₚ, i.e. the B-spline of the homogeneous points (wᵢxᵢ, wᵢ) projected
//! back, which draws conic sections exactly.
//!
//! A [`NurbsCurve`] keeps two B-splines on the same knots: the numerator A(u) = Σ wᵢNᵢ,ₚ(u)xᵢ
//! and the denominator w(u) = Σ wᵢNᵢ,ₚ(u). Derivatives of any order follow from A = w·X by the
//! quotient (Leibniz) rule, X⁽ᵏ⁾ = (A⁽ᵏ⁾ − Σᵢ₌₁ᵏ C(k, i)·w⁽ⁱ⁾·X⁽ᵏ⁻ⁱ⁾)/w. Parameters follow
//! [`BSplineCurve`]: t ∈ [0, 1] is mapped affinely onto the knot domain (periodically when
//! closed).
//!
//! A rational curve is no [`PiecewiseBezier`], so there is no `to_bezier` here: instead
//! [`NurbsCurve::to_rational_bezier`] gives the exact rational Bézier segments
//! ([`RationalBezierCurve`]) and [`NurbsCurve::to_homogeneous_bezier`] the same as a pair of
//! polynomial Bézier chains (numerator, denominator).

use glam::DVec2;
use hi_bezier::{PiecewiseBezier, RationalBezierCurve};
use hi_curve::Error as CurveError;

use super::bspline::{BSplineCurve, point_spread};
use crate::check::check_points;
use crate::{ControlPoint, Error};
use hi_curve::ParamCurve;

/// A NURBS curve: control points, positive weights and a knot vector (§2.12).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ParamCurve;
/// use hi_compare::nurbs::NurbsCurve;
///
/// // The exact unit circle: 9 control points, degree 2.
/// let circle = NurbsCurve::circle(DVec2::ZERO, 1.0);
/// for i in 0..=100 {
///     let t = i as f64 / 100.0;
///     assert!((circle.eval(t).length() - 1.0).abs() < 1e-15);
///     assert!((circle.curvature(t).unwrap() - 1.0).abs() < 1e-12);
/// }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurve<P> {
    // Invariant: weights.len() == control.len(), every weight finite and positive; numerator
    // has control points wᵢxᵢ and denominator wᵢ, on the same knots and degree.
    control: Vec<P>,
    weights: Vec<f64>,
    numerator: BSplineCurve<P>,
    denominator: BSplineCurve<f64>,
}

fn check_weights(n_points: usize, weights: &[f64]) -> Result<(), Error> {
    if weights.len() != n_points {
        return Err(Error::Curve(CurveError::InvalidCount {
            what: "number of weights",
            value: weights.len(),
            expected: "one weight per control point",
        }));
    }
    match weights.iter().position(|w| !(w.is_finite() && *w > 0.0)) {
        Some(index) => Err(Error::InvalidWeight { index, value: weights[index] }),
        None => Ok(()),
    }
}

impl<P: ControlPoint> NurbsCurve<P> {
    /// The open NURBS curve of degree p with these knots, control points and weights.
    ///
    /// # Errors
    ///
    /// The errors of [`BSplineCurve::try_new`], [`hi_curve::Error::InvalidCount`] unless there is one
    /// weight per control point, and [`Error::InvalidWeight`] for a weight that is not finite
    /// and positive.
    pub fn try_new(
        degree: usize,
        knots: Vec<f64>,
        control: Vec<P>,
        weights: Vec<f64>,
    ) -> Result<Self, Error> {
        check_points(&control)?;
        check_weights(control.len(), &weights)?;
        let weighted = control.iter().zip(&weights).map(|(x, w)| *x * *w).collect();
        let numerator = BSplineCurve::try_new(degree, knots.clone(), weighted)?;
        let denominator = BSplineCurve::try_new(degree, knots, weights.clone())?;
        Ok(Self { control, weights, numerator, denominator })
    }

    /// The closed (periodic) NURBS curve of degree p with n + 1 breakpoints, as
    /// [`BSplineCurve::try_new_periodic`].
    ///
    /// # Errors
    ///
    /// The errors of [`BSplineCurve::try_new_periodic`], [`hi_curve::Error::InvalidCount`] unless there
    /// is one weight per control point, and [`Error::InvalidWeight`] for a weight that is not
    /// finite and positive.
    pub fn try_new_periodic(
        degree: usize,
        breakpoints: Vec<f64>,
        control: Vec<P>,
        weights: Vec<f64>,
    ) -> Result<Self, Error> {
        check_points(&control)?;
        check_weights(control.len(), &weights)?;
        let weighted = control.iter().zip(&weights).map(|(x, w)| *x * *w).collect();
        let numerator = BSplineCurve::try_new_periodic(degree, breakpoints.clone(), weighted)?;
        let denominator = BSplineCurve::try_new_periodic(degree, breakpoints, weights.clone())?;
        Ok(Self { control, weights, numerator, denominator })
    }

    /// The degree p.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.numerator.degree()
    }

    /// The knots (or the breakpoints of a closed curve), as given.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        self.numerator.knots()
    }

    /// The control points xᵢ.
    #[must_use]
    pub fn control_points(&self) -> &[P] {
        &self.control
    }

    /// The weights wᵢ.
    #[must_use]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// Whether the curve is closed (built by [`NurbsCurve::try_new_periodic`]); its
    /// [`knots`](NurbsCurve::knots) are then the n + 1 breakpoints of one period.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.numerator.is_closed()
    }

    /// The curve parameters of the ends of the polynomial pieces, as
    /// [`BSplineCurve::breakpoints`].
    #[must_use]
    pub fn breakpoints(&self) -> Vec<f64> {
        self.numerator.breakpoints()
    }

    /// X(t) = A(t)/w(t).
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        self.numerator.eval(t) * (1.0 / self.denominator.eval(t))
    }

    /// The derivative X⁽ᵏ⁾(t) of any order by the quotient rule (exact; a rational curve has
    /// non-zero derivatives of every order).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        let w: Vec<f64> = (0..=order).map(|i| self.denominator.eval_deriv(t, i)).collect();
        let inv_w = 1.0 / w[0];
        let mut derivs: Vec<P> = Vec::with_capacity(order + 1);
        for k in 0..=order {
            let mut v = self.numerator.eval_deriv(t, k);
            let mut binom = 1.0;
            for i in 1..=k {
                binom = binom * (k + 1 - i) as f64 / i as f64;
                v = v - derivs[k - i] * (binom * w[i]);
            }
            derivs.push(v * inv_w);
        }
        derivs[order]
    }

    /// The rational basis R₀(t), …, R_{m−1}(t): wᵢNᵢ(u)/Σⱼ wⱼNⱼ(u). A partition of unity.
    #[must_use]
    pub fn basis_values(&self, t: f64) -> Vec<f64> {
        let mut values = self.numerator.basis_values(t);
        let mut sum = 0.0;
        for (v, w) in values.iter_mut().zip(&self.weights) {
            *v *= w;
            sum += *v;
        }
        values.iter_mut().for_each(|v| *v /= sum);
        values
    }

    /// The exact rational Bézier segments, as homogeneous chains: segment i of the curve is
    /// Aᵢ(v)/wᵢ(v), Aᵢ the i-th segment of the first chain (control points wₖxₖ of the
    /// rational Bézier curve) and wᵢ that of the second (its weights wₖ). Parameters as
    /// [`NurbsCurve::breakpoints`].
    #[must_use]
    pub fn to_homogeneous_bezier(&self) -> (PiecewiseBezier<P>, PiecewiseBezier<f64>) {
        (self.numerator.to_bezier(), self.denominator.to_bezier())
    }

    /// The exact rational Bézier segments of degree p, one per non-empty knot interval (the
    /// homogeneous chains of [`NurbsCurve::to_homogeneous_bezier`] projected back): segment i
    /// at v ∈ [0, 1] is this curve at t = tᵢ + v·(tᵢ₊₁ − tᵢ) with tᵢ from
    /// [`NurbsCurve::breakpoints`]. (`hi-bezier` has no piecewise rational type, hence a
    /// `Vec`.)
    ///
    /// # Panics
    ///
    /// Does not panic: the weights of the segments are convex combinations of the (positive)
    /// weights.
    #[must_use]
    pub fn to_rational_bezier(&self) -> Vec<RationalBezierCurve<P>> {
        let (numerator, denominator) = self.to_homogeneous_bezier();
        numerator
            .segments()
            .iter()
            .zip(denominator.segments())
            .map(|(a, w)| {
                let weights = w.control_points().to_vec();
                let points = a
                    .control_points()
                    .iter()
                    .zip(&weights)
                    .map(|(p, wi)| *p * (1.0 / wi))
                    .collect();
                RationalBezierCurve::try_new(points, weights)
                    .expect("convex combinations of positive weights are positive")
            })
            .collect()
    }
}

impl NurbsCurve<DVec2> {
    /// The exact circle of this centre and radius: the classic degree-2 NURBS with 9 control
    /// points on the circumscribed square, weights 1 and √2/2 alternately, and knots
    /// (0, 0, 0, ¼, ¼, ½, ½, ¾, ¾, 1, 1, 1). It starts at centre + (r, 0) and runs
    /// counter-clockwise, one quadrant per quarter of t (not at constant speed).
    ///
    /// # Panics
    ///
    /// Panics if `center` or `radius` is not finite, or `radius` is not positive.
    #[must_use]
    pub fn circle(center: DVec2, radius: f64) -> Self {
        assert!(
            center.is_finite() && radius.is_finite() && radius > 0.0,
            "circle needs a finite centre and a finite positive radius, got {center} and {radius}"
        );
        let corners = [
            (1.0, 0.0),
            (1.0, 1.0),
            (0.0, 1.0),
            (-1.0, 1.0),
            (-1.0, 0.0),
            (-1.0, -1.0),
            (0.0, -1.0),
            (1.0, -1.0),
            (1.0, 0.0),
        ];
        let control = corners.iter().map(|&(x, y)| center + DVec2::new(x, y) * radius).collect();
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let weights = vec![1.0, h, 1.0, h, 1.0, h, 1.0, h, 1.0];
        let knots = vec![0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0];
        Self::try_new(2, knots, control, weights).expect("the circle's data is valid")
    }
}

impl<P: ControlPoint> ParamCurve<P> for NurbsCurve<P> {
    fn eval(&self, t: f64) -> P {
        NurbsCurve::eval(self, t)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> P {
        NurbsCurve::eval_deriv(self, t, order)
    }

    fn scale(&self) -> f64 {
        point_spread(&self.control)
    }

    fn is_periodic(&self) -> bool {
        self.numerator.is_closed()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quotient_rule_matches_difference_quotients() {
        let circle = NurbsCurve::circle(DVec2::new(1.0, -2.0), 3.0);
        let h = 1e-5;
        for t in [0.1, 0.3, 0.6, 0.9] {
            for order in 1..=4 {
                let fd = (circle.eval_deriv(t + h, order - 1)
                    - circle.eval_deriv(t - h, order - 1))
                    / (2.0 * h);
                let d = circle.eval_deriv(t, order);
                assert!((d - fd).length() < 1e-5 * (1.0 + d.length()), "t={t} order={order}");
            }
        }
    }

    #[test]
    fn bad_weights_are_rejected() {
        let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        let pts = vec![0.0, 1.0, 2.0];
        let bad = NurbsCurve::try_new(2, knots.clone(), pts.clone(), vec![1.0, 0.0, 1.0]);
        assert_eq!(bad, Err(Error::InvalidWeight { index: 1, value: 0.0 }));
        assert!(
            NurbsCurve::try_new(2, knots.clone(), pts.clone(), vec![1.0, f64::NAN, 1.0]).is_err()
        );
        assert!(NurbsCurve::try_new(2, knots, pts, vec![1.0]).is_err());
    }
}
