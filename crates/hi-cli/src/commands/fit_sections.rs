// SPDX-License-Identifier: MIT
//! `hi fit --param sections`: algorithm 1 of §5.3 (cross-sections, a harmonic curve per
//! contour, insertion, rotation alignment, the reversed traversal), with its per-section
//! diagnostics and the measured problems printed as warnings.

use std::path::PathBuf;

use hi_geomimage::Stage;
use hi_geomimage::distance::Distances;
use hi_geomimage::scan::read_scan;
use hi_geomimage::sections::{ContourOrder, SectionFit, SectionOptions, SliceAxis, fit_sections};
use hi_mesh::export::{self, MeshFormat};
use hi_surface::MeshOptions;

use crate::cli::{AxisName, FitArgs, OrderName};
use crate::commands::surface_example::{grid_json, write_file};
use crate::error::{Failure, stderr_line};
use crate::output::{Json, Object};

/// Fits by algorithm 1, writes the surface and returns the summary (also written to
/// `--report`).
///
/// # Errors
///
/// [`Failure::Input`] for an unreadable scan, options that `hi fit --param sections` does not
/// take, an input algorithm 1 rejects (naming the section or point), an unknown output
/// extension, or an output that cannot be written.
pub(crate) fn run(args: &FitArgs) -> Result<Json, Failure> {
    let ext = args.output.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let as_grid = ext.as_deref() == Some("json");
    if !as_grid {
        MeshFormat::from_path(&args.output)
            .map_err(|e| Failure::input(format!("-o: {e} (or .json for the surface's grid)")))?;
    }
    for (given, name) in [
        (args.smooth.is_some(), "--smooth"),
        (args.reduce.is_some(), "--reduce"),
        (args.centre.is_some(), "--centre"),
    ] {
        if given {
            return Err(Failure::input(format!(
                "{name} is for the geometry images, not for --param sections"
            )));
        }
    }
    let scan = read_scan(&args.scan)
        .map_err(|e| Failure::input(format!("{}: {e}", args.scan.display())))?;
    let options = SectionOptions {
        axis: match args.axis {
            AxisName::X => SliceAxis::X,
            AxisName::Y => SliceAxis::Y,
            AxisName::Z => SliceAxis::Z,
            AxisName::Principal => SliceAxis::Principal,
        },
        slices: args.slices,
        order: match args.order {
            OrderName::Angular => ContourOrder::Angular,
            OrderName::Nearest => ContourOrder::NearestNeighbour,
        },
        ..SectionOptions::default()
    };
    let fitted = fit_sections(&scan.points, &options)
        .map_err(|e| Failure::input(format!("{}: {e}", args.scan.display())))?;
    for problem in &fitted.report.problems {
        eprintln!("{}", stderr_line(&format!("warning: {problem}")));
    }
    let files: Vec<PathBuf> = if as_grid {
        write_file(&args.output, &grid_json(&fitted.surface.rows()), false)?;
        vec![args.output.clone()]
    } else {
        let (u0, u1) = fitted.covering_window();
        let (m, n) = (fitted.surface.m(), fitted.surface.n());
        let mesh_options = MeshOptions {
            n_u: m.max(3),
            n_v: 2 * n,
            u_range: [u0, u1],
            v_range: [0.0, 1.0],
            ..MeshOptions::default()
        };
        let mesh = fitted.surface.to_mesh(&mesh_options)?;
        export::save(&mesh, &args.output)?
    };
    let summary = summary(args, &fitted, scan.dropped_points, &files);
    if let Some(path) = &args.report {
        write_file(path, &summary, true)?;
    }
    Ok(summary)
}

fn distances(d: Option<&Distances>) -> Json {
    d.map_or(Json::Null, |d| {
        Object::new()
            .field("mean", Json::Number(d.mean))
            .field("rms", Json::Number(d.rms))
            .field("max", Json::Number(d.max))
            .field("diagonal", Json::Number(d.diagonal))
            .field("relative", Json::numbers(d.relative()))
            .build()
    })
}

/// The summary of a fit by algorithm 1 as JSON.
fn summary(args: &FitArgs, fitted: &SectionFit, dropped: usize, files: &[PathBuf]) -> Json {
    let r = &fitted.report;
    let stages = fitted
        .stages
        .iter()
        .map(|s: &Stage| {
            Object::new()
                .field("name", Json::String(s.kind.name().to_owned()))
                .field("seconds", Json::Number(s.seconds))
                .build()
        })
        .collect();
    let sections = r
        .slices
        .iter()
        .map(|s| {
            Object::new()
                .field("range", Json::numbers([s.range.0, s.range.1]))
                .field("height", Json::Number(s.height))
                .field("points", Json::Count(s.points))
                .field("radius", Json::Number(s.radius))
                .field("polygon_crossings", Json::Count(s.polygon_crossings))
                .field("misordered", Json::Number(s.misordered))
                .field("curve_crossings", Json::Count(s.curve_crossings))
                .field("overshoot", Json::Number(s.overshoot))
                .field("rotation", Json::Number(s.rotation))
                .field("deviation", Json::Number(s.deviation))
                .field("deviation_unaligned", Json::Number(s.deviation_unaligned))
                .build()
        })
        .collect();
    Object::new()
        .field("scan", Json::String(args.scan.display().to_string()))
        .field("points", Json::Count(r.points))
        .field("dropped_points", Json::Count(dropped))
        .field("axis", Json::point(&r.axis))
        .field("sections", Json::Array(sections))
        .field("contour_points", Json::Count(r.contour_points))
        .field(
            "surface",
            Json::Array(vec![Json::Count(r.surface_size.0), Json::Count(r.surface_size.1)]),
        )
        .field("stages", Json::Array(stages))
        .field("deviation", Json::Number(r.deviation))
        .field("deviation_unaligned", Json::Number(r.deviation_unaligned))
        .field("sampling_scale", Json::Number(r.sampling_scale))
        .field("surface_to_points", distances(r.surface_to_points.as_ref()))
        .field("errors", distances(r.points_to_surface.as_ref()))
        .field(
            "problems",
            Json::Array(r.problems.iter().map(|p| Json::String(p.to_string())).collect()),
        )
        .field(
            "files",
            Json::Array(files.iter().map(|f| Json::String(f.display().to_string())).collect()),
        )
        .build()
}
