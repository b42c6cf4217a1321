// SPDX-License-Identifier: MIT
//! Large clouds: the grid summary against sums computed here point by point, the cell chosen
//! for a count against the count it gives, and the zero set of points scattered at random (not
//! on a grid) closed with no holes: the spacing the local surface estimates follows the density
//! for both.

use std::f64::consts::{PI, TAU};

use glam::DVec3;
use hi_scan::cloud::{cell_for_count, occupied_cells, spatial_order, summarise};
use hi_scan::implicit::{CELL, PointSurface};
use hi_scan::repair::mesh_parts;

/// A deterministic pseudo-random sequence in [0, 1).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

/// `n` points scattered uniformly at random over the sphere of radius `r` (Archimedes: z
/// uniform), displaced along the normal by up to ±`noise`.
fn sphere_points(n: usize, r: f64, noise: f64, seed: u64) -> Vec<DVec3> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            let z = 2.0 * lcg(&mut s) - 1.0;
            let a = TAU * lcg(&mut s);
            let e = (1.0 - z * z).sqrt();
            DVec3::new(e * a.cos(), e * a.sin(), z) * (r + noise * (2.0 * lcg(&mut s) - 1.0))
        })
        .collect()
}

#[test]
fn a_summary_is_the_mean_of_each_cell() {
    let points = sphere_points(20_000, 1.0, 0.0, 7);
    let normals: Vec<DVec3> = points.iter().map(|p| *p * 3.0).collect();
    let cell = 0.05;
    let s = summarise(&points, Some(&normals), cell).unwrap();
    assert_eq!(s.counts.iter().map(|&c| c as usize).sum::<usize>(), points.len());
    assert_eq!(s.points.len(), occupied_cells(&points, cell).unwrap());
    // Every summary point is the mean of the points in its cell, grouped here by a hash map.
    let lo = points.iter().fold(DVec3::INFINITY, |a, p| a.min(*p));
    let mut cells: std::collections::HashMap<[i64; 3], (DVec3, usize)> = Default::default();
    for p in &points {
        #[expect(clippy::cast_possible_truncation, reason = "a small grid")]
        let key = ((*p - lo) / cell).floor().to_array().map(|x| x as i64);
        let e = cells.entry(key).or_default();
        e.0 += *p;
        e.1 += 1;
    }
    assert_eq!(cells.len(), s.points.len());
    for (q, &c) in s.points.iter().zip(&s.counts) {
        #[expect(clippy::cast_possible_truncation, reason = "a small grid")]
        let key = ((*q - lo) / cell).floor().to_array().map(|x| x as i64);
        let (sum, count) = cells[&key];
        assert_eq!(count, c as usize, "{key:?}");
        assert!(q.distance(sum / count as f64) < 1e-12, "{key:?}");
    }
    // The normals of points on a sphere average to the outward radial direction of the cell.
    let normals = s.normals.expect("normals given");
    for (q, n) in s.points.iter().zip(&normals) {
        assert!(n.dot(q.normalize()) > 0.99, "{q} {n}");
    }
}

#[test]
fn the_cell_for_a_count_gives_that_count() {
    // A surface (300 000 points on a sphere) and a curve-like cloud (points along a helix).
    let points = sphere_points(300_000, 2.0, 0.0, 3);
    for target in [2_000, 20_000, 60_000] {
        let cell = cell_for_count(&points, target).unwrap();
        let found = occupied_cells(&points, cell).unwrap() as f64;
        assert!((found / target as f64 - 1.0).abs() < 0.1, "{target}: {found}");
    }
    let helix: Vec<DVec3> = (0..100_000)
        .map(|k| {
            let t = k as f64 / 100_000.0 * 20.0 * PI;
            DVec3::new(t.cos(), t.sin(), 0.05 * t)
        })
        .collect();
    let cell = cell_for_count(&helix, 5_000).unwrap();
    let found = occupied_cells(&helix, cell).unwrap() as f64;
    assert!((found / 5_000.0 - 1.0).abs() < 0.1, "helix: {found}");
}

#[test]
fn bad_clouds_are_named() {
    let points = sphere_points(100, 1.0, 0.0, 1);
    assert!(summarise(&[], None, 0.1).is_err());
    assert!(summarise(&points, None, 0.0).is_err());
    assert!(summarise(&points, None, f64::NAN).is_err());
    assert!(summarise(&points, Some(&[DVec3::Z]), 0.1).is_err());
    assert!(summarise(&[DVec3::ZERO, DVec3::NAN], None, 0.1).is_err());
    // 2²¹ cells along an axis at most.
    assert!(summarise(&points, None, 1e-9).is_err());
    assert!(cell_for_count(&points, 1_000).is_err(), "more cells than points");
    assert!(cell_for_count(&[DVec3::ONE; 50], 10).is_err(), "all points coincide");
    assert!(spatial_order(&[]).is_empty());
}

#[test]
fn points_scattered_at_random_close_with_no_hole() {
    // Random points have nearest neighbours about half as far as their spacing: a zero set on a
    // grid of 1.5 nearest-neighbour distances would break into holes (every fit of a sampled
    // cloud did). On the spacing from the density, it is one closed surface of genus 0.
    let points = sphere_points(40_000, 1.0, 1e-4, 11);
    let surface = PointSurface::try_new(&points, None, 16).unwrap();
    // 40 000 points on an area of 4π, at random: a spacing of 2/√(π·density) = 4/√40 000.
    let expected = 2.0 / (PI * 40_000.0 / (4.0 * PI)).sqrt();
    assert!((surface.spacing() / expected - 1.0).abs() < 0.1, "{}", surface.spacing());
    let (v, t) = surface.zero_set(CELL * surface.spacing()).unwrap();
    let parts = mesh_parts(&v, &t).unwrap();
    assert_eq!(parts.parts.len(), 1, "one part");
    let topology = hi_scan::repair::part_topology(&parts.parts[0]);
    assert_eq!((topology.genus, topology.loops.len()), (0, 0), "{topology:?}");
    assert!(v.iter().all(|p| (p.length() - 1.0).abs() < 0.01));
}
