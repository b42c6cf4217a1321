// SPDX-License-Identifier: MIT
//! The half-edge connectivity of a triangle mesh, its cotangent Laplacian with weights kept
//! positive, in compressed sparse row (CSR) form, and a preconditioned conjugate-gradient
//! solver for it (Pinkall and Polthier 1993, "Computing discrete minimal surfaces and their
//! conjugates"; Hestenes and Stiefel 1952, "Methods of conjugate gradients for solving linear
//! systems"; Vaněk, Mandel and Brezina 1996, "Algebraic multigrid by smoothed aggregation for
//! second and fourth order elliptic problems").
//!
//! **The weights.** Edge ij gets wᵢⱼ = ½ (c₁ cot α + c₂ cot β), α and β the angles opposite
//! it in its one or two triangles and c a positive factor per triangle (1 for the plain
//! Laplacian; the stretch relaxation of the flat parameterisations changes it). Obtuse angles
//! make cotangent weights negative, and the embedding theorems the flat parameterisations rest
//! on — Tutte (1963), Floater (2003, "One-to-one piecewise linear mappings over
//! triangulations"), Gortler, Gotsman and Thurston (2006, "Discrete one-forms on meshes and
//! applications to 3D mesh parameterization") — need positive ones; so each weight is clamped
//! from below to [`MIN_WEIGHT`] times ½ (c₁ + c₂), and each cotangent to ±[`MAX_COT`] (a
//! triangle of zero area would otherwise give an infinite one). With every weight positive and
//! the mesh connected, L = D − W (D the row sums of W) is positive semi-definite with the
//! constants as its kernel, and positive definite once one vertex is held fixed.
//!
//! **The solver.** Written here rather than taken from a crate: the systems are symmetric
//! positive definite and sparse (about seven entries a row), conjugate gradients solve them
//! from a warm start (the previous map, during the relaxation rounds) to a tolerance with an
//! iteration cap, and no sparse-factorisation crate is in the dependency tree. Several
//! right-hand sides that share the matrix (the u and v coordinates of a map) run in lockstep,
//! each with its own step lengths, so the matrix is read once per iteration for all of them.
//! Vertices can be held fixed (Dirichlet values): their rows are left out of the system and
//! their values enter the others' right-hand sides. The preconditioner is the diagonal (Jacobi)
//! for small systems; its iteration count grows with the mesh's diameter in edges (about 1250
//! for a torus of 10⁵ vertices at a relative residual of 10⁻⁸), so above
//! [`MULTIGRID_ABOVE`] free vertices it is one V-cycle of smoothed-aggregation multigrid
//! (damped Jacobi smoothing, aggregates of strongly connected neighbours, the prolongator
//! smoothed with the filtered matrix, Galerkin coarse matrices, a dense Cholesky factor at the
//! bottom), which takes about a dozen at any size. A hierarchy is built for one matrix: it
//! preconditions another with the same free rows correctly, but one whose weights differ by
//! large, uneven factors (the stretch relaxation's later rounds) in up to a hundred times the
//! iterations, so the relaxation builds one per round. Where coarsening stalls (too few strong
//! connections left to aggregate) above a thousand rows, the coarsest level is smoothed by
//! Jacobi sweeps rather than factored densely (a dense factor the size of a mesh would take
//! minutes and gigabytes). Dot
//! products are summed in fixed blocks of rows and the blocks in order, and every other
//! parallel loop writes its own rows, so the result does not depend on the number of threads.
//!
//! The connectivity is in `topology`, the multigrid preconditioner in `multigrid`.

mod multigrid;
mod topology;

use glam::DVec3;

use crate::Error;
use hi_par::*;

pub(crate) use multigrid::{MULTIGRID_ABOVE, Multigrid};
pub(crate) use topology::{Topology, head, tail};

/// "No half-edge": the twin of a boundary half-edge, or an absent side of a Laplacian entry.
pub(crate) const NONE: u32 = u32::MAX;

/// The floor of an edge weight, relative to the mean factor of its triangles: small enough
/// to leave a well-shaped mesh's weights (about 0.58 for equilateral triangles) alone, large
/// enough to keep every weight positive.
pub(crate) const MIN_WEIGHT: f64 = 1e-3;

/// The largest cotangent used: an angle below about 0.006° counts as that angle.
pub(crate) const MAX_COT: f64 = 1e4;

/// Rows per block of a dot product (fixed, so sums do not depend on threads).
pub(crate) const BLOCK: usize = 2048;

