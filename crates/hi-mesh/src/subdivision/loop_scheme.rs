// SPDX-License-Identifier: MIT
//! Loop subdivision of triangle meshes (C. Loop, *Smooth subdivision surfaces based on
//! triangles*, M.Sc. thesis, Utah 1987; Hardy 2005, §4.5), with the boundary rules of Hoppe
//! et al. 1994, and its limit positions and normals.
//!
//! Each triangle is split into four. A new edge vertex is 3/8·(a + b) + 1/8·(c + d) for an
//! interior edge ab with opposite vertices c, d, and the midpoint of a boundary edge. An old
//! interior vertex v of valence n moves to (1 − nβ)·v + β·Σ vᵢ; an old boundary vertex to
//! 1/8·(v₋ + v₊) + 3/4·v with its two boundary neighbours v₋, v₊.

use glam::DVec3;

use super::PolyMesh;
use super::poly_mesh::{NONE, Rings};
use crate::Error;

/// The weight β of the Loop vertex rule, for valence n.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum LoopWeights {
    /// Loop's original β = (1/n)·(5/8 − (3/8 + 1/4·cos(2π/n))²), as in CGAL, `OpenMesh`, `trimesh`
    /// and `MeshLab`.
    #[default]
    Loop,
    /// Warren's simplification (J. Warren, *Subdivision methods for geometric design*, 1995):
    /// β = 3/(8n) for n > 3, β = 3/16 for n = 3.
    Warren,
}

impl LoopWeights {
    /// β for valence `n` (≥ 1).
    #[must_use]
    pub fn beta(self, n: usize) -> f64 {
        let nf = n as f64;
        match self {
            LoopWeights::Loop => {
                let c = 0.375 + 0.25 * (2.0 * std::f64::consts::PI / nf).cos();
                (0.625 - c * c) / nf
            }
            LoopWeights::Warren if n == 3 => 3.0 / 16.0,
            LoopWeights::Warren => 3.0 / (8.0 * nf),
        }
    }
}

/// One step of Loop subdivision (see the module notes): V + E vertices, 4F triangles. Old
/// vertices keep their indices; the vertex of edge e is V + e in the order of the edges.
///
/// # Errors
///
/// [`Error::WrongPrimitive`] if a face is not a triangle.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_mesh::subdivision::{LoopWeights, PolyMesh, loop_step};
///
/// let octa = PolyMesh::octahedron();
/// let once = loop_step(&octa, LoopWeights::Loop)?;
/// assert_eq!((once.n_vertices(), once.n_faces()), (18, 32));
/// // (1, 0, 0) has valence 4, β = 31/256: it moves to x = 1 − 4β = 0.515625.
/// assert!((once.positions()[0] - DVec3::new(0.515625, 0.0, 0.0)).length() < 1e-15);
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn loop_step(mesh: &PolyMesh, weights: LoopWeights) -> Result<PolyMesh, Error> {
    mesh.require_triangles("Loop subdivision")?;
    let p = mesh.positions();
    let nv = mesh.n_vertices();
    let (sums, valences) = mesh.neighbour_sums();
    let mut positions = Vec::with_capacity(nv + mesh.n_edges());
    let mut ring = Vec::new();
    // β of the common valences, computed once.
    let betas: Vec<f64> = (0..32).map(|n| if n == 0 { 0.0 } else { weights.beta(n) }).collect();
    for v in 0..nv {
        let pv = p[v];
        positions.push(if valences[v] == 0 {
            pv
        } else if mesh.is_boundary_vertex(v) {
            mesh.ring_into(v as u32, &mut ring);
            let (a, b) = (p[ring[0] as usize], p[ring[ring.len() - 1] as usize]);
            0.75 * pv + 0.125 * (a + b)
        } else {
            let n = valences[v] as usize;
            let beta = betas.get(n).copied().unwrap_or_else(|| weights.beta(n));
            (1.0 - n as f64 * beta) * pv + beta * sums[v]
        });
    }
    positions.resize(nv + mesh.n_edges(), DVec3::ZERO);
    // Triangles only: half-edge h = 3f + i, the next one 3f + (i + 1) mod 3.
    let next = |h: u32| if h % 3 == 2 { h - 2 } else { h + 1 };
    for h in 0..mesh.n_halfedges() as u32 {
        let t = mesh.twin(h);
        if t != NONE && t < h {
            continue;
        }
        let (a, b) = (p[mesh.from(h) as usize], p[mesh.from(next(h)) as usize]);
        let e = nv + mesh.he_edge(h) as usize;
        positions[e] = if t == NONE {
            0.5 * (a + b)
        } else {
            let c = p[mesh.from(next(next(h))) as usize];
            let d = p[mesh.from(next(next(t))) as usize];
            0.375 * (a + b) + 0.125 * (c + d)
        };
    }
    split_1_to_4(mesh, positions)
}

