// SPDX-License-Identifier: MIT
//! Fairness measures to compare curves by (Hardy 2005, §2.15 curvature and torsion, §3.5
//! curvature plots, §2.4 and §3.8 the convex hull).
//!
//! For any plane [`ParamCurve`](crate::ParamCurve): curvature plot data (t, κ(t)), the
//! largest |κ|, the number of monotone pieces of κ, the bending energy ∫ κ² ds, the length,
//! and the *confinement*: the area of the convex hull of the curve over the area of the convex
//! hull of its points (1 or less when the curve stays in the hull of its control polygon, as
//! Bézier and B-spline curves do, §2.4; above 1 when it bulges out, as interpolating curves
//! do, §3.8). For space curves, curvature and torsion plot data.

use glam::DVec2;
use hi_bezier::{convex_hull_2d, polygon_area};
use hi_curve::Error as CurveError;

use crate::Error;
use crate::check::MAX_SAMPLES;
use crate::check::check_points;
use hi_curve::{PlaneCurve, SpaceCurve};

/// Nodes and weights of 8-point Gauss–Legendre quadrature on [−1, 1] (positive half).
const GAUSS_8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// Relative accuracy the bending energy and the length aim for.
const QUADRATURE_ACCURACY: f64 = 1e-12;

/// Splits the adaptive quadrature may make, per sample interval: the budget that keeps it
/// finite where κ² ds is not integrable (a cusp) or the error sits at rounding level.
const SPLITS_PER_INTERVAL: usize = 16;

/// Relative size of a change of κ, against max |κ|, below which [`fairness`] does not count a
/// turning point of κ (see [`monotone_pieces`]).
pub const MONOTONE_TOLERANCE: f64 = 1e-6;

/// A point of a curvature plot: the parameter and the signed curvature there (`None` where
/// the curve is singular, X′ = 0).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CurvatureSample {
    /// The parameter t.
    pub t: f64,
    /// The signed curvature κ(t), positive where the curve turns left.
    pub curvature: Option<f64>,
}

/// A point of the curvature and torsion plots of a space curve.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SpaceCurvatureSample {
    /// The parameter t.
    pub t: f64,
    /// The curvature κ(t) ≥ 0 (`None` where X′ = 0).
    pub curvature: Option<f64>,
    /// The torsion τ(t) (`None` where X′ × X″ = 0: a singular point or an inflection).
    pub torsion: Option<f64>,
}

/// The fairness numbers of a plane curve; see [`fairness`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Fairness {
    /// The largest |κ| (0 for a straight curve).
    pub max_curvature: f64,
    /// A parameter where |κ| is largest.
    pub max_curvature_at: f64,
    /// The number of maximal pieces on which κ is monotone (1 for constant κ; for a closed
    /// curve, the number of extrema of κ around the cycle).
    pub monotone_pieces: usize,
    /// The bending energy ∫ κ² ds over the curve (one period of a closed curve).
    pub bending_energy: f64,
    /// The estimated absolute error of `bending_energy`. It is tiny for a smooth curve; a large
    /// value (against the energy) means the quadrature ran out of its budget, as it does
    /// near a cusp, where ∫ κ² ds diverges.
    pub bending_energy_error: f64,
    /// The length ∫ ds.
    pub length: f64,
    /// The area of the convex hull of the curve over the area of the convex hull of the
    /// points; `None` when the points are collinear (their hull has no area).
    pub confinement: Option<f64>,
}

/// The curvature plot of a plane curve: (t, κ(t)) at `samples` parameters, t = j/N
/// (j = 0, …, N − 1) for a periodic curve and t = j/(N − 1) (j = 0, …, N − 1) for an open
/// one.
///
/// # Errors
///
/// [`hi_curve::Error::InvalidCount`] unless 2 ≤ `samples` ≤ 2²⁸.
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::HarmonicCurve;
/// use hi_compare::fairness::curvature_plot;
///
/// let circle = HarmonicCurve::new(vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y]);
/// let plot = curvature_plot(&circle, 8).unwrap();
/// assert_eq!(plot[2].t, 0.25);
/// assert!(plot.iter().all(|s| (s.curvature.unwrap() - 1.0).abs() < 1e-12));
/// ```
pub fn curvature_plot<C: PlaneCurve + ?Sized>(
    curve: &C,
    samples: usize,
) -> Result<Vec<CurvatureSample>, Error> {
    let ts = sample_parameters(curve.is_periodic(), samples)?;
    Ok(ts
        .into_iter()
        .map(|t| CurvatureSample { t, curvature: curve.signed_curvature(t) })
        .collect())
}

