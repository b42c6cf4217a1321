// SPDX-License-Identifier: MIT
//! End-to-end tests of `hi surface bezier` (§5.7): the patch file passes through the grid
//! points, the Hermite report meets the tolerance, meshes read back with `gltf` with one
//! colour per patch, the OBJ free-form file has one surface per patch, and bad input fails.

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use common::{TempFile, bad_on, dist, num, ok, points};
use serde_json::Value;

/// The grid file of `hi surface example ARGS`, as text.
fn example(args: &[&str]) -> String {
    let mut all = vec!["surface", "example"];
    all.extend(args);
    ok(&all).to_string()
}

/// Runs `hi surface bezier` on `grid` with `args`, writing to a temporary file with `ext`.
fn convert(grid: &str, ext: &str, args: &[&str]) -> (Value, TempFile) {
    let input = TempFile::new(grid);
    let out = TempFile::path_with(ext);
    let mut all = vec!["surface", "bezier", "--input", input.path(), "-o", out.path()];
    all.extend(args);
    (ok(&all), out)
}

/// The Bernstein basis value Bᵈᵢ(s).
fn bernstein(d: usize, i: usize, s: f64) -> f64 {
    let binom = (0..i).fold(1.0, |acc, k| acc * (d - k) as f64 / (k + 1) as f64);
    binom * s.powi(i as i32) * (1.0 - s).powi((d - i) as i32)
}

#[test]
fn thesis_patches_in_json_pass_through_the_grid() {
    let grid = example(&["torus", "--samples", "6x5"]);
    let (out, file) = convert(&grid, "json", &["--scheme", "thesis-cubic"]);
    assert_eq!(out["report"]["patches"], 30, "m×n patches");
    let json: Value =
        serde_json::from_str(&std::fs::read_to_string(file.as_path()).expect("written"))
            .expect("JSON");
    let rows: Vec<Vec<Vec<f64>>> = {
        let g: Value = serde_json::from_str(&grid).expect("grid");
        g["grid"].as_array().expect("rows").iter().map(points).collect()
    };
    let patches = json["patches"].as_array().expect("patches");
    // Patch (a, b) starts at grid point (a, b): evaluate its Bézier form at (0, 0) and at the
    // far corner by the Bernstein sum, written here.
    for (idx, patch) in patches.iter().enumerate() {
        let (a, b) = (idx / 5, idx % 5);
        let control: Vec<Vec<Vec<f64>>> =
            patch["control"].as_array().expect("control").iter().map(points).collect();
        let eval = |s: f64, t: f64| {
            let mut p = [0.0; 3];
            for (i, row) in control.iter().enumerate() {
                for (j, c) in row.iter().enumerate() {
                    let w = bernstein(3, i, s) * bernstein(3, j, t);
                    for d in 0..3 {
                        p[d] += w * c[d];
                    }
                }
            }
            p.to_vec()
        };
        assert!(dist(&eval(0.0, 0.0), &rows[a][b]) < 1e-12, "patch ({a}, {b}) corner");
        assert!(dist(&eval(1.0, 1.0), &rows[(a + 1) % 6][(b + 1) % 5]) < 1e-12, "far corner");
        assert_eq!(num(&patch["u"][0]), a as f64 / 6.0, "window");
    }
}

#[test]
fn hermite_patches_meet_the_tolerance_and_mesh_with_a_colour_per_patch() {
    let grid = example(&["torus"]);
    let (out, file) = convert(&grid, "glb", &["--tolerance", "1e-3", "--samples", "4"]);
    let report = &out["report"];
    assert!(num(&report["bound"]) <= 1e-3, "{report}");
    assert!(num(&report["max_deviation"]) <= num(&report["bound"]), "{report}");
    assert!(num(&report["max_normal_jump"]) < 1e-7, "C1: {report}");
    let patches = report["patches"].as_u64().expect("count") as usize;
    let (doc, buffers, _) = gltf::import(file.as_path()).expect("valid glTF");
    let prim = doc.meshes().next().expect("mesh").primitives().next().expect("primitive");
    let reader = prim.reader(|b| Some(&buffers[b.index()]));
    let colors: Vec<[f32; 3]> = reader.read_colors(0).expect("COLOR_0").into_rgb_f32().collect();
    assert_eq!(colors.len(), patches * 25, "(k + 1)² vertices per patch");
    for chunk in colors.chunks(25) {
        assert!(chunk.iter().all(|c| c == &chunk[0]), "one colour per patch");
    }
}

#[test]
fn obj_output_has_one_free_form_surface_per_patch() {
    let grid = example(&["sphere"]);
    let (out, file) = convert(&grid, "obj", &["--scheme", "thesis-cubic"]);
    let text = std::fs::read_to_string(file.as_path()).expect("written");
    assert_eq!(out["report"]["patches"], 16, "4×4 patches");
    assert_eq!(text.matches("cstype bezier").count(), 16, "cstype per patch");
    assert_eq!(text.lines().filter(|l| l.starts_with("surf ")).count(), 16, "surf per patch");
    assert_eq!(text.lines().filter(|l| l.starts_with("v ")).count(), 256, "16 control points each");
}

#[test]
fn bad_input_is_one_line() {
    let grid = example(&["torus"]);
    bad_on(&grid, &["surface", "bezier", "-o", "x.stl"], "unknown extension");
    bad_on(&grid, &["surface", "bezier", "-o", "x.json", "--tolerance", "0"], "tolerance");
    bad_on(&grid, &["surface", "bezier", "-o", "x.json", "--scheme", "cubic"], "unknown scheme");
    bad_on(&grid, &["surface", "bezier", "-o", "x.glb", "--samples", "0"], "--samples");
    let small = example(&["torus", "--samples", "2x6"]);
    bad_on(&small, &["surface", "bezier", "-o", "x.json", "--scheme", "thesis-quintic"], "n ≥ 3");
}