/// The cotangent Laplacian L = D − W of a mesh in CSR form: row i lists i's neighbours j
/// with wᵢⱼ > 0, and D holds the row sums.
#[derive(Clone, Debug)]
pub(crate) struct Laplacian {
    start: Vec<u32>,
    columns: Vec<u32>,
    /// For each entry (i, j): the half-edge i → j and the half-edge j → i ([`NONE`] if
    /// absent, on the boundary).
    sides: Vec<[u32; 2]>,
    weights: Vec<f64>,
    diagonal: Vec<f64>,
}

/// The settings of a conjugate-gradient solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CgOptions {
    /// Stop when ‖b − Ax‖ ≤ tolerance · ‖b − A x₀‖ for x₀ zero on the free vertices (the
    /// system's own right-hand side), for every right-hand side.
    pub(crate) tolerance: f64,
    /// Give up after this many iterations.
    pub(crate) max_iterations: usize,
    /// Precondition by multigrid above this many free vertices, by the diagonal up to it.
    pub(crate) multigrid_above: usize,
}

impl CgOptions {
    /// A tolerance and an iteration cap, multigrid above [`MULTIGRID_ABOVE`] free vertices.
    pub(crate) const fn new(tolerance: f64, max_iterations: usize) -> Self {
        Self { tolerance, max_iterations, multigrid_above: MULTIGRID_ABOVE }
    }
}

/// What a solve took.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CgReport {
    /// Iterations (matrix–vector products).
    pub(crate) iterations: usize,
    /// The largest relative residual over the right-hand sides at the end.
    pub(crate) residual: f64,
}

