// SPDX-License-Identifier: MIT
//! `cargo xtask bench <topic>`: timings side by side with the peer programs, in the same run,
//! written as one section of `docs/performance.md`.
//!
//! Each topic owns a section between the markers `<!-- bench:TOPIC -->` and
//! `<!-- /bench:TOPIC -->`; a run rewrites its own section and leaves the others as they are,
//! so the report collects the latest run of every topic. Each section describes the machine
//! it was measured on ([`machine`]) and gives ratios, peer time over ours, so that a number
//! above 1 means we are faster.
//!
//! | topic | what |
//! |---|---|
//! | [`curves`] | uniform sampling of a harmonic curve: the thesis's direct sum, our FFT path and `scipy.signal.resample`, n = 16 … 16 384 |
//! | [`subdivision`] | one step of each scheme of §4.5 on ≥ 100 000 faces, against `OpenMesh` and CGAL, and Loop and Catmull-Clark against mesh size |
//! | [`fit`] | the fitting pipeline per scan (Table 5.1), 4× upsampling against scipy, screened Poisson (pymeshlab), and both against image size; its subsection [`clouds`] (also run alone as `fit-clouds`): point clouds of 2·10⁵ and 2·10⁶ points, bare vertices and scans of any topology against Poisson, time and peak memory as whole processes |
//! | [`render`] | the torus by interval Newton, interval bisection, Bézier patches and a mesh (§5.6), and time against image size |
//! | [`batch`] | scans fitted per minute: one `hi fit` process per scan against `hi fit --out-dir`, `harmonic.fit_many` and `fit_many` over a two-worker Dask cluster; and the Python calls' overhead against the same Rust calls, n = 16 … 16 384 |
//!
//! `cargo xtask bench` (or `bench all`) runs every topic in turn and writes the whole report
//! afresh, with a summary table of the headline ratios at the top. Every topic also plots how
//! its costs grow with the size of the problem, on log axes, with the fitted exponent of each
//! curve ([`growth_plot`], and [`log_log_plot`] for peak memory as well as time).
//!
//! A sub-topic owns a subsection inside its topic's section, between markers of its own
//! (`<!-- bench:fit-clouds -->` inside `<!-- bench:fit -->`): `cargo xtask bench fit` writes it
//! with the rest, `cargo xtask bench fit-clouds` rewrites only it. Options after the topic:
//! `--small` (small inputs, for trying the bench out: written under
//! `target/xtask-bench/small/`, never into `docs/`) and `--only NAME,NAME` (only the rows whose
//! name contains one of the words: written under `target/xtask-bench/only/`, never into
//! `docs/`, whose tables and gallery hold every row).

mod batch;
mod clouds;
mod curves;
mod fit;
mod poisson;
mod render;
mod sampling;
mod subdivision;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use glam::DVec2;

use crate::figures::plot::{Legend, Marker, PALETTE, Pen, Plot};

/// The report, relative to the workspace root.
const REPORT: &str = "docs/performance.md";

/// The topics, in the order of the report.
const TOPICS: &[&str] = &["curves", "subdivision", "fit", "render", "batch"];

/// The sub-topics, each with the topic whose section holds its subsection.
const SUBTOPICS: &[(&str, &str)] = &[("fit-clouds", "fit")];

/// What one topic measured: its section of the report and its headline rows for the summary.
pub(crate) struct Section {
    /// The section's Markdown, from its `##` heading on.
    pub(crate) body: String,
    /// The summary rows: what was measured, our time, the peer and its time, peer / ours.
    pub(crate) headlines: Vec<Headline>,
    /// The summary rows of its sub-topics' subsections (which the body holds, within their
    /// markers), by sub-topic.
    pub(crate) sub_headlines: Vec<(&'static str, Vec<Headline>)>,
}

/// How a run was asked for, from the options after the topic.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Options {
    /// Small inputs, written under `target/xtask-bench/small/` instead of `docs/`.
    pub(crate) small: bool,
    /// Only the rows whose name contains one of these (all rows when empty).
    pub(crate) only: Vec<String>,
}

impl Options {
    /// Whether the row `name` is to be measured.
    pub(crate) fn wants(&self, name: &str) -> bool {
        let name = name.to_ascii_lowercase();
        self.only.is_empty() || self.only.iter().any(|w| name.contains(w.as_str()))
    }
}

/// One row of the summary: a measurement of ours against a peer's, in the same run.
pub(crate) struct Headline {
    /// What was measured, on what input.
    pub(crate) what: String,
    /// Our time.
    pub(crate) ours: Duration,
    /// The peer (a program, or a baseline of our own such as the direct sum).
    pub(crate) peer: String,
    /// The peer's time, if it was measured.
    pub(crate) theirs: Option<Duration>,
}

