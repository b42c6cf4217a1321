// SPDX-License-Identifier: MIT
//! One step drawn: the notation of Loop subdivision (figure 4.8) and how Loop, √3 and
//! Catmull-Clark split the faces (figures 4.9, 4.19, 4.24).

use std::collections::BTreeSet;
use std::f64::consts::PI;

use anyhow::{Context, Result};
use glam::{DVec2, DVec3};
use hi_mesh::subdivision::{PolyMesh, Scheme};

use super::super::plot::{
    BLUE, GREEN, GREY, INK, Legend, Marker, ORANGE, Pen, Plot, VERMILION, clear_of_point,
    render_row, sub,
};
use super::LOOP;
use super::library::Step;
use super::meshes::{edges, quad_torus, tri_torus};

/// Figure 4.8: the notation of Loop subdivision, before and after one step on a fan of n = 6
/// triangles.
pub(super) fn notation(title: &str) -> Result<Vec<u8>> {
    const N: u32 = 6;
    let mut positions = vec![DVec3::ZERO];
    positions.extend((0..N).map(|k| {
        let (s, c) = (2.0 * PI * f64::from(k) / f64::from(N)).sin_cos();
        DVec3::new(c, s, 0.0)
    }));
    let faces: Vec<[u32; 3]> = (0..N).map(|k| [0, 1 + k, 1 + (k + 1) % N]).collect();
    let fan = PolyMesh::try_new(positions, &faces)?;
    let refined = LOOP.step(&fan)?;
    let step = Step { n_old: fan.n_vertices(), refined: refined.clone(), rows: Vec::new() };
    let flat = |p: &DVec3| p.truncate();
    let ring_name = |base: &str, k: u32, sup: &str| {
        if k == N - 1 {
            format!("{base}ₙ₋₁{sup}")
        } else {
            format!("{}{sup}", sub(base, k as usize))
        }
    };

    let old: Vec<DVec2> = fan.positions().iter().map(flat).collect();
    let mut before = Plot::projection("(a) xᵏ and its neighbours yᵢᵏ");
    for [a, b] in edges(fan.faces()) {
        before =
            before.curve(vec![old[a as usize], old[b as usize]], Pen::solid(GREY).width(1.0), None);
    }
    before = before.points(&old, Marker::point(INK), None).note(old[0], "xᵏ", (14.0, 12.0), INK);
    for k in 0..N {
        let p = old[1 + k as usize];
        before = before.note(p, &ring_name("y", k, "ᵏ"), (22.0 * p.x, 18.0 * p.y), INK);
    }

    let new: Vec<DVec2> = refined.positions().iter().map(flat).collect();
    let mut after = Plot::projection("(b) after one step: xᵏ⁺¹ and the edge points xᵢᵏ⁺¹");
    for [a, b] in edges(refined.faces()) {
        after =
            after.curve(vec![new[a as usize], new[b as usize]], Pen::solid(GREY).width(1.0), None);
    }
    let mut named = vec![new[0]];
    after = after.note(new[0], "xᵏ⁺¹", (16.0, 12.0), VERMILION);
    for k in 0..N {
        let e = step.joined_to(&[0, 1 + k])?;
        let p = new[e];
        named.push(p);
        // Between the spoke through the point and the next (the spoke itself runs on outward).
        let d = DVec2::from_angle(PI / f64::from(N)).rotate(p.normalize_or_zero());
        let name = ring_name("x", k, "ᵏ⁺¹");
        let off = clear_of_point(DVec2::new(d.x, -d.y), name.chars().count());
        after = after.note(p, &name, (off.x, -off.y), VERMILION);
    }
    let others: Vec<DVec2> =
        new.iter().copied().filter(|p| !named.iter().any(|q| q.distance(*p) < 1e-12)).collect();
    after = after.points(&others, Marker::small(GREY), None).points(
        &named,
        Marker::point(VERMILION),
        None,
    );
    render_row(title, &[&before, &after])
}

/// Which face split [`split`] draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum SplitKind {
    /// Loop's 1 → 4 split (figure 4.9).
    Loop,
    /// The √3 split and flip (figure 4.19).
    Sqrt3,
    /// Catmull-Clark's split of each k-gon into k quads (figure 4.24).
    CatmullClark,
}

