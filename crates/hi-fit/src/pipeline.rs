// SPDX-License-Identifier: MIT
//! One scan through the pipeline: read, fitted, its warnings, its meshes and files.

use std::path::{Path, PathBuf};

use glam::DVec3;
use hi_geomimage::fit::{DroppedPart, PartReport, Progress, UNREACHED, mesh_oversample};
use hi_geomimage::layout_mesh::layout_mesh;
use hi_geomimage::{Domain, Fit, FitOptions, Layout, SourceImage, fit};
use hi_mesh::TriangleMesh;
use hi_mesh::export::{self, NamedMesh};
use hi_scan::scan::Scan;
use serde::Serialize;

use crate::Error;

/// Above this fraction of rays meeting the scan more than once, a fit warns when its surface
/// follows the outermost shell the rays met ([`hi_geomimage::SourceImage::follows_outer_shell`]).
const NON_STAR_WARNING: f64 = 0.05;

/// Above this fraction of the scan's points left unreached by the surface (farther than
/// [`hi_geomimage::fit::UNREACHED`] of the diagonal from it), a fit warns.
const UNREACHED_WARNING: f64 = 0.01;

/// Parts named one by one in a warning; more are counted.
const NAMED_PARTS: usize = 5;

/// `n thing` or `n things`.
fn count(n: usize, one: &str, many: &str) -> String {
    if n == 1 { format!("1 {one}") } else { format!("{n} {many}") }
}

/// The parts left out, named (the first few) with their size.
fn dropped_list(dropped: &[DroppedPart]) -> String {
    let described: Vec<String> = dropped
        .iter()
        .map(|d| format!("{} ({:.2}% of the area)", d.name, 100.0 * d.area_fraction))
        .collect();
    names(&described.iter().map(String::as_str).collect::<Vec<_>>())
}

/// Whether the parts left out hold enough of the scan's points to be why `unreached` of them
/// are far from the surface: at least half as many. (Specks left out of a scan whose thin parts
/// the wrap missed hold a few points; the missed parts hold the rest.)
fn dropped_hold(dropped: &[DroppedPart], unreached: f64) -> bool {
    let held: f64 = dropped.iter().map(|d| d.point_fraction).sum();
    !dropped.is_empty() && held >= 0.5 * unreached
}

/// Names, the first few of them, then how many more.
fn names(parts: &[&str]) -> String {
    let mut out: Vec<String> = parts.iter().take(NAMED_PARTS).map(|s| (*s).to_owned()).collect();
    if parts.len() > NAMED_PARTS {
        out.push(format!("and {} more", parts.len() - NAMED_PARTS));
    }
    out.join(", ")
}

/// What the fit found and did about its parts' topology, in words, one line per kind of thing
/// done (a torus, an open sheet, holes closed, handles cut), naming the parts; a lone part's
/// line says it all.
fn topology_notes(parts: &[PartReport]) -> Vec<String> {
    if let [part] = parts {
        let r = &part.repair;
        let mut did = Vec::new();
        match part.domain {
            Domain::Torus => did.push("fitted over the torus with no cut".to_owned()),
            Domain::Sheet => did.push(format!(
                "an open sheet ({}), fitted open",
                count(part.boundary_loops, "boundary loop", "boundary loops")
            )),
            Domain::Sphere(_) => {}
        }
        if r.holes > 0 {
            did.push(format!("{} closed", count(r.holes, "hole", "holes")));
        }
        if r.handles_cut > 0 {
            did.push(format!(
                "{} cut (genus {}), both sides of each cut closed",
                count(r.handles_cut, "handle", "handles"),
                part.genus
            ));
        }
        return if did.is_empty() {
            Vec::new()
        } else {
            vec![format!("{}: {}", part.name, did.join("; "))]
        };
    }
    let pick = |keep: &dyn Fn(&PartReport) -> bool| -> Vec<&str> {
        parts.iter().filter(|p| keep(p)).map(|p| p.name.as_str()).collect()
    };
    let tori = pick(&|p| p.domain == Domain::Torus);
    let sheets = pick(&|p| p.domain == Domain::Sheet);
    let holed = pick(&|p| p.repair.holes > 0);
    let cut = pick(&|p| p.repair.handles_cut > 0);
    let holes: usize = parts.iter().map(|p| p.repair.holes).sum();
    let handles: usize = parts.iter().map(|p| p.repair.handles_cut).sum();
    let mut lines = Vec::new();
    if !tori.is_empty() {
        lines.push(format!("genus 1, fitted over the torus with no cut: {}", names(&tori)));
    }
    if !sheets.is_empty() {
        lines.push(format!("open sheets, fitted open: {}", names(&sheets)));
    }
    if !holed.is_empty() {
        lines.push(format!("{} closed in {}", count(holes, "hole", "holes"), names(&holed)));
    }
    if !cut.is_empty() {
        lines.push(format!(
            "{} cut, both sides of each cut closed, in {}",
            count(handles, "handle", "handles"),
            names(&cut)
        ));
    }
    lines
}

