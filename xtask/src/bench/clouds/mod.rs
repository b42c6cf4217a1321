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

mod figure;
mod growth;
mod inputs;
mod measure;
mod report;

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result};
use glam::DVec3;

use super::poisson;
use super::{Headline, Options};
use figure::figure;
use growth::{growth, headlines};
use inputs::cases;
use measure::{load_average, measure_all, run_once};
use report::{Conditions, intro, targets_met};

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
        name: "building",
        source: Source::Cgal("data/points_3/building.ply"),
        what: "point set with normals: a building's walls and roof, open below",
        eye: [1.0, -0.7, 0.8],
        up: [0.0, 0.0, 1.0],
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
    let results = measure_all(root, scale, &hi, &out, &cases, &bar)?;
    let load_after = load_average();
    let minutes = started.elapsed().as_secs_f64() / 60.0;
    let conditions = Conditions { floor, load_before, load_after, minutes };
    let mut s = intro(scale, options.small, &results, &conditions);
    s.push_str(&report::tables(root, scale, &results, &missing));
    s.push_str(&targets_met(&results));
    s.push_str(&figure(docs, &results)?);
    let headlines = headlines(&results);
    s.push_str(&growth(docs, &results)?);
    Ok((s, headlines))
}

#[cfg(test)]
mod tests {
    use super::super::poisson::Measured;
    use super::measure::{Measurement, error_line, median_f64};
    use super::report::{
        Verdicts, cell_text, count_name, load_note, mib, row, secs, shape_cell, timed_cell,
        topology_summary, verdict_cell, verdicts,
    };
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

    #[test]
    fn a_row_of_each_table_is_formatted_cell_by_cell() {
        let case = |group, label: &str, what: &str, points| Case {
            group,
            model: "bunny".to_owned(),
            label: label.to_owned(),
            stem: String::new(),
            what: what.to_owned(),
            ours_input: PathBuf::new(),
            peer_input: PathBuf::new(),
            reference: String::new(),
            points,
            eye: DVec3::Z,
            up: DVec3::Y,
        };
        let measured =
            |mean, back_p99, back_max| Measured { mean, back_p99, back_max, ..Measured::default() };
        let theirs = Outcome::Done { seconds: 10.0, peak_kib: 300.0 * 1024.0, runs: 1 };
        let m = Measurement {
            ours: Outcome::Done { seconds: 4.0, peak_kib: 200.0 * 1024.0, runs: 3 },
            theirs: theirs.clone(),
            ours_m: Some(measured(1e-4, 2e-4, 5e-4)),
            theirs_m: Some(measured(2e-4, 3e-4, 1e-3)),
            report: Some(serde_json::json!({"method": "radial"})),
            notes: vec!["ours: warning: x".to_owned()],
        };
        let root = Path::new("/somewhere/repo");
        let c = case(Group::Cloud, "bunny, 2·10⁵ points", "", 200_000);
        assert_eq!(
            row(root, &c, &m, false),
            [
                "bunny, 2·10⁵ points",
                "2·10⁵",
                "4.00 / 10.0 (once)",
                "✓ 2.50×",
                "200 / 300",
                "✓ 0.67×",
                "0.010 / 0.020",
                "✓ 0.50×",
                "0.020 / 0.030",
                "0.050 / 0.100",
                "radial",
                "ours: warning: x",
            ]
        );
        let failed = Measurement {
            ours: Outcome::Failed { message: "boom".to_owned(), seconds: 1.5, peak_kib: 1024.0 },
            theirs,
            ours_m: None,
            theirs_m: Some(measured(2e-4, 3e-4, 1e-3)),
            report: None,
            notes: Vec::new(),
        };
        let c = case(Group::Topology, "club", "mesh, one open sheet", 35_947);
        assert_eq!(
            row(root, &c, &failed, false),
            [
                "club",
                "mesh, one open sheet",
                "35\u{2009}947",
                "failed / 10.0 (once)",
                "✗",
                "failed / 300",
                "✗",
                "– / 0.020",
                "✗",
                "– / 0.030",
                "– / 0.100",
                "–",
                "–",
                "– / –",
                "ours failed after 1.50 s: boom",
            ]
        );
    }
}
