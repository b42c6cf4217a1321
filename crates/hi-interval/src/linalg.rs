// SPDX-License-Identifier: MIT
//! Interval vectors and matrices with the norms of Hardy 2005, §5.6: ‖X‖ = maxᵢ |Xᵢ|, the
//! distance d(X, Y) = max(‖a − c‖, ‖b − d‖), the maximum row-sum norm ‖A‖ = maxᵢ Σⱼ |Aᵢⱼ|
//! (compatible: ‖AX‖ ≤ ‖A‖ ‖X‖), and the mean-value form C(f, X, y) = f(y) + F′(X)(X − y).
//!
//! Vectors are plain slices `&[Interval]` (boxes); matrices are the row-major [`IntervalMatrix`].
//! All norms are rounded up, so they bound the real norms from above.

use crate::Interval;
use crate::round::add_up;

/// The interval vector norm ‖X‖ = maxᵢ |Xᵢ| (§5.6), with |Xᵢ| the magnitude.
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, norm};
/// assert_eq!(norm(&[Interval::new(-3.0, 1.0), Interval::new(2.0, 2.5)]), 3.0);
/// ```
#[must_use]
pub fn norm(x: &[Interval]) -> f64 {
    x.iter().map(|v| v.mag()).fold(0.0, f64::max)
}

/// The distance d(X, Y) = max(‖a − c‖, ‖b − d‖) between interval vectors with lower ends a, c
/// and upper ends b, d (§5.6), rounded up; `+∞` when the lengths differ or an entry is empty.
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, distance};
/// let x = [Interval::new(0.0, 1.0)];
/// let y = [Interval::new(0.5, 3.0)];
/// assert_eq!(distance(&x, &y), 2.0);
/// ```
#[must_use]
pub fn distance(x: &[Interval], y: &[Interval]) -> f64 {
    if x.len() != y.len() || x.iter().chain(y).any(|v| v.is_empty()) {
        return f64::INFINITY;
    }
    x.iter()
        .zip(y)
        .map(|(p, q)| {
            (Interval::point(p.lo()) - Interval::point(q.lo()))
                .mag()
                .max((Interval::point(p.hi()) - Interval::point(q.hi())).mag())
        })
        .fold(0.0, f64::max)
}

/// Midpoints m(X) of a box, entry by entry (§5.6).
#[must_use]
pub fn midpoint(x: &[Interval]) -> Vec<f64> {
    x.iter().map(|v| v.mid()).collect()
}

/// Largest entry width of a box (`0` for an empty slice).
#[must_use]
pub fn max_width(x: &[Interval]) -> f64 {
    x.iter().map(|v| v.width()).fold(0.0, f64::max)
}

/// Entry-wise hull of two boxes of the same length.
#[must_use]
pub fn hull(x: &[Interval], y: &[Interval]) -> Vec<Interval> {
    x.iter().zip(y).map(|(a, b)| a.hull(*b)).collect()
}

/// Entry-wise intersection; `None` when some entry is empty (the boxes are disjoint).
#[must_use]
pub fn intersection(x: &[Interval], y: &[Interval]) -> Option<Vec<Interval>> {
    let res: Vec<Interval> = x.iter().zip(y).map(|(a, b)| a.intersection(*b)).collect();
    if res.iter().any(|v| v.is_empty()) { None } else { Some(res) }
}

/// A dense row-major matrix of intervals (§5.6: "matrices with intervals as entries").
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, IntervalMatrix};
/// let a = IntervalMatrix::from_rows(vec![
///     vec![Interval::new(1.0, 2.0), Interval::new(-1.0, 0.0)],
///     vec![Interval::ZERO, Interval::new(0.5, 0.5)],
/// ]);
/// assert_eq!(a.norm(), 3.0); // max(2 + 1, 0.5)
/// let x = [Interval::new(1.0, 1.0), Interval::new(2.0, 2.0)];
/// let y = a.mul_vec(&x);
/// assert_eq!(y[0], Interval::new(-1.0, 2.0));
/// assert!(a.mul_vec(&x)[0].mag() <= a.norm() * hi_interval::norm(&x)); // compatibility
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct IntervalMatrix {
    // Invariant: entries.len() == n_rows * n_cols.
    n_rows: usize,
    n_cols: usize,
    entries: Vec<Interval>,
}

