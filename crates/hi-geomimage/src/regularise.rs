// SPDX-License-Identifier: MIT
//! A regularised harmonic surface through a geometry image (beyond §5.4, whose smoothing is a
//! box or Gaussian filter of a chosen width): the trigonometric polynomial that best balances
//! closeness to the texels against curvature, with the balance chosen from the image itself.
//!
//! The harmonic surface through an image with texels xᵢⱼ has the 2-D discrete Fourier
//! coefficients x̂ₖₗ of the texels. Among all trigonometric polynomials q of the same degrees,
//!
//! Σᵢⱼ |q(i/rows, j/cols) − xᵢⱼ|² + λ · Σₖₗ wₖₗ |q̂ₖₗ|²,  wₖₗ = (k² + l²)²
//!
//! (k, l the signed frequencies; the penalty is the discrete ∫|Δq|², the thin-plate energy of
//! each coordinate) is smallest for q̂ₖₗ = sₖₗ x̂ₖₗ with sₖₗ = 1 / (1 + λ wₖₗ): the fit is a
//! filter in the spectral domain, O(N log N) with no linear system. λ = 0 gives back the
//! interpolating surface of the thesis.
//!
//! λ is chosen in one of two ways, each costing O(N) per trial λ on the power spectrum binned
//! by w (Parseval: ‖(I − S)x‖² is a sum over the frequencies):
//! - from a noise level σ (the discrepancy principle of Morozov): the largest λ that moves
//!   the texels by at most σ in root mean square — the surface may depart from the data by
//!   what the data's own scatter allows, and no more (σ from [`hi_scan::noise`]);
//! - by generalised cross-validation (Craven and Wahba 1979): λ minimising
//!   GCV(λ) = N · ‖(I − S)x‖² / (tr(I − S))², the mean squared error of predicting each texel
//!   from the others, which needs no noise level but assumes the texels' errors independent.
//!
//! The filter depends on k² and l² only, so it keeps the half-turn symmetry of the doubled
//! layouts.

use glam::DVec3;
use hi_par::*;
use rustfft::FftPlanner;
use rustfft::num_complex::Complex64;

use crate::{Error, GeometryImage};

/// How the surface through a geometry image is regularised.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Regularisation {
    /// None: the surface interpolates the texels (the thesis).
    Off,
    /// Left to the caller: [`crate::fit()`] makes it [`Regularisation::Noise`] with the noise
    /// left in the texels (√(6/16) of the scan's estimated noise, all of it for noise as large as
    /// the points' spacing) for images made from points
    /// and [`Regularisation::Off`] for images sampled from a mesh; [`regularise`] itself treats it as [`Regularisation::Gcv`].
    #[default]
    Auto,
    /// λ by the discrepancy principle for this noise level σ (≥ 0, in the units of the
    /// texels).
    Noise(f64),
    /// λ chosen by generalised cross-validation.
    Gcv,
    /// This λ (≥ 0).
    Weight(f64),
}

/// What [`regularise`] did.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RegularisationReport {
    /// The weight λ used.
    pub lambda: f64,
    /// The effective number of degrees of freedom kept, tr(S), as a fraction of the texels
    /// (1 for interpolation).
    pub kept: f64,
    /// The root mean square change of a texel, ‖(I − S)x‖/√N.
    pub rms_change: f64,
    /// The largest change of a texel.
    pub max_change: f64,
}

/// The forward or inverse 2-D DFT of `data` (rows × cols, row-major) in place.
fn fft2(data: &mut [Complex64], rows: usize, cols: usize, inverse: bool) {
    let mut planner = FftPlanner::new();
    let (along_rows, along_cols) = if inverse {
        (planner.plan_fft_inverse(cols), planner.plan_fft_inverse(rows))
    } else {
        (planner.plan_fft_forward(cols), planner.plan_fft_forward(rows))
    };
    data.par_chunks_mut(cols).for_each(|row| along_rows.process(row));
    // Columns: transpose, transform rows, transpose back.
    let mut t = vec![Complex64::default(); rows * cols];
    for i in 0..rows {
        for j in 0..cols {
            t[j * rows + i] = data[i * cols + j];
        }
    }
    t.par_chunks_mut(rows).for_each(|col| along_cols.process(col));
    for j in 0..cols {
        for i in 0..rows {
            data[i * cols + j] = t[j * rows + i];
        }
    }
}

