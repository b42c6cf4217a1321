// SPDX-License-Identifier: MIT
//! The zero set of a function sampled on a regular grid, as a triangle mesh (naive surface nets,
//! Gibson 1998): one vertex in every cell whose corners change sign, at the mean of the points
//! where the function, interpolated linearly along the cell's edges, crosses zero; and for every
//! grid edge that changes sign, the quad of the four cells around it, split along its shorter
//! diagonal.
//!
//! Negative values are inside, zero and positive outside, NaN unknown: a cell with an unknown
//! corner has no vertex, so the mesh has a boundary where the known values end. The triangles
//! wind counter-clockwise seen from outside, so a closed zero set inside the known part of the
//! grid gives a closed mesh of positive volume.
//!
//! The values are kept in bricks of 8³ nodes, only those bricks that hold a known value
//! stored: a zero set sampled in a band about a surface (as
//! [`PointSurface::zero_set`](crate::implicit::PointSurface::zero_set) samples it) takes memory
//! in proportion to the band, not to the volume the grid spans (for the bare vertices of a head
//! scan, a quarter of the bricks of its 207 × 194 × 131 grid).
//!
//! Written here rather than taken from a crate: the ones published work in `f32` on fixed
//! chunks, where the fit wants `f64` on a grid sized to the scan.

use glam::DVec3;

use crate::{Error, NonFiniteInput};

/// Marks a cell with no vertex.
const NONE: u32 = u32::MAX;

/// The most grid nodes [`surface_nets`] takes (2²⁷: a 512³ grid).
pub const MAX_NODES: usize = 1 << 27;

/// The most grid nodes a sparse grid spans, stored or not (2³²: its table of bricks, one
/// 4-byte entry per 8³ nodes, is then 32 MiB). A point set whose parts lie far apart (a
/// country's points on the globe with its islands and territories overseas) spans a grid of
/// its fine cell far larger than the band its surfaces fill.
pub const MAX_SPARSE_NODES: u64 = 1 << 32;

/// A function sampled at the nodes of a regular grid.
#[derive(Clone, Copy, Debug)]
pub struct Grid<'a> {
    /// The position of node (0, 0, 0).
    pub origin: DVec3,
    /// The distance between neighbouring nodes, the same along every axis.
    pub spacing: f64,
    /// Nodes along x, y and z (at least 2 each).
    pub dims: [usize; 3],
    /// The values, x fastest then y then z: node (i, j, k) at `i + dims[0]·(j + dims[1]·k)`;
    /// NaN where the function is not known.
    pub values: &'a [f64],
}

/// The triangle mesh of the zero set of `grid` (see the module documentation): vertex positions
/// and counter-clockwise triangles.
///
/// A face of the grid whose corners alternate in sign (inside, outside, inside, outside) would
/// put four triangles on one edge; before meshing, its outside corner nearest zero is moved
/// just inside (its value negated and scaled by 10⁻⁹, so that the crossings hardly move), so
/// that the inside diagonal connects, until no such face is left. Every edge of the result
/// then has two triangles.
///
/// # Errors
///
/// [`Error::InvalidOption`] for a grid with fewer than 2 nodes along an axis, more than
/// [`MAX_NODES`] nodes, a value count other than the node count or a spacing that is not
/// positive and finite; [`Error::NonFinite`] for an infinite value or an origin that is NaN or
/// infinite.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::surfacenets::{Grid, surface_nets};
///
/// // The sphere of radius 1 through its signed distance on a 24³ grid over [−1.5, 1.5]³.
/// let (n, h) = (24, 3.0 / 23.0);
/// let origin = DVec3::splat(-1.5);
/// let values: Vec<f64> = (0..n * n * n)
///     .map(|t| (origin + DVec3::new((t % n) as f64, (t / n % n) as f64, (t / n / n) as f64) * h))
///     .map(|p| p.length() - 1.0)
///     .collect();
/// let (points, triangles) =
///     surface_nets(&Grid { origin, spacing: h, dims: [n; 3], values: &values }).unwrap();
/// assert!(points.iter().all(|p| (p.length() - 1.0).abs() < 0.5 * h));
/// // A closed surface of genus 0: V − E + F = 2 with E = 3F/2.
/// assert_eq!(points.len() as i64 - triangles.len() as i64 / 2, 2);
/// ```
pub fn surface_nets(grid: &Grid<'_>) -> Result<(Vec<DVec3>, Vec<[u32; 3]>), Error> {
    check_grid(grid)?;
    let &Grid { origin, spacing, dims, values } = grid;
    let mut sparse = SparseGrid::new(origin, spacing, dims);
    let [nx, ny, _] = dims;
    for (t, &v) in values.iter().enumerate() {
        if !v.is_nan() {
            sparse.set(t % nx, t / nx % ny, t / nx / ny, v);
        }
    }
    Ok(sparse.surface_nets())
}

