// SPDX-License-Identifier: MIT
//! Cubic B-spline interpolation (Hardy 2005, §2.11, open and "Periodic Interpolation"): the
//! C² cubic spline through n points at parameters t₀ < … < tₙ₋₁, with its knots at those
//! parameters, as a [`BSplineCurve`].
//!
//! # Ends of an open spline
//!
//! An open interpolating cubic has two degrees of freedom left, fixed by an [`EndCondition`]:
//!
//! * [`EndCondition::Coincident`], the thesis's choice (§2.11, eq. 2.9): the first two and the
//!   last two of the control points x₀, …, x_{n+1} coincide, x₀ = x₁ and xₙ = xₙ₊₁. On clamped
//!   knots the end derivative is 3(x₁ − x₀)/(u₄ − u₁), so this is the spline with *zero end
//!   derivatives* (scipy's `CubicSpline(bc_type='clamped')`): the curve stops at its ends,
//!   where its curvature is undefined;
//! * [`EndCondition::Natural`]: zero second derivative at both ends (scipy's `'natural'`);
//! * [`EndCondition::NotAKnot`]: the third derivative is continuous at t₁ and tₙ₋₂ (scipy's
//!   default `'not-a-knot'`).
//!
//! # Method
//!
//! The thesis sets up the tridiagonal system for the control points directly; for non-uniform
//! knots that matrix need not be diagonally dominant (the B-spline centred at a knot can be
//! small there when the neighbouring intervals are very unequal), in its periodic form either.
//! The same spline is found here from the classical tridiagonal system for the derivatives sᵢ
//! at the nodes (de Boor, *A Practical Guide to Splines*, ch. IV),
//!
//! hᵢ·sᵢ₋₁ + 2(hᵢ₋₁ + hᵢ)·sᵢ + hᵢ₋₁·sᵢ₊₁ = 3(hᵢ·δᵢ₋₁ + hᵢ₋₁·δᵢ),  hᵢ = tᵢ₊₁ − tᵢ,
//! δᵢ = (xᵢ₊₁ − xᵢ)/hᵢ,
//!
//! which is strictly diagonally dominant (except for the not-a-knot end rows, whose
//! elimination still leaves positive pivots): O(n) by the Thomas algorithm when open and by
//! Sherman–Morrison on the cyclic system when periodic. Each B-spline control point is then
//! the blossom (polar form) of the cubic at the three inner knots of its basis function, so the
//! result satisfies the thesis's equations (2.10) exactly as its own solve would.
//!
//! # Parameters
//!
//! The curve parameter t is the interpolation parameter: X(tᵢ) = xᵢ ([`Parameters`]:
//! uniform, chord length, or given). Open splines have t₀ = 0 and tₙ₋₁ = 1; periodic ones have
//! tᵢ ∈ [0, 1) and period 1.

use hi_bezier::PiecewiseBezier;
use hi_curve::Error as CurveError;

use super::bspline::BSplineCurve;
use super::cardinal::{Closure, chord_length_parameters};
use super::lagrange::check_increasing;
use crate::check::check_points;
use crate::{ControlPoint, Error};
use hi_curve::ParamCurve;

/// The parameters tᵢ at which an interpolating spline passes through its points.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Parameters {
    /// tᵢ = i/(n − 1) (open) or i/n (periodic).
    Uniform,
    /// Chord-length fractions (§2.11), with the closing chord when periodic; see
    /// [`chord_length_parameters`].
    ChordLength,
    /// These parameters, strictly increasing: for an open spline in any units (mapped
    /// affinely onto [0, 1]), for a periodic one in [0, 1).
    Given(Vec<f64>),
}

/// How an open interpolating cubic spline ends; see the [module documentation](self).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum EndCondition {
    /// Coincident end control points x₀ = x₁, xₙ = xₙ₋₁ (§2.11): zero end derivatives.
    Coincident,
    /// Zero second derivatives at the ends.
    Natural,
    /// Continuous third derivatives at the second and the second-last node.
    NotAKnot,
}

