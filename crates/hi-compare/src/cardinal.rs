// SPDX-License-Identifier: MIT
//! Interpolating piecewise cubic Hermite splines (Hardy 2005, §2.6 Catmull-Rom, §2.7
//! Bessel-Overhauser, §2.8 tension-continuity-bias): each piece is the cubic Bézier curve
//! xᵢ, xᵢ + hᵢ·D⁺ᵢ/3, xᵢ₊₁ − hᵢ·D⁻ᵢ₊₁/3, xᵢ₊₁ (hᵢ = tᵢ₊₁ − tᵢ), so the curve passes through every
//! point, and the families differ only in the tangents D⁻ᵢ (arriving) and D⁺ᵢ (leaving).
//!
//! With the secant velocities vᵢ₊½ = (xᵢ₊₁ − xᵢ)/(tᵢ₊₁ − tᵢ):
//!
//! * Catmull-Rom (Catmull & Rom 1974, "A class of local interpolating splines"), on uniform
//!   tᵢ = i/s: D = (x_{i+1} − x_{i−1})/2 per unit segment (eq. 2.8), C¹;
//! * Bessel-Overhauser (§2.7; Overhauser 1968; the "Bessel tangent", the slope at the middle
//!   point of the parabola through three points), on chord-length tᵢ:
//!   D = (hᵢ·vᵢ₋½ + hᵢ₋₁·vᵢ₊½)/(hᵢ₋₁ + hᵢ), C¹;
//! * Kochanek–Bartels (Kochanek & Bartels 1984, "Interpolating splines with local tension,
//!   continuity, and bias control"), on uniform tᵢ, with tension T, continuity C and bias B
//!   per point: D⁻ᵢ = (1−T)(1−C)(1+B)/2·vᵢ₋½ + (1−T)(1+C)(1−B)/2·vᵢ₊½ and
//!   D⁺ᵢ = (1−T)(1+C)(1+B)/2·vᵢ₋½ + (1−T)(1−C)(1−B)/2·vᵢ₊½; T = C = B = 0 is Catmull-Rom,
//!   and C ≠ 0 makes a corner (D⁻ ≠ D⁺).
//!
//! # Parameters and ends
//!
//! The curve parameter t ∈ [0, 1] *is* the node parameter: tᵢ = i/s for Catmull-Rom and TCB
//! (s segments: n − 1 open, n closed, so each piece covers an equal share of [0, 1] and
//! [`HermiteSpline::to_bezier`] has the same parameter), chord-length fractions for
//! Bessel-Overhauser (then each Bézier segment is its piece reparametrised linearly, see
//! [`HermiteSpline::breakpoints`]). Tangents are derivatives with respect to t.
//!
//! A closed curve is 1-periodic: the last piece runs from xₙ₋₁ back to x₀. An open curve needs
//! tangents at its ends, which lack one neighbour; the rule here is a *reflected phantom
//! point*: x₋₁ = 2x₀ − x₁ at t₋₁ = 2t₀ − t₁ (and likewise after the last point), so that
//! v₋½ = v½. For Catmull-Rom and Bessel-Overhauser the end tangent is then the end secant
//! velocity v½, for TCB (1−T)(1+BC)·v½. (The thesis's §2.6 instead uses the first and last
//! points only to steer the tangents and does not pass through them; to get that curve, drop
//! the two end pieces.)

use hi_bezier::{BezierCurve, PiecewiseBezier};
use hi_curve::Error as CurveError;

use super::bspline::point_spread;
use crate::check::check_points;
use crate::{ControlPoint, Error};
use hi_curve::ParamCurve;

/// Whether a curve through n points is open (from the first to the last point) or closed (a
/// loop, 1-periodic in t).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Closure {
    /// From x₀ at t = 0 to xₙ₋₁ at t = 1: n − 1 pieces.
    Open,
    /// A loop through x₀, …, xₙ₋₁ and back to x₀: n pieces, 1-periodic.
    Closed,
}

