// SPDX-License-Identifier: MIT
//! `hi fit`: a harmonic surface fitted to each part of a scan through a geometry image (§5.3,
//! §5.4, §5.8), with a progress bar, a summary, and warnings naming what the fit changed or
//! could not reach; or, with `--out-dir`, a batch of scans fitted in parallel with one JSON line
//! each in `summary.jsonl`. The pipeline, the warnings, the summary and the batch are
//! `hi-fit`'s, which the Python package shares; this module reads the command line, draws the
//! progress and writes `--bezier` patches. `--param sections` goes to algorithm 1 instead
//! ([`super::fit_sections`]).

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_fit::batch::{self, BatchOptions, Record, Status};
use hi_fit::{OutputFormat, fit_scan, read_scan, save_parts, summary, warnings, write_outputs};
use hi_geomimage::fit::{Boundary, Progress};
use hi_geomimage::regularise::Regularisation;
use hi_geomimage::{ErrorMeasure, Fit, FitOptions, Layout, Method, Smoothing};
use hi_mesh::export::MeshFormat;
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;

use crate::cli::{FitArgs, FormatName, MethodName, ParamName};
use crate::commands::surface_bezier;
use crate::commands::surface_example::write_file;
use crate::error::{Failure, stderr_line};
use crate::output::{Json, check_writable, json};

/// Samples per patch side in the mesh of `--bezier`.
const BEZIER_SAMPLES: usize = 4;

/// A `hi-fit` error as a failure of `hi`: its message, one line.
fn failure(e: hi_fit::Error) -> Failure {
    Failure::input(e.to_string())
}

/// The progress bar on a terminal (hidden otherwise): the parts (or scans) done of all, and
/// what is being done.
fn progress_bar(unit: &str) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(1);
    if let Ok(style) = ProgressStyle::with_template(&format!(
        "{{spinner}} {{elapsed}} [{{bar:24}}] {{pos}}/{{len}} {unit} · {{msg}}"
    )) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.enable_steady_tick(std::time::Duration::from_millis(100));
    bar
}

/// The fit's options from the command line.
fn options(args: &FitArgs, layout: Layout) -> Result<FitOptions, Failure> {
    let centre = match &args.centre {
        None => None,
        Some(list) => match list.0[..] {
            [x, y, z] => Some(DVec3::new(x, y, z)),
            _ => return Err(Failure::input("--centre: expected three numbers x,y,z")),
        },
    };
    // --smooth 0: the thesis's interpolation, with no smoothing or regularisation at all.
    let interpolate = args.smooth == Some(0.0);
    if interpolate && args.regularise.is_some_and(|r| r != Regularisation::Off) {
        return Err(Failure::input("--smooth 0 interpolates: it takes no --regularise"));
    }
    Ok(FitOptions {
        method: match args.method {
            MethodName::Auto => Method::Auto,
            MethodName::Mesh => Method::Mesh,
            MethodName::ShrinkWrap => Method::ShrinkWrap,
            MethodName::Radial => Method::Radial,
            MethodName::Contours => Method::Contours,
        },
        layout,
        resolution: args.resolution.map(|s| (s.0, s.1)),
        boundary: if args.closed {
            Boundary::Closed
        } else if args.open {
            Boundary::Open
        } else {
            Boundary::Auto
        },
        centre,
        smoothing: args.smooth.filter(|&s| s != 0.0).map(|sigma| Smoothing::Gaussian { sigma }),
        regularisation: if interpolate {
            Regularisation::Off
        } else {
            args.regularise.unwrap_or(Regularisation::Auto)
        },
        reduce: args.reduce,
        error: if args.no_error {
            ErrorMeasure::Off
        } else if args.exact_error {
            ErrorMeasure::Exact
        } else {
            ErrorMeasure::Fast
        },
        ..FitOptions::default()
    })
}

