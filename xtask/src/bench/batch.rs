// SPDX-License-Identifier: MIT
//! `cargo xtask bench batch`: scans fitted per minute on this machine, and the Python calls'
//! overhead against the same Rust calls, in one run.
//!
//! Throughput: the committed models of `fixtures/models` fitted four ways, each from scratch
//! into a fresh folder — one `hi fit SCAN -o OUT` process per scan, one after the other (the
//! baseline); one `hi fit SCAN... --out-dir DIR` process; `harmonic.fit_many` on this machine;
//! and `harmonic.fit_many` over a Dask `distributed.LocalCluster` of two single-threaded workers
//! (started, with `harmonic` imported on them, before the clock). Whole batches are timed,
//! reading and writing included: one untimed run of each way, then the median of
//! [`BATCH_RUNS`].
//!
//! Overhead: the curve of [`super::curves`] sampled at N = 16n by
//! `HarmonicCurve::sample_uniform`, in-process here and through
//! `harmonic.HarmonicCurve(x).sample_uniform(16 * n)` from Python, for n = 16 … 16 384; and how
//! both grow with n, on log axes (`docs/perf-batch.svg`).
//!
//! The Python side runs through `xtask/peers/batch_peers.py`. So that it runs the same sources
//! as the Rust side, the bench first installs the package from this checkout (`pip install
//! ./crates/hi-py`, with the workspace's target folder: seconds when nothing changed).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use hi_curve::HarmonicCurve;
use serde_json::Value;

use super::{
    Growth, Headline, Section, growth_plot, machine, median, ms, progress_bar, ratio, table,
};

/// The scans: the committed models, relative to the workspace root.
const MODELS: &str = "fixtures/models";
/// The extensions of the scans taken from [`MODELS`].
const EXTENSIONS: [&str; 5] = ["obj", "pts", "stl", "off", "ply"];
/// Timed runs of each way of fitting the batch (after one untimed run).
const BATCH_RUNS: usize = 3;
/// Curve sizes n of the overhead (samples N = 16n); the first and the last are the headlines.
const SIZES: [usize; 4] = [16, 256, 4096, 16_384];
/// Samples per data point, as in [`super::curves`].
const FACTOR: usize = 16;
/// Timed runs of each call (after one untimed run).
const RUNS: usize = 7;
/// Curve points per timed run: a run is `CALLS / n` calls (at least one), so that the small
/// calls are timed many at a time.
const CALLS: usize = 32_768;
/// The growth plot, in `docs/`.
const PLOT: &str = "perf-batch.svg";
/// The workers of the Dask cluster (as `batch_peers.py` starts it).
const WORKERS: usize = 2;

/// The calls of one timed run at `n` points.
fn reps(n: usize) -> usize {
    (CALLS / n.max(1)).max(1)
}

/// The Python side's throughput: the time of each timed run of each way.
#[derive(Debug, PartialEq)]
struct Throughput {
    /// `fit_many` on this machine.
    local: Vec<Duration>,
    /// `fit_many` over the Dask cluster.
    dask: Vec<Duration>,
}