/// Chord-length parameters in [0, 1]: t₀ = 0 and tᵢ the length of the polygon up to xᵢ divided
/// by its total length — which ends at xₙ₋₁ (so tₙ₋₁ = 1) when open and includes the closing
/// chord from xₙ₋₁ to x₀ when closed (§2.11, Epstein's heuristic tᵢ − tᵢ₋₁ = |xᵢ − xᵢ₋₁|).
///
/// # Errors
///
/// [`hi_curve::Error::Empty`], [`hi_curve::Error::NonFinitePoint`], [`Error::TooFewPoints`] for fewer than 2 points,
/// [`hi_curve::Error::CoincidentPoints`] when two consecutive points coincide (cyclically if closed).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_compare::cardinal::{Closure, chord_length_parameters};
///
/// let pts = [DVec2::ZERO, DVec2::X, DVec2::new(1.0, 2.0)];
/// assert_eq!(chord_length_parameters(&pts, Closure::Open).unwrap(), vec![0.0, 1.0 / 3.0, 1.0]);
/// // Closed, the chord back to the start (length √5) counts too.
/// let closed = chord_length_parameters(&pts, Closure::Closed).unwrap();
/// assert!((closed[1] - 1.0 / (3.0 + 5f64.sqrt())).abs() < 1e-15);
/// ```
pub fn chord_length_parameters<P: ControlPoint>(
    points: &[P],
    closure: Closure,
) -> Result<Vec<f64>, Error> {
    check_points(points)?;
    let n = points.len();
    if n < 2 {
        return Err(Error::TooFewPoints { what: "chord-length parameters", needed: 2, got: n });
    }
    let n_chords = if closure == Closure::Closed { n } else { n - 1 };
    let mut acc = Vec::with_capacity(n);
    let mut len = 0.0;
    acc.push(0.0);
    for first in 0..n_chords {
        let second = (first + 1) % n;
        let chord = (points[second] - points[first]).norm();
        if chord == 0.0 {
            return Err(Error::Curve(CurveError::CoincidentPoints { first, second }));
        }
        len += chord;
        if second != 0 {
            acc.push(len);
        }
    }
    let mut res: Vec<f64> = acc.into_iter().map(|s| s / len).collect();
    if closure == Closure::Open {
        res[n - 1] = 1.0;
    }
    Ok(res)
}

/// Tension, continuity and bias of a Kochanek–Bartels key (§2.8). All zero is Catmull-Rom;
/// the usual range of each is [−1, 1].
///
/// * tension T: 1 stops the curve at the point (zero tangent), −1 doubles the tangent;
/// * continuity C: 0 is C¹, other values make a corner (the arriving and leaving tangents
///   differ);
/// * bias B: −1 takes the direction of the next chord, 1 that of the previous one.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Tcb {
    /// Tension T.
    pub tension: f64,
    /// Continuity C.
    pub continuity: f64,
    /// Bias B.
    pub bias: f64,
}

impl Tcb {
    /// T = C = B = 0: Catmull-Rom.
    pub const CATMULL_ROM: Tcb = Tcb { tension: 0.0, continuity: 0.0, bias: 0.0 };

    /// The key with these tension, continuity and bias.
    #[must_use]
    pub const fn new(tension: f64, continuity: f64, bias: f64) -> Self {
        Self { tension, continuity, bias }
    }

    fn check(&self) -> Result<(), Error> {
        for (name, value) in
            [("tension", self.tension), ("continuity", self.continuity), ("bias", self.bias)]
        {
            if !value.is_finite() {
                return Err(Error::Curve(CurveError::NonFiniteParameter { name, value }));
            }
        }
        Ok(())
    }

    /// The arriving and leaving tangents from the neighbouring secant velocities (§2.8).
    fn tangents<P: ControlPoint>(&self, v_prev: P, v_next: P) -> (P, P) {
        let Tcb { tension: t, continuity: c, bias: b } = *self;
        let arriving = v_prev * ((1.0 - t) * (1.0 - c) * (1.0 + b) / 2.0)
            + v_next * ((1.0 - t) * (1.0 + c) * (1.0 - b) / 2.0);
        let leaving = v_prev * ((1.0 - t) * (1.0 + c) * (1.0 + b) / 2.0)
            + v_next * ((1.0 - t) * (1.0 - c) * (1.0 - b) / 2.0);
        (arriving, leaving)
    }
}

