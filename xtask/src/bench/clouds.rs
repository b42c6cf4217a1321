// SPDX-License-Identifier: MIT
//! `cargo xtask bench fit`, part three (also run alone as `cargo xtask bench fit-clouds`):
//! `hi fit` against screened Poisson on raw point clouds at scanner scale and on scans of any
//! topology, time and peak memory both measured as whole processes.
//!
//! The rows:
//! - clouds of 2·10⁵ points sampled from every mesh model of [`super::poisson::MODELS`], and
//!   of 2·10⁶ from those of [`BIG`] ([`super::sampling`]: uniform by area, Gaussian noise of
//!   10⁻⁴ of the diagonal, seed [`SEED`]; cached under `target/xtask-bench/clouds/`);
//! - each of those models given as its bare vertices (an XYZ, no triangles);
//! - scans of other topologies ([`TOPOLOGY`]): several closed parts, genus 1 and 3, open
//!   sheets and holes (the MIT Hoppe meshes of the shared data, the many-part fixtures, CGAL's
//!   demo data when `libcgal-demo` is installed, and a sampled torus-knot tube made here), with
//!   what `hi fit`'s report says of their parts and topology;
//! - how time and peak memory grow with the number of points, on clouds of one model
//!   ([`GROWTH_MODEL`]) from 2·10⁴ to 2·10⁶ points, both programs, log–log, with the fitted
//!   exponents.
//!
//! Each command runs under `xtask/peers/measure.py`, which starts it as its only child and
//! prints its wall time and `getrusage(RUSAGE_CHILDREN).ru_maxrss`. A command that fails (or
//! runs past the time limit) is a row with its error, not an error of the bench. Each row is
//! checked against the targets: our whole command at least 2× faster than Poisson's, our peak
//! memory no more than Poisson's, our mean scan→surface distance (trimesh's, as in the table
//! above) no more than Poisson's. A figure shows each input, Poisson's surface and ours.

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use glam::DVec3;
use hi_scan::scan::{Scan, read_scan};
use indicatif::ProgressBar;
use serde_json::Value;

use super::poisson::{
    self, DEPTH, Measured, View, compose, locate, missing_panel, path_str, render_panels,
    scan_display,
};
use super::sampling::{
    SplitMix64, cloud_file, diagonal, sample_triangles, torus_knot_tube, with_noise, write_xyz,
};
use super::{Headline, Options, Quantity, Series, log_log_plot, machine, table};

/// The seed of every cloud.
const SEED: u64 = 1;

/// The noise: the standard deviation of each coordinate's Gaussian displacement, as a fraction
/// of the diagonal of the model's bounding box.
const NOISE: f64 = 1e-4;

/// The models whose largest clouds (2·10⁶ points) are measured: the bunny (the growth model)
/// and Nefertiti (the largest mesh of the set, a bust with an open base).
const BIG: &[&str] = &["bunny", "nefertiti"];

/// The model of the growth plots.
const GROWTH_MODEL: &str = "bunny";

/// Points drawn of a point set in the figure (every k-th).
const BEADS: usize = 20_000;

/// A panel of the figure.
const PANEL: (u32, u32) = (200, 160);

/// Inputs per line of the figure.
const PER_LINE: usize = 2;

/// The sizes of one run: full, or small for trying the bench out.
struct Scale {
    /// Points of the clouds of every model.
    cloud: usize,
    /// Points of the clouds of the models of [`BIG`].
    big: usize,
    /// Points of the growth plots' clouds.
    growth: &'static [usize],
    /// Points of the torus-knot cloud.
    knot: usize,
    /// Seconds a command may run before it is stopped (and its row says so).
    timeout: f64,
    /// Whether the timings are one run each, with no warm-up.
    once: bool,
}

/// The bench as reported.
const FULL: Scale = Scale {
    cloud: 200_000,
    big: 2_000_000,
    growth: &[20_000, 60_000, 200_000, 600_000, 2_000_000],
    knot: 200_000,
    timeout: 1800.0,
    once: false,
};

/// `--small`: a tenth of the points and one run of each command.
const SMALL: Scale = Scale {
    cloud: 20_000,
    big: 60_000,
    growth: &[2_000, 6_000, 20_000, 60_000],
    knot: 20_000,
    timeout: 600.0,
    once: true,
};

/// Timed runs of a command, of which the median is taken.
const RUNS: usize = 3;

/// Seconds from which a first run is timed too, rather than an untimed warm-up: reading the
/// input, which is what a warm run saves, is then a small part of the whole.
const WARM_ENOUGH: f64 = 10.0;

/// Seconds from which a first run is the only one: a command that long gains little from a
/// warm start, and three runs of each would triple the longest rows of the bench.
const LONG: f64 = 60.0;

/// The runs of a command whose first run took `first` seconds: whether that first run is
/// timed (else it was an untimed warm-up), and how many are timed in all. [`RUNS`] timed after
/// a warm-up below [`WARM_ENOUGH`]; [`RUNS`] with the first among them below [`LONG`]; the
/// first alone from there; the first alone with `once` (`--small`).
fn plan(first: f64, once: bool) -> (bool, usize) {
    if once || first >= LONG {
        (true, 1)
    } else if first >= WARM_ENOUGH {
        (true, RUNS)
    } else {
        (false, RUNS)
    }
}

