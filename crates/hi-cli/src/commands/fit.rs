// SPDX-License-Identifier: MIT
//! `hi fit`: a harmonic surface fitted to each part of a scan through a geometry image (§5.3,
//! §5.4, §5.8), with a progress bar, a summary, and warnings naming what the fit changed or
//! could not reach (parts left out, handles cut, points unreached, a scan that is not
//! star-shaped where the surface follows its outermost shell); several parts are written as one
//! scene of named meshes. `--param sections` goes to algorithm 1 instead
//! ([`super::fit_sections`]).

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use glam::DVec3;
use hi_curve::ReductionDeviation;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_geomimage::fit::{
    Boundary, DroppedPart, FitErrors, PartReport, Progress, RowPoints, Stage, UNREACHED,
    mesh_oversample,
};
use hi_geomimage::layout_mesh::layout_mesh;
use hi_geomimage::regularise::{Regularisation, RegularisationReport};
use hi_geomimage::{
    Domain, ErrorMeasure, Fit, FitOptions, Layout, Method, Smoothing, SourceImage, fit,
};
use hi_mesh::TriangleMesh;
use hi_mesh::export::{self, MeshFormat, NamedMesh};
use hi_scan::scan::read_scan;
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;

use crate::cli::{FitArgs, MethodName, ParamName};
use crate::commands::fit_sections::DistancesOut;
use crate::commands::surface_bezier;
use crate::commands::surface_example::{grid_json, write_file};
use crate::error::{Failure, about_file, stderr_line};
use crate::output::{Json, check_writable, file_names, json};

/// Above this fraction of rays meeting the scan more than once, `hi fit` warns when its surface
/// follows the outermost shell the rays met ([`hi_geomimage::SourceImage::follows_outer_shell`]).
const NON_STAR_WARNING: f64 = 0.05;

/// Above this fraction of the scan's points left unreached by the surface (farther than
/// [`hi_geomimage::fit::UNREACHED`] of the diagonal from it), `hi fit` warns.
const UNREACHED_WARNING: f64 = 0.01;

/// Samples per patch side in the mesh of `--bezier`.
const BEZIER_SAMPLES: usize = 4;

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

/// The warnings and notes of a fit of `scan`, one line each: the topology found and what was
/// done about it, parts left out, rays that met several shells where the surface follows the
/// outermost one, and points of the scan the surface did not reach, with the cause when the
/// fit knows it.
fn warnings(fitted: &Fit, scan: &Path) -> Vec<String> {
    let report = &fitted.report;
    let mut lines = Vec::new();
    if report.dropped_points > 0 {
        lines.push(format!(
            "warning: {} with a NaN or infinite coordinate {} left out of {}",
            count(report.dropped_points, "point", "points"),
            if report.dropped_points == 1 { "was" } else { "were" },
            scan.display()
        ));
    }
    if report.parts.len() > 1 {
        lines.push(format!(
            "note: {} has {} parts to fit (of at least {}% of its area): each is fitted on its own, named part 1, part 2, … by area, largest first",
            scan.display(),
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
            scan.display(),
            100.0 * area,
            dropped_list(&report.dropped_parts)
        ));
    }
    let source = &fitted.largest().source;
    let outer_shell = source.follows_outer_shell() && report.non_star_fraction > NON_STAR_WARNING;
    if outer_shell {
        lines.push(format!(
            "warning: {:.1}% of the rays meet {} more than once: it is not star-shaped about the centre, and the surface follows its outermost shell there",
            100.0 * report.non_star_fraction,
            scan.display()
        ));
    }
    if let Some(errors) = &report.both_ways
        && errors.unreached_fraction > UNREACHED_WARNING
    {
        let cause = if !report.dropped_parts.is_empty() {
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
            scan.display(),
            100.0 * UNREACHED
        ));
    }
    lines
}

/// The progress bar on a terminal (hidden otherwise): the parts done of all, and the stage.
fn progress_bar() -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(1);
    if let Ok(style) =
        ProgressStyle::with_template("{spinner} {elapsed} [{bar:24}] {pos}/{len} parts · {msg}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.enable_steady_tick(std::time::Duration::from_millis(100));
    bar
}

