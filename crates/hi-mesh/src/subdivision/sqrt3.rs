// SPDX-License-Identifier: MIT
//! √3 subdivision of closed triangle meshes: Kobbelt's approximating scheme (L. Kobbelt,
//! *√3-subdivision*, SIGGRAPH 2000) and the interpolating scheme of Labsik and Greiner
//! (U. Labsik, G. Greiner, *Interpolatory √3-subdivision*, Eurographics 2000); Hardy 2005,
//! §4.5.
//!
//! Both insert one vertex per triangle, join it to the triangle's corners, and flip every old
//! edge, so each step triples the triangles and rotates the mesh by 30°; two steps are a
//! 1 → 9 refinement. Kobbelt's new vertex is the centroid, and an old vertex of valence n moves
//! to (1 − αₙ)·v + αₙ/n·Σ vᵢ with αₙ = (4 − 2cos(2π/n))/9. Labsik–Greiner keep old vertices,
//! and place the new one by a 12-point stencil when the three corners have valence 6, and
//! otherwise by averaging the stencils of the extraordinary corners (see
//! [`interpolating_sqrt3_step`]).

use std::f64::consts::PI;

use glam::DVec3;

use super::PolyMesh;
use super::poly_mesh::Rings;
use crate::Error;

/// One step of Kobbelt's √3 subdivision: V + F vertices (old ones first, then one per face in
/// face order), 3F triangles.
///
/// # Errors
///
/// [`Error::WrongPrimitive`] for a face that is not a triangle; [`Error::OpenMesh`]
/// for a mesh with boundary (Kobbelt's two-step boundary rule is not implemented).
///
/// # Examples
///
/// ```
/// use hi_mesh::subdivision::{PolyMesh, sqrt3_step};
///
/// let octa = PolyMesh::octahedron();
/// let once = sqrt3_step(&octa)?;
/// assert_eq!((once.n_vertices(), once.n_faces()), (14, 24));
/// // Valence 4: α = 4/9, and the neighbours of (1,0,0) sum to zero.
/// assert!((once.positions()[0].x - 5.0 / 9.0).abs() < 1e-15);
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn sqrt3_step(mesh: &PolyMesh) -> Result<PolyMesh, Error> {
    mesh.require_triangles("√3 subdivision")?;
    mesh.require_closed("√3 subdivision")?;
    let p = mesh.positions();
    // Closed: every vertex with faces is interior, its valence its outgoing half-edges.
    let (sums, valences) = mesh.neighbour_sums();
    let alpha = |n: u32| (4.0 - 2.0 * (2.0 * PI / f64::from(n)).cos()) / 9.0;
    let alphas: Vec<f64> = (0..32).map(|n| if n == 0 { 0.0 } else { alpha(n) }).collect();
    let mut positions = Vec::with_capacity(mesh.n_vertices() + mesh.n_faces());
    for (v, (&pv, &n)) in p.iter().zip(&valences).enumerate() {
        if n == 0 {
            positions.push(pv);
            continue;
        }
        let a = alphas.get(n as usize).copied().unwrap_or_else(|| alpha(n));
        positions.push((1.0 - a) * pv + a / f64::from(n) * sums[v]);
    }
    for f in mesh.faces() {
        positions.push(f.iter().map(|&k| p[k as usize]).sum::<DVec3>() / 3.0);
    }
    split_and_flip(mesh, positions)
}

