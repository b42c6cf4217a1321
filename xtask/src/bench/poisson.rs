// SPDX-License-Identifier: MIT
//! `cargo xtask bench fit`, part two: `hi fit` against screened Poisson reconstruction as a user
//! meets them, whole commands from reading the scan to writing the mesh, on the shared models.
//!
//! For each model the scan's points (for a mesh, the points its triangles use) go to both:
//! - ours: `hi fit MODEL -o ours.glb --report r.json`, with its defaults;
//! - Poisson: `python3 xtask/peers/fit_peers.py poisson points.xyz poisson.ply 8`
//!   (pymeshlab, depth 8, normals from 10 neighbours), interpreter start and import included,
//!   as a user running it would wait for them.
//!
//! Both are timed as processes (median of five after a warm-up), and both outputs are measured
//! by the same independent program, trimesh (`fit_peers.py distances`): 5 000 scan points to the
//! output, 5 000 points sampled on the output to the scan (its triangles, or its nearest point
//! for a point set), and whether the output is watertight as stored. Our own report adds the
//! measurement over every point and the part of the surface that bridges holes in the scan.
//!
//! The targets of the comparison, checked per model: mean scan→surface no larger than
//! Poisson's, largest at most 1.5× Poisson's, surface→scan within 2 % of the diagonal (on the
//! part of our surface that covers the scan; holes the scan leaves open are bridged and said
//! so), watertight output, and the whole command at least 5× faster.
//!
//! It also renders each model three ways (the scan, Poisson's surface, ours) into
//! `docs/fit-vs-poisson.png`, shown under the table in `docs/performance.md`.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use glam::{DVec2, DVec3};
use hi_mesh::TriangleMesh;
use hi_raytrace::{Camera, Geometry, Light, MeshObject, RenderOptions, Scene, SceneObject, render};
use hi_scan::scan::read_scan;
use indicatif::ProgressBar;

use super::{Headline, median, table};

/// The models, in the order of the issue that asked for the comparison: (name, file, the eye
/// direction and up vector that show the model from the front).
const MODELS: &[(&str, &str, [f64; 3], [f64; 3])] = &[
    ("bunny", "bunny.obj", [0.3, 0.25, 1.0], [0.0, 1.0, 0.0]),
    ("spot", "spot.obj", [-1.0, 0.35, 0.6], [0.0, 1.0, 0.0]),
    ("cow", "cow.obj", [0.5, 0.4, 1.0], [0.0, 1.0, 0.0]),
    ("duck", "duck.obj", [0.7, 0.4, 1.0], [0.0, 1.0, 0.0]),
    ("horse", "horse.ply", [1.0, 0.3, 0.4], [0.0, 1.0, 0.0]),
    ("nefertiti", "nefertiti.obj", [0.2, -1.0, 0.2], [0.0, 0.0, 1.0]),
    ("wuson", "wuson.off", [0.3, 0.3, 1.0], [0.0, 1.0, 0.0]),
    ("ducky_points", "ducky_points.obj", [0.7, 0.4, 1.0], [0.0, 1.0, 0.0]),
    ("cactus", "cactus.pts", [1.0, -0.4, 0.3], [0.0, 0.0, 1.0]),
];

/// Timed runs of each command, after one untimed run.
const RUNS: usize = 5;

/// Points each way in trimesh's measurement.
const SAMPLES: &str = "5000";

/// Poisson's octree depth.
const DEPTH: &str = "8";

/// The size of one panel of the figure.
const PANEL: (u32, u32) = (300, 240);

/// Where a model is: committed in `fixtures/models`, else in the shared data folder.
fn locate(root: &Path, file: &str) -> Option<PathBuf> {
    [root.join("fixtures/models").join(file), root.join("../shared/data/models").join(file)]
        .into_iter()
        .find(|p| p.exists())
}

