// SPDX-License-Identifier: MIT
//! Scenes of named meshes (`export::save_scene`, `export::load_scene`): a closed icosphere, a
//! closed torus and an open square sheet with a boundary, written as GLB, glTF and OBJ, read
//! back part by part with their names; bad scenes refused with an error naming the part; the
//! single-mesh files are the one-part scene's; and two independent readers agree — the Khronos
//! glTF-Validator (no error, no warning) and trimesh (one named geometry per part).
//!
//! The validator runs through `xtask/peers/gltf-validator/validate.js` (`npm ci` in that
//! directory), trimesh through `python3`. Without them a check says so and passes, unless
//! `HI_REQUIRE_PEERS=1` is set (as CI does), when it fails.
#![cfg(all(feature = "gltf", feature = "obj"))]

use std::collections::HashMap;
use std::f64::consts::{PI, TAU};
use std::path::{Path, PathBuf};
use std::process::Command;

use glam::{DVec2, DVec3};
use hi_mesh::export::{self, Connectivity, NamedMesh};
use hi_mesh::{Error, TriangleMesh};
use hi_testkit::skip;

const VALIDATOR_DIR: &str =
    concat!(env!("CARGO_MANIFEST_DIR"), "/../../xtask/peers/gltf-validator");

/// A directory of this test's own.
fn dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("scene").join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A colour of each vertex, from its position (components in [0, 1]).
fn colored(mesh: TriangleMesh) -> TriangleMesh {
    let colors = mesh
        .positions()
        .iter()
        .map(|p| (p.normalize_or_zero() * 0.5 + 0.5).as_vec3().to_array())
        .collect();
    mesh.try_with_colors(colors).unwrap()
}

