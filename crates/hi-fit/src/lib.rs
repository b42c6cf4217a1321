// SPDX-License-Identifier: MIT
//! Scan fitting as a program runs it (thesis §5.3, §5.4, §5.8, and past the thesis as
//! `hi-geomimage` goes): the one implementation behind the `hi fit` command and the `harmonic`
//! Python package's `fit` and `fit_many`, so that both give the same surfaces, the same report
//! and the same errors.
//!
//! - [`read_scan`] and [`fit_scan`]: a scan read (every format of `hi-scan`) and fitted part by
//!   part ([`hi_geomimage::fit()`]), errors naming the scan;
//! - [`warnings`]: what the fit changed or could not reach, one line each, as `hi fit` prints
//!   them (parts left out, handles cut, holes closed, points unreached, shells hidden);
//! - [`part_meshes`], [`save_parts`], [`write_outputs`]: each part's mesh, and the files
//!   (one mesh, a scene of named meshes for several parts, or the surfaces' grids as JSON);
//! - [`summary`]: the report of a fit as `hi fit` prints it ([`Summary`]);
//! - [`batch`]: many scans fitted in parallel into one folder, one JSON line per scan in
//!   `summary.jsonl`, failures recorded and the rest carried on, done scans skipped on a second
//!   run.
//!
//! ```no_run
//! use hi_fit::{OutputFormat, fit_scan, read_scan, write_outputs};
//! use hi_geomimage::FitOptions;
//!
//! let path = std::path::Path::new("duck.obj");
//! let scan = read_scan(path)?;
//! let mut fitted = fit_scan(&scan, "duck.obj", &FitOptions::default(), &mut |_| {})?;
//! let files = write_outputs(&mut fitted, "duck.obj", "duck.glb".as_ref(), OutputFormat::Glb)?;
//! # Ok::<(), hi_fit::Error>(())
//! ```

pub mod batch;
mod error;
mod pipeline;
mod report;

pub use error::Error;
pub use pipeline::{
    Grids, OutputFormat, fit_scan, grids, part_meshes, read_scan, save_parts, warnings, write_json,
    write_outputs,
};
pub use report::{DistancesOut, Summary, summary};