/// Nodes along each side of a brick of a [`SparseGrid`].
const BRICK: usize = 8;

/// Nodes in a brick.
const BRICK_NODES: usize = BRICK * BRICK * BRICK;

/// A function sampled at the nodes of a regular grid (as [`Grid`]), kept in bricks of 8³ nodes
/// of which only those holding a known value are stored: its memory grows with the band where
/// the function is known (about a surface, for [`crate::implicit::PointSurface::zero_set`]),
/// not with the volume the grid spans. Nodes outside every stored brick are unknown (NaN).
#[derive(Debug)]
pub(crate) struct SparseGrid {
    origin: DVec3,
    spacing: f64,
    dims: [usize; 3],
    /// Bricks along x, y and z.
    bricks: [usize; 3],
    /// Each brick's place in `values` (in bricks), [`NONE`] where it is not stored.
    table: Vec<u32>,
    /// Each stored brick's index in `table`.
    stored: Vec<usize>,
    /// The stored bricks' values, [`BRICK_NODES`] each, x fastest then y then z.
    values: Vec<f64>,
}

impl SparseGrid {
    /// A grid of `dims` nodes from `origin`, `spacing` apart, with no value known. The caller
    /// checks the dimensions ([`check_grid`]'s bounds).
    pub(crate) fn new(origin: DVec3, spacing: f64, dims: [usize; 3]) -> Self {
        let bricks = dims.map(|d| d.div_ceil(BRICK));
        Self {
            origin,
            spacing,
            dims,
            bricks,
            table: vec![NONE; bricks[0] * bricks[1] * bricks[2]],
            stored: Vec::new(),
            values: Vec::new(),
        }
    }

    /// The index in `table` of the brick holding node (i, j, k).
    const fn brick_of(&self, i: usize, j: usize, k: usize) -> usize {
        i / BRICK + self.bricks[0] * (j / BRICK + self.bricks[1] * (k / BRICK))
    }

    /// The place of node (i, j, k) within its brick.
    const fn within(i: usize, j: usize, k: usize) -> usize {
        i % BRICK + BRICK * (j % BRICK + BRICK * (k % BRICK))
    }

    /// The index in `values` of node (i, j, k), `None` when its brick is not stored.
    fn slot(&self, i: usize, j: usize, k: usize) -> Option<usize> {
        let b = self.table[self.brick_of(i, j, k)];
        (b != NONE).then(|| b as usize * BRICK_NODES + Self::within(i, j, k))
    }

    /// The value at node (i, j, k): NaN where it is not known.
    pub(crate) fn get(&self, i: usize, j: usize, k: usize) -> f64 {
        self.slot(i, j, k).map_or(f64::NAN, |s| self.values[s])
    }

    /// The bricks stored, and the bricks the whole grid spans.
    #[cfg(test)]
    pub(crate) fn bricks_stored(&self) -> (usize, usize) {
        (self.stored.len(), self.table.len())
    }

