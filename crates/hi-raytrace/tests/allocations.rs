// SPDX-License-Identifier: MIT
//! The kernels a ray meets allocate nothing: the direct and spectral evaluations of a
//! harmonic surface with its partials, the interval search of a harmonic object, Newton on
//! Bézier pieces (split at ray time where needed), and the BVH and triangle test of a mesh, each counted by the allocator over a few hundred rays (after one warm-up ray,
//! which may size the search stack kept by each thread).

use std::hint::black_box;

use allocation_counter::measure;
use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree, Tolerance};
use hi_raytrace::{BezierObject, BezierOptions, HarmonicObject, HarmonicOptions, MeshObject, Ray};
use hi_surface::{MeshOptions, torus};

/// Rays from in front of the torus (its ring in the xy plane) through a grid of points.
fn rays() -> Vec<Ray> {
    let eye = DVec3::new(0.0, -8.0, 3.0);
    let mut out = Vec::new();
    for i in 0..20 {
        for j in 0..12 {
            let target = DVec3::new(-3.0 + 0.3 * i as f64, 0.0, -0.6 + 0.1 * j as f64);
            out.push(Ray::new(eye, target - eye));
        }
    }
    out
}

#[test]
fn intersections_allocate_nothing_per_ray() {
    let surface = torus(2.0, 0.5);
    let rays = rays();
    // The counter sees this thread's allocations (a control: the search stack made anew).
    let control = measure(|| {
        black_box(Vec::<[f64; 12]>::with_capacity(64));
    });
    assert_eq!(control.count_total, 1, "the counter counts");

    let kernel = measure(|| {
        for r in &rays {
            black_box(surface.eval_with_partials(r.dir.x, r.dir.z));
            black_box(surface.eval_deriv(r.dir.x, r.dir.z, 2, 1));
            black_box(surface.eval(r.dir.x, r.dir.z));
        }
    });
    assert_eq!(kernel.count_total, 0, "spectral evaluation: {kernel:?}");

    let harmonic = HarmonicObject::try_new(surface.clone(), &HarmonicOptions::default())
        .expect("a valid surface");
    let hits = rays.iter().filter(|r| harmonic.intersect(r).is_some()).count();
    assert!(hits > 40, "the rays meet the torus: {hits} hits");
    let search = measure(|| {
        for r in &rays {
            black_box(harmonic.intersect(r));
            black_box(harmonic.occluded(r));
        }
    });
    assert_eq!(search.count_total, 0, "interval search: {search:?}");

    let cubic = BezierScheme::Hermite(HermiteDegree::Cubic);
    let patches = surface.to_bezier(cubic, Tolerance::Absolute(1e-4)).expect("converts");
    let bezier =
        BezierObject::try_from_surface(&patches, &BezierOptions::default()).expect("valid");
    // A coarse build leaves pieces that rays must split (the sub-piece path of the search).
    let coarse = BezierOptions { max_depth: 1, ..BezierOptions::default() };
    let split = BezierObject::try_from_surface(&patches, &coarse).expect("valid");
    let pieces = measure(|| {
        for r in &rays {
            black_box(bezier.intersect(r));
            black_box(bezier.occluded(r));
            black_box(split.intersect(r));
        }
    });
    assert_eq!(pieces.count_total, 0, "Bézier pieces: {pieces:?}");

    let opts = MeshOptions { n_u: 64, n_v: 32, ..MeshOptions::default() };
    let mesh = MeshObject::new(surface.to_mesh(&opts).expect("meshes"));
    let triangles = measure(|| {
        for r in &rays {
            black_box(mesh.intersect(r));
            black_box(mesh.occluded(r));
        }
    });
    assert_eq!(triangles.count_total, 0, "mesh BVH: {triangles:?}");
}