impl Headline {
    /// The summary row: topic, what, ours, peer, theirs, peer / ours.
    fn row(&self, topic: &str) -> Vec<String> {
        vec![
            topic.to_owned(),
            self.what.clone(),
            ms(self.ours),
            self.peer.clone(),
            self.theirs.map_or_else(|| "not measured".to_owned(), ms),
            self.theirs.map_or_else(|| "–".to_owned(), |t| ratio(t, self.ours)),
        ]
    }
}

/// Runs the benchmarks of `topic` (every topic for `None` or `"all"`) and rewrites its
/// section of the report (the whole report for every topic).
///
/// # Errors
///
/// For an unknown topic, a failed measurement of our own code, or an unwritable report. A peer
/// that is missing or fails is reported in the section, not as an error.
pub(crate) fn run(root: &Path, topic: Option<&str>, options: &Options) -> Result<()> {
    if let Some(&(sub, parent)) = SUBTOPICS.iter().find(|(s, _)| Some(*s) == topic) {
        return run_subtopic(root, sub, parent, options);
    }
    let topics: Vec<&str> = match topic {
        None | Some("all") => TOPICS.to_vec(),
        Some(t) if TOPICS.contains(&t) => vec![t],
        Some(t) => bail!(
            "unknown bench topic {t:?}; topics: all, {}, {}",
            TOPICS.join(", "),
            SUBTOPICS.iter().map(|(s, _)| *s).collect::<Vec<_>>().join(", ")
        ),
    };
    if options.small || !options.only.is_empty() {
        bail!(
            "--small and --only apply to the sub-topics ({}), which write elsewhere",
            SUBTOPICS.iter().map(|(s, _)| *s).collect::<Vec<_>>().join(", ")
        );
    }
    let path = root.join(REPORT);
    let mut doc = if topics.len() == TOPICS.len() {
        String::new()
    } else {
        std::fs::read_to_string(&path).unwrap_or_default()
    };
    for (k, topic) in topics.iter().enumerate() {
        if topics.len() > 1 {
            eprintln!("bench {}/{}: {topic}", k + 1, topics.len());
        }
        let section = match *topic {
            "curves" => curves::run(root)?,
            "subdivision" => subdivision::run(root)?,
            "fit" => fit::run(root, options)?,
            "render" => render::run(root)?,
            "batch" => batch::run(root)?,
            _ => unreachable!("checked against TOPICS"),
        };
        doc = with_section(&doc, topic, &section.body);
        let rows: Vec<Vec<String>> = section.headlines.iter().map(|h| h.row(topic)).collect();
        doc = with_summary(&doc, topic, &rows);
        for (sub, headlines) in &section.sub_headlines {
            let rows: Vec<Vec<String>> = headlines.iter().map(|h| h.row(sub)).collect();
            doc = with_summary(&doc, sub, &rows);
        }
        // Written after every topic, so that a failure later keeps what was measured.
        std::fs::write(&path, &doc).with_context(|| format!("writing {}", path.display()))?;
        println!("bench {topic}: section written to {REPORT}");
    }
    Ok(())
}

/// The folder a sub-topic run with `options` writes its report (`performance.md`) and figures
/// into: `docs/` for a whole run; `target/xtask-bench/small/` with `--small`, or
/// `target/xtask-bench/only/` with `--only` alone, so that a partial run never replaces the
/// committed report's tables and gallery, which hold every row.
fn report_dir(root: &Path, options: &Options) -> PathBuf {
    if options.small {
        root.join("target/xtask-bench/small")
    } else if options.only.is_empty() {
        root.join("docs")
    } else {
        root.join("target/xtask-bench/only")
    }
}

/// Runs the sub-topic `sub` alone and rewrites its subsection inside the section of `parent`
/// (of the report, or of a report of its own elsewhere for a partial run: [`report_dir`]).
fn run_subtopic(root: &Path, sub: &str, parent: &str, options: &Options) -> Result<()> {
    let docs = report_dir(root, options);
    let path = docs.join("performance.md");
    std::fs::create_dir_all(&docs).with_context(|| format!("creating {}", docs.display()))?;
    let doc = std::fs::read_to_string(&path).unwrap_or_default();
    let (body, headlines) = match sub {
        "fit-clouds" => clouds::run(root, &docs, options)?,
        _ => unreachable!("checked against SUBTOPICS"),
    };
    let doc = with_subsection(&doc, parent, sub, &body);
    let rows: Vec<Vec<String>> = headlines.iter().map(|h| h.row(sub)).collect();
    let doc = with_summary(&doc, sub, &rows);
    std::fs::write(&path, &doc).with_context(|| format!("writing {}", path.display()))?;
    println!("bench {sub}: subsection written to {}", path.display());
    Ok(())
}