/// The fit's options from the command line.
fn options(args: &FitArgs, layout: Layout) -> Result<FitOptions, Failure> {
    let centre = match &args.centre {
        None => None,
        Some(list) => match list.0[..] {
            [x, y, z] => Some(DVec3::new(x, y, z)),
            _ => return Err(Failure::input("--centre: expected three numbers x,y,z")),
        },
    };
    // --smooth 0: the thesis's interpolation, with no smoothing or regularisation at all.
    let interpolate = args.smooth == Some(0.0);
    if interpolate && args.regularise.is_some_and(|r| r != Regularisation::Off) {
        return Err(Failure::input("--smooth 0 interpolates: it takes no --regularise"));
    }
    Ok(FitOptions {
        method: match args.method {
            MethodName::Auto => Method::Auto,
            MethodName::Mesh => Method::Mesh,
            MethodName::ShrinkWrap => Method::ShrinkWrap,
            MethodName::Radial => Method::Radial,
            MethodName::Contours => Method::Contours,
        },
        layout,
        resolution: args.resolution.map(|s| (s.0, s.1)),
        boundary: if args.closed {
            Boundary::Closed
        } else if args.open {
            Boundary::Open
        } else {
            Boundary::Auto
        },
        centre,
        smoothing: args.smooth.filter(|&s| s != 0.0).map(|sigma| Smoothing::Gaussian { sigma }),
        regularisation: if interpolate {
            Regularisation::Off
        } else {
            args.regularise.unwrap_or(Regularisation::Auto)
        },
        reduce: args.reduce,
        error: if args.no_error {
            ErrorMeasure::Off
        } else if args.exact_error {
            ErrorMeasure::Exact
        } else {
            ErrorMeasure::Fast
        },
        ..FitOptions::default()
    })
}

/// Fits, writes the surfaces and returns the summary (also written to `--report`).
///
/// # Errors
///
/// [`Failure::Input`] for an unreadable or malformed scan (with its line or byte), bad
/// options, an unknown output extension, or an output that cannot be written.
pub(crate) fn run(args: &FitArgs) -> Result<Json, Failure> {
    if !args.bezier && (args.tolerance.is_some() || args.bezier_scheme.is_some()) {
        return Err(Failure::input("--tolerance and --bezier-scheme apply with --bezier only"));
    }
    let layout = match layout(args)? {
        Some(layout) => layout,
        None => return super::fit_sections::run(args),
    };
    if args.slices.is_some() {
        return Err(Failure::input("--slices applies to --param sections only"));
    }
    let ext = args.output.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let as_grid = ext.as_deref() == Some("json");
    if !as_grid {
        MeshFormat::try_from_path(&args.output)
            .map_err(|e| Failure::input(format!("-o: {e} (or .json for the surface's grid)")))?;
    }
    check_writable(&args.output, "-o")?;
    if let Some(report) = &args.report {
        check_writable(report, "--report")?;
    }
    let options = options(args, layout)?;
    let bar = progress_bar();
    bar.set_message("reading the scan");
    let scan = read_scan(&args.scan)
        .map_err(|e| Failure::input(about_file(&args.scan, &e.to_string())))?;
    let result = fit(&scan, &options, &mut |p: Progress| {
        bar.set_length(p.parts as u64);
        bar.set_position(p.part as u64);
        bar.set_message(p.stage.name());
    });
    bar.finish_and_clear();
    let mut fitted = result.map_err(|e| Failure::input(format!("{}: {e}", args.scan.display())))?;
    for warning in warnings(&fitted, &args.scan) {
        eprintln!("{}", stderr_line(&warning));
    }
    let mut bezier_report = None;
    let files: Vec<PathBuf> = if args.bezier {
        let (files, report) = write_bezier(args, &fitted, ext.as_deref(), as_grid)?;
        bezier_report = Some(report);
        files
    } else if as_grid {
        write_file(&args.output, &grids_json(&fitted)?, false)?;
        vec![args.output.clone()]
    } else {
        let meshes = part_meshes(&mut fitted, &args.scan)?;
        save_parts(&fitted, &meshes, &args.output)?
    };
    let summary = summary(args, &fitted, &files, bezier_report)?;
    if let Some(path) = &args.report {
        write_file(path, &summary, true)?;
    }
    Ok(summary)
}

