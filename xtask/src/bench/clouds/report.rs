// SPDX-License-Identifier: MIT
//! The report: numbers as table cells, the targets of each row, the rows of the tables, and
//! the text around them.

use std::fmt::Write as _;
use std::path::Path;

use serde_json::Value;

use super::super::poisson::{self, DEPTH, Measured};
use super::super::{machine, table};
use super::measure::{Measurement, RowResult};
use super::{BIG, CGAL_DATA, Case, Group, LONG, Outcome, RUNS, SEED, Scale, WARM_ENOUGH};

/// "2·10⁵" for a power of ten times a digit, else the number with thin spaces (12 345).
pub(super) fn count_name(n: usize) -> String {
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
pub(super) fn cell_text(message: &str, root: &Path) -> String {
    let prefix = format!("{}/", root.display());
    let one_line = message.replace(&prefix, "").replace('\n', " ").replace('|', "\\|");
    if one_line.chars().count() > 240 {
        format!("{}…", one_line.chars().take(239).collect::<String>())
    } else {
        one_line
    }
}

/// Seconds with three significant digits (whole seconds from 100 s).
pub(super) fn secs(s: f64) -> String {
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
pub(super) fn mib(kib: f64) -> String {
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
pub(super) struct Verdicts {
    /// Our whole command at least 2× faster than Poisson's.
    pub(super) speed: Option<bool>,
    /// Our peak memory no more than Poisson's.
    pub(super) memory: Option<bool>,
    /// Our mean scan→surface distance no more than Poisson's.
    pub(super) mean: Option<bool>,
}

/// What the targets compare of one side: (seconds, peak KiB, mean scan→surface distance if
/// measured).
pub(super) type Side = (f64, f64, Option<f64>);

/// The verdicts from (seconds, peak KiB, mean distance) of each side, `None` for a side that
/// failed: a failure of ours misses every target; one of Poisson's leaves nothing to compare.
pub(super) fn verdicts(ours: Option<Side>, theirs: Option<Side>) -> Verdicts {
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
pub(super) fn verdict_cell(met: Option<bool>, ratio: f64) -> String {
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
pub(super) fn topology_summary(report: &Value) -> String {
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
pub(super) fn shape_cell(m: Option<&Measured>) -> String {
    match m.and_then(|m| m.bodies.zip(m.euler)) {
        Some((b, e)) => format!("{b}, χ {e}"),
        None => "–".to_owned(),
    }
}

/// A time for a table: seconds, with "(once)" when a full run timed the command once.
pub(super) fn timed_cell(o: &Outcome, small: bool) -> Option<String> {
    match o {
        Outcome::Done { seconds, runs: 1, .. } if !small => {
            Some(format!("{} (once)", secs(*seconds)))
        }
        Outcome::Done { seconds, .. } => Some(secs(*seconds)),
        Outcome::Failed { .. } => None,
    }
}

/// One line of a table (`small`: every command was run once, so that goes unsaid).
pub(super) fn row(root: &Path, c: &Case, m: &Measurement, small: bool) -> Vec<String> {
    let scale_once = small;
    let (ours, theirs) = sides(m);
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

/// What the load averages at the start and end of a run say of its times, on a machine of
/// `cores` cores: nothing when both stay under one per core; else that the times, Poisson's
/// most, are inflated.
pub(super) fn load_note(before: f64, after: f64, cores: usize) -> &'static str {
    if before.max(after) > cores as f64 {
        " Other work shared the cores for at least part of the run, so every time here is longer \
         than on a quiet machine, and Poisson's most: pymeshlab's OpenMP threads wait for each \
         other by spinning, which an oversubscribed machine makes several times slower (the \
         speed-ups are then flattering to us)."
    } else {
        ""
    }
}

/// What the targets compare of each side of a row (`None` for a side that failed): ours, then
/// Poisson's.
fn sides(m: &Measurement) -> (Option<Side>, Option<Side>) {
    let side =
        |o: &Outcome, mm: Option<&Measured>| o.done().map(|(t, k)| (t, k, mm.map(|x| x.mean)));
    (side(&m.ours, m.ours_m.as_ref()), side(&m.theirs, m.theirs_m.as_ref()))
}

/// What the run met on the machine, for the text: the wrapper's own peak (KiB), the load
/// average at the start and at the end, and the minutes the run took.
pub(super) struct Conditions {
    pub(super) floor: f64,
    pub(super) load_before: f64,
    pub(super) load_after: f64,
    pub(super) minutes: f64,
}

/// The subsection's heading and its account of the inputs and the measurement (`small`: a
/// `--small` run), with the models given as bare vertices in `results`.
pub(super) fn intro(
    scale: &Scale,
    small: bool,
    results: &[RowResult<'_>],
    conditions: &Conditions,
) -> String {
    let Conditions { floor, load_before, load_after, minutes } = *conditions;
    let mut s = String::new();
    let scale_note = if small {
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
         use, no triangles), and so is every other mesh of the shared data and \
         `fixtures/models` (the teapot, the dragon, Hoppe's cessna, mechanical part and club, \
         the spider and the head scan: several parts, genus 3, an open sheet; as bare vertices \
         only). Both programs read the same XYZ file. The scans of other \
         topologies give `hi fit` the mesh file and Poisson the points its triangles use, as \
         above (a point set with normals, CGAL's kitten and building, goes to both as positions only; CGAL's \
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
        minutes,
        load_note(
            load_before,
            load_after,
            std::thread::available_parallelism().map_or(1, std::num::NonZero::get)
        ),
    );
    s
}

/// The three tables, each with its heading when it has rows (clouds, bare vertices, other
/// topologies), and the inputs not found.
pub(super) fn tables(
    root: &Path,
    scale: &Scale,
    results: &[RowResult<'_>],
    missing: &[String],
) -> String {
    let mut s = String::new();
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
    s
}

/// The line counting the targets met over the rows of the tables, and our failures.
pub(super) fn targets_met(results: &[RowResult<'_>]) -> String {
    let mut s = String::new();
    let all: Vec<Verdicts> = results
        .iter()
        .filter(|(c, ..)| c.group != Group::Growth)
        .map(|(_, m, _)| {
            let (ours, theirs) = sides(m);
            verdicts(ours, theirs)
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
    s
}
