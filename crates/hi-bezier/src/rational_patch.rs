// SPDX-License-Identifier: MIT
//! Rational tensor-product Bézier patches (Hardy 2005, §4.3 "Rational Bézier Surfaces"):
//! p(u, v) = Σⱼₖ Bᵐⱼ(u)Bⁿₖ(v)wⱼₖxⱼₖ / Σⱼₖ Bᵐⱼ(u)Bⁿₖ(v)wⱼₖ, and exact surfaces of revolution
//! (cylinders, spheres, tori) built from rational arcs.

use glam::{DVec2, DVec3};

use crate::bernstein::binomial;
use crate::bounds::Aabb;
use crate::curve::with_scratch;
use crate::error::check_points;
use crate::patch::unit_normal;
use crate::rational::rational_de_casteljau;
use crate::{BezierPatch, ControlPoint, Error, RationalBezierCurve};

/// A rational tensor-product Bézier patch of degree (m, n): an (m + 1) × (n + 1) grid of
/// control points xⱼₖ with positive weights wⱼₖ, over (u, v) ∈ [0, 1]², u over the row index.
///
/// # Examples
///
/// ```
/// use std::f64::consts::FRAC_PI_2;
///
/// use glam::DVec2;
/// use hi_bezier::{RationalBezierCurve, RationalBezierPatch};
///
/// // An exact octant of the unit sphere: a quarter meridian (radius, height) revolved
/// // through a quarter turn.
/// let meridian = RationalBezierCurve::circle_arc(DVec2::ZERO, 1.0, 0.0, FRAC_PI_2).unwrap();
/// let turn = RationalBezierCurve::circle_arc(DVec2::ZERO, 1.0, 0.0, FRAC_PI_2).unwrap();
/// let octant = RationalBezierPatch::revolve(&meridian, &turn);
/// assert!((octant.eval(0.3, 0.6).length() - 1.0).abs() < 1e-15);
/// assert!(octant.normal(1.0, 0.5).is_none()); // the pole is a collapsed edge
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBezierPatch<P> {
    // Invariant: points is a valid BezierPatch grid; weights has its shape, all positive and
    // finite.
    points: BezierPatch<P>,
    weights: Vec<f64>,
}

impl<P: ControlPoint> RationalBezierPatch<P> {
    /// The patch with control rows `rows[j][k]` = xⱼₖ and weights `weights[j][k]` = wⱼₖ.
    ///
    /// # Errors
    ///
    /// The errors of [`BezierPatch::try_new`] for the points; [`Error::WeightCount`] if the
    /// number of weight rows differs from the number of control rows,
    /// [`Error::RaggedGrid`] if a weight row differs in length from the control rows,
    /// [`Error::InvalidWeight`] for a weight that is not positive and finite (row-major index).
    pub fn try_new(rows: Vec<Vec<P>>, weights: Vec<Vec<f64>>) -> Result<Self, Error> {
        let points = BezierPatch::try_new(rows)?;
        let n_rows = points.degree_u() + 1;
        let n_cols = points.degree_v() + 1;
        if weights.len() != n_rows {
            return Err(Error::WeightCount { expected: n_rows, found: weights.len() });
        }
        if let Some((row, r)) = weights.iter().enumerate().find(|(_, r)| r.len() != n_cols) {
            return Err(Error::RaggedGrid { row, expected: n_cols, found: r.len() });
        }
        let weights: Vec<f64> = weights.into_iter().flatten().collect();
        crate::error::check_weights(weights.len(), &weights)?;
        Ok(Self { points, weights })
    }