/// Where a scan of [`TOPOLOGY`] comes from.
#[derive(Clone, Copy, Debug)]
enum Source {
    /// A model of `fixtures/models` or the shared data.
    Model(&'static str),
    /// A file of CGAL's demo data (`data.tar.gz` of Debian's `libcgal-demo`).
    Cgal(&'static str),
    /// The torus-knot tube made here, sampled.
    Knot,
}

/// A scan of another topology: (row name, where it is, what it is, eye direction, up).
struct Topo {
    name: &'static str,
    source: Source,
    what: &'static str,
    eye: [f64; 3],
    up: [f64; 3],
}

/// The scans of other topologies.
const TOPOLOGY: &[Topo] = &[
    Topo {
        name: "cessna",
        source: Source::Model("hoppe-cessna.obj"),
        what: "mesh, 11 closed parts",
        eye: [0.8, 0.5, 0.6],
        up: [0.0, 0.0, 1.0],
    },
    Topo {
        name: "mechpart",
        source: Source::Model("hoppe-mechpart.obj"),
        what: "mesh, closed, genus 3",
        eye: [0.6, 0.5, 0.8],
        up: [0.0, 1.0, 0.0],
    },
    Topo {
        name: "club",
        source: Source::Model("hoppe-club.obj"),
        what: "mesh, one open sheet",
        eye: [0.3, 0.4, 1.0],
        up: [0.0, 1.0, 0.0],
    },
    Topo {
        name: "spider",
        source: Source::Model("spider.stl"),
        what: "mesh, many parts",
        eye: [0.6, -0.8, 0.7],
        up: [0.0, 0.0, 1.0],
    },
    Topo {
        name: "wuson",
        source: Source::Model("wuson.off"),
        what: "mesh, many parts",
        eye: [0.3, 0.3, 1.0],
        up: [0.0, 1.0, 0.0],
    },
    Topo {
        name: "kitten",
        source: Source::Cgal("data/points_3/kitten.xyz"),
        what: "point set, genus 1",
        eye: [0.3, 0.3, 1.0],
        up: [0.0, 1.0, 0.0],
    },
    Topo {
        name: "knot1",
        source: Source::Cgal("data/meshes/knot1.off"),
        what: "mesh, closed, genus 1 (a knotted tube)",
        eye: [0.2, 0.3, 1.0],
        up: [0.0, 1.0, 0.0],
    },
    Topo {
        name: "three_peaks",
        source: Source::Cgal("data/meshes/three_peaks.off"),
        what: "mesh, one open sheet",
        eye: [0.6, -0.8, 0.7],
        up: [0.0, 0.0, 1.0],
    },
    Topo {
        name: "elephant-with-holes",
        source: Source::Cgal("data/meshes/elephant-with-holes.off"),
        what: "mesh with holes",
        eye: [1.0, 0.3, 0.4],
        up: [0.0, 1.0, 0.0],
    },
    Topo {
        name: "torus knot",
        source: Source::Knot,
        what: "cloud of a trefoil tube made here, genus 1",
        eye: [0.2, 0.3, 1.0],
        up: [0.0, 1.0, 0.0],
    },
];

/// CGAL's demo data, as Debian installs it.
const CGAL_DATA: &str = "/usr/share/doc/libcgal-demo/data.tar.gz";

/// The table a row belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Group {
    /// Clouds sampled from the models.
    Cloud,
    /// The models' bare vertices.
    Vertices,
    /// Other topologies.
    Topology,
    /// Clouds measured for the growth plots only.
    Growth,
}

/// One row: what each program is given, and how it is measured and drawn.
struct Case {
    group: Group,
    /// The model (or scan) it comes from.
    model: String,
    /// The row's name.
    label: String,
    /// The name of its output files.
    stem: String,
    /// What the input is (topology rows).
    what: String,
    /// The file `hi fit` reads.
    ours_input: PathBuf,
    /// The XYZ file Poisson reads, and trimesh's scan points.
    peer_input: PathBuf,
    /// trimesh's reference for surface → scan: a mesh file, or `-` for the points.
    reference: String,
    /// Points in `peer_input`.
    points: usize,
    /// The camera of the figure.
    eye: DVec3,
    up: DVec3,
}

/// How a command went: its median time and peak memory, or why it failed.
#[derive(Clone, Debug, PartialEq)]
enum Outcome {
    /// Every run succeeded.
    Done {
        /// Median wall time, seconds.
        seconds: f64,
        /// Median peak resident set, KiB.
        peak_kib: f64,
        /// Timed runs.
        runs: usize,
    },
    /// A run failed: the error, and what that run cost up to its end.
    Failed { message: String, seconds: f64, peak_kib: f64 },
}

impl Outcome {
    fn done(&self) -> Option<(f64, f64)> {
        match self {
            Self::Done { seconds, peak_kib, .. } => Some((*seconds, *peak_kib)),
            Self::Failed { .. } => None,
        }
    }
}

/// One run under `measure.py`.
struct RunOut {
    seconds: f64,
    peak_kib: f64,
    /// `None` when it succeeded, else the error.
    error: Option<String>,
    /// Its stderr.
    stderr: String,
}

/// What was measured of one row.
struct Measurement {
    ours: Outcome,
    theirs: Outcome,
    ours_m: Option<Measured>,
    theirs_m: Option<Measured>,
    /// `hi fit`'s report, when it succeeded.
    report: Option<Value>,
    /// Our warnings and the errors of the measurement itself.
    notes: Vec<String>,
}

/// Runs `program args` once under `measure.py`.
fn run_once(root: &Path, timeout: f64, program: &Path, args: &[&str]) -> Result<RunOut> {
    let out = Command::new("python3")
        .args(["-I", "-S"])
        .arg(root.join("xtask/peers/measure.py"))
        .arg(format!("{timeout}"))
        .arg(program)
        .args(args)
        .output()
        .context("running python3 (the measurement wrapper needs it)")?;
    if !out.status.success() {
        bail!("measure.py {}: {}", program.display(), String::from_utf8_lossy(&out.stderr).trim());
    }
    let v: Value = serde_json::from_slice(&out.stdout).context("measure.py's JSON")?;
    let stderr = v["stderr"].as_str().unwrap_or("").to_owned();
    let error = if v["timed_out"].as_bool() == Some(true) {
        Some(format!("stopped after {timeout:.0} s, the time limit"))
    } else {
        match v["status"].as_i64() {
            Some(0) => None,
            Some(3) if program.ends_with("python3") => {
                Some("not installed (`pip install pymeshlab`)".to_owned())
            }
            status => Some(error_line(&stderr).unwrap_or_else(|| match status {
                Some(s) => format!("exit status {s}"),
                None => "killed by a signal".to_owned(),
            })),
        }
    };
    Ok(RunOut {
        seconds: v["seconds"].as_f64().unwrap_or(f64::NAN),
        peak_kib: v["peak_kib"].as_f64().unwrap_or(f64::NAN),
        error,
        stderr,
    })
}

/// The last line of `stderr` that is not a warning or a Python traceback's frame: the error.
fn error_line(stderr: &str) -> Option<String> {
    stderr
        .lines()
        .map(str::trim)
        .rev()
        .find(|l| !l.is_empty() && !l.starts_with("warning:") && !l.starts_with("File \""))
        .map(str::to_owned)
}

/// Runs a command as [`plan`] asks, with a message on `bar` for each run; the median time and
/// peak memory, or the first failure, and the stderr of the last run.
fn measured(
    root: &Path,
    scale: &Scale,
    what: &str,
    bar: &ProgressBar,
    program: &Path,
    args: &[&str],
) -> Result<(Outcome, String)> {
    let failed = |run: RunOut| {
        let message = run.error.unwrap_or_default();
        (Outcome::Failed { message, seconds: run.seconds, peak_kib: run.peak_kib }, run.stderr)
    };
    bar.set_message(format!("{what}, run 1"));
    let first = run_once(root, scale.timeout, program, args)?;
    if first.error.is_some() {
        return Ok(failed(first));
    }
    let (counts, timed) = plan(first.seconds, scale.once);
    let (mut seconds, mut peaks) = (Vec::new(), Vec::new());
    if counts {
        seconds.push(first.seconds);
        peaks.push(first.peak_kib);
    }
    let mut stderr = first.stderr;
    let total = timed + usize::from(!counts);
    while seconds.len() < timed {
        bar.set_message(format!(
            "{what}, run {} of {total}",
            2 + seconds.len() - usize::from(counts)
        ));
        let run = run_once(root, scale.timeout, program, args)?;
        if run.error.is_some() {
            return Ok(failed(run));
        }
        seconds.push(run.seconds);
        peaks.push(run.peak_kib);
        stderr = run.stderr;
    }
    Ok((
        Outcome::Done { seconds: median_f64(seconds), peak_kib: median_f64(peaks), runs: timed },
        stderr,
    ))
}

/// The median of `values` (the lower middle for an even count, as [`super::median`] takes it); NaN
/// if empty.
fn median_f64(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len().saturating_sub(1) / 2).copied().unwrap_or(f64::NAN)
}

