// SPDX-License-Identifier: MIT
//! Running the two programs: each command under `xtask/peers/measure.py` as [`super::plan`]
//! asks, trimesh's measurement of both outputs, and the machine's load.

use std::path::Path;
use std::process::Command;

use anyhow::{Context, Result, bail};
use indicatif::ProgressBar;
use serde_json::Value;

use super::super::poisson::{self, DEPTH, Measured, path_str};
use super::figure::panels;
use super::report::cell_text;
use super::{Case, Group, Outcome, Scale, plan};

/// One row as measured: its case, what was measured, and its panels with why they could not
/// be drawn (`None` for a row of the growth plots only, which is not drawn).
pub(super) type RowResult<'a> =
    (&'a Case, Measurement, Option<(Vec<image::RgbImage>, Option<String>)>);

/// One run under `measure.py`.
pub(super) struct RunOut {
    pub(super) seconds: f64,
    pub(super) peak_kib: f64,
    /// `None` when it succeeded, else the error.
    pub(super) error: Option<String>,
    /// Its stderr.
    pub(super) stderr: String,
}

/// What was measured of one row.
pub(super) struct Measurement {
    pub(super) ours: Outcome,
    pub(super) theirs: Outcome,
    pub(super) ours_m: Option<Measured>,
    pub(super) theirs_m: Option<Measured>,
    /// `hi fit`'s report, when it succeeded.
    pub(super) report: Option<Value>,
    /// Our warnings and the errors of the measurement itself.
    pub(super) notes: Vec<String>,
}

/// Runs `program args` once under `measure.py`.
pub(super) fn run_once(root: &Path, timeout: f64, program: &Path, args: &[&str]) -> Result<RunOut> {
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
pub(super) fn error_line(stderr: &str) -> Option<String> {
    stderr
        .lines()
        .map(str::trim)
        .rev()
        .find(|l| !l.is_empty() && !l.starts_with("warning:") && !l.starts_with("File \""))
        .map(str::to_owned)
}

/// Runs a command as [`plan`] asks, with a message on `bar` for each run; the median time and
/// peak memory, or the first failure, and the stderr of the last run.
pub(super) fn measured(
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

/// The median of `values` (the lower middle for an even count, as [`super::super::median`]
/// takes it); NaN if empty.
pub(super) fn median_f64(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len().saturating_sub(1) / 2).copied().unwrap_or(f64::NAN)
}

/// Measures one row: both commands, trimesh's measurement of both outputs.
pub(super) fn measure_case(
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

/// Measures and draws every row of `cases` (each run of `hi` writing into `out`), with the
/// progress on `bar`: a step for each of a row's two commands and one for its drawing.
pub(super) fn measure_all<'a>(
    root: &Path,
    scale: &Scale,
    hi: &Path,
    out: &Path,
    cases: &'a [Case],
    bar: &ProgressBar,
) -> Result<Vec<RowResult<'a>>> {
    // Steps: each row's two commands (however many runs), and its drawing.
    let steps: usize = cases.iter().map(|c| 2 + usize::from(c.group != Group::Growth)).sum();
    bar.set_length(steps as u64);
    let mut results = Vec::new();
    for c in cases {
        let m = measure_case(root, scale, hi, out, c, bar)?;
        bar.inc(2);
        let drawn = if c.group == Group::Growth {
            None
        } else {
            bar.set_message(format!("{}: drawing", c.label));
            let p = panels(root, out, c, &m);
            bar.inc(1);
            Some(p)
        };
        results.push((c, m, drawn));
    }
    bar.finish_and_clear();
    Ok(results)
}

/// The 1-minute load average, from `/proc/loadavg` (NaN where there is none).
pub(super) fn load_average() -> f64 {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().and_then(|w| w.parse().ok()))
        .unwrap_or(f64::NAN)
}
