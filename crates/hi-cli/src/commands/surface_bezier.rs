// SPDX-License-Identifier: MIT
//! `hi surface bezier`: a harmonic surface as Bézier patches (Hardy 2005, §5.7).

use std::path::Path;

use glam::DVec3;
use hi_mesh::export;
use hi_surface::bezier::{PatchReport, SurfaceBezier};

use crate::cli::SurfaceBezierArgs;
use crate::commands::surface_example::write_file;
use crate::error::Failure;
use crate::input::read_surface;
use crate::output::{Json, Object};

/// The output kinds, from the extension of `-o`.
enum Output {
    Json,
    Obj,
    Mesh,
}

/// Writes the patches and returns `{"files": [...], "report": {...}}`.
///
/// # Errors
///
/// [`Failure::Input`] for a bad grid file, an unknown extension, a bad tolerance or sample
/// count, a conversion the library rejects, or an output file that cannot be written.
pub(crate) fn run(args: &SurfaceBezierArgs, pretty: bool) -> Result<Json, Failure> {
    let ext = args.output.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let kind = match ext.as_deref() {
        Some("json") => Output::Json,
        Some("obj") => Output::Obj,
        Some("gltf" | "glb") => Output::Mesh,
        _ => {
            return Err(Failure::input(format!(
                "-o {}: unknown extension, expected .json, .obj, .gltf or .glb",
                args.output.display()
            )));
        }
    };
    if !(1..=64).contains(&args.samples) {
        return Err(Failure::input(format!("--samples {}: expected 1 to 64", args.samples)));
    }
    let surface = read_surface(&args.input.input)?;
    let patches = surface
        .to_bezier(
            args.scheme,
            args.tolerance
                .map_or(hi_curve::bezier::DEFAULT_TOLERANCE, hi_curve::bezier::Tolerance::Absolute),
        )
        .map_err(|e| Failure::input(format!("--scheme/--tolerance: {e}")))?;
    let report = report_json(args.scheme.name(), &patches.report);
    let files = match kind {
        Output::Json => {
            write_file(
                &args.output,
                &patches_json(args.scheme.name(), &patches, report.clone()),
                pretty,
            )?;
            vec![args.output.clone()]
        }
        Output::Obj => {
            let all: Vec<usize> = (0..patches.patches.len()).collect();
            write_obj(&patches, &all, &args.output)?;
            vec![args.output.clone()]
        }
        Output::Mesh => {
            let mesh = patches
                .to_triangle_mesh(args.samples)
                .map_err(|e| Failure::input(format!("--samples: {e}")))?;
            export::save(&mesh, &args.output)?
        }
    };
    Ok(Object::new()
        .field(
            "files",
            Json::Array(files.iter().map(|f| Json::String(f.display().to_string())).collect()),
        )
        .field("report", report)
        .build())
}

/// The report as JSON.
pub(crate) fn report_json(scheme: &str, r: &PatchReport) -> Json {
    Object::new()
        .field("scheme", Json::String(scheme.to_owned()))
        .field("patches", Json::Count(r.patches))
        .field("degree", Json::Array(vec![Json::Count(r.degree.0), Json::Count(r.degree.1)]))
        .field("max_deviation", Json::Number(r.max_deviation))
        .field("rms_deviation", Json::Number(r.rms_deviation))
        .field("bound", Json::Number(r.bound))
        .field("max_normal_jump", Json::Number(r.max_normal_jump))
        .build()
}

/// The patches file: breaks, each patch's window, degrees and control points, the report.
pub(crate) fn patches_json(scheme: &str, b: &SurfaceBezier<DVec3>, report: Json) -> Json {
    let nv = b.v_breaks.len() - 1;
    let patches = b
        .patches
        .iter()
        .enumerate()
        .map(|(idx, p)| {
            let (a, c) = (idx / nv, idx % nv);
            Object::new()
                .field("u", Json::numbers([b.u_breaks[a], b.u_breaks[a + 1]]))
                .field("v", Json::numbers([b.v_breaks[c], b.v_breaks[c + 1]]))
                .field(
                    "degree",
                    Json::Array(vec![Json::Count(p.degree_u()), Json::Count(p.degree_v())]),
                )
                .field("control", Json::Array(p.rows().iter().map(|r| Json::points(r)).collect()))
                .build()
        })
        .collect();
    Object::new()
        .field("scheme", Json::String(scheme.to_owned()))
        .field("u_breaks", Json::numbers(b.u_breaks.iter().copied()))
        .field("v_breaks", Json::numbers(b.v_breaks.iter().copied()))
        .field("patches", Json::Array(patches))
        .field("report", report)
        .build()
}

/// Writes the patches `indices` as an OBJ free-form file.
pub(crate) fn write_obj(
    b: &SurfaceBezier<DVec3>,
    indices: &[usize],
    path: &Path,
) -> Result<(), Failure> {
    let fail = |e: std::io::Error| Failure::input(format!("{}: cannot write: {e}", path.display()));
    let file = std::fs::File::create(path).map_err(fail)?;
    b.write_obj_of(std::io::BufWriter::new(file), indices).map_err(fail)
}
