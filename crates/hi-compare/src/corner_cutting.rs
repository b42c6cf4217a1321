// SPDX-License-Identifier: MIT
//! Curve subdivision: Chaikin's corner cutting and the interpolatory 4-point scheme
//! (Hardy 2005, §4.5, figures 4.6 and 4.7).
//!
//! Both refine a polygon P⁰ = (x₀, …, xₙ₋₁) step by step, P^(k+1) from P^k, and converge to a
//! smooth limit curve P^∞:
//!
//! - Chaikin [1974]: every edge (xᵢ, xᵢ₊₁) is replaced by its points at ¼ and ¾,
//!   x^(k+1)₂ᵢ = ¾·xᵢ + ¼·xᵢ₊₁, x^(k+1)₂ᵢ₊₁ = ¼·xᵢ + ¾·xᵢ₊₁. The limit is the uniform quadratic
//!   B-spline with control polygon P⁰ ([`ChaikinCurve`] evaluates it exactly).
//! - Dyn, Levin and Gregory's 4-point scheme [1987]: the old points stay, x^(k+1)₂ᵢ = xᵢ, and a
//!   new point goes in every edge, x^(k+1)₂ᵢ₊₁ = (½ + w)(xᵢ + xᵢ₊₁) − w(xᵢ₋₁ + xᵢ₊₂), with the
//!   tension w = 1/16 by default (it then reproduces cubic polynomials). The limit has no
//!   closed form; [`FourPointCurve`] gives the refined polygons, whose points all lie on it.
//!
//! Closed polygons are refined cyclically (indices modulo the number of points), as in the
//! thesis. The end rules for open polygons are documented on each type.
//!
//! [1974]: https://doi.org/10.1016/0146-664X(74)90028-8
//! [1987]: https://doi.org/10.1016/0167-8396(87)90001-X

use crate::check::{MAX_SAMPLES, spread};
use crate::check::{check_param, check_points};
use crate::{ControlPoint, Error};
use hi_curve::Error as CurveError;
use hi_curve::ParamCurve;

/// The default tension w = 1/16 of the 4-point scheme: the midpoint of the cubic through four
/// consecutive points.
pub const DEFAULT_FOUR_POINT_WEIGHT: f64 = 1.0 / 16.0;

/// Chaikin's corner cutting and its limit, the uniform quadratic B-spline (Hardy 2005, §4.5,
/// figure 4.6).
///
/// **Closed** polygons of n points: each step maps n points to 2n. The limit is the periodic
/// uniform quadratic B-spline with control points x₀, …, xₙ₋₁: n segments, segment j with
/// control points xⱼ, xⱼ₊₁, xⱼ₊₂ (indices mod n) running from the midpoint of edge j to the
/// midpoint of edge j + 1, tangent to the polygon there.
///
/// **Open** polygons keep their end points: each step maps (x₀, …, xₙ₋₁) to x₀, the cuts of
/// the n − 1 edges, xₙ₋₁ (2n points). That is plain corner cutting (every edge cut, no point
/// kept) of the polygon with doubled ends, x₀, x₀, x₁, …, xₙ₋₁, xₙ₋₁, so the limit is the
/// uniform quadratic B-spline with that control polygon: n segments from x₀ to xₙ₋₁,
/// straight along the first and the last half edges. (Its parametrisation has X′ = 0 at the
/// two ends.)
///
/// As a [`ParamCurve`], t ∈ [0, 1] covers the n segments uniformly, segment j on
/// [j/n, (j+1)/n]; the closed curve is 1-periodic and starts at (x₀ + x₁)/2. The midpoints
/// of the edges of P^k (with doubled ends when open) lie on the limit: edge m at
/// t = m/(n·2^k).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ParamCurve;
/// use hi_compare::corner_cutting::ChaikinCurve;
///
/// let square = vec![DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
/// let curve = ChaikinCurve::try_new(square, true).unwrap();
/// let polygons = curve.refine(2).unwrap();
/// assert_eq!(polygons[1][0], DVec2::new(0.25, 0.0)); // ¾·x₀ + ¼·x₁
/// assert_eq!(polygons[2].len(), 16);
/// // The limit passes through the edge midpoints, tangent to the edges.
/// assert_eq!(curve.eval(0.0), DVec2::new(0.5, 0.0));
/// assert!(curve.eval_deriv(0.0, 1).y.abs() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ChaikinCurve<P> {
    // Invariant: at least two points, all finite.
    points: Vec<P>,
    closed: bool,
    scale: f64,
}

