// SPDX-License-Identifier: MIT
//! The masks of each scheme: the stencil of each rule, read off one step on a mesh that
//! holds it, and its formula.

use std::f64::consts::PI;

use anyhow::{Context, Result, ensure};
use glam::DVec2;
use hi_mesh::subdivision::{LoopWeights, Scheme};

use super::formulas::{butterfly_weights, labsik_greiner, loop_beta, sqrt3_alpha};
use super::library::{Mask, Step, mask, ring_layout};
use super::meshes::{Sample, cone, quad_torus, tri_grid, tri_torus};
use super::{LOOP, TORUS};

/// Loop's vertex mask for valence `n` with `weights`.
pub(super) fn loop_vertex(weights: LoopWeights, n: u32) -> Result<Mask> {
    let (mesh, v) = if n == 6 {
        let s = tri_torus()?;
        (s.mesh, s.centre)
    } else {
        cone(n, false)?
    };
    let step = Step::new(Scheme::Loop(weights), &mesh)?;
    let new = step.vertex_point(&mesh, v)?;
    let beta = loop_beta(weights, n);
    let mut expected = vec![(v, DVec2::ZERO, 1.0 - f64::from(n) * beta)];
    expected.extend(ring_layout(&mesh, v).into_iter().map(|(r, p)| (r, p, beta)));
    mask(&step, &mesh, new, &expected, DVec2::ZERO, &format!("Loop vertex mask, n = {n}"))
}

/// Loop's edge mask, on the torus.
pub(super) fn loop_edge() -> Result<Mask> {
    let s = tri_torus()?;
    let h = 3.0_f64.sqrt() / 2.0;
    let spec = [
        ((0.0, 0.0), 3.0 / 8.0),
        ((1.0, 0.0), 3.0 / 8.0),
        ((0.5, h), 1.0 / 8.0),
        ((0.5, -h), 1.0 / 8.0),
    ];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(LOOP, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, 0.0), "Loop edge mask")
}

/// Loop's boundary masks (Hoppe et al. 1994) on a flat open patch: the vertex mask 3/4, 1/8,
/// 1/8 (the interior neighbours weigh 0), or, if `edge`, the edge mask 1/2, 1/2 (the opposite
/// vertex weighs 0).
pub(super) fn loop_boundary(edge: bool) -> Result<Mask> {
    let s = tri_grid(false)?;
    let y = -f64::from(TORUS / 2) * 3.0_f64.sqrt() / 2.0;
    let h = 3.0_f64.sqrt() / 2.0;
    let x0 = -y / 3.0_f64.sqrt();
    let spec: Vec<((f64, f64), f64)> = if edge {
        vec![((x0, y), 0.5), ((x0 + 1.0, y), 0.5), ((x0 + 0.5, y + h), 0.0)]
    } else {
        vec![
            ((x0, y), 0.75),
            ((x0 - 1.0, y), 0.125),
            ((x0 + 1.0, y), 0.125),
            ((x0 - 0.5, y + h), 0.0),
            ((x0 + 0.5, y + h), 0.0),
        ]
    };
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(LOOP, &s.mesh)?;
    ensure!(
        s.mesh.is_boundary_vertex(expected[0].0 as usize),
        "the patch's vertex is not on the boundary"
    );
    let (new, new_point) = if edge {
        (step.joined_to(&[expected[0].0, expected[1].0])?, DVec2::new(x0 + 0.5, y))
    } else {
        (step.vertex_point(&s.mesh, expected[0].0)?, DVec2::new(x0, y))
    };
    mask(&step, &s.mesh, new, &expected, new_point, "Loop boundary mask")
}

/// The stencil vertices drawn at the given layout positions, with their weights.
pub(super) fn at_layout(s: &Sample, spec: &[((f64, f64), f64)]) -> Result<Vec<(u32, DVec2, f64)>> {
    spec.iter()
        .map(|&((x, y), w)| {
            let p = DVec2::new(x, y);
            Ok((s.vertex_at(p)?, p, w))
        })
        .collect()
}