/// A cubic B-spline through given points (§2.11): open with an [`EndCondition`], or
/// periodic (C² everywhere, the seam included).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ParamCurve;
/// use hi_compare::bspline_interp::{InterpolatingSpline, Parameters};
///
/// // The pentagon of docs/peers.md §2b, uniform periodic interpolation (scipy's splprep per=1).
/// let pts = vec![
///     DVec2::new(0.0, 0.0), DVec2::new(3.0, 1.0), DVec2::new(4.0, 4.0),
///     DVec2::new(1.0, 5.0), DVec2::new(-1.0, 2.0),
/// ];
/// let curve = InterpolatingSpline::try_periodic(pts.clone(), Parameters::Uniform).unwrap();
/// assert!((curve.eval(0.4) - pts[2]).length() < 1e-14);
/// assert!((curve.eval(0.1) - DVec2::new(1.465909, 0.125)).length() < 1e-6);
/// assert!((curve.curvature(0.1).unwrap() - 0.245253).abs() < 1e-6);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct InterpolatingSpline<P> {
    // Invariant: spline passes through points[i] at params[i]; params strictly increasing, in
    // [0, 1] (open, first 0 and last 1) or [0, 1) (periodic).
    points: Vec<P>,
    params: Vec<f64>,
    end: Option<EndCondition>,
    spline: BSplineCurve<P>,
}

impl<P: ControlPoint> InterpolatingSpline<P> {
    /// The open interpolating cubic spline (§2.11): X(0) = x₀, X(tᵢ) = xᵢ, X(1) = xₙ₋₁, its
    /// knots clamped at 0 and 1 with the interior knots at the parameters.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`], [`hi_curve::Error::NonFinitePoint`], [`Error::TooFewPoints`] for fewer than 2
    /// points (4 with [`EndCondition::NotAKnot`]), [`hi_curve::Error::CoincidentPoints`] for repeated
    /// consecutive points with chord-length parameters, and [`hi_curve::Error::ParameterCountMismatch`],
    /// [`hi_curve::Error::NonFiniteParameter`], [`hi_curve::Error::ParametersNotDistinct`] or
    /// [`Error::ParametersNotIncreasing`] for bad given parameters; [`Error::Overflow`] if
    /// the coordinates are too large for the solve.
    pub fn try_open(points: Vec<P>, params: Parameters, end: EndCondition) -> Result<Self, Error> {
        check_points(&points)?;
        let n = points.len();
        let needed = if end == EndCondition::NotAKnot { 4 } else { 2 };
        if n < needed {
            let what = if needed == 4 {
                "a not-a-knot interpolating spline"
            } else {
                "an interpolating spline"
            };
            return Err(Error::TooFewPoints { what, needed, got: n });
        }
        let params = match params {
            Parameters::Uniform => (0..n).map(|i| i as f64 / (n - 1) as f64).collect(),
            Parameters::ChordLength => chord_length_parameters(&points, Closure::Open)?,
            Parameters::Given(given) => {
                check_increasing(n, &given)?;
                let (a, b) = (given[0], given[n - 1]);
                let mut res: Vec<f64> = given.iter().map(|&u| (u - a) / (b - a)).collect();
                res[n - 1] = 1.0;
                res
            }
        };
        let slopes = open_slopes(&points, &params, end)?;
        // Clamped knots: t₀ four times, the interior parameters, tₙ₋₁ four times.
        let mut knots = vec![params[0]; 3];
        knots.extend_from_slice(&params);
        knots.extend(std::iter::repeat_n(params[n - 1], 3));
        // Control point j is the blossom at knots j+1..j+3, taken on the widest piece inside
        // its support [u_j, u_{j+4}] (pieces j − 3 … j), where it extrapolates least.
        let width = |k: usize| params[k + 1] - params[k];
        let control = (0..n + 2)
            .map(|j| {
                let (lo, hi) = (j.saturating_sub(3), j.min(n - 2));
                let k = (lo..=hi).fold(lo, |best, k| if width(k) > width(best) { k } else { best });
                let segment = hermite_bezier(&points, &slopes, k, k + 1, width(k));
                blossom(&segment, params[k], params[k + 1], &knots[j + 1..j + 4])
            })
            .collect();
        let spline = BSplineCurve::try_new(3, knots, control)?;
        Ok(Self { points, params, end: Some(end), spline })
    }

