// SPDX-License-Identifier: MIT
//! METAPOST's curves through points: Hobby's algorithm (Hardy 2005, §2.14, eqs. 2.14–2.16).
//!
//! A METAPOST path `z₀..z₁..…..zₙ₋₁` (open) or `z₀..…..zₙ₋₁..cycle` (closed) is a chain of
//! cubic Bézier segments through the points. Its control points follow from the tangent
//! directions at the knots: for the segment from zₖ to zₖ₊₁ with chord dₖ, turning angle θₖ at
//! the start and φₖ₊₁ at the end (both measured from the chord),
//!
//! postcontrol(zₖ) = zₖ + (ρ(θ, φ)/(3τₖ))·R(θ)·(zₖ₊₁ − zₖ),
//! precontrol(zₖ₊₁) = zₖ₊₁ − (σ(θ, φ)/(3τₖ₊₁))·R(−φ)·(zₖ₊₁ − zₖ),
//!
//! with Hobby's velocity functions ([`rho`], [`sigma`]) and tensions τ. The angles come from
//! Hobby's *mock curvature* equations (eq. 2.14) at the interior knots, which make the
//! curvature of consecutive segments nearly continuous, with curl conditions (eqs. 2.15 and
//! 2.16) at the ends of an open path: a tridiagonal system solved in O(n) for open paths, a
//! cyclic one (also O(n)) for closed paths.
//!
//! The implementation is a transcription of METAPOST's own `make_choices`, `solve_choices`,
//! `set_controls`, `velocity` and `curl_ratio` (mp.w and mpmathdouble.w, after the part
//! "Choosing control points" of Knuth's *METAFONT: The Program*), in the same operation order
//! as METAPOST's `-numbersystem=double`, so the control points agree
//! with `mpost -numbersystem=double` to about 1e-15 relative (the committed fixture
//! `fixtures/curve/mpost_hobby.json` and a live run of mpost check it). That includes
//! METAPOST's rules for coincident neighbouring points (a degenerate segment, with curl 1 on
//! both sides), for `tension atleast` (velocities reduced to stay inside the bounding
//! triangle), the clamping of velocities and curl ratios at 4, and one quirk of the double
//! arithmetic: at a curled end whose tension is smaller than the tension at the other end of
//! its segment, `-numbersystem=double` computes a different curl ratio than Hobby's formula
//! (which METAPOST's default fixed-point arithmetic follows). With the default curls and
//! tensions the two agree. Direction specifications (`{dir}`, explicit controls) are not
//! offered.
//!
//! Hobby's algorithm is planar: the angles are turning angles in the plane, so the curve is
//! implemented for [`DVec2`] only (3-D paths are not METAPOST's).
//!
//! References: J. D. Hobby, [Smooth, easy to compute interpolating splines], *Discrete and
//! Computational Geometry* 1 (1986) 123–140; D. E. Knuth, *METAFONT: The Program* (1986),
//! part "Choosing control points"; J. D. Hobby, *A User's Manual for METAPOST* (1992).
//!
//! [Smooth, easy to compute interpolating splines]: https://doi.org/10.1007/BF02187690
//!
//! The transcription of METAPOST's `make_choices` is in `choices`.

mod choices;

use glam::DVec2;
use hi_bezier::{BezierCurve, PiecewiseBezier};
use hi_curve::Error as CurveError;

use crate::Error;
use crate::check::check_points;
use crate::check::spread;
use hi_curve::ParamCurve;

use choices::{Knot, Side, make_choices};

/// The smallest tension METAPOST accepts (it replaces smaller ones by 1, "Improper tension").
pub const MIN_TENSION: f64 = 0.75;

/// √2, the constant a of α in Hobby's velocity function (Hobby 1986, METAPOST).
const HOBBY_A: f64 = std::f64::consts::SQRT_2;
/// The constant b = 1/16 of α.
const HOBBY_B: f64 = 1.0 / 16.0;

