// SPDX-License-Identifier: MIT
//! End-to-end tests of `hi fit` on scans generated here: points on an ellipsoid (the fitted
//! grid must lie on it), two nested spheres (no surface passes through both: the inner one is
//! named as unreached, and the rays as well when the surface follows them), the cactus (not star-shaped, but wrapped from its signed distance: no warning),
//! and malformed files (one line naming the problem).

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use common::{TempFile, bad, ellipsoid_xyz, num, ok, run};
use serde_json::Value;

fn scan_file(text: &str, ext: &str) -> TempFile {
    let file = TempFile::path_with(ext);
    std::fs::write(file.as_path(), text).expect("temp file is writable");
    file
}

#[test]
fn an_ellipsoid_fits_and_its_grid_lies_on_it() {
    let axes = [1.5, 1.0, 0.7];
    let scan = scan_file(&ellipsoid_xyz(40_000, axes), "xyz");
    let grid_file = TempFile::path_with("json");
    let report_file = TempFile::path_with("json");
    let out = ok(&[
        "fit",
        scan.path(),
        "-o",
        grid_file.path(),
        "--resolution",
        "32x32",
        "--param",
        "flat-octahedron",
        "--report",
        report_file.path(),
    ]);
    assert_eq!(out["points"].as_u64(), Some(40_000));
    assert_eq!(num(&out["non_star_fraction"]), 0.0);
    // Bare points are wrapped from the zero set of their signed distance, and the summary
    // says so.
    assert_eq!(out["method"], "shrink-wrap");
    let reason = out["method_reason"].as_str().expect("a reason");
    assert!(reason.contains("zero set of their signed distance"), "{reason}");
    let report: Value =
        serde_json::from_str(&std::fs::read_to_string(report_file.as_path()).expect("report"))
            .expect("JSON");
    assert_eq!(report, out, "the report file holds the printed summary");
    let relative = out["errors"]["relative"].as_array().expect("errors");
    assert!(num(&relative[0]) < 1e-3, "mean distance {}", relative[0]);
    // The grid's points are the geometry image's texels: on the ellipsoid.
    let grid: Value =
        serde_json::from_str(&std::fs::read_to_string(grid_file.as_path()).expect("grid"))
            .expect("JSON");
    let rows = grid["grid"].as_array().expect("rows");
    assert_eq!(rows.len(), 32);
    for row in rows {
        for p in row.as_array().expect("a row") {
            let [x, y, z] = [0, 1, 2].map(|i| num(&p[i]));
            let q = (x / axes[0]).powi(2) + (y / axes[1]).powi(2) + (z / axes[2]).powi(2);
            assert!((q - 1.0).abs() < 1e-2, "({x}, {y}, {z}): {q}");
        }
    }
    // And as a mesh: a GLB that reads back.
    let glb = TempFile::path_with("glb");
    let out =
        ok(&["fit", scan.path(), "-o", glb.path(), "--resolution", "16x16", "--reduce", "0.25"]);
    assert_eq!(out["surface"], serde_json::json!([8, 8]));
    assert!(num(&out["reduction"]["max_deviation"]) <= num(&out["reduction"]["upper_bound"]));
    let (doc, _, _) = gltf::import(glb.as_path()).expect("the GLB reads back");
    assert_eq!(doc.meshes().count(), 1);
}

/// Two nested spheres: the default fit finds two parts and fits each on its own, so every point
/// is reached and both spheres are written as named meshes; the rays of `--method radial`
/// cannot pass through both, so that surface follows the outer shell, and the inner sphere's
/// points (half of them, each 1 from the outer sphere, 14% of the diagonal) are named as
/// unreached, and the rays that met both as well.
#[test]
fn nested_spheres_are_two_parts_and_the_rays_get_a_warning() {
    let mut text = ellipsoid_xyz(5000, [1.0; 3]);
    text.push_str(&ellipsoid_xyz(5000, [2.0; 3]));
    let scan = scan_file(&text, "xyz");
    let out_file = TempFile::path_with("glb");
    let fitted = |method: &str| {
        let out = run(&[
            "fit",
            scan.path(),
            "-o",
            out_file.path(),
            "--resolution",
            "16x16",
            "--centre",
            "0,0,0",
            "--method",
            method,
        ]);
        assert_eq!(out.status.code(), Some(0), "{method}");
        let report: Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
        (report, String::from_utf8(out.stderr).expect("UTF-8"))
    };
    let (report, stderr) = fitted("auto");
    assert_eq!(report["topology"]["parts"], 2, "{report}");
    assert_eq!(report["parts"][0]["name"], "part 1");
    // The outer sphere has four times the inner one's area.
    let share = num(&report["parts"][0]["area_fraction"]);
    assert!((share - 0.8).abs() < 0.02, "{share}");
    assert!(num(&report["both_ways"]["unreached_fraction"]) == 0.0, "{report}");
    assert!(
        stderr.starts_with("hi: note:")
            && stderr.contains("2 parts")
            && !stderr.contains("warning"),
        "{stderr}"
    );
    let (doc, _, _) = gltf::import(out_file.as_path()).expect("the GLB reads back");
    let names: Vec<&str> = doc.nodes().filter_map(|n| n.name()).collect();
    assert_eq!(names, ["part 1", "part 2"]);
    let (_, radial) = fitted("radial");
    let lines: Vec<&str> = radial.lines().collect();
    assert_eq!(lines.len(), 2, "{radial}");
    assert!(lines[0].starts_with("hi: warning: 100.0% of the rays meet"), "{radial}");
    assert!(
        lines[1].starts_with("hi: warning: 50.0% of the points of")
            && lines[1].ends_with("they lie inside the outermost shell"),
        "{radial}"
    );
}

