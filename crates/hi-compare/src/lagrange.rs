// SPDX-License-Identifier: MIT
//! Lagrange interpolation (Hardy 2005, §2.4): the polynomial q(u) = Σₖ Lₖ(u)·xₖ of degree
//! n − 1 through n points, Lₖ(u) = Πⱼ≠ₖ (u − uⱼ)/(uₖ − uⱼ), evaluated by Neville's algorithm.
//!
//! The node parameters u₀ < … < uₙ₋₁ are in their own units (the thesis's example 2.1 uses
//! uⱼ = j); as a [`ParamCurve`] the curve runs over t ∈ [0, 1] with u = u₀ + t·(uₙ₋₁ − u₀), so
//! it is open, from x₀ at t = 0 to xₙ₋₁ at t = 1. The default nodes are uniform, tⱼ = j/(n − 1).

use hi_bezier::{BezierCurve, PiecewiseBezier};
use hi_curve::Error as CurveError;

use super::bspline::point_spread;
use crate::check::check_points;
use crate::{ControlPoint, Error};
use hi_curve::ParamCurve;

/// Checks node parameters: as many as points, finite, strictly increasing.
pub(super) fn check_increasing(n_points: usize, params: &[f64]) -> Result<(), Error> {
    if params.len() != n_points {
        return Err(Error::Curve(CurveError::ParameterCountMismatch {
            points: n_points,
            params: params.len(),
        }));
    }
    if let Some(&value) = params.iter().find(|u| !u.is_finite()) {
        return Err(Error::Curve(CurveError::NonFiniteParameter { name: "parameter", value }));
    }
    for index in 1..params.len() {
        if params[index] == params[index - 1] {
            return Err(Error::Curve(CurveError::ParametersNotDistinct {
                first: index - 1,
                second: index,
            }));
        }
        if params[index] < params[index - 1] {
            return Err(Error::ParametersNotIncreasing { index });
        }
    }
    Ok(())
}

/// The Lagrange basis L₀, …, Lₙ₋₁ of distinct nodes (figure 2.1), in node units u.
///
/// Lₖ(uⱼ) = δⱼₖ and Σₖ Lₖ(u) = 1 (so Lagrange curves are affine invariant, theorem 2.1), but
/// the Lₖ take negative values: the curve need not stay in the convex hull of its points.
///
/// # Examples
///
/// ```
/// use hi_compare::lagrange::LagrangeBasis;
///
/// // Figure 2.1: uniform nodes 0, 1, 2, 3.
/// let basis = LagrangeBasis::try_new(vec![0.0, 1.0, 2.0, 3.0]).unwrap();
/// assert_eq!(basis.eval(1, 1.0), 1.0);
/// assert_eq!(basis.eval(1, 2.0), 0.0);
/// // L₀(1.5) = (0.5)(−0.5)(−1.5)/((−1)(−2)(−3)) = −1/16.
/// assert!((basis.eval(0, 1.5) + 1.0 / 16.0).abs() < 1e-15);
/// let sum: f64 = basis.eval_all(2.7).iter().sum();
/// assert!((sum - 1.0).abs() < 1e-14);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct LagrangeBasis {
    // Invariant: at least one node, finite, strictly increasing.
    nodes: Vec<f64>,
}

impl LagrangeBasis {
    /// The basis of these nodes.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`] for no nodes, [`hi_curve::Error::NonFiniteParameter`] for a NaN or infinite
    /// node, [`hi_curve::Error::ParametersNotDistinct`] or [`Error::ParametersNotIncreasing`] unless they
    /// strictly increase.
    pub fn try_new(nodes: Vec<f64>) -> Result<Self, Error> {
        if nodes.is_empty() {
            return Err(Error::Curve(CurveError::Empty));
        }
        check_increasing(nodes.len(), &nodes)?;
        Ok(Self { nodes })
    }

