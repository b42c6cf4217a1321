// SPDX-License-Identifier: MIT
//! `hi fit`: a harmonic surface fitted to a scan through a geometry image (§5.3, §5.4, §5.8),
//! with a progress display, a summary and a warning when the scan is not star-shaped and the
//! surface could only follow its outermost shell;
//! `--param sections` goes to algorithm 1 instead ([`super::fit_sections`]).

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use glam::DVec3;
use hi_curve::ReductionError;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_geomimage::fit::{RowPoints, Stage, UNREACHED, mesh_oversample};
use hi_geomimage::layout_mesh::layout_mesh;
use hi_geomimage::regularise::{Regularisation, RegularisationReport};
use hi_geomimage::{ErrorMeasure, Fit, FitOptions, Layout, Method, Smoothing, SourceImage, fit};
use hi_mesh::export::{self, MeshFormat};
use hi_scan::scan::read_scan;
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;

use crate::cli::{FitArgs, MethodName, ParamName};
use crate::commands::fit_sections::DistancesOut;
use crate::commands::surface_bezier;
use crate::commands::surface_example::{grid_json, write_file};
use crate::error::{Failure, about_file, stderr_line};
use crate::output::{Json, check_writable, file_names, json};

/// Above this fraction of rays meeting the scan more than once, `hi fit` warns when its surface
/// follows the outermost shell the rays met ([`hi_geomimage::SourceImage::follows_outer_shell`]).
const NON_STAR_WARNING: f64 = 0.05;

/// Above this fraction of the scan's points left unreached by the surface (farther than
/// [`hi_geomimage::fit::UNREACHED`] of the diagonal from it), `hi fit` warns.
const UNREACHED_WARNING: f64 = 0.01;

/// Samples per patch side in the mesh of `--bezier`.
const BEZIER_SAMPLES: usize = 4;

/// The warnings of a fit of `scan`, one line each: rays that met several shells where the
/// surface follows the outermost one, and points of the scan the surface did not reach, with
/// the cause when the fit knows it.
fn warnings(fitted: &Fit, scan: &Path) -> Vec<String> {
    let report = &fitted.report;
    let mut lines = Vec::new();
    let outer_shell =
        fitted.source.follows_outer_shell() && report.non_star_fraction > NON_STAR_WARNING;
    if outer_shell {
        lines.push(format!(
            "warning: {:.1}% of the rays meet {} more than once: it is not star-shaped about the centre, and the surface follows its outermost shell there",
            100.0 * report.non_star_fraction,
            scan.display()
        ));
    }
    if let Some(errors) = &report.both_ways
        && errors.unreached_fraction > UNREACHED_WARNING
    {
        let cause = match &fitted.source {
            SourceImage::Mesh(m) if m.area_kept < 1.0 - 1e-9 => format!(
                ": only the largest part of the mesh was fitted ({:.1}% of its area)",
                100.0 * m.area_kept
            ),
            _ if outer_shell => ": they lie inside the outermost shell".to_owned(),
            SourceImage::ShrinkWrap(_) => {
                ": the wrap did not reach them (inner shells, separate parts, or parts thinner than its grid)"
                    .to_owned()
            }
            _ => String::new(),
        };
        lines.push(format!(
            "warning: {:.1}% of the points of {} are farther than {}% of the diagonal from the surface{cause}",
            100.0 * errors.unreached_fraction,
            scan.display(),
            100.0 * UNREACHED
        ));
    }
    lines
}

