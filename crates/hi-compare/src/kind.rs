// SPDX-License-Identifier: MIT
//! Every curve family of the thesis's comparisons by name (Hardy 2005, chapter 2, §2.13,
//! §2.14 and §4.5 beside the harmonic curve of chapter 3): [`CurveKind`] names a family,
//! [`CurveKind::build`] draws its curve through given points, and [`AnyCurve`] is that curve,
//! a [`ParamCurve`] whatever the family, so a program (the `hi` command line, a figure) can
//! let its user pick the family at run time.
//!
//! # The curve each kind draws
//!
//! Every kind takes nothing but the points; the remaining choices are fixed as follows.
//!
//! | name | curve | closed | parameter of point k (n points) |
//! |---|---|---|---|
//! | `harmonic` | [`HarmonicCurve`] (§3.2, §3.3) | yes | k/n |
//! | `trig` | [`TrigonometricCurve`], real part (§2.13) | yes | k/n |
//! | `lagrange` | [`LagrangeCurve`], uniform nodes (§2.4) | no | k/(n − 1) |
//! | `catmull-rom` | [`HermiteSpline::catmull_rom`] (§2.6) | yes | k/n |
//! | `bessel-overhauser` | [`HermiteSpline::bessel_overhauser`] (§2.7) | yes | chord length |
//! | `tcb` | [`HermiteSpline::kochanek_bartels`], T = C = B = 0 (§2.8) | yes | k/n |
//! | `bspline-periodic` | [`InterpolatingSpline::try_periodic`], uniform (§2.11) | yes | k/n |
//! | `bspline-open` | [`InterpolatingSpline::try_open`], uniform, natural ends (§2.11) | no | k/(n − 1) |
//! | `hobby-closed` | [`HobbyCurve`], `..cycle`, tension 1 (§2.14) | yes | k/n |
//! | `hobby-open` | [`HobbyCurve`], curl 1 at both ends, tension 1 (§2.14) | no | k/(n − 1) |
//! | `chaikin` | [`ChaikinCurve`]: the exact limit, a uniform quadratic B-spline (§4.5) | yes | none: approximating, (x₀ + x₁)/2 at t = 0 |
//! | `four-point` | [`FourPointCurve`], w = 1/16, approximated as below (§4.5) | yes | k/n |
//!
//! Where the thesis compares closed curves (chapter 3 and figures 4.6 and 4.7) the kinds that
//! could be either are closed, like the harmonic curve; `lagrange`, `bspline-open` and
//! `hobby-open` are the open ones. With T = C = B = 0, `tcb` is the same curve as
//! `catmull-rom` (§2.8). `bspline-open` has natural ends ([`EndCondition::Natural`]: X″ = 0
//! there), not the thesis's coincident end control points ([`EndCondition::Coincident`]): with
//! those the curve stops at its ends (X′ = 0), its curvature grows like 1/t towards them and
//! its bending energy is infinite, so no fairness comparison could include it.
//!
//! The 4-point scheme's limit has no closed form, and it is C¹ but not C²: `four-point` is the
//! refined polygon P^k after k = [`FOUR_POINT_STEPS`] steps (every point of P^k lies exactly
//! on the limit, point i at t = i/(n·2^k)), joined by
//! the periodic cubic spline through them at uniform parameters
//! ([`InterpolatingSpline::try_periodic`]). That spline is C², so its curvature is continuous
//! and the fairness measures converge quickly; they are those of the approximation (the
//! limit's curvature is not defined everywhere).
//!
//! # Bézier form
//!
//! The piecewise polynomial kinds convert to [`PiecewiseBezier`] ([`AnyCurve::to_bezier`]):
//! cubic segments for the Hermite, B-spline and Hobby kinds (for Hobby: knot, postcontrol,
//! precontrol, next knot, as METAPOST reports them), quadratic ones for `chaikin`, and one
//! segment of degree n − 1 for `lagrange`. Segment i covers t ∈ [i/s, (i + 1)/s] of s segments,
//! the parameter of [`ParamCurve::eval`], except for `bessel-overhauser`, whose segments are
//! its chord-length pieces each reparametrised linearly
//! ([`HermiteSpline::breakpoints`]). `harmonic`, `trig` and `four-point` are not polynomial.

use hi_curve::Error as CurveError;
use std::fmt;
use std::str::FromStr;

