// SPDX-License-Identifier: MIT
//! `hi surface bspline-fit`: the bicubic B-spline surface through slices of points (Hardy 2005,
//! §4.4, Watt & Watt's curve network), as JSON (knots, control net, Bézier patches) or as a
//! triangle mesh (OBJ, glTF, GLB).

use std::path::Path;

use glam::DVec3;
use hi_compare::bspline_fit::{
    BSplineFit, BSplineFitOptions, BezierPatchGrid, EndCondition, Parameters,
};
use hi_mesh::export::{self, MeshFormat};

use crate::cli::{BsplineEnd, BsplineParams, SurfaceBsplineArgs};
use crate::commands::surface_example::write_file;
use crate::error::Failure;
use crate::input::read_slices;
use crate::output::{Json, Object};

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
            MeshFormat::from_path(path)
                .map_err(|e| Failure::input(format!("-o: {e} (or .json for the surface)")))?,
        ),
        _ => None,
    };
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
    let Some(path) = &args.output else { return Ok(surface_json(&fit)) };
    let (n_control_u, n_control_v) = fit.surface().n_control();
    let mut out = Object::new();
    if mesh_format.is_some() {
        let mesh = fit
            .surface()
            .to_mesh(args.resolution.0, args.resolution.1)
            .map_err(|e| Failure::input(format!("--resolution: {e}")))?;
        let files = export::save(&mesh, path)?;
        out.push(
            "files",
            Json::Array(files.iter().map(|f| Json::String(f.display().to_string())).collect()),
        );
        out.push("vertices", Json::Count(mesh.n_vertices()));
        out.push("triangles", Json::Count(mesh.n_triangles()));
    } else {
        write_file(path, &surface_json(&fit), pretty)?;
        out.push("files", Json::Array(vec![Json::String(path.display().to_string())]));
    }
    out.push("control", Json::Array(vec![Json::Count(n_control_u), Json::Count(n_control_v)]));
    Ok(out.build())
}

/// True for a `.json` output path.
fn is_json(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("json"))
}

/// The surface as JSON: degree, closed flags, knots, control net, the data's parameters, and
/// the exact and Adini Bézier patches.
fn surface_json(fit: &BSplineFit) -> Json {
    let s = fit.surface();
    let pair = |a: bool, b: bool| Json::Array(vec![Json::Bool(a), Json::Bool(b)]);
    Object::new()
        .field("degree", Json::Array(vec![Json::Count(3), Json::Count(3)]))
        .field("closed", pair(s.is_closed_u(), s.is_closed_v()))
        .field("u_knots", Json::numbers(s.u_knots().iter().copied()))
        .field("v_knots", Json::numbers(s.v_knots().iter().copied()))
        .field("control", Json::Array(s.control_rows().iter().map(|r| Json::points(r)).collect()))
        .field(
            "u_params",
            Json::Array(fit.u_params().iter().map(|p| Json::numbers(p.iter().copied())).collect()),
        )
        .field("v_params", Json::numbers(fit.v_params().iter().copied()))
        .field("patches", patches_json(&s.to_bezier_patches()))
        .field("adini_patches", patches_json(&s.to_adini_patches()))
        .build()
}

/// `{"u_breaks": [...], "v_breaks": [...], "control": [patch, ...]}`, each patch its 4×4 net
/// (rows along u), row-major over the patches.
fn patches_json(grid: &BezierPatchGrid) -> Json {
    let nets = grid
        .patches()
        .iter()
        .map(|p| Json::Array(p.rows().iter().map(|r: &Vec<DVec3>| Json::points(r)).collect()))
        .collect();
    Object::new()
        .field("u_breaks", Json::numbers(grid.u_breaks().iter().copied()))
        .field("v_breaks", Json::numbers(grid.v_breaks().iter().copied()))
        .field("control", Json::Array(nets))
        .build()
}
