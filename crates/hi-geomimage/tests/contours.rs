// SPDX-License-Identifier: MIT
//! The §5.8 geometry image of contours: rows of located scan points, each made into a
//! harmonic contour and resampled to the columns by Theorem 5.3.

use glam::DVec3;
use hi_curve::HarmonicCurve;
use hi_geomimage::contours::contour_image;
use hi_geomimage::spherical::SphericalOptions;
use hi_geomimage::{FitOptions, Layout, Method, fit};
use hi_scan::scan::Scan;

/// `n` points on the ellipsoid with semi-axes `axes` (a Fibonacci lattice).
fn ellipsoid(n: usize, axes: DVec3) -> Vec<DVec3> {
    hi_testkit::fibonacci_sphere(n).map(|d| axes * DVec3::from(d)).collect()
}

/// The distinct values of a cyclic row, in order (runs once, the wrap joined).
fn distinct(row: &[Option<usize>]) -> Vec<usize> {
    let mut list: Vec<usize> = Vec::new();
    for v in row.iter().flatten() {
        if list.last() != Some(v) {
            list.push(*v);
        }
    }
    while list.len() > 1 && list.last() == list.first() {
        list.pop();
    }
    list
}

#[test]
fn each_row_is_the_harmonic_contour_through_its_located_points() {
    let points = ellipsoid(30_000, DVec3::new(1.4, 1.0, 0.8));
    let (rows, cols) = (24, 40);
    for layout in [Layout::FlatOctahedron, Layout::Sphere, Layout::Octahedron] {
        let options = SphericalOptions { layout, rows, cols, ..SphericalOptions::default() };
        let image = contour_image(&points, &options).unwrap();
        assert!(image.empty_rows.is_empty() && image.hole_fraction == 0.0);
        // The rows that are neither mirrors nor their own mirror.
        let free: Vec<usize> = match layout {
            Layout::Octahedron => (0..rows).collect(),
            _ => (1..rows / 2).collect(),
        };
        for i in free {
            let list = distinct(&image.located[i * cols..(i + 1) * cols]);
            assert_eq!(list.len(), image.row_points[i], "{layout:?} row {i}");
            // The harmonic curve through the image's row (N = cols samples) is the curve
            // through the row's K located points: it passes through them at k/K.
            let row: Vec<DVec3> = (0..cols).map(|j| image.image.get(i, j)).collect();
            let curve = HarmonicCurve::try_new(row).unwrap();
            for (k, &p) in list.iter().enumerate() {
                let at = curve.eval(k as f64 / list.len() as f64);
                assert!(at.distance(points[p]) < 1e-11, "{layout:?} row {i} point {k}");
            }
        }
    }
}

#[test]
fn doubled_layouts_keep_their_symmetry_exactly() {
    let points = ellipsoid(20_000, DVec3::new(1.2, 1.0, 0.9));
    let (rows, cols) = (16, 24);
    let options = SphericalOptions {
        layout: Layout::FlatOctahedron,
        rows,
        cols,
        ..SphericalOptions::default()
    };
    let image = contour_image(&points, &options).unwrap();
    for i in 0..rows {
        for j in 0..cols {
            // The flattened octahedron's half-turn: (i, j) and (rows − i, cols/2 − j).
            let (a, b) = ((rows - i) % rows, (cols + cols / 2 - j) % cols);
            assert_eq!(image.image.get(i, j), image.image.get(a, b), "({i}, {j})");
        }
    }
}

#[test]
fn a_fit_from_contours_stays_on_the_ellipsoid() {
    let axes = DVec3::new(1.5, 1.0, 0.7);
    let scan = Scan { points: ellipsoid(60_000, axes), ..Scan::default() };
    let options = FitOptions {
        method: Method::Contours,
        layout: Layout::FlatOctahedron,
        resolution: Some((64, 64)),
        ..FitOptions::thesis()
    };
    let result = fit(&scan, &options, &mut |_| {}).unwrap();
    let rp = result.report.row_points.unwrap();
    assert!(rp.min >= 16 && rp.max <= 64 && rp.empty_rows == 0, "{rp:?}");
    // Texels are scan points or lie on contours between them: the surface stays within a few
    // thousandths of the diagonal of the ellipsoid (|x/a|² + … = 1 off by at most 1%).
    let errors = result.report.errors.as_ref().unwrap();
    let [mean, _, max] = errors.relative();
    assert!(mean < 2e-3 && max < 2e-2, "mean {mean}, max {max}");
    for i in 0..32 {
        for j in 0..64 {
            let p = result.largest().surface.eval(i as f64 / 64.0, j as f64 / 64.0) / axes;
            assert!((p.length() - 1.0).abs() < 0.01, "({i}, {j}): {}", p.length());
        }
    }
}