/// The warnings and notes of a fit of `scan` (its name in the lines), one line each, as `hi fit`
/// prints them on stderr: the topology found and what was
/// done about it, parts left out, rays that met several shells where the surface follows the
/// outermost one, and points of the scan the surface did not reach, with the cause when the
/// fit knows it.
pub fn warnings(fitted: &Fit, scan: &str) -> Vec<String> {
    let report = &fitted.report;
    let mut lines = Vec::new();
    if report.dropped_points > 0 {
        lines.push(format!(
            "warning: {} with a NaN or infinite coordinate {} left out of {}",
            count(report.dropped_points, "point", "points"),
            if report.dropped_points == 1 { "was" } else { "were" },
            scan
        ));
    }
    if report.parts.len() > 1 {
        lines.push(format!(
            "note: {} has {} parts to fit (of at least {}% of its area): each is fitted on its own, named part 1, part 2, … by area, largest first",
            scan,
            report.parts.len(),
            100.0 * report.part_floor,
        ));
    }
    for note in topology_notes(&report.parts) {
        lines.push(format!("note: {note}"));
    }
    if !report.dropped_parts.is_empty() {
        let area: f64 = report.dropped_parts.iter().map(|d| d.area_fraction).sum();
        lines.push(format!(
            "warning: {} of {} left out, {:.2}% of its area: {}",
            count(report.dropped_parts.len(), "part", "parts"),
            scan,
            100.0 * area,
            dropped_list(&report.dropped_parts)
        ));
    }
    let volume = report.noise.is_some_and(|n| n.volume);
    if volume {
        lines.push(format!(
            "warning: the points of {scan} fill a volume rather than lie on a surface (as thick as they are wide in neighbourhoods of every size tried): no surface follows them, and the one fitted only wraps them"
        ));
    }
    let source = &fitted.largest().source;
    let outer_shell = source.follows_outer_shell() && report.non_star_fraction > NON_STAR_WARNING;
    if outer_shell {
        lines.push(format!(
            "warning: {:.1}% of the rays meet {} more than once: it is not star-shaped about the centre, and the surface follows its outermost shell there",
            100.0 * report.non_star_fraction,
            scan
        ));
    }
    if let Some(errors) = &report.both_ways
        && errors.unreached_fraction > UNREACHED_WARNING
    {
        // Noise whose three σ pass the threshold leaves points beyond it about any surface
        // through the middle of the scatter (4.6 % of them at two σ).
        let diagonal = errors.scan_to_surface.diagonal;
        let noisy =
            report.noise.map(|n| n.sigma).filter(|&sigma| 3.0 * sigma > UNREACHED * diagonal);
        let cause = if volume {
            ": they fill a volume".to_owned()
        } else if let Some(sigma) = noisy {
            format!(
                ": the scan's noise puts them there (σ estimated at {:.2}% of the diagonal)",
                100.0 * sigma / diagonal
            )
        } else if dropped_hold(&report.dropped_parts, errors.unreached_fraction) {
            format!(": parts were left out ({})", dropped_list(&report.dropped_parts))
        } else if outer_shell {
            ": they lie inside the outermost shell".to_owned()
        } else if matches!(source, SourceImage::ShrinkWrap(_)) {
            ": the wrap did not reach them (inner shells, or parts thinner than its grid)"
                .to_owned()
        } else {
            String::new()
        };
        lines.push(format!(
            "warning: {:.1}% of the points of {} are farther than {}% of the diagonal from the surface{cause}",
            100.0 * errors.unreached_fraction,
            scan,
            100.0 * UNREACHED
        ));
    }
    lines
}