/// The cactus's arms hide parts of it from the centre, but the shrink-wrap from the zero set of
/// its signed distance reaches them: no warning, every point reached, and the hole the scan
/// leaves at its base named as closed.
#[test]
fn a_wrapped_scan_that_is_not_star_shaped_gets_no_warning() {
    let scan = concat!(env!("CARGO_MANIFEST_DIR"), "/../../fixtures/models/cactus.pts");
    let glb = TempFile::path_with("glb");
    let out = run(&["fit", scan, "-o", glb.path()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert!(!stderr.contains("warning"), "no warning: {stderr}");
    let report: Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    assert_eq!(report["method"], "shrink-wrap");
    assert!(
        report["method_reason"].as_str().is_some_and(|r| r.contains("zero set")),
        "{}",
        report["method_reason"]
    );
    assert_eq!(report["topology"]["genus"], serde_json::json!([0]));
    let holes = report["parts"][0]["holes_filled"].as_u64().expect("holes");
    if holes > 0 {
        assert!(stderr.contains(&format!("part 1: {holes} hole")), "{stderr}");
    }
    assert!(
        num(&report["both_ways"]["unreached_fraction"]) < 0.001,
        "{}",
        report["both_ways"]["unreached_fraction"]
    );
}

#[test]
fn bad_scans_and_options_are_named() {
    let out = TempFile::path_with("glb");
    let scan = scan_file("0 0 0\n1 0 0\n0 1\n", "xyz");
    bad(&["fit", scan.path(), "-o", out.path()], "XYZ, line 3: expected 3 numbers");
    let good = scan_file(&ellipsoid_xyz(500, [1.0; 3]), "xyz");
    bad(&["fit", good.path(), "-o", "out.stl"], "-o:");
    bad(&["fit", good.path(), "-o", out.path(), "--resolution", "15x16"], "an even number of rows");
    bad(&["fit", good.path(), "-o", out.path(), "--reduce", "2"], "reduce");
    bad(
        &["fit", good.path(), "-o", out.path(), "--centre", "1,2"],
        "--centre: expected three numbers",
    );
    bad(&["fit", "scan.las", "-o", out.path()], "unknown scan format");
}

#[test]
fn bezier_output_meets_its_tolerance_and_covers_the_object_once() {
    let scan = scan_file(&ellipsoid_xyz(20_000, [1.5, 1.0, 0.7]), "xyz");
    // The patches as JSON: the corners of the Hermite patches lie on the fitted surface, whose
    // grid points are on the ellipsoid.
    let json = TempFile::path_with("json");
    let out = ok(&[
        "fit",
        scan.path(),
        "-o",
        json.path(),
        "--resolution",
        "16x16",
        "--bezier",
        "--tolerance",
        "1e-3",
    ]);
    let b = &out["bezier"];
    assert_eq!(b["scheme"], "hermite", "default scheme");
    assert!(num(&b["bound"]) <= 1e-3 && num(&b["max_deviation"]) <= num(&b["bound"]), "{b}");
    assert!(num(&b["max_normal_jump"]) < 1e-6, "C1: {b}");
    let file: Value =
        serde_json::from_str(&std::fs::read_to_string(json.as_path()).expect("patches"))
            .expect("JSON");
    assert_eq!(
        file["patches"].as_array().expect("patches").len() as u64,
        b["patches"].as_u64().expect("count"),
        "every patch is in the file"
    );
    // The sphere layout covers the object over u ∈ [0, ½]: half the patch rows.
    assert_eq!(b["patches_once"].as_u64().expect("once") * 2, b["patches"].as_u64().expect("all"));
    // The thesis scheme as a coloured mesh: one colour per patch.
    let glb = TempFile::path_with("glb");
    let out = ok(&[
        "fit",
        scan.path(),
        "-o",
        glb.path(),
        "--resolution",
        "16x16",
        "--bezier",
        "--bezier-scheme",
        "thesis-cubic",
    ]);
    assert_eq!(out["bezier"]["patches"], 256, "m×n thesis patches");
    let (doc, buffers, _) = gltf::import(glb.as_path()).expect("the GLB reads back");
    let prim = doc.meshes().next().expect("mesh").primitives().next().expect("primitive");
    let colors: Vec<[f32; 3]> = prim
        .reader(|buf| Some(&buffers[buf.index()]))
        .read_colors(0)
        .expect("COLOR_0")
        .into_rgb_f32()
        .collect();
    assert_eq!(colors.len(), 128 * 25, "the 128 patches of one cover, 5×5 vertices each");
    bad(&["fit", scan.path(), "-o", "x.glb", "--tolerance", "1e-3"], "apply with --bezier only");
    bad(
        &["fit", scan.path(), "-o", "x.glb", "--param", "sections", "--bezier"],
        "geometry-image layouts",
    );
    bad(&["fit", scan.path(), "-o", "x.glb", "--bezier", "--tolerance", "0"], "tolerance");
    bad(
        &["fit", scan.path(), "-o", "x.glb", "--bezier-scheme", "hermite"],
        "apply with --bezier only",
    );
}

#[test]
fn contours_of_located_points_give_the_combined_pipeline_of_section_5_8() {
    let axes = [1.5, 1.0, 0.7];
    let scan = scan_file(&ellipsoid_xyz(40_000, axes), "xyz");
    let glb = TempFile::path_with("glb");
    // §5.8: a flattened octahedron sampled finer than needed, smoothed, reduced to a quarter,
    // then Bézier patches.
    let out = ok(&[
        "fit",
        scan.path(),
        "-o",
        glb.path(),
        "--param",
        "flat-octahedron",
        "--method",
        "contours",
        "--resolution",
        "64x64",
        "--smooth",
        "0.7",
        "--reduce",
        "0.25",
        "--bezier",
    ]);
    assert_eq!(out["surface"], serde_json::json!([32, 32]));
    let rows = &out["row_points"];
    assert!(rows["min"].as_u64().expect("min") >= 16, "{rows}");
    assert!(rows["max"].as_u64().expect("max") <= 64, "{rows}");
    assert_eq!(rows["empty_rows"].as_u64(), Some(0));
    let relative = out["errors"]["relative"].as_array().expect("errors");
    assert!(num(&relative[0]) < 3e-3, "mean distance {}", relative[0]);
    assert!(out["bezier"]["max_deviation"].is_number(), "{out}");
    // The radial image has no row counts.
    let plain = ok(&["fit", scan.path(), "-o", glb.path(), "--resolution", "16x16"]);
    assert!(plain["row_points"].is_null());
    bad(
        &["fit", scan.path(), "-o", glb.path(), "--param", "sections", "--method", "contours"],
        "--method applies to the geometry-image layouts",
    );
}

#[test]
fn a_glb_scan_without_normals_is_fitted_where_its_node_puts_it() {
    let axes = [1.5f32, 1.0, 0.7];
    let (positions, triangles) = common::ellipsoid_mesh(24, 48, axes);
    let scan = TempFile::path_with("glb");
    let bytes = common::glb_without_normals(&positions, &triangles, 2.0, [10.0, 0.0, 0.0]);
    std::fs::write(scan.as_path(), bytes).expect("temp file is writable");
    let out_file = TempFile::path_with("glb");
    let out = ok(&["fit", scan.path(), "-o", out_file.path()]);
    assert_eq!(out["method"], "mesh", "{out}");
    assert_eq!(out["points"].as_u64(), Some(positions.len() as u64));
    // The output lies on the ellipsoid scaled by 2 about (10, 0, 0), where the node put it.
    let (doc, buffers, _) = gltf::import(out_file.as_path()).expect("the GLB reads back");
    let mesh = doc.meshes().next().expect("a mesh");
    let mut seen = 0;
    for primitive in mesh.primitives() {
        let reader = primitive.reader(|b| Some(&buffers[b.index()]));
        for [x, y, z] in reader.read_positions().expect("positions") {
            let q = ((x - 10.0) / (2.0 * axes[0])).powi(2)
                + (y / (2.0 * axes[1])).powi(2)
                + (z / (2.0 * axes[2])).powi(2);
            assert!((q - 1.0).abs() < 0.02, "({x}, {y}, {z}): {q}");
            seen += 1;
        }
    }
    assert!(seen > 100);
}

#[test]
fn an_image_with_no_scan_data_is_refused() {
    let few = scan_file("0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.1 0.1 0.1\n", "xyz");
    let out = TempFile::path_with("glb");
    bad(&["fit", few.path(), "-o", out.path(), "--method", "radial"], "found no scan data");
    bad(&["fit", few.path(), "-o", out.path()], "too few points");
}
