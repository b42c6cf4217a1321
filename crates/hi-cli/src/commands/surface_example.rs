// SPDX-License-Identifier: MIT
//! `hi surface example`: the grid of the exact sphere or torus (docs/math.md §3) or of a test
//! surface of Hardy 2005, §5.9.

use std::path::Path;

use glam::DVec3;
use hi_surface::{ParametricSurface, sphere, test_surface, test_surfaces, torus};

use crate::args::Size;
use crate::cli::SurfaceExampleArgs;
use crate::error::Failure;
use serde::Serialize;

use crate::output::{self, Json, check_writable, file_names, write_json};

/// Radius of the `sphere` example.
const SPHERE_RADIUS: f64 = 1.0;

/// Radii R and r of the `torus` example (those of §5.9's torus).
const TORUS_RADII: (f64, f64) = (2.0, 1.0);

/// The grid `{"grid": [[[x, y, z], ...], ...]}`, or with `-o` the grid written to the file
/// and `{"files": [FILE], "m": M, "n": N}`.
///
/// # Errors
///
/// [`Failure::Input`] for an unknown name, a sample count too large, or an output file that
/// cannot be written.
pub(crate) fn run(args: &SurfaceExampleArgs, pretty: bool) -> Result<Json, Failure> {
    if let Some(path) = &args.output {
        check_writable(path, "-o")?;
    }
    let grid = example_grid(&args.name, args.samples)?;
    let (m, n) = (grid.len(), grid.first().map_or(0, Vec::len));
    let json = grid_json(&grid)?;
    match &args.output {
        None => Ok(json),
        Some(path) => {
            write_file(path, &json, pretty)?;
            /// `{"files": [FILE], "m": M, "n": N}`.
            #[derive(Serialize)]
            struct Written {
                files: Vec<String>,
                m: usize,
                n: usize,
            }
            output::json(&Written { files: file_names(std::slice::from_ref(path)), m, n })
        }
    }
}

/// Largest number of grid points an example may have (2²⁴: about 1 GB of JSON).
const MAX_POINTS: usize = 1 << 24;

/// The rows of the example grid called `name`.
fn example_grid(name: &str, samples: Option<Size>) -> Result<Vec<Vec<DVec3>>, Failure> {
    if let Some(Size(m, n)) = samples
        && m.checked_mul(n).is_none_or(|total| total > MAX_POINTS)
    {
        return Err(Failure::input(format!(
            "--samples: {m}x{n} is too many points: at most 2^24 = {MAX_POINTS}"
        )));
    }
    let exact = match name {
        "sphere" => Some(sphere(SPHERE_RADIUS)),
        "torus" => Some(torus(TORUS_RADII.0, TORUS_RADII.1)),
        _ => None,
    };
    if let Some(surface) = exact {
        return Ok(match samples {
            None => surface.rows(),
            Some(Size(m, n)) => {
                let samples = surface.sample_uniform(m, n, 0, 0)?;
                samples.values.chunks(n).map(<[DVec3]>::to_vec).collect()
            }
        });
    }
    let surface = find_test_surface(name)?;
    let Size(m, n) = samples.unwrap_or(Size(surface.samples.0, surface.samples.1));
    Ok(surface.sample_grid(m, n))
}

/// The §5.9 surface called `name`, or numbered `name` (figure 5.31 to 5.43).
fn find_test_surface(name: &str) -> Result<ParametricSurface, Failure> {
    test_surface(name)
        .filter(|s| s.name != "sphere" && s.name != "torus")
        .or_else(|| test_surfaces().into_iter().find(|s| s.figure == name))
        .ok_or_else(|| {
            let names: Vec<&str> = test_surfaces()
                .iter()
                .map(|s| s.name)
                .filter(|n| *n != "sphere" && *n != "torus")
                .collect();
            Failure::input(format!(
                "unknown example surface '{name}': expected sphere, torus, {}, or a figure \
                 number 5.31 to 5.43",
                names.join(", ")
            ))
        })
}

/// The grid file `{"grid": [[[x, y, z], ...], ...]}` of the rows of a grid, as the surface
/// commands read it.
pub(crate) fn grid_json(rows: &[Vec<DVec3>]) -> Result<Json, Failure> {
    /// `{"grid": rows}`.
    #[derive(Serialize)]
    struct Grid<'a> {
        grid: &'a [Vec<DVec3>],
    }
    output::json(&Grid { grid: rows })
}

/// Writes `json` to the file at `path`.
pub(crate) fn write_file(path: &Path, json: &Json, pretty: bool) -> Result<(), Failure> {
    let fail = |e: std::io::Error| Failure::input(format!("{}: cannot write: {e}", path.display()));
    let file = std::fs::File::create(path).map_err(fail)?;
    write_json(&mut std::io::BufWriter::new(file), json, pretty).map_err(fail)
}
