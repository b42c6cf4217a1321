// SPDX-License-Identifier: MIT
//! Harmonic curves as piecewise Bézier curves (Hardy 2005, §5.7; docs/math.md §4): the thesis's two
//! schemes, which approximate the basis σₖ by piecewise polynomials, and a C1 Hermite scheme
//! that reaches any tolerance, each with its deviation measured and bounded.
//!
//! | scheme | pieces | continuity | deviation |
//! |---|---|---|---|
//! | [`BezierScheme::ThesisCubic`] | n cubics on [a/n, (a+1)/n], through 4 equally spaced samples of each σₖ | C0 | a plateau: ≈ 6.2e-3 of the basis for every n |
//! | [`BezierScheme::ThesisQuintic`] | two quintics between consecutive zeros of σ′, Hermite data (value, σ′, σ″) at the ends and the middle | C2 | a plateau of ≈ 3e-4; the points are not interpolated exactly |
//! | [`BezierScheme::Hermite`] | cubic (or quintic) Hermite pieces of the curve itself, split until a guaranteed bound is below the tolerance | C1 (C2) | below the tolerance |
//!
//! The two thesis schemes are linear maps of the data: a [`BasisPieces`] holds the control
//! values `P[a][k][j]` of the approximation of σₖ on piece a, and [`BasisPieces::apply`] sums
//! them with the points, Σₖ `P[a][k][j]`·xₖ, exactly as the thesis builds its patches. The cubic
//! scheme keeps the partition of unity (the control values of each piece sum to 1 over k), so
//! it is affine invariant, and its ends are Kronecker deltas, so it passes through the points.
//! The quintic scheme does neither exactly: each σₖ is interpolated at its own breaks (the zeros
//! of σₖ′, which miss the nodes j/n, j ≠ k), so Σₖ Sₖ differs from 1, and Sₖ(j/n) from δⱼₖ, by
//! about the scheme's error. That error is a plateau too: 1.5e-4 to 4.3e-4 of the basis for
//! every n (9–25 times below the cubic's), since the pieces shrink with the oscillation.
//!
//! # Deviation: measured and bounded
//!
//! [`BezierReport`] gives the largest and the RMS distance between the curve and its Bézier
//! form on a dense sample (every piece at [`SAMPLES_PER_PIECE`] + 1 points), and a guaranteed
//! bound from the remainder of polynomial interpolation: on a piece of width h,
//!
//! - 4 equally spaced nodes (thesis cubic): |x − p| ≤ h⁴/1944 · max‖x⁗‖;
//! - cubic Hermite (value and derivative at both ends): |x − p| ≤ h⁴/384 · max‖x⁗‖;
//! - quintic Hermite (value and two derivatives at both ends): |x − p| ≤ h⁶/46080 · max‖x⁽⁶⁾‖;
//!
//! with max‖x⁽ᵖ⁾‖ over the piece enclosed by interval arithmetic (`hi-interval`) on the
//! curve's Fourier series, term by term, so the bound holds for every t, not only the sampled.
//! (The thesis quintic approximates each σₖ on its own pieces; its bound is σ's bound on its
//! pieces times Σₖ ‖xₖ‖, as the approximated basis does not sum to one.)
//!
//! The thesis schemes' [`BasisPieces`] are in `basis`.

mod basis;

use hi_bezier::{Aabb, BezierCurve, ControlPoint, PiecewiseBezier};
use hi_interval::Interval;

use crate::{Error, Fourier, HarmonicCurve};

pub use basis::BasisPieces;
use basis::{cubic_hermite, quintic_hermite};

/// Samples per piece for the measured deviation (the ends included: `SAMPLES_PER_PIECE + 1`).
pub const SAMPLES_PER_PIECE: usize = 32;

/// How close a Bézier conversion ([`HarmonicCurve::to_bezier`], and the surfaces' of
/// `hi-surface`) must stay to the harmonic curve or surface: the bound the Hermite schemes
/// refine to (the thesis's schemes have a fixed error and only report it).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Tolerance {
    /// A distance, in the units of the points.
    Absolute(f64),
    /// A fraction of the diagonal of the points' bounding box.
    Relative(f64),
}

