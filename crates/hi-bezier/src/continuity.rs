// SPDX-License-Identifier: MIT
//! Continuity at the joins of piecewise Bézier curves (Hardy 2005, definitions 2.5 and 2.6,
//! eq. 2.4 and 2.5): position gap (C0), tangent mismatch (C1) and tangent angle (G1).

use crate::{BezierCurve, ControlPoint, PiecewiseBezier};

/// What happens where one segment q ends and the next, r, starts.
///
/// Tangents are the end derivatives of eq. 2.4 in each segment's own parameter,
/// q′(1) = n(Qₙ − Qₙ₋₁) and r′(0) = m(R₁ − R₀); as all segments of a [`PiecewiseBezier`] have
/// the same parameter length, C1 in these is C1 in the global parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Join {
    /// Index of the segment that ends here (the next one starts here; for the closing join of
    /// [`PiecewiseBezier::closing_join`], the last segment).
    pub index: usize,
    /// C0 gap |r(0) − q(1)|.
    pub gap: f64,
    /// C1 mismatch |r′(0) − q′(1)|.
    pub tangent_mismatch: f64,
    /// G1 angle between q′(1) and r′(0), in [0, π]; `None` if either tangent is zero.
    pub angle: Option<f64>,
    /// Speed ratio |q′(1)|/|r′(0)|, the s of §2.5 (1 at a C1 join); `None` if r′(0) = 0.
    pub speed_ratio: Option<f64>,
}

impl Join {
    /// Measures the join of the end of `q` and the start of `r`.
    #[must_use]
    pub fn between<P: ControlPoint>(index: usize, q: &BezierCurve<P>, r: &BezierCurve<P>) -> Self {
        let end_tangent = q.eval_deriv(1.0, 1);
        let start_tangent = r.eval_deriv(0.0, 1);
        let gap = (r.eval(0.0) - q.eval(1.0)).norm();
        let tangent_mismatch = (start_tangent - end_tangent).norm();
        let (a, b) = (end_tangent.norm(), start_tangent.norm());
        let angle = (a > 0.0 && b > 0.0).then(|| {
            // Kahan's formula 2·atan2(|â − b̂|, |â + b̂|): accurate for tiny and near-π angles.
            let (ua, ub) = (end_tangent * (1.0 / a), start_tangent * (1.0 / b));
            2.0 * (ua - ub).norm().atan2((ua + ub).norm())
        });
        let speed_ratio = (b > 0.0).then(|| a / b);
        Self { index, gap, tangent_mismatch, angle, speed_ratio }
    }
}

impl<P: ControlPoint> PiecewiseBezier<P> {
    /// The s − 1 interior joins, in order.
    #[must_use]
    pub fn joins(&self) -> Vec<Join> {
        self.segments()
            .windows(2)
            .enumerate()
            .map(|(i, w)| Join::between(i, &w[0], &w[1]))
            .collect()
    }

    /// The join of the end of the last segment with the start of the first: what a closed
    /// chain has to satisfy as well.
    #[must_use]
    pub fn closing_join(&self) -> Join {
        let s = self.segments();
        Join::between(s.len() - 1, &s[s.len() - 1], &s[0])
    }

    /// True if every interior gap is at most `tolerance`.
    #[must_use]
    pub fn is_c0(&self, tolerance: f64) -> bool {
        self.joins().iter().all(|j| j.gap <= tolerance)
    }

    /// True if every interior gap and tangent mismatch is at most `tolerance`.
    #[must_use]
    pub fn is_c1(&self, tolerance: f64) -> bool {
        self.joins().iter().all(|j| j.gap <= tolerance && j.tangent_mismatch <= tolerance)
    }

    /// True if every interior gap is at most `gap_tolerance` and both tangents at every join are
    /// non-zero and at most `angle_tolerance` (radians) apart (definition 2.6).
    #[must_use]
    pub fn is_g1(&self, gap_tolerance: f64, angle_tolerance: f64) -> bool {
        self.joins()
            .iter()
            .all(|j| j.gap <= gap_tolerance && j.angle.is_some_and(|a| a <= angle_tolerance))
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use glam::DVec2;

    use super::*;

    #[test]
    fn right_angle_join() {
        let q = BezierCurve::new(vec![DVec2::ZERO, DVec2::X]);
        let r = BezierCurve::new(vec![DVec2::X, DVec2::new(1.0, 2.0)]);
        let j = Join::between(0, &q, &r);
        assert_eq!(j.gap, 0.0);
        assert!((j.angle.unwrap() - FRAC_PI_2).abs() < 1e-15);
        assert_eq!(j.speed_ratio, Some(0.5));
        assert!((j.tangent_mismatch - 5f64.sqrt()).abs() < 1e-15);
        let chain = PiecewiseBezier::new(vec![q, r]);
        assert!(chain.is_c0(0.0) && !chain.is_g1(0.0, 1.0));
        let closing = chain.closing_join();
        assert!((closing.gap - 5f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn zero_tangent_has_no_angle() {
        let q = BezierCurve::new(vec![0.0, 1.0, 1.0]);
        let r = BezierCurve::new(vec![1.0, 2.0]);
        let j = Join::between(0, &q, &r);
        assert_eq!(j.angle, None);
        assert_eq!(j.speed_ratio, Some(0.0));
    }
}
