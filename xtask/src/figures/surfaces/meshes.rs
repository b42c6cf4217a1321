// SPDX-License-Identifier: MIT
//! Meshing the surfaces: a parametric surface by its derivatives, a control grid as a closed
//! quad mesh, and markers (small balls) at points.

use anyhow::{Result, ensure};
use glam::{DVec2, DVec3};
use hi_mesh::subdivision::PolyMesh;
use hi_mesh::{TriangleMesh, srgb_to_linear_rgb};
use hi_surface::{HarmonicSurface, ParamRange, ParamWindow, SurfaceDerivs};

use super::{MARKER_SRGB, SURFACE_SRGB};

/// A triangle mesh of a parametric surface, given by its derivatives, over `window` with
/// `n_u`×`n_v` quads (see the module notes), and the parameters (u, v) of its vertices.
pub(super) fn parametric_mesh(
    derivs: &dyn Fn(f64, f64) -> SurfaceDerivs,
    scale: f64,
    window: ParamWindow,
    (n_u, n_v): (usize, usize),
) -> Result<(TriangleMesh, Vec<DVec2>)> {
    let ParamWindow { u: ParamRange { start: u0, end: u1 }, v: ParamRange { start: v0, end: v1 } } =
        window;
    let cols = n_v + 1;
    let mut params = Vec::with_capacity((n_u + 1) * cols);
    for i in 0..=n_u {
        for l in 0..=n_v {
            params.push(DVec2::new(
                u0 + (u1 - u0) * i as f64 / n_u as f64,
                v0 + (v1 - v0) * l as f64 / n_v as f64,
            ));
        }
    }
    let samples: Vec<SurfaceDerivs> = params.iter().map(|t| derivs(t.x, t.y)).collect();
    let size = samples.iter().map(|d| d.p.length()).fold(scale, f64::max);
    let tol = 1e-9 * size;
    let at = |i: usize, l: usize| (i * cols + l) as u32;
    let position = |k: u32| samples[k as usize].p;
    let mut triangles = Vec::with_capacity(2 * n_u * n_v);
    for i in 0..n_u {
        for l in 0..n_v {
            let (a, b, c, d) = (at(i, l), at(i + 1, l), at(i + 1, l + 1), at(i, l + 1));
            for t in [[a, b, c], [a, c, d]] {
                let [pa, pb, pc] = t.map(position);
                if pa.distance(pb) > tol && pb.distance(pc) > tol && pa.distance(pc) > tol {
                    triangles.push(t);
                }
            }
        }
    }
    // Keep the vertices triangles use, in grid order.
    let mut new_index = vec![u32::MAX; samples.len()];
    for &k in triangles.iter().flatten() {
        new_index[k as usize] = 0;
    }
    let mut used = Vec::with_capacity(samples.len());
    for (k, slot) in new_index.iter_mut().enumerate() {
        if *slot == 0 {
            *slot = used.len() as u32;
            used.push(k);
        }
    }
    let positions: Vec<DVec3> = used.iter().map(|&k| samples[k].p).collect();
    // The area-weighted normal of the triangles at each vertex: a vertex normal points to its
    // side (where the parameterisation folds, ∂u × ∂v turns against the triangles' winding,
    // and a renderer would shade those triangles from behind).
    let mut winding = vec![DVec3::ZERO; samples.len()];
    for t in &triangles {
        let [a, b, c] = t.map(position);
        let n = (b - a).cross(c - a);
        for &k in t {
            winding[k as usize] += n;
        }
    }
    let normals: Vec<DVec3> = used
        .iter()
        .map(|&k| {
            let n = samples[k].normal(scale).unwrap_or_else(|| {
                // The sum of the normals of the triangles at this point.
                let here = samples[k].p;
                let sum: DVec3 = triangles
                    .iter()
                    .filter(|t| t.iter().any(|&g| position(g).distance(here) <= tol))
                    .map(|t| {
                        let [a, b, c] = t.map(position);
                        (b - a).cross(c - a)
                    })
                    .sum();
                sum.try_normalize().unwrap_or(DVec3::Z)
            });
            if n.dot(winding[k]) < 0.0 { -n } else { n }
        })
        .collect();
    let uvs: Vec<DVec2> = used
        .iter()
        .map(|&k| DVec2::new((k / cols) as f64 / n_u as f64, (k % cols) as f64 / n_v as f64))
        .collect();
    let triangles: Vec<[u32; 3]> =
        triangles.into_iter().map(|t| t.map(|k| new_index[k as usize])).collect();
    let params = used.iter().map(|&k| params[k]).collect();
    Ok((TriangleMesh::try_new(positions, normals, uvs, triangles)?, params))
}

