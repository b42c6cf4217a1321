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

use glam::DVec3;

use crate::Error;
use hi_par::*;

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

/// The half-edges of a triangle mesh: half-edge h = 3f + k runs from corner k of triangle f to
/// corner k + 1 (mod 3).
#[derive(Clone, Debug)]
pub(crate) struct Topology {
    /// The opposite half-edge, or [`NONE`] on the boundary.
    pub(crate) twin: Vec<u32>,
    /// Outgoing half-edges of each vertex: `out[out_start[v]..out_start[v + 1]]` (one per
    /// triangle at v).
    pub(crate) out_start: Vec<u32>,
    pub(crate) out: Vec<u32>,
    /// Half-edges with no twin.
    pub(crate) boundary: Vec<u32>,
}

/// The tail (start vertex) of half-edge h.
pub(crate) fn tail(triangles: &[[u32; 3]], h: u32) -> u32 {
    triangles[(h / 3) as usize][(h % 3) as usize]
}

/// The head (end vertex) of half-edge h.
pub(crate) fn head(triangles: &[[u32; 3]], h: u32) -> u32 {
    triangles[(h / 3) as usize][((h % 3 + 1) % 3) as usize]
}

/// The half-edge before h in its triangle (ending where h starts).
pub(crate) const fn prev(h: u32) -> u32 {
    h - h % 3 + (h % 3 + 2) % 3
}

impl Topology {
    /// The connectivity of `triangles` over `vertex_count` vertices.
    ///
    /// # Errors
    ///
    /// [`Error::Topology`] naming the first problem: an index out of range, a triangle with a
    /// repeated corner, an edge used twice in the same direction (three or more triangles on
    /// an edge, or two wound inconsistently), a vertex in no triangle, or a vertex whose
    /// triangles do not form one fan (two sheets touching at a point).
    pub(crate) fn new(vertex_count: usize, triangles: &[[u32; 3]]) -> Result<Self, Error> {
        let topo = |what: String| Error::Topology { what };
        if vertex_count >= NONE as usize || 3 * triangles.len() >= NONE as usize {
            return Err(topo("the mesh is too large for 32-bit indices".to_owned()));
        }
        for (f, t) in triangles.iter().enumerate() {
            if let Some(&k) = t.iter().find(|&&k| k as usize >= vertex_count) {
                return Err(topo(format!(
                    "triangle {f} refers to vertex {k}, but there are {vertex_count} vertices"
                )));
            }
            if t[0] == t[1] || t[1] == t[2] || t[2] == t[0] {
                return Err(topo(format!("triangle {f} repeats a vertex ({t:?})")));
            }
        }
        let mut out_start = vec![0u32; vertex_count + 1];
        for t in triangles {
            for &k in t {
                out_start[k as usize + 1] += 1;
            }
        }
        for v in 0..vertex_count {
            out_start[v + 1] += out_start[v];
        }
        if let Some(v) = (0..vertex_count).find(|&v| out_start[v] == out_start[v + 1]) {
            return Err(topo(format!("vertex {v} is in no triangle")));
        }
        let mut fill = out_start.clone();
        let mut out = vec![0u32; 3 * triangles.len()];
        for (f, t) in triangles.iter().enumerate() {
            for (k, &v) in t.iter().enumerate() {
                out[fill[v as usize] as usize] = (3 * f + k) as u32;
                fill[v as usize] += 1;
            }
        }
        let outgoing =
            |v: u32| &out[out_start[v as usize] as usize..out_start[v as usize + 1] as usize];
        // Twins: half-edge a → b finds b → a among b's outgoing half-edges; a second a → b
        // among a's is an error (marked, then named below).
        const TWICE: u32 = NONE - 1;
        let twin: Vec<u32> = (0..3 * triangles.len() as u32)
            .into_par_iter()
            .with_min_len(4096)
            .map(|h| {
                let (a, b) = (tail(triangles, h), head(triangles, h));
                if outgoing(a).iter().any(|&g| g != h && head(triangles, g) == b) {
                    return TWICE;
                }
                outgoing(b).iter().copied().find(|&g| head(triangles, g) == a).unwrap_or(NONE)
            })
            .collect();
        if let Some(h) = twin.iter().position(|&t| t == TWICE) {
            let h = h as u32;
            let (a, b) = (tail(triangles, h), head(triangles, h));
            let g = outgoing(a)
                .iter()
                .copied()
                .find(|&g| g != h && head(triangles, g) == b)
                .unwrap_or(h);
            return Err(topo(format!(
                "edge ({a}, {b}) is used in the same direction by triangles {} and {}: the mesh is not 2-manifold or not consistently oriented",
                (h / 3).min(g / 3),
                (h / 3).max(g / 3)
            )));
        }
        let boundary: Vec<u32> =
            (0..twin.len() as u32).filter(|&h| twin[h as usize] == NONE).collect();
        let topology = Self { twin, out_start, out, boundary };
        // One fan per vertex: walking around it from one outgoing half-edge reaches all.
        for v in 0..vertex_count as u32 {
            let ring = topology.outgoing(v);
            let starts = ring.iter().filter(|&&h| topology.twin[h as usize] == NONE).count();
            let start = match starts {
                0 => ring[0],
                1 => ring
                    .iter()
                    .copied()
                    .find(|&h| topology.twin[h as usize] == NONE)
                    .unwrap_or(ring[0]),
                _ => {
                    return Err(topo(format!(
                        "vertex {v} joins {starts} separate fans of triangles (two sheets touch there)"
                    )));
                }
            };
            let (mut h, mut seen) = (start, 0usize);
            loop {
                seen += 1;
                let next = topology.twin[prev(h) as usize];
                if next == NONE || next == start || seen > ring.len() {
                    break;
                }
                h = next;
            }
            if seen != ring.len() {
                return Err(topo(format!(
                    "vertex {v} joins separate fans of triangles (two sheets touch there)"
                )));
            }
        }
        Ok(topology)
    }

