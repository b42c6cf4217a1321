// SPDX-License-Identifier: MIT
//! Reference computations, for tests, benchmarks and the figures that compare methods: the
//! thesis's direct sums beside the spectral (FFT) paths of [`HarmonicCurve`]. Each gives the
//! same result as a faster method of the curve, named in its documentation; none is the way
//! to compute anything.
//!
//! Compiled only with the crate's `testing` feature.

use crate::curve::check_count;
use crate::{ControlPoint, Error, HarmonicCurve};

/// X(l/N) for l = 0, …, N−1 by the thesis's direct sum (§3.3): O(n·N). The same points as
/// [`HarmonicCurve::sample_uniform`] (O(N log N)), to about 1e-15 relative.
///
/// # Errors
///
/// [`Error::InvalidCount`] unless 1 ≤ N ≤ 2²⁸.
///
/// # Examples
///
/// ```
/// use hi_curve::{HarmonicCurve, testing};
///
/// let curve = HarmonicCurve::try_new(vec![0.0, 1.0, 0.5, -2.0, 0.25])?;
/// let (fast, direct) = (curve.sample_uniform(40)?, testing::sample_uniform_direct(&curve, 40)?);
/// assert!(fast.iter().zip(&direct).all(|(a, b)| (a - b).abs() < 1e-14));
/// # Ok::<(), hi_curve::Error>(())
/// ```
pub fn sample_uniform_direct<P: ControlPoint>(
    curve: &HarmonicCurve<P>,
    n_samples: usize,
) -> Result<Vec<P>, Error> {
    check_count("number of samples", n_samples)?;
    Ok((0..n_samples).map(|l| curve.eval(l as f64 / n_samples as f64)).collect())
}

/// One step of harmonic subdivision (§5.2) by the thesis's direct formula, O(n²): the 2n
/// points with x₂ᵢ = xᵢ and x₂ᵢ₊₁ = Σⱼ σⱼ((2i + 1)/(2n))·xⱼ. The same points as
/// [`HarmonicCurve::subdivide`] with one level (an FFT, O(n log n)).
#[must_use]
pub fn subdivide_step_direct<P: ControlPoint>(curve: &HarmonicCurve<P>) -> Vec<P> {
    let n = curve.n();
    let mut out = Vec::with_capacity(2 * n);
    for (i, p) in curve.points().iter().enumerate() {
        out.push(*p);
        out.push(curve.eval((2 * i + 1) as f64 / (2 * n) as f64));
    }
    out
}