    /// The patch with these control rows and weights.
    ///
    /// # Panics
    ///
    /// Panics on invalid input; see [`RationalBezierPatch::try_new`].
    #[must_use]
    pub fn new(rows: Vec<Vec<P>>, weights: Vec<Vec<f64>>) -> Self {
        Self::try_new(rows, weights).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The polynomial patch as a rational one with unit weights.
    #[must_use]
    pub fn from_polynomial(patch: &BezierPatch<P>) -> Self {
        Self { points: patch.clone(), weights: vec![1.0; patch.control_points().len()] }
    }

    /// The degree m in u.
    #[must_use]
    pub fn degree_u(&self) -> usize {
        self.points.degree_u()
    }

    /// The degree n in v.
    #[must_use]
    pub fn degree_v(&self) -> usize {
        self.points.degree_v()
    }

    /// The control points, row-major.
    #[must_use]
    pub fn control_points(&self) -> &[P] {
        self.points.control_points()
    }

    /// The weights, row-major.
    #[must_use]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The homogeneous form: the polynomial patches A = Σ BB·w·x and W = Σ BB·w, with p = A/W.
    #[must_use]
    pub fn homogeneous(&self) -> (BezierPatch<P>, BezierPatch<f64>) {
        let (n_rows, n_cols) = (self.degree_u() + 1, self.degree_v() + 1);
        let a = self.control_points().iter().zip(&self.weights).map(|(&p, &w)| p * w).collect();
        (
            BezierPatch::from_parts(n_rows, n_cols, a),
            BezierPatch::from_parts(n_rows, n_cols, self.weights.clone()),
        )
    }

    /// p(u, v) by rational de Casteljau steps along each row (in v), then along the column (in
    /// u): convex combinations throughout for (u, v) ∈ [0, 1]².
    #[must_use]
    pub fn eval(&self, u: f64, v: f64) -> P {
        let n_cols = self.degree_v() + 1;
        let mut column_p = Vec::with_capacity(self.degree_u() + 1);
        let mut column_w = Vec::with_capacity(self.degree_u() + 1);
        for (r, w) in self.control_points().chunks(n_cols).zip(self.weights.chunks(n_cols)) {
            let (p, w) = with_scratch(r, |r| with_scratch(w, |w| rational_de_casteljau(r, w, v)));
            column_p.push(p);
            column_w.push(w);
        }
        rational_de_casteljau(&mut column_p, &mut column_w, u).0
    }

    /// The partial derivative ∂ᵃ⁺ᵇp/∂uᵃ∂vᵇ at (u, v), a = `order_u`, b = `order_v`, by the
    /// quotient rule on p = A/W:
    /// p⁽ᵃ'ᵇ⁾ = (A⁽ᵃ'ᵇ⁾ − Σ₍ᵢ,ⱼ₎≠₍₀,₀₎ C(a, i)C(b, j)·W⁽ⁱ'ʲ⁾·p⁽ᵃ⁻ⁱ'ᵇ⁻ʲ⁾) / W.
    #[must_use]
    pub fn eval_deriv(&self, u: f64, v: f64, order_u: usize, order_v: usize) -> P {
        let (a, w) = self.homogeneous();
        let (na, nb) = (order_u + 1, order_v + 1);
        let wd: Vec<f64> = (0..na * nb).map(|idx| w.eval_deriv(u, v, idx / nb, idx % nb)).collect();
        let mut table = vec![P::ZERO; na * nb];
        for i in 0..na {
            for j in 0..nb {
                if i == 0 && j == 0 {
                    table[0] = self.eval(u, v);
                    continue;
                }
                let mut num = a.eval_deriv(u, v, i, j);
                for p in 0..=i {
                    for q in 0..=j {
                        if p == 0 && q == 0 {
                            continue;
                        }
                        let c = binomial(i, p) * binomial(j, q) * wd[p * nb + q];
                        num = num - table[(i - p) * nb + (j - q)] * c;
                    }
                }
                table[i * nb + j] = num * (1.0 / wd[0]);
            }
        }
        table[na * nb - 1]
    }

    /// Splits at u = t ∈ [0, 1] into the pieces over [0, t] and [t, 1] in u.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidArgument`] unless 0 ≤ t ≤ 1.
    pub fn split_u(&self, t: f64) -> Result<(Self, Self), Error> {
        check_unit(t)?;
        let (a, w) = self.homogeneous();
        let (a0, a1) = a.split_u(t);
        let (w0, w1) = w.split_u(t);
        Ok((Self::from_homogeneous(&a0, &w0), Self::from_homogeneous(&a1, &w1)))
    }

    /// Splits at v = t ∈ [0, 1] into the pieces over [0, t] and [t, 1] in v.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidArgument`] unless 0 ≤ t ≤ 1.
    pub fn split_v(&self, t: f64) -> Result<(Self, Self), Error> {
        check_unit(t)?;
        let (a, w) = self.homogeneous();
        let (a0, a1) = a.split_v(t);
        let (w0, w1) = w.split_v(t);
        Ok((Self::from_homogeneous(&a0, &w0), Self::from_homogeneous(&a1, &w1)))
    }

    /// Builds from homogeneous patches with positive weights.
    fn from_homogeneous(a: &BezierPatch<P>, w: &BezierPatch<f64>) -> Self {
        let (n_rows, n_cols) = (a.degree_u() + 1, a.degree_v() + 1);
        let points = a
            .control_points()
            .iter()
            .zip(w.control_points())
            .map(|(&p, &wi)| p * (1.0 / wi))
            .collect();
        Self {
            points: BezierPatch::from_parts(n_rows, n_cols, points),
            weights: w.control_points().to_vec(),
        }
    }

    /// The box of the control points, which holds the patch (positive weights).
    #[must_use]
    pub fn control_bounding_box(&self) -> Aabb<P> {
        self.points.control_bounding_box()
    }
}

impl RationalBezierPatch<DVec3> {
    /// The unit normal (∂p/∂u × ∂p/∂v)/|…|, `None` where the patch is degenerate (see
    /// [`BezierPatch::normal`]).
    #[must_use]
    pub fn normal(&self, u: f64, v: f64) -> Option<DVec3> {
        unit_normal(self.eval_deriv(u, v, 1, 0), self.eval_deriv(u, v, 0, 1))
    }

