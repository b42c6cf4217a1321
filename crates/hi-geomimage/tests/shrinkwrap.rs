// SPDX-License-Identifier: MIT
//! Shrink-wrapped geometry images of point sets, on a surface whose distance is known in
//! closed form: a peanut (two overlapping spheres) seen from a centre in one lobe, from which
//! rays past the waist meet the other lobe twice.

use std::f64::consts::PI;

use glam::DVec3;
use hi_geomimage::shrinkwrap::{ShrinkWrapOptions, shrink_wrap};
use hi_geomimage::spherical::{SphericalOptions, spherical_image};
use hi_geomimage::{Error, Layout};

/// The two spheres of the peanut: radius 1 about (±0.9, 0, 0).
const LOBES: [DVec3; 2] = [DVec3::new(-0.9, 0.0, 0.0), DVec3::new(0.9, 0.0, 0.0)];

/// The distance from x to the peanut (the boundary of the union of the two balls), for x
/// outside the waist's groove: the lesser of the distances to the two spheres.
fn peanut_distance(x: DVec3) -> f64 {
    let f = LOBES.iter().map(|c| x.distance(*c) - 1.0).fold(f64::INFINITY, f64::min);
    f.abs()
}

/// Points on the peanut: a Fibonacci sphere on each lobe, less what lies inside the other.
fn peanut_points(noise: f64) -> Vec<DVec3> {
    let golden = PI * (3.0 - 5f64.sqrt());
    let n = 20_000;
    let mut k = 0u64;
    let mut jitter = || {
        k = k.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        noise * ((k >> 11) as f64 / (1u64 << 53) as f64 - 0.5)
    };
    let mut points = Vec::new();
    for (a, c) in LOBES.iter().enumerate() {
        for i in 0..n {
            let z = 1.0 - (2 * i + 1) as f64 / n as f64;
            let s = (1.0 - z * z).sqrt();
            let phi = i as f64 * golden;
            let p = *c + DVec3::new(s * phi.cos(), s * phi.sin(), z);
            if p.distance(LOBES[1 - a]) > 1.0 {
                points.push(*c + (p - *c) * (1.0 + jitter()));
            }
        }
    }
    points
}

/// The largest distance from the surface's covering half (sampled finely) to the peanut, away
/// from its waist (where the distance above is only a bound).
fn surface_error(surface: &hi_surface::HarmonicSurface<DVec3>) -> f64 {
    let (m, n) = (2 * surface.m(), 2 * surface.n());
    let samples = surface.sample_uniform(m, n, 0, 0).unwrap().values;
    samples[..(m / 2 + 1) * n]
        .iter()
        .filter(|x| x.x.abs() > 0.2)
        .map(|x| peanut_distance(*x))
        .fold(0.0, f64::max)
}

#[test]
fn the_lobe_the_rays_cannot_see_is_wrapped() {
    // From inside one lobe near its far end, rays past the waist leave the near lobe and meet
    // the far one twice: its side facing the waist is hidden from them.
    let centre = Some(DVec3::new(-1.3, 0.0, 0.0));
    for noise in [0.0, 0.01] {
        let points = peanut_points(noise);
        let (rows, cols) = (128, 128);
        let options = ShrinkWrapOptions { rows, cols, centre, ..ShrinkWrapOptions::default() };
        let wrapped = shrink_wrap(&points, None, &options).unwrap();
        let wrap_error = surface_error(&wrapped.image.surface().unwrap());
        let rays = SphericalOptions {
            layout: Layout::FlatOctahedron,
            rows,
            cols,
            centre,
            ..SphericalOptions::default()
        };
        let radial = spherical_image(&points, &rays).unwrap();
        let radial_error = surface_error(&radial.image.surface().unwrap());
        eprintln!(
            "noise {noise}: wrapped within {wrap_error:.4} (filled {:.3}), radial within {radial_error:.4} (non-star {:.3}, holes {:.3})",
            wrapped.filled_fraction, radial.non_star_fraction, radial.hole_fraction
        );
        assert!(radial.non_star_fraction > 0.02, "the rays meet the peanut more than once");
        // The image's texels are about 0.05 apart on the peanut: within half that of it after
        // the wrap (plus the noise), and the radial image far off where it bridges the waist.
        assert!(radial_error > 0.15, "the rays alone: {radial_error}");
        assert!(wrap_error < 0.025 + noise, "wrapped: {wrap_error}");
    }
}

#[test]
fn the_doubled_image_keeps_its_symmetry() {
    let points = peanut_points(0.0);
    for layout in [Layout::FlatOctahedron, Layout::Sphere] {
        let (rows, cols) = (32, 32);
        let options = ShrinkWrapOptions { layout, rows, cols, ..ShrinkWrapOptions::default() };
        let w = shrink_wrap(&points, None, &options).unwrap();
        for i in 0..rows {
            for j in 0..cols {
                let d = layout.direction(i, j, rows, cols);
                for k in 0..rows * cols {
                    if k != i * cols + j
                        && layout.direction(k / cols, k % cols, rows, cols).distance(d) < 1e-12
                    {
                        assert_eq!(w.image.texels()[k], w.image.get(i, j), "{layout:?} ({i}, {j})");
                    }
                }
            }
        }
    }
}

#[test]
fn bad_input_is_named() {
    let options = ShrinkWrapOptions::default();
    assert!(matches!(shrink_wrap(&[], None, &options), Err(Error::TooFewPoints { .. })));
    assert!(matches!(shrink_wrap(&[DVec3::NAN; 10], None, &options), Err(Error::NonFinite { .. })));
    let points = peanut_points(0.0);
    assert!(
        shrink_wrap(&points, Some(&[DVec3::Z]), &options).is_err(),
        "one normal for many points"
    );
    let odd = ShrinkWrapOptions { rows: 31, ..options };
    assert!(shrink_wrap(&points, None, &odd).is_err());
}
