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
pub(super) const MODELS: &[(&str, &str, [f64; 3], [f64; 3])] = &[
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
pub(super) const DEPTH: &str = "8";

/// The size of one panel of the figure.
const PANEL: (u32, u32) = (300, 240);

/// Where a model is: committed in `fixtures/models`, else in the shared data folder.
pub(super) fn locate(root: &Path, file: &str) -> Option<PathBuf> {
    [root.join("fixtures/models").join(file), root.join("../shared/data/models").join(file)]
        .into_iter()
        .find(|p| p.exists())
}

/// trimesh's measurement of one output.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Measured {
    /// Scan → surface, mean, relative to the diagonal.
    pub(super) mean: f64,
    /// Scan → surface, largest.
    pub(super) max: f64,
    /// Surface → scan, 99th percentile.
    pub(super) back_p99: f64,
    /// Surface → scan, largest.
    pub(super) back_max: f64,
    /// Every edge shared by two faces, as stored.
    pub(super) watertight: bool,
    /// Connected parts, after welding coincident vertices.
    pub(super) bodies: Option<u64>,
    /// Euler characteristic V − E + F, after welding.
    pub(super) euler: Option<i64>,
}

fn measured(v: &serde_json::Value) -> Measured {
    let f = |a: &str, b: &str| v[a][b].as_f64().unwrap_or(f64::NAN);
    Measured {
        mean: f("scan_to_surface", "mean"),
        max: f("scan_to_surface", "max"),
        back_p99: f("surface_to_scan", "p99"),
        back_max: f("surface_to_scan", "max"),
        watertight: v["watertight"].as_bool().unwrap_or(false),
        bodies: v["bodies"].as_u64(),
        euler: v["euler_number"].as_i64(),
    }
}