/// "2·10⁵" for a power of ten times a digit, else the number with thin spaces (12 345).
fn count_name(n: usize) -> String {
    const SUPER: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let digits = n.to_string();
    let zeros = digits.len() - digits.trim_end_matches('0').len();
    if n >= 1000 && digits.len() - zeros == 1 {
        let exponent: String = zeros
            .to_string()
            .chars()
            .map(|c| SUPER[c.to_digit(10).unwrap_or(0) as usize])
            .collect();
        return format!("{}·10{exponent}", &digits[..1]);
    }
    let mut out = String::new();
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k).is_multiple_of(3) {
            out.push('\u{2009}');
        }
        out.push(c);
    }
    out
}

/// `message` with the workspace's own path taken out (paths relative to the workspace root),
/// `|` escaped for a table cell, on one line, at most 240 characters.
fn cell_text(message: &str, root: &Path) -> String {
    let prefix = format!("{}/", root.display());
    let one_line = message.replace(&prefix, "").replace('\n', " ").replace('|', "\\|");
    if one_line.chars().count() > 240 {
        format!("{}…", one_line.chars().take(239).collect::<String>())
    } else {
        one_line
    }
}

/// Seconds with three significant digits (whole seconds from 100 s).
fn secs(s: f64) -> String {
    if !s.is_finite() {
        return "–".to_owned();
    }
    if s >= 100.0 {
        format!("{s:.0}")
    } else if s >= 10.0 {
        format!("{s:.1}")
    } else if s >= 1.0 {
        format!("{s:.2}")
    } else {
        format!("{s:.3}")
    }
}

/// KiB as MiB: whole from 100 MiB, else one decimal.
fn mib(kib: f64) -> String {
    let m = kib / 1024.0;
    if !m.is_finite() {
        "–".to_owned()
    } else if m >= 100.0 {
        format!("{m:.0}")
    } else {
        format!("{m:.1}")
    }
}

/// The targets of one row, each met, missed, or not decidable (`None`: Poisson failed, or a
/// distance could not be measured).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Verdicts {
    /// Our whole command at least 2× faster than Poisson's.
    speed: Option<bool>,
    /// Our peak memory no more than Poisson's.
    memory: Option<bool>,
    /// Our mean scan→surface distance no more than Poisson's.
    mean: Option<bool>,
}

/// What the targets compare of one side: (seconds, peak KiB, mean scan→surface distance if
/// measured).
type Side = (f64, f64, Option<f64>);

/// The verdicts from (seconds, peak KiB, mean distance) of each side, `None` for a side that
/// failed: a failure of ours misses every target; one of Poisson's leaves nothing to compare.
fn verdicts(ours: Option<Side>, theirs: Option<Side>) -> Verdicts {
    match (ours, theirs) {
        (None, _) => Verdicts { speed: Some(false), memory: Some(false), mean: Some(false) },
        (Some(_), None) => Verdicts { speed: None, memory: None, mean: None },
        (Some((t, m, d)), Some((pt, pm, pd))) => Verdicts {
            speed: Some(pt >= 2.0 * t),
            memory: Some(m <= pm),
            mean: d.zip(pd).map(|(d, pd)| d <= pd),
        },
    }
}

/// A verdict's cell: "✓ 3.10×", "✗ 0.52×", or "–".
fn verdict_cell(met: Option<bool>, ratio: f64) -> String {
    let ratio = if ratio.is_finite() {
        if ratio >= 10.0 { format!(" {ratio:.0}×") } else { format!(" {ratio:.2}×") }
    } else {
        String::new()
    };
    match met {
        Some(true) => format!("✓{ratio}"),
        Some(false) => format!("✗{ratio}"),
        None => "–".to_owned(),
    }
}

/// What `hi fit`'s report says of the scan's topology: its parts fitted, each part's domain
/// with its genus and boundary loops (the first four, then how many more), and the parts left
/// out: "2 parts: torus (genus 1), sheet (1 loop); 3 left out"; "–" for a report without
/// them (algorithm 1's).
fn topology_summary(report: &Value) -> String {
    let Some(parts) = report["parts"].as_array() else { return "–".to_owned() };
    let describe = |p: &Value| {
        let domain = p["domain"].as_str().unwrap_or("?");
        let genus = p["genus"].as_u64().unwrap_or(0);
        let loops = p["boundary_loops"].as_u64().unwrap_or(0);
        let mut bits = Vec::new();
        if genus > 0 {
            bits.push(format!("genus {genus}"));
        }
        if loops > 0 {
            bits.push(if loops == 1 { "1 loop".to_owned() } else { format!("{loops} loops") });
        }
        if bits.is_empty() { domain.to_owned() } else { format!("{domain} ({})", bits.join(", ")) }
    };
    let mut listed: Vec<String> = parts.iter().take(4).map(describe).collect();
    if parts.len() > 4 {
        listed.push(format!("… {} more", parts.len() - 4));
    }
    let mut out = format!(
        "{} {}: {}",
        parts.len(),
        if parts.len() == 1 { "part" } else { "parts" },
        listed.join(", ")
    );
    if let Some(n) = report["dropped_parts"].as_array().map(Vec::len).filter(|&n| n > 0) {
        out.push_str(&format!("; {n} left out"));
    }
    out
}

/// A trimesh measurement's parts and Euler characteristic: "3, χ 6".
fn shape_cell(m: Option<&Measured>) -> String {
    match m.and_then(|m| m.bodies.zip(m.euler)) {
        Some((b, e)) => format!("{b}, χ {e}"),
        None => "–".to_owned(),
    }
}

/// Extracts the CGAL files [`TOPOLOGY`] uses into `target/xtask-bench/cgal/` (once); the
/// folder, or why not.
fn cgal_data(root: &Path) -> std::result::Result<PathBuf, String> {
    let dir = root.join("target/xtask-bench/cgal");
    let wanted: Vec<&str> = TOPOLOGY
        .iter()
        .filter_map(|t| match t.source {
            Source::Cgal(f) => Some(f),
            _ => None,
        })
        .collect();
    if wanted.iter().all(|f| dir.join(f).exists()) {
        return Ok(dir);
    }
    if !Path::new(CGAL_DATA).exists() {
        return Err(format!("{CGAL_DATA} (Debian's libcgal-demo) is not installed"));
    }
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let status = Command::new("tar")
        .arg("xzf")
        .arg(CGAL_DATA)
        .arg("-C")
        .arg(&dir)
        .args(&wanted)
        .status()
        .map_err(|e| format!("tar: {e}"))?;
    if !status.success() {
        return Err(format!("tar could not extract {} from {CGAL_DATA}", wanted.join(", ")));
    }
    Ok(dir)
}

/// The points of `scan` its triangles use (all of them for a point set).
fn used_points(scan: &Scan) -> Vec<DVec3> {
    let mut used = vec![scan.triangles.is_empty(); scan.points.len()];
    for t in &scan.triangles {
        for &k in t {
            used[k as usize] = true;
        }
    }
    scan.points.iter().zip(&used).filter(|(_, u)| **u).map(|(p, _)| *p).collect()
}

/// The cloud of `n` points of the mesh `scan` (named `name`), from the cache or made now.
fn cloud(dir: &Path, name: &str, scan: &Scan, n: usize, bar: &ProgressBar) -> Result<PathBuf> {
    let path = cloud_file(dir, name, n, SEED);
    if !path.exists() {
        bar.set_message(format!("sampling {} points of {name}", count_name(n)));
        let mut rng = SplitMix64::new(SEED);
        let points = sample_triangles(&scan.points, &scan.triangles, n, &mut rng)?;
        let sigma = NOISE * diagonal(&used_points(scan));
        write_xyz(&path, &with_noise(points, sigma, &mut rng))?;
    }
    Ok(path)
}

