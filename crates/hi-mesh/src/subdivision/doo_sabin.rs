// SPDX-License-Identifier: MIT
//! Doo-Sabin subdivision of closed polygon meshes (D. Doo, M. Sabin, *Behaviour of recursive
//! division surfaces near extraordinary points*, CAD 10(6), 1978; Hardy 2005, §4.5).
//!
//! Every corner of every face gives a new vertex; for corner i of a k-gon with vertices
//! v₀ … v_{k−1}, it is Σⱼ αᵢⱼ·vⱼ with αᵢᵢ = (k + 5)/(4k) and
//! αᵢⱼ = (3 + 2cos(2π(i − j)/k))/(4k) for j ≠ i (for a quad: 9/16, 3/16, 1/16, 3/16). The new
//! faces are one per old face (its corner vertices), one quad per old edge and one n-gon per
//! old vertex of valence n.

use std::f64::consts::PI;

use glam::DVec3;

use super::PolyMesh;
use crate::Error;

/// One step of Doo-Sabin subdivision: one vertex per face corner (in corner order),
/// F + E + V faces (face-faces first, then edge-faces, then vertex-faces).
///
/// # Errors
///
/// [`Error::OpenMesh`] for a mesh with boundary (no boundary rule is implemented);
/// [`Error::UnsupportedVertex`] for a vertex of valence 2.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_mesh::subdivision::{PolyMesh, doo_sabin_step};
///
/// let once = doo_sabin_step(&PolyMesh::cube())?;
/// assert_eq!((once.n_vertices(), once.n_faces()), (24, 26));
/// // Near corner (0,0,0) on the face z = 0: 3/16·(1,0,0) + 1/16·(1,1,0) + 3/16·(0,1,0).
/// assert!(once.positions().iter().any(|p| (*p - DVec3::new(0.25, 0.25, 0.0)).length() < 1e-15));
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn doo_sabin_step(mesh: &PolyMesh) -> Result<PolyMesh, Error> {
    mesh.require_closed("Doo-Sabin subdivision")?;
    if let Some(vertex) =
        (0..mesh.n_vertices()).find(|&v| matches!(mesh.fan(v as u32).count(), 1 | 2))
    {
        return Err(Error::UnsupportedVertex {
            vertex,
            reason: "Doo-Sabin needs valence 3 or more (a vertex face would have two sides)",
        });
    }
    let p = mesh.positions();
    let n_he = mesh.n_halfedges();
    let mut positions = Vec::with_capacity(n_he);
    let mut weights: Vec<Vec<f64>> = Vec::new();
    for face in mesh.faces() {
        let k = face.len();
        if weights.len() <= k {
            weights.resize(k + 1, Vec::new());
        }
        if weights[k].is_empty() {
            let kf = k as f64;
            weights[k] = (0..k)
                .map(|d| {
                    if d == 0 {
                        (kf + 5.0) / (4.0 * kf)
                    } else {
                        (3.0 + 2.0 * (2.0 * PI * d as f64 / kf).cos()) / (4.0 * kf)
                    }
                })
                .collect();
        }
        let w = &weights[k];
        for i in 0..k {
            let mut q = DVec3::ZERO;
            for (j, &vj) in face.iter().enumerate() {
                q += w[(i + k - j) % k] * p[vj as usize];
            }
            positions.push(q);
        }
    }
    let mut corners: Vec<u32> = Vec::with_capacity(3 * n_he);
    let mut face_start: Vec<u32> =
        Vec::with_capacity(mesh.n_faces() + mesh.n_edges() + mesh.n_vertices() + 1);
    face_start.push(0);
    // Face-faces: the corners of each face, in order.
    for h in 0..n_he as u32 {
        corners.push(h);
        if mesh.next(h) == mesh.face_he(mesh.he_face(h) as usize) {
            face_start.push(corners.len() as u32);
        }
    }
    // Edge-faces: h = a → b in f, t = b → a in g: (f, b), (f, a), (g, a), (g, b).
    for h in 0..n_he as u32 {
        let t = mesh.twin(h);
        if t < h {
            continue;
        }
        corners.extend_from_slice(&[mesh.next(h), h, mesh.next(t), t]);
        face_start.push(corners.len() as u32);
    }
    // Vertex-faces: the corners at v, counter-clockwise.
    for v in 0..mesh.n_vertices() as u32 {
        let before = corners.len();
        corners.extend(mesh.fan(v));
        if corners.len() > before {
            face_start.push(corners.len() as u32);
        }
    }
    PolyMesh::from_parts(positions, face_start, corners)
}
