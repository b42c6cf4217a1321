// SPDX-License-Identifier: MIT
//! The mesh being simplified and refined, and its simplification to a tetrahedron by half-edge
//! collapses (step 1 of the module documentation of `sphereparam`).

use std::f64::consts::PI;

use glam::DVec3;
use hi_par::*;

use super::relax::SHAPE_WEIGHT;
use crate::Error;
use hi_scan::repair::ClosedMesh;

/// One half-edge collapse: `v` merged into `u`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Collapse {
    pub(super) v: u32,
    pub(super) u: u32,
    /// The two triangles that contained both.
    pub(super) removed: [u32; 2],
    /// The range of `Hierarchy::changed` holding (face << 2 | corner) of the triangles whose
    /// corner v became u.
    pub(super) changed: (u32, u32),
}

pub(super) struct Hierarchy {
    pub(super) positions: Vec<DVec3>,
    pub(super) faces: Vec<[u32; 3]>,
    pub(super) face_alive: Vec<bool>,
    pub(super) vertex_faces: Vec<Vec<u32>>,
    pub(super) alive: Vec<bool>,
    /// Surface area (times the face's weight) and squared edge lengths [opposite corner 0, 1,
    /// 2] of each face as it is now (recomputed when a face's corners change).
    pub(super) face_area: Vec<f64>,
    pub(super) face_l2: Vec<[f64; 3]>,
    /// The weight of the shape term of [`face_energy`](super::relax::face_energy).
    pub(super) face_shape: Vec<f64>,
    /// Surface area over the sphere's, for the shape weights.
    pub(super) shape_scale: f64,
    pub(super) collapses: Vec<Collapse>,
    pub(super) changed: Vec<u32>,
    pub(super) level_starts: Vec<usize>,
    pub(super) forced: usize,
    pub(super) area_floor: f64,
    /// Each vertex's weight in the stretch (empty: all 1); a face's is its corners' mean.
    pub(super) weights: Vec<f64>,
}

impl Hierarchy {
    pub(super) fn new(mesh: &ClosedMesh, weights: Option<&[f64]>) -> Self {
        let n = mesh.positions.len();
        let mut vertex_faces = vec![Vec::with_capacity(7); n];
        for (f, t) in mesh.triangles.iter().enumerate() {
            for &k in t {
                vertex_faces[k as usize].push(f as u32);
            }
        }
        let mut h = Self {
            positions: mesh.positions.clone(),
            faces: mesh.triangles.clone(),
            face_alive: vec![true; mesh.triangles.len()],
            vertex_faces,
            alive: vec![true; n],
            face_area: vec![0.0; mesh.triangles.len()],
            face_l2: vec![[0.0; 3]; mesh.triangles.len()],
            face_shape: vec![0.0; mesh.triangles.len()],
            shape_scale: SHAPE_WEIGHT * mesh.area() / (4.0 * PI),
            collapses: Vec::with_capacity(n),
            changed: Vec::with_capacity(6 * n),
            level_starts: Vec::new(),
            forced: 0,
            area_floor: 0.01 * mesh.area() / mesh.triangles.len().max(1) as f64,
            weights: weights.map(<[f64]>::to_vec).unwrap_or_default(),
        };
        for f in 0..mesh.triangles.len() {
            h.update_face_geometry(f);
        }
        h
    }

    pub(super) fn update_face_geometry(&mut self, f: usize) {
        let [a, b, c] = self.faces[f].map(|k| self.positions[k as usize]);
        // Every triangle keeps some weight, so that the energy's barrier holds a triangle
        // open on the sphere even where it is flat on the surface.
        // The weight scales the whole of the face's energy, the shape term too.
        let w = if self.weights.is_empty() {
            1.0
        } else {
            self.faces[f].iter().map(|&k| self.weights[k as usize]).sum::<f64>() / 3.0
        };
        self.face_area[f] = (0.5 * (b - a).cross(c - a).length()).max(self.area_floor) * w;
        self.face_l2[f] =
            [(b - c).length_squared(), (c - a).length_squared(), (a - b).length_squared()];
        // A uniform map spends σ² = (surface area / sphere area) on a triangle of surface
        // area A: the shape term is weighed against that.
        self.face_shape[f] = self.shape_scale * self.face_area[f];
    }

    /// The neighbours of v (alive faces), unsorted, each once.
    pub(super) fn ring(&self, v: u32, out: &mut Vec<u32>) {
        out.clear();
        for &f in &self.vertex_faces[v as usize] {
            for &k in &self.faces[f as usize] {
                if k != v && !out.contains(&k) {
                    out.push(k);
                }
            }
        }
    }

    /// Whether v can be merged into its neighbour u keeping a 2-manifold: they share exactly
    /// two neighbours.
    fn link_ok(&self, u: u32, ring_v: &[u32], scratch: &mut Vec<u32>) -> bool {
        self.ring(u, scratch);
        ring_v.iter().filter(|k| scratch.contains(k)).count() == 2
    }

