// SPDX-License-Identifier: MIT
//! Issue 9's agreement check on a fitted scan: a harmonic surface fitted through a geometry
//! image (§5.3) ray traced directly (interval Newton) and through its C1 Bézier patches (§5.7).
//! Where both hit, the hit distances differ by less than the patches' bound (measured along the
//! normal); a pixel hit by one and missed by the other is allowed only on a silhouette.
//! (The torus and a synthetic surface are checked in `hi-raytrace`'s own tests.)

use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_geomimage::{ErrorMeasure, FitOptions, Layout, Smoothing, fit};
use hi_raytrace::{BezierObject, BezierOptions, Camera, HarmonicObject, HarmonicOptions, Ray};
use hi_scan::scan::Scan;

/// Points on r = 1 + 0.15 sin 5θ cos 3φ (a Fibonacci lattice).
fn bumpy_scan(n: usize) -> Scan {
    let points = hi_testkit::fibonacci_sphere(n)
        .map(|d| {
            let d = DVec3::from(d);
            let (theta, phi) = (d.z.acos(), d.y.atan2(d.x));
            d * (1.0 + 0.15 * (5.0 * theta).sin() * (3.0 * phi).cos())
        })
        .collect();
    Scan { points, ..Scan::default() }
}

#[test]
fn bezier_and_interval_agree_on_a_fitted_scan() {
    let options = FitOptions {
        layout: Layout::FlatOctahedron,
        resolution: Some((24, 24)),
        smoothing: Some(Smoothing::Gaussian { sigma: 0.7 }),
        error: ErrorMeasure::Off,
        ..FitOptions::thesis()
    };
    let surface =
        fit(&bumpy_scan(30_000), &options, &mut |_| {}).expect("fits").parts.remove(0).surface;
    let patches = surface
        .to_bezier(
            BezierScheme::Hermite(HermiteDegree::Cubic),
            hi_curve::bezier::Tolerance::Absolute(1e-4),
        )
        .expect("converts");
    let bound = patches.report.bound;
    assert!(bound <= 1e-4, "the conversion's bound {bound}");
    let bezier =
        BezierObject::try_from_surface(&patches, &BezierOptions::default()).expect("patches");
    let interval =
        HarmonicObject::try_new(surface, &HarmonicOptions::default()).expect("the surface");
    let camera =
        Camera::try_new(DVec3::new(1.5, -4.0, 2.5), DVec3::ZERO, DVec3::Z, 0.7).expect("camera");
    let n = 32;
    let rays: Vec<Ray> = (0..n * n)
        .map(|i| {
            let (x, y) = ((i % n) as f64 + 0.5, (i / n) as f64 + 0.5);
            camera.ray(x / n as f64, y / n as f64, 1.0)
        })
        .collect();
    let by_bezier: Vec<_> = rays.iter().map(|r| bezier.intersect(r)).collect();
    let by_interval: Vec<_> = rays.iter().map(|r| interval.intersect(r)).collect();
    let hit = |i: usize| (by_bezier[i].is_some(), by_interval[i].is_some());
    // A silhouette pixel: a 4-neighbour differs in hit or miss for either method.
    let silhouette = |i: usize| {
        let (x, y) = (i % n, i / n);
        [
            (x > 0).then(|| i - 1),
            (x + 1 < n).then(|| i + 1),
            (y > 0).then(|| i - n),
            (y + 1 < n).then(|| i + n),
        ]
        .into_iter()
        .flatten()
        .any(|j| hit(j) != hit(i))
    };
    let (mut both, mut one_only) = (0, 0);
    for i in 0..n * n {
        match (by_bezier[i], by_interval[i]) {
            (Some(b), Some(h)) => {
                both += 1;
                let normal = interval.surface().normal(h.u, h.v).expect("a regular point");
                let along_normal = (b.t - h.t).abs() * normal.dot(rays[i].dir).abs();
                assert!(along_normal <= bound + 1e-9, "pixel {i}: {along_normal:e} > {bound:e}");
            }
            (None, None) => {}
            _ => one_only += usize::from(!silhouette(i)),
        }
    }
    assert_eq!(one_only, 0, "pixels hit by one method only, away from silhouettes");
    assert!(both > n * n / 5, "only {both} pixels hit by both");
}