/// Fits, writes the surfaces and returns the summary (also written to `--report`); with
/// `--out-dir`, the batch ([`run_batch`]).
///
/// # Errors
///
/// [`Failure::Input`] for an unreadable or malformed scan (with its line or byte), bad
/// options, an unknown output extension, or an output that cannot be written.
pub(crate) fn run(args: &FitArgs) -> Result<Json, Failure> {
    if !args.bezier && (args.tolerance.is_some() || args.bezier_scheme.is_some()) {
        return Err(Failure::input("--tolerance and --bezier-scheme apply with --bezier only"));
    }
    let (scan_path, output) = match (&args.out_dir, &args.scans[..], &args.output) {
        (Some(dir), _, _) => return run_batch(args, dir),
        (None, _, _) if args.format.is_some() || args.force || args.jobs.is_some() => {
            return Err(Failure::input("--format, --force and --jobs apply with --out-dir only"));
        }
        (None, [scan], Some(output)) => (scan.as_path(), output.as_path()),
        (None, _, _) => {
            return Err(Failure::input(
                "-o fits one scan: give one SCAN, or --out-dir DIR for several",
            ));
        }
    };
    let layout = match layout(args)? {
        Some(layout) => layout,
        None => return super::fit_sections::run(args, scan_path, output),
    };
    if args.slices.is_some() {
        return Err(Failure::input("--slices applies to --param sections only"));
    }
    let ext = output.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let as_grid = ext.as_deref() == Some("json");
    if !as_grid {
        MeshFormat::try_from_path(output)
            .map_err(|e| Failure::input(format!("-o: {e} (or .json for the surface's grid)")))?;
    }
    check_writable(output, "-o")?;
    if let Some(report) = &args.report {
        check_writable(report, "--report")?;
    }
    let options = options(args, layout)?;
    let bar = progress_bar("parts");
    bar.set_message("reading the scan");
    let scan = read_scan(scan_path).map_err(failure)?;
    let name = scan_path.display().to_string();
    let result = fit_scan(&scan, &name, &options, &mut |p: Progress| {
        bar.set_length(p.parts as u64);
        bar.set_position(p.part as u64);
        bar.set_message(p.stage.name());
    });
    bar.finish_and_clear();
    let mut fitted = result.map_err(failure)?;
    for warning in warnings(&fitted, &name) {
        eprintln!("{}", stderr_line(&warning));
    }
    let mut bezier_report = None;
    let files: Vec<PathBuf> = if args.bezier {
        let (files, report) =
            write_bezier(args, (scan_path, output), &fitted, ext.as_deref(), as_grid)?;
        bezier_report = Some(report.into_raw());
        files
    } else {
        let format = OutputFormat::from_path(output).map_err(failure)?;
        write_outputs(&mut fitted, &name, output, format).map_err(failure)?
    };
    let summary = json(&summary(&name, &fitted, &files, bezier_report))?;
    if let Some(path) = &args.report {
        write_file(path, &summary, true)?;
    }
    Ok(summary)
}

/// `hi fit SCAN... --out-dir DIR`: every scan fitted into `DIR` ([`hi_fit::batch`]) with one
/// progress bar, each failure on stderr as it happens; the output is the count of scans done,
/// skipped and failed, and the run fails (exit status 2) when any scan did.
fn run_batch(args: &FitArgs, dir: &Path) -> Result<Json, Failure> {
    if args.param == ParamName::Sections {
        return Err(Failure::input(
            "--out-dir fits by geometry images: it takes no --param sections",
        ));
    }
    let layout = layout(args)?.unwrap_or(Layout::FlatOctahedron);
    let scans = batch::expand(&args.scans).map_err(failure)?;
    let format = match args.format.unwrap_or(FormatName::Glb) {
        FormatName::Glb => OutputFormat::Glb,
        FormatName::Gltf => OutputFormat::Gltf,
        FormatName::Obj => OutputFormat::Obj,
        FormatName::Json => OutputFormat::Json,
    };
    let cores = std::thread::available_parallelism().map_or(1, std::num::NonZero::get);
    let options = BatchOptions {
        format,
        force: args.force,
        jobs: args.jobs.unwrap_or(cores).max(1),
        fit: options(args, layout)?,
    };
    let bar = progress_bar("scans");
    bar.set_length(scans.len() as u64);
    bar.set_message("fitting");
    let on_done = |record: &Record, finished: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(finished as u64);
        bar.set_message(record.input.clone());
        if let Some(error) = &record.error {
            bar.suspend(|| eprintln!("{}", stderr_line(&format!("failed: {error}"))));
        }
    };
    let outcome = batch::run(&scans, dir, &options, &on_done).map_err(failure)?;
    bar.finish_and_clear();
    let failed = outcome.failed();
    #[derive(Serialize)]
    struct BatchOut {
        out_dir: String,
        summary: String,
        fitted: usize,
        skipped: usize,
        failed: usize,
        failures: Vec<String>,
    }
    let out = json(&BatchOut {
        out_dir: dir.display().to_string(),
        summary: dir.join(batch::SUMMARY_FILE).display().to_string(),
        fitted: outcome.records.len() - failed,
        skipped: outcome.skipped.len(),
        failed,
        failures: outcome
            .records
            .iter()
            .filter(|r| r.status == Status::Failed)
            .map(|r| r.input.clone())
            .collect(),
    })?;
    if failed > 0 {
        // The counts on stdout still, and the exit status says that some failed.
        return Err(Failure::Batch { output: out, failed });
    }
    Ok(out)
}