/// The tolerance of a conversion unless another is asked for: 10⁻⁴ of the diagonal of the
/// points' bounding box.
pub const DEFAULT_TOLERANCE: Tolerance = Tolerance::Relative(1e-4);

impl Tolerance {
    /// The tolerance as a distance, for points whose bounding box has this diagonal; `None`
    /// when its value is not a finite positive number.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_curve::bezier::{DEFAULT_TOLERANCE, Tolerance};
    ///
    /// assert_eq!(DEFAULT_TOLERANCE.distance(2.0), Some(2e-4));
    /// assert_eq!(Tolerance::Absolute(1e-6).distance(2.0), Some(1e-6));
    /// assert_eq!(Tolerance::Absolute(-1.0).distance(2.0), None);
    /// ```
    #[must_use]
    pub fn distance(self, diagonal: f64) -> Option<f64> {
        let (value, scale) = match self {
            Tolerance::Absolute(value) => (value, 1.0),
            Tolerance::Relative(value) => (value, diagonal.max(f64::MIN_POSITIVE)),
        };
        (value.is_finite() && value > 0.0).then_some(value * scale)
    }

    /// The number given, absolute or relative.
    #[must_use]
    pub fn value(self) -> f64 {
        match self {
            Tolerance::Absolute(value) | Tolerance::Relative(value) => value,
        }
    }
}

/// The most pieces the adaptive Hermite scheme makes before it gives up.
pub const MAX_PIECES: usize = 1 << 20;

/// The degree of the pieces of [`BezierScheme::Hermite`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum HermiteDegree {
    /// Cubic pieces with the value and the first derivative of the curve at both ends: C1.
    #[default]
    Cubic,
    /// Quintic pieces with the value and the first two derivatives at both ends: C2.
    Quintic,
}

/// How a harmonic curve becomes Bézier pieces (§5.7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BezierScheme {
    /// The thesis's cubic scheme (docs/math.md §4): on each [a/n, (a+1)/n] one cubic per σₖ through
    /// σₖ at a/n + i/(3n), i = 0 … 3. C0; the data points are interpolated.
    ThesisCubic,
    /// The thesis's earlier degree-5 scheme: two quintic Hermite pieces (value, σ′, σ″) between
    /// consecutive zeros of σ′, split at the midpoint; the zeros are found by interval Newton
    /// ([`Sigma::deriv_roots`](crate::Sigma::deriv_roots)). The pieces of all σₖ are merged,
    /// so a curve piece ends wherever one σₖ's piece ends.
    ThesisQuintic,
    /// Hermite pieces of the curve itself (value and derivatives of the true curve at the joins),
    /// starting from [a/n, (a+1)/n] and halved until the guaranteed bound is below the tolerance.
    Hermite(HermiteDegree),
}

impl BezierScheme {
    /// The scheme's name on the command line: `thesis-cubic`, `thesis-quintic`, `hermite`,
    /// `hermite-quintic`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            BezierScheme::ThesisCubic => "thesis-cubic",
            BezierScheme::ThesisQuintic => "thesis-quintic",
            BezierScheme::Hermite(HermiteDegree::Cubic) => "hermite",
            BezierScheme::Hermite(HermiteDegree::Quintic) => "hermite-quintic",
        }
    }

    /// The remainder of the scheme's interpolation on a piece of width h, (c, r) with
    /// |x − p| ≤ c·hʳ·max‖x⁽ʳ⁾‖: 4 equally spaced nodes (thesis cubic) c = 1/1944, r = 4
    /// ((h/3)⁴·max|s(s−1)(s−2)(s−3)|/4!, the max being 1); cubic Hermite 1/384, r = 4
    /// ((h/2)⁴/4!); quintic Hermite, also for each σₖ of the thesis quintic, 1/46080, r = 6
    /// ((h/2)⁶/6!).
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_curve::bezier::{BezierScheme, HermiteDegree};
    /// assert_eq!(BezierScheme::Hermite(HermiteDegree::Cubic).remainder(), (1.0 / 384.0, 4));
    /// ```
    #[must_use]
    pub fn remainder(self) -> (f64, usize) {
        match self {
            BezierScheme::ThesisCubic => (1.0 / 1944.0, 4),
            BezierScheme::Hermite(HermiteDegree::Cubic) => (1.0 / 384.0, 4),
            BezierScheme::ThesisQuintic | BezierScheme::Hermite(HermiteDegree::Quintic) => {
                (1.0 / 46080.0, 6)
            }
        }
    }

    /// The scheme of a name of [`BezierScheme::name`].
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            "thesis-cubic" => BezierScheme::ThesisCubic,
            "thesis-quintic" => BezierScheme::ThesisQuintic,
            "hermite" => BezierScheme::Hermite(HermiteDegree::Cubic),
            "hermite-quintic" => BezierScheme::Hermite(HermiteDegree::Quintic),
            _ => return None,
        })
    }
}

