// SPDX-License-Identifier: MIT
//! The meshes the masks are read off: tori unrolled about a vertex, cones of any valence;
//! and the edges of a set of faces.

use std::collections::BTreeSet;
use std::f64::consts::PI;

use anyhow::{Context, Result, ensure};
use glam::{DVec2, DVec3};
use hi_mesh::subdivision::{PolyMesh, Scheme};

use super::{LOOP, TORUS};

/// A closed mesh and where its vertices are drawn (the torus unrolled about its centre vertex).
#[derive(Clone, Debug)]
pub(super) struct Sample {
    /// The mesh.
    pub(super) mesh: PolyMesh,
    /// Plane position of every vertex.
    pub(super) layout: Vec<DVec2>,
    /// The vertex drawn at the origin.
    pub(super) centre: u32,
}

impl Sample {
    /// The vertex drawn at `p`.
    pub(super) fn vertex_at(&self, p: DVec2) -> Result<u32> {
        let found = self.layout.iter().position(|q| q.distance(p) < 1e-9);
        let v = found.with_context(|| format!("no vertex is drawn at {p}"))?;
        Ok(u32::try_from(v)?)
    }
}

/// A point of the torus with radii 3 and 1 at angles 2πi/`n`, 2πj/`n`.
fn torus_point(i: u32, j: u32, n: u32) -> DVec3 {
    let (su, cu) = (2.0 * PI * f64::from(i) / f64::from(n)).sin_cos();
    let (sv, cv) = (2.0 * PI * f64::from(j) / f64::from(n)).sin_cos();
    DVec3::new((3.0 + cv) * cu, (3.0 + cv) * su, sv)
}

/// A [`TORUS`] × [`TORUS`] grid of vertices (i, j) ↦ i + `TORUS`·j on a torus (or, if not
/// `closed`, a flat open patch), with `cell` giving the faces of cell (i, j) and `plane` the
/// drawing position of the offset (i, j) from the centre (`TORUS`/2, `TORUS`/2).
fn grid(
    closed: bool,
    cell: impl Fn(&dyn Fn(u32, u32) -> u32, u32, u32) -> Vec<Vec<u32>>,
    plane: impl Fn(f64, f64) -> DVec2,
) -> Result<Sample> {
    let n = TORUS;
    let idx = |i: u32, j: u32| (i % n) + n * (j % n);
    let mut positions = Vec::new();
    let mut layout = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (di, dj) = (f64::from(i) - f64::from(n / 2), f64::from(j) - f64::from(n / 2));
            let at = plane(di, dj);
            positions.push(if closed { torus_point(i, j, n) } else { at.extend(0.0) });
            layout.push(at);
        }
    }
    let cells = if closed { n } else { n - 1 };
    let mut faces = Vec::new();
    for j in 0..cells {
        for i in 0..cells {
            faces.extend(cell(&idx, i, j));
        }
    }
    let mesh = PolyMesh::try_new(positions, &faces)?;
    Ok(Sample { mesh, layout, centre: idx(n / 2, n / 2) })
}

/// The triangulated torus (every vertex of valence 6), drawn on the triangular lattice; or, if
/// not `closed`, the same triangulation of a flat open patch.
pub(super) fn tri_grid(closed: bool) -> Result<Sample> {
    grid(
        closed,
        |idx, i, j| {
            vec![
                vec![idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)],
                vec![idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)],
            ]
        },
        |di, dj| DVec2::new(di - dj / 2.0, dj * 3.0_f64.sqrt() / 2.0),
    )
}

/// The triangulated torus: every vertex has valence 6.
pub(super) fn tri_torus() -> Result<Sample> {
    tri_grid(true)
}

/// The quad torus (every vertex of valence 4), drawn on the square lattice.
pub(super) fn quad_torus() -> Result<Sample> {
    grid(
        true,
        |idx, i, j| vec![vec![idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]],
        DVec2::new,
    )
}

/// A closed mesh with a vertex of valence `n` (returned) whose faces are triangles with corners
/// of valence 6 (`quads` false: the bipyramid over an n-gon after one Loop step, the vertex its
/// apex) or quads (`quads` true: the prism over an n-gon after one Catmull-Clark step, the
/// vertex the face point of a cap).
pub(super) fn cone(n: u32, quads: bool) -> Result<(PolyMesh, u32)> {
    let ring = |k: u32| {
        let (s, c) = (2.0 * PI * f64::from(k) / f64::from(n)).sin_cos();
        DVec3::new(c, s, 0.0)
    };
    if quads {
        let mut positions: Vec<DVec3> = (0..n).map(ring).collect();
        positions.extend((0..n).map(|k| ring(k) + DVec3::Z));
        let mut faces: Vec<Vec<u32>> = vec![(0..n).rev().collect(), (n..2 * n).collect()];
        for k in 0..n {
            let l = (k + 1) % n;
            faces.push(vec![k, l, n + l, n + k]);
        }
        let mesh = Scheme::CatmullClark.step(&PolyMesh::try_new(positions, &faces)?)?;
        let v = (2 * n as usize..mesh.n_vertices())
            .find(|&v| {
                mesh.valence(v) == n as usize
                    && mesh.faces().filter(|f| f.contains(&(v as u32))).all(|f| f.len() == 4)
            })
            .context("the refined prism has no vertex of valence n")?;
        Ok((mesh, u32::try_from(v)?))
    } else {
        let mut positions = vec![DVec3::Z, -DVec3::Z];
        positions.extend((0..n).map(ring));
        let mut faces = Vec::new();
        for k in 0..n {
            let l = (k + 1) % n;
            faces.push([2 + k, 2 + l, 0]);
            faces.push([2 + l, 2 + k, 1]);
        }
        let mesh = LOOP.step(&PolyMesh::try_new(positions, &faces)?)?;
        let ring_ok = mesh.neighbors(0).iter().all(|&r| mesh.valence(r as usize) == 6);
        ensure!(
            mesh.valence(0) == n as usize && ring_ok,
            "the refined bipyramid is not as expected"
        );
        Ok((mesh, 0))
    }
}

/// The undirected edges of `faces`, sorted.
pub(super) fn edges<'a>(faces: impl Iterator<Item = &'a [u32]>) -> BTreeSet<[u32; 2]> {
    let mut set = BTreeSet::new();
    for f in faces {
        for (i, &a) in f.iter().enumerate() {
            let b = f[(i + 1) % f.len()];
            set.insert([a.min(b), a.max(b)]);
        }
    }
    set
}
