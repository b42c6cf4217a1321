// SPDX-License-Identifier: MIT
//! Fast evaluation of a harmonic surface on grids of parameters.
//!
//! Two paths, both exact:
//! * separable basis matrices for any parameters: with Bᵤ[i][j] = σᵐⱼ⁽ᵖ⁾(uᵢ) and
//!   Bᵥ[l][k] = σⁿₖ⁽q⁾(vₗ), the samples are Bᵤ·X·Bᵥᵀ, O(m·n·V + U·m·V) instead of
//!   O(U·V·m·n);
//! * the 2-D FFT for the uniform grid over the whole period, p(i/U, l/V): Theorem 5.3 on both
//!   axes (O(U·V·log(U·V)), Nyquist terms split for even sizes, docs/math.md §7). When both axes
//!   grow past the grid's highest frequency the padded 2-D spectrum is transformed directly
//!   (`fft2`, the work of `scipy.signal.resample` on both axes); otherwise the frequencies fold
//!   and each row, then each column, is sampled by its own FFT.
//!
//! Rows and columns are processed in parallel with rayon.

use hi_curve::{ControlPoint, Fourier, Sigma};
use hi_par::*;

use crate::{Error, HarmonicSurface};

/// Largest number of samples per axis (2²⁴) and in all (2²⁸).
const MAX_PER_AXIS: usize = 1 << 24;
const MAX_TOTAL: usize = 1 << 28;

/// Samples of a surface on a grid of parameters, row-major: `values[i·n_v + l]` is at
/// (uᵢ, vₗ).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GridSamples<P> {
    /// Number of u parameters (rows).
    pub n_u: usize,
    /// Number of v parameters (columns).
    pub n_v: usize,
    /// The values, row-major.
    pub values: Vec<P>,
}

impl<P: Copy> GridSamples<P> {
    /// The value at row i, column l.
    ///
    /// # Panics
    ///
    /// Panics if i ≥ `n_u` or l ≥ `n_v`.
    #[must_use]
    pub fn get(&self, i: usize, l: usize) -> P {
        assert!(
            i < self.n_u && l < self.n_v,
            "sample ({i}, {l}) out of range {}×{}",
            self.n_u,
            self.n_v
        );
        self.values[i * self.n_v + l]
    }
}

pub(crate) fn check_sizes(n_u: usize, n_v: usize) -> Result<(), Error> {
    for (what, value) in [("number of u samples", n_u), ("number of v samples", n_v)] {
        if !(1..=MAX_PER_AXIS).contains(&value) {
            return Err(Error::InvalidCount { what, value, expected: "between 1 and 2^24" });
        }
    }
    if n_u.saturating_mul(n_v) > MAX_TOTAL {
        return Err(Error::InvalidCount {
            what: "number of samples",
            value: n_u * n_v,
            expected: "at most 2^28",
        });
    }
    Ok(())
}

pub(crate) fn check_params(name: &'static str, params: &[f64]) -> Result<(), Error> {
    match params.iter().find(|t| !t.is_finite()) {
        Some(&value) => Err(Error::NonFiniteParameter { name, value }),
        None => Ok(()),
    }
}

/// Row i of the basis matrix: σⱼ⁽ᵖ⁾(t) for every j.
fn basis_row(sigma: Sigma, t: f64, order: usize) -> Vec<f64> {
    if order == 0 {
        sigma.values(t)
    } else {
        (0..sigma.n()).map(|j| sigma.deriv(j, t, order)).collect()
    }
}

impl<P: ControlPoint> HarmonicSurface<P> {
    /// ∂^{p+q}p/∂uᵖ∂v^q at every (uᵢ, vₗ), by separable basis matrices (any parameters).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] for empty or too large parameter lists,
    /// [`Error::NonFiniteParameter`] for a NaN or infinite parameter.
    pub fn sample_params(
        &self,
        us: &[f64],
        vs: &[f64],
        p: usize,
        q: usize,
    ) -> Result<GridSamples<P>, Error> {
        check_sizes(us.len(), vs.len())?;
        check_params("u", us)?;
        check_params("v", vs)?;
        let (m, n) = (self.m(), self.n());
        let (sigma_u, sigma_v) = (Sigma::new(m), Sigma::new(n));
        let bv: Vec<Vec<f64>> = vs.par_iter().map(|&v| basis_row(sigma_v, v, q)).collect();
        // T = X·B_vᵀ: for each grid row j and each v_l, Σₖ xⱼₖ·B_v[l][k]  (m × V).
        let t: Vec<P> = self
            .points()
            .par_chunks(n)
            .flat_map_iter(|row| {
                bv.iter().map(move |b| row.iter().zip(b).fold(P::ZERO, |acc, (x, w)| acc + *x * *w))
            })
            .collect();
        let n_v = vs.len();
        let mut values = vec![P::ZERO; us.len() * n_v];
        values.par_chunks_mut(n_v).zip(us.par_iter()).for_each(|(out, &u)| {
            let bu = basis_row(sigma_u, u, p);
            for (j, w) in bu.iter().enumerate() {
                for (o, x) in out.iter_mut().zip(&t[j * n_v..(j + 1) * n_v]) {
                    *o += *x * *w;
                }
            }
        });
        Ok(GridSamples { n_u: us.len(), n_v, values })
    }

    /// ∂^{p+q}p/∂uᵖ∂v^q at (i/U, l/V) for i < U, l < V: the uniform grid over the whole
    /// period, by FFT along both axes (Theorem 5.3 applied twice).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] unless 1 ≤ U, V ≤ 2²⁴ and U·V ≤ 2²⁸.
    pub fn sample_uniform(
        &self,
        n_u: usize,
        n_v: usize,
        p: usize,
        q: usize,
    ) -> Result<GridSamples<P>, Error> {
        check_sizes(n_u, n_v)?;
        let (m, n) = (self.m(), self.n());
        if (n_u, n_v, p, q) == (m, n, 0, 0) {
            // The surface interpolates its grid (eq. 5.1): the samples are the grid itself.
            return Ok(GridSamples { n_u, n_v, values: self.points().to_vec() });
        }
        if n_u > 2 * (m / 2) && n_v > 2 * (n / 2) {
            // No frequency folds: the 2-D spectrum, padded.
            let values = crate::fft2::upsample(self.points(), (m, n), (n_u, n_v), (p, q));
            return Ok(GridSamples { n_u, n_v, values });
        }
        // Along v, every grid row: m rows of V samples.
        let rows: Vec<Vec<P>> = self
            .points()
            .par_chunks(n)
            .map(|row| Fourier::from_points(row).sample_uniform_deriv(n_v, q))
            .collect();
        // Along u, every column of that: V columns of U samples.
        let cols: Vec<Vec<P>> = (0..n_v)
            .into_par_iter()
            .map(|l| {
                let column: Vec<P> = (0..m).map(|j| rows[j][l]).collect();
                Fourier::from_points(&column).sample_uniform_deriv(n_u, p)
            })
            .collect();
        let mut values = vec![P::ZERO; n_u * n_v];
        values.par_chunks_mut(n_v).enumerate().for_each(|(i, out)| {
            for (l, o) in out.iter_mut().enumerate() {
                *o = cols[l][i];
            }
        });
        Ok(GridSamples { n_u, n_v, values })
    }
}
