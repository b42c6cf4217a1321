// SPDX-License-Identifier: MIT
//! The 2-D spectral path of [`HarmonicSurface::sample_uniform`](crate::HarmonicSurface::sample_uniform)
//! when both axes grow past the grid's highest frequency (Theorem 5.3 on both axes, docs/math.md §7).
//!
//! One coordinate at a time: a real FFT along v for each of the m grid rows (n/2 + 1 bins), a
//! complex FFT along u for each of those bins, the derivative factors (2πis)ᵖ(2πik)^q, the
//! zero padding to U along u (the Nyquist row of an even m split in half between ±m/2), an
//! inverse complex FFT of length U for each bin, then an inverse real FFT of length V for each
//! of the U output rows (the Nyquist column of an even n halved: its conjugate half is implied).
//! Only the n/2 + 1 non-negative v frequencies are ever carried, so the work is that of
//! `scipy.signal.resample` on both axes: (n/2 + 1) complex FFTs of length U and U real FFTs of
//! length V per coordinate. Buffers are allocated once per call and per worker, never per line.

use std::f64::consts::TAU;

use hi_curve::ControlPoint;
use hi_par::*;
use realfft::RealFftPlanner;
use realfft::num_complex::Complex;
use rustfft::FftPlanner;

/// (iw)ᵖ with w = 2πs, as a complex factor.
fn derivative_factor(s: f64, order: usize) -> Complex<f64> {
    let w = (TAU * s).powi(i32::try_from(order).unwrap_or(i32::MAX));
    match order % 4 {
        0 => Complex::new(w, 0.0),
        1 => Complex::new(0.0, w),
        2 => Complex::new(-w, 0.0),
        _ => Complex::new(0.0, -w),
    }
}

/// ∂^{p+q}/∂uᵖ∂v^q of the harmonic surface through the row-major m×n grid `points`, at
/// (i/U, l/V), row-major. Requires U > 2⌊m/2⌋ and V > 2⌊n/2⌋ (no frequency folds).
#[allow(
    clippy::missing_panics_doc,
    reason = "private; the FFT buffers come from their plans and the imaginary parts that must be zero are zeroed"
)]
pub(crate) fn upsample<P: ControlPoint + Send + Sync>(
    points: &[P],
    (m, n): (usize, usize),
    (n_u, n_v): (usize, usize),
    (p, q): (usize, usize),
) -> Vec<P> {
    debug_assert!(
        n_u > 2 * (m / 2) && n_v > 2 * (n / 2) && points.len() == m * n,
        "the caller checks that no frequency folds and that the grid is m×n"
    );
    let kh = n / 2 + 1;
    let dim = P::DIM;
    let mut real_planner = RealFftPlanner::<f64>::new();
    let row_fft = real_planner.plan_fft_forward(n);
    let row_ifft = real_planner.plan_fft_inverse(n_v);
    let mut planner = FftPlanner::<f64>::new();
    let col_fft = planner.plan_fft_forward(m);
    let col_ifft = planner.plan_fft_inverse(n_u);

    // 1. Along v: rows[j][c][k], the n/2 + 1 bins of coordinate c of grid row j.
    let mut rows = vec![Complex::new(0.0, 0.0); m * dim * kh];
    rows.par_chunks_mut(dim * kh).zip(points.par_chunks(n)).for_each_init(
        || (row_fft.make_input_vec(), row_fft.make_scratch_vec()),
        |(input, scratch), (out, row)| {
            for (c, bins) in out.chunks_mut(kh).enumerate() {
                for (x, pt) in input.iter_mut().zip(row) {
                    *x = pt.coord(c);
                }
                row_fft
                    .process_with_scratch(input, bins, scratch)
                    .expect("buffer sizes come from the plan");
            }
        },
    );

    // 2. Along u, for every (coordinate, bin): FFT of length m, derivative factors and
    //    padding, inverse FFT of length U. cols[(c·kh + k)·U + i].
    let scale = 1.0 / (m * n) as f64;
    let half_m = m / 2;
    let mut cols = vec![Complex::new(0.0, 0.0); dim * kh * n_u];
    let scratch_len = col_fft.get_inplace_scratch_len().max(col_ifft.get_inplace_scratch_len());
    cols.par_chunks_mut(n_u).enumerate().for_each_init(
        || (vec![Complex::new(0.0, 0.0); m], vec![Complex::new(0.0, 0.0); scratch_len]),
        |(column, scratch), (ck, out)| {
            let (c, k) = (ck / kh, ck % kh);
            for (j, x) in column.iter_mut().enumerate() {
                *x = rows[(j * dim + c) * kh + k];
            }
            col_fft.process_with_scratch(column, &mut scratch[..col_fft.get_inplace_scratch_len()]);
            // The v factor: (2πik)^q, the Nyquist column of an even n halved.
            let mut fv = derivative_factor(k as f64, q) * scale;
            if n.is_multiple_of(2) && k == n / 2 {
                fv *= 0.5;
            }
            out.fill(Complex::new(0.0, 0.0));
            for (h, &x) in column.iter().enumerate() {
                let x = x * fv;
                if m.is_multiple_of(2) && h == half_m {
                    // Split between +m/2 and −m/2.
                    let s = half_m as f64;
                    out[half_m] += x * 0.5 * derivative_factor(s, p);
                    out[n_u - half_m] += x * 0.5 * derivative_factor(-s, p);
                } else if h <= half_m {
                    out[h] += x * derivative_factor(h as f64, p);
                } else {
                    let s = h as f64 - m as f64;
                    out[n_u + h - m] += x * derivative_factor(s, p);
                }
            }
            col_ifft.process_with_scratch(out, &mut scratch[..col_ifft.get_inplace_scratch_len()]);
        },
    );

    // 3. Along v again, for every output row: the inverse real FFT of length V.
    let mut values = vec![P::ZERO; n_u * n_v];
    values.par_chunks_mut(n_v).enumerate().for_each_init(
        || (row_ifft.make_input_vec(), vec![vec![0.0; n_v]; dim], row_ifft.make_scratch_vec()),
        |(spectrum, coords, scratch), (i, out)| {
            for (c, coord) in coords.iter_mut().enumerate() {
                spectrum.fill(Complex::new(0.0, 0.0));
                for (k, s) in spectrum.iter_mut().take(kh).enumerate() {
                    *s = cols[(c * kh + k) * n_u + i];
                }
                // The result is real: bin 0 (and V/2 for an even V) has no imaginary part.
                spectrum[0].im = 0.0;
                if n_v.is_multiple_of(2) {
                    spectrum[n_v / 2].im = 0.0;
                }
                row_ifft
                    .process_with_scratch(spectrum, coord, scratch)
                    .expect("buffer sizes come from the plan, imaginary parts are zeroed");
            }
            for (l, o) in out.iter_mut().enumerate() {
                *o = P::from_coords(|c| coords[c][l]);
            }
        },
    );
    values
}