/// An XYZ of `points` at `path`, unless it is there already (its content depends only on its
/// name).
fn cached_xyz(path: &Path, points: impl FnOnce() -> Vec<DVec3>) -> Result<()> {
    if !path.exists() {
        write_xyz(path, &points())?;
    }
    Ok(())
}

/// Writes a mesh as OFF.
fn write_off(path: &Path, points: &[DVec3], triangles: &[[u32; 3]]) -> Result<()> {
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(w, "OFF\n{} {} 0", points.len(), triangles.len())?;
    for p in points {
        writeln!(w, "{} {} {}", p.x, p.y, p.z)?;
    }
    for t in triangles {
        writeln!(w, "3 {} {} {}", t[0], t[1], t[2])?;
    }
    w.flush()?;
    Ok(())
}

/// The rows, their inputs made or found; and the inputs not found.
fn cases(
    root: &Path,
    scale: &Scale,
    options: &Options,
    dir: &Path,
    bar: &ProgressBar,
) -> Result<(Vec<Case>, Vec<String>)> {
    let mut clouds = Vec::new();
    let mut vertices = Vec::new();
    let mut growth = Vec::new();
    let mut topology = Vec::new();
    let mut missing = Vec::new();
    let case =
        |group, model: &str, label: String, input: &Path, peer: &Path, reference: &str| Case {
            group,
            model: model.to_owned(),
            stem: label.replace(' ', "-"),
            label,
            what: String::new(),
            ours_input: input.to_path_buf(),
            peer_input: peer.to_path_buf(),
            reference: reference.to_owned(),
            points: 0,
            eye: DVec3::Z,
            up: DVec3::Y,
        };
    for &(name, file, eye, up) in poisson::MODELS {
        let wanted = |label: &str| options.wants(label);
        if !wanted(name) {
            continue;
        }
        let Some(path) = locate(root, file) else {
            missing.push(file.to_owned());
            continue;
        };
        let scan = read_scan(&path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
        if scan.triangles.is_empty() {
            continue; // a point set: nothing to sample
        }
        let reference = path_str(&path)?.to_owned();
        let view = |mut c: Case, n: usize| {
            c.points = n;
            c.eye = DVec3::from(eye);
            c.up = DVec3::from(up);
            c
        };
        let mut sizes = vec![(Group::Cloud, scale.cloud)];
        if BIG.contains(&name) {
            sizes.push((Group::Cloud, scale.big));
        }
        if name == GROWTH_MODEL {
            sizes.extend(
                scale
                    .growth
                    .iter()
                    .filter(|n| !sizes.iter().any(|(_, m)| m == *n))
                    .map(|n| (Group::Growth, *n))
                    .collect::<Vec<_>>(),
            );
        }
        for (group, n) in sizes {
            let xyz = cloud(dir, name, &scan, n, bar)?;
            let label = format!("{name}, {} points", count_name(n));
            let mut c = view(case(group, name, label, &xyz, &xyz, &reference), n);
            c.stem = format!("{name}-{n}");
            if group == Group::Growth { growth.push(c) } else { clouds.push(c) }
        }
        let xyz = dir.join(format!("{name}-vertices.xyz"));
        let points = used_points(&scan);
        let n = points.len();
        cached_xyz(&xyz, || points)?;
        let label = format!("{name}, {} vertices", count_name(n));
        let mut c = view(case(Group::Vertices, name, label, &xyz, &xyz, &reference), n);
        c.stem = format!("{name}-vertices");
        vertices.push(c);
    }
    let mut cgal = None;
    for t in TOPOLOGY.iter().filter(|t| options.wants(t.name)) {
        let (input, reference) = match t.source {
            Source::Model(file) => match locate(root, file) {
                Some(p) => (p.clone(), path_str(&p)?.to_owned()),
                None => {
                    missing.push(file.to_owned());
                    continue;
                }
            },
            Source::Cgal(file) => match cgal.get_or_insert_with(|| cgal_data(root)) {
                Ok(d) => {
                    let p = d.join(file);
                    let reference = if file.ends_with(".xyz") {
                        "-".to_owned()
                    } else {
                        path_str(&p)?.to_owned()
                    };
                    (p, reference)
                }
                Err(why) => {
                    missing.push(format!("{file} ({why})"));
                    continue;
                }
            },
            Source::Knot => {
                let mesh = dir.join("torus-knot-tube.off");
                let (points, triangles) = torus_knot_tube(0.4, 720, 48);
                if !mesh.exists() {
                    write_off(&mesh, &points, &triangles)?;
                }
                let scan = Scan { points, triangles, ..Scan::default() };
                let xyz = cloud(dir, "torus-knot", &scan, scale.knot, bar)?;
                (xyz, path_str(&mesh)?.to_owned())
            }
        };
        let scan = read_scan(&input).map_err(|e| anyhow::anyhow!("{}: {e}", input.display()))?;
        let stem = t.name.replace(' ', "-");
        // Poisson is given the points: those the triangles use, positions only.
        let peer = if matches!(t.source, Source::Knot) {
            input.clone()
        } else {
            let xyz = dir.join(format!("{stem}-points.xyz"));
            let points = used_points(&scan);
            cached_xyz(&xyz, || points)?;
            xyz
        };
        // A point set with normals is given to both as positions only.
        let ours = if scan.triangles.is_empty() { peer.clone() } else { input.clone() };
        let n = used_points(&scan).len();
        let mut c = case(Group::Topology, &stem, t.name.to_owned(), &ours, &peer, &reference);
        c.what = t.what.to_owned();
        c.points = n;
        c.eye = DVec3::from(t.eye);
        c.up = DVec3::from(t.up);
        topology.push(c);
    }
    growth.sort_by_key(|c| c.points);
    let mut all = clouds;
    all.extend(vertices);
    all.extend(topology);
    all.extend(growth);
    Ok((all, missing))
}

/// Measures one row: both commands, trimesh's measurement of both outputs.
fn measure_case(
    root: &Path,
    scale: &Scale,
    hi: &Path,
    out: &Path,
    c: &Case,
    bar: &ProgressBar,
) -> Result<Measurement> {
    let stem = &c.stem;
    let (glb, report, ply) = (
        out.join(format!("{stem}-ours.glb")),
        out.join(format!("{stem}-report.json")),
        out.join(format!("{stem}-poisson.ply")),
    );
    for stale in [&glb, &report, &ply] {
        let _ = std::fs::remove_file(stale);
    }
    let (mut ours, stderr) = measured(
        root,
        scale,
        &format!("{}: hi fit", c.label),
        bar,
        hi,
        &["fit", path_str(&c.ours_input)?, "-o", path_str(&glb)?, "--report", path_str(&report)?],
    )?;
    // "hi: INPUT: what went wrong" as "what went wrong": the row names the input.
    if let Outcome::Failed { message, .. } = &mut ours {
        let input = format!("{}: ", c.ours_input.display());
        let short = message.trim_start_matches("hi: ").trim_start_matches(input.as_str());
        *message = short.to_owned();
    }
    let mut notes: Vec<String> = stderr
        .lines()
        .filter(|l| l.starts_with("warning:"))
        .map(|l| format!("ours: {}", cell_text(l, root)))
        .collect();
    let script = root.join("xtask/peers/fit_peers.py");
    let (theirs, _) = measured(
        root,
        scale,
        &format!("{}: Poisson", c.label),
        bar,
        Path::new("python3"),
        &[path_str(&script)?, "poisson", path_str(&c.peer_input)?, path_str(&ply)?, DEPTH],
    )?;
    let report = match ours {
        Outcome::Done { .. } => std::fs::read_to_string(&report)
            .ok()
            .and_then(|s| serde_json::from_str::<Value>(&s).ok()),
        Outcome::Failed { .. } => None,
    };
    let mut trimesh = |side: &str, outcome: &Outcome, file: &Path| -> Option<Measured> {
        outcome.done()?;
        if c.group == Group::Growth {
            return None;
        }
        bar.set_message(format!("{}: trimesh on {side} surface", c.label));
        match poisson::measure(root, &c.peer_input, &c.reference, file) {
            Ok(m) => Some(m),
            Err(e) => {
                notes.push(format!("{side} measurement: {}", cell_text(&e.to_string(), root)));
                None
            }
        }
    };
    let ours_m = trimesh("our", &ours, &glb);
    let theirs_m = trimesh("Poisson's", &theirs, &ply);
    Ok(Measurement { ours, theirs, ours_m, theirs_m, report, notes })
}

/// The panels of one row: the input, Poisson's surface, ours (a pale panel with a cross for a
/// side that failed).
fn panels(
    root: &Path,
    out: &Path,
    c: &Case,
    m: &Measurement,
) -> (Vec<image::RgbImage>, Option<String>) {
    let stem = &c.stem;
    let (glb, ply) =
        (out.join(format!("{stem}-ours.glb")), out.join(format!("{stem}-poisson.ply")));
    let view = View { eye: c.eye, up: c.up, panel: PANEL };
    let drawn = read_scan(&c.ours_input)
        .map_err(|e| anyhow::anyhow!("{}: {e}", c.ours_input.display()))
        .and_then(|scan| {
            render_panels(
                &scan_display(&scan, BEADS),
                &[m.theirs.done().map(|_| ply.as_path()), m.ours.done().map(|_| glb.as_path())],
                view,
            )
        });
    match drawn {
        Ok(p) => (p, None),
        Err(e) => (
            vec![missing_panel(PANEL); 3],
            Some(format!("not drawn: {}", cell_text(&e.to_string(), root))),
        ),
    }
}

/// A time for a table: seconds, with "(once)" when a full run timed the command once.
fn timed_cell(o: &Outcome, small: bool) -> Option<String> {
    match o {
        Outcome::Done { seconds, runs: 1, .. } if !small => {
            Some(format!("{} (once)", secs(*seconds)))
        }
        Outcome::Done { seconds, .. } => Some(secs(*seconds)),
        Outcome::Failed { .. } => None,
    }
}

/// One line of a table (`small`: every command was run once, so that goes unsaid).
fn row(root: &Path, c: &Case, m: &Measurement, small: bool) -> Vec<String> {
    let scale_once = small;
    let side =
        |o: &Outcome, mm: Option<&Measured>| o.done().map(|(t, k)| (t, k, mm.map(|x| x.mean)));
    let (ours, theirs) = (side(&m.ours, m.ours_m.as_ref()), side(&m.theirs, m.theirs_m.as_ref()));
    let v = verdicts(ours, theirs);
    let ratio = |f: &dyn Fn(Side, Side) -> Option<f64>| {
        ours.zip(theirs).and_then(|(a, b)| f(a, b)).unwrap_or(f64::NAN)
    };
    let pair = |a: Option<String>, b: Option<String>| {
        format!(
            "{} / {}",
            a.unwrap_or_else(|| "failed".to_owned()),
            b.unwrap_or_else(|| "failed".to_owned())
        )
    };
    let pct = |m: Option<&Measured>, f: fn(&Measured) -> f64| {
        m.map_or_else(|| "–".to_owned(), |m| format!("{:.3}", 100.0 * f(m)))
    };
    let mut notes = Vec::new();
    for (who, o) in [("ours", &m.ours), ("Poisson", &m.theirs)] {
        if let Outcome::Failed { message, seconds, .. } = o {
            notes.push(format!(
                "{who} failed after {} s: {}",
                secs(*seconds),
                cell_text(message, root)
            ));
        }
    }
    notes.extend(m.notes.iter().cloned());
    let mut cells = vec![
        c.label.clone(),
        count_name(c.points),
        pair(timed_cell(&m.ours, scale_once), timed_cell(&m.theirs, scale_once)),
        verdict_cell(v.speed, ratio(&|a, b| Some(b.0 / a.0))),
        pair(m.ours.done().map(|d| mib(d.1)), m.theirs.done().map(|d| mib(d.1))),
        verdict_cell(v.memory, ratio(&|a, b| Some(a.1 / b.1))),
        format!(
            "{} / {}",
            pct(m.ours_m.as_ref(), |m| m.mean),
            pct(m.theirs_m.as_ref(), |m| m.mean)
        ),
        verdict_cell(v.mean, ratio(&|a, b| a.2.zip(b.2).map(|(x, y)| x / y))),
        format!(
            "{} / {}",
            pct(m.ours_m.as_ref(), |m| m.back_p99),
            pct(m.theirs_m.as_ref(), |m| m.back_p99)
        ),
        format!(
            "{} / {}",
            pct(m.ours_m.as_ref(), |m| m.back_max),
            pct(m.theirs_m.as_ref(), |m| m.back_max)
        ),
        m.report.as_ref().and_then(|r| r["method"].as_str()).unwrap_or("–").to_owned(),
    ];
    if c.group == Group::Topology {
        cells.insert(1, c.what.clone());
        cells.push(m.report.as_ref().map_or_else(|| "–".to_owned(), topology_summary));
        cells.push(format!(
            "{} / {}",
            shape_cell(m.ours_m.as_ref()),
            shape_cell(m.theirs_m.as_ref())
        ));
    }
    cells.push(if notes.is_empty() { "–".to_owned() } else { notes.join("; ") });
    cells
}

/// The 1-minute load average, from `/proc/loadavg` (NaN where there is none).
fn load_average() -> f64 {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().and_then(|w| w.parse().ok()))
        .unwrap_or(f64::NAN)
}

