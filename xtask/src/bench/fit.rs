// SPDX-License-Identifier: MIT
//! `cargo xtask bench fit`: the fitting pipeline of §5.3–§5.8 timed stage by stage (Table 5.1
//! regenerated on this machine), 4× upsampling against `scipy.signal.resample`, and the same
//! scans reconstructed by screened Poisson (pymeshlab), all in one run.
//!
//! Scans: two built in (points on an ellipsoid and on a bumpy star-shaped solid) and the real
//! models of `shared/data/models` when they are there (the section says which were used).
//! Peers run through `xtask/peers/fit_peers.py`.

use std::f64::consts::PI;
use std::fmt::Write as _;
use std::io::{IsTerminal, Write as _};
use std::path::Path;
use std::process::Command;
use std::time::Duration;

use anyhow::{Context, Result, bail};
use glam::DVec3;
use hi_geomimage::distance::{bounding_diagonal, distances_to_mesh};
use hi_geomimage::scan::{Scan, read_scan};
use hi_geomimage::{FitOptions, Layout, fit};
use hi_surface::HarmonicSurface;
use indicatif::{ProgressBar, ProgressStyle};

use super::{machine, median_time, ms, ratio, table};

/// Timed runs of our upsampling (after a warm-up).
const RUNS: usize = 5;

/// The geometry image of the pipeline: rows × columns.
const IMAGE: usize = 256;

/// Depth of the screened Poisson octree.
const POISSON_DEPTH: usize = 8;

/// The real models used when present, relative to the workspace root.
const REAL: &[&str] = &[
    "../shared/data/models/bunny.obj",
    "../shared/data/models/spot.obj",
    "../shared/data/models/cow.obj",
    "../shared/data/models/duck.obj",
];

/// `n` points spread over the surface r(d) = radius(d) in direction d (a Fibonacci lattice).
fn star_points(n: usize, radius: impl Fn(DVec3) -> DVec3) -> Vec<DVec3> {
    let golden = PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|k| {
            let z = 1.0 - (2 * k + 1) as f64 / n as f64;
            let s = (1.0 - z * z).sqrt();
            let phi = k as f64 * golden;
            radius(DVec3::new(s * phi.cos(), s * phi.sin(), z))
        })
        .collect()
}

/// The scans: (name, source, scan).
fn scans(root: &Path) -> Vec<(String, String, Result<Scan>)> {
    let mut out = vec![
        (
            "ellipsoid".to_owned(),
            "built in: 100 000 points, semi-axes 1.5, 1, 0.7".to_owned(),
            Ok(Scan {
                points: star_points(100_000, |d| d * DVec3::new(1.5, 1.0, 0.7)),
                ..Scan::default()
            }),
        ),
        (
            "bumpy".to_owned(),
            "built in: 200 000 points on r = 1 + 0.15 sin 5θ cos 3φ".to_owned(),
            Ok(Scan {
                points: star_points(200_000, |d| {
                    let (theta, phi) = (d.z.acos(), d.y.atan2(d.x));
                    d * (1.0 + 0.15 * (5.0 * theta).sin() * (3.0 * phi).cos())
                }),
                ..Scan::default()
            }),
        ),
    ];
    for rel in REAL {
        let path = root.join(rel);
        let name = path.file_stem().map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        if path.exists() {
            let scan = read_scan(&path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()));
            let source = format!("`shared/data/models/{name}.obj`");
            out.push((name, source, scan));
        }
    }
    out
}

/// Writes `points` as an ASCII PLY point cloud.
fn write_ply(points: &[DVec3], path: &Path) -> Result<()> {
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(
        w,
        "ply\nformat ascii 1.0\nelement vertex {}\nproperty double x\nproperty double y\nproperty double z\nend_header",
        points.len()
    )?;
    for p in points {
        writeln!(w, "{} {} {}", p.x, p.y, p.z)?;
    }
    w.flush()?;
    Ok(())
}

/// Runs the peer script; `Ok(None)` when the peer is not installed.
fn peer(root: &Path, args: &[&str]) -> Result<Option<serde_json::Value>> {
    let script = root.join("xtask/peers/fit_peers.py");
    let out = match Command::new("python3").arg(&script).args(args).output() {
        Ok(out) => out,
        Err(_) => return Ok(None),
    };
    if out.status.code() == Some(3) {
        return Ok(None);
    }
    if !out.status.success() {
        bail!("{} {args:?}: {}", script.display(), String::from_utf8_lossy(&out.stderr).trim());
    }
    Ok(Some(serde_json::from_slice(&out.stdout).context("the peer's JSON")?))
}

