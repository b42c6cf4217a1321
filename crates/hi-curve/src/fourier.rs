// SPDX-License-Identifier: MIT
//! Fourier coefficients of a harmonic curve and uniform sampling by FFT (docs/math.md §7).
//!
//! The harmonic curve through n points is the real trigonometric polynomial
//!
//! X(t) = a₀ + Σⱼ₌₁ᴹ (aⱼ·cos 2πjt + bⱼ·sin 2πjt),  M = ⌊n/2⌋,
//!
//! with aⱼ = (2/n)·Σₖ xₖ cos(2πjk/n), bⱼ = (2/n)·Σₖ xₖ sin(2πjk/n), a₀ the mean, and for even n
//! the Nyquist term halved, `a_M` = (1/n)·Σₖ (−1)ᵏ xₖ, `b_M` = 0 (eq. 5.1; the thesis's `b_m` = 0).
//! In complex form cⱼ = (aⱼ − i·bⱼ)/2 = c̄₋ⱼ, so for even n the Nyquist bin is split in half
//! between +M and −M, which is what makes the even case real.
//!
//! Sampling N uniform points is then an inverse FFT of length N of the zero-padded (N > 2M) or
//! folded (N ≤ 2M) spectrum: O(N log N) instead of the O(nN) direct sum. Two coordinates share
//! one complex transform, as x + i·y.

use std::cell::RefCell;
use std::f64::consts::PI;
use std::sync::Arc;

use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

use crate::ControlPoint;
use crate::sinpi::{for_each_harmonic, pow_order, quarter_turns};

thread_local! {
    static PLANNER: RefCell<RealFftPlanner<f64>> = RefCell::new(RealFftPlanner::new());
    static COMPLEX_PLANNER: RefCell<FftPlanner<f64>> = RefCell::new(FftPlanner::new());
}

fn forward_plan(len: usize) -> Arc<dyn RealToComplex<f64>> {
    PLANNER.with(|p| p.borrow_mut().plan_fft_forward(len))
}

fn inverse_plan(len: usize) -> Arc<dyn ComplexToReal<f64>> {
    PLANNER.with(|p| p.borrow_mut().plan_fft_inverse(len))
}

fn complex_inverse_plan(len: usize) -> Arc<dyn Fft<f64>> {
    COMPLEX_PLANNER.with(|p| p.borrow_mut().plan_fft_inverse(len))
}

/// The largest sampling length whose work buffers a thread keeps between calls (about 24 MB
/// of buffers); longer transforms allocate their own.
const KEEP_BUFFERS_UP_TO: usize = 1 << 20;

/// The plans of uniform sampling at N points: two coordinates at a time share one complex
/// inverse FFT of length N (x + i·y; each is real, so they come apart as the real and the
/// imaginary part), and a last coordinate left over (odd dimension) takes an inverse real FFT.
struct InversePlans {
    /// For the coordinate pairs; `None` in dimension 1.
    pair: Option<Arc<dyn Fft<f64>>>,
    /// For the coordinate left over; `None` in even dimension.
    single: Option<Arc<dyn ComplexToReal<f64>>>,
}

impl InversePlans {
    fn new(len: usize, dim: usize) -> Self {
        Self {
            pair: (dim >= 2).then(|| complex_inverse_plan(len)),
            single: (dim % 2 == 1).then(|| inverse_plan(len)),
        }
    }
}

/// The work buffers of uniform sampling: one complex column per coordinate pair (transformed
/// in place), and for a coordinate left over its half spectrum and real output column.
#[derive(Default)]
struct InverseBuffers {
    /// `dim / 2` columns of N values, one after the other.
    pairs: Vec<Complex<f64>>,
    spectrum: Vec<Complex<f64>>,
    output: Vec<f64>,
    scratch: Vec<Complex<f64>>,
}