/// A tension at one end of a segment: METAPOST's `tension τ` or `tension atleast τ`.
///
/// A larger tension pulls the control point towards its knot (the velocity is divided by τ).
/// With `at_least`, METAPOST also shortens the control arms where needed so that the segment
/// stays inside the triangle formed by its chord and its end tangents, when that triangle
/// exists (Knuth, *METAFONT: The Program*, "Choosing control points").
///
/// # Examples
///
/// ```
/// use hi_compare::hobby::Tension;
///
/// assert_eq!(Tension::default(), Tension::new(1.0));
/// assert!(Tension::at_least(1.5).at_least);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Tension {
    /// τ; must be finite and at least [`MIN_TENSION`] = 3/4 (checked by
    /// [`HobbyCurve::try_new`]).
    pub value: f64,
    /// True for `tension atleast τ`.
    pub at_least: bool,
}

impl Tension {
    /// METAPOST's default, `tension 1`.
    pub const DEFAULT: Self = Self { value: 1.0, at_least: false };

    /// `tension value`.
    #[must_use]
    pub const fn new(value: f64) -> Self {
        Self { value, at_least: false }
    }

    /// `tension atleast value`.
    #[must_use]
    pub const fn at_least(value: f64) -> Self {
        Self { value, at_least: true }
    }

    /// METAPOST's internal form: the value, negated for `atleast`.
    fn signed(self) -> f64 {
        if self.at_least { -self.value } else { self.value }
    }
}

impl Default for Tension {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// The tensions of one segment, `..tension α and β..`: α at the knot where the segment starts
/// (METAPOST's right tension of that knot), β at the knot where it ends (its left tension).
///
/// # Examples
///
/// ```
/// use hi_compare::hobby::{Join, Tension};
///
/// let join = Join::uniform(Tension::new(2.0)); // `..tension 2..`
/// assert_eq!(join, Join::new(Tension::new(2.0), Tension::new(2.0)));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Join {
    /// α, the tension at the start of the segment.
    pub start: Tension,
    /// β, the tension at the end of the segment.
    pub end: Tension,
}

impl Join {
    /// `..tension start and end..`.
    #[must_use]
    pub const fn new(start: Tension, end: Tension) -> Self {
        Self { start, end }
    }

    /// `..tension τ..`: the same tension at both ends.
    #[must_use]
    pub const fn uniform(tension: Tension) -> Self {
        Self { start: tension, end: tension }
    }
}

/// How to join the points: closed or open, curls at the ends, tensions.
///
/// The default is METAPOST's plain `z₀..z₁..…..zₙ₋₁`: open, curl 1 at both ends, tension 1
/// everywhere.
///
/// # Examples
///
/// ```
/// use hi_compare::hobby::{HobbyOptions, Tension};
///
/// // z₀{curl 2}..tension atleast 1..z₁..…..{curl 0}zₙ₋₁
/// let options = HobbyOptions::open().with_curls(2.0, 0.0).with_tension(Tension::at_least(1.0));
/// assert!(!options.closed);
/// assert_eq!(HobbyOptions::default(), HobbyOptions::open());
/// ```
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct HobbyOptions {
    /// True for a closed path (`..cycle`); false for an open one.
    pub closed: bool,
    /// The curl γ₀ at the first knot of an open path (eq. 2.15): 1 (the default) makes the end
    /// a circular arc for three points on a circle, 0 makes the curvature vanish at the end;
    /// finite and non-negative. Ignored for closed paths.
    pub start_curl: f64,
    /// The curl γₙ at the last knot of an open path (eq. 2.16). Ignored for closed paths.
    pub end_curl: f64,
    /// The tension at both ends of every segment, unless `joins` is not empty.
    pub tension: Tension,
    /// Per-segment tensions: empty (use `tension`), or one [`Join`] per segment — n − 1 for an
    /// open path of n points, n for a closed one, join k after point k.
    pub joins: Vec<Join>,
}

impl HobbyOptions {
    /// An open path `z₀..…..zₙ₋₁` with curl 1 at both ends and tension 1.
    #[must_use]
    pub fn open() -> Self {
        Self {
            closed: false,
            start_curl: 1.0,
            end_curl: 1.0,
            tension: Tension::DEFAULT,
            joins: Vec::new(),
        }
    }

    /// A closed path `z₀..…..zₙ₋₁..cycle` with tension 1.
    #[must_use]
    pub fn closed() -> Self {
        Self { closed: true, ..Self::open() }
    }

