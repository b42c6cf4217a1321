// SPDX-License-Identifier: MIT
//! The theorems of chapter 5 on a harmonic curve: rotation (Thm 5.1), insertion and reduction
//! (Thm 5.3, §5.4) and harmonic subdivision (§5.2). docs/math.md §2.
//!
//! All of them resample the curve at N uniform parameters, yⱼ = X(j/N + o), which is an
//! inverse FFT of the (shifted) spectrum: O(N log N) where the thesis sums in O(nN).

use crate::curve::{MAX_SAMPLES, check_count, spread};
use crate::point::check_param;
use crate::{ControlPoint, Error, HarmonicCurve};

/// How far a reduced curve (§5.4) strays from the original: the curve through N < n resampled
/// points passes through them, but not through the rest of the original curve.
///
/// With D(t) = X(t) − Y(t), a trigonometric polynomial of degree M = ⌊n/2⌋ made of the
/// discarded (and aliased) spectrum, `max_deviation` is max |D| on a grid of at least 32·M
/// points and `upper_bound` a guaranteed bound of maxₜ |D(t)| (Bernstein's inequality on the
/// grid, or the ℓ¹ norm of the spectrum of D, whichever is smaller). Insertion (N ≥ n) is exact
/// by Theorem 5.3, and both are then 0.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ReductionDeviation {
    /// max |X − Y| measured on a fine uniform grid.
    pub max_deviation: f64,
    /// A guaranteed upper bound of maxₜ |X(t) − Y(t)|.
    pub upper_bound: f64,
}

impl<P: ControlPoint> HarmonicCurve<P> {
    /// Theorem 5.1 exactly as the thesis states it: the n points yⱼ = Σₖ σₖ(j/n + o)·xₖ =
    /// X(j/n + o), and the harmonic curve through them.
    ///
    /// For odd n the new curve is the old one shifted, Y(t) = X(t + o). **For even n it is not**
    /// (docs/math.md §2): Y(t) = X(t + o) + c·sin(πno)·sin(πnt) with c = (1/n)Σₖ(−1)ᵏxₖ, so the
    /// theorem holds only when n·o is an integer (a relabelling of the points) or c = 0 (for
    /// instance a regular polygon). [`HarmonicCurve::rotate`] is exact for every n.
    ///
    /// # Errors
    ///
    /// [`Error::NonFiniteParameter`] if `offset` is NaN or infinite.
    #[doc(alias = "theorem 5.1")]
    pub fn rotate_theorem_5_1(&self, offset: f64) -> Result<Self, Error> {
        check_param("offset", offset)?;
        let n = self.n();
        let steps = offset * n as f64;
        let points = if steps == steps.round() {
            // A whole number of steps: yⱼ = xⱼ₊ₛ exactly.
            let s = (steps.rem_euclid(n as f64)) as usize % n;
            let mut p = self.points().to_vec();
            p.rotate_left(s);
            p
        } else {
            self.fourier().shifted(offset).sample_uniform(n)
        };
        Self::try_new(points)
    }

    /// Exact rotation for every n: a curve Y with Y(t) = X(t + o) for all t.
    ///
    /// For odd n this is [`HarmonicCurve::rotate_theorem_5_1`]. For even n the curve is first
    /// lifted to n + 1 points by Theorem 5.3 (exact), so the result has n + 1 points
    /// (docs/math.md §7).
    ///
    /// # Errors
    ///
    /// [`Error::NonFiniteParameter`] if `offset` is NaN or infinite.
    pub fn rotate(&self, offset: f64) -> Result<Self, Error> {
        check_param("offset", offset)?;
        if self.n() % 2 == 1 {
            return self.rotate_theorem_5_1(offset);
        }
        self.resample(self.n() + 1)?.0.rotate_theorem_5_1(offset)
    }

