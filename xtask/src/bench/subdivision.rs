// SPDX-License-Identifier: MIT
//! `cargo xtask bench subdivision`: one step of each subdivision scheme of §4.5 on a closed
//! mesh of at least 100 000 faces, ours against `OpenMesh`'s command-line subdivider and CGAL's
//! `Subdivision_method_3` (the program `fixtures/subdivision/cgal_subdiv.cpp`, built here with
//! `-O2`), in the same run.
//!
//! The inputs are those of the criterion bench `crates/hi-mesh/benches/subdivision.rs`: the
//! star after five Loop steps and two √3 steps (221 184 triangles) and the star after seven
//! Catmull-Clark steps (294 912 quads). Our time is one in-memory step, building the new
//! half-edge mesh included; each peer reads the same mesh from an OFF file and prints the time
//! of its subdivision call alone (`OpenMesh`: "Done [..]", the CGAL program: "seconds=..").
//!
//! How the cost grows: one Loop step (ours, `OpenMesh`, CGAL) and one Catmull-Clark step (ours,
//! CGAL) on the star refined 2 … 6 times, plotted against the face count on log axes
//! (`docs/perf-subdivision.svg`).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

use anyhow::{Context, Result, bail, ensure};
use hi_mesh::subdivision::{LoopWeights, PolyMesh, Scheme};
use indicatif::ProgressBar;

use super::{
    Growth, Headline, Section, growth_plot, machine, median, median_time, ms, output_line,
    progress_bar, ratio, table,
};

/// Timed runs of our step (after a warm-up).
const OUR_RUNS: usize = 5;
/// Runs of each peer (the median of their printed times).
const PEER_RUNS: usize = 3;

/// A peer program.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Peer {
    /// `OpenMesh-commandlineSubdivider` (Debian `libopenmesh-apps`).
    OpenMesh,
    /// `cgal_subdiv.cpp` against CGAL (Debian `libcgal-dev`).
    Cgal,
}

impl Peer {
    /// The peer's name in the report.
    fn name(self) -> &'static str {
        match self {
            Peer::OpenMesh => "OpenMesh",
            Peer::Cgal => "CGAL",
        }
    }

    /// The peer's name for `scheme`, or `None` if it has no such scheme.
    fn method(self, scheme: Scheme) -> Option<&'static str> {
        match (self, scheme) {
            (Peer::OpenMesh, Scheme::Loop(LoopWeights::Loop)) => Some("-l"),
            (Peer::OpenMesh, Scheme::Butterfly) => Some("-B"),
            (Peer::OpenMesh, Scheme::Sqrt3) => Some("-s"),
            (Peer::OpenMesh, Scheme::InterpolatingSqrt3) => Some("-b"),
            (Peer::Cgal, Scheme::Loop(LoopWeights::Loop)) => Some("loop"),
            (Peer::Cgal, Scheme::Sqrt3) => Some("sqrt3"),
            (Peer::Cgal, Scheme::CatmullClark) => Some("cc"),
            (Peer::Cgal, Scheme::DooSabin) => Some("ds"),
            _ => None,
        }
    }
}

/// What became of one peer on one job.
#[derive(Clone, Debug)]
enum Outcome {
    /// The median of the times the peer printed.
    Time(Duration),
    /// The peer has no such scheme.
    NoScheme,
    /// The peer is not installed.
    Absent,
    /// The peer ran and failed; the reason.
    Failed(String),
}

/// The time a peer printed: `OpenMesh`'s "Done [8.290cs]" or the CGAL program's "seconds=0.25".
fn parse_time(peer: Peer, stdout: &str) -> Option<Duration> {
    let secs = match peer {
        Peer::OpenMesh => {
            let inner = stdout.split("Done [").nth(1)?.split(']').next()?.trim();
            let split = inner.find(|c: char| c.is_ascii_alphabetic() || c == 'µ')?;
            let (value, unit) = inner.split_at(split);
            let scale = match unit {
                "s" => 1.0,
                "cs" => 1e-2,
                "ms" => 1e-3,
                "us" | "µs" => 1e-6,
                _ => return None,
            };
            value.trim().parse::<f64>().ok()? * scale
        }
        Peer::Cgal => stdout.split("seconds=").nth(1)?.split_whitespace().next()?.parse().ok()?,
    };
    (secs.is_finite() && secs >= 0.0).then(|| Duration::from_secs_f64(secs))
}

