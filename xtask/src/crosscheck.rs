// SPDX-License-Identifier: MIT
//! `cargo xtask crosscheck`: every model the figures emit read back by other programs, and
//! every peer comparison of the test suites, in one report, `docs/crosscheck.md`, with pass or
//! fail per item.
//!
//! The figures:
//! - every figure is drawn again; each `.glb` was read back by the `gltf` crate as the mesh in
//!   memory while it was drawn, and the committed files must equal what is drawn now;
//! - every `.glb` is loaded (`hi_mesh::export::load`, the `gltf` crate) and written again
//!   as OBJ and as glTF (JSON + `.bin`); both are read back (`tobj`, `gltf`) and must equal the
//!   mesh exactly at f32;
//! - trimesh loads every `.glb`, `.gltf` and `.obj` and must find the same vertices, faces and
//!   coordinate sums;
//! - the Khronos glTF-Validator must report 0 errors and 0 warnings on every `.glb` and `.gltf`;
//! - Blender (headless) imports a sample of them and must find the same vertices and faces.
//!
//! The peers: the test files that compare with METAPOST, scipy, CGAL, `OpenMesh`, `pymeshlab`,
//! trimesh, mpmath and python-flint, and the validator, run with `HI_REQUIRE_PEERS=1` so that a
//! missing peer fails rather than skips.
//!
//! A program that is not installed makes its items fail under `HI_REQUIRE_PEERS=1` and be
//! marked skipped otherwise. The command fails if any item fails.

use std::fmt::Write as _;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result, bail};
use hi_mesh::export;
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::Value;

use crate::figures;

/// How many files Blender imports (it takes about a second each).
const BLENDER_SAMPLE: usize = 6;

/// The test files that compare with peer programs: (what, peers, crate, test file).
const PEER_SUITES: &[(&str, &str, &str, &str)] = &[
    ("Hobby's curves (§2.9)", "METAPOST (`mpost`)", "hi-compare", "hobby"),
    ("trigonometric resampling (§3.3)", "scipy `signal.resample`", "hi-curve", "peer_scipy"),
    (
        "interpolating and periodic B-splines (§2.6)",
        "scipy `CubicSpline` and `splprep`",
        "hi-compare",
        "bspline",
    ),
    (
        "B-spline surface interpolation (§4.4)",
        "scipy tensor-product splines",
        "hi-compare",
        "peer_scipy_bspline",
    ),
    (
        "subdivision surfaces (§4.3)",
        "CGAL, OpenMesh, pymeshlab, trimesh",
        "hi-mesh",
        "subdivision_peers",
    ),
    ("mesh export", "Khronos glTF-Validator", "hi-surface", "export_validator"),
    ("interval arithmetic (§5.6)", "mpmath, python-flint", "hi-interval", "peer_mpmath"),
];

/// The outcome of one item.
#[derive(Clone, Debug)]
enum Outcome {
    Pass(String),
    Fail(String),
    Skipped(String),
}

/// One line of the report.
#[derive(Clone, Debug)]
struct Item {
    what: String,
    tool: String,
    outcome: Outcome,
}

/// Whether missing peers are failures.
fn required() -> bool {
    std::env::var("HI_REQUIRE_PEERS").is_ok_and(|v| v == "1")
}

/// A missing program: a failure when peers are required, a skip otherwise.
fn missing(why: impl Into<String>) -> Outcome {
    let why = why.into();
    if required() { Outcome::Fail(format!("not installed: {why}")) } else { Outcome::Skipped(why) }
}