use glam::DVec2;
use hi_bezier::{BezierCurve, PiecewiseBezier};

use super::bspline_interp::{EndCondition, InterpolatingSpline, Parameters};
use super::cardinal::{Closure, HermiteSpline, Tcb};
use super::corner_cutting::{ChaikinCurve, FourPointCurve};
use super::hobby::{HobbyCurve, HobbyOptions};
use super::lagrange::LagrangeCurve;
use crate::check::check_count;
use crate::check::check_points;
use hi_curve::ParamCurve;
use hi_curve::{HarmonicCurve, TrigonometricCurve};

use crate::{ControlPoint, Error};

/// The number of steps of the 4-point scheme whose polygon approximates its limit for
/// [`CurveKind::FourPoint`] (see the [module documentation](self)): 16 points per point.
pub const FOUR_POINT_STEPS: usize = 4;

/// A family of curves through points: the harmonic curve and every curve the thesis compares
/// it with (Hardy 2005, chapters 2–4). The [module documentation](self) says which curve of
/// each family [`CurveKind::build`] draws.
///
/// The names (`Display` and `FromStr`) are those of the `hi` command line: `harmonic`, `trig`,
/// `lagrange`, `catmull-rom`, `bessel-overhauser`, `tcb`, `bspline-periodic`, `bspline-open`,
/// `hobby-closed`, `hobby-open`, `chaikin`, `four-point`.
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ParamCurve;
/// use hi_compare::CurveKind;
///
/// let kind: CurveKind = "bspline-periodic".parse().unwrap();
/// assert_eq!(kind, CurveKind::BSplinePeriodic);
/// assert_eq!(kind.to_string(), "bspline-periodic");
/// assert!("b-spline".parse::<CurveKind>().unwrap_err().to_string().contains("catmull-rom"));
///
/// // Every interpolating kind passes through the points; the square's third point is at t = 1/2.
/// let square = vec![DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
/// for kind in [CurveKind::Harmonic, CurveKind::CatmullRom, CurveKind::HobbyClosed] {
///     let curve = kind.build(square.clone()).unwrap();
///     assert!((curve.eval(0.5) - DVec2::ONE).length() < 1e-14, "{kind}");
/// }
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum CurveKind {
    /// `harmonic`: the harmonic curve (§3.2, §3.3).
    Harmonic,
    /// `trig`: trigonometric interpolation with frequencies 0…n − 1, real part (§2.13).
    Trig,
    /// `lagrange`: the Lagrange polynomial on uniform nodes (§2.4).
    Lagrange,
    /// `catmull-rom`: the closed Catmull-Rom spline (§2.6).
    CatmullRom,
    /// `bessel-overhauser`: the closed Bessel-Overhauser spline, chord length (§2.7).
    BesselOverhauser,
    /// `tcb`: the closed Kochanek–Bartels spline with T = C = B = 0 (§2.8).
    Tcb,
    /// `bspline-periodic`: periodic cubic B-spline interpolation, uniform (§2.11).
    BSplinePeriodic,
    /// `bspline-open`: open cubic B-spline interpolation, uniform, natural ends (§2.11).
    BSplineOpen,
    /// `hobby-closed`: METAPOST's closed path `..cycle` (§2.14).
    HobbyClosed,
    /// `hobby-open`: METAPOST's open path with curl 1 at both ends (§2.14).
    HobbyOpen,
    /// `chaikin`: the limit of Chaikin's corner cutting on the closed polygon (§4.5).
    Chaikin,
    /// `four-point`: the 4-point scheme on the closed polygon, w = 1/16 (§4.5).
    FourPoint,
}

impl CurveKind {
    /// Every kind, in the order of the thesis's presentation used by the command line.
    pub const ALL: [CurveKind; 12] = [
        CurveKind::Harmonic,
        CurveKind::Trig,
        CurveKind::Lagrange,
        CurveKind::CatmullRom,
        CurveKind::BesselOverhauser,
        CurveKind::Tcb,
        CurveKind::BSplinePeriodic,
        CurveKind::BSplineOpen,
        CurveKind::HobbyClosed,
        CurveKind::HobbyOpen,
        CurveKind::Chaikin,
        CurveKind::FourPoint,
    ];

