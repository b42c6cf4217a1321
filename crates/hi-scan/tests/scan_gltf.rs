// SPDX-License-Identifier: MIT
//! glTF scans: a binary glTF written byte by byte here (not by our writer), with a node
//! hierarchy of translation, rotation, scale and a mirroring matrix, a primitive without
//! normals, indexed and non-indexed primitives and a strip. The expected world positions are
//! the matrices multiplied out by hand; trimesh reads the same file as a peer.

use std::f64::consts::FRAC_1_SQRT_2;

use glam::DVec3;
use hi_scan::scan::{ScanFormat, parse_scan, read_scan};

/// Mesh A: a triangle, three positions, no normals, no indices.
const A: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
/// Mesh B: a strip of two triangles over four positions, with normals (+z) and indices.
const B: [[f32; 3]; 4] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]];
const B_INDICES: [u16; 4] = [0, 1, 2, 3];

/// The GLB: node 0 translates by (1, 2, 3) and holds node 1, which rotates by 90° about z,
/// scales by 2 and draws mesh A; node 2 mirrors x and shifts by (0, 0, 5) by a matrix and
/// draws mesh B.
fn glb() -> Vec<u8> {
    let mut bin = Vec::new();
    for p in A.iter().chain(&B) {
        for c in p {
            bin.extend(c.to_le_bytes());
        }
    }
    for _ in &B {
        for c in [0.0f32, 0.0, 1.0] {
            bin.extend(c.to_le_bytes());
        }
    }
    for i in B_INDICES {
        bin.extend(i.to_le_bytes());
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let s = FRAC_1_SQRT_2;
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0,2]}}],
"nodes":[{{"translation":[1,2,3],"children":[1]}},
 {{"rotation":[0,0,{s},{s}],"scale":[2,2,2],"mesh":0}},
 {{"matrix":[-1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,5,1],"mesh":1}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}},
 {{"primitives":[{{"attributes":{{"POSITION":1,"NORMAL":2}},"indices":3,"mode":5}}]}}],
"buffers":[{{"byteLength":{len}}}],
"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":36}},{{"buffer":0,"byteOffset":36,"byteLength":48}},
 {{"buffer":0,"byteOffset":84,"byteLength":48}},{{"buffer":0,"byteOffset":132,"byteLength":8}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}},
 {{"bufferView":1,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}},
 {{"bufferView":2,"componentType":5126,"count":4,"type":"VEC3"}},
 {{"bufferView":3,"componentType":5123,"count":4,"type":"SCALAR"}}]}}"#,
        len = bin.len()
    );
    let mut json = json.into_bytes();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    let mut out = Vec::new();
    out.extend(b"glTF");
    out.extend(2u32.to_le_bytes());
    out.extend(u32::try_from(12 + 8 + json.len() + 8 + bin.len()).unwrap().to_le_bytes());
    out.extend(u32::try_from(json.len()).unwrap().to_le_bytes());
    out.extend(b"JSON");
    out.extend(&json);
    out.extend(u32::try_from(bin.len()).unwrap().to_le_bytes());
    out.extend(b"BIN\0");
    out.extend(&bin);
    out
}

/// The world positions, by hand: A by translate ∘ rotate(90° about z) ∘ scale 2, B by the
/// mirror in x then up by 5.
fn expected() -> Vec<DVec3> {
    let a = A.iter().map(|p| {
        let [x, y, z] = p.map(f64::from);
        // Scale by 2, rotate (x, y) → (−y, x), translate.
        DVec3::new(-2.0 * y + 1.0, 2.0 * x + 2.0, 2.0 * z + 3.0)
    });
    let b = B.iter().map(|p| {
        let [x, y, z] = p.map(f64::from);
        DVec3::new(-x, y, z + 5.0)
    });
    a.chain(b).collect()
}

#[test]
fn a_glb_scan_is_placed_in_the_world() {
    let bytes = glb();
    let scan = parse_scan(&bytes, ScanFormat::Glb).unwrap();
    let want = expected();
    assert_eq!(scan.points.len(), want.len());
    for (got, want) in scan.points.iter().zip(&want) {
        assert!(got.distance(*want) < 1e-6, "{got} vs {want}");
    }
    // One triangle of A, two of the strip of B; the mirror reverses B's winding so that its
    // triangles still face the way its normals do.
    assert_eq!(scan.triangles.len(), 3);
    assert_eq!(scan.triangles[0], [0, 1, 2]);
    let p = &scan.points;
    for t in &scan.triangles[1..] {
        let [a, b, c] = t.map(|k| p[k as usize]);
        assert!((b - a).cross(c - a).z > 0.0, "B's triangles face +z after the mirror: {t:?}");
    }
    // Not every primitive has normals: none are given.
    assert!(scan.normals.is_none());
    // The same file as .gltf text with the buffer embedded as a data URI is not this test's
    // concern; a .gltf naming an external buffer cannot be read from its bytes alone.
    let external = br#"{"asset":{"version":"2.0"},"buffers":[{"byteLength":4,"uri":"x.bin"}]}"#;
    let err = parse_scan(external, ScanFormat::Gltf).unwrap_err();
    assert!(err.to_string().contains("another file"), "{err}");
}