/// trimesh's measurement of one output.
#[derive(Clone, Copy, Debug, Default)]
struct Measured {
    mean: f64,
    max: f64,
    back_max: f64,
    watertight: bool,
}

fn measured(v: &serde_json::Value) -> Measured {
    let f = |a: &str, b: &str| v[a][b].as_f64().unwrap_or(f64::NAN);
    Measured {
        mean: f("scan_to_surface", "mean"),
        max: f("scan_to_surface", "max"),
        back_max: f("surface_to_scan", "max"),
        watertight: v["watertight"].as_bool().unwrap_or(false),
    }
}

/// One model's row.
struct Row {
    name: String,
    points: usize,
    ours: Duration,
    poisson: Duration,
    ours_m: Measured,
    poisson_m: Measured,
    report: serde_json::Value,
}

/// Runs `program args` `RUNS + 1` times; the median time of the last `RUNS`, and the last run's
/// stdout.
fn timed(program: &Path, args: &[&str]) -> Result<(Duration, Vec<u8>)> {
    let mut times = Vec::new();
    let mut stdout = Vec::new();
    for run in 0..=RUNS {
        let start = Instant::now();
        let out = Command::new(program)
            .args(args)
            .output()
            .with_context(|| format!("running {}", program.display()))?;
        let t = start.elapsed();
        if out.status.code() == Some(3) {
            bail!("the peer is not installed");
        }
        if !out.status.success() {
            bail!(
                "{} {args:?}: {}",
                program.display(),
                String::from_utf8_lossy(&out.stderr).trim()
            );
        }
        if run > 0 {
            times.push(t);
        }
        stdout = out.stdout;
    }
    Ok((median(times), stdout))
}

fn path_str(p: &Path) -> Result<&str> {
    p.to_str().context("a non-UTF-8 path")
}