/// Reads the scan at `path` (OBJ, PLY, OFF, STL, XYZ, PTS, glTF, GLB, by its extension).
///
/// # Errors
///
/// [`Error::Open`] when the file cannot be opened (with the system's reason), [`Error::Read`]
/// for an unknown extension or malformed contents (with the line or byte).
pub fn read_scan(path: &Path) -> Result<Scan, Error> {
    // The extension first: a name no reader takes is named as such, whether the file is there.
    hi_scan::scan::ScanFormat::try_from_path(path)
        .map_err(|source| Error::Read { path: path.to_owned(), source })?;
    if let Err(source) = std::fs::File::open(path) {
        return Err(Error::Open { path: path.to_owned(), source });
    }
    if path.is_dir() {
        let source = std::io::Error::new(std::io::ErrorKind::IsADirectory, "it is a folder");
        return Err(Error::Open { path: path.to_owned(), source });
    }
    hi_scan::scan::read_scan(path).map_err(|source| Error::Read { path: path.to_owned(), source })
}

/// Fits `scan` (named `name` in errors) part by part with `options`, announcing each stage to
/// `progress` ([`hi_geomimage::fit()`]).
///
/// # Errors
///
/// [`Error::Fit`], naming the scan, for whatever stopped the fit (too few points, an image
/// that is mostly holes, a part that cannot be parameterised, bad options).
pub fn fit_scan(
    scan: &Scan,
    name: &str,
    options: &FitOptions,
    progress: &mut (dyn FnMut(Progress) + Send),
) -> Result<Fit, Error> {
    fit(scan, options, progress).map_err(|source| Error::Fit { scan: name.to_owned(), source })
}

/// What a fit writes: a mesh of each part's surface in one of `hi-mesh`'s formats (several
/// parts as one scene of named meshes), or the surfaces' grids as JSON (`{"grid": …}` for one
/// part, `{"parts": [{"name", "grid"}, …]}` for several), which `hi surface` reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputFormat {
    /// Binary glTF 2.0.
    Glb,
    /// glTF 2.0 with its `.bin` beside it.
    Gltf,
    /// Wavefront OBJ (one object per part).
    Obj,
    /// The grids of the surfaces, as JSON.
    Json,
}

impl OutputFormat {
    /// The format of a file name's extension (`glb`, `gltf`, `obj`, `json`; any case).
    ///
    /// # Errors
    ///
    /// [`Error::Input`] naming the extension and the formats there are.
    pub fn from_path(path: &Path) -> Result<Self, Error> {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        Self::from_name(ext).map_err(|_| {
            Error::Input(format!(
                "{}: unknown output format '{ext}' (expected .glb, .gltf, .obj or .json)",
                path.display()
            ))
        })
    }

    /// The format of a name (`glb`, `gltf`, `obj`, `json`; any case).
    ///
    /// # Errors
    ///
    /// [`Error::Input`] naming the formats there are.
    pub fn from_name(name: &str) -> Result<Self, Error> {
        match name.to_ascii_lowercase().as_str() {
            "glb" => Ok(Self::Glb),
            "gltf" => Ok(Self::Gltf),
            "obj" => Ok(Self::Obj),
            "json" => Ok(Self::Json),
            _ => Err(Error::Input(format!(
                "unknown output format '{name}' (expected glb, gltf, obj or json)"
            ))),
        }
    }

    /// The extension of its files, which is also its name.
    #[must_use]
    pub fn extension(self) -> &'static str {
        match self {
            Self::Glb => "glb",
            Self::Gltf => "gltf",
            Self::Obj => "obj",
            Self::Json => "json",
        }
    }
}

/// Each part's mesh: the one its error was measured on, or the same made now (at the sampling
/// the error measurement uses, [`mesh_oversample`]); named by `scan` in errors.
///
/// # Errors
///
/// [`Error::Fit`] if a part's surface cannot be meshed.
pub fn part_meshes(fitted: &mut Fit, scan: &str) -> Result<Vec<TriangleMesh>, Error> {
    let mut meshes = Vec::with_capacity(fitted.parts.len());
    for (k, part) in fitted.parts.iter_mut().enumerate() {
        let mesh = match part.mesh.take() {
            Some(m) => m.mesh,
            None => {
                let share = fitted.report.parts.get(k).map_or(1.0, |r| r.area_fraction);
                let per_texel = mesh_oversample(&part.surface, share);
                let per_texel = if part.domain == Domain::Sphere(Layout::Octahedron) {
                    per_texel.next_multiple_of(2)
                } else {
                    per_texel
                };
                layout_mesh(&part.surface, part.domain, per_texel)
                    .map_err(|source| Error::Fit { scan: scan.to_owned(), source })?
                    .mesh
            }
        };
        meshes.push(mesh);
    }
    Ok(meshes)
}