    /// Whether merging v into u turns none of v's other triangles over on the surface (their
    /// normals keep within 90° of where they were) — and the quadric cost of the move.
    fn collapse_geometry(&self, v: u32, u: u32) -> bool {
        let pu = self.positions[u as usize];
        for &f in &self.vertex_faces[v as usize] {
            let t = self.faces[f as usize];
            if t.contains(&u) {
                continue;
            }
            let [a, b, c] = t.map(|k| self.positions[k as usize]);
            let before = (b - a).cross(c - a);
            let [a2, b2, c2] = t.map(|k| if k == v { pu } else { self.positions[k as usize] });
            let after = (b2 - a2).cross(c2 - a2);
            if before.dot(after) <= 0.0 {
                return false;
            }
        }
        true
    }

    /// Merges v into u (the caller has checked the link condition).
    fn collapse(&mut self, v: u32, u: u32) {
        let start = self.changed.len() as u32;
        let mut removed = [u32::MAX; 2];
        let faces_v = std::mem::take(&mut self.vertex_faces[v as usize]);
        for &f in &faces_v {
            let t = self.faces[f as usize];
            if t.contains(&u) {
                // Goes away: detach it from its other two corners.
                self.face_alive[f as usize] = false;
                if removed[0] == u32::MAX {
                    removed[0] = f;
                } else {
                    removed[1] = f;
                }
                for &k in &t {
                    if k != v {
                        let list = &mut self.vertex_faces[k as usize];
                        if let Some(i) = list.iter().position(|&g| g == f) {
                            list.swap_remove(i);
                        }
                    }
                }
            } else {
                let corner = t.iter().position(|&k| k == v).unwrap_or(0);
                self.faces[f as usize][corner] = u;
                self.changed.push((f << 2) | corner as u32);
                self.vertex_faces[u as usize].push(f);
                self.update_face_geometry(f as usize);
            }
        }
        self.vertex_faces[v as usize] = faces_v; // kept for the undo, but v is dead
        self.alive[v as usize] = false;
        self.collapses.push(Collapse {
            v,
            u,
            removed,
            changed: (start, self.changed.len() as u32),
        });
    }

    /// Simplifies to a tetrahedron in rounds of independent collapses.
    pub(super) fn simplify(&mut self) -> Result<(), Error> {
        let n = self.positions.len();
        let mut s = Simplification {
            quadric: self.quadrics(),
            best: vec![(f64::INFINITY, u32::MAX); n],
            dirty: vec![true; n],
            blocked: vec![false; n],
            candidates: Vec::with_capacity(n),
            ring_v: Vec::new(),
            scratch: Vec::new(),
        };
        let mut remaining = n;
        let mut strict = true;
        while remaining > 4 {
            self.level_starts.push(self.collapses.len());
            self.refresh_best(&mut s);
            self.cheapest_half(&mut s);
            let done = self.collapse_round(&mut s, strict, &mut remaining);
            if done == 0 {
                self.level_starts.pop();
                if strict {
                    strict = false;
                    continue;
                }
                return Err(Error::Topology {
                    what: format!(
                        "the mesh could not be simplified below {remaining} vertices (no edge can be collapsed)"
                    ),
                });
            }
            strict = true;
        }
        Ok(())
    }

    /// The quadric of each vertex (Garland and Heckbert): Σ over its faces of (n·x − n·p)² with
    /// n the face normal times √area.
    fn quadrics(&self) -> Vec<[f64; 10]> {
        let n = self.positions.len();
        let mut quadric = vec![[0.0f64; 10]; n];
        for f in 0..self.faces.len() {
            let [a, b, c] = self.faces[f].map(|k| self.positions[k as usize]);
            let m = (b - a).cross(c - a);
            let len = m.length();
            if len <= 0.0 {
                continue;
            }
            let nn = m / len;
            let w = 0.5 * len;
            let d = -nn.dot(a);
            let q = [
                nn.x * nn.x,
                nn.x * nn.y,
                nn.x * nn.z,
                nn.x * d,
                nn.y * nn.y,
                nn.y * nn.z,
                nn.y * d,
                nn.z * nn.z,
                nn.z * d,
                d * d,
            ];
            for &k in &self.faces[f] {
                for (acc, x) in quadric[k as usize].iter_mut().zip(q) {
                    *acc += w * x;
                }
            }
        }
        quadric
    }

    /// A round's first stage: each changed vertex's cheapest neighbour, in parallel (reads
    /// only).
    fn refresh_best(&self, s: &mut Simplification) {
        let n = self.positions.len();
        let (quadric, dirty) = (&s.quadric, &s.dirty);
        let fresh: Vec<(u32, (f64, u32))> = (0..n as u32)
            .into_par_iter()
            .with_min_len(1024)
            .filter(|&v| self.alive[v as usize] && dirty[v as usize])
            .map_init(Vec::new, |ring, v| {
                self.ring(v, ring);
                let mut b = (f64::INFINITY, u32::MAX);
                for &u in ring.iter() {
                    let c = pair_cost(quadric, v, u, self.positions[u as usize]);
                    if c < b.0 || b.1 == u32::MAX {
                        b = (c, u);
                    }
                }
                (v, b)
            })
            .collect();
        for (v, b) in fresh {
            s.best[v as usize] = b;
            s.dirty[v as usize] = false;
        }
    }