impl IntervalMatrix {
    /// The `n_rows × n_cols` zero matrix.
    #[must_use]
    pub fn zeros(n_rows: usize, n_cols: usize) -> Self {
        Self { n_rows, n_cols, entries: vec![Interval::ZERO; n_rows * n_cols] }
    }

    /// The `n × n` identity I.
    #[must_use]
    pub fn identity(n: usize) -> Self {
        let mut res = Self::zeros(n, n);
        for i in 0..n {
            res.set(i, i, Interval::ONE);
        }
        res
    }

    /// A matrix from rows. Rows shorter than the first are padded with `[0, 0]`, longer ones cut,
    /// so this never panics.
    #[must_use]
    pub fn from_rows(rows: Vec<Vec<Interval>>) -> Self {
        let n_rows = rows.len();
        let n_cols = rows.first().map_or(0, Vec::len);
        let mut res = Self::zeros(n_rows, n_cols);
        for (i, row) in rows.into_iter().enumerate() {
            for (j, v) in row.into_iter().take(n_cols).enumerate() {
                res.set(i, j, v);
            }
        }
        res
    }

    /// A point matrix from real rows (see [`IntervalMatrix::from_rows`] for ragged rows).
    #[must_use]
    pub fn from_real_rows(rows: &[Vec<f64>]) -> Self {
        Self::from_rows(
            rows.iter().map(|r| r.iter().map(|&v| Interval::point(v)).collect()).collect(),
        )
    }

    /// Number of rows.
    #[must_use]
    pub fn n_rows(&self) -> usize {
        self.n_rows
    }

    /// Number of columns.
    #[must_use]
    pub fn n_cols(&self) -> usize {
        self.n_cols
    }

    /// Entry (i, j); `EMPTY` outside the matrix.
    #[must_use]
    pub fn get(&self, i: usize, j: usize) -> Interval {
        if i < self.n_rows && j < self.n_cols {
            self.entries[i * self.n_cols + j]
        } else {
            Interval::EMPTY
        }
    }

    /// Sets entry (i, j); ignored outside the matrix.
    pub fn set(&mut self, i: usize, j: usize, v: Interval) {
        if i < self.n_rows && j < self.n_cols {
            self.entries[i * self.n_cols + j] = v;
        }
    }

    /// The maximum row-sum norm ‖A‖ = maxᵢ Σⱼ |Aᵢⱼ| (§5.6), rounded up.
    #[must_use]
    pub fn norm(&self) -> f64 {
        (0..self.n_rows)
            .map(|i| (0..self.n_cols).map(|j| self.get(i, j).mag()).fold(0.0, add_up))
            .fold(0.0, f64::max)
    }

    /// Entry-wise midpoints m(A) as rows of doubles.
    #[must_use]
    pub fn midpoint(&self) -> Vec<Vec<f64>> {
        (0..self.n_rows).map(|i| (0..self.n_cols).map(|j| self.get(i, j).mid()).collect()).collect()
    }

    /// The product A·X with a box X; entries beyond `x.len()` count as empty, giving empty rows.
    #[must_use]
    pub fn mul_vec(&self, x: &[Interval]) -> Vec<Interval> {
        (0..self.n_rows)
            .map(|i| {
                if x.len() != self.n_cols {
                    return Interval::EMPTY;
                }
                (0..self.n_cols).map(|j| self.get(i, j) * x[j]).sum()
            })
            .collect()
    }

    /// The product A·B; an empty matrix of the right size when the shapes do not match.
    #[must_use]
    pub fn mul_mat(&self, b: &Self) -> Self {
        let mut res = Self::zeros(self.n_rows, b.n_cols);
        for i in 0..self.n_rows {
            for j in 0..b.n_cols {
                let v = if self.n_cols == b.n_rows {
                    (0..self.n_cols).map(|k| self.get(i, k) * b.get(k, j)).sum()
                } else {
                    Interval::EMPTY
                };
                res.set(i, j, v);
            }
        }
        res
    }