    /// The nodes u₀ < … < uₙ₋₁.
    #[must_use]
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// Lₖ(u) = Πⱼ≠ₖ (u − uⱼ)/(uₖ − uⱼ).
    ///
    /// # Panics
    ///
    /// Panics if `k` is not below the number of nodes.
    #[must_use]
    pub fn eval(&self, k: usize, u: f64) -> f64 {
        assert!(k < self.nodes.len(), "basis index {k} out of range (< {})", self.nodes.len());
        let uk = self.nodes[k];
        self.nodes
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != k)
            .map(|(_, &uj)| (u - uj) / (uk - uj))
            .product()
    }

    /// All the values L₀(u), …, Lₙ₋₁(u).
    #[must_use]
    pub fn eval_all(&self, u: f64) -> Vec<f64> {
        (0..self.nodes.len()).map(|k| self.eval(k, u)).collect()
    }
}

/// The Lagrange interpolating polynomial curve through n points (§2.4), degree n − 1.
///
/// Polynomials of degree below n are reproduced exactly; with many uniform nodes the curve
/// oscillates strongly (Runge's phenomenon, the "significant problem" of §2.4).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ParamCurve;
/// use hi_compare::lagrange::LagrangeCurve;
///
/// // Points on the parabola y = x², uniform nodes: the curve is that parabola.
/// let pts: Vec<DVec2> = (0..4).map(|i| DVec2::new(i as f64, (i * i) as f64)).collect();
/// let curve = LagrangeCurve::try_new(pts).unwrap();
/// assert!((curve.eval(1.0 / 3.0) - DVec2::new(1.0, 1.0)).length() < 1e-14);
/// let p = curve.eval(0.5); // x = 1.5 at t = 1/2
/// assert!((p - DVec2::new(1.5, 2.25)).length() < 1e-14);
/// assert!(curve.eval_deriv(0.5, 3).length() < 1e-12); // degree 2 data, so X‴ = 0
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct LagrangeCurve<P> {
    // Invariant: points.len() == basis.nodes().len() >= 2, points finite.
    points: Vec<P>,
    basis: LagrangeBasis,
}

