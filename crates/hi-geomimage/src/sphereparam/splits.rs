// SPDX-License-Identifier: MIT
//! Undoing the collapses: the base tetrahedron on the sphere, and each vertex split placed in
//! the kernel of its ring (steps 2 and 3 of the module documentation of `sphereparam`).

use glam::DVec3;

use super::simplify::{Collapse, Hierarchy};
use crate::Error;

impl Hierarchy {
    /// Undoes the last collapse.
    pub(super) fn split(&mut self, c: Collapse) {
        let Collapse { v, u, removed, changed } = c;
        self.alive[v as usize] = true;
        let mut faces_v = Vec::with_capacity(8);
        for i in changed.0..changed.1 {
            let code = self.changed[i as usize];
            let (f, corner) = (code >> 2, (code & 3) as usize);
            self.faces[f as usize][corner] = v;
            self.update_face_geometry(f as usize);
            let list = &mut self.vertex_faces[u as usize];
            if let Some(k) = list.iter().position(|&g| g == f) {
                list.swap_remove(k);
            }
            faces_v.push(f);
        }
        for &f in &removed {
            if f == u32::MAX {
                continue;
            }
            self.face_alive[f as usize] = true;
            for &k in &self.faces[f as usize] {
                if k != v {
                    self.vertex_faces[k as usize].push(f);
                }
            }
            faces_v.push(f);
        }
        self.vertex_faces[v as usize] = faces_v;
    }
}

/// Whether v at position x has every triangle wound correctly.
fn valid_at(h: &Hierarchy, sphere: &[DVec3], v: u32, x: DVec3) -> bool {
    h.vertex_faces[v as usize].iter().all(|&f| {
        let t = h.faces[f as usize];
        let [a, b, c] = t.map(|k| if k == v { x } else { sphere[k as usize] });
        let n = (b - a).cross(c - a);
        n.dot(a + b + c) > 0.0 && n.length_squared() > 0.0
    })
}

/// The deepest point of the kernel of v's ring: the point on the sphere farthest (in the
/// sense of min m̂·x) inside all the great circles through v's ring edges, where m̂ is the
/// unit normal of the plane through the origin and ring edge (b, c), and the kernel is
/// {x : m̂·x > 0 for every edge}. At the optimum one, two or three of the constraints are
/// equally tight, so it is among x = m̂ᵢ, x ∝ m̂ᵢ + m̂ⱼ and the points equidistant from three
/// planes; `None` if none is inside (the kernel is empty or too thin for rounding).
fn kernel_centre(h: &Hierarchy, sphere: &[DVec3], v: u32) -> Option<DVec3> {
    let mut m: Vec<DVec3> = Vec::with_capacity(8);
    for &f in &h.vertex_faces[v as usize] {
        let t = h.faces[f as usize];
        let k = t.iter().position(|&w| w == v)?;
        let (b, c) = (sphere[t[(k + 1) % 3] as usize], sphere[t[(k + 2) % 3] as usize]);
        let n = b.cross(c).normalize_or_zero();
        if n == DVec3::ZERO {
            return None;
        }
        m.push(n);
    }
    let margin = |x: DVec3| m.iter().map(|n| n.dot(x)).fold(f64::INFINITY, f64::min);
    let mut best: Option<(f64, DVec3)> = None;
    let mut consider = |x: DVec3| {
        let x = x.normalize_or_zero();
        if x == DVec3::ZERO {
            return;
        }
        let t = margin(x);
        if t > 0.0 && best.is_none_or(|(b, _)| t > b) {
            best = Some((t, x));
        }
    };
    for i in 0..m.len() {
        consider(m[i]);
        for j in i + 1..m.len() {
            consider(m[i] + m[j]);
            for k in j + 1..m.len() {
                let x = (m[j] - m[i]).cross(m[k] - m[i]);
                consider(x);
                consider(-x);
            }
        }
    }
    let (_, x) = best?;
    valid_at(h, sphere, v, x).then_some(x)
}