/// `doc` with the subsection `sub` (inside the section of `parent`) replaced by `body`: put at
/// the end of that section when absent, and the section made (holding only the subsection)
/// when that is absent too.
fn with_subsection(doc: &str, parent: &str, sub: &str, body: &str) -> String {
    let (start, end) = (format!("<!-- bench:{sub} -->"), format!("<!-- /bench:{sub} -->"));
    let block = format!("{start}\n{}\n{end}", body.trim_end());
    if let (Some(a), Some(b)) = (doc.find(&start), doc.find(&end))
        && a < b
    {
        return format!("{}{block}{}", &doc[..a], &doc[b + end.len()..]);
    }
    let parent_end = format!("<!-- /bench:{parent} -->");
    match doc.find(&parent_end) {
        Some(at) => format!("{}\n\n{block}\n{}", doc[..at].trim_end(), &doc[at..]),
        None => with_section(
            doc,
            parent,
            &format!(
                "## {parent}\n\nOnly the subsection below has been measured so far (`cargo \
                 xtask bench {parent}` for the whole section).\n\n{block}"
            ),
        ),
    }
}

/// The report's heading, written when the file is new.
const HEADER: &str = "# Performance\n\n\
Measured by `cargo xtask bench` (every topic; `cargo xtask bench <topic>` for one; see \
`xtask/src/bench/`): each section is one run, with our code and the peer programs timed side by \
side on the same inputs and the same machine. Ratios are the peer's time over ours: above 1, we \
are faster. Timings of our code are the median of several runs after a warm-up, in-process, in \
the release profile; peer timings are those the peer programs print for the same work, so file \
reading and writing are left out on both sides. The thesis's own timings (2005 hardware) are \
quoted as anchors where they exist. Each section ends with a plot of how its costs grow with \
the size of the problem (log axes), and the fitted exponent of each curve: time ∝ size^slope; \
the summary gathers the headline ratios and every exponent.\n";

/// The summary's markers and table header.
const SUMMARY_START: &str = "<!-- bench:summary -->";
/// The end of the summary.
const SUMMARY_END: &str = "<!-- /bench:summary -->";
/// The summary's columns.
const SUMMARY_HEADER: [&str; 6] =
    ["topic", "measured", "ours (ms)", "against", "their time (ms)", "theirs / ours"];

/// `doc` with the summary rows of `topic` replaced by `rows`, the other topics' rows kept in
/// the order of [`TOPICS`]. The summary sits after the header, before the first section.
fn with_summary(doc: &str, topic: &str, rows: &[Vec<String>]) -> String {
    let doc = if doc.trim().is_empty() { HEADER.to_owned() } else { doc.to_owned() };
    let (before, old, after) = match (doc.find(SUMMARY_START), doc.find(SUMMARY_END)) {
        (Some(a), Some(b)) if a < b => (
            doc[..a].to_owned(),
            doc[a + SUMMARY_START.len()..b].to_owned(),
            doc[b + SUMMARY_END.len()..].to_owned(),
        ),
        _ => match doc.find("<!-- bench:") {
            Some(at) => (doc[..at].to_owned(), String::new(), format!("\n{}", &doc[at..])),
            None => (format!("{}\n", doc.trim_end()), String::new(), String::new()),
        },
    };
    // The rows already there, by topic: every row of the headline table after its header.
    let headlines = old.split(GROWTH_HEADING).next().unwrap_or("");
    let mut kept: Vec<Vec<String>> = headlines
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| topic |"))
        .map(|l| l.trim().trim_matches('|').split(" | ").map(|c| c.trim().to_owned()).collect())
        .filter(|r: &Vec<String>| r.first().is_some_and(|t| t != topic))
        .collect();
    kept.extend(rows.iter().cloned());
    // A sub-topic's rows go with its topic's, after them.
    let order = |t: &str| {
        let (t, sub) =
            SUBTOPICS.iter().position(|(s, _)| *s == t).map_or((t, 0), |k| (SUBTOPICS[k].1, k + 1));
        (TOPICS.iter().position(|x| *x == t).unwrap_or(TOPICS.len()), sub)
    };
    kept.sort_by_key(|r| order(r.first().map_or("", String::as_str)));
    let body = format!(
        "## Summary\n\nThe headline of each topic: our time against the peer's in the same run \
         (details, inputs and the machine in each section).\n\n{}\n{GROWTH_HEADING}\n\nThe \
         fitted exponent of every curve of the sections' growth plots: time (or peak memory) ∝ \
         size^p, least squares on the log–log points, so 1 is linear.\n\n{}",
        table(&SUMMARY_HEADER, &kept),
        table(&GROWTH_HEADER, &growth_rows(&format!("{before}{after}")))
    );
    format!("{before}{SUMMARY_START}\n{body}{SUMMARY_END}{after}")
}

