// SPDX-License-Identifier: MIT
//! A spherical parameterisation of a closed genus-0 mesh, and the geometry image sampled from
//! it (beyond §5.3: the thesis casts rays from a centre, which needs a star-shaped object; here
//! any genus-0 surface works, as in Praun and Hoppe, "Spherical parametrization and
//! remeshing", SIGGRAPH 2003).
//!
//! **The map.** Every vertex of a [`ClosedMesh`] gets a point on the unit sphere so that every
//! triangle, taken as the flat triangle between its three sphere points, is wound
//! counter-clockwise seen from outside (a·(b × c) > 0): the triangles tile the sphere once,
//! with no fold. The piecewise-linear map from those triangles to the mesh's triangles is then
//! one-to-one, and a texel that looks along direction d (any [`Layout`]) holds the point of
//! the mesh that d falls on. Texels hold x, y, z of the surface itself, not a distance along a
//! ray, so ears, limbs and overhangs are sampled like everything else.
//!
//! **How.** As Praun and Hoppe do, coarse to fine:
//! 1. the mesh is simplified to a tetrahedron by half-edge collapses (a vertex merged into a
//!    neighbour, which keeps its position), in rounds that each remove an independent set of
//!    vertices, cheapest first by the quadric error of Garland and Heckbert; a collapse must
//!    keep the mesh a 2-manifold (the link condition: the edge's ends share exactly two
//!    neighbours) and, while possible, not turn a triangle over;
//! 2. the tetrahedron goes onto the sphere as the regular one;
//! 3. the collapses are undone in reverse; each vertex that comes back is placed in the kernel
//!    of its ring of neighbours (where all its triangles are wound correctly): at the deepest
//!    point of the kernel (the centre of its largest inscribed circle), or, on the fine levels,
//!    at its neighbours' centroid when that is in the kernel; the kernel is never empty next to
//!    the vertex it had been merged into, where the last fallback puts it;
//! 4. vertices are moved to lower the L² stretch of the map from the sphere to the surface
//!    (Sander, Snyder, Gortler and Hoppe 2001), E = Σ A (σ₁² + σ₂²)/2 over the triangles,
//!    A the triangle's area on the surface and σ the singular values of the map's Jacobian:
//!    each vertex just placed (and, on the coarse levels, the one it split from), every vertex
//!    each time the mesh has grown by half while it is coarse, and every vertex of the
//!    finished map. Minimising E spreads the surface evenly over the sphere (no part
//!    undersampled in the image). Each move is a Newton step on the sphere, halved until it
//!    lowers E with every triangle of the vertex wound correctly; as the set of such positions
//!    is convex (an intersection of hemispheres), the map stays one-to-one throughout. E is
//!    made a barrier against every way a triangle can degenerate on the sphere, and a small
//!    shape term keeps triangles that are slivers on the surface from becoming slivers on the
//!    sphere (see `face_energy`). The vertices of each colour of a greedy colouring move in
//!    parallel.
//!
//! **The image.** For each texel, the triangle containing its direction is found by walking
//! across triangle edges from the texel before it, and the texel is the surface point at the
//! barycentric coordinates of the direction's intersection with the triangle's plane (continuous
//! across edges). Texels in triangles that closed a hole are flagged.

use std::f64::consts::PI;

use glam::{DMat3, DVec3};
use hi_par::*;

use crate::{Error, GeometryImage, Layout};
use hi_scan::repair::ClosedMesh;

/// The weight of the shape term against the stretch (see [`face_energy`]).
const SHAPE_WEIGHT: f64 = 0.1;

/// The settings of [`parameterise`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SphereParamOptions {
    /// Relaxation sweeps over every vertex each time the mesh has grown by half during the
    /// refinement, while it has at most [`SphereParamOptions::fine_vertices`]. Default 4.
    pub sweeps: usize,
    /// Sweeps over every vertex of the finished map. Default 1.
    pub final_sweeps: usize,
    /// Above this many vertices the refinement only places vertices and relaxes each once
    /// (the coarse levels have shaped the map by then; the final sweeps adjust it locally).
    /// Default 10 000.
    pub fine_vertices: usize,
}

impl Default for SphereParamOptions {
    fn default() -> Self {
        Self { sweeps: 4, final_sweeps: 1, fine_vertices: 10_000 }
    }
}

/// How good a spherical parameterisation is.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ParamQuality {
    /// Rounds of collapses from the mesh to the tetrahedron.
    pub levels: usize,
    /// Collapses that had to turn a triangle over on the surface (none was left otherwise).
    pub forced_collapses: usize,
    /// The L² stretch efficiency of Praun and Hoppe: (area on the sphere / area on the
    /// surface) over E, scaled so that a map with the same stretch everywhere gives 1; in
    /// (0, 1], higher is better.
    pub stretch_efficiency: f64,
    /// The ratio of the largest to the smallest (area on the sphere / area on the surface)
    /// over the triangles with a surface area above a millionth of the mean: how much denser
    /// the image samples one part of the surface than another.
    pub area_ratio: f64,
    /// Triangles wound the wrong way on the sphere (0 for a valid map).
    pub folded_triangles: usize,
}

