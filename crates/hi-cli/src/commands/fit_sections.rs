// SPDX-License-Identifier: MIT
//! `hi fit --param sections`: algorithm 1 of §5.3 (cross-sections, a harmonic curve per
//! contour, insertion, rotation alignment, the reversed traversal), with its per-section
//! diagnostics and the measured problems printed as warnings.

use std::path::{Path, PathBuf};

use glam::DVec3;

use hi_fit::DistancesOut;
use hi_geomimage::Stage;
use hi_geomimage::sections::{
    ContourOrder, SectionFit, SectionOptions, SliceAxis, SliceReport, fit_sections,
};
use hi_mesh::export::{self, MeshFormat};
use hi_scan::scan::read_scan;
use hi_surface::MeshOptions;
use serde::Serialize;

use crate::cli::{AxisName, FitArgs, OrderName};
use crate::commands::surface_example::{grid_json, write_file};
use crate::error::{Failure, about_file, stderr_line};
use crate::output::{Json, check_writable, file_names, json};
use hi_surface::{ParamRange, ParamWindow};

/// Fits by algorithm 1, writes the surface and returns the summary (also written to
/// `--report`).
///
/// # Errors
///
/// [`Failure::Input`] for an unreadable scan, options that `hi fit --param sections` does not
/// take, an input algorithm 1 rejects (naming the section or point), an unknown output
/// extension, or an output that cannot be written.
pub(crate) fn run(args: &FitArgs, scan_path: &Path, output: &Path) -> Result<Json, Failure> {
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
    for (given, name) in [
        (args.smooth.is_some(), "--smooth"),
        (args.reduce.is_some(), "--reduce"),
        (args.centre.is_some(), "--centre"),
        (args.resolution.is_some(), "--resolution"),
        (args.regularise.is_some(), "--regularise"),
    ] {
        if given {
            return Err(Failure::input(format!(
                "{name} is for the geometry images, not for --param sections"
            )));
        }
    }
    let scan =
        read_scan(scan_path).map_err(|e| Failure::input(about_file(scan_path, &e.to_string())))?;
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
        .map_err(|e| Failure::input(format!("{}: {e}", scan_path.display())))?;
    for problem in &fitted.report.problems {
        eprintln!("{}", stderr_line(&format!("warning: {problem}")));
    }
    let files: Vec<PathBuf> = if as_grid {
        write_file(output, &grid_json(&fitted.surface.rows())?, false)?;
        vec![output.to_owned()]
    } else {
        let u = fitted.covering_window();
        let (m, n) = (fitted.surface.m(), fitted.surface.n());
        let mesh_options = MeshOptions {
            n_u: m.max(3),
            n_v: 2 * n,
            window: ParamWindow::new(u, ParamRange::UNIT),
            ..MeshOptions::default()
        };
        let mesh = fitted.surface.to_mesh(&mesh_options)?;
        export::save(&mesh, output)?
    };
    let summary = summary(scan_path, &fitted, scan.dropped_points, &files)?;
    if let Some(path) = &args.report {
        write_file(path, &summary, true)?;
    }
    Ok(summary)
}

/// The summary of a fit by algorithm 1 as JSON.
fn summary(
    scan_path: &Path,
    fitted: &SectionFit,
    dropped: usize,
    files: &[PathBuf],
) -> Result<Json, Failure> {
    let r = &fitted.report;
    /// The printed summary.
    #[derive(Serialize)]
    struct Summary<'a> {
        scan: String,
        points: usize,
        dropped_points: usize,
        axis: DVec3,
        sections: &'a [SliceReport],
        contour_points: usize,
        surface: (usize, usize),
        stages: &'a [Stage],
        deviation: f64,
        deviation_unaligned: f64,
        sampling_scale: f64,
        surface_to_points: Option<DistancesOut>,
        errors: Option<DistancesOut>,
        problems: Vec<String>,
        files: Vec<String>,
    }
    json(&Summary {
        scan: scan_path.display().to_string(),
        points: r.points,
        dropped_points: dropped,
        axis: r.axis,
        sections: &r.slices,
        contour_points: r.contour_points,
        surface: r.surface_size,
        stages: &fitted.stages,
        deviation: r.deviation,
        deviation_unaligned: r.deviation_unaligned,
        sampling_scale: r.sampling_scale,
        surface_to_points: r.surface_to_points.as_ref().map(DistancesOut::of),
        errors: r.points_to_surface.as_ref().map(DistancesOut::of),
        problems: r.problems.iter().map(ToString::to_string).collect(),
        files: file_names(files),
    })
}
