// SPDX-License-Identifier: MIT
//! Closest points on triangle meshes: the hierarchy against brute force over every triangle,
//! the nearest-vertex query against the same, and the fit's exact measurement against the
//! closed-form distance to a sphere.

use std::f64::consts::PI;

use glam::DVec3;
use hi_geomimage::Layout;
use hi_geomimage::closest::{NearMesh, TriangleBvh};
use hi_geomimage::distance::closest_point_on_triangle;
use hi_geomimage::fit::{ErrorMeasure, measure_fit};

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

#[test]
fn the_measurements_match_the_sphere() {
    // Points at known distances from the exact unit sphere: radius 1 + d.
    let golden = PI * (3.0 - 5f64.sqrt());
    let n = 4000;
    let offset = |k: usize| if k.is_multiple_of(2) { 0.01 } else { -0.02 };
    let points: Vec<DVec3> = (0..n)
        .map(|k| {
            let z = 1.0 - (2 * k + 1) as f64 / n as f64;
            let s = (1.0 - z * z).sqrt();
            let phi = k as f64 * golden;
            DVec3::new(s * phi.cos(), s * phi.sin(), z) * (1.0 + offset(k))
        })
        .collect();
    let sphere = hi_surface::sphere(1.0);
    let (exact, _) =
        measure_fit(&sphere, Layout::Sphere, None, &points, &[], ErrorMeasure::Exact).unwrap();
    // To the Hermite interpolation's error: h⁴/384 · |p⁗| for h = 1/192 of the parameter,
    // |p⁗| ≤ (2π)⁴ · 2 for the sphere's u and v: about 2·10⁻⁸.
    for (k, d) in exact.scan_to_surface.per_point.iter().enumerate() {
        assert!((d - offset(k).abs()).abs() < 2e-8, "point {k}: {d}");
    }
    // The fast measurement is to the mesh of the sphere, inside it by at most the sagitta of
    // its triangles: r²/2 for their circumradius r ≤ h/√2, h = 2π/192 the grid's spacing.
    let (fast, mesh) =
        measure_fit(&sphere, Layout::Sphere, None, &points, &[], ErrorMeasure::Fast).unwrap();
    let sagitta = (2.0 * PI / 192.0).powi(2) / 4.0;
    for (k, d) in fast.scan_to_surface.per_point.iter().enumerate() {
        assert!((d - offset(k).abs()).abs() <= sagitta, "point {k}: {d}");
    }
    // Surface → scan: the mesh's samples are on the sphere, the scan's points at most 0.02
    // off it and about 0.03 apart: within a spacing of the nearest.
    assert!(fast.surface_to_scan.max < 0.05, "{}", fast.surface_to_scan.max);
    assert!(mesh.mesh.n_triangles() > 0);
    assert!(measure_fit(&sphere, Layout::Sphere, None, &points, &[], ErrorMeasure::Off).is_err());
}