/// The layout of `--param`, or `None` for `--param sections` (algorithm 1, no geometry image),
/// after checking that no option of the other kind is given.
fn layout(args: &FitArgs) -> Result<Option<Layout>, Failure> {
    let only_images = |what: &str| {
        Err(Failure::input(format!(
            "{what} to the geometry-image layouts (--param sphere, octahedron or flat-octahedron)"
        )))
    };
    match args.param {
        ParamName::Sphere => Ok(Some(Layout::Sphere)),
        ParamName::Octahedron => Ok(Some(Layout::Octahedron)),
        ParamName::FlatOctahedron => Ok(Some(Layout::FlatOctahedron)),
        ParamName::Sections if args.bezier => only_images("--bezier applies"),
        ParamName::Sections if args.method != MethodName::Auto => only_images("--method applies"),
        ParamName::Sections if args.closed || args.open => only_images("--closed and --open apply"),
        ParamName::Sections => Ok(None),
    }
}

/// The grid of the one part's surface, or `{"parts": [{"name", "grid"}, …]}` for several.
fn grids_json(fitted: &Fit) -> Result<Json, Failure> {
    Ok(match &fitted.parts[..] {
        [only] => grid_json(&only.surface.rows())?,
        parts => {
            let named: Vec<(String, Json)> = fitted
                .report
                .parts
                .iter()
                .zip(parts)
                .map(|(r, p)| Ok((r.name.clone(), grid_json(&p.surface.rows())?)))
                .collect::<Result<_, Failure>>()?;
            json(&serde_json::json!({
                "parts": named.into_iter().map(|(name, grid)| serde_json::json!({"name": name, "grid": grid})).collect::<Vec<_>>()
            }))?
        }
    })
}

/// Each part's mesh: the one its error was measured on, or the same made now.
fn part_meshes(fitted: &mut Fit, scan: &Path) -> Result<Vec<TriangleMesh>, Failure> {
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
                    .map_err(|e| Failure::input(format!("{}: {e}", scan.display())))?
                    .mesh
            }
        };
        meshes.push(mesh);
    }
    Ok(meshes)
}

/// Writes one mesh per part: the one mesh as it is, or several as one scene of named meshes.
fn save_parts(
    fitted: &Fit,
    meshes: &[TriangleMesh],
    output: &Path,
) -> Result<Vec<PathBuf>, Failure> {
    Ok(match meshes {
        [only] => export::save(only, output)?,
        _ => {
            let named: Vec<NamedMesh<'_>> = fitted
                .report
                .parts
                .iter()
                .zip(meshes)
                .map(|(r, m)| NamedMesh::new(&r.name, m))
                .collect();
            export::save_scene(&named, output)?
        }
    })
}