/// Seconds from a peer's JSON.
fn seconds(v: &serde_json::Value, key: &str) -> Duration {
    Duration::from_secs_f64(v[key].as_f64().unwrap_or(f64::NAN).max(0.0))
}

/// The relative distances [mean, RMS, max] from `points` to a triangle mesh, over `diagonal`.
fn relative(
    points: &[DVec3],
    vertices: &[DVec3],
    triangles: &[[u32; 3]],
    diagonal: f64,
) -> Result<[f64; 3]> {
    let d = distances_to_mesh(points, vertices, triangles)?;
    Ok([d.mean / diagonal, d.rms / diagonal, d.max / diagonal])
}

/// "1.2e-3 / 2.0e-3 / 9.9e-3".
fn errors(e: [f64; 3]) -> String {
    format!("{:.1e} / {:.1e} / {:.1e}", e[0], e[1], e[2])
}

/// Measures everything and returns the report's section.
pub(super) fn run(root: &Path) -> Result<String> {
    let dir = root.join("target/xtask-bench/fit");
    std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    let scans = scans(root);
    let bar = if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(2 * scans.len() as u64 + 2);
        bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}")?);
        bar
    } else {
        ProgressBar::hidden()
    };
    let options = FitOptions {
        layout: Layout::FlatOctahedron,
        rows: IMAGE,
        cols: IMAGE,
        ..FitOptions::default()
    };
    let mut pipeline = Vec::new();
    let mut poisson = Vec::new();
    let mut sources = Vec::new();
    for (name, source, scan) in &scans {
        sources.push(format!("{name}: {source}"));
        let scan = match scan {
            Ok(s) => s,
            Err(e) => {
                pipeline.push(vec![name.clone(), format!("unreadable: {e}")]);
                continue;
            }
        };
        bar.set_message(format!("fit {name}"));
        let fitted = fit(scan, &options, &mut |_| {})?;
        let r = &fitted.report;
        let stage = |want: &str| {
            r.stages.iter().filter(|s| s.name.contains(want)).map(|s| s.seconds).sum::<f64>()
        };
        let total: f64 = r.stages.iter().map(|s| s.seconds).sum();
        // The fit a user waits for: every stage but the measurement of its error.
        let without_error = total - stage("fit error");
        let ours = r.errors.as_ref().map(|d| d.relative());
        let stages: Vec<String> =
            r.stages.iter().map(|s| format!("{} {:.3}", s.name, s.seconds)).collect();
        pipeline.push(vec![
            name.clone(),
            r.points.to_string(),
            format!("{:.3}", stage("geometry image")),
            format!("{:.3}", stage("rasterisation")),
            format!("{without_error:.3}"),
            format!("{total:.3}"),
            stages.join("; "),
            ours.map_or_else(|| "–".to_owned(), errors),
            format!("{:.1}%", 100.0 * r.non_star_fraction),
        ]);
        bar.inc(1);
        bar.set_message(format!("screened Poisson {name}"));
        let (input, output) =
            (dir.join(format!("{name}.ply")), dir.join(format!("{name}-poisson.ply")));
        write_ply(&scan.points, &input)?;
        let depth = POISSON_DEPTH.to_string();
        let args = ["poisson", &path_str(&input)?, &path_str(&output)?, depth.as_str()];
        let row = match peer(root, &args)? {
            None => vec![
                name.clone(),
                "pymeshlab not installed".to_owned(),
                "–".to_owned(),
                "–".to_owned(),
                "–".to_owned(),
            ],
            Some(v) => {
                let mesh =
                    read_scan(&output).map_err(|e| anyhow::anyhow!("{}: {e}", output.display()))?;
                let diagonal = bounding_diagonal(&scan.points);
                let theirs = relative(&scan.points, &mesh.points, &mesh.triangles, diagonal)?;
                vec![
                    name.clone(),
                    format!("{without_error:.3}"),
                    format!(
                        "{:.3}",
                        (seconds(&v, "seconds") + seconds(&v, "normals_seconds")).as_secs_f64()
                    ),
                    ours.map_or_else(|| "–".to_owned(), errors),
                    errors(theirs),
                ]
            }
        };
        poisson.push(row);
        bar.inc(1);
    }
    let mut upsampling = Vec::new();
    for size in [256usize, 257] {
        bar.set_message(format!("4× upsampling {size}²"));
        let grid: Vec<DVec3> = (0..size * size)
            .map(|i| {
                let x = i as f64;
                DVec3::new((0.37 * x).sin(), (0.11 * x).cos(), (0.05 * x).sin() * 0.5)
            })
            .collect();
        let surface = HarmonicSurface::try_from_flat(size, size, grid)?;
        let one = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
        let single = one.install(|| {
            median_time(RUNS, || {
                std::hint::black_box(surface.sample_uniform(4 * size, 4 * size, 0, 0)?);
                Ok(())
            })
        })?;
        let all = median_time(RUNS, || {
            std::hint::black_box(surface.sample_uniform(4 * size, 4 * size, 0, 0)?);
            Ok(())
        })?;
        let n = size.to_string();
        let scipy = peer(root, &["resample", n.as_str(), n.as_str(), "5"])?;
        let (theirs, r) = match scipy {
            Some(v) => {
                let t = seconds(&v, "seconds");
                (ms(t), ratio(t, single))
            }
            None => ("scipy not installed".to_owned(), "–".to_owned()),
        };
        upsampling.push(vec![
            format!("{size}×{size}×3 → {}×{}", 4 * size, 4 * size),
            ms(single),
            ms(all),
            theirs,
            r,
        ]);
        bar.inc(1);
    }
    bar.finish_and_clear();
    let mut s = String::new();
    let _ = write!(
        s,
        "## Fitting (§5.3–§5.8, Table 5.1)\n\n\
         The pipeline of `hi_geomimage::fit` on each scan: a {IMAGE}×{IMAGE} flattened-octahedron \
         geometry image (algorithm 2), the harmonic surface through it (no linear system), the \
         4× rasterisation the thesis times as \"harmonic interpolation\", and the distances from \
         every scan point to the surface (\"fit\" is every stage but that measurement, which \
         is exact and the slowest). Times in seconds, one run each (rayon may use every \
         core). The thesis's Table 5.1 (2005 hardware): about 7 minutes of harmonic interpolation \
         per model; 5 min 43 s for the whole mannequin and 43 min for Spock.\n\n\
         Scans: {}.\n\nMachine: {}.\n\n",
        sources.join("; "),
        machine()
    );
    s.push_str("### Table 5.1, regenerated\n\n");
    s.push_str(&table(
        &[
            "scan",
            "points",
            "geometry image (s)",
            "harmonic interpolation at 4× (s)",
            "fit (s)",
            "with its error measured (s)",
            "stages (s)",
            "distance to scan: mean / RMS / max (of the diagonal)",
            "not star-shaped",
        ],
        &pipeline,
    ));
    s.push_str(
        "\n### 4× upsampling against `scipy.signal.resample`\n\n\
         A three-channel image resampled to 4× along both axes: ours by FFT \
         (`HarmonicSurface::sample_uniform`, Theorem 5.3 twice), on one thread and on every core; \
         scipy's `resample` applied to axis 0 then axis 1 (one thread), median of 5 runs after a \
         warm-up. The ratio is scipy's time over ours on one thread.\n\n",
    );
    s.push_str(&table(
        &["image", "ours, 1 thread (ms)", "ours, all cores (ms)", "scipy (ms)", "scipy / ours"],
        &upsampling,
    ));
    let _ = write!(
        s,
        "\n### Against screened Poisson reconstruction\n\n\
         The same points given to pymeshlab's `generate_surface_reconstruction_screened_poisson` \
         (depth {POISSON_DEPTH}, normals estimated from 10 neighbours first; its time includes \
         that), and the distances from every scan point to its mesh measured as ours are.\n\n"
    );
    s.push_str(&table(
        &[
            "scan",
            "harmonic fit, error not measured (s)",
            "screened Poisson (s)",
            "harmonic: mean / RMS / max",
            "Poisson: mean / RMS / max",
        ],
        &poisson,
    ));
    Ok(s)
}

/// A path as a UTF-8 string for a command line.
fn path_str(p: &Path) -> Result<String> {
    p.to_str().map(str::to_owned).context("a non-UTF-8 path")
}