/// The comparison: the section's Markdown, its headlines, and whether pymeshlab was there.
pub(super) fn versus_poisson(root: &Path, bar: &ProgressBar) -> Result<(String, Vec<Headline>)> {
    let dir = root.join("target/xtask-bench/poisson");
    std::fs::create_dir_all(&dir)?;
    bar.set_message("building hi");
    let status = Command::new("cargo")
        .args(["build", "--quiet", "--release", "-p", "hi-cli"])
        .current_dir(root)
        .status()
        .context("building hi")?;
    if !status.success() {
        bail!("cargo build -p hi-cli failed");
    }
    let hi = root.join("target/release/hi");
    let python = PathBuf::from("python3");
    let script = root.join("xtask/peers/fit_peers.py");
    let mut rows = Vec::new();
    let mut missing = Vec::new();
    let mut panels = Vec::new();
    for &(name, file, eye, up) in MODELS {
        let Some(path) = locate(root, file) else {
            missing.push(file);
            continue;
        };
        bar.set_message(format!("versus Poisson: {name}"));
        let scan = read_scan(&path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        // The points both are given: for a mesh, those its triangles use.
        let mut used = vec![scan.triangles.is_empty(); scan.points.len()];
        for t in &scan.triangles {
            for &k in t {
                used[k as usize] = true;
            }
        }
        let points: Vec<DVec3> =
            scan.points.iter().zip(&used).filter(|(_, u)| **u).map(|(p, _)| *p).collect();
        let xyz = dir.join(format!("{name}.xyz"));
        let mut w = std::io::BufWriter::new(std::fs::File::create(&xyz)?);
        for p in &points {
            writeln!(w, "{} {} {}", p.x, p.y, p.z)?;
        }
        w.flush()?;
        drop(w);
        let ours_glb = dir.join(format!("{name}-ours.glb"));
        let report = dir.join(format!("{name}-report.json"));
        let (ours, _) = timed(
            &hi,
            &["fit", path_str(&path)?, "-o", path_str(&ours_glb)?, "--report", path_str(&report)?],
        )?;
        let report: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&report)?)?;
        let poisson_ply = dir.join(format!("{name}-poisson.ply"));
        let script_s = path_str(&script)?.to_owned();
        let poisson = match timed(
            &python,
            &[&script_s, "poisson", path_str(&xyz)?, path_str(&poisson_ply)?, DEPTH],
        ) {
            Ok((t, _)) => t,
            Err(e) if e.to_string().contains("not installed") => {
                bail!("pymeshlab is not installed: `pip install pymeshlab trimesh rtree scipy`")
            }
            Err(e) => return Err(e),
        };
        let scan_arg =
            if scan.triangles.is_empty() { "-".to_owned() } else { path_str(&path)?.to_owned() };
        let measure = |out: &Path| -> Result<Measured> {
            let o = Command::new(&python)
                .args([
                    &script_s,
                    "distances",
                    path_str(&xyz)?,
                    &scan_arg,
                    path_str(out)?,
                    SAMPLES,
                    "1",
                ])
                .output()?;
            if o.status.code() == Some(3) {
                bail!("trimesh is not installed: `pip install trimesh rtree scipy`");
            }
            if !o.status.success() {
                bail!(
                    "trimesh on {}: {}",
                    out.display(),
                    String::from_utf8_lossy(&o.stderr).trim()
                );
            }
            Ok(measured(&serde_json::from_slice(&o.stdout)?))
        };
        let (ours_m, poisson_m) = (measure(&ours_glb)?, measure(&poisson_ply)?);
        bar.set_message(format!("versus Poisson: rendering {name}"));
        panels.push(render_row(&scan, &poisson_ply, &ours_glb, DVec3::from(eye), DVec3::from(up))?);
        rows.push(Row {
            name: name.to_owned(),
            points: points.len(),
            ours,
            poisson,
            ours_m,
            poisson_m,
            report,
        });
        bar.inc(1);
    }
    let mut s = String::new();
    let _ = write!(
        s,
        "\n### Against screened Poisson, whole commands\n\n\
         `hi fit MODEL -o ours.glb` with its defaults against screened Poisson (pymeshlab, depth \
         {DEPTH}, normals from 10 neighbours) on the same points, both timed as whole processes \
         from reading the scan to writing the mesh (median of {RUNS} after a warm-up; Poisson's \
         includes starting Python and importing pymeshlab, as a user waits for them). Distances \
         as percentages of the bounding-box diagonal, measured for both outputs by trimesh \
         ({SAMPLES} scan points to the surface, {SAMPLES} surface samples to the scan); \"all\" \
         is our own measurement over every scan point, and \"scan part\" our surface→scan \
         maximum over the part of the surface that covers the scan (without the patches that \
         bridge holes the scan leaves open, whose farthest point is given as \"bridged\"). \
         Targets: mean ≤ Poisson's, max ≤ 1.5 × Poisson's, surface→scan ≤ 2 %, watertight, ≥ 5× \
         faster.\n\n"
    );
    let pct = |x: f64| format!("{:.3}", 100.0 * x);
    let mut table_rows = Vec::new();
    let mut headlines = Vec::new();
    let mut misses = Vec::new();
    for r in &rows {
        let rel = |key: &str, i: usize| {
            r.report["both_ways"][key]["relative"][i].as_f64().unwrap_or(f64::NAN)
        };
        let bridged = r.report["both_ways"]["filled_to_scan_max_relative"].as_f64().unwrap_or(0.0);
        let speed = r.poisson.as_secs_f64() / r.ours.as_secs_f64().max(1e-9);
        let checks = [
            (
                "mean",
                r.ours_m.mean <= r.poisson_m.mean,
                format!("mean {:.2}× Poisson's", r.ours_m.mean / r.poisson_m.mean),
            ),
            (
                "max",
                r.ours_m.max <= 1.5 * r.poisson_m.max,
                format!("max {:.2}× Poisson's", r.ours_m.max / r.poisson_m.max),
            ),
            (
                "surface→scan",
                rel("surface_to_scan", 2) <= 0.02,
                format!("surface→scan {} %", pct(rel("surface_to_scan", 2))),
            ),
            ("watertight", r.ours_m.watertight, "not watertight".to_owned()),
            ("speed", speed >= 5.0, format!("{speed:.1}× faster")),
        ];
        let failed: Vec<String> = checks.iter().filter(|c| !c.1).map(|c| c.2.clone()).collect();
        if !failed.is_empty() {
            misses.push(format!("{}: {}", r.name, failed.join(", ")));
        }
        table_rows.push(vec![
            r.name.clone(),
            r.points.to_string(),
            r.report["method"].as_str().unwrap_or("?").to_owned(),
            format!("{:.3} / {:.3}", r.ours.as_secs_f64(), r.poisson.as_secs_f64()),
            format!("{speed:.1}×"),
            format!(
                "{} / {} (all {})",
                pct(r.ours_m.mean),
                pct(r.poisson_m.mean),
                pct(rel("scan_to_surface", 0))
            ),
            format!(
                "{} / {} (all {})",
                pct(r.ours_m.max),
                pct(r.poisson_m.max),
                pct(rel("scan_to_surface", 2))
            ),
            format!(
                "{} / {} (scan part {}{})",
                pct(r.ours_m.back_max),
                pct(r.poisson_m.back_max),
                pct(rel("surface_to_scan", 2)),
                if bridged > 0.0 { format!(", bridged {}", pct(bridged)) } else { String::new() }
            ),
            format!("{} / {}", yes(r.ours_m.watertight), yes(r.poisson_m.watertight)),
            if failed.is_empty() { "all met".to_owned() } else { failed.join("; ") },
        ]);
        headlines.push(Headline {
            what: format!("`hi fit` on {}, whole command", r.name),
            ours: r.ours,
            peer: "screened Poisson (pymeshlab), whole command".to_owned(),
            theirs: Some(r.poisson),
        });
    }
    s.push_str(&table(
        &[
            "model",
            "points",
            "our method",
            "time (s): ours / Poisson",
            "speed-up",
            "scan→surface mean (%): ours / Poisson",
            "scan→surface max (%): ours / Poisson",
            "surface→scan max (%): ours / Poisson",
            "watertight: ours / Poisson",
            "targets",
        ],
        &table_rows,
    ));
    if !missing.is_empty() {
        let _ = write!(s, "\nNot found here, so not measured: {}.\n", missing.join(", "));
    }
    if misses.is_empty() {
        s.push_str("\nEvery target is met on every model measured.\n");
    } else {
        let _ = write!(s, "\nTargets missed: {}.\n", misses.join("; "));
    }
    // The figure beside the other plots of the report.
    if !panels.is_empty() {
        let figure = compose(&panels)?;
        std::fs::write(root.join("docs/fit-vs-poisson.png"), figure)?;
        s.push_str(
            "\nEach row: the scan (points drawn as small beads when it has no faces), screened \
             Poisson's surface, and ours, from the same viewpoint.\n\n\
             ![each model as scan, Poisson, ours](fit-vs-poisson.png)\n",
        );
    }
    Ok((s, headlines))
}