/// Fits, writes the surface and returns the summary (also written to `--report`).
///
/// # Errors
///
/// [`Failure::Input`] for an unreadable or malformed scan (with its line or byte), bad
/// options, an unknown output extension, or an output that cannot be written.
pub(crate) fn run(args: &FitArgs) -> Result<Json, Failure> {
    if !args.bezier && (args.tolerance.is_some() || args.bezier_scheme.is_some()) {
        return Err(Failure::input("--tolerance and --bezier-scheme apply with --bezier only"));
    }
    let layout = match args.param {
        ParamName::Sphere => Layout::Sphere,
        ParamName::Octahedron => Layout::Octahedron,
        ParamName::FlatOctahedron => Layout::FlatOctahedron,
        ParamName::Sections if args.bezier => {
            return Err(Failure::input(
                "--bezier applies to the geometry-image layouts (--param sphere, octahedron or flat-octahedron)",
            ));
        }
        ParamName::Sections if args.method != MethodName::Auto => {
            return Err(Failure::input(
                "--method applies to the geometry-image layouts (--param sphere, octahedron or flat-octahedron)",
            ));
        }
        ParamName::Sections => return super::fit_sections::run(args),
    };
    if args.slices.is_some() {
        return Err(Failure::input("--slices applies to --param sections only"));
    }
    let ext = args.output.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let as_grid = ext.as_deref() == Some("json");
    if !as_grid {
        MeshFormat::from_path(&args.output)
            .map_err(|e| Failure::input(format!("-o: {e} (or .json for the surface's grid)")))?;
    }
    check_writable(&args.output, "-o")?;
    if let Some(report) = &args.report {
        check_writable(report, "--report")?;
    }
    let centre = match &args.centre {
        None => None,
        Some(list) => match list.0[..] {
            [x, y, z] => Some(DVec3::new(x, y, z)),
            _ => return Err(Failure::input("--centre: expected three numbers x,y,z")),
        },
    };
    let scan = read_scan(&args.scan)
        .map_err(|e| Failure::input(about_file(&args.scan, &e.to_string())))?;
    // --smooth 0: the thesis's interpolation, with no smoothing or regularisation at all.
    let interpolate = args.smooth == Some(0.0);
    if interpolate && args.regularise.is_some_and(|r| r != Regularisation::Off) {
        return Err(Failure::input("--smooth 0 interpolates: it takes no --regularise"));
    }
    let options = FitOptions {
        method: match args.method {
            MethodName::Auto => Method::Auto,
            MethodName::Mesh => Method::Mesh,
            MethodName::ShrinkWrap => Method::ShrinkWrap,
            MethodName::Radial => Method::Radial,
            MethodName::Contours => Method::Contours,
        },
        layout,
        resolution: args.resolution.map(|s| (s.0, s.1)),
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
    };
    let bar = if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new_spinner();
        if let Ok(style) = ProgressStyle::with_template("{spinner} {elapsed} {msg}") {
            bar.set_style(style);
        }
        bar.enable_steady_tick(std::time::Duration::from_millis(100));
        bar
    } else {
        ProgressBar::hidden()
    };
    let result = fit(&scan, &options, &mut |stage| bar.set_message(stage.name()));
    bar.finish_and_clear();
    let mut fitted = result.map_err(|e| Failure::input(format!("{}: {e}", args.scan.display())))?;
    for warning in warnings(&fitted, &args.scan) {
        eprintln!("{}", stderr_line(&warning));
    }
    let mut bezier_report = None;
    let files: Vec<PathBuf> = if args.bezier {
        let start = std::time::Instant::now();
        let scheme = args.bezier_scheme.unwrap_or(BezierScheme::Hermite(HermiteDegree::Cubic));
        let patches = fitted
            .surface
            .to_bezier(
                scheme,
                args.tolerance.map_or(
                    hi_curve::bezier::DEFAULT_TOLERANCE,
                    hi_curve::bezier::Tolerance::Absolute,
                ),
            )
            .map_err(|e| Failure::input(format!("--bezier: {e}")))?;
        let seconds = start.elapsed().as_secs_f64();
        let u = options.layout.covering_window();
        let once = patches.patches_in(u);
        let name = scheme.name();
        let report = BezierOut {
            report: surface_bezier::Report { scheme: name, report: &patches.report },
            seconds,
            patches_once: once.len(),
        };
        let files = if as_grid {
            let file = surface_bezier::patches_json(name, &patches, &report)?;
            write_file(&args.output, &file, false)?;
            vec![args.output.clone()]
        } else if ext.as_deref() == Some("obj") {
            surface_bezier::write_obj(&patches, &once, &args.output)?;
            vec![args.output.clone()]
        } else {
            let mesh = patches
                .to_triangle_mesh_of(BEZIER_SAMPLES, &once)
                .map_err(|e| Failure::input(format!("--bezier: {e}")))?;
            export::save(&mesh, &args.output)?
        };
        bezier_report = Some(json(&report)?);
        files
    } else if as_grid {
        write_file(&args.output, &grid_json(&fitted.surface.rows())?, false)?;
        vec![args.output.clone()]
    } else {
        // The closed mesh the error was measured on, or the same made now.
        let mesh = match fitted.mesh.take() {
            Some(m) => m.mesh,
            None => {
                let per_texel = mesh_oversample(&fitted.surface);
                let per_texel = if layout == Layout::Octahedron {
                    per_texel.next_multiple_of(2)
                } else {
                    per_texel
                };
                layout_mesh(&fitted.surface, layout, per_texel)
                    .map_err(|e| Failure::input(format!("{}: {e}", args.scan.display())))?
                    .mesh
            }
        };
        export::save(&mesh, &args.output)?
    };
    let summary = summary(args, &fitted, &files, bezier_report)?;
    if let Some(path) = &args.report {
        write_file(path, &summary, true)?;
    }
    Ok(summary)
}