/// The regular 10-point butterfly mask (tension w = 0) on the torus.
pub(super) fn butterfly_regular() -> Result<Mask> {
    let s = tri_torus()?;
    let h = 3.0_f64.sqrt() / 2.0;
    let e = -1.0 / 16.0;
    let spec = [
        ((0.0, 0.0), 0.5),
        ((1.0, 0.0), 0.5),
        ((0.5, h), 1.0 / 8.0),
        ((0.5, -h), 1.0 / 8.0),
        ((-0.5, h), e),
        ((1.5, h), e),
        ((-0.5, -h), e),
        ((1.5, -h), e),
        ((-1.0, 0.0), 0.0),
        ((2.0, 0.0), 0.0),
    ];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(Scheme::Butterfly, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, 0.0), "regular butterfly mask")
}

/// The butterfly mask of an edge from a vertex of valence `k` ≠ 6 to a regular one.
pub(super) fn butterfly_extraordinary(k: u32) -> Result<Mask> {
    let (mesh, v) = cone(k, false)?;
    let ring = ring_layout(&mesh, v);
    let s = butterfly_weights(k);
    let step = Step::new(Scheme::Butterfly, &mesh)?;
    let new = step.joined_to(&[v, ring[0].0])?;
    let mut expected = vec![(v, DVec2::ZERO, 0.75)];
    expected.extend(ring.iter().zip(&s).map(|(&(r, p), &w)| (r, p, w)));
    mask(&step, &mesh, new, &expected, ring[0].1 / 2.0, &format!("butterfly mask, K = {k}"))
}

/// Kobbelt's √3 vertex mask for valence `n`.
pub(super) fn sqrt3_vertex(n: u32) -> Result<Mask> {
    let (mesh, v) = if n == 6 {
        let s = tri_torus()?;
        (s.mesh, s.centre)
    } else {
        cone(n, false)?
    };
    let step = Step::new(Scheme::Sqrt3, &mesh)?;
    let new = step.vertex_point(&mesh, v)?;
    let alpha = sqrt3_alpha(n);
    let mut expected = vec![(v, DVec2::ZERO, 1.0 - alpha)];
    expected.extend(ring_layout(&mesh, v).into_iter().map(|(r, p)| (r, p, alpha / f64::from(n))));
    mask(&step, &mesh, new, &expected, DVec2::ZERO, &format!("√3 vertex mask, n = {n}"))
}

/// Kobbelt's √3 face mask, on the torus.
pub(super) fn sqrt3_face() -> Result<Mask> {
    let s = tri_torus()?;
    let h = 3.0_f64.sqrt() / 2.0;
    let third = 1.0 / 3.0;
    let expected = at_layout(&s, &[((0.0, 0.0), third), ((1.0, 0.0), third), ((0.5, h), third)])?;
    let step = Step::new(Scheme::Sqrt3, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0, expected[2].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, h / 3.0), "√3 face mask")
}

/// The regular 12-point mask of Labsik and Greiner, on the torus.
pub(super) fn labsik_greiner_regular() -> Result<Mask> {
    let s = tri_torus()?;
    let h = 3.0_f64.sqrt() / 2.0;
    let (corner, tip, other) = (32.0 / 81.0, -1.0 / 81.0, -2.0 / 81.0);
    let spec = [
        ((0.0, 0.0), corner),
        ((1.0, 0.0), corner),
        ((0.5, h), corner),
        ((0.5, -h), tip),
        ((1.5, h), tip),
        ((-0.5, h), tip),
        ((-1.0, 0.0), other),
        ((-0.5, -h), other),
        ((2.0, 0.0), other),
        ((1.5, -h), other),
        ((1.0, 2.0 * h), other),
        ((0.0, 2.0 * h), other),
    ];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(Scheme::InterpolatingSqrt3, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0, expected[2].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, h / 3.0), "regular interpolating √3 mask")
}