    /// The surface (r(u)·x(v), r(u)·y(v), z(u)) swept by the profile u ↦ (r(u), z(u)) (radius
    /// and height, `profile`) turned about the z axis through the directions
    /// v ↦ (x(v), y(v)) of `turn`. With `turn` an exact unit-circle arc this is an exact
    /// surface of revolution: a cylinder for a vertical segment profile, a sphere for a
    /// meridian arc, a cone or a torus.
    ///
    /// The control points are (rⱼxₖ, rⱼyₖ, zⱼ) with weights aⱼbₖ (aⱼ, bₖ the curves' weights):
    /// the numerator and denominator then factor into the curves' own, which is why the
    /// result is exact.
    #[must_use]
    pub fn revolve(
        profile: &RationalBezierCurve<DVec2>,
        turn: &RationalBezierCurve<DVec2>,
    ) -> Self {
        let (n_rows, n_cols) = (profile.degree() + 1, turn.degree() + 1);
        let mut points = Vec::with_capacity(n_rows * n_cols);
        let mut weights = Vec::with_capacity(n_rows * n_cols);
        for (rz, a) in profile.control_points().iter().zip(profile.weights()) {
            for (xy, b) in turn.control_points().iter().zip(turn.weights()) {
                points.push(DVec3::new(rz.x * xy.x, rz.x * xy.y, rz.y));
                weights.push(a * b);
            }
        }
        debug_assert!(check_points(&points).is_ok(), "products of finite numbers");
        Self { points: BezierPatch::from_parts(n_rows, n_cols, points), weights }
    }
}

/// Checks that a split parameter lies in [0, 1].
fn check_unit(t: f64) -> Result<(), Error> {
    if (0.0..=1.0).contains(&t) {
        Ok(())
    } else {
        Err(Error::InvalidArgument { name: "t", value: t, expected: "a number in [0, 1]" })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation() {
        let rows = vec![vec![0.0, 1.0], vec![2.0, 3.0]];
        assert_eq!(
            RationalBezierPatch::try_new(rows.clone(), vec![vec![1.0, 1.0]]),
            Err(Error::WeightCount { expected: 2, found: 1 })
        );
        assert_eq!(
            RationalBezierPatch::try_new(rows.clone(), vec![vec![1.0, 1.0], vec![1.0]]),
            Err(Error::RaggedGrid { row: 1, expected: 2, found: 1 })
        );
        assert_eq!(
            RationalBezierPatch::try_new(rows.clone(), vec![vec![1.0, 1.0], vec![1.0, 0.0]]),
            Err(Error::InvalidWeight { index: 3, value: 0.0 })
        );
        let p = RationalBezierPatch::new(rows, vec![vec![1.0, 2.0], vec![3.0, 4.0]]);
        assert!(p.split_u(-0.1).is_err());
    }

    #[test]
    fn unit_weights_are_polynomial() {
        let poly = BezierPatch::try_from_fn(2, 3, |j, k| {
            DVec3::new(j as f64, k as f64, (j * k) as f64 * 0.3)
        })
        .unwrap();
        let rat = RationalBezierPatch::from_polynomial(&poly);
        for (u, v) in [(0.1, 0.2), (0.5, 0.9), (1.0, 0.0)] {
            assert!((rat.eval(u, v) - poly.eval(u, v)).length() < 1e-14);
            for (a, b) in [(1, 0), (0, 1), (1, 1), (2, 1)] {
                let d = rat.eval_deriv(u, v, a, b) - poly.eval_deriv(u, v, a, b);
                assert!(d.length() < 1e-11, "({a}, {b}) at ({u}, {v}): {d}");
            }
        }
    }
}