/// The 1 → 4 split of every triangle, with edge vertices V + e; shared by Loop and the
/// butterfly scheme.
pub(crate) fn split_1_to_4(mesh: &PolyMesh, positions: Vec<DVec3>) -> Result<PolyMesh, Error> {
    let nv = mesh.n_vertices() as u32;
    let nf = mesh.n_faces();
    let mut corners = Vec::with_capacity(12 * nf);
    for f in 0..nf {
        let h0 = mesh.face_he(f);
        let (h1, h2) = (mesh.next(h0), mesh.prev(h0));
        let [a, b, c] = [h0, h1, h2].map(|h| mesh.from(h));
        let [ab, bc, ca] = [h0, h1, h2].map(|h| nv + mesh.he_edge(h));
        corners.extend_from_slice(&[a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca]);
    }
    // Twins: parent half-edge h = 3f + i (a → b) splits into a → ab, corner 3i of the child
    // faces of f, and ab → b, corner 3(i + 1 mod 3) + 2; each half's twin is the other half
    // of twin(h). The middle triangle's edges pair with the corner triangles' inner edges.
    let first = |h: u32| 12 * (h / 3) + 3 * (h % 3);
    let second = |h: u32| 12 * (h / 3) + 3 * ((h % 3 + 1) % 3) + 2;
    let mut twin = vec![NONE; 12 * nf];
    for h in 0..3 * nf as u32 {
        let t = mesh.twin(h);
        if t != NONE {
            twin[first(h) as usize] = second(t);
            twin[second(h) as usize] = first(t);
        }
    }
    for f in 0..nf {
        let base = 12 * f as u32;
        for (x, y) in [(9, 4), (10, 7), (11, 1)] {
            twin[(base + x) as usize] = base + y;
            twin[(base + y) as usize] = base + x;
        }
    }
    let face_start = (0..=4 * nf as u32).map(|f| 3 * f).collect();
    PolyMesh::from_twins(positions, face_start, corners, twin)
}

/// Where a vertex of a Loop or Catmull-Clark surface ends up after infinitely many steps, and
/// the surface normal there.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LimitPoint {
    /// The limit position.
    pub position: DVec3,
    /// The unit limit normal, from the two tangent masks; `None` on the boundary (only the
    /// boundary curve's tangent is defined by its cubic B-spline) and where the tangents are
    /// parallel.
    pub normal: Option<DVec3>,
}

/// Limit positions and normals of the vertices of a triangle mesh under Loop subdivision with
/// `weights`.
///
/// Interior vertex of valence n (Loop 1987; Hoppe et al. 1994): position
/// (1 − nχ)·v + χ·Σ vᵢ with χ = 1/(3/(8β) + n); tangents t₁ = Σ cos(2πi/n)·vᵢ and
/// t₂ = Σ sin(2πi/n)·vᵢ (neighbours counter-clockwise), normal t₁ × t₂ normalised. A regular
/// vertex (n = 6, β = 1/16) goes to v/2 + Σ vᵢ/12. Boundary vertex: the cubic B-spline limit
/// (v₋ + 4v + v₊)/6 of the boundary curve, no normal. A vertex without faces stays put.
///
/// # Errors
///
/// [`Error::WrongPrimitive`] if a face is not a triangle.
///
/// # Examples
///
/// ```
/// use hi_mesh::subdivision::{LoopWeights, PolyMesh, loop_limit};
///
/// let octa = PolyMesh::octahedron();
/// let limit = loop_limit(&octa, LoopWeights::Loop)?;
/// // Symmetry: the limit of (1, 0, 0) lies on the x axis, with normal +x.
/// let l = limit[0];
/// assert!(l.position.y.abs() < 1e-15 && l.position.z.abs() < 1e-15);
/// assert!((l.normal.unwrap() - glam::DVec3::X).length() < 1e-12);
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn loop_limit(mesh: &PolyMesh, weights: LoopWeights) -> Result<Vec<LimitPoint>, Error> {
    mesh.require_triangles("Loop limit")?;
    let p = mesh.positions();
    let rings = Rings::new(mesh);
    let mut res = Vec::with_capacity(mesh.n_vertices());
    for v in 0..mesh.n_vertices() as u32 {
        let ring = rings.ring(v);
        let pv = p[v as usize];
        let point = if ring.is_empty() {
            LimitPoint { position: pv, normal: None }
        } else if rings.is_boundary(v) {
            let (a, b) = (p[ring[0] as usize], p[ring[ring.len() - 1] as usize]);
            LimitPoint { position: (a + 4.0 * pv + b) / 6.0, normal: None }
        } else {
            let n = ring.len();
            let chi = 1.0 / (3.0 / (8.0 * weights.beta(n)) + n as f64);
            let sum: DVec3 = ring.iter().map(|&k| p[k as usize]).sum();
            let (t1, t2) = tangent_masks(ring.iter().map(|&k| p[k as usize]), n);
            LimitPoint {
                position: (1.0 - n as f64 * chi) * pv + chi * sum,
                normal: t1.cross(t2).try_normalize(),
            }
        };
        res.push(point);
    }
    Ok(res)
}

/// Σ cos(2πi/n)·pᵢ and Σ sin(2πi/n)·pᵢ.
fn tangent_masks(points: impl Iterator<Item = DVec3>, n: usize) -> (DVec3, DVec3) {
    let mut t1 = DVec3::ZERO;
    let mut t2 = DVec3::ZERO;
    for (i, q) in points.enumerate() {
        let (s, c) = (2.0 * std::f64::consts::PI * i as f64 / n as f64).sin_cos();
        t1 += c * q;
        t2 += s * q;
    }
    (t1, t2)
}