/// `program` found on `PATH`.
fn on_path(program: &str) -> Option<PathBuf> {
    std::env::split_paths(&std::env::var_os("PATH")?).map(|d| d.join(program)).find(|p| p.is_file())
}

/// Builds the CGAL program with `-O2 -DNDEBUG` into `dir`; `None` if g++ or CGAL is missing.
fn build_cgal(root: &Path, dir: &Path) -> Option<PathBuf> {
    let exe = dir.join("cgal_subdiv_o2");
    let src = root.join("fixtures/subdivision/cgal_subdiv.cpp");
    let status = Command::new("g++")
        .args(["-O2", "-DNDEBUG", "-std=c++17"])
        .arg(&src)
        .arg("-o")
        .arg(&exe)
        .status()
        .ok()?;
    status.success().then_some(exe)
}

/// Runs `peer` `PEER_RUNS` times on `input` and returns the median printed time.
fn run_peer(peer: Peer, exe: Option<&Path>, scheme: Scheme, input: &Path, dir: &Path) -> Outcome {
    let Some(method) = peer.method(scheme) else { return Outcome::NoScheme };
    let Some(exe) = exe else { return Outcome::Absent };
    let mut times = Vec::with_capacity(PEER_RUNS);
    for _ in 0..PEER_RUNS {
        let mut cmd = Command::new(exe);
        match peer {
            Peer::OpenMesh => cmd.args([method, "1"]).arg(input).arg(dir.join("openmesh-out.obj")),
            Peer::Cgal => cmd.args([method, "1"]).arg(input).arg(dir.join("cgal-out.off")),
        };
        let out = match cmd.output() {
            Ok(out) => out,
            Err(e) => return Outcome::Failed(e.to_string()),
        };
        let stdout = String::from_utf8_lossy(&out.stdout);
        if !out.status.success() {
            let stderr = String::from_utf8_lossy(&out.stderr);
            return Outcome::Failed(format!("exit {}: {}", out.status, stderr.trim()));
        }
        match parse_time(peer, &stdout) {
            Some(t) => times.push(t),
            None => return Outcome::Failed("no time in its output".to_owned()),
        }
    }
    Outcome::Time(median(times))
}

/// The inputs: (label, mesh).
fn inputs() -> Result<[(String, PolyMesh); 2]> {
    let tri = Scheme::Loop(LoopWeights::Loop).steps(&PolyMesh::star(), 5)?;
    let tri = Scheme::Sqrt3.steps(&tri, 2)?;
    let quad = Scheme::CatmullClark.steps(&PolyMesh::star(), 7)?;
    ensure!(tri.n_faces() >= 100_000 && quad.n_faces() >= 100_000, "the inputs are too small");
    Ok([(format!("{} triangles", tri.n_faces()), tri), (format!("{} quads", quad.n_faces()), quad)])
}

