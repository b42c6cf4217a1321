// SPDX-License-Identifier: MIT
//! End-to-end tests of `hi fit --param sections` (algorithm 1, §5.3) on scans generated here:
//! rings on an ellipsoid (the fitted grid lies on it, the report carries every section),
//! random points on a sphere (fitted badly: warnings and problems), and bad options.

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use std::f64::consts::TAU;

use common::{TempFile, bad, num, run};
use serde_json::Value;

/// `k` rings of `per_ring` points on the ellipsoid with semi-axes `axes`, at the centres of `k`
/// equal slabs of z, each turned by a different phase, as XYZ text.
fn rings_xyz(k: usize, per_ring: usize, axes: [f64; 3]) -> String {
    let mut text = String::new();
    for i in 0..k {
        let z = axes[2] * ((2 * i + 1) as f64 / k as f64 - 1.0);
        let s = (1.0 - (z / axes[2]).powi(2)).sqrt();
        for j in 0..per_ring {
            let phi = TAU * (j as f64 + 0.37 * i as f64) / per_ring as f64;
            text += &format!("{} {} {}\n", axes[0] * s * phi.cos(), axes[1] * s * phi.sin(), z);
        }
    }
    text
}

fn scan_file(text: &str) -> TempFile {
    let file = TempFile::path_with("xyz");
    std::fs::write(file.as_path(), text).expect("temp file is writable");
    file
}

#[test]
fn rings_on_an_ellipsoid_give_a_grid_on_it_and_a_report_per_section() {
    let axes = [1.5, 1.0, 0.7];
    let scan = scan_file(&rings_xyz(10, 16, axes));
    let grid_file = TempFile::path_with("json");
    let report_file = TempFile::path_with("json");
    let args = [
        "fit",
        scan.path(),
        "-o",
        grid_file.path(),
        "--param",
        "sections",
        "--slices",
        "10",
        "--report",
        report_file.path(),
    ];
    let out = run(&args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stderr.is_empty(), "no warnings: {}", String::from_utf8_lossy(&out.stderr));
    let summary: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let report: Value =
        serde_json::from_str(&std::fs::read_to_string(report_file.as_path()).expect("report"))
            .expect("JSON");
    assert_eq!(report, summary, "the report file holds the printed summary");
    assert_eq!(summary["points"].as_u64(), Some(160));
    let sections = summary["sections"].as_array().expect("sections");
    assert_eq!(sections.len(), 10);
    for s in sections {
        assert_eq!(s["points"].as_u64(), Some(16));
        assert_eq!(s["misordered"].as_f64(), Some(0.0));
    }
    // N: the least even number above 16; the grid 2K × N.
    assert_eq!(summary["contour_points"].as_u64(), Some(18));
    assert_eq!(summary["surface"], serde_json::json!([20, 18]));
    assert_eq!(summary["problems"], serde_json::json!([]));
    assert!(num(&summary["deviation"]) < num(&summary["deviation_unaligned"]));
    // The grid's points lie on the ellipses of the rings (a regular polygon's harmonic curve is
    // its ellipse), so on the ellipsoid.
    let grid: Value =
        serde_json::from_str(&std::fs::read_to_string(grid_file.as_path()).expect("grid"))
            .expect("JSON");
    let rows = grid["grid"].as_array().expect("rows");
    assert_eq!(rows.len(), 20);
    for row in rows {
        for p in row.as_array().expect("a row") {
            let [x, y, z] = [0, 1, 2].map(|i| num(&p[i]));
            let q = (x / axes[0]).powi(2) + (y / axes[1]).powi(2) + (z / axes[2]).powi(2);
            assert!((q - 1.0).abs() < 1e-12, "({x}, {y}, {z}): {q}");
        }
    }
    // And as a mesh: a GLB that reads back.
    let glb = TempFile::path_with("glb");
    let out = run(&["fit", scan.path(), "-o", glb.path(), "--param", "sections", "--slices", "10"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let (doc, _, _) = gltf::import(glb.as_path()).expect("the GLB reads back");
    assert_eq!(doc.meshes().count(), 1);
}

#[test]
fn random_points_on_a_sphere_fit_badly_and_say_so() {
    // A fixed scatter (a 64-bit LCG) of 500 points on the unit sphere.
    let mut state = 2005u64;
    let mut next = || {
        state =
            state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut text = String::new();
    for _ in 0..500 {
        let (z, a) = (2.0 * next() - 1.0, TAU * next());
        let s = (1.0 - z * z).sqrt();
        text += &format!("{} {} {}\n", s * a.cos(), s * a.sin(), z);
    }
    let scan = scan_file(&text);
    let out_file = TempFile::path_with("json");
    let out =
        run(&["fit", scan.path(), "-o", out_file.path(), "--param", "sections", "--axis", "z"]);
    assert!(out.status.success());
    let summary: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let problems = summary["problems"].as_array().expect("problems");
    assert!(!problems.is_empty());
    let stderr = String::from_utf8(out.stderr).expect("UTF-8");
    assert_eq!(stderr.lines().count(), problems.len(), "one warning per problem");
    assert!(stderr.lines().all(|l| l.starts_with("hi: warning: section")), "{stderr}");
}

#[test]
fn bad_options_name_the_problem() {
    let scan = scan_file(&rings_xyz(6, 8, [1.0; 3]));
    let out = TempFile::path_with("json");
    let fit = |extra: &[&str], expected: &str| {
        let mut args = vec!["fit", scan.path(), "-o", out.path(), "--param", "sections"];
        args.extend_from_slice(extra);
        bad(&args, expected);
    };
    fit(&["--slices", "1"], "option slices = 1 is out of range");
    fit(&["--slices", "x"], "not a whole number");
    fit(&["--slices", "12"], "section 1 of 12");
    fit(&["--axis", "w"], "--axis");
    fit(&["--smooth", "1"], "--smooth is for the geometry images");
    fit(&["--axis", "x", "--slices", "40"], "section 0 of 40");
}
