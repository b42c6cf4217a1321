// SPDX-License-Identifier: MIT
//! The stretch energy of the map and its relaxation (step 4 of the module documentation of
//! `sphereparam`): Newton steps on the sphere, vertex by vertex, by colour classes in parallel.

use glam::{DMat3, DVec3};
use hi_par::*;

use super::simplify::Hierarchy;

/// The weight of the shape term against the stretch (see [`face_energy`]).
pub(super) const SHAPE_WEIGHT: f64 = 0.1;

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
pub(super) fn face_energy(
    a: DVec3,
    b: DVec3,
    c: DVec3,
    area: f64,
    l2: [f64; 3],
    shape: f64,
) -> f64 {
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
pub(super) fn face_energy_grad(
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
// Relaxing the vertices.

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
pub(super) fn relax_vertex(h: &Hierarchy, sphere: &[DVec3], v: u32) -> Option<(DVec3, f64)> {
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

/// Sweeps of stretch relaxation over the alive vertices: Gauss–Seidel by colour classes (no
/// two neighbours share a colour, so each class moves in parallel, every vertex against its
/// neighbours' latest positions).
pub(super) fn relax(h: &Hierarchy, sphere: &mut [DVec3], sweeps: usize) {
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