/// The two extra rows of Table 4.1, without peers: one step of harmonic tensor-product
/// subdivision (§5.2) of a 256×256 grid (to 512×512, by FFT along both axes) and the B-spline
/// fit (§4.4) of 256 closed slices of 256 points with uniform parameters, and of 64 slices of 64
/// points with chord-length parameters (whose merged knot vectors grow with the slices).
fn extra_rows() -> Result<Vec<Vec<String>>> {
    use glam::DVec3;
    use hi_compare::bspline_fit::{BSplineFit, BSplineFitOptions, Parameters};
    use hi_surface::HarmonicSurface;
    let m = 256;
    let point = |j: usize, k: usize| {
        let (u, v) = (j as f64 / m as f64, k as f64 / m as f64);
        let (tu, tv) = (std::f64::consts::TAU * u, std::f64::consts::TAU * v);
        let r = 1.0 + 0.2 * (5.0 * tu).sin() * (3.0 * tv).cos();
        DVec3::new((3.0 + r * tv.cos()) * tu.cos(), (3.0 + r * tv.cos()) * tu.sin(), r * tv.sin())
    };
    let rows: Vec<Vec<DVec3>> = (0..m).map(|j| (0..m).map(|k| point(j, k)).collect()).collect();
    let surface = HarmonicSurface::new(rows.clone());
    let harmonic = median_time(OUR_RUNS, || {
        std::hint::black_box(surface.subdivide(1)?);
        Ok(())
    })?;
    // Uniform parameters: one knot vector for every slice. With chord length every slice
    // brings its own knots and the merged U-knot vector (§4.4, step 2) holds them all: a
    // smaller case shows that cost.
    let uniform = BSplineFitOptions {
        closed_u: true,
        closed_v: true,
        u_params: Parameters::Uniform,
        v_params: Parameters::Uniform,
        ..Default::default()
    };
    let bspline = median_time(OUR_RUNS, || {
        std::hint::black_box(BSplineFit::try_new(rows.clone(), &uniform)?);
        Ok(())
    })?;
    let small: Vec<Vec<DVec3>> =
        (0..m).step_by(4).map(|j| (0..m).step_by(4).map(|k| point(j, k)).collect()).collect();
    let chord = BSplineFitOptions { closed_u: true, closed_v: true, ..Default::default() };
    let merged = BSplineFit::try_new(small.clone(), &chord)?.surface().n_control();
    let bspline_chord = median_time(OUR_RUNS, || {
        std::hint::black_box(BSplineFit::try_new(small.clone(), &chord)?);
        Ok(())
    })?;
    let none = || ["–".to_owned(), "–".to_owned(), "–".to_owned(), "–".to_owned()];
    let row = |name: &str, input: &str, t: Duration| {
        let mut r =
            vec![name.to_owned(), input.to_owned(), ms(t), format!("{:.1}", 1.0 / t.as_secs_f64())];
        r.extend(none());
        r
    };
    Ok(vec![
        row("harmonic subdivision (§5.2)", "256×256 grid → 512×512", harmonic),
        row("B-spline fit (§4.4), uniform parameters", "256 closed slices of 256 points", bspline),
        row(
            "B-spline fit (§4.4), chord length",
            &format!("64 closed slices of 64 points → {}×{} control net", merged.0, merged.1),
            bspline_chord,
        ),
    ])
}

/// Refinement levels of the star for the growth plot (faces grow 4× per level).
const GROWTH_LEVELS: std::ops::RangeInclusive<usize> = 2..=6;

/// One Loop step (ours, `OpenMesh`, CGAL) and one Catmull-Clark step (ours, CGAL) on the star
/// refined by the same scheme at each of [`GROWTH_LEVELS`], against the face count.
fn growth(
    dir: &Path,
    openmesh: Option<&Path>,
    cgal: Option<&Path>,
    bar: &ProgressBar,
) -> Result<Vec<Growth>> {
    let mut series = Vec::new();
    for scheme in [Scheme::Loop(LoopWeights::Loop), Scheme::CatmullClark] {
        let mut ours = Vec::new();
        let mut peers: Vec<(Peer, Vec<(f64, Duration)>)> = Vec::new();
        let mut mesh = scheme.steps(&PolyMesh::star(), *GROWTH_LEVELS.start())?;
        for level in GROWTH_LEVELS {
            if level > *GROWTH_LEVELS.start() {
                mesh = scheme.step(&mesh)?;
            }
            bar.set_message(format!("{} growth: {} faces", scheme.name(), mesh.n_faces()));
            let faces = mesh.n_faces() as f64;
            let t = median_time(OUR_RUNS, || {
                std::hint::black_box(scheme.step(&mesh)?);
                Ok(())
            })?;
            ours.push((faces, t));
            let file = dir.join(format!("growth-{level}.off"));
            mesh.save(&file)?;
            for (peer, exe) in [(Peer::OpenMesh, openmesh), (Peer::Cgal, cgal)] {
                if let Outcome::Time(t) = run_peer(peer, exe, scheme, &file, dir) {
                    match peers.iter_mut().find(|(p, _)| *p == peer) {
                        Some((_, points)) => points.push((faces, t)),
                        None => peers.push((peer, vec![(faces, t)])),
                    }
                }
            }
            bar.inc(1);
        }
        series.push(Growth { name: format!("{} (ours)", scheme.name()), points: ours });
        for (peer, points) in peers {
            series.push(Growth { name: format!("{} ({})", scheme.name(), peer.name()), points });
        }
    }
    Ok(series)
}