    /// The same path with this tension on every segment (and no per-segment joins).
    #[must_use]
    pub fn with_tension(self, tension: Tension) -> Self {
        Self { tension, joins: Vec::new(), ..self }
    }

    /// The same path with these curls at the start and the end (open paths only).
    #[must_use]
    pub fn with_curls(self, start_curl: f64, end_curl: f64) -> Self {
        Self { start_curl, end_curl, ..self }
    }

    /// The same path with per-segment tensions.
    #[must_use]
    pub fn with_joins(self, joins: Vec<Join>) -> Self {
        Self { joins, ..self }
    }
}

impl Default for HobbyOptions {
    fn default() -> Self {
        Self::open()
    }
}

/// One knot of a METAPOST path as `mpost` reports it: `point k`, `precontrol k` and
/// `postcontrol k` of the path.
///
/// The segment from knot k to knot k + 1 is the cubic Bézier curve with control points
/// (point k, postcontrol k, precontrol k + 1, point k + 1). At the ends of an open path,
/// METAPOST sets the unused precontrol of the first knot and postcontrol of the last knot to
/// the knot itself.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct HobbyKnot {
    /// The interpolated point zₖ.
    pub point: DVec2,
    /// The control point before zₖ (of the incoming segment).
    pub precontrol: DVec2,
    /// The control point after zₖ (of the outgoing segment).
    pub postcontrol: DVec2,
}

/// A METAPOST curve through points by Hobby's algorithm: piecewise cubic Bézier, G¹ at the
/// knots (Hardy 2005, §2.14).
///
/// As a [`ParamCurve`] it is parametrised by METAPOST's time scaled to [0, 1]: with s
/// segments, t ∈ [k/s, (k+1)/s] is segment k at local time s·t − k, and the curve passes
/// through zₖ at t = k/s. A closed curve is 1-periodic; an open one is defined on [0, 1] and
/// extended beyond it by the polynomials of its end segments. At a knot, derivatives are those
/// of the segment that starts there (the curve is only G¹ there, its curvature jumps).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ParamCurve;
/// use hi_compare::hobby::{HobbyOptions, HobbyCurve};
///
/// // The irregular pentagon of docs/peers.md §1, closed; METAPOST reports postcontrol 0 as
/// // (1.0192962739791576, -0.52255030401962921).
/// let points = vec![
///     DVec2::new(0.0, 0.0),
///     DVec2::new(3.0, 1.0),
///     DVec2::new(4.0, 4.0),
///     DVec2::new(1.0, 5.0),
///     DVec2::new(-1.0, 2.0),
/// ];
/// let curve = HobbyCurve::try_new(points.clone(), &HobbyOptions::closed()).unwrap();
/// let post = curve.knots()[0].postcontrol;
/// assert!((post - DVec2::new(1.0192962739791576, -0.52255030401962921)).length() < 1e-14);
/// for (k, p) in points.iter().enumerate() {
///     assert!((curve.eval(k as f64 / 5.0) - *p).length() < 1e-14);
/// }
/// assert!(HobbyCurve::try_new(points[..1].to_vec(), &HobbyOptions::open()).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HobbyCurve {
    // Invariant: at least two knots, all finite; segment k runs from knot k to knot k + 1
    // (mod n when closed).
    knots: Vec<HobbyKnot>,
    closed: bool,
    // Largest distance of a point from the centroid of the points.
    scale: f64,
}