/// The control grid of `surface` as a closed mesh: each quad split into two triangles,
/// area-weighted face normals, UVs (j/m, k/n).
pub(super) fn control_mesh(surface: &HarmonicSurface<DVec3>) -> Result<TriangleMesh> {
    let (m, n) = (surface.m(), surface.n());
    let at = |j: usize, k: usize| ((j % m) * n + k % n) as u32;
    let positions = surface.points().to_vec();
    let mut triangles = Vec::with_capacity(2 * m * n);
    for j in 0..m {
        for k in 0..n {
            let (a, b, c, d) = (at(j, k), at(j + 1, k), at(j + 1, k + 1), at(j, k + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    let mut sums = vec![DVec3::ZERO; positions.len()];
    for t in &triangles {
        let [a, b, c] = t.map(|k| positions[k as usize]);
        let face = (b - a).cross(c - a);
        for &k in t {
            sums[k as usize] += face;
        }
    }
    let normals = sums.into_iter().map(|s| s.try_normalize().unwrap_or(DVec3::Z)).collect();
    let uvs = (0..m * n).map(|g| DVec2::new((g / n) as f64 / m as f64, (g % n) as f64 / n as f64));
    Ok(TriangleMesh::try_new(positions, normals, uvs.collect(), triangles)?)
}

/// `mesh` with a small red ball of radius `radius` at each of the distinct `points`;
/// the mesh keeps its colours, or becomes light grey if it had none.
pub(super) fn with_markers(
    mesh: &TriangleMesh,
    points: &[DVec3],
    radius: f64,
) -> Result<TriangleMesh> {
    let mut positions = mesh.positions().to_vec();
    let mut normals = mesh.normals().to_vec();
    let mut uvs = mesh.uvs().to_vec();
    let mut triangles = mesh.triangles().to_vec();
    let mut colors = mesh.colors().map_or_else(
        || vec![srgb_to_linear_rgb(SURFACE_SRGB); mesh.n_vertices()],
        <[[f32; 3]]>::to_vec,
    );
    push_balls(
        (&mut positions, &mut normals, &mut uvs, &mut triangles, &mut colors),
        points,
        radius,
        MARKER_LEVELS,
    )?;
    Ok(TriangleMesh::try_new(positions, normals, uvs, triangles)?.try_with_colors(colors)?)
}

/// Data points drawn alone as small red octahedra ("beads", [`BEAD_LEVELS`]) of `radius`, one
/// per distinct point.
///
/// # Errors
///
/// If there is no point or more than 2³² corners.
pub(crate) fn beads(points: &[DVec3], radius: f64) -> Result<TriangleMesh> {
    let mut parts = (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    push_balls(
        (&mut parts.0, &mut parts.1, &mut parts.2, &mut parts.3, &mut parts.4),
        points,
        radius,
        BEAD_LEVELS,
    )?;
    let (positions, normals, uvs, triangles, colors) = parts;
    ensure!(!triangles.is_empty(), "no points to draw");
    Ok(TriangleMesh::try_new(positions, normals, uvs, triangles)?.try_with_colors(colors)?)
}

/// The parts of a mesh being built: positions, normals, UVs, triangles and colours.
type Parts<'a> = (
    &'a mut Vec<DVec3>,
    &'a mut Vec<DVec3>,
    &'a mut Vec<DVec2>,
    &'a mut Vec<[u32; 3]>,
    &'a mut Vec<[f32; 3]>,
);

/// The unit ball the renders of point sets draw each point as: [`geodesic`] cut twice — 66
/// vertices, 128 faces, a 16-sided outline, round at the few pixels a point covers.
pub(crate) fn ball() -> (Vec<DVec3>, Vec<[u32; 3]>) {
    geodesic(2)
}

/// How many times the markers' balls are cut ([`geodesic`]): once — 18 vertices, 32 faces, an
/// 8-sided outline under smooth normals, a third of the file size of [`ball`]'s.
const MARKER_LEVELS: u32 = 1;

/// How many times the beads' balls are cut: not at all (octahedra). A bead model holds
/// thousands of them, drawn a few pixels wide; cut once, the models of 5.7–5.9 alone would
/// take 1.4 MB more of the figures' 60 MB.
const BEAD_LEVELS: u32 = 0;

/// The octahedron (`PolyMesh::octahedron`) with its edges halved `levels` times (each face cut into 4 each time) and
/// every vertex pushed out to the unit sphere, its faces wound outwards.
pub(crate) fn geodesic(levels: u32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let octahedron = PolyMesh::octahedron();
    let mut vertices = octahedron.positions().to_vec();
    let mut faces: Vec<[u32; 3]> = octahedron.faces().map(|f| [f[0], f[1], f[2]]).collect();
    for _ in 0..levels {
        // Each edge's midpoint once, keyed by its ends.
        let mut middles = std::collections::BTreeMap::new();
        let mut middle = |a: u32, b: u32, vertices: &mut Vec<DVec3>| {
            *middles.entry((a.min(b), a.max(b))).or_insert_with(|| {
                vertices.push((vertices[a as usize] + vertices[b as usize]).normalize());
                (vertices.len() - 1) as u32
            })
        };
        faces = faces
            .iter()
            .flat_map(|&[a, b, c]| {
                let (ab, bc, ca) = (
                    middle(a, b, &mut vertices),
                    middle(b, c, &mut vertices),
                    middle(c, a, &mut vertices),
                );
                [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
            })
            .collect();
    }
    (vertices, faces)
}

/// Appends a red ball ([`geodesic`] cut `levels` times) of `radius` at each distinct point of
/// `points` (points within a thousandth of the radius of one already drawn are drawn once).
fn push_balls(
    (positions, normals, uvs, triangles, colors): Parts<'_>,
    points: &[DVec3],
    radius: f64,
    levels: u32,
) -> Result<()> {
    let mut distinct: Vec<DVec3> = Vec::new();
    for &p in points {
        if distinct.iter().all(|q| q.distance(p) > 1e-3 * radius) {
            distinct.push(p);
        }
    }
    let (unit, faces) = geodesic(levels);
    for p in distinct {
        let base = u32::try_from(positions.len())?;
        for &e in &unit {
            positions.push(p + radius * e);
            normals.push(e);
            uvs.push(DVec2::ZERO);
            colors.push(srgb_to_linear_rgb(MARKER_SRGB));
        }
        triangles.extend(faces.iter().map(|f| f.map(|i| base + i)));
    }
    Ok(())
}
