// SPDX-License-Identifier: MIT
//! `cargo xtask bench fit`: the fitting pipeline of §5.3–§5.8 timed stage by stage (Table 5.1
//! regenerated on this machine), 4× upsampling against `scipy.signal.resample`, and the same
//! scans reconstructed by screened Poisson (pymeshlab), all in one run.
//!
//! Scans: two built in (points on an ellipsoid and on a bumpy star-shaped solid) and the real
//! models of `shared/data/models` when they are there (the section says which were used).
//! Peers run through `xtask/peers/fit_peers.py`.
//!
//! How the costs grow: 4× upsampling (ours and scipy) and the fit of the ellipsoid against the
//! number of texels, 64² … 512², on log axes (`docs/perf-fit.svg`).
//!
//! Then [`super::poisson`] (whole commands against screened Poisson on the shared models) and
//! [`super::clouds`] (point clouds at scanner scale and scans of any topology, time and peak
//! memory, in a subsection of its own that `cargo xtask bench fit-clouds` rewrites alone).

use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

use anyhow::{Context, Result, bail};
use glam::DVec3;
use hi_curve::bezier::BezierScheme;
use hi_geomimage::{ErrorMeasure, FitOptions, Layout, Method, Smoothing, fit};
use hi_scan::scan::{Scan, read_scan};
use hi_surface::HarmonicSurface;
use indicatif::ProgressBar;

use super::{
    Growth, Headline, Section, growth_plot, machine, median_time, ms, progress_bar, ratio, table,
};

/// Timed runs of our upsampling (after a warm-up).
const RUNS: usize = 5;

/// The geometry image of the pipeline: rows × columns.
const IMAGE: usize = 256;

/// Image sides of the growth plot.
const GROWTH_SIDES: [usize; 4] = [64, 128, 256, 512];

/// The thesis's Table 5.1: about 7 minutes of harmonic interpolation per model.
const THESIS_INTERPOLATION: Duration = Duration::from_secs(7 * 60);

/// The thesis's §5.8: 5 min 43 s to take the mannequin to Bézier patches.
const THESIS_MANNEQUIN: Duration = Duration::from_secs(5 * 60 + 43);

/// The thesis's §5.8: 43 minutes for Spock.
const THESIS_SPOCK: Duration = Duration::from_secs(43 * 60);

/// One run of §5.8's combined pipeline.
struct Combined {
    /// The time of each stage: (name, seconds).
    stages: Vec<(String, f64)>,
    /// The whole run.
    total: Duration,
    /// The number of Bézier patches.
    patches: usize,
}

/// §5.8's combined pipeline on `scan`: an [`IMAGE`]×[`IMAGE`] contour image, smoothed (σ = 1
/// texel), reduced to a quarter of its texels and converted to the thesis's cubic patches.
fn combined(scan: &Scan) -> Result<Combined> {
    let options = FitOptions {
        method: Method::Contours,
        layout: Layout::FlatOctahedron,
        resolution: Some((IMAGE, IMAGE)),
        smoothing: Some(Smoothing::Gaussian { sigma: 1.0 }),
        reduce: Some(0.25),
        rasterise: false,
        error: ErrorMeasure::Off,
        ..FitOptions::thesis()
    };
    let start = std::time::Instant::now();
    let fitted = fit(scan, &options, &mut |_| {})?;
    let converting = std::time::Instant::now();
    let patches = fitted
        .largest()
        .surface
        .to_bezier(BezierScheme::ThesisCubic, hi_curve::bezier::DEFAULT_TOLERANCE)?;
    let end = std::time::Instant::now();
    let mut stages: Vec<(String, f64)> =
        fitted.stages.iter().map(|s| (s.kind.name().to_owned(), s.seconds)).collect();
    stages.push(("Bézier patches".to_owned(), (end - converting).as_secs_f64()));
    Ok(Combined { stages, total: end - start, patches: patches.report.patches })
}

/// The real models used when present, relative to the workspace root.
const REAL: &[&str] = &[
    "../shared/data/models/bunny.obj",
    "../shared/data/models/spot.obj",
    "../shared/data/models/cow.obj",
    "../shared/data/models/duck.obj",
];