/// Stage `stage` of the face split of figures 4.9, 4.19 and 4.24 on a window of a torus: 0 the
/// mesh, 1 with the new points, then (√3) the face points joined to the corners and the
/// library's refined mesh, or (Loop, Catmull-Clark) the library's refined mesh.
pub(super) fn split(title: &str, kind: SplitKind, stage: u32) -> Result<Vec<u8>> {
    let (sample, scheme, radius) = match kind {
        SplitKind::Loop => (tri_torus()?, LOOP, 1.0),
        SplitKind::Sqrt3 => (tri_torus()?, Scheme::Sqrt3, 2.0),
        SplitKind::CatmullClark => (quad_torus()?, Scheme::CatmullClark, 2.0_f64.sqrt()),
    };
    let mesh = &sample.mesh;
    let inside = |v: u32| sample.layout[v as usize].length() <= radius + 1e-9;
    let window: Vec<Vec<u32>> =
        mesh.faces().filter(|f| f.iter().all(|&v| inside(v))).map(<[u32]>::to_vec).collect();
    let step = Step { n_old: mesh.n_vertices(), refined: scheme.step(mesh)?, rows: Vec::new() };
    let old_edges = edges(window.iter().map(Vec::as_slice));

    // The new vertices of the window and where they are drawn.
    let (face_points, edge_points) =
        split_points(kind, &sample.layout, &window, &old_edges, &step)?;
    let old_vertices: BTreeSet<u32> = window.iter().flatten().copied().collect();
    let mut drawn_at = vec![None; step.refined.n_vertices()];
    for &v in &old_vertices {
        drawn_at[v as usize] = Some(sample.layout[v as usize]);
    }
    for &(w, p) in face_points.iter().chain(&edge_points) {
        drawn_at[w] = Some(p);
    }

    let old_at: Vec<DVec2> = old_vertices.iter().map(|&v| sample.layout[v as usize]).collect();
    let face_at: Vec<DVec2> = face_points.iter().map(|f| f.1).collect();
    let edge_at: Vec<DVec2> = edge_points.iter().map(|e| e.1).collect();
    let segment = |[a, b]: [u32; 2], at: &dyn Fn(u32) -> Option<DVec2>| -> Option<Vec<DVec2>> {
        Some(vec![at(a)?, at(b)?])
    };
    let old_pos = |v: u32| Some(sample.layout[v as usize]);
    let new_pos = |v: u32| drawn_at[v as usize];
    let mut plot = Plot::projection(title);
    let last = if kind == SplitKind::Sqrt3 { 3 } else { 2 };
    if stage < last {
        for e in &old_edges {
            plot = plot.curve(
                segment(*e, &old_pos).context("an old edge")?,
                Pen::solid(INK).width(1.0),
                None,
            );
        }
    }
    if kind == SplitKind::Sqrt3 && stage == 2 {
        plot = sqrt3_joins(plot, &face_points, &window, &sample.layout);
    }
    if stage == last {
        if kind == SplitKind::Sqrt3 {
            for e in &old_edges {
                plot = plot.polygon(&segment(*e, &old_pos).context("an old edge")?, false);
            }
        }
        let kept =
            step.refined.faces().filter(|f| f.iter().all(|&v| drawn_at[v as usize].is_some()));
        for e in edges(kept) {
            plot = plot.curve(
                segment(e, &new_pos).context("a new edge")?,
                Pen::solid(BLUE).width(1.0),
                None,
            );
        }
    }
    plot = plot.points(&old_at, Marker::point(INK), None);
    if stage >= 1 {
        plot = split_markers(plot, kind, &old_at, &face_at, &edge_at);
    }
    plot.render()
}

/// New vertices of the refined mesh, each with where [`split`] draws it.
type Placed = Vec<(usize, DVec2)>;

/// The new points of [`split`] in the `window` of faces of a mesh drawn at `layout`, each
/// with where it is drawn: the face points (√3, Catmull-Clark) at their face's centroid, and
/// the edge points (Loop, Catmull-Clark) at the midpoints of the `old_edges`.
fn split_points(
    kind: SplitKind,
    layout: &[DVec2],
    window: &[Vec<u32>],
    old_edges: &BTreeSet<[u32; 2]>,
    step: &Step,
) -> Result<(Placed, Placed)> {
    let mut face_points = Vec::new();
    let mut edge_points = Vec::new();
    for f in window {
        let centroid = f.iter().map(|&v| layout[v as usize]).sum::<DVec2>() / f.len() as f64;
        match kind {
            SplitKind::Loop => {}
            SplitKind::Sqrt3 => face_points.push((step.joined_to(f)?, centroid)),
            SplitKind::CatmullClark => face_points.push((step.in_faces_with(f)?, centroid)),
        }
    }
    if kind != SplitKind::Sqrt3 {
        for [a, b] in old_edges {
            let mid = (layout[*a as usize] + layout[*b as usize]) / 2.0;
            edge_points.push((step.joined_to(&[*a, *b])?, mid));
        }
    }
    Ok((face_points, edge_points))
}

/// `plot` with each √3 face point joined to the corners of its face of the `window` (drawn
/// at `layout`).
fn sqrt3_joins(
    mut plot: Plot,
    face_points: &[(usize, DVec2)],
    window: &[Vec<u32>],
    layout: &[DVec2],
) -> Plot {
    for &(_, c) in face_points {
        for f in window {
            let centroid = f.iter().map(|&v| layout[v as usize]).sum::<DVec2>() / 3.0;
            if centroid.distance(c) < 1e-12 {
                for &v in f {
                    plot =
                        plot.curve(vec![c, layout[v as usize]], Pen::solid(BLUE).width(1.0), None);
                }
            }
        }
    }
    plot
}

/// `plot` with the new points of [`split`] marked: the vertex points (Catmull-Clark), the face
/// points and the edge points, with a legend for Catmull-Clark.
fn split_markers(
    mut plot: Plot,
    kind: SplitKind,
    old_at: &[DVec2],
    face_at: &[DVec2],
    edge_at: &[DVec2],
) -> Plot {
    let cc = kind == SplitKind::CatmullClark;
    if cc {
        plot = plot.points(old_at, Marker::ring(VERMILION), Some("vertex points"));
    }
    if !face_at.is_empty() {
        plot = plot.points(face_at, Marker::point(GREEN), cc.then_some("face points"));
    }
    if !edge_at.is_empty() {
        let color = if cc { ORANGE } else { VERMILION };
        plot = plot.points(edge_at, Marker::point(color), cc.then_some("edge points"));
    }
    if cc {
        plot = plot.legend(Legend::UpperRight);
    }
    plot
}
