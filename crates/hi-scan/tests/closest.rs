// SPDX-License-Identifier: MIT
//! Closest points on triangle meshes: the hierarchy against brute force over every triangle,
//! and the nearest-vertex query against the same.

use std::f64::consts::PI;

use glam::DVec3;
use hi_scan::closest::{NearMesh, TriangleBvh};
use hi_scan::distance::closest_point_on_triangle;

/// A deterministic pseudo-random sequence in [0, 1).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

fn brute(p: DVec3, v: &[DVec3], t: &[[u32; 3]]) -> f64 {
    t.iter()
        .map(|tri| {
            let [a, b, c] = tri.map(|k| v[k as usize]);
            closest_point_on_triangle(p, a, b, c).distance(p)
        })
        .fold(f64::INFINITY, f64::min)
}

/// A bumpy closed grid surface (a sphere-like u × v grid), with a few degenerate triangles.
fn bumpy_mesh(nu: usize, nv: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut v = Vec::new();
    for i in 0..=nu {
        for j in 0..nv {
            let (th, ph) = (PI * i as f64 / nu as f64, 2.0 * PI * j as f64 / nv as f64);
            let r = 1.0 + 0.2 * (3.0 * th).sin() * (4.0 * ph).cos();
            v.push(DVec3::new(r * th.sin() * ph.cos(), r * th.sin() * ph.sin(), r * th.cos()));
        }
    }
    let at = |i: usize, j: usize| (i * nv + j % nv) as u32;
    let mut t = Vec::new();
    for i in 0..nu {
        for j in 0..nv {
            t.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            t.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    (v, t)
}

#[test]
fn the_hierarchy_finds_the_closest_triangle() {
    let (v, t) = bumpy_mesh(30, 40);
    let bvh = TriangleBvh::try_new(&v, &t).unwrap();
    let mut seed = 7;
    for k in 0..2000 {
        // Near the mesh, inside it, far away, and exactly on vertices.
        let p = if k % 10 == 0 {
            v[k % v.len()]
        } else {
            let scale = [0.3, 1.0, 1.3, 10.0][k % 4];
            DVec3::new(lcg(&mut seed) - 0.5, lcg(&mut seed) - 0.5, lcg(&mut seed) - 0.5)
                * 2.0
                * scale
        };
        let c = bvh.closest(p);
        let want = brute(p, &v, &t);
        assert!(
            (c.distance - want).abs() <= 1e-12 * want.max(1.0),
            "{p}: {} vs {want}",
            c.distance
        );
        assert!((c.point.distance(p) - c.distance).abs() < 1e-12, "the point is at the distance");
        let [a, b, cc] = t[c.triangle as usize].map(|x| v[x as usize]);
        assert!(closest_point_on_triangle(p, a, b, cc).distance(c.point) < 1e-12, "its triangle");
    }
    assert!(TriangleBvh::try_new(&v, &[]).is_err());
    assert!(TriangleBvh::try_new(&v, &[[0, 1, 100_000]]).is_err());
    assert!(TriangleBvh::try_new(&[DVec3::NAN; 3], &[[0, 1, 2]]).is_err());
}

#[test]
fn the_nearest_vertex_query_is_exact_near_the_mesh() {
    let (v, t) = bumpy_mesh(30, 40);
    let near = NearMesh::try_new(&v, &t).unwrap();
    let mut seed = 11;
    let mut worst: f64 = 0.0;
    // Triangles of fair shape (the grid's rows near the poles are slivers, where the nearest
    // vertex can be a pole that none of the closest triangles has).
    for tri in t.iter().step_by(7).filter(|tri| tri.iter().all(|&x| v[x as usize].z.abs() < 0.8)) {
        // A point on the triangle, pushed off along its normal by up to a tenth of its size.
        let [a, b, c] = tri.map(|x| v[x as usize]);
        let (s, r) = (lcg(&mut seed), lcg(&mut seed));
        let (s, r) = if s + r > 1.0 { (1.0 - s, 1.0 - r) } else { (s, r) };
        let n = (b - a).cross(c - a).normalize_or_zero();
        let p =
            a + (b - a) * s + (c - a) * r + n * (0.1 * (lcg(&mut seed) - 0.5) * (b - a).length());
        let got = near.distance(p);
        let want = brute(p, &v, &t);
        assert!(got >= want - 1e-12, "never below the true distance");
        worst = worst.max(got - want);
    }
    assert!(worst < 1e-12, "exact for points near the mesh: off by {worst}");
}