/// The report of `--bezier`: the conversion's, its time and the patches written.
#[derive(Serialize)]
struct BezierOut<'a> {
    #[serde(flatten)]
    report: surface_bezier::Report<'a>,
    seconds: f64,
    patches_once: usize,
}

/// What `hi fit` did to a mesh scan before parameterising it.
#[derive(Serialize)]
struct MeshOut {
    holes_filled: usize,
    hole_edges: usize,
    parts: usize,
    area_kept: f64,
    welded_points: usize,
    dropped_triangles: usize,
    reoriented_triangles: usize,
    split_vertices: usize,
    handles_cut: usize,
    stretch_efficiency: f64,
    levels: usize,
}

/// Both directions of the fit's error, as printed.
#[derive(Serialize)]
struct BothWaysOut {
    scan_to_surface: DistancesOut,
    surface_to_scan: DistancesOut,
    filled_to_scan_max: f64,
    filled_to_scan_max_relative: f64,
    unreached_fraction: f64,
    diagonal: f64,
}

/// The Hausdorff distance of an exact error measurement.
#[derive(Serialize)]
struct HausdorffOut {
    distance: f64,
    relative: f64,
    scan_to_surface_max: f64,
    surface_to_scan_max: f64,
}

/// The printed summary of `hi fit`.
#[derive(Serialize)]
struct Summary<'a> {
    scan: String,
    method: &'static str,
    method_reason: &'a str,
    points: usize,
    unused_points: usize,
    image_points: usize,
    dropped_points: usize,
    image: [usize; 2],
    surface: (usize, usize),
    non_star_fraction: f64,
    hole_fraction: f64,
    row_points: Option<&'a RowPoints>,
    mesh: Option<MeshOut>,
    regularisation: &'a RegularisationReport,
    stages: &'a [Stage],
    reduction: Option<&'a ReductionError>,
    errors: Option<DistancesOut>,
    both_ways: Option<BothWaysOut>,
    hausdorff: Option<HausdorffOut>,
    files: Vec<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    bezier: Option<Json>,
}

/// `x / d`, or 0 for an empty diagonal.
fn relative(x: f64, d: f64) -> f64 {
    if d > 0.0 { x / d } else { 0.0 }
}

/// The summary of a fit as JSON.
fn summary(
    args: &FitArgs,
    fitted: &Fit,
    files: &[PathBuf],
    bezier: Option<Json>,
) -> Result<Json, Failure> {
    let r = &fitted.report;
    let mesh = match &fitted.source {
        SourceImage::Mesh(m) => Some(MeshOut {
            holes_filled: m.repair.holes,
            hole_edges: m.repair.hole_edges,
            parts: m.repair.components,
            area_kept: m.area_kept,
            welded_points: m.repair.welded_points,
            dropped_triangles: m.repair.dropped_triangles,
            reoriented_triangles: m.repair.reoriented_triangles,
            split_vertices: m.repair.split_vertices,
            handles_cut: m.repair.handles_cut,
            stretch_efficiency: m.quality.stretch_efficiency,
            levels: m.quality.levels,
        }),
        _ => None,
    };
    let image = fitted.source.image();
    json(&Summary {
        scan: args.scan.display().to_string(),
        method: r.method.name(),
        method_reason: &r.method_reason,
        points: r.points,
        unused_points: r.unused_points,
        image_points: r.image_points,
        dropped_points: r.dropped_points,
        image: [image.rows(), image.cols()],
        surface: r.surface_size,
        non_star_fraction: r.non_star_fraction,
        hole_fraction: r.hole_fraction,
        row_points: r.row_points.as_ref(),
        mesh,
        regularisation: &r.regularisation,
        stages: &fitted.stages,
        reduction: r.reduction.as_ref(),
        errors: r.errors.as_ref().map(DistancesOut::of),
        both_ways: r.both_ways.as_ref().map(|e| {
            let diagonal = e.scan_to_surface.diagonal;
            BothWaysOut {
                scan_to_surface: DistancesOut::of(&e.scan_to_surface),
                surface_to_scan: DistancesOut::of(&e.surface_to_scan),
                filled_to_scan_max: e.filled_to_scan_max,
                filled_to_scan_max_relative: relative(e.filled_to_scan_max, diagonal),
                unreached_fraction: e.unreached_fraction,
                diagonal,
            }
        }),
        hausdorff: r.hausdorff.as_ref().map(|h| HausdorffOut {
            distance: h.distance(),
            relative: relative(h.distance(), h.scan_to_surface.diagonal),
            scan_to_surface_max: h.scan_to_surface.max,
            surface_to_scan_max: h.surface_to_scan.max,
        }),
        files: file_names(files),
        bezier,
    })
}