impl<P: ControlPoint> ChaikinCurve<P> {
    /// Chaikin's scheme on the polygon `points`, closed or open.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`] for no points, [`hi_curve::Error::NonFinitePoint`] for a NaN or infinite
    /// coordinate, [`Error::TooFewPoints`] for a single point.
    pub fn try_new(points: Vec<P>, closed: bool) -> Result<Self, Error> {
        check_polygon(&points, "Chaikin's scheme")?;
        let scale = polygon_scale(&points);
        Ok(Self { points, closed, scale })
    }

    /// Chaikin's scheme on the polygon `points`.
    ///
    /// # Panics
    ///
    /// Panics on invalid input; see [`ChaikinCurve::try_new`].
    #[must_use]
    pub fn new(points: Vec<P>, closed: bool) -> Self {
        Self::try_new(points, closed).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The control polygon P⁰.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// True for a closed polygon.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The polygons P⁰, P¹, …, P^steps (each step doubles the number of points).
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::InvalidCount`] if P^steps would have more than 2²⁸ points.
    pub fn refine(&self, steps: usize) -> Result<Vec<Vec<P>>, Error> {
        check_steps(steps, self.points.len(), |m| 2 * m)?;
        let mut res = Vec::with_capacity(steps + 1);
        let mut current = self.points.clone();
        for _ in 0..steps {
            let next = chaikin_step(&current, self.closed);
            res.push(std::mem::replace(&mut current, next));
        }
        res.push(current);
        Ok(res)
    }

    /// The number of quadratic segments of the limit, n (open or closed).
    #[must_use]
    pub fn n_segments(&self) -> usize {
        self.points.len()
    }

    /// Control point i of the limit B-spline: xᵢ mod n when closed, the polygon with doubled
    /// ends when open.
    fn control(&self, i: usize) -> P {
        let n = self.points.len();
        if self.closed { self.points[i % n] } else { self.points[i.saturating_sub(1).min(n - 1)] }
    }
}

/// One step of Chaikin's scheme (Hardy 2005, §4.5): the ¼ and ¾ points of every edge; an open
/// polygon keeps its two end points.
///
/// # Examples
///
/// ```
/// use hi_compare::corner_cutting::chaikin_step;
///
/// assert_eq!(chaikin_step(&[0.0, 4.0, 8.0], false), vec![0.0, 1.0, 3.0, 5.0, 7.0, 8.0]);
/// assert_eq!(chaikin_step(&[0.0, 4.0], true), vec![1.0, 3.0, 3.0, 1.0]);
/// ```
#[must_use]
pub fn chaikin_step<P: ControlPoint>(polygon: &[P], closed: bool) -> Vec<P> {
    let n = polygon.len();
    let n_edges = if closed { n } else { n.saturating_sub(1) };
    let mut res = Vec::with_capacity(2 * n);
    if !closed && let Some(&first) = polygon.first() {
        res.push(first);
    }
    for i in 0..n_edges {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        res.push(a * 0.75 + b * 0.25);
        res.push(a * 0.25 + b * 0.75);
    }
    if !closed && n >= 2 {
        res.push(polygon[n - 1]);
    }
    res
}

impl<P: ControlPoint> ParamCurve<P> for ChaikinCurve<P> {
    fn eval(&self, t: f64) -> P {
        self.eval_deriv(t, 0)
    }

    /// Derivatives of the quadratic B-spline segment containing t (the segment that starts at
    /// t when t is a join, where the curve is C¹ but X″ jumps).
    fn eval_deriv(&self, t: f64, order: usize) -> P {
        let n = self.points.len();
        let t = if self.closed { t - t.floor() } else { t };
        let u = t * n as f64;
        // Clamping extends an open curve by its end segments.
        let j = u.floor().clamp(0.0, (n - 1) as f64) as usize;
        let s = u - j as f64;
        let (a, b, c) = (self.control(j), self.control(j + 1), self.control(j + 2));
        let m = n as f64;
        match order {
            0 => a * (0.5 * (1.0 - s) * (1.0 - s)) + b * (0.5 + s - s * s) + c * (0.5 * s * s),
            1 => (a * (s - 1.0) + b * (1.0 - 2.0 * s) + c * s) * m,
            2 => (a - b * 2.0 + c) * (m * m),
            _ => P::ZERO,
        }
    }

    fn scale(&self) -> f64 {
        self.scale
    }

    fn is_periodic(&self) -> bool {
        self.closed
    }
}

/// The interpolatory 4-point scheme of Dyn, Levin and Gregory (Hardy 2005, §4.5, figure 4.7).
///
/// Each step keeps every point and inserts one in every edge,
/// x^(k+1)₂ᵢ₊₁ = (½ + w)(xᵢ + xᵢ₊₁) − w(xᵢ₋₁ + xᵢ₊₂). With w = 0 it is linear interpolation;
/// for 0 < w < 1/8 the limit is C¹ (the thesis's range); w = 1/16 (the default) inserts the
/// midpoint of the cubic through the four points, so the scheme reproduces cubic polynomials
/// sampled at uniform parameters.
///
/// **Closed** polygons: indices modulo n; n points become 2n.
///
/// **Open** polygons (end rule): the missing neighbour x₋₁ (or xₙ) of the first (or last)
/// edge is extrapolated by the polynomial of degree min(3, n − 1) through the first (or last)
/// min(4, n) points — x₋₁ = 4x₀ − 6x₁ + 4x₂ − x₃ for n ≥ 4. The scheme then reproduces cubics
/// up to the ends (for w = 1/16, the first new point is (5x₀ + 15x₁ − 5x₂ + x₃)/16). n points
/// become 2n − 1 and the end points stay.
///
/// The limit curve has no closed form and no [`ParamCurve`] here: it is approximated by the
/// refined polygon. Since the scheme is interpolatory, every point of P^k lies exactly on the
/// limit: point i of P^k is P^∞(i/(n·2^k)) when closed and P^∞(i/((n − 1)·2^k)) when open,
/// with the parameter of the thesis's figures (x₀ at 0, one unit of 1/n or 1/(n − 1) per
/// edge of P⁰).
///
/// # Examples
///
/// ```
/// use hi_compare::corner_cutting::FourPointCurve;
///
/// // Samples of the cubic t³ at t = 0, 1, 2, 3, 4: the refined polygon samples it at halves.
/// let scheme = FourPointCurve::try_new(vec![0.0, 1.0, 8.0, 27.0, 64.0], false).unwrap();
/// let polygons = scheme.refine(3).unwrap();
/// assert_eq!(polygons[3].len(), 33);
/// for (i, x) in polygons[3].iter().enumerate() {
///     let t = i as f64 / 8.0;
///     assert!((x - t * t * t).abs() < 1e-12);
/// }
/// assert_eq!(polygons[1][2], 1.0); // the old points stay
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct FourPointCurve<P> {
    // Invariant: at least two points, all finite; 0 ≤ weight ≤ 1/8.
    points: Vec<P>,
    closed: bool,
    weight: f64,
}

impl<P: ControlPoint> FourPointCurve<P> {
    /// The 4-point scheme with the default tension w = 1/16 on the polygon `points`.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`] for no points, [`hi_curve::Error::NonFinitePoint`] for a NaN or infinite
    /// coordinate, [`Error::TooFewPoints`] for a single point.
    pub fn try_new(points: Vec<P>, closed: bool) -> Result<Self, Error> {
        Self::try_with_weight(points, closed, DEFAULT_FOUR_POINT_WEIGHT)
    }

    /// The 4-point scheme with the default tension w = 1/16.
    ///
    /// # Panics
    ///
    /// Panics on invalid input; see [`FourPointCurve::try_new`].
    #[must_use]
    pub fn new(points: Vec<P>, closed: bool) -> Self {
        Self::try_new(points, closed).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The 4-point scheme with tension `weight` = w.
    ///
    /// # Errors
    ///
    /// As [`FourPointCurve::try_new`], and [`hi_curve::Error::NonFiniteParameter`] or
    /// [`hi_curve::Error::ParameterOutOfBounds`] unless 0 ≤ w ≤ 1/8.
    pub fn try_with_weight(points: Vec<P>, closed: bool, weight: f64) -> Result<Self, Error> {
        check_polygon(&points, "the 4-point scheme")?;
        check_param("w", weight)?;
        if !(0.0..=0.125).contains(&weight) {
            return Err(Error::Curve(CurveError::ParameterOutOfBounds {
                name: "w",
                value: weight,
                expected: "0 <= w <= 1/8 (Hardy 2005, section 4.5)",
            }));
        }
        Ok(Self { points, closed, weight })
    }

    /// The control polygon P⁰, which the limit interpolates.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// True for a closed polygon.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The tension w.
    #[must_use]
    pub fn weight(&self) -> f64 {
        self.weight
    }

    /// The polygons P⁰, P¹, …, P^steps.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::InvalidCount`] if P^steps would have more than 2²⁸ points.
    pub fn refine(&self, steps: usize) -> Result<Vec<Vec<P>>, Error> {
        let closed = self.closed;
        check_steps(steps, self.points.len(), |m| if closed { 2 * m } else { 2 * m - 1 })?;
        let mut res = Vec::with_capacity(steps + 1);
        let mut current = self.points.clone();
        for _ in 0..steps {
            let next = four_point_step(&current, closed, self.weight);
            res.push(std::mem::replace(&mut current, next));
        }
        res.push(current);
        Ok(res)
    }

    /// The parameter of point i of P^k on the limit curve (x₀ at 0, P⁰'s edges of length 1/n
    /// when closed and 1/(n − 1) when open).
    #[must_use]
    pub fn parameter(&self, step: usize, i: usize) -> f64 {
        let n = self.points.len();
        let n_edges = if self.closed { n } else { n - 1 };
        i as f64 / n_edges as f64 * 0.5f64.powi(i32::try_from(step).unwrap_or(i32::MAX))
    }
}

/// One step of the 4-point scheme with tension `weight` (Hardy 2005, §4.5): the old points
/// and a new one in every edge; an open polygon uses the extrapolated end neighbours described
/// on [`FourPointCurve`].
///
/// # Examples
///
/// ```
/// use hi_compare::corner_cutting::four_point_step;
///
/// // Linear data stay linear, for every tension.
/// assert_eq!(four_point_step(&[0.0, 2.0, 4.0], false, 0.125), vec![0.0, 1.0, 2.0, 3.0, 4.0]);
/// ```
#[must_use]
pub fn four_point_step<P: ControlPoint>(polygon: &[P], closed: bool, weight: f64) -> Vec<P> {
    let n = polygon.len();
    let mut res = Vec::with_capacity(2 * n);
    if n < 2 {
        res.extend_from_slice(polygon);
        return res;
    }
    let n_edges = if closed { n } else { n - 1 };
    let (before, after) = if closed {
        (polygon[n - 1], polygon[0])
    } else {
        let reversed: Vec<P> = polygon.iter().rev().take(4).copied().collect();
        (extrapolate(&polygon[..n.min(4)]), extrapolate(&reversed))
    };
    // Point i of the polygon extended by one neighbour on each side.
    let at = |i: isize| -> P {
        if i < 0 {
            before
        } else if i as usize >= n {
            if closed { polygon[i as usize % n] } else { after }
        } else {
            polygon[i as usize]
        }
    };
    for i in 0..n_edges as isize {
        res.push(at(i));
        let inner = at(i) + at(i + 1);
        let outer = at(i - 1) + at(i + 2);
        res.push(inner * (0.5 + weight) - outer * weight);
    }
    if !closed {
        res.push(polygon[n - 1]);
    }
    res
}

/// The value before `points[0]` of the polynomial of degree len − 1 through `points` at
/// unit spacing (2 to 4 points).
fn extrapolate<P: ControlPoint>(points: &[P]) -> P {
    match *points {
        [a, b] => a * 2.0 - b,
        [a, b, c] => a * 3.0 - b * 3.0 + c,
        [a, b, c, d, ..] => a * 4.0 - b * 6.0 + c * 4.0 - d,
        [a] => a,
        [] => P::ZERO,
    }
}

fn check_polygon<P: ControlPoint>(points: &[P], what: &'static str) -> Result<(), Error> {
    check_points(points)?;
    if points.len() < 2 {
        return Err(Error::TooFewPoints { what, needed: 2, got: points.len() });
    }
    Ok(())
}

/// Checks that `steps` refinements, each mapping m points to `grow(m)`, stay within
/// [`MAX_SAMPLES`] points.
fn check_steps(steps: usize, n: usize, grow: impl Fn(usize) -> usize) -> Result<(), Error> {
    let mut m = n;
    for _ in 0..steps {
        m = grow(m);
        if m > MAX_SAMPLES {
            return Err(Error::Curve(CurveError::InvalidCount {
                what: "number of subdivision steps",
                value: steps,
                expected: "few enough that the refined polygon has at most 2^28 points",
            }));
        }
    }
    Ok(())
}

/// The largest distance of a point from the centroid of the polygon.
fn polygon_scale<P: ControlPoint>(points: &[P]) -> f64 {
    let mut centroid = P::ZERO;
    for &p in points {
        centroid += p;
    }
    spread(points, centroid * (1.0 / points.len() as f64))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn rejects_bad_input() {
        assert_eq!(
            ChaikinCurve::<f64>::try_new(vec![], true),
            Err(Error::Curve(CurveError::Empty))
        );
        assert!(matches!(
            ChaikinCurve::try_new(vec![1.0], false),
            Err(Error::TooFewPoints { needed: 2, got: 1, .. })
        ));
        assert_eq!(
            FourPointCurve::try_new(vec![DVec2::ZERO, DVec2::INFINITY], true),
            Err(Error::Curve(CurveError::NonFinitePoint { index: 1 }))
        );
        for w in [-0.01, 0.2] {
            assert!(matches!(
                FourPointCurve::try_with_weight(vec![0.0, 1.0], true, w),
                Err(Error::Curve(CurveError::ParameterOutOfBounds { name: "w", .. }))
            ));
        }
        assert!(matches!(
            FourPointCurve::try_with_weight(vec![0.0, 1.0], true, f64::NAN),
            Err(Error::Curve(CurveError::NonFiniteParameter { .. }))
        ));
        let c = ChaikinCurve::new(vec![0.0, 1.0, 2.0], true);
        assert!(matches!(c.refine(40), Err(Error::Curve(CurveError::InvalidCount { .. }))));
        assert_eq!(c.refine(0).unwrap(), vec![vec![0.0, 1.0, 2.0]]);
    }

    #[test]
    fn extrapolation_is_exact_for_low_degrees() {
        let cubic = |t: f64| 2.0 * t * t * t - t * t + 3.0 * t - 1.0;
        let pts: Vec<f64> = (0..4).map(|i| cubic(i as f64)).collect();
        assert!((extrapolate(&pts) - cubic(-1.0)).abs() < 1e-12);
        let quadratic = |t: f64| t * t - 2.0 * t;
        let pts: Vec<f64> = (0..3).map(|i| quadratic(i as f64)).collect();
        assert!((extrapolate(&pts) - quadratic(-1.0)).abs() < 1e-12);
    }
}