/// The piece of the breaks 0 = b₀ < … < bₖ = 1 holding t (taken modulo 1), and the local
/// parameter (t − bₐ)/(bₐ₊₁ − bₐ) in it: how [`BezierSpline`] (and the patches of `hi-surface`,
/// per direction) find their piece.
///
/// # Panics
///
/// If `breaks` has fewer than two values.
///
/// # Examples
///
/// ```
/// let (a, s) = hi_curve::bezier::locate(&[0.0, 0.25, 1.0], 1.625);
/// assert_eq!((a, s), (1, 0.5));
/// ```
#[must_use]
pub fn locate(breaks: &[f64], t: f64) -> (usize, f64) {
    let t = t.rem_euclid(1.0);
    let pieces = breaks.len() - 1;
    let a = breaks.partition_point(|&b| b <= t).saturating_sub(1).min(pieces - 1);
    let (b0, b1) = (breaks[a], breaks[a + 1]);
    (a, ((t - b0) / (b1 - b0)).clamp(0.0, 1.0))
}

/// A closed chain of Bézier pieces over the harmonic parameter: piece a covers
/// t ∈ [`breaks[a]`, `breaks[a+1]`] with local parameter s = (t − `breaks[a]`)/(`breaks[a+1]` − `breaks[a]`).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(bound = "P: ControlPoint + serde::Serialize"))]
pub struct BezierSpline<P> {
    // Invariant: breaks as for BasisPieces; segments.len() = breaks.len() − 1 ≥ 1.
    breaks: Vec<f64>,
    segments: Vec<BezierCurve<P>>,
}

impl<P: ControlPoint> BezierSpline<P> {
    /// The pieces.
    #[must_use]
    pub fn segments(&self) -> &[BezierCurve<P>] {
        &self.segments
    }

    /// The piece boundaries in the harmonic parameter, from 0 to 1.
    #[must_use]
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }

    /// The point at t (taken modulo 1).
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        let (a, s) = locate(&self.breaks, t);
        self.segments[a].eval(s)
    }

    /// The derivative of order `order` with respect to t (one-sided at the breaks: the piece
    /// that starts there).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        let (a, s) = locate(&self.breaks, t);
        let h = self.breaks[a + 1] - self.breaks[a];
        self.segments[a].eval_deriv(s, order) * h.powi(-(order as i32))
    }

    /// The same pieces as a [`PiecewiseBezier`] (piece i on [i/s, (i+1)/s] there: the same
    /// point set, parameterised piece by piece).
    #[must_use]
    pub fn to_piecewise(&self) -> PiecewiseBezier<P> {
        PiecewiseBezier::new(self.segments.clone())
    }

    /// The largest angle (radians) between the tangents on either side of a join, over every
    /// join including the closing one; 0 for a C1 chain (joins where a tangent vanishes are
    /// skipped).
    #[must_use]
    pub fn max_tangent_jump(&self) -> f64 {
        let m = self.segments.len();
        let mut worst: f64 = 0.0;
        for a in 0..m {
            let (left, right) = (&self.segments[a], &self.segments[(a + 1) % m]);
            let (l, r) = (left.eval_deriv(1.0, 1), right.eval_deriv(0.0, 1));
            let (nl, nr) = (l.norm(), r.norm());
            if nl > 0.0 && nr > 0.0 {
                // 2·atan2(|l̂ − r̂|, |l̂ + r̂|): accurate for small angles, unlike acos.
                let (l, r) = (l * (1.0 / nl), r * (1.0 / nr));
                worst = worst.max(2.0 * (l - r).norm().atan2((l + r).norm()));
            }
        }
        worst
    }
}