    /// The vertices.
    pub(crate) fn vertex_count(&self) -> usize {
        self.out_start.len() - 1
    }

    /// The outgoing half-edges of v.
    pub(crate) fn outgoing(&self, v: u32) -> &[u32] {
        &self.out[self.out_start[v as usize] as usize..self.out_start[v as usize + 1] as usize]
    }

    /// Edges: half-edges counted once each (a pair of twins once, a boundary half-edge once).
    pub(crate) fn edge_count(&self) -> usize {
        (self.twin.len() + self.boundary.len()) / 2
    }

    /// The Euler characteristic V − E + F.
    pub(crate) fn euler_characteristic(&self) -> i64 {
        self.vertex_count() as i64 - self.edge_count() as i64 + (self.twin.len() / 3) as i64
    }

    /// The number of connected parts (by shared vertices).
    pub(crate) fn components(&self, triangles: &[[u32; 3]]) -> usize {
        let n = self.vertex_count();
        let mut seen = vec![false; n];
        let mut stack = Vec::new();
        let mut parts = 0;
        for s in 0..n as u32 {
            if seen[s as usize] {
                continue;
            }
            parts += 1;
            seen[s as usize] = true;
            stack.push(s);
            while let Some(v) = stack.pop() {
                for &h in self.outgoing(v) {
                    // Both other corners of the triangle: the head of h, and the tail of the
                    // half-edge before it (a boundary vertex's last neighbour is only that).
                    for w in [head(triangles, h), tail(triangles, prev(h))] {
                        if !seen[w as usize] {
                            seen[w as usize] = true;
                            stack.push(w);
                        }
                    }
                }
            }
        }
        parts
    }