/// The heading of the summary's table of growth exponents.
const GROWTH_HEADING: &str = "### Growth";
/// Its columns.
const GROWTH_HEADER: [&str; 5] = ["topic", "of", "size", "method", "exponent p"];

/// The growth exponents of every section of `doc`, in the order of [`TOPICS`]: one row per
/// curve, read from the line [`log_log_plot`] writes under each plot (a subsection's with its
/// section's).
fn growth_rows(doc: &str) -> Vec<Vec<String>> {
    const LEAD: &str = "Fitted exponents (";
    let mut rows = Vec::new();
    for topic in TOPICS {
        let (start, end) = (format!("<!-- bench:{topic} -->"), format!("<!-- /bench:{topic} -->"));
        let Some(section) =
            doc.find(&start).and_then(|a| doc[a..].find(&end).map(|b| &doc[a..a + b]))
        else {
            continue;
        };
        for line in section.lines().filter_map(|l| l.strip_prefix(LEAD)) {
            let Some((of, line)) = line.split_once(" ∝ ") else {
                continue;
            };
            let Some((size, fits)) = line.split_once("^p").zip(line.split_once("): ")) else {
                continue;
            };
            for fit in fits.1.trim_end_matches('.').split("; ") {
                if let Some((method, p)) = fit.rsplit_once(' ') {
                    rows.push(vec![
                        (*topic).to_owned(),
                        of.to_owned(),
                        size.0.to_owned(),
                        method.to_owned(),
                        p.to_owned(),
                    ]);
                }
            }
        }
    }
    rows
}

/// `doc` with the section of `topic` replaced by `body` (if absent, put before the section of
/// the next topic of [`TOPICS`] that is there, or at the end; the header added if `doc` is
/// empty).
fn with_section(doc: &str, topic: &str, body: &str) -> String {
    let (start, end) = (format!("<!-- bench:{topic} -->"), format!("<!-- /bench:{topic} -->"));
    let section = format!("{start}\n{}\n{end}", body.trim_end());
    let doc = if doc.trim().is_empty() { HEADER.to_owned() } else { doc.to_owned() };
    if let (Some(a), Some(b)) = (doc.find(&start), doc.find(&end))
        && a < b
    {
        return format!("{}{section}{}", &doc[..a], &doc[b + end.len()..]);
    }
    let later = TOPICS
        .iter()
        .skip_while(|t| **t != topic)
        .skip(1)
        .find_map(|t| doc.find(&format!("<!-- bench:{t} -->")));
    match later {
        Some(at) => format!("{}{section}\n{}", &doc[..at], &doc[at..]),
        None => format!("{}\n{section}\n", doc.trim_end()),
    }
}

/// One measured curve of a growth plot of time: a method's time at each problem size.
pub(crate) struct Growth {
    /// The method, as the legend names it.
    pub(crate) name: String,
    /// (problem size, time) pairs, sizes increasing.
    pub(crate) points: Vec<(f64, Duration)>,
}

/// The least-squares slope of log y against log x over the points with both positive: the
/// exponent p of y ∝ xᵖ. `None` for fewer than two such points or a single x.
pub(crate) fn power_law_exponent(points: &[(f64, f64)]) -> Option<f64> {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0 && x.is_finite() && y.is_finite())
        .map(|(x, y)| (x.log10(), y.log10()))
        .collect();
    if logs.len() < 2 {
        return None;
    }
    let k = logs.len() as f64;
    let (mx, my) = logs.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + x / k, b + y / k));
    let (sxy, sxx) = logs
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + (x - mx) * (y - my), b + (x - mx) * (x - mx)));
    (sxx > 0.0).then(|| sxy / sxx)
}

/// What a growth plot shows against the size of the problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Quantity {
    /// Time, in seconds.
    Time,
    /// Peak memory (resident set), in MiB.
    PeakMemory,
}

