// SPDX-License-Identifier: MIT
//! End-to-end tests of `hi surface bspline-fit` (Hardy 2005, §4.4): the JSON surface, evaluated
//! here from its knots and control net with `hi_curve`'s B-spline basis (and from its Bézier
//! patches with Bernstein polynomials), passes through every input point; meshes read back;
//! bad input fails with exit status 2 and one line.

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use common::{TempFile, bad, bad_on, nums, ok, ok_on, points};
use hi_compare::bspline::BSplineBasis;
use serde_json::Value;

/// Slices across a bump, of different lengths.
fn slices() -> Vec<Vec<[f64; 3]>> {
    (0..4)
        .map(|s| {
            let n = 5 + s % 3;
            (0..n)
                .map(|k| {
                    let x = 3.0 * k as f64 / (n - 1) as f64;
                    let y = s as f64 * 0.7;
                    [x, y + 0.1 * x, (1.2 * x).sin() * (0.8 * y).cos()]
                })
                .collect()
        })
        .collect()
}

/// Closed slices: rings of a tube.
fn rings() -> Vec<Vec<[f64; 3]>> {
    (0..4)
        .map(|s| {
            let n = 6 + s % 2;
            (0..n)
                .map(|k| {
                    let a = std::f64::consts::TAU * k as f64 / n as f64;
                    [(1.0 + 0.1 * s as f64) * a.cos(), a.sin(), s as f64]
                })
                .collect()
        })
        .collect()
}

fn text(data: &[Vec<[f64; 3]>]) -> String {
    serde_json::to_string(data).expect("slices serialise")
}

/// p(u, v) of an open surface from its JSON knots and net: Σ Nᵢ(u)·Mₗ(v)·xᵢₗ.
fn eval_open(out: &Value, u: f64, v: f64) -> [f64; 3] {
    let nu = BSplineBasis::try_new(3, nums(&out["u_knots"])).unwrap().eval_all(u);
    let nv = BSplineBasis::try_new(3, nums(&out["v_knots"])).unwrap().eval_all(v);
    let mut p = [0.0; 3];
    for (i, row) in out["control"].as_array().unwrap().iter().enumerate() {
        for (l, x) in points(row).iter().enumerate() {
            for c in 0..3 {
                p[c] += nu[i] * nv[l] * x[c];
            }
        }
    }
    p
}

/// p(u, v) from the JSON Bézier patches: the patch holding (u, v), Bernstein polynomials.
fn eval_patches(patches: &Value, u: f64, v: f64) -> [f64; 3] {
    let (ub, vb) = (nums(&patches["u_breaks"]), nums(&patches["v_breaks"]));
    let find = |b: &[f64], x: f64| {
        let i = b.partition_point(|&k| k <= x).saturating_sub(1).min(b.len() - 2);
        (i, (x - b[i]) / (b[i + 1] - b[i]))
    };
    let ((i, s), (l, t)) = (find(&ub, u), find(&vb, v));
    let bern = |t: f64| {
        [(1.0 - t).powi(3), 3.0 * t * (1.0 - t).powi(2), 3.0 * t * t * (1.0 - t), t.powi(3)]
    };
    let (bu, bv) = (bern(s), bern(t));
    let net = &patches["control"][i * (vb.len() - 1) + l];
    let mut p = [0.0; 3];
    for (j, row) in net.as_array().unwrap().iter().enumerate() {
        for (k, x) in points(row).iter().enumerate() {
            for c in 0..3 {
                p[c] += bu[j] * bv[k] * x[c];
            }
        }
    }
    p
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|c| (a[c] - b[c]).powi(2)).sum::<f64>().sqrt()
}

#[test]
fn the_json_surface_passes_through_every_point() {
    let data = slices();
    let out = ok_on(&text(&data), &["surface", "bspline-fit"]);
    assert_eq!(nums(&out["degree"]), [3.0, 3.0]);
    assert_eq!(out["closed"], serde_json::json!([false, false]));
    let u_params = out["u_params"].as_array().unwrap();
    let v_params = nums(&out["v_params"]);
    for (s, slice) in data.iter().enumerate() {
        let us = nums(&u_params[s]);
        for (k, x) in slice.iter().enumerate() {
            let d = distance(eval_open(&out, us[k], v_params[s]), *x);
            assert!(d < 1e-12, "slice {s}, point {k}: {d:e}");
            let d = distance(eval_patches(&out["patches"], us[k], v_params[s]), *x);
            assert!(d < 1e-12, "patches, slice {s}, point {k}: {d:e}");
        }
    }
    // Adini's patches keep the network's nodes: every patch corner.
    let (ub, vb) = (nums(&out["patches"]["u_breaks"]), nums(&out["patches"]["v_breaks"]));
    for &u in &ub {
        for &v in &vb {
            let d = distance(eval_patches(&out["adini_patches"], u, v), eval_open(&out, u, v));
            assert!(d < 1e-12, "Adini node ({u}, {v})");
        }
    }
}

