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
//! Written here rather than taken from a crate: the ones published work in `f32` on fixed
//! chunks, where the fit wants `f64` on a grid sized to the scan.

use glam::DVec3;

use crate::{Error, NonFiniteInput};

/// Marks a cell with no vertex.
const NONE: u32 = u32::MAX;

/// The most grid nodes [`surface_nets`] takes (2²⁷: a 512³ grid).
pub const MAX_NODES: usize = 1 << 27;

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
    let &Grid { origin, spacing, dims, values } = grid;
    let [nx, ny, nz] = dims;
    check_grid(grid)?;
    let node = |i: usize, j: usize, k: usize| i + nx * (j + ny * k);
    let values = &resolve_ambiguous_faces(values, dims);
    let (cx, cy) = (nx - 1, ny - 1);
    let cell = |i: usize, j: usize, k: usize| i + cx * (j + cy * k);
    let (vertex, points) = cell_vertices(values, dims, origin, spacing);
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
    // vertices, counter-clockwise about the edge's direction (x: in the (y, z) plane; y: in the
    // (z, x) plane; z: in the (x, y) plane), turned to face the outside end.
    let at = |i: usize, j: usize, k: usize| vertex[cell(i, j, k)];
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let value = values[node(i, j, k)];
                if value.is_nan() {
                    continue;
                }
                let here = value < 0.0;
                let (inner_i, inner_j, inner_k) =
                    (i > 0 && i < cx, j > 0 && j < cy, k > 0 && k < nz - 1);
                if i < cx && inner_j && inner_k && here != (values[node(i + 1, j, k)] < 0.0) {
                    quad(
                        [at(i, j - 1, k - 1), at(i, j, k - 1), at(i, j, k), at(i, j - 1, k)],
                        here,
                    );
                }
                if j < cy && inner_i && inner_k && here != (values[node(i, j + 1, k)] < 0.0) {
                    quad(
                        [at(i - 1, j, k - 1), at(i - 1, j, k), at(i, j, k), at(i, j, k - 1)],
                        here,
                    );
                }
                if k < nz - 1 && inner_i && inner_j && here != (values[node(i, j, k + 1)] < 0.0) {
                    quad(
                        [at(i - 1, j - 1, k), at(i, j - 1, k), at(i, j, k), at(i - 1, j, k)],
                        here,
                    );
                }
            }
        }
    }
    Ok((points, triangles))
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

/// The vertices of [`surface_nets`]: in each cell the surface crosses, the mean of the points
/// where it crosses the cell's edges (linear along each); each cell's vertex ([`NONE`] where
/// there is none) and the points.
fn cell_vertices(
    values: &[f64],
    dims: [usize; 3],
    origin: DVec3,
    spacing: f64,
) -> (Vec<u32>, Vec<DVec3>) {
    let [nx, ny, nz] = dims;
    let node = |i: usize, j: usize, k: usize| i + nx * (j + ny * k);
    let (cx, cy) = (nx - 1, ny - 1);
    let cell = |i: usize, j: usize, k: usize| i + cx * (j + cy * k);
    let mut vertex = vec![NONE; cx * cy * (nz - 1)];
    let mut points = Vec::new();
    for k in 0..nz - 1 {
        for j in 0..cy {
            for i in 0..cx {
                let v: [f64; 8] = CORNERS.map(|c| values[node(i + c[0], j + c[1], k + c[2])]);
                if v.iter().any(|x| x.is_nan()) {
                    continue;
                }
                let inside = v.iter().filter(|&&x| x < 0.0).count();
                if inside == 0 || inside == 8 {
                    continue;
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
                vertex[cell(i, j, k)] = points.len() as u32;
                let local = sum / count;
                points.push(origin + (DVec3::new(i as f64, j as f64, k as f64) + local) * spacing);
            }
        }
    }
    (vertex, points)
}

/// The values with every face whose corners alternate in sign resolved (see [`surface_nets`]):
/// every face is looked at once, and after a corner moves inside, the faces around it again.
/// Corners only ever move inside, so this ends.
fn resolve_ambiguous_faces(values: &[f64], dims: [usize; 3]) -> Vec<f64> {
    let [nx, ny, nz] = dims;
    let mut v = values.to_vec();
    let node = |i: usize, j: usize, k: usize| i + nx * (j + ny * k);
    // The faces whose lowest corner is node (i, j, k): spanning (x, y), (y, z) and (z, x).
    let faces_at = |i: usize, j: usize, k: usize| {
        [
            (i + 1 < nx && j + 1 < ny).then(|| {
                [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k)]
            }),
            (j + 1 < ny && k + 1 < nz).then(|| {
                [node(i, j, k), node(i, j + 1, k), node(i, j + 1, k + 1), node(i, j, k + 1)]
            }),
            (k + 1 < nz && i + 1 < nx).then(|| {
                [node(i, j, k), node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j, k)]
            }),
        ]
    };
    // The node that must move inside for a face to stop alternating: its outside corner
    // nearest zero, so that the inside diagonal connects.
    let to_move = |v: &[f64], face: [usize; 4]| {
        if face.iter().any(|&t| v[t].is_nan()) {
            return None;
        }
        let s = face.map(|t| v[t] < 0.0);
        if s[0] != s[2] || s[1] != s[3] || s[0] == s[1] {
            return None;
        }
        face.into_iter().filter(|&t| v[t] >= 0.0).min_by(|&a, &b| v[a].total_cmp(&v[b]))
    };
    // One sweep over every face in order, then again round each corner that moved.
    let mut pending = Vec::new();
    let look = |v: &mut [f64], anchor: usize, pending: &mut Vec<usize>| {
        let (i, j, k) = (anchor % nx, anchor / nx % ny, anchor / nx / ny);
        for face in faces_at(i, j, k).into_iter().flatten() {
            let Some(t) = to_move(v, face) else { continue };
            v[t] = -1e-9 * v[t] - f64::MIN_POSITIVE;
            // Every face with t as a corner has its lowest corner within one step below t.
            let (ti, tj, tk) = (t % nx, t / nx % ny, t / nx / ny);
            for dk in 0..=tk.min(1) {
                for dj in 0..=tj.min(1) {
                    for di in 0..=ti.min(1) {
                        pending.push(node(ti - di, tj - dj, tk - dk));
                    }
                }
            }
        }
    };
    for anchor in 0..nx * ny * nz {
        look(&mut v, anchor, &mut pending);
    }
    while let Some(anchor) = pending.pop() {
        look(&mut v, anchor, &mut pending);
    }
    v
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