impl Quantity {
    /// The name in the line of fitted exponents, "time ∝ …".
    const fn name(self) -> &'static str {
        match self {
            Self::Time => "time",
            Self::PeakMemory => "peak memory",
        }
    }

    /// The unit of the vertical axis.
    const fn unit(self) -> &'static str {
        match self {
            Self::Time => "seconds",
            Self::PeakMemory => "MiB",
        }
    }
}

/// One curve of a [`log_log_plot`]: (problem size, value) pairs, sizes increasing, in the
/// unit of its [`Quantity`].
pub(crate) struct Series {
    /// The method, as the legend names it.
    pub(crate) name: String,
    /// (problem size, value) pairs.
    pub(crate) points: Vec<(f64, f64)>,
    /// Whether its exponent is fitted (and listed in the summary); not for a series of runs
    /// that failed, say, drawn for what they cost.
    pub(crate) fitted: bool,
}

/// Writes a log–log plot of `series` (time against `x_desc`) to `file` under `docs/`, and
/// returns the Markdown that shows it, with each curve's fitted exponent.
///
/// # Errors
///
/// When the plot cannot be drawn or written.
pub(crate) fn growth_plot(
    root: &Path,
    file: &str,
    title: &str,
    x_desc: &str,
    series: &[Growth],
) -> Result<String> {
    let series: Vec<Series> = series
        .iter()
        .map(|g| Series {
            name: g.name.clone(),
            points: g.points.iter().map(|(n, t)| (*n, t.as_secs_f64())).collect(),
            fitted: true,
        })
        .collect();
    log_log_plot(&root.join("docs"), file, title, x_desc, Quantity::Time, &series)
}

/// Writes a log–log plot of `series` (`quantity` against `x_desc`) to `file` in `dir`, and
/// returns the Markdown that shows it (from a page in the same folder), with the fitted
/// exponent of each curve that asks for one, on the line [`growth_rows`] reads back.
///
/// # Errors
///
/// When the plot cannot be drawn or written.
pub(crate) fn log_log_plot(
    dir: &Path,
    file: &str,
    title: &str,
    x_desc: &str,
    quantity: Quantity,
    series: &[Series],
) -> Result<String> {
    let mut plot =
        Plot::function(title, &format!("log₁₀ {x_desc}"), &format!("log₁₀ {}", quantity.unit()))
            .legend(Legend::UpperLeft);
    let mut slopes = Vec::new();
    for (k, g) in series.iter().enumerate() {
        let color = PALETTE[k % PALETTE.len()];
        let points: Vec<DVec2> = g
            .points
            .iter()
            .filter(|(n, y)| *n > 0.0 && *y > 0.0)
            .map(|(n, y)| DVec2::new(n.log10(), y.log10()))
            .collect();
        if points.is_empty() {
            continue;
        }
        if g.fitted {
            plot = plot.points(&points, Marker::small(color), None);
            plot = plot.curve(points, Pen::solid(color), Some(&g.name));
            if let Some(p) = power_law_exponent(&g.points) {
                slopes.push(format!("{} {p:.2}", g.name));
            }
        } else {
            plot = plot.points(&points, Marker::ring(color), Some(&g.name));
        }
    }
    let path = dir.join(file);
    std::fs::write(&path, plot.render()?).with_context(|| format!("writing {}", path.display()))?;
    let slopes = if slopes.is_empty() {
        "none (no curve has two points)".to_owned()
    } else {
        slopes.join("; ")
    };
    Ok(format!(
        "![{title}]({file})\n\nFitted exponents ({} ∝ {x_desc}^p, least squares on the log–log \
         points; 1 is linear): {slopes}.\n",
        quantity.name()
    ))
}

/// A progress bar of `len` steps on a terminal, hidden otherwise (so reports and CI logs stay
/// clean).
///
/// # Errors
///
/// If the bar's template does not parse.
pub(crate) fn progress_bar(len: u64) -> Result<indicatif::ProgressBar> {
    use std::io::IsTerminal as _;
    if !std::io::stderr().is_terminal() {
        return Ok(indicatif::ProgressBar::hidden());
    }
    let bar = indicatif::ProgressBar::new(len);
    bar.set_style(indicatif::ProgressStyle::with_template(
        "[{elapsed_precise}] {bar:40} {pos}/{len} {msg}",
    )?);
    Ok(bar)
}

/// One line on the machine and toolchain: CPU model, logical cores, OS, rustc.
pub(crate) fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".to_owned());
    let cores = std::thread::available_parallelism().map_or(0, std::num::NonZero::get);
    let rustc = output_line("rustc", &["-V"]).unwrap_or_else(|| "rustc (unknown)".to_owned());
    let os = output_line("uname", &["-sr"]).unwrap_or_else(|| std::env::consts::OS.to_owned());
    format!("{cpu}, {cores} logical cores; {os}; {rustc}")
}