/// A piecewise cubic Hermite curve through n points with given arriving and leaving tangents
/// at each point: the common form of Catmull-Rom, Bessel-Overhauser and Kochanek–Bartels
/// (TCB) splines, built by their constructors. See the [module documentation](self).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ParamCurve;
/// use hi_compare::cardinal::{Closure, HermiteSpline};
///
/// let pts = vec![DVec2::ZERO, DVec2::new(1.0, 1.0), DVec2::new(3.0, 1.0), DVec2::new(4.0, 0.0)];
/// let curve = HermiteSpline::catmull_rom(pts.clone(), Closure::Open).unwrap();
/// // Passes through x₁ at t = 1/3 with tangent (x₂ − x₀)/2 per unit segment (eq. 2.8).
/// assert!((curve.eval(1.0 / 3.0) - pts[1]).length() < 1e-15);
/// let per_segment = curve.eval_deriv(1.0 / 3.0, 1) / 3.0;
/// assert!((per_segment - (pts[2] - pts[0]) / 2.0).length() < 1e-14);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HermiteSpline<P> {
    // Invariant: points finite, at least 2 (open) or 3 (closed); knots strictly increasing,
    // one per point plus (closed) knots[n] = knots[0] + 1; open knots[0] = 0, knots[n−1] = 1.
    points: Vec<P>,
    knots: Vec<f64>,
    // dX/dt arriving at and leaving each point.
    arriving: Vec<P>,
    leaving: Vec<P>,
    closed: bool,
}

impl<P: ControlPoint> HermiteSpline<P> {
    /// The Catmull-Rom spline (§2.6): uniform parameters, tangents (x_{i+1} − x_{i−1})/2 per
    /// unit segment, reflected phantom end points when open.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`], [`hi_curve::Error::NonFinitePoint`], [`Error::TooFewPoints`] for fewer than 2
    /// points (open) or 3 (closed), and [`Error::Overflow`] if coordinates are so large that a
    /// Bézier control point overflows.
    pub fn catmull_rom(points: Vec<P>, closure: Closure) -> Result<Self, Error> {
        Self::kochanek_bartels(points, closure, Tcb::CATMULL_ROM)
    }

    /// The Bessel-Overhauser spline (§2.7) on chord-length parameters.
    ///
    /// # Errors
    ///
    /// As [`HermiteSpline::catmull_rom`], and [`hi_curve::Error::CoincidentPoints`] when two consecutive
    /// points coincide.
    pub fn bessel_overhauser(points: Vec<P>, closure: Closure) -> Result<Self, Error> {
        check_points(&points)?;
        let params = chord_length_parameters(&points, closure)?;
        Self::bessel_overhauser_with_params(points, params, closure)
    }

    /// The Bessel-Overhauser spline (§2.7) on the given node parameters: strictly increasing;
    /// when open in any units (mapped affinely so that the first is t = 0 and the last t = 1),
    /// when closed in [0, 1) (the curve passes through xᵢ at t = tᵢ, period 1).
    ///
    /// # Errors
    ///
    /// As [`HermiteSpline::catmull_rom`], and [`hi_curve::Error::ParameterCountMismatch`],
    /// [`hi_curve::Error::NonFiniteParameter`], [`hi_curve::Error::ParametersNotDistinct`],
    /// [`Error::ParametersNotIncreasing`] or (closed) [`hi_curve::Error::NodeOutOfRange`] for bad
    /// parameters.
    pub fn bessel_overhauser_with_params(
        points: Vec<P>,
        params: Vec<f64>,
        closure: Closure,
    ) -> Result<Self, Error> {
        let knots = checked_knots(&points, &params, closure)?;
        Self::build(points, knots, closure, |_, v_prev, v_next, h_prev, h_next| {
            let d = (v_prev * h_next + v_next * h_prev) * (1.0 / (h_prev + h_next));
            (d, d)
        })
    }

