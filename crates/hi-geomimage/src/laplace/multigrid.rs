// SPDX-License-Identifier: MIT
//! Smoothed-aggregation multigrid (Vaněk, Mandel and Brezina 1996, "Algebraic multigrid by
//! smoothed aggregation for second and fourth order elliptic problems"), as a preconditioner:
//! with the diagonal alone, conjugate gradients need a number of iterations growing with the
//! square root of the condition number, about the mesh's diameter in edges (over a thousand
//! for 10⁵ vertices); one V-cycle per iteration makes it about a dozen at any size.

use hi_par::*;

use super::{BLOCK, Laplacian, NONE};

/// Above this many free vertices the solve is preconditioned by multigrid.
pub(crate) const MULTIGRID_ABOVE: usize = 2000;

/// Below this many rows a level is solved directly.
const COARSEST: usize = 200;

/// The most rows of a coarsest level solved directly (a dense Cholesky factor: n² numbers,
/// n³/6 multiply-adds). Coarsening stops early when a level's aggregates are not much fewer
/// than its rows (too few strong connections); a coarsest level larger than this is then
/// smoothed by [`COARSE_SWEEPS`] Jacobi sweeps instead, not factored (which, at the size of
/// the mesh, would take minutes and gigabytes).
pub(super) const DENSE_MAX: usize = 1000;

/// The Jacobi sweeps that stand in for the solve of a coarsest level too large to factor: an
/// odd number, so that the V-cycle stays symmetric positive definite whatever the spectrum.
const COARSE_SWEEPS: usize = 5;

/// The damping of the Jacobi smoother and of the prolongator's smoothing: 2/3, for the
/// eigenvalues of D⁻¹A in (0, 2] of a weighted Laplacian.
const OMEGA: f64 = 2.0 / 3.0;

/// Jacobi sweeps before and after each coarse correction (one each takes about a third more
/// iterations and no less time).
const SWEEPS: usize = 2;

/// A sparse matrix in CSR form; for a square one, the diagonal kept apart (`diag`, empty for a
/// rectangular one).
#[derive(Clone, Debug, Default)]
pub(super) struct Csr {
    start: Vec<u32>,
    cols: Vec<u32>,
    vals: Vec<f64>,
    diag: Vec<f64>,
}

/// A block of rows being built: columns, values, row lengths, diagonal entries.
type RowBlock = (Vec<u32>, Vec<f64>, Vec<u32>, Vec<f64>);

/// Appends (k, v) to the row being built, adding v to k's entry if it has one; `mark[k]` is
/// the entry's index in `cols` (or [`NONE`]).
fn accumulate(k: u32, v: f64, cols: &mut Vec<u32>, vals: &mut Vec<f64>, mark: &mut [u32]) {
    let m = &mut mark[k as usize];
    if *m == NONE {
        *m = cols.len() as u32;
        cols.push(k);
        vals.push(v);
    } else {
        vals[*m as usize] += v;
    }
}

impl Csr {
    pub(super) fn rows(&self) -> usize {
        self.start.len() - 1
    }

    fn row(&self, i: usize) -> (&[u32], &[f64]) {
        let r = self.start[i] as usize..self.start[i + 1] as usize;
        (&self.cols[r.clone()], &self.vals[r])
    }