/// The first line a command prints, if it runs and succeeds.
pub(crate) fn output_line(program: &str, args: &[&str]) -> Option<String> {
    let out = Command::new(program).args(args).output().ok()?;
    if !out.status.success() {
        return None;
    }
    String::from_utf8_lossy(&out.stdout).lines().next().map(|l| l.trim().to_owned())
}

/// The median of `runs` timings of `f`, after one untimed warm-up run.
///
/// # Errors
///
/// The first error of `f`.
pub(crate) fn median_time(runs: usize, mut f: impl FnMut() -> Result<()>) -> Result<Duration> {
    f()?;
    let mut times = Vec::with_capacity(runs);
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        f()?;
        times.push(start.elapsed());
    }
    Ok(median(times))
}

/// The median of `times` (the lower middle for an even count); zero if empty.
pub(crate) fn median(mut times: Vec<Duration>) -> Duration {
    times.sort_unstable();
    times.get(times.len().saturating_sub(1) / 2).copied().unwrap_or_default()
}

/// A duration in milliseconds with three significant digits (whole milliseconds from 100 on).
pub(crate) fn ms(d: Duration) -> String {
    let v = d.as_secs_f64() * 1e3;
    if v >= 100.0 || v <= 0.0 {
        return format!("{v:.0}");
    }
    // Digits after the point: 1 from 10 ms, 2 from 1 ms, 3 from 0.1 ms, …
    let decimals = (2.0 - v.log10().floor()).clamp(0.0, 9.0) as usize;
    format!("{v:.decimals$}")
}

/// The ratio `peer / ours` as "3.2×".
pub(crate) fn ratio(peer: Duration, ours: Duration) -> String {
    let r = peer.as_secs_f64() / ours.as_secs_f64().max(1e-12);
    if r >= 10.0 { format!("{r:.0}×") } else { format!("{r:.2}×") }
}

