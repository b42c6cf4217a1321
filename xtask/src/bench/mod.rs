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
//! | [`subdivision`] | one step of each scheme of §4.5 on ≥ 100 000 faces, against `OpenMesh` and CGAL |
//! | [`fit`] | the fitting pipeline per scan (Table 5.1), 4× upsampling against scipy, screened Poisson (pymeshlab) |
//! | [`render`] | the torus by interval Newton, interval bisection, Bézier patches and a mesh (§5.6), and time against image size |

mod fit;
mod render;
mod subdivision;

use std::fmt::Write as _;
use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};

/// The report, relative to the workspace root.
const REPORT: &str = "docs/performance.md";

/// The topics, in the order of the report.
const TOPICS: &[&str] = &["subdivision", "fit", "render"];

/// Runs the benchmarks of `topic` and rewrites its section of the report.
///
/// # Errors
///
/// For an unknown topic, a failed measurement of our own code, or an unwritable report. A peer
/// that is missing or fails is reported in the section, not as an error.
pub(crate) fn run(root: &Path, topic: Option<&str>) -> Result<()> {
    let topic = match topic {
        Some(t) if TOPICS.contains(&t) => t,
        Some(t) => bail!("unknown bench topic {t:?}; topics: {}", TOPICS.join(", ")),
        None => bail!("usage: cargo xtask bench <{}>", TOPICS.join("|")),
    };
    let body = match topic {
        "subdivision" => subdivision::run(root)?,
        "fit" => fit::run(root)?,
        "render" => render::run(root)?,
        _ => unreachable!("checked against TOPICS"),
    };
    let path = root.join(REPORT);
    let old = std::fs::read_to_string(&path).unwrap_or_default();
    let new = with_section(&old, topic, &body);
    std::fs::write(&path, new).with_context(|| format!("writing {}", path.display()))?;
    println!("bench {topic}: section written to {REPORT}");
    Ok(())
}

/// The report's heading, written when the file is new.
const HEADER: &str = "# Performance\n\n\
Measured by `cargo xtask bench <topic>` (see `xtask/src/bench/`): each section is one run, with \
our code and the peer programs timed side by side on the same inputs and the same machine. \
Ratios are the peer's time over ours: above 1, we are faster. Timings of our code are the median \
of several runs after a warm-up, in-process, in the release profile; peer timings are those the \
peer programs print for the same work, so file reading and writing are left out on both sides. \
The thesis's own timings (2005 hardware) are quoted as anchors where they exist.\n";

/// `doc` with the section of `topic` replaced by `body` (appended if absent; the header added
/// if `doc` is empty).
fn with_section(doc: &str, topic: &str, body: &str) -> String {
    let (start, end) = (format!("<!-- bench:{topic} -->"), format!("<!-- /bench:{topic} -->"));
    let section = format!("{start}\n{}\n{end}", body.trim_end());
    let doc = if doc.trim().is_empty() { HEADER.to_owned() } else { doc.to_owned() };
    match (doc.find(&start), doc.find(&end)) {
        (Some(a), Some(b)) if a < b => {
            format!("{}{section}{}", &doc[..a], &doc[b + end.len()..])
        }
        _ => format!("{}\n{section}\n", doc.trim_end()),
    }
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

/// A duration in milliseconds with three significant digits.
pub(crate) fn ms(d: Duration) -> String {
    let v = d.as_secs_f64() * 1e3;
    if v >= 100.0 {
        format!("{v:.0}")
    } else if v >= 10.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    }
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
    }

    #[test]
    fn median_and_formats() {
        let d = |ms| Duration::from_millis(ms);
        assert_eq!(median(vec![d(5), d(1), d(3)]), d(3), "odd count");
        assert_eq!(median(vec![d(4), d(1), d(3), d(2)]), d(2), "even count: lower middle");
        assert_eq!(median(Vec::new()), Duration::ZERO, "empty");
        assert_eq!(ms(Duration::from_micros(1234)), "1.23", "ms");
        assert_eq!(ms(Duration::from_millis(250)), "250", "ms");
        assert_eq!(ratio(d(30), d(10)), "3.00×", "ratio");
        assert_eq!(ratio(d(300), d(10)), "30×", "ratio");
    }
}
