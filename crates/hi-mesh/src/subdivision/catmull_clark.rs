// SPDX-License-Identifier: MIT
//! Catmull-Clark subdivision of arbitrary polygon meshes (E. Catmull, J. Clark, *Recursively
//! generated B-spline surfaces on arbitrary topological meshes*, CAD 10(6), 1978; Hardy 2005,
//! §4.5), with crease boundary rules, and its limit positions and normals.
//!
//! Each k-gon becomes k quads. The face vertex is the centroid f of the face. The vertex of an
//! interior edge ab is (a + b + f₁ + f₂)/4, of a boundary edge the midpoint (a + b)/2. An old
//! interior vertex v of valence n moves to (Q + 2R + (n − 3)·v)/n, Q the mean of the
//! centroids of its faces, R the mean of the midpoints of its edges; an old boundary vertex to
//! 1/8·(v₋ + v₊) + 3/4·v (the cubic B-spline rule along the boundary).

use std::f64::consts::PI;

use glam::DVec3;

use super::PolyMesh;
use super::loop_scheme::LimitPoint;
use super::poly_mesh::{NONE, Rings};
use crate::Error;

/// One step of Catmull-Clark subdivision: V + E + F vertices (old vertices, then one per edge,
/// then one per face), Σ kᶠ quads (k quads per k-gon).
///
/// # Errors
///
/// None at present for a valid [`PolyMesh`] (every polygon and boundary is handled); the
/// `Result` is kept for the uniform scheme signature and for [`Error::TooLarge`].
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_mesh::subdivision::{PolyMesh, catmull_clark_step};
///
/// let cube = PolyMesh::cube();
/// let once = catmull_clark_step(&cube)?;
/// assert_eq!((once.n_vertices(), once.n_faces()), (26, 24));
/// // Corner (0,0,0), valence 3: (Q + 2R)/3 with Q = (1/3, 1/3, 1/3), R = (1/6, 1/6, 1/6).
/// assert!((once.positions()[0] - DVec3::splat(2.0 / 9.0)).length() < 1e-15);
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn catmull_clark_step(mesh: &PolyMesh) -> Result<PolyMesh, Error> {
    let p = mesh.positions();
    let (nv, ne, nf) = (mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
    let n_he = mesh.n_halfedges();
    let centroids: Vec<DVec3> = mesh
        .faces()
        .map(|f| f.iter().map(|&k| p[k as usize]).sum::<DVec3>() / f.len() as f64)
        .collect();
    let mut positions = vec![DVec3::ZERO; nv + ne + nf];
    // Per old vertex: the sums of its faces' centroids and of its neighbours (over its
    // outgoing half-edges) and their number.
    let mut q = vec![DVec3::ZERO; nv];
    let mut r = vec![DVec3::ZERO; nv];
    let mut n = vec![0_u32; nv];
    // Face f, corner h (vertex v): the quad v, e(h), f, e(prev h).
    let mut corners = Vec::with_capacity(4 * n_he);
    // Quad h is v → e(h) → f → e(prev h) → v: its first side is the first half of h, whose
    // twin is the second half of twin(h) (the last side of the quad of next(twin h)); its
    // inner sides pair with those of the quads of next(h) and prev(h).
    let mut twin = vec![NONE; 4 * n_he];
    let (nv32, face0) = (nv as u32, (nv + ne) as u32);
    for (f, &centroid) in centroids.iter().enumerate() {
        let (start, end) = mesh.face_range(f);
        for h in start..end {
            let next = if h + 1 == end { start } else { h + 1 };
            let prev = if h == start { end - 1 } else { h - 1 };
            let (a, b) = (mesh.from(h), mesh.from(next));
            q[a as usize] += centroid;
            r[a as usize] += p[b as usize];
            n[a as usize] += 1;
            let t = mesh.twin(h);
            if t == NONE || h < t {
                let (pa, pb) = (p[a as usize], p[b as usize]);
                positions[nv + mesh.he_edge(h) as usize] = if t == NONE {
                    0.5 * (pa + pb)
                } else {
                    0.25 * (pa + pb + centroid + centroids[mesh.he_face(t) as usize])
                };
            }
            corners.extend_from_slice(&[
                a,
                nv32 + mesh.he_edge(h),
                face0 + f as u32,
                nv32 + mesh.he_edge(prev),
            ]);
            let k = 4 * h as usize;
            if t != NONE {
                twin[k] = 4 * mesh.next(t) + 3;
            }
            let t = mesh.twin(prev);
            if t != NONE {
                twin[k + 3] = 4 * t;
            }
            twin[k + 1] = 4 * next + 2;
            twin[k + 2] = 4 * prev + 1;
        }
    }
    let mut ring = Vec::new();
    for v in 0..nv {
        let pv = p[v];
        positions[v] = if n[v] == 0 {
            pv
        } else if mesh.is_boundary_vertex(v) {
            mesh.ring_into(v as u32, &mut ring);
            // On the boundary: the cubic B-spline rule with the two boundary neighbours.
            0.75 * pv + 0.125 * (p[ring[0] as usize] + p[ring[ring.len() - 1] as usize])
        } else {
            let nf64 = f64::from(n[v]);
            let q = q[v] / nf64;
            let r = 0.5 * (pv + r[v] / nf64);
            (q + 2.0 * r + (nf64 - 3.0) * pv) / nf64
        };
    }
    positions[nv + ne..].copy_from_slice(&centroids);
    let face_start = (0..=n_he as u32).map(|f| 4 * f).collect();
    PolyMesh::from_twins(positions, face_start, corners, twin)
}

/// Limit positions and normals of the vertices of a quad mesh under Catmull-Clark
/// subdivision (apply [`catmull_clark_step`] once first for other polygons).
///
/// Interior vertex v of valence n with edge neighbours eᵢ and diagonal (face) neighbours fᵢ,
/// counter-clockwise, fᵢ between eᵢ and the next edge neighbour (Halstead, Kass and `DeRose` 1993): position
/// (n²·v + 4·Σ eᵢ + Σ fᵢ)/(n(n + 5)); tangents t₁ = Σ Aₙ·cos(2πi/n)·eᵢ + (cos(2πi/n) +
/// cos(2π(i+1)/n))·fᵢ and t₂ likewise with sines, Aₙ = 1 + cos(2π/n) + cos(π/n)·√(2(9 +
/// cos(2π/n))); normal t₁ × t₂ normalised. Boundary vertex: (v₋ + 4v + v₊)/6 along the
/// boundary, no normal. A vertex without faces stays put.
///
/// # Errors
///
/// [`Error::WrongPrimitive`] naming the first face that is not a quad.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_mesh::subdivision::{PolyMesh, catmull_clark_limit, catmull_clark_step};
///
/// let cube = catmull_clark_step(&PolyMesh::cube())?;
/// let limit = catmull_clark_limit(&cube)?;
/// // By symmetry the limit of the corner lies on the diagonal, its normal along −(1, 1, 1).
/// let c = limit[0];
/// assert!((c.position.x - c.position.y).abs() < 1e-15);
/// assert!((c.normal.unwrap() + DVec3::ONE.normalize()).length() < 1e-12);
/// # Ok::<(), hi_mesh::Error>(())
/// ```
pub fn catmull_clark_limit(mesh: &PolyMesh) -> Result<Vec<LimitPoint>, Error> {
    if let Some(face) = (0..mesh.n_faces()).find(|&f| mesh.face_len(f) != 4) {
        return Err(Error::WrongPrimitive {
            scheme: "the Catmull-Clark limit",
            face,
            n_sides: mesh.face_len(face),
            expected: "a quad mesh",
        });
    }
    let p = mesh.positions();
    let rings = Rings::new(mesh);
    let mut res = Vec::with_capacity(mesh.n_vertices());
    for v in 0..mesh.n_vertices() as u32 {
        let pv = p[v as usize];
        let ring = rings.ring(v);
        if ring.is_empty() {
            res.push(LimitPoint { position: pv, normal: None });
            continue;
        }
        if rings.is_boundary(v) {
            let (a, b) = (p[ring[0] as usize], p[ring[ring.len() - 1] as usize]);
            res.push(LimitPoint { position: (a + 4.0 * pv + b) / 6.0, normal: None });
            continue;
        }
        let n = ring.len();
        let nf = n as f64;
        let mut sum_e = DVec3::ZERO;
        let mut sum_f = DVec3::ZERO;
        let mut t1 = DVec3::ZERO;
        let mut t2 = DVec3::ZERO;
        let a_n = 1.0
            + (2.0 * PI / nf).cos()
            + (PI / nf).cos() * (2.0 * (9.0 + (2.0 * PI / nf).cos())).sqrt();
        for (i, h) in mesh.fan(v).enumerate() {
            let e = p[mesh.to(h) as usize];
            let f = p[mesh.to(mesh.next(h)) as usize];
            sum_e += e;
            sum_f += f;
            let (s0, c0) = (2.0 * PI * i as f64 / nf).sin_cos();
            let (s1, c1) = (2.0 * PI * (i + 1) as f64 / nf).sin_cos();
            t1 += a_n * c0 * e + (c0 + c1) * f;
            t2 += a_n * s0 * e + (s0 + s1) * f;
        }
        res.push(LimitPoint {
            position: (nf * nf * pv + 4.0 * sum_e + sum_f) / (nf * (nf + 5.0)),
            normal: t1.cross(t2).try_normalize(),
        });
    }
    Ok(res)
}