    /// The periodic interpolating cubic spline (§2.11, "Periodic Interpolation"): 1-periodic,
    /// C² everywhere, X(tᵢ) = xᵢ.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`], [`hi_curve::Error::NonFinitePoint`], [`Error::TooFewPoints`] for fewer than 3
    /// points, [`hi_curve::Error::CoincidentPoints`] for repeated consecutive points with chord-length
    /// parameters, and [`hi_curve::Error::ParameterCountMismatch`], [`hi_curve::Error::NonFiniteParameter`],
    /// [`hi_curve::Error::ParametersNotDistinct`], [`Error::ParametersNotIncreasing`] or
    /// [`hi_curve::Error::NodeOutOfRange`] for bad given parameters; [`Error::Overflow`] if the
    /// coordinates are too large for the solve.
    pub fn try_periodic(points: Vec<P>, params: Parameters) -> Result<Self, Error> {
        check_points(&points)?;
        let n = points.len();
        if n < 3 {
            return Err(Error::TooFewPoints {
                what: "a periodic interpolating spline",
                needed: 3,
                got: n,
            });
        }
        let params = match params {
            Parameters::Uniform => (0..n).map(|i| i as f64 / n as f64).collect(),
            Parameters::ChordLength => chord_length_parameters(&points, Closure::Closed)?,
            Parameters::Given(given) => {
                check_increasing(n, &given)?;
                if let Some(index) = given.iter().position(|u| !(0.0..1.0).contains(u)) {
                    return Err(Error::Curve(CurveError::NodeOutOfRange {
                        index,
                        value: given[index],
                    }));
                }
                given
            }
        };
        let slopes = periodic_slopes(&points, &params)?;
        let mut breakpoints = params.clone();
        breakpoints.push(params[0] + 1.0);
        // Control point i: the blossom at τᵢ₋₁, τᵢ, τᵢ₊₁ (its basis is centred at τᵢ), taken on
        // the widest piece inside its support [τᵢ₋₂, τᵢ₊₂], where it extrapolates least. The
        // parameters are unrolled periodically: τ_{k+n} = τ_k + 1.
        let tau = |k: isize| {
            let n = n as isize;
            params[k.rem_euclid(n) as usize] + k.div_euclid(n) as f64
        };
        let width = |k: isize| tau(k + 1) - tau(k);
        let control = (0..n as isize)
            .map(|i| {
                let k = (i - 1..=i + 1)
                    .fold(i - 2, |best, k| if width(k) > width(best) { k } else { best });
                let (a, b) =
                    (k.rem_euclid(n as isize) as usize, (k + 1).rem_euclid(n as isize) as usize);
                let segment = hermite_bezier(&points, &slopes, a, b, width(k));
                blossom(&segment, tau(k), tau(k + 1), &[tau(i - 1), tau(i), tau(i + 1)])
            })
            .collect();
        let spline = BSplineCurve::try_new_periodic(3, breakpoints, control)?;
        Ok(Self { points, params, end: None, spline })
    }

    /// The interpolated points.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The parameters tᵢ with X(tᵢ) = xᵢ.
    #[must_use]
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// The end condition of an open spline; `None` when periodic.
    #[must_use]
    pub fn end_condition(&self) -> Option<EndCondition> {
        self.end
    }

    /// The cubic B-spline (§2.11: clamped knots at the parameters, control points x₀ … xₙ₊₁;
    /// periodic: breakpoints at the parameters, n control points).
    #[must_use]
    pub fn spline(&self) -> &BSplineCurve<P> {
        &self.spline
    }

    /// X(t).
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        self.spline.eval(t)
    }

    /// X⁽ʳ⁾(t) of any order (exact; zero above 3 inside a piece).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        self.spline.eval_deriv(t, order)
    }

    /// The parameters of the ends of the pieces, as [`BSplineCurve::breakpoints`]: the tᵢ
    /// (with t₀ + 1 last when periodic).
    #[must_use]
    pub fn breakpoints(&self) -> Vec<f64> {
        self.spline.breakpoints()
    }

    /// The same curve as cubic Bézier segments, one per piece (uniform parameters: the same
    /// parameter too; otherwise see [`InterpolatingSpline::breakpoints`]).
    #[must_use]
    pub fn to_bezier(&self) -> PiecewiseBezier<P> {
        self.spline.to_bezier()
    }
}