#[test]
fn the_mesh_loader_computes_flat_normals() {
    let dir = std::env::temp_dir().join(format!("hi-scan-gltf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("hand.glb");
    std::fs::write(&path, glb()).unwrap();
    // The scan reader from a path too.
    let scan = read_scan(&path).unwrap();
    assert_eq!(scan.points.len(), 7);
    let mesh = hi_mesh::export::load(&path).unwrap();
    // A had no normals: flat, its triangle (rotated into the plane z = 3) faces +z.
    let a: Vec<DVec3> = expected()[..3].to_vec();
    let flat = (a[1] - a[0]).cross(a[2] - a[0]).normalize();
    let tri = mesh.triangles()[0];
    for &k in &tri {
        assert!(mesh.normals()[k as usize].distance(flat) < 1e-6, "flat normal");
        assert!(a.iter().any(|p| p.distance(mesh.positions()[k as usize]) < 1e-6));
    }
    // B's normals, +z, through the mirror's inverse transpose: still +z.
    for t in &mesh.triangles()[1..] {
        for &k in t {
            assert!(mesh.normals()[k as usize].distance(DVec3::Z) < 1e-6);
        }
    }
    // trimesh, as a peer, sees the same points.
    let required = hi_testkit::peers_required();
    let script = "import sys, trimesh\n\
                  s = trimesh.load(sys.argv[1], force='mesh', process=False)\n\
                  print(' '.join('%.6f %.6f %.6f' % tuple(v) for v in s.vertices))";
    match std::process::Command::new("python3").args(["-c", script]).arg(&path).output() {
        Ok(o) if o.status.success() => {
            let numbers: Vec<f64> = String::from_utf8_lossy(&o.stdout)
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            let theirs: Vec<DVec3> =
                numbers.chunks_exact(3).map(|c| DVec3::new(c[0], c[1], c[2])).collect();
            for want in expected() {
                assert!(theirs.iter().any(|p| p.distance(want) < 1e-5), "trimesh lacks {want}");
            }
            for p in &theirs {
                assert!(expected().iter().any(|w| w.distance(*p) < 1e-5), "trimesh has {p} extra");
            }
        }
        other => {
            let why = match other {
                Ok(o) => String::from_utf8_lossy(&o.stderr).lines().last().unwrap_or("").to_owned(),
                Err(e) => e.to_string(),
            };
            assert!(!required, "HI_REQUIRE_PEERS=1 but python3 with trimesh is not usable: {why}");
            eprintln!("trimesh check skipped: python3 with trimesh is not usable ({why})");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn malformed_glbs_are_named() {
    let good = glb();
    for (bytes, what) in [
        (b"glTF".to_vec(), "cut short"),
        (
            [b"glTF".to_vec(), 1u32.to_le_bytes().to_vec(), 20u32.to_le_bytes().to_vec()].concat(),
            "glTF 2",
        ),
        (
            [b"glTF".to_vec(), 2u32.to_le_bytes().to_vec(), 5u32.to_le_bytes().to_vec()].concat(),
            "length",
        ),
        (good[..good.len() - 10].to_vec(), "length"),
    ] {
        let err = parse_scan(&bytes, ScanFormat::Glb).unwrap_err();
        assert!(err.to_string().starts_with("GLB: ") && err.to_string().contains(what), "{err}");
    }
}

#[test]
fn a_stride_shorter_than_its_element_is_named() {
    // Found by fuzzing (docs/reliability.md): positions of 12 bytes in a buffer view of
    // byteStride 5. The `gltf` crate's reader asserts on it; the readers refuse it first.
    let data = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
        "buffers":[{{"byteLength":36,"uri":"data:application/octet-stream;base64,{data}"}}],
        "bufferViews":[{{"buffer":0,"byteStride":5,"byteLength":36}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":2,"type":"VEC3",
        "min":[0,0,0],"max":[1,1,1]}}]}}"#
    );
    let err = parse_scan(json.as_bytes(), ScanFormat::Gltf).unwrap_err().to_string();
    assert!(err.contains("POSITION accessor's buffer view has a byte stride of 5"), "{err}");
    assert!(err.contains("12 bytes"), "{err}");
    // With the stride of its element the same file reads.
    let fixed = json.replace(r#""byteStride":5"#, r#""byteStride":12"#);
    assert_eq!(parse_scan(fixed.as_bytes(), ScanFormat::Gltf).unwrap().points.len(), 2);
}