/// The curvature and torsion plots of a space curve (Hardy 2005, §2.15), at the parameters of
/// [`curvature_plot`].
///
/// # Errors
///
/// [`hi_curve::Error::InvalidCount`] unless 2 ≤ `samples` ≤ 2²⁸.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_curve::HarmonicCurve;
/// use hi_compare::fairness::space_curvature_plot;
///
/// // Four points of a twisted square: a closed space curve with torsion.
/// let pts = vec![DVec3::X, DVec3::new(0.0, 1.0, 0.5), -DVec3::X, DVec3::new(0.0, -1.0, 0.5)];
/// let plot = space_curvature_plot(&HarmonicCurve::new(pts), 16).unwrap();
/// assert!(plot.iter().all(|s| s.curvature.unwrap() > 0.0));
/// assert!(plot.iter().any(|s| s.torsion.unwrap().abs() > 0.1));
/// ```
pub fn space_curvature_plot<C: SpaceCurve + ?Sized>(
    curve: &C,
    samples: usize,
) -> Result<Vec<SpaceCurvatureSample>, Error> {
    let ts = sample_parameters(curve.is_periodic(), samples)?;
    Ok(ts
        .into_iter()
        .map(|t| SpaceCurvatureSample {
            t,
            curvature: curve.curvature(t),
            torsion: curve.torsion(t),
        })
        .collect())
}

/// The fairness numbers of a plane curve, from `samples` parameters (those of
/// [`curvature_plot`]), with `points` its control polygon or data points (for the
/// confinement).
///
/// - **Largest |κ|**: the largest sampled |κ|, refined by a golden-section search over the two
///   sample intervals around it.
/// - **Monotone pieces** of the signed κ: [`monotone_pieces`] of the sampled κ (singular
///   samples left out) with tolerance [`MONOTONE_TOLERANCE`]·max |κ|, periodic for a periodic
///   curve. Constant κ counts as 1 piece.
/// - **Bending energy** ∫ κ² |X′| dt and **length** ∫ |X′| dt: for a periodic curve, the
///   trapezoidal rule on the samples and on the samples with the midpoints added; if the two
///   agree to 10⁻¹² relative (a smooth periodic curve, where the rule converges
///   geometrically) that is the result. Otherwise (open curves, and curves whose curvature
///   jumps at knots, such as piecewise cubic ones) globally adaptive 8-point Gauss–Legendre
///   quadrature starting from the sample intervals: the interval with the largest error is
///   halved until the errors sum to 10⁻¹² relative or 16 splits per sample interval are
///   spent, so it always ends. Singular points (X′ = 0) contribute nothing; near a cusp the
///   true energy diverges (logarithmically): the value is then large, depends on the
///   resolution, and [`Fairness::bending_energy_error`] says so.
/// - **Confinement**: area of the convex hull of the curve's samples over the area of the
///   convex hull of `points`. The sampled hull lies inside the true one, which makes the
///   ratio low by O(N⁻²) relative for a smooth curve ((2π/N)²/6 for a circle: 7·10⁻⁸ at
///   N = 10⁴).
///
/// The hulls are [`hi_bezier::convex_hull_2d`] (Andrew's monotone chain).
///
/// # Errors
///
/// [`hi_curve::Error::InvalidCount`] unless 3 ≤ `samples` ≤ 2²⁸; [`hi_curve::Error::Empty`] or
/// [`hi_curve::Error::NonFinitePoint`] for bad `points`.
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::HarmonicCurve;
/// use hi_compare::fairness::fairness;
///
/// // The harmonic curve through a square's vertices is its circumcircle (radius 1).
/// let square = vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
/// let f = fairness(&HarmonicCurve::new(square.clone()), &square, 4096).unwrap();
/// assert!((f.max_curvature - 1.0).abs() < 1e-12);
/// assert_eq!(f.monotone_pieces, 1);
/// assert!((f.bending_energy - 2.0 * std::f64::consts::PI).abs() < 1e-11);
/// // The circle's area over the square's: π/2.
/// assert!((f.confinement.unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-6);
/// ```
pub fn fairness<C: PlaneCurve + ?Sized>(
    curve: &C,
    points: &[DVec2],
    samples: usize,
) -> Result<Fairness, Error> {
    check_points(points)?;
    if samples < 3 {
        return Err(Error::Curve(CurveError::InvalidCount {
            what: "number of samples",
            value: samples,
            expected: "between 3 and 2^28",
        }));
    }
    let plot = curvature_plot(curve, samples)?;
    let periodic = curve.is_periodic();

    let (max_curvature, max_curvature_at) = max_abs_curvature(curve, &plot);
    let kappas: Vec<f64> = plot.iter().filter_map(|s| s.curvature).collect();
    let monotone_pieces = monotone_pieces(&kappas, periodic, MONOTONE_TOLERANCE * max_curvature);
    let ((bending_energy, length), bending_energy_error) = energy_and_length(curve, &plot);

    let curve_points: Vec<DVec2> = plot.iter().map(|s| curve.eval(s.t)).collect();
    let hull_of_points = convex_hull_area(points);
    let extent = bounding_diagonal(points);
    let confinement = (hull_of_points > 1e-14 * extent * extent)
        .then(|| convex_hull_area(&curve_points) / hull_of_points);

    Ok(Fairness {
        max_curvature,
        max_curvature_at,
        monotone_pieces,
        bending_energy,
        bending_energy_error,
        length,
        confinement,
    })
}