#[test]
fn closed_slices_and_json_files() {
    let data = rings();
    let file = TempFile::path_with("json");
    let out = ok_on(&text(&data), &["surface", "bspline-fit", "--closed-u", "-o", file.path()]);
    assert_eq!(out["files"][0].as_str(), Some(file.path()));
    let surface: Value =
        serde_json::from_str(&std::fs::read_to_string(file.as_path()).unwrap()).unwrap();
    assert_eq!(surface["closed"], serde_json::json!([true, false]));
    let u_params = surface["u_params"].as_array().unwrap();
    let v_params = nums(&surface["v_params"]);
    for (s, slice) in data.iter().enumerate() {
        let us = nums(&u_params[s]);
        for (k, x) in slice.iter().enumerate() {
            let d = distance(eval_patches(&surface["patches"], us[k], v_params[s]), *x);
            assert!(d < 1e-12, "slice {s}, point {k}: {d:e}");
        }
    }
}

#[test]
fn meshes_are_written_and_read_back() {
    let data = slices();
    for ext in ["obj", "gltf", "glb"] {
        let file = TempFile::path_with(ext);
        let out = ok_on(
            &text(&data),
            &["surface", "bspline-fit", "--resolution", "8x5", "-o", file.path()],
        );
        assert_eq!(out["vertices"].as_u64(), Some(9 * 6), "{ext}");
        assert_eq!(out["triangles"].as_u64(), Some(2 * 8 * 5), "{ext}");
        assert!(file.as_path().exists(), "{ext} written");
    }
    let file = TempFile::path_with("obj");
    ok_on(&text(&data), &["surface", "bspline-fit", "--resolution", "4x3", "-o", file.path()]);
    let (models, _) = tobj::load_obj(file.as_path(), &tobj::GPU_LOAD_OPTIONS).expect("OBJ reads");
    let first = &models[0].mesh.positions[..3];
    // Vertex (0, 0) is the surface corner, the first point of the first slice.
    for c in 0..3 {
        assert!((f64::from(first[c]) - data[0][0][c]).abs() < 1e-6, "corner");
    }
    // stdin and other options.
    let out = ok(&[
        "surface",
        "bspline-fit",
        "--input",
        TempFile::new(&text(&data)).path(),
        "--end",
        "not-a-knot",
        "--params",
        "uniform",
    ]);
    assert_eq!(nums(&out["v_params"]), [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]);
}

#[test]
fn bad_input_fails_with_one_line() {
    let cmd = ["surface", "bspline-fit"];
    bad_on("[]", &cmd, "needs at least 2 slices, 0 given");
    bad_on("[[[0,0,0],[1,0,0]]]", &cmd, "needs at least 2 slices, 1 given");
    bad_on("[[[0,0,0],[1,0,0]],[[0,1,0]]]", &cmd, "slice 1 has 1 points");
    bad_on("[[[0,0,0],[1,0,0]],[[0,1,0],[0,1,0]]]", &cmd, "slice 1: points 0 and 1 coincide");
    bad_on("[[[0,0,0],[1,0,0]],[[0,0,0],[1,0,0]]]", &cmd, "slices 0 and 1 coincide");
    bad_on("[[[0,0],[1,0]],[[0,1],[1,1]]]", &cmd, "slice 0, point 0 has 2 coordinates");
    bad_on("[[[0,0,1e999]]]", &cmd, "number out of range");
    bad_on("{\"grid\": []}", &cmd, "unknown key \"grid\"");
    bad_on(
        "[[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]]",
        &["surface", "bspline-fit", "--closed-u"],
        "slice 0 has 2 points",
    );
    let data = text(&rings());
    bad_on(
        &data,
        &["surface", "bspline-fit", "--closed-u", "--resolution", "2x4", "-o", "x.glb"],
        "--resolution",
    );
    bad_on(&data, &["surface", "bspline-fit", "-o", "x.stl"], "unknown mesh file extension");
    bad(&["surface", "bspline-fit", "--input", "/nonexistent/slices.json"], "cannot read");
}
