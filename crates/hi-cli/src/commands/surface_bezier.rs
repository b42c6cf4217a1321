// SPDX-License-Identifier: MIT
//! `hi surface bezier`: a harmonic surface as Bézier patches (Hardy 2005, §5.7).

use std::path::Path;

use glam::DVec3;
use hi_mesh::export;
use hi_surface::bezier::{PatchReport, SurfaceBezier};
use serde::Serialize;

use crate::cli::SurfaceBezierArgs;
use crate::commands::surface_example::write_file;
use crate::error::Failure;
use crate::input::read_surface;
use crate::output::{Json, check_writable, file_names, json};

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
    check_writable(&args.output, "-o")?;
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
    let report = Report { scheme: args.scheme.name(), report: &patches.report };
    let files = match kind {
        Output::Json => {
            write_file(
                &args.output,
                &patches_json(args.scheme.name(), &patches, &report)?,
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
    /// `{"files", "report"}`.
    #[derive(Serialize)]
    struct Written<'a> {
        files: Vec<String>,
        report: Report<'a>,
    }
    json(&Written { files: file_names(&files), report })
}

/// The report of a conversion to patches: the scheme's name and the library's
/// [`PatchReport`].
#[derive(Clone, Copy, Debug, Serialize)]
pub(crate) struct Report<'a> {
    /// The scheme's name.
    pub(crate) scheme: &'a str,
    /// The patch count, degrees, deviations and bound, and the largest normal jump.
    #[serde(flatten)]
    pub(crate) report: &'a PatchReport,
}

/// One patch of the patches file: its window, degrees and control rows (along u).
#[derive(Serialize)]
struct PatchOut {
    u: [f64; 2],
    v: [f64; 2],
    degree: [usize; 2],
    control: Vec<Vec<DVec3>>,
}

/// The patches file: breaks, each patch's window, degrees and control points, the report.
pub(crate) fn patches_json(
    scheme: &str,
    b: &SurfaceBezier<DVec3>,
    report: &impl Serialize,
) -> Result<Json, Failure> {
    let nv = b.v_breaks.len() - 1;
    /// `{"scheme", "u_breaks", "v_breaks", "patches", "report"}`.
    #[derive(Serialize)]
    struct File<'a, R> {
        scheme: &'a str,
        u_breaks: &'a [f64],
        v_breaks: &'a [f64],
        patches: Vec<PatchOut>,
        report: R,
    }
    json(&File {
        scheme,
        u_breaks: &b.u_breaks,
        v_breaks: &b.v_breaks,
        patches: b
            .patches
            .iter()
            .enumerate()
            .map(|(idx, p)| {
                let (a, c) = (idx / nv, idx % nv);
                PatchOut {
                    u: [b.u_breaks[a], b.u_breaks[a + 1]],
                    v: [b.v_breaks[c], b.v_breaks[c + 1]],
                    degree: [p.degree_u(), p.degree_v()],
                    control: p.rows(),
                }
            })
            .collect(),
        report,
    })
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
