// SPDX-License-Identifier: MIT
//! The Bernstein polynomials Bⁿᵢ(t) = C(n, i)·tⁱ·(1 − t)ⁿ⁻ⁱ (Hardy 2005, eq. 2.2) and their
//! derivatives of every order (eq. 2.3 applied repeatedly).

/// The Bernstein basis of degree n: the n + 1 polynomials Bⁿᵢ(t) = C(n, i)·tⁱ·(1 − t)ⁿ⁻ⁱ,
/// i = 0, …, n (Hardy 2005, eq. 2.2).
///
/// Values are computed by the triangular recurrence Bʳᵢ = (1 − t)·Bʳ⁻¹ᵢ + t·Bʳ⁻¹ᵢ₋₁ (the
/// de Casteljau scheme run on the unit vectors), never through C(n, i) and powers, so they are
/// stable for every degree: for t ∈ [0, 1] every step is a convex combination of non-negative
/// numbers, nothing overflows even for n in the thousands, and Σᵢ Bⁿᵢ(t) = 1 to rounding.
///
/// Derivatives use d/dt Bⁿᵢ = n·(Bⁿ⁻¹ᵢ₋₁ − Bⁿ⁻¹ᵢ) (eq. 2.3) k times:
///
/// dᵏ/dtᵏ Bⁿᵢ(t) = n!/(n − k)! · Σⱼ₌₀ᵏ (−1)ᵏ⁻ʲ·C(k, j)·Bⁿ⁻ᵏᵢ₋ⱼ(t),
///
/// with Bᵐⱼ = 0 for j outside 0..=m; every derivative of order k > n is 0.
///
/// # Examples
///
/// ```
/// use hi_bezier::Bernstein;
///
/// let b = Bernstein::new(3);
/// // B³₁(t) = 3t(1 − t)², and the basis is a partition of unity (§2.5).
/// assert!((b.eval(1, 0.25) - 3.0 * 0.25 * 0.75 * 0.75).abs() < 1e-16);
/// assert!((b.values(0.3).iter().sum::<f64>() - 1.0).abs() < 1e-15);
/// // d/dt B³₃ = 3t², d²/dt² B³₃ = 6t.
/// assert!((b.eval_deriv(3, 0.5, 1) - 0.75).abs() < 1e-15);
/// assert!((b.eval_deriv(3, 0.5, 2) - 3.0).abs() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[doc(alias = "Bernstein polynomial")]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Bernstein {
    n: usize,
}

impl Bernstein {
    /// The basis of degree `n` (n + 1 polynomials).
    #[must_use]
    pub fn new(n: usize) -> Self {
        Self { n }
    }

    /// The degree n.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.n
    }

    /// Bⁿᵢ(t); 0 for i > n. Stable for every t (extrapolates outside [0, 1]).
    ///
    /// Runs the recurrence only on the entries 0..=min(i, n − i) that feed Bⁿᵢ, costing
    /// O(n·min(i, n − i)).
    #[must_use]
    pub fn eval(&self, i: usize, t: f64) -> f64 {
        let n = self.n;
        if i > n {
            return 0.0;
        }
        // By symmetry Bⁿᵢ(t) = Bⁿₙ₋ᵢ(1 − t): run the shorter band.
        if i <= n - i { band(n, i, t, 1.0 - t) } else { band(n, n - i, 1.0 - t, t) }
    }

    /// All of Bⁿ₀(t), …, Bⁿₙ(t) in O(n²).
    #[must_use]
    pub fn values(&self, t: f64) -> Vec<f64> {
        let mut out = Vec::new();
        self.values_into(t, &mut out);
        out
    }

    /// All of Bⁿ₀(t), …, Bⁿₙ(t), written into `out` (resized to n + 1).
    pub fn values_into(&self, t: f64, out: &mut Vec<f64>) {
        all_values(self.n, t, out);
    }

    /// All of Bⁿ₀(t), …, Bⁿₙ(t) and their first derivatives (eq. 2.3: n·(Bⁿ⁻¹ᵢ₋₁ − Bⁿ⁻¹ᵢ)) in
    /// fixed arrays of size `N`, entries above n zero, without allocating: the kernel of a
    /// patch evaluation inside a ray tracer. `None` when n ≥ `N`.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_bezier::Bernstein;
    ///
    /// let (b, db) = Bernstein::new(3).values_with_derivatives::<8>(0.25).unwrap();
    /// assert!((b[1] - 3.0 * 0.25 * 0.75 * 0.75).abs() < 1e-16);
    /// assert!((db[3] - 3.0 * 0.25 * 0.25).abs() < 1e-16); // d/dt t³
    /// assert_eq!(b[4..], [0.0; 4]);
    /// assert!(Bernstein::new(8).values_with_derivatives::<8>(0.5).is_none());
    /// ```
    #[must_use]
    pub fn values_with_derivatives<const N: usize>(&self, t: f64) -> Option<([f64; N], [f64; N])> {
        let n = self.n;
        if n >= N {
            return None;
        }
        let (mut b, mut db) = ([0.0; N], [0.0; N]);
        let s = 1.0 - t;
        b[0] = 1.0;
        for k in 1..=n {
            if k == n {
                // The derivative from the values of degree n − 1: n·(Bᵢ₋₁ − Bᵢ).
                for i in 0..=n {
                    let left = if i > 0 { b[i - 1] } else { 0.0 };
                    let right = if i < n { b[i] } else { 0.0 };
                    db[i] = n as f64 * (left - right);
                }
            }
            b[k] = t * b[k - 1];
            for i in (1..k).rev() {
                b[i] = s * b[i] + t * b[i - 1];
            }
            b[0] *= s;
        }
        Some((b, db))
    }

    /// The derivative of order `order` of Bⁿᵢ at t (order 0 is the value); 0 for i > n or
    /// order > n.
    #[must_use]
    pub fn eval_deriv(&self, i: usize, t: f64, order: usize) -> f64 {
        let n = self.n;
        if i > n || order > n {
            return 0.0;
        }
        let lower = Bernstein::new(n - order);
        let mut sum = 0.0;
        for j in 0..=order.min(i) {
            if i - j > n - order {
                continue;
            }
            let sign = if (order - j).is_multiple_of(2) { 1.0 } else { -1.0 };
            sum += sign * binomial(order, j) * lower.eval(i - j, t);
        }
        falling_factorial(n, order) * sum
    }

    /// The derivatives of order `order` of all n + 1 polynomials at t.
    #[must_use]
    pub fn derivs(&self, t: f64, order: usize) -> Vec<f64> {
        let n = self.n;
        let mut out = vec![0.0; n + 1];
        if order > n {
            return out;
        }
        let lower = Bernstein::new(n - order).values(t);
        let scale = falling_factorial(n, order);
        for (i, slot) in out.iter_mut().enumerate() {
            let mut sum = 0.0;
            for j in 0..=order.min(i) {
                if let Some(b) = lower.get(i - j) {
                    let sign = if (order - j).is_multiple_of(2) { 1.0 } else { -1.0 };
                    sum += sign * binomial(order, j) * b;
                }
            }
            *slot = scale * sum;
        }
        out
    }
}

