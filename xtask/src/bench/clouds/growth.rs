// SPDX-License-Identifier: MIT
//! How time and peak memory grow with the number of points, on the clouds of
//! [`GROWTH_MODEL`]: the headlines, the table and the two log–log plots.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use super::super::{Headline, Quantity, Series, log_log_plot, table};
use super::measure::{Measurement, RowResult};
use super::report::{count_name, mib, secs};
use super::{GROWTH_MODEL, Group, Outcome};

/// The headlines: `hi fit` against Poisson on each cloud of the table of [`GROWTH_MODEL`]
/// where both succeeded.
pub(super) fn headlines(results: &[RowResult<'_>]) -> Vec<Headline> {
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
    headlines
}

/// Writes the growth plots into `docs` and returns the growth subsection (its table and
/// plots); nothing with fewer than two clouds of [`GROWTH_MODEL`].
pub(super) fn growth(docs: &Path, results: &[RowResult<'_>]) -> Result<String> {
    let mut s = String::new();
    let growth: Vec<&RowResult<'_>> = {
        let mut g: Vec<_> = results
            .iter()
            .filter(|(c, ..)| {
                c.model == GROWTH_MODEL && matches!(c.group, Group::Cloud | Group::Growth)
            })
            .collect();
        g.sort_by_key(|(c, ..)| c.points);
        g
    };
    if growth.len() >= 2 {
        let mut tables = Vec::new();
        let mut plots = Vec::new();
        for quantity in [Quantity::Time, Quantity::PeakMemory] {
            plots.push(growth_plot(docs, &growth, quantity)?);
        }
        for (c, m, _) in &growth {
            tables.push(vec![count_name(c.points), growth_cell(&m.ours), growth_cell(&m.theirs)]);
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
    Ok(s)
}

/// Writes the log–log plot of `quantity` against the points of the `growth` rows into `docs`
/// (our failed runs as rings, left out of the fit); its Markdown.
fn growth_plot(docs: &Path, growth: &[&RowResult<'_>], quantity: Quantity) -> Result<String> {
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
        Series { name: "screened Poisson".to_owned(), points: ok(|m| &m.theirs), fitted: true },
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
        Quantity::PeakMemory => ("perf-fit-clouds-memory.svg", "Peak memory against cloud size"),
    };
    log_log_plot(docs, file, &format!("{title} ({GROWTH_MODEL})"), "points", quantity, &series)
}

/// A cell of the growth table: "12.3 s, 456 MiB (3 runs)", or how much a failed run cost.
fn growth_cell(o: &Outcome) -> String {
    match o {
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
    }
}