/// What a conversion achieved (§5.7): pieces, deviation from the harmonic curve (measured and
/// bounded) and continuity.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BezierReport {
    /// Number of Bézier pieces.
    pub pieces: usize,
    /// Degree of the pieces.
    pub degree: usize,
    /// Largest distance between the curve and its Bézier form on the dense sample.
    pub max_deviation: f64,
    /// RMS distance on the dense sample.
    pub rms_deviation: f64,
    /// A guaranteed upper bound of the distance for every t (interval arithmetic; see the
    /// module documentation).
    pub bound: f64,
    /// The largest tangent angle jump at a join, radians.
    pub max_tangent_jump: f64,
}

/// A harmonic curve's Bézier form with its report.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(bound = "P: ControlPoint + serde::Serialize"))]
pub struct CurveBezier<P> {
    /// The pieces.
    pub spline: BezierSpline<P>,
    /// What they achieve.
    pub report: BezierReport,
}

/// An enclosure of sup ‖X⁽ᵖ⁾(t)‖ over t ∈ [t0, t1] for a Fourier series: per coordinate the
/// interval sum of the terms (2πj)ᵖ·[aⱼ cos(2πjt + pπ/2) + bⱼ sin(2πjt + pπ/2)], then the
/// Euclidean norm of the per-coordinate magnitudes, rounded up.
pub(crate) fn deriv_bound<P: ControlPoint>(f: &Fourier<P>, t0: f64, t1: f64, order: usize) -> f64 {
    let t = Interval::new(t0.min(t1), t0.max(t1));
    let two_pi = Interval::PI * Interval::point(2.0);
    let mut sums = vec![Interval::point(0.0); P::DIM];
    for j in 1..=f.degree() {
        let jf = Interval::point(j as f64);
        let w = (two_pi * jf).powi(order as i32);
        let (s, c) = (two_pi * jf * t).sin_cos();
        // Turning by pπ/2: (cos, sin) → (−sin, cos) per quarter turn.
        let (cp, sp) = match order % 4 {
            0 => (c, s),
            1 => (-s, c),
            2 => (-c, -s),
            _ => (s, -c),
        };
        let (a, b) = (f.cos_coeffs()[j], f.sin_coeffs()[j]);
        for (d, sum) in sums.iter_mut().enumerate() {
            let term = (Interval::point(a.coord(d)) * cp + Interval::point(b.coord(d)) * sp) * w;
            *sum += term;
        }
    }
    if order == 0 {
        let a0 = f.cos_coeffs()[0];
        for (d, sum) in sums.iter_mut().enumerate() {
            *sum += Interval::point(a0.coord(d));
        }
    }
    let sq = sums.iter().fold(Interval::point(0.0), |acc, s| {
        let m = Interval::point(s.mag());
        acc + m * m
    });
    sq.sqrt().hi()
}

/// The guaranteed bound of one piece [t0, t1], with a relative margin of 1e-9 for the rounding
/// of the control points.
fn piece_bound<P: ControlPoint>(f: &Fourier<P>, scheme: BezierScheme, t0: f64, t1: f64) -> f64 {
    let (c, p) = scheme.remainder();
    let h = t1 - t0;
    c * h.powi(p as i32) * deriv_bound(f, t0, t1, p) * (1.0 + 1e-9)
}