/// The penalty weight w of frequency index (k, l) of a rows × cols spectrum.
fn weight(k: usize, l: usize, rows: usize, cols: usize) -> f64 {
    let fk = k.min(rows - k) as f64;
    let fl = l.min(cols - l) as f64;
    let r2 = fk * fk + fl * fl;
    r2 * r2
}

/// The regularised image: texels q(i/rows, j/cols) of the surface q of the module
/// documentation, whose harmonic surface is q itself; and what was done.
///
/// # Errors
///
/// [`Error::InvalidOption`] for a negative or non-finite λ.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::GeometryImage;
/// use hi_geomimage::regularise::{Regularisation, regularise};
///
/// // A smooth image plus a checkerboard of ±0.01 (the highest frequency): the weight chosen
/// // for that noise level takes the checkerboard out and keeps the rest.
/// let (rows, cols) = (32, 32);
/// let texels: Vec<DVec3> = (0..rows * cols)
///     .map(|t| {
///         let (i, j) = (t / cols, t % cols);
///         let (u, v) = (i as f64 / rows as f64, j as f64 / cols as f64);
///         let noise = if (i + j) % 2 == 0 { 0.01 } else { -0.01 };
///         let smooth = (std::f64::consts::TAU * u).cos() + (std::f64::consts::TAU * v).sin();
///         DVec3::new(smooth + noise, 0.0, 0.0)
///     })
///     .collect();
/// let image = GeometryImage::try_new(rows, cols, texels).unwrap();
/// let (smooth, report) = regularise(&image, Regularisation::Noise(0.01)).unwrap();
/// assert!(report.lambda > 0.0);
/// let worst = smooth.texels().iter().enumerate().map(|(t, p)| {
///     let (u, v) = ((t / cols) as f64 / rows as f64, (t % cols) as f64 / cols as f64);
///     (p.x - (std::f64::consts::TAU * u).cos() - (std::f64::consts::TAU * v).sin()).abs()
/// }).fold(0.0, f64::max);
/// assert!(worst < 0.002, "{worst}");
/// ```
pub fn regularise(
    image: &GeometryImage,
    how: Regularisation,
) -> Result<(GeometryImage, RegularisationReport), Error> {
    let (rows, cols) = (image.rows(), image.cols());
    let n = rows * cols;
    if let Regularisation::Weight(l) | Regularisation::Noise(l) = how
        && !(l >= 0.0 && l.is_finite())
    {
        return Err(Error::InvalidOption {
            name: "regularisation weight or noise level",
            value: l,
            expected: "a finite number ≥ 0",
        });
    }
    if matches!(how, Regularisation::Off | Regularisation::Weight(0.0) | Regularisation::Noise(0.0))
    {
        let report =
            RegularisationReport { lambda: 0.0, kept: 1.0, rms_change: 0.0, max_change: 0.0 };
        return Ok((image.clone(), report));
    }
    // x and y packed as one complex signal, z in another: the filter is real and symmetric
    // in (k, l) ↔ (−k, −l), so it acts on each part alone.
    let mut xy: Vec<Complex64> = image.texels().iter().map(|p| Complex64::new(p.x, p.y)).collect();
    let mut z: Vec<Complex64> = image.texels().iter().map(|p| Complex64::new(p.z, 0.0)).collect();
    join(|| fft2(&mut xy, rows, cols, false), || fft2(&mut z, rows, cols, false));
    let lambda = match how {
        Regularisation::Weight(l) => l,
        Regularisation::Noise(sigma) => {
            discrepancy_lambda(&Binned::new(&xy, &z, rows, cols), sigma)
        }
        _ => gcv_lambda(&Binned::new(&xy, &z, rows, cols)),
    };
    let mut kept = 0.0;
    for k in 0..rows {
        for l in 0..cols {
            let s = 1.0 / (1.0 + lambda * weight(k, l, rows, cols));
            kept += s;
            xy[k * cols + l] *= s;
            z[k * cols + l] *= s;
        }
    }
    join(|| fft2(&mut xy, rows, cols, true), || fft2(&mut z, rows, cols, true));
    let scale = 1.0 / n as f64;
    let texels: Vec<DVec3> =
        xy.iter().zip(&z).map(|(a, b)| DVec3::new(a.re, a.im, b.re) * scale).collect();
    let (mut sum2, mut max) = (0.0, 0.0f64);
    for (a, b) in texels.iter().zip(image.texels()) {
        let d = a.distance(*b);
        sum2 += d * d;
        max = max.max(d);
    }
    let report = RegularisationReport {
        lambda,
        kept: kept / n as f64,
        rms_change: (sum2 / n as f64).sqrt(),
        max_change: max,
    };
    Ok((GeometryImage::try_new(rows, cols, texels)?, report))
}