/// The bending energy ∫ κ² ds and the length ∫ ds of a plane curve (one period when
/// periodic), by the quadrature described on [`fairness`] over `samples` sample intervals.
///
/// # Errors
///
/// [`hi_curve::Error::InvalidCount`] unless 2 ≤ `samples` ≤ 2²⁸.
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_compare::fairness::bending_energy;
/// use hi_compare::hobby::{HobbyOptions, HobbyCurve};
///
/// // Three collinear points: a straight segment of length 2, no bending.
/// let line = HobbyCurve::new(vec![DVec2::ZERO, DVec2::X, 2.0 * DVec2::X], &HobbyOptions::open());
/// let (energy, length) = bending_energy(&line, 16).unwrap();
/// assert!(energy.abs() < 1e-20 && (length - 2.0).abs() < 1e-12);
/// ```
pub fn bending_energy<C: PlaneCurve + ?Sized>(
    curve: &C,
    samples: usize,
) -> Result<(f64, f64), Error> {
    let plot = curvature_plot(curve, samples)?;
    Ok(energy_and_length(curve, &plot).0)
}

/// The number of maximal monotone pieces of a sequence of values (samples of κ), robust to
/// noise: a turning point counts only once the values have moved back from the last extreme
/// by more than `tolerance` (hysteresis), so jitter below `tolerance` on a flat stretch is
/// ignored and extrema less prominent than that are merged.
///
/// For an open sequence the count is the number of turning points plus 1. For a `periodic`
/// one (the samples of a closed curve, the last followed by the first) it is the number of
/// extrema around the cycle (every piece runs from one extremum to the next), counted from
/// the largest value. A sequence whose range is within `tolerance` is 1 piece; non-finite
/// values are skipped, and no values give 0.
///
/// # Examples
///
/// ```
/// use hi_compare::fairness::monotone_pieces;
///
/// let wave = [0.0, 1.0, 2.0, 1.0, 0.0, 1.0, 2.0, 1.0];
/// assert_eq!(monotone_pieces(&wave, false, 0.1), 4);
/// assert_eq!(monotone_pieces(&wave, true, 0.1), 4); // two maxima, two minima
/// assert_eq!(monotone_pieces(&[1.0, 1.0 + 1e-12, 1.0], true, 1e-9), 1);
/// assert_eq!(monotone_pieces(&[0.0, 1.0, 0.99, 2.0], false, 0.1), 1); // a dip below tolerance
/// ```
#[must_use]
pub fn monotone_pieces(values: &[f64], periodic: bool, tolerance: f64) -> usize {
    let values: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    let Some(&first) = values.first() else {
        return 0;
    };
    let tolerance = if tolerance.is_finite() { tolerance.abs() } else { 0.0 };
    let (lo, hi) = values.iter().fold((first, first), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    if hi - lo <= tolerance {
        return 1;
    }
    let n = values.len();
    let mut turns = 0;
    if periodic {
        // Start at the largest value, falling, and go once round back to it.
        let start = values.iter().position(|&v| v == hi).unwrap_or(0);
        let mut falling = true;
        let mut extreme = hi;
        for i in 1..=n {
            let v = values[(start + i) % n];
            track(v, &mut falling, &mut extreme, &mut turns, tolerance);
        }
        turns + 1
    } else {
        // Undecided until the values leave the band around the first one.
        let mut direction: Option<(bool, f64)> = None;
        for &v in &values[1..] {
            match &mut direction {
                None if v > first + tolerance => direction = Some((false, v)),
                None if v < first - tolerance => direction = Some((true, v)),
                None => {}
                Some((falling, extreme)) => track(v, falling, extreme, &mut turns, tolerance),
            }
        }
        turns + 1
    }
}

/// One step of the hysteresis: extend the current run or turn.
fn track(v: f64, falling: &mut bool, extreme: &mut f64, turns: &mut usize, tolerance: f64) {
    if *falling {
        if v < *extreme {
            *extreme = v;
        } else if v > *extreme + tolerance {
            *turns += 1;
            *falling = false;
            *extreme = v;
        }
    } else if v > *extreme {
        *extreme = v;
    } else if v < *extreme - tolerance {
        *turns += 1;
        *falling = true;
        *extreme = v;
    }
}

/// The sample parameters: j/N for a periodic curve, j/(N − 1) for an open one.
fn sample_parameters(periodic: bool, samples: usize) -> Result<Vec<f64>, Error> {
    if !(2..=MAX_SAMPLES).contains(&samples) {
        return Err(Error::Curve(CurveError::InvalidCount {
            what: "number of samples",
            value: samples,
            expected: "between 2 and 2^28",
        }));
    }
    let denominator = if periodic { samples } else { samples - 1 } as f64;
    Ok((0..samples).map(|j| j as f64 / denominator).collect())
}

/// The largest sampled |κ| and where, refined by golden-section search on the neighbouring
/// sample intervals.
fn max_abs_curvature<C: PlaneCurve + ?Sized>(curve: &C, plot: &[CurvatureSample]) -> (f64, f64) {
    let best = plot.iter().enumerate().filter_map(|(j, s)| s.curvature.map(|k| (j, k.abs()))).fold(
        None,
        |best: Option<(usize, f64)>, (j, k)| match best {
            Some((_, b)) if b >= k => best,
            _ => Some((j, k)),
        },
    );
    let Some((j, kappa)) = best else {
        return (0.0, 0.0);
    };
    let t = plot[j].t;
    let h = if plot.len() > 1 { (plot[1].t - plot[0].t).abs() } else { 0.0 };
    let (mut a, mut b) = (t - h, t + h);
    if !curve.is_periodic() {
        a = a.max(0.0);
        b = b.min(1.0);
    }
    let f = |t: f64| curve.signed_curvature(t).map_or(f64::NEG_INFINITY, f64::abs);
    // Golden-section search for a maximum of |κ| on [a, b].
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - ratio * (b - a);
    let mut d = a + ratio * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..80 {
        if fc >= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - ratio * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + ratio * (b - a);
            fd = f(d);
        }
    }
    let (t_best, k_best) = if fc >= fd { (c, fc) } else { (d, fd) };
    if k_best > kappa { (k_best, t_best) } else { (kappa, t) }
}