impl<P: ControlPoint> HarmonicCurve<P> {
    /// The curve as Bézier pieces by `scheme` (§5.7), with the deviation measured on a dense
    /// sample and bounded by interval arithmetic. `tolerance` is the largest deviation the
    /// Hermite scheme may leave, absolute or relative to the diagonal of the points' bounding
    /// box ([`DEFAULT_TOLERANCE`]: 10⁻⁴ of it); the thesis schemes have a fixed number of
    /// pieces and only report theirs.
    ///
    /// # Errors
    ///
    /// [`Error::NonFiniteParameter`] or [`Error::ParameterOutOfBounds`] for a tolerance that is
    /// not finite and positive, or too small to reach with pieces wider than 1e-9;
    /// [`Error::InvalidCount`] for the quintic thesis scheme with n ≤ 2, or if the Hermite
    /// scheme needs more than [`MAX_PIECES`] pieces.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_curve::HarmonicCurve;
    /// use hi_curve::bezier::{BezierScheme, DEFAULT_TOLERANCE, HermiteDegree, Tolerance};
    ///
    /// let square = vec![DVec2::new(1.0, 0.0), DVec2::Y, DVec2::new(-1.0, 0.0), -DVec2::Y];
    /// let curve = HarmonicCurve::new(square);
    /// let cubic = BezierScheme::Hermite(HermiteDegree::Cubic);
    /// let c1 = curve.to_bezier(cubic, Tolerance::Absolute(1e-6))?;
    /// assert!(c1.report.bound <= 1e-6 && c1.report.max_deviation <= c1.report.bound);
    /// assert!(c1.report.max_tangent_jump < 1e-9);
    /// // The thesis's cubic scheme: n pieces, C0, through the points.
    /// let thesis = curve.to_bezier(BezierScheme::ThesisCubic, DEFAULT_TOLERANCE)?;
    /// assert_eq!(thesis.report.pieces, 4);
    /// assert!((thesis.spline.eval(0.25) - DVec2::Y).length() < 1e-15);
    /// # Ok::<(), hi_curve::Error>(())
    /// ```
    pub fn to_bezier(
        &self,
        scheme: BezierScheme,
        tolerance: Tolerance,
    ) -> Result<CurveBezier<P>, Error> {
        let value = tolerance.value();
        if !value.is_finite() {
            return Err(Error::NonFiniteParameter { name: "tolerance", value });
        }
        let Some(tolerance) = tolerance.distance(bounding_diagonal(self.points())) else {
            return Err(Error::ParameterOutOfBounds {
                name: "tolerance",
                value,
                expected: "a positive number",
            });
        };
        let n = self.n();
        let fourier = self.fourier();
        let (spline, bound) = match scheme {
            BezierScheme::ThesisCubic => {
                let spline = BasisPieces::thesis_cubic(n)?.apply(self.points())?;
                let bound = spline
                    .breaks
                    .windows(2)
                    .map(|w| piece_bound(fourier, scheme, w[0], w[1]))
                    .fold(0.0, f64::max);
                (spline, bound)
            }
            BezierScheme::ThesisQuintic => {
                let pieces = BasisPieces::thesis_quintic(n)?;
                let spline = pieces.apply(self.points())?;
                // Each σₖ is σ's approximation shifted, so |σₖ − Sₖ| is bounded by σ's bound
                // on its own pieces; the Sₖ need not sum to one (they are interpolants on
                // different pieces), so the curve's bound is that times Σₖ ‖xₖ‖.
                let sigma_fourier = Fourier::from_points(
                    &(0..n).map(|k| f64::from(u8::from(k == 0))).collect::<Vec<_>>(),
                );
                let basis_bound = pieces
                    .own
                    .windows(2)
                    .map(|w| piece_bound(&sigma_fourier, scheme, w[0], w[1]))
                    .fold(0.0, f64::max);
                let size: f64 = self.points().iter().map(|&x| x.norm()).sum();
                (spline, basis_bound * size)
            }
            BezierScheme::Hermite(degree) => hermite(self, fourier, degree, tolerance)?,
        };
        let (max_deviation, rms_deviation) = measure(self, &spline);
        let report = BezierReport {
            pieces: spline.segments.len(),
            degree: spline.segments[0].degree(),
            max_deviation,
            rms_deviation,
            bound,
            max_tangent_jump: spline.max_tangent_jump(),
        };
        Ok(CurveBezier { spline, report })
    }
}