impl InverseBuffers {
    /// Sized for `plans` at length `len` in dimension `dim` (contents unspecified).
    fn fit(&mut self, plans: &InversePlans, len: usize, dim: usize) {
        let zero = Complex::new(0.0, 0.0);
        let mut scratch = 0;
        self.pairs.resize(dim / 2 * len, zero);
        if let Some(plan) = &plans.pair {
            scratch = plan.get_inplace_scratch_len();
        }
        if let Some(plan) = &plans.single {
            self.spectrum.resize(plan.complex_len(), zero);
            self.output.resize(len, 0.0);
            scratch = scratch.max(plan.get_scratch_len());
        }
        self.scratch.resize(scratch, zero);
    }
}

thread_local! {
    // Reused by uniform sampling: fresh buffers for every call cost more in page faults than
    // the transform itself for N in the thousands.
    static INVERSE_BUFFERS: RefCell<InverseBuffers> = RefCell::new(InverseBuffers::default());
}

/// Runs `f` with buffers sized for `plans`: this thread's kept ones (taken out for the call,
/// so a nested call gets fresh ones), or fresh ones for a long transform.
fn with_inverse_buffers<R>(
    plans: &InversePlans,
    len: usize,
    dim: usize,
    f: impl FnOnce(&mut InverseBuffers) -> R,
) -> R {
    let keep = len <= KEEP_BUFFERS_UP_TO;
    let mut buffers = if keep { INVERSE_BUFFERS.take() } else { InverseBuffers::default() };
    buffers.fit(plans, len, dim);
    let out = f(&mut buffers);
    if keep {
        INVERSE_BUFFERS.set(buffers);
    }
    out
}

/// A real trigonometric polynomial X(t) = a₀ + Σⱼ₌₁ᴹ (aⱼ cos 2πjt + bⱼ sin 2πjt) with point
/// coefficients: the spectrum of a harmonic curve (docs/math.md §7, eq. 5.1).
///
/// # Examples
///
/// ```
/// use hi_curve::Fourier;
///
/// // Four samples of cos 2πt: a₁ = 1, everything else 0.
/// let f = Fourier::from_points(&[1.0, 0.0, -1.0, 0.0]);
/// assert_eq!(f.degree(), 2);
/// assert!((f.cos_coeffs()[1] - 1.0).abs() < 1e-15);
/// assert!(f.cos_coeffs()[2].abs() < 1e-15 && f.sin_coeffs()[1].abs() < 1e-15);
/// // FFT sampling at 8 points gives cos(2πl/8).
/// let s = f.sample_uniform(8);
/// assert!((s[1] - 0.5f64.sqrt()).abs() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Fourier<P> {
    // Invariant: cos.len() == sin.len() >= 1; sin[0] is zero.
    cos: Vec<P>,
    sin: Vec<P>,
}

impl<P: ControlPoint> Fourier<P> {
    /// The spectrum of the harmonic curve through `points` (one real FFT per coordinate).
    ///
    /// An empty slice gives the zero polynomial of degree 0.
    #[must_use]
    #[allow(clippy::missing_panics_doc, reason = "the FFT buffers come from the plan itself")]
    pub fn from_points(points: &[P]) -> Self {
        let n = points.len();
        if n == 0 {
            return Self { cos: vec![P::ZERO], sin: vec![P::ZERO] };
        }
        let m = n / 2;
        let plan = forward_plan(n);
        let mut input = plan.make_input_vec();
        let mut spectrum = plan.make_output_vec();
        let mut scratch = plan.make_scratch_vec();
        // spectra[i][j] = Σₖ xₖ[i]·e^{−2πijk/n}
        let mut spectra = Vec::with_capacity(P::DIM);
        for i in 0..P::DIM {
            for (slot, p) in input.iter_mut().zip(points) {
                *slot = p.coord(i);
            }
            plan.process_with_scratch(&mut input, &mut spectrum, &mut scratch)
                .expect("buffer sizes come from the plan");
            spectra.push(spectrum.clone());
        }
        let nf = n as f64;
        let (cos, sin) = (0..=m)
            .map(|j| {
                let real_only = j == 0 || (n.is_multiple_of(2) && j == m);
                let scale = if real_only { 1.0 / nf } else { 2.0 / nf };
                let a = P::from_coords(|i| spectra[i][j].re * scale);
                let b =
                    if real_only { P::ZERO } else { P::from_coords(|i| -spectra[i][j].im * scale) };
                (a, b)
            })
            .unzip();
        Self { cos, sin }
    }