/// Places v (just split off u) in the kernel of its ring.
pub(super) fn place(h: &Hierarchy, sphere: &[DVec3], v: u32, u: u32, fine: bool) -> Option<DVec3> {
    if fine {
        // Most rings of a fine level are nearly flat and convex: their centroid will do.
        let mut sum = DVec3::ZERO;
        for &f in &h.vertex_faces[v as usize] {
            let t = h.faces[f as usize];
            let k = t.iter().position(|&w| w == v).unwrap_or(0);
            sum += sphere[t[(k + 1) % 3] as usize];
        }
        let x = sum.normalize_or_zero();
        if x != DVec3::ZERO && valid_at(h, sphere, v, x) {
            return Some(x);
        }
    }
    if let Some(x) = kernel_centre(h, sphere, v) {
        return Some(x);
    }
    let pu = sphere[u as usize];
    let mut ring = Vec::new();
    for &f in &h.vertex_faces[v as usize] {
        for &k in &h.faces[f as usize] {
            if k != v && !ring.contains(&k) {
                ring.push(k);
            }
        }
    }
    // Into the sector of v's neighbours seen from u: the new triangles are (u, v, l) and
    // (u, r, v), so v must lie counter-clockwise from r and clockwise from l, about u.
    let (mut l, mut r) = (None, None);
    for &f in &h.vertex_faces[v as usize] {
        let t = h.faces[f as usize];
        if let Some(k) = t.iter().position(|&w| w == u) {
            if t[(k + 1) % 3] == v {
                l = Some(t[(k + 2) % 3]);
            } else {
                r = Some(t[(k + 1) % 3]);
            }
        }
    }
    let (Some(l), Some(r)) = (l, r) else { return None };
    let e1 = pu.any_orthonormal_vector();
    let e2 = pu.cross(e1);
    let angle = |k: u32| {
        let d = sphere[k as usize] - pu;
        d.dot(e2).atan2(d.dot(e1))
    };
    let (al, ar) = (angle(l), angle(r));
    let sector = (al - ar).rem_euclid(std::f64::consts::TAU);
    let mid = ar + 0.5 * sector;
    let dir = e1 * mid.cos() + e2 * mid.sin();
    let shortest = ring
        .iter()
        .filter(|&&k| k != u)
        .map(|&k| (sphere[k as usize] - pu).length())
        .fold(f64::INFINITY, f64::min);
    let mut t = 0.25 * shortest;
    for _ in 0..40 {
        let x = (pu + t * dir).normalize();
        if x.is_finite() && x != pu && valid_at(h, sphere, v, x) {
            return Some(x);
        }
        t *= 0.5;
    }
    None
}

/// The regular tetrahedron's corners, wound to match the four remaining faces.
pub(super) fn base(h: &Hierarchy, sphere: &mut [DVec3]) -> Result<(), Error> {
    let verts: Vec<u32> = (0..h.alive.len() as u32).filter(|&v| h.alive[v as usize]).collect();
    let faces: Vec<[u32; 3]> =
        (0..h.faces.len()).filter(|&f| h.face_alive[f]).map(|f| h.faces[f]).collect();
    if verts.len() != 4 || faces.len() != 4 {
        return Err(Error::Topology {
            what: format!(
                "the simplified mesh is not a tetrahedron ({} vertices, {} triangles)",
                verts.len(),
                faces.len()
            ),
        });
    }
    let s = 1.0 / 3f64.sqrt();
    let mut corners =
        [DVec3::new(s, s, s), DVec3::new(s, -s, -s), DVec3::new(-s, s, -s), DVec3::new(-s, -s, s)];
    let wound = |corners: &[DVec3; 4]| {
        faces.iter().all(|t| {
            let [a, b, c] = t.map(|k| corners[verts.iter().position(|&w| w == k).unwrap_or(0)]);
            a.dot(b.cross(c)) > 0.0
        })
    };
    if !wound(&corners) {
        corners.swap(0, 1);
        if !wound(&corners) {
            return Err(Error::Topology {
                what: "the simplified tetrahedron is not consistently wound".to_owned(),
            });
        }
    }
    for (k, &v) in verts.iter().enumerate() {
        sphere[v as usize] = corners[k];
    }
    Ok(())
}