/// `--bezier`: each part's surface as Bézier patches, written as JSON or OBJ (one part) or as a
/// mesh of the patches of one cover of each part; the files and the report of the largest.
fn write_bezier(
    args: &FitArgs,
    fitted: &Fit,
    ext: Option<&str>,
    as_grid: bool,
) -> Result<(Vec<PathBuf>, Json), Failure> {
    let start = std::time::Instant::now();
    let scheme = args.bezier_scheme.unwrap_or(BezierScheme::Hermite(HermiteDegree::Cubic));
    let tolerance = args
        .tolerance
        .map_or(hi_curve::bezier::DEFAULT_TOLERANCE, hi_curve::bezier::Tolerance::Absolute);
    let all = fitted
        .parts
        .iter()
        .map(|p| p.surface.to_bezier(scheme, tolerance))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| Failure::input(format!("--bezier: {e}")))?;
    let seconds = start.elapsed().as_secs_f64();
    // The patches of one cover of each part.
    let once: Vec<Vec<usize>> = all
        .iter()
        .zip(&fitted.parts)
        .map(|(patches, part)| {
            let w = part.domain.covering_window();
            (0..patches.patches.len())
                .filter(|&i| {
                    let p = patches.window(i);
                    p.u.start >= w.u.start - 1e-12
                        && p.u.end <= w.u.end + 1e-12
                        && p.v.start >= w.v.start - 1e-12
                        && p.v.end <= w.v.end + 1e-12
                })
                .collect()
        })
        .collect();
    let name = scheme.name();
    let report = BezierOut {
        report: surface_bezier::Report { scheme: name, report: &all[0].report },
        seconds,
        patches_once: once.iter().map(Vec::len).sum(),
    };
    let several = all.len() > 1;
    let files = if (as_grid || ext == Some("obj")) && several {
        return Err(Failure::input(format!(
            "--bezier writes one surface's patches to .json or .obj, and {} has {} parts: write a .glb or .gltf scene",
            args.scan.display(),
            all.len()
        )));
    } else if as_grid {
        let file = surface_bezier::patches_json(name, &all[0], &report)?;
        write_file(&args.output, &file, false)?;
        vec![args.output.clone()]
    } else if ext == Some("obj") {
        surface_bezier::write_obj(&all[0], &once[0], &args.output)?;
        vec![args.output.clone()]
    } else {
        let meshes = all
            .iter()
            .zip(&once)
            .map(|(patches, once)| patches.to_triangle_mesh_of(BEZIER_SAMPLES, once))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| Failure::input(format!("--bezier: {e}")))?;
        save_parts(fitted, &meshes, &args.output)?
    };
    Ok((files, json(&report)?))
}

/// The report of `--bezier`: the conversion's, its time and the patches written.
#[derive(Serialize)]
struct BezierOut<'a> {
    #[serde(flatten)]
    report: surface_bezier::Report<'a>,
    seconds: f64,
    patches_once: usize,
}

/// What `hi fit` did to the largest part of a mesh scan before parameterising it.
#[derive(Serialize)]
struct MeshOut {
    holes_filled: usize,
    hole_edges: usize,
    parts: usize,
    area_kept: f64,
    welded_points: usize,
    dropped_triangles: usize,
    reoriented_triangles: usize,
    split_vertices: usize,
    handles_cut: usize,
    stretch_efficiency: f64,
    area_ratio: f64,
}

/// Both directions of the fit's error, as printed.
#[derive(Serialize)]
struct BothWaysOut {
    scan_to_surface: DistancesOut,
    surface_to_scan: DistancesOut,
    filled_to_scan_max: f64,
    filled_to_scan_max_relative: f64,
    unreached_fraction: f64,
    diagonal: f64,
}

impl BothWaysOut {
    fn of(e: &FitErrors) -> Self {
        let diagonal = e.scan_to_surface.diagonal;
        Self {
            scan_to_surface: DistancesOut::of(&e.scan_to_surface),
            surface_to_scan: DistancesOut::of(&e.surface_to_scan),
            filled_to_scan_max: e.filled_to_scan_max,
            filled_to_scan_max_relative: relative(e.filled_to_scan_max, diagonal),
            unreached_fraction: e.unreached_fraction,
            diagonal,
        }
    }
}

/// The Hausdorff distance of an exact error measurement.
#[derive(Serialize)]
struct HausdorffOut {
    distance: f64,
    relative: f64,
    scan_to_surface_max: f64,
    surface_to_scan_max: f64,
}

/// One part, as printed.
#[derive(Serialize)]
struct PartOut<'a> {
    name: &'a str,
    domain: &'static str,
    why: &'a str,
    area_fraction: f64,
    genus: usize,
    boundary_loops: usize,
    holes_filled: usize,
    handles_cut: usize,
    image: [usize; 2],
    surface: (usize, usize),
    hole_fraction: f64,
    both_ways: Option<BothWaysOut>,
}

/// The topology found, as printed.
#[derive(Serialize)]
struct TopologyOut {
    parts: usize,
    parts_dropped: usize,
    part_floor: f64,
    genus: Vec<usize>,
    boundary_loops: Vec<usize>,
    domains: Vec<&'static str>,
}

