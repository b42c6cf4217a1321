// SPDX-License-Identifier: MIT
//! A symmetric positive definite matrix that is banded but for its last row and column, which
//! may be full (an "arrow"), and its Cholesky factorisation: the normal equations of a hole's
//! cap fairing (`holes`), whose vertices, ordered spoke by spoke, couple only to the spokes
//! about them, but for the centre, which neighbours the whole innermost ring.
//!
//! Factorising an n × n matrix of half-bandwidth b costs about n b² operations and solving
//! with the factor 2 n b (Golub and Van Loan, *Matrix Computations*, 4th ed., §4.3.5, banded
//! Cholesky); the full last row adds n b and 2 n.

use glam::DVec3;

/// A symmetric n × n matrix M with M\[i\]\[j\] = 0 for |i − j| > `band` unless i or j is n − 1,
/// its lower triangle stored: row i < n − 1 from column i − `band` (or 0) to i, and the whole
/// last row.
#[derive(Debug, Clone)]
pub(super) struct ArrowBand {
    n: usize,
    band: usize,
    /// Row i's entry at column i − d is `rows[i * (band + 1) + d]`, for d in 0..=band.
    rows: Vec<f64>,
    /// The last row, columns 0..n.
    last: Vec<f64>,
}

impl ArrowBand {
    /// The zero matrix of order `n` (at least 1) and half-bandwidth `band`.
    pub(super) fn zeros(n: usize, band: usize) -> Self {
        ArrowBand { n, band, rows: vec![0.0; n * (band + 1)], last: vec![0.0; n] }
    }

    /// Adds `value` to M\[i\]\[j\] and, for i ≠ j, to M\[j\]\[i\]. Returns `false`, changing
    /// nothing, when (i, j) lies outside the band, the last row and the last column.
    pub(super) fn add(&mut self, i: usize, j: usize, value: f64) -> bool {
        let (hi, lo) = if i >= j { (i, j) } else { (j, i) };
        if hi >= self.n {
            false
        } else if hi + 1 == self.n {
            self.last[lo] += value;
            true
        } else if hi - lo <= self.band {
            self.rows[hi * (self.band + 1) + hi - lo] += value;
            true
        } else {
            false
        }
    }

    /// The lower-triangular factor L with L Lᵀ = M, stored in the same shape (banded Cholesky:
    /// a row's fill stays within the band, and the last row's within itself). `None` when a
    /// pivot is not positive and finite: M is not positive definite (to rounding).
    pub(super) fn cholesky(mut self) -> Option<Self> {
        let (n, b) = (self.n, self.band);
        let w = b + 1;
        for i in 0..n - 1 {
            let first = i.saturating_sub(b);
            for j in first..=i {
                // L[i][j] = (M[i][j] − Σ_k L[i][k] L[j][k]) / L[j][j], k over both rows' bands.
                let from = first.max(j.saturating_sub(b));
                let mut sum = self.rows[i * w + i - j];
                for k in from..j {
                    sum -= self.rows[i * w + i - k] * self.rows[j * w + j - k];
                }
                if j == i {
                    if !(sum > 0.0 && sum.is_finite()) {
                        return None;
                    }
                    self.rows[i * w] = sum.sqrt();
                } else {
                    self.rows[i * w + i - j] = sum / self.rows[j * w];
                }
            }
        }
        // The last row: L[n−1][j] for every j, then its pivot.
        for j in 0..n - 1 {
            let mut sum = self.last[j];
            for k in j.saturating_sub(b)..j {
                sum -= self.last[k] * self.rows[j * w + j - k];
            }
            self.last[j] = sum / self.rows[j * w];
        }
        let pivot = self.last[n - 1] - self.last[..n - 1].iter().map(|l| l * l).sum::<f64>();
        if !(pivot > 0.0 && pivot.is_finite()) {
            return None;
        }
        self.last[n - 1] = pivot.sqrt();
        Some(self)
    }

