// SPDX-License-Identifier: MIT
//! Conic sections as rational quadratic Bézier curves (Hardy 2005, §2.5 "Bézier Curves: Conic
//! Sections", figure 2.8): exact circular and elliptic arcs, full circles as several arcs, and
//! the classification of a conic by its weight.

use std::f64::consts::PI;

use glam::DVec2;

use crate::error::{check_finite, check_points};
use crate::{ControlPoint, Error, RationalBezierCurve};

/// The type of the conic a rational quadratic Bézier curve traces, fixed by the invariant
/// k = w₁²/(w₀w₂) (the squared middle weight of the standard form w₀ = w₂ = 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum ConicType {
    /// k < 1: an arc of an ellipse (a circle for the right control points).
    Ellipse,
    /// k = 1: an arc of a parabola (the polynomial quadratic).
    Parabola,
    /// k > 1: an arc of one branch of a hyperbola.
    Hyperbola,
}

impl<P: ControlPoint> RationalBezierCurve<P> {
    /// The conic arc from `p0` to `p2` with tangents towards `p1` at both ends: the rational
    /// quadratic with weights (1, w, 1). It is an ellipse for w < 1, a parabola for w = 1 and a
    /// hyperbola for w > 1 ([`RationalBezierCurve::conic_type`]).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinitePoint`] for a non-finite point, [`Error::InvalidWeight`] (index 1)
    /// unless w is positive and finite.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_bezier::{ConicType, RationalBezierCurve};
    ///
    /// let arc = |w| RationalBezierCurve::conic(DVec2::X, DVec2::ONE, DVec2::Y, w).unwrap();
    /// assert_eq!(arc(0.5).conic_type(), Some(ConicType::Ellipse));
    /// assert_eq!(arc(1.0).conic_type(), Some(ConicType::Parabola));
    /// assert_eq!(arc(2.0).conic_type(), Some(ConicType::Hyperbola));
    /// // w = cos 45° gives the quarter of the unit circle.
    /// let quarter = arc(std::f64::consts::FRAC_1_SQRT_2);
    /// assert!((quarter.eval(0.3).length() - 1.0).abs() < 1e-15);
    /// ```
    pub fn conic(p0: P, p1: P, p2: P, w: f64) -> Result<Self, Error> {
        Self::try_new(vec![p0, p1, p2], vec![1.0, w, 1.0])
    }

    /// The conic type of a rational quadratic (`None` for other degrees), from
    /// k = w₁²/(w₀w₂) compared with 1 exactly in floating point.
    #[must_use]
    pub fn conic_type(&self) -> Option<ConicType> {
        let k = self.conic_shape_factor()?.powi(2);
        Some(if k < 1.0 {
            ConicType::Ellipse
        } else if k > 1.0 {
            ConicType::Hyperbola
        } else {
            ConicType::Parabola
        })
    }

    /// The middle weight of the standard form, w₁/√(w₀w₂), of a rational quadratic (`None`
    /// for other degrees); for a circular arc of angle θ it is cos(θ/2).
    #[must_use]
    pub fn conic_shape_factor(&self) -> Option<f64> {
        match self.weights() {
            &[w0, w1, w2] => Some(w1 / (w0 * w2).sqrt()),
            _ => None,
        }
    }

    /// The arc θ ↦ c + cos θ·a + sin θ·b for θ from `start` to `start + sweep`, |sweep| < π, as
    /// one exact rational quadratic: an arc of the ellipse with conjugate semi-axes a and b (a
    /// circle of radius r for orthogonal a, b of length r), in any dimension.
    ///
    /// With the half angle φ = sweep/2 and the middle angle m = start + φ, the control points
    /// are the end points and c + (cos m·a + sin m·b)/cos φ (where the end tangents meet), with
    /// weights (1, cos φ, 1).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinitePoint`] for a non-finite point (index 0, 1, 2 for `center`, `a`,
    /// `b`), [`Error::InvalidArgument`] for a non-finite `start` or unless |sweep| < π.
    pub fn ellipse_arc(center: P, a: P, b: P, start: f64, sweep: f64) -> Result<Self, Error> {
        check_points(&[center, a, b])?;
        check_finite("start", start)?;
        if sweep.is_nan() || sweep.abs() >= PI {
            return Err(Error::InvalidArgument {
                name: "sweep",
                value: sweep,
                expected: "an angle of magnitude less than π (split larger arcs)",
            });
        }
        let at = |theta: f64| center + a * theta.cos() + b * theta.sin();
        let half = 0.5 * sweep;
        let mid = start + half;
        let w = half.cos();
        let apex = center + (a * mid.cos() + b * mid.sin()) * (1.0 / w);
        Self::try_new(vec![at(start), apex, at(start + sweep)], vec![1.0, w, 1.0])
    }

