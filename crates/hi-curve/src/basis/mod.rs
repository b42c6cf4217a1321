// SPDX-License-Identifier: MIT
//! The harmonic basis σⁿₖ (Hardy 2005, eq. 3.13 and 3.21–3.26) in all its evaluation forms.
//!
//! σⁿ(t) = sin(nπt) / (n·sin(πt)) for odd n, and cos(πt)·sin(nπt) / (n·sin(πt)) for even n;
//! σⁿₖ(t) = σⁿ(t − k/n). Both are 1-periodic and even, equal to 1 at the integers, and
//! σⁿₖ(j/n) = δⱼₖ, so X(t) = Σₖ σⁿₖ(t)·xₖ passes through every point.
//!
//! Four ways to evaluate the same function, as the thesis derives them: see [`Form`].
//!
//! Derivatives of any order come from the cosine sum (eq. 5.4 generalised).

mod chebyshev;
pub(crate) mod closed_form;
mod cosine_sum;
mod interval;
mod recurrence;

use crate::Error;

/// One of the four evaluation forms of σⁿₖ, which agree to rounding except where noted.
///
/// | form | source | cost | accuracy |
/// |---|---|---|---|
/// | `ClosedForm` | eq. 3.13 / 3.26 | O(1) | a few ulps, any t (argument reduced exactly) |
/// | `Recurrence` | §3.6, division-free | O(n) | a few ulps times √n |
/// | `CosineSum` | eq. 3.28 / 3.29 | O(n) | a few ulps times √n |
/// | `Chebyshev` | §3.9 | O(n) | degrades as n² near nodes, see [`Sigma::chebyshev`] |
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Form {
    /// sin(nπd)/(n·sin(πd)) (times cos(πd) for even n), eq. 3.13 and 3.26, with d = t − k/n
    /// reduced modulo 1 exactly. The default.
    ClosedForm,
    /// ς₁ = 1, ςⱼ = cos((j−1)πd) + cos(πd)·ςⱼ₋₁; σ = ςₙ/n (times cos(πd) for even n), §3.6.
    Recurrence,
    /// (1/n)·[1 + 2Σⱼ cos(2πjd)] (odd) or (1/n)·[1 + cos(nπd) + 2Σⱼ cos(2πjd)] (even),
    /// eq. 3.28 and 3.29.
    CosineSum,
    /// Uₙ₋₁(φₖ)/n (odd) or φₖ·Uₙ₋₁(φₖ)/n (even) with φₖ = s·cos(πk/n) + √(1−s²)·sin(πk/n) and
    /// s = cos(πt), t taken in [0, 1), §3.9.
    Chebyshev,
}

impl Form {
    /// All four forms, closed form first.
    pub const ALL: [Form; 4] =
        [Form::ClosedForm, Form::Recurrence, Form::CosineSum, Form::Chebyshev];
}

/// The harmonic basis of size n: the functions σⁿ₀, …, σⁿₙ₋₁ (Hardy 2005, §3.2–3.3).
///
/// The index k is taken modulo n everywhere, since σⁿₖ₊ₙ = σⁿₖ.
///
/// # Examples
///
/// ```
/// use hi_curve::{Form, Sigma};
///
/// let sigma = Sigma::new(4);
/// // σₖ(j/n) = δⱼₖ: the basis interpolates.
/// assert!((sigma.eval(1, 0.25) - 1.0).abs() < 1e-15);
/// assert!(sigma.eval(1, 0.5).abs() < 1e-15);
/// // A partition of unity at any t.
/// let sum: f64 = sigma.values(0.3).iter().sum();
/// assert!((sum - 1.0).abs() < 1e-15);
/// // All forms give the same value.
/// let t = 0.137;
/// for form in Form::ALL {
///     assert!((sigma.eval_form(form, 2, t) - sigma.eval(2, t)).abs() < 1e-14);
/// }
/// ```
#[doc(alias = "sigma")]
#[doc(alias = "Dirichlet kernel")]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Sigma {
    // Invariant: n >= 1.
    n: usize,
}

impl Sigma {
    /// The basis of size `n`.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroBasisSize`] if `n == 0`.
    pub fn try_new(n: usize) -> Result<Self, Error> {
        if n == 0 { Err(Error::ZeroBasisSize) } else { Ok(Self { n }) }
    }