impl HobbyCurve {
    /// The METAPOST path through `points` with the ends and tensions of `options`.
    ///
    /// # Errors
    ///
    /// - [`hi_curve::Error::Empty`] for no points, [`hi_curve::Error::NonFinitePoint`] for a NaN or infinite
    ///   coordinate, [`Error::TooFewPoints`] for a single point;
    /// - [`hi_curve::Error::ParameterOutOfBounds`] for a tension below 3/4 or not finite, or a curl that
    ///   is negative or not finite;
    /// - [`hi_curve::Error::InvalidCount`] if `options.joins` is neither empty nor one per segment.
    pub fn try_new(points: Vec<DVec2>, options: &HobbyOptions) -> Result<Self, Error> {
        check_points(&points)?;
        let n = points.len();
        if n < 2 {
            return Err(Error::TooFewPoints { what: "a Hobby curve", needed: 2, got: n });
        }
        let n_segments = if options.closed { n } else { n - 1 };
        let joins = if options.joins.is_empty() {
            vec![Join::uniform(options.tension); n_segments]
        } else if options.joins.len() == n_segments {
            options.joins.clone()
        } else {
            return Err(Error::Curve(CurveError::InvalidCount {
                what: "number of joins",
                value: options.joins.len(),
                expected: "one per segment: n - 1 for an open path of n points, n for a closed one",
            }));
        };
        for join in &joins {
            check_tension(join.start)?;
            check_tension(join.end)?;
        }
        if !options.closed {
            check_curl(options.start_curl)?;
            check_curl(options.end_curl)?;
        }

        let mut knots: Vec<Knot> = points
            .iter()
            .map(|&point| Knot {
                point,
                left: Side::Open,
                right: Side::Open,
                left_tension: 1.0,
                right_tension: 1.0,
                pre: point,
                post: point,
            })
            .collect();
        for (k, join) in joins.iter().enumerate() {
            knots[k].right_tension = join.start.signed();
            knots[(k + 1) % n].left_tension = join.end.signed();
        }
        if !options.closed {
            knots[0].left = Side::Endpoint;
            knots[0].right = Side::Curl(options.start_curl);
            knots[n - 1].left = Side::Curl(options.end_curl);
            knots[n - 1].right = Side::Endpoint;
        }
        make_choices(&mut knots);

        let knots: Vec<HobbyKnot> = knots
            .iter()
            .map(|k| HobbyKnot { point: k.point, precontrol: k.pre, postcontrol: k.post })
            .collect();
        let centroid = points.iter().copied().sum::<DVec2>() / n as f64;
        Ok(Self { knots, closed: options.closed, scale: spread(&points, centroid) })
    }