/// The Labsik–Greiner mask of a face with one corner of valence `k` ≠ 6.
pub(super) fn labsik_greiner_extraordinary(k: u32) -> Result<Mask> {
    let (mesh, v) = cone(k, false)?;
    let ring = ring_layout(&mesh, v);
    let step = Step::new(Scheme::InterpolatingSqrt3, &mesh)?;
    let new = step.joined_to(&[v, ring[0].0, ring[1].0])?;
    // The face (v, r₀, r₁) lies about the direction π/K.
    let bisector = PI / f64::from(k);
    let mut expected = vec![(v, DVec2::ZERO, labsik_greiner(k, 0.0).0)];
    expected
        .extend(ring.iter().map(|&(r, p)| (r, p, labsik_greiner(k, p.y.atan2(p.x) - bisector).1)));
    let new_point = (ring[0].1 + ring[1].1) / 3.0;
    mask(&step, &mesh, new, &expected, new_point, &format!("interpolating √3 mask, K = {k}"))
}

/// The Catmull-Clark face mask of a quad of the torus.
pub(super) fn catmull_clark_face() -> Result<Mask> {
    let s = quad_torus()?;
    let spec = [((0.0, 0.0), 0.25), ((1.0, 0.0), 0.25), ((1.0, 1.0), 0.25), ((0.0, 1.0), 0.25)];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(Scheme::CatmullClark, &s.mesh)?;
    let corners: Vec<u32> = expected.iter().map(|e| e.0).collect();
    let new = step.in_faces_with(&corners)?;
    mask(&step, &s.mesh, new, &expected, DVec2::splat(0.5), "Catmull-Clark face mask")
}

/// The Catmull-Clark edge mask ¼(v + v′ + f + f′) on the torus: 3/8 at the ends, 1/16 at the
/// other corners of the two quads.
pub(super) fn catmull_clark_edge() -> Result<Mask> {
    let s = quad_torus()?;
    let o = 1.0 / 16.0;
    let spec = [
        ((0.0, 0.0), 0.375),
        ((1.0, 0.0), 0.375),
        ((0.0, 1.0), o),
        ((1.0, 1.0), o),
        ((0.0, -1.0), o),
        ((1.0, -1.0), o),
    ];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(Scheme::CatmullClark, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, 0.0), "Catmull-Clark edge mask")
}

/// The Catmull-Clark vertex mask (n − 2)/n·v + 1/n²·Σeᵢ + 1/n²·Σfᵢ for valence `n` among
/// quads: v weighs (n − 2)/n + 1/(4n), an edge neighbour 3/(2n²), a diagonal one 1/(4n²).
pub(super) fn catmull_clark_vertex(n: u32) -> Result<Mask> {
    let (mesh, v) = if n == 4 {
        let s = quad_torus()?;
        (s.mesh, s.centre)
    } else {
        cone(n, true)?
    };
    let nf = f64::from(n);
    let ring = ring_layout(&mesh, v);
    let mut expected = vec![(v, DVec2::ZERO, (nf - 2.0) / nf + 1.0 / (4.0 * nf))];
    for (i, &(e, p)) in ring.iter().enumerate() {
        expected.push((e, p, 3.0 / (2.0 * nf * nf)));
        let (e2, p2) = ring[(i + 1) % ring.len()];
        let quad = mesh
            .faces()
            .find(|f| f.len() == 4 && f.contains(&v) && f.contains(&e) && f.contains(&e2))
            .context("no quad between two neighbours")?;
        let at = quad.iter().position(|&c| c == v).context("the quad lost its corner")?;
        expected.push((quad[(at + 2) % 4], p + p2, 1.0 / (4.0 * nf * nf)));
    }
    let step = Step::new(Scheme::CatmullClark, &mesh)?;
    let new = step.vertex_point(&mesh, v)?;
    mask(&step, &mesh, new, &expected, DVec2::ZERO, &format!("Catmull-Clark vertex mask, n = {n}"))
}