impl<P: ControlPoint> LagrangeCurve<P> {
    /// The curve through `points` at the uniform nodes tⱼ = j/(n − 1).
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`], [`hi_curve::Error::NonFinitePoint`], and [`Error::TooFewPoints`] for a single
    /// point.
    pub fn try_new(points: Vec<P>) -> Result<Self, Error> {
        let n = points.len();
        let nodes = (0..n).map(|j| j as f64 / (n.max(2) - 1) as f64).collect();
        Self::try_with_params(points, nodes)
    }

    /// The curve through `points` at the node parameters `params` (strictly increasing, any
    /// units: the curve parameter t ∈ [0, 1] is mapped onto [u₀, uₙ₋₁]).
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`], [`hi_curve::Error::NonFinitePoint`], [`Error::TooFewPoints`] for a single point,
    /// [`hi_curve::Error::ParameterCountMismatch`], [`hi_curve::Error::NonFiniteParameter`],
    /// [`hi_curve::Error::ParametersNotDistinct`] and [`Error::ParametersNotIncreasing`] for bad nodes.
    pub fn try_with_params(points: Vec<P>, params: Vec<f64>) -> Result<Self, Error> {
        check_points(&points)?;
        if points.len() < 2 {
            return Err(Error::TooFewPoints { what: "a Lagrange curve", needed: 2, got: 1 });
        }
        check_increasing(points.len(), &params)?;
        Ok(Self { points, basis: LagrangeBasis { nodes: params } })
    }

    /// The interpolated points.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The basis (its nodes are the node parameters, in their own units).
    #[must_use]
    pub fn basis(&self) -> &LagrangeBasis {
        &self.basis
    }

    /// The degree n − 1.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The node parameter u of the curve parameter t.
    #[must_use]
    pub fn node_param(&self, t: f64) -> f64 {
        let (a, b) = self.span();
        a + t * (b - a)
    }

    fn span(&self) -> (f64, f64) {
        let nodes = &self.basis.nodes;
        (nodes[0], nodes[nodes.len() - 1])
    }

    /// X(t) by Neville's algorithm (§2.4), O(n²).
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        self.eval_deriv(t, 0)
    }

    /// X⁽ʳ⁾(t) of any order (0 above n − 1), by Neville's algorithm on derivatives: the
    /// recursion pᵢ..ⱼ = ((u − uᵢ)·pᵢ₊₁..ⱼ − (u − uⱼ)·pᵢ..ⱼ₋₁)/(uⱼ − uᵢ) differentiated r times,
    /// pᵢ..ⱼ⁽ʳ⁾ = ((u − uᵢ)·pᵢ₊₁..ⱼ⁽ʳ⁾ + r·pᵢ₊₁..ⱼ⁽ʳ⁻¹⁾ − (u − uⱼ)·pᵢ..ⱼ₋₁⁽ʳ⁾ − r·pᵢ..ⱼ₋₁⁽ʳ⁻¹⁾)
    /// / (uⱼ − uᵢ), in O(r·n²).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        let (a, b) = self.span();
        self.node_deriv(self.node_param(t), order) * (b - a).powi(order as i32)
    }

    /// The r-th derivative with respect to u, at u.
    fn node_deriv(&self, u: f64, order: usize) -> P {
        let n = self.points.len();
        if order >= n {
            return P::ZERO;
        }
        let nodes = &self.basis.nodes;
        // table[r][i] holds p⁽ʳ⁾ᵢ..ᵢ₊ₗ after level l.
        let mut table: Vec<Vec<P>> = vec![vec![P::ZERO; n]; order + 1];
        table[0].copy_from_slice(&self.points);
        for level in 1..n {
            for i in 0..n - level {
                let j = i + level;
                let inv = 1.0 / (nodes[j] - nodes[i]);
                let (wi, wj) = (u - nodes[i], u - nodes[j]);
                // Higher orders first: they read the lower orders of the previous level.
                for r in (0..=order).rev() {
                    let mut v = table[r][i + 1] * wi - table[r][i] * wj;
                    if r > 0 {
                        v += (table[r - 1][i + 1] - table[r - 1][i]) * r as f64;
                    }
                    table[r][i] = v * inv;
                }
            }
        }
        table[order][0]
    }

    /// The same polynomial as one Bézier curve of degree n − 1 over t ∈ [0, 1] (the same
    /// parameter): the Newton form X = c₀ + (t − τ₀)(c₁ + (t − τ₁)(c₂ + …)) (divided
    /// differences cₖ at the nodes τₖ ∈ [0, 1]) is evaluated by Horner's rule in Bernstein
    /// form, each product with a linear factor (t − τₖ) = −τₖ·(1 − t) + (1 − τₖ)·t raising the
    /// degree by one. This power-to-Bernstein conversion avoids the monomial basis; it is exact
    /// in exact arithmetic.
    ///
    /// Conditioning limit: the Bernstein coefficients of a high-degree interpolant are much
    /// larger than the curve (they grow like 2ⁿ for uniform nodes), and de Casteljau's
    /// algorithm cancels them, so the Bézier curve carries an absolute error of about
    /// 10⁻¹⁶ × (largest control point). Measured for uniform nodes and random data in [−1, 1],
    /// relative to the largest value of the curve: the Bézier curve agrees with
    /// [`LagrangeCurve::eval`] to 2e-14 at n = 10, 2e-11 at n = 20, 3e-10 at n = 30 and 3e-8
    /// at n = 40 (when the curve itself overshoots its data by a factor 10⁸: beyond n ≈ 20
    /// neither the curve nor its conversion is of practical use).
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if a Bernstein coefficient overflows (which takes a high degree: the
    /// coefficients grow like 2ⁿ).
    pub fn to_bezier(&self) -> Result<PiecewiseBezier<P>, Error> {
        let n = self.points.len();
        let (a, b) = self.span();
        let tau: Vec<f64> = self.basis.nodes.iter().map(|&u| (u - a) / (b - a)).collect();
        // Divided differences in place: coef[k] = x[τ₀, …, τₖ].
        let mut coef = self.points.clone();
        for level in 1..n {
            for k in (level..n).rev() {
                coef[k] = (coef[k] - coef[k - 1]) * (1.0 / (tau[k] - tau[k - level]));
            }
        }
        // Horner in Bernstein form, innermost first.
        let mut bern = vec![coef[n - 1]];
        for k in (0..n - 1).rev() {
            let m = bern.len(); // current degree + 1
            let (lo, hi) = (-tau[k], 1.0 - tau[k]);
            let raised = (0..=m)
                .map(|i| {
                    let mut v = coef[k];
                    if i < m {
                        v += bern[i] * (lo * (m - i) as f64 / m as f64);
                    }
                    if i > 0 {
                        v += bern[i - 1] * (hi * i as f64 / m as f64);
                    }
                    v
                })
                .collect();
            bern = raised;
        }
        let overflow = |_| Error::Overflow { what: "Bernstein form of the Lagrange polynomial" };
        let segment = BezierCurve::try_new(bern).map_err(overflow)?;
        PiecewiseBezier::try_new(vec![segment]).map_err(overflow)
    }
}

