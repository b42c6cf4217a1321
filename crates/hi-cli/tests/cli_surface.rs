// SPDX-License-Identifier: MIT
//! End-to-end tests of `hi surface eval|mesh|example`: the sphere and torus examples checked
//! against their closed forms (|p| = r, K = 1/r², H = −1/r; the torus's K = sin θ/(r(R + r sin θ))),
//! meshes read back with `tobj` and `gltf`, and every kind of bad input.

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use std::f64::consts::TAU;

use common::{TempFile, bad, bad_on, dist, num, nums, ok, ok_on, points};
use serde_json::Value;

/// The grid file of `hi surface example ARGS`, as text.
fn example(args: &[&str]) -> String {
    let mut all = vec!["surface", "example"];
    all.extend(args);
    ok(&all).to_string()
}

/// The rows of a grid file.
fn grid_rows(grid: &str) -> Vec<Vec<Vec<f64>>> {
    let json: Value = serde_json::from_str(grid).expect("JSON");
    json["grid"].as_array().expect("rows").iter().map(points).collect()
}

#[test]
fn sphere_has_radius_1_curvature_1_and_an_outward_normal() {
    let grid = example(&["sphere"]);
    let rows = grid_rows(&grid);
    assert_eq!((rows.len(), rows[0].len()), (4, 4), "the exact 4×4 grid");
    // Pairs (u, v) inside u ∈ (0, ½), which covers the sphere once.
    let us = [0.05, 0.1, 0.2, 0.25, 0.3, 0.45, 0.4];
    let vs = [0.0, 0.3, 0.5, 0.9, 0.15, 0.6, 0.01];
    let list = |xs: &[f64]| xs.iter().map(f64::to_string).collect::<Vec<_>>().join(",");
    let out = ok_on(&grid, &["surface", "eval", "--u", &list(&us), "--v", &list(&vs)]);
    let mut keys: Vec<&str> = out.as_object().expect("object").keys().map(String::as_str).collect();
    keys.sort_unstable();
    assert_eq!(keys, ["gaussian", "mean", "normal", "p", "pu", "puu", "puv", "pv", "pvv"], "keys");
    let p = points(&out["p"]);
    let normal = points(&out["normal"]);
    let (gaussian, mean) = (nums(&out["gaussian"]), nums(&out["mean"]));
    assert_eq!(p.len(), us.len(), "one entry per pair");
    for i in 0..us.len() {
        let r = p[i].iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!((r - 1.0).abs() < 1e-14, "|p| = 1 at pair {i}");
        assert!((gaussian[i] - 1.0).abs() < 1e-12, "K = 1/r² at pair {i}: {}", gaussian[i]);
        assert!((mean[i] + 1.0).abs() < 1e-12, "H = −1/r at pair {i}: {}", mean[i]);
        assert!(dist(&normal[i], &p[i]) < 1e-12, "outward unit normal at pair {i}");
    }
    // The closed form p = (sin 2πu cos 2πv, sin 2πu sin 2πv, cos 2πu) and its u derivative.
    let pu = points(&out["pu"]);
    for i in 0..us.len() {
        let (a, b) = (TAU * us[i], TAU * vs[i]);
        let want = [a.sin() * b.cos(), a.sin() * b.sin(), a.cos()];
        assert!(dist(&p[i], &want) < 1e-14, "p at pair {i}");
        let want_u = [TAU * a.cos() * b.cos(), TAU * a.cos() * b.sin(), -TAU * a.sin()];
        assert!(dist(&pu[i], &want_u) < 1e-12, "pu at pair {i}");
    }
}

#[test]
fn sphere_poles_have_no_normal() {
    let out =
        ok_on(&example(&["sphere"]), &["surface", "eval", "--u", "0,0.5,0.25", "--v", "0.3,0.7,0"]);
    for key in ["normal", "gaussian", "mean"] {
        let values = out[key].as_array().expect("an array");
        assert!(values[0].is_null() && values[1].is_null(), "{key} is null at the poles");
        assert!(!values[2].is_null(), "{key} is defined on the equator");
    }
    assert!(dist(&points(&out["p"])[1], &[0.0, 0.0, -1.0]) < 1e-14, "the south pole");
}

