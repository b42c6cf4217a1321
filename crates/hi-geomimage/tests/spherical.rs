// SPDX-License-Identifier: MIT
//! The spherical geometry image (algorithm 2, §5.3) on shapes whose answer is known: spheres
//! (the harmonic surface through the image is then exactly the sphere, since its texels are
//! samples of a trigonometric polynomial of degree 1 in u and v), ellipsoids (the distance
//! along a ray has a closed form), two nested spheres (never star-shaped) and a half sphere
//! (holes).

use glam::DVec3;
use hi_geomimage::Error;
use hi_geomimage::spherical::{SphericalOptions, ray_direction, spherical_image};
use hi_surface::ParamRange;

/// `n` points spread evenly over the unit sphere (a Fibonacci lattice).
fn fibonacci(n: usize) -> Vec<DVec3> {
    hi_testkit::fibonacci_sphere(n).map(DVec3::from).collect()
}

fn options(rows: usize, cols: usize) -> SphericalOptions {
    SphericalOptions { rows, cols, ..SphericalOptions::default() }
}

#[test]
fn a_sphere_gives_the_exact_harmonic_sphere() {
    let centre = DVec3::new(0.5, -1.0, 2.0);
    let points: Vec<DVec3> = fibonacci(20_000).into_iter().map(|p| centre + 3.0 * p).collect();
    let result =
        spherical_image(&points, &SphericalOptions { centre: Some(centre), ..options(32, 48) })
            .unwrap();
    assert_eq!(result.non_star_fraction, 0.0);
    assert_eq!(result.hole_fraction, 0.0);
    for r in &result.radii {
        assert!((r - 3.0).abs() < 1e-12, "every ray meets the sphere at distance 3: {r}");
    }
    let surface = result.image.surface().unwrap();
    for a in 0..40 {
        for b in 0..40 {
            let (u, v) = (a as f64 / 80.0 + 0.003, b as f64 / 40.0 + 0.001);
            let d = (surface.eval(u, v) - centre).length();
            assert!((d - 3.0).abs() < 1e-11, "p({u}, {v}) is {d} from the centre");
        }
    }
}

#[test]
fn the_image_repeats_past_the_south_pole() {
    let points = fibonacci(3000);
    let result = spherical_image(&points, &options(16, 20)).unwrap();
    let img = &result.image;
    for i in 1..16 {
        for j in 0..20 {
            assert_eq!(img.get(i, j), img.get(16 - i, j + 10), "texel ({i}, {j})");
        }
    }
    // The pole rows look along ±z whatever the column.
    for j in 0..20 {
        assert!((ray_direction(0, j, 16, 20) - DVec3::Z).length() < 1e-15);
        assert!((ray_direction(8, j, 16, 20) + DVec3::Z).length() < 1e-15);
    }
}

#[test]
fn an_ellipsoid_matches_the_distance_along_each_ray() {
    let (a, b, c) = (2.0, 1.0, 0.6);
    let points: Vec<DVec3> =
        fibonacci(200_000).into_iter().map(|p| DVec3::new(a * p.x, b * p.y, c * p.z)).collect();
    let opts = SphericalOptions { centre: Some(DVec3::ZERO), ..options(64, 64) };
    let result = spherical_image(&points, &opts).unwrap();
    assert_eq!(result.non_star_fraction, 0.0);
    let mut worst = 0.0f64;
    for i in 0..64 {
        for j in 0..64 {
            let d = ray_direction(i, j, 64, 64);
            let exact = 1.0 / ((d.x / a).powi(2) + (d.y / b).powi(2) + (d.z / c).powi(2)).sqrt();
            worst = worst.max((result.radii[i * 64 + j] - exact).abs() / exact);
        }
    }
    // Averaging over a cone of a few hundredths of a radian costs a relative error of the
    // order of the cone's angle squared times the curvature ratio.
    assert!(worst < 5e-3, "worst relative error of the ray distance: {worst:e}");
}

