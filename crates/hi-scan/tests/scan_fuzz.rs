// SPDX-License-Identifier: MIT
//! No reader panics, whatever the bytes: random bytes, and valid files of every format with
//! random bytes changed, inserted or cut off. (The `fuzz/` folder holds the same targets for
//! coverage-guided fuzzing with `cargo fuzz`.)

use hi_scan::scan::{ScanFormat, parse_scan};
use hi_testkit::proptest_config;
use proptest::prelude::*;

/// A small valid file of each format.
fn seed(format: ScanFormat) -> Vec<u8> {
    match format {
        ScanFormat::Obj => {
            b"v 0 0 0\nvn 0 0 1\nv 1 0 0\nvn 0 0 1\nv 0 1 0\nvn 0 0 1\nf 1/1/1 2//2 -1\n".to_vec()
        }
        ScanFormat::Ply => {
            let mut b =
                b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n\
                          property float y\nproperty float z\nelement face 1\n\
                          property list uchar uint vertex_indices\nelement tristrips 1\n\
                          property list int int vertex_indices\nend_header\n"
                    .to_vec();
            for v in [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
                b.extend(v.to_le_bytes());
            }
            b.push(3);
            for k in [0u32, 1, 2] {
                b.extend(k.to_le_bytes());
            }
            for k in [4i32, 0, 1, 2, -1] {
                b.extend(k.to_le_bytes());
            }
            b
        }
        ScanFormat::Off => {
            b"NOFF\n3 1 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n".to_vec()
        }
        ScanFormat::Stl => {
            let mut b = vec![0u8; 80];
            b.extend(1u32.to_le_bytes());
            b.extend([0u8; 12]);
            for v in [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
                b.extend(v.to_le_bytes());
            }
            b.extend([0u8; 2]);
            b
        }
        ScanFormat::Xyz => b"0 0 0 0 0 1\n1,0,0,0,0,1\n".to_vec(),
        ScanFormat::Pts => b"# x\np 0 0 0\np 1 0 0\n".to_vec(),
        ScanFormat::Gltf => format!(
            r#"{{"asset":{{"version":"2.0"}},"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}}}}]}}],
"nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}],
"buffers":[{{"byteLength":36,"uri":"data:application/octet-stream;base64,{TRIANGLE_BASE64}"}}],
"bufferViews":[{{"buffer":0,"byteLength":36}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}}]}}"#
        )
        .into_bytes(),
        ScanFormat::Glb => {
            let mut json = br#"{"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"buffers":[{"byteLength":36}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]}"#
                .to_vec();
            while !json.len().is_multiple_of(4) {
                json.push(b' ');
            }
            let length = |n: usize| u32::try_from(n).expect("a small file").to_le_bytes();
            let mut b = b"glTF".to_vec();
            b.extend(2u32.to_le_bytes());
            b.extend(length(12 + 8 + json.len() + 8 + 36));
            b.extend(length(json.len()));
            b.extend(b"JSON");
            b.extend(&json);
            b.extend(length(36));
            b.extend(b"BIN\0");
            for v in [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
                b.extend(v.to_le_bytes());
            }
            b
        }
    }
}

/// The positions (0, 0, 0), (1, 0, 0), (0, 1, 0) as little-endian `f32`, in base64.
const TRIANGLE_BASE64: &str = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

/// An edit of a file: replace, insert or remove a byte, or cut the file.
#[derive(Clone, Debug)]
enum Edit {
    Set(usize, u8),
    Insert(usize, u8),
    Remove(usize),
    Cut(usize),
}

fn edit() -> impl Strategy<Value = Edit> {
    // Bytes that matter to the parsers are more likely than others.
    let byte = prop_oneof![
        any::<u8>(),
        prop::sample::select(b"0123456789-+.eE \n\r\t/#pvfn,{}[]\":\xff\x00".to_vec()),
    ];
    prop_oneof![
        (any::<usize>(), byte.clone()).prop_map(|(i, b)| Edit::Set(i, b)),
        (any::<usize>(), byte).prop_map(|(i, b)| Edit::Insert(i, b)),
        any::<usize>().prop_map(Edit::Remove),
        any::<usize>().prop_map(Edit::Cut),
    ]
}

fn apply(bytes: &mut Vec<u8>, edit: &Edit) {
    let n = bytes.len();
    match *edit {
        Edit::Set(i, b) if n > 0 => bytes[i % n] = b,
        Edit::Insert(i, b) => bytes.insert(i % (n + 1), b),
        Edit::Remove(i) if n > 0 => {
            bytes.remove(i % n);
        }
        Edit::Cut(i) => bytes.truncate(i % (n + 1)),
        _ => {}
    }
}

proptest! {
    #![proptest_config(proptest_config(2000))]

    /// Random bytes: an error or a scan, never a panic.
    #[test]
    fn random_bytes(bytes in prop::collection::vec(any::<u8>(), 0..400), f in 0usize..ScanFormat::ALL.len()) {
        let format = ScanFormat::ALL[f];
        if let Ok(scan) = parse_scan(&bytes, format) {
            prop_assert!(scan.points.iter().all(|p| p.is_finite()));
        }
    }

    /// Valid files with a few edits: an error or a consistent scan, never a panic.
    #[test]
    fn edited_files(f in 0usize..ScanFormat::ALL.len(), edits in prop::collection::vec(edit(), 1..6)) {
        let format = ScanFormat::ALL[f];
        let mut bytes = seed(format);
        for e in &edits {
            apply(&mut bytes, e);
        }
        if let Ok(scan) = parse_scan(&bytes, format) {
            let n = scan.points.len();
            prop_assert!(scan.points.iter().all(|p| p.is_finite()));
            prop_assert!(scan.triangles.iter().flatten().all(|&k| (k as usize) < n));
            if let Some(normals) = &scan.normals {
                prop_assert_eq!(normals.len(), n);
            }
        }
    }
}

#[test]
fn the_seeds_are_valid() {
    for format in ScanFormat::ALL {
        let scan = parse_scan(&seed(format), format).unwrap_or_else(|e| panic!("{format}: {e}"));
        assert!(scan.points.len() >= 2, "{format}");
    }
}