    /// The Kochanek–Bartels (TCB) spline (§2.8) with the same tension, continuity and bias at
    /// every point, on uniform parameters.
    ///
    /// # Errors
    ///
    /// As [`HermiteSpline::catmull_rom`], and [`hi_curve::Error::NonFiniteParameter`] for a non-finite
    /// T, C or B.
    pub fn kochanek_bartels(points: Vec<P>, closure: Closure, tcb: Tcb) -> Result<Self, Error> {
        let n = points.len();
        Self::kochanek_bartels_per_point(points, closure, &vec![tcb; n])
    }

    /// The Kochanek–Bartels (TCB) spline (§2.8) with tension, continuity and bias given per
    /// point, on uniform parameters.
    ///
    /// # Errors
    ///
    /// As [`HermiteSpline::kochanek_bartels`], and [`hi_curve::Error::ParameterCountMismatch`] unless
    /// there is one key per point.
    pub fn kochanek_bartels_per_point(
        points: Vec<P>,
        closure: Closure,
        tcb: &[Tcb],
    ) -> Result<Self, Error> {
        check_points(&points)?;
        let n = points.len();
        if tcb.len() != n {
            return Err(Error::Curve(CurveError::ParameterCountMismatch {
                points: n,
                params: tcb.len(),
            }));
        }
        tcb.iter().try_for_each(Tcb::check)?;
        let n_segments = if closure == Closure::Closed { n } else { n.saturating_sub(1) };
        let params = (0..n).map(|i| i as f64 / n_segments.max(1) as f64).collect::<Vec<_>>();
        let knots = checked_knots(&points, &params, closure)?;
        Self::build(points, knots, closure, |i, v_prev, v_next, _, _| {
            tcb[i].tangents(v_prev, v_next)
        })
    }

    /// Assembles the spline, the tangents at point i given by
    /// `rule(i, v_prev, v_next, h_prev, h_next)` from the secant velocities and parameter steps
    /// on either side (reflected at the ends of an open curve).
    fn build(
        points: Vec<P>,
        knots: Vec<f64>,
        closure: Closure,
        rule: impl Fn(usize, P, P, f64, f64) -> (P, P),
    ) -> Result<Self, Error> {
        let n = points.len();
        let closed = closure == Closure::Closed;
        let n_segments = if closed { n } else { n - 1 };
        let h: Vec<f64> = (0..n_segments).map(|i| knots[i + 1] - knots[i]).collect();
        let v: Vec<P> =
            (0..n_segments).map(|i| (points[(i + 1) % n] - points[i]) * (1.0 / h[i])).collect();
        let (mut arriving, mut leaving) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for i in 0..n {
            let (prev, next) = if closed {
                ((i + n - 1) % n, i)
            } else if i == 0 {
                (0, 0)
            } else if i == n - 1 {
                (n - 2, n - 2)
            } else {
                (i - 1, i)
            };
            let (a, l) = rule(i, v[prev], v[next], h[prev], h[next]);
            arriving.push(a);
            leaving.push(l);
        }
        let res = Self { points, knots, arriving, leaving, closed };
        // Invariant: every Bézier control point is finite (huge coordinates could overflow).
        if (0..n_segments).any(|i| res.segment(i).iter().any(|p| !p.is_finite())) {
            return Err(Error::Overflow { what: "tangent of the spline" });
        }
        Ok(res)
    }

    /// The interpolated points.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// True for a closed curve.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The derivatives dX/dt with which the curve arrives at each point (D⁻ᵢ).
    #[must_use]
    pub fn arriving_tangents(&self) -> &[P] {
        &self.arriving
    }

    /// The derivatives dX/dt with which the curve leaves each point (D⁺ᵢ).
    #[must_use]
    pub fn leaving_tangents(&self) -> &[P] {
        &self.leaving
    }