    /// The METAPOST path through `points`.
    ///
    /// # Panics
    ///
    /// Panics on invalid input; see [`HobbyCurve::try_new`].
    #[must_use]
    pub fn new(points: Vec<DVec2>, options: &HobbyOptions) -> Self {
        Self::try_new(points, options).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The knots with their control points, as METAPOST reports them.
    #[must_use]
    pub fn knots(&self) -> &[HobbyKnot] {
        &self.knots
    }

    /// True for a closed path.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The number of cubic segments s: n for a closed path, n − 1 for an open one.
    #[must_use]
    pub fn n_segments(&self) -> usize {
        if self.closed { self.knots.len() } else { self.knots.len() - 1 }
    }

    /// The four control points of segment `k`, or `None` if k ≥ s.
    #[must_use]
    pub fn segment(&self, k: usize) -> Option<[DVec2; 4]> {
        if k >= self.n_segments() {
            return None;
        }
        let (a, b) = (&self.knots[k], &self.knots[(k + 1) % self.knots.len()]);
        Some([a.point, a.postcontrol, b.precontrol, b.point])
    }

    /// The path as a chain of cubic Bézier segments, segment k on u ∈ [k/s, (k+1)/s] (the
    /// same parametrisation as [`ParamCurve::eval`]).
    ///
    /// # Panics
    ///
    /// Never: a Hobby curve has at least one segment.
    #[must_use]
    pub fn to_bezier(&self) -> PiecewiseBezier<DVec2> {
        let segments = (0..self.n_segments())
            .filter_map(|k| self.segment(k))
            .map(|control| BezierCurve::new(control.to_vec()))
            .collect();
        PiecewiseBezier::try_new(segments).expect("a Hobby curve has at least one segment")
    }

    /// The segment and the local time of the parameter t, scaled by s (u = s·t).
    fn locate(&self, t: f64) -> ([DVec2; 4], f64) {
        let s = self.n_segments();
        let t = if self.closed { t - t.floor() } else { t };
        let u = t * s as f64;
        // Clamping keeps a closed curve's t just below 1 in the last segment and extends an
        // open curve by its end polynomials.
        let k = u.floor().clamp(0.0, (s - 1) as f64) as usize;
        (self.segment(k).expect("k < s by the clamp"), u - k as f64)
    }
}

impl ParamCurve<DVec2> for HobbyCurve {
    fn eval(&self, t: f64) -> DVec2 {
        self.eval_deriv(t, 0)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> DVec2 {
        let ([p0, p1, p2, p3], x) = self.locate(t);
        let y = 1.0 - x;
        let s = self.n_segments() as f64;
        match order {
            0 => {
                // de Casteljau, as lerps: exact for a degenerate (constant) segment.
                let lerp = |a: DVec2, b: DVec2| a + (b - a) * x;
                let (l1, l2, l3) = (lerp(p0, p1), lerp(p1, p2), lerp(p2, p3));
                let (m1, m2) = (lerp(l1, l2), lerp(l2, l3));
                lerp(m1, m2)
            }
            1 => {
                ((p1 - p0) * (y * y) + (p2 - p1) * (2.0 * x * y) + (p3 - p2) * (x * x)) * (3.0 * s)
            }
            2 => ((p2 - p1 * 2.0 + p0) * y + (p3 - p2 * 2.0 + p1) * x) * (6.0 * s * s),
            3 => (p3 - p2 * 3.0 + p1 * 3.0 - p0) * (6.0 * s * s * s),
            _ => DVec2::ZERO,
        }
    }

    fn scale(&self) -> f64 {
        self.scale
    }

    fn is_periodic(&self) -> bool {
        self.closed
    }
}

/// Hobby's velocity function ρ(θ, φ) (Hardy 2005, §2.14; Hobby 1986, eq. 10): the length of
/// the first control arm of a segment with unit chord and tension 1, times 3, when the
/// tangent at its start turns by θ and the tangent at its end by φ from the chord.
///
/// ρ(θ, φ) = (2 + α) / (1 + (1 − c)·cos θ + c·cos φ),
/// α = a·(sin θ − b·sin φ)·(sin φ − b·sin θ)·(cos θ − cos φ),
///
/// with a = √2, b = 1/16, c = (3 − √5)/2. (METAPOST limits ρ/(3τ) to 4.)
///
/// # Examples
///
/// ```
/// use hi_compare::hobby::{rho, sigma};
///
/// // A circular arc of angle 2θ: θ = φ, and ρ = 2/(1 + cos θ).
/// let theta = std::f64::consts::PI / 7.0;
/// assert!((rho(theta, theta) - 2.0 / (1.0 + theta.cos())).abs() < 1e-15);
/// assert_eq!(sigma(0.3, 0.1), rho(0.1, 0.3));
/// ```
#[must_use]
pub fn rho(theta: f64, phi: f64) -> f64 {
    let (st, ct) = theta.sin_cos();
    let (sf, cf) = phi.sin_cos();
    let c = (3.0 - 5f64.sqrt()) / 2.0;
    let alpha = HOBBY_A * (st - HOBBY_B * sf) * (sf - HOBBY_B * st) * (ct - cf);
    (2.0 + alpha) / (1.0 + (1.0 - c) * ct + c * cf)
}

/// Hobby's velocity function for the second control arm, σ(θ, φ) = ρ(φ, θ) (Hardy 2005,
/// §2.14).
#[must_use]
pub fn sigma(theta: f64, phi: f64) -> f64 {
    rho(phi, theta)
}

fn check_tension(tension: Tension) -> Result<(), Error> {
    if tension.value.is_finite() && tension.value >= MIN_TENSION {
        Ok(())
    } else {
        Err(Error::Curve(CurveError::ParameterOutOfBounds {
            name: "tension",
            value: tension.value,
            expected: "a finite number of at least 3/4 (METAPOST's smallest tension)",
        }))
    }
}

fn check_curl(curl: f64) -> Result<(), Error> {
    if curl.is_finite() && curl >= 0.0 {
        Ok(())
    } else {
        Err(Error::Curve(CurveError::ParameterOutOfBounds {
            name: "curl",
            value: curl,
            expected: "a finite non-negative number",
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::choices::curl_ratio;
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn regular_heptagon_arm_is_rho_times_chord() {
        let points: Vec<DVec2> =
            (0..7).map(|k| DVec2::from_angle(2.0 * PI * k as f64 / 7.0)).collect();
        let curve = HobbyCurve::new(points, &HobbyOptions::closed());
        let theta = PI / 7.0;
        let arm = rho(theta, theta) / 3.0 * 2.0 * theta.sin();
        assert!((arm - 0.304_324_632_520_2).abs() < 1e-16, "{arm}");
        for knot in curve.knots() {
            assert!(((knot.postcontrol - knot.point).length() - arm).abs() < 1e-15);
            assert!(((knot.precontrol - knot.point).length() - arm).abs() < 1e-15);
        }
    }

    #[test]
    fn curl_ratio_matches_closed_form_when_alpha_at_most_beta() {
        for (gamma, a, b) in [(1.0, 2.0, 1.0), (0.5, 3.0, 0.8), (2.0, 1.0, 1.0), (0.0, 1.5, 1.5)] {
            let (alpha, beta): (f64, f64) = (1.0 / a, 1.0 / b);
            let exact = ((3.0 - alpha) * alpha * alpha * gamma + beta.powi(3))
                / (alpha.powi(3) * gamma + (3.0 - beta) * beta * beta);
            assert!((curl_ratio(gamma, a, b) - exact.min(4.0)).abs() < 1e-14, "{gamma} {a} {b}");
        }
    }

    #[test]
    fn rejects_bad_input() {
        let pts = vec![DVec2::ZERO, DVec2::X, DVec2::Y];
        let bad_tension = HobbyOptions::closed().with_tension(Tension::new(0.5));
        assert!(matches!(
            HobbyCurve::try_new(pts.clone(), &bad_tension),
            Err(Error::Curve(CurveError::ParameterOutOfBounds { name: "tension", .. }))
        ));
        let nan_tension = HobbyOptions::closed().with_tension(Tension::at_least(f64::NAN));
        assert!(HobbyCurve::try_new(pts.clone(), &nan_tension).is_err());
        let bad_curl = HobbyOptions::open().with_curls(-1.0, 1.0);
        assert!(matches!(
            HobbyCurve::try_new(pts.clone(), &bad_curl),
            Err(Error::Curve(CurveError::ParameterOutOfBounds { name: "curl", .. }))
        ));
        let joins = HobbyOptions::open().with_joins(vec![Join::default(); 3]);
        assert!(matches!(
            HobbyCurve::try_new(pts.clone(), &joins),
            Err(Error::Curve(CurveError::InvalidCount { .. }))
        ));
        assert!(
            HobbyCurve::try_new(
                pts.clone(),
                &HobbyOptions::closed().with_joins(vec![Join::default(); 3])
            )
            .is_ok()
        );
        assert_eq!(
            HobbyCurve::try_new(vec![], &HobbyOptions::open()),
            Err(Error::Curve(CurveError::Empty))
        );
        assert_eq!(
            HobbyCurve::try_new(vec![DVec2::ZERO, DVec2::NAN], &HobbyOptions::open()),
            Err(Error::Curve(CurveError::NonFinitePoint { index: 1 }))
        );
        // A closed curve's curls are ignored, whatever they are.
        assert!(
            HobbyCurve::try_new(pts, &HobbyOptions::closed().with_curls(-1.0, f64::NAN)).is_ok()
        );
    }

    #[test]
    fn coincident_points_give_degenerate_segments() {
        let a = DVec2::new(1.0, 2.0);
        for options in [HobbyOptions::open(), HobbyOptions::closed()] {
            let curve = HobbyCurve::new(vec![a, a, a], &options);
            for knot in curve.knots() {
                assert_eq!((knot.precontrol, knot.postcontrol), (a, a));
            }
            assert_eq!(curve.eval(0.3), a);
            assert_eq!(curve.curvature(0.3), None);
        }
    }

    #[test]
    fn derivatives_match_finite_differences() {
        let pts =
            vec![DVec2::ZERO, DVec2::new(3.0, 1.0), DVec2::new(4.0, 4.0), DVec2::new(1.0, 5.0)];
        for options in [HobbyOptions::open(), HobbyOptions::closed()] {
            let curve = HobbyCurve::new(pts.clone(), &options);
            let h = 1e-6;
            for t in [0.05, 0.3, 0.61, 0.9] {
                for order in 0..3 {
                    let fd = (curve.eval_deriv(t + h, order) - curve.eval_deriv(t - h, order))
                        / (2.0 * h);
                    let d = curve.eval_deriv(t, order + 1);
                    assert!((fd - d).length() < 1e-5 * d.length().max(1.0), "{t} {order}");
                }
            }
        }
    }
}
