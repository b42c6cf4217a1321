// SPDX-License-Identifier: MIT
//! The subcommands: each reads its input, calls `hi-curve` or `hi-surface` and returns the
//! JSON to print.

mod basis;
mod bezier_basis;
mod eval;
mod fairness;
mod fit;
mod fit_sections;
mod nonuniform;
mod render;
mod resample;
mod scene_file;

#[cfg(test)]
pub(crate) use scene_file::SceneFile;
mod rotate;
mod sample;
mod subdivide;
mod subdivide_mesh;
mod surface_bezier;
mod surface_bspline;
mod surface_eval;
mod surface_example;
mod surface_mesh;
mod to_bezier;

use crate::cli::{BezierCommand, Command, CurveCommand, SurfaceCommand};
use crate::error::Failure;
use crate::output::Json;

/// Runs `command` and returns its output (`pretty` is for files the command writes itself).
///
/// # Errors
///
/// [`Failure::Input`] for bad input, arguments the library rejects, or an output file (`-o`)
/// that cannot be written.
pub(crate) fn run(command: &Command, pretty: bool) -> Result<Json, Failure> {
    match command {
        Command::Basis(args) => basis::run(args),
        Command::Subdivide(args) => subdivide_mesh::run(args),
        Command::Fit(args) => fit::run(args),
        Command::Bezier(BezierCommand::Basis(args)) => bezier_basis::run(args),
        Command::Render(args) => render::run(args),
        Command::Curve(CurveCommand::Eval(args)) => eval::run(args),
        Command::Curve(CurveCommand::Sample(args)) => sample::run(args),
        Command::Curve(CurveCommand::Fairness(args)) => fairness::run(args),
        Command::Curve(CurveCommand::ToBezier(args)) => to_bezier::run(args),
        Command::Curve(CurveCommand::Rotate(args)) => rotate::run(args),
        Command::Curve(CurveCommand::Resample(args)) => resample::run(args),
        Command::Curve(CurveCommand::Subdivide(args)) => subdivide::run(args),
        Command::Curve(CurveCommand::Nonuniform(args)) => nonuniform::run(args),
        Command::Surface(SurfaceCommand::Eval(args)) => surface_eval::run(args),
        Command::Surface(SurfaceCommand::Mesh(args)) => surface_mesh::run(args),
        Command::Surface(SurfaceCommand::Example(args)) => surface_example::run(args, pretty),
        Command::Surface(SurfaceCommand::Bezier(args)) => surface_bezier::run(args, pretty),
        Command::Surface(SurfaceCommand::BsplineFit(args)) => surface_bspline::run(args, pretty),
    }
}
