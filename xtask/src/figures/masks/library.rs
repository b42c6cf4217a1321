// SPDX-License-Identifier: MIT
//! Reading the weights off the library: one step per old vertex gives the subdivision
//! matrix ([`Step`]), from which a mask is checked against its formula ([`mask`]).

use std::f64::consts::PI;

use anyhow::{Result, bail, ensure};
use glam::{DVec2, DVec3};
use hi_mesh::subdivision::{PolyMesh, Scheme};

use super::TOL;

/// One step of a scheme on a mesh and its subdivision matrix.
#[derive(Clone, Debug)]
pub(super) struct Step {
    /// The number of old vertices.
    pub(super) n_old: usize,
    /// The refined mesh of the unperturbed step.
    pub(super) refined: PolyMesh,
    /// `rows[i][j]`: the weight of old vertex j in new vertex i.
    pub(super) rows: Vec<Vec<f64>>,
}

impl Step {
    /// Applies `scheme` once to `mesh` and once more per old vertex j, with x = 1 at j and
    /// x = 0 elsewhere, reading the weights of j off the new x coordinates.
    pub(super) fn new(scheme: Scheme, mesh: &PolyMesh) -> Result<Self> {
        let refined = scheme.step(mesh)?;
        let faces: Vec<Vec<u32>> = mesh.faces().map(<[u32]>::to_vec).collect();
        let n_old = mesh.n_vertices();
        let mut rows = vec![vec![0.0; n_old]; refined.n_vertices()];
        for j in 0..n_old {
            let positions = mesh
                .positions()
                .iter()
                .enumerate()
                .map(|(i, p)| DVec3::new(if i == j { 1.0 } else { 0.0 }, p.y, p.z))
                .collect();
            let impulse = scheme.step(&PolyMesh::try_new(positions, &faces)?)?;
            ensure!(
                impulse.n_vertices() == refined.n_vertices() && impulse.faces().eq(refined.faces()),
                "{}: the refined connectivity depends on the positions",
                scheme.name()
            );
            for (row, p) in rows.iter_mut().zip(impulse.positions()) {
                row[j] = p.x;
            }
        }
        Ok(Self { n_old, refined, rows })
    }

    /// The new vertex joined by an edge to every old vertex of `olds` (an edge point, a √3 face
    /// point).
    pub(super) fn joined_to(&self, olds: &[u32]) -> Result<usize> {
        let found: Vec<usize> = (self.n_old..self.refined.n_vertices())
            .filter(|&w| {
                let ring = self.refined.neighbors(w);
                olds.iter().all(|o| ring.contains(o))
            })
            .collect();
        match found[..] {
            [w] => Ok(w),
            _ => bail!("{} new vertices are joined to {olds:?}", found.len()),
        }
    }

    /// The new vertex that shares a refined face with every old vertex of `corners` (the
    /// Catmull-Clark face point).
    pub(super) fn in_faces_with(&self, corners: &[u32]) -> Result<usize> {
        let found: Vec<usize> = (self.n_old..self.refined.n_vertices())
            .filter(|&w| {
                corners
                    .iter()
                    .all(|c| self.refined.faces().any(|f| f.contains(c) && f.contains(&(w as u32))))
            })
            .collect();
        match found[..] {
            [w] => Ok(w),
            _ => bail!("{} new vertices share faces with {corners:?}", found.len()),
        }
    }

    /// The new position of old vertex `v` (it keeps its index), checked to keep its valence.
    pub(super) fn vertex_point(&self, mesh: &PolyMesh, v: u32) -> Result<usize> {
        let v = v as usize;
        ensure!(
            self.refined.valence(v) == mesh.valence(v),
            "vertex {v} changed its valence: it is not the vertex point"
        );
        Ok(v)
    }
}

/// A mask ready to draw: the old vertices of its stencil, where they are drawn and their
/// weights as read off the library, the mesh edges between them and the new point.
#[derive(Clone, Debug)]
pub(super) struct Mask {
    /// Drawing positions of the stencil's vertices.
    pub(super) at: Vec<DVec2>,
    /// Their weights, read off the library.
    pub(super) weights: Vec<f64>,
    /// Mesh edges between stencil vertices.
    pub(super) edges: Vec<[DVec2; 2]>,
    /// Where the new point is drawn.
    pub(super) new_point: DVec2,
}

/// The mask of new vertex `new` of `step`: checks every old vertex's weight against
/// `expected` (stencil vertex, drawing position, formula weight; vertices not listed must weigh
/// 0) and keeps the listed vertices for drawing.
pub(super) fn mask(
    step: &Step,
    mesh: &PolyMesh,
    new: usize,
    expected: &[(u32, DVec2, f64)],
    new_point: DVec2,
    what: &str,
) -> Result<Mask> {
    let row = &step.rows[new];
    for (j, &got) in row.iter().enumerate() {
        let listed: Vec<f64> = expected.iter().filter(|e| e.0 as usize == j).map(|e| e.2).collect();
        ensure!(listed.len() <= 1, "{what}: vertex {j} is listed twice");
        let want = listed.first().copied().unwrap_or(0.0);
        ensure!(
            (got - want).abs() <= TOL,
            "{what}: old vertex {j} weighs {got} in the library, {want} by the formula"
        );
    }
    let mut edges = Vec::new();
    for (a, pa, _) in expected {
        let ring = mesh.neighbors(*a as usize);
        for (b, pb, _) in expected {
            if a < b && ring.contains(b) {
                edges.push([*pa, *pb]);
            }
        }
    }
    Ok(Mask {
        at: expected.iter().map(|e| e.1).collect(),
        weights: expected.iter().map(|e| row[e.0 as usize]).collect(),
        edges,
        new_point,
    })
}

/// The neighbours of `v` (counter-clockwise) on the unit circle, the first at angle 0.
pub(super) fn ring_layout(mesh: &PolyMesh, v: u32) -> Vec<(u32, DVec2)> {
    let ring = mesh.neighbors(v as usize);
    let n = ring.len() as f64;
    ring.iter()
        .enumerate()
        .map(|(i, &r)| {
            let (s, c) = (2.0 * PI * i as f64 / n).sin_cos();
            (r, DVec2::new(c, s))
        })
        .collect()
}
