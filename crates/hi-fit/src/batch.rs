// SPDX-License-Identifier: MIT
//! Many scans fitted into one folder: `hi fit SCAN... --out-dir DIR` and the Python package's
//! `fit_many` (on this machine, or one [`fit_one`] per task on a cluster's workers).
//!
//! Every scan `NAME.EXT` is fitted with the same options into `DIR/NAME.FORMAT`, and one JSON
//! line is appended to `DIR/summary.jsonl` for it ([`Record`]): the input, the output, whether
//! it succeeded, the method, the error both ways, the times, the warnings, or the error that
//! stopped it. A scan that cannot be read or fitted is recorded and the others go on.
//!
//! **Resume rule** ([`plan`]): a scan is done, and skipped, when `summary.jsonl` holds a line
//! with status `"ok"` for the same input and output and the output file exists; `force` redoes
//! it. A line is appended only once its files are written, so a run that was stopped redoes
//! the scans it was fitting; a scan that failed is tried again.

use std::collections::{HashMap, HashSet};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use hi_geomimage::FitOptions;
use serde::{Deserialize, Serialize};

use crate::report::BothWaysOut;
use crate::{Error, OutputFormat, fit_scan, read_scan, warnings, write_outputs};

/// The file of a batch's records, one JSON line per scan, in its output folder.
pub const SUMMARY_FILE: &str = "summary.jsonl";

/// The scans named by `inputs`: a file is itself (whatever its extension; an unknown one is
/// recorded as a failure when fitted), a folder its files with a scan extension (not its
/// subfolders), and a name with `*`, `?` or `[` that is not a file a glob pattern, its matches
/// in order. Each scan appears once, in the order first named.
///
/// # Errors
///
/// [`Error::Input`] for a folder that cannot be listed or holds no scan, a bad pattern, or a
/// pattern that matches nothing.
pub fn expand(inputs: &[PathBuf]) -> Result<Vec<PathBuf>, Error> {
    let mut scans = Vec::new();
    for input in inputs {
        let text = input.to_string_lossy();
        if input.is_dir() {
            let listed = std::fs::read_dir(input)
                .map_err(|e| Error::Input(format!("{}: cannot list: {e}", input.display())))?;
            let mut found: Vec<PathBuf> = listed
                .filter_map(Result::ok)
                .map(|entry| entry.path())
                .filter(|p| p.is_file() && is_scan(p))
                .collect();
            if found.is_empty() {
                return Err(Error::Input(format!("{}: no scan in this folder", input.display())));
            }
            found.sort();
            scans.extend(found);
        } else if !input.exists() && text.contains(['*', '?', '[']) {
            let paths =
                glob::glob(&text).map_err(|e| Error::Input(format!("{text}: bad pattern: {e}")))?;
            let found: Vec<PathBuf> =
                paths.filter_map(Result::ok).filter(|p| p.is_file()).collect();
            if found.is_empty() {
                return Err(Error::Input(format!("{text}: no file matches")));
            }
            scans.extend(found);
        } else {
            scans.push(input.clone());
        }
    }
    let mut seen = HashSet::new();
    scans.retain(|s| seen.insert(s.clone()));
    Ok(scans)
}

/// Whether `path` has the extension of a scan format.
fn is_scan(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| hi_scan::scan::ScanFormat::from_extension(e).is_some())
}

/// One scan of a batch and the file it is fitted into.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Job {
    /// The scan.
    pub input: PathBuf,
    /// Its output, `DIR/NAME.FORMAT`.
    pub output: PathBuf,
}

/// What a batch will do: the scans to fit, and those skipped as done.
#[derive(Clone, Debug, Default)]
pub struct Plan {
    /// The scans to fit, in the order given.
    pub jobs: Vec<Job>,
    /// The scans already done (see the module's resume rule).
    pub skipped: Vec<Job>,
}