/// Bⁿᵢ(t) for i ≤ n/2 by the recurrence restricted to indices 0..=i, with `a` = t and `b` = 1 − t
/// (swapped by the caller for the symmetric half).
fn band(n: usize, i: usize, a: f64, b: f64) -> f64 {
    let mut row = vec![0.0; i + 1];
    row[0] = 1.0;
    for r in 1..=n {
        // Entries above i never feed back into index i, so the row stops there.
        let hi = i.min(r);
        for j in (1..=hi).rev() {
            row[j] = b * row[j] + a * row[j - 1];
        }
        row[0] *= b;
    }
    row[i]
}

/// All Bⁿᵢ(t) by the triangular recurrence.
fn all_values(n: usize, t: f64, out: &mut Vec<f64>) {
    let s = 1.0 - t;
    out.clear();
    out.resize(n + 1, 0.0);
    out[0] = 1.0;
    for r in 1..=n {
        for j in (1..=r).rev() {
            out[j] = s * out[j] + t * out[j - 1];
        }
        out[0] *= s;
    }
}

/// The binomial coefficient C(n, k) as a float (exact while it fits in 53 bits), 0 for k > n.
#[must_use]
pub(crate) fn binomial(n: usize, k: usize) -> f64 {
    if k > n {
        return 0.0;
    }
    let k = k.min(n - k);
    let mut res = 1.0;
    for j in 0..k {
        // C(n, j + 1) = C(n, j)·(n − j)/(j + 1): every intermediate is an integer.
        res = res * (n - j) as f64 / (j + 1) as f64;
    }
    res.round()
}

/// n·(n − 1)·…·(n − k + 1) = n!/(n − k)!.
#[must_use]
pub(crate) fn falling_factorial(n: usize, k: usize) -> f64 {
    (0..k).map(|j| (n - j) as f64).product()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomials() {
        assert_eq!(binomial(5, 2), 10.0);
        assert_eq!(binomial(10, 0), 1.0);
        assert_eq!(binomial(10, 10), 1.0);
        assert_eq!(binomial(3, 4), 0.0);
        assert_eq!(binomial(52, 26), 495_918_532_948_104.0);
        assert_eq!(falling_factorial(5, 3), 60.0);
        assert_eq!(falling_factorial(5, 0), 1.0);
    }

    #[test]
    fn single_values_match_the_full_row() {
        for n in [0usize, 1, 2, 5, 13, 40] {
            let b = Bernstein::new(n);
            for &t in &[-0.5, 0.0, 0.1, 0.5, 0.77, 1.0, 1.3] {
                let row = b.values(t);
                for (i, v) in row.iter().enumerate() {
                    let w = b.eval(i, t);
                    assert!((v - w).abs() <= 1e-14 * (1.0 + v.abs()), "n={n} i={i} t={t}");
                }
                assert_eq!(b.eval(n + 1, t), 0.0, "beyond the degree");
            }
        }
    }

    #[test]
    fn high_degree_is_finite_and_sums_to_one() {
        let b = Bernstein::new(2000);
        let row = b.values(0.37);
        assert!(row.iter().all(|v| v.is_finite() && *v >= 0.0), "no overflow at n = 2000");
        assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-12, "partition of unity");
        // The peak is near i = n·t.
        assert!((b.eval(740, 0.37) - row[740]).abs() < 1e-15, "band evaluation");
    }
}