/// Runs the cross-checks and writes `docs/crosscheck.md`.
///
/// # Errors
///
/// If an item fails (after the report is written), or the report cannot be written.
pub(crate) fn run(root: &Path) -> Result<()> {
    let bar = if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new_spinner();
        bar.set_style(ProgressStyle::with_template("{spinner} {elapsed} {msg}")?);
        bar.enable_steady_tick(std::time::Duration::from_millis(100));
        bar
    } else {
        ProgressBar::hidden()
    };
    let mut items = Vec::new();
    let tmp = std::env::temp_dir().join(format!("harmonic-crosscheck-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).context("a temporary directory")?;
    let result = check_figures(root, &tmp, &bar, &mut items);
    let _ = std::fs::remove_dir_all(&tmp);
    result?;
    for &(what, peers, krate, test) in PEER_SUITES {
        bar.set_message(format!("peers: {test}"));
        items.push(Item {
            what: format!("{what}: `cargo test -p {krate} --test {test}`"),
            tool: peers.to_owned(),
            outcome: peer_suite(root, krate, test),
        });
    }
    bar.finish_and_clear();
    let report = report(&items);
    let path = root.join("docs/crosscheck.md");
    std::fs::write(&path, &report).with_context(|| format!("writing {}", path.display()))?;
    let failed: Vec<&Item> =
        items.iter().filter(|i| matches!(i.outcome, Outcome::Fail(_))).collect();
    let skipped = items.iter().filter(|i| matches!(i.outcome, Outcome::Skipped(_))).count();
    println!(
        "crosscheck: {} items, {} passed, {} failed, {skipped} skipped; report in docs/crosscheck.md",
        items.len(),
        items.len() - failed.len() - skipped,
        failed.len()
    );
    if !failed.is_empty() {
        let names: Vec<&str> = failed.iter().map(|i| i.what.as_str()).collect();
        bail!("crosscheck failed: {}", names.join("; "));
    }
    Ok(())
}

/// The figure items.
fn check_figures(root: &Path, tmp: &Path, bar: &ProgressBar, items: &mut Vec<Item>) -> Result<()> {
    bar.set_message("drawing the figures");
    // The renders are left out: `cargo xtask figures --check` compares them.
    let generated = figures::generate(false, figures::Renders::Skip, None)?;
    let stale = figures::stale_files(&root.join("docs/figures"), &generated)?;
    let outputs = &generated.files;
    let glbs: Vec<&(String, Vec<u8>)> =
        outputs.iter().filter(|(name, _)| name.ends_with(".glb")).collect();
    items.push(Item {
        what: format!(
            "{} figure files drawn; every `.glb` read back as the mesh in memory",
            outputs.len()
        ),
        tool: "`gltf` crate".to_owned(),
        outcome: Outcome::Pass(format!(
            "{} models, positions, normals, UVs, colours and indices bit for bit at f32",
            glbs.len()
        )),
    });
    items.push(Item {
        what: "the committed figures are the ones drawn (the renders: present; `cargo xtask \
               figures --check` compares them)"
            .to_owned(),
        tool: "byte comparison".to_owned(),
        outcome: if stale.is_empty() {
            Outcome::Pass(format!(
                "{} files, {} renders present",
                outputs.len(),
                generated.skipped.len()
            ))
        } else {
            Outcome::Fail(format!("stale: {}", stale.join(", ")))
        },
    });
    // Every model written again as OBJ and glTF, and read back.
    bar.set_message("re-exporting the models as OBJ and glTF");
    let (files, obj_bad, gltf_bad) = re_export(tmp, &glbs)?;
    for (ext, tool, bad, agreement) in [
        (
            "OBJ",
            "`tobj`",
            obj_bad,
            "positions, normals and triangles (up to renumbering) exact at f32; UVs and colours within 1e-6",
        ),
        ("glTF (JSON + .bin)", "`gltf` crate", gltf_bad, "everything exact at f32"),
    ] {
        items.push(Item {
            what: format!("every model written again as {ext} and read back"),
            tool: tool.to_owned(),
            outcome: if bad.is_empty() {
                Outcome::Pass(format!("{} files: {agreement}", glbs.len()))
            } else {
                Outcome::Fail(bad.join("; "))
            },
        });
    }
    check_files(root, bar, &files, glbs.len(), items);
    Ok(())
}

/// Every model of `glbs` written into `tmp` as it is, and again as OBJ and glTF, each read
/// back: the files with their meshes, and the OBJ and glTF files that did not agree.
fn re_export(tmp: &Path, glbs: &[&(String, Vec<u8>)]) -> Result<ReExported> {
    let mut files: Vec<(PathBuf, hi_mesh::TriangleMesh)> = Vec::new();
    let (mut obj_bad, mut gltf_bad) = (Vec::new(), Vec::new());
    for (name, bytes) in glbs {
        let glb = tmp.join(name);
        std::fs::write(&glb, bytes)?;
        let mesh = export::load(&glb).with_context(|| format!("loading {name}"))?;
        let stem = name.trim_end_matches(".glb");
        for (ext, bad) in [("obj", &mut obj_bad), ("gltf", &mut gltf_bad)] {
            let path = tmp.join(format!("{stem}.{ext}"));
            export::save(&mesh, &path)?;
            let back = export::read_back(&mesh, &path)?;
            // Positions and normals exact at f32 in both; OBJ stores t as 1 − t and colours as
            // sRGB, which round trip to within an f32 step.
            let display = if ext == "obj" { 1e-6 } else { 0.0 };
            if !back.agrees_within(0.0, display) {
                bad.push(format!("{stem}.{ext}: {back}"));
            }
            files.push((path, mesh.clone()));
        }
        files.push((glb, mesh));
    }
    Ok((files, obj_bad, gltf_bad))
}

/// The files written by [`re_export`] with their meshes, then the OBJ and the glTF files that
/// did not read back as written.
type ReExported = (Vec<(PathBuf, hi_mesh::TriangleMesh)>, Vec<String>, Vec<String>);

/// The items of the other programs reading the `files` of the `models` re-exported: trimesh,
/// the Khronos glTF-Validator, Blender on a sample.
fn check_files(
    root: &Path,
    bar: &ProgressBar,
    files: &[(PathBuf, hi_mesh::TriangleMesh)],
    models: usize,
    items: &mut Vec<Item>,
) {
    bar.set_message("trimesh");
    items.push(Item {
        what: format!("trimesh loads every `.glb`, `.gltf` and `.obj` ({} files)", files.len()),
        tool: "trimesh".to_owned(),
        outcome: trimesh(root, files),
    });
    bar.set_message("Khronos glTF-Validator");
    let gltfs: Vec<&Path> = files
        .iter()
        .map(|(p, _)| p.as_path())
        .filter(|p| p.extension().is_some_and(|e| e == "glb" || e == "gltf"))
        .collect();
    items.push(Item {
        what: format!("every `.glb` and `.gltf` valid ({} files)", gltfs.len()),
        tool: "Khronos glTF-Validator".to_owned(),
        outcome: validator(&gltfs),
    });
    bar.set_message("Blender");
    let step = (models / (BLENDER_SAMPLE / 2)).max(1);
    let sample: Vec<&(PathBuf, hi_mesh::TriangleMesh)> = files
        .iter()
        .filter(|(p, _)| p.extension().is_some_and(|e| e == "glb" || e == "obj"))
        .enumerate()
        .filter(|(k, _)| (k / 2) % step == 0)
        .map(|(_, f)| f)
        .take(BLENDER_SAMPLE)
        .collect();
    items.push(Item {
        what: format!("a sample of {} models imported headless", sample.len()),
        tool: "Blender".to_owned(),
        outcome: blender(root, &sample),
    });
}

/// trimesh's counts and coordinate sums against the meshes.
fn trimesh(root: &Path, files: &[(PathBuf, hi_mesh::TriangleMesh)]) -> Outcome {
    let script = root.join("xtask/peers/trimesh_load.py");
    let output =
        match Command::new("python3").arg(&script).args(files.iter().map(|(p, _)| p)).output() {
            Ok(o) if o.status.success() => o,
            Ok(o) => {
                return missing(
                    String::from_utf8_lossy(&o.stderr)
                        .lines()
                        .last()
                        .unwrap_or("python3 failed")
                        .to_owned(),
                );
            }
            Err(e) => return missing(format!("python3: {e}")),
        };
    let stdout = String::from_utf8_lossy(&output.stdout);
    let mut bad = Vec::new();
    let mut watertight = 0;
    let lines: Vec<Value> = stdout.lines().filter_map(|l| serde_json::from_str(l).ok()).collect();
    if lines.len() != files.len() {
        return Outcome::Fail(format!("{} answers for {} files", lines.len(), files.len()));
    }
    for (line, (path, mesh)) in lines.iter().zip(files) {
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        if let Some(e) = line["error"].as_str() {
            bad.push(format!("{name}: {e}"));
            continue;
        }
        let sum = mesh.positions().iter().fold([0.0; 3], |s, p| {
            let q = p.as_vec3();
            [s[0] + f64::from(q.x), s[1] + f64::from(q.y), s[2] + f64::from(q.z)]
        });
        // OBJ holds each coordinate as the shortest decimal of its f32, which trimesh reads as
        // f64: within half an f32 step (2⁻²⁴ relative) of the value, so the sums agree to
        // 2⁻²⁴·Σ|x| (the binary formats exactly).
        let magnitude = mesh.positions().iter().fold([0.0; 3], |s, p| {
            let q = p.as_vec3().abs();
            [s[0] + f64::from(q.x), s[1] + f64::from(q.y), s[2] + f64::from(q.z)]
        });
        let found: Vec<f64> = line["sum"]
            .as_array()
            .map(|a| a.iter().filter_map(Value::as_f64).collect())
            .unwrap_or_default();
        let sums_agree = found.len() == 3
            && (0..3).all(|i| (found[i] - sum[i]).abs() <= 6e-8 * magnitude[i] + 1e-12);
        if line["vertices"].as_u64() != Some(mesh.n_vertices() as u64)
            || line["faces"].as_u64() != Some(mesh.n_triangles() as u64)
            || !sums_agree
        {
            bad.push(format!(
                "{name}: trimesh {}/{} vertices/faces, sum {found:?}; ours {}/{}, sum {sum:?}",
                line["vertices"],
                line["faces"],
                mesh.n_vertices(),
                mesh.n_triangles()
            ));
        }
        if line["watertight"].as_bool() == Some(true) {
            watertight += 1;
        }
    }
    if bad.is_empty() {
        Outcome::Pass(format!(
            "same vertices, faces and coordinate sums (to an f32 step) in all {} files; {watertight} watertight",
            files.len()
        ))
    } else {
        Outcome::Fail(bad.join("; "))
    }
}

/// The Khronos validator on `files`.
fn validator(files: &[&Path]) -> Outcome {
    let dir = match figures::glb::validator() {
        Ok(dir) => dir,
        Err(why) => return missing(why),
    };
    let output = match Command::new("node").arg(dir.join("validate.js")).args(files).output() {
        Ok(o) => o,
        Err(e) => return missing(format!("node: {e}")),
    };
    let stdout = String::from_utf8_lossy(&output.stdout);
    let summaries: Vec<&str> = stdout.lines().filter(|l| l.contains(": validator ")).collect();
    let clean = summaries.iter().filter(|l| l.contains(" errors=0 warnings=0 ")).count();
    if output.status.success() && summaries.len() == files.len() && clean == files.len() {
        Outcome::Pass(format!("0 errors and 0 warnings in all {} files", files.len()))
    } else {
        let bad: Vec<&str> =
            summaries.iter().filter(|l| !l.contains(" errors=0 warnings=0 ")).copied().collect();
        Outcome::Fail(format!(
            "{clean} of {} clean; {}{}",
            files.len(),
            bad.join("; "),
            String::from_utf8_lossy(&output.stderr).trim()
        ))
    }
}

/// Blender's import of `sample`.
fn blender(root: &Path, sample: &[&(PathBuf, hi_mesh::TriangleMesh)]) -> Outcome {
    let script = root.join("xtask/peers/blender_import.py");
    let output = match Command::new("blender")
        .args(["--background", "--factory-startup", "--python"])
        .arg(&script)
        .arg("--")
        .args(sample.iter().map(|(p, _)| p))
        .output()
    {
        Ok(o) => o,
        Err(e) => return missing(format!("blender: {e}")),
    };
    let stdout = String::from_utf8_lossy(&output.stdout);
    let mut bad = Vec::new();
    for (path, mesh) in sample {
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let prefix = format!("IMPORT {}: ", path.display());
        let Some(line) = stdout.lines().find(|l| l.starts_with(&prefix)) else {
            bad.push(format!("{name}: no report"));
            continue;
        };
        let want = format!("meshes=1 verts={} faces={}", mesh.n_vertices(), mesh.n_triangles());
        if !line.ends_with(&want) {
            bad.push(format!("{name}: {} (expected {want})", &line[prefix.len()..]));
        }
    }
    if bad.is_empty() && output.status.success() {
        let names: Vec<String> = sample
            .iter()
            .filter_map(|(p, _)| p.file_name().map(|n| n.to_string_lossy().into_owned()))
            .collect();
        Outcome::Pass(format!("same vertices and faces: {}", names.join(", ")))
    } else {
        Outcome::Fail(format!(
            "{}; {}",
            bad.join("; "),
            String::from_utf8_lossy(&output.stderr).lines().last().unwrap_or("")
        ))
    }
}

/// One peer test file, run with peers required.
fn peer_suite(root: &Path, krate: &str, test: &str) -> Outcome {
    let output = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_owned()))
        .current_dir(root)
        .env("HI_REQUIRE_PEERS", "1")
        .args(["test", "-q", "-p", krate, "--test", test])
        .output();
    let output = match output {
        Ok(o) => o,
        Err(e) => return Outcome::Fail(format!("cargo: {e}")),
    };
    let stdout = String::from_utf8_lossy(&output.stdout);
    let summary = stdout
        .lines()
        .find(|l| l.starts_with("test result:"))
        .unwrap_or("no test summary")
        .to_owned();
    if output.status.success() {
        Outcome::Pass(summary.trim_start_matches("test result: ").to_owned())
    } else {
        let stderr = String::from_utf8_lossy(&output.stderr);
        let why = stdout
            .lines()
            .chain(stderr.lines())
            .find(|l| {
                l.contains("panicked") || l.contains("not installed") || l.starts_with("error")
            })
            .unwrap_or("failed");
        Outcome::Fail(format!("{summary}; {why}"))
    }
}

/// The report page.
fn report(items: &[Item]) -> String {
    let mut s = String::from(
        "# Cross-checks\n\n\
         Written by `cargo xtask crosscheck` (see `xtask/src/crosscheck.rs`): every model the figures emit read \
         back by other programs, and every comparison of the test suites with a peer program, run with the peers \
         required. CI runs it on a clean clone.\n\n\
         | # | what | checked with | result | detail |\n|---|---|---|---|---|\n",
    );
    for (k, item) in items.iter().enumerate() {
        let (result, detail) = match &item.outcome {
            Outcome::Pass(d) => ("pass", d.as_str()),
            Outcome::Fail(d) => ("**FAIL**", d.as_str()),
            Outcome::Skipped(d) => ("skipped", d.as_str()),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {result} | {} |",
            k + 1,
            item.what,
            item.tool,
            detail.replace('|', "\\|")
        );
    }
    s
}
