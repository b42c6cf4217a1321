// SPDX-License-Identifier: MIT
//! Mesh repair and the spherical parameterisation, checked on meshes built here whose answer is
//! known: the closed surface they bound, their genus, and exact closest points found by brute
//! force over every triangle.

use std::f64::consts::{PI, TAU};

use glam::DVec3;
use hi_geomimage::Layout;
use hi_geomimage::sphereparam::{SphereParamOptions, parameterise, parameterise_weighted};
use hi_geomimage::spherical::{SphericalOptions, spherical_image};
use hi_scan::distance::closest_point_on_triangle;
use hi_scan::repair::{ADDED_VERTEX, close_mesh};

mod common;
use common::icosphere;

/// A tube of radius `r` about the arc of the unit circle from angle 0 to `sweep`, closed by
/// flat discs: genus 0, and for a sweep above π its centroid lies outside it, so no ray from
/// there meets it only once.
fn bent_tube(sweep: f64, r: f64, rings: usize, around: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut p = Vec::new();
    for i in 0..rings {
        let th = sweep * i as f64 / (rings - 1) as f64;
        let (c, s) = (th.cos(), th.sin());
        for j in 0..around {
            let ph = TAU * j as f64 / around as f64;
            let rho = 1.0 + r * ph.cos();
            p.push(DVec3::new(rho * c, rho * s, r * ph.sin()));
        }
    }
    let mut t = Vec::new();
    let at = |i: usize, j: usize| (i * around + j % around) as u32;
    for i in 0..rings - 1 {
        for j in 0..around {
            t.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            t.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    // Caps: a fan around each end's centre.
    let first = p.len() as u32;
    p.push(DVec3::X);
    p.push(DVec3::new(sweep.cos(), sweep.sin(), 0.0));
    for j in 0..around {
        t.push([first, at(0, j + 1), at(0, j)]);
        t.push([first + 1, at(rings - 1, j), at(rings - 1, j + 1)]);
    }
    (p, t)
}

/// The exact distance from x to the triangle mesh, by brute force.
fn mesh_distance(x: DVec3, p: &[DVec3], t: &[[u32; 3]]) -> f64 {
    t.iter()
        .map(|tri| {
            let [a, b, c] = tri.map(|k| p[k as usize]);
            closest_point_on_triangle(x, a, b, c).distance(x)
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn a_sphere_maps_without_folds_and_its_image_lies_on_the_mesh() {
    let (p, t) = icosphere(3, 2.0);
    let closed = close_mesh(&p, &t).unwrap();
    assert_eq!(closed.repair.holes, 0);
    assert!(!closed.repair.flipped, "the icosphere winds outward");
    let param = parameterise(&closed, &SphereParamOptions::default()).unwrap();
    let q = param.quality();
    assert_eq!(q.folded_triangles, 0);
    // A sphere can be mapped to itself: the stretch is nearly uniform.
    assert!(q.stretch_efficiency > 0.9, "{q:?}");
    for s in param.sphere() {
        assert!((s.length() - 1.0).abs() < 1e-12, "on the unit sphere");
    }
    for layout in [Layout::Sphere, Layout::Octahedron, Layout::FlatOctahedron] {
        let image = param.image(layout, 32, 32).unwrap();
        assert_eq!(image.filled_fraction, 0.0);
        for x in image.image.texels() {
            let d = mesh_distance(*x, &p, &t);
            assert!(d < 1e-12, "{layout:?}: a texel {d} off the mesh");
        }
    }
    // The spherical triangles cover the sphere exactly once: their solid angles sum to 4π.
    let solid: f64 = closed
        .triangles
        .iter()
        .map(|tri| {
            let [a, b, c] = tri.map(|k| param.sphere()[k as usize]);
            2.0 * a.dot(b.cross(c)).atan2(1.0 + a.dot(b) + b.dot(c) + c.dot(a))
        })
        .sum();
    assert!((solid - 4.0 * PI).abs() < 1e-9, "solid angle {solid}");
}

#[test]
fn a_shape_no_ray_sees_once_is_sampled_everywhere() {
    let (p, t) = bent_tube(1.5 * PI, 0.3, 60, 24);
    let closed = close_mesh(&p, &t).unwrap();
    let param = parameterise(&closed, &SphereParamOptions::default()).unwrap();
    assert_eq!(param.quality().folded_triangles, 0);
    let image = param.image(Layout::FlatOctahedron, 128, 128).unwrap();
    let surface = image.image.surface().unwrap();
    // Every vertex of the tube is near the harmonic surface through the image, and the surface
    // (its covering half) is near the tube.
    let samples = surface.sample_uniform(256, 256, 0, 0).unwrap().values;
    let half = &samples[..128 * 256];
    let near =
        |x: DVec3, set: &[DVec3]| set.iter().map(|y| y.distance(x)).fold(f64::INFINITY, f64::min);
    let worst_vertex = p.iter().map(|x| near(*x, half)).fold(0.0, f64::max);
    let worst_sample =
        half.iter().step_by(7).map(|x| mesh_distance(*x, &p, &t)).fold(0.0, f64::max);
    // The tube's area is about 9.4 and the image has 128²/2 distinct texels, about 0.034
    // apart on it. Every vertex is within a texel spacing of the nearest sample (the samples
    // are half a spacing apart), and the surface stays within half a spacing of the tube
    // even at the right-angled rims of its end discs, where an interpolating trigonometric
    // polynomial overshoots most.
    assert!(worst_vertex < 0.034, "a vertex {worst_vertex} from the surface");
    assert!(worst_sample < 0.017, "a surface point {worst_sample} from the tube");
    // The thesis's radial image cannot: every ray from the centroid that meets the tube meets
    // it twice, and the image keeps only the outer wall.
    let radial = spherical_image(
        &p,
        &SphericalOptions {
            layout: Layout::FlatOctahedron,
            rows: 128,
            cols: 128,
            ..SphericalOptions::default()
        },
    )
    .unwrap();
    assert!(radial.non_star_fraction > 0.2, "{}", radial.non_star_fraction);
    let radial_samples =
        radial.image.surface().unwrap().sample_uniform(256, 256, 0, 0).unwrap().values;
    let radial_worst = p.iter().map(|x| near(*x, &radial_samples[..128 * 256])).fold(0.0, f64::max);
    assert!(radial_worst > 0.3, "the radial image reaches the inner wall? {radial_worst}");
}

#[test]
fn the_doubled_layouts_keep_their_symmetry() {
    let (p, t) = bent_tube(PI, 0.4, 20, 12);
    let param = parameterise(&close_mesh(&p, &t).unwrap(), &SphereParamOptions::default()).unwrap();
    for layout in [Layout::Sphere, Layout::FlatOctahedron] {
        let (rows, cols) = (24, 16);
        let image = param.image(layout, rows, cols).unwrap();
        for i in 0..rows {
            for j in 0..cols {
                // Both texels look along the same direction, so they must be equal.
                let (a, b) = (layout.direction(i, j, rows, cols), image.image.get(i, j));
                let k = (0..rows * cols)
                    .find(|&k| {
                        (k / cols, k % cols) != (i, j)
                            && layout.direction(k / cols, k % cols, rows, cols).distance(a) < 1e-12
                    })
                    .map(|k| image.image.texels()[k]);
                if let Some(other) = k {
                    assert_eq!(other, b, "{layout:?} ({i}, {j})");
                }
            }
        }
    }
}

#[test]
fn holes_are_closed_and_flagged() {
    // An icosphere with a cap cut off: one hole.
    let (p, t) = icosphere(3, 1.0);
    let cut: Vec<[u32; 3]> = t
        .iter()
        .copied()
        .filter(|tri| tri.iter().map(|&k| p[k as usize].z).sum::<f64>() < 2.4)
        .collect();
    let closed = close_mesh(&p, &cut).unwrap();
    assert_eq!(closed.repair.holes, 1);
    assert!(closed.filled.iter().any(|&f| f));
    assert!(closed.scan_vertex.contains(&ADDED_VERTEX));
    // The fill is a membrane across the hole's rim: flat there, so the cap's volume is missing.
    let full = 4.0 / 3.0 * PI;
    assert!(closed.volume() < full && closed.volume() > 0.9 * full, "{}", closed.volume());
    let param = parameterise(&closed, &SphereParamOptions::default()).unwrap();
    let image = param.image(Layout::FlatOctahedron, 64, 64).unwrap();
    // The texels flagged are those above the rim (about the cap's share of the sphere).
    assert!(
        image.filled_fraction > 0.0 && image.filled_fraction < 0.2,
        "{}",
        image.filled_fraction
    );
    for (x, filled) in image.image.texels().iter().zip(&image.filled) {
        if *filled {
            assert!(x.z > 0.7, "a filled texel below the rim: {x}");
        }
    }
}

#[test]
fn a_pinched_vertex_is_split() {
    // A tube around a circle whose first ring is pinched to one point P, which both ends meet:
    // split at P it is a sphere (a tube with two cones for ends).
    let (rings, around) = (12, 8);
    let mut p = vec![DVec3::new(1.0, 0.0, 0.0)];
    for i in 1..rings {
        let th = TAU * i as f64 / rings as f64;
        let r = 0.3 * (th / 2.0).sin(); // 0 at the pinch
        for j in 0..around {
            let ph = TAU * j as f64 / around as f64;
            let rho = 1.0 + r * ph.cos();
            p.push(DVec3::new(rho * th.cos(), rho * th.sin(), r * ph.sin()));
        }
    }
    let at = |i: usize, j: usize| (1 + (i - 1) * around + j % around) as u32;
    let mut t = Vec::new();
    for i in 1..rings - 1 {
        for j in 0..around {
            t.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            t.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    for j in 0..around {
        t.push([0, at(1, j), at(1, j + 1)]);
        t.push([0, at(rings - 1, j + 1), at(rings - 1, j)]);
    }
    let closed = close_mesh(&p, &t).unwrap();
    assert_eq!(closed.repair.split_vertices, 1);
    assert_eq!(closed.positions.len(), p.len() + 1);
    assert!(parameterise(&closed, &SphereParamOptions::default()).is_ok());
}

#[test]
fn meshes_that_are_not_spheres_are_cut_or_refused() {
    // A torus: genus 1.
    let (p, t) = common::torus(12, 8, 2.0, 1.0);
    // It is cut across its tube, and the cuts closed: genus 0, the torus's shape and volume
    // (2π²Rr² = 4π² for the smooth torus; the polygon's is smaller).
    let cut = close_mesh(&p, &t).expect("a torus is cut to genus 0");
    assert_eq!(cut.repair.handles_cut, 1);
    let v = cut.volume();
    assert!(v > 0.8 * 4.0 * PI * PI && v < 4.0 * PI * PI, "volume {v}");
    // A Möbius band: one-sided.
    let k = 10;
    let mut p = Vec::new();
    for i in 0..k {
        let u = TAU * i as f64 / k as f64;
        for s in [-0.3, 0.3] {
            let w = s * (u / 2.0).cos();
            p.push(DVec3::new((1.0 + w) * u.cos(), (1.0 + w) * u.sin(), s * (u / 2.0).sin()));
        }
    }
    let mut t = Vec::new();
    for i in 0..k {
        let (a, b) = (2 * i as u32, 2 * i as u32 + 1);
        let (c, d) = if i + 1 < k { (a + 2, b + 2) } else { (1, 0) }; // the half twist
        t.push([a, c, d]);
        t.push([a, d, b]);
    }
    let err = close_mesh(&p, &t).unwrap_err();
    assert!(err.to_string().contains("one-sided"), "{err}");
    // Bad input.
    assert!(matches!(close_mesh(&[DVec3::NAN], &[]), Err(hi_scan::Error::NonFinite { .. })));
    assert!(matches!(
        close_mesh(&[DVec3::ZERO; 3], &[[0, 1, 3]]),
        Err(hi_scan::Error::InvalidOption { .. })
    ));
    assert!(matches!(close_mesh(&[DVec3::ZERO; 3], &[]), Err(hi_scan::Error::Topology { .. })));
    assert!(matches!(
        close_mesh(&[DVec3::ZERO; 3], &[[0, 1, 1]]),
        Err(hi_scan::Error::Topology { .. })
    ));
}

#[test]
fn repeated_points_and_faces_are_cleaned() {
    let (p, t) = icosphere(1, 1.0);
    // Every point twice; triangles use both copies; one triangle listed twice, one reversed
    // copy, and a loose triangle far away.
    let n = p.len() as u32;
    let mut points = p.clone();
    points.extend(p.iter().copied());
    let mut tris: Vec<[u32; 3]> = t
        .iter()
        .enumerate()
        .map(|(i, tri)| if i % 2 == 0 { *tri } else { tri.map(|k| k + n) })
        .collect();
    tris.push(t[0]);
    tris.push([t[1][0], t[1][2], t[1][1]]);
    points.extend([DVec3::splat(10.0), DVec3::new(10.0, 11.0, 10.0), DVec3::new(11.0, 10.0, 10.0)]);
    tris.push([2 * n, 2 * n + 1, 2 * n + 2]);
    let closed = close_mesh(&points, &tris).unwrap();
    assert_eq!(closed.repair.welded_points, p.len());
    assert_eq!(closed.repair.dropped_triangles, 2);
    assert_eq!(closed.repair.components, 2);
    assert_eq!(closed.repair.dropped_component_triangles, 1);
    assert_eq!(closed.triangles.len(), t.len());
    assert_eq!(closed.positions.len(), p.len());
    assert!(closed.volume() > 0.0);
}

/// The share of the sphere's area that the triangles of `mesh` centred above z = 0 take in
/// `param` (their flat triangles on the sphere, over all of them).
fn upper_share(param: &hi_geomimage::sphereparam::SphereParam) -> f64 {
    let (mesh, s) = (param.mesh(), param.sphere());
    let (mut upper, mut all) = (0.0, 0.0);
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|k| s[k as usize]);
        let area = 0.5 * (b - a).cross(c - a).length();
        all += area;
        if t.iter().map(|&k| mesh.positions[k as usize].z).sum::<f64>() > 0.0 {
            upper += area;
        }
    }
    upper / all
}

/// The share of the sphere taken by the upper half of the unit sphere, its weight `w` against
/// the lower half's 1, in the least weighted L² stretch among the maps of the sphere to itself
/// that turn about its axis (latitude θ to latitude φ(θ)): E = ∫ w ((dθ/dφ)² + (sin θ /
/// sin φ)²)/2 dA, its two terms the squared stretches along the meridian and the parallel.
/// Minimised over φ at 40 latitudes by Gauss–Seidel sweeps of golden-section searches.
fn least_stretch_upper_share(w: f64) -> f64 {
    let n = 40;
    let theta: Vec<f64> = (0..=n).map(|i| PI * i as f64 / n as f64).collect();
    let mut phi = theta.clone();
    // The energy of the band between latitudes i and i + 1 (the factor 2π left out).
    let band = |i: usize, phi: &[f64]| -> f64 {
        let (dt, dp) = (theta[i + 1] - theta[i], phi[i + 1] - phi[i]);
        if dp <= 0.0 {
            return f64::INFINITY;
        }
        let (tm, pm) = (0.5 * (theta[i] + theta[i + 1]), 0.5 * (phi[i] + phi[i + 1]));
        let weight = if tm < 0.5 * PI { w } else { 1.0 };
        weight * 0.5 * ((dt / dp).powi(2) + (tm.sin() / pm.sin()).powi(2)) * tm.sin() * dt
    };
    let golden = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..3000 {
        for i in 1..n {
            let (mut lo, mut hi) = (phi[i - 1], phi[i + 1]);
            let at = |x: f64, phi: &mut [f64]| {
                phi[i] = x;
                band(i - 1, phi) + band(i, phi)
            };
            for _ in 0..40 {
                let (a, b) = (hi - golden * (hi - lo), lo + golden * (hi - lo));
                if at(a, &mut phi) < at(b, &mut phi) {
                    hi = b;
                } else {
                    lo = a;
                }
            }
            phi[i] = 0.5 * (lo + hi);
        }
    }
    (1.0 - phi[n / 2].cos()) / 2.0
}

/// Weights in the stretch give a region more of the sphere, about in proportion to the square
/// root of its weight (the module documentation's Lagrange condition, which leaves out what
/// the map's anisotropy costs): a sphere whose upper half weighs 4 times its lower half's
/// gives it the share of the least stretch computed along its latitudes, a little below
/// √4 / (√4 + 1) = 2/3, rather than 1/2.
#[test]
fn weights_give_a_region_sphere_area_as_their_square_root() {
    let (p, t) = icosphere(4, 1.0);
    let closed = close_mesh(&p, &t).unwrap();
    let options = SphereParamOptions::default();
    let even = upper_share(&parameterise(&closed, &options).unwrap());
    assert!((even - 0.5).abs() < 0.01, "unweighted: {even}");
    for w in [4.0, 0.25] {
        let expected = least_stretch_upper_share(w);
        let area_only = w.sqrt() / (w.sqrt() + 1.0);
        assert!((expected - 0.5).abs() < (area_only - 0.5).abs(), "{expected} vs {area_only}");
        let weights: Vec<f64> =
            closed.positions.iter().map(|x| if x.z > 0.0 { w } else { 1.0 }).collect();
        let param = parameterise_weighted(&closed, &weights, &options).unwrap();
        assert_eq!(param.quality().folded_triangles, 0);
        let share = upper_share(&param);
        assert!((share - expected).abs() < 0.02, "weight {w}: {share}, not {expected}");
    }
    // A weight count other than the vertex count, or a weight that is not positive, is refused.
    for bad in
        [vec![1.0; 3], vec![0.0; closed.positions.len()], vec![f64::NAN; closed.positions.len()]]
    {
        let e = parameterise_weighted(&closed, &bad, &options).unwrap_err().to_string();
        assert!(e.contains("weights"), "{e}");
    }
}
