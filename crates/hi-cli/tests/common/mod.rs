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