    /// The name of the kind, as `Display` prints it and `FromStr` reads it.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            CurveKind::Harmonic => "harmonic",
            CurveKind::Trig => "trig",
            CurveKind::Lagrange => "lagrange",
            CurveKind::CatmullRom => "catmull-rom",
            CurveKind::BesselOverhauser => "bessel-overhauser",
            CurveKind::Tcb => "tcb",
            CurveKind::BSplinePeriodic => "bspline-periodic",
            CurveKind::BSplineOpen => "bspline-open",
            CurveKind::HobbyClosed => "hobby-closed",
            CurveKind::HobbyOpen => "hobby-open",
            CurveKind::Chaikin => "chaikin",
            CurveKind::FourPoint => "four-point",
        }
    }

    /// True if the curve of this kind is closed and 1-periodic; false if it runs from the
    /// first point at t = 0 to the last at t = 1.
    #[must_use]
    pub const fn is_closed(self) -> bool {
        !matches!(self, CurveKind::Lagrange | CurveKind::BSplineOpen | CurveKind::HobbyOpen)
    }

    /// True if the curve of this kind is piecewise polynomial, so that
    /// [`AnyCurve::to_bezier`] converts it.
    #[must_use]
    pub const fn is_polynomial(self) -> bool {
        !matches!(self, CurveKind::Harmonic | CurveKind::Trig | CurveKind::FourPoint)
    }

    /// True if the curve of this kind is planar only (Hobby's algorithm): it needs 2-D points.
    #[must_use]
    pub const fn is_planar(self) -> bool {
        matches!(self, CurveKind::HobbyClosed | CurveKind::HobbyOpen)
    }

    /// The curve of this kind through `points` (the choices of the
    /// [module documentation](self)).
    ///
    /// # Errors
    ///
    /// - [`hi_curve::Error::Empty`] for no points, [`hi_curve::Error::NonFinitePoint`] for a NaN or infinite
    ///   coordinate;
    /// - [`Error::TooFewPoints`] below the size the kind needs: 1 for `harmonic` and `trig`,
    ///   3 for the closed Hermite kinds and `bspline-periodic`, 2 for the others;
    /// - [`hi_curve::Error::CoincidentPoints`] for `bessel-overhauser` when two consecutive points
    ///   (cyclically) coincide;
    /// - [`hi_curve::Error::InvalidCount`] for a Hobby kind with points that are not 2-D;
    /// - [`Error::Overflow`] when coordinates are too large for the construction.
    pub fn build<P: ControlPoint>(self, points: Vec<P>) -> Result<AnyCurve<P>, Error> {
        check_points(&points)?;
        let inner = match self {
            CurveKind::Harmonic => Inner::Harmonic(HarmonicCurve::try_new(points.clone())?),
            CurveKind::Trig => Inner::Trig(TrigonometricCurve::try_new(points.clone())?),
            CurveKind::Lagrange => Inner::Lagrange(LagrangeCurve::try_new(points.clone())?),
            CurveKind::CatmullRom => {
                Inner::Hermite(HermiteSpline::catmull_rom(points.clone(), Closure::Closed)?)
            }
            CurveKind::BesselOverhauser => {
                Inner::Hermite(HermiteSpline::bessel_overhauser(points.clone(), Closure::Closed)?)
            }
            CurveKind::Tcb => Inner::Hermite(HermiteSpline::kochanek_bartels(
                points.clone(),
                Closure::Closed,
                Tcb::new(0.0, 0.0, 0.0),
            )?),
            CurveKind::BSplinePeriodic => Inner::Spline(InterpolatingSpline::try_periodic(
                points.clone(),
                Parameters::Uniform,
            )?),
            CurveKind::BSplineOpen => Inner::Spline(InterpolatingSpline::try_open(
                points.clone(),
                Parameters::Uniform,
                EndCondition::Natural,
            )?),
            CurveKind::HobbyClosed | CurveKind::HobbyOpen => {
                if P::DIM != 2 {
                    return Err(Error::Curve(CurveError::InvalidCount {
                        what: "dimension of the points",
                        value: P::DIM,
                        expected: "2: Hobby's algorithm (METAPOST) is planar",
                    }));
                }
                let plane = points.iter().map(|p| DVec2::new(p.coord(0), p.coord(1))).collect();
                let config = if self == CurveKind::HobbyClosed {
                    HobbyOptions::closed()
                } else {
                    HobbyOptions::open()
                };
                Inner::Hobby(HobbyCurve::try_new(plane, &config)?)
            }
            CurveKind::Chaikin => Inner::Chaikin(ChaikinCurve::try_new(points.clone(), true)?),
            CurveKind::FourPoint => {
                let scheme = FourPointCurve::try_new(points.clone(), true)?;
                // refine returns steps + 1 polygons, so the last one is P^k.
                let refined = scheme.refine(FOUR_POINT_STEPS)?.pop().unwrap_or_default();
                Inner::FourPoint(InterpolatingSpline::try_periodic(refined, Parameters::Uniform)?)
            }
        };
        Ok(AnyCurve { kind: self, points, inner })
    }
}

