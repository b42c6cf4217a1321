// SPDX-License-Identifier: MIT
//! The report of a fit as it is printed: the library's report with the relative errors, the
//! topology gathered, and the files written.

use std::path::PathBuf;

use hi_curve::ReductionDeviation;
use hi_geomimage::fit::{DroppedPart, FitErrors, RowPoints, Stage};
use hi_geomimage::regularise::RegularisationReport;
use hi_geomimage::{Fit, SourceImage};
use hi_scan::distance::Distances;
use serde::Serialize;
use serde_json::value::RawValue;

/// A one-way distance as printed: the library's summary and the relative numbers.
#[derive(Clone, Debug, Serialize)]
pub struct DistancesOut {
    /// The mean distance.
    pub mean: f64,
    /// The root mean square distance.
    pub rms: f64,
    /// The largest distance.
    pub max: f64,
    /// The diagonal of the scan's bounding box.
    pub diagonal: f64,
    /// Mean, RMS and max divided by the diagonal.
    pub relative: [f64; 3],
}

impl DistancesOut {
    /// The printed form of `d`.
    #[must_use]
    pub fn of(d: &Distances) -> Self {
        DistancesOut {
            mean: d.mean,
            rms: d.rms,
            max: d.max,
            diagonal: d.diagonal,
            relative: d.relative(),
        }
    }
}

/// What `hi fit` did to the largest part of a mesh scan before parameterising it.
#[derive(Debug, Serialize)]
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
#[derive(Debug, Serialize)]
pub(crate) struct BothWaysOut {
    scan_to_surface: DistancesOut,
    surface_to_scan: DistancesOut,
    filled_to_scan_max: f64,
    filled_to_scan_max_relative: f64,
    unreached_fraction: f64,
    diagonal: f64,
}

impl BothWaysOut {
    pub(crate) fn of(e: &FitErrors) -> Self {
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
#[derive(Debug, Serialize)]
struct HausdorffOut {
    distance: f64,
    relative: f64,
    scan_to_surface_max: f64,
    surface_to_scan_max: f64,
}

/// One part, as printed.
#[derive(Debug, Serialize)]
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
#[derive(Debug, Serialize)]
struct TopologyOut {
    parts: usize,
    parts_dropped: usize,
    part_floor: f64,
    genus: Vec<usize>,
    boundary_loops: Vec<usize>,
    domains: Vec<&'static str>,
}

/// The report of a fit as `hi fit` prints it and the Python package returns it: the method and
/// why, the points, the image, the surface, the stages and their times, the error both ways,
/// the topology and each part, the parts left out, and the files written.
#[derive(Debug, Serialize)]
pub struct Summary<'a> {
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
    bezier: Option<Box<RawValue>>,
}

/// `x / d`, or 0 for an empty diagonal.
fn relative(x: f64, d: f64) -> f64 {
    if d > 0.0 { x / d } else { 0.0 }
}

/// The summary of a fit of the scan named `scan` as `hi fit` prints it, with the files written
/// and the report of a Bézier conversion when there was one.
#[must_use]
pub fn summary<'a>(
    scan: &str,
    fitted: &'a Fit,
    files: &[PathBuf],
    bezier: Option<Box<RawValue>>,
) -> Summary<'a> {
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
    Summary {
        scan: scan.to_owned(),
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
        files: files.iter().map(|f| f.display().to_string()).collect(),
        bezier,
    }
}