/// Measures every scheme and returns the report's section.
pub(super) fn run(root: &Path) -> Result<Section> {
    let dir = root.join("target/xtask-bench/subdivision");
    std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    let inputs = inputs()?;
    let mut files = Vec::new();
    for (i, (_, mesh)) in inputs.iter().enumerate() {
        let path = dir.join(format!("input{i}.off"));
        mesh.save(&path)?;
        files.push(path);
    }
    let openmesh = on_path("OpenMesh-commandlineSubdivider");
    let cgal = build_cgal(root, &dir);
    let openmesh_version =
        output_line("dpkg-query", &["-W", "-f", "${Version}", "libopenmesh-apps"]);
    let cgal_version = output_line("dpkg-query", &["-W", "-f", "${Version}", "libcgal-dev"]);

    let jobs: Vec<(Scheme, usize)> = Scheme::ALL
        .iter()
        .flat_map(|&s| {
            let polygons = matches!(s, Scheme::CatmullClark | Scheme::DooSabin);
            let which: &[usize] = if polygons { &[0, 1] } else { &[0] };
            which.iter().map(move |&i| (s, i))
        })
        .collect();
    let bar = progress_bar(jobs.len() as u64 + 2 * GROWTH_LEVELS.count() as u64)?;
    let mut rows = Vec::new();
    let mut headlines = Vec::new();
    for &(scheme, i) in &jobs {
        let (label, mesh) = &inputs[i];
        bar.set_message(format!("{} on {label}", scheme.name()));
        let peers = [(Peer::OpenMesh, openmesh.as_deref()), (Peer::Cgal, cgal.as_deref())];
        let row = scheme_row(scheme, i, (label, mesh), &files[i], &dir, peers, &mut headlines)?;
        rows.push(row);
        bar.inc(1);
    }
    bar.set_message("harmonic subdivision and the B-spline fit");
    rows.extend(extra_rows()?);
    let series = growth(&dir, openmesh.as_deref(), cgal.as_deref(), &bar)?;
    bar.finish_and_clear();
    let plot = growth_plot(
        root,
        "perf-subdivision.svg",
        "One subdivision step against mesh size",
        "faces",
        &series,
    )?;
    if rows.is_empty() {
        bail!("nothing was measured");
    }
    let body = body(openmesh_version.as_deref(), cgal_version.as_deref(), &rows, &plot);
    Ok(Section { body, headlines, sub_headlines: Vec::new() })
}

/// One row of the table: one step of `scheme` on input `i` (`label`, its mesh, saved as
/// `file`), ours and each of `peers`; the headlines (Loop against both peers, Catmull-Clark on
/// quads against CGAL) added to `headlines`.
fn scheme_row(
    scheme: Scheme,
    i: usize,
    (label, mesh): (&str, &PolyMesh),
    file: &Path,
    dir: &Path,
    peers: [(Peer, Option<&Path>); 2],
    headlines: &mut Vec<Headline>,
) -> Result<Vec<String>> {
    let ours = median_time(OUR_RUNS, || {
        std::hint::black_box(scheme.step(mesh)?);
        Ok(())
    })?;
    let per_second = 1.0 / ours.as_secs_f64();
    let mut row =
        vec![scheme.name().to_owned(), label.to_owned(), ms(ours), format!("{per_second:.1}")];
    for (peer, exe) in peers {
        match run_peer(peer, exe, scheme, file, dir) {
            Outcome::Time(t) => {
                // The headlines: Loop against both peers, Catmull-Clark on quads against CGAL.
                let headline = matches!(scheme, Scheme::Loop(LoopWeights::Loop))
                    || (scheme == Scheme::CatmullClark && i == 1);
                if headline {
                    headlines.push(Headline {
                        what: format!("one {} step, {label}", scheme.name()),
                        ours,
                        peer: peer.name().to_owned(),
                        theirs: Some(t),
                    });
                }
                row.push(ms(t));
                row.push(ratio(t, ours));
            }
            Outcome::NoScheme => row.extend(["–".to_owned(), "–".to_owned()]),
            Outcome::Absent => row.extend(["not installed".to_owned(), "–".to_owned()]),
            Outcome::Failed(why) => {
                row.extend([format!("failed: {}", why.replace('|', "/")), "–".to_owned()]);
            }
        }
    }
    Ok(row)
}

