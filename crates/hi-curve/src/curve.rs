// SPDX-License-Identifier: MIT
//! The harmonic curve X(t) = Σₖ σⁿₖ(t)·xₖ (Hardy 2005, eq. 3.15 and 3.25).

use crate::basis::closed_form;
use crate::differential::ParamCurve;
use crate::point::check_points;
use crate::{ControlPoint, DEFAULT_ACCURACY, Error, Fourier, Sigma};

/// Largest number of samples the FFT paths accept in one call (2²⁸ points).
pub(crate) const MAX_SAMPLES: usize = 1 << 28;

/// The harmonic interpolating curve through n points: smooth, 1-periodic, X(k/n) = xₖ
/// (Hardy 2005, §3.2 for odd n, §3.3 for even n).
///
/// Points may be `f64`, [`glam::DVec2`] or [`glam::DVec3`] (any [`ControlPoint`]). The curve
/// keeps its points and their spectrum ([`Fourier`]), computed once by FFT, so both the thesis's
/// direct sum and the spectral paths are available.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_curve::{HarmonicCurve, SpaceCurve};
///
/// // A tour of the cube's vertices in Gray-code order (the stand-in of figure 3.14).
/// let cube: Vec<DVec3> = [0, 1, 3, 2, 6, 7, 5, 4]
///     .iter()
///     .map(|&g| DVec3::new((g & 1) as f64, ((g >> 1) & 1) as f64, ((g >> 2) & 1) as f64))
///     .collect();
/// let curve = HarmonicCurve::try_new(cube.clone()).unwrap();
/// for (k, p) in cube.iter().enumerate() {
///     assert!((curve.eval(k as f64 / 8.0) - *p).length() < 1e-15);
/// }
/// assert!(curve.torsion(0.1).is_some());
/// assert!(HarmonicCurve::<DVec3>::try_new(vec![]).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HarmonicCurve<P> {
    // Invariant: points is non-empty and every coordinate is finite; fourier is its spectrum.
    points: Vec<P>,
    fourier: Fourier<P>,
}

impl<P: ControlPoint> HarmonicCurve<P> {
    /// The harmonic curve through `points`, x₀ at t = 0, xₖ at t = k/n.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no points, [`Error::NonFinitePoint`] for a NaN or infinite
    /// coordinate.
    pub fn try_new(points: Vec<P>) -> Result<Self, Error> {
        check_points(&points)?;
        let fourier = Fourier::from_points(&points);
        Ok(Self { points, fourier })
    }

    /// The harmonic curve through `points`.
    ///
    /// # Panics
    ///
    /// Panics on empty or non-finite input; see [`HarmonicCurve::try_new`].
    #[must_use]
    pub fn new(points: Vec<P>) -> Self {
        Self::try_new(points).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The interpolated points x₀, …, xₙ₋₁.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The number of points n.
    #[must_use]
    pub fn n(&self) -> usize {
        self.points.len()
    }

    /// The basis σⁿ of this curve.
    #[must_use]
    pub fn basis(&self) -> Sigma {
        Sigma::new(self.n())
    }

    /// The spectrum of the curve: X(t) = a₀ + Σⱼ (aⱼ cos 2πjt + bⱼ sin 2πjt).
    #[must_use]
    pub fn fourier(&self) -> &Fourier<P> {
        &self.fourier
    }

    /// The centroid of the points, a₀ = (1/n)·Σₖ xₖ, which is also the mean of X over a period.
    #[must_use]
    pub fn centroid(&self) -> P {
        self.fourier.cos_coeffs()[0]
    }

    /// X(t) = Σₖ σⁿₖ(t)·xₖ by the thesis's direct sum with the closed-form basis, O(n).
    ///
    /// Exact at the nodes up to rounding: X(k/n) = xₖ. A non-finite t gives NaN coordinates.
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        let mut res = P::ZERO;
        closed_form::for_each_value(self.n(), t, |k, s| res += self.points[k] * s);
        res
    }

    /// The derivative X⁽ᵖ⁾(t) of any order, from the spectrum, O(n/2).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        if order == 0 {
            return self.eval(t);
        }
        self.fourier.eval_deriv(t, order)
    }

    /// X at each of `ts`.
    #[must_use]
    pub fn eval_many(&self, ts: &[f64]) -> Vec<P> {
        ts.iter().map(|&t| self.eval(t)).collect()
    }

    /// X(l/N) for l = 0, …, N−1 by FFT (spectral zero-padding, docs/math.md §7): O(N log N).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] unless 1 ≤ N ≤ 2²⁸.
    pub fn sample_uniform(&self, n_samples: usize) -> Result<Vec<P>, Error> {
        self.sample_uniform_deriv(n_samples, 0)
    }

    /// X⁽ᵖ⁾(l/N) for l = 0, …, N−1 by FFT.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] unless 1 ≤ N ≤ 2²⁸.
    pub fn sample_uniform_deriv(&self, n_samples: usize, order: usize) -> Result<Vec<P>, Error> {
        check_count("number of samples", n_samples)?;
        Ok(self.fourier.sample_uniform_deriv(n_samples, order))
    }

    /// Length of the closed curve over one period, to an absolute `accuracy`
    /// ([`DEFAULT_ACCURACY`] is a good default).
    ///
    /// |X′| is smooth and periodic, so the trapezoidal rule on N uniform samples (taken by FFT)
    /// converges geometrically; N doubles from 2n until two estimates agree to `accuracy` or to
    /// rounding (1e-14 relative), up to 2²⁴ samples, where even a curve with a cusp (a kink
    /// in |X′|) has about 1e-14 relative error.
    #[must_use]
    pub fn arclen(&self, accuracy: f64) -> f64 {
        let accuracy = if accuracy > 0.0 { accuracy } else { DEFAULT_ACCURACY };
        let mut n_samples = (2 * self.n()).max(16);
        let mut prev = self.trapezoid_length(n_samples);
        while n_samples < (1 << 24) {
            n_samples *= 2;
            let next = self.trapezoid_length(n_samples);
            if (next - prev).abs() <= accuracy.max(1e-14 * next) {
                return next;
            }
            prev = next;
        }
        prev
    }

    fn trapezoid_length(&self, n_samples: usize) -> f64 {
        let d1 = self.fourier.sample_uniform_deriv(n_samples, 1);
        d1.iter().map(|d| d.norm()).sum::<f64>() / n_samples as f64
    }
}

/// Checks a sample count against 1 ≤ N ≤ [`MAX_SAMPLES`].
pub(crate) fn check_count(what: &'static str, value: usize) -> Result<(), Error> {
    if (1..=MAX_SAMPLES).contains(&value) {
        Ok(())
    } else {
        Err(Error::InvalidCount { what, value, expected: "between 1 and 2^28" })
    }
}

/// The largest distance of a point from the centroid (at least the smallest positive double).
pub(crate) fn spread<P: ControlPoint>(points: &[P], centroid: P) -> f64 {
    points.iter().map(|p| (*p - centroid).norm()).fold(f64::MIN_POSITIVE, f64::max)
}

impl<P: ControlPoint> ParamCurve<P> for HarmonicCurve<P> {
    fn eval(&self, t: f64) -> P {
        HarmonicCurve::eval(self, t)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> P {
        HarmonicCurve::eval_deriv(self, t, order)
    }

    fn scale(&self) -> f64 {
        spread(&self.points, self.centroid())
    }

    fn is_periodic(&self) -> bool {
        true
    }
}