/// The layout of `--param`, or `None` for `--param sections` (algorithm 1, no geometry image),
/// after checking that no option of the other kind is given.
fn layout(args: &FitArgs) -> Result<Option<Layout>, Failure> {
    let only_images = |what: &str| {
        Err(Failure::input(format!(
            "{what} to the geometry-image layouts (--param sphere, octahedron or flat-octahedron)"
        )))
    };
    match args.param {
        ParamName::Sphere => Ok(Some(Layout::Sphere)),
        ParamName::Octahedron => Ok(Some(Layout::Octahedron)),
        ParamName::FlatOctahedron => Ok(Some(Layout::FlatOctahedron)),
        ParamName::Sections if args.bezier => only_images("--bezier applies"),
        ParamName::Sections if args.method != MethodName::Auto => only_images("--method applies"),
        ParamName::Sections if args.closed || args.open => only_images("--closed and --open apply"),
        ParamName::Sections => Ok(None),
    }
}

/// `--bezier`: each part's surface as Bézier patches, written as JSON or OBJ (one part) or as a
/// mesh of the patches of one cover of each part; the files and the report of the largest.
fn write_bezier(
    args: &FitArgs,
    (scan, output): (&Path, &Path),
    fitted: &Fit,
    ext: Option<&str>,
    as_grid: bool,
) -> Result<(Vec<PathBuf>, Json), Failure> {
    let start = std::time::Instant::now();
    let scheme = args.bezier_scheme.unwrap_or(BezierScheme::Hermite(HermiteDegree::Cubic));
    let tolerance = args
        .tolerance
        .map_or(hi_curve::bezier::DEFAULT_TOLERANCE, hi_curve::bezier::Tolerance::Absolute);
    let all = fitted
        .parts
        .iter()
        .map(|p| p.surface.to_bezier(scheme, tolerance))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| Failure::input(format!("--bezier: {e}")))?;
    let seconds = start.elapsed().as_secs_f64();
    // The patches of one cover of each part.
    let once: Vec<Vec<usize>> = all
        .iter()
        .zip(&fitted.parts)
        .map(|(patches, part)| {
            let w = part.domain.covering_window();
            (0..patches.patches.len())
                .filter(|&i| {
                    let p = patches.window(i);
                    p.u.start >= w.u.start - 1e-12
                        && p.u.end <= w.u.end + 1e-12
                        && p.v.start >= w.v.start - 1e-12
                        && p.v.end <= w.v.end + 1e-12
                })
                .collect()
        })
        .collect();
    let name = scheme.name();
    let report = BezierOut {
        report: surface_bezier::Report { scheme: name, report: &all[0].report },
        seconds,
        patches_once: once.iter().map(Vec::len).sum(),
    };
    let several = all.len() > 1;
    let files = if (as_grid || ext == Some("obj")) && several {
        return Err(Failure::input(format!(
            "--bezier writes one surface's patches to .json or .obj, and {} has {} parts: write a .glb or .gltf scene",
            scan.display(),
            all.len()
        )));
    } else if as_grid {
        let file = surface_bezier::patches_json(name, &all[0], &report)?;
        write_file(output, &file, false)?;
        vec![output.to_owned()]
    } else if ext == Some("obj") {
        surface_bezier::write_obj(&all[0], &once[0], output)?;
        vec![output.to_owned()]
    } else {
        let meshes = all
            .iter()
            .zip(&once)
            .map(|(patches, once)| patches.to_triangle_mesh_of(BEZIER_SAMPLES, once))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| Failure::input(format!("--bezier: {e}")))?;
        save_parts(fitted, &meshes, output).map_err(failure)?
    };
    Ok((files, json(&report)?))
}

/// The report of `--bezier`: the conversion's, its time and the patches written.
#[derive(Serialize)]
struct BezierOut<'a> {
    #[serde(flatten)]
    report: surface_bezier::Report<'a>,
    seconds: f64,
    patches_once: usize,
}
