// SPDX-License-Identifier: MIT
//! Project automation for the `harmonic` workspace, run as `cargo xtask <command>`
//! (see <https://github.com/matklad/cargo-xtask/>).
//!
//! Commands (`cargo xtask --help`, and `--help` after each):
//! - `figures [--check] [--no-renders]`: regenerate the thesis figures into `docs/figures/`
//!   (with `--check`, fail instead if a committed file is stale; with `--no-renders`, leave the
//!   renders, most of the work, as they are: for drafting, as the figure test checks);
//! - `bench [topic]`: time our code and the peer programs side by side and write
//!   `docs/performance.md`: every topic (`bench` or `bench all`) or one topic's section
//!   (`curves`, `subdivision`, `fit`, `render`, `batch`: scans per minute and the Python calls'
//!   overhead), or one subsection (`fit-clouds`: point clouds, bare vertices and scans of any
//!   topology against Poisson, with `--small` for small inputs written under
//!   `target/xtask-bench/small/`, and `--only a,b` for some rows);
//! - `crosscheck`: read back every model the figures emit with other programs (tobj, trimesh,
//!   the Khronos validator, Blender) and run every peer comparison, into `docs/crosscheck.md`;
//! - `layers`: check that no crate depends on a crate above it (docs/architecture.md).

mod bench;
mod crosscheck;
mod figures;
mod layers;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Result;
use clap::{Parser, Subcommand, ValueEnum};

/// Project automation for the harmonic workspace: the thesis figures, the benchmarks against
/// the peer programs, the cross-checks of the emitted models, and the layer rule.
#[derive(Debug, Parser)]
#[command(name = "cargo xtask", bin_name = "cargo xtask")]
struct Cli {
    #[command(subcommand)]
    command: Task,
}

/// The tasks.
#[derive(Debug, Subcommand)]
enum Task {
    /// Regenerate every figure and table of the thesis into docs/figures/.
    Figures {
        /// Fail instead of writing if a committed file is stale.
        #[arg(long)]
        check: bool,
        /// Leave the renders (most of the work) as they are: for drafting, as the figure test
        /// checks.
        #[arg(long)]
        no_renders: bool,
        /// Draw only these figures (their numbers, e.g. `5.37,5.38`), leaving the others' files
        /// as they are; the index and the gallery are written whole.
        #[arg(long, value_delimiter = ',', value_name = "FIGURES", conflicts_with = "all")]
        only: Vec<String>,
        /// Draw every figure, even those whose inputs (sources, data, compiler) hash the same as
        /// when their files were written (docs/figures/inputs.json), which are otherwise left.
        #[arg(long)]
        all: bool,
    },
    /// Time our code and the peer programs side by side in the same run, into
    /// docs/performance.md.
    Bench {
        /// The topic: every one (all, the default), one topic's section, or one subsection
        /// (fit-clouds: point clouds, bare vertices and scans of any topology against
        /// screened Poisson).
        #[arg(value_enum, default_value_t = Topic::All)]
        topic: Topic,
        /// Small inputs, for trying the bench out (fit-clouds only): written under
        /// target/xtask-bench/small/, never into docs/.
        #[arg(long)]
        small: bool,
        /// Only the rows whose name contains one of these words (fit-clouds only).
        #[arg(long, value_delimiter = ',', value_name = "WORD,...")]
        only: Vec<String>,
    },
    /// Read back every model the figures emit with other programs (tobj, trimesh, the Khronos
    /// glTF-Validator, Blender) and run every peer comparison, into docs/crosscheck.md.
    Crosscheck,
    /// Check that no crate depends on a crate above it (docs/architecture.md).
    Layers,
}

