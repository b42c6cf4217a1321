// SPDX-License-Identifier: MIT
//! The thesis's final non-uniform formula (§3.10), as printed, with the real part taken.
//!
//! X(t) = Re Σⱼ e^{iωⱼt}·wⱼ with ωⱼ = 2π(n−1)(tⱼ − m/n), w = A⁻¹x, Aₖⱼ = e^{2πik(tⱼ − m/n)},
//! m = ⌊n/2⌋. A is a Vandermonde matrix in the distinct unit-circle nodes e^{2πi(tⱼ − m/n)},
//! so it is invertible; it is solved by LU with partial pivoting, O(n³).

use realfft::num_complex::Complex64;

use super::linalg::{Lu, norm1};
use super::{ComplexPoint, complex_of, max_over_gaps};
use crate::sinpi::{pow_order, quarter_turns, sin_cos_pi};
use crate::{ControlPoint, Error};

#[derive(Clone, Debug, PartialEq)]
pub(super) struct Thesis<P> {
    /// ωⱼ/π = 2(n−1)(tⱼ − m/n).
    omegas_over_pi: Vec<f64>,
    /// wⱼ = (A⁻¹x)ⱼ per coordinate.
    weights: Vec<ComplexPoint<P>>,
    /// A⁻¹, row-major.
    inverse: Vec<Complex64>,
    matrix_condition: f64,
}

impl<P: ControlPoint> Thesis<P> {
    pub(super) fn new(points: &[P], params: &[f64]) -> Result<Self, Error> {
        let n = points.len();
        let m = (n / 2) as f64;
        let nf = n as f64;
        let shifted: Vec<f64> = params.iter().map(|&t| t - m / nf).collect();
        // Aₖⱼ = e^{2πik(tⱼ − m/n)}, row k, column j.
        let mut a = Vec::with_capacity(n * n);
        for k in 0..n {
            for &s in &shifted {
                let (sin, cos) = sin_cos_pi(2.0 * k as f64 * s);
                a.push(Complex64::new(cos, sin));
            }
        }
        let norm_a = norm1(&a, n);
        let lu =
            Lu::factor(a, n).ok_or(Error::Singular { what: "Vandermonde matrix of §3.10" })?;
        let inverse = lu.inverse();
        let matrix_condition = norm_a * norm1(&inverse, n);
        if !matrix_condition.is_finite() {
            return Err(Error::Singular { what: "Vandermonde matrix of §3.10" });
        }
        let coords: Vec<Vec<Complex64>> = (0..P::DIM)
            .map(|i| {
                let rhs: Vec<Complex64> =
                    points.iter().map(|p| Complex64::new(p.coord(i), 0.0)).collect();
                lu.solve(&rhs)
            })
            .collect();
        let weights = (0..n).map(|j| complex_of(&coords, j)).collect();
        let omegas_over_pi = shifted.iter().map(|s| 2.0 * (nf - 1.0) * s).collect();
        Ok(Self { omegas_over_pi, weights, inverse, matrix_condition })
    }

    /// Re Σⱼ (iωⱼ)ᵖ·e^{iωⱼt}·wⱼ.
    pub(super) fn eval_deriv(&self, t: f64, order: usize) -> P {
        let mut res = P::ZERO;
        for (&w_pi, &(re, im)) in self.omegas_over_pi.iter().zip(&self.weights) {
            let (s, c) = sin_cos_pi(w_pi * t);
            let (sp, cp) = quarter_turns(s, c, order);
            let scale = pow_order(w_pi * std::f64::consts::PI, order);
            // Re[(cp + i sp)(re + i im)] = cp·re − sp·im
            res += (re * cp - im * sp) * scale;
        }
        res
    }

    pub(super) fn matrix_condition(&self) -> f64 {
        self.matrix_condition
    }

    /// maxₜ Σₖ |Re Σⱼ e^{iωⱼt}(A⁻¹)ⱼₖ| on t ∈ [0, 1].
    pub(super) fn lebesgue(&self) -> f64 {
        let n = self.weights.len();
        if n == 1 {
            return 1.0;
        }
        let nodes: Vec<f64> = (0..n).map(|k| k as f64 / (n - 1) as f64).collect();
        max_over_gaps(&nodes, false, |t| {
            let e: Vec<Complex64> = self
                .omegas_over_pi
                .iter()
                .map(|&w_pi| {
                    let (s, c) = sin_cos_pi(w_pi * t);
                    Complex64::new(c, s)
                })
                .collect();
            (0..n)
                .map(|k| (0..n).map(|j| (e[j] * self.inverse[j * n + k]).re).sum::<f64>().abs())
                .sum::<f64>()
        })
    }
}
