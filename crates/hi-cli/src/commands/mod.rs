// SPDX-License-Identifier: MIT
//! The subcommands: each reads its input, calls `hi-curve` and returns the JSON to print.

mod basis;
mod eval;
mod nonuniform;
mod resample;
mod rotate;
mod sample;
mod subdivide;

use crate::cli::{Command, CurveCommand};
use crate::error::Failure;
use crate::output::Json;

/// Runs `command` and returns its output.
///
/// # Errors
///
/// [`Failure::Input`] for bad input or arguments the library rejects.
pub(crate) fn run(command: &Command) -> Result<Json, Failure> {
    match command {
        Command::Basis(args) => basis::run(args),
        Command::Curve(CurveCommand::Eval(args)) => eval::run(args),
        Command::Curve(CurveCommand::Sample(args)) => sample::run(args),
        Command::Curve(CurveCommand::Rotate(args)) => rotate::run(args),
        Command::Curve(CurveCommand::Resample(args)) => resample::run(args),
        Command::Curve(CurveCommand::Subdivide(args)) => subdivide::run(args),
        Command::Curve(CurveCommand::Nonuniform(args)) => nonuniform::run(args),
    }
}