#[test]
fn nested_spheres_are_not_star_shaped() {
    let mut points: Vec<DVec3> = fibonacci(20_000);
    points.extend(fibonacci(20_000).into_iter().map(|p| 2.0 * p));
    let result = spherical_image(
        &points,
        &SphericalOptions { centre: Some(DVec3::ZERO), ..options(32, 32) },
    )
    .unwrap();
    assert!(result.non_star_fraction > 0.99, "{}", result.non_star_fraction);
    assert!(result.non_star.iter().all(|&b| b));
    // The outer shell is the one kept.
    assert!(result.radii.iter().all(|r| (r - 2.0).abs() < 1e-12));
}

#[test]
fn a_half_sphere_leaves_holes_that_are_filled() {
    let points: Vec<DVec3> = fibonacci(20_000).into_iter().filter(|p| p.z > 0.0).collect();
    let opts = SphericalOptions { centre: Some(DVec3::ZERO), max_angle: 0.1, ..options(32, 32) };
    let result = spherical_image(&points, &opts).unwrap();
    // Rays with z < −sin(0.1) find nothing within 0.1 rad: a little under half of the rays.
    assert!(result.hole_fraction > 0.35 && result.hole_fraction < 0.5, "{}", result.hole_fraction);
    for i in 0..32 {
        for j in 0..32 {
            let d = ray_direction(i, j, 32, 32);
            let t = i * 32 + j;
            if d.z > 0.2 {
                assert!(!result.holes[t] && (result.radii[t] - 1.0).abs() < 1e-12);
            }
            if d.z < -0.2 {
                assert!(result.holes[t], "texel ({i}, {j}) looks away from every point");
            }
            // Filled from neighbours at distance 1: the filled value is 1 too.
            assert!((result.radii[t] - 1.0).abs() < 1e-12);
        }
    }
}

#[test]
fn bad_input_is_named() {
    let points = fibonacci(100);
    let err = |o: SphericalOptions, p: &[DVec3]| spherical_image(p, &o).unwrap_err().to_string();
    assert_eq!(
        err(options(15, 16), &points),
        "image resolution 15x16 is out of range: an even number of rows (both poles are texels)"
    );
    assert_eq!(
        err(options(0, 16), &points),
        "image resolution 0x16 is out of range: each side at least 2 and at most 2²⁶ texels in all"
    );
    let mut bad = points.clone();
    bad[7].y = f64::NAN;
    assert_eq!(err(options(8, 8), &bad), "point 7 has a NaN or infinite coordinate");
    assert_eq!(err(options(8, 8), &[]), "too few points: 0 given, at least 3 needed");
    assert_eq!(
        err(
            SphericalOptions { centre: Some(DVec3::ZERO), ..options(8, 8) },
            &[DVec3::ZERO, DVec3::X]
        ),
        "too few points: 1 given, at least 3 needed"
    );
    assert_eq!(
        err(SphericalOptions { max_angle: 0.0, ..options(8, 8) }, &points),
        "option max_angle = 0 is out of range: 0 < angle ≤ π radians"
    );
    assert_eq!(
        err(SphericalOptions { centre: Some(DVec3::INFINITY), ..options(8, 8) }, &points),
        "the centre has a NaN or infinite coordinate"
    );
    assert!(matches!(
        spherical_image(&points, &SphericalOptions { neighbours: 2, ..options(8, 8) }),
        Err(Error::InvalidOption { name: "min_neighbours", .. })
    ));
}

mod octahedral {
    use super::*;
    use hi_geomimage::Smoothing;
    use hi_geomimage::spherical::{Layout, octahedral_direction};

