// SPDX-License-Identifier: MIT
//! Curved PN triangles (`TriangleMesh::curved`) against what is known of them: a sphere's
//! coarse mesh with the sphere's normals comes much nearer the sphere, flat faces stay flat,
//! creases stay closed, and the colours, UVs and legend follow.

use std::collections::HashMap;

use glam::{DVec2, DVec3};
use hi_mesh::{ColorMap, ColorScale, Palette, PolyMesh, TriangleMesh};

/// The unit sphere as a subdivided octahedron (`levels` midpoint splits, the new vertices
/// pushed onto the sphere), with the sphere's normals.
fn sphere(levels: usize) -> TriangleMesh {
    let octahedron = PolyMesh::octahedron();
    let mut p = octahedron.positions().to_vec();
    let mut t: Vec<[u32; 3]> = octahedron.faces().map(|f| [f[0], f[1], f[2]]).collect();
    for _ in 0..levels {
        let mut mid: HashMap<(u32, u32), u32> = HashMap::new();
        let mut split = |a: u32, b: u32, p: &mut Vec<DVec3>| {
            *mid.entry((a.min(b), a.max(b))).or_insert_with(|| {
                p.push(((p[a as usize] + p[b as usize]) / 2.0).normalize());
                (p.len() - 1) as u32
            })
        };
        let mut next = Vec::new();
        for [a, b, c] in t {
            let (ab, bc, ca) = (split(a, b, &mut p), split(b, c, &mut p), split(c, a, &mut p));
            next.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        t = next;
    }
    let n = p.clone();
    let uv = vec![DVec2::ZERO; p.len()];
    TriangleMesh::try_new(p, n, uv, t).unwrap()
}

/// The edges used by one triangle only.
fn open_edges(mesh: &TriangleMesh) -> usize {
    let mut count: HashMap<(u32, u32), usize> = HashMap::new();
    for t in mesh.triangles() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    count.values().filter(|&&c| c == 1).count()
}

#[test]
fn a_coarse_sphere_comes_near_the_sphere() {
    let coarse = sphere(2); // 128 triangles
    let level = 4;
    let curved = coarse.curved(level).unwrap();
    assert_eq!(curved.n_triangles(), coarse.n_triangles() * level * level);
    // The old vertices stay, first and in order.
    assert_eq!(&curved.positions()[..coarse.n_vertices()], coarse.positions());
    // The same tessellation of the flat triangles: its points' distance below the sphere
    // (the chord's sag) against the curved one's, both measured from the sphere itself.
    let flat_sag = coarse
        .triangles()
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|k| coarse.positions()[k as usize]);
            1.0 - ((a + b + c) / 3.0).length()
        })
        .fold(0.0, f64::max);
    let curved_error =
        curved.positions().iter().map(|q| (q.length() - 1.0).abs()).fold(0.0, f64::max);
    assert!(flat_sag > 0.03, "{flat_sag}");
    assert!(curved_error < flat_sag / 10.0, "curved {curved_error} against flat {flat_sag}");
    // The normals are near the sphere's too (its normal at q is q/|q|).
    let worst = curved
        .positions()
        .iter()
        .zip(curved.normals())
        .map(|(q, n)| q.normalize().dot(*n))
        .fold(1.0, f64::min);
    assert!(worst > 0.995, "{worst}");
    // Closed before, closed after: each edge's inner vertices are shared by its two triangles.
    assert_eq!(open_edges(&coarse), 0);
    assert_eq!(open_edges(&curved), 0);
    // V − E + F = 2 still.
    let (v, f) = (curved.n_vertices() as i64, curved.n_triangles() as i64);
    assert_eq!(v - 3 * f / 2 + f, 2);
}

