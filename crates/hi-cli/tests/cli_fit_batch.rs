// SPDX-License-Identifier: MIT
//! End-to-end tests of `hi fit SCAN... --out-dir DIR`: every scan fitted into the folder with
//! one line each in `summary.jsonl`, a bad scan recorded while the others go on (and the exit
//! status saying so), a second run skipping what is done and retrying what failed, `--force`
//! redoing everything, the outputs equal byte for byte to those of `hi fit SCAN -o OUT` (one
//! pipeline), folders and globs as inputs, and two scans of one name refused.

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use std::path::{Path, PathBuf};

use common::{bad, ellipsoid_xyz, ok, run};
use serde_json::Value;

/// A fresh folder under the system's temporary folder, removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new(name: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("hi-cli-batch-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("temp folder");
        Self(dir)
    }

    fn join(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }

    fn text(&self, name: &str) -> String {
        self.join(name).display().to_string()
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Writes the scans of the tests into `dir`: two ellipsoids and one malformed file.
fn scans(dir: &TempDir) -> [String; 3] {
    std::fs::write(dir.join("round.xyz"), ellipsoid_xyz(400, [1.0; 3])).expect("write");
    std::fs::write(dir.join("long.xyz"), ellipsoid_xyz(400, [2.0, 1.0, 1.0])).expect("write");
    std::fs::write(dir.join("broken.xyz"), "0 0 0\n1 0 0\n0 1\n").expect("write");
    [dir.text("round.xyz"), dir.text("long.xyz"), dir.text("broken.xyz")]
}

/// The records of the summary in `out`, by input.
fn records(out: &Path) -> Vec<Value> {
    let text = std::fs::read_to_string(out.join("summary.jsonl")).expect("summary.jsonl");
    text.lines().map(|l| serde_json::from_str(l).expect("each line is JSON")).collect()
}

/// Runs a batch that must fail (some scan did): exit status 2, its counts on stdout, one line
/// on stderr per failure and the count.
fn failing(args: &[&str]) -> (Value, String) {
    let out = run(args);
    let stderr = String::from_utf8(out.stderr).expect("stderr is UTF-8");
    assert_eq!(out.status.code(), Some(2), "hi {args:?}: exit status (stderr: {stderr})");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let stdout = String::from_utf8(out.stdout).expect("stdout is UTF-8");
    (serde_json::from_str(&stdout).expect("the batch's counts on stdout"), stderr)
}

#[test]
fn a_batch_fits_every_scan_records_failures_and_resumes() {
    let dir = TempDir::new("resume");
    let [round, long, broken] = scans(&dir);
    let out = dir.text("out");
    let args = ["fit", &round, &broken, &long, "--out-dir", &out, "--jobs", "2"];
    let (counts, stderr) = failing(&args);
    assert_eq!((counts["fitted"].as_u64(), counts["failed"].as_u64()), (Some(2), Some(1)));
    assert!(stderr.contains("XYZ, line 3: expected 3 numbers"), "{stderr}");
    assert!(stderr.contains("1 scan failed"), "{stderr}");
    let first = records(dir.join("out").as_path());
    assert_eq!(first.len(), 3, "one line per scan");
    for record in &first {
        let input = record["input"].as_str().expect("input");
        let ok = record["status"] == "ok";
        assert_eq!(ok, input != broken, "{record}");
        if ok {
            let output = record["output"].as_str().expect("output");
            assert!(Path::new(output).is_file(), "{output} written");
            assert!(output.ends_with(".glb"), "{output}");
            assert!(record["both_ways"]["scan_to_surface"]["max"].as_f64().is_some(), "{record}");
            assert!(record["seconds"]["total"].as_f64().is_some_and(|t| t >= 0.0), "{record}");
            assert!(record.get("error").is_none(), "{record}");
        } else {
            assert!(record["error"].as_str().is_some_and(|e| e.contains("line 3")), "{record}");
        }
    }
    let modified = |name: &str| {
        std::fs::metadata(dir.join("out").join(name)).and_then(|m| m.modified()).expect("mtime")
    };
    let before = modified("round.glb");
    // Again: the two done are skipped, the broken one is tried again (and fails again).
    let (counts, _) = failing(&args);
    assert_eq!(counts["skipped"].as_u64(), Some(2), "{counts}");
    assert_eq!(counts["fitted"].as_u64(), Some(0), "{counts}");
    assert_eq!(counts["failures"], serde_json::json!([broken]), "{counts}");
    assert_eq!(records(dir.join("out").as_path()).len(), 4, "one more line, for the retried scan");
    assert_eq!(modified("round.glb"), before, "a done scan is not written again");
    // Once the broken scan is left out, the run succeeds with nothing to do.
    let done = ok(&["fit", &round, &long, "--out-dir", &out]);
    assert_eq!((done["fitted"].as_u64(), done["skipped"].as_u64()), (Some(0), Some(2)));
    // --force fits them again; a done scan whose output went missing is fitted again too.
    let forced = ok(&["fit", &round, &long, "--out-dir", &out, "--force"]);
    assert_eq!(forced["fitted"].as_u64(), Some(2), "{forced}");
    std::fs::remove_file(dir.join("out").join("long.glb")).expect("remove");
    let redone = ok(&["fit", &round, &long, "--out-dir", &out]);
    assert_eq!((redone["fitted"].as_u64(), redone["skipped"].as_u64()), (Some(1), Some(1)));
}

#[test]
fn a_batch_writes_what_a_single_fit_writes() {
    let dir = TempDir::new("same");
    let [round, long, _] = scans(&dir);
    let out = dir.text("out");
    ok(&["fit", &round, &long, "--out-dir", &out, "--format", "json"]);
    for (scan, name) in [(&round, "round"), (&long, "long")] {
        let single = dir.text(&format!("{name}-single.json"));
        ok(&["fit", scan, "-o", &single]);
        let batch = std::fs::read(dir.join("out").join(format!("{name}.json"))).expect("batch");
        assert!(batch == std::fs::read(&single).expect("single"), "{name}: same bytes");
    }
    for record in records(dir.join("out").as_path()) {
        assert_eq!(record["status"], "ok", "{record}");
    }
}

#[test]
fn folders_and_globs_name_the_scans() {
    let dir = TempDir::new("globs");
    scans(&dir);
    std::fs::write(dir.join("notes.txt"), "not a scan").expect("write");
    let out = dir.text("out-folder");
    let (counts, _) = failing(&["fit", &dir.0.display().to_string(), "--out-dir", &out]);
    // The folder's three scans (not the notes, not the output folder itself).
    assert_eq!((counts["fitted"].as_u64(), counts["failed"].as_u64()), (Some(2), Some(1)));
    let pattern = dir.text("r*.xyz");
    let out = dir.text("out-glob");
    let counts = ok(&["fit", &pattern, "--out-dir", &out, "--format", "obj"]);
    assert_eq!(counts["fitted"].as_u64(), Some(1), "{counts}");
    assert!(dir.join("out-glob").join("round.obj").is_file(), "round.obj");
    bad(&["fit", &dir.text("q*.xyz"), "--out-dir", &out], "no file matches");
}

#[test]
fn bad_batches_are_refused_at_once() {
    let dir = TempDir::new("bad");
    let [round, ..] = scans(&dir);
    std::fs::create_dir_all(dir.join("other")).expect("folder");
    std::fs::write(dir.join("other").join("round.xyz"), ellipsoid_xyz(100, [1.0; 3])).expect("w");
    let out = dir.text("out");
    let twin = dir.join("other").join("round.xyz").display().to_string();
    bad(&["fit", &round, &twin, "--out-dir", &out], "would both be written to");
    bad(&["fit", &round, &twin, "-o", &dir.text("x.glb")], "-o fits one scan");
    bad(&["fit", &round, "--out-dir", &out, "--param", "sections"], "--param sections");
    bad(&["fit", &round, "--force", "-o", &dir.text("x.glb")], "apply with --out-dir only");
    bad(&["fit", &round, "--jobs", "2", "-o", &dir.text("x.glb")], "apply with --out-dir only");
}
