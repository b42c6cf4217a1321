// SPDX-License-Identifier: MIT
//! Helpers shared by the end-to-end tests of the `hi` binary in `cli_compare.rs` and
//! `cli_surface.rs`: temporary files, running `hi`, and reading its JSON.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};

use serde_json::Value;

/// A temporary path under the system temp directory (with this extension), removed on drop
/// together with the files `hi` writes beside it (a `.gltf`'s `.bin`).
pub(crate) struct TempFile(PathBuf);

impl TempFile {
    /// A fresh path with extension `ext` and no file yet.
    pub(crate) fn path_with(ext: &str) -> Self {
        static COUNTER: AtomicUsize = AtomicUsize::new(0);
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        Self(std::env::temp_dir().join(format!("hi-cli-test2-{}-{n}.{ext}", std::process::id())))
    }

    /// A JSON file holding `contents`.
    pub(crate) fn new(contents: &str) -> Self {
        let file = Self::path_with("json");
        std::fs::write(&file.0, contents).expect("temp file is writable");
        file
    }

    /// The path as a string.
    pub(crate) fn path(&self) -> &str {
        self.0.to_str().expect("temp paths are UTF-8 in these tests")
    }

    /// The path.
    pub(crate) fn as_path(&self) -> &Path {
        &self.0
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
        let _ = std::fs::remove_file(self.0.with_extension("bin"));
    }
}

/// Runs `hi` with `args`.
pub(crate) fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hi"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .output()
        .expect("the hi binary runs")
}

/// Runs a command that must succeed and parses its one line of JSON.
pub(crate) fn ok(args: &[&str]) -> Value {
    let out = run(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "hi {args:?} failed ({:?}): {stderr}", out.status);
    assert!(stderr.is_empty(), "hi {args:?} wrote to stderr: {stderr}");
    let text = String::from_utf8(out.stdout).expect("stdout is UTF-8");
    assert!(text.ends_with('\n') && text.lines().count() == 1, "one line of JSON: {text}");
    serde_json::from_str(&text).expect("stdout is JSON")
}

/// [`ok`] with `--input FILE` added, the file holding `input`.
pub(crate) fn ok_on(input: &str, args: &[&str]) -> Value {
    let file = TempFile::new(input);
    let mut all = args.to_vec();
    all.extend(["--input", file.path()]);
    ok(&all)
}

/// Asserts a bad-input failure: exit status 2, nothing on stdout, exactly one line on stderr
/// that starts with `hi: ` and contains `expected`, and no trace of a panic.
pub(crate) fn bad(args: &[&str], expected: &str) {
    let out = run(args);
    let stderr = String::from_utf8(out.stderr).expect("stderr is UTF-8");
    assert_eq!(out.status.code(), Some(2), "hi {args:?}: exit status (stderr: {stderr})");
    assert!(out.stdout.is_empty(), "hi {args:?}: nothing on stdout");
    assert!(
        stderr.ends_with('\n') && stderr.matches('\n').count() == 1,
        "hi {args:?}: one line: {stderr:?}"
    );
    assert!(stderr.starts_with("hi: "), "hi {args:?}: prefix: {stderr}");
    assert!(stderr.contains(expected), "hi {args:?}: {stderr:?} should contain {expected:?}");
    for word in ["panicked", "backtrace", "RUST_BACKTRACE", "internal error"] {
        assert!(!stderr.contains(word), "hi {args:?}: {stderr}");
    }
}

/// [`bad`] with `--input FILE` added, the file holding `input`.
pub(crate) fn bad_on(input: &str, args: &[&str], expected: &str) {
    let file = TempFile::new(input);
    let mut all = args.to_vec();
    all.extend(["--input", file.path()]);
    bad(&all, expected);
}

/// A JSON number.
pub(crate) fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// An array of numbers.
pub(crate) fn nums(v: &Value) -> Vec<f64> {
    v.as_array().expect("an array").iter().map(num).collect()
}

/// An array of points, each as its coordinates.
pub(crate) fn points(v: &Value) -> Vec<Vec<f64>> {
    v.as_array().expect("an array of points").iter().map(nums).collect()
}

/// The Euclidean distance of two points given as coordinates.
pub(crate) fn dist(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len(), "same dimension");
    a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum::<f64>().sqrt()
}