    /// A round's candidates: the cheapest part of the alive vertices by their best collapse,
    /// cheapest first.
    fn cheapest_half(&self, s: &mut Simplification) {
        let n = self.positions.len();
        let candidates = &mut s.candidates;
        candidates.clear();
        for v in 0..n as u32 {
            if self.alive[v as usize] {
                candidates.push((s.best[v as usize].0, v));
            }
        }
        let limit = candidates.len().div_ceil(2).max(1);
        if limit < candidates.len() {
            candidates.select_nth_unstable_by(limit, |a, b| a.0.total_cmp(&b.0));
            candidates.truncate(limit);
        }
        candidates.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
    }

    /// A round's collapses, as an independent set: each candidate in turn, unless a neighbour
    /// has collapsed in this round, merged into its cheapest admissible neighbour (link
    /// condition, and no triangle turned over while `strict`). Returns how many were made.
    fn collapse_round(
        &mut self,
        s: &mut Simplification,
        strict: bool,
        remaining: &mut usize,
    ) -> usize {
        let Simplification { quadric, best, dirty, blocked, candidates, ring_v, scratch } = s;
        blocked.iter_mut().for_each(|b| *b = false);
        let mut done = 0;
        for &(_, v) in candidates.iter() {
            if *remaining <= 4 {
                break;
            }
            if blocked[v as usize] {
                continue;
            }
            self.ring(v, ring_v);
            let ring_v: &[u32] = ring_v;
            let admissible = |h: &Self, u: u32, scratch: &mut Vec<u32>| {
                h.link_ok(u, ring_v, scratch) && (!strict || h.collapse_geometry(v, u))
            };
            let cached = best[v as usize].1;
            let target = if ring_v.contains(&cached) && admissible(self, cached, scratch) {
                Some(cached)
            } else {
                let mut options: Vec<(f64, u32)> = ring_v
                    .iter()
                    .map(|&u| (pair_cost(quadric, v, u, self.positions[u as usize]), u))
                    .collect();
                options.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
                options.into_iter().map(|o| o.1).find(|&u| admissible(self, u, scratch))
            };
            let Some(u) = target else { continue };
            blocked[v as usize] = true;
            for &k in ring_v {
                blocked[k as usize] = true;
                dirty[k as usize] = true;
            }
            let qv = quadric[v as usize];
            for (a, b) in quadric[u as usize].iter_mut().zip(qv) {
                *a += b;
            }
            if !strict {
                self.forced += 1;
            }
            self.collapse(v, u);
            // u's quadric changed: every neighbour's cost of merging into it did too.
            for &f in &self.vertex_faces[u as usize] {
                for &k in &self.faces[f as usize] {
                    dirty[k as usize] = true;
                }
            }
            *remaining -= 1;
            done += 1;
        }
        done
    }
}

/// The working state of [`Hierarchy::simplify`] across its rounds.
struct Simplification {
    /// Each vertex's quadric, with those of the vertices merged into it.
    quadric: Vec<[f64; 10]>,
    /// Each vertex's cheapest neighbour to merge into, kept until its ring changes.
    best: Vec<(f64, u32)>,
    /// The vertices whose ring or neighbours' quadrics changed since `best` was found.
    dirty: Vec<bool>,
    /// The vertices that collapsed or neighbour a collapse in this round.
    blocked: Vec<bool>,
    /// The round's vertices to collapse, cheapest first.
    candidates: Vec<(f64, u32)>,
    ring_v: Vec<u32>,
    scratch: Vec<u32>,
}

/// The quadric error of `q` at p.
fn quadric_cost(q: &[f64; 10], p: DVec3) -> f64 {
    let (x, y, z) = (p.x, p.y, p.z);
    q[0] * x * x
        + 2.0 * q[1] * x * y
        + 2.0 * q[2] * x * z
        + 2.0 * q[3] * x
        + q[4] * y * y
        + 2.0 * q[5] * y * z
        + 2.0 * q[6] * y
        + q[7] * z * z
        + 2.0 * q[8] * z
        + q[9]
}

/// The cost of merging v into u at p: the two quadrics summed, at p, at least 0.
fn pair_cost(quadric: &[[f64; 10]], v: u32, u: u32, p: DVec3) -> f64 {
    let mut q = quadric[v as usize];
    for (a, b) in q.iter_mut().zip(&quadric[u as usize]) {
        *a += b;
    }
    quadric_cost(&q, p).max(0.0)
}
