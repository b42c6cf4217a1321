// SPDX-License-Identifier: MIT
//! The local surface of a point set, its moving least-squares projection and its noise estimate
//! in any units, on samples whose answers are known: spheres, tori and parallel sheets, clean or
//! displaced by a known noise, evenly or unevenly dense.

use std::f64::consts::TAU;

use glam::DVec3;
use hi_scan::implicit::PointSurface;
use hi_scan::noise::noise_estimate;
use hi_testkit::lcg;

/// A standard normal deviate (Box–Muller).
fn gaussian(seed: &mut u64) -> f64 {
    let u = lcg(seed).max(f64::MIN_POSITIVE);
    (-2.0 * u.ln()).sqrt() * (TAU * lcg(seed)).cos()
}

/// `n` points scattered uniformly at random over the torus of radii `big` and `small` (by
/// rejection on the area element), displaced along the normal by N(0, `sigma`²).
fn torus_points(n: usize, big: f64, small: f64, sigma: f64, seed: u64) -> Vec<DVec3> {
    let mut s = seed;
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let (u, v) = (TAU * lcg(&mut s), TAU * lcg(&mut s));
        // The area element is small (big + small cos v) du dv.
        if lcg(&mut s) * (big + small) > big + small * v.cos() {
            continue;
        }
        let normal = DVec3::new(v.cos() * u.cos(), v.cos() * u.sin(), v.sin());
        let centre = DVec3::new(big * u.cos(), big * u.sin(), 0.0);
        out.push(centre + normal * (small + sigma * gaussian(&mut s)));
    }
    out
}

/// `n` points scattered uniformly at random over the unit sphere whose z lies in `z_range`
/// (Archimedes: z uniform).
fn zone_points(n: usize, (z0, z1): (f64, f64), seed: u64) -> Vec<DVec3> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            let z = z0 + (z1 - z0) * lcg(&mut s);
            let a = TAU * lcg(&mut s);
            let e = (1.0 - z * z).sqrt();
            DVec3::new(e * a.cos(), e * a.sin(), z)
        })
        .collect()
}

#[test]
fn the_noise_estimate_finds_the_noise_in_any_units() {
    // 20 000 points on a torus of radii 1 and 0.3, displaced by σ = 0.002 along the normal.
    let sigma = 0.002;
    let points = torus_points(20_000, 1.0, 0.3, sigma, 3);
    let at_one = noise_estimate(&points).sigma;
    assert!((at_one / sigma - 1.0).abs() < 0.15, "σ estimated as {at_one}, not {sigma}");
    // The same scan in other units: the estimate scales with it (a scan in metres whose
    // neighbourhoods span a millimetre is fitted as well as one in millimetres).
    for scale in [1e-4, 1e3] {
        let scaled: Vec<DVec3> = points.iter().map(|p| *p * scale).collect();
        let estimate = noise_estimate(&scaled).sigma / scale;
        assert!(
            (estimate / at_one - 1.0).abs() < 1e-6,
            "at scale {scale}: {estimate} against {at_one}"
        );
    }
}

#[test]
fn a_sparse_clean_sample_of_a_curved_surface_has_no_noise() {
    // 1 500 points on a thin torus: 24 neighbours span a third of the tube's circumference, where
    // a quadric misses the circle by far more than rounding. The scales tell that apart
    // from noise: the clean sample's estimate is below a tenth of the noise that a sample with
    // σ = 0.003 gets.
    let clean = noise_estimate(&torus_points(1_500, 1.0, 0.25, 0.0, 5)).sigma;
    let sigma = 0.003;
    let noisy = noise_estimate(&torus_points(1_500, 1.0, 0.25, sigma, 5)).sigma;
    assert!(clean < 0.1 * sigma, "clean sample: {clean}");
    assert!((noisy / sigma - 1.0).abs() < 0.35, "σ estimated as {noisy}, not {sigma}");
}