/// The topics of `cargo xtask bench`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Topic {
    /// Every topic, the whole report written afresh.
    All,
    /// Uniform sampling of a harmonic curve: the direct sum, the FFT path and scipy's resample.
    Curves,
    /// One step of each subdivision scheme against `OpenMesh` and CGAL.
    Subdivision,
    /// The fitting pipeline against scipy and screened Poisson, with its fit-clouds subsection.
    Fit,
    /// The fit-clouds subsection alone.
    FitClouds,
    /// Ray tracing the torus by interval Newton, bisection, Bézier patches and a mesh.
    Render,
    /// Scans fitted per minute (one `hi fit` per scan, `hi fit --out-dir`, `harmonic.fit_many`
    /// here and on a two-worker Dask cluster), and the Python calls' overhead against Rust's.
    Batch,
}

impl Topic {
    /// The topic's name, as the report's section markers spell it.
    fn name(self) -> &'static str {
        match self {
            Self::All => "all",
            Self::Curves => "curves",
            Self::Subdivision => "subdivision",
            Self::Fit => "fit",
            Self::FitClouds => "fit-clouds",
            Self::Render => "render",
            Self::Batch => "batch",
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // The chain of causes on one line; the backtrace only when asked for.
            if std::env::var_os("RUST_BACKTRACE").is_some_and(|v| v != "0") {
                eprintln!("error: {e:?}");
            } else {
                eprintln!("error: {e:#}");
            }
            ExitCode::FAILURE
        }
    }
}

fn run(task: Task) -> Result<()> {
    let root = project_root();
    match task {
        Task::Figures { check, no_renders, only, all } => {
            let renders = if no_renders { figures::Renders::Skip } else { figures::Renders::Draw };
            let select = if all {
                figures::Select::All
            } else if only.is_empty() {
                figures::Select::Changed
            } else {
                figures::Select::Only(only)
            };
            figures::run(&root, check, renders, &select)
        }
        Task::Bench { topic, small, only } => {
            let options = bench::Options {
                small,
                only: only
                    .iter()
                    .filter(|w| !w.is_empty())
                    .map(|w| w.to_ascii_lowercase())
                    .collect(),
            };
            bench::run(&root, Some(topic.name()), &options)
        }
        Task::Crosscheck => crosscheck::run(&root),
        Task::Layers => {
            layers::check(&root)?;
            println!("layers: every crate depends only on crates below it");
            Ok(())
        }
    }
}

/// The workspace root: the parent of this crate's directory.
pub(crate) fn project_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives in the workspace root")
        .to_path_buf()
}

#[cfg(test)]
mod tests {
    use clap::CommandFactory;

    use super::*;

    #[test]
    fn the_command_line_is_well_formed_and_read_as_documented() {
        Cli::command().debug_assert();
        let read = |args: &[&str]| Cli::try_parse_from([&["cargo xtask"], args].concat());
        let Task::Bench { topic, small, only } =
            read(&["bench", "fit-clouds", "--small", "--only", "Bunny,knot"]).unwrap().command
        else {
            panic!("not bench");
        };
        assert_eq!((topic, small), (Topic::FitClouds, true));
        assert_eq!(only, ["Bunny", "knot"]);
        let Task::Bench { topic, .. } = read(&["bench"]).unwrap().command else { panic!() };
        assert_eq!(topic, Topic::All);
        let Task::Bench { topic, small, only } = read(&["bench", "batch"]).unwrap().command else {
            panic!("not bench");
        };
        assert_eq!((topic, small, only.is_empty()), (Topic::Batch, false, true));
        assert_eq!(topic.name(), "batch");
        assert!(read(&["bench", "fast"]).is_err(), "an unknown topic");
        assert!(read(&["bench", "--only"]).is_err(), "--only without its list");
        assert!(read(&["figures", "--fast"]).is_err(), "an unknown option");
        // Help is an answer, not an error: clap's DisplayHelp.
        let help = read(&["--help"]).unwrap_err();
        assert_eq!(help.kind(), clap::error::ErrorKind::DisplayHelp);
        assert!(help.to_string().contains("figures") && help.to_string().contains("layers"));
        let help = read(&["bench", "--help"]).unwrap_err().to_string();
        assert!(help.contains("fit-clouds") && help.contains("--only"), "{help}");
        assert!(help.contains("batch") && help.contains("Dask"), "{help}");
    }
}