/// trimesh's measurement of the reconstruction `out` (`fit_peers.py distances`): [`SAMPLES`]
/// points of `points` (an XYZ file) to `out`, as many samples of `out` to `scan` (a mesh file,
/// or `-` for the points themselves).
///
/// # Errors
///
/// When trimesh is not installed or fails on the files.
pub(super) fn measure(root: &Path, points: &Path, scan: &str, out: &Path) -> Result<Measured> {
    let script = root.join("xtask/peers/fit_peers.py");
    let o = Command::new("python3")
        .arg(&script)
        .args(["distances", path_str(points)?, scan, path_str(out)?, SAMPLES, "1"])
        .output()?;
    if o.status.code() == Some(3) {
        bail!("trimesh is not installed: `pip install trimesh rtree scipy`");
    }
    if !o.status.success() {
        bail!("trimesh on {}: {}", out.display(), String::from_utf8_lossy(&o.stderr).trim());
    }
    Ok(measured(&serde_json::from_slice(&o.stdout)?))
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

pub(super) fn path_str(p: &Path) -> Result<&str> {
    p.to_str().context("a non-UTF-8 path")
}

/// Builds `hi` in the release profile and returns its path.
///
/// # Errors
///
/// When cargo fails.
pub(super) fn build_hi(root: &Path) -> Result<PathBuf> {
    let status = Command::new("cargo")
        .args(["build", "--quiet", "--release", "-p", "hi-cli"])
        .current_dir(root)
        .status()
        .context("building hi")?;
    if !status.success() {
        bail!("cargo build -p hi-cli failed");
    }
    Ok(root.join("target/release/hi"))
}

/// The comparison: the section's Markdown, its headlines, and whether pymeshlab was there.
pub(super) fn versus_poisson(root: &Path, bar: &ProgressBar) -> Result<(String, Vec<Headline>)> {
    let dir = root.join("target/xtask-bench/poisson");
    std::fs::create_dir_all(&dir)?;
    bar.set_message("building hi");
    let hi = build_hi(root)?;
    let mut rows = Vec::new();
    let mut missing = Vec::new();
    let mut panels = Vec::new();
    for &(name, file, eye, up) in MODELS {
        let Some(path) = locate(root, file) else {
            missing.push(file);
            continue;
        };
        let (row, drawn) = versus_model(root, &dir, &hi, name, &path, (eye, up), bar)?;
        panels.push(drawn);
        rows.push(row);
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
    let mut table_rows = Vec::new();
    let mut headlines = Vec::new();
    let mut misses = Vec::new();
    for r in &rows {
        let (cells, failed) = poisson_row(r);
        if !failed.is_empty() {
            misses.push(format!("{}: {}", r.name, failed.join(", ")));
        }
        table_rows.push(cells);
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
        let figure = compose(&panels, PANEL, 1)?;
        std::fs::write(root.join("docs/fit-vs-poisson.png"), figure)?;
        s.push_str(
            "\nEach row: the scan (points drawn as small beads when it has no faces), screened \
             Poisson's surface, and ours, from the same viewpoint.\n\n\
             ![each model as scan, Poisson, ours](fit-vs-poisson.png)\n",
        );
    }
    Ok((s, headlines))
}

/// Both programs on the model `name` read from `path` (writing into `dir`), measured by
/// trimesh and drawn from `(eye, up)`: its row and its panels.
fn versus_model(
    root: &Path,
    dir: &Path,
    hi: &Path,
    name: &str,
    path: &Path,
    (eye, up): ([f64; 3], [f64; 3]),
    bar: &ProgressBar,
) -> Result<(Row, Vec<image::RgbImage>)> {
    let python = PathBuf::from("python3");
    let script = root.join("xtask/peers/fit_peers.py");
    bar.set_message(format!("versus Poisson: {name}"));
    let scan = read_scan(path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
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
        hi,
        &["fit", path_str(path)?, "-o", path_str(&ours_glb)?, "--report", path_str(&report)?],
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
        if scan.triangles.is_empty() { "-".to_owned() } else { path_str(path)?.to_owned() };
    let (ours_m, poisson_m) =
        (measure(root, &xyz, &scan_arg, &ours_glb)?, measure(root, &xyz, &scan_arg, &poisson_ply)?);
    bar.set_message(format!("versus Poisson: rendering {name}"));
    let view = View { eye: DVec3::from(eye), up: DVec3::from(up), panel: PANEL };
    let panels = render_panels(
        &scan_display(&scan, usize::MAX),
        &[Some(poisson_ply.as_path()), Some(ours_glb.as_path())],
        view,
    )?;
    let row = Row {
        name: name.to_owned(),
        points: points.len(),
        ours,
        poisson,
        ours_m,
        poisson_m,
        report,
    };
    Ok((row, panels))
}

/// The table's cells of one model, and the targets it missed.
fn poisson_row(r: &Row) -> (Vec<String>, Vec<String>) {
    let pct = |x: f64| format!("{:.3}", 100.0 * x);
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
    let cells = vec![
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
    ];
    (cells, failed)
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

/// What a panel draws of the input: its triangles, or for a point set the points as beads.
pub(super) struct Display {
    /// The points (for a point set, at most the number asked for, spread over the set).
    pub(super) points: Vec<DVec3>,
    /// The triangles; none for a point set.
    pub(super) triangles: Vec<[u32; 3]>,
    /// The corners of the bounding box of the whole input.
    pub(super) bounds: (DVec3, DVec3),
}

/// The display of `scan`: its mesh, or at most `beads` of its points (every k-th).
pub(super) fn scan_display(scan: &hi_scan::scan::Scan, beads: usize) -> Display {
    let bounds = scan
        .points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    if !scan.triangles.is_empty() {
        return Display { points: scan.points.clone(), triangles: scan.triangles.clone(), bounds };
    }
    let step = scan.points.len().div_ceil(beads.max(1)).max(1);
    Display {
        points: scan.points.iter().step_by(step).copied().collect(),
        triangles: Vec::new(),
        bounds,
    }
}

/// Where the camera looks from and the size of a panel.
#[derive(Clone, Copy, Debug)]
pub(super) struct View {
    /// The direction of the eye from the model's centre.
    pub(super) eye: DVec3,
    /// The up vector.
    pub(super) up: DVec3,
    /// Width and height of the panel.
    pub(super) panel: (u32, u32),
}

/// The panel of a reconstruction that is missing (it failed): pale red with a cross.
pub(super) fn missing_panel(panel: (u32, u32)) -> image::RgbImage {
    let (w, h) = panel;
    let mut img = image::RgbImage::from_pixel(w, h, image::Rgb([250, 232, 232]));
    let (cx, cy, r) = (f64::from(w) / 2.0, f64::from(h) / 2.0, f64::from(w.min(h)) / 6.0);
    for y in 0..h {
        for x in 0..w {
            let (dx, dy) = (f64::from(x) - cx, f64::from(y) - cy);
            if dx.abs() <= r && dy.abs() <= r && (dx.abs() - dy.abs()).abs() < 2.0 {
                img.put_pixel(x, y, image::Rgb([200, 60, 60]));
            }
        }
    }
    img
}

/// The panels of one input: the input itself, then each output (every triangle primitive of
/// the file, all parts of a multi-part scene, as [`read_scan`] reads a glTF scene), or a
/// [`missing_panel`] for `None`, as RGB images.
pub(super) fn render_panels(
    input: &Display,
    outputs: &[Option<&Path>],
    view: View,
) -> Result<Vec<image::RgbImage>> {
    let View { eye, up, panel } = view;
    let (lo, hi) = input.bounds;
    let diagonal = (hi - lo).length();
    let scan_mesh = if input.triangles.is_empty() {
        beads(&input.points, 0.0025 * diagonal)?
    } else {
        mesh_of(input.points.clone(), input.triangles.clone())?
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
        width: panel.0,
        height: panel.1,
        samples_per_pixel: 4,
        tile_size: 16,
        first_pass: 0,
    };
    let draw = |mesh: TriangleMesh| -> Result<image::RgbImage> {
        let mut object = SceneObject::new(Geometry::Mesh(MeshObject::new(mesh)));
        object.material.color = [0.72, 0.74, 0.78];
        let scene = Scene::try_new(vec![object], lights.clone(), [1.0; 3])?;
        let out = render(&scene, &camera, &settings, None)?;
        let png = out.png_bytes()?;
        Ok(image::load_from_memory(&png)?.to_rgb8())
    };
    let mut panels = vec![draw(scan_mesh)?];
    for out in outputs {
        panels.push(match out {
            Some(path) => draw(read(path)?)?,
            None => missing_panel(panel),
        });
    }
    Ok(panels)
}

/// The panels laid out `per_line` inputs to a line of the figure, each input's panels side by
/// side (as many as the first input has), in reading order, as a PNG.
pub(super) fn compose(
    rows: &[Vec<image::RgbImage>],
    panel: (u32, u32),
    per_line: usize,
) -> Result<Vec<u8>> {
    // Between two inputs on a line: a gap with a grey rule down its middle.
    const GAP: u32 = 16;
    let (w, h) = panel;
    let per_line = per_line.max(1);
    let each = u32::try_from(rows.first().map_or(1, Vec::len))? * w + GAP;
    let lines = u32::try_from(rows.len().div_ceil(per_line))?;
    let width = each * u32::try_from(per_line)? - GAP;
    let mut out = image::RgbImage::from_pixel(width, h * lines, image::Rgb([255, 255, 255]));
    for slot in 1..u32::try_from(per_line)? {
        let x = slot * each - GAP / 2;
        for y in 0..h * lines {
            out.put_pixel(x, y, image::Rgb([200, 200, 200]));
        }
    }
    for (i, row) in rows.iter().enumerate() {
        let (line, slot) = (u32::try_from(i / per_line)?, u32::try_from(i % per_line)?);
        for (j, panel) in row.iter().enumerate() {
            let x = slot * each + u32::try_from(j)? * w;
            image::imageops::overlay(&mut out, panel, i64::from(x), i64::from(line * h));
        }
    }
    let mut bytes = Vec::new();
    out.write_to(&mut std::io::Cursor::new(&mut bytes), image::ImageFormat::Png)?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_of_the_table_against_poisson_is_formatted_cell_by_cell() {
        let measured = |mean, max, back_max, watertight| Measured {
            mean,
            max,
            back_max,
            watertight,
            ..Measured::default()
        };
        let r = Row {
            name: "bunny".to_owned(),
            points: 35_947,
            ours: Duration::from_secs(1),
            poisson: Duration::from_secs(3),
            ours_m: measured(1e-4, 1e-3, 2e-3, true),
            poisson_m: measured(2e-4, 5e-4, 1e-3, false),
            report: serde_json::json!({
                "method": "radial",
                "both_ways": {
                    "scan_to_surface": {"relative": [1.2e-4, 0.0, 1.5e-3]},
                    "surface_to_scan": {"relative": [0.0, 0.0, 0.005]},
                    "filled_to_scan_max_relative": 0.001,
                },
            }),
        };
        let (cells, failed) = poisson_row(&r);
        assert_eq!(failed, ["max 2.00× Poisson's", "3.0× faster"]);
        assert_eq!(
            cells,
            [
                "bunny",
                "35947",
                "radial",
                "1.000 / 3.000",
                "3.0×",
                "0.010 / 0.020 (all 0.012)",
                "0.100 / 0.050 (all 0.150)",
                "0.200 / 0.100 (scan part 0.500, bridged 0.100)",
                "yes / no",
                "max 2.00× Poisson's; 3.0× faster",
            ]
        );
    }

    /// A GLB of three triangles in two meshes: mesh 0 with two primitives (the unit triangle in
    /// z = 0, and the same lifted to z = 1), placed as it is; mesh 1 (the unit triangle) placed
    /// by a node translated by 10 along x.
    fn two_part_glb() -> Vec<u8> {
        let json = r#"{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],
            "nodes":[{"mesh":0},{"mesh":1,"translation":[10,0,0]}],
            "meshes":[{"primitives":[{"attributes":{"POSITION":0}},{"attributes":{"POSITION":1}}]},
                      {"primitives":[{"attributes":{"POSITION":0}}]}],
            "accessors":[
              {"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
              {"bufferView":1,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,1],"max":[1,1,1]}],
            "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},
                           {"buffer":0,"byteOffset":36,"byteLength":36}],
            "buffers":[{"byteLength":72}]}"#;
        let mut json = json.as_bytes().to_vec();
        while !json.len().is_multiple_of(4) {
            json.push(b' ');
        }
        let corners: [[f32; 3]; 6] = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 1.0],
            [0.0, 1.0, 1.0],
        ];
        let bin: Vec<u8> = corners.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        let word = |x: usize| u32::try_from(x).expect("small").to_le_bytes();
        let mut glb = b"glTF".to_vec();
        glb.extend(2u32.to_le_bytes());
        glb.extend(word(12 + 8 + json.len() + 8 + bin.len()));
        glb.extend(word(json.len()));
        glb.extend(b"JSON");
        glb.extend(&json);
        glb.extend(word(bin.len()));
        glb.extend(b"BIN\0");
        glb.extend(&bin);
        glb
    }

    #[test]
    fn a_multi_part_glb_is_read_and_drawn_whole() {
        let dir = std::env::temp_dir().join(format!("xtask-glb-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        let path = dir.join("parts.glb");
        std::fs::write(&path, two_part_glb()).expect("written");
        // Every primitive of every mesh the scene places, with the node's transform.
        let scan = read_scan(&path).expect("read");
        assert_eq!(scan.triangles.len(), 3, "{scan:?}");
        assert!(scan.points.iter().any(|p| (*p - DVec3::new(11.0, 0.0, 0.0)).length() < 1e-6));
        assert!(scan.points.iter().any(|p| (*p - DVec3::new(1.0, 0.0, 1.0)).length() < 1e-6));
        // Drawn: both parts show, one in each half of the panel (the camera looks down z at
        // the box from x = 0 to 11).
        let input = Display {
            points: scan.points.clone(),
            triangles: scan.triangles.clone(),
            bounds: (DVec3::ZERO, DVec3::new(11.0, 1.0, 1.0)),
        };
        let view = View { eye: DVec3::Z, up: DVec3::Y, panel: (120, 80) };
        let panels = render_panels(&input, &[Some(path.as_path()), None], view).expect("drawn");
        assert_eq!(panels.len(), 3, "the input, the output, the missing one");
        let inked = |img: &image::RgbImage, xs: std::ops::Range<u32>| {
            img.enumerate_pixels().any(|(x, _, p)| xs.contains(&x) && p.0 != [255, 255, 255])
        };
        assert!(inked(&panels[1], 0..60) && inked(&panels[1], 60..120), "both parts drawn");
        assert_eq!(panels[2].get_pixel(0, 0).0, [250, 232, 232], "a failed side is marked");
        std::fs::remove_dir_all(&dir).expect("removed");
    }

    #[test]
    fn panels_are_laid_out_inputs_to_a_line_with_a_rule_between() {
        let red = image::RgbImage::from_pixel(4, 3, image::Rgb([255, 0, 0]));
        let rows = vec![vec![red.clone(), red.clone()]; 3];
        let png = compose(&rows, (4, 3), 2).expect("composed");
        let img = image::load_from_memory(&png).expect("a PNG").to_rgb8();
        // Two inputs of two panels a line, 16 pixels between them; two lines.
        assert_eq!(img.dimensions(), (2 * 8 + 16, 6));
        assert_eq!(img.get_pixel(0, 0).0, [255, 0, 0]);
        assert_eq!(img.get_pixel(8 + 8, 0).0, [200, 200, 200], "the rule");
        assert_eq!(img.get_pixel(24, 0).0, [255, 0, 0], "the second input");
        assert_eq!(img.get_pixel(24, 4).0, [255, 255, 255], "the last line has one input");
        // One input a line: as the comparison's figure has always been.
        let png = compose(&rows, (4, 3), 1).expect("composed");
        let img = image::load_from_memory(&png).expect("a PNG").to_rgb8();
        assert_eq!(img.dimensions(), (8, 9));
    }
}