impl fmt::Display for CurveKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for CurveKind {
    type Err = Error;

    /// The kind of this name (exactly as [`CurveKind::name`] spells it).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        CurveKind::ALL
            .into_iter()
            .find(|kind| kind.name() == s)
            .ok_or_else(|| Error::UnknownKind { name: s.to_owned() })
    }
}

/// The curve of any [`CurveKind`] through some points: a [`ParamCurve`] over t ∈ [0, 1]
/// (1-periodic when closed) that dispatches to the curve of its kind. Built by
/// [`CurveKind::build`].
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ParamCurve;
/// use hi_compare::CurveKind;
///
/// let pts = vec![DVec2::ZERO, DVec2::new(2.0, 1.0), DVec2::new(4.0, 0.0)];
/// let curve = CurveKind::Lagrange.build(pts).unwrap();
/// assert!(!curve.is_periodic());
/// // The parabola through the three points is y = x(4 − x)/4: at x = 1, y = 3/4.
/// assert!((curve.eval(0.25) - DVec2::new(1.0, 0.75)).length() < 1e-15);
/// let bezier = curve.to_bezier().unwrap();
/// assert!((bezier.eval(0.25) - curve.eval(0.25)).length() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct AnyCurve<P> {
    kind: CurveKind,
    // Invariant: finite and non-empty; the points the curve was built through.
    points: Vec<P>,
    // Invariant: the curve of `kind` through `points`; `Hobby` only when P::DIM == 2.
    inner: Inner<P>,
}

/// The curve of each kind.
#[derive(Clone, Debug, PartialEq)]
enum Inner<P> {
    Harmonic(HarmonicCurve<P>),
    Trig(TrigonometricCurve<P>),
    Lagrange(LagrangeCurve<P>),
    Hermite(HermiteSpline<P>),
    Spline(InterpolatingSpline<P>),
    Hobby(HobbyCurve),
    Chaikin(ChaikinCurve<P>),
    // The periodic spline through the refined polygon.
    FourPoint(InterpolatingSpline<P>),
}

impl<P: ControlPoint> AnyCurve<P> {
    /// The kind of the curve.
    #[must_use]
    pub fn kind(&self) -> CurveKind {
        self.kind
    }

    /// The points the curve was built through (the control polygon for `chaikin` and
    /// `four-point`).
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The harmonic curve, for a curve of kind `harmonic`.
    #[must_use]
    pub fn as_harmonic(&self) -> Option<&HarmonicCurve<P>> {
        match &self.inner {
            Inner::Harmonic(curve) => Some(curve),
            _ => None,
        }
    }

