// SPDX-License-Identifier: MIT
//! The scan readers: small files written by hand (the expected points and faces are the ones
//! written), binary files built byte by byte in the test, malformed files with their error
//! messages, and the real models of the shared data folder checked against the vertex and
//! face counts their source lists (and against `tobj` for OBJ meshes).

use std::path::PathBuf;

use glam::DVec3;
use hi_scan::scan::{Location, Scan, ScanFormat, parse_scan, read_scan};

/// The tetrahedron used by the hand-written files.
const TETRA: [[f64; 3]; 4] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// Its faces, 0-based, outward.
const TETRA_FACES: [[u32; 3]; 4] = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];

fn tetra_points() -> Vec<DVec3> {
    TETRA.iter().map(|p| DVec3::from_array(*p)).collect()
}

fn parse(text: &str, format: ScanFormat) -> Scan {
    parse_scan(text.as_bytes(), format).unwrap_or_else(|e| panic!("{format}: {e}"))
}

fn error(bytes: &[u8], format: ScanFormat) -> String {
    parse_scan(bytes, format).expect_err("malformed input must be rejected").to_string()
}

#[test]
fn obj_mesh_with_every_index_form() {
    let text = "# tetrahedron\nmtllib x.mtl\no t\nv 0 0 0\nv 1 0 0\r\nv 0 1 0\nv 0 0 1 1.0\n\
                vt 0 0\nvn 0 0 -1\ns off\nf 1 3 2\nf 1/1 2/1 4/1\nf 1//1 4//1 3//1\nf -3/1/1 -2/1/1 -1/1/1\n";
    let scan = parse(text, ScanFormat::Obj);
    assert_eq!(scan.points, tetra_points());
    assert_eq!(scan.triangles, TETRA_FACES);
    assert_eq!(scan.normals, None, "one vn for four v is not a normal per point");
}

#[test]
fn obj_points_with_normals_and_quads() {
    let scan = parse("v 1 2 3\nvn 0 0 1\nv 4 5 6\nvn 0 1 0\n", ScanFormat::Obj);
    assert_eq!(scan.points, [DVec3::new(1.0, 2.0, 3.0), DVec3::new(4.0, 5.0, 6.0)]);
    assert_eq!(scan.normals, Some(vec![DVec3::Z, DVec3::Y]));
    assert!(scan.triangles.is_empty());
    let quad = parse("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", ScanFormat::Obj);
    assert_eq!(quad.triangles, [[0, 1, 2], [0, 2, 3]], "a fan from the first corner");
}

