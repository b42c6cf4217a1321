// SPDX-License-Identifier: MIT
//! Fit-quality distances against geometry whose distances are known: closest points on
//! triangles against a brute-force search, points near the exact harmonic sphere, points
//! near a cube mesh, an icosphere against the sphere, and the fit's measurements (fast and
//! exact) against the closed-form distance to the sphere.

use glam::DVec3;
use hi_geomimage::Layout;
use hi_geomimage::distance::{distances_to_surface, hausdorff};
use hi_geomimage::fit::{ErrorMeasure, measure_fit};
use hi_scan::distance::{bounding_diagonal, closest_point_on_triangle, distances_to_mesh};

mod common;

/// A small deterministic generator (xorshift), so the test needs no dependency.
struct Rng(u64);

impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn point(&mut self, scale: f64) -> DVec3 {
        DVec3::new(self.uniform() - 0.5, self.uniform() - 0.5, self.uniform() - 0.5) * scale
    }
}

#[test]
fn closest_points_match_a_brute_force_search() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for _ in 0..200 {
        let (a, b, c) = (rng.point(2.0), rng.point(2.0), rng.point(2.0));
        let p = rng.point(4.0);
        let q = closest_point_on_triangle(p, a, b, c);
        // The closest point must lie on the triangle and be no farther than any point of a
        // dense barycentric grid over it.
        let steps = 300;
        let mut best = f64::INFINITY;
        for i in 0..=steps {
            for j in 0..=steps - i {
                let (s, t) = (f64::from(i) / f64::from(steps), f64::from(j) / f64::from(steps));
                best = best.min((a + (b - a) * s + (c - a) * t).distance(p));
            }
        }
        let d = q.distance(p);
        assert!(d <= best + 1e-12, "closest {d} but the grid found {best}");
        let spacing = (b - a).length().max((c - a).length()) / f64::from(steps);
        assert!(best - d < spacing, "grid {best} is much farther than {d}");
        let n = (b - a).cross(c - a).normalize();
        assert!((q - a).dot(n).abs() < 1e-12, "the closest point lies in the triangle's plane");
    }
}

/// How far the triangulated 128 × 128 samples of the unit harmonic sphere can be from it.
fn sag() -> f64 {
    1.0 - (2f64.sqrt() * std::f64::consts::PI / 128.0).cos()
}

#[test]
fn points_near_the_harmonic_sphere() {
    let sphere = hi_surface::sphere(1.0);
    let mut rng = Rng(42);
    let points: Vec<DVec3> = (0..500)
        .map(|_| {
            let d = rng.point(2.0).normalize();
            d * (0.5 + rng.uniform())
        })
        .collect();
    let got = distances_to_surface(&sphere, &points, 32).unwrap();
    for (p, d) in points.iter().zip(&got.per_point) {
        let exact = (p.length() - 1.0).abs();
        // 128 × 128 samples over the doubled sphere, 2π/128 apart in both angles: a
        // triangle's diagonal spans at most √2·2π/128 of arc and sags by 1 − cos(√2·π/128).
        assert!((d - exact).abs() < sag(), "|p| = {}: {d} against {exact}", p.length());
    }
    assert!((got.diagonal - bounding_diagonal(&points)).abs() < 1e-15);
    let n = points.len() as f64;
    let mean: f64 = got.per_point.iter().sum::<f64>() / n;
    assert!((got.mean - mean).abs() < 1e-15);
    assert!(got.max >= got.rms && got.rms >= got.mean);
}

/// The unit cube [0, 1]³ as 12 outward triangles.
fn cube() -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let v = (0..8)
        .map(|k| DVec3::new(f64::from(k & 1), f64::from((k >> 1) & 1), f64::from(k >> 2)))
        .collect();
    let quads =
        [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let t = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
    (v, t)
}

#[test]
fn points_near_a_cube() {
    let (v, t) = cube();
    let points = [
        DVec3::new(0.5, 0.5, 1.25),  // above the top face: 0.25
        DVec3::new(0.5, 0.5, 0.5),   // the centre: 0.5 to every face
        DVec3::new(2.0, 2.0, 2.0),   // beyond a corner: √3
        DVec3::new(0.5, -1.0, -1.0), // beyond an edge: √2
        DVec3::new(0.3, 0.0, 0.7),   // on a face
    ];
    let d = distances_to_mesh(&points, &v, &t).unwrap();
    let exact = [0.25, 0.5, 3f64.sqrt(), 2f64.sqrt(), 0.0];
    for (got, want) in d.per_point.iter().zip(exact) {
        assert!((got - want).abs() < 1e-15, "{got} against {want}");
    }
    assert!((d.diagonal - 3f64.sqrt()).abs() < 1e-15);
    assert!(distances_to_mesh(&points, &v, &[]).is_err());
    assert!(distances_to_mesh(&points, &v, &[[0, 1, 8]]).is_err());
    assert!(distances_to_mesh(&[DVec3::NAN], &v, &t).is_err());
}

#[test]
fn an_icosphere_against_the_sphere() {
    // The icosahedron, each face split in 4 twice, vertices pushed onto the unit sphere.
    let (v, t) = common::icosphere(2, 1.0);
    let h = hausdorff(&hi_surface::sphere(1.0), &v, &t, 32).unwrap();
    // The vertices lie on the sphere: only the sampling error of the surface remains.
    assert!(h.scan_to_surface.max < sag(), "{}", h.scan_to_surface.max);
    // The sphere bulges out of each flat face by at most 1 − (distance of the face's plane
    // from the centre), largest over the faces.
    let sag = t
        .iter()
        .map(|f| {
            let [a, b, c] = f.map(|k| v[k as usize]);
            1.0 - (b - a).cross(c - a).normalize().dot(a).abs()
        })
        .fold(0.0, f64::max);
    assert!(
        h.surface_to_scan.max <= sag + 1e-12,
        "{} against the bound {sag}",
        h.surface_to_scan.max
    );
    assert!(h.surface_to_scan.max > 0.5 * sag, "{} against {sag}", h.surface_to_scan.max);
    assert_eq!(h.distance(), h.surface_to_scan.max);
}

#[test]
fn the_measurements_match_the_sphere() {
    // Points at known distances from the exact unit sphere: radius 1 + d.
    let offset = |k: usize| if k.is_multiple_of(2) { 0.01 } else { -0.02 };
    let points: Vec<DVec3> = hi_testkit::fibonacci_sphere(4000)
        .enumerate()
        .map(|(k, d)| DVec3::from(d) * (1.0 + offset(k)))
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
    let sagitta = (2.0 * std::f64::consts::PI / 192.0).powi(2) / 4.0;
    for (k, d) in fast.scan_to_surface.per_point.iter().enumerate() {
        assert!((d - offset(k).abs()).abs() <= sagitta, "point {k}: {d}");
    }
    // Surface → scan: the mesh's samples are on the sphere, the scan's points at most 0.02
    // off it and about 0.03 apart: within a spacing of the nearest.
    assert!(fast.surface_to_scan.max < 0.05, "{}", fast.surface_to_scan.max);
    assert!(mesh.mesh.n_triangles() > 0);
    assert!(measure_fit(&sphere, Layout::Sphere, None, &points, &[], ErrorMeasure::Off).is_err());
}