    /// The parameters t₀ < t₁ < … of the ends of the pieces (one more than the number of
    /// pieces; the curve passes through xᵢ at tᵢ, and a closed curve returns to x₀ at
    /// t₀ + 1). Segment i of [`HermiteSpline::to_bezier`] at its own parameter v ∈ [0, 1] is
    /// this curve at t = tᵢ + v·(tᵢ₊₁ − tᵢ).
    #[must_use]
    pub fn breakpoints(&self) -> &[f64] {
        &self.knots
    }

    fn n_segments(&self) -> usize {
        self.knots.len() - 1
    }

    /// The cubic Bézier control points of piece i.
    fn segment(&self, i: usize) -> [P; 4] {
        let n = self.points.len();
        let h = self.knots[i + 1] - self.knots[i];
        let (a, b) = (self.points[i], self.points[(i + 1) % n]);
        [a, a + self.leaving[i] * (h / 3.0), b - self.arriving[(i + 1) % n] * (h / 3.0), b]
    }

    /// The piece holding t and the local parameter v ∈ [0, 1] (outside for extrapolation).
    fn locate(&self, t: f64) -> (usize, f64) {
        let t0 = self.knots[0];
        let t = if self.closed { t0 + (t - t0).rem_euclid(1.0) } else { t };
        let s = self.n_segments();
        let i = self.knots.partition_point(|&k| k <= t).saturating_sub(1).min(s - 1);
        (i, (t - self.knots[i]) / (self.knots[i + 1] - self.knots[i]))
    }

    /// X(t).
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        self.eval_deriv(t, 0)
    }

    /// X⁽ʳ⁾(t) of any order (exact; zero above 3 inside a piece; at a join, the piece on the
    /// right).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        let (i, v) = self.locate(t);
        let h = self.knots[i + 1] - self.knots[i];
        cubic_deriv(self.segment(i), v, order) * h.powi(-(order as i32))
    }

    /// The same curve as a chain of cubic Bézier curves, one per piece (see
    /// [`HermiteSpline::breakpoints`] for their parameters).
    ///
    /// # Panics
    ///
    /// Does not panic: the constructors check that every control point is finite.
    #[must_use]
    pub fn to_bezier(&self) -> PiecewiseBezier<P> {
        let segments = (0..self.n_segments())
            .map(|i| {
                BezierCurve::try_new(self.segment(i).to_vec())
                    .expect("finite points and tangents give finite control points")
            })
            .collect();
        PiecewiseBezier::try_new(segments).expect("at least one piece")
    }
}

/// The r-th derivative of a cubic Bézier curve with respect to its own parameter v.
fn cubic_deriv<P: ControlPoint>(mut b: [P; 4], v: f64, order: usize) -> P {
    if order > 3 {
        return P::ZERO;
    }
    for r in 0..order {
        for k in 0..3 - r {
            b[k] = (b[k + 1] - b[k]) * (3 - r) as f64;
        }
    }
    let q = 3 - order;
    for level in 1..=q {
        for k in 0..=q - level {
            b[k] = b[k] * (1.0 - v) + b[k + 1] * v;
        }
    }
    b[0]
}

/// Checks points and node parameters and returns the knots of the pieces: open, normalised to
/// [0, 1]; closed, the parameters plus t₀ + 1.
fn checked_knots<P: ControlPoint>(
    points: &[P],
    params: &[f64],
    closure: Closure,
) -> Result<Vec<f64>, Error> {
    check_points(points)?;
    let n = points.len();
    let needed = if closure == Closure::Closed { 3 } else { 2 };
    if n < needed {
        let what = if needed == 3 { "a closed spline" } else { "an open spline" };
        return Err(Error::TooFewPoints { what, needed, got: n });
    }
    super::lagrange::check_increasing(n, params)?;
    match closure {
        Closure::Open => {
            let (a, b) = (params[0], params[n - 1]);
            let mut knots: Vec<f64> = params.iter().map(|&u| (u - a) / (b - a)).collect();
            knots[n - 1] = 1.0;
            Ok(knots)
        }
        Closure::Closed => {
            if let Some(index) = params.iter().position(|u| !(0.0..1.0).contains(u)) {
                return Err(Error::Curve(CurveError::NodeOutOfRange {
                    index,
                    value: params[index],
                }));
            }
            let mut knots = params.to_vec();
            knots.push(params[0] + 1.0);
            if knots[n] <= knots[n - 1] {
                return Err(Error::Curve(CurveError::ParametersNotDistinct {
                    first: n - 1,
                    second: 0,
                }));
            }
            Ok(knots)
        }
    }
}