    /// A − B entry by entry (shapes must match; otherwise the result has empty entries).
    #[must_use]
    pub fn sub_mat(&self, b: &Self) -> Self {
        let mut res = Self::zeros(self.n_rows, self.n_cols);
        for i in 0..self.n_rows {
            for j in 0..self.n_cols {
                res.set(i, j, self.get(i, j) - b.get(i, j));
            }
        }
        res
    }
}

/// The inverse of a real square matrix by Gaussian elimination with partial pivoting, or `None`
/// when it is (numerically) singular or not square. Used for the preconditioner Y = m(F′(X))⁻¹ of
/// the Krawczyk operator (§5.6), which need not be exact: the operator is rigorous for any Y.
///
/// # Examples
///
/// ```
/// use hi_interval::real_inverse;
/// let inv = real_inverse(&[vec![2.0, 0.0], vec![0.0, 4.0]]).unwrap();
/// assert_eq!(inv, vec![vec![0.5, 0.0], vec![0.0, 0.25]]);
/// assert!(real_inverse(&[vec![1.0, 2.0], vec![2.0, 4.0]]).is_none());
/// ```
#[must_use]
pub fn real_inverse(a: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    if a.iter().any(|r| r.len() != n) {
        return None;
    }
    let mut m: Vec<Vec<f64>> = a
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let mut row = r.clone();
            row.extend((0..n).map(|j| if i == j { 1.0 } else { 0.0 }));
            row
        })
        .collect();
    let scale = a.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
    if !scale.is_finite() || scale == 0.0 {
        return None;
    }
    for col in 0..n {
        let pivot = (col..n).max_by(|&p, &q| m[p][col].abs().total_cmp(&m[q][col].abs()))?;
        if m[pivot][col].abs() <= scale * 1e-14 {
            return None;
        }
        m.swap(col, pivot);
        let p = m[col][col];
        for v in &mut m[col] {
            *v /= p;
        }
        let pivot_row = m[col].clone();
        for (r, row) in m.iter_mut().enumerate() {
            let f = row[col];
            if r != col && f != 0.0 {
                for (v, p) in row.iter_mut().zip(&pivot_row) {
                    *v -= f * p;
                }
            }
        }
    }
    let inv: Vec<Vec<f64>> = m.into_iter().map(|r| r[n..].to_vec()).collect();
    if inv.iter().flatten().all(|v| v.is_finite()) { Some(inv) } else { None }
}

/// The mean-value form C(f, X, y) = f(y) + F′(X)(X − y) (§5.6, Theorem 5.4), an enclosure of
/// {f(x) : x ∈ X} for any y ∈ X, given an enclosure `f_y` of f(y) and the interval Jacobian
/// `jacobian` = F′(X).
///
/// # Examples
///
/// ```
/// use hi_interval::{Interval, IntervalMatrix, mean_value_form};
/// // f(x) = x² on X = [0.9, 1.1], y = 1: f(y) = 1, F'(X) = 2X = [1.8, 2.2].
/// let x = [Interval::new(0.9, 1.1)];
/// let jac = IntervalMatrix::from_rows(vec![vec![Interval::new(1.8, 2.2)]]);
/// let c = mean_value_form(&[Interval::ONE], &jac, &x, &[1.0]);
/// assert!(c[0].contains(0.81) && c[0].contains(1.21));
/// ```
#[must_use]
pub fn mean_value_form(
    f_y: &[Interval],
    jacobian: &IntervalMatrix,
    x: &[Interval],
    y: &[f64],
) -> Vec<Interval> {
    let dx: Vec<Interval> = x.iter().zip(y).map(|(xi, &yi)| *xi - yi).collect();
    f_y.iter().zip(jacobian.mul_vec(&dx)).map(|(a, b)| *a + b).collect()
}