#[test]
fn obj_errors_name_the_line() {
    assert_eq!(
        error(b"v 0 0 0\nv 1 x 0\n", ScanFormat::Obj),
        "OBJ, line 2: coordinate: \"x\" is not a number"
    );
    assert_eq!(
        error(b"v 0 0\n", ScanFormat::Obj),
        "OBJ, line 1: expected 3 coordinates after `v`, found 2"
    );
    assert_eq!(
        error(b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", ScanFormat::Obj),
        "OBJ, line 4: face index 4 is out of range (the file has 3 vertices)"
    );
    assert_eq!(
        error(b"v 0 0 0\nf 0 1 1\n", ScanFormat::Obj),
        "OBJ, line 2: face index 0 (OBJ indices start at 1)"
    );
    assert_eq!(
        error(b"v 0 0 0\nf -1 -2 -1\n", ScanFormat::Obj),
        "OBJ, line 2: a relative face index points before the first vertex"
    );
    assert_eq!(
        error(b"v 0 0 0\nf 1 1\n", ScanFormat::Obj),
        "OBJ, line 2: a face needs at least 3 vertices, found 2"
    );
    assert_eq!(error(b"# nothing\n", ScanFormat::Obj), "OBJ: the file holds no points");
}

#[test]
fn non_finite_points_are_dropped_with_their_faces() {
    let text = "v 0 0 0\nv 1 0 0\nv nan 1 0\nv 0 0 1\nv 0 inf 0\nf 1 2 4\nf 1 3 2\nf 2 5 4\n";
    let scan = parse(text, ScanFormat::Obj);
    assert_eq!(scan.points, [DVec3::ZERO, DVec3::X, DVec3::Z]);
    assert_eq!(scan.triangles, [[0, 1, 2]]);
    assert_eq!((scan.dropped_points, scan.dropped_faces), (2, 2));
    assert_eq!(
        error(b"v nan 0 0\n", ScanFormat::Obj),
        "OBJ: all 1 points have a NaN or infinite coordinate"
    );
}

#[test]
fn off_variants() {
    let off = "OFF\n# a comment\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2 255 0 0\n3 1 2 3\n";
    let scan = parse(off, ScanFormat::Off);
    assert_eq!(scan.points, tetra_points());
    assert_eq!(scan.triangles, TETRA_FACES);
    let same_line = "OFF 4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
    assert_eq!(parse(same_line, ScanFormat::Off).triangles, [[0, 1, 2], [0, 2, 3]]);
    let noff = "CNOFF\n1 0 0\n1 2 3 0 0 1 0.5 0.5 0.5 1\n";
    let scan = parse(noff, ScanFormat::Off);
    assert_eq!(scan.points, [DVec3::new(1.0, 2.0, 3.0)]);
    assert_eq!(scan.normals, Some(vec![DVec3::Z]));
}

#[test]
fn off_errors() {
    assert_eq!(
        error(b"OF\n", ScanFormat::Off),
        "OFF, line 1: expected the keyword OFF, found \"OF\""
    );
    assert_eq!(
        error(b"OFF\n2 0 0\n0 0 0\n", ScanFormat::Off),
        "OFF: the file ends after 1 of 2 vertices"
    );
    assert_eq!(
        error(b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", ScanFormat::Off),
        "OFF, line 6: face index 3 is out of range (the file has 3 vertices)"
    );
    assert_eq!(
        error(b"OFF\n1 0 0\n0 0\n", ScanFormat::Off),
        "OFF, line 3: expected 3 coordinates for a vertex, found 2"
    );
    assert_eq!(error(b"", ScanFormat::Off), "OFF: the file is empty");
    assert_eq!(
        error(b"OFF BINARY\n", ScanFormat::Off),
        "OFF, line 1: binary OFF is not supported; write it as text"
    );
}

/// The tetrahedron as PLY with its header; `body` appended.
fn ply_header(format: &str, face: &str) -> String {
    format!(
        "ply\nformat {format} 1.0\ncomment hand-written\nelement vertex 4\nproperty float x\n\
         property float y\nproperty float z\nelement {face}\nproperty list uchar int vertex_indices\n\
         element extra 1\nproperty double w\nend_header\n"
    )
}

#[test]
fn ply_ascii_and_both_binary_orders_agree() {
    let ascii = ply_header("ascii", "face 4")
        + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n2.5\n";
    let scan = parse(&ascii, ScanFormat::Ply);
    assert_eq!(scan.points, tetra_points());
    assert_eq!(scan.triangles, TETRA_FACES);
    for (name, big) in [("binary_little_endian", false), ("binary_big_endian", true)] {
        let mut bytes = ply_header(name, "face 4").into_bytes();
        let f32b = |v: f32| if big { v.to_be_bytes() } else { v.to_le_bytes() };
        let i32b = |v: i32| if big { v.to_be_bytes() } else { v.to_le_bytes() };
        for p in TETRA {
            for c in p {
                #[expect(clippy::cast_possible_truncation, reason = "0 and 1 are f32")]
                bytes.extend(f32b(c as f32));
            }
        }
        for f in TETRA_FACES {
            bytes.push(3);
            for k in f {
                bytes.extend(i32b(i32::try_from(k).unwrap()));
            }
        }
        bytes.extend(if big { 2.5f64.to_be_bytes() } else { 2.5f64.to_le_bytes() });
        let binary = parse_scan(&bytes, ScanFormat::Ply).unwrap();
        assert_eq!(binary, scan, "{name}");
        // One byte short: the error points at the last value's offset.
        let short = &bytes[..bytes.len() - 1];
        let e = parse_scan(short, ScanFormat::Ply).unwrap_err();
        let hi_scan::Error::Read { location, .. } = &e else { panic!("{name}: {e:?}") };
        assert_eq!(*location, Location::Byte(bytes.len() - 8), "{name}: {e}");
    }
}

#[test]
fn ply_triangle_strips_and_normals() {
    let text = "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\n\
                property double z\nproperty double nx\nproperty double ny\nproperty double nz\n\
                element tristrips 1\nproperty list int int vertex_indices\nend_header\n\
                0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n1 1 0 0 0 1\n2 1 0 0 0 1\n7 0 1 2 3 -1 3 4\n";
    let scan = parse(text, ScanFormat::Ply);
    // Strip 0 1 2 3: (0 1 2), then (2 1 3) with the winding flipped; the strip "3 4" after
    // the restart is too short for a triangle.
    assert_eq!(scan.triangles, [[0, 1, 2], [2, 1, 3]]);
    assert_eq!(scan.normals.as_ref().map(Vec::len), Some(5));
    assert!(scan.normals.unwrap().iter().all(|n| *n == DVec3::Z));
}

#[test]
fn ply_errors() {
    assert_eq!(
        error(b"plx\n", ScanFormat::Ply),
        "PLY, line 1: the file does not start with the line `ply`"
    );
    assert_eq!(
        error(
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n",
            ScanFormat::Ply
        ),
        "PLY, line 3: the `vertex` element lacks x, y or z"
    );
    let head = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n";
    assert_eq!(
        error(format!("{head}end_header\n0 0 zero\n").as_bytes(), ScanFormat::Ply),
        "PLY, line 8: \"zero\" is not a F32 value"
    );
    assert_eq!(
        error(format!("{head}element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n3 0 0 1\n").as_bytes(), ScanFormat::Ply),
        "PLY, line 11: face index 1 is out of range (the file has 1 vertices)"
    );
    assert_eq!(error(head.as_bytes(), ScanFormat::Ply), "PLY: the header has no `end_header` line");
    assert_eq!(
        error(b"ply\nformat binary_middle_endian 1.0\n", ScanFormat::Ply),
        "PLY, line 2: unknown format \"binary_middle_endian\""
    );
}

/// The tetrahedron as binary STL: 80-byte header, count, 50 bytes per facet.
fn tetra_stl_binary(header_start: &[u8]) -> Vec<u8> {
    let mut bytes = vec![0u8; 80];
    bytes[..header_start.len()].copy_from_slice(header_start);
    bytes.extend(4u32.to_le_bytes());
    for f in TETRA_FACES {
        bytes.extend([0u8; 12]); // the facet normal, unused
        for k in f {
            for c in TETRA[k as usize] {
                #[expect(clippy::cast_possible_truncation, reason = "0 and 1 are f32")]
                bytes.extend((c as f32).to_le_bytes());
            }
        }
        bytes.extend([0u8; 2]);
    }
    bytes
}

#[test]
fn stl_binary_and_ascii_weld_corners() {
    // A binary header may begin with "solid": the size decides.
    for header in [b"binary".as_slice(), b"solid looks like ascii"] {
        let scan = parse_scan(&tetra_stl_binary(header), ScanFormat::Stl).unwrap();
        assert_eq!(scan.points.len(), 4, "12 corners weld into 4 points");
        assert_eq!(scan.triangles.len(), 4);
        for (t, f) in scan.triangles.iter().zip(TETRA_FACES) {
            let got: Vec<DVec3> = t.iter().map(|&k| scan.points[k as usize]).collect();
            let want: Vec<DVec3> =
                f.iter().map(|&k| DVec3::from_array(TETRA[k as usize])).collect();
            assert_eq!(got, want);
        }
    }
    let mut ascii = String::from("solid tetra\n");
    for f in TETRA_FACES {
        ascii += "  facet normal 0 0 0\n    outer loop\n";
        for k in f {
            let [x, y, z] = TETRA[k as usize];
            ascii += &format!("      vertex {x} {y} {z}\n");
        }
        ascii += "    endloop\n  endfacet\n";
    }
    ascii += "endsolid tetra\n";
    let a = parse(&ascii, ScanFormat::Stl);
    let b = parse_scan(&tetra_stl_binary(b""), ScanFormat::Stl).unwrap();
    assert_eq!(a, b);
    // Points are numbered in order of first use: 0, 2, 1, 3 of the tetrahedron.
    assert_eq!(a.points, [0, 2, 1, 3].map(|k| DVec3::from_array(TETRA[k])));
}

#[test]
fn stl_errors() {
    assert_eq!(
        error(b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n", ScanFormat::Stl),
        "STL, line 7: a facet has 2 vertices; STL facets are triangles"
    );
    assert_eq!(
        error(b"solid x\nfacet normal 0 0 1\n", ScanFormat::Stl),
        "STL, line 2: the facet begun on line 2 never ends"
    );
    let mut truncated = tetra_stl_binary(b"");
    truncated.pop();
    assert_eq!(
        error(&truncated, ScanFormat::Stl),
        "STL, byte 80: the binary header announces 4 triangles, 284 bytes, but the file has 283"
    );
    assert_eq!(
        error(b"hello", ScanFormat::Stl),
        "STL: 5 bytes is too short for binary STL (84-byte header) and it is not ASCII STL"
    );
}

#[test]
fn xyz_and_pts() {
    let scan = parse("# x y z nx ny nz\n1 2 3 0 0 1\n4,5,6,0,1,0\n\n", ScanFormat::Xyz);
    assert_eq!(scan.points, [DVec3::new(1.0, 2.0, 3.0), DVec3::new(4.0, 5.0, 6.0)]);
    assert_eq!(scan.normals, Some(vec![DVec3::Z, DVec3::Y]));
    assert_eq!(
        error(b"1 2 3\n1 2 3 4 5 6\n", ScanFormat::Xyz),
        "XYZ, line 2: 6 numbers, but line 1 has 3"
    );
    assert_eq!(
        error(b"1 2\n", ScanFormat::Xyz),
        "XYZ, line 1: expected 3 numbers (x y z) or 6 (x y z nx ny nz), found 2"
    );
    let pts = parse("# a3d\nd 0 0 0\ns 0 0 0\ng 1 0 0\np 1 2 3\np -1e-3 2E2 .5\n", ScanFormat::Pts);
    assert_eq!(pts.points, [DVec3::new(1.0, 2.0, 3.0), DVec3::new(-1e-3, 200.0, 0.5)]);
}

#[test]
fn formats_come_from_extensions() {
    assert_eq!(ScanFormat::try_from_path("a/b.PLY".as_ref()).unwrap(), ScanFormat::Ply);
    assert_eq!(ScanFormat::try_from_path("x.GLB".as_ref()).unwrap(), ScanFormat::Glb);
    assert_eq!(ScanFormat::try_from_path("x.gltf".as_ref()).unwrap(), ScanFormat::Gltf);
    // CGAL's points with normals are XYZ lines of six numbers.
    assert_eq!(ScanFormat::try_from_path("oni.PWN".as_ref()).unwrap(), ScanFormat::Xyz);
    let e = ScanFormat::try_from_path("scan.las".as_ref()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "scan.las: unknown scan format \"las\"; expected one of .obj, .ply, .off, .stl, .xyz, .pwn, .pts, .gltf, .glb"
    );
    let e = read_scan("no/such/file.obj".as_ref()).unwrap_err();
    assert!(e.to_string().starts_with("OBJ: cannot read no/such/file.obj:"), "{e}");
}

/// The shared folder of third-party models, where it is (see `hi_testkit`).
fn models() -> Option<PathBuf> {
    hi_testkit::shared_models()
}

#[test]
fn real_models_have_the_counts_their_sources_list() {
    let Some(dir) = models() else { return };
    // (file, points, triangles, normals per point) as listed in the folder's SOURCES.md; the
    // STL count is its unique vertices (4104 stored corners).
    let expected = [
        ("bunny.obj", 35947, 69451, false),
        ("cow.obj", 2903, 5804, false),
        ("teapot.obj", 3644, 6320, false),
        ("spot.obj", 2930, 5856, false),
        ("horse.ply", 48485, 96966, true),
        ("nefertiti.obj", 49971, 99938, false),
        ("dragon.ply", 50002, 100000, true),
        ("duck.obj", 10093, 20182, false),
        ("ducky_points.obj", 18090, 0, true),
        ("cactus.pts", 3318, 0, false),
        ("distcap.pts", 12745, 0, false),
        ("wuson.off", 3205, 3732, false),
        ("spider.stl", 722, 1368, false),
    ];
    for (file, points, triangles, normals) in expected {
        let path = dir.join(file);
        if !path.exists() {
            hi_testkit::skip(&format!("the shared model {file} is absent"));
            continue;
        }
        let scan = read_scan(&path).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(scan.points.len() + scan.dropped_points, points, "{file}: points");
        assert_eq!(scan.triangles.len() + scan.dropped_faces, triangles, "{file}: triangles");
        assert_eq!(scan.normals.is_some(), normals, "{file}: normals");
        assert_eq!(scan.dropped_points, 0, "{file}: finite");
    }
}

#[test]
fn obj_meshes_agree_with_tobj() {
    let Some(dir) = models() else { return };
    for file in ["cow.obj", "spot.obj", "duck.obj", "teapot.obj"] {
        let path = dir.join(file);
        if !path.exists() {
            continue;
        }
        let ours = read_scan(&path).unwrap();
        let options = tobj::LoadOptions { triangulate: true, ..tobj::LoadOptions::default() };
        let (models, _) = tobj::load_obj(&path, &options).expect("tobj reads it");
        let mut triangles = Vec::new();
        let mut max_dev = 0.0f64;
        for m in &models {
            // tobj renumbers each object's vertices; compare the triangles' corner positions.
            let pos = |k: u32| {
                let p = &m.mesh.positions[3 * k as usize..3 * k as usize + 3];
                DVec3::new(p[0].into(), p[1].into(), p[2].into())
            };
            triangles
                .extend(m.mesh.indices.chunks_exact(3).map(|t| [pos(t[0]), pos(t[1]), pos(t[2])]));
        }
        assert_eq!(triangles.len(), ours.triangles.len(), "{file}: triangle count");
        for (theirs, t) in triangles.iter().zip(&ours.triangles) {
            for c in 0..3 {
                let d = (theirs[c] - ours.points[t[c] as usize]).abs().max_element();
                max_dev = max_dev.max(d / ours.points[t[c] as usize].abs().max_element().max(1.0));
            }
        }
        assert!(max_dev < 1e-7, "{file}: corners differ from tobj's by {max_dev:e} (relative)");
    }
}

#[test]
fn a_scan_from_arrays_is_checked_and_cleaned_as_a_file_is() {
    let points = vec![DVec3::ZERO, DVec3::X, DVec3::new(f64::NAN, 0.0, 0.0), DVec3::Y];
    let scan = Scan::from_arrays(points.clone(), &[[0, 1, 3], [0, 2, 3]]).expect("valid");
    // The point with a NaN goes, with the triangle that uses it; the indices follow.
    assert_eq!(scan.points.len(), 3, "{scan:?}");
    assert_eq!((scan.dropped_points, scan.dropped_faces), (1, 1), "{scan:?}");
    assert_eq!(scan.triangles, vec![[0, 1, 2]], "{scan:?}");
    let e = Scan::from_arrays(points, &[[0, 1, 4]]).expect_err("index past the points");
    assert!(e.to_string().contains("triangle 0 uses vertex 4, and there are 4 points"), "{e}");
    assert!(Scan::from_arrays(Vec::new(), &[]).is_err(), "no point");
}
