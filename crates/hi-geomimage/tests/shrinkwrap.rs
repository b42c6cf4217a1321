// SPDX-License-Identifier: MIT
//! Shrink-wrapped geometry images of point sets, on a surface whose distance is known in
//! closed form: a peanut (two overlapping spheres) seen from a centre in one lobe, from which
//! rays past the waist meet the other lobe twice.

use std::f64::consts::PI;
use std::num::NonZero;

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
    let mut k = 0u64;
    let mut jitter = || {
        k = k.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        noise * ((k >> 11) as f64 / (1u64 << 53) as f64 - 0.5)
    };
    let mut points = Vec::new();
    for (a, c) in LOBES.iter().enumerate() {
        for d in hi_testkit::fibonacci_sphere(20_000) {
            let p = *c + DVec3::from(d);
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

/// The signed distance to a capsule of radius `r` about the segment a–b.
fn capsule(x: DVec3, a: DVec3, b: DVec3, r: f64) -> f64 {
    let t = ((x - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
    x.distance(a + (b - a) * t) - r
}

/// Points about `spacing` apart on the capsule a–b of radius r (its cylinder, and the caps
/// where `caps` says), keeping those for which `keep` holds.
fn capsule_points(
    a: DVec3,
    b: DVec3,
    r: f64,
    spacing: f64,
    caps: [bool; 2],
    keep: &dyn Fn(DVec3) -> bool,
) -> Vec<DVec3> {
    let axis = (b - a).normalize();
    let (e1, e2) = axis.any_orthonormal_pair();
    let mut out = Vec::new();
    let around = (2.0 * PI * r / spacing).ceil() as usize;
    let along = ((b - a).length() / spacing).ceil() as usize;
    for i in 0..=along {
        for j in 0..around {
            let phi = 2.0 * PI * (j as f64 + 0.5 * (i % 2) as f64) / around as f64;
            out.push(
                a + (b - a) * (i as f64 / along as f64) + (e1 * phi.cos() + e2 * phi.sin()) * r,
            );
        }
    }
    // The caps: Fibonacci points on the hemispheres.
    let n = (2.0 * PI * r * r / (spacing * spacing)).ceil() as usize;
    for (end, sign, wanted) in [(a, -1.0, caps[0]), (b, 1.0, caps[1])] {
        if !wanted {
            continue;
        }
        for k in 0..n {
            let z = (k as f64 + 0.5) / n as f64;
            let s = (1.0 - z * z).sqrt();
            let phi = k as f64 * PI * (3.0 - 5f64.sqrt());
            out.push(end + (axis * sign * z + (e1 * phi.cos() + e2 * phi.sin()) * s) * r);
        }
    }
    out.retain(|p| keep(*p));
    out
}

#[test]
fn a_u_shape_is_wrapped_into_the_gap_between_its_arms() {
    // Two upright arms joined by a bar at the bottom: from the points' mean, in the gap between
    // the arms, every ray meets the shape from outside, and the rays alone would bridge the gap.
    let r = 0.3;
    let segments = [
        (DVec3::new(-1.0, 0.0, 0.0), DVec3::new(-1.0, 0.0, 2.0)),
        (DVec3::new(1.0, 0.0, 0.0), DVec3::new(1.0, 0.0, 2.0)),
        (DVec3::new(-1.0, 0.0, 0.0), DVec3::new(1.0, 0.0, 0.0)),
    ];
    let distance = |x: DVec3| {
        segments.iter().map(|(a, b)| capsule(x, *a, *b, r)).fold(f64::INFINITY, f64::min)
    };
    let mut points = Vec::new();
    for (k, (a, b)) in segments.iter().enumerate() {
        let others = |x: DVec3| {
            segments
                .iter()
                .enumerate()
                .filter(|(j, _)| *j != k)
                .all(|(_, (c, d))| capsule(x, *c, *d, r) > -1e-9)
        };
        // The arms' lower caps are inside the bar or on its end caps.
        let caps = [k == 2, true];
        points.extend(capsule_points(*a, *b, r, 0.03, caps, &others));
    }
    let options = ShrinkWrapOptions { rows: 128, cols: 128, ..ShrinkWrapOptions::default() };
    let wrapped = shrink_wrap(&points, None, &options).unwrap();
    assert!(wrapped.implicit_start, "the zero set of the signed distance is one sphere");
    assert!(wrapped.non_star_fraction > 0.05, "{}", wrapped.non_star_fraction);
    // The whole surface (both halves of the doubled image), sampled at twice the texels: on
    // the U, away from the grooves where the arms meet the bar (where |distance| is a bound).
    let surface = wrapped.image.surface().unwrap();
    let samples = surface.sample_uniform(2 * surface.m(), 2 * surface.n(), 0, 0).unwrap().values;
    let error =
        samples.iter().filter(|x| x.z > r + 0.2).map(|x| distance(*x).abs()).fold(0.0, f64::max);
    eprintln!(
        "U: {} points, surface within {error:.4}, filled {}",
        points.len(),
        wrapped.filled_fraction
    );
    // Texels are about 0.04 apart on the U, and on it; a bridge across the gap would be 0.7
    // off.
    assert!(error < 0.01, "{error}");
    assert_eq!(wrapped.filled_fraction, 0.0);
}

#[test]
fn a_tube_open_at_the_bottom_is_bridged_and_the_bridge_flagged() {
    let (a, b, r) = (DVec3::ZERO, DVec3::new(0.0, 0.0, 2.0), 0.5);
    let points = capsule_points(a, b, r, 0.03, [false, true], &|_| true);
    let options = ShrinkWrapOptions { rows: 128, cols: 128, ..ShrinkWrapOptions::default() };
    let wrapped = shrink_wrap(&points, None, &options).unwrap();
    assert!(wrapped.implicit_start);
    // The bottom disc is a fifth of the area (π r² of 2π r·2 + 2π r² + π r²).
    assert!(
        wrapped.filled_fraction > 0.05 && wrapped.filled_fraction < 0.2,
        "{}",
        wrapped.filled_fraction
    );
    let mut worst = 0.0f64;
    for (x, filled) in wrapped.image.texels().iter().zip(&wrapped.filled) {
        if *filled {
            // On the bridge: across the opening, below its rim, where a cap that leaves the
            // tube along its wall (a thin plate) closes it, no wider than the tube.
            assert!(x.z < 0.05 && x.z > -(r + 0.1) && x.truncate().length() < r + 0.05, "{x}");
        } else {
            worst = worst.max(capsule(*x, a, b, r).abs());
        }
    }
    eprintln!("tube: surface within {worst:.4} where the points are");
    assert!(worst < 0.01, "{worst}");
}

#[test]
fn the_creases_of_a_real_scan_are_reached() {
    // The rubber duck of `fixtures/models` (18 090 points, their normals left out): its head
    // has creases about one point spacing wide and two or three deep, which the zero set of
    // step 1 (a grid of 1.5 spacings) bridges. The points in them pull the texels in.
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../fixtures/models/ducky_points.obj");
    let points = hi_scan::scan::read_scan(std::path::Path::new(path)).unwrap().points;
    let options = ShrinkWrapOptions { rows: 288, cols: 288, ..ShrinkWrapOptions::default() };
    let wrapped = shrink_wrap(&points, None, &options).unwrap();
    assert!(wrapped.implicit_start, "the duck's zero set closes to a sphere");
    assert!(wrapped.pulled > 0, "no texel was pulled");
    // The median distance from a point to its nearest other point.
    let tree = |p: &[DVec3]| -> kiddo::ImmutableKdTree<f64, 3> {
        kiddo::ImmutableKdTree::new_from_slice(&p.iter().map(|p| p.to_array()).collect::<Vec<_>>())
            .unwrap()
    };
    let among = tree(&points);
    let mut gaps: Vec<f64> = points
        .iter()
        .map(|p| {
            let two = among
                .query(&p.to_array())
                .nearest_n::<kiddo::SquaredEuclidean<f64>>(NonZero::new(2).unwrap())
                .execute();
            two[1].distance.sqrt()
        })
        .collect();
    gaps.sort_by(f64::total_cmp);
    let spacing = gaps[gaps.len() / 2];
    // Each point to the nearest sample of the surface, sampled at four times the texels along
    // each axis: at most the distance to the surface plus half a sample's spacing.
    let surface = wrapped.image.surface().unwrap();
    let samples = surface.sample_uniform(4 * surface.m(), 4 * surface.n(), 0, 0).unwrap().values;
    let on_surface = tree(&samples);
    let worst = points
        .iter()
        .map(|p| {
            let q = p.to_array();
            on_surface
                .query(&q)
                .nearest_one::<kiddo::SquaredEuclidean<f64>>()
                .execute()
                .distance
                .sqrt()
        })
        .fold(0.0, f64::max);
    eprintln!("duck: spacing {spacing:.4}, worst point {worst:.4}, pulled {}", wrapped.pulled);
    // The worst point lies in a crease. Where the texels fall about it depends on the sphere's
    // parameterisation, which moves with the rounding of the patches: pulled by its nearest
    // texel only, it was 1.22 of these median gaps off before the patches were fitted in the
    // units of their neighbourhoods and 1.80 after; pulling the nearby texel whose normal's
    // line passes nearest brings it to 1.34 (0.90 on a grid 8 % finer). Held so that it grows
    // no worse.
    assert!(worst < 1.4 * spacing, "{worst} (spacing {spacing})");
}