/// `n` points spread over the surface r(d) = radius(d) in direction d (a Fibonacci lattice).
fn star_points(n: usize, radius: impl Fn(DVec3) -> DVec3) -> Vec<DVec3> {
    hi_testkit::fibonacci_sphere(n).map(|d| radius(DVec3::from(d))).collect()
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

/// "1.2e-3 / 2.0e-3 / 9.9e-3".
fn errors(e: [f64; 3]) -> String {
    format!("{:.1e} / {:.1e} / {:.1e}", e[0], e[1], e[2])
}

/// Our 4× upsampling of a `size`² three-channel image on one thread and on every core, and
/// scipy's time for the same work (`None` when scipy is not installed).
fn upsample(root: &Path, size: usize) -> Result<(Duration, Duration, Option<Duration>)> {
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
    Ok((single, all, scipy.map(|v| seconds(&v, "seconds"))))
}

/// The growth series: 4× upsampling (ours on one thread, scipy) and the fit of `scan` (every
/// stage but the error measurement), against the texels of the image.
fn growth(root: &Path, scan: &Scan, bar: &ProgressBar) -> Result<Vec<Growth>> {
    let (mut ours, mut theirs, mut fits) = (Vec::new(), Vec::new(), Vec::new());
    for side in GROWTH_SIDES {
        bar.set_message(format!("growth: {side}²"));
        let texels = (side * side) as f64;
        let (single, _, scipy) = upsample(root, side)?;
        ours.push((texels, single));
        if let Some(t) = scipy {
            theirs.push((texels, t));
        }
        let options = FitOptions {
            layout: Layout::FlatOctahedron,
            resolution: Some((side, side)),
            error: ErrorMeasure::Off,
            ..FitOptions::thesis()
        };
        let t = median_time(3, || {
            std::hint::black_box(fit(scan, &options, &mut |_| {})?);
            Ok(())
        })?;
        fits.push((texels, t));
        bar.inc(1);
    }
    Ok(vec![
        Growth { name: "4× upsampling (ours, 1 thread)".to_owned(), points: ours },
        Growth { name: "4× upsampling (scipy)".to_owned(), points: theirs },
        Growth { name: "fit of the ellipsoid (ours)".to_owned(), points: fits },
    ])
}

/// Measures everything and returns the report's section.
pub(super) fn run(root: &Path, bench: &super::Options) -> Result<Section> {
    let dir = root.join("target/xtask-bench/fit");
    std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    let scans = scans(root);
    let bar = progress_bar((3 * scans.len() + 4 + GROWTH_SIDES.len()) as u64)?;
    let sources: Vec<String> =
        scans.iter().map(|(name, source, _)| format!("{name}: {source}")).collect();
    let (pipeline, slowest_interpolation) = table51(&scans, &bar)?;
    let (upsampling, mut headlines) = upsampling(root, &bar)?;
    if !slowest_interpolation.is_zero() {
        headlines.push(Headline {
            what: "harmonic interpolation at 4× of a 256² image (slowest scan)".to_owned(),
            ours: slowest_interpolation,
            peer: "the thesis's Table 5.1 (about 7 min, 2005 hardware)".to_owned(),
            theirs: Some(THESIS_INTERPOLATION),
        });
    }
    let (pipeline58, more) = pipeline58(&scans, &bar)?;
    headlines.extend(more);
    let growth = match scans.first() {
        Some((_, _, Ok(scan))) => growth(root, scan, &bar)?,
        _ => bail!("the built-in ellipsoid is missing"),
    };
    bar.finish_and_clear();
    let mut s = tables(&sources, &pipeline, &upsampling, &pipeline58);
    let (versus, more) = super::poisson::versus_poisson(root, &bar)?;
    s.push_str(&versus);
    headlines.extend(more);
    let plot = growth_plot(
        root,
        "perf-fit.svg",
        "4× upsampling and fitting against image size",
        "texels",
        &growth,
    )?;
    let _ = write!(
        s,
        "\n### Growth\n\n\
         4× upsampling of a three-channel image (ours on one thread, scipy as above) and the fit \
         of the built-in ellipsoid (flattened octahedron, every stage but the error measurement, \
         median of 3 runs), for images of {} texels:\n\n{plot}",
        GROWTH_SIDES.map(|n| format!("{n}²")).join(", ")
    );
    // Point clouds and scans of any topology, a subsection of its own (`bench fit-clouds`).
    let (clouds, cloud_headlines) = super::clouds::run(root, &root.join("docs"), bench)?;
    let _ = write!(
        s,
        "\n<!-- bench:fit-clouds -->\n{}\n<!-- /bench:fit-clouds -->\n",
        clouds.trim_end()
    );
    Ok(Section { body: s, headlines, sub_headlines: vec![("fit-clouds", cloud_headlines)] })
}

/// Table 5.1's rows: the fit of each scan (at [`IMAGE`]², flattened octahedron), stage by
/// stage; and the slowest harmonic interpolation among them.
fn table51(
    scans: &[(String, String, Result<Scan>)],
    bar: &ProgressBar,
) -> Result<(Vec<Vec<String>>, Duration)> {
    let options = FitOptions {
        layout: Layout::FlatOctahedron,
        resolution: Some((IMAGE, IMAGE)),
        ..FitOptions::thesis()
    };
    let mut pipeline = Vec::new();
    let mut slowest_interpolation = Duration::ZERO;
    for (name, _, scan) in scans {
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
            fitted
                .stages
                .iter()
                .filter(|s| s.kind.name().contains(want))
                .map(|s| s.seconds)
                .sum::<f64>()
        };
        let total: f64 = fitted.stages.iter().map(|s| s.seconds).sum();
        // The fit a user waits for: every stage but the measurement of its error.
        let without_error = total - stage("fit error");
        slowest_interpolation =
            slowest_interpolation.max(Duration::from_secs_f64(stage("rasterisation")));
        let ours = r.errors.as_ref().map(|d| d.relative());
        let stages: Vec<String> =
            fitted.stages.iter().map(|s| format!("{} {:.3}", s.kind, s.seconds)).collect();
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
    }
    Ok((pipeline, slowest_interpolation))
}