    /// N samples of the curve: X(l/N), l = 0, …, N − 1, for a closed curve (by FFT for the
    /// harmonic one, [`HarmonicCurve::sample_uniform`]); X(l/(N − 1)), both ends included, for
    /// an open one (X(0) when N = 1).
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::InvalidCount`] unless 1 ≤ N ≤ 2²⁸.
    pub fn sample(&self, n_samples: usize) -> Result<Vec<P>, Error> {
        check_count("number of samples", n_samples)?;
        if let Inner::Harmonic(curve) = &self.inner {
            return Ok(curve.sample_uniform(n_samples)?);
        }
        let step = if self.kind.is_closed() {
            1.0 / n_samples as f64
        } else {
            1.0 / n_samples.saturating_sub(1).max(1) as f64
        };
        Ok((0..n_samples).map(|l| self.eval(l as f64 * step)).collect())
    }

    /// The curve as a chain of Bézier segments, for the piecewise polynomial kinds (see the
    /// [module documentation](self) for their degrees and parameters).
    ///
    /// # Errors
    ///
    /// [`Error::NotPolynomial`] for `harmonic`, `trig` and `four-point`; [`Error::Overflow`]
    /// if the Bernstein coefficients of a high-degree Lagrange polynomial overflow.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_compare::{CurveKind, Error};
    ///
    /// let curve = CurveKind::Harmonic.build(vec![DVec2::X, DVec2::Y, -DVec2::X]).unwrap();
    /// let err = curve.to_bezier().unwrap_err();
    /// assert_eq!(err, Error::NotPolynomial { kind: CurveKind::Harmonic });
    /// assert!(err.to_string().contains("not piecewise polynomial"));
    /// ```
    pub fn to_bezier(&self) -> Result<PiecewiseBezier<P>, Error> {
        let not_polynomial = || Error::NotPolynomial { kind: self.kind };
        match &self.inner {
            Inner::Harmonic(_) | Inner::Trig(_) | Inner::FourPoint(_) => Err(not_polynomial()),
            Inner::Lagrange(curve) => curve.to_bezier(),
            Inner::Hermite(curve) => Ok(curve.to_bezier()),
            Inner::Spline(curve) => Ok(curve.to_bezier()),
            Inner::Hobby(curve) => {
                let segments = curve
                    .to_bezier()
                    .segments()
                    .iter()
                    .map(|segment| segment.try_map(to_point::<P>))
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(|_| Error::Overflow { what: "Bézier form of the Hobby curve" })?;
                PiecewiseBezier::try_new(segments).map_err(|_| Error::Curve(CurveError::Empty))
            }
            Inner::Chaikin(curve) => chaikin_bezier(curve.points()),
        }
    }
}

/// A 2-D point as a point of type `P` (which has two coordinates: the invariant of
/// [`Inner::Hobby`]).
fn to_point<P: ControlPoint>(v: DVec2) -> P {
    P::from_coords(|i| v[i])
}

/// The quadratic Bézier segments of the closed uniform quadratic B-spline with control points
/// `points` (the limit of Chaikin's scheme): segment j has the B-spline control points xⱼ,
/// xⱼ₊₁, xⱼ₊₂ (mod n) and Bézier control points (xⱼ + xⱼ₊₁)/2, xⱼ₊₁, (xⱼ₊₁ + xⱼ₊₂)/2.
fn chaikin_bezier<P: ControlPoint>(points: &[P]) -> Result<PiecewiseBezier<P>, Error> {
    let n = points.len();
    let overflow = |_| Error::Overflow { what: "Bézier form of the Chaikin curve" };
    let segments = (0..n)
        .map(|j| {
            let (a, b, c) = (points[j], points[(j + 1) % n], points[(j + 2) % n]);
            BezierCurve::try_new(vec![(a + b) * 0.5, b, (b + c) * 0.5]).map_err(overflow)
        })
        .collect::<Result<Vec<_>, _>>()?;
    PiecewiseBezier::try_new(segments).map_err(|_| Error::Curve(CurveError::Empty))
}

impl<P: ControlPoint> ParamCurve<P> for AnyCurve<P> {
    fn eval(&self, t: f64) -> P {
        match &self.inner {
            Inner::Harmonic(curve) => curve.eval(t),
            Inner::Trig(curve) => curve.eval(t),
            Inner::Lagrange(curve) => curve.eval(t),
            Inner::Hermite(curve) => curve.eval(t),
            Inner::Spline(curve) | Inner::FourPoint(curve) => curve.eval(t),
            Inner::Hobby(curve) => to_point(ParamCurve::eval(curve, t)),
            Inner::Chaikin(curve) => ParamCurve::eval(curve, t),
        }
    }

    fn eval_deriv(&self, t: f64, order: usize) -> P {
        match &self.inner {
            Inner::Harmonic(curve) => curve.eval_deriv(t, order),
            Inner::Trig(curve) => curve.eval_deriv(t, order),
            Inner::Lagrange(curve) => curve.eval_deriv(t, order),
            Inner::Hermite(curve) => curve.eval_deriv(t, order),
            Inner::Spline(curve) | Inner::FourPoint(curve) => curve.eval_deriv(t, order),
            Inner::Hobby(curve) => to_point(ParamCurve::eval_deriv(curve, t, order)),
            Inner::Chaikin(curve) => ParamCurve::eval_deriv(curve, t, order),
        }
    }

