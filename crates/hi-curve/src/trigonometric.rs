// SPDX-License-Identifier: MIT
//! Trigonometric interpolation as in §2.13 of the thesis (figure 3.13, 3.14).
//!
//! q(t) = Σₖ₌₀ⁿ⁻¹ cₖ·e^{2πikt} with cₖ = (1/n)·Σₘ xₘ·e^{−2πikm/n}, the discrete Fourier
//! transform of the points: frequencies 0, …, n−1, not the symmetric −⌊n/2⌋…⌊n/2⌋ of the
//! harmonic curve. For real points q is complex between the nodes; the thesis plots each
//! coordinate's real part, which interpolates the points (q(k/n) = xₖ) but oscillates with
//! frequencies up to n − 1. That is the curve this type evaluates; [`TrigonometricCurve::eval_complex`]
//! gives the imaginary part too.

use std::f64::consts::PI;

use crate::differential::ParamCurve;
use crate::point::check_points;
use crate::sinpi::{for_each_harmonic, pow_order, quarter_turns};
use crate::{ControlPoint, Error, Fourier};

/// The trigonometric interpolant of §2.13 (frequencies 0…n−1), real part per coordinate.
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::{HarmonicCurve, TrigonometricCurve};
///
/// let square = vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
/// let trig = TrigonometricCurve::try_new(square.clone()).unwrap();
/// // It interpolates, but it is not the circle the harmonic curve draws.
/// assert!((trig.eval(0.25) - DVec2::Y).length() < 1e-15);
/// let harmonic = HarmonicCurve::new(square);
/// assert!((trig.eval(0.125) - harmonic.eval(0.125)).length() > 0.1);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TrigonometricCurve<P> {
    // Invariant: non-empty, finite; coeffs[k] = (Re cₖ, Im cₖ) for k < n.
    points: Vec<P>,
    coeffs: Vec<(P, P)>,
}

impl<P: ControlPoint> TrigonometricCurve<P> {
    /// The trigonometric interpolant of §2.13 through `points` at t = k/n.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] or [`Error::NonFinitePoint`].
    pub fn try_new(points: Vec<P>) -> Result<Self, Error> {
        check_points(&points)?;
        let n = points.len();
        let f = Fourier::from_points(&points);
        let (a, b) = (f.cos_coeffs(), f.sin_coeffs());
        // cⱼ = X̂ⱼ/n: from the real spectrum, cⱼ = (aⱼ − i bⱼ)/2 for 0 < j < n/2, c₀ = a₀,
        // c_{n/2} = a_{n/2} for even n, and c_{n−j} = c̄ⱼ.
        let coeffs = (0..n)
            .map(|k| {
                let (j, conj) = if k <= n / 2 { (k, false) } else { (n - k, true) };
                if j == 0 || (n.is_multiple_of(2) && j == n / 2) {
                    (a[j], P::ZERO)
                } else {
                    let im = b[j] * -0.5;
                    (a[j] * 0.5, if conj { -im } else { im })
                }
            })
            .collect();
        Ok(Self { points, coeffs })
    }

    /// The interpolated points.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The coefficients cₖ = (Re, Im) for k = 0, …, n−1.
    #[must_use]
    pub fn coeffs(&self) -> &[(P, P)] {
        &self.coeffs
    }

    /// Re q(t), coordinate by coordinate.
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        self.eval_deriv(t, 0)
    }

    /// (Re q(t), Im q(t)).
    #[must_use]
    pub fn eval_complex(&self, t: f64) -> (P, P) {
        self.eval_complex_deriv(t, 0)
    }

    /// Re q⁽ᵖ⁾(t).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        self.eval_complex_deriv(t, order).0
    }

    /// q⁽ᵖ⁾(t) = Σₖ (2πik)ᵖ·cₖ·e^{2πikt}, as (real part, imaginary part).
    #[must_use]
    pub fn eval_complex_deriv(&self, t: f64, order: usize) -> (P, P) {
        let (mut re, mut im) = if order == 0 { self.coeffs[0] } else { (P::ZERO, P::ZERO) };
        for_each_harmonic(t, self.coeffs.len() - 1, |k, c, s| {
            // (2πk)ᵖ·e^{i(2πkt + pπ/2)}·(cr + i·ci)
            let w = pow_order(2.0 * PI * k as f64, order);
            let (sp, cp) = quarter_turns(s, c, order);
            let (cr, ci) = self.coeffs[k];
            re += (cr * cp - ci * sp) * w;
            im += (cr * sp + ci * cp) * w;
        });
        (re, im)
    }
}

impl<P: ControlPoint> ParamCurve<P> for TrigonometricCurve<P> {
    fn eval(&self, t: f64) -> P {
        TrigonometricCurve::eval(self, t)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> P {
        TrigonometricCurve::eval_deriv(self, t, order)
    }

    fn scale(&self) -> f64 {
        crate::curve::spread(&self.points, self.coeffs[0].0)
    }

    fn is_periodic(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coefficients_are_the_dft() {
        let x = [1.0, -2.0, 0.5, 3.0, 0.25];
        let q = TrigonometricCurve::try_new(x.to_vec()).unwrap();
        let n = x.len();
        for (k, &(re, im)) in q.coeffs().iter().enumerate() {
            let (mut dr, mut di) = (0.0, 0.0);
            for (m, xm) in x.iter().enumerate() {
                let a = -2.0 * PI * (k * m) as f64 / n as f64;
                dr += xm * a.cos() / n as f64;
                di += xm * a.sin() / n as f64;
            }
            assert!((re - dr).abs() < 1e-15 && (im - di).abs() < 1e-15, "k={k}");
        }
        for (k, xk) in x.iter().enumerate() {
            let (re, im) = q.eval_complex(k as f64 / n as f64);
            assert!((re - xk).abs() < 1e-14 && im.abs() < 1e-14, "k={k}");
        }
    }
}