/// The jobs of `scans` into `out_dir` in `format`, less those done unless `force` (the resume
/// rule of the module). Makes `out_dir` if it does not exist.
///
/// # Errors
///
/// [`Error::Input`] when two scans would be written to one output (same name in different
/// folders, or different extensions), or `out_dir` cannot be made or is not a folder.
pub fn plan(
    scans: &[PathBuf],
    out_dir: &Path,
    format: OutputFormat,
    force: bool,
) -> Result<Plan, Error> {
    std::fs::create_dir_all(out_dir)
        .map_err(|e| Error::Input(format!("{}: cannot make the folder: {e}", out_dir.display())))?;
    let mut outputs: HashMap<PathBuf, &Path> = HashMap::new();
    let mut plan = Plan::default();
    let done = if force { HashSet::new() } else { done_jobs(out_dir) };
    for scan in scans {
        let name = scan.file_stem().map_or_else(|| "scan".into(), |s| s.to_string_lossy());
        let output = out_dir.join(format!("{name}.{}", format.extension()));
        if let Some(other) = outputs.insert(output.clone(), scan) {
            return Err(Error::Input(format!(
                "{} and {} would both be written to {}: fit them into different folders",
                other.display(),
                scan.display(),
                output.display()
            )));
        }
        let job = Job { input: scan.clone(), output };
        let key = (path_text(&job.input), path_text(&job.output));
        if done.contains(&key) && job.output.is_file() {
            plan.skipped.push(job);
        } else {
            plan.jobs.push(job);
        }
    }
    Ok(plan)
}

/// The (input, output) pairs recorded as done in `out_dir`'s summary; lines that do not read
/// (one cut short when a run was stopped) are passed over.
fn done_jobs(out_dir: &Path) -> HashSet<(String, String)> {
    let Ok(text) = std::fs::read_to_string(out_dir.join(SUMMARY_FILE)) else {
        return HashSet::new();
    };
    text.lines()
        .filter_map(|line| serde_json::from_str::<RecordKey>(line).ok())
        .filter(|r| r.status == Status::Ok)
        .map(|r| (r.input, r.output))
        .collect()
}

/// The fields of a record that the resume rule reads.
#[derive(Deserialize)]
struct RecordKey {
    input: String,
    output: String,
    status: Status,
}

/// A path as it is written in the records.
fn path_text(path: &Path) -> String {
    path.display().to_string()
}

/// Whether a scan was fitted.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    /// Fitted and written.
    Ok,
    /// Stopped by the error in the record.
    Failed,
}

/// Wall-clock seconds of each step of one scan.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Seconds {
    /// Reading the scan.
    pub read: f64,
    /// The fit, its error measured.
    pub fit: f64,
    /// Meshing and writing the output.
    pub write: f64,
    /// All of it.
    pub total: f64,
}

/// One line of `summary.jsonl`: what became of one scan.
#[derive(Debug, Serialize)]
pub struct Record {
    /// The scan, as named.
    pub input: String,
    /// The file it was (to be) fitted into.
    pub output: String,
    /// Whether it was fitted.
    pub status: Status,
    /// The method that ran ([`hi_geomimage::Method`]'s name).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub method: Option<&'static str>,
    /// The parts fitted.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub parts: Option<usize>,
    /// The scan's points.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub points: Option<usize>,
    /// The error both ways, as in the report of `hi fit`.
    #[serde(skip_serializing_if = "Option::is_none")]
    both_ways: Option<BothWaysOut>,
    /// The files written (a `.gltf` has its `.bin`).
    pub files: Vec<String>,
    /// The times of its steps.
    pub seconds: Seconds,
    /// The warnings and notes of the fit, as `hi fit` prints them.
    pub warnings: Vec<String>,
    /// The error that stopped it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

impl Record {
    /// The record as one line of JSON (no newline).
    #[must_use]
    pub fn to_line(&self) -> String {
        // Every field serialises (strings, numbers, arrays); a non-finite number becomes null.
        serde_json::to_string(self).unwrap_or_else(|e| {
            format!(
                "{{\"input\":{:?},\"output\":{:?},\"status\":\"failed\",\"error\":{:?}}}",
                self.input,
                self.output,
                e.to_string()
            )
        })
    }
}

/// Fits one scan of a batch into its output with `options`, never failing: what went wrong is
/// in the record. This is the unit of work a cluster's worker runs.
#[must_use]
pub fn fit_one(job: &Job, options: &FitOptions, format: OutputFormat) -> Record {
    let start = Instant::now();
    let name = path_text(&job.input);
    let mut record = Record {
        input: name.clone(),
        output: path_text(&job.output),
        status: Status::Failed,
        method: None,
        parts: None,
        points: None,
        both_ways: None,
        files: Vec::new(),
        seconds: Seconds::default(),
        warnings: Vec::new(),
        error: None,
    };
    let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        fit_into(job, &name, options, format, &mut record)
    }));
    match run {
        Ok(Ok(())) => record.status = Status::Ok,
        Ok(Err(e)) => record.error = Some(e.to_string()),
        Err(panic) => {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            record.error =
                Some(format!("{name}: internal error (a bug, please report it): {what}"));
        }
    }
    record.seconds.total = start.elapsed().as_secs_f64();
    record
}

