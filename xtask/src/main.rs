// SPDX-License-Identifier: MIT
//! Project automation for the `harmonic` workspace, run as `cargo xtask <command>`
//! (see <https://github.com/matklad/cargo-xtask/>).
//!
//! Commands:
//! - `figures [--check] [--no-renders]`: regenerate the thesis figures into `docs/figures/`
//!   (with `--check`, fail instead if a committed file is stale; with `--no-renders`, leave the
//!   renders, most of the work, as they are: for drafting, as the figure test checks);
//! - `bench [topic]`: time our code and the peer programs side by side and write
//!   `docs/performance.md`: every topic (`bench` or `bench all`) or one topic's section
//!   (`curves`, `subdivision`, `fit`, `render`), or one subsection (`fit-clouds`: point clouds,
//!   bare vertices and scans of any topology against Poisson, with `--small` for small inputs
//!   written under `target/xtask-bench/small/`, and `--only a,b` for some rows);
//! - `crosscheck`: read back every model the figures emit with other programs (tobj, trimesh,
//!   the Khronos validator, Blender) and run every peer comparison, into `docs/crosscheck.md`;
//! - `layers`: check that no crate depends on a crate above it (docs/architecture.md).

mod bench;
mod crosscheck;
mod figures;
mod layers;

use std::path::{Path, PathBuf};

use anyhow::{Result, bail};

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let root = project_root();
    match args.first().map(String::as_str) {
        Some("figures") => {
            let renders = if args.iter().any(|a| a == "--no-renders") {
                figures::Renders::Skip
            } else {
                figures::Renders::Draw
            };
            figures::run(&root, args.iter().any(|a| a == "--check"), renders)
        }
        Some("bench") => {
            // `bench [topic] [--small] [--only a,b]`.
            let rest = &args[1..];
            let (topic, rest) = match rest.split_first() {
                Some((t, more)) if !t.starts_with("--") => (Some(t.as_str()), more),
                _ => (None, rest),
            };
            bench::run(&root, topic, &bench::Options::parse(rest)?)
        }
        Some("crosscheck") => crosscheck::run(&root),
        Some("layers") => {
            layers::check(&root)?;
            println!("layers: every crate depends only on crates below it");
            Ok(())
        }
        _ => bail!(
            "usage: cargo xtask <figures [--check] [--no-renders] | bench [all|curves|subdivision|fit|render|fit-clouds [--small] [--only a,b]] | crosscheck | layers>"
        ),
    }
}

/// The workspace root: the parent of this crate's directory.
pub(crate) fn project_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives in the workspace root")
        .to_path_buf()
}