#[test]
fn torus_samples_give_the_same_torus_and_its_curvature() {
    // R = 2, r = 1: p = ((R + r sin θ) cos 2πv, (R + r sin θ) sin 2πv, r cos θ), θ = 2πu, and
    // K = sin θ/(r(R + r sin θ)).
    let grid = example(&["torus", "--samples", "8x6"]);
    let rows = grid_rows(&grid);
    assert_eq!((rows.len(), rows[0].len()), (8, 6), "the requested samples");
    let torus = |u: f64, v: f64| {
        let (t, w) = (TAU * u, 2.0 + (TAU * u).sin());
        [w * (TAU * v).cos(), w * (TAU * v).sin(), t.cos()]
    };
    for (j, row) in rows.iter().enumerate() {
        for (k, x) in row.iter().enumerate() {
            assert!(dist(x, &torus(j as f64 / 8.0, k as f64 / 6.0)) < 1e-14, "grid ({j}, {k})");
        }
    }
    let (us, vs) = ([0.1, 0.3, 0.6, 0.85], [0.2, 0.55, 0.05, 0.7]);
    let list = |xs: &[f64]| xs.iter().map(f64::to_string).collect::<Vec<_>>().join(",");
    let out = ok_on(&grid, &["surface", "eval", "--u", &list(&us), "--v", &list(&vs)]);
    let (p, gaussian) = (points(&out["p"]), nums(&out["gaussian"]));
    for i in 0..us.len() {
        assert!(dist(&p[i], &torus(us[i], vs[i])) < 1e-13, "p at pair {i}");
        let s = (TAU * us[i]).sin();
        assert!((gaussian[i] - s / (2.0 + s)).abs() < 1e-12, "K at pair {i}");
    }
}

#[test]
fn examples_of_section_5_9_and_output_files() {
    let plane = grid_rows(&example(&["plane"]));
    assert_eq!((plane.len(), plane[0].len()), (24, 4), "the thesis's 24×4");
    assert_eq!(grid_rows(&example(&["solomon-fine"])).len(), 48, "48×4");
    assert_eq!(grid_rows(&example(&["5.33", "--samples", "6x5"]))[0].len(), 5, "by figure");
    let file = TempFile::path_with("json");
    let out = ok(&["surface", "example", "klein", "-o", file.path()]);
    assert_eq!(out["files"][0].as_str(), Some(file.path()), "names the file");
    assert_eq!((num(&out["m"]), num(&out["n"])), (24.0, 4.0), "size");
    let written = std::fs::read_to_string(file.as_path()).expect("the file exists");
    assert_eq!(grid_rows(&written), grid_rows(&example(&["klein"])), "same grid as stdout");
}

/// Meshes the torus grid (R = 2, r = 1) to `path` with these extra options and returns the
/// summary printed.
fn mesh_torus(path: &str, extra: &[&str]) -> Value {
    let grid = example(&["torus"]);
    let mut args = vec!["surface", "mesh", "-o", path];
    args.extend(extra);
    ok_on(&grid, &args)
}

/// Distance of a point from the torus R = 2, r = 1.
fn off_torus(p: &[f32]) -> f64 {
    let (x, y, z) = (f64::from(p[0]), f64::from(p[1]), f64::from(p[2]));
    ((x.hypot(y) - 2.0).hypot(z) - 1.0).abs()
}

