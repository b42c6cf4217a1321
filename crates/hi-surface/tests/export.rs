// SPDX-License-Identifier: MIT
//! OBJ and glTF 2.0 export (§5.5: the surface as polygons for other software): read-back
//! equality through `gltf::import` and `tobj`, accessor bounds and index types, file naming,
//! and errors for unwritable paths, unknown extensions and unreadable files.

use std::io::{self, Write};
use std::path::PathBuf;

use hi_mesh::Error;
use hi_mesh::export::{self, Connectivity, MeshFormat};
use hi_mesh::{ColorMap, ColorScale, TriangleMesh};
use hi_surface::{CurvatureColoring, CurvatureQuantity, MeshOptions, Seam, sphere, torus};
use hi_surface::{ParamRange, ParamWindow};

fn tmp(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("export");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn colored(quantity: CurvatureQuantity) -> Option<CurvatureColoring> {
    Some(CurvatureColoring {
        quantity,
        map: ColorMap {
            scale: ColorScale::Symmetric,
            coverage: 1.0,
            palette: hi_mesh::Palette::Thesis,
        },
    })
}

/// Meshes with and without colours, welded and split, u16 and u32 indices.
fn meshes() -> Vec<(&'static str, TriangleMesh)> {
    let half = MeshOptions {
        n_u: 12,
        n_v: 20,
        window: ParamWindow::new(ParamRange::new(0.0, 0.5), ParamRange::UNIT),
        ..Default::default()
    };
    let cases = [
        ("sphere", sphere(1.25), half),
        (
            "sphere_k",
            sphere(1.25),
            MeshOptions { color: colored(CurvatureQuantity::Gaussian), ..half },
        ),
        (
            "sphere_split_h",
            sphere(1.25),
            MeshOptions { seam: Seam::Split, color: colored(CurvatureQuantity::Mean), ..half },
        ),
        ("torus", torus(2.0, 0.5), MeshOptions { n_u: 16, n_v: 24, ..Default::default() }),
        (
            "torus_big",
            torus(2.0, 0.5),
            MeshOptions {
                n_u: 260,
                n_v: 260,
                color: colored(CurvatureQuantity::Mean),
                ..Default::default()
            },
        ),
    ];
    cases.into_iter().map(|(n, s, o)| (n, s.to_mesh(&o).unwrap())).collect()
}

#[test]
fn gltf_and_glb_read_back_exactly() {
    for (name, mesh) in meshes() {
        for ext in ["gltf", "glb"] {
            let path = tmp(&format!("{name}.{ext}"));
            let files = export::save(&mesh, &path).unwrap();
            assert_eq!(
                files.len(),
                if ext == "gltf" { 2 } else { 1 },
                "{name}.{ext}: files {files:?}"
            );
            let report = export::read_back(&mesh, &path).unwrap();
            assert!(report.is_exact(), "{name}.{ext}: {report}");
            assert_eq!(
                report.connectivity,
                Connectivity::Identical,
                "{name}.{ext}: same index list"
            );
            assert_eq!(
                report.color_error.is_some(),
                mesh.colors().is_some(),
                "{name}.{ext}: colours"
            );
        }
    }
}

#[test]
fn obj_reads_back_to_f32_precision() {
    for (name, mesh) in meshes() {
        let path = tmp(&format!("{name}.obj"));
        export::save(&mesh, &path).unwrap();
        let report = export::read_back(&mesh, &path).unwrap();
        // tobj numbers vertices by first use; positions and normals are the exact f32 written.
        assert_ne!(report.connectivity, Connectivity::Different, "{name}: {report}");
        assert_eq!(report.position_error, 0.0, "{name}: {report}");
        assert_eq!(report.normal_error, 0.0, "{name}: {report}");
        // t is stored as 1 − t (one f32 rounding), colours as sRGB (a conversion each way).
        assert!(report.uv_error <= 6e-8, "{name}: {report}");
        assert!(report.color_error.is_none_or(|e| e <= 1e-6), "{name}: {report}");
        assert!(report.agrees_within(0.0, 1e-6), "{name}: {report}");
    }
}

#[test]
fn accessors_have_exact_bounds_and_fitting_index_types() {
    for (name, mesh) in meshes() {
        let path = tmp(&format!("{name}_bounds.glb"));
        export::save(&mesh, &path).unwrap();
        let (doc, _, _) = gltf::import(&path).unwrap();
        assert!(
            doc.as_json().asset.generator.as_deref().unwrap().starts_with("harmonic"),
            "generator"
        );
        let prim = doc.meshes().next().unwrap().primitives().next().unwrap();
        let pos = prim.get(&gltf::Semantic::Positions).unwrap();
        let to_f32 = |v: gltf::json::Value| -> Vec<f32> {
            v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap() as f32).collect()
        };
        let (lo, hi) = (to_f32(pos.min().unwrap()), to_f32(pos.max().unwrap()));
        for axis in 0..3 {
            let values = mesh.positions().iter().map(|p| p.as_vec3()[axis]);
            let (a, b) =
                values.fold((f32::INFINITY, f32::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
            assert_eq!(
                (lo[axis], hi[axis]),
                (a, b),
                "{name}: axis {axis} bounds are those of the f32 written"
            );
        }
        let indices = prim.indices().unwrap();
        let expected = if mesh.n_vertices() <= 65_535 {
            gltf::accessor::DataType::U16
        } else {
            gltf::accessor::DataType::U32
        };
        assert_eq!(indices.data_type(), expected, "{name}: {} vertices", mesh.n_vertices());
        assert_eq!(
            prim.get(&gltf::Semantic::Colors(0)).is_some(),
            mesh.colors().is_some(),
            "{name}: COLOR_0"
        );
        assert!(prim.get(&gltf::Semantic::TexCoords(0)).is_some(), "{name}: TEXCOORD_0");
    }
    // The big torus needs u32 indices: 260² vertices.
    assert!(meshes().iter().any(|(_, m)| m.n_vertices() > 65_535), "a u32 case is tested");
}

#[test]
fn normals_in_files_are_unit() {
    let (_, mesh) = meshes().into_iter().find(|(n, _)| *n == "sphere_k").unwrap();
    let path = tmp("normals.glb");
    export::save(&mesh, &path).unwrap();
    let (doc, buffers, _) = gltf::import(&path).unwrap();
    let prim = doc.meshes().next().unwrap().primitives().next().unwrap();
    let reader = prim.reader(|b| Some(&buffers[b.index()]));
    for n in reader.read_normals().unwrap() {
        let len = glam::Vec3::from(n).length();
        assert!((len - 1.0).abs() < 1e-6, "|n| = {len}");
    }
}

#[test]
fn gltf_buffer_name_is_percent_encoded() {
    let (_, mesh) = meshes().into_iter().next().unwrap();
    let path = tmp("a mesh #1.gltf");
    let files = export::save(&mesh, &path).unwrap();
    assert_eq!(files[1], tmp("a mesh #1.bin"), "buffer beside the JSON");
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains("\"uri\": \"a%20mesh%20%231.bin\""), "encoded URI");
    assert!(export::read_back(&mesh, &path).unwrap().is_exact(), "and it loads");
}

#[test]
fn unknown_extensions_are_errors() {
    let (_, mesh) = meshes().into_iter().next().unwrap();
    for name in ["mesh.stl", "mesh", "mesh.gltf.txt", "mesh.bin"] {
        let path = tmp(name);
        let e = export::save(&mesh, &path).unwrap_err();
        assert!(matches!(e, Error::UnknownExtension { .. }), "{name}: {e:?}");
        assert!(!path.exists() || name == "mesh.bin", "{name}: nothing written");
        assert!(matches!(export::load(&path), Err(Error::UnknownExtension { .. })), "{name}");
        assert!(e.to_string().contains(name) && !e.to_string().contains('\n'), "{e}");
    }
    assert_eq!(MeshFormat::try_from_path("X.Obj".as_ref()).unwrap(), MeshFormat::Obj, "any case");
}

#[test]
fn unwritable_paths_are_errors() {
    let (_, mesh) = meshes().into_iter().next().unwrap();
    let missing_dir = tmp("no-such-directory");
    let _ = std::fs::remove_dir_all(&missing_dir);
    for ext in ["obj", "gltf", "glb"] {
        let path = missing_dir.join(format!("mesh.{ext}"));
        let e = export::save(&mesh, &path).unwrap_err();
        match &e {
            Error::Io { path: Some(p), kind, .. } => {
                assert_eq!(p, &path, "{ext}: names the file");
                assert_eq!(*kind, io::ErrorKind::NotFound, "{ext}");
            }
            other => panic!("{ext}: {other:?}"),
        }
        assert!(!e.to_string().contains('\n'), "one line: {e}");
    }
    // A directory where the file should go.
    let dir_path = tmp("a-directory.glb");
    std::fs::create_dir_all(&dir_path).unwrap();
    let e = export::save(&mesh, &dir_path).unwrap_err();
    assert!(matches!(e, Error::Io { .. }), "{e:?}");
}

/// A writer that fails after `left` bytes.
struct Failing {
    left: usize,
}

impl Write for Failing {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.left == 0 {
            return Err(io::Error::new(io::ErrorKind::StorageFull, "disk full"));
        }
        let n = buf.len().min(self.left);
        self.left -= n;
        Ok(n)
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

#[test]
fn failing_writers_are_errors() {
    let (_, mesh) = meshes().into_iter().next().unwrap();
    for left in [0, 100, 1000] {
        let glb = export::write_glb(&mesh, Failing { left });
        let obj = export::write_obj(&mesh, Failing { left });
        let gltf = export::write_gltf(&mesh, Failing { left }, Vec::new(), "x.bin");
        let bin = export::write_gltf(&mesh, Vec::new(), Failing { left }, "x.bin");
        for r in [glb, obj, gltf, bin] {
            assert!(
                matches!(r, Err(Error::Io { path: None, kind: io::ErrorKind::StorageFull, .. })),
                "{left}: {r:?}"
            );
        }
    }
}

#[test]
fn unreadable_files_are_errors() {
    let missing = tmp("missing.glb");
    let _ = std::fs::remove_file(&missing);
    assert!(
        matches!(export::load(&missing), Err(Error::Io { kind: io::ErrorKind::NotFound, .. })),
        "missing glb"
    );
    let missing_obj = tmp("missing.obj");
    let _ = std::fs::remove_file(&missing_obj);
    assert!(matches!(export::load(&missing_obj), Err(Error::Io { .. })), "missing obj");
    for (name, content) in [
        ("garbage.glb", "not a glb"),
        ("garbage.gltf", "{ nope"),
        ("points.obj", "v 0 0 0\nv 1 0 0\n"),
    ] {
        let path = tmp(name);
        std::fs::write(&path, content).unwrap();
        let e = export::load(&path).unwrap_err();
        assert!(matches!(e, Error::Format { path: Some(_), .. }), "{name}: {e:?}");
        assert!(!e.to_string().contains('\n'), "{name}: one line: {e}");
    }
    // A .gltf whose buffer is missing.
    let (_, mesh) = meshes().into_iter().next().unwrap();
    let path = tmp("lost_buffer.gltf");
    let files = export::save(&mesh, &path).unwrap();
    std::fs::remove_file(&files[1]).unwrap();
    assert!(export::load(&path).is_err(), "buffer gone");
}

#[test]
fn compare_detects_differences() {
    let meshes = meshes();
    let (a, b) = (&meshes[0].1, &meshes[1].1);
    let same = export::compare(a, a);
    assert!(same.is_exact(), "{same}");
    // Same grid, one with colours: only the colours differ.
    let r = export::compare(a, b);
    assert_eq!(r.color_error, Some(f64::INFINITY), "{r}");
    assert!(!r.is_exact(), "{r}");
    // Different meshes.
    let r = export::compare(a, &meshes[3].1);
    assert_eq!(r.connectivity, Connectivity::Different, "{r}");
    assert!(!r.agrees_within(1.0, 1.0), "{r}");
}

#[test]
fn a_glb_with_edges_reads_back_as_its_triangles() {
    for (name, mesh) in meshes() {
        // Every vertex joined to the next: lines the reader leaves out.
        let n = u32::try_from(mesh.n_vertices()).unwrap();
        let edges: Vec<[u32; 2]> = (0..n - 1).map(|k| [k, k + 1]).collect();
        let path = tmp(&format!("{name}-edges.glb"));
        let mut file = std::fs::File::create(&path).unwrap();
        export::write_glb_with_edges(&mesh, &edges, &mut file).unwrap();
        drop(file);
        let report = export::read_back(&mesh, &path).unwrap();
        assert!(report.is_exact(), "{name}: {report}");
        assert_eq!(report.connectivity, Connectivity::Identical, "{name}");
    }
}