    /// A matrix of `rows` rows built in parallel blocks: `row(i, cols, vals, mark)` appends
    /// row i's entries (with [`accumulate`], `mark` a scratch array of `width` entries, all
    /// [`NONE`] between rows) and returns its diagonal entry, if `square`.
    fn build<F>(rows: usize, width: usize, square: bool, row: F) -> Self
    where
        F: Fn(usize, &mut Vec<u32>, &mut Vec<f64>, &mut [u32]) -> f64 + Sync,
    {
        let blocks: Vec<RowBlock> = (0..rows.div_ceil(BLOCK))
            .into_par_iter()
            .map(|b| {
                let mut mark = vec![NONE; width];
                let (mut cols, mut vals) = (Vec::new(), Vec::new());
                let (mut lens, mut diag) = (Vec::with_capacity(BLOCK), Vec::new());
                for i in b * BLOCK..((b + 1) * BLOCK).min(rows) {
                    let before = cols.len();
                    let d = row(i, &mut cols, &mut vals, &mut mark);
                    for &k in &cols[before..] {
                        if (k as usize) < width {
                            mark[k as usize] = NONE;
                        }
                    }
                    if square {
                        diag.push(d);
                    }
                    lens.push((cols.len() - before) as u32);
                }
                (cols, vals, lens, diag)
            })
            .collect();
        let total: usize = blocks.iter().map(|b| b.0.len()).sum();
        let mut m = Self {
            start: Vec::with_capacity(rows + 1),
            cols: Vec::with_capacity(total),
            vals: Vec::with_capacity(total),
            diag: Vec::with_capacity(if square { rows } else { 0 }),
        };
        m.start.push(0);
        for (cols, vals, lens, diag) in blocks {
            let mut at = m.cols.len() as u32;
            for l in lens {
                at += l;
                m.start.push(at);
            }
            m.cols.extend(cols);
            m.vals.extend(vals);
            m.diag.extend(diag);
        }
        m
    }

    /// For each row i of block `blk` (rows `BLOCK·blk..`, as many as `out` has), sets
    /// `out[i − BLOCK·blk]` to `f(i, (A x)ᵢ, out[i − BLOCK·blk])`, (A x)ᵢ with the diagonal for a
    /// square matrix. (One pass over the block's rows: walking the row starts in order,
    /// rather than slicing each row apart, takes a third less time on rows of a few entries.)
    #[inline]
    fn rows_times<const K: usize>(
        &self,
        blk: usize,
        x: &[[f64; K]],
        out: &mut [[f64; K]],
        f: impl Fn(usize, [f64; K], [f64; K]) -> [f64; K],
    ) {
        let first = blk * BLOCK;
        let starts = &self.start[first..=first + out.len()];
        let square = !self.diag.is_empty();
        for (o, (w, yo)) in starts.windows(2).zip(out.iter_mut()).enumerate() {
            let i = first + o;
            let range = w[0] as usize..w[1] as usize;
            let mut acc = if square { x[i].map(|v| v * self.diag[i]) } else { [0.0; K] };
            for (&j, &a) in self.cols[range.clone()].iter().zip(&self.vals[range]) {
                let xj = x[j as usize];
                for c in 0..K {
                    acc[c] += a * xj[c];
                }
            }
            *yo = f(i, acc, *yo);
        }
    }

    /// y = A x.
    fn apply<const K: usize>(&self, x: &[[f64; K]], y: &mut [[f64; K]]) {
        y.par_chunks_mut(BLOCK)
            .enumerate()
            .for_each(|(blk, chunk)| self.rows_times(blk, x, chunk, |_, ax, _| ax));
    }

    /// A · B (B rectangular, `width` columns); no diagonal kept apart unless `square`, then
    /// the entry (i, i) is.
    fn times(&self, b: &Self, width: usize, square: bool) -> Self {
        Self::build(self.rows(), width, square, |i, cols, vals, mark| {
            let start = cols.len();
            if !self.diag.is_empty() {
                let (bc, bv) = b.row(i);
                for (&k, &w) in bc.iter().zip(bv) {
                    accumulate(k, self.diag[i] * w, cols, vals, mark);
                }
            }
            let (ac, av) = self.row(i);
            for (&j, &a) in ac.iter().zip(av) {
                let (bc, bv) = b.row(j as usize);
                for (&k, &w) in bc.iter().zip(bv) {
                    accumulate(k, a * w, cols, vals, mark);
                }
            }
            if !square {
                return 0.0;
            }
            // The diagonal entry apart (its mark is cleared by the caller's sweep, which skips
            // nothing: i stays in `mark` only through `cols`).
            match cols[start..].iter().position(|&k| k as usize == i) {
                Some(p) => {
                    mark[i] = NONE;
                    cols.remove(start + p);
                    vals.remove(start + p)
                }
                None => 0.0,
            }
        })
    }