impl<P: ControlPoint> ParamCurve<P> for InterpolatingSpline<P> {
    fn eval(&self, t: f64) -> P {
        self.spline.eval(t)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> P {
        self.spline.eval_deriv(t, order)
    }

    fn scale(&self) -> f64 {
        ParamCurve::scale(&self.spline)
    }

    fn is_periodic(&self) -> bool {
        self.end.is_none()
    }
}

/// The cubic Bézier control points of the Hermite piece of length h from node i to node j (the
/// next one).
fn hermite_bezier<P: ControlPoint>(
    points: &[P],
    slopes: &[P],
    i: usize,
    j: usize,
    h: f64,
) -> [P; 4] {
    [points[i], points[i] + slopes[i] * (h / 3.0), points[j] - slopes[j] * (h / 3.0), points[j]]
}

/// The blossom f(x₁, x₂, x₃) of the cubic with Bézier control points `b` over [a, c].
fn blossom<P: ControlPoint>(b: &[P; 4], a: f64, c: f64, args: &[f64]) -> P {
    let mut d = *b;
    for (level, &x) in args.iter().enumerate() {
        let v = (x - a) / (c - a);
        for k in 0..3 - level {
            d[k] = d[k] * (1.0 - v) + d[k + 1] * v;
        }
    }
    d[0]
}

/// The node derivatives of the open spline (the rows of the end condition, then the interior
/// rows of the module documentation), by the Thomas algorithm.
fn open_slopes<P: ControlPoint>(
    points: &[P],
    params: &[f64],
    end: EndCondition,
) -> Result<Vec<P>, Error> {
    let n = points.len();
    let h: Vec<f64> = params.windows(2).map(|w| w[1] - w[0]).collect();
    let delta: Vec<P> = (0..n - 1).map(|i| (points[i + 1] - points[i]) * (1.0 / h[i])).collect();
    let (mut sub, mut diag, mut sup) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut rhs = vec![P::ZERO; n];
    for i in 1..n - 1 {
        sub[i] = h[i];
        diag[i] = 2.0 * (h[i - 1] + h[i]);
        sup[i] = h[i - 1];
        rhs[i] = (delta[i - 1] * h[i] + delta[i] * h[i - 1]) * 3.0;
    }
    let last = n - 1;
    match end {
        EndCondition::Coincident => {
            diag[0] = 1.0;
            diag[last] = 1.0;
        }
        EndCondition::Natural => {
            (diag[0], sup[0], rhs[0]) = (2.0, 1.0, delta[0] * 3.0);
            (sub[last], diag[last], rhs[last]) = (1.0, 2.0, delta[last - 1] * 3.0);
        }
        EndCondition::NotAKnot => {
            // As scipy's CubicSpline: the third-derivative jump at t₁ (and tₙ₋₂), with the
            // neighbouring row eliminated so that the system stays tridiagonal.
            let d = h[0] + h[1];
            diag[0] = h[1];
            sup[0] = d;
            rhs[0] = (delta[0] * ((h[0] + 2.0 * d) * h[1]) + delta[1] * (h[0] * h[0])) * (1.0 / d);
            let (ha, hb) = (h[last - 2], h[last - 1]);
            let d = ha + hb;
            sub[last] = d;
            diag[last] = ha;
            rhs[last] =
                (delta[last - 2] * (hb * hb) + delta[last - 1] * ((2.0 * d + hb) * ha)) * (1.0 / d);
        }
    }
    let slopes = solve_tridiagonal(&sub, &diag, &sup, rhs)?;
    check_slopes(slopes)
}

/// Rejects slopes that overflowed (finite but huge input).
fn check_slopes<P: ControlPoint>(slopes: Vec<P>) -> Result<Vec<P>, Error> {
    if slopes.iter().all(|s| s.is_finite()) {
        Ok(slopes)
    } else {
        Err(Error::Overflow { what: "interpolating spline" })
    }
}

/// The node derivatives of the periodic spline: the cyclic system by Sherman–Morrison.
fn periodic_slopes<P: ControlPoint>(points: &[P], params: &[f64]) -> Result<Vec<P>, Error> {
    let n = points.len();
    let h: Vec<f64> = (0..n)
        .map(|i| if i + 1 < n { params[i + 1] - params[i] } else { params[0] + 1.0 - params[i] })
        .collect();
    let delta: Vec<P> = (0..n).map(|i| (points[(i + 1) % n] - points[i]) * (1.0 / h[i])).collect();
    let (mut sub, mut diag, mut sup) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut rhs = vec![P::ZERO; n];
    for i in 0..n {
        let prev = (i + n - 1) % n;
        sub[i] = h[i];
        diag[i] = 2.0 * (h[prev] + h[i]);
        sup[i] = h[prev];
        rhs[i] = (delta[prev] * h[i] + delta[i] * h[prev]) * 3.0;
    }
    // Corners: row 0 holds s_{n−1} (coefficient sub[0]), row n−1 holds s₀ (sup[n−1]).
    let (top_right, bottom_left) = (sub[0], sup[n - 1]);
    sub[0] = 0.0;
    sup[n - 1] = 0.0;
    // A = T + u·vᵀ with u = (γ, 0, …, 0, bottom_left), v = (1, 0, …, 0, top_right/γ).
    let gamma = -diag[0];
    diag[0] -= gamma;
    diag[n - 1] -= bottom_left * top_right / gamma;
    let x = solve_tridiagonal(&sub, &diag, &sup, rhs)?;
    let mut u = vec![0.0; n];
    u[0] = gamma;
    u[n - 1] = bottom_left;
    let z = solve_tridiagonal(&sub, &diag, &sup, u)?;
    let denom = 1.0 + z[0] + top_right * z[n - 1] / gamma;
    if denom == 0.0 || !denom.is_finite() {
        return Err(Error::Curve(CurveError::Singular { what: "periodic spline system" }));
    }
    let factor = (x[0] + x[n - 1] * (top_right / gamma)) * (1.0 / denom);
    check_slopes(x.iter().zip(&z).map(|(xi, zi)| *xi - factor * *zi).collect())
}

/// Solves the tridiagonal system sub[i]·x[i−1] + diag[i]·x[i] + sup[i]·x[i+1] = rhs[i] by the
/// Thomas algorithm (no pivoting: the systems here are diagonally dominant).
fn solve_tridiagonal<P: ControlPoint>(
    sub: &[f64],
    diag: &[f64],
    sup: &[f64],
    mut rhs: Vec<P>,
) -> Result<Vec<P>, Error> {
    let n = diag.len();
    let mut c = vec![0.0; n];
    let mut prev_c = 0.0;
    for i in 0..n {
        let pivot = diag[i] - if i > 0 { sub[i] * prev_c } else { 0.0 };
        if pivot == 0.0 || !pivot.is_finite() {
            return Err(Error::Curve(CurveError::Singular { what: "spline interpolation system" }));
        }
        c[i] = sup[i] / pivot;
        let r = if i > 0 { rhs[i] - rhs[i - 1] * sub[i] } else { rhs[i] };
        rhs[i] = r * (1.0 / pivot);
        prev_c = c[i];
    }
    for i in (0..n.saturating_sub(1)).rev() {
        let next = rhs[i + 1];
        rhs[i] = rhs[i] - next * c[i];
    }
    Ok(rhs)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn tridiagonal_and_cyclic_solves() {
        let x = solve_tridiagonal(
            &[0.0, 1.0, 1.0],
            &[4.0, 4.0, 4.0],
            &[1.0, 1.0, 0.0],
            vec![5.0, 6.0, 5.0],
        )
        .unwrap();
        for v in x {
            assert!((v - 1.0).abs() < 1e-15);
        }
        // Periodic slopes of samples of sin(2πt): close to 2π cos(2πt).
        let n = 64;
        let params: Vec<f64> = (0..n).map(|i| i as f64 / n as f64).collect();
        let pts: Vec<f64> = params.iter().map(|t| (std::f64::consts::TAU * t).sin()).collect();
        let s = periodic_slopes(&pts, &params).unwrap();
        for (t, si) in params.iter().zip(s) {
            assert!((si - std::f64::consts::TAU * (std::f64::consts::TAU * t).cos()).abs() < 1e-4);
        }
    }

    #[test]
    fn thesis_end_control_points_coincide() {
        let pts = vec![DVec2::ZERO, DVec2::X, DVec2::new(2.0, 1.0), DVec2::new(2.0, 3.0)];
        let curve = InterpolatingSpline::try_open(
            pts.clone(),
            Parameters::Uniform,
            EndCondition::Coincident,
        )
        .unwrap();
        let c = curve.spline().control_points();
        assert_eq!(c.len(), pts.len() + 2);
        assert!((c[0] - pts[0]).length() < 1e-15 && (c[1] - pts[0]).length() < 1e-15);
        assert!((c[5] - pts[3]).length() < 1e-15 && (c[4] - pts[3]).length() < 1e-15);
        assert!(curve.eval_deriv(0.0, 1).length() < 1e-14);
    }

    #[test]
    fn bad_input_is_rejected() {
        let three = vec![0.0, 1.0, 0.5];
        assert!(
            InterpolatingSpline::try_open(
                three.clone(),
                Parameters::Uniform,
                EndCondition::NotAKnot
            )
            .is_err()
        );
        assert!(InterpolatingSpline::try_periodic(vec![0.0, 1.0], Parameters::Uniform).is_err());
        let given = Parameters::Given(vec![0.0, 0.5, 1.0]);
        assert!(matches!(
            InterpolatingSpline::try_periodic(three.clone(), given),
            Err(Error::Curve(CurveError::NodeOutOfRange { index: 2, .. }))
        ));
        let dup = vec![0.0, 1.0, 1.0, 2.0];
        assert!(matches!(
            InterpolatingSpline::try_open(dup, Parameters::ChordLength, EndCondition::Natural),
            Err(Error::Curve(CurveError::CoincidentPoints { first: 1, second: 2 }))
        ));
    }
}