    /// Stores the brick holding node (i, j, k), its values unknown, if it is not stored yet;
    /// its index in `values`, in bricks.
    fn store(&mut self, i: usize, j: usize, k: usize) -> usize {
        let b = self.brick_of(i, j, k);
        if self.table[b] == NONE {
            self.table[b] = u32::try_from(self.stored.len()).unwrap_or(NONE);
            self.stored.push(b);
            self.values.resize(self.values.len() + BRICK_NODES, f64::NAN);
        }
        self.table[b] as usize
    }

    /// Sets the value at node (i, j, k), storing its brick if need be.
    pub(crate) fn set(&mut self, i: usize, j: usize, k: usize, value: f64) {
        let b = self.store(i, j, k);
        self.values[b * BRICK_NODES + Self::within(i, j, k)] = value;
    }

    /// Every stored node's position and value, the values mutable (in parallel with the
    /// `parallel` feature): `f(position, &mut value)`.
    pub(crate) fn update(&mut self, f: impl Fn(DVec3, &mut f64) + Sync + Send) {
        use hi_par::*;
        let (origin, spacing, bricks, dims) = (self.origin, self.spacing, self.bricks, self.dims);
        let stored = &self.stored;
        self.values.par_chunks_mut(BRICK_NODES).enumerate().for_each(|(s, brick)| {
            let b = stored[s];
            let corner = [b % bricks[0], b / bricks[0] % bricks[1], b / bricks[0] / bricks[1]]
                .map(|c| c * BRICK);
            for (w, value) in brick.iter_mut().enumerate() {
                let n = [
                    corner[0] + w % BRICK,
                    corner[1] + w / BRICK % BRICK,
                    corner[2] + w / BRICK / BRICK,
                ];
                if n[0] < dims[0] && n[1] < dims[1] && n[2] < dims[2] {
                    let p = origin + DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64) * spacing;
                    f(p, value);
                }
            }
        });
    }

    /// Calls `f(i, j, k)` for every node of a stored brick inside the grid, in the order of
    /// [`Grid`]'s values (x fastest, then y, then z), skipping the bricks not stored.
    fn each_stored_node(&self, mut f: impl FnMut(usize, usize, usize)) {
        let [nx, ny, nz] = self.dims;
        let [bx, by, _] = self.bricks;
        // The stored bricks in the table's order: by layer (k), then row (j), then along x,
        // so that the empty rows and layers of a grid spanning parts far apart cost nothing.
        let mut bricks = self.stored.clone();
        bricks.sort_unstable();
        for layer in bricks.chunk_by(|a, b| a / (bx * by) == b / (bx * by)) {
            let bk = layer[0] / (bx * by);
            let rows: Vec<&[usize]> = layer.chunk_by(|a, b| a / bx == b / bx).collect();
            for k in bk * BRICK..((bk + 1) * BRICK).min(nz) {
                for row in &rows {
                    let bj = row[0] / bx % by;
                    for j in bj * BRICK..((bj + 1) * BRICK).min(ny) {
                        for &b in *row {
                            let bi = b % bx;
                            for i in bi * BRICK..((bi + 1) * BRICK).min(nx) {
                                f(i, j, k);
                            }
                        }
                    }
                }
            }
        }
    }

    /// [`surface_nets`] on this grid.
    pub(crate) fn surface_nets(mut self) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        self.resolve_ambiguous_faces();
        let [nx, ny, nz] = self.dims;
        let (cx, cy) = (nx - 1, ny - 1);
        let (vertex, points) = self.cell_vertices();
        let mut triangles = Vec::with_capacity(2 * points.len());
        let mut quad = |q: [u32; 4], outward: bool| {
            if q.contains(&NONE) {
                // A cell beside the edge has an unknown corner.
                return;
            }
            let [a, b, c, d] = if outward { q } else { [q[3], q[2], q[1], q[0]] };
            let p = |v: u32| points[v as usize];
            // The shorter diagonal.
            if p(a).distance_squared(p(c)) <= p(b).distance_squared(p(d)) {
                triangles.push([a, b, c]);
                triangles.push([a, c, d]);
            } else {
                triangles.push([a, b, d]);
                triangles.push([b, c, d]);
            }
        };
        // Every grid edge that changes sign, with four cells around it: the quad of their
        // vertices, counter-clockwise about the edge's direction (x: in the (y, z) plane; y: in
        // the (z, x) plane; z: in the (x, y) plane), turned to face the outside end.
        let at = |i: usize, j: usize, k: usize| self.slot(i, j, k).map_or(NONE, |s| vertex[s]);
        let inside = |i: usize, j: usize, k: usize| self.get(i, j, k) < 0.0;
        self.each_stored_node(|i, j, k| {
            let value = self.get(i, j, k);
            if value.is_nan() {
                return;
            }
            let here = value < 0.0;
            let (inner_i, inner_j, inner_k) =
                (i > 0 && i < cx, j > 0 && j < cy, k > 0 && k < nz - 1);
            if i < cx && inner_j && inner_k && here != inside(i + 1, j, k) {
                quad([at(i, j - 1, k - 1), at(i, j, k - 1), at(i, j, k), at(i, j - 1, k)], here);
            }
            if j < cy && inner_i && inner_k && here != inside(i, j + 1, k) {
                quad([at(i - 1, j, k - 1), at(i - 1, j, k), at(i, j, k), at(i, j, k - 1)], here);
            }
            if k < nz - 1 && inner_i && inner_j && here != inside(i, j, k + 1) {
                quad([at(i - 1, j - 1, k), at(i, j - 1, k), at(i, j, k), at(i - 1, j, k)], here);
            }
        });
        (points, triangles)
    }
    /// The vertices of [`surface_nets`]: in each cell the surface crosses, the mean of the
    /// points where it crosses the cell's edges (linear along each); each cell's vertex (kept
    /// as the values are, a cell at its lowest node; [`NONE`] where there is none) and the
    /// points.
    fn cell_vertices(&self) -> (Vec<u32>, Vec<DVec3>) {
        let [nx, ny, nz] = self.dims;
        let mut vertex = vec![NONE; self.values.len()];
        let mut points = Vec::new();
        self.each_stored_node(|i, j, k| {
            if i + 1 >= nx || j + 1 >= ny || k + 1 >= nz {
                return;
            }
            let v: [f64; 8] = CORNERS.map(|c| self.get(i + c[0], j + c[1], k + c[2]));
            if v.iter().any(|x| x.is_nan()) {
                return;
            }
            let inside = v.iter().filter(|&&x| x < 0.0).count();
            if inside == 0 || inside == 8 {
                return;
            }
            let (mut sum, mut count) = (DVec3::ZERO, 0.0);
            for [a, b] in EDGES {
                if (v[a] < 0.0) != (v[b] < 0.0) {
                    let t = v[a] / (v[a] - v[b]);
                    let pa = DVec3::from_array(CORNERS[a].map(|c| c as f64));
                    let pb = DVec3::from_array(CORNERS[b].map(|c| c as f64));
                    sum += pa + (pb - pa) * t;
                    count += 1.0;
                }
            }
            if let Some(s) = self.slot(i, j, k) {
                vertex[s] = u32::try_from(points.len()).unwrap_or(NONE);
            }
            let local = sum / count;
            points.push(
                self.origin + (DVec3::new(i as f64, j as f64, k as f64) + local) * self.spacing,
            );
        });
        (vertex, points)
    }

    /// Resolves every face whose corners alternate in sign (see [`surface_nets`]): every face
    /// is looked at once, and after a corner moves inside, the faces around it again. Corners
    /// only ever move inside, so this ends.
    fn resolve_ambiguous_faces(&mut self) {
        let [nx, ny, nz] = self.dims;
        // The faces whose lowest corner is node (i, j, k): spanning (x, y), (y, z) and (z, x).
        let faces_at = |i: usize, j: usize, k: usize| {
            [
                (i + 1 < nx && j + 1 < ny)
                    .then(|| [[i, j, k], [i + 1, j, k], [i + 1, j + 1, k], [i, j + 1, k]]),
                (j + 1 < ny && k + 1 < nz)
                    .then(|| [[i, j, k], [i, j + 1, k], [i, j + 1, k + 1], [i, j, k + 1]]),
                (k + 1 < nz && i + 1 < nx)
                    .then(|| [[i, j, k], [i, j, k + 1], [i + 1, j, k + 1], [i + 1, j, k]]),
            ]
        };
        // The values apart from the grid, which the sweep reads for where each node's value is.
        let mut values = std::mem::take(&mut self.values);
        let grid = &*self;
        // The node that must move inside for a face to stop alternating: its outside corner
        // nearest zero, so that the inside diagonal connects; with its value's place.
        let to_move = |values: &[f64], face: [[usize; 3]; 4]| {
            let slots = face.map(|[i, j, k]| grid.slot(i, j, k));
            if slots.contains(&None) {
                return None;
            }
            let v = slots.map(|s| s.map_or(f64::NAN, |s| values[s]));
            if v.iter().any(|x| x.is_nan()) {
                return None;
            }
            let s = v.map(|x| x < 0.0);
            if s[0] != s[2] || s[1] != s[3] || s[0] == s[1] {
                return None;
            }
            (0..4)
                .filter(|&c| v[c] >= 0.0)
                .min_by(|&a, &b| v[a].total_cmp(&v[b]))
                .and_then(|c| slots[c].map(|s| (face[c], s)))
        };
        // One sweep over every face in order, then again round each corner that moved.
        let mut pending: Vec<[usize; 3]> = Vec::new();
        let look = |values: &mut [f64], [i, j, k]: [usize; 3], pending: &mut Vec<[usize; 3]>| {
            // Every face here has this node for a corner: none alternates where it is unknown.
            if grid.slot(i, j, k).is_none_or(|s| values[s].is_nan()) {
                return;
            }
            for face in faces_at(i, j, k).into_iter().flatten() {
                let Some(([ti, tj, tk], s)) = to_move(values, face) else { continue };
                values[s] = -1e-9 * values[s] - f64::MIN_POSITIVE;
                // Every face with this corner has its lowest corner within one step below it.
                for dk in 0..=tk.min(1) {
                    for dj in 0..=tj.min(1) {
                        for di in 0..=ti.min(1) {
                            pending.push([ti - di, tj - dj, tk - dk]);
                        }
                    }
                }
            }
        };
        grid.each_stored_node(|i, j, k| look(&mut values, [i, j, k], &mut pending));
        while let Some(anchor) = pending.pop() {
            look(&mut values, anchor, &mut pending);
        }
        self.values = values;
    }
}