    /// The transpose of a rectangular matrix with `width` columns.
    fn transpose(&self, width: usize) -> Self {
        let mut count = vec![0u32; width + 1];
        for &k in &self.cols {
            count[k as usize + 1] += 1;
        }
        for k in 0..width {
            count[k + 1] += count[k];
        }
        let mut fill = count.clone();
        let mut cols = vec![0u32; self.cols.len()];
        let mut vals = vec![0.0; self.cols.len()];
        for i in 0..self.rows() {
            let (c, v) = self.row(i);
            for (&k, &a) in c.iter().zip(v) {
                let s = fill[k as usize] as usize;
                cols[s] = i as u32;
                vals[s] = a;
                fill[k as usize] += 1;
            }
        }
        Self { start: count, cols, vals, diag: Vec::new() }
    }
}

/// One level of the hierarchy: its matrix, the prolongator to it from the next coarser level
/// and its transpose (the restriction).
#[derive(Debug)]
pub(super) struct Level {
    a: Csr,
    p: Csr,
    pt: Csr,
}

/// A smoothed-aggregation multigrid V-cycle for the free rows of a Laplacian, with its work
/// vectors (K = 2 right-hand sides).
#[derive(Debug)]
pub(crate) struct Multigrid {
    /// The free vertices, in order (level 0's rows).
    free: Vec<u32>,
    pub(super) levels: Vec<Level>,
    pub(super) coarsest: Csr,
    /// The Cholesky factor of the coarsest matrix (row-major, lower), 0 on pivots that were
    /// not positive; `None` for a coarsest level above [`DENSE_MAX`] rows (smoothed instead).
    pub(super) factor: Option<Vec<f64>>,
}

impl Multigrid {
    /// The hierarchy for the free rows of `lap`.
    pub(crate) fn new(lap: &Laplacian, fixed: Option<&[bool]>) -> Self {
        let n = lap.size();
        let free: Vec<u32> =
            (0..n as u32).filter(|&i| !fixed.is_some_and(|f| f[i as usize])).collect();
        let mut index = vec![NONE; n];
        for (k, &i) in free.iter().enumerate() {
            index[i as usize] = k as u32;
        }
        // Level 0: the free rows and columns (edges to fixed vertices stay in the diagonal).
        let mut a = Csr::build(free.len(), 0, true, |r, cols, vals, _| {
            let i = free[r] as usize;
            let (c, ws, _) = lap.row(i);
            for (&j, &w) in c.iter().zip(ws) {
                if index[j as usize] != NONE {
                    cols.push(index[j as usize]);
                    vals.push(-w);
                }
            }
            lap.diagonal[i]
        });
        let mut levels = Vec::new();
        while a.rows() > COARSEST && levels.len() < 24 {
            let (agg, count) = aggregate(&a);
            if count == 0 || count as f64 > 0.85 * a.rows() as f64 {
                break;
            }
            let p = prolongator(&a, &agg, count);
            let pt = p.transpose(count);
            let ap = a.times(&p, count, false);
            let coarse = pt.times(&ap, count, true);
            levels.push(Level { a: std::mem::replace(&mut a, coarse), p, pt });
        }
        let factor = (a.rows() <= DENSE_MAX).then(|| cholesky(&a));
        Self { free, levels, coarsest: a, factor }
    }

    /// z = M r on the full vectors (0 on fixed rows).
    pub(super) fn apply<const K: usize>(&self, r: &[[f64; K]], z: &mut [[f64; K]]) {
        let b: Vec<[f64; K]> = self.free.iter().map(|&i| r[i as usize]).collect();
        let x = self.cycle(0, b);
        z.iter_mut().for_each(|v| *v = [0.0; K]);
        for (&i, v) in self.free.iter().zip(x) {
            z[i as usize] = v;
        }
    }

