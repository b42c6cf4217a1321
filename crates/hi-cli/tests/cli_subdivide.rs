// SPDX-License-Identifier: MIT
//! End-to-end tests of `hi subdivide`: the refined meshes are read back from the written files
//! (OBJ parsed here by hand, GLB by the `gltf` crate) and checked against the values the peer
//! programs give (docs/peers.md §3: CGAL, `OpenMesh` and trimesh agree on them).

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use common::{TempFile, bad, ok};

/// A mesh file with `ext` holding `text`.
fn mesh_file(ext: &str, text: &str) -> TempFile {
    let file = TempFile::path_with(ext);
    std::fs::write(file.as_path(), text).expect("temp file is writable");
    file
}

/// The unit cube [0, 1]³ of six outward quads.
const CUBE: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n\
                    f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";

/// The octahedron ±eᵢ as OFF.
const OCTAHEDRON: &str = "OFF\n6 8 12\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n\
                          3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";

/// The `v` lines of an OBJ file.
fn obj_vertices(path: &std::path::Path) -> Vec<[f64; 3]> {
    std::fs::read_to_string(path)
        .expect("the output exists")
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().expect("a number")).collect();
            [v[0], v[1], v[2]]
        })
        .collect()
}

#[test]
fn catmull_clark_on_the_cube() {
    let input = mesh_file("obj", CUBE);
    let out = TempFile::path_with("obj");
    let report = ok(&[
        "subdivide",
        "--scheme",
        "catmull-clark",
        "--steps",
        "1",
        input.path(),
        "-o",
        out.path(),
    ]);
    // 8 + 12 + 6 vertices, 24 quads, 48 edges.
    assert_eq!(
        (report["vertices"].as_u64(), report["edges"].as_u64(), report["faces"].as_u64()),
        (Some(26), Some(48), Some(24))
    );
    let v = obj_vertices(out.as_path());
    assert_eq!(v.len(), 26);
    // The corner (0, 0, 0) moves to (2/9, 2/9, 2/9) (docs/peers.md §3).
    let corner = v
        .iter()
        .copied()
        .min_by(|a, b| a.iter().sum::<f64>().total_cmp(&b.iter().sum()))
        .expect("vertices");
    for c in corner {
        assert!((c - 2.0 / 9.0).abs() < 1e-12, "{corner:?}");
    }
}

#[test]
fn loop_on_the_octahedron_to_glb() {
    let input = mesh_file("off", OCTAHEDRON);
    let out = TempFile::path_with("obj");
    let report =
        ok(&["subdivide", "--scheme", "loop", "--steps", "2", input.path(), "-o", out.path()]);
    assert_eq!((report["vertices"].as_u64(), report["faces"].as_u64()), (Some(66), Some(128)));
    // (1, 0, 0) moves to x = 0.447510 after two steps (docs/peers.md §3).
    let x = obj_vertices(out.as_path()).iter().map(|p| p[0]).fold(f64::MIN, f64::max);
    assert!((x - 0.447_510).abs() < 5e-7, "{x}");
    let glb = TempFile::path_with("glb");
    ok(&["subdivide", "--scheme", "loop", "--steps", "1", input.path(), "-o", glb.path()]);
    let (doc, buffers, _) = gltf::import(glb.as_path()).expect("the GLB reads back");
    let mesh = doc.meshes().next().expect("one mesh");
    let prim = mesh.primitives().next().expect("one primitive");
    let reader = prim.reader(|b| Some(&buffers[b.index()]));
    let n = reader.read_positions().expect("positions").count();
    assert!(n >= 18, "18 vertices after one step (more if split for normals): {n}");
    let x = reader
        .read_positions()
        .expect("positions")
        .map(|p| f64::from(p[0]))
        .fold(f64::MIN, f64::max);
    assert!((x - 0.515_625).abs() < 1e-6, "{x}");
}

#[test]
fn bad_input_is_named() {
    let cube = mesh_file("obj", CUBE);
    let out = TempFile::path_with("obj");
    bad(&["subdivide", "--scheme", "loop", "--steps", "1", cube.path(), "-o", out.path()], "loop");
    bad(
        &["subdivide", "--scheme", "sqrt3", "--steps", "9", cube.path(), "-o", out.path()],
        "--steps: 9 is too many (at most 8)",
    );
    let wrong = TempFile::path_with("stl");
    bad(
        &[
            "subdivide",
            "--scheme",
            "catmull-clark",
            "--steps",
            "1",
            cube.path(),
            "-o",
            wrong.path(),
        ],
        "unknown extension",
    );
    bad(
        &[
            "subdivide",
            "--scheme",
            "catmull-clark",
            "--steps",
            "1",
            "no/such/mesh.obj",
            "-o",
            out.path(),
        ],
        "no/such/mesh.obj",
    );
    let broken = mesh_file("off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
    bad(
        &["subdivide", "--scheme", "doo-sabin", "--steps", "1", broken.path(), "-o", out.path()],
        broken.path(),
    );
}