// The corners of a cell, as offsets, and its twelve edges as pairs of corners.
const CORNERS: [[usize; 3]; 8] =
    [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1]];
const EDGES: [[usize; 2]; 12] = [
    [0, 1],
    [2, 3],
    [4, 5],
    [6, 7],
    [0, 2],
    [1, 3],
    [4, 6],
    [5, 7],
    [0, 4],
    [1, 5],
    [2, 6],
    [3, 7],
];

/// The checks of [`surface_nets`]: at least 2 nodes along each axis and at most
/// [`MAX_NODES`] in all, one value per node, a positive finite spacing, a finite origin, and
/// no infinite value.
fn check_grid(grid: &Grid<'_>) -> Result<(), Error> {
    let &Grid { origin, spacing, dims, values } = grid;
    let [nx, ny, nz] = dims;
    if dims.iter().any(|&d| d < 2) {
        return Err(Error::InvalidOption {
            name: "grid nodes along an axis",
            value: dims.iter().copied().min().unwrap_or(0) as f64,
            expected: "at least 2",
        });
    }
    let nodes = nx.checked_mul(ny).and_then(|m| m.checked_mul(nz)).unwrap_or(usize::MAX);
    if nodes > MAX_NODES {
        return Err(Error::InvalidOption {
            name: "grid nodes",
            value: nodes as f64,
            expected: "at most 2^27",
        });
    }
    if values.len() != nodes {
        return Err(Error::InvalidOption {
            name: "grid values",
            value: values.len() as f64,
            expected: "one value per node",
        });
    }
    if !(spacing.is_finite() && spacing > 0.0) {
        return Err(Error::InvalidOption {
            name: "grid spacing",
            value: spacing,
            expected: "positive and finite",
        });
    }
    if !origin.is_finite() {
        return Err(Error::NonFinite { what: NonFiniteInput::GridOrigin });
    }
    if let Some(k) = values.iter().position(|v| v.is_infinite()) {
        return Err(Error::NonFinite { what: NonFiniteInput::GridValue(k) });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The edges of a triangle list with how many triangles use each (as unordered pairs), and
    /// how many use each directed edge.
    fn edge_counts(triangles: &[[u32; 3]]) -> (Vec<usize>, usize) {
        let mut undirected = std::collections::HashMap::new();
        let mut directed = std::collections::HashMap::new();
        for t in triangles {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                *undirected.entry((a.min(b), a.max(b))).or_insert(0usize) += 1;
                *directed.entry((a, b)).or_insert(0usize) += 1;
            }
        }
        let repeated = directed.values().filter(|&&c| c > 1).count();
        (undirected.into_values().collect(), repeated)
    }

    /// Samples `f` on an n³ grid over [−r, r]³.
    fn sampled(n: usize, r: f64, f: impl Fn(DVec3) -> f64) -> (DVec3, f64, Vec<f64>) {
        let h = 2.0 * r / (n - 1) as f64;
        let origin = DVec3::splat(-r);
        let values = (0..n * n * n)
            .map(|t| {
                origin + DVec3::new((t % n) as f64, (t / n % n) as f64, (t / n / n) as f64) * h
            })
            .map(f)
            .collect();
        (origin, h, values)
    }

    #[test]
    fn a_torus_is_closed_with_genus_one_and_outward() {
        let (big, small) = (1.0, 0.4);
        let (origin, h, values) = sampled(40, 1.6, |p: DVec3| {
            let q = DVec3::new(p.truncate().length() - big, p.z, 0.0);
            q.length() - small
        });
        let (points, triangles) =
            surface_nets(&Grid { origin, spacing: h, dims: [40; 3], values: &values }).unwrap();
        let (counts, repeated) = edge_counts(&triangles);
        assert!(counts.iter().all(|&c| c == 2), "every edge on two triangles");
        assert_eq!(repeated, 0, "consistently wound");
        // V − E + F = 0.
        assert_eq!(points.len() as i64 - counts.len() as i64 + triangles.len() as i64, 0);
        // Its volume, 2π²Rr², by the divergence theorem over the triangles: positive (outward).
        let volume: f64 = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|k| points[k as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum();
        let exact = 2.0 * std::f64::consts::PI.powi(2) * big * small * small;
        assert!((volume - exact).abs() < 0.03 * exact, "{volume} against {exact}");
    }

    #[test]
    fn faces_with_alternating_corners_give_manifold_edges() {
        // Two balls touching along a line of nodes: their sign pattern alternates across the
        // faces where they meet diagonally.
        let (origin, h, values) = sampled(21, 2.0, |p: DVec3| {
            let a = (p - DVec3::new(-0.7, -0.7, 0.0)).length() - 0.99;
            let b = (p - DVec3::new(0.7, 0.7, 0.0)).length() - 0.99;
            a.min(b)
        });
        let (_, triangles) =
            surface_nets(&Grid { origin, spacing: h, dims: [21; 3], values: &values }).unwrap();
        let (counts, repeated) = edge_counts(&triangles);
        assert!(counts.iter().all(|&c| c == 2), "every edge on two triangles");
        assert_eq!(repeated, 0);
    }

    #[test]
    fn unknown_values_leave_a_boundary() {
        // The sphere with its top cap unknown: an open mesh whose boundary edges are on one
        // triangle each.
        let (origin, h, mut values) = sampled(24, 1.5, |p: DVec3| p.length() - 1.0);
        let n = 24;
        for (t, v) in values.iter_mut().enumerate() {
            if origin.z + (t / n / n) as f64 * h > 0.5 {
                *v = f64::NAN;
            }
        }
        let (points, triangles) =
            surface_nets(&Grid { origin, spacing: h, dims: [n; 3], values: &values }).unwrap();
        let (counts, _) = edge_counts(&triangles);
        assert!(counts.contains(&1), "a boundary");
        assert!(counts.iter().all(|&c| c <= 2));
        assert!(points.iter().all(|p| p.z < 0.5 + h));
    }

    #[test]
    fn a_band_about_a_surface_stores_only_its_bricks() {
        // The unit sphere's signed distance known within 2 cells of it on a 96³ grid, set
        // node by node: a closed genus-0 mesh on the sphere, across the seams of the bricks,
        // from a fifth of the bricks (a shell of radius 4 bricks in a cube of 12).
        let (n, r) = (96, 1.5);
        let h = 2.0 * r / (n - 1) as f64;
        let origin = DVec3::splat(-r);
        let mut grid = SparseGrid::new(origin, h, [n; 3]);
        for k in 0..n {
            for j in 0..n {
                for i in 0..n {
                    let p = origin + DVec3::new(i as f64, j as f64, k as f64) * h;
                    let f = p.length() - 1.0;
                    if f.abs() < 2.0 * h {
                        grid.set(i, j, k, f);
                    }
                }
            }
        }
        let (stored, all) = grid.bricks_stored();
        assert_eq!(all, 12 * 12 * 12);
        assert!(stored < all * 35 / 100, "{stored} of {all} bricks stored");
        let (points, triangles) = grid.surface_nets();
        let (counts, repeated) = edge_counts(&triangles);
        assert!(counts.iter().all(|&c| c == 2), "every edge on two triangles");
        assert_eq!(repeated, 0);
        assert_eq!(points.len() as i64 - counts.len() as i64 + triangles.len() as i64, 2);
        assert!(points.iter().all(|p| (p.length() - 1.0).abs() < 0.5 * h));
    }

    #[test]
    fn bad_grids_are_named() {
        let values = vec![1.0; 8];
        let grid = |dims, spacing, values: &[f64]| {
            surface_nets(&Grid { origin: DVec3::ZERO, spacing, dims, values })
        };
        assert!(
            matches!(grid([2, 2, 2], 1.0, &values), Ok((p, t)) if p.is_empty() && t.is_empty())
        );
        assert!(matches!(grid([1, 2, 4], 1.0, &values), Err(Error::InvalidOption { .. })));
        assert!(matches!(grid([2, 2, 3], 1.0, &values), Err(Error::InvalidOption { .. })));
        assert!(matches!(grid([2, 2, 2], 0.0, &values), Err(Error::InvalidOption { .. })));
        assert!(matches!(grid([2, 2, 2], f64::NAN, &values), Err(Error::InvalidOption { .. })));
        let mut bad = values.clone();
        bad[3] = f64::INFINITY;
        assert!(matches!(grid([2, 2, 2], 1.0, &bad), Err(Error::NonFinite { .. })));
        assert!(matches!(
            grid([1 << 10, 1 << 10, 1 << 10], 1.0, &values),
            Err(Error::InvalidOption { .. })
        ));
    }
}