/// The unit icosphere: the icosahedron with each triangle split in four `levels` times, the
/// new vertices pushed onto the sphere. Closed.
fn icosphere(levels: usize) -> TriangleMesh {
    let g = (1.0 + 5f64.sqrt()) / 2.0;
    let mut p: Vec<DVec3> = [
        [-1.0, g, 0.0],
        [1.0, g, 0.0],
        [-1.0, -g, 0.0],
        [1.0, -g, 0.0],
        [0.0, -1.0, g],
        [0.0, 1.0, g],
        [0.0, -1.0, -g],
        [0.0, 1.0, -g],
        [g, 0.0, -1.0],
        [g, 0.0, 1.0],
        [-g, 0.0, -1.0],
        [-g, 0.0, 1.0],
    ]
    .iter()
    .map(|&c| DVec3::from(c).normalize())
    .collect();
    let mut t: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..levels {
        let mut mid: HashMap<(u32, u32), u32> = HashMap::new();
        let mut midpoint = |a: u32, b: u32, p: &mut Vec<DVec3>| {
            *mid.entry((a.min(b), a.max(b))).or_insert_with(|| {
                p.push(((p[a as usize] + p[b as usize]) / 2.0).normalize());
                (p.len() - 1) as u32
            })
        };
        t = t
            .iter()
            .flat_map(|&[a, b, c]| {
                let (ab, bc, ca) =
                    (midpoint(a, b, &mut p), midpoint(b, c, &mut p), midpoint(c, a, &mut p));
                [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
            })
            .collect();
    }
    let uv = p.iter().map(|q| DVec2::new(q.y.atan2(q.x) / TAU + 0.5, q.z.acos() / PI)).collect();
    TriangleMesh::try_new(p.clone(), p, uv, t).unwrap()
}

/// A torus of radii 2 and 0.5 about (5, 0, 0), `n_u` × `n_v` vertices welded around both
/// circles. Closed.
fn torus(n_u: usize, n_v: usize) -> TriangleMesh {
    let (mut p, mut n, mut uv, mut t) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for i in 0..n_u {
        for j in 0..n_v {
            let (s, r) = (i as f64 / n_u as f64, j as f64 / n_v as f64);
            let (u, v) = (TAU * s, TAU * r);
            let normal = DVec3::new(v.cos() * u.cos(), v.cos() * u.sin(), v.sin());
            p.push(DVec3::new(5.0 + 2.0 * u.cos(), 2.0 * u.sin(), 0.0) + 0.5 * normal);
            n.push(normal);
            uv.push(DVec2::new(s, r));
        }
    }
    let k = |i: usize, j: usize| ((i % n_u) * n_v + j % n_v) as u32;
    for i in 0..n_u {
        for j in 0..n_v {
            t.push([k(i, j), k(i + 1, j), k(i + 1, j + 1)]);
            t.push([k(i, j), k(i + 1, j + 1), k(i, j + 1)]);
        }
    }
    TriangleMesh::try_new(p, n, uv, t).unwrap()
}

/// An open square sheet of `n` × `n` squares at z = −3, facing +z: its boundary has 4n edges.
fn sheet(n: usize) -> TriangleMesh {
    let (mut p, mut uv, mut t) = (Vec::new(), Vec::new(), Vec::new());
    for i in 0..=n {
        for j in 0..=n {
            let q = DVec2::new(i as f64, j as f64) / n as f64;
            p.push(DVec3::new(2.0 * q.x - 1.0, 2.0 * q.y - 1.0, -3.0));
            uv.push(q);
        }
    }
    let k = |i: usize, j: usize| (i * (n + 1) + j) as u32;
    for i in 0..n {
        for j in 0..n {
            t.push([k(i, j), k(i + 1, j), k(i + 1, j + 1)]);
            t.push([k(i, j), k(i + 1, j + 1), k(i, j + 1)]);
        }
    }
    let normals = vec![DVec3::Z; p.len()];
    TriangleMesh::try_new(p, normals, uv, t).unwrap()
}

/// The number of edges with one triangle, counted on positions (so that a reader's
/// renumbering or a seam does not change it).
fn boundary_edges(mesh: &TriangleMesh) -> usize {
    let key = |k: u32| mesh.positions()[k as usize].to_array().map(f64::to_bits);
    let mut count: HashMap<([u64; 3], [u64; 3]), usize> = HashMap::new();
    for t in mesh.triangles() {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            let (a, b) = (key(a), key(b));
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    count.values().filter(|&&c| c == 1).count()
}

/// The three parts, with or without colours.
fn three_parts(with_colors: bool) -> Vec<(&'static str, TriangleMesh)> {
    let parts = [("icosphere", icosphere(2)), ("torus", torus(24, 12)), ("open sheet", sheet(8))];
    parts.into_iter().map(|(name, m)| (name, if with_colors { colored(m) } else { m })).collect()
}

fn named<'a>(parts: &'a [(&'static str, TriangleMesh)]) -> Vec<NamedMesh<'a>> {
    parts.iter().map(|(name, mesh)| NamedMesh::new(name, mesh)).collect()
}

#[test]
fn the_parts_are_what_they_should_be() {
    let [sphere, torus, sheet] =
        three_parts(false).into_iter().map(|(_, m)| m).collect::<Vec<_>>().try_into().unwrap();
    assert_eq!((sphere.n_vertices(), sphere.n_triangles()), (162, 320), "icosphere of level 2");
    assert_eq!(boundary_edges(&sphere), 0, "the icosphere is closed");
    assert_eq!(boundary_edges(&torus), 0, "the torus is closed");
    assert_eq!(boundary_edges(&sheet), 32, "the sheet is open");
}

/// Every format returns the three parts, in order, with their names and their geometry to
/// f32 precision; the sheet keeps its boundary; `load` reads the same file as one mesh.
#[test]
fn three_parts_read_back_from_every_format() {
    let dir = dir("three_parts");
    for with_colors in [false, true] {
        let parts = three_parts(with_colors);
        let scene = named(&parts);
        for ext in ["glb", "gltf", "obj"] {
            let path = dir.join(format!("parts_{with_colors}.{ext}"));
            let files = export::save_scene(&scene, &path).unwrap();
            let expected_files = if ext == "gltf" {
                vec![path.clone(), path.with_extension("bin")]
            } else {
                vec![path.clone()]
            };
            assert_eq!(files, expected_files, "{ext}: the files written");

            let found = export::load_scene(&path).unwrap();
            let names: Vec<&str> = found.iter().map(|(n, _)| n.as_str()).collect();
            assert_eq!(names, ["icosphere", "torus", "open sheet"], "{ext}: names and order");
            let report = export::compare_scene(&scene, &found);
            assert!(report.names_agree(), "{ext}: {report}");
            assert_eq!(report.parts.len(), 3, "{ext}: {report}");
            for ((name, mesh), part) in parts.iter().zip(&report.parts) {
                assert_eq!(part.color_error.is_some(), with_colors, "{ext} {name}: {part}");
                if ext == "obj" {
                    // tobj numbers vertices by first use; positions and normals are the f32
                    // written, t is stored as 1 − t and colours as sRGB.
                    assert_ne!(part.connectivity, Connectivity::Different, "{ext} {name}: {part}");
                    assert_eq!(part.position_error, 0.0, "{ext} {name}: {part}");
                    assert_eq!(part.normal_error, 0.0, "{ext} {name}: {part}");
                    assert!(part.uv_error <= 6e-8, "{ext} {name}: {part}");
                    assert!(part.agrees_within(0.0, 1e-6), "{ext} {name}: {part}");
                } else {
                    assert!(part.is_exact(), "{ext} {name}: {part}");
                    assert_eq!(part.connectivity, Connectivity::Identical, "{ext} {name}");
                }
                assert_eq!(part.found_vertices, mesh.n_vertices(), "{ext} {name}: {part}");
            }
            let tolerance = if ext == "obj" { 1e-6 } else { 0.0 };
            assert!(report.agrees_within(0.0, tolerance), "{ext}: {report}");
            if ext != "obj" {
                assert!(report.is_exact(), "{ext}: {report}");
            }
            assert_eq!(
                export::read_back_scene(&scene, &path).unwrap(),
                report,
                "{ext}: read_back_scene is load_scene and compare_scene"
            );
            for ((name, mesh), (_, read)) in parts.iter().zip(&found) {
                assert_eq!(boundary_edges(read), boundary_edges(mesh), "{ext} {name}: boundary");
            }

            // The single-mesh reader takes the parts as one mesh.
            let whole = export::load(&path).unwrap();
            let n: usize = parts.iter().map(|(_, m)| m.n_vertices()).sum();
            let t: usize = parts.iter().map(|(_, m)| m.n_triangles()).sum();
            assert_eq!((whole.n_vertices(), whole.n_triangles()), (n, t), "{ext}: load");
        }
    }
}

/// glTF keeps colours part by part and picks each part's index size: a coloured torus of more
/// than 65 535 vertices (u32 indices) beside parts without colours (u16). OBJ colours every
/// vertex or none, so the OBJ writer refuses that scene, naming a part without colours.
#[test]
fn parts_differ_in_colours_and_index_sizes() {
    let dir = dir("mixed");
    let big = colored(torus(300, 240));
    assert!(big.n_vertices() > 65_535, "u32 indices");
    let (sphere, sheet) = (icosphere(1), sheet(3));
    let scene = [
        NamedMesh::new("small sphere", &sphere),
        NamedMesh::new("big torus", &big),
        NamedMesh::new("sheet", &sheet),
    ];
    for ext in ["glb", "gltf"] {
        let path = dir.join(format!("mixed.{ext}"));
        export::save_scene(&scene, &path).unwrap();
        let report = export::read_back_scene(&scene, &path).unwrap();
        assert!(report.is_exact(), "{ext}: {report}");
        let colors: Vec<bool> = report.parts.iter().map(|p| p.color_error.is_some()).collect();
        assert_eq!(colors, [false, true, false], "{ext}: colours where they were");

        let (document, _, _) = gltf::import(&path).unwrap();
        let index_types: Vec<_> = document
            .meshes()
            .map(|m| m.primitives().next().unwrap().indices().unwrap().data_type())
            .collect();
        use gltf::accessor::DataType::{U16, U32};
        assert_eq!(index_types, [U16, U32, U16], "{ext}: index sizes");
        assert_eq!(document.buffers().count(), 1, "{ext}: one buffer");
        assert_eq!(document.materials().count(), 1, "{ext}: one material");
        let scenes: Vec<Vec<Option<&str>>> =
            document.scenes().map(|s| s.nodes().map(|n| n.name()).collect()).collect();
        assert_eq!(scenes, [[Some("small sphere"), Some("big torus"), Some("sheet")]], "{ext}");
        for node in document.nodes() {
            assert_eq!(node.name(), node.mesh().unwrap().name(), "{ext}: node name = mesh name");
        }
        for accessor in document.accessors().filter(|a| a.count() > 0) {
            let is_position = document.meshes().any(|m| {
                m.primitives().any(|p| {
                    p.get(&gltf::Semantic::Positions).is_some_and(|a| a.index() == accessor.index())
                })
            });
            assert_eq!(accessor.min().is_some(), is_position, "{ext}: min on positions");
            assert_eq!(accessor.max().is_some(), is_position, "{ext}: max on positions");
        }
    }
    let path = dir.join("mixed.obj");
    let _ = std::fs::remove_file(&path);
    let err = export::save_scene(&scene, &path).unwrap_err();
    assert!(matches!(err, Error::InvalidPart { part: 0, .. }), "{err:?}");
    let message = err.to_string();
    assert!(
        message.starts_with("scene part 0 (\"small sphere\"): it has no vertex colours but part 1"),
        "{message}"
    );
    assert!(!path.exists(), "nothing written");
}

/// No parts, an empty name, a repeated one, one over two lines or with a blank at an end: an
/// error naming the part, from every writer, before any file is created.
#[test]
fn bad_scenes_are_refused() {
    let dir = dir("bad");
    let (a, b) = (icosphere(0), sheet(1));
    let cases: [(&str, Vec<NamedMesh<'_>>, &str); 6] = [
        ("none", vec![], "number of scene parts = 0 is invalid: expected at least 1"),
        (
            "empty",
            vec![NamedMesh::new("a", &a), NamedMesh::new("", &b)],
            "scene part 1 (\"\"): its name is empty; every part needs a name",
        ),
        (
            "duplicate",
            vec![NamedMesh::new("eye", &a), NamedMesh::new("teeth", &b), NamedMesh::new("eye", &b)],
            "scene part 2 (\"eye\"): its name is that of part 0; part names must be unique",
        ),
        (
            "newline",
            vec![NamedMesh::new("left\neye", &a)],
            "scene part 0 (\"left\\neye\"): its name has the control character or line break \
             U+000A at byte 4; a name is printed on one line",
        ),
        (
            "separator",
            vec![NamedMesh::new("lid\u{2028}", &a)],
            "scene part 0 (\"lid\\u{2028}\"): its name has the control character or line break \
             U+2028 at byte 3; a name is printed on one line",
        ),
        (
            "blank",
            vec![NamedMesh::new("pot", &a), NamedMesh::new(" lid", &b)],
            "scene part 1 (\" lid\"): its name starts or ends with whitespace, which OBJ readers \
             drop",
        ),
    ];
    for (case, parts, message) in &cases {
        for ext in ["glb", "gltf", "obj"] {
            let path = dir.join(format!("{case}.{ext}"));
            let _ = std::fs::remove_file(&path);
            let _ = std::fs::remove_file(path.with_extension("bin"));
            let err = export::save_scene(parts, &path).unwrap_err();
            assert_eq!(err.to_string(), *message, "{case}.{ext}");
            assert!(!path.exists() && !path.with_extension("bin").exists(), "{case}.{ext}");
        }
        let names = parts.iter().map(|p| p.name);
        assert_eq!(export::check_part_names(names).unwrap_err().to_string(), *message, "{case}");
        let writers = [
            export::write_scene_glb(parts, Vec::new()),
            export::write_scene_gltf(parts, Vec::new(), Vec::new(), "x.bin"),
            export::write_scene_obj(parts, Vec::new()),
        ];
        for result in writers {
            assert_eq!(result.unwrap_err().to_string(), *message, "{case}: a writer");
        }
    }
    // An unknown extension is named before the parts are looked at.
    let err = export::save_scene(&[], dir.join("scene.stl")).unwrap_err();
    assert!(err.to_string().contains("unknown mesh file extension"), "{err}");
}

/// `save` of one mesh writes the file of the one-part scene of the same name (`harmonic
/// surface` in glTF, `harmonic_surface` in OBJ), byte for byte: one writer for both.
#[test]
fn a_single_mesh_is_the_one_part_scene() {
    let mesh = colored(torus(10, 8));
    let (single, scene) = (dir("single"), dir("one_part"));
    for (ext, name) in
        [("glb", "harmonic surface"), ("gltf", "harmonic surface"), ("obj", "harmonic_surface")]
    {
        let a = export::save(&mesh, single.join(format!("mesh.{ext}"))).unwrap();
        let b =
            export::save_scene(&[NamedMesh::new(name, &mesh)], scene.join(format!("mesh.{ext}")))
                .unwrap();
        assert_eq!(a.len(), b.len(), "{ext}");
        for (a, b) in a.iter().zip(&b) {
            assert_eq!(std::fs::read(a).unwrap(), std::fs::read(b).unwrap(), "{}", a.display());
        }
        let found = export::load_scene(&b[0]).unwrap();
        assert_eq!(found.len(), 1, "{ext}");
        assert_eq!(found[0].0, name, "{ext}");
    }
}

/// A mesh without texture coordinates (every UV at the origin, as `from_triangles` gives) is
/// written without `TEXCOORD_0`, and reads back with its UVs at the origin as it had; a mesh
/// with them keeps them. The buffer without them is smaller by the 8 bytes a vertex they took.
#[test]
fn texture_coordinates_are_written_only_when_the_mesh_has_them() {
    let dir = dir("uvs");
    let with = torus(10, 8);
    assert!(with.uvs().iter().any(|t| *t != DVec2::ZERO));
    let without =
        TriangleMesh::from_triangles(with.positions().to_vec(), with.triangles().to_vec()).unwrap();
    let sizes: Vec<u64> = [(&with, "with"), (&without, "without")]
        .iter()
        .map(|(mesh, name)| {
            let path = dir.join(format!("{name}.glb"));
            export::save(mesh, &path).unwrap();
            let (doc, _, _) = gltf::import(&path).unwrap();
            let prim = doc.meshes().next().unwrap().primitives().next().unwrap();
            let has = prim.get(&gltf::Semantic::TexCoords(0)).is_some();
            assert_eq!(has, *name == "with", "{name}");
            let found = export::load_scene(&path).unwrap().remove(0).1;
            assert_eq!(found.uvs().len(), mesh.n_vertices(), "{name}");
            for (a, b) in found.uvs().iter().zip(mesh.uvs()) {
                assert_eq!(a.as_vec2(), b.as_vec2(), "{name}");
            }
            doc.buffers().map(|b| b.length() as u64).sum::<u64>()
        })
        .collect();
    assert_eq!(sizes[0] - sizes[1], 8 * with.n_vertices() as u64, "{sizes:?}");
}

/// A glTF scene as other programs write it: a node without a name takes its mesh's, one with
/// neither takes `mesh_k`; node transforms are applied part by part.
#[test]
fn gltf_parts_take_names_and_transforms_from_their_nodes() {
    let dir = dir("nodes");
    let parts = three_parts(false);
    let path = dir.join("nodes.gltf");
    export::save_scene(&named(&parts), &path).unwrap();
    let mut json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
    let nodes = json["nodes"].as_array_mut().unwrap();
    nodes[0].as_object_mut().unwrap().remove("name");
    nodes[1]["name"] = "moved".into();
    nodes[1]["translation"] = serde_json::json!([0.0, 0.0, 10.0]);
    nodes[2].as_object_mut().unwrap().remove("name");
    json["meshes"][2].as_object_mut().unwrap().remove("name");
    std::fs::write(&path, serde_json::to_vec(&json).unwrap()).unwrap();

    let found = export::load_scene(&path).unwrap();
    let names: Vec<&str> = found.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["icosphere", "moved", "mesh_2"], "node, else mesh, else index");
    let (torus, moved) = (&parts[1].1, &found[1].1);
    for (p, q) in torus.positions().iter().zip(moved.positions()) {
        assert_eq!(p.as_vec3().as_dvec3() + DVec3::new(0.0, 0.0, 10.0), *q, "translated");
    }
    assert!(export::compare(&parts[0].1, &found[0].1).is_exact(), "the sphere is in place");
}

/// The Khronos glTF-Validator: no error and no warning on the scenes' `.glb` and `.gltf`
/// files; the only notes are the UVs no texture uses.
#[test]
fn khronos_validator_reports_no_errors_or_warnings() {
    if !Path::new(VALIDATOR_DIR).join("node_modules/gltf-validator").is_dir() {
        skip("gltf-validator is not installed (run `npm ci` in xtask/peers/gltf-validator)");
        return;
    }
    let dir = dir("validator");
    let colored_parts = three_parts(true);
    let plain_parts = three_parts(false);
    let big = torus(300, 240);
    let sphere = colored(icosphere(1));
    let mixed = [NamedMesh::new("big torus", &big), NamedMesh::new("sphere", &sphere)];
    let mut files = Vec::new();
    for (name, scene) in [
        ("colored", named(&colored_parts)),
        ("plain", named(&plain_parts)),
        ("mixed", mixed.to_vec()),
    ] {
        for ext in ["glb", "gltf"] {
            let path = dir.join(format!("{name}.{ext}"));
            export::save_scene(&scene, &path).unwrap();
            files.push(path);
        }
    }
    let output = match Command::new("node")
        .arg(Path::new(VALIDATOR_DIR).join("validate.js"))
        .args(&files)
        .output()
    {
        Ok(o) => o,
        Err(e) => return skip(&format!("node is not usable: {e}")),
    };
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr);
    eprintln!("{stdout}{stderr}");
    assert!(output.status.success(), "the validator found errors or warnings:\n{stdout}{stderr}");
    let summaries: Vec<&str> = stdout.lines().filter(|l| l.contains(": validator ")).collect();
    assert_eq!(summaries.len(), files.len(), "one report per file:\n{stdout}");
    for line in &summaries {
        assert!(line.contains(" errors=0 warnings=0 "), "{line}");
    }
    for line in stdout.lines().filter(|l| l.starts_with("  [")) {
        let unused_uvs = (0..3).any(|k| {
            line.contains(&format!(
                "[INFO] UNUSED_OBJECT /meshes/{k}/primitives/0/attributes/TEXCOORD_0"
            ))
        });
        assert!(unused_uvs, "{line}");
    }
}

/// trimesh opens the GLB as a `Scene` of one geometry per part, named as the part, in the
/// order of the parts, each placed by a node of the same name; and the OBJ the same way when
/// asked to split it into its objects (`split_objects=True`; in an order of its own), with
/// the parts' vertex counts (nothing merged: `process=False`). Left to its defaults, trimesh
/// reads the OBJ as one mesh of all the parts.
#[test]
fn trimesh_opens_one_named_geometry_per_part() {
    let dir = dir("trimesh");
    let parts = three_parts(true);
    let expected: Vec<(String, usize)> =
        parts.iter().map(|(name, m)| (name.to_string(), m.n_vertices())).collect();
    let script = r#"
import json, sys, trimesh
path = sys.argv[1]
split = {'split_objects': True} if path.endswith('.obj') else {}
scene = trimesh.load(path, process=False, **split)
merged = type(trimesh.load(path, process=False)).__name__
geometry = [[name, len(g.vertices)] for name, g in scene.geometry.items()]
nodes = sorted(scene.graph.nodes_geometry)
kind = type(scene).__name__
print(json.dumps({"type": kind, "geometry": geometry, "nodes": nodes, "merged": merged}))
"#;
    for ext in ["glb", "obj"] {
        let path = dir.join(format!("parts.{ext}"));
        export::save_scene(&named(&parts), &path).unwrap();
        let out = Command::new("python3").args(["-c", script]).arg(&path).output();
        let text = match out {
            Ok(o) if o.status.success() => String::from_utf8_lossy(&o.stdout).into_owned(),
            other => {
                let why = match other {
                    Ok(o) => {
                        String::from_utf8_lossy(&o.stderr).lines().last().unwrap_or("").to_owned()
                    }
                    Err(e) => e.to_string(),
                };
                return skip(&format!("python3 with trimesh is not usable ({why})"));
            }
        };
        eprintln!("trimesh, {ext}: {}", text.trim());
        let seen: serde_json::Value = serde_json::from_str(text.trim()).unwrap();
        assert_eq!(seen["type"], "Scene", "{ext}: {text}");
        let mut geometry: Vec<(String, usize)> =
            serde_json::from_value(seen["geometry"].clone()).unwrap();
        let mut expected = expected.clone();
        if ext == "obj" {
            // The objects' order is trimesh's own (5.2 lists them last first).
            geometry.sort();
            expected.sort();
        }
        assert_eq!(geometry, expected, "{ext}: geometry names, order and vertex counts");
        let nodes: Vec<String> = serde_json::from_value(seen["nodes"].clone()).unwrap();
        let mut names: Vec<String> = expected.iter().map(|(name, _)| name.clone()).collect();
        names.sort();
        assert_eq!(nodes, names, "{ext}: node names");
        let merged = if ext == "obj" { "Trimesh" } else { "Scene" };
        assert_eq!(seen["merged"], merged, "{ext}: what trimesh's defaults give");
    }
}
