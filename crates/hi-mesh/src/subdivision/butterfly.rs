// SPDX-License-Identifier: MIT
//! The modified butterfly scheme (D. Zorin, P. Schröder, W. Sweldens, *Interpolating
//! subdivision for meshes with arbitrary topology*, SIGGRAPH 1996; Hardy 2005, §4.5): an
//! interpolating 1 → 4 split of closed triangle meshes.
//!
//! Old vertices stay. The vertex of edge ab is, when a and b both have valence 6, the
//! 10-point stencil (1/2 − w)·(a + b) + (1/8 + 2w)·(c + d) − (1/16 + w)·(e₁ + e₂ + e₃ + e₄)
//! plus w·(f₁ + f₂), where c, d are opposite ab, eᵢ are the tips of the four triangles beyond,
//! and f₁, f₂ are the neighbours of a and b straight across from b and a (w = 0 gives the
//! 8-point butterfly of Dyn, Levin and Gregory, which the peers use). When one end, say a,
//! has valence K ≠ 6, the vertex is 3/4·a + Σⱼ sⱼ·aⱼ over a's neighbours a₀ = b, a₁, … in
//! order, with s = (5/12, −1/12, −1/12) for K = 3, (3/8, 0, −1/8, 0) for K = 4, and
//! sⱼ = (1/4 + cos(2πj/K) + 1/2·cos(4πj/K))/K for K ≥ 5; when both ends are extraordinary,
//! the two such points are averaged.

use std::f64::consts::PI;

use glam::DVec3;

use super::PolyMesh;
use super::loop_scheme::split_1_to_4;
use super::poly_mesh::Rings;
use crate::Error;

/// One step of the modified butterfly scheme with tension w = 0 (see the module notes): V + E
/// vertices (the old ones first, unchanged), 4F triangles.
///
/// # Errors
///
/// [`Error::WrongPrimitive`] for a face that is not a triangle; [`Error::OpenMesh`]
/// for a mesh with boundary (Zorin's boundary rules are not implemented).
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_mesh::subdivision::{PolyMesh, butterfly_step};
///
/// let octa = PolyMesh::octahedron();
/// let once = butterfly_step(&octa)?;
/// assert_eq!(once.positions()[..6], octa.positions()[..]); // interpolating
/// // Edge (1,0,0)–(0,1,0): both ends have valence 4, the average of two K = 4 stencils.
/// assert!(once.positions().iter().any(|p| (*p - DVec3::new(0.625, 0.625, 0.0)).length() < 1e-15));
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn butterfly_step(mesh: &PolyMesh) -> Result<PolyMesh, Error> {
    butterfly_step_with_tension(mesh, 0.0)
}

/// One step of the modified butterfly scheme with tension `w` in the regular 10-point
/// stencil (Zorin et al. 1996, §4); see [`butterfly_step`].
///
/// # Errors
///
/// As [`butterfly_step`].
pub fn butterfly_step_with_tension(mesh: &PolyMesh, w: f64) -> Result<PolyMesh, Error> {
    mesh.require_triangles("the modified butterfly scheme")?;
    mesh.require_closed("the modified butterfly scheme")?;
    let p = mesh.positions();
    let nv = mesh.n_vertices();
    let rings = Rings::new(mesh);
    let mut positions = Vec::with_capacity(nv + mesh.n_edges());
    positions.extend_from_slice(p);
    positions.resize(nv + mesh.n_edges(), DVec3::ZERO);
    let mut weights_cache: Vec<Vec<f64>> = Vec::new();
    for h in 0..mesh.n_halfedges() as u32 {
        let t = mesh.twin(h);
        if t < h {
            continue;
        }
        let (a, b) = (mesh.from(h), mesh.to(h));
        let (ra, rb) = (rings.ring(a), rings.ring(b));
        let ia = ra.iter().position(|&k| k == b).unwrap_or(0);
        let ib = rb.iter().position(|&k| k == a).unwrap_or(0);
        let at = |r: &[u32], i0: usize, j: usize| p[r[(i0 + j) % r.len()] as usize];
        let q = match (ra.len(), rb.len()) {
            (6, 6) => {
                // a's ring from b: b, c, e, f₁, e, d; b's ring from a: a, d, e, f₂, e, c.
                (0.5 - w) * (p[a as usize] + p[b as usize])
                    + (0.125 + 2.0 * w) * (at(ra, ia, 1) + at(ra, ia, 5))
                    - (0.0625 + w) * (at(ra, ia, 2) + at(ra, ia, 4) + at(rb, ib, 2) + at(rb, ib, 4))
                    + w * (at(ra, ia, 3) + at(rb, ib, 3))
            }
            (ka, 6) => extraordinary(p, a, ra, ia, weights_for(&mut weights_cache, ka)),
            (6, kb) => extraordinary(p, b, rb, ib, weights_for(&mut weights_cache, kb)),
            (ka, kb) => {
                let qa = extraordinary(p, a, ra, ia, weights_for(&mut weights_cache, ka));
                let qb = extraordinary(p, b, rb, ib, weights_for(&mut weights_cache, kb));
                0.5 * (qa + qb)
            }
        };
        positions[nv + mesh.he_edge(h) as usize] = q;
    }
    split_1_to_4(mesh, positions)
}

/// 3/4·v + Σⱼ sⱼ·ring[(i0 + j) mod K].
fn extraordinary(p: &[DVec3], v: u32, ring: &[u32], i0: usize, s: &[f64]) -> DVec3 {
    let k = ring.len();
    let mut q = 0.75 * p[v as usize];
    for (j, &sj) in s.iter().enumerate() {
        q += sj * p[ring[(i0 + j) % k] as usize];
    }
    q
}

/// The weights sⱼ of Zorin et al. for valence `k`, cached by valence.
fn weights_for(cache: &mut Vec<Vec<f64>>, k: usize) -> &[f64] {
    if cache.len() <= k {
        cache.resize(k + 1, Vec::new());
    }
    if cache[k].is_empty() {
        cache[k] = butterfly_weights(k);
    }
    &cache[k]
}

/// The extraordinary-vertex weights s₀ … s_{K−1} of Zorin et al. 1996 (they sum to 1/4).
#[must_use]
pub(crate) fn butterfly_weights(k: usize) -> Vec<f64> {
    match k {
        3 => vec![5.0 / 12.0, -1.0 / 12.0, -1.0 / 12.0],
        4 => vec![0.375, 0.0, -0.125, 0.0],
        _ => (0..k)
            .map(|j| {
                let x = 2.0 * PI * j as f64 / k as f64;
                (0.25 + x.cos() + 0.5 * (2.0 * x).cos()) / k as f64
            })
            .collect(),
    }
}