    fn scale(&self) -> f64 {
        match &self.inner {
            Inner::Harmonic(curve) => ParamCurve::scale(curve),
            Inner::Trig(curve) => ParamCurve::scale(curve),
            Inner::Lagrange(curve) => ParamCurve::scale(curve),
            Inner::Hermite(curve) => ParamCurve::scale(curve),
            Inner::Spline(curve) | Inner::FourPoint(curve) => ParamCurve::scale(curve),
            Inner::Hobby(curve) => ParamCurve::scale(curve),
            Inner::Chaikin(curve) => ParamCurve::scale(curve),
        }
    }

    fn is_periodic(&self) -> bool {
        self.kind.is_closed()
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;

    fn pentagon() -> Vec<DVec2> {
        vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(3.0, 1.0),
            DVec2::new(4.0, 4.0),
            DVec2::new(1.0, 5.0),
            DVec2::new(-1.0, 2.0),
        ]
    }

    #[test]
    fn names_round_trip() {
        for kind in CurveKind::ALL {
            assert_eq!(kind.name().parse::<CurveKind>(), Ok(kind), "{kind}");
            assert_eq!(kind.to_string(), kind.name(), "{kind}");
        }
        let err = "Harmonic".parse::<CurveKind>().unwrap_err();
        assert!(
            err.to_string()
                .starts_with("unknown curve kind 'Harmonic': expected one of harmonic, trig,"),
            "{err}"
        );
    }

    #[test]
    fn every_kind_builds_and_periodicity_matches() {
        for kind in CurveKind::ALL {
            let curve = kind.build(pentagon()).unwrap();
            assert_eq!(curve.kind(), kind, "{kind}");
            assert_eq!(curve.is_periodic(), kind.is_closed(), "{kind}");
            if kind.is_closed() {
                let (a, b) = (curve.eval(0.1), curve.eval(1.1));
                assert!((a - b).length() < 1e-9, "{kind}: periodic");
            }
            assert_eq!(curve.to_bezier().is_ok(), kind.is_polynomial(), "{kind}");
        }
    }

    #[test]
    fn bezier_forms_reproduce_the_curves() {
        for kind in CurveKind::ALL.into_iter().filter(|k| k.is_polynomial()) {
            if kind == CurveKind::BesselOverhauser {
                continue; // reparametrised segments
            }
            let curve = kind.build(pentagon()).unwrap();
            let bezier = curve.to_bezier().unwrap();
            for i in 0..=40 {
                let t = f64::from(i) / 40.0;
                let d = (bezier.eval(t) - curve.eval(t)).length();
                assert!(d < 1e-12, "{kind} at {t}: {d}");
            }
        }
    }

    #[test]
    fn four_point_passes_through_the_limit_points() {
        let pts = pentagon();
        let curve = CurveKind::FourPoint.build(pts.clone()).unwrap();
        let n = pts.len();
        for (k, p) in pts.iter().enumerate() {
            assert!((curve.eval(k as f64 / n as f64) - *p).length() < 1e-12, "point {k}");
        }
        // The first new point of the scheme: (9/16)(x₀ + x₁) − (1/16)(x₄ + x₂).
        let mid = (pts[0] + pts[1]) * (9.0 / 16.0) - (pts[4] + pts[2]) * (1.0 / 16.0);
        assert!((curve.eval(0.5 / n as f64) - mid).length() < 1e-12, "midpoint");
    }

    #[test]
    fn hobby_needs_plane_points_and_sampling_counts() {
        let err = CurveKind::HobbyOpen.build(vec![DVec3::X, DVec3::Y]).unwrap_err();
        assert!(err.to_string().contains("planar"), "{err}");
        let curve = CurveKind::BSplineOpen.build(vec![0.0, 1.0, 3.0]).unwrap();
        let samples = curve.sample(3).unwrap();
        assert_eq!(samples, vec![0.0, 1.0, 3.0]);
        assert!(curve.sample(0).is_err(), "zero samples");
        assert_eq!(
            CurveKind::CatmullRom.build(vec![0.0, 1.0]).unwrap_err(),
            Error::TooFewPoints { what: "a closed spline", needed: 3, got: 2 }
        );
    }
}