/// κ²|X′| and |X′| at t; singular points give zero.
fn integrands<C: PlaneCurve + ?Sized>(curve: &C, t: f64) -> (f64, f64) {
    match curve.signed_curvature(t) {
        Some(kappa) => {
            let speed = curve.eval_deriv(t, 1).length();
            (kappa * kappa * speed, speed)
        }
        None => (0.0, 0.0),
    }
}

/// ∫ κ² ds and ∫ ds over the sampled parameter range (see [`fairness`]), and the estimated
/// absolute error of the first.
fn energy_and_length<C: PlaneCurve + ?Sized>(
    curve: &C,
    plot: &[CurvatureSample],
) -> ((f64, f64), f64) {
    let n = plot.len();
    let periodic = curve.is_periodic();
    let mut samples = PairSum::default();
    for s in plot {
        samples.add(integrands(curve, s.t));
    }
    let coarse = if periodic {
        let h = 1.0 / n as f64;
        let mut with_midpoints = samples;
        for s in plot {
            with_midpoints.add(integrands(curve, s.t + 0.5 * h));
        }
        let (e1, l1) = samples.scaled(h);
        let (e2, l2) = with_midpoints.scaled(0.5 * h);
        let close =
            |x: f64, y: f64| (x - y).abs() <= QUADRATURE_ACCURACY * y.abs().max(f64::MIN_POSITIVE);
        if close(e1, e2) && close(l1, l2) {
            return ((e2, l2), (e1 - e2).abs());
        }
        (e2, l2)
    } else {
        let h = 1.0 / (n - 1) as f64;
        let (first, last) = (integrands(curve, plot[0].t), integrands(curve, plot[n - 1].t));
        samples.add((-0.5 * (first.0 + last.0), -0.5 * (first.1 + last.1)));
        samples.scaled(h)
    };
    let n_intervals = if periodic { n } else { n - 1 };
    let f = |t: f64| integrands(curve, t);
    let pieces = (0..n_intervals).map(|j| (plot[j].t, if j + 1 < n { plot[j + 1].t } else { 1.0 }));
    // Relative tolerances, with a floor for a straight curve (zero energy), where only
    // rounding noise is left: 10⁻¹² of the energy of a circle as long as the curve.
    let floor = if coarse.1 > 0.0 { 1.0 / coarse.1 } else { 0.0 };
    let tolerance =
        (QUADRATURE_ACCURACY * coarse.0.abs().max(floor), QUADRATURE_ACCURACY * coarse.1.abs());
    adaptive_gauss(&f, pieces, tolerance, SPLITS_PER_INTERVAL * n_intervals)
}