    #[test]
    fn the_square_maps_onto_the_octahedron() {
        for k in 0..400 {
            let (s, t) = ((k % 20) as f64 / 10.0 - 0.95, (k / 20) as f64 / 10.0 - 0.95);
            let d = octahedral_direction(s, t);
            let z = 1.0 - s.abs() - t.abs();
            // The point of the octahedron |x| + |y| + |z| = 1 along d.
            let o = d / (d.x.abs() + d.y.abs() + d.z.abs());
            if z >= 0.0 {
                assert!((o - DVec3::new(s, t, z)).length() < 1e-15, "({s}, {t})");
            } else {
                // Folded: the corner triangles are the lower half, mirrored over the edges.
                assert!((o.z - z).abs() < 1e-15 && (o.x.abs() - (1.0 - t.abs())).abs() < 1e-15);
                assert!((o.y.abs() - (1.0 - s.abs())).abs() < 1e-15, "({s}, {t})");
            }
            // The symmetries that make the flattened image periodic.
            for other in
                [(2.0 - s, -t), (-s, 2.0 - t), (s + 2.0, t + 2.0), (s + 2.0, t - 2.0), (s - 4.0, t)]
            {
                let e = octahedral_direction(other.0, other.1);
                assert!((e - d).length() < 1e-14, "({s}, {t}) against {other:?}");
            }
        }
    }

    /// The largest angle between neighbouring texel directions, wrapping around.
    fn largest_step(layout: Layout, rows: usize, cols: usize) -> f64 {
        let mut worst = 0.0f64;
        for i in 0..rows {
            for j in 0..cols {
                let d = layout.direction(i, j, rows, cols);
                for (a, b) in [(i + 1, j), (i, j + 1)] {
                    worst = worst.max(d.angle_between(layout.direction(a, b, rows, cols)));
                }
            }
        }
        worst
    }

    #[test]
    fn the_flattened_octahedron_has_no_seams() {
        // Neighbouring texels look along neighbouring directions everywhere for the flattened
        // octahedron and the sphere; the plain octahedron jumps across the wrapped edges.
        let (rows, cols) = (32, 32);
        let flat = largest_step(Layout::FlatOctahedron, rows, cols);
        let sphere = largest_step(Layout::Sphere, rows, cols);
        let plain = largest_step(Layout::Octahedron, rows, cols);
        assert!(flat < 0.3 && sphere < 0.3, "flat {flat}, sphere {sphere}");
        assert!(plain > 2.0, "the plain octahedron's wrapped edges join far-apart texels: {plain}");
    }

    #[test]
    fn octahedral_images_of_a_sphere() {
        let points = fibonacci(20_000);
        let mut shrink = Vec::new();
        for layout in [Layout::Sphere, Layout::FlatOctahedron, Layout::Octahedron] {
            let options = SphericalOptions { layout, centre: Some(DVec3::ZERO), ..options(32, 32) };
            let result = spherical_image(&points, &options).unwrap();
            assert!(result.radii.iter().all(|r| (r - 1.0).abs() < 1e-12), "{layout:?}");
            assert_eq!((result.non_star_fraction, result.hole_fraction), (0.0, 0.0));
            // Gaussian smoothing pulls a curved surface inwards a little (by about σ²h²κ/2
            // for texel spacing h); across the seams of the plain octahedron it averages
            // texels from opposite sides of the sphere.
            let smooth = result.image.smoothed(Smoothing::Gaussian { sigma: 1.0 }).unwrap();
            shrink
                .push(smooth.texels().iter().map(|p| (p.length() - 1.0).abs()).fold(0.0, f64::max));
        }
        let [sphere, flat, plain] = shrink[..] else { unreachable!() };
        assert!(flat < 0.06 && sphere < 0.06, "sphere {sphere}, flat {flat}");
        assert!(plain > 5.0 * flat, "plain {plain} against flat {flat}");
        // The flattened octahedron's second half repeats the first, turned.
        let flat = SphericalOptions { layout: Layout::FlatOctahedron, ..options(16, 12) };
        let image = spherical_image(&points, &flat).unwrap().image;
        for i in 1..16 {
            for j in 0..12 {
                let twin = image.get(16 - i, (12 + 6 - j) % 12);
                assert_eq!(image.get(i, j), twin, "({i}, {j})");
            }
        }
        assert_eq!(Layout::FlatOctahedron.covering_window(), ParamRange::new(0.0, 0.5));
    }
}