    /// The V-cycle at `level` from x = 0: [`SWEEPS`] damped Jacobi sweeps, the coarse
    /// correction, as many sweeps again (symmetric, so a valid preconditioner for conjugate
    /// gradients).
    fn cycle<const K: usize>(&self, level: usize, b: Vec<[f64; K]>) -> Vec<[f64; K]> {
        if level == self.levels.len() {
            return match &self.factor {
                Some(l) => solve_dense(&self.coarsest, l, &b),
                None => {
                    let mut next = vec![[0.0; K]; b.len()];
                    smooth(
                        &self.coarsest,
                        &b,
                        jacobi_start(&self.coarsest, &b),
                        &mut next,
                        COARSE_SWEEPS - 1,
                    )
                }
            };
        }
        let Level { a, p, pt } = &self.levels[level];
        let mut next = vec![[0.0; K]; a.rows()];
        let mut x = smooth(a, &b, jacobi_start(a, &b), &mut next, SWEEPS - 1);
        // The residual, restricted.
        next.par_chunks_mut(BLOCK).enumerate().for_each(|(blk, chunk)| {
            a.rows_times(blk, &x, chunk, |i, ax, _| std::array::from_fn(|c| b[i][c] - ax[c]));
        });
        let mut bc = vec![[0.0; K]; pt.rows()];
        pt.apply(&next, &mut bc);
        let xc = self.cycle(level + 1, bc);
        x.par_chunks_mut(BLOCK).enumerate().for_each(|(blk, chunk)| {
            p.rows_times(blk, &xc, chunk, |_, corr, xi| std::array::from_fn(|c| xi[c] + corr[c]));
        });
        smooth(a, &b, x, &mut next, SWEEPS)
    }
}

/// The first damped Jacobi sweep on A x = b from x = 0: x = ω D⁻¹ b.
fn jacobi_start<const K: usize>(a: &Csr, b: &[[f64; K]]) -> Vec<[f64; K]> {
    b.par_iter()
        .zip(a.diag.par_iter())
        .map(|(bi, &d)| if d > 0.0 { bi.map(|v| OMEGA * v / d) } else { [0.0; K] })
        .collect()
}

/// `sweeps` damped Jacobi sweeps x ← x + ω D⁻¹ (b − A x) from `x`, `next` a buffer of the same
/// size.
fn smooth<const K: usize>(
    a: &Csr,
    b: &[[f64; K]],
    mut x: Vec<[f64; K]>,
    next: &mut Vec<[f64; K]>,
    sweeps: usize,
) -> Vec<[f64; K]> {
    for _ in 0..sweeps {
        next.par_chunks_mut(BLOCK).enumerate().for_each(|(blk, chunk)| {
            a.rows_times(blk, &x, chunk, |i, ax, _| {
                let d = a.diag[i];
                if d > 0.0 {
                    std::array::from_fn(|c| x[i][c] + OMEGA * (b[i][c] - ax[c]) / d)
                } else {
                    x[i]
                }
            });
        });
        std::mem::swap(&mut x, next);
    }
    x
}

/// Aggregates of the matrix's graph (strong connections: |aᵢⱼ| ≥ 0.08 √(aᵢᵢ aⱼⱼ)): first
/// every vertex whose strong neighbours are all free, with them; then each vertex left joins
/// the aggregate of its strongest neighbour of the first pass; what is still left starts
/// aggregates of its own. Returns each row's aggregate and their number.
#[expect(clippy::needless_range_loop, reason = "each pass reads and writes other rows' entries")]
fn aggregate(a: &Csr) -> (Vec<u32>, usize) {
    let n = a.rows();
    let strong = |i: usize, j: u32, v: f64| strong(a, i, j, v);
    let mut agg = vec![NONE; n];
    let mut count = 0u32;
    for i in 0..n {
        if agg[i] != NONE {
            continue;
        }
        let (c, v) = a.row(i);
        if c.iter().zip(v).any(|(&j, &x)| strong(i, j, x) && agg[j as usize] != NONE) {
            continue;
        }
        agg[i] = count;
        for (&j, &x) in c.iter().zip(v) {
            if strong(i, j, x) {
                agg[j as usize] = count;
            }
        }
        count += 1;
    }
    let first = agg.clone();
    for i in 0..n {
        if agg[i] != NONE {
            continue;
        }
        let (c, v) = a.row(i);
        let best = c
            .iter()
            .zip(v)
            .filter(|&(&j, &x)| strong(i, j, x) && first[j as usize] != NONE)
            .fold(None, |acc: Option<(f64, u32)>, (&j, &x)| match acc {
                Some((m, _)) if m >= x.abs() => acc,
                _ => Some((x.abs(), first[j as usize])),
            });
        if let Some((_, g)) = best {
            agg[i] = g;
        }
    }
    for i in 0..n {
        if agg[i] != NONE {
            continue;
        }
        agg[i] = count;
        let (c, v) = a.row(i);
        for (&j, &x) in c.iter().zip(v) {
            if strong(i, j, x) && agg[j as usize] == NONE {
                agg[j as usize] = count;
            }
        }
        count += 1;
    }
    (agg, count as usize)
}