#[test]
fn obj_mesh_reads_back_with_the_requested_vertices() {
    let file = TempFile::path_with("obj");
    let out = mesh_torus(file.path(), &["--resolution", "16x12"]);
    // Closed in u and v: 16·12 vertices, none repeated, two triangles per quad.
    assert_eq!(out["vertices"], Value::from(16 * 12), "{out}");
    assert_eq!(out["triangles"], Value::from(2 * 16 * 12), "{out}");
    let options = tobj::LoadOptions { single_index: true, triangulate: true, ..Default::default() };
    let (models, _) = tobj::load_obj(file.as_path(), &options).expect("tobj reads the file");
    let mesh = &models[0].mesh;
    assert_eq!(mesh.positions.len(), 3 * 16 * 12, "positions");
    assert_eq!(mesh.indices.len(), 3 * 2 * 16 * 12, "triangles");
    assert_eq!(mesh.normals.len(), mesh.positions.len(), "normals");
    assert_eq!(mesh.texcoords.len(), 2 * 16 * 12, "UVs");
    assert!(mesh.positions.chunks(3).all(|p| off_torus(p) < 1e-6), "vertices on the torus");
}

#[test]
fn glb_and_gltf_meshes_read_back_with_colours_and_windows() {
    let glb = TempFile::path_with("glb");
    let out = mesh_torus(
        glb.path(),
        &["--resolution", "8x10", "--window", "0,0.5,0,0.25", "--color", "gaussian"],
    );
    // Neither direction is a whole period: (8 + 1)·(10 + 1) vertices.
    assert_eq!(out["vertices"], Value::from(9 * 11), "{out}");
    assert_eq!(out["legend"]["quantity"], Value::from("K"), "{out}");
    let (doc, buffers, _) = gltf::import(glb.as_path()).expect("gltf reads the file");
    let primitive = doc.meshes().next().expect("a mesh").primitives().next().expect("a primitive");
    let reader = primitive.reader(|b| Some(&buffers[b.index()]));
    let positions: Vec<[f32; 3]> = reader.read_positions().expect("positions").collect();
    assert_eq!(positions.len(), 9 * 11, "vertices");
    assert!(positions.iter().all(|p| off_torus(p) < 1e-6), "on the torus");
    assert_eq!(reader.read_indices().expect("indices").into_u32().count(), 3 * 2 * 8 * 10);
    assert_eq!(reader.read_colors(0).expect("colours").into_rgb_f32().count(), 9 * 11);

    let gltf_file = TempFile::path_with("gltf");
    let out = mesh_torus(gltf_file.path(), &["--resolution", "6x5", "--color", "mean"]);
    let files: Vec<&str> =
        out["files"].as_array().expect("files").iter().filter_map(Value::as_str).collect();
    assert_eq!(files.len(), 2, "the .gltf and its .bin");
    assert!(files[1].ends_with(".bin") && std::path::Path::new(files[1]).exists(), "{files:?}");
    let (doc, _, _) = gltf::import(gltf_file.as_path()).expect("gltf reads the file");
    let count = doc
        .meshes()
        .next()
        .expect("a mesh")
        .primitives()
        .next()
        .expect("a primitive")
        .get(&gltf::Semantic::Positions)
        .expect("positions")
        .count();
    assert_eq!(count, 6 * 5, "vertices");
}