impl Laplacian {
    /// The structure of the Laplacian of a mesh, with every weight 0 (set them with
    /// [`Laplacian::set_cotangent_weights`]).
    pub(crate) fn new(topology: &Topology, triangles: &[[u32; 3]]) -> Self {
        let n = topology.vertex_count();
        let mut start = vec![0u32; n + 1];
        for v in 0..n {
            start[v + 1] = topology.outgoing(v as u32).len() as u32;
        }
        // A boundary vertex also neighbours the tail of its incoming boundary half-edge.
        for &h in &topology.boundary {
            start[head(triangles, h) as usize + 1] += 1;
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        let total = start[n] as usize;
        let mut columns = vec![0u32; total];
        let mut sides = vec![[NONE; 2]; total];
        let mut fill = start.clone();
        for v in 0..n as u32 {
            for &h in topology.outgoing(v) {
                let s = fill[v as usize] as usize;
                columns[s] = head(triangles, h);
                sides[s] = [h, topology.twin[h as usize]];
                fill[v as usize] += 1;
            }
        }
        for &h in &topology.boundary {
            let v = head(triangles, h) as usize;
            let s = fill[v] as usize;
            columns[s] = tail(triangles, h);
            sides[s] = [NONE, h];
            fill[v] += 1;
        }
        Self { start, columns, sides, weights: vec![0.0; total], diagonal: vec![0.0; n] }
    }

    /// Sets the weights to the clamped cotangent weights of the mesh at `positions`, the
    /// terms of triangle f multiplied by `scale[f]` (all 1 if `None`): see the module
    /// documentation.
    pub(crate) fn set_cotangent_weights(
        &mut self,
        positions: &[DVec3],
        triangles: &[[u32; 3]],
        scale: Option<&[f64]>,
    ) {
        // ½ c cot of the angle opposite each half-edge.
        let half: Vec<f64> = (0..3 * triangles.len())
            .into_par_iter()
            .with_min_len(4096)
            .map(|h| {
                let (f, k) = (h / 3, h % 3);
                let t = triangles[f];
                let o = positions[t[(k + 2) % 3] as usize];
                let (a, b) = (positions[t[k] as usize] - o, positions[t[(k + 1) % 3] as usize] - o);
                let cross = a.cross(b).length();
                let dot = a.dot(b);
                let cot = if cross > 0.0 {
                    (dot / cross).clamp(-MAX_COT, MAX_COT)
                } else if dot > 0.0 {
                    MAX_COT
                } else if dot < 0.0 {
                    -MAX_COT
                } else {
                    0.0
                };
                let c = scale.map_or(1.0, |s| s[f]);
                0.5 * c * if cot.is_finite() { cot } else { 0.0 }
            })
            .collect();
        let factor = |h: u32| scale.map_or(1.0, |s| s[(h / 3) as usize]);
        let sides = &self.sides;
        self.weights.par_iter_mut().enumerate().with_min_len(4096).for_each(|(s, w)| {
            let (mut sum, mut c) = (0.0, 0.0);
            for h in sides[s] {
                if h != NONE {
                    sum += half[h as usize];
                    c += 0.5 * factor(h);
                }
            }
            *w = sum.max(MIN_WEIGHT * c);
        });
        let (start, weights) = (&self.start, &self.weights);
        self.diagonal.par_iter_mut().enumerate().with_min_len(4096).for_each(|(i, d)| {
            *d = weights[start[i] as usize..start[i + 1] as usize].iter().sum();
        });
    }

    /// The vertices (rows).
    pub(crate) fn size(&self) -> usize {
        self.diagonal.len()
    }

    /// Row i: its neighbours, their weights, and for each the half-edges i → j and j → i.
    pub(crate) fn row(&self, i: usize) -> (&[u32], &[f64], &[[u32; 2]]) {
        let r = self.start[i] as usize..self.start[i + 1] as usize;
        (&self.columns[r.clone()], &self.weights[r.clone()], &self.sides[r])
    }

    /// The row sums of W (the diagonal of L).
    #[cfg(test)]
    pub(crate) fn diagonal(&self) -> &[f64] {
        &self.diagonal
    }

    /// The vertices split into classes of which no two are neighbours (greedy colouring in
    /// index order).
    pub(crate) fn colour_classes(&self) -> Vec<Vec<u32>> {
        let n = self.size();
        let mut colour = vec![u32::MAX; n];
        let mut classes: Vec<Vec<u32>> = Vec::new();
        let mut used = Vec::new();
        for v in 0..n {
            used.clear();
            used.extend(
                self.row(v).0.iter().map(|&j| colour[j as usize]).filter(|&c| c != u32::MAX),
            );
            let c = (0..).find(|c| !used.contains(c)).unwrap_or(0);
            colour[v] = c;
            if classes.len() <= c as usize {
                classes.resize(c as usize + 1, Vec::new());
            }
            classes[c as usize].push(v as u32);
        }
        classes
    }

    /// q = L p on the free rows (0 on fixed ones; every row for `None`), and its dot product
    /// with p, per column, as block sums.
    fn apply<const K: usize>(
        &self,
        fixed: Option<&[bool]>,
        p: &[[f64; K]],
        q: &mut [[f64; K]],
    ) -> Vec<[f64; K]> {
        q.par_chunks_mut(BLOCK)
            .enumerate()
            .map(|(b, chunk)| {
                let mut dot = [0.0; K];
                let first = b * BLOCK;
                let starts = &self.start[first..=first + chunk.len()];
                for (o, (w, qi)) in starts.windows(2).zip(chunk.iter_mut()).enumerate() {
                    let i = first + o;
                    if fixed.is_some_and(|f| f[i]) {
                        *qi = [0.0; K];
                        continue;
                    }
                    let mut acc = p[i].map(|x| x * self.diagonal[i]);
                    let range = w[0] as usize..w[1] as usize;
                    for (&j, &w) in self.columns[range.clone()].iter().zip(&self.weights[range]) {
                        let pj = p[j as usize];
                        for c in 0..K {
                            acc[c] -= w * pj[c];
                        }
                    }
                    for c in 0..K {
                        dot[c] += acc[c] * p[i][c];
                    }
                    *qi = acc;
                }
                dot
            })
            .collect()
    }

    /// The preconditioner of [`Laplacian::solve`] for the free rows: multigrid above
    /// `options.multigrid_above` free vertices, else `None` (the diagonal).
    pub(crate) fn preconditioner(
        &self,
        fixed: Option<&[bool]>,
        options: CgOptions,
    ) -> Option<Multigrid> {
        let free = (0..self.size()).filter(|&i| !fixed.is_some_and(|f| f[i])).count();
        (free > options.multigrid_above).then(|| Multigrid::new(self, fixed))
    }

    /// Solves L x = b for x on the vertices not `fixed`, K right-hand sides at once, from the
    /// values in `x` (a warm start; the fixed vertices' values are kept and enter the other
    /// rows). With nothing fixed, L is singular: hold at least one vertex of a closed mesh.
    /// Preconditioned by `multigrid` (from [`Laplacian::preconditioner`], for this matrix or
    /// for another one with the same free rows: any symmetric positive definite
    /// preconditioner leads to the same solution, a close one in as few iterations), or by the
    /// diagonal for `None`.
    ///
    /// # Errors
    ///
    /// [`Error::Topology`] if a right-hand side, a start value or an intermediate is not finite,
    /// if the system turns out not to be positive definite, or if the tolerance is not met
    /// within the iteration cap.
    pub(crate) fn solve<const K: usize>(
        &self,
        fixed: Option<&[bool]>,
        b: &[[f64; K]],
        x: &mut [[f64; K]],
        options: CgOptions,
        multigrid: Option<&Multigrid>,
    ) -> Result<CgReport, Error> {
        let n = self.size();
        let fail = |what: String| Err(Error::Topology { what });
        if b.len() != n || x.len() != n || fixed.is_some_and(|f| f.len() != n) {
            return fail("the Laplacian solve was given vectors of the wrong size".to_owned());
        }
        if b.iter().chain(x.iter()).any(|v| v.iter().any(|c| !c.is_finite())) {
            return fail("the Laplacian solve was given a NaN or infinite value".to_owned());
        }
        let free = |i: usize| !fixed.is_some_and(|f| f[i]);
        // The reference: the residual with the free values zero.
        let mut p: Vec<[f64; K]> = (0..n).map(|i| if free(i) { [0.0; K] } else { x[i] }).collect();
        let mut q = vec![[0.0; K]; n];
        let mut r = vec![[0.0; K]; n];
        let mut z = vec![[0.0; K]; n];
        self.apply(None, &p, &mut q);
        let reference = residual(fixed, b, &q, &mut r).map(f64::sqrt);
        self.apply(None, x, &mut q);
        let mut rr = residual(fixed, b, &q, &mut r);
        let relative =
            |rr: &[f64; K]| -> [f64; K] {
                std::array::from_fn(|c| {
                    if reference[c] > 0.0 { rr[c].sqrt() / reference[c] } else { 0.0 }
                })
            };
        let mut active = [true; K];
        for c in 0..K {
            if reference[c] == 0.0 {
                // b − A x_fixed = 0: the solution is 0 on the free vertices.
                for i in (0..n).filter(|&i| free(i)) {
                    x[i][c] = 0.0;
                    r[i][c] = 0.0;
                }
                active[c] = false;
            } else if rr[c].sqrt() <= options.tolerance * reference[c] {
                active[c] = false;
            }
        }
        let mut rz = self.precondition(multigrid, &r, &mut z);
        p.copy_from_slice(&z);
        let mut report = CgReport { iterations: 0, residual: 0.0 };
        while active.iter().any(|&a| a) {
            if report.iterations >= options.max_iterations {
                let worst = relative(&rr).iter().copied().fold(0.0, f64::max);
                return fail(format!(
                    "the Laplacian solve did not converge: relative residual {worst:.1e} after {} iterations (tolerance {:.1e})",
                    report.iterations, options.tolerance
                ));
            }
            report.iterations += 1;
            let pq = sum_blocks(&self.apply(fixed, &p, &mut q));
            let mut alpha = [0.0; K];
            for c in 0..K {
                if active[c] {
                    if !(pq[c] > 0.0 && pq[c].is_finite() && rz[c] > 0.0) {
                        return fail(
                            "the Laplacian solve broke down (the system is not positive definite)"
                                .to_owned(),
                        );
                    }
                    alpha[c] = rz[c] / pq[c];
                }
            }
            rr = step(x, &mut r, &p, &q, alpha);
            if rr.iter().any(|v| !v.is_finite()) {
                return fail("the Laplacian solve produced a NaN or infinite value".to_owned());
            }
            let rel = relative(&rr);
            for c in 0..K {
                if active[c] && rel[c] <= options.tolerance {
                    active[c] = false;
                }
            }
            if !active.iter().any(|&a| a) {
                break;
            }
            // β = r'z'/rz per column; converged columns keep still (α = β = 0 from here).
            let rz_new = self.precondition(multigrid, &r, &mut z);
            let beta: [f64; K] =
                std::array::from_fn(
                    |c| if active[c] && rz[c] > 0.0 { rz_new[c] / rz[c] } else { 0.0 },
                );
            next_direction(&mut p, &z, beta);
            rz = rz_new;
        }
        report.residual = relative(&rr).iter().copied().fold(0.0, f64::max);
        Ok(report)
    }

    /// The preconditioning stage of [`Laplacian::solve`]: z = M r (one multigrid V-cycle, or
    /// the diagonal for `None`), and r·z per column.
    fn precondition<const K: usize>(
        &self,
        multigrid: Option<&Multigrid>,
        r: &[[f64; K]],
        z: &mut [[f64; K]],
    ) -> [f64; K] {
        if let Some(mg) = multigrid {
            mg.apply(r, z);
            let blocks: Vec<[f64; K]> = r
                .par_chunks(BLOCK)
                .zip(z.par_chunks(BLOCK))
                .map(|(rs, zs)| {
                    let mut s = [0.0; K];
                    for (ri, zi) in rs.iter().zip(zs) {
                        for c in 0..K {
                            s[c] += ri[c] * zi[c];
                        }
                    }
                    s
                })
                .collect();
            return sum_blocks(&blocks);
        }
        let blocks: Vec<[f64; K]> = z
            .par_chunks_mut(BLOCK)
            .enumerate()
            .map(|(blk, chunk)| {
                let mut s = [0.0; K];
                for (o, zi) in chunk.iter_mut().enumerate() {
                    let i = blk * BLOCK + o;
                    let d = self.diagonal[i];
                    for c in 0..K {
                        zi[c] = if d > 0.0 { r[i][c] / d } else { 0.0 };
                        s[c] += r[i][c] * zi[c];
                    }
                }
                s
            })
            .collect();
        sum_blocks(&blocks)
    }
}

/// The residual stage of [`Laplacian::solve`]: r = b − q on the free rows (0 on the fixed
/// ones), and |r|² per column.
fn residual<const K: usize>(
    fixed: Option<&[bool]>,
    b: &[[f64; K]],
    q: &[[f64; K]],
    r: &mut [[f64; K]],
) -> [f64; K] {
    let free = |i: usize| !fixed.is_some_and(|f| f[i]);
    let blocks: Vec<[f64; K]> = r
        .par_chunks_mut(BLOCK)
        .enumerate()
        .map(|(blk, chunk)| {
            let mut s = [0.0; K];
            for (o, ri) in chunk.iter_mut().enumerate() {
                let i = blk * BLOCK + o;
                if free(i) {
                    for c in 0..K {
                        ri[c] = b[i][c] - q[i][c];
                        s[c] += ri[c] * ri[c];
                    }
                } else {
                    *ri = [0.0; K];
                }
            }
            s
        })
        .collect();
    sum_blocks(&blocks)
}

/// The step of a conjugate-gradient iteration in [`Laplacian::solve`]: x += α p, r −= α q, and
/// the new |r|² per column.
fn step<const K: usize>(
    x: &mut [[f64; K]],
    r: &mut [[f64; K]],
    p: &[[f64; K]],
    q: &[[f64; K]],
    alpha: [f64; K],
) -> [f64; K] {
    let blocks: Vec<[f64; K]> = x
        .par_chunks_mut(BLOCK)
        .zip(r.par_chunks_mut(BLOCK))
        .enumerate()
        .map(|(blk, (xs, rs))| {
            let mut s = [0.0; K];
            for (o, (xi, ri)) in xs.iter_mut().zip(rs.iter_mut()).enumerate() {
                let i = blk * BLOCK + o;
                for c in 0..K {
                    xi[c] += alpha[c] * p[i][c];
                    ri[c] -= alpha[c] * q[i][c];
                    s[c] += ri[c] * ri[c];
                }
            }
            s
        })
        .collect();
    sum_blocks(&blocks)
}

/// The new search direction of a conjugate-gradient iteration in [`Laplacian::solve`]:
/// p = z + β p.
fn next_direction<const K: usize>(p: &mut [[f64; K]], z: &[[f64; K]], beta: [f64; K]) {
    p.par_chunks_mut(BLOCK).zip(z.par_chunks(BLOCK)).for_each(|(ps, zs)| {
        for (pi, zi) in ps.iter_mut().zip(zs) {
            for c in 0..K {
                pi[c] = zi[c] + beta[c] * pi[c];
            }
        }
    });
}

/// The sum of per-block partial sums, in block order.
fn sum_blocks<const K: usize>(blocks: &[[f64; K]]) -> [f64; K] {
    let mut s = [0.0; K];
    for blk in blocks {
        for c in 0..K {
            s[c] += blk[c];
        }
    }
    s
}

#[cfg(test)]
mod tests;