/// What the load averages at the start and end of a run say of its times, on a machine of
/// `cores` cores: nothing when both stay under one per core; else that the times, Poisson's
/// most, are inflated.
fn load_note(before: f64, after: f64, cores: usize) -> &'static str {
    if before.max(after) > cores as f64 {
        " Other work shared the cores for at least part of the run, so every time here is longer \
         than on a quiet machine, and Poisson's most: pymeshlab's OpenMP threads wait for each \
         other by spinning, which an oversubscribed machine makes several times slower (the \
         speed-ups are then flattering to us)."
    } else {
        ""
    }
}

/// Measures every row and returns the subsection's Markdown (figures written into `docs`) and
/// its headlines.
///
/// # Errors
///
/// When an input cannot be made or read, the wrapper cannot run, or a figure cannot be
/// written; a command that fails is a row, not an error.
pub(super) fn run(root: &Path, docs: &Path, options: &Options) -> Result<(String, Vec<Headline>)> {
    let started = Instant::now();
    let load_before = load_average();
    let scale = if options.small { &SMALL } else { &FULL };
    let dir = root.join("target/xtask-bench/clouds");
    let out =
        if options.small { root.join("target/xtask-bench/small/out") } else { dir.join("out") };
    for d in [&dir, &out] {
        std::fs::create_dir_all(d).with_context(|| format!("creating {}", d.display()))?;
    }
    let bar = super::progress_bar(0)?;
    bar.set_message("building hi");
    let hi = poisson::build_hi(root)?;
    let floor = run_once(root, 60.0, Path::new("true"), &[])?.peak_kib;
    let (cases, missing) = cases(root, scale, options, &dir, &bar)?;
    // Steps: each row's two commands (however many runs), and its drawing.
    let steps: usize = cases.iter().map(|c| 2 + usize::from(c.group != Group::Growth)).sum();
    bar.set_length(steps as u64);
    let mut results = Vec::new();
    for c in &cases {
        let m = measure_case(root, scale, &hi, &out, c, &bar)?;
        bar.inc(2);
        let drawn = if c.group == Group::Growth {
            None
        } else {
            bar.set_message(format!("{}: drawing", c.label));
            let p = panels(root, &out, c, &m);
            bar.inc(1);
            Some(p)
        };
        results.push((c, m, drawn));
    }
    bar.finish_and_clear();
    let load_after = load_average();

    let mut s = String::new();
    let scale_note = if options.small {
        "\n**Small run** (`--small`: a tenth of the points, one run of each command, no warm-up): \
         for trying the bench out, not for reading.\n"
    } else {
        ""
    };
    let big_list = BIG.join(" and ");
    let timing = if scale.once {
        "one run of each command, no warm-up".to_owned()
    } else {
        format!(
            "the median of {RUNS} runs after an untimed warm-up; when the first run takes \
             {WARM_ENOUGH:.0} s or more it is timed, as the first of the {RUNS}, and when it \
             takes {LONG:.0} s or more it is the only one (\"once\" beside the time: a command \
             that long gains little from a warm start, and three runs of each would triple the \
             longest rows)"
        )
    };
    let _ = write!(
        s,
        "### Point clouds and scans of any topology, time and memory\n{scale_note}\n\
         `hi fit INPUT -o ours.glb` against screened Poisson (pymeshlab, depth {DEPTH}, normals \
         from 10 neighbours), both as whole processes, on raw point clouds at scanner scale and \
         on scans with several parts, handles, open sheets and holes.\n\n\
         **Inputs.** Clouds of {} points sampled from every mesh model of the table above \
         ({}), and of {} points from {big_list} only (their commands take minutes each on both \
         sides). A \
         cloud is drawn uniformly by area on the mesh's triangles (a triangle chosen with \
         probability proportional to its area, then (1 − √r₁) a + √r₁ (1 − r₂) b + √r₁ r₂ c \
         with r₁, r₂ uniform), from splitmix64 with seed {SEED}; then every point is displaced \
         by isotropic Gaussian noise, each coordinate independently N(0, σ²) with σ = 10⁻⁴ of \
         the diagonal of the mesh's bounding box (σ along the normal; the displacement's length \
         has root mean square √3 σ). Clouds are written as XYZ (ten significant digits) and \
         cached under `target/xtask-bench/clouds/`, named by model, size and seed. The same \
         models are also given as their bare vertices (an XYZ of the vertices the triangles \
         use, no triangles). Both programs read the same XYZ file. The scans of other \
         topologies give `hi fit` the mesh file and Poisson the points its triangles use, as \
         above (a point set with normals, CGAL's kitten, goes to both as positions only; CGAL's \
         files are extracted from `{CGAL_DATA}` into `target/xtask-bench/cgal/`); the torus \
         knot is a tube of radius 0.4 about the trefoil ((2 + cos 3t) cos 2t, (2 + cos 3t) sin \
         2t, sin 3t), meshed with 720 × 48 quads and sampled as the clouds are, {} points.\n\n\
         **Measurement.** Each command runs under `xtask/peers/measure.py`, which starts it as \
         its only child: wall time from start to exit, and peak memory as the child's \
         `getrusage(RUSAGE_CHILDREN).ru_maxrss` (its peak resident set, threads included; \
         Poisson's includes the Python interpreter and pymeshlab, as a user running it meets \
         them). The child starts as a copy of the wrapper, so no measurement goes below the \
         wrapper's own size: {} MiB here (the peak of `true`). Times and peaks are {timing}; a \
         command stopped after {:.0} s counts as failed. Distances as percentages of the \
         bounding-box diagonal of the input points, measured by trimesh for both outputs as \
         above (5 000 scan points to the surface; surface samples to the source mesh's \
         triangles, or to the points for a point set, their 99th percentile, which a crack \
         left where a handle was cut would raise, and their largest). A failed command is a row with its \
         error (and a pale panel with a cross in the figure). Targets, per row: our whole \
         command at least 2× faster than Poisson's (the ratio is Poisson's time over ours), our \
         peak memory no more than Poisson's (ours over Poisson's), our mean scan→surface \
         distance no more than Poisson's (ours over Poisson's); ✗ for every target when ours \
         failed, – when Poisson failed.\n\n\
         Machine: {}. Load average (1 min) at the start of this subsection's run \
         {load_before:.2}, at its end {load_after:.2}; the run took {:.0} min.{}\n",
        count_name(scale.cloud),
        poisson::MODELS
            .iter()
            .filter(|(n, ..)| results
                .iter()
                .any(|(c, ..)| c.group == Group::Vertices && c.model == *n))
            .map(|(n, ..)| *n)
            .collect::<Vec<_>>()
            .join(", "),
        count_name(scale.big),
        count_name(scale.knot),
        mib(floor),
        scale.timeout,
        machine(),
        started.elapsed().as_secs_f64() / 60.0,
        load_note(
            load_before,
            load_after,
            std::thread::available_parallelism().map_or(1, std::num::NonZero::get)
        ),
    );
    let header = [
        "input",
        "points",
        "time (s): ours / Poisson",
        "≥ 2× faster",
        "peak memory (MiB): ours / Poisson",
        "memory ≤ Poisson's",
        "scan→surface mean (%): ours / Poisson",
        "mean ≤ Poisson's",
        "surface→scan p99 (%): ours / Poisson",
        "surface→scan max (%): ours / Poisson",
        "our method",
    ];
    let rows_of = |group: Group| -> Vec<Vec<String>> {
        results
            .iter()
            .filter(|(c, ..)| c.group == group)
            .map(|(c, m, _)| row(root, c, m, scale.once))
            .collect()
    };
    let (cloud_rows, vertex_rows, topo_rows) =
        (rows_of(Group::Cloud), rows_of(Group::Vertices), rows_of(Group::Topology));
    let mut with_notes: Vec<&str> = header.to_vec();
    with_notes.push("notes");
    if !cloud_rows.is_empty() {
        s.push_str("\n#### Clouds sampled from the models\n\n");
        s.push_str(&table(&with_notes, &cloud_rows));
    }
    if !vertex_rows.is_empty() {
        s.push_str("\n#### The models as bare vertices\n\n");
        s.push_str(&table(&with_notes, &vertex_rows));
    }
    if !topo_rows.is_empty() {
        s.push_str(
            "\n#### Scans of other topologies\n\n\"our report\" is what `hi fit`'s JSON \
             report says of the scan's topology and parts (`topology`, `parts`; else the parts \
             its mesh repair found, `mesh.parts`; – when it says nothing); \"outputs\" are the \
             connected parts and Euler characteristic V − E + F of each output as trimesh finds \
             them after welding coincident vertices (χ = 2 − 2g for one closed part of genus g).\n\n",
        );
        let mut h: Vec<&str> = header.to_vec();
        h.insert(1, "the input");
        h.extend(["our report: topology and parts", "outputs: parts, χ (ours / Poisson)", "notes"]);
        s.push_str(&table(&h, &topo_rows));
    }
    if !missing.is_empty() {
        let _ = write!(s, "\nNot found here, so not measured: {}.\n", missing.join("; "));
    }
    // Targets met, in all.
    let all: Vec<Verdicts> = results
        .iter()
        .filter(|(c, ..)| c.group != Group::Growth)
        .map(|(_, m, _)| {
            let side = |o: &Outcome, mm: Option<&Measured>| {
                o.done().map(|(t, k)| (t, k, mm.map(|x| x.mean)))
            };
            verdicts(side(&m.ours, m.ours_m.as_ref()), side(&m.theirs, m.theirs_m.as_ref()))
        })
        .collect();
    let count = |f: fn(&Verdicts) -> Option<bool>| {
        let met = all.iter().filter(|v| f(v) == Some(true)).count();
        let decided = all.iter().filter(|v| f(v).is_some()).count();
        format!("{met} of {decided}")
    };
    let failed = results
        .iter()
        .filter(|(c, m, _)| c.group != Group::Growth && m.ours.done().is_none())
        .count();
    let _ = write!(
        s,
        "\nTargets met over the {} rows: ≥ 2× faster {}, memory ≤ Poisson's {}, mean ≤ \
         Poisson's {}; `hi fit` failed on {failed}.\n",
        all.len(),
        count(|v| v.speed),
        count(|v| v.memory),
        count(|v| v.mean),
    );
    // The figure.
    let drawn: Vec<(&Case, &Vec<image::RgbImage>)> =
        results.iter().filter_map(|(c, _, p)| p.as_ref().map(|(p, _)| (*c, p))).collect();
    let not_drawn: Vec<String> = results
        .iter()
        .filter_map(|(c, _, p)| {
            p.as_ref().and_then(|(_, e)| e.as_ref()).map(|e| format!("{}: {e}", c.label))
        })
        .collect();
    if !drawn.is_empty() {
        let panels: Vec<Vec<image::RgbImage>> = drawn.iter().map(|(_, p)| (*p).clone()).collect();
        let png = compose(&panels, PANEL, PER_LINE)?;
        let path = docs.join("fit-clouds.png");
        std::fs::write(&path, png).with_context(|| format!("writing {}", path.display()))?;
        let order: Vec<String> = drawn.iter().map(|(c, _)| c.label.clone()).collect();
        let _ = write!(
            s,
            "\nEach input as three panels: the input (a point set as small beads, at most {} of \
             them), Poisson's surface, ours (every part of the file); a pale panel with a cross \
             where the command failed. {PER_LINE} inputs to a line, in the order of the tables: \
             {}.\n\n![each input, Poisson's surface and ours](fit-clouds.png)\n",
            count_name(BEADS),
            order.join("; "),
        );
        if !not_drawn.is_empty() {
            let _ = write!(s, "\nNot drawn: {}.\n", not_drawn.join("; "));
        }
    }
    // Growth.
    let growth: Vec<&(&Case, Measurement, _)> = {
        let mut g: Vec<_> = results
            .iter()
            .filter(|(c, ..)| {
                c.model == GROWTH_MODEL && matches!(c.group, Group::Cloud | Group::Growth)
            })
            .collect();
        g.sort_by_key(|(c, ..)| c.points);
        g
    };
    let mut headlines = Vec::new();
    for (c, m, _) in
        results.iter().filter(|(c, ..)| c.model == GROWTH_MODEL && c.group == Group::Cloud)
    {
        if let (Some((t, _)), Some((pt, _))) = (m.ours.done(), m.theirs.done()) {
            headlines.push(Headline {
                what: format!(
                    "`hi fit` on a cloud of {} points ({GROWTH_MODEL}), whole command",
                    count_name(c.points)
                ),
                ours: std::time::Duration::from_secs_f64(t),
                peer: "screened Poisson (pymeshlab), whole command".to_owned(),
                theirs: Some(std::time::Duration::from_secs_f64(pt)),
            });
        }
    }
    if growth.len() >= 2 {
        let mut tables = Vec::new();
        let mut plots = Vec::new();
        for quantity in [Quantity::Time, Quantity::PeakMemory] {
            let value = |(t, k): (f64, f64)| match quantity {
                Quantity::Time => t,
                Quantity::PeakMemory => k / 1024.0,
            };
            let ok = |side: fn(&Measurement) -> &Outcome| -> Vec<(f64, f64)> {
                growth
                    .iter()
                    .filter_map(|(c, m, _)| side(m).done().map(|d| (c.points as f64, value(d))))
                    .collect()
            };
            let failed_runs: Vec<(f64, f64)> = growth
                .iter()
                .filter_map(|(c, m, _)| match &m.ours {
                    Outcome::Failed { seconds, peak_kib, .. } => {
                        Some((c.points as f64, value((*seconds, *peak_kib))))
                    }
                    Outcome::Done { .. } => None,
                })
                .collect();
            let mut series = vec![
                Series { name: "hi fit".to_owned(), points: ok(|m| &m.ours), fitted: true },
                Series {
                    name: "screened Poisson".to_owned(),
                    points: ok(|m| &m.theirs),
                    fitted: true,
                },
            ];
            if !failed_runs.is_empty() {
                series.push(Series {
                    name: "hi fit, failed (to the error)".to_owned(),
                    points: failed_runs,
                    fitted: false,
                });
            }
            let (file, title) = match quantity {
                Quantity::Time => ("perf-fit-clouds.svg", "Whole-command time against cloud size"),
                Quantity::PeakMemory => {
                    ("perf-fit-clouds-memory.svg", "Peak memory against cloud size")
                }
            };
            plots.push(log_log_plot(
                docs,
                file,
                &format!("{title} ({GROWTH_MODEL})"),
                "points",
                quantity,
                &series,
            )?);
        }
        for (c, m, _) in &growth {
            let cell = |o: &Outcome| match o {
                Outcome::Done { seconds, peak_kib, runs } => {
                    format!(
                        "{} s, {} MiB ({runs} run{})",
                        secs(*seconds),
                        mib(*peak_kib),
                        if *runs == 1 { "" } else { "s" }
                    )
                }
                Outcome::Failed { seconds, peak_kib, .. } => {
                    format!("failed after {} s, {} MiB", secs(*seconds), mib(*peak_kib))
                }
            };
            tables.push(vec![count_name(c.points), cell(&m.ours), cell(&m.theirs)]);
        }
        let _ = write!(
            s,
            "\n#### Growth with the number of points\n\nClouds of the {GROWTH_MODEL} made as \
             above, {} points, each command timed as in the tables (a run that failed is drawn \
             as a ring at what it cost up to its error, and left out of the fit):\n\n{}\n{}\n{}",
            growth.iter().map(|(c, ..)| count_name(c.points)).collect::<Vec<_>>().join(", "),
            table(&["points", "hi fit", "screened Poisson"], &tables),
            plots[0],
            plots[1],
        );
    }
    Ok((s, headlines))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_are_named_as_powers_of_ten() {
        assert_eq!(count_name(200_000), "2·10⁵");
        assert_eq!(count_name(2_000_000), "2·10⁶");
        assert_eq!(count_name(60_000), "6·10⁴");
        assert_eq!(count_name(10_000_000_000), "1·10¹⁰");
        assert_eq!(count_name(35_947), "35\u{2009}947");
        assert_eq!(count_name(1_234_567), "1\u{2009}234\u{2009}567");
        assert_eq!(count_name(500), "500");
        assert_eq!(count_name(0), "0");
    }

    #[test]
    fn long_commands_are_run_fewer_times() {
        // A first run under 10 s warms up, then three are timed.
        assert_eq!(plan(2.5, false), (false, 3));
        // From 10 s it is the first of the three; from 60 s the only one.
        assert_eq!(plan(10.0, false), (true, 3));
        assert_eq!(plan(59.9, false), (true, 3));
        assert_eq!(plan(60.0, false), (true, 1));
        assert_eq!(plan(600.0, false), (true, 1));
        // --small: one run of everything.
        assert_eq!(plan(0.1, true), (true, 1));
        let done = |runs| Outcome::Done { seconds: 75.31, peak_kib: 1.0, runs };
        assert_eq!(timed_cell(&done(1), false).as_deref(), Some("75.3 (once)"));
        assert_eq!(timed_cell(&done(1), true).as_deref(), Some("75.3"));
        assert_eq!(timed_cell(&done(3), false).as_deref(), Some("75.3"));
        let failed = Outcome::Failed { message: String::new(), seconds: 1.0, peak_kib: 1.0 };
        assert_eq!(timed_cell(&failed, false), None);
        assert_eq!(median_f64(vec![3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median_f64(vec![4.0, 1.0]), 1.0, "the lower of two");
        assert!(median_f64(Vec::new()).is_nan());
    }

    #[test]
    fn targets_are_checked_per_row() {
        // Poisson 10 s, 300 MiB, mean 2e-4; ours 4 s (2.5× faster), 200 MiB, mean 1e-4.
        let theirs = Some((10.0, 300.0, Some(2e-4)));
        let all = Verdicts { speed: Some(true), memory: Some(true), mean: Some(true) };
        assert_eq!(verdicts(Some((4.0, 200.0, Some(1e-4))), theirs), all);
        // Exactly 2× and equal memory and mean meet the targets; a hair slower does not.
        assert_eq!(verdicts(Some((5.0, 300.0, Some(2e-4))), theirs), all);
        assert_eq!(
            verdicts(Some((5.000_001, 300.1, Some(2.1e-4))), theirs),
            Verdicts { speed: Some(false), memory: Some(false), mean: Some(false) }
        );
        // A distance that could not be measured leaves that target undecided.
        assert_eq!(verdicts(Some((4.0, 200.0, None)), theirs).mean, None);
        // Ours failed: every target missed; Poisson failed: nothing to compare.
        let none = Verdicts { speed: Some(false), memory: Some(false), mean: Some(false) };
        assert_eq!(verdicts(None, theirs), none);
        assert_eq!(verdicts(None, None), none);
        let undecided = Verdicts { speed: None, memory: None, mean: None };
        assert_eq!(verdicts(Some((4.0, 200.0, Some(1e-4))), None), undecided);
        assert_eq!(verdict_cell(Some(true), 2.5), "✓ 2.50×");
        assert_eq!(verdict_cell(Some(false), 0.25), "✗ 0.25×");
        assert_eq!(verdict_cell(Some(true), 31.4), "✓ 31×");
        assert_eq!(verdict_cell(Some(false), f64::NAN), "✗");
        assert_eq!(verdict_cell(None, 1.0), "–");
    }

    #[test]
    fn numbers_and_messages_fit_a_table_cell() {
        assert_eq!(secs(123.4), "123");
        assert_eq!(secs(12.34), "12.3");
        assert_eq!(secs(1.234), "1.23");
        assert_eq!(secs(0.1234), "0.123");
        assert_eq!(secs(f64::NAN), "–");
        assert_eq!(mib(2048.0), "2.0");
        assert_eq!(mib(1024.0 * 150.4), "150");
        let root = Path::new("/somewhere/repo");
        assert_eq!(
            cell_text("/somewhere/repo/target/x.xyz: 51 % of a | b\nmore", root),
            "target/x.xyz: 51 % of a \\| b more"
        );
        assert_eq!(cell_text(&"é".repeat(300), root).chars().count(), 240);
        let err = "warning: 2% unreached\nerror: the scan is an open sheet\n";
        assert_eq!(error_line(err).as_deref(), Some("error: the scan is an open sheet"));
        assert_eq!(error_line("warning: only\n"), None);
    }

    #[test]
    fn the_report_is_read_for_parts_and_topology() {
        let report = serde_json::json!({
            "parts": [
                {"name": "part 1", "domain": "torus", "genus": 1, "boundary_loops": 0},
                {"name": "part 2", "domain": "sphere", "genus": 3, "boundary_loops": 2},
                {"name": "part 3", "domain": "sheet", "genus": 0, "boundary_loops": 1},
                {"name": "part 4", "domain": "sphere", "genus": 0, "boundary_loops": 0},
                {"name": "part 5", "domain": "sphere", "genus": 0, "boundary_loops": 0},
            ],
            "dropped_parts": [{"name": "part 6"}, {"name": "part 7"}],
        });
        assert_eq!(
            topology_summary(&report),
            "5 parts: torus (genus 1), sphere (genus 3, 2 loops), sheet (1 loop), sphere, … 1 more; \
             2 left out"
        );
        let one = serde_json::json!({"parts": [{"domain": "sphere"}], "dropped_parts": []});
        assert_eq!(topology_summary(&one), "1 part: sphere");
        // Algorithm 1's report has no parts.
        assert_eq!(topology_summary(&serde_json::json!({"method": "radial"})), "–");
    }

    #[test]
    fn a_loaded_machine_is_said_to_be_one() {
        assert_eq!(load_note(0.4, 1.9, 2), "");
        assert!(load_note(2.1, 0.3, 2).contains("OpenMP"));
        assert!(load_note(0.3, 5.0, 2).contains("flattering"));
        assert_eq!(load_note(f64::NAN, f64::NAN, 2), "", "no /proc/loadavg");
    }

    #[test]
    fn the_output_shape_cell_names_parts_and_euler_characteristic() {
        let m = Measured { bodies: Some(3), euler: Some(6), ..Measured::default() };
        assert_eq!(shape_cell(Some(&m)), "3, χ 6");
        assert_eq!(shape_cell(Some(&Measured::default())), "–");
        assert_eq!(shape_cell(None), "–");
    }
}