    /// The boundary loops, each as its half-edges in order (each ends where the next starts;
    /// the mesh lies to the left of each).
    pub(crate) fn boundary_loops(&self, triangles: &[[u32; 3]]) -> Vec<Vec<u32>> {
        // The one outgoing boundary half-edge of each boundary vertex (one fan per vertex).
        let mut next_of = std::collections::HashMap::with_capacity(self.boundary.len());
        for &h in &self.boundary {
            next_of.insert(tail(triangles, h), h);
        }
        let mut used = std::collections::HashSet::with_capacity(self.boundary.len());
        let mut loops = Vec::new();
        for &h0 in &self.boundary {
            if used.contains(&h0) {
                continue;
            }
            let mut lp = Vec::new();
            let mut h = h0;
            while used.insert(h) {
                lp.push(h);
                match next_of.get(&head(triangles, h)) {
                    Some(&g) => h = g,
                    None => break,
                }
            }
            loops.push(lp);
        }
        loops
    }
}

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
        let residual = |q: &[[f64; K]], r: &mut [[f64; K]]| -> [f64; K] {
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
        };
        self.apply(None, &p, &mut q);
        let reference = residual(&q, &mut r).map(f64::sqrt);
        self.apply(None, x, &mut q);
        let mut rr = residual(&q, &mut r);
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
        // z = M r and r·z.
        let precondition = |r: &[[f64; K]], z: &mut [[f64; K]]| -> [f64; K] {
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
        };
        let mut rz = precondition(&r, &mut z);
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
            rr = sum_blocks(&blocks);
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
            let rz_new = precondition(&r, &mut z);
            let beta: [f64; K] =
                std::array::from_fn(
                    |c| if active[c] && rz[c] > 0.0 { rz_new[c] / rz[c] } else { 0.0 },
                );
            p.par_chunks_mut(BLOCK).zip(z.par_chunks(BLOCK)).for_each(|(ps, zs)| {
                for (pi, zi) in ps.iter_mut().zip(zs) {
                    for c in 0..K {
                        pi[c] = zi[c] + beta[c] * pi[c];
                    }
                }
            });
            rz = rz_new;
        }
        report.residual = relative(&rr).iter().copied().fold(0.0, f64::max);
        Ok(report)
    }
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

// ---------------------------------------------------------------------------------------------
// Smoothed-aggregation multigrid (Vaněk, Mandel and Brezina 1996, "Algebraic multigrid by
// smoothed aggregation for second and fourth order elliptic problems"), as a preconditioner:
// with the diagonal alone, conjugate gradients need a number of iterations growing with the
// square root of the condition number, about the mesh's diameter in edges (over a thousand
// for 10⁵ vertices); one V-cycle per iteration makes it about a dozen at any size.

/// Above this many free vertices the solve is preconditioned by multigrid.
pub(crate) const MULTIGRID_ABOVE: usize = 2000;

/// Below this many rows a level is solved directly.
const COARSEST: usize = 200;