/// The smoothed prolongator P = (I − ω D̃⁻¹Ã) P₀, P₀ the aggregates' indicator and Ã the
/// filtered matrix (the weak connections added to the diagonal, so that P keeps the stencil of
/// the strong ones and constants stay constants): row i is (1 − ω) at i's aggregate plus
/// ω (−aᵢⱼ / d̃) at each strong neighbour j's, d̃ = aᵢᵢ + Σ over weak j of aᵢⱼ. (Smoothing
/// with A itself fills the coarse matrices in: on a hemisphere meshed by rings, with a pole of
/// high degree and slivers around it, five times more entries two levels down.)
fn prolongator(a: &Csr, agg: &[u32], count: usize) -> Csr {
    Csr::build(a.rows(), count, false, |i, cols, vals, mark| {
        accumulate(agg[i], 1.0 - OMEGA, cols, vals, mark);
        let (c, v) = a.row(i);
        let mut d = a.diag[i];
        for (&j, &x) in c.iter().zip(v) {
            if !strong(a, i, j, x) {
                d += x;
            }
        }
        for (&j, &x) in c.iter().zip(v) {
            if strong(a, i, j, x) {
                let w = if d > 0.0 { -OMEGA * x / d } else { 0.0 };
                accumulate(agg[j as usize], w, cols, vals, mark);
            }
        }
        0.0
    })
}

/// Whether aᵢⱼ = x is a strong connection: |aᵢⱼ| ≥ 0.08 √(aᵢᵢ aⱼⱼ).
fn strong(a: &Csr, i: usize, j: u32, x: f64) -> bool {
    let d = a.diag[i] * a.diag[j as usize];
    d > 0.0 && x * x >= 0.0064 * d
}

/// The Cholesky factor of a small square matrix (dense, row-major, lower); a pivot that is
/// not positive (a singular matrix) leaves its row and column 0.
fn cholesky(a: &Csr) -> Vec<f64> {
    let n = a.rows();
    let mut l = vec![0.0; n * n];
    for i in 0..n {
        l[i * n + i] = a.diag[i];
        let (c, v) = a.row(i);
        for (&j, &x) in c.iter().zip(v) {
            l[i * n + j as usize] += x;
        }
    }
    let scale = a.diag.iter().copied().fold(0.0, f64::max);
    for k in 0..n {
        let pivot = l[k * n + k];
        if pivot.is_nan() || pivot <= 1e-14 * scale {
            for i in 0..n {
                l[i * n + k] = 0.0;
            }
            continue;
        }
        let s = pivot.sqrt();
        l[k * n + k] = s;
        for i in k + 1..n {
            l[i * n + k] /= s;
        }
        for j in k + 1..n {
            let ljk = l[j * n + k];
            if ljk == 0.0 {
                continue;
            }
            for i in j..n {
                l[i * n + j] -= l[i * n + k] * ljk;
            }
        }
    }
    l
}

/// Solves with the factor of [`cholesky`] (0 where a pivot was dropped).
fn solve_dense<const K: usize>(a: &Csr, l: &[f64], b: &[[f64; K]]) -> Vec<[f64; K]> {
    let n = a.rows();
    let mut y = b.to_vec();
    for i in 0..n {
        let d = l[i * n + i];
        for k in 0..i {
            let (lik, yk) = (l[i * n + k], y[k]);
            for (a, b) in y[i].iter_mut().zip(yk) {
                *a -= lik * b;
            }
        }
        y[i] = if d > 0.0 { y[i].map(|v| v / d) } else { [0.0; K] };
    }
    for i in (0..n).rev() {
        let d = l[i * n + i];
        for k in i + 1..n {
            let (lki, yk) = (l[k * n + i], y[k]);
            for (a, b) in y[i].iter_mut().zip(yk) {
                *a -= lki * b;
            }
        }
        y[i] = if d > 0.0 { y[i].map(|v| v / d) } else { [0.0; K] };
    }
    y
}