/// Compensated (Neumaier) sums of pairs, so that long sums keep full accuracy.
#[derive(Clone, Copy, Debug, Default)]
struct PairSum {
    sums: [f64; 2],
    compensations: [f64; 2],
}

impl PairSum {
    fn add(&mut self, (a, b): (f64, f64)) {
        for (i, x) in [a, b].into_iter().enumerate() {
            let sum = self.sums[i];
            let next = sum + x;
            self.compensations[i] +=
                if sum.abs() >= x.abs() { (sum - next) + x } else { (x - next) + sum };
            self.sums[i] = next;
        }
    }

    fn scaled(&self, factor: f64) -> (f64, f64) {
        (
            (self.sums[0] + self.compensations[0]) * factor,
            (self.sums[1] + self.compensations[1]) * factor,
        )
    }
}

fn gauss(f: &impl Fn(f64) -> (f64, f64), a: f64, b: f64) -> (f64, f64) {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let (mut e, mut l) = (0.0, 0.0);
    for &(x, w) in &GAUSS_8 {
        let (e1, l1) = f(mid - half * x);
        let (e2, l2) = f(mid + half * x);
        e += w * (e1 + e2);
        l += w * (l1 + l2);
    }
    (half * e, half * l)
}

/// One interval of the globally adaptive quadrature: its bounds, its Gauss estimate from two
/// halves, and the error estimate (difference from the whole-interval estimate).
struct Piece {
    a: f64,
    b: f64,
    value: (f64, f64),
    error: (f64, f64),
}

impl Piece {
    fn new(f: &impl Fn(f64) -> (f64, f64), a: f64, b: f64) -> Self {
        let whole = gauss(f, a, b);
        let mid = 0.5 * (a + b);
        let (left, right) = (gauss(f, a, mid), gauss(f, mid, b));
        let value = (left.0 + right.0, left.1 + right.1);
        Self { a, b, value, error: ((whole.0 - value.0).abs(), (whole.1 - value.1).abs()) }
    }

    /// The error measured against the tolerances (the larger of the two ratios).
    fn badness(&self, tolerance: (f64, f64)) -> f64 {
        let ratio = |e: f64, t: f64| {
            if t > 0.0 {
                e / t
            } else if e > 0.0 {
                f64::MAX
            } else {
                0.0
            }
        };
        ratio(self.error.0, tolerance.0).max(ratio(self.error.1, tolerance.1))
    }
}