/// The rows of 4× upsampling against scipy, at 256² and 257², and their headlines.
fn upsampling(root: &Path, bar: &ProgressBar) -> Result<(Vec<Vec<String>>, Vec<Headline>)> {
    let mut headlines = Vec::new();
    let mut upsampling = Vec::new();
    for size in [256usize, 257] {
        bar.set_message(format!("4× upsampling {size}²"));
        let (single, all, scipy) = upsample(root, size)?;
        let (theirs, r) = match scipy {
            Some(t) => (ms(t), ratio(t, single)),
            None => ("scipy not installed".to_owned(), "–".to_owned()),
        };
        headlines.push(Headline {
            what: format!("4× upsampling of a {size}² three-channel image, 1 thread"),
            ours: single,
            peer: "`scipy.signal.resample` on both axes".to_owned(),
            theirs: scipy,
        });
        upsampling.push(vec![
            format!("{size}×{size}×3 → {}×{}", 4 * size, 4 * size),
            ms(single),
            ms(all),
            theirs,
            r,
        ]);
        bar.inc(1);
    }
    Ok((upsampling, headlines))
}

/// The rows of §5.8's combined pipeline, and the headlines of the two heads against the
/// thesis's times.
fn pipeline58(
    scans: &[(String, String, Result<Scan>)],
    bar: &ProgressBar,
) -> Result<(Vec<Vec<String>>, Vec<Headline>)> {
    let mut headlines = Vec::new();
    // §5.8's combined pipeline: the head stand-ins of figures 5.29 and 5.30 (the thesis's
    // mannequin and Spock), then every scan.
    let mut pipeline58 = Vec::new();
    let heads = [
        ("head (mannequin stand-in)", crate::figures::scans::head_scan(false)?),
        ("pointed head (Spock stand-in)", crate::figures::scans::head_scan(true)?),
    ];
    let all = heads
        .iter()
        .map(|(n, s)| (n.to_string(), s))
        .chain(scans.iter().filter_map(|(n, _, s)| s.as_ref().ok().map(|s| (n.clone(), s))));
    for (name, scan) in all {
        bar.set_message(format!("§5.8 pipeline {name}"));
        let Combined { stages, total, patches } = combined(scan)?;
        let anchor = if name.starts_with("head") {
            Some(("5 min 43 s (mannequin)", THESIS_MANNEQUIN))
        } else if name.starts_with("pointed") {
            Some(("43 min (Spock)", THESIS_SPOCK))
        } else {
            None
        };
        if let Some((what, thesis)) = anchor {
            headlines.push(Headline {
                what: format!("§5.8's whole pipeline to Bézier patches, {name}"),
                ours: total,
                peer: format!("the thesis's {what}, 2005 hardware"),
                theirs: Some(thesis),
            });
        }
        let stages: Vec<String> = stages.iter().map(|(n, t)| format!("{n} {t:.3}")).collect();
        pipeline58.push(vec![
            name,
            scan.points.len().to_string(),
            patches.to_string(),
            format!("{:.3}", total.as_secs_f64()),
            stages.join("; "),
            anchor
                .map_or_else(|| "–".to_owned(), |(what, t)| format!("{what}: {}", ratio(t, total))),
        ]);
        bar.inc(1);
    }
    Ok((pipeline58, headlines))
}

/// The section's opening and its first three tables: Table 5.1, 4× upsampling, §5.8's
/// combined pipeline.
fn tables(
    sources: &[String],
    pipeline: &[Vec<String>],
    upsampling: &[Vec<String>],
    pipeline58: &[Vec<String>],
) -> String {
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
        pipeline,
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
        upsampling,
    ));
    let _ = write!(
        s,
        "\n### §5.8's combined pipeline, to Bézier patches\n\n\
         What the thesis timed at 5 min 43 s for its mannequin and 43 min for Spock: a \
         {IMAGE}×{IMAGE} flattened-octahedron image whose rows are harmonic contours through the \
         scan points the rays located (`Texels::Contours`), smoothed by a Gaussian of σ = 1 texel, \
         reduced to a quarter of its texels by Theorem 5.3, and converted to the thesis's cubic \
         Bézier patches (§5.7). One run each, in seconds. The mannequin and Spock are not \
         available: the head scans of figures 5.29 and 5.30 (60 000 noisy points on Lee \
         Perry-Smith's head scan, CC BY 3.0, its ears round or drawn up to a point) stand in for \
         them; the thesis's image size is illegible in the extracted text.\n\n"
    );
    s.push_str(&table(
        &["scan", "points", "patches", "total (s)", "stages (s)", "the thesis / ours"],
        pipeline58,
    ));
    s
}