    /// The basis of size `n`.
    ///
    /// # Panics
    ///
    /// Panics if `n == 0`; see [`Sigma::try_new`].
    #[must_use]
    pub fn new(n: usize) -> Self {
        Self::try_new(n).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The number of basis functions n.
    #[must_use]
    pub fn n(&self) -> usize {
        self.n
    }

    /// True if n is odd, where σ is the Dirichlet kernel itself (§3.2).
    #[must_use]
    pub fn is_odd(&self) -> bool {
        self.n % 2 == 1
    }

    /// σⁿ(t) = σⁿ₀(t), the kernel (eq. 3.13 / 3.26).
    #[must_use]
    pub fn kernel(&self, t: f64) -> f64 {
        self.eval(0, t)
    }

    /// σⁿₖ(t) in the closed form (eq. 3.13 / 3.26), the fastest and most accurate form.
    #[must_use]
    pub fn eval(&self, k: usize, t: f64) -> f64 {
        closed_form::eval(self.n, k % self.n, t)
    }

    /// σⁿₖ(t) in the chosen [`Form`].
    #[must_use]
    pub fn eval_form(&self, form: Form, k: usize, t: f64) -> f64 {
        let k = k % self.n;
        match form {
            Form::ClosedForm => closed_form::eval(self.n, k, t),
            Form::Recurrence => recurrence::eval(self.n, k, t),
            Form::CosineSum => cosine_sum::eval_deriv(self.n, k, t, 0),
            Form::Chebyshev => chebyshev::eval(self.n, k, t),
        }
    }

    /// σⁿₖ(t) by the division-free recurrence of §3.6; O(n).
    #[must_use]
    pub fn recurrence(&self, k: usize, t: f64) -> f64 {
        self.eval_form(Form::Recurrence, k, t)
    }

    /// σⁿₖ(t) by the cosine sum of eq. 3.28 (odd n) or 3.29 (even n); O(n).
    #[must_use]
    pub fn cosine_sum(&self, k: usize, t: f64) -> f64 {
        self.eval_form(Form::CosineSum, k, t)
    }

    /// σⁿₖ(t) by the Chebyshev form of §3.9; O(n).
    ///
    /// t is first taken modulo 1 into [0, 1), where √(1−s²) = sin(πt) holds. This form is the
    /// least accurate. The argument φₖ = cos(π(t − k/n)) is rounded to a double, and Uₙ₋₁ has
    /// slope up to n³/3 where φₖ is near ±1 (t next to a node), so the error grows like n²·ε/3
    /// (measured against the closed form for t ∈ [0.05, 0.95]: 3e-13 at n = 64, 4e-12 at
    /// n = 256, 5e-11 at n = 1024, 5e-10 at n = 4096). Near t ≡ 0 (mod 1), s = cos(πt) is flat
    /// and drops the low bits of t, which costs up to about n·1e-9.
    #[must_use]
    pub fn chebyshev(&self, k: usize, t: f64) -> f64 {
        self.eval_form(Form::Chebyshev, k, t)
    }

    /// The derivative dᵖσⁿₖ/dtᵖ(t) of any order p (p = 0 is the value), from the cosine sum
    /// (eq. 5.4 for p = 1): dᵖ/dtᵖ cos(ωt) = ωᵖ·cos(ωt + pπ/2). O(n).
    ///
    /// The magnitude grows like (πn)ᵖ; once that overflows (p ≳ 700/ln(πn)) the result is ±∞
    /// or NaN (∞ − ∞ between terms of the sum).
    #[must_use]
    pub fn deriv(&self, k: usize, t: f64, order: usize) -> f64 {
        if order == 0 {
            return self.eval(k, t);
        }
        cosine_sum::eval_deriv(self.n, k % self.n, t, order)
    }

    /// All n values σⁿ₀(t), …, σⁿₙ₋₁(t), in O(n) with one sine per function.
    #[must_use]
    pub fn values(&self, t: f64) -> Vec<f64> {
        let mut out = vec![0.0; self.n];
        closed_form::eval_all(self.n, t, &mut out);
        out
    }

    /// Calls `f(k, σⁿₖ(t))` for k = 0, …, n − 1 in order, without allocating: the values of
    /// [`Sigma::values`], bit for bit.
    ///
    /// # Examples
    ///
    /// ```
    /// let mut sum = 0.0;
    /// hi_curve::Sigma::new(6).for_each_value(0.3, |_, s| sum += s);
    /// assert!((sum - 1.0).abs() < 1e-14); // a partition of unity (Theorem 3.1)
    /// ```
    #[inline]
    pub fn for_each_value(&self, t: f64, f: impl FnMut(usize, f64)) {
        closed_form::for_each_value(self.n, t, f);
    }

    /// Writes σⁿ₀(t), …, σⁿₙ₋₁(t) into `out`, which is resized to n.
    pub fn values_into(&self, t: f64, out: &mut Vec<f64>) {
        out.resize(self.n, 0.0);
        closed_form::eval_all(self.n, t, out);
    }

    /// The complex kernel of eq. 3.23, returned as (real part, imaginary part).
    ///
    /// For even n the thesis first derives the complex operator
    /// Jᵗ = Σₖ [cos(π(t − k/n))·sin(nπ(t − k/n))/(n·sin(π(t − k/n))) + (i/n)·sin(π(nt − k))]·Jᵏ
    /// and keeps only its real part, which is σⁿₖ(t). The imaginary parts sum to zero over k,
    /// which is why taking the real part of the curve loses nothing. For odd n the kernel is
    /// real and the imaginary part is 0.
    #[must_use]
    pub fn complex(&self, k: usize, t: f64) -> (f64, f64) {
        let k = k % self.n;
        let re = self.eval(k, t);
        if self.is_odd() {
            return (re, 0.0);
        }
        // sin(π(nt − k)) = (−1)ᵏ·sin(π·n·t); n·t is formed exactly.
        let r = crate::sinpi::reduce_period(t);
        let s = crate::sinpi::sin_cos_pi_mul(self.n as f64, r).0;
        let sign = if k.is_multiple_of(2) { 1.0 } else { -1.0 };
        (re, sign * s / self.n as f64)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_is_rejected() {
        assert_eq!(Sigma::try_new(0), Err(Error::ZeroBasisSize));
    }

    #[test]
    fn n_equal_one_is_the_constant() {
        let s = Sigma::new(1);
        for form in Form::ALL {
            for t in [0.0, 0.3, -7.25, 0.999] {
                assert!((s.eval_form(form, 0, t) - 1.0).abs() < 1e-15, "{form:?} t={t}");
            }
        }
        assert_eq!(s.deriv(0, 0.3, 2), 0.0);
    }

    #[test]
    fn known_values() {
        // n = 3: σ(1/2) = sin(3π/2)/(3·sin(π/2)) = −1/3.
        assert!((Sigma::new(3).kernel(0.5) + 1.0 / 3.0).abs() < 1e-16);
        // n = 4: σ(1/2) = cos(π/2)·… = 0, σ(1/8) = cos(π/8)·sin(π/2)/(4 sin(π/8)).
        let s4 = Sigma::new(4);
        assert!(s4.kernel(0.5).abs() < 1e-16);
        let pi8 = std::f64::consts::PI / 8.0;
        assert!((s4.kernel(0.125) - pi8.cos() / (4.0 * pi8.sin())).abs() < 1e-15);
        // The even kernel is 1-periodic, not just 2-periodic (docs/math.md §1).
        assert!((s4.kernel(1.125) - s4.kernel(0.125)).abs() < 1e-15);
    }

    #[test]
    fn even_kernel_near_one_is_reduced() {
        // docs/math.md §1: the naive formula gives 1.0000942 at n = 6, t = 1 − 1e-12.
        let v = Sigma::new(6).kernel(1.0 - 1e-12);
        assert!((v - 1.0).abs() < 1e-15, "{v}");
    }

    #[test]
    fn complex_imaginary_parts_sum_to_zero() {
        let s = Sigma::new(8);
        for t in [0.1, 0.37, 0.9] {
            let im: f64 = (0..8).map(|k| s.complex(k, t).1).sum();
            assert!(im.abs() < 1e-15, "t={t}: {im}");
            // The imaginary part itself is not zero.
            assert!(s.complex(1, t).1.abs() > 1e-3);
        }
    }
}