/// A markdown table from a header and rows.
pub(crate) fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut s = format!("| {} |\n|{}\n", header.join(" | "), "---|".repeat(header.len()));
    for r in rows {
        let _ = writeln!(s, "| {} |", r.join(" | "));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_section_is_appended_then_replaced_and_others_are_kept() {
        let first = with_section("", "a", "first body");
        assert!(first.starts_with("# Performance"), "header on a new file");
        let both = with_section(&first, "b", "two");
        let replaced = with_section(&both, "a", "three\n");
        assert!(replaced.contains("<!-- bench:a -->\nthree\n<!-- /bench:a -->"), "{replaced}");
        assert!(!replaced.contains("first body"), "the old body is gone");
        assert!(replaced.contains("<!-- bench:b -->\ntwo\n<!-- /bench:b -->"), "b is kept");
        assert!(
            replaced.find("bench:a").expect("a") < replaced.find("bench:b").expect("b"),
            "a keeps its place"
        );
        // A known topic goes before the next topic that is there.
        let doc = with_section(&with_section("", "render", "r"), "fit", "f");
        let doc = with_section(&doc, "curves", "c");
        let at = |t: &str| doc.find(&format!("<!-- bench:{t} -->")).expect("present");
        assert!(at("curves") < at("fit") && at("fit") < at("render"), "topic order: {doc}");
    }

    #[test]
    fn the_summary_keeps_other_topics_rows_in_topic_order() {
        let row = |t: &str, what: &str| vec![t.to_owned(), what.to_owned(), "1".to_owned()];
        let doc = with_section("", "fit", "## Fitting");
        let doc = with_summary(&doc, "fit", &[row("fit", "upsampling")]);
        let doc = with_summary(&doc, "curves", &[row("curves", "old"), row("curves", "two")]);
        let doc = with_summary(&doc, "curves", &[row("curves", "new")]);
        let start = doc.find(SUMMARY_START).expect("a summary");
        assert!(start < doc.find("<!-- bench:fit -->").expect("fit"), "summary first: {doc}");
        assert!(doc.starts_with("# Performance"), "the header stays on top: {doc}");
        let curves = doc.find("| curves | new | 1 |").expect("the new curves row");
        let fit = doc.find("| fit | upsampling | 1 |").expect("the fit row is kept");
        assert!(curves < fit, "topic order: {doc}");
        assert!(!doc.contains("| curves | old"), "old rows are replaced: {doc}");
        assert!(!doc.contains("| curves | two"), "old rows are replaced: {doc}");
        assert_eq!(doc.matches(SUMMARY_START).count(), 1, "one summary: {doc}");
    }

    #[test]
    fn the_summary_lists_every_growth_exponent_of_the_sections() {
        let fits = |size: &str, list: &str| {
            format!(
                "![plot](p.svg)\n\nFitted exponents (time ∝ {size}^p, least squares on the \
                 log–log points; 1 is linear): {list}.\n"
            )
        };
        let doc = with_section("", "render", &fits("pixels", "bezier 0.93; mesh 0.72"));
        let doc = with_summary(&doc, "render", &[]);
        let doc = with_section(&doc, "curves", &fits("n", "FFT (ours) 1.17; scipy, 2 axes 0.77"));
        let doc = with_summary(&doc, "curves", &[vec!["curves".to_owned(), "a".to_owned()]]);
        let summary = &doc[..doc.find(SUMMARY_END).expect("a summary")];
        let rows = [
            "| curves | time | n | FFT (ours) | 1.17 |",
            "| curves | time | n | scipy, 2 axes | 0.77 |",
            "| render | time | pixels | bezier | 0.93 |",
            "| render | time | pixels | mesh | 0.72 |",
        ];
        let at: Vec<usize> =
            rows.iter().map(|r| summary.find(r).unwrap_or_else(|| panic!("{r}: {doc}"))).collect();
        assert!(at.windows(2).all(|w| w[0] < w[1]), "topic order: {summary}");
        // The headline rows stay in their own table, and the growth rows are not read back as
        // headlines when the summary is rewritten.
        let again = with_summary(&doc, "render", &[]);
        assert_eq!(again, doc, "rewriting the summary changes nothing");
        assert!(
            summary.find("| curves | a |").expect("headline")
                < summary.find(GROWTH_HEADING).expect("growth")
        );
    }

    #[test]
    fn the_slope_is_the_exponent_of_a_power_law() {
        // t = 3e-6 · n^1.5 exactly: the fitted exponent is 1.5.
        let points: Vec<(f64, f64)> =
            [16.0, 64.0, 256.0, 1024.0].iter().map(|&n: &f64| (n, 3e-6 * n.powf(1.5))).collect();
        let p = power_law_exponent(&points).expect("four points");
        assert!((p - 1.5).abs() < 1e-9, "slope {p}");
        assert_eq!(power_law_exponent(&points[..1]), None, "one point has no slope");
        // Points that cannot be on log axes are left out: what remains is y = 5x, slope 1.
        let with_zero = [(0.0, 1.0), (2.0, 0.0), (10.0, 50.0), (1000.0, 5000.0), (5.0, f64::NAN)];
        let p = power_law_exponent(&with_zero).expect("two good points");
        assert!((p - 1.0).abs() < 1e-12, "slope {p}");
        assert_eq!(power_law_exponent(&[(3.0, 1.0), (3.0, 2.0)]), None, "one abscissa");
        // Least squares through (1, 1), (10, 10), (100, 1000) in log₁₀: x = 0, 1, 2 and
        // y = 0, 1, 3, slope Σ(x − 1)(y − 4/3) / Σ(x − 1)² = (4/3 + 5/3) / 2 = 3/2.
        let p = power_law_exponent(&[(1.0, 1.0), (10.0, 10.0), (100.0, 1000.0)]).expect("three");
        assert!((p - 1.5).abs() < 1e-12, "slope {p}");
    }

    #[test]
    fn memory_exponents_are_listed_beside_time_exponents() {
        let body = "### Clouds\n\nFitted exponents (time ∝ points^p, least squares on the log–log \
                    points; 1 is linear): hi fit 1.02; Poisson 0.91.\n\nFitted exponents (peak \
                    memory ∝ points^p, least squares on the log–log points; 1 is linear): hi fit \
                    0.88; Poisson 0.64.\n";
        let doc = with_section("", "fit", "## Fitting");
        let doc = with_subsection(&doc, "fit", "fit-clouds", body);
        let rows = growth_rows(&doc);
        let want = |r: [&str; 5]| r.map(str::to_owned).to_vec();
        assert_eq!(
            rows,
            vec![
                want(["fit", "time", "points", "hi fit", "1.02"]),
                want(["fit", "time", "points", "Poisson", "0.91"]),
                want(["fit", "peak memory", "points", "hi fit", "0.88"]),
                want(["fit", "peak memory", "points", "Poisson", "0.64"]),
            ]
        );
    }

    #[test]
    fn a_subsection_lives_inside_its_section_and_is_replaced_alone() {
        // Absent: made at the end of the section.
        let doc = with_section("", "fit", "## Fitting\n\nrows");
        let doc = with_section(&doc, "render", "## Rendering");
        let doc = with_subsection(&doc, "fit", "fit-clouds", "### Clouds\n\nfirst");
        let inner = doc.find("<!-- bench:fit-clouds -->").expect("the subsection");
        assert!(doc.find("rows").expect("fit's body") < inner, "{doc}");
        assert!(inner < doc.find("<!-- /bench:fit -->").expect("fit's end"), "{doc}");
        // Present: replaced, the section around it kept.
        let again = with_subsection(&doc, "fit", "fit-clouds", "### Clouds\n\nsecond");
        assert!(again.contains(
            "<!-- bench:fit-clouds -->\n### Clouds\n\nsecond\n<!-- /bench:fit-clouds -->"
        ));
        assert!(
            !again.contains("first") && again.contains("rows") && again.contains("## Rendering")
        );
        // The whole section, rewritten with the subsection in it, is not confused with it.
        let whole = with_section(
            &again,
            "fit",
            "## Fitting\n\nnew rows\n<!-- bench:fit-clouds -->\nthird\n<!-- /bench:fit-clouds -->",
        );
        assert_eq!(whole.matches("<!-- bench:fit-clouds -->").count(), 1, "{whole}");
        assert!(
            whole.contains("third") && !whole.contains("second") && whole.contains("## Rendering")
        );
        // No section to hold it: one is made.
        let alone = with_subsection("", "fit", "fit-clouds", "### Clouds");
        let (a, b) = (alone.find("<!-- bench:fit -->"), alone.find("<!-- bench:fit-clouds -->"));
        assert!(a.is_some() && a < b && alone.starts_with("# Performance"), "{alone}");
        // Its summary rows follow the topic's, and replace only its own.
        let row = |t: &str, what: &str| vec![t.to_owned(), what.to_owned()];
        let doc = with_summary(&whole, "fit-clouds", &[row("fit-clouds", "bunny cloud")]);
        let doc = with_summary(&doc, "fit", &[row("fit", "upsampling")]);
        let doc = with_summary(&doc, "curves", &[row("curves", "fft")]);
        let at = |r: &str| doc.find(r).unwrap_or_else(|| panic!("{r}: {doc}"));
        assert!(at("| curves | fft |") < at("| fit | upsampling |"));
        assert!(at("| fit | upsampling |") < at("| fit-clouds | bunny cloud |"));
    }

    #[test]
    fn partial_runs_never_write_the_committed_report() {
        let root = Path::new("ws");
        let only = |words: &[&str]| words.iter().map(|w| (*w).to_owned()).collect::<Vec<_>>();
        let whole = report_dir(root, &Options::default()).join("performance.md");
        assert_eq!(whole, root.join(REPORT), "a whole run");
        let o = Options { small: false, only: only(&["head"]) };
        assert_eq!(report_dir(root, &o), root.join("target/xtask-bench/only"), "--only");
        for o in
            [Options { small: true, only: Vec::new() }, Options { small: true, only: only(&["x"]) }]
        {
            assert_eq!(report_dir(root, &o), root.join("target/xtask-bench/small"), "{o:?}");
        }
    }

    #[test]
    fn rows_are_chosen_by_words() {
        let o = Options { small: false, only: vec!["bunny".to_owned(), "knot".to_owned()] };
        assert!(o.wants("Bunny, 2·10⁵ points") && o.wants("torus knot") && !o.wants("cow"));
        assert!(Options::default().wants("anything"));
    }

    #[test]
    fn median_and_formats() {
        let d = |ms| Duration::from_millis(ms);
        assert_eq!(median(vec![d(5), d(1), d(3)]), d(3), "odd count");
        assert_eq!(median(vec![d(4), d(1), d(3), d(2)]), d(2), "even count: lower middle");
        assert_eq!(median(Vec::new()), Duration::ZERO, "empty");
        assert_eq!(ms(Duration::from_micros(1234)), "1.23", "ms");
        assert_eq!(ms(Duration::from_millis(250)), "250", "ms");
        assert_eq!(ms(Duration::from_micros(12_345)), "12.3", "ms");
        assert_eq!(
            ms(Duration::from_nanos(3_456)),
            "0.00346",
            "three significant digits below 0.01 ms"
        );
        assert_eq!(ms(Duration::from_micros(250)), "0.250", "ms");
        assert_eq!(ms(Duration::ZERO), "0", "zero");
        assert_eq!(ratio(d(30), d(10)), "3.00×", "ratio");
        assert_eq!(ratio(d(300), d(10)), "30×", "ratio");
    }
}
