// SPDX-License-Identifier: MIT
//! `hi fit` on scans of any topology, end to end: a scan of three parts (a sphere, a ring and
//! an open sheet) gives three named meshes in one scene, which read back with the glTF reader,
//! pass the Khronos glTF-Validator and open in trimesh as three named geometries; an open sheet
//! gives a mesh with one boundary loop that follows the scan's rim; `--closed` caps it instead;
//! two sheets far apart are each fitted; a cube of 8 vertices is fitted;
//! an unevenly dense range scan (CGAL's, where present) is fitted; and bad clouds are named.
//! The validator and trimesh are peers: without them a check says so and passes, unless
//! `HI_REQUIRE_PEERS=1` (as in CI).

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use std::collections::HashMap;
use std::f64::consts::{PI, TAU};
use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;

use common::{TempFile, bad, num, run};
use hi_testkit::skip;

/// A triangle mesh as OBJ text.
fn obj(points: &[[f64; 3]], triangles: &[[usize; 3]]) -> String {
    let mut s = String::new();
    for p in points {
        let _ = writeln!(s, "v {} {} {}", p[0], p[1], p[2]);
    }
    for t in triangles {
        let _ = writeln!(s, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    s
}

/// A u × v grid of quads over `at(i, j)` (wrapping in u and/or v) appended to a mesh.
fn grid(
    mesh: &mut (Vec<[f64; 3]>, Vec<[usize; 3]>),
    (nu, nv): (usize, usize),
    wrap: (bool, bool),
    at: impl Fn(usize, usize) -> [f64; 3],
) {
    let offset = mesh.0.len();
    let (ru, rv) = (if wrap.0 { nu } else { nu + 1 }, if wrap.1 { nv } else { nv + 1 });
    mesh.0.extend((0..ru * rv).map(|k| at(k / rv, k % rv)));
    let id = |i: usize, j: usize| offset + (i % ru) * rv + j % rv;
    for i in 0..nu {
        for j in 0..nv {
            let q = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            mesh.1.push([q[0], q[1], q[2]]);
            mesh.1.push([q[0], q[2], q[3]]);
        }
    }
}

/// The height field of the open sheet over [−1, 1]².
fn height(x: f64, y: f64) -> f64 {
    0.15 * (2.0 * x).sin() * (1.5 * y).cos()
}

/// The sheet: 40 × 40 quads over [−1, 1]² at height `height`, shifted by `at`.
fn sheet(mesh: &mut (Vec<[f64; 3]>, Vec<[usize; 3]>), at: [f64; 3]) {
    grid(mesh, (40, 40), (false, false), |i, j| {
        let (x, y) = (i as f64 / 20.0 - 1.0, j as f64 / 20.0 - 1.0);
        [x + at[0], y + at[1], height(x, y) + at[2]]
    });
}

/// A sphere of radius 1 at the origin (poles exact, so that they weld), a torus (R = 1,
/// r = 0.35) about (4, 0, 0) and the sheet about (0, 4, 0).
fn three_parts() -> String {
    let mut mesh = (Vec::new(), Vec::new());
    grid(&mut mesh, (32, 48), (false, true), |i, j| {
        let (a, b) = (PI * i as f64 / 32.0, TAU * j as f64 / 48.0);
        match i {
            0 => [0.0, 0.0, 1.0],
            32 => [0.0, 0.0, -1.0],
            _ => [a.sin() * b.cos(), a.sin() * b.sin(), a.cos()],
        }
    });
    grid(&mut mesh, (64, 24), (true, true), |i, j| {
        let (a, b) = (TAU * i as f64 / 64.0, TAU * j as f64 / 24.0);
        let rho = 1.0 + 0.35 * b.cos();
        [4.0 + rho * a.cos(), rho * a.sin(), 0.35 * b.sin()]
    });
    sheet(&mut mesh, [0.0, 4.0, 0.0]);
    obj(&mesh.0, &mesh.1)
}

/// Runs a fit that must succeed (notes and warnings may go to stderr) and parses its JSON.
fn fitted(args: &[&str]) -> serde_json::Value {
    let out = run(args);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("JSON on stdout")
}

fn scan_file(text: &str, ext: &str) -> TempFile {
    let file = TempFile::path_with(ext);
    std::fs::write(file.as_path(), text).expect("temp file is writable");
    file
}

/// The edges of a mesh with the number of triangles on each.
fn edge_uses(triangles: &[[u32; 3]]) -> HashMap<(u32, u32), usize> {
    let mut uses = HashMap::new();
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            *uses.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    uses
}

#[test]
fn three_parts_give_three_named_meshes_that_peers_accept() {
    let scan = scan_file(&three_parts(), "obj");
    let glb = TempFile::path_with("glb");
    let out = run(&["fit", scan.path(), "-o", glb.path()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(report["topology"]["parts"], 3, "{report}");
    // Largest first: the sphere (4π ≈ 12.6), the torus (4π²Rr ≈ 13.8) — the torus, then —
    // and the sheet (a little over 4).
    let domains: Vec<&str> = report["parts"]
        .as_array()
        .expect("parts")
        .iter()
        .map(|p| p["domain"].as_str().unwrap())
        .collect();
    assert_eq!(domains, ["torus", "sphere", "sheet"], "{report}");
    assert_eq!(report["topology"]["genus"], serde_json::json!([1, 0, 0]));
    assert_eq!(report["topology"]["boundary_loops"], serde_json::json!([0, 0, 1]));
    assert!(num(&report["both_ways"]["unreached_fraction"]) == 0.0, "{report}");
    assert!(
        stderr.contains("genus 1, fitted over the torus with no cut: part 1")
            && stderr.contains("open sheets, fitted open: part 3"),
        "{stderr}"
    );
    // Three nodes, named, each with its mesh; the closed ones closed, the sheet with a rim.
    let (doc, buffers, _) = gltf::import(glb.as_path()).expect("the GLB reads back");
    let names: Vec<&str> = doc.nodes().filter_map(|n| n.name()).collect();
    assert_eq!(names, ["part 1", "part 2", "part 3"]);
    for (k, mesh) in doc.meshes().enumerate() {
        let primitive = mesh.primitives().next().expect("a primitive");
        let reader = primitive.reader(|b| Some(&buffers[b.index()]));
        let indices: Vec<u32> = reader.read_indices().expect("indices").into_u32().collect();
        let triangles: Vec<[u32; 3]> = indices.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
        let rim = edge_uses(&triangles).values().filter(|&&n| n == 1).count();
        if k < 2 {
            assert_eq!(rim, 0, "part {} is closed", k + 1);
        } else {
            assert!(rim > 0, "the sheet has a rim");
        }
    }
    // The Khronos validator: no error, no warning.
    let validator = concat!(env!("CARGO_MANIFEST_DIR"), "/../../xtask/peers/gltf-validator");
    if Path::new(validator).join("node_modules/gltf-validator").is_dir() {
        let output = Command::new("node")
            .arg(Path::new(validator).join("validate.js"))
            .arg(glb.as_path())
            .output();
        match output {
            Ok(o) => {
                let text = String::from_utf8_lossy(&o.stdout);
                assert!(o.status.success(), "the validator found errors or warnings:\n{text}");
                assert!(text.contains(" errors=0 warnings=0 "), "{text}");
            }
            Err(e) => skip(&format!("node is not usable: {e}")),
        }
    } else {
        skip("gltf-validator is not installed (run `npm ci` in xtask/peers/gltf-validator)");
    }
    // trimesh: a scene of three geometries named as the parts.
    let script = "import json, sys, trimesh\n\
        s = trimesh.load(sys.argv[1], process=False)\n\
        print(json.dumps({'type': type(s).__name__, 'names': list(s.geometry.keys()), \
        'watertight': [g.is_watertight for g in s.geometry.values()]}))";
    match Command::new("python3").args(["-c", script]).arg(glb.as_path()).output() {
        Ok(o) if o.status.success() => {
            let seen: serde_json::Value =
                serde_json::from_slice(&o.stdout).expect("trimesh's JSON");
            assert_eq!(seen["type"], "Scene", "{seen}");
            assert_eq!(seen["names"], serde_json::json!(["part 1", "part 2", "part 3"]), "{seen}");
            assert_eq!(seen["watertight"], serde_json::json!([true, true, false]), "{seen}");
        }
        Ok(o) => skip(&format!(
            "python3 with trimesh is not usable ({})",
            String::from_utf8_lossy(&o.stderr).lines().last().unwrap_or("")
        )),
        Err(e) => skip(&format!("python3 is not usable: {e}")),
    }
    // The same as one OBJ of three named objects.
    let objfile = TempFile::path_with("obj");
    fitted(&["fit", scan.path(), "-o", objfile.path()]);
    let text = std::fs::read_to_string(objfile.as_path()).expect("the OBJ");
    let objects: Vec<&str> = text.lines().filter(|l| l.starts_with("o ")).collect();
    assert_eq!(objects, ["o part 1", "o part 2", "o part 3"]);
}

/// The distance from p to the polyline through `rim` (closed).
fn to_polyline(p: [f64; 3], rim: &[[f64; 3]]) -> f64 {
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    (0..rim.len())
        .map(|k| {
            let (a, b) = (rim[k], rim[(k + 1) % rim.len()]);
            let (ab, ap) = (sub(b, a), sub(p, a));
            let t = (dot(ap, ab) / dot(ab, ab)).clamp(0.0, 1.0);
            let d = sub(ap, [ab[0] * t, ab[1] * t, ab[2] * t]);
            dot(d, d).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

/// An open sheet (a height field over a square, no volume) is fitted as an open surface: its
/// mesh has one boundary loop, which follows the scan's rim both ways within 0.5 % of the
/// diagonal; the surface lies on the height field; `--closed` caps it into a closed mesh.
#[test]
fn an_open_sheet_gives_one_rim_that_follows_the_scans() {
    let mut mesh = (Vec::new(), Vec::new());
    sheet(&mut mesh, [0.0; 3]);
    let scan = scan_file(&obj(&mesh.0, &mesh.1), "obj");
    let glb = TempFile::path_with("glb");
    let report = fitted(&["fit", scan.path(), "-o", glb.path()]);
    assert_eq!(report["topology"]["domains"], serde_json::json!(["sheet"]), "{report}");
    let (doc, buffers, _) = gltf::import(glb.as_path()).expect("the GLB reads back");
    let primitive = doc.meshes().next().expect("a mesh").primitives().next().expect("a primitive");
    let reader = primitive.reader(|b| Some(&buffers[b.index()]));
    let positions: Vec<[f64; 3]> =
        reader.read_positions().expect("positions").map(|p| p.map(f64::from)).collect();
    let indices: Vec<u32> = reader.read_indices().expect("indices").into_u32().collect();
    let triangles: Vec<[u32; 3]> = indices.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
    // One boundary loop: its edges chain into a single cycle.
    let rim_edges: Vec<(u32, u32)> =
        edge_uses(&triangles).into_iter().filter(|(_, n)| *n == 1).map(|(e, _)| e).collect();
    let mut next: HashMap<u32, Vec<u32>> = HashMap::new();
    for &(a, b) in &rim_edges {
        next.entry(a).or_default().push(b);
        next.entry(b).or_default().push(a);
    }
    assert!(next.values().all(|n| n.len() == 2), "the rim is a simple curve");
    let start = rim_edges[0].0;
    let (mut prev, mut at, mut steps) = (start, next[&start][0], 1);
    while at != start {
        let n = &next[&at];
        let to = if n[0] == prev { n[1] } else { n[0] };
        (prev, at, steps) = (at, to, steps + 1);
    }
    assert_eq!(steps, rim_edges.len(), "one loop through every rim edge");
    // The scan's rim: the square's border, 160 vertices in order.
    let n = 41;
    let border: Vec<(usize, usize)> = (0..40)
        .map(|j| (0, j))
        .chain((0..40).map(|i| (i, 40)))
        .chain((0..40).map(|j| (40, 40 - j)))
        .chain((0..40).map(|i| (40 - i, 0)))
        .collect();
    let scan_rim: Vec<[f64; 3]> = border.iter().map(|&(i, j)| mesh.0[i * n + j]).collect();
    let diagonal = (8.0f64 + 0.09).sqrt();
    let rim_vertices: Vec<[f64; 3]> = next.keys().map(|&v| positions[v as usize]).collect();
    let worst = rim_vertices.iter().map(|&p| to_polyline(p, &scan_rim)).fold(0.0, f64::max);
    assert!(worst < 0.005 * diagonal, "a rim vertex {worst} from the scan's rim");
    let back = scan_rim
        .iter()
        .map(|&q| {
            rim_vertices
                .iter()
                .map(|p| {
                    ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
                })
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    assert!(back < 0.02 * diagonal, "a scan rim vertex {back} from the fitted rim");
    // On the height field.
    let off = positions.iter().map(|p| (p[2] - height(p[0], p[1])).abs()).fold(0.0, f64::max);
    assert!(off < 0.002 * diagonal, "{off}");
    // --closed: one closed part, its rim capped.
    let closed = fitted(&["fit", scan.path(), "-o", glb.path(), "--closed"]);
    assert_eq!(closed["topology"]["domains"], serde_json::json!(["sphere"]), "{closed}");
    assert_eq!(closed["parts"][0]["holes_filled"], 1);
}

/// Two open sheets' bare points 100 units apart along the diagonal (islands far off the
/// mainland): the zero set's grid spans more nodes than a dense grid holds (2·10⁹ on its finer
/// grid, 3·10⁸ on its coarser), and each sheet is fitted as an open sheet on its own, through
/// its points.
#[test]
fn parts_far_apart_are_each_fitted() {
    let mut mesh = (Vec::new(), Vec::new());
    sheet(&mut mesh, [0.0; 3]);
    sheet(&mut mesh, [100.0; 3]);
    let mut xyz = String::new();
    for p in &mesh.0 {
        let _ = writeln!(xyz, "{} {} {}", p[0], p[1], p[2]);
    }
    let scan = scan_file(&xyz, "xyz");
    let glb = TempFile::path_with("glb");
    let report = fitted(&["fit", scan.path(), "-o", glb.path()]);
    assert_eq!(report["topology"]["domains"], serde_json::json!(["sheet", "sheet"]), "{report}");
    // Every point near its sheet, against a sheet's own diagonal: 10⁻⁴ of it on average, a
    // hundredth at worst.
    let diagonal = (8.0f64 + 0.09).sqrt();
    for part in report["parts"].as_array().expect("parts") {
        let errors = &part["both_ways"]["scan_to_surface"];
        let (mean, max) = (num(&errors["mean"]), num(&errors["max"]));
        assert!(mean < 1e-4 * diagonal && max < 0.01 * diagonal, "{part}");
    }
}

/// A coarse mesh whose few vertices are its corners (a cube's 8) is a part like any other:
/// fitted over the sphere from its faces, not left out as a fragment of a grid would be, on an
/// image of at least 256² (at 64², eight texels per vertex, the cube came out wavy all over).
/// Its corners lie within 1.5 % of the diagonal of the surface, which spans the cube's box
/// within 2 % (the harmonic surface rounds the corners and edges).
#[test]
fn a_coarse_mesh_of_few_vertices_is_fitted() {
    let corners: Vec<[f64; 3]> = (0..8)
        .map(|k| [f64::from(k & 1), f64::from((k >> 1) & 1), f64::from((k >> 2) & 1)])
        .collect();
    // Two triangles per face, wound outward.
    let faces =
        [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let triangles: Vec<[usize; 3]> =
        faces.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
    let scan = scan_file(&obj(&corners, &triangles), "obj");
    let glb = TempFile::path_with("glb");
    let report = fitted(&["fit", scan.path(), "-o", glb.path()]);
    assert_eq!(report["method"], "mesh", "{report}");
    assert_eq!(report["topology"]["domains"], serde_json::json!(["sphere"]), "{report}");
    assert_eq!(report["dropped_parts"], serde_json::json!([]), "{report}");
    assert_eq!(report["image"], serde_json::json!([256, 256]), "{report}");
    let worst = num(&report["both_ways"]["scan_to_surface"]["relative"][2]);
    assert!(worst < 0.015, "a corner {worst} of the diagonal off");
    let (doc, buffers, _) = gltf::import(glb.as_path()).expect("the GLB reads back");
    let primitive = doc.meshes().next().expect("a mesh").primitives().next().expect("a primitive");
    let reader = primitive.reader(|b| Some(&buffers[b.index()]));
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in reader.read_positions().expect("positions") {
        for k in 0..3 {
            lo[k] = lo[k].min(f64::from(p[k]));
            hi[k] = hi[k].max(f64::from(p[k]));
        }
    }
    let tolerance = 0.02 * 3.0f64.sqrt();
    for k in 0..3 {
        assert!(lo[k].abs() < tolerance && (hi[k] - 1.0).abs() < tolerance, "{lo:?} {hi:?}");
    }
}

#[test]
fn bad_clouds_are_named() {
    let out = TempFile::path_with("glb");
    // Too few points.
    let few = scan_file("0 0 0\n1 0 0\n0 1 0\n", "xyz");
    bad(&["fit", few.path(), "-o", out.path()], "too few points");
    // All on a line.
    let line: String = (0..200).map(|k| format!("{} {} {}\n", k, 2 * k, -k)).collect();
    let line = scan_file(&line, "xyz");
    bad(&["fit", line.path(), "-o", out.path()], "lie on a line");
    // All on a plane: an open sheet, or with --closed an error.
    let plane: String = (0..900).map(|k| format!("{} {} 0\n", k % 30, k / 30)).collect();
    let plane = scan_file(&plane, "xyz");
    bad(&["fit", plane.path(), "-o", out.path(), "--closed"], "lie on a plane");
    let sheet = fitted(&["fit", plane.path(), "-o", out.path()]);
    assert_eq!(sheet["topology"]["domains"], serde_json::json!(["sheet"]), "{sheet}");
    // Non-finite coordinates: dropped and counted, with a warning; none left is an error.
    let mut text = String::from("nan 0 0\n0 inf 0\n");
    text.push_str(
        &(0..900)
            .map(|k| {
                format!(
                    "{} {} {}\n",
                    (k % 30) as f64 / 29.0,
                    (k / 30) as f64 / 29.0,
                    ((k % 7) as f64 * 0.1).sin()
                )
            })
            .collect::<String>(),
    );
    let nonfinite = scan_file(&text, "xyz");
    let output = run(&["fit", nonfinite.path(), "-o", out.path()]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    assert!(
        stderr.contains("2 points with a NaN or infinite coordinate were left out"),
        "{stderr}"
    );
    let all_bad = scan_file("nan 0 0\n0 inf 0\n1 1 nan\n", "xyz");
    bad(
        &["fit", all_bad.path(), "-o", out.path()],
        "all 3 points have a NaN or infinite coordinate",
    );
    // --closed and --open exclude each other, and are not for the sections.
    bad(&["fit", plane.path(), "-o", out.path(), "--closed", "--open"], "--open");
    bad(
        &["fit", plane.path(), "-o", out.path(), "--param", "sections", "--open"],
        "--closed and --open apply",
    );
}

#[test]
fn an_uneven_scan_whose_fine_grid_folds_is_fitted_on_the_median_grid() {
    // CGAL's `radar.xyz` (a range scan of 20 950 points whose density follows its scan lines):
    // unevenly dense, so its zero set is first taken on the finer grid of its dense parts,
    // whose largest sheet does not map onto the square without folds. The fit then takes the
    // grid of the median spacing, as for evenly dense points, and succeeds.
    let Some(archive) = hi_testkit::cgal_demo_data() else { return };
    let dir = std::env::temp_dir().join(format!("hi-cli-radar-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let status = Command::new("tar")
        .args(["xzf", &archive.to_string_lossy(), "-C", &dir.to_string_lossy()])
        .arg("data/points_3/radar.xyz")
        .status()
        .expect("tar runs");
    assert!(status.success(), "tar could not extract radar.xyz");
    let scan = dir.join("data/points_3/radar.xyz");
    let out = TempFile::path_with("obj");
    let report = fitted(&["fit", &scan.to_string_lossy(), "-o", out.path()]);
    let _ = std::fs::remove_dir_all(&dir);
    let domains = report["topology"]["domains"].as_array().expect("domains");
    assert!(domains.iter().all(|d| d == "sheet"), "{report}");
    let mean = num(&report["both_ways"]["scan_to_surface"]["relative"][0]);
    assert!(mean < 1e-3, "mean {mean} of the diagonal");
    assert!(num(&report["both_ways"]["unreached_fraction"]) < 0.01, "{report}");
}

#[test]
fn points_beyond_the_threshold_by_noise_are_said_to_be_noise() {
    // 20 000 points about the unit sphere, displaced radially by σ = 0.05 (twice their
    // spacing, 1.45 % of the diagonal of about 3.46): a surface through the middle of the
    // scatter leaves the points displaced by more than 2 % of the diagonal (1.4 σ, 17 % of them)
    // beyond it. The warning names the noise as the cause, with its estimate.
    let sigma = 0.05;
    let mut text = String::new();
    for p in hi_testkit::noisy_sphere(20_000, sigma, 11) {
        writeln!(text, "{} {} {}", p[0], p[1], p[2]).expect("to a string");
    }
    let scan = scan_file(&text, "xyz");
    let out = TempFile::path_with("glb");
    let run = run(&["fit", scan.path(), "-o", out.path()]);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    let stderr = String::from_utf8_lossy(&run.stderr);
    let line = stderr.lines().find(|l| l.contains("farther than")).expect("an unreached warning");
    assert!(line.contains("the scan's noise puts them there"), "{line}");
    let estimate: f64 = line
        .split("σ estimated at ")
        .nth(1)
        .and_then(|rest| rest.split('%').next())
        .and_then(|x| x.parse().ok())
        .expect("the estimate in the line");
    // The diagonal of the points' bounding box, as the report measures it.
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for line in text.lines() {
        for (k, x) in line.split(' ').enumerate() {
            let x: f64 = x.parse().expect("a number");
            (lo[k], hi[k]) = (lo[k].min(x), hi[k].max(x));
        }
    }
    let diagonal = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt();
    let expected = 100.0 * sigma / diagonal;
    assert!((estimate / expected - 1.0).abs() < 0.15, "{line}: σ is {expected:.2}%");
}

#[test]
fn points_that_fill_a_volume_are_said_to_fill_it() {
    // 3 000 points scattered through a cube (as some point sets are, made for meshing a
    // volume): no surface runs through them. The fit wraps them, and says that they fill a
    // volume, for the warning and as the cause of the points it leaves far from its surface.
    let mut seed = 5u64;
    let mut text = String::new();
    for _ in 0..3_000 {
        let mut uniform = || hi_testkit::lcg(&mut seed);
        let (x, y, z) = (uniform(), uniform(), uniform());
        writeln!(text, "{x} {y} {z}").expect("to a string");
    }
    let scan = scan_file(&text, "xyz");
    let out = TempFile::path_with("glb");
    let run = run(&["fit", scan.path(), "-o", out.path()]);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(stderr.contains("fill a volume rather than lie on a surface"), "{stderr}");
    for far in stderr.lines().filter(|l| l.contains("farther than")) {
        assert!(far.ends_with("they fill a volume"), "{far}");
    }
}