/// Points as the JSON array `[[x, y], ...]`.
pub(crate) fn json_points(pts: &[Vec<f64>]) -> String {
    serde_json::to_string(pts).expect("points serialise")
}

/// A binary glTF of one triangle mesh with positions and `u32` indices and no normals, placed
/// by a node that scales by `scale` and then translates by `translation`: written byte by
/// byte here, not by the library's writer.
pub(crate) fn glb_without_normals(
    positions: &[[f32; 3]],
    triangles: &[[u32; 3]],
    scale: f32,
    translation: [f32; 3],
) -> Vec<u8> {
    let mut bin = Vec::new();
    for c in positions.iter().flatten() {
        bin.extend(c.to_le_bytes());
    }
    let index_offset = bin.len();
    for k in triangles.iter().flatten() {
        bin.extend(k.to_le_bytes());
    }
    let (mut min, mut max) = ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
    for p in positions {
        for i in 0..3 {
            min[i] = min[i].min(p[i]);
            max[i] = max[i].max(p[i]);
        }
    }
    let [tx, ty, tz] = translation;
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],
"nodes":[{{"translation":[{tx},{ty},{tz}],"scale":[{scale},{scale},{scale}],"mesh":0}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1}}]}}],
"buffers":[{{"byteLength":{len}}}],
"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":{index_offset}}},
 {{"buffer":0,"byteOffset":{index_offset},"byteLength":{index_len}}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":{count},"type":"VEC3","min":{min:?},"max":{max:?}}},
 {{"bufferView":1,"componentType":5125,"count":{indices},"type":"SCALAR"}}]}}"#,
        len = bin.len(),
        index_len = bin.len() - index_offset,
        count = positions.len(),
        indices = 3 * triangles.len(),
    );
    let mut json = json.into_bytes();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    let length = |n: usize| u32::try_from(n).expect("a small file").to_le_bytes();
    let mut out = b"glTF".to_vec();
    out.extend(2u32.to_le_bytes());
    out.extend(length(12 + 8 + json.len() + 8 + bin.len()));
    out.extend(length(json.len()));
    out.extend(b"JSON");
    out.extend(&json);
    out.extend(length(bin.len()));
    out.extend(b"BIN\0");
    out.extend(&bin);
    out
}

/// A closed, outward latitude–longitude mesh of the ellipsoid with semi-axes `axes`: `rings`
/// rings of `segments` points between two poles.
pub(crate) fn ellipsoid_mesh(
    rings: usize,
    segments: usize,
    axes: [f32; 3],
) -> (Vec<[f32; 3]>, Vec<[u32; 3]>) {
    let index = |k: usize| u32::try_from(k).expect("a small mesh");
    let mut positions = vec![[0.0, 0.0, axes[2]]];
    for i in 1..=rings {
        let theta = std::f32::consts::PI * i as f32 / (rings + 1) as f32;
        for j in 0..segments {
            let phi = std::f32::consts::TAU * j as f32 / segments as f32;
            positions.push([
                axes[0] * theta.sin() * phi.cos(),
                axes[1] * theta.sin() * phi.sin(),
                axes[2] * theta.cos(),
            ]);
        }
    }
    positions.push([0.0, 0.0, -axes[2]]);
    let south = positions.len() - 1;
    let at = |i: usize, j: usize| 1 + (i - 1) * segments + j % segments;
    let mut triangles = Vec::new();
    for j in 0..segments {
        triangles.push([0, index(at(1, j)), index(at(1, j + 1))]);
        triangles.push([index(south), index(at(rings, j + 1)), index(at(rings, j))]);
    }
    for i in 1..rings {
        for j in 0..segments {
            let [a, b, c, d] = [at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)];
            triangles.push([index(a), index(c), index(d)]);
            triangles.push([index(a), index(d), index(b)]);
        }
    }
    (positions, triangles)
}

/// `n` points on the ellipsoid with semi-axes `axes` (a Fibonacci lattice), as XYZ text.
pub(crate) fn ellipsoid_xyz(n: usize, axes: [f64; 3]) -> String {
    hi_testkit::fibonacci_sphere(n)
        .map(|[x, y, z]| format!("{} {} {}\n", axes[0] * x, axes[1] * y, axes[2] * z))
        .collect()
}