/// Writes one mesh per part to `output` (its extension names the format): the one mesh as it
/// is, or several as one scene of meshes named as the report names the parts. Returns the
/// files written (a `.gltf` has its `.bin`).
///
/// # Errors
///
/// [`Error::Write`] naming the file and the reason.
pub fn save_parts(
    fitted: &Fit,
    meshes: &[TriangleMesh],
    output: &Path,
) -> Result<Vec<PathBuf>, Error> {
    let written = match meshes {
        [only] => export::save(only, output),
        _ => {
            let named: Vec<NamedMesh<'_>> = fitted
                .report
                .parts
                .iter()
                .zip(meshes)
                .map(|(r, m)| NamedMesh::new(&r.name, m))
                .collect();
            export::save_scene(&named, output)
        }
    };
    written.map_err(|e| Error::Write { path: output.to_owned(), message: e.to_string() })
}

/// The grids of a fit's surfaces as written to JSON (see [`OutputFormat::Json`]).
#[derive(Debug, Serialize)]
#[serde(untagged)]
pub enum Grids<'a> {
    /// One part: `{"grid": rows}`.
    One {
        /// The rows of the grid.
        grid: Vec<Vec<DVec3>>,
    },
    /// Several: `{"parts": [{"name", "grid"}, …]}`.
    Several {
        /// The parts, largest first.
        parts: Vec<NamedGrid<'a>>,
    },
}

/// A part's name and grid.
#[derive(Debug, Serialize)]
pub struct NamedGrid<'a> {
    /// The part's name in the report.
    pub name: &'a str,
    /// The rows of its grid.
    pub grid: Vec<Vec<DVec3>>,
}

/// The grids of `fitted`'s surfaces.
#[must_use]
pub fn grids(fitted: &Fit) -> Grids<'_> {
    match &fitted.parts[..] {
        [only] => Grids::One { grid: only.surface.rows() },
        parts => Grids::Several {
            parts: fitted
                .report
                .parts
                .iter()
                .zip(parts)
                .map(|(r, p)| NamedGrid { name: &r.name, grid: p.surface.rows() })
                .collect(),
        },
    }
}

/// Writes `value` as compact JSON and a newline to the file at `path`.
///
/// # Errors
///
/// [`Error::Write`] naming the file and the reason.
pub fn write_json(path: &Path, value: &impl Serialize) -> Result<(), Error> {
    use std::io::Write;
    let fail =
        |e: &dyn std::fmt::Display| Error::Write { path: path.to_owned(), message: e.to_string() };
    let file = std::fs::File::create(path).map_err(|e| fail(&e))?;
    let mut out = std::io::BufWriter::new(file);
    serde_json::to_writer(&mut out, value).map_err(|e| fail(&e))?;
    out.write_all(b"\n").and_then(|()| out.flush()).map_err(|e| fail(&e))
}

/// Writes a fit of the scan `scan` to `output` in `format`: the parts' meshes ([`part_meshes`],
/// [`save_parts`]) or their grids ([`grids`]). Returns the files written.
///
/// # Errors
///
/// [`Error::Fit`] if a surface cannot be meshed, [`Error::Write`] if a file cannot be written.
pub fn write_outputs(
    fitted: &mut Fit,
    scan: &str,
    output: &Path,
    format: OutputFormat,
) -> Result<Vec<PathBuf>, Error> {
    if format == OutputFormat::Json {
        write_json(output, &grids(fitted))?;
        return Ok(vec![output.to_owned()]);
    }
    let meshes = part_meshes(fitted, scan)?;
    save_parts(fitted, &meshes, output)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dropped(point_fraction: f64) -> DroppedPart {
        DroppedPart {
            name: "part 2".to_owned(),
            vertices: 4,
            area_fraction: 0.0003,
            point_fraction,
            reason: "below the floor".to_owned(),
        }
    }

    /// The parts left out are named as the cause of points far from the surface only when
    /// they hold at least half as many points as are far.
    #[test]
    fn parts_left_out_are_the_cause_only_when_they_hold_the_points() {
        // Two specks holding 0.4 % of the points, 21.7 % unreached: the specks are not why.
        assert!(!dropped_hold(&[dropped(0.002), dropped(0.002)], 0.217));
        // A part left out with 15 % of the points, 20 % unreached: it is.
        assert!(dropped_hold(&[dropped(0.15)], 0.2));
        // Exactly half, from two parts.
        assert!(dropped_hold(&[dropped(0.05), dropped(0.05)], 0.2));
        assert!(!dropped_hold(&[], 0.2));
    }
}