fn yes(b: bool) -> &'static str {
    if b { "yes" } else { "no" }
}

/// A mesh as the renderer takes it: flat-shaded normals computed here when it needs them.
fn mesh_of(positions: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Result<TriangleMesh> {
    // Un-indexed: one normal per triangle, as glTF's flat shading would draw it.
    let mut p = Vec::with_capacity(3 * triangles.len());
    let mut n = Vec::with_capacity(3 * triangles.len());
    let mut t = Vec::with_capacity(triangles.len());
    for tri in &triangles {
        let [a, b, c] = tri.map(|k| positions[k as usize]);
        let normal = (b - a).cross(c - a).try_normalize().unwrap_or(DVec3::Z);
        let base = u32::try_from(p.len())?;
        p.extend([a, b, c]);
        n.extend([normal; 3]);
        t.push([base, base + 1, base + 2]);
    }
    let uv = vec![DVec2::ZERO; p.len()];
    Ok(TriangleMesh::try_new(p, n, uv, t)?)
}

/// Small octahedra at the points, for drawing a point set.
fn beads(points: &[DVec3], size: f64) -> Result<TriangleMesh> {
    let dirs = [DVec3::X, DVec3::Y, DVec3::Z, DVec3::NEG_X, DVec3::NEG_Y, DVec3::NEG_Z];
    let faces =
        [[0, 1, 2], [1, 3, 2], [3, 4, 2], [4, 0, 2], [1, 0, 5], [3, 1, 5], [4, 3, 5], [0, 4, 5]];
    let mut p = Vec::with_capacity(6 * points.len());
    let mut t = Vec::with_capacity(8 * points.len());
    for (k, c) in points.iter().enumerate() {
        let base = u32::try_from(6 * k)?;
        p.extend(dirs.iter().map(|d| *c + *d * size));
        t.extend(faces.iter().map(|f| f.map(|i: u32| base + i)));
    }
    mesh_of(p, t)
}

/// The three panels of one model, as RGB images.
fn render_row(
    scan: &hi_scan::scan::Scan,
    poisson: &Path,
    ours: &Path,
    eye: DVec3,
    up: DVec3,
) -> Result<Vec<image::RgbImage>> {
    let (lo, hi) = scan
        .points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let diagonal = (hi - lo).length();
    let scan_mesh = if scan.triangles.is_empty() {
        beads(&scan.points, 0.0025 * diagonal)?
    } else {
        mesh_of(scan.points.clone(), scan.triangles.clone())?
    };
    let read = |path: &Path| -> Result<TriangleMesh> {
        let s = read_scan(path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        mesh_of(s.points, s.triangles)
    };
    let camera = Camera::framing(0.5 * (lo + hi), 0.5 * diagonal, eye, up, 0.55)?;
    let side = eye.cross(up).try_normalize().unwrap_or(DVec3::X);
    let lights = vec![
        Light::Directional { direction: eye + up * 1.2 + side * 0.6, intensity: [0.85; 3] },
        Light::Directional { direction: eye - side, intensity: [0.3; 3] },
    ];
    let settings = RenderOptions {
        width: PANEL.0,
        height: PANEL.1,
        samples_per_pixel: 4,
        tile_size: 16,
        first_pass: 0,
    };
    [scan_mesh, read(poisson)?, read(ours)?]
        .into_iter()
        .map(|mesh| {
            let mut object = SceneObject::new(Geometry::Mesh(MeshObject::new(mesh)));
            object.material.color = [0.72, 0.74, 0.78];
            let scene = Scene::try_new(vec![object], lights.clone(), [1.0; 3])?;
            let out = render(&scene, &camera, &settings, None)?;
            let png = out.png_bytes()?;
            Ok(image::load_from_memory(&png)?.to_rgb8())
        })
        .collect()
}

/// The panels laid out one model per row.
fn compose(rows: &[Vec<image::RgbImage>]) -> Result<Vec<u8>> {
    let (w, h) = PANEL;
    let mut out = image::RgbImage::from_pixel(
        3 * w,
        h * u32::try_from(rows.len())?,
        image::Rgb([255, 255, 255]),
    );
    for (i, row) in rows.iter().enumerate() {
        for (j, panel) in row.iter().enumerate() {
            image::imageops::overlay(
                &mut out,
                panel,
                i64::from(u32::try_from(j)? * w),
                i64::from(u32::try_from(i)? * h),
            );
        }
    }
    let mut bytes = Vec::new();
    out.write_to(&mut std::io::Cursor::new(&mut bytes), image::ImageFormat::Png)?;
    Ok(bytes)
}
