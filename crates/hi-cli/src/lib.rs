// SPDX-License-Identifier: MIT
//! The library behind `hi`: the harmonic curves and surfaces of A. Hardy's 2005 thesis,
//! everything they are compared with, scan fitting and rendering (the `hi-*` crates) on the
//! command line, with JSON in and out. `hi --help` and `hi COMMAND --help` give every option.
//!
//! ```text
//! hi basis [roots]    values and derivatives of σⁿₖ; roots of its derivatives (§5.6)
//! hi curve eval|sample|fairness|to-bezier|rotate|resample|subdivide|nonuniform --input FILE
//!                     the harmonic curve (or, with --kind, a comparison curve) through points
//! hi surface eval|mesh|example|bezier|bspline-fit
//!                     harmonic surfaces, meshes (OBJ, glTF, GLB), Bézier patches, B-spline fits
//! hi subdivide        --scheme SCHEME --steps K IN.(obj|off) -o OUT: subdivision surfaces (§4.5)
//! hi fit SCAN -o OUT  a harmonic surface fitted to a scan (§5.3, §5.4, §5.8); SCAN... --out-dir
//!                     DIR fits many in parallel, one line each in DIR/summary.jsonl
//! hi bezier basis     control values of σₖ on the pieces of a thesis scheme (§5.7)
//! hi render           SCENE.json -o OUT.png, or --quick FILE -o OUT.png (§5.5, §5.6)
//! ```
//!
//! The input is `{"points": [...]}` or a bare array of points, or for surfaces
//! `{"grid": [...]}` or a bare array of rows ([`parse_points`], [`parse_grid`]), the output
//! one JSON object on stdout. Bad input exits with status 2 and one line on
//! stderr; `hi --help` has the details.
//!
//! The binary is [`run`] with mimalloc as its allocator. The rest of this library is the
//! binary's own code, public only where the fuzz targets (`crates/hi-cli/fuzz`) link it: the
//! JSON readers of points and grids ([`parse_points`], [`parse_grid`]). It is not an API for
//! other programs; they use the `hi-*` crates.

mod args;
mod cli;
mod commands;
mod error;
mod help;
mod input;
mod output;
#[cfg(test)]
mod schemas;

use std::io::{self, BufWriter};
use std::process::ExitCode;

use clap::Parser;
use clap::error::ErrorKind;

pub use crate::input::{Points, parse_grid, parse_points};

use crate::cli::{Cli, command_path};
use crate::error::{EXIT_BAD_INPUT, EXIT_OUTPUT, Failure, flatten_clap_error, stderr_line};

/// The `hi` command: reads the command line, runs the command, writes its JSON to stdout, and
/// says what went wrong in one line on stderr. Exit status 0, 1 when the output could not be
/// written, 2 for bad input (the help of `hi --help`).
#[must_use]
pub fn run() -> ExitCode {
    install_panic_hook();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_failure(&e),
    };
    let result = commands::run(&cli.command, cli.pretty).and_then(|json| {
        output::write_json(&mut BufWriter::new(io::stdout().lock()), &json, cli.pretty)
            .map_err(Failure::Output)
    });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader went away (`hi … | head`): it wants no more, and no message either.
        Err(Failure::Output(e)) if e.kind() == io::ErrorKind::BrokenPipe => {
            ExitCode::from(EXIT_OUTPUT)
        }
        Err(failure) => {
            if let Failure::Batch { output: json, .. } = &failure {
                // The batch's counts still go to stdout; a failure to print them changes nothing.
                let out = &mut BufWriter::new(io::stdout().lock());
                let _ = output::write_json(out, json, cli.pretty);
            }
            eprintln!("{}", stderr_line(&failure.to_string()));
            failure.exit_code()
        }
    }
}

/// Prints help or version as clap does, and any usage error as one line (exit status 2).
fn clap_failure(e: &clap::Error) -> ExitCode {
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            // Printing help can only fail if stdout is gone; there is nothing left to say then.
            let _ = e.print();
            ExitCode::SUCCESS
        }
        _ => {
            let command =
                command_path(std::env::args_os().map(|a| a.to_string_lossy().into_owned()));
            eprintln!("{}", stderr_line(&flatten_clap_error(&e.render().to_string(), &command)));
            ExitCode::from(EXIT_BAD_INPUT)
        }
    }
}

/// Replaces Rust's panic message and backtrace by one line: a panic is a bug in `hi`,
/// `hi-curve` or `hi-surface`, never a way to report bad input.
fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        let payload = info.payload();
        let message = payload
            .downcast_ref::<&str>()
            .copied()
            .or_else(|| payload.downcast_ref::<String>().map(String::as_str))
            .unwrap_or("unknown cause");
        let place =
            info.location().map(|l| format!(" ({}:{})", l.file(), l.line())).unwrap_or_default();
        eprintln!(
            "{}",
            stderr_line(&format!("internal error, please report it: {message}{place}"))
        );
    }));
}