/// A spherical parameterisation: the mesh and one unit vector per vertex.
#[derive(Clone, Debug)]
pub struct SphereParam {
    mesh: ClosedMesh,
    sphere: Vec<DVec3>,
    across: Vec<[u32; 3]>,
    quality: ParamQuality,
}

/// A geometry image sampled from a [`SphereParam`].
#[derive(Clone, Debug, PartialEq)]
pub struct ParamImage {
    /// The image: texel (i, j) is the surface point that direction
    /// `layout.direction(i, j, rows, cols)` falls on.
    pub image: GeometryImage,
    /// Texels that fell on a triangle added to close a hole (row-major).
    pub filled: Vec<bool>,
    /// The fraction of the distinct texels (each direction once) that fell in a closed hole.
    pub filled_fraction: f64,
}

// ---------------------------------------------------------------------------------------------
// The stretch energy of one triangle and its gradient.

/// The L² stretch energy A·(σ₁² + σ₂²)/2 of the affine map from the triangle (a, b, c)
/// (sphere points) to a surface triangle of area `area` and squared edge lengths
/// `l2 = [|pb − pc|², |pc − pa|², |pa − pb|²]`, plus a shape term; ∞ if (a, b, c) is wound the
/// wrong way (a·(b × c) ≤ 0).
///
/// For the flat triangle abc, σ₁² + σ₂² = ‖J‖² (Frobenius) = N/|n|² with n = (b − a) × (c − a) and
/// N = ℓ₁ (b − a)·(c − a) + ℓ₂ (c − b)·(a − b) + ℓ₃ (a − c)·(b − c), ℓ₁, ℓ₂, ℓ₃ the squared
/// lengths of the surface triangle's edges opposite a, b, c (the cotangent form
/// of the Dirichlet energy, with the roles of the two triangles exchanged). |n| is replaced by
/// det = a·(b × c), equal to it to second order for small triangles, which vanishes as the
/// triangle's great circles line up (a triangle as large as a hemisphere): so the energy is a
/// barrier against every way a triangle on the sphere can degenerate.
///
/// `shape` weighs a second term, shape · Q with Q = (|b − a|² + |c − b|² + |a − c|²) / (2√3 ·
/// det), which is 1 for a small equilateral triangle and grows without bound as the triangle
/// flattens: it keeps a triangle that is a sliver on the surface from becoming one on the
/// sphere, where later vertex splits would have no room.
fn face_energy(a: DVec3, b: DVec3, c: DVec3, area: f64, l2: [f64; 3], shape: f64) -> f64 {
    let det = a.dot(b.cross(c));
    if det <= 0.0 {
        return f64::INFINITY;
    }
    let num = l2[0] * (b - a).dot(c - a) + l2[1] * (c - b).dot(a - b) + l2[2] * (a - c).dot(b - c);
    let sq = (b - a).length_squared() + (c - b).length_squared() + (a - c).length_squared();
    0.5 * area * num / (det * det) + shape * sq / (2.0 * 3f64.sqrt() * det)
}

/// The energy of [`face_energy`], its gradient and its Hessian with respect to a (in space,
/// before the restriction to the sphere).
fn face_energy_grad(
    a: DVec3,
    b: DVec3,
    c: DVec3,
    area: f64,
    l2: [f64; 3],
    shape: f64,
) -> (f64, DVec3, DMat3) {
    let bc = b.cross(c);
    let det = a.dot(bc);
    if det <= 0.0 {
        return (f64::INFINITY, DVec3::ZERO, DMat3::ZERO);
    }
    let num = l2[0] * (b - a).dot(c - a) + l2[1] * (c - b).dot(a - b) + l2[2] * (a - c).dot(b - c);
    let dnum = l2[0] * (2.0 * a - b - c) + (l2[1] - l2[2]) * (c - b);
    let sq = (b - a).length_squared() + (c - b).length_squared() + (a - c).length_squared();
    let dsq = 2.0 * (2.0 * a - b - c);
    let k = 2.0 * 3f64.sqrt();
    let (d1, d2) = (1.0 / det, 1.0 / (det * det));
    let (d3, d4) = (d2 * d1, d2 * d2);
    let outer = |x: DVec3, y: DVec3| DMat3::from_cols(x * y.x, x * y.y, x * y.z);
    let sym = |x: DVec3, y: DVec3| outer(x, y) + outer(y, x);
    let bb = outer(bc, bc);
    // f₁ = N/det², f₂ = S/det; ∇²N = 2L²_a I, ∇²S = 4I, ∇det = b × c, ∇²det = 0.
    let e = 0.5 * area * num * d2 + shape * sq * d1 / k;
    let g = 0.5 * area * (dnum * d2 - 2.0 * num * d3 * bc) + shape * (dsq * d1 - sq * d2 * bc) / k;
    let h1 = DMat3::from_diagonal(DVec3::splat(2.0 * l2[0] * d2)) - sym(dnum, bc) * (2.0 * d3)
        + bb * (6.0 * num * d4);
    let h2 =
        DMat3::from_diagonal(DVec3::splat(4.0 * d1)) - sym(dsq, bc) * d2 + bb * (2.0 * sq * d3);
    (e, g, h1 * (0.5 * area) + h2 * (shape / k))
}