impl<P: ControlPoint> ParamCurve<P> for LagrangeCurve<P> {
    fn eval(&self, t: f64) -> P {
        LagrangeCurve::eval(self, t)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> P {
        LagrangeCurve::eval_deriv(self, t, order)
    }

    fn scale(&self) -> f64 {
        point_spread(&self.points)
    }

    fn is_periodic(&self) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn neville_derivatives_of_a_cubic() {
        // x(u) = u³ − 2u + 1 at nodes 0, 0.5, 2, 3 (units), the curve over t ∈ [0, 1] is
        // x(3t), so X′(t) = 3x′(3t), X″ = 9x″, X‴ = 27x‴.
        let f = |u: f64| u * u * u - 2.0 * u + 1.0;
        let nodes = vec![0.0, 0.5, 2.0, 3.0];
        let curve =
            LagrangeCurve::try_with_params(nodes.iter().map(|&u| f(u)).collect(), nodes).unwrap();
        for t in [0.0, 0.2, 0.7, 1.0] {
            let u = 3.0 * t;
            assert!((curve.eval(t) - f(u)).abs() < 1e-13);
            assert!((curve.eval_deriv(t, 1) - 3.0 * (3.0 * u * u - 2.0)).abs() < 1e-12);
            assert!((curve.eval_deriv(t, 2) - 9.0 * 6.0 * u).abs() < 1e-11);
            assert!((curve.eval_deriv(t, 3) - 27.0 * 6.0).abs() < 1e-10);
            assert_eq!(curve.eval_deriv(t, 4), 0.0);
        }
    }

    #[test]
    fn bad_nodes_are_rejected() {
        let pts = vec![1.0, 2.0, 3.0];
        assert!(matches!(
            LagrangeCurve::try_with_params(pts.clone(), vec![0.0, 1.0, 1.0]),
            Err(Error::Curve(CurveError::ParametersNotDistinct { first: 1, second: 2 }))
        ));
        assert!(matches!(
            LagrangeCurve::try_with_params(pts.clone(), vec![0.0, 2.0, 1.0]),
            Err(Error::ParametersNotIncreasing { index: 2 })
        ));
        assert!(LagrangeCurve::try_with_params(pts.clone(), vec![0.0, 1.0]).is_err());
        assert!(LagrangeCurve::try_new(vec![1.0]).is_err());
        assert!(LagrangeCurve::<f64>::try_new(vec![]).is_err());
        assert!(LagrangeBasis::try_new(vec![0.0, f64::NAN]).is_err());
    }
}