/// The most rows of a coarsest level solved directly (a dense Cholesky factor: n² numbers,
/// n³/6 multiply-adds). Coarsening stops early when a level's aggregates are not much fewer
/// than its rows (too few strong connections); a coarsest level larger than this is then
/// smoothed by [`COARSE_SWEEPS`] Jacobi sweeps instead, not factored (which, at the size of
/// the mesh, would take minutes and gigabytes).
const DENSE_MAX: usize = 1000;

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
struct Csr {
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
    fn rows(&self) -> usize {
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
struct Level {
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
    levels: Vec<Level>,
    coarsest: Csr,
    /// The Cholesky factor of the coarsest matrix (row-major, lower), 0 on pivots that were
    /// not positive; `None` for a coarsest level above [`DENSE_MAX`] rows (smoothed instead).
    factor: Option<Vec<f64>>,
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
    fn apply<const K: usize>(&self, r: &[[f64; K]], z: &mut [[f64; K]]) {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A patch of the equilateral triangle lattice, `n × n` vertices, in the plane z = 0.
    fn lattice(n: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let h = 3f64.sqrt() / 2.0;
        let mut p = Vec::new();
        for i in 0..n {
            for j in 0..n {
                p.push(DVec3::new(j as f64 + 0.5 * i as f64, h * i as f64, 0.0));
            }
        }
        let at = |i: usize, j: usize| (i * n + j) as u32;
        let mut t = Vec::new();
        for i in 0..n - 1 {
            for j in 0..n - 1 {
                t.push([at(i, j), at(i, j + 1), at(i + 1, j)]);
                t.push([at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)]);
            }
        }
        (p, t)
    }

    /// Cotangent weights reproduce linear functions (linear precision): fix the boundary of
    /// an equilateral lattice to a linear function and the solve returns it inside.
    #[test]
    fn linear_functions_are_reproduced() {
        let (p, t) = lattice(30);
        let topo = Topology::new(p.len(), &t).unwrap();
        let mut lap = Laplacian::new(&topo, &t);
        lap.set_cotangent_weights(&p, &t, None);
        // Every interior edge of the lattice has weight ½(cot 60° + cot 60°) = 1/√3.
        let (_, ws, _) = lap.row(31);
        for &w in ws {
            assert!((w - 1.0 / 3f64.sqrt()).abs() < 1e-12, "weight {w}");
        }
        let mut fixed = vec![false; p.len()];
        for &h in &topo.boundary {
            fixed[tail(&t, h) as usize] = true;
        }
        let f = |x: DVec3| [2.0 * x.x - 3.0 * x.y + 1.0, 0.5 * x.x + x.y];
        let mut x: Vec<[f64; 2]> =
            p.iter().zip(&fixed).map(|(q, &fx)| if fx { f(*q) } else { [0.0; 2] }).collect();
        let b = vec![[0.0; 2]; p.len()];
        let opts = CgOptions::new(1e-13, 1000);
        let report = lap
            .solve(Some(&fixed), &b, &mut x, opts, lap.preconditioner(Some(&fixed), opts).as_ref())
            .unwrap();
        assert!(report.residual <= 1e-13, "{report:?}");
        for (q, xi) in p.iter().zip(&x) {
            let e = f(*q);
            assert!((xi[0] - e[0]).abs() < 1e-9 && (xi[1] - e[1]).abs() < 1e-9, "{xi:?} vs {e:?}");
        }
        // A warm start at the answer takes no iteration.
        let again = lap
            .solve(Some(&fixed), &b, &mut x, opts, lap.preconditioner(Some(&fixed), opts).as_ref())
            .unwrap();
        assert_eq!(again.iterations, 0, "{again:?}");
    }

    /// The solve against a dense Cholesky factorisation of the same system, with a right-hand
    /// side and a warm start of random values.
    #[test]
    fn solve_matches_a_dense_factorisation() {
        let (mut p, t) = lattice(8);
        // Irregular positions: some weights negative before the clamp.
        let mut s = 12345u64;
        let mut rnd = || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for q in &mut p {
            *q += DVec3::new(0.4 * rnd(), 0.4 * rnd(), 0.3 * rnd());
        }
        let topo = Topology::new(p.len(), &t).unwrap();
        let mut lap = Laplacian::new(&topo, &t);
        let scale: Vec<f64> = t.iter().map(|_| 0.5 + rnd().abs()).collect();
        lap.set_cotangent_weights(&p, &t, Some(&scale));
        let n = p.len();
        // Symmetric with positive weights.
        for i in 0..n {
            let (cols, ws, _) = lap.row(i);
            for (&j, &w) in cols.iter().zip(ws) {
                assert!(w > 0.0, "weight {w}");
                let (cj, wj, _) = lap.row(j as usize);
                let back = cj.iter().position(|&k| k as usize == i).map(|k| wj[k]);
                assert_eq!(back, Some(w), "symmetric");
            }
        }
        let fixed: Vec<bool> = (0..n).map(|i| i == 5).collect();
        let b: Vec<[f64; 1]> = (0..n).map(|i| [if i == 5 { 0.0 } else { rnd() }]).collect();
        let mut x: Vec<[f64; 1]> = (0..n).map(|_| [rnd()]).collect();
        let held = x[5][0];
        let opts = CgOptions::new(1e-14, 10_000);
        lap.solve(Some(&fixed), &b, &mut x, opts, lap.preconditioner(Some(&fixed), opts).as_ref())
            .unwrap();
        // Dense: A y = b − (column 5)·held over the free rows, by Cholesky.
        let free: Vec<usize> = (0..n).filter(|&i| i != 5).collect();
        let m = free.len();
        let mut a = vec![vec![0.0; m]; m];
        let mut rhs = vec![0.0; m];
        for (r, &i) in free.iter().enumerate() {
            a[r][r] = lap.diagonal()[i];
            rhs[r] = b[i][0];
            let (cols, ws, _) = lap.row(i);
            for (&j, &w) in cols.iter().zip(ws) {
                if j == 5 {
                    rhs[r] += w * held;
                } else {
                    let c = free.iter().position(|&k| k == j as usize).unwrap();
                    a[r][c] -= w;
                }
            }
        }
        for k in 0..m {
            a[k][k] = a[k][k].sqrt();
            for i in k + 1..m {
                a[i][k] /= a[k][k];
            }
            for j in k + 1..m {
                for i in j..m {
                    a[i][j] -= a[i][k] * a[j][k];
                }
            }
        }
        let mut y = rhs;
        for i in 0..m {
            for k in 0..i {
                y[i] -= a[i][k] * y[k];
            }
            y[i] /= a[i][i];
        }
        for i in (0..m).rev() {
            for k in i + 1..m {
                y[i] -= a[k][i] * y[k];
            }
            y[i] /= a[i][i];
        }
        for (r, &i) in free.iter().enumerate() {
            assert!((x[i][0] - y[r]).abs() < 1e-9 * (1.0 + y[r].abs()), "{} vs {}", x[i][0], y[r]);
        }
        assert_eq!(x[5][0], held, "the fixed value is kept");
    }

    /// Multigrid and the diagonal precondition the same system: the same solution, in far
    /// fewer iterations; and linear functions are still reproduced.
    #[test]
    fn multigrid_solves_the_same_system() {
        let (p, t) = lattice(80);
        let topo = Topology::new(p.len(), &t).unwrap();
        let mut lap = Laplacian::new(&topo, &t);
        lap.set_cotangent_weights(&p, &t, None);
        let n = p.len();
        let mut fixed = vec![false; n];
        for &h in &topo.boundary {
            fixed[tail(&t, h) as usize] = true;
        }
        let mut s = 99u64;
        let mut rnd = || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let b: Vec<[f64; 2]> = (0..n).map(|_| [rnd(), rnd()]).collect();
        let start: Vec<[f64; 2]> = p.iter().map(|q| [q.x - 2.0 * q.y, 0.3 * q.x]).collect();
        let (mut x_mg, mut x_j) = (start.clone(), start.clone());
        let mg = CgOptions::new(1e-12, 10_000);
        let jacobi = CgOptions { multigrid_above: usize::MAX, ..mg };
        let r_mg = lap
            .solve(Some(&fixed), &b, &mut x_mg, mg, lap.preconditioner(Some(&fixed), mg).as_ref())
            .unwrap();
        let r_j = lap
            .solve(
                Some(&fixed),
                &b,
                &mut x_j,
                jacobi,
                lap.preconditioner(Some(&fixed), jacobi).as_ref(),
            )
            .unwrap();
        assert!(r_mg.iterations * 4 < r_j.iterations, "{r_mg:?} vs {r_j:?}");
        let scale = x_j.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        for (a, c) in x_mg.iter().zip(&x_j) {
            for k in 0..2 {
                assert!((a[k] - c[k]).abs() < 1e-8 * scale, "{a:?} vs {c:?}");
            }
        }
        // Linear precision through the multigrid path.
        let f = |x: DVec3| [2.0 * x.x - 3.0 * x.y + 1.0, 0.5 * x.x + x.y];
        let mut x: Vec<[f64; 2]> =
            p.iter().zip(&fixed).map(|(q, &fx)| if fx { f(*q) } else { [0.0; 2] }).collect();
        let zero = vec![[0.0; 2]; n];
        lap.solve(Some(&fixed), &zero, &mut x, mg, lap.preconditioner(Some(&fixed), mg).as_ref())
            .unwrap();
        for (q, xi) in p.iter().zip(&x) {
            let e = f(*q);
            assert!((xi[0] - e[0]).abs() < 1e-8 && (xi[1] - e[1]).abs() < 1e-8, "{xi:?} vs {e:?}");
        }
    }

    /// A hierarchy whose coarsening stalls (here at once: two of the lattice's three colour
    /// classes held, so no two free vertices are neighbours and no aggregate forms) above
    /// [`DENSE_MAX`] rows smooths its coarsest level rather than factoring it, and still
    /// preconditions the solve to the same answer as the diagonal.
    #[test]
    fn a_stalled_hierarchy_is_not_factored() {
        let n = 80;
        let (p, t) = lattice(n);
        let topo = Topology::new(p.len(), &t).unwrap();
        let mut lap = Laplacian::new(&topo, &t);
        lap.set_cotangent_weights(&p, &t, None);
        let fixed: Vec<bool> = (0..n * n).map(|k| (k / n + 2 * (k % n)) % 3 != 0).collect();
        let free = fixed.iter().filter(|&&f| !f).count();
        assert!(free > DENSE_MAX, "{free} free vertices");
        let mg = Multigrid::new(&lap, Some(&fixed));
        assert!(mg.levels.is_empty() && mg.factor.is_none(), "{} levels", mg.levels.len());
        assert_eq!(mg.coarsest.rows(), free, "the coarsest level is the free rows");
        let b: Vec<[f64; 2]> = (0..n * n).map(|k| [(k % 7) as f64 - 3.0, (k % 5) as f64]).collect();
        let start: Vec<[f64; 2]> = p.iter().map(|q| [q.x, q.y]).collect();
        let opts = CgOptions::new(1e-12, 1000);
        let (mut x_mg, mut x_j) = (start.clone(), start);
        let r_mg = lap.solve(Some(&fixed), &b, &mut x_mg, opts, Some(&mg)).unwrap();
        let r_j = lap.solve(Some(&fixed), &b, &mut x_j, opts, None).unwrap();
        assert!(r_mg.iterations <= r_j.iterations, "{r_mg:?} vs {r_j:?}");
        for (a, c) in x_mg.iter().zip(&x_j) {
            for k in 0..2 {
                assert!((a[k] - c[k]).abs() < 1e-9 * (1.0 + c[k].abs()), "{a:?} vs {c:?}");
            }
        }
    }

    #[test]
    fn failures_are_errors() {
        let (p, t) = lattice(6);
        let topo = Topology::new(p.len(), &t).unwrap();
        let mut lap = Laplacian::new(&topo, &t);
        lap.set_cotangent_weights(&p, &t, None);
        let n = p.len();
        let fixed: Vec<bool> = (0..n).map(|i| i == 0).collect();
        let b: Vec<[f64; 1]> = (0..n).map(|i| [if i == 3 { 1.0 } else { 0.0 }]).collect();
        let mut x = vec![[0.0]; n];
        let few = CgOptions::new(1e-14, 2);
        let e = lap
            .solve(Some(&fixed), &b, &mut x, few, lap.preconditioner(Some(&fixed), few).as_ref())
            .unwrap_err();
        assert!(e.to_string().contains("did not converge"), "{e}");
        let mut bad = b.clone();
        bad[4] = [f64::NAN];
        let opts = CgOptions::new(1e-10, 100);
        assert!(
            lap.solve(
                Some(&fixed),
                &bad,
                &mut x,
                opts,
                lap.preconditioner(Some(&fixed), opts).as_ref()
            )
            .is_err(),
            "NaN"
        );
        // Wrong sizes.
        assert!(
            lap.solve(
                Some(&fixed),
                &b[1..],
                &mut x,
                opts,
                lap.preconditioner(Some(&fixed), opts).as_ref()
            )
            .is_err(),
            "size"
        );
    }

    #[test]
    fn topology_errors_name_the_problem() {
        let t = [[0, 1, 2], [0, 1, 3]];
        let e = Topology::new(4, &t).unwrap_err().to_string();
        assert!(e.contains("same direction"), "{e}");
        let e = Topology::new(5, &[[0, 1, 2], [2, 1, 3]]).unwrap_err().to_string();
        assert!(e.contains("vertex 4 is in no triangle"), "{e}");
        let e = Topology::new(3, &[[0, 1, 1]]).unwrap_err().to_string();
        assert!(e.contains("repeats"), "{e}");
        let e = Topology::new(3, &[[0, 1, 7]]).unwrap_err().to_string();
        assert!(e.contains("vertex 7"), "{e}");
        // Two triangles touching at vertex 0 only.
        let e = Topology::new(5, &[[0, 1, 2], [0, 3, 4]]).unwrap_err().to_string();
        assert!(e.contains("vertex 0 joins 2 separate fans"), "{e}");
        // A good strip: counts.
        let topo = Topology::new(4, &[[0, 1, 2], [2, 1, 3]]).unwrap();
        assert_eq!(topo.edge_count(), 5);
        assert_eq!(topo.euler_characteristic(), 1);
        assert_eq!(topo.boundary_loops(&[[0, 1, 2], [2, 1, 3]]).len(), 1);
    }
}