/// Runs the measurements and returns the report's section.
pub(super) fn run(root: &Path) -> Result<Section> {
    let bar = progress_bar(7)?;
    bar.set_message("pip install ./crates/hi-py");
    let install = install(root)?;
    bar.inc(1);
    bar.set_message("building hi");
    let hi = super::poisson::build_hi(root)?;
    bar.inc(1);
    let scans = scans(root)?;
    let dir = root.join("target/xtask-bench/batch");
    bar.set_message("one hi fit per scan");
    let per_process = median(time_batches(&dir, "process", |out| per_process(&hi, &scans, out))?);
    bar.inc(1);
    bar.set_message("hi fit --out-dir");
    let cli = median(time_batches(&dir, "cli", |out| out_dir(&hi, &scans, out))?);
    bar.inc(1);
    bar.set_message("fit_many, here and on Dask");
    let mut args = vec!["throughput".to_owned(), BATCH_RUNS.to_string()];
    args.push(path_arg(&dir.join("python"))?);
    for s in &scans {
        args.push(path_arg(s)?);
    }
    let python = parse_throughput(&peer(root, &args)?, scans.len(), BATCH_RUNS)?;
    let (local, dask) = (median(python.local), median(python.dask));
    bar.inc(1);
    bar.set_message("Rust calls");
    let rust = SIZES.iter().map(|&n| rust_call(n)).collect::<Result<Vec<_>>>()?;
    bar.inc(1);
    bar.set_message("Python calls");
    let mut args = vec!["overhead".to_owned(), RUNS.to_string()];
    args.extend(SIZES.iter().map(|&n| format!("{n},{}", reps(n))));
    let from_python: Vec<Duration> =
        parse_overhead(&peer(root, &args)?, SIZES.len(), RUNS)?.into_iter().map(median).collect();
    bar.inc(1);
    bar.finish_and_clear();

    let count = scans.len();
    let throughput = vec![
        throughput_row(
            "one `hi fit SCAN -o OUT` process per scan",
            count,
            per_process,
            per_process,
        ),
        throughput_row("`hi fit SCAN... --out-dir DIR`", count, cli, per_process),
        throughput_row("`harmonic.fit_many` (this machine)", count, local, per_process),
        throughput_row(
            &format!("`harmonic.fit_many` (Dask, {WORKERS} workers)"),
            count,
            dask,
            per_process,
        ),
    ];
    let mut headlines = Vec::new();
    let baseline = format!(
        "one `hi fit` process per scan ({:.0} scans/min)",
        scans_per_minute(count, per_process)
    );
    for (way, t) in [("on this machine", local), (&format!("on Dask, {WORKERS} workers"), dask)] {
        headlines.push(Headline {
            what: format!(
                "{count} scans of `{MODELS}` by `harmonic.fit_many` {way} ({:.0} scans/min)",
                scans_per_minute(count, t)
            ),
            ours: t,
            peer: baseline.clone(),
            theirs: Some(per_process),
        });
    }
    let overhead: Vec<Vec<String>> = SIZES
        .iter()
        .zip(rust.iter().zip(&from_python))
        .map(|(&n, (&r, &p))| overhead_row(n, r, p))
        .collect();
    for (k, &n) in SIZES.iter().enumerate() {
        if k == 0 || k == SIZES.len() - 1 {
            headlines.push(Headline {
                what: format!(
                    "`HarmonicCurve::sample_uniform`, n = {n}, N = {}, called from Rust",
                    FACTOR * n
                ),
                ours: rust[k],
                peer: "the same call from Python (`harmonic`): the ratio is the binding's cost"
                    .to_owned(),
                theirs: Some(from_python[k]),
            });
        }
    }
    let points = |times: &[Duration]| -> Vec<(f64, Duration)> {
        SIZES.iter().zip(times).map(|(&n, &t)| (n as f64, t)).collect()
    };
    let plot = growth_plot(
        root,
        PLOT,
        "One call sampling a harmonic curve through n points at 16n parameters",
        "n",
        &[
            Growth { name: "Rust call".to_owned(), points: points(&rust) },
            Growth { name: "Python call".to_owned(), points: points(&from_python) },
        ],
    )?;
    let body = body(count, install, &throughput, &overhead, &plot);
    Ok(Section { body, headlines, sub_headlines: Vec::new() })
}

/// Installs the package from this checkout, as `pip install ./crates/hi-py` with the
/// workspace's target folder, and returns how long that took.
fn install(root: &Path) -> Result<Duration> {
    let target =
        std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root.join("target"), PathBuf::from);
    let start = Instant::now();
    let out = Command::new("python3")
        .args(["-m", "pip", "install", "--quiet", "./crates/hi-py"])
        .current_dir(root)
        .env("CARGO_TARGET_DIR", target)
        .output()
        .context("running `python3 -m pip` (is python3 on the PATH?)")?;
    if !out.status.success() {
        bail!(
            "`pip install ./crates/hi-py` failed (the bench installs the package from this \
             checkout before timing it; the build needs maturin: `pip install maturin`):\n{}",
            last_lines(&String::from_utf8_lossy(&out.stderr), 20)
        );
    }
    Ok(start.elapsed())
}

