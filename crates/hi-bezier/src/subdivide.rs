// SPDX-License-Identifier: MIT
//! Subdivision of Bézier curves (Hardy 2005, Theorem 2.2 and figure 2.7): the two halves of a
//! curve split at t₀ are Bézier curves of the same degree whose control points are the edges of
//! de Casteljau's triangle; subsegments [t₀, t₁] come from the blossom.

use crate::curve::lerp;
use crate::{BezierCurve, ControlPoint, ParamRange};

impl<P: ControlPoint> BezierCurve<P> {
    /// Splits the curve at t₀ (Theorem 2.2): returns q₁(t) = q(t₀·t) and
    /// q₂(t) = q(t₀ + (1 − t₀)·t), both of degree n, with control points p⁰₀, p¹₀, …, pⁿ₀ and
    /// pⁿ₀, pⁿ⁻¹₁, …, p⁰ₙ of eq. 2.6.
    ///
    /// Any finite t₀ works; outside [0, 1] one of the pieces extends the curve.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_bezier::BezierCurve;
    ///
    /// let c = BezierCurve::new(vec![DVec2::ZERO, DVec2::Y, DVec2::ONE, DVec2::X]);
    /// let (left, right) = c.split(0.3);
    /// assert!((left.eval(0.5) - c.eval(0.15)).length() < 1e-15);
    /// assert!((right.eval(0.5) - c.eval(0.65)).length() < 1e-15);
    /// ```
    #[must_use]
    #[doc(alias = "theorem 2.2")]
    pub fn split(&self, t0: f64) -> (Self, Self) {
        let (left, right) = split_points(self.control_points(), t0);
        (Self::from_vec_unchecked(left), Self::from_vec_unchecked(right))
    }

    /// The piece of the curve over `range` = [t₀, t₁] as a Bézier curve of the same degree,
    /// reparametrised to [0, 1]: r(s) = q(t₀ + (t₁ − t₀)·s). t₀ > t₁ gives the reversed piece.
    ///
    /// The control points are the blossom values Rᵢ = q[t₀, …, t₀ (n − i times), t₁, …, t₁
    /// (i times)], computed by de Casteljau steps with t₁ then t₀, so no division by t₁ or by
    /// t₁ − t₀ is needed.
    #[must_use]
    pub fn subsegment(&self, range: ParamRange) -> Self {
        Self::from_vec_unchecked(subsegment_points(self.control_points(), range.start, range.end))
    }
}

/// The two control polygons of Theorem 2.2 for a split at `t`.
pub(crate) fn split_points<P: ControlPoint>(control: &[P], t: f64) -> (Vec<P>, Vec<P>) {
    let n = control.len();
    let mut work = control.to_vec();
    let mut left = Vec::with_capacity(n);
    let mut right = vec![control[n - 1]; n];
    left.push(work[0]);
    for level in 1..n {
        for i in 0..n - level {
            work[i] = lerp(work[i], work[i + 1], t);
        }
        left.push(work[0]);
        right[n - 1 - level] = work[n - 1 - level];
    }
    (left, right)
}

/// The control polygon of the piece over [t₀, t₁] by blossoming.
pub(crate) fn subsegment_points<P: ControlPoint>(control: &[P], t0: f64, t1: f64) -> Vec<P> {
    let len = control.len();
    let mut out = vec![P::ZERO; len];
    let (mut after_t1, mut work) = (control.to_vec(), vec![P::ZERO; len]);
    subsegment_with(t0, t1, &mut after_t1, &mut work, &mut out);
    out
}

/// The control points of [`subsegment_points`] written into `out` (of the length of
/// `control`, at most `N`), with scratch arrays of `N` points on the stack: no allocation, and
/// cubics (`N = 4`) zero and copy no more than they use.
pub(crate) fn subsegment_on_stack<P: ControlPoint, const N: usize>(
    control: &[P],
    t0: f64,
    t1: f64,
    out: &mut [P],
) {
    let len = control.len();
    let (mut after_t1, mut work) = ([P::ZERO; N], [P::ZERO; N]);
    after_t1[..len].copy_from_slice(control);
    subsegment_with(t0, t1, &mut after_t1[..len], &mut work[..len], &mut out[..len]);
}

/// Blossoming into `out`: point i is the control polygon after i de Casteljau steps with t₁
/// (kept in `after_t1`, which starts as the control polygon), then n − i steps with t₀ (in
/// `work`). All three slices have the length of the control polygon.
fn subsegment_with<P: ControlPoint>(
    t0: f64,
    t1: f64,
    after_t1: &mut [P],
    work: &mut [P],
    out: &mut [P],
) {
    let n = after_t1.len() - 1;
    for (i, slot) in out.iter_mut().enumerate() {
        let len = n + 1 - i;
        work[..len].copy_from_slice(&after_t1[..len]);
        for level in 1..len {
            for j in 0..len - level {
                work[j] = lerp(work[j], work[j + 1], t0);
            }
        }
        *slot = work[0];
        if i < n {
            for j in 0..len - 1 {
                after_t1[j] = lerp(after_t1[j], after_t1[j + 1], t1);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_of_a_line_is_two_lines() {
        let c = BezierCurve::new(vec![0.0, 4.0]);
        let (a, b) = c.split(0.25);
        assert_eq!(a.control_points(), &[0.0, 1.0]);
        assert_eq!(b.control_points(), &[1.0, 4.0]);
        let (a, b) = BezierCurve::new(vec![7.0]).split(0.5);
        assert_eq!((a.degree(), b.degree()), (0, 0));
    }

    #[test]
    fn subsegment_ends_and_reversal() {
        let c = BezierCurve::new(vec![0.0, 3.0, -1.0, 2.0, 5.0]);
        let s = c.subsegment(ParamRange::new(0.2, 0.9));
        assert!((s.control_points()[0] - c.eval(0.2)).abs() < 1e-14);
        assert!((s.control_points()[4] - c.eval(0.9)).abs() < 1e-14);
        let r = c.subsegment(ParamRange::new(0.9, 0.2));
        assert!((r.eval(0.3) - s.eval(0.7)).abs() < 1e-14);
        let whole = c.subsegment(ParamRange::new(0.0, 1.0));
        for (p, q) in whole.control_points().iter().zip(c.control_points()) {
            assert!((p - q).abs() < 1e-15);
        }
    }
}