/// Globally adaptive Gauss–Kronrod-style quadrature of both integrands over `pieces`: the
/// piece with the largest error is halved until the summed errors are within `tolerance` or
/// `budget` splits are spent (always finite). Returns the two integrals and the estimated
/// absolute error of the first.
fn adaptive_gauss(
    f: &impl Fn(f64) -> (f64, f64),
    pieces: impl Iterator<Item = (f64, f64)>,
    tolerance: (f64, f64),
    budget: usize,
) -> ((f64, f64), f64) {
    let mut all: Vec<Piece> = pieces.map(|(a, b)| Piece::new(f, a, b)).collect();
    let total_error = |all: &[Piece]| {
        all.iter().fold((0.0, 0.0), |acc, p| (acc.0 + p.error.0, acc.1 + p.error.1))
    };
    // A max-heap of (badness, index); stale entries are skipped by comparing the stored value.
    let mut heap: std::collections::BinaryHeap<(OrderedBadness, usize)> =
        all.iter().enumerate().map(|(i, p)| (OrderedBadness(p.badness(tolerance)), i)).collect();
    let (mut error_e, mut error_l) = total_error(&all);
    for _ in 0..budget {
        if error_e <= tolerance.0 && error_l <= tolerance.1 {
            break;
        }
        let Some((OrderedBadness(bad), i)) = heap.pop() else { break };
        if bad == 0.0 {
            break;
        }
        let (a, b) = (all[i].a, all[i].b);
        let mid = 0.5 * (a + b);
        if !(a < mid && mid < b) {
            continue; // cannot be split further in floating point
        }
        error_e -= all[i].error.0;
        error_l -= all[i].error.1;
        all[i] = Piece::new(f, a, mid);
        all.push(Piece::new(f, mid, b));
        for k in [i, all.len() - 1] {
            error_e += all[k].error.0;
            error_l += all[k].error.1;
            heap.push((OrderedBadness(all[k].badness(tolerance)), k));
        }
    }
    let mut total = PairSum::default();
    for p in &all {
        total.add(p.value);
    }
    (total.scaled(1.0), total_error(&all).0)
}

/// A badness that orders by `total_cmp`, for the heap.
#[derive(Clone, Copy, Debug, PartialEq)]
struct OrderedBadness(f64);

impl Eq for OrderedBadness {}

impl PartialOrd for OrderedBadness {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for OrderedBadness {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}

fn convex_hull_area(points: &[DVec2]) -> f64 {
    polygon_area(&convex_hull_2d(points)).abs()
}

/// The diagonal of the bounding box of `points`.
fn bounding_diagonal(points: &[DVec2]) -> f64 {
    let lo = points.iter().copied().fold(DVec2::INFINITY, DVec2::min);
    let hi = points.iter().copied().fold(DVec2::NEG_INFINITY, DVec2::max);
    (hi - lo).length()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hull_area_of_known_sets() {
        let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y, DVec2::splat(0.5)];
        assert!((convex_hull_area(&square) - 1.0).abs() < 1e-15);
        let line = [DVec2::ZERO, DVec2::X, DVec2::splat(2.0) * DVec2::X];
        assert_eq!(convex_hull_area(&line), 0.0);
        let triangle = [DVec2::ZERO, DVec2::new(4.0, 0.0), DVec2::new(0.0, 3.0), DVec2::ONE];
        assert!((convex_hull_area(&triangle) - 6.0).abs() < 1e-15);
        assert_eq!(convex_hull_area(&[DVec2::ONE, DVec2::ONE]), 0.0);
    }

    #[test]
    fn monotone_pieces_rules() {
        assert_eq!(monotone_pieces(&[], true, 0.0), 0);
        assert_eq!(monotone_pieces(&[3.0], false, 0.0), 1);
        assert_eq!(monotone_pieces(&[0.0, 1.0, 2.0, 3.0], false, 0.0), 1);
        assert_eq!(monotone_pieces(&[0.0, 1.0, 2.0, 3.0], true, 0.0), 2); // a max and a min
        assert_eq!(monotone_pieces(&[0.0, 2.0, 1.0, 3.0], false, 0.5), 3);
        assert_eq!(monotone_pieces(&[1.0, f64::NAN, 2.0, 1.0], false, 0.1), 2);
        // Noise on a flat stretch between a rise and a fall does not count.
        let noisy = [0.0, 1.0, 1.0 + 1e-9, 1.0 - 1e-9, 1.0 + 2e-9, 0.0];
        assert_eq!(monotone_pieces(&noisy, false, 1e-6), 2);
    }

    #[test]
    fn sample_parameters_cover_the_range() {
        assert_eq!(sample_parameters(true, 4).unwrap(), vec![0.0, 0.25, 0.5, 0.75]);
        assert_eq!(sample_parameters(false, 3).unwrap(), vec![0.0, 0.5, 1.0]);
        assert!(sample_parameters(false, 1).is_err());
    }
}