/// The last `count` lines of `text`.
fn last_lines(text: &str, count: usize) -> String {
    let lines: Vec<&str> = text.trim_end().lines().collect();
    lines[lines.len().saturating_sub(count)..].join("\n")
}

/// The scans of [`MODELS`] with one of [`EXTENSIONS`], sorted.
fn scans(root: &Path) -> Result<Vec<PathBuf>> {
    let dir = root.join(MODELS);
    let mut scans = Vec::new();
    for entry in std::fs::read_dir(&dir).with_context(|| format!("reading {}", dir.display()))? {
        let path = entry.with_context(|| format!("reading {}", dir.display()))?.path();
        let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        if path.is_file() && ext.is_some_and(|e| EXTENSIONS.contains(&e.as_str())) {
            scans.push(path);
        }
    }
    if scans.is_empty() {
        bail!("no scans ({}) in {}", EXTENSIONS.join(", "), dir.display());
    }
    scans.sort();
    Ok(scans)
}

/// A path as a command-line argument of the peer script.
fn path_arg(path: &Path) -> Result<String> {
    path.to_str()
        .map(str::to_owned)
        .with_context(|| format!("a non-UTF-8 path: {}", path.display()))
}

/// The output of `scan` in `out`: `out/NAME.glb`.
fn output_of(scan: &Path, out: &Path) -> Result<PathBuf> {
    let stem = scan.file_stem().with_context(|| format!("no file name: {}", scan.display()))?;
    let mut name = stem.to_os_string();
    name.push(".glb");
    Ok(out.join(name))
}

/// The timed runs of one way of fitting the batch: `fit` into a fresh folder
/// `dir/NAME-RUN` each time, the first run untimed.
fn time_batches(
    dir: &Path,
    name: &str,
    mut fit: impl FnMut(&Path) -> Result<()>,
) -> Result<Vec<Duration>> {
    let mut times = Vec::with_capacity(BATCH_RUNS);
    for run in 0..=BATCH_RUNS {
        let out = dir.join(format!("{name}-{run}"));
        if out.exists() {
            std::fs::remove_dir_all(&out).with_context(|| format!("removing {}", out.display()))?;
        }
        std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
        let start = Instant::now();
        fit(&out)?;
        if run > 0 {
            times.push(start.elapsed());
        }
    }
    Ok(times)
}

/// Runs `cmd` (described as `what`), which must succeed.
fn succeed(cmd: &mut Command, what: &str) -> Result<()> {
    let out = cmd
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .output()
        .with_context(|| format!("running {what}"))?;
    if !out.status.success() {
        bail!("{what} failed ({}): {}", out.status, String::from_utf8_lossy(&out.stderr).trim());
    }
    Ok(())
}

/// Fails unless every scan's output is in `out`.
fn check_outputs(scans: &[PathBuf], out: &Path, what: &str) -> Result<()> {
    for scan in scans {
        let file = output_of(scan, out)?;
        if !file.is_file() {
            bail!("{what} did not write {}", file.display());
        }
    }
    Ok(())
}

/// One `hi fit SCAN -o OUT` process per scan, one after the other.
fn per_process(hi: &Path, scans: &[PathBuf], out: &Path) -> Result<()> {
    for scan in scans {
        let what = format!("hi fit {}", scan.display());
        succeed(Command::new(hi).arg("fit").arg(scan).arg("-o").arg(output_of(scan, out)?), &what)?;
    }
    check_outputs(scans, out, "hi fit SCAN -o OUT")
}

/// One `hi fit SCAN... --out-dir DIR` process.
fn out_dir(hi: &Path, scans: &[PathBuf], out: &Path) -> Result<()> {
    succeed(
        Command::new(hi).arg("fit").args(scans).arg("--out-dir").arg(out),
        "hi fit SCAN... --out-dir",
    )?;
    check_outputs(scans, out, "hi fit SCAN... --out-dir")
}