/// The power spectrum of the packed channels binned by penalty weight: (mean w, power,
/// frequencies) per bin, the mean (w = 0) left out; and the texel count.
struct Binned {
    bins: Vec<(f64, f64, f64)>,
    n: f64,
    w_max: f64,
}

impl Binned {
    fn new(xy: &[Complex64], z: &[Complex64], rows: usize, cols: usize) -> Self {
        const BINS: usize = 2048;
        let w_max = weight(rows / 2, cols / 2, rows, cols).max(1.0);
        let log_max = w_max.ln();
        let mut power = vec![0.0; BINS];
        let mut count = vec![0.0; BINS];
        let mut centre = vec![0.0; BINS];
        for k in 0..rows {
            for l in 0..cols {
                let w = weight(k, l, rows, cols);
                if w == 0.0 {
                    continue; // the mean: never penalised
                }
                #[expect(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "in 0..BINS"
                )]
                let b = ((w.ln() / log_max) * (BINS - 1) as f64)
                    .round()
                    .clamp(0.0, (BINS - 1) as f64) as usize;
                let t = k * cols + l;
                power[b] += xy[t].norm_sqr() + z[t].norm_sqr();
                count[b] += 1.0;
                centre[b] += w;
            }
        }
        let bins = (0..BINS)
            .filter(|&b| count[b] > 0.0)
            .map(|b| (centre[b] / count[b], power[b], count[b]))
            .collect();
        Self { bins, n: (rows * cols) as f64, w_max }
    }

    /// ‖(I − S)x‖² (Parseval: the unnormalised DFT's power over N) and tr(I − S).
    fn residual(&self, lambda: f64) -> (f64, f64) {
        let (mut rss, mut trace) = (0.0, 0.0);
        for &(w, p, c) in &self.bins {
            let r = lambda * w / (1.0 + lambda * w); // 1 − s
            rss += r * r * p;
            trace += r * c;
        }
        (rss / self.n, trace)
    }
}

/// The largest λ whose filter moves the texels by at most σ in root mean square.
fn discrepancy_lambda(b: &Binned, sigma: f64) -> f64 {
    let budget = sigma * sigma * b.n;
    let moved = |log_lambda: f64| b.residual(log_lambda.exp()).0;
    let (mut lo, mut hi) = ((1e-6 / b.w_max).ln(), (1e10 / b.w_max).ln());
    if moved(lo) > budget {
        return 0.0;
    }
    if moved(hi) <= budget {
        return hi.exp();
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if moved(mid) <= budget {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo.exp()
}

/// The λ minimising GCV.
fn gcv_lambda(b: &Binned) -> f64 {
    let gcv = |log_lambda: f64| {
        let (rss, trace) = b.residual(log_lambda.exp());
        if trace <= 0.0 { f64::INFINITY } else { b.n * rss / (trace * trace) }
    };
    let w_max = b.w_max;
    // λ·w_max from 10⁻⁴ to 10⁸: from no effect to smoothing away all but the lowest modes.
    let (lo, hi) = ((1e-4 / w_max).ln(), (1e8 / w_max).ln());
    let steps = 60;
    let mut best = (f64::INFINITY, lo);
    for i in 0..=steps {
        let x = lo + (hi - lo) * i as f64 / steps as f64;
        let g = gcv(x);
        if g < best.0 {
            best = (g, x);
        }
    }
    // Golden-section refinement within the neighbouring grid steps.
    let h = (hi - lo) / steps as f64;
    let (mut a, mut b) = (best.1 - h, best.1 + h);
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..40 {
        let (c, d) = (b - phi * (b - a), a + phi * (b - a));
        if gcv(c) < gcv(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let x = 0.5 * (a + b);
    // At the low end of the range the fit is interpolation.
    if x <= lo + h { 0.0 } else { x.exp() }
}