    /// A trigonometric polynomial from its coefficients `a₀…a_M` and `b₀…b_M`.
    ///
    /// Returns `None` if the two lists differ in length or are empty. b₀ is ignored (sin 0 = 0).
    #[must_use]
    pub fn from_coeffs(cos: Vec<P>, mut sin: Vec<P>) -> Option<Self> {
        if cos.is_empty() || cos.len() != sin.len() {
            return None;
        }
        sin[0] = P::ZERO;
        Some(Self { cos, sin })
    }

    /// The degree M: the highest frequency that may be present.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.cos.len() - 1
    }

    /// The cosine coefficients a₀, …, `a_M` (a₀ is the centroid of the points).
    #[must_use]
    pub fn cos_coeffs(&self) -> &[P] {
        &self.cos
    }

    /// The sine coefficients b₀ (always 0), …, `b_M`.
    #[must_use]
    pub fn sin_coeffs(&self) -> &[P] {
        &self.sin
    }

    /// The complex coefficient cⱼ of e^{2πijt} for −M ≤ j ≤ M, as (real part, imaginary part):
    /// c₀ = a₀, cⱼ = (aⱼ − i·bⱼ)/2 and c₋ⱼ = c̄ⱼ.
    #[must_use]
    pub fn complex_coeff(&self, j: isize) -> Option<(P, P)> {
        let a = j.unsigned_abs();
        if a > self.degree() {
            return None;
        }
        if j == 0 {
            return Some((self.cos[0], P::ZERO));
        }
        let im = if j > 0 { -self.sin[a] * 0.5 } else { self.sin[a] * 0.5 };
        Some((self.cos[a] * 0.5, im))
    }

    /// The spectral basis and its derivatives at t: for j = 0, …, `degree`, the pair
    /// (dᵖ/dtᵖ cos 2πjt, dᵖ/dtᵖ sin 2πjt) = (2πj)ᵖ·(cos(2πjt + pπ/2), sin(2πjt + pπ/2)).
    ///
    /// Tensor-product surfaces evaluate their 2-D spectra with one such row per direction.
    ///
    /// # Examples
    ///
    /// ```
    /// let row = hi_curve::Fourier::<f64>::trig_basis(2, 0.125, 1);
    /// // d/dt cos 4πt = −4π sin 4πt = −4π at t = 1/8.
    /// assert!((row[2].0 + 4.0 * std::f64::consts::PI).abs() < 1e-13);
    /// assert_eq!(row[0], (0.0, 0.0));
    /// ```
    #[must_use]
    pub fn trig_basis(degree: usize, t: f64, order: usize) -> Vec<(f64, f64)> {
        let mut row = Vec::with_capacity(degree + 1);
        Self::for_each_trig(degree, t, order, |_, c, s| row.push((c, s)));
        row
    }

    /// The row of [`Fourier::trig_basis`] without allocating: calls `f(j, c, s)` with
    /// (c, s) = (dᵖ/dtᵖ cos 2πjt, dᵖ/dtᵖ sin 2πjt) for j = 0, …, `degree` in order, the same
    /// values bit for bit. The harmonics come from a rotation re-anchored by an exactly reduced
    /// `sin_cos` every 16 steps, so their error stays within a few ulps for any degree.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_curve::Fourier;
    ///
    /// let mut sum = 0.0;
    /// Fourier::<f64>::for_each_trig(3, 0.1, 0, |_, c, _| sum += c);
    /// let expected: f64 = (0..=3).map(|j| (std::f64::consts::TAU * j as f64 * 0.1).cos()).sum();
    /// assert!((sum - expected).abs() < 1e-14);
    /// ```
    #[inline]
    pub fn for_each_trig(degree: usize, t: f64, order: usize, mut f: impl FnMut(usize, f64, f64)) {
        if order == 0 {
            f(0, 1.0, 0.0);
        } else {
            f(0, 0.0, 0.0);
        }
        for_each_harmonic(t, degree, |j, c, s| {
            let w = pow_order(2.0 * PI * j as f64, order);
            let (sp, cp) = quarter_turns(s, c, order);
            f(j, w * cp, w * sp);
        });
    }

    /// X(t) by the spectral sum, O(M).
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        self.eval_deriv(t, 0)
    }

    /// The derivative X⁽ᵖ⁾(t) = Σⱼ (2πj)ᵖ·[aⱼ cos(2πjt + pπ/2) + bⱼ sin(2πjt + pπ/2)], O(M).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        let mut res = if order == 0 { self.cos[0] } else { P::ZERO };
        for_each_harmonic(t, self.degree(), |j, c, s| {
            let w = pow_order(2.0 * PI * j as f64, order);
            let (sp, cp) = quarter_turns(s, c, order);
            res += (self.cos[j] * cp + self.sin[j] * sp) * w;
        });
        res
    }

    /// X(l/N) for l = 0, …, N−1 by one inverse complex FFT per pair of coordinates (x + i·y:
    /// both are real, so they are its real and imaginary parts) and an inverse real FFT for a
    /// coordinate left over, O(M + N log N).
    ///
    /// Exact sampling for every N ≥ 1: when N ≤ 2M the frequencies fold (alias) onto the N
    /// output bins as sampling folds them. N = 0 gives an empty vector.
    #[must_use]
    pub fn sample_uniform(&self, n_samples: usize) -> Vec<P> {
        self.sample_uniform_deriv(n_samples, 0)
    }

    /// X⁽ᵖ⁾(l/N) for l = 0, …, N−1 by FFT; see [`Fourier::sample_uniform`].
    #[must_use]
    #[allow(
        clippy::missing_panics_doc,
        reason = "the FFT buffers come from the plan and the imaginary parts that must be zero are zeroed"
    )]
    pub fn sample_uniform_deriv(&self, n_samples: usize, order: usize) -> Vec<P> {
        if n_samples == 0 {
            return Vec::new();
        }
        let big_n = n_samples;
        let half = big_n / 2;
        // cⱼ·(2πij)ᵖ for coordinate i; its conjugate is the coefficient at −j.
        let coeff = |i: usize, j: usize| {
            let c = Complex::new(0.5 * self.cos[j].coord(i), -0.5 * self.sin[j].coord(i));
            if order == 0 {
                return c;
            }
            // (iw)ᵖ = wᵖ·iᵖ
            let w = pow_order(2.0 * PI * j as f64, order);
            match order % 4 {
                0 => c * w,
                1 => Complex::new(-c.im, c.re) * w,
                2 => -c * w,
                _ => Complex::new(c.im, -c.re) * w,
            }
        };
        let dc = |i: usize| if order == 0 { self.cos[0].coord(i) } else { 0.0 };
        let plans = InversePlans::new(big_n, P::DIM);
        with_inverse_buffers(&plans, big_n, P::DIM, |b| {
            if let Some(plan) = &plans.pair {
                for (k, column) in b.pairs.chunks_exact_mut(big_n).enumerate() {
                    // The spectrum of x + i·y: cⱼ(x) + i·cⱼ(y) at j, c̄ⱼ(x) + i·c̄ⱼ(y) at −j,
                    // each folded onto j mod N.
                    let (ix, iy) = (2 * k, 2 * k + 1);
                    column.fill(Complex::new(0.0, 0.0));
                    column[0] += Complex::new(dc(ix), dc(iy));
                    for j in 1..=self.degree() {
                        let (cx, cy) = (coeff(ix, j), coeff(iy, j));
                        let p = j % big_n;
                        column[p] += Complex::new(cx.re - cy.im, cx.im + cy.re);
                        column[(big_n - p) % big_n] += Complex::new(cx.re + cy.im, cy.re - cx.im);
                    }
                    plan.process_with_scratch(column, &mut b.scratch);
                }
            }
            if let Some(plan) = &plans.single {
                let i = P::DIM - 1;
                b.spectrum.fill(Complex::new(0.0, 0.0));
                b.spectrum[0].re += dc(i);
                for j in 1..=self.degree() {
                    let c = coeff(i, j);
                    let p = j % big_n;
                    let q = (big_n - p) % big_n;
                    if p <= half {
                        b.spectrum[p] += c;
                    }
                    if q <= half {
                        b.spectrum[q] += c.conj();
                    }
                }
                // The result is real: bins 0 and N/2 (N even) have no imaginary part.
                b.spectrum[0].im = 0.0;
                if big_n.is_multiple_of(2) {
                    b.spectrum[half].im = 0.0;
                }
                plan.process_with_scratch(&mut b.spectrum, &mut b.output, &mut b.scratch)
                    .expect("buffer sizes come from the plan, imaginary parts are zeroed");
            }
            // Assembled once from the columns.
            if P::DIM == 2 {
                return b.pairs.iter().map(|z| P::from_coords(|c| [z.re, z.im][c])).collect();
            }
            let (pairs, single) = (&b.pairs, &b.output);
            (0..big_n)
                .map(|l| {
                    P::from_coords(|c| {
                        if c + 1 < P::DIM || P::DIM % 2 == 0 {
                            let z = pairs[c / 2 * big_n + l];
                            if c % 2 == 0 { z.re } else { z.im }
                        } else {
                            single[l]
                        }
                    })
                })
                .collect()
        })
    }

    /// The polynomial t ↦ X(t + offset): aⱼ' = aⱼ cos φ + bⱼ sin φ, bⱼ' = bⱼ cos φ − aⱼ sin φ
    /// with φ = 2πj·offset.
    #[must_use]
    pub fn shifted(&self, offset: f64) -> Self {
        let mut res = self.clone();
        for_each_harmonic(offset, self.degree(), |j, c, s| {
            res.cos[j] = self.cos[j] * c + self.sin[j] * s;
            res.sin[j] = self.sin[j] * c - self.cos[j] * s;
        });
        res
    }

    /// The difference `self − other`, as a polynomial of the larger degree.
    #[must_use]
    pub fn sub(&self, other: &Self) -> Self {
        let len = self.cos.len().max(other.cos.len());
        let get = |v: &[P], j: usize| v.get(j).copied().unwrap_or(P::ZERO);
        Self {
            cos: (0..len).map(|j| get(&self.cos, j) - get(&other.cos, j)).collect(),
            sin: (0..len).map(|j| get(&self.sin, j) - get(&other.sin, j)).collect(),
        }
    }

    /// An upper bound of maxₜ |X(t)|: |a₀| + Σⱼ √(|aⱼ|² + |bⱼ|²) (Cauchy–Schwarz on each term).
    #[must_use]
    pub fn sup_bound(&self) -> f64 {
        self.cos[0].norm()
            + (1..=self.degree())
                .map(|j| (self.cos[j].dot(self.cos[j]) + self.sin[j].dot(self.sin[j])).sqrt())
                .sum::<f64>()
    }

    /// maxₜ |X(t)| measured on a uniform grid of L ≥ 32·M points (by FFT), with a guaranteed
    /// upper bound: by Bernstein's inequality |X'| ≤ 2πM·max|X|, so
    /// max|X| ≤ `max_grid` / (1 − πM/L). Returns (grid maximum, upper bound).
    #[must_use]
    pub fn sup_norm(&self) -> (f64, f64) {
        let m = self.degree();
        let l = (32 * m).max(64);
        let grid = self.sample_uniform(l).into_iter().map(|p| p.norm()).fold(0.0, f64::max);
        let bernstein = grid / (1.0 - PI * m as f64 / l as f64);
        (grid, bernstein.min(self.sup_bound()).max(grid))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec2, DVec3};

    /// Every uniform sample of `f` against the spectral sum at its parameter, for lengths that
    /// grow, shrink (below 2M the frequencies alias), repeat and change order of derivative.
    fn check_uniform_samples<P: ControlPoint + std::fmt::Debug>(f: &Fourier<P>) {
        for (n_samples, order) in [(64, 0), (7, 1), (1000, 0), (3, 0), (64, 2), (1000, 1), (1, 0)] {
            let fft = f.sample_uniform_deriv(n_samples, order);
            assert_eq!(fft.len(), n_samples, "length");
            for (l, p) in fft.iter().enumerate() {
                let q = f.eval_deriv(l as f64 / n_samples as f64, order);
                let scale = (2.0 * PI * 4.0).powi(order as i32).max(1.0);
                assert!(
                    (*p - q).norm() < 1e-12 * scale,
                    "dimension {}, N = {n_samples}, order {order}, sample {l}: {p:?} against {q:?}",
                    P::DIM
                );
            }
        }
    }

    #[test]
    fn kept_buffers_never_leak_between_calls() {
        // One thread samples each curve in turn, reusing its buffers each time: in dimension 2
        // one complex transform carries both coordinates, in dimension 3 a real one the last,
        // in dimension 1 only the real one runs.
        let pts: Vec<DVec3> = (0..9)
            .map(|k| {
                let k = k as f64;
                DVec3::new(k.sin() * 2.0, (1.7 * k).cos(), (0.3 * k).exp())
            })
            .collect();
        for _ in 0..2 {
            check_uniform_samples(&Fourier::from_points(&pts));
            check_uniform_samples(&Fourier::from_points(
                &pts.iter().map(|p| p.truncate()).collect::<Vec<DVec2>>(),
            ));
            check_uniform_samples(&Fourier::from_points(
                &pts.iter().map(|p| p.z).collect::<Vec<f64>>(),
            ));
        }
    }

    fn direct_dft_coeffs(x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let n = x.len();
        let m = n / 2;
        let mut a = vec![0.0; m + 1];
        let mut b = vec![0.0; m + 1];
        for j in 0..=m {
            let scale =
                if j == 0 || (n.is_multiple_of(2) && j == m) { 1.0 } else { 2.0 } / n as f64;
            for (k, xk) in x.iter().enumerate() {
                let ang = 2.0 * PI * (j * k) as f64 / n as f64;
                a[j] += scale * xk * ang.cos();
                b[j] += scale * xk * ang.sin();
            }
        }
        if n.is_multiple_of(2) {
            b[m] = 0.0;
        }
        (a, b)
    }

    #[test]
    fn fft_coefficients_match_direct_dft() {
        for n in [1usize, 2, 3, 4, 5, 8, 13, 64] {
            let x: Vec<f64> = (0..n).map(|k| ((k * 7 + 3) % 11) as f64 - 4.5).collect();
            let f = Fourier::from_points(&x);
            let (a, b) = direct_dft_coeffs(&x);
            for j in 0..=n / 2 {
                assert!((f.cos_coeffs()[j] - a[j]).abs() < 1e-13, "n={n} a{j}");
                assert!((f.sin_coeffs()[j] - b[j]).abs() < 1e-13, "n={n} b{j}");
            }
        }
    }

    #[test]
    fn folded_sampling_matches_direct_evaluation() {
        let pts: Vec<DVec2> =
            (0..9).map(|k| DVec2::new((k as f64).sin() * 3.0, (k * k) as f64 * 0.1)).collect();
        let f = Fourier::from_points(&pts);
        for big_n in [1usize, 2, 3, 4, 5, 8, 9, 10, 17, 40] {
            for order in 0..3 {
                let s = f.sample_uniform_deriv(big_n, order);
                for (l, p) in s.iter().enumerate() {
                    let direct = f.eval_deriv(l as f64 / big_n as f64, order);
                    let scale = 1.0 + direct.length();
                    assert!((*p - direct).length() < 1e-12 * scale, "N={big_n} p={order} l={l}");
                }
            }
        }
    }

    #[test]
    fn shift_moves_the_curve() {
        let f = Fourier::from_points(&[0.3, -1.0, 2.0, 0.5, 0.25]);
        let g = f.shifted(0.17);
        for t in [0.0, 0.1, 0.55] {
            assert!((g.eval(t) - f.eval(t + 0.17)).abs() < 1e-14);
        }
    }

    #[test]
    fn sup_norm_brackets_the_maximum() {
        let f = Fourier::from_coeffs(vec![0.0, 0.0, 0.0, 1.0], vec![0.0; 4]).unwrap();
        let (grid, bound) = f.sup_norm();
        assert!((grid - 1.0).abs() < 1e-15 && (1.0..1.2).contains(&bound), "{grid} {bound}");
    }
}
