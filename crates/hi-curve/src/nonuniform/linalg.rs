// SPDX-License-Identifier: MIT
//! Dense complex LU factorisation with partial pivoting, for the thesis's Vandermonde system.

use realfft::num_complex::Complex64;

/// An n×n complex matrix in row-major order, LU-factorised in place with partial pivoting.
#[derive(Debug)]
pub(super) struct Lu {
    n: usize,
    lu: Vec<Complex64>,
    perm: Vec<usize>,
}

impl Lu {
    /// Factorises `a` (row-major, n×n). Returns `None` if a pivot is exactly zero.
    pub(super) fn factor(mut a: Vec<Complex64>, n: usize) -> Option<Self> {
        debug_assert_eq!(a.len(), n * n, "matrix must be n×n");
        let mut perm: Vec<usize> = (0..n).collect();
        for col in 0..n {
            let pivot = (col..n)
                .max_by(|&i, &j| a[i * n + col].norm().total_cmp(&a[j * n + col].norm()))
                .expect("col < n");
            if a[pivot * n + col].norm() == 0.0 {
                return None;
            }
            if pivot != col {
                for c in 0..n {
                    a.swap(pivot * n + c, col * n + c);
                }
                perm.swap(pivot, col);
            }
            let inv = a[col * n + col].inv();
            for row in col + 1..n {
                let factor = a[row * n + col] * inv;
                a[row * n + col] = factor;
                for c in col + 1..n {
                    let upper = a[col * n + c];
                    a[row * n + c] -= factor * upper;
                }
            }
        }
        Some(Self { n, lu: a, perm })
    }

    /// Solves A·x = b.
    pub(super) fn solve(&self, b: &[Complex64]) -> Vec<Complex64> {
        let n = self.n;
        let mut x: Vec<Complex64> = self.perm.iter().map(|&p| b[p]).collect();
        for row in 0..n {
            for c in 0..row {
                let l = self.lu[row * n + c];
                x[row] = x[row] - l * x[c];
            }
        }
        for row in (0..n).rev() {
            for c in row + 1..n {
                let u = self.lu[row * n + c];
                x[row] = x[row] - u * x[c];
            }
            x[row] /= self.lu[row * n + row];
        }
        x
    }

    /// A⁻¹, row-major.
    pub(super) fn inverse(&self) -> Vec<Complex64> {
        let n = self.n;
        let mut inv = vec![Complex64::new(0.0, 0.0); n * n];
        let mut e = vec![Complex64::new(0.0, 0.0); n];
        for col in 0..n {
            e.fill(Complex64::new(0.0, 0.0));
            e[col] = Complex64::new(1.0, 0.0);
            let x = self.solve(&e);
            for row in 0..n {
                inv[row * n + col] = x[row];
            }
        }
        inv
    }
}

/// The 1-norm (largest column sum of moduli) of a row-major n×n matrix.
pub(super) fn norm1(a: &[Complex64], n: usize) -> f64 {
    (0..n).map(|c| (0..n).map(|r| a[r * n + c].norm()).sum::<f64>()).fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_and_inverts() {
        let c = |re: f64, im: f64| Complex64::new(re, im);
        let a = vec![c(0.0, 1.0), c(2.0, 0.0), c(1.0, -1.0), c(3.0, 0.5)];
        let lu = Lu::factor(a.clone(), 2).unwrap();
        let b = vec![c(1.0, 2.0), c(-1.0, 0.0)];
        let x = lu.solve(&b);
        for r in 0..2 {
            let ax = a[r * 2] * x[0] + a[r * 2 + 1] * x[1];
            assert!((ax - b[r]).norm() < 1e-15);
        }
        let inv = lu.inverse();
        let prod00 = a[0] * inv[0] + a[1] * inv[2];
        let prod01 = a[0] * inv[1] + a[1] * inv[3];
        assert!((prod00 - c(1.0, 0.0)).norm() < 1e-15 && prod01.norm() < 1e-15);
        assert!(Lu::factor(vec![c(1.0, 0.0), c(2.0, 0.0), c(2.0, 0.0), c(4.0, 0.0)], 2).is_none());
    }
}