    /// Solves M x = `rhs` in place (three right-hand sides at once, one per coordinate), with
    /// `self` the factor L of [`cholesky`](Self::cholesky): L y = rhs forwards, then Lᵀ x = y
    /// backwards.
    pub(super) fn solve(&self, rhs: &mut [DVec3]) {
        let (n, b) = (self.n, self.band);
        let w = b + 1;
        for i in 0..n - 1 {
            // Row i's entries at columns i − 1, i − 2, … (d = 1, 2, …).
            let from = i.saturating_sub(b);
            let row = &self.rows[i * w + 1..=i * w + i - from];
            let known: DVec3 = rhs[from..i].iter().rev().zip(row).map(|(y, l)| *y * *l).sum();
            rhs[i] = (rhs[i] - known) / self.rows[i * w];
        }
        let known: DVec3 = rhs[..n - 1].iter().zip(&self.last).map(|(y, l)| *y * *l).sum();
        // y[n − 1], then at once x[n − 1] = y[n − 1] / L[n − 1][n − 1].
        rhs[n - 1] = (rhs[n - 1] - known) / (self.last[n - 1] * self.last[n - 1]);
        // Backwards: x[i] = (y[i] − Σ_{k > i} L[k][i] x[k]) / L[i][i].
        for i in (0..n - 1).rev() {
            let below: DVec3 =
                (i + 1..(i + w).min(n - 1)).map(|k| rhs[k] * self.rows[k * w + k - i]).sum();
            rhs[i] = (rhs[i] - rhs[n - 1] * self.last[i] - below) / self.rows[i * w];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The factor solves what a dense elimination does: a matrix of order 9, band 2 and a full
    /// last row, M = Aᵀ A + I for a fixed A (positive definite), against Gauss–Jordan
    /// elimination with partial pivoting on the dense matrix, written out here.
    #[test]
    fn the_arrow_band_factor_solves_as_dense_elimination_does() {
        let n = 9;
        let band = 2;
        // Rows of A, each touching columns within the band, and one touching the last column.
        let mut dense = vec![vec![0.0f64; n]; n];
        let mut m = ArrowBand::zeros(n, band);
        for (i, row) in dense.iter_mut().enumerate() {
            row[i] += 1.0;
            assert!(m.add(i, i, 1.0));
        }
        for r in 0..n - 1 {
            let mut row: Vec<(usize, f64)> = (r..(r + band + 1).min(n - 1))
                .map(|c| (c, 1.0 + (r * 7 + c * 3) as f64 % 5.0))
                .collect();
            if r % 3 == 0 {
                row.push((n - 1, -0.5 - r as f64 / 10.0));
            }
            for &(a, wa) in &row {
                for &(c, wc) in &row {
                    dense[a][c] += wa * wc;
                    if a >= c {
                        assert!(m.add(a, c, wa * wc));
                    }
                }
            }
        }
        assert!(!m.add(5, 1, 1.0), "outside the band");
        let rhs: Vec<DVec3> =
            (0..n).map(|i| DVec3::new(i as f64, 1.0 - i as f64 * 0.5, (i * i) as f64)).collect();
        let mut x = rhs.clone();
        m.cholesky().expect("positive definite").solve(&mut x);
        // Gauss–Jordan on [dense | rhs], one coordinate at a time.
        for axis in 0..3 {
            let mut a: Vec<Vec<f64>> =
                (0..n).map(|i| [dense[i].clone(), vec![rhs[i][axis]]].concat()).collect();
            for col in 0..n {
                let p =
                    (col..n).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs())).unwrap();
                a.swap(col, p);
                let pivot = a[col][col];
                for v in &mut a[col] {
                    *v /= pivot;
                }
                for i in 0..n {
                    if i != col {
                        let f = a[i][col];
                        let pivot_row = a[col].clone();
                        for (v, p) in a[i].iter_mut().zip(&pivot_row) {
                            *v -= f * p;
                        }
                    }
                }
            }
            for i in 0..n {
                assert!(
                    (x[i][axis] - a[i][n]).abs() < 1e-10,
                    "x[{i}][{axis}] {} against {}",
                    x[i][axis],
                    a[i][n]
                );
            }
        }
    }

    /// A matrix that is not positive definite has no factor.
    #[test]
    fn an_indefinite_matrix_has_no_factor() {
        let mut m = ArrowBand::zeros(3, 1);
        for (i, j, v) in [(0, 0, 1.0), (1, 0, 2.0), (1, 1, 1.0), (2, 2, 1.0)] {
            assert!(m.add(i, j, v));
        }
        assert!(m.cholesky().is_none(), "[[1, 2], [2, 1]] is indefinite");
        let mut m = ArrowBand::zeros(3, 1);
        for (i, j, v) in [(0, 0, 1.0), (1, 1, 1.0), (2, 0, 2.0), (2, 2, 1.0)] {
            assert!(m.add(i, j, v));
        }
        assert!(m.cholesky().is_none(), "the last row makes it indefinite");
    }
}