// ---------------------------------------------------------------------------------------------
// The mesh being simplified and refined.

/// One half-edge collapse: `v` merged into `u`.
#[derive(Clone, Copy, Debug)]
struct Collapse {
    v: u32,
    u: u32,
    /// The two triangles that contained both.
    removed: [u32; 2],
    /// The range of `Hierarchy::changed` holding (face << 2 | corner) of the triangles whose
    /// corner v became u.
    changed: (u32, u32),
}

struct Hierarchy {
    positions: Vec<DVec3>,
    faces: Vec<[u32; 3]>,
    face_alive: Vec<bool>,
    vertex_faces: Vec<Vec<u32>>,
    alive: Vec<bool>,
    /// Surface area and squared edge lengths [opposite corner 0, 1, 2] of each face as it is
    /// now (recomputed when a face's corners change).
    face_area: Vec<f64>,
    face_l2: Vec<[f64; 3]>,
    /// The weight of the shape term of [`face_energy`].
    face_shape: Vec<f64>,
    /// Surface area over the sphere's, for the shape weights.
    shape_scale: f64,
    collapses: Vec<Collapse>,
    changed: Vec<u32>,
    level_starts: Vec<usize>,
    forced: usize,
    area_floor: f64,
}

impl Hierarchy {
    fn new(mesh: &ClosedMesh) -> Self {
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
        };
        for f in 0..mesh.triangles.len() {
            h.update_face_geometry(f);
        }
        h
    }

    fn update_face_geometry(&mut self, f: usize) {
        let [a, b, c] = self.faces[f].map(|k| self.positions[k as usize]);
        // Every triangle keeps some weight, so that the energy's barrier holds a triangle
        // open on the sphere even where it is flat on the surface.
        self.face_area[f] = (0.5 * (b - a).cross(c - a).length()).max(self.area_floor);
        self.face_l2[f] =
            [(b - c).length_squared(), (c - a).length_squared(), (a - b).length_squared()];
        // A uniform map spends σ² = (surface area / sphere area) on a triangle of surface
        // area A: the shape term is weighed against that.
        self.face_shape[f] = self.shape_scale * self.face_area[f];
    }

    /// The neighbours of v (alive faces), unsorted, each once.
    fn ring(&self, v: u32, out: &mut Vec<u32>) {
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

    /// Undoes the last collapse.
    fn split(&mut self, c: Collapse) {
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

    /// Simplifies to a tetrahedron in rounds of independent collapses.
    fn simplify(&mut self) -> Result<(), Error> {
        let n = self.positions.len();
        // Quadrics: Σ over faces of (n·x − n·p)² with n the face normal times √area.
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
        let cost = |q: &[f64; 10], p: DVec3| {
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
        };
        let mut remaining = n;
        let mut ring_v = Vec::new();
        let mut scratch = Vec::new();
        let mut strict = true;
        // Each vertex's cheapest neighbour to merge into, kept until its ring changes.
        let mut best: Vec<(f64, u32)> = vec![(f64::INFINITY, u32::MAX); n];
        let mut dirty = vec![true; n];
        let mut blocked = vec![false; n];
        let mut candidates: Vec<(f64, u32)> = Vec::with_capacity(n);
        let pair_cost = |quadric: &[[f64; 10]], v: u32, u: u32, p: DVec3| {
            let mut q = quadric[v as usize];
            for (a, b) in q.iter_mut().zip(&quadric[u as usize]) {
                *a += b;
            }
            cost(&q, p).max(0.0)
        };
        while remaining > 4 {
            self.level_starts.push(self.collapses.len());
            candidates.clear();
            // Each changed vertex's cheapest neighbour, in parallel (reads only).
            let this = &*self;
            let fresh: Vec<(u32, (f64, u32))> = (0..n as u32)
                .into_par_iter()
                .with_min_len(1024)
                .filter(|&v| this.alive[v as usize] && dirty[v as usize])
                .map_init(Vec::new, |ring, v| {
                    this.ring(v, ring);
                    let mut b = (f64::INFINITY, u32::MAX);
                    for &u in ring.iter() {
                        let c = pair_cost(&quadric, v, u, this.positions[u as usize]);
                        if c < b.0 || b.1 == u32::MAX {
                            b = (c, u);
                        }
                    }
                    (v, b)
                })
                .collect();
            for (v, b) in fresh {
                best[v as usize] = b;
                dirty[v as usize] = false;
            }
            for v in 0..n as u32 {
                if self.alive[v as usize] {
                    candidates.push((best[v as usize].0, v));
                }
            }
            // The cheapest part of the candidates, as an independent set.
            let limit = candidates.len().div_ceil(2).max(1);
            if limit < candidates.len() {
                candidates.select_nth_unstable_by(limit, |a, b| a.0.total_cmp(&b.0));
                candidates.truncate(limit);
            }
            candidates.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
            blocked.iter_mut().for_each(|b| *b = false);
            let mut done = 0;
            for &(_, v) in &candidates {
                if remaining <= 4 {
                    break;
                }
                if blocked[v as usize] {
                    continue;
                }
                self.ring(v, &mut ring_v);
                let admissible = |h: &Self, u: u32, scratch: &mut Vec<u32>| {
                    h.link_ok(u, &ring_v, scratch) && (!strict || h.collapse_geometry(v, u))
                };
                let cached = best[v as usize].1;
                let target = if ring_v.contains(&cached) && admissible(self, cached, &mut scratch) {
                    Some(cached)
                } else {
                    let mut options: Vec<(f64, u32)> = ring_v
                        .iter()
                        .map(|&u| (pair_cost(&quadric, v, u, self.positions[u as usize]), u))
                        .collect();
                    options.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
                    options.into_iter().map(|o| o.1).find(|&u| admissible(self, u, &mut scratch))
                };
                let Some(u) = target else { continue };
                blocked[v as usize] = true;
                for &k in &ring_v {
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
                remaining -= 1;
                done += 1;
            }
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
}

// ---------------------------------------------------------------------------------------------
// Placing vertices on the sphere and relaxing them.

/// Whether v at position x has every triangle wound correctly.
fn valid_at(h: &Hierarchy, sphere: &[DVec3], v: u32, x: DVec3) -> bool {
    h.vertex_faces[v as usize].iter().all(|&f| {
        let t = h.faces[f as usize];
        let [a, b, c] = t.map(|k| if k == v { x } else { sphere[k as usize] });
        let n = (b - a).cross(c - a);
        n.dot(a + b + c) > 0.0 && n.length_squared() > 0.0
    })
}

/// The energy of v's triangles with v at x, and its gradient and Hessian in space.
fn vertex_energy(h: &Hierarchy, sphere: &[DVec3], v: u32, x: DVec3) -> (f64, DVec3, DMat3) {
    let (mut e, mut g, mut s) = (0.0, DVec3::ZERO, DMat3::ZERO);
    for &f in &h.vertex_faces[v as usize] {
        let t = h.faces[f as usize];
        let k = t.iter().position(|&w| w == v).unwrap_or(0);
        let (b, c) = (sphere[t[(k + 1) % 3] as usize], sphere[t[(k + 2) % 3] as usize]);
        let l2 = h.face_l2[f as usize];
        let l2 = [l2[k], l2[(k + 1) % 3], l2[(k + 2) % 3]];
        let (fe, fg, fs) =
            face_energy_grad(x, b, c, h.face_area[f as usize], l2, h.face_shape[f as usize]);
        e += fe;
        g += fg;
        s += fs;
    }
    (e, g, s)
}

fn vertex_energy_only(h: &Hierarchy, sphere: &[DVec3], v: u32, x: DVec3) -> f64 {
    let mut e = 0.0;
    for &f in &h.vertex_faces[v as usize] {
        let t = h.faces[f as usize];
        let k = t.iter().position(|&w| w == v).unwrap_or(0);
        let (b, c) = (sphere[t[(k + 1) % 3] as usize], sphere[t[(k + 2) % 3] as usize]);
        let l2 = h.face_l2[f as usize];
        e += face_energy(
            x,
            b,
            c,
            h.face_area[f as usize],
            [l2[k], l2[(k + 1) % 3], l2[(k + 2) % 3]],
            h.face_shape[f as usize],
        );
        if !e.is_finite() {
            return e;
        }
    }
    e
}

/// One stretch-lowering move of v, and the mean distance to its neighbours: a Newton step in the tangent plane (the Hessian from
/// differences of the gradient), or a steepest-descent step where the Hessian is not positive,
/// no longer than half the shortest edge at v, halved until it lowers the energy with every
/// triangle wound correctly.
fn relax_vertex(h: &Hierarchy, sphere: &[DVec3], v: u32) -> Option<(DVec3, f64)> {
    let x = sphere[v as usize];
    let (e0, g, hs) = vertex_energy(h, sphere, v, x);
    if !e0.is_finite() {
        return None;
    }
    // Steps no longer than half the mean distance to the neighbours (each neighbour is
    // counted twice, as each triangle is visited).
    let (mut reach, mut count) = (0.0, 0usize);
    for &f in &h.vertex_faces[v as usize] {
        for &k in &h.faces[f as usize] {
            if k != v {
                reach += (sphere[k as usize] - x).length();
                count += 1;
            }
        }
    }
    reach /= count.max(1) as f64;
    if reach.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    let e1 = x.any_orthonormal_vector();
    let e2 = x.cross(e1);
    let g2 = [g.dot(e1), g.dot(e2)];
    if g2[0] == 0.0 && g2[1] == 0.0 {
        return None;
    }
    // The Hessian on the sphere in (e1, e2): the tangent part of the spatial Hessian, less
    // (x·∇E) for the sphere's curvature.
    let gx = g.dot(x);
    let (a, b, c) =
        (e1.dot(hs * e1) - gx, 0.5 * (e1.dot(hs * e2) + e2.dot(hs * e1)), e2.dot(hs * e2) - gx);
    let mut step = DVec3::ZERO;
    let det = a * c - b * b;
    if a > 0.0 && det > 0.0 {
        let s1 = -(c * g2[0] - b * g2[1]) / det;
        let s2 = -(-b * g2[0] + a * g2[1]) / det;
        step = s1 * e1 + s2 * e2;
    }
    if step == DVec3::ZERO || !step.is_finite() {
        let gt = g2[0] * e1 + g2[1] * e2;
        step = -gt * (0.5 * reach / gt.length());
    }
    let len = step.length();
    if len > 0.5 * reach {
        step *= 0.5 * reach / len;
    }
    for _ in 0..40 {
        let y = (x + step).normalize();
        if y.is_finite() && y != x {
            let e = vertex_energy_only(h, sphere, v, y);
            if e < e0 {
                return Some((y, reach));
            }
        }
        step *= 0.5;
    }
    None
}

/// Above this many vertices a round's splits are placed together, in parallel (below it, one
/// at a time, each settled with the vertex it came from).
const BATCH_ABOVE: usize = 2000;

/// Sweeps of stretch relaxation over the alive vertices: Gauss–Seidel by colour classes (no
/// two neighbours share a colour, so each class moves in parallel, every vertex against its
/// neighbours' latest positions).
fn relax(h: &Hierarchy, sphere: &mut [DVec3], sweeps: usize) {
    if sweeps == 0 {
        return;
    }
    let classes = colour_classes(h);
    // A vertex is visited again only if it or a neighbour moved noticeably in the last sweep.
    let mut active = vec![true; h.alive.len()];
    let mut next = vec![false; h.alive.len()];
    for _ in 0..sweeps {
        for class in &classes {
            let moves: Vec<(u32, DVec3, bool)> = class
                .par_iter()
                .with_min_len(256)
                .filter(|&&v| active[v as usize])
                .filter_map(|&v| {
                    let x = sphere[v as usize];
                    relax_vertex(h, sphere, v)
                        .map(|(y, reach)| (v, y, (y - x).length() > 1e-3 * reach))
                })
                .collect();
            for (v, y, noticeable) in moves {
                sphere[v as usize] = y;
                if noticeable {
                    for &f in &h.vertex_faces[v as usize] {
                        for &k in &h.faces[f as usize] {
                            next[k as usize] = true;
                        }
                    }
                }
            }
        }
        std::mem::swap(&mut active, &mut next);
        next.iter_mut().for_each(|x| *x = false);
    }
}

/// The alive vertices split into classes of which no two are neighbours (greedy colouring).
fn colour_classes(h: &Hierarchy) -> Vec<Vec<u32>> {
    let n = h.alive.len();
    let mut colour = vec![u8::MAX; n];
    let mut classes: Vec<Vec<u32>> = Vec::new();
    let mut ring = Vec::new();
    for v in 0..n as u32 {
        if !h.alive[v as usize] {
            continue;
        }
        h.ring(v, &mut ring);
        let mut used = 0u64;
        for &k in &ring {
            let c = colour[k as usize];
            if c < 64 {
                used |= 1 << c;
            }
        }
        let c = (!used).trailing_zeros().min(63) as u8;
        colour[v as usize] = c;
        if classes.len() <= c as usize {
            classes.resize(c as usize + 1, Vec::new());
        }
        classes[c as usize].push(v);
    }
    classes
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
fn place(h: &Hierarchy, sphere: &[DVec3], v: u32, u: u32, fine: bool) -> Option<DVec3> {
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
fn base(h: &Hierarchy, sphere: &mut [DVec3]) -> Result<(), Error> {
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

/// Parameterises a closed genus-0 mesh over the unit sphere; see the module documentation.
///
/// # Errors
///
/// [`Error::Topology`] if the mesh cannot be simplified to a tetrahedron or a vertex cannot be
/// placed without folding the map (neither happens for a valid [`ClosedMesh`] in exact
/// arithmetic; the error guards against rounding in extreme meshes); [`Error::InvalidOption`]
/// for 0 final sweeps.
pub fn parameterise(mesh: &ClosedMesh, options: &SphereParamOptions) -> Result<SphereParam, Error> {
    let mut h = Hierarchy::new(mesh);
    h.simplify()?;
    let n = mesh.positions.len();
    let mut sphere = vec![DVec3::ZERO; n];
    base(&h, &mut sphere)?;
    relax(&h, &mut sphere, options.sweeps.max(1) * 4);
    let levels = h.level_starts.len();
    let mut present = 4usize;
    let mut last_relaxed = 4usize;
    let collapses = std::mem::take(&mut h.collapses);
    for level in (0..levels).rev() {
        let start = h.level_starts[level];
        let end = if level + 1 < levels { h.level_starts[level + 1] } else { collapses.len() };
        if present > BATCH_ABOVE {
            // A round's collapses were independent (no two of its vertices neighbours), so
            // its splits can all be made first and their vertices placed and settled in
            // parallel: each reads only its own ring, which no other vertex of the round is
            // in. (One split at a time would also settle the vertex each came from; here those
            // settle in the sweeps below.)
            let fine = present > options.fine_vertices;
            let batch = &collapses[start..end];
            for &c in batch.iter().rev() {
                h.split(c);
            }
            let placed: Vec<Option<DVec3>> = batch
                .par_iter()
                .with_min_len(64)
                .map(|c| place(&h, &sphere, c.v, c.u, fine))
                .collect();
            for (c, x) in batch.iter().zip(placed) {
                let Some(x) = x else {
                    return Err(Error::Topology {
                        what: "a vertex could not be placed on the sphere without a fold"
                            .to_owned(),
                    });
                };
                sphere[c.v as usize] = x;
            }
            for _ in 0..if fine { 1 } else { 3 } {
                let settled: Vec<Option<(DVec3, f64)>> = batch
                    .par_iter()
                    .with_min_len(64)
                    .map(|c| relax_vertex(&h, &sphere, c.v))
                    .collect();
                for (c, y) in batch.iter().zip(settled) {
                    if let Some((y, _)) = y {
                        sphere[c.v as usize] = y;
                    }
                }
            }
            present += batch.len();
            if fine {
                continue;
            }
        } else {
            for &c in collapses[start..end].iter().rev() {
                h.split(c);
                let fine = present > options.fine_vertices;
                let Some(x) = place(&h, &sphere, c.v, c.u, fine) else {
                    return Err(Error::Topology {
                        what: "a vertex could not be placed on the sphere without a fold"
                            .to_owned(),
                    });
                };
                sphere[c.v as usize] = x;
                // Settle the new vertex and the one it came from at once, so that no triangle
                // stays a sliver for the next splits to subdivide.
                let (iters, which) = if fine { (1, 1) } else { (3, 2) };
                for _ in 0..iters {
                    for &w in &[c.v, c.u][..which] {
                        if let Some((y, _)) = relax_vertex(&h, &sphere, w) {
                            sphere[w as usize] = y;
                        }
                    }
                }
                present += 1;
            }
        }
        if 2 * present >= 3 * last_relaxed {
            let sweeps = if present > options.fine_vertices { 0 } else { options.sweeps };
            relax(&h, &mut sphere, sweeps);
            last_relaxed = present;
        }
    }
    relax(&h, &mut sphere, options.final_sweeps);
    let quality = measure(mesh, &sphere, levels, h.forced);
    if quality.folded_triangles > 0 {
        return Err(Error::Topology {
            what: format!("the spherical map folds {} triangles over", quality.folded_triangles),
        });
    }
    let across = triangle_neighbours(&mesh.triangles);
    Ok(SphereParam { mesh: mesh.clone(), sphere, across, quality })
}

/// Stretch efficiency, area ratio and folds of a map.
fn measure(mesh: &ClosedMesh, sphere: &[DVec3], levels: usize, forced: usize) -> ParamQuality {
    let (mut e, mut area_s, mut area_p) = (0.0, 0.0, 0.0);
    let mut folded = 0;
    let mut ratios = Vec::with_capacity(mesh.triangles.len());
    let mean_area = mesh.area() / mesh.triangles.len().max(1) as f64;
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|k| sphere[k as usize]);
        let [pa, pb, pc] = t.map(|k| mesh.positions[k as usize]);
        let ap = 0.5 * (pb - pa).cross(pc - pa).length();
        let n = (b - a).cross(c - a);
        if n.dot(a + b + c) <= 0.0 || n.length_squared() == 0.0 {
            folded += 1;
            continue;
        }
        let as_ = 0.5 * n.length();
        let l2 =
            [(pb - pc).length_squared(), (pc - pa).length_squared(), (pa - pb).length_squared()];
        // The stretch of the map from the flat triangle abc itself (|n| rather than the
        // barrier's det).
        let num =
            l2[0] * (b - a).dot(c - a) + l2[1] * (c - b).dot(a - b) + l2[2] * (a - c).dot(b - c);
        e += 0.5 * ap * num / n.length_squared();
        area_s += as_;
        area_p += ap;
        if ap > 1e-6 * mean_area {
            ratios.push(as_ / ap);
        }
    }
    // A map with the same stretch everywhere has σ₁ = σ₂ = √(area_p / area_s), so E equals
    // area_p · area_p / area_s; the efficiency is that over E.
    let efficiency = if e > 0.0 { (area_p * area_p / area_s / e).min(1.0) } else { 0.0 };
    let (lo, hi) =
        ratios.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &r| (lo.min(r), hi.max(r)));
    ParamQuality {
        levels,
        forced_collapses: forced,
        stretch_efficiency: efficiency,
        area_ratio: if lo > 0.0 { hi / lo } else { f64::INFINITY },
        folded_triangles: folded,
    }
}

/// For each triangle edge k (corner k to k + 1), the triangle across it.
fn triangle_neighbours(triangles: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let mut half: Vec<(u64, u32)> = Vec::with_capacity(3 * triangles.len());
    for (f, t) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let key = if a < b {
                (u64::from(a) << 32) | u64::from(b)
            } else {
                (u64::from(b) << 32) | u64::from(a)
            };
            half.push((key, (f as u32) * 3 + k as u32));
        }
    }
    half.par_sort_unstable();
    let mut across = vec![[u32::MAX; 3]; triangles.len()];
    for w in half.chunks_exact(2) {
        if w[0].0 == w[1].0 {
            let (a, b) = (w[0].1, w[1].1);
            across[(a / 3) as usize][(a % 3) as usize] = b / 3;
            across[(b / 3) as usize][(b % 3) as usize] = a / 3;
        }
    }
    across
}

impl SphereParam {
    /// The mesh parameterised.
    #[must_use]
    pub const fn mesh(&self) -> &ClosedMesh {
        &self.mesh
    }

    /// The point on the unit sphere of each vertex.
    #[must_use]
    pub fn sphere(&self) -> &[DVec3] {
        &self.sphere
    }

    /// How good the map is.
    #[must_use]
    pub const fn quality(&self) -> ParamQuality {
        self.quality
    }

    /// The triangle whose sphere triangle contains direction d, found by walking from
    /// triangle `from`, and d's barycentric coordinates in it.
    fn locate(&self, d: DVec3, mut from: usize) -> (usize, [f64; 3]) {
        let limit = 4 * self.mesh.triangles.len() + 16;
        for _ in 0..limit {
            let t = self.mesh.triangles[from];
            let [a, b, c] = t.map(|k| self.sphere[k as usize]);
            // s[k]: d against the plane through the origin and edge k (corner k to k + 1).
            let s = [d.dot(a.cross(b)), d.dot(b.cross(c)), d.dot(c.cross(a))];
            let (k, worst) = (0..3)
                .map(|k| (k, s[k]))
                .fold((0, f64::INFINITY), |acc, x| if x.1 < acc.1 { x } else { acc });
            if worst >= 0.0 || self.across[from][k] == u32::MAX {
                let total = s[0] + s[1] + s[2];
                // Barycentric: a's weight is the volume against edge bc, and so on.
                let bary = if total > 0.0 {
                    [s[1].max(0.0) / total, s[2].max(0.0) / total, s[0].max(0.0) / total]
                } else {
                    [1.0 / 3.0; 3]
                };
                let sum = bary[0] + bary[1] + bary[2];
                return (from, bary.map(|x| x / sum));
            }
            from = self.across[from][k] as usize;
        }
        (from, [1.0 / 3.0; 3])
    }

    /// The geometry image of the map in `layout`: each texel the surface point its direction
    /// falls on.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidResolution`] for fewer than 2 rows or columns, too many texels, or an
    /// odd number of rows in a doubled layout.
    pub fn image(&self, layout: Layout, rows: usize, cols: usize) -> Result<ParamImage, Error> {
        crate::image::check_resolution(rows, cols)?;
        if !rows.is_multiple_of(2) && layout != Layout::Octahedron {
            return Err(Error::InvalidResolution {
                rows,
                cols,
                expected: "an even number of rows (both poles are texels)",
            });
        }
        let mirror = layout.mirror(rows, cols);
        let cast_rows = if mirror.is_some() { rows / 2 + 1 } else { rows };
        // A start triangle for each row: walk there from triangle 0 along the first column.
        let mut starts = Vec::with_capacity(cast_rows);
        let mut from = 0;
        for i in 0..cast_rows {
            let (f, _) = self.locate(layout.direction(i, 0, rows, cols), from);
            starts.push(f);
            from = f;
        }
        let rows_of: Vec<Vec<(DVec3, bool)>> = (0..cast_rows)
            .into_par_iter()
            .map(|i| {
                let mut from = starts[i];
                (0..cols)
                    .map(|j| {
                        let (f, w) = self.locate(layout.direction(i, j, rows, cols), from);
                        from = f;
                        let t = self.mesh.triangles[f];
                        let p = t
                            .iter()
                            .zip(w)
                            .map(|(&k, x)| self.mesh.positions[k as usize] * x)
                            .sum::<DVec3>();
                        (p, self.mesh.filled[f])
                    })
                    .collect()
            })
            .collect();
        let mut texels: Vec<DVec3> = rows_of.iter().flatten().map(|x| x.0).collect();
        let mut filled: Vec<bool> = rows_of.iter().flatten().map(|x| x.1).collect();
        if let Some(mirror) = &mirror {
            crate::spherical::complete_by_symmetry(&mut texels, rows, cols, mirror);
            crate::spherical::complete_by_symmetry(&mut filled, rows, cols, mirror);
        }
        let distinct = match layout {
            Layout::Sphere | Layout::FlatOctahedron => rows / 2 * cols,
            Layout::Octahedron => rows * cols,
        };
        let filled_fraction =
            filled[..distinct].iter().filter(|&&f| f).count() as f64 / distinct as f64;
        Ok(ParamImage {
            image: GeometryImage::try_new(rows, cols, texels)?,
            filled,
            filled_fraction,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The analytic gradient and Hessian of a face's energy against central differences.
    #[test]
    fn face_energy_derivatives_match_differences() {
        let a = DVec3::new(0.1, 0.05, 1.0).normalize();
        let b = DVec3::new(0.4, 0.0, 1.0).normalize();
        let c = DVec3::new(0.1, 0.35, 1.0).normalize();
        let (area, l2, shape) = (0.7, [0.9, 1.3, 0.6], 0.2);
        let (e, g, hess) = face_energy_grad(a, b, c, area, l2, shape);
        assert!((e - face_energy(a, b, c, area, l2, shape)).abs() < 1e-12 * e, "energy");
        let h = 1e-6;
        for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
            let (ep, gp, _) = face_energy_grad(a + h * axis, b, c, area, l2, shape);
            let (em, gm, _) = face_energy_grad(a - h * axis, b, c, area, l2, shape);
            let dg = (ep - em) / (2.0 * h);
            assert!(
                (dg - g.dot(axis)).abs() < 1e-6 * g.length(),
                "gradient along {axis}: {dg} vs {}",
                g.dot(axis)
            );
            let dh = (gp - gm) / (2.0 * h);
            let column = hess * axis;
            assert!(
                (dh - column).length() < 1e-5 * column.length().max(1.0),
                "Hessian column {axis}: {dh} vs {column}"
            );
        }
        // Wound the wrong way: infinite.
        assert_eq!(face_energy(a, c, b, area, l2, shape), f64::INFINITY);
    }

    /// A map whose triangles keep the surface's shape and have areas in proportion has
    /// stretch efficiency 1.
    #[test]
    fn uniform_stretch_has_efficiency_one() {
        // The regular octahedron on the unit sphere is its own map.
        let p = [DVec3::X, DVec3::Y, DVec3::Z, DVec3::NEG_X, DVec3::NEG_Y, DVec3::NEG_Z];
        let t = vec![
            [0, 1, 2],
            [1, 3, 2],
            [3, 4, 2],
            [4, 0, 2],
            [1, 0, 5],
            [3, 1, 5],
            [4, 3, 5],
            [0, 4, 5],
        ];
        let mesh = ClosedMesh {
            positions: p.iter().map(|x| *x * 3.0).collect(),
            triangles: t,
            scan_vertex: (0..6).collect(),
            filled: vec![false; 8],
            repair: hi_scan::repair::Repair::default(),
        };
        let q = measure(&mesh, &p, 0, 0);
        assert!((q.stretch_efficiency - 1.0).abs() < 1e-12, "{q:?}");
        assert!((q.area_ratio - 1.0).abs() < 1e-12, "{q:?}");
        assert_eq!(q.folded_triangles, 0);
    }
}