/// One step of the interpolating √3 scheme of Labsik and Greiner: old vertices unchanged, a new
/// vertex per face, 3F triangles.
///
/// Regular face (all corners of valence 6): 32/81 for each corner, −1/81 for the tip of each
/// neighbouring triangle, −2/81 for the six other vertices of the corners' rings. Otherwise the
/// mean over the extraordinary corners v (valence K) of w·v + Σᵢ wᵢ·vᵢ, the ring v₀, v₁, …
/// running counter-clockwise from the corner before v in the face: K = 3: w = 8/9,
/// wᵢ = (4, −5, 4)/27; K = 4: w = 7/9, wᵢ = (2, −1, −1, 2)/9; K ≥ 5: with a = 2cos(π/K)/3,
/// w = 1 − a², wᵢ = (a² + 2a·cos(2πi/K + π/K) + 2a²·cos(4πi/K + 2π/K))/K.
///
/// # Errors
///
/// [`Error::WrongPrimitive`] for a face that is not a triangle; [`Error::OpenMesh`]
/// for a mesh with boundary.
///
/// # Examples
///
/// ```
/// use hi_mesh::subdivision::{PolyMesh, interpolating_sqrt3_step};
///
/// let octa = PolyMesh::octahedron();
/// let once = interpolating_sqrt3_step(&octa)?;
/// assert_eq!(once.positions()[..6], octa.positions()[..]);
/// // Face (1,0,0), (0,1,0), (0,0,1): three valence-4 stencils averaged, 13/27 each.
/// let m = once.positions()[6];
/// assert!((m - glam::DVec3::splat(13.0 / 27.0)).length() < 1e-15);
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn interpolating_sqrt3_step(mesh: &PolyMesh) -> Result<PolyMesh, Error> {
    mesh.require_triangles("interpolating √3 subdivision")?;
    mesh.require_closed("interpolating √3 subdivision")?;
    let p = mesh.positions();
    let rings = Rings::new(mesh);
    let mut positions = Vec::with_capacity(mesh.n_vertices() + mesh.n_faces());
    positions.extend_from_slice(p);
    let mut cache: Vec<Vec<f64>> = Vec::new();
    for face in mesh.faces() {
        // Each corner's ring, rotated to start at the corner before it in the face.
        let mut regular = true;
        let mut rotated: [(u32, usize); 3] = [(0, 0); 3];
        for i in 0..3 {
            let v = face[i];
            let before = face[(i + 2) % 3];
            let ring = rings.ring(v);
            let i0 = ring.iter().position(|&k| k == before).unwrap_or(0);
            rotated[i] = (v, i0);
            regular &= ring.len() == 6;
        }
        let q = if regular {
            let mut q = DVec3::ZERO;
            for &(v, i0) in &rotated {
                let ring = rings.ring(v);
                let at = |j: usize| p[ring[(i0 + j) % 6] as usize];
                q += 32.0 * p[v as usize] - at(1) - 2.0 * (at(2) + at(3));
            }
            q / 81.0
        } else {
            let mut q = DVec3::ZERO;
            let mut n_irregular = 0;
            for &(v, i0) in &rotated {
                let ring = rings.ring(v);
                let k = ring.len();
                if k == 6 {
                    continue;
                }
                n_irregular += 1;
                if cache.len() <= k {
                    cache.resize(k + 1, Vec::new());
                }
                if cache[k].is_empty() {
                    cache[k] = labsik_greiner_weights(k);
                }
                let w = &cache[k];
                q += w[k] * p[v as usize];
                for (j, wj) in w[..k].iter().enumerate() {
                    q += *wj * p[ring[(i0 + j) % k] as usize];
                }
            }
            q / f64::from(n_irregular)
        };
        positions.push(q);
    }
    split_and_flip(mesh, positions)
}

/// The Labsik–Greiner weights w₀ … w_{K−1} and, last, the weight of the centre (sum 1).
fn labsik_greiner_weights(k: usize) -> Vec<f64> {
    match k {
        3 => vec![4.0 / 27.0, -5.0 / 27.0, 4.0 / 27.0, 8.0 / 9.0],
        4 => vec![2.0 / 9.0, -1.0 / 9.0, -1.0 / 9.0, 2.0 / 9.0, 7.0 / 9.0],
        _ => {
            let kf = k as f64;
            let a = 2.0 * (PI / kf).cos() / 3.0;
            let mut w: Vec<f64> = (0..k)
                .map(|i| {
                    let x = 2.0 * PI * i as f64 / kf + PI / kf;
                    (a * a + 2.0 * a * x.cos() + 2.0 * a * a * (2.0 * x).cos()) / kf
                })
                .collect();
            w.push(1.0 - a * a);
            w
        }
    }
}

/// The 1 → 3 split with face vertices V + f, followed by flipping every old edge: one
/// triangle (a, mᵍ, mᶠ) per half-edge a → b of face f whose twin lies in face g.
fn split_and_flip(mesh: &PolyMesh, positions: Vec<DVec3>) -> Result<PolyMesh, Error> {
    let nv = mesh.n_vertices() as u32;
    let n_he = mesh.n_halfedges();
    let mut corners = Vec::with_capacity(3 * n_he);
    for h in 0..n_he as u32 {
        let g = mesh.he_face(mesh.twin(h));
        corners.extend_from_slice(&[mesh.from(h), nv + g, nv + mesh.he_face(h)]);
    }
    // Child face h is a → G → F (G, F the centres of the faces of twin(h) and h): its flipped
    // edge G → F pairs with that of twin(h), F → a with a → F of the child of
    // twin(prev h), and a → G with G → a of the child of next(twin h).
    let mut twin = vec![0_u32; 3 * n_he];
    for h in 0..n_he as u32 {
        let k = 3 * h as usize;
        twin[k] = 3 * mesh.next(mesh.twin(h)) + 2;
        twin[k + 1] = 3 * mesh.twin(h) + 1;
        twin[k + 2] = 3 * mesh.twin(mesh.prev(h));
    }
    let face_start = (0..=n_he as u32).map(|f| 3 * f).collect();
    PolyMesh::from_twins(positions, face_start, corners, twin)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labsik_greiner_weights_sum_to_one() {
        for k in 3..20 {
            let s: f64 = labsik_greiner_weights(k).iter().sum();
            assert!((s - 1.0).abs() < 1e-14, "K = {k}: {s}");
        }
    }
}