#[test]
fn flat_faces_stay_flat_and_creases_stay_closed() {
    // A cube of 12 triangles whose faces have their own vertices (4 each) and normals: every
    // vertex is a crease vertex, every edge straight, every patch the face's plane.
    let mut p = Vec::new();
    let mut n = Vec::new();
    let mut t = Vec::new();
    for axis in 0..3 {
        for side in [-1.0, 1.0] {
            let normal =
                DVec3::from_array(std::array::from_fn(|k| if k == axis { side } else { 0.0 }));
            let (u, v) =
                (normal.any_orthonormal_vector(), normal.cross(normal.any_orthonormal_vector()));
            let base = p.len() as u32;
            for (a, b) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                p.push(normal + u * a + v * b);
                n.push(normal);
            }
            t.extend([[base, base + 1, base + 2], [base, base + 2, base + 3]]);
        }
    }
    let cube = TriangleMesh::try_new(p, n, vec![DVec2::ZERO; 24], t).unwrap();
    let curved = cube.curved(3).unwrap();
    for (q, normal) in curved.positions().iter().zip(curved.normals()) {
        // On the cube: one coordinate ±1, the others within [−1, 1], the normal its face's.
        assert!((q.abs().max_element() - 1.0).abs() < 1e-12, "{q}");
        assert!((normal.dot(*q) - 1.0).abs() < 1e-12, "{q} {normal}");
    }
    // Each of the cube's 12 edges is cut at the same two places from both its faces.
    let mut on_edges: Vec<[i64; 3]> = curved
        .positions()
        .iter()
        .filter(|q| q.abs().to_array().iter().filter(|c| (**c - 1.0).abs() < 1e-12).count() == 2)
        .map(|q| (*q * 3.0).round().to_array().map(|c| c as i64))
        .collect();
    on_edges.sort_unstable();
    on_edges.dedup();
    assert_eq!(on_edges.len(), 12 * 2, "two points inside each edge");
}

#[test]
fn colours_uvs_and_the_legend_follow() {
    let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y];
    let uv = vec![DVec2::ZERO, DVec2::X, DVec2::Y];
    let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 3], uv, vec![[0, 1, 2]]).unwrap();
    let map = ColorMap { scale: ColorScale::Magnitude, coverage: 1.0, palette: Palette::Viridis };
    let mapping = map.try_apply(&[0.0, 1.0, 2.0]).unwrap();
    let mesh = mesh.try_with_mapping(mapping).unwrap();
    let curved = mesh.curved(3).unwrap();
    assert_eq!((curved.n_vertices(), curved.n_triangles()), (10, 9));
    assert_eq!(curved.legend(), mesh.legend());
    let colors = curved.colors().unwrap();
    for ((q, uv), c) in curved.positions().iter().zip(curved.uvs()).zip(colors) {
        // A flat triangle with one normal stays itself, its UVs the positions' (u, v) = (x, y).
        assert!(q.z.abs() < 1e-15 && (q.truncate() - *uv).length() < 1e-15, "{q} {uv}");
        // Each channel is the corners' blended linearly.
        let [c0, c1, c2] = [0, 1, 2].map(|k| mesh.colors().unwrap()[k]);
        let (b1, b2) = (q.x, q.y);
        for i in 0..3 {
            let want =
                f64::from(c0[i]) * (1.0 - b1 - b2) + f64::from(c1[i]) * b1 + f64::from(c2[i]) * b2;
            assert!((f64::from(c[i]) - want).abs() < 1e-6, "{c:?}");
        }
    }
    // Every triangle keeps the winding (counter-clockwise about +z).
    for t in curved.triangles() {
        let [a, b, c] = t.map(|k| curved.positions()[k as usize]);
        assert!((b - a).cross(c - a).z > 0.0);
    }
}

#[test]
fn level_one_is_the_mesh_and_level_zero_an_error() {
    let mesh = sphere(1);
    let same = mesh.curved(1).unwrap();
    assert_eq!(same.positions(), mesh.positions());
    assert_eq!(same.triangles(), mesh.triangles());
    let message = mesh.curved(0).unwrap_err().to_string();
    assert!(message.contains("PN triangle level"), "{message}");
}

#[test]
fn opposite_normals_across_a_fold_still_give_unit_normals() {
    // Corner normals that cancel along an edge (a fold of a parameterisation): every new
    // vertex still has a unit normal (the mesh's own check), the nearest corner's where they
    // cancel.
    let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y];
    let n = vec![DVec3::Z, -DVec3::Z, DVec3::Z];
    let mesh = TriangleMesh::try_new(p, n, vec![DVec2::ZERO; 3], vec![[0, 1, 2]]).unwrap();
    let curved = mesh.curved(4).unwrap();
    assert!(curved.normals().iter().all(|n| (n.length() - 1.0).abs() < 1e-9));
    assert_eq!(curved.n_triangles(), 16);
}