impl<P: ControlPoint> ParamCurve<P> for HermiteSpline<P> {
    fn eval(&self, t: f64) -> P {
        HermiteSpline::eval(self, t)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> P {
        HermiteSpline::eval_deriv(self, t, order)
    }

    fn scale(&self) -> f64 {
        point_spread(&self.points)
    }

    fn is_periodic(&self) -> bool {
        self.closed
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn cubic_deriv_of_a_known_cubic() {
        // Control points of v³ (degree elevated): 0, 0, 0, 1.
        let b = [0.0, 0.0, 0.0, 1.0];
        for v in [0.0, 0.3, 1.0] {
            assert!((cubic_deriv(b, v, 0) - v * v * v).abs() < 1e-15);
            assert!((cubic_deriv(b, v, 1) - 3.0 * v * v).abs() < 1e-15);
            assert!((cubic_deriv(b, v, 2) - 6.0 * v).abs() < 1e-15);
            assert!((cubic_deriv(b, v, 3) - 6.0).abs() < 1e-15);
            assert_eq!(cubic_deriv(b, v, 4), 0.0);
        }
    }

    #[test]
    fn open_end_tangent_is_the_end_secant() {
        let pts = vec![DVec2::ZERO, DVec2::new(1.0, 2.0), DVec2::new(4.0, 2.0)];
        let cr = HermiteSpline::catmull_rom(pts.clone(), Closure::Open).unwrap();
        assert!((cr.eval_deriv(0.0, 1) / 2.0 - pts[1]).length() < 1e-15);
        assert!((cr.eval_deriv(1.0, 1) / 2.0 - (pts[2] - pts[1])).length() < 1e-14);
        let bo = HermiteSpline::bessel_overhauser(pts.clone(), Closure::Open).unwrap();
        let len = 5f64.sqrt() + 3.0;
        assert!((bo.eval_deriv(0.0, 1) - pts[1] * len / 5f64.sqrt()).length() < 1e-13);
    }

    #[test]
    fn bad_input_is_rejected() {
        let pts = vec![DVec2::ZERO, DVec2::X];
        assert!(HermiteSpline::catmull_rom(pts.clone(), Closure::Closed).is_err());
        assert!(HermiteSpline::catmull_rom(vec![DVec2::ZERO], Closure::Open).is_err());
        let dup = vec![DVec2::ZERO, DVec2::X, DVec2::X];
        assert!(matches!(
            HermiteSpline::bessel_overhauser(dup, Closure::Open),
            Err(Error::Curve(CurveError::CoincidentPoints { first: 1, second: 2 }))
        ));
        let tcb = Tcb::new(f64::NAN, 0.0, 0.0);
        assert!(HermiteSpline::kochanek_bartels(pts.clone(), Closure::Open, tcb).is_err());
        assert!(
            HermiteSpline::kochanek_bartels_per_point(
                pts.clone(),
                Closure::Open,
                &[Tcb::default()]
            )
            .is_err()
        );
        let tri = vec![DVec2::ZERO, DVec2::X, DVec2::Y];
        assert!(matches!(
            HermiteSpline::bessel_overhauser_with_params(tri, vec![0.0, 0.5, 1.0], Closure::Closed),
            Err(Error::Curve(CurveError::NodeOutOfRange { index: 2, .. }))
        ));
    }
}