    /// The whole ellipse θ ↦ c + cos θ·a + sin θ·b, θ ∈ [0, 2π], as `n_arcs` ≥ 3 consecutive
    /// exact arcs of equal angle 2π/`n_arcs` ([`RationalBezierCurve::ellipse_arc`]).
    ///
    /// # Errors
    ///
    /// [`Error::TooFewPoints`] (of arcs) for `n_arcs` < 3, and the errors of
    /// [`RationalBezierCurve::ellipse_arc`].
    pub fn ellipse(center: P, a: P, b: P, n_arcs: usize) -> Result<Vec<Self>, Error> {
        if n_arcs < 3 {
            return Err(Error::TooFewPoints { needed: 3, found: n_arcs });
        }
        let sweep = 2.0 * PI / n_arcs as f64;
        (0..n_arcs).map(|k| Self::ellipse_arc(center, a, b, k as f64 * sweep, sweep)).collect()
    }
}

impl RationalBezierCurve<DVec2> {
    /// The exact circular arc of `radius` about `center` from angle `start` through `sweep`
    /// (|sweep| < π; negative sweeps run clockwise): a rational quadratic with middle weight
    /// cos(sweep/2).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidArgument`] unless `radius` is positive and finite and |sweep| < π, and
    /// the errors of [`RationalBezierCurve::ellipse_arc`].
    ///
    /// # Examples
    ///
    /// ```
    /// use std::f64::consts::PI;
    ///
    /// use glam::DVec2;
    /// use hi_bezier::RationalBezierCurve;
    ///
    /// let arc = RationalBezierCurve::circle_arc(DVec2::ZERO, 2.0, 0.0, 2.0 * PI / 3.0).unwrap();
    /// assert!((arc.eval(0.5) - 2.0 * DVec2::from_angle(PI / 3.0)).length() < 1e-15);
    /// assert!((arc.weights()[1] - 0.5).abs() < 1e-15); // cos 60°
    /// ```
    pub fn circle_arc(center: DVec2, radius: f64, start: f64, sweep: f64) -> Result<Self, Error> {
        check_radius(radius)?;
        Self::ellipse_arc(center, DVec2::X * radius, DVec2::Y * radius, start, sweep)
    }

    /// The full circle as `n_arcs` ≥ 3 exact arcs, counter-clockwise from angle 0.
    ///
    /// # Errors
    ///
    /// [`Error::TooFewPoints`] for `n_arcs` < 3, [`Error::InvalidArgument`] unless `radius` is
    /// positive and finite, [`Error::NonFinitePoint`] for a non-finite centre.
    pub fn circle(center: DVec2, radius: f64, n_arcs: usize) -> Result<Vec<Self>, Error> {
        check_radius(radius)?;
        Self::ellipse(center, DVec2::X * radius, DVec2::Y * radius, n_arcs)
    }
}

/// Checks that a radius is positive and finite.
fn check_radius(radius: f64) -> Result<(), Error> {
    if radius.is_finite() && radius > 0.0 {
        Ok(())
    } else {
        Err(Error::InvalidArgument {
            name: "radius",
            value: radius,
            expected: "a positive finite number",
        })
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;

    #[test]
    fn arc_validation() {
        let c = DVec2::ZERO;
        assert!(matches!(
            RationalBezierCurve::circle_arc(c, 1.0, 0.0, PI),
            Err(Error::InvalidArgument { name: "sweep", .. })
        ));
        assert!(matches!(
            RationalBezierCurve::circle_arc(c, -1.0, 0.0, 1.0),
            Err(Error::InvalidArgument { name: "radius", .. })
        ));
        assert!(matches!(
            RationalBezierCurve::circle_arc(c, 1.0, f64::NAN, 1.0),
            Err(Error::InvalidArgument { name: "start", .. })
        ));
        assert_eq!(
            RationalBezierCurve::circle(c, 1.0, 2),
            Err(Error::TooFewPoints { needed: 3, found: 2 })
        );
        assert!(RationalBezierCurve::conic(0.0, 1.0, 2.0, 0.0).is_err());
        assert_eq!(RationalBezierCurve::new(vec![0.0, 1.0], vec![1.0, 1.0]).conic_type(), None);
    }

    #[test]
    fn space_circle() {
        // A circle of radius 2 in the plane x + y + z = 0 about (1, 1, 1).
        let center = DVec3::ONE;
        let a = DVec3::new(1.0, -1.0, 0.0).normalize() * 2.0;
        let b = DVec3::new(1.0, 1.0, -2.0).normalize() * 2.0;
        for arc in RationalBezierCurve::ellipse(center, a, b, 5).unwrap() {
            for i in 0..=16 {
                let p = arc.eval(i as f64 / 16.0);
                assert!(((p - center).length() - 2.0).abs() < 1e-14);
                assert!((p - center).dot(DVec3::ONE).abs() < 1e-14);
            }
        }
    }
}
