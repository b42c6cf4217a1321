// SPDX-License-Identifier: MIT
//! `hi fit`: a harmonic surface fitted to a scan through a geometry image (§5.3, §5.4, §5.8),
//! with a progress display, a summary and a warning when the scan is not star-shaped;
//! `--param sections` goes to algorithm 1 instead ([`super::fit_sections`]).

use std::io::IsTerminal;
use std::path::PathBuf;

use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_geomimage::fit::mesh_oversample;
use hi_geomimage::layout_mesh::layout_mesh;
use hi_geomimage::regularise::Regularisation;
use hi_geomimage::scan::read_scan;
use hi_geomimage::{ErrorMeasure, FitOptions, Layout, Method, Smoothing, fit};
use hi_mesh::export::{self, MeshFormat};
use indicatif::{ProgressBar, ProgressStyle};

use crate::cli::{FitArgs, MethodName, ParamName};
use crate::commands::surface_bezier;
use crate::commands::surface_example::{grid_json, write_file};
use crate::error::{Failure, stderr_line};
use crate::output::{Json, Object};

/// Above this fraction of rays meeting the scan more than once, `hi fit` warns.
const NON_STAR_WARNING: f64 = 0.05;

/// Samples per patch side in the mesh of `--bezier`.
const BEZIER_SAMPLES: usize = 4;

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
    let ext = args.output.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let as_grid = ext.as_deref() == Some("json");
    if !as_grid {
        MeshFormat::from_path(&args.output)
            .map_err(|e| Failure::input(format!("-o: {e} (or .json for the surface's grid)")))?;
    }
    let centre = match &args.centre {
        None => None,
        Some(list) => match list.0[..] {
            [x, y, z] => Some(DVec3::new(x, y, z)),
            _ => return Err(Failure::input("--centre: expected three numbers x,y,z")),
        },
    };
    let scan = read_scan(&args.scan)
        .map_err(|e| Failure::input(format!("{}: {e}", args.scan.display())))?;
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
    let report = &fitted.report;
    if report.non_star_fraction > NON_STAR_WARNING {
        eprintln!(
            "{}",
            stderr_line(&format!(
                "warning: {:.1}% of the rays meet {} more than once: it is not star-shaped about the centre, and the surface follows its outermost shell there",
                100.0 * report.non_star_fraction,
                args.scan.display()
            ))
        );
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
        let (u0, u1) = options.layout.covering_window();
        let once = patches.patches_in([u0, u1]);
        let name = scheme.name();
        let mut report = surface_bezier::report_json(name, &patches.report);
        if let Json::Object(fields) = &mut report {
            fields.push(("seconds".to_owned(), Json::Number(seconds)));
            fields.push(("patches_once".to_owned(), Json::Count(once.len())));
        }
        bezier_report = Some(report.clone());
        if as_grid {
            write_file(&args.output, &surface_bezier::patches_json(name, &patches, report), false)?;
            vec![args.output.clone()]
        } else if ext.as_deref() == Some("obj") {
            surface_bezier::write_obj(&patches, &once, &args.output)?;
            vec![args.output.clone()]
        } else {
            let mesh = patches
                .to_triangle_mesh_of(BEZIER_SAMPLES, &once)
                .map_err(|e| Failure::input(format!("--bezier: {e}")))?;
            export::save(&mesh, &args.output)?
        }
    } else if as_grid {
        write_file(&args.output, &grid_json(&fitted.surface.rows()), false)?;
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
    let mut summary = summary(args, &fitted, &files);
    if let (Some(b), Json::Object(fields)) = (bezier_report, &mut summary) {
        fields.push(("bezier".to_owned(), b));
    }
    if let Some(path) = &args.report {
        write_file(path, &summary, true)?;
    }
    Ok(summary)
}