/// Runs `xtask/peers/batch_peers.py` with `args` and returns the JSON it prints.
fn peer(root: &Path, args: &[String]) -> Result<Value> {
    let script = root.join("xtask/peers/batch_peers.py");
    let out = Command::new("python3")
        .arg(&script)
        .args(args)
        .output()
        .context("running python3 (is it on the PATH?)")?;
    let stderr = last_lines(&String::from_utf8_lossy(&out.stderr), 10);
    match out.status.code() {
        Some(3) => bail!(
            "the Python package is not installed ({stderr}): run `pip install ./crates/hi-py` \
             (with CARGO_TARGET_DIR at the workspace's target folder)"
        ),
        Some(4) => bail!(
            "Dask is not installed ({stderr}): run `pip install dask distributed` (and `pip \
             install ./crates/hi-py` for the package)"
        ),
        _ if !out.status.success() => {
            bail!("{} {}: {stderr}", script.display(), args.first().map_or("", String::as_str))
        }
        _ => {}
    }
    serde_json::from_slice(&out.stdout).context("the JSON of batch_peers.py")
}

/// A JSON array of times in seconds, as durations.
fn durations(value: &Value, what: &str) -> Result<Vec<Duration>> {
    value
        .as_array()
        .with_context(|| format!("{what}: not an array"))?
        .iter()
        .map(|t| {
            let s = t.as_f64().with_context(|| format!("{what}: {t} is not a number"))?;
            Duration::try_from_secs_f64(s).with_context(|| format!("{what}: {s} is not a time"))
        })
        .collect()
}

/// Fails unless `times` holds `runs` times.
fn check_runs(times: &[Duration], runs: usize, what: &str) -> Result<()> {
    if times.len() != runs {
        bail!("{what}: {} runs timed, not {runs}", times.len());
    }
    Ok(())
}

/// The throughput printed by `batch_peers.py throughput`, which must have fitted `scans`
/// scans `runs` times each way.
fn parse_throughput(v: &Value, scans: usize, runs: usize) -> Result<Throughput> {
    let fitted = v["scans"].as_u64().context("no \"scans\" in the peer's JSON")?;
    if usize::try_from(fitted).ok() != Some(scans) {
        bail!("the peer fitted {fitted} scans, not {scans}");
    }
    let local = durations(&v["local"], "\"local\"")?;
    let dask = durations(&v["dask"], "\"dask\"")?;
    check_runs(&local, runs, "\"local\"")?;
    check_runs(&dask, runs, "\"dask\"")?;
    Ok(Throughput { local, dask })
}

/// The times per call printed by `batch_peers.py overhead`: `runs` for each of `sizes` sizes.
fn parse_overhead(v: &Value, sizes: usize, runs: usize) -> Result<Vec<Vec<Duration>>> {
    let per_size = v["seconds"].as_array().context("no \"seconds\" in the peer's JSON")?;
    if per_size.len() != sizes {
        bail!("the peer timed {} sizes, not {sizes}", per_size.len());
    }
    per_size
        .iter()
        .enumerate()
        .map(|(k, times)| {
            let what = format!("size {}", k + 1);
            let times = durations(times, &what)?;
            check_runs(&times, runs, &what)?;
            Ok(times)
        })
        .collect()
}

/// The median time of one in-process call of `HarmonicCurve::sample_uniform` at `n` points and
/// 16n samples: [`RUNS`] runs of [`reps`] calls each, after an untimed run.
fn rust_call(n: usize) -> Result<Duration> {
    let curve = HarmonicCurve::try_new(super::curves::points(n))?;
    let reps = reps(n);
    let per_run = u32::try_from(reps).context("too many calls per run")?;
    let mut times = Vec::with_capacity(RUNS);
    for run in 0..=RUNS {
        let start = Instant::now();
        for _ in 0..reps {
            std::hint::black_box(curve.sample_uniform(FACTOR * n)?);
        }
        if run > 0 {
            times.push(start.elapsed() / per_run);
        }
    }
    Ok(median(times))
}

/// Scans per minute for `scans` scans fitted in `t`.
fn scans_per_minute(scans: usize, t: Duration) -> f64 {
    60.0 * scans as f64 / t.as_secs_f64().max(1e-12)
}