#[test]
fn bad_grids_and_outputs() {
    let eval = ["surface", "eval", "--u", "0.1", "--v", "0.2"];
    bad_on("[[[0,0,0],[1,0,0]],[[0,1,0]]]", &eval, "row 1 of the grid has 1 points, row 0 has 2");
    bad_on(r#"{"grid": [[[0,0,NaN]]]}"#, &eval, "invalid JSON");
    bad_on("[[[0,0,1e999]]]", &eval, "must be finite");
    bad_on("[[[0,0],[1,1]]]", &eval, "surface points must have 3");
    bad_on("[]", &eval, "the grid is empty");
    bad_on("[[]]", &eval, "the grid is empty");
    bad_on(r#"{"points": [[[0,0,0]]]}"#, &eval, "unknown key");
    bad_on("[[[0,0,0]]]", &["surface", "eval", "--u", "0.1,0.2", "--v", "0.2"], "one v for each u");
    bad_on("[[[0,0,0]]]", &["surface", "eval", "--u", "nan", "--v", "0.2"], "not a finite number");
    let torus = example(&["torus"]);
    bad_on(
        &torus,
        &["surface", "mesh", "-o", "/tmp/hi-cli-test-mesh.stl"],
        "unknown mesh file extension",
    );
    bad_on(
        &torus,
        &["surface", "mesh", "-o", "/nonexistent/dir/torus.obj"],
        "/nonexistent/dir/torus.obj",
    );
    bad_on(
        &torus,
        &["surface", "mesh", "--resolution", "2x8", "-o", "/tmp/hi-cli-test-mesh.obj"],
        "--resolution",
    );
    bad_on(
        &torus,
        &["surface", "mesh", "--resolution", "0x8", "-o", "/tmp/hi-cli-test-mesh.obj"],
        "must be at least 1",
    );
    bad_on(
        &torus,
        &["surface", "mesh", "--window", "0,1,1,0", "-o", "/tmp/hi-cli-test-mesh.obj"],
        "v0 < v1",
    );
    bad_on(
        &torus,
        &["surface", "mesh", "--color", "red", "-o", "/tmp/hi-cli-test-mesh.obj"],
        "gaussian",
    );
    bad(&["surface", "example", "teapot"], "unknown example surface 'teapot'");
    bad(&["surface", "example", "sphere", "--samples", "4x0"], "--samples");
    bad(&["surface", "example", "sphere", "--samples", "100000x100000"], "too many points");
    bad(&["surface", "example", "sphere", "-o", "/nonexistent/dir/sphere.json"], "cannot write");
}

#[test]
fn a_diverging_palette_keeps_the_sign_of_the_curvature() {
    // The torus's K is positive outside and negative inside: on cool–warm the legend runs from
    // −a to a, the inside blue and the outside red; on the thesis's ramp from 0.
    let glb = TempFile::path_with("glb");
    let out = mesh_torus(
        glb.path(),
        &["--resolution", "16x16", "--color", "gaussian", "--palette", "coolwarm"],
    );
    let (min, max) =
        (out["legend"]["min"].as_f64().unwrap(), out["legend"]["max"].as_f64().unwrap());
    assert!(min < 0.0 && (min + max).abs() < 1e-12, "{out}");
    let (doc, buffers, _) = gltf::import(glb.as_path()).expect("gltf reads the file");
    let primitive = doc.meshes().next().expect("a mesh").primitives().next().expect("a primitive");
    let reader = primitive.reader(|b| Some(&buffers[b.index()]));
    let colors: Vec<[f32; 3]> = reader.read_colors(0).expect("colours").into_rgb_f32().collect();
    let positions: Vec<[f32; 3]> = reader.read_positions().expect("positions").collect();
    // Outermost vertex (K > 0): more red than blue; innermost (K < 0): more blue than red.
    let radius = |p: &[f32; 3]| p[0].hypot(p[1]);
    let outer = (0..positions.len())
        .max_by(|&a, &b| radius(&positions[a]).total_cmp(&radius(&positions[b])))
        .unwrap();
    let inner = (0..positions.len())
        .min_by(|&a, &b| radius(&positions[a]).total_cmp(&radius(&positions[b])))
        .unwrap();
    assert!(colors[outer][0] > colors[outer][2], "outside {:?}", colors[outer]);
    assert!(colors[inner][2] > colors[inner][0], "inside {:?}", colors[inner]);
    let thesis = mesh_torus(glb.path(), &["--resolution", "16x16", "--color", "gaussian"]);
    assert_eq!(thesis["legend"]["min"], Value::from(0.0), "{thesis}");
    // --palette needs --color.
    bad(&["surface", "mesh", "--palette", "viridis", "-o", glb.path()], "--color");
}