/// The diagonal of the bounding box of `points` (0 for none).
fn bounding_diagonal<P: ControlPoint>(points: &[P]) -> f64 {
    Aabb::from_points(points).map_or(0.0, |b| b.size().norm())
}

/// The adaptive Hermite pieces and the largest piece bound.
fn hermite<P: ControlPoint>(
    curve: &HarmonicCurve<P>,
    fourier: &Fourier<P>,
    degree: HermiteDegree,
    tolerance: f64,
) -> Result<(BezierSpline<P>, f64), Error> {
    let scheme = BezierScheme::Hermite(degree);
    let n = curve.n().max(1);
    // A stack of pieces to examine, last-in first-out in reverse order so the output is sorted.
    let mut todo: Vec<(f64, f64)> =
        (0..n).rev().map(|a| (a as f64 / n as f64, (a + 1) as f64 / n as f64)).collect();
    let mut breaks = vec![0.0];
    let mut segments = Vec::new();
    let mut worst: f64 = 0.0;
    // The value and derivatives at t that the pieces need (the cubic has no use for the second).
    let data = |t: f64| {
        let second = match degree {
            HermiteDegree::Cubic => P::ZERO,
            HermiteDegree::Quintic => fourier.eval_deriv(t, 2),
        };
        [curve.eval(t), fourier.eval_deriv(t, 1), second]
    };
    let mut end: Option<(f64, [P; 3])> = None;
    while let Some((t0, t1)) = todo.pop() {
        let bound = piece_bound(fourier, scheme, t0, t1);
        if bound > tolerance {
            if t1 - t0 <= 1e-9 {
                return Err(Error::ParameterOutOfBounds {
                    name: "tolerance",
                    value: tolerance,
                    expected: "one the pieces can reach (pieces narrower than 1e-9 would be needed)",
                });
            }
            if segments.len() + todo.len() + 2 > MAX_PIECES {
                return Err(Error::InvalidCount {
                    what: "Bézier pieces needed for the tolerance",
                    value: MAX_PIECES,
                    expected: "a larger tolerance (the limit of pieces was reached)",
                });
            }
            let mid = 0.5 * (t0 + t1);
            todo.push((mid, t1));
            todo.push((t0, mid));
            continue;
        }
        worst = worst.max(bound);
        // Pieces are accepted in order, so each join's data serves the piece ending there and
        // the next one.
        let start = match end.take() {
            Some((t, data)) if t == t0 => data,
            _ => data(t0),
        };
        let stop = data(t1);
        let h = t1 - t0;
        let control = match degree {
            HermiteDegree::Cubic => {
                cubic_hermite([start[0], start[1]], [stop[0], stop[1]], h).to_vec()
            }
            HermiteDegree::Quintic => quintic_hermite(start, stop, h).to_vec(),
        };
        end = Some((t1, stop));
        segments.push(BezierCurve::new(control));
        breaks.push(t1);
    }
    Ok((BezierSpline { breaks, segments }, worst))
}

/// The largest and the RMS distance between the curve and the spline on every piece at
/// [`SAMPLES_PER_PIECE`] + 1 points.
fn measure<P: ControlPoint>(curve: &HarmonicCurve<P>, spline: &BezierSpline<P>) -> (f64, f64) {
    let (mut max, mut sum, mut count) = (0.0_f64, 0.0, 0_usize);
    for (a, seg) in spline.segments.iter().enumerate() {
        let (t0, t1) = (spline.breaks[a], spline.breaks[a + 1]);
        for i in 0..=SAMPLES_PER_PIECE {
            let s = i as f64 / SAMPLES_PER_PIECE as f64;
            let d = (seg.eval(s) - curve.eval(t0 + s * (t1 - t0))).norm();
            max = max.max(d);
            sum += d * d;
            count += 1;
        }
    }
    (max, (sum / count.max(1) as f64).sqrt())
}