#[test]
fn the_vertices_of_a_mesh_refined_where_it_curves_have_no_noise() {
    // Wuson's vertices (the fixture) lie on its mesh exactly, so their noise is 0; the mesh is
    // dense where it curves and sparse where it is flat, so the surface's departure from a
    // quadric grows with the neighbourhood more slowly than r³. Two scales and the r³ law took
    // that slower growth for noise of 0.14 % of the diagonal; the fit over four scales finds
    // under a hundredth of that.
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/models/wuson.off");
    let scan = hi_scan::scan::read_scan(&path).unwrap();
    let mut points = scan.points.clone();
    points.sort_by(|a, b| a.to_array().partial_cmp(&b.to_array()).unwrap());
    points.dedup();
    let (lo, hi) =
        points.iter().fold((DVec3::MAX, DVec3::MIN), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let diagonal = lo.distance(hi);
    let estimate = noise_estimate(&points).sigma / diagonal;
    assert!(
        estimate < 1e-5,
        "{} points: noise estimated as {estimate} of the diagonal",
        points.len()
    );
    // Noise of 0.3 % of the diagonal, well above the surface's departure at the smallest scale,
    // is found to within 35 %.
    let mut seed = 17;
    let sigma = 3e-3 * diagonal;
    let noisy: Vec<DVec3> = points
        .iter()
        .map(|p| {
            *p + DVec3::new(gaussian(&mut seed), gaussian(&mut seed), gaussian(&mut seed)) * sigma
        })
        .collect();
    let found = noise_estimate(&noisy).sigma;
    assert!((found / sigma - 1.0).abs() < 0.35, "σ estimated as {found}, not {sigma}");
}

#[test]
fn noise_as_large_as_the_spacing_is_found_at_wider_scales() {
    // 20 000 points on a torus of radii 1 and 0.3 (spacing about 0.017), displaced along the
    // normal by σ = 0.02 and 0.04: 24 neighbours make a lump as thick as it is wide, whose
    // quadric follows the scatter (the four small scales alone found about 0.4 σ); the wider
    // neighbourhoods find σ. Noise under the spacing keeps its estimate from the small scales.
    for sigma in [0.02, 0.04] {
        let found = noise_estimate(&torus_points(20_000, 1.0, 0.3, sigma, 7));
        assert!(found.lump && !found.volume, "σ = {sigma} not taken as a lump: {found:?}");
        let found = found.sigma;
        assert!((found / sigma - 1.0).abs() < 0.12, "σ estimated as {found}, not {sigma}");
    }
    // Noise of a tenth of the spacing is no lump, and its estimate is that of the small scales.
    assert!(!noise_estimate(&torus_points(20_000, 1.0, 0.3, 0.002, 7)).lump);
    // Points filling a cube are as thick at every scale, and no wider neighbourhood is thin:
    // no lump of noise about a surface, but a volume. The noisy tori are not.
    let mut seed = 9;
    let cube: Vec<DVec3> =
        (0..3_000).map(|_| DVec3::new(lcg(&mut seed), lcg(&mut seed), lcg(&mut seed))).collect();
    let cube = noise_estimate(&cube);
    assert!(!cube.lump && cube.volume, "{cube:?}");
    // CGAL's `sphere_20k.xyz`: 21 000 points about the unit sphere whose distances from the
    // centre scatter by 0.04, twice their spacing. The estimate is that scatter, measured here
    // directly (the standard deviation of the points' distances from their centroid).
    let Some(archive) = hi_testkit::cgal_demo_data() else { return };
    let dir = std::env::temp_dir().join(format!("hi-scan-sphere20k-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let status = std::process::Command::new("tar")
        .args(["xzf", &archive.to_string_lossy(), "-C", &dir.to_string_lossy()])
        .arg("data/points_3/sphere_20k.xyz")
        .status()
        .expect("tar runs");
    assert!(status.success(), "tar could not extract sphere_20k.xyz");
    let scan = hi_scan::scan::read_scan(&dir.join("data/points_3/sphere_20k.xyz"));
    let _ = std::fs::remove_dir_all(&dir);
    let points = scan.expect("sphere_20k.xyz reads").points;
    let centre = points.iter().copied().sum::<DVec3>() / points.len() as f64;
    let radii: Vec<f64> = points.iter().map(|p| p.distance(centre)).collect();
    let mean = radii.iter().sum::<f64>() / radii.len() as f64;
    let scatter =
        (radii.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / radii.len() as f64).sqrt();
    let found = noise_estimate(&points);
    assert!(found.lump, "{found:?}");
    let found = found.sigma;
    assert!((found / scatter - 1.0).abs() < 0.1, "σ estimated as {found}, scatter {scatter}");
}

#[test]
fn patches_follow_a_small_sphere_as_closely_as_a_large_one() {
    // 4 000 points on spheres of radius 1 and 10⁻³ (a part in metres whose spacing is 50 µm):
    // points off the sphere project onto it to the accuracy of a quadric, in both units. A plane
    // through each point would miss the sphere between points by about spacing²/(2r), 10⁻³ r.
    for radius in [1.0, 1e-3] {
        let points: Vec<DVec3> =
            zone_points(4_000, (-1.0, 1.0), 11).iter().map(|p| *p * radius).collect();
        let surface = PointSurface::try_new(&points, None, 16).unwrap();
        let mut seed = 13;
        let worst = (0..500)
            .map(|_| {
                let z = 2.0 * lcg(&mut seed) - 1.0;
                let a = TAU * lcg(&mut seed);
                let e = (1.0 - z * z).sqrt();
                let direction = DVec3::new(e * a.cos(), e * a.sin(), z);
                let (q, _) = surface.project(direction * radius * 1.01, direction);
                (q.length() / radius - 1.0).abs()
            })
            .fold(0.0, f64::max);
        assert!(worst < 1e-4, "radius {radius}: projections {worst} of the radius off the sphere");
    }
}

/// The documented rule of [`PointSurface::fine_spacing`] computed by brute force: each point's
/// spacing r/√2 from its 8th nearest other point, found by sorting all distances.
fn fine_spacing_by_brute_force(points: &[DVec3]) -> (f64, f64) {
    let mut spacings: Vec<f64> = points
        .iter()
        .map(|p| {
            let mut d: Vec<f64> = points.iter().map(|q| q.distance_squared(*p)).collect();
            d.sort_by(f64::total_cmp);
            // d[0] is the point itself.
            (d[8] / 2.0).sqrt()
        })
        .collect();
    spacings.sort_by(f64::total_cmp);
    let median = spacings[spacings.len() / 2];
    let evenness = spacings[spacings.len() / 10] / (0.78 * median);
    (median, if evenness >= 0.8 { median } else { evenness.max(0.5) * median })
}

#[test]
fn the_zero_set_grid_follows_the_denser_parts() {
    // Evenly dense at random: the grid follows the median spacing.
    let even = PointSurface::try_new(&zone_points(4_000, (-1.0, 1.0), 17), None, 16).unwrap();
    let ratio = even.fine_spacing() / even.spacing();
    assert!(ratio > 0.95 && ratio <= 1.0, "even: {ratio}");
    // A cap (z > 0.8, a tenth of the sphere) with 1 000 points, the rest with 3 000: the cap is
    // three times as dense, its points a quarter of all, so the 10th percentile of the spacings
    // lies among its points and the median among the rest's.
    let mut points = zone_points(1_000, (0.8, 1.0), 19);
    points.extend(zone_points(3_000, (-1.0, 0.8), 23));
    let uneven = PointSurface::try_new(&points, None, 16).unwrap();
    let (median, fine) = fine_spacing_by_brute_force(&points);
    assert!((uneven.spacing() / median - 1.0).abs() < 1e-12);
    assert!((uneven.fine_spacing() / fine - 1.0).abs() < 1e-12);
    let ratio = fine / median;
    assert!(ratio < 0.8, "uneven: {ratio}");
    assert!((uneven.zero_set_cell() / fine - hi_scan::implicit::CELL).abs() < 1e-12);
    // And its zero set on that grid is one closed surface of genus 0 near the sphere.
    let (vertices, triangles) = uneven.zero_set(uneven.zero_set_cell()).unwrap();
    assert!(vertices.iter().all(|p| (p.length() - 1.0).abs() < 0.01));
    assert_eq!(vertices.len() as i64 - triangles.len() as i64 / 2, 2);
}

#[test]
fn moving_least_squares_keeps_to_the_sheet_it_starts_on() {
    // Two parallel sheets of a thin part, z = 0 and z = 0.04, sampled at 0.02 (staggered): a
    // point just above the lower sheet projects onto it when the fit keeps to points within
    // 0.01 of its tangent plane, and is drawn off it towards the other sheet when it takes all
    // its neighbours (a little: the weights favour the nearest points).
    let mut points = Vec::new();
    for i in 0..30 {
        for j in 0..30 {
            let (x, y) = (i as f64 * 0.02, j as f64 * 0.02);
            points.push(DVec3::new(x, y, 0.0));
            points.push(DVec3::new(x + 0.01, y + 0.01, 0.04));
        }
    }
    let mls = hi_scan::implicit::MovingLeastSquares::try_new(&points).unwrap();
    let x = DVec3::new(0.3, 0.3, 0.005);
    let q = mls.project(x, DVec3::Z, 0.01).unwrap();
    assert!(q.distance(DVec3::new(0.3, 0.3, 0.0)) < 1e-12, "{q}");
    let mixed = mls.project(x, DVec3::Z, 1.0).unwrap();
    assert!(mixed.z > 1e-4 && mixed.z < 0.035, "{mixed}");
    // Too few points within the band: no projection.
    assert!(mls.project(DVec3::new(0.3, 0.3, 0.02), DVec3::Z, 0.001).is_none());
    // Bad input is named.
    assert!(hi_scan::implicit::MovingLeastSquares::try_new(&points[..10]).is_err());
    let mut bad = points.clone();
    bad[3].x = f64::NAN;
    assert!(hi_scan::implicit::MovingLeastSquares::try_new(&bad).is_err());
}

/// A point far from every point is projected onto the patches at a height they were fitted
/// over, not along their quadrics' growth: on the paraboloid z = x² + y² sampled over
/// [−0.5, 0.5]² (its patches' quadrics z ≈ x² + y², curvature 2), the point (10, 0, 0) goes
/// to the foot on the edge patches' tangent planes, raised by at most their height at 4
/// spacings from their points (about 0.1), so no farther from it than its nearest point and
/// that; the quadrics themselves would lift it by tens along their normals. Near the points
/// the projection lies on the surface.
#[test]
fn far_points_project_to_heights_the_patches_were_fitted_over() {
    let points: Vec<DVec3> = (0..441)
        .map(|k| {
            let (x, y) = ((k % 21) as f64 * 0.05 - 0.5, (k / 21) as f64 * 0.05 - 0.5);
            DVec3::new(x, y, x * x + y * y)
        })
        .collect();
    let surface = PointSurface::try_new(&points, None, 16).unwrap();
    let x = DVec3::new(10.0, 0.0, 0.0);
    let (q, nearest) = surface.project(x, DVec3::Z);
    assert!(nearest > 9.0);
    assert!(q.is_finite() && q.distance(x) < nearest + 0.2, "{q}, nearest {nearest}");
    let (near, _) = surface.project(DVec3::new(0.1, 0.05, 0.2), DVec3::Z);
    assert!((near.z - (near.x * near.x + near.y * near.y)).abs() < 1e-3, "{near}");
    assert!(near.distance(DVec3::new(0.1, 0.05, 0.2)) < 0.2, "{near}");
}

#[test]
fn normals_with_sides_mixed_at_random_are_oriented_by_the_tree() {
    // The torus sampled with its outward normals, half of them turned in at random (their
    // directions right, their sides not one orientation, as an estimate of directions alone
    // gives): the signed distance is still negative inside the tube and positive outside,
    // everywhere round it. Given with their sides all outward, or all turned in, they keep them.
    let points = torus_points(6000, 1.0, 0.35, 0.0, 7);
    let outward: Vec<DVec3> = points
        .iter()
        .map(|p| {
            let ring = DVec3::new(p.x, p.y, 0.0).normalize();
            (*p - ring).normalize()
        })
        .collect();
    let mut seed = 11;
    let mixed: Vec<DVec3> =
        outward.iter().map(|n| if lcg(&mut seed) < 0.5 { -*n } else { *n }).collect();
    let inward: Vec<DVec3> = outward.iter().map(|n| -*n).collect();
    // Points inside the tube and outside it, half its radius from the surface.
    let probes = |sign: f64| -> Vec<DVec3> {
        (0..64)
            .map(|k| {
                let (a, b) = (TAU * k as f64 / 64.0, TAU * (k * 7 % 64) as f64 / 64.0);
                let ring = DVec3::new(a.cos(), a.sin(), 0.0);
                let across = ring * b.cos() + DVec3::Z * b.sin();
                ring + across * (0.35 + sign * 0.17)
            })
            .collect()
    };
    let sides = |normals: &[DVec3]| {
        let surface = PointSurface::try_new(&points, Some(normals), 16).unwrap();
        let count = |sign: f64| {
            probes(sign).iter().filter(|x| surface.signed_distance(**x).0 * sign > 0.0).count()
        };
        (count(-1.0), count(1.0))
    };
    assert_eq!(sides(&mixed), (64, 64), "mixed sides: the tree's, outward");
    assert_eq!(sides(&outward), (64, 64), "outward: kept");
    assert_eq!(sides(&inward), (0, 0), "inward: kept, every sign the other way");
}

#[test]
fn the_zero_set_of_parts_far_apart_is_found_on_a_sparse_grid() {
    // Two unit spheres of 2000 points each, 260 radii apart along the diagonal: the grid of the
    // zero set spans about 2·10⁹ nodes (beyond a dense grid's 2²⁷), of which only the bands
    // about the spheres are stored. Each sphere gives its own closed part, on the sphere.
    let sphere = |centre: DVec3| -> Vec<DVec3> {
        (0..2000)
            .map(|k| {
                let z = 1.0 - (2 * k + 1) as f64 / 2000.0;
                let phi = k as f64 * 2.399_963_229_728_653;
                let s = (1.0 - z * z).sqrt();
                centre + DVec3::new(s * phi.cos(), s * phi.sin(), z)
            })
            .collect()
    };
    let far = DVec3::splat(150.0);
    let points = [sphere(DVec3::ZERO), sphere(far)].concat();
    let surface = PointSurface::try_new(&points, None, 16).unwrap();
    let cell = hi_scan::implicit::CELL * surface.spacing();
    let nodes = (far + DVec3::splat(2.0)) / cell;
    assert!(nodes.x * nodes.y * nodes.z > (1u64 << 27) as f64);
    let (vertices, triangles) = surface.zero_set(cell).unwrap();
    let parts = hi_scan::repair::mesh_parts(&vertices, &triangles).unwrap();
    assert_eq!(parts.parts.len(), 2);
    for part in &parts.parts {
        let centre = if part.positions[0].length() < 2.0 { DVec3::ZERO } else { far };
        assert!(part.positions.iter().all(|p| (p.distance(centre) - 1.0).abs() < 0.02));
        // Closed, of genus 0.
        assert_eq!(part.positions.len() as i64 - part.triangles.len() as i64 / 2, 2);
    }
}