/// A row of the throughput table: the way, its seconds, its scans per minute, and the
/// `baseline`'s time over its own.
fn throughput_row(way: &str, scans: usize, t: Duration, baseline: Duration) -> Vec<String> {
    vec![
        way.to_owned(),
        format!("{:.2}", t.as_secs_f64()),
        format!("{:.0}", scans_per_minute(scans, t)),
        ratio(baseline, t),
    ]
}

/// `python − rust` in milliseconds, with its sign.
fn difference(python: Duration, rust: Duration) -> String {
    if python >= rust { ms(python - rust) } else { format!("−{}", ms(rust - python)) }
}

/// A row of the overhead table: the input, Rust's and Python's times, the difference and the
/// ratio Python / Rust.
fn overhead_row(n: usize, rust: Duration, python: Duration) -> Vec<String> {
    vec![
        format!("n = {n}, N = {}", FACTOR * n),
        ms(rust),
        ms(python),
        difference(python, rust),
        ratio(python, rust),
    ]
}

/// The section's text around its two tables and the growth `plot`.
fn body(
    scans: usize,
    install: Duration,
    throughput: &[Vec<String>],
    overhead: &[Vec<String>],
    plot: &str,
) -> String {
    let mut s = String::new();
    let _ = write!(
        s,
        "## Batch throughput and the Python calls' overhead\n\n\
         Machine: {}.\n\n\
         The Python side is the `harmonic` package of this checkout: the bench installs it first \
         (`pip install ./crates/hi-py` with the workspace's target folder, {:.1} s in this run), \
         so that both sides run the same sources.\n\n\
         ### Scans per minute\n\n\
         The {scans} committed models of `{MODELS}` ({}), fitted with `hi fit`'s defaults into \
         glTF four ways: one `hi fit SCAN -o OUT` process per scan, one after the other (the \
         baseline); one `hi fit SCAN... --out-dir DIR` process (as many scans at a time as \
         cores); `harmonic.fit_many(scans, out_dir)` on this machine (the same); and \
         `harmonic.fit_many(scans, out_dir, client=client)` over a Dask \
         `distributed.LocalCluster` of {WORKERS} single-threaded workers, started (with \
         `harmonic` imported on them) before the clock. Each way writes into a fresh folder; the \
         whole batch is timed, reading, writing and process starts included. Medians of \
         {BATCH_RUNS} runs after one untimed run. The last column is the baseline's time over \
         the way's: how many times the baseline's scans per minute it fits.\n\n",
        machine(),
        install.as_secs_f64(),
        EXTENSIONS.map(|e| format!(".{e}")).join(", "),
    );
    s.push_str(&table(
        &["way", "seconds", "scans per minute", "against one process per scan"],
        throughput,
    ));
    let _ = write!(
        s,
        "\n### The Python calls' overhead\n\n\
         The curve of the curves section, through n points xₖ = (3 sin 0.37k, cos 1.3k + 0.01k), \
         sampled at N = {FACTOR}n uniform parameters: `HarmonicCurve::sample_uniform` called \
         in-process here, and `harmonic.HarmonicCurve(x).sample_uniform(16 * n)` from Python \
         (`xtask/peers/batch_peers.py`), on the same curve built once. Each run is {CALLS}/n calls \
         (at least one) in a loop; times per call, medians of {RUNS} runs after one untimed \
         run, in ms. What Python adds: the call through the interpreter, the argument, the GIL \
         released and taken back, and the samples copied into a new NumPy array. Python / Rust \
         is the cost of calling from Python: 1 would be free; in the summary it stands in the \
         column theirs / ours, with the Rust call as ours.\n\n"
    );
    s.push_str(&table(
        &["input", "Rust (ms)", "Python (ms)", "Python − Rust (ms)", "Python / Rust"],
        overhead,
    ));
    let _ = write!(s, "\nHow one call grows with n (log axes):\n\n{plot}");
    s
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;

    #[test]
    fn the_throughput_json_is_read_and_checked() {
        let v = json!({"local": [2.5, 2.0, 3.0], "dask": [1.5, 1.25, 1.75], "scans": 7});
        let t = parse_throughput(&v, 7, 3).expect("well formed");
        let s = Duration::from_secs_f64;
        assert_eq!(t.local, [s(2.5), s(2.0), s(3.0)]);
        assert_eq!(t.dask, [s(1.5), s(1.25), s(1.75)]);
        assert!(parse_throughput(&v, 6, 3).is_err(), "another count of scans");
        assert!(parse_throughput(&v, 7, 4).is_err(), "another count of runs");
        let missing = json!({"local": [1.0], "scans": 7});
        assert!(parse_throughput(&missing, 7, 1).is_err(), "no dask times");
        let text = json!({"local": ["1"], "dask": [1.0], "scans": 7});
        assert!(parse_throughput(&text, 7, 1).is_err(), "a time that is not a number");
        let negative = json!({"local": [-1.0], "dask": [1.0], "scans": 7});
        let e = parse_throughput(&negative, 7, 1).expect_err("a negative time");
        assert!(e.to_string().contains("not a time"), "{e}");
        assert!(parse_throughput(&json!({"local": [1.0], "dask": [1.0]}), 7, 1).is_err());
    }

    #[test]
    fn the_overhead_json_is_read_and_checked() {
        let v = json!({"seconds": [[3e-6, 2e-6], [0.008, 0.009]]});
        let t = parse_overhead(&v, 2, 2).expect("well formed");
        assert_eq!(t[0], [Duration::from_micros(3), Duration::from_micros(2)]);
        assert_eq!(t[1], [Duration::from_millis(8), Duration::from_millis(9)]);
        assert!(parse_overhead(&v, 3, 2).is_err(), "another count of sizes");
        assert!(parse_overhead(&v, 2, 3).is_err(), "another count of runs");
        assert!(parse_overhead(&json!({"seconds": [1.0, 2.0]}), 2, 1).is_err(), "not nested");
        assert!(parse_overhead(&json!({"times": [[1.0]]}), 1, 1).is_err(), "no \"seconds\"");
    }

    #[test]
    fn rows_give_scans_per_minute_and_the_ratios() {
        // 7 scans in 2.8 s: 150 per minute; the baseline's 4.2 s over 2.8 s is 1.5.
        let row =
            throughput_row("way", 7, Duration::from_millis(2800), Duration::from_millis(4200));
        assert_eq!(row, ["way", "2.80", "150", "1.50×"]);
        assert!((scans_per_minute(3, Duration::from_secs(90)) - 2.0).abs() < 1e-12);
        // 0.5 µs in Rust, 3 µs from Python: 2.5 µs more, 6 times as long.
        let row = overhead_row(16, Duration::from_nanos(500), Duration::from_micros(3));
        assert_eq!(row, ["n = 16, N = 256", "0.000500", "0.00300", "0.00250", "6.00×"]);
        let row = overhead_row(16_384, Duration::from_micros(3400), Duration::from_micros(8100));
        assert_eq!(row, ["n = 16384, N = 262144", "3.40", "8.10", "4.70", "2.38×"]);
        // Noise can make the Python call the quicker: the difference keeps its sign.
        assert_eq!(difference(Duration::from_millis(2), Duration::from_millis(3)), "−1.00");
    }

    #[test]
    fn small_calls_are_timed_many_at_a_time() {
        assert_eq!(reps(16), 2048);
        assert_eq!(reps(16_384), 2);
        assert_eq!(reps(100_000), 1, "at least one call");
        assert_eq!(last_lines("a\nb\nc\n", 2), "b\nc");
        assert_eq!(last_lines("a", 5), "a");
    }

    #[test]
    fn the_scans_are_the_committed_models_sorted() {
        let scans = scans(&crate::project_root()).expect("fixtures/models");
        assert!(!scans.is_empty());
        assert!(scans.windows(2).all(|w| w[0] < w[1]), "sorted: {scans:?}");
        let names: Vec<String> = scans
            .iter()
            .map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default())
            .collect();
        assert!(names.contains(&"spot.obj".to_owned()), "{names:?}");
        assert!(!names.iter().any(|n| n.ends_with(".md")), "only scans: {names:?}");
        let out = output_of(&scans[0], Path::new("out")).expect("a file name");
        assert_eq!(out.parent(), Some(Path::new("out")));
        assert_eq!(out.extension().and_then(|e| e.to_str()), Some("glb"));
    }
}