/// The section's text around its table of `rows` and its growth `plot`, with the peers'
/// versions.
fn body(
    openmesh_version: Option<&str>,
    cgal_version: Option<&str>,
    rows: &[Vec<String>],
    plot: &str,
) -> String {
    let header = [
        "scheme",
        "input",
        "ours (ms / step)",
        "ours (steps / s)",
        "OpenMesh (ms)",
        "OpenMesh / ours",
        "CGAL (ms)",
        "CGAL / ours",
    ];
    format!(
        "## Subdivision (§4.5, Table 4.1)\n\n\
         One step of each scheme on a closed mesh of at least 100 000 faces: the star \
         (`PolyMesh::star`) after five Loop and two √3 steps, and after seven Catmull-Clark steps. \
         Ours: `hi_mesh::subdivision`, one step in memory, the new half-edge mesh built (its \
         adjacency derived from the old mesh's by index arithmetic, no sort; a test checks it \
         against the general builder, which pairs half-edges by sorting and validates), one thread, median of {OUR_RUNS} runs. Peers, median of {PEER_RUNS} runs of \
         the time they print for the subdivision call alone: `OpenMesh-commandlineSubdivider` \
         (OpenMesh {}), CGAL `Subdivision_method_3` (CGAL {}) through \
         `fixtures/subdivision/cgal_subdiv.cpp` built with `g++ -O2 -DNDEBUG`. \"–\": the peer \
         has no such scheme. The last three rows are the extra rows of Table 4.1 \
         (`docs/figures/README.md`), which has the counts and interpolation errors of every \
         scheme; their time is one step or one fit (rayon may use every core here). The thesis \
         gives no timings for subdivision.\n\n\
         Machine: {}.\n\n{}\n\
         How one step's time grows with the mesh: Loop on the star after 2 … 6 Loop steps, and \
         Catmull-Clark on the star after 2 … 6 Catmull-Clark steps (log axes):\n\n{plot}",
        openmesh_version.unwrap_or("not installed"),
        cgal_version.unwrap_or("not installed"),
        machine(),
        table(&header, rows)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peer_times_are_parsed() {
        let openmesh = "Subdivide 1 times with 'Uniform Loop'\n  Done [33.944cs]\n  #V 49154";
        assert_eq!(
            parse_time(Peer::OpenMesh, openmesh),
            Some(Duration::from_secs_f64(0.33944)),
            "centiseconds"
        );
        assert_eq!(
            parse_time(Peer::OpenMesh, "Done [1.5s]"),
            Some(Duration::from_secs_f64(1.5)),
            "seconds"
        );
        assert_eq!(
            parse_time(Peer::OpenMesh, "Done [12ms]"),
            Some(Duration::from_millis(12)),
            "ms"
        );
        assert_eq!(parse_time(Peer::OpenMesh, "Done [12 parsecs]"), None, "unknown unit");
        assert_eq!(
            parse_time(Peer::Cgal, "loop x1: V=50 F=96 seconds=9.8204e-05\n"),
            Some(Duration::from_secs_f64(9.8204e-05)),
            "CGAL"
        );
        assert_eq!(parse_time(Peer::Cgal, "loop x1: V=50 F=96\n"), None, "no time");
    }

    #[test]
    fn every_peer_scheme_is_one_the_peer_tests_compare() {
        // The peers must run the same scheme as ours (checked vertex by vertex in
        // hi-mesh's subdivision_peers test): Loop's β, not Warren's; no CC in OpenMesh.
        assert_eq!(Peer::OpenMesh.method(Scheme::Loop(LoopWeights::Warren)), None, "Warren");
        assert_eq!(Peer::OpenMesh.method(Scheme::CatmullClark), None, "no CC in OpenMesh");
        assert_eq!(Peer::Cgal.method(Scheme::Butterfly), None, "no butterfly in CGAL");
    }
}