    /// Theorem 5.3: the N points yⱼ = Σₖ σⁿₖ(j/N)·xₖ = X(j/N) and the harmonic curve through
    /// them, with the error this introduced.
    ///
    /// For N ≥ n (insertion of m = N − n points) the new curve is identical to the old one,
    /// for every n and N (Thm 5.3), and the error is zero. For N < n (reduction, §5.4) the new
    /// curve passes through the N resampled points only; the returned [`ReductionDeviation`] says
    /// how far it strays. Where j·n/N is an integer the point is copied exactly (yⱼ = x_{jn/N}).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] unless 1 ≤ N ≤ 2²⁸.
    #[doc(alias = "theorem 5.3")]
    pub fn resample(&self, n_new: usize) -> Result<(Self, ReductionDeviation), Error> {
        check_count("number of points", n_new)?;
        let n = self.n();
        let mut points = self.fourier().sample_uniform(n_new);
        for (j, y) in points.iter_mut().enumerate() {
            let num = j as u128 * n as u128;
            if num.is_multiple_of(n_new as u128) {
                *y = self.points()[(num / n_new as u128) as usize];
            }
        }
        let curve = Self::try_new(points)?;
        if n_new >= n {
            return Ok((curve, ReductionDeviation::default()));
        }
        let diff = self.fourier().sub(curve.fourier());
        let (max_deviation, upper_bound) = diff.sup_norm();
        Ok((curve, ReductionDeviation { max_deviation, upper_bound }))
    }

    /// Theorem 5.3 with m ≥ 0 inserted points: the same curve through n + m points (exact).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] if n + m exceeds 2²⁸.
    pub fn insert(&self, m: usize) -> Result<Self, Error> {
        let n_new = self.n().saturating_add(m);
        Ok(self.resample(n_new)?.0)
    }

    /// Harmonic subdivision (§5.2), `levels` times: each level doubles the points,
    /// x^{k+1}_{2i} = `x^k_i` and x^{k+1}_{2i+1} = Σⱼ `σⱼ((2i+1)/(2n))·x^k_j`.
    ///
    /// Every level lies on the original curve (level L is X(i/(n·2ᴸ))), so the curve returned
    /// is the same curve through n·2ᴸ points; it is computed in one FFT, and the original points
    /// are copied exactly into every 2ᴸ-th place.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] if n·2ᴸ exceeds 2²⁸.
    pub fn subdivide(&self, levels: u32) -> Result<Self, Error> {
        let n_new = self.subdivided_len(levels)?;
        Ok(self.resample(n_new)?.0)
    }

    /// The point sets of harmonic subdivision at levels 0, 1, …, `levels` (figure 5.2).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] if n·2ᴸ exceeds 2²⁸.
    pub fn subdivision_stages(&self, levels: u32) -> Result<Vec<Vec<P>>, Error> {
        self.subdivided_len(levels)?;
        (0..=levels).map(|l| Ok(self.resample(self.n() << l)?.0.points().to_vec())).collect()
    }

    fn subdivided_len(&self, levels: u32) -> Result<usize, Error> {
        let too_many = Error::InvalidCount {
            what: "subdivision levels",
            value: levels as usize,
            expected: "n·2^levels ≤ 2^28",
        };
        let factor =
            1usize.checked_shl(levels).filter(|_| levels < usize::BITS).ok_or(too_many.clone())?;
        match self.n().checked_mul(factor) {
            Some(len) if len <= MAX_SAMPLES => Ok(len),
            _ => Err(too_many),
        }
    }

    /// The alternating sum c = (1/n)·Σₖ (−1)ᵏ·xₖ of an even-n curve: the cosine coefficient of
    /// the Nyquist frequency, and the size of the defect of Theorem 5.1 (docs/math.md §2).
    /// Zero for odd n.
    #[must_use]
    pub fn alternating_mean(&self) -> P {
        let n = self.n();
        if n % 2 == 1 {
            return P::ZERO;
        }
        self.fourier().cos_coeffs()[n / 2]
    }

    /// The largest distance of a point from the centroid.
    #[must_use]
    pub fn radius(&self) -> f64 {
        spread(self.points(), self.centroid())
    }
}
