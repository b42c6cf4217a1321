// SPDX-License-Identifier: MIT
//! The bad-input suite: every subcommand given an empty input, non-finite numbers, ragged
//! rows, points of the wrong dimension, counts that would allocate too much, missing inputs and
//! outputs that cannot be written — each answered with exit status 2 and one line on stderr
//! naming the problem (`common::bad` checks the status, the single line, the `hi: ` prefix,
//! the expected words and the absence of a panic). Outputs are checked before any work: a
//! command that would also fail later on its input reports the output.

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use common::{TempFile, bad, bad_on};

/// The curve commands that read points, with their other required arguments.
const CURVE_COMMANDS: &[&[&str]] = &[
    &["curve", "eval", "--t", "0.5"],
    &["curve", "sample", "--count", "8"],
    &["curve", "fairness"],
    &["curve", "to-bezier", "--kind", "harmonic"],
    &["curve", "rotate", "--offset", "0.1"],
    &["curve", "resample", "--count", "3"],
    &["curve", "subdivide", "--levels", "1"],
    &["curve", "nonuniform", "--variant", "nodes", "--t", "0.5"],
];

/// A folder that does not exist, for outputs that cannot be written.
const NO_FOLDER: &str = "/nonexistent-hi-folder";

#[test]
fn curve_commands_name_bad_points() {
    for &command in CURVE_COMMANDS {
        bad_on("", command, "invalid JSON");
        bad_on("   \n", command, "invalid JSON");
        bad_on("[]", command, "no points given");
        bad_on(r#"{"points": []}"#, command, "no points given");
        bad_on("[[1, 2], [3]]", command, "point 1 has 1 coordinates, point 0 has 2");
        bad_on(
            r#"[[1, "NaN"], [0, 1]]"#,
            command,
            "point 0, coordinate 1: invalid type: string \"NaN\", expected a number",
        );
        bad_on("[[1, 2], [1e999, 0]]", command, "would be infinite");
        bad_on("[[1, 2, 3, 4]]", command, "point 0 has 4 coordinates");
        bad_on(r#"{"points": [[0, 0]], "extra": 1}"#, command, "unknown key");
        let mut missing = command.to_vec();
        missing.extend(["--input", "/nonexistent-hi-input.json"]);
        bad(&missing, "No such file");
    }
    // Curvature and the hull areas need plane points.
    bad_on("[[0, 0, 0], [1, 0, 0], [0, 1, 1]]", &["curve", "fairness"], "need 2-D points");
    bad_on("[0, 1, 0.5]", &["curve", "fairness"], "need 2-D points");
}

#[test]
fn curve_flags_must_be_finite_and_in_range() {
    let square = "[[0, 0], [1, 0], [1, 1], [0, 1]]";
    for (args, expected) in [
        (&["curve", "eval", "--t", "nan"][..], "not a finite number"),
        (&["curve", "eval", "--t", "0.5,inf"], "item 1: 'inf' is not a finite number"),
        (&["curve", "rotate", "--offset=-inf"], "not a finite number"),
        (
            &[
                "curve",
                "nonuniform",
                "--variant",
                "nodes",
                "--t",
                "0.5",
                "--params",
                "0,nan,0.5,0.7",
            ],
            "item 1: 'nan' is not a finite number",
        ),
        (
            &["curve", "nonuniform", "--variant", "nodes", "--t", "0.5", "--params", "0,0.5"],
            "--params",
        ),
        // Counts that would allocate too much are refused before any allocation.
        (&["curve", "sample", "--count", "100000000000"], "2^28"),
        (&["curve", "resample", "--count", "100000000000"], "2^28"),
        (&["curve", "subdivide", "--levels", "60"], "2^28"),
        (&["curve", "fairness", "--samples", "100000000000"], "2^28"),
        (&["curve", "eval", "--t", "0.5", "--derivatives", "100000"], "at most 1024"),
        (&["curve", "resample", "--count", "0"], "at least 1"),
    ] {
        bad_on(square, args, expected);
    }
}

#[test]
fn basis_commands_refuse_bad_sizes() {
    bad(&["basis", "--n", "0", "--k", "0", "--t", "0.5"], "--n");
    bad(&["basis", "--n", "3", "--k", "3", "--t", "0.5"], "--k");
    bad(&["basis", "--n", "3", "--k", "0", "--t", "nan"], "not a finite number");
    bad(&["basis", "--n", "3", "--k", "0", "--t", "0.5", "--derivatives", "100000"], "1024");
    bad(&["basis", "roots", "--n", "100000", "--derivative", "1"], "too large");
    bad(&["basis", "roots", "--n", "3", "--derivative", "100"], "too large");
    bad(&["bezier", "basis", "--n", "100000", "--scheme", "thesis-cubic"], "too large");
    bad(&["bezier", "basis", "--n", "0", "--scheme", "thesis-cubic"], "--n");
}

/// A 4×4 grid of 3-D points (a bumpy torus-like net), as the surface commands read it.
fn grid() -> String {
    let rows: Vec<String> = (0..4)
        .map(|j| {
            let row: Vec<String> =
                (0..4).map(|k| format!("[{}, {}, {}]", j, k, (j * k) % 3)).collect();
            format!("[{}]", row.join(", "))
        })
        .collect();
    format!("[{}]", rows.join(", "))
}

#[test]
fn surface_commands_name_bad_grids() {
    let out_glb = TempFile::path_with("glb");
    let out_json = TempFile::path_with("json");
    let commands: [&[&str]; 3] = [
        &["surface", "eval", "--u", "0.1", "--v", "0.2"],
        &["surface", "mesh", "-o", out_glb.path()],
        &["surface", "bezier", "-o", out_json.path()],
    ];
    for command in commands {
        bad_on("", command, "invalid JSON");
        bad_on("[]", command, "the grid is empty");
        bad_on(r#"{"grid": []}"#, command, "the grid is empty");
        bad_on("[[[0, 0, 0], [1, 0, 0]], [[0, 1, 0]]]", command, "must be rectangular");
        bad_on("[[[0, 0], [1, 0]], [[0, 1], [1, 1]]]", command, "surface points must have 3");
        bad_on("[[[0, 0, 0], [1e999, 0, 0]]]", command, "would be infinite");
        bad_on(r#"[[[0, 0, "x"]]]"#, command, "row 0, point 0, coordinate 2: invalid type: string");
        bad_on("[[0, 1], [2, 3]]", command, "surface points must have 3");
    }
    // Slices for the B-spline surface fit of §4.4.
    let bspline: &[&str] = &["surface", "bspline-fit"];
    bad_on("", bspline, "invalid JSON");
    bad_on("[]", bspline, "at least 2 slices, 0 given");
    bad_on("[[[0, 0], [1, 0]], [[0, 1], [1, 1]]]", bspline, "surface points must have 3");
    bad_on("[[[0, 0, 0], [1e999, 0, 0]], [[0, 0, 1], [1, 0, 1]]]", bspline, "would be infinite");
}

#[test]
fn surface_flags_must_be_finite_and_sizes_bounded() {
    let grid = grid();
    let out = TempFile::path_with("glb");
    for (args, expected) in [
        (&["surface", "eval", "--u", "nan", "--v", "0.2"][..], "not a finite number"),
        (&["surface", "eval", "--u", "0.1,0.2", "--v", "0.2"], "--u"),
        (&["surface", "mesh", "-o", out.path(), "--window", "0,nan,0,1"], "not a finite number"),
        (&["surface", "mesh", "-o", out.path(), "--window", "0.5,0.5,0,1"], "invalid"),
        (&["surface", "mesh", "-o", out.path(), "--resolution", "100000x100000"], "2^28"),
        (&["surface", "bezier", "-o", out.path(), "--tolerance", "nan"], "not a finite number"),
        (&["surface", "bezier", "-o", out.path(), "--samples", "100000"], "--samples"),
    ] {
        bad_on(&grid, args, expected);
    }
    bad(&["surface", "example", "torus", "--samples", "100000x100000"], "too many points");
    bad(&["surface", "example", "no-such-surface"], "unknown example surface");
}

#[test]
fn scans_and_meshes_are_named_when_missing_or_malformed() {
    let out = TempFile::path_with("glb");
    bad(&["fit", "/nonexistent-hi-scan.xyz", "-o", out.path()], "No such file");
    bad(
        &["subdivide", "--scheme", "loop", "--steps", "1", "/nonexistent-hi.obj", "-o", out.path()],
        "No such file",
    );
    bad(&["render", "/nonexistent-hi-scene.json", "-o", "x.png"], "No such file");

    let three = TempFile::path_with("xyz");
    std::fs::write(three.as_path(), "0 0 0\n1 0 0\n0 1 0\n").expect("writable");
    bad(&["fit", three.path(), "-o", out.path()], "too few points");
    let empty = TempFile::path_with("xyz");
    std::fs::write(empty.as_path(), "").expect("writable");
    bad(&["fit", empty.path(), "-o", out.path()], empty.path());
    let nan = TempFile::path_with("xyz");
    std::fs::write(nan.as_path(), "0 0 0\n1 0 0\n0 1 0\n0 0 1\nnan 0 0\n").expect("writable");
    // Non-finite points are dropped and counted; four finite points are too few for a fit.
    bad(&["fit", nan.path(), "-o", out.path()], "too few points");

    let obj = TempFile::path_with("obj");
    std::fs::write(obj.as_path(), "v 0 0 0\nf 1 2 3\n").expect("writable");
    bad(
        &["subdivide", "--scheme", "loop", "--steps", "1", obj.path(), "-o", out.path()],
        "index 2 is out of range",
    );
    bad(
        &["subdivide", "--scheme", "loop", "--steps", "40", obj.path(), "-o", out.path()],
        "too many",
    );

    for args in [
        &["fit", three.path(), "-o", out.path(), "--resolution", "100000x100000"][..],
        &["fit", three.path(), "-o", out.path(), "--smooth", "nan"],
        &["fit", three.path(), "-o", out.path(), "--centre", "0,nan,0"],
        &["fit", three.path(), "-o", out.path(), "--reduce", "inf"],
        &["render", "--quick", three.path(), "-o", "x.png", "--width", "100000"],
        &["render", "--quick", three.path(), "-o", "x.png", "--width", "0"],
    ] {
        let out = common::run(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "hi {args:?}: {stderr}");
        assert_eq!(stderr.matches('\n').count(), 1, "hi {args:?}: one line: {stderr}");
    }
}

#[test]
fn outputs_are_checked_before_the_work() {
    // Each command would fail later on its input (three points are too few for a fit; a
    // 2-D grid is no surface) or succeed; an output that cannot be written is reported first.
    let three = TempFile::path_with("xyz");
    std::fs::write(three.as_path(), "0 0 0\n1 0 0\n0 1 0\n").expect("writable");
    let grid_file = TempFile::new(&grid());
    let folder = std::env::temp_dir();
    let folder = folder.to_str().expect("UTF-8 temp dir");
    let glb = format!("{NO_FOLDER}/out.glb");
    let json = format!("{NO_FOLDER}/out.json");
    let png = format!("{NO_FOLDER}/out.png");
    let obj = format!("{NO_FOLDER}/out.obj");
    let spot = concat!(env!("CARGO_MANIFEST_DIR"), "/../../fixtures/models/spot.obj");
    let report = TempFile::path_with("json");
    for (args, path) in [
        (vec!["fit", three.path(), "-o", &glb], glb.as_str()),
        (vec!["fit", three.path(), "-o", &json], json.as_str()),
        (vec!["fit", three.path(), "-o", &glb, "--param", "sections"], glb.as_str()),
        (vec!["fit", three.path(), "-o", report.path(), "--report", &json], json.as_str()),
        (vec!["surface", "mesh", "--input", grid_file.path(), "-o", &glb], glb.as_str()),
        (vec!["surface", "bezier", "--input", grid_file.path(), "-o", &json], json.as_str()),
        (vec!["surface", "example", "torus", "-o", &json], json.as_str()),
        (vec!["surface", "bspline-fit", "--input", grid_file.path(), "-o", &glb], glb.as_str()),
        (vec!["subdivide", "--scheme", "loop", "--steps", "2", spot, "-o", &obj], obj.as_str()),
        (vec!["render", "--quick", grid_file.path(), "-o", &png], png.as_str()),
    ] {
        bad(&args, &format!("{path}: cannot write"));
    }
    // A folder where the file should go.
    for args in [
        vec!["fit", three.path(), "-o", folder, "--report", folder],
        vec!["surface", "example", "torus", "-o", folder],
    ] {
        bad(&args, "");
    }
    // The check leaves no file behind.
    assert!(!report.as_path().exists(), "the writability check removed its probe");
}
