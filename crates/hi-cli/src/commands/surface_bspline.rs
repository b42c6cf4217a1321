// SPDX-License-Identifier: MIT
//! `hi surface bspline-fit`: the bicubic B-spline surface through slices of points (Hardy 2005,
//! §4.4, Watt & Watt's curve network), as JSON (knots, control net, Bézier patches) or as a
//! triangle mesh (OBJ, glTF, GLB).

use std::path::Path;

use glam::DVec3;
use hi_bezier::BezierPatch;
use hi_compare::bspline_fit::{
    BSplineFit, BSplineFitOptions, BezierPatchGrid, EndCondition, Parameters,
};
use hi_mesh::export::{self, MeshFormat};
use serde::Serialize;

use crate::cli::{BsplineEnd, BsplineParams, SurfaceBsplineArgs};
use crate::commands::surface_example::write_file;
use crate::error::Failure;
use crate::input::read_slices;
use crate::output::{Json, check_writable, file_names, json};

/// Fits the surface; without `-o` returns the surface's JSON, with `-o OUT.json` writes it
/// there, with a mesh extension writes the mesh; then returns `{"files": [...], ...}`.
///
/// # Errors
///
/// [`Failure::Input`] for bad slices (too few, too short, coincident points), an unknown
/// extension, a resolution the mesher rejects, or an output file that cannot be written.
pub(crate) fn run(args: &SurfaceBsplineArgs, pretty: bool) -> Result<Json, Failure> {
    // Check the extension before reading and fitting: a typo should fail at once.
    let mesh_format = match &args.output {
        Some(path) if !is_json(path) => Some(
            MeshFormat::try_from_path(path)
                .map_err(|e| Failure::input(format!("-o: {e} (or .json for the surface)")))?,
        ),
        _ => None,
    };
    if let Some(path) = &args.output {
        check_writable(path, "-o")?;
    }
    let (name, slices) = read_slices(&args.input)?;
    let end = match args.end {
        BsplineEnd::Natural => EndCondition::Natural,
        BsplineEnd::NotAKnot => EndCondition::NotAKnot,
        BsplineEnd::Clamped => EndCondition::Coincident,
    };
    let params = match args.params {
        BsplineParams::ChordLength => Parameters::ChordLength,
        BsplineParams::Uniform => Parameters::Uniform,
    };
    let options = BSplineFitOptions {
        closed_u: args.closed_u,
        closed_v: args.closed_v,
        end_u: end,
        end_v: end,
        u_params: params.clone(),
        v_params: params,
    };
    let fit = BSplineFit::try_new(slices, &options)
        .map_err(|e| Failure::input(format!("{name}: {e}")))?;
    let Some(path) = &args.output else { return surface_json(&fit) };
    let (n_control_u, n_control_v) = fit.surface().n_control();
    /// `{"files", "vertices", "triangles", "control"}` (no counts for a `.json` file).
    #[derive(Serialize)]
    struct Written {
        files: Vec<String>,
        #[serde(skip_serializing_if = "Option::is_none")]
        vertices: Option<usize>,
        #[serde(skip_serializing_if = "Option::is_none")]
        triangles: Option<usize>,
        control: [usize; 2],
    }
    let written = if mesh_format.is_some() {
        let mesh = fit
            .surface()
            .to_mesh(args.resolution.0, args.resolution.1)
            .map_err(|e| Failure::input(format!("--resolution: {e}")))?;
        let files = export::save(&mesh, path)?;
        Written {
            files: file_names(&files),
            vertices: Some(mesh.n_vertices()),
            triangles: Some(mesh.n_triangles()),
            control: [n_control_u, n_control_v],
        }
    } else {
        write_file(path, &surface_json(&fit)?, pretty)?;
        Written {
            files: file_names(std::slice::from_ref(path)),
            vertices: None,
            triangles: None,
            control: [n_control_u, n_control_v],
        }
    };
    json(&written)
}

/// True for a `.json` output path.
fn is_json(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("json"))
}

/// The surface as JSON: degree, closed flags, knots, control net, the data's parameters, and
/// the exact and Adini Bézier patches.
fn surface_json(fit: &BSplineFit) -> Result<Json, Failure> {
    let s = fit.surface();
    /// The surface file.
    #[derive(Serialize)]
    struct File<'a> {
        degree: [usize; 2],
        closed: [bool; 2],
        u_knots: &'a [f64],
        v_knots: &'a [f64],
        control: Vec<Vec<DVec3>>,
        u_params: &'a [Vec<f64>],
        v_params: &'a [f64],
        patches: Patches,
        adini_patches: Patches,
    }
    json(&File {
        degree: [3, 3],
        closed: [s.is_closed_u(), s.is_closed_v()],
        u_knots: s.u_knots(),
        v_knots: s.v_knots(),
        control: s.control_rows(),
        u_params: fit.u_params(),
        v_params: fit.v_params(),
        patches: Patches::of(&s.to_bezier_patches()),
        adini_patches: Patches::of(&s.to_adini_patches()),
    })
}

/// `{"u_breaks": [...], "v_breaks": [...], "control": [patch, ...]}`, each patch its 4×4 net
/// (rows along u), row-major over the patches.
#[derive(Serialize)]
struct Patches {
    u_breaks: Vec<f64>,
    v_breaks: Vec<f64>,
    control: Vec<Vec<Vec<DVec3>>>,
}

impl Patches {
    fn of(grid: &BezierPatchGrid) -> Self {
        Patches {
            u_breaks: grid.u_breaks().to_vec(),
            v_breaks: grid.v_breaks().to_vec(),
            control: grid.patches().iter().map(BezierPatch::rows).collect(),
        }
    }
}