/// The summary of a fit as JSON.
fn summary(args: &FitArgs, fitted: &hi_geomimage::Fit, files: &[PathBuf]) -> Json {
    let r = &fitted.report;
    let stages = fitted
        .stages
        .iter()
        .map(|s| {
            Object::new()
                .field("name", Json::String(s.kind.name().to_owned()))
                .field("seconds", Json::Number(s.seconds))
                .build()
        })
        .collect();
    let reduction = r.reduction.map_or(Json::Null, |e| {
        Object::new()
            .field("max_deviation", Json::Number(e.max_deviation))
            .field("upper_bound", Json::Number(e.upper_bound))
            .build()
    });
    let errors = r.errors.as_ref().map_or(Json::Null, |d| {
        Object::new()
            .field("mean", Json::Number(d.mean))
            .field("rms", Json::Number(d.rms))
            .field("max", Json::Number(d.max))
            .field("diagonal", Json::Number(d.diagonal))
            .field("relative", Json::numbers(d.relative()))
            .build()
    });
    let hausdorff = r.hausdorff.as_ref().map_or(Json::Null, |h| {
        let diagonal = h.scan_to_surface.diagonal;
        Object::new()
            .field("distance", Json::Number(h.distance()))
            .field(
                "relative",
                Json::Number(if diagonal > 0.0 { h.distance() / diagonal } else { 0.0 }),
            )
            .field("scan_to_surface_max", Json::Number(h.scan_to_surface.max))
            .field("surface_to_scan_max", Json::Number(h.surface_to_scan.max))
            .build()
    });
    let row_points = r.row_points.map_or(Json::Null, |rp| {
        Object::new()
            .field("min", Json::Count(rp.min))
            .field("mean", Json::Number(rp.mean))
            .field("max", Json::Count(rp.max))
            .field("empty_rows", Json::Count(rp.empty_rows))
            .build()
    });
    let distances = |d: &hi_geomimage::distance::Distances| {
        Object::new()
            .field("mean", Json::Number(d.mean))
            .field("rms", Json::Number(d.rms))
            .field("max", Json::Number(d.max))
            .field("relative", Json::numbers(d.relative()))
            .build()
    };
    let both_ways = r.both_ways.as_ref().map_or(Json::Null, |e| {
        let diagonal = e.scan_to_surface.diagonal;
        Object::new()
            .field("scan_to_surface", distances(&e.scan_to_surface))
            .field("surface_to_scan", distances(&e.surface_to_scan))
            .field("filled_to_scan_max", Json::Number(e.filled_to_scan_max))
            .field(
                "filled_to_scan_max_relative",
                Json::Number(if diagonal > 0.0 { e.filled_to_scan_max / diagonal } else { 0.0 }),
            )
            .field("unreached_fraction", Json::Number(e.unreached_fraction))
            .field("diagonal", Json::Number(diagonal))
            .build()
    });
    let mesh = match &fitted.source {
        hi_geomimage::SourceImage::Mesh(m) => Object::new()
            .field("holes_filled", Json::Count(m.repair.holes))
            .field("hole_edges", Json::Count(m.repair.hole_edges))
            .field("parts", Json::Count(m.repair.components))
            .field("area_kept", Json::Number(m.area_kept))
            .field("welded_points", Json::Count(m.repair.welded_points))
            .field("dropped_triangles", Json::Count(m.repair.dropped_triangles))
            .field("reoriented_triangles", Json::Count(m.repair.reoriented_triangles))
            .field("split_vertices", Json::Count(m.repair.split_vertices))
            .field("stretch_efficiency", Json::Number(m.quality.stretch_efficiency))
            .field("levels", Json::Count(m.quality.levels))
            .build(),
        _ => Json::Null,
    };
    let regularisation = Object::new()
        .field("lambda", Json::Number(r.regularisation.lambda))
        .field("kept", Json::Number(r.regularisation.kept))
        .field("rms_change", Json::Number(r.regularisation.rms_change))
        .field("max_change", Json::Number(r.regularisation.max_change))
        .build();
    Object::new()
        .field("scan", Json::String(args.scan.display().to_string()))
        .field("method", Json::String(r.method.name().to_owned()))
        .field("method_reason", Json::String(r.method_reason.clone()))
        .field("points", Json::Count(r.points))
        .field("unused_points", Json::Count(r.unused_points))
        .field("image_points", Json::Count(r.image_points))
        .field("dropped_points", Json::Count(r.dropped_points))
        .field(
            "image",
            Json::Array(vec![
                Json::Count(fitted.source.image().rows()),
                Json::Count(fitted.source.image().cols()),
            ]),
        )
        .field(
            "surface",
            Json::Array(vec![Json::Count(r.surface_size.0), Json::Count(r.surface_size.1)]),
        )
        .field("non_star_fraction", Json::Number(r.non_star_fraction))
        .field("hole_fraction", Json::Number(r.hole_fraction))
        .field("row_points", row_points)
        .field("mesh", mesh)
        .field("regularisation", regularisation)
        .field("stages", Json::Array(stages))
        .field("reduction", reduction)
        .field("errors", errors)
        .field("both_ways", both_ways)
        .field("hausdorff", hausdorff)
        .field(
            "files",
            Json::Array(files.iter().map(|f| Json::String(f.display().to_string())).collect()),
        )
        .build()
}