/// The printed summary of `hi fit`.
#[derive(Serialize)]
struct Summary<'a> {
    scan: String,
    method: &'static str,
    method_reason: &'a str,
    points: usize,
    unused_points: usize,
    image_points: usize,
    dropped_points: usize,
    image: [usize; 2],
    surface: (usize, usize),
    non_star_fraction: f64,
    hole_fraction: f64,
    row_points: Option<&'a RowPoints>,
    mesh: Option<MeshOut>,
    regularisation: &'a RegularisationReport,
    stages: &'a [Stage],
    reduction: Option<&'a ReductionDeviation>,
    errors: Option<DistancesOut>,
    both_ways: Option<BothWaysOut>,
    hausdorff: Option<HausdorffOut>,
    topology: TopologyOut,
    parts: Vec<PartOut<'a>>,
    dropped_parts: &'a [DroppedPart],
    files: Vec<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    bezier: Option<Json>,
}

/// `x / d`, or 0 for an empty diagonal.
fn relative(x: f64, d: f64) -> f64 {
    if d > 0.0 { x / d } else { 0.0 }
}

/// The summary of a fit as JSON.
fn summary(
    args: &FitArgs,
    fitted: &Fit,
    files: &[PathBuf],
    bezier: Option<Json>,
) -> Result<Json, Failure> {
    let r = &fitted.report;
    let mesh = match &fitted.largest().source {
        SourceImage::Mesh(m) => Some(MeshOut {
            holes_filled: m.repair.holes,
            hole_edges: m.repair.hole_edges,
            parts: m.repair.components,
            area_kept: m.area_kept,
            welded_points: m.repair.welded_points,
            dropped_triangles: m.repair.dropped_triangles,
            reoriented_triangles: m.repair.reoriented_triangles,
            split_vertices: m.repair.split_vertices,
            handles_cut: m.repair.handles_cut,
            stretch_efficiency: m.quality.stretch_efficiency(),
            area_ratio: m.quality.area_ratio(),
        }),
        _ => None,
    };
    let image = fitted.largest().source.image();
    json(&Summary {
        scan: args.scan.display().to_string(),
        method: r.method.name(),
        method_reason: &r.method_reason,
        points: r.points,
        unused_points: r.unused_points,
        image_points: r.image_points,
        dropped_points: r.dropped_points,
        image: [image.rows(), image.cols()],
        surface: r.surface_size,
        non_star_fraction: r.non_star_fraction,
        hole_fraction: r.hole_fraction,
        row_points: r.row_points.as_ref(),
        mesh,
        regularisation: &r.regularisation,
        stages: &fitted.stages,
        reduction: r.reduction.as_ref(),
        errors: r.errors.as_ref().map(DistancesOut::of),
        both_ways: r.both_ways.as_ref().map(BothWaysOut::of),
        hausdorff: r.hausdorff.as_ref().map(|h| HausdorffOut {
            distance: h.distance(),
            relative: relative(h.distance(), h.scan_to_surface.diagonal),
            scan_to_surface_max: h.scan_to_surface.max,
            surface_to_scan_max: h.surface_to_scan.max,
        }),
        topology: TopologyOut {
            parts: r.parts.len(),
            parts_dropped: r.dropped_parts.len(),
            part_floor: r.part_floor,
            genus: r.parts.iter().map(|p| p.genus).collect(),
            boundary_loops: r.parts.iter().map(|p| p.boundary_loops).collect(),
            domains: r.parts.iter().map(|p| p.domain.name()).collect(),
        },
        parts: r
            .parts
            .iter()
            .map(|p| PartOut {
                name: &p.name,
                domain: p.domain.name(),
                why: &p.why,
                area_fraction: p.area_fraction,
                genus: p.genus,
                boundary_loops: p.boundary_loops,
                holes_filled: p.repair.holes,
                handles_cut: p.repair.handles_cut,
                image: [p.image_size.0, p.image_size.1],
                surface: p.surface_size,
                hole_fraction: p.hole_fraction,
                both_ways: p.errors.as_ref().map(BothWaysOut::of),
            })
            .collect(),
        dropped_parts: &r.dropped_parts,
        files: file_names(files),
        bezier,
    })
}