/// The steps of [`fit_one`], filling in `record` as they go.
fn fit_into(
    job: &Job,
    name: &str,
    options: &FitOptions,
    format: OutputFormat,
    record: &mut Record,
) -> Result<(), Error> {
    let start = Instant::now();
    let scan = read_scan(&job.input)?;
    record.seconds.read = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let mut fitted = fit_scan(&scan, name, options, &mut |_| {})?;
    record.seconds.fit = start.elapsed().as_secs_f64();
    record.method = Some(fitted.report.method.name());
    record.parts = Some(fitted.parts.len());
    record.points = Some(fitted.report.points);
    record.both_ways = fitted.report.both_ways.as_ref().map(BothWaysOut::of);
    record.warnings = warnings(&fitted, name);
    let start = Instant::now();
    let files = write_outputs(&mut fitted, name, &job.output, format)?;
    record.seconds.write = start.elapsed().as_secs_f64();
    record.files = files.iter().map(|f| path_text(f)).collect();
    Ok(())
}

/// Appends `line` and a newline to the summary in `out_dir`.
///
/// # Errors
///
/// [`Error::Write`] if the summary cannot be opened or written.
pub fn append_line(out_dir: &Path, line: &str) -> Result<(), Error> {
    let path = out_dir.join(SUMMARY_FILE);
    let fail = |e: std::io::Error| Error::Write { path: path.clone(), message: e.to_string() };
    let mut file =
        std::fs::OpenOptions::new().create(true).append(true).open(&path).map_err(fail)?;
    // One write per line, so that lines of concurrent writers do not interleave.
    file.write_all(format!("{line}\n").as_bytes()).map_err(fail)
}

/// How a batch is run.
#[derive(Clone, Debug)]
pub struct BatchOptions {
    /// The format of the outputs.
    pub format: OutputFormat,
    /// Redo the scans already done.
    pub force: bool,
    /// Scans fitted at once (each fit also uses every core for its own work); at least 1.
    pub jobs: usize,
    /// The options of every fit.
    pub fit: FitOptions,
}

/// What a batch did.
#[derive(Debug, Default)]
pub struct Outcome {
    /// The records of the scans fitted (or tried), in the order of the inputs.
    pub records: Vec<Record>,
    /// The scans skipped as done.
    pub skipped: Vec<Job>,
}

impl Outcome {
    /// The scans that failed.
    #[must_use]
    pub fn failed(&self) -> usize {
        self.records.iter().filter(|r| r.status == Status::Failed).count()
    }
}

/// Fits every scan of `scans` into `out_dir` ([`plan`], then [`fit_one`] on `jobs` scans at a
/// time, each record appended to the summary as its scan finishes). `on_done` is told of each
/// record with the count finished and the count to fit, from the thread that fitted it.
///
/// # Errors
///
/// The errors of [`plan`], and [`Error::Write`] if the summary cannot be written (the scans
/// go on; the first such error is returned at the end).
pub fn run(
    scans: &[PathBuf],
    out_dir: &Path,
    options: &BatchOptions,
    on_done: &(dyn Fn(&Record, usize, usize) + Sync),
) -> Result<Outcome, Error> {
    let plan = plan(scans, out_dir, options.format, options.force)?;
    let total = plan.jobs.len();
    let next = AtomicUsize::new(0);
    let finished = AtomicUsize::new(0);
    let records: Mutex<Vec<(usize, Record)>> = Mutex::new(Vec::with_capacity(total));
    let write_error: Mutex<Option<Error>> = Mutex::new(None);
    let summary = Mutex::new(());
    let worker = || {
        loop {
            let k = next.fetch_add(1, Ordering::Relaxed);
            let Some(job) = plan.jobs.get(k) else { break };
            let record = fit_one(job, &options.fit, options.format);
            {
                let _one_writer = summary.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
                if let Err(e) = append_line(out_dir, &record.to_line()) {
                    let mut first =
                        write_error.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
                    first.get_or_insert(e);
                }
            }
            on_done(&record, finished.fetch_add(1, Ordering::Relaxed) + 1, total);
            records.lock().unwrap_or_else(std::sync::PoisonError::into_inner).push((k, record));
        }
    };
    let threads = options.jobs.clamp(1, total.max(1));
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(worker);
        }
    });
    if let Some(e) = write_error.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner) {
        return Err(e);
    }
    let mut records = records.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner);
    records.sort_by_key(|(k, _)| *k);
    Ok(Outcome { records: records.into_iter().map(|(_, r)| r).collect(), skipped: plan.skipped })
}
