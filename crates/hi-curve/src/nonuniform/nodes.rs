// SPDX-License-Identifier: MIT
//! Trigonometric interpolation at arbitrary nodes in barycentric form (Henrici 1979,
//! Berrut 1984): the non-uniform curve that really passes through xₖ at tₖ.
//!
//! With wₖ = 1/Πⱼ≠ₖ sin(π(tₖ − tⱼ)) and g = csc for odd n, cot for even n:
//!
//! X(t) = Σₖ wₖ·g(π(t − tₖ))·xₖ / Σₖ wₖ·g(π(t − tₖ)).
//!
//! The cardinal functions are ℓₖ(t) = Πⱼ≠ₖ sin(π(t − tⱼ))/sin(π(tₖ − tⱼ)) for odd n and the
//! same times cos(π(t − tₖ)) for even n. For even n all ℓₖ share the top term
//! sin(π(nt − Σⱼtⱼ)), so they span one n-dimensional space that contains the constants: the
//! interpolant exists and is unique for every set of distinct nodes, the ℓₖ sum to 1 (the
//! curve is affine invariant), and for tₖ = k/n the space is the harmonic one and ℓₖ = σⁿₖ.
//! No linear system is solved: O(n²) set-up, O(n) per evaluation.

use super::max_over_gaps;
use crate::sinpi::{reduce_period, sin_cos_pi};
use crate::{ControlPoint, Fourier};

#[derive(Clone, Debug, PartialEq)]
pub(super) struct Nodes<P> {
    points: Vec<P>,
    params: Vec<f64>,
    /// Barycentric weights, scaled so the largest magnitude is 1.
    weights: Vec<f64>,
    even: bool,
    /// The spectrum of the interpolant (for derivatives).
    fourier: Fourier<P>,
}

impl<P: ControlPoint> Nodes<P> {
    pub(super) fn new(points: &[P], params: &[f64]) -> Self {
        let n = points.len();
        // log|wₖ| and sign, to avoid under- and overflow for large n.
        let mut logs = Vec::with_capacity(n);
        let mut signs = Vec::with_capacity(n);
        for k in 0..n {
            let (mut log, mut sign) = (0.0, 1.0);
            for j in (0..n).filter(|&j| j != k) {
                let s = sin_cos_pi(params[k] - params[j]).0;
                log -= s.abs().ln();
                if s < 0.0 {
                    sign = -sign;
                }
            }
            logs.push(log);
            signs.push(sign);
        }
        let top = logs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let weights = logs.iter().zip(&signs).map(|(l, s)| s * (l - top).exp()).collect();
        let mut res = Self {
            points: points.to_vec(),
            params: params.to_vec(),
            weights,
            even: n.is_multiple_of(2),
            fourier: Fourier::from_points(&[P::ZERO]),
        };
        // The interpolant has degree ⌊n/2⌋; an odd number L ≥ n of uniform samples determines it.
        let n_samples = n | 1;
        let samples: Vec<P> =
            (0..n_samples).map(|l| res.eval(l as f64 / n_samples as f64)).collect();
        res.fourier = Fourier::from_points(&samples);
        res
    }

    pub(super) fn fourier(&self) -> &Fourier<P> {
        &self.fourier
    }

    /// gₖ(t)·wₖ for every k, or `Err(k)` if t is node k.
    fn terms(&self, t: f64, mut f: impl FnMut(usize, f64)) -> Result<(), usize> {
        // One reduction of t for all k: csc(π(t − tₖ)) changes sign under t → t + 1, so every
        // term must see the same representative of t.
        let t01 = {
            let r = reduce_period(t);
            if r < 0.0 { r + 1.0 } else { r }
        };
        for (k, (&tk, &wk)) in self.params.iter().zip(&self.weights).enumerate() {
            let d = t01 - tk;
            if d == 0.0 {
                return Err(k);
            }
            let (s, c) = sin_cos_pi(d);
            let g = if self.even { c / s } else { 1.0 / s };
            f(k, wk * g);
        }
        Ok(())
    }

    pub(super) fn eval(&self, t: f64) -> P {
        if self.points.len() == 1 {
            return self.points[0];
        }
        let mut num = P::ZERO;
        let mut den = 0.0;
        match self.terms(t, |k, w| {
            num += self.points[k] * w;
            den += w;
        }) {
            Ok(()) => num * (1.0 / den),
            Err(k) => self.points[k],
        }
    }

    /// maxₜ Σₖ |ℓₖ(t)| with ℓₖ = wₖgₖ/Σⱼ wⱼgⱼ.
    pub(super) fn lebesgue(&self) -> f64 {
        max_over_gaps(&self.params, true, |t| {
            let (mut abs_sum, mut sum) = (0.0, 0.0);
            match self.terms(t, |_, w| {
                abs_sum += w.abs();
                sum += w;
            }) {
                Ok(()) => abs_sum / sum.abs(),
                Err(_) => 1.0,
            }
        })
    }
}
