// SPDX-License-Identifier: MIT
//! The whole fitting pipeline: scan → its parts → a geometry image of each → (smoothing,
//! regularisation) → (reduction by Theorem 5.3) → harmonic surfaces → a mesh of each, timed
//! stage by stage, with the diagnostics and the fit's error both ways (§5.3–§5.4, §5.8, and
//! past them).
//!
//! How the geometry images are made ([`Method`]):
//!
//! | method | from | texels | when [`Method::Auto`] picks it |
//! |---|---|---|---|
//! | [`Method::Mesh`] | a mesh | each part of the mesh ([`hi_scan::repair`]) parameterised over the domain its topology asks for ([`Domain`], [`parts`]), each texel the surface point its parameter falls on | the scan has triangles, and its parts above the floor ([`PART_FLOOR`]) hold at least half its area |
//! | [`Method::ShrinkWrap`] | points | each part of the zero set of the points' signed distance ([`hi_scan::implicit`]) parameterised the same way, its texels projected onto the points' patches, pulled into the creases it bridged ([`crate::shrinkwrap`]) and refined by a moving least-squares fit to the points about each ([`hi_scan::implicit::MovingLeastSquares`]); a cloud larger than the images can hold is first summarised on a grid ([`hi_scan::cloud`]) | otherwise: point sets, and meshes the mesh method cannot take |
//! | [`Method::Radial`] | points | the distance along each ray from a centre (algorithm 2, [`crate::spherical`]) | never (the thesis's algorithm 2) |
//! | [`Method::Contours`] | points | the scan point each ray located, rows made contours (§5.8, [`crate::contours`]) | never (the thesis's §5.8) |
//!
//! A scan of several parts (separate eyes, a lid, an aeroplane's wheels) gives a surface per
//! part above the floor, each with its share of the texels; a part of genus 1 is fitted over
//! the torus with no cut, an open sheet over the mirrored square (see [`parts`]). A point set's
//! parts are those of its zero set that at least [`PART_MIN_VERTICES`] of its points are
//! nearest to: the rest are fragments of the grid (a few cells where the signed distance
//! crosses zero off the surface), counted in [`FitReport::method_reason`]. The ray methods fit
//! the whole scan as one surface.
//!
//! Then, per part, the thesis's optional Gaussian smoothing, the regularisation
//! ([`Regularisation`]: by default, for images made from points, a thin-plate penalty weighed
//! so that the surface departs from the texels by the noise left in them (the scan's own noise
//! level, [`hi_scan::noise`], as averaged by the quadric patches the texels lie on, or all of
//! it for a scan as thick as its points are far apart, whose patches follow the scatter), and none
//! for images sampled from a mesh, whose texels lie exactly on the scan's surface), the
//! optional reduction, and the harmonic surface through the result.
//!
//! The defaults ([`FitOptions::default`]) are the best this crate knows; [`FitOptions::thesis`]
//! reproduces the thesis's algorithm 2 (a 128² latitude–longitude image, no regularisation).

mod images;
mod measure;
pub mod parts;
mod report;
mod source;
mod stages;
mod surfaces;

use std::borrow::Cow;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use glam::DVec3;
use hi_curve::ReductionDeviation;
use hi_par::*;
use hi_scan::cloud::{cell_for_count, merge_duplicates, summarise};
use hi_scan::distance::{Distances, bounding_diagonal};
use hi_scan::implicit::{CELL, MovingLeastSquares, PointSurface};
use hi_scan::repair::{MAX_HANDLES, MeshPart, MeshParts, Repair, mesh_parts};
use hi_scan::scan::Scan;
use hi_surface::HarmonicSurface;

pub use measure::measure_fit;
pub use parts::{Boundary, DroppedPart, SHEET_SPAN};
pub use source::{MapQuality, MeshSource, SourceImage};
pub use stages::{Progress, Stage, StageKind};

use crate::contours::contour_image;
use crate::distance::{Hausdorff, distances_to_surface, hausdorff};
use crate::domain::Domain;
use crate::layout_mesh::LayoutMesh;
use crate::regularise::{Regularisation, RegularisationReport, regularise};
use crate::shrinkwrap::{ShrinkWrapImage, ShrinkWrapOptions, settle, shrink_wrap};
use crate::sphereparam::mesh_density_weights;
use crate::spherical::{Layout, SphericalOptions, spherical_image};
use crate::{Error, GeometryImage, Smoothing};
use hi_scan::repair::ClosedMesh;
use images::{Sourced, Sources, leave_out_guesswork, sources};
use parts::{PlannedPart, drop_fragments, part_image_or_sphere, plan, vertex_counts};
use report::{measure_error, part_report, row_points};
use surfaces::{Surfaced, filled_on_grid, regularisation_for, surface_of};

/// How the geometry image is made; see the module documentation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Method {
    /// A parameterisation of each part of the scan's mesh, when its parts above the floor hold
    /// at least half its area; the shrink-wrap otherwise.
    #[default]
    Auto,
    /// A parameterisation of each part of the scan's mesh (over the sphere, the torus or the
    /// square, [`Domain`]).
    Mesh,
    /// A surface wrapped onto the points ([`crate::shrinkwrap`]): each part of the zero set of
    /// their signed distance parameterised, its texels projected onto them and pulled into the
    /// creases it bridged.
    ShrinkWrap,
    /// Rays from a centre, the distance along each averaged over the points about it
    /// (algorithm 2).
    Radial,
    /// Rays from a centre, each keeping the scan point it located, rows made contours (§5.8).
    Contours,
}

impl Method {
    /// The name used in reports: "mesh", "shrink-wrap", "radial", "contours" ("auto" before
    /// it is resolved).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Auto => "auto",
            Self::Mesh => "mesh",
            Self::ShrinkWrap => "shrink-wrap",
            Self::Radial => "radial",
            Self::Contours => "contours",
        }
    }
}

/// How the fit's error is measured.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum ErrorMeasure {
    /// Not measured.
    Off,
    /// Both ways against the surface sampled on a grid this many times finer than its own and
    /// triangulated: scan points to that triangulation, its samples to the scan's triangles
    /// (or nearest points).
    Sampled(usize),
    /// Both ways against the mesh the fit is written as ([`FitPart::mesh`], sampled
    /// [`mesh_oversample`] times per texel): every scan point to its closest point on the
    /// mesh, every mesh vertex to the scan's triangles (or nearest point), exactly, by a
    /// bounding-volume hierarchy ([`hi_scan::closest`]).
    #[default]
    Fast,
    /// As [`ErrorMeasure::Fast`] with the exact hierarchy both ways, then each scan point's
    /// closest point on the mesh refined onto the harmonic surface itself by Gauss–Newton
    /// steps (on the bicubic Hermite interpolant of its values and derivatives at the grid,
    /// O(h⁴) from the surface): the distance to the surface, not to its mesh.
    Exact,
}

/// The settings of [`fit`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FitOptions {
    /// How the geometry image is made. Default [`Method::Auto`].
    pub method: Method,
    /// The parameterisation of the geometry image: spherical (algorithm 2), octahedral or
    /// flattened octahedral (§5.3). Default [`Layout::FlatOctahedron`].
    pub layout: Layout,
    /// Geometry image rows × columns (rows even but for the plain octahedron); `None` picks
    /// a size from the scan ([`auto_resolution`] for a mesh, [`auto_resolution_points`] for a
    /// point set). A scan of several parts shares these texels
    /// out among them by area, and a part over the torus or the square takes as many in the
    /// aspect its map asks for. Default `None`.
    pub resolution: Option<(usize, usize)>,
    /// Which parts with a boundary are open sheets. Default [`Boundary::Auto`].
    pub boundary: Boundary,
    /// The centre of the rays; `None` for the mean of the points.
    pub centre: Option<DVec3>,
    /// A smoothing filter applied to the geometry image (§5.4), if any.
    pub smoothing: Option<Smoothing>,
    /// The regularisation of the surface through the image. Default
    /// [`Regularisation::Auto`]: to the noise left in the texels for images made from points
    /// (the scan's noise level times √(6/16), or all of it for a lump of noise, see
    /// [`crate::fit()`]), none for images sampled from a mesh.
    pub regularisation: Regularisation,
    /// Keep about this fraction of the texels by Theorem 5.3 (each side scaled by its square
    /// root; §5.8 keeps 0.25), if any. In (0, 1].
    pub reduce: Option<f64>,
    /// For the ray methods, a mesh with fewer points than this gets more, sampled on its
    /// triangles ([`hi_scan::sampling::densify`]), for the geometry image (errors are still
    /// measured against the scan's own points and mesh). Default 200 000; 0 turns it off.
    pub densify: usize,
    /// Time the 4× rasterisation of the surface that the thesis's Table 5.1 times as
    /// "harmonic interpolation". Default false.
    pub rasterise: bool,
    /// How the error is measured. Default [`ErrorMeasure::Fast`].
    pub error: ErrorMeasure,
    /// Refuse an image made by rays (algorithm 2, §5.8, or the rays' wrap) that has more than
    /// this fraction of filled texels (texels no scan data reached), with
    /// [`Error::MostlyHoles`]: such a surface is mostly guesswork (with several parts, that part
    /// is left out). Default [`MAX_HOLE_FRACTION`]; 1 accepts any image with at least one
    /// measured texel (an image with none is always refused). The caps a parameterisation puts
    /// over a scan's holes are reported ([`PartReport::hole_fraction`]), not refused.
    pub max_hole_fraction: f64,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            method: Method::Auto,
            layout: Layout::FlatOctahedron,
            resolution: None,
            boundary: Boundary::Auto,
            centre: None,
            smoothing: None,
            regularisation: Regularisation::Auto,
            reduce: None,
            densify: 200_000,
            rasterise: false,
            error: ErrorMeasure::Fast,
            max_hole_fraction: MAX_HOLE_FRACTION,
        }
    }
}

impl FitOptions {
    /// The thesis's algorithm 2 as it stands: rays from the centroid over a 128 × 128
    /// latitude–longitude image, interpolated with no regularisation, the 4× rasterisation of
    /// Table 5.1 timed, the error measured on the surface sampled 4× finer; images with many
    /// holes are fitted (the thesis fills them, and shows what that does, Figure 5.24).
    #[must_use]
    pub fn thesis() -> Self {
        Self {
            method: Method::Radial,
            layout: Layout::Sphere,
            resolution: Some((128, 128)),
            regularisation: Regularisation::Off,
            rasterise: true,
            error: ErrorMeasure::Sampled(4),
            max_hole_fraction: 1.0,
            ..Self::default()
        }
    }
}

/// The image size [`fit`] picks for a mesh of `points` vertices: square, a multiple of 32, with
/// about eight distinct texels per vertex (half the texels of a doubled layout), from
/// [`MESH_MIN_SIDE`]² to 512². Even a good parameterisation samples some parts of a surface a
/// few times more densely than others, and the sparsest parts must still see every vertex.
///
/// # Examples
///
/// ```
/// use hi_geomimage::fit::auto_resolution;
///
/// assert_eq!(auto_resolution(100), (256, 256));
/// assert_eq!(auto_resolution(3_000), (256, 256));
/// assert_eq!(auto_resolution(10_000), (416, 416));
/// assert_eq!(auto_resolution(35_000), (512, 512));
/// ```
#[must_use]
pub fn auto_resolution(points: usize) -> (usize, usize) {
    let side = texel_side(points).max(MESH_MIN_SIDE);
    (side, side)
}

/// The least side [`auto_resolution`] gives a mesh. A coarse mesh's few vertices are corners
/// of flat faces whose edges the harmonic surface can only round: its ripples beside them are
/// as wide as a texel, so a cube of 8 vertices fitted at 64² is wavy all over (its corners 2 %
/// of the diagonal off), at 128² rippled along its edges, and at 256² smooth but for a fringe
/// at the edges (its corners 0.7 % off), at little cost for so small a mesh.
pub const MESH_MIN_SIDE: usize = 256;

/// The side of a square image with about eight distinct texels per point (side²/2 ≈ 8·points),
/// a multiple of 32 from 64 to 512.
fn texel_side(points: usize) -> usize {
    let side = (16.0 * points as f64).sqrt();
    #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "clamped")]
    let side = ((side / 32.0).ceil() as usize * 32).clamp(64, 512);
    side
}

/// The image size [`fit`] picks for a point set of `points` points: square, a multiple of 32,
/// from 64² to 512². A point set's texels are projections onto the surface its points sample,
/// so a dense cloud needs no more texels than points: about two distinct texels per point (half
/// the texels of a doubled layout). A sparse set needs more: between its points the texels
/// follow the local quadrics, and its sparsest parts (a leg or a horn, which even a good
/// parameterisation samples a few times less densely than the body) must still see every
/// point; so up to [`SPARSE_SIDE`]² it gets twelve distinct texels per point, half as many
/// again as a mesh's vertices get (a point set has no triangles to say where its surface runs
/// between its points).
///
/// # Examples
///
/// ```
/// use hi_geomimage::fit::auto_resolution_points;
///
/// assert_eq!(auto_resolution_points(500), (128, 128));
/// assert_eq!(auto_resolution_points(3_000), (288, 288));
/// assert_eq!(auto_resolution_points(18_000), (320, 320));
/// assert_eq!(auto_resolution_points(50_000), (448, 448));
/// assert_eq!(auto_resolution_points(200_000), (512, 512));
/// ```
#[must_use]
pub fn auto_resolution_points(points: usize) -> (usize, usize) {
    let dense = texel_side(points / 4);
    let sparse = texel_side(points.saturating_mul(3) / 2).min(SPARSE_SIDE);
    let side = dense.max(sparse);
    (side, side)
}

/// The largest side [`auto_resolution_points`] gives a sparse point set beyond two distinct
/// texels per point.
pub const SPARSE_SIDE: usize = 320;

/// How many distinct located points the rows of a §5.8 image had.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RowPoints {
    /// The fewest in a row.
    pub min: usize,
    /// The mean over the rows.
    pub mean: f64,
    /// The most in a row (at most the number of columns).
    pub max: usize,
    /// Rows that located no point (filled from their neighbours).
    pub empty_rows: usize,
}

/// The fit's error both ways.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FitErrors {
    /// From each scan point (for a mesh: each point its triangles use) to the surface.
    pub scan_to_surface: Distances,
    /// From each sample of the surface, except those on filled texels, to the scan (its
    /// triangles, or its nearest point for a point set).
    pub surface_to_scan: Distances,
    /// The largest distance from a sample on filled texels to the scan (0 when none was
    /// filled): how far the surface had to bridge gaps in the data.
    pub filled_to_scan_max: f64,
    /// The fraction of the scan points farther from the surface than [`UNREACHED`] of the
    /// diagonal: parts of the scan the surface did not reach.
    pub unreached_fraction: f64,
}

/// What was done with one part of the scan, and how well its surface fits.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PartReport {
    /// Its name: `part 1`, `part 2`, … by area, largest first (the ray methods' one surface is
    /// `part 1`).
    pub name: String,
    /// The domain it was fitted over.
    pub domain: Domain,
    /// Why that domain, in words.
    pub why: String,
    /// Its share of the scan's area (1 for a surface of the whole scan).
    pub area_fraction: f64,
    /// Its genus once its holes are closed (before any handle is cut).
    pub genus: usize,
    /// Its boundary loops, before any was closed.
    pub boundary_loops: usize,
    /// What was repaired to make it the surface its domain needs (holes filled, handles cut).
    pub repair: Repair,
    /// The image size (rows, columns).
    pub image_size: (usize, usize),
    /// The grid of the final surface (rows, columns).
    pub surface_size: (usize, usize),
    /// The fraction of the rays from the centre that met several shells (0 where no rays were
    /// cast).
    pub non_star_fraction: f64,
    /// The fraction of the image with no data, filled (holes, cuts).
    pub hole_fraction: f64,
    /// The regularisation applied.
    pub regularisation: RegularisationReport,
    /// The error of the reduction, if one was made.
    pub reduction: Option<ReductionDeviation>,
    /// Both ways: the scan points nearest this part's surface to it, and its samples to the
    /// scan, if measured (summaries: the per-point distances are in [`FitReport::errors`]).
    pub errors: Option<FitErrors>,
}

/// What [`fit`] did and how well the result fits.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FitReport {
    /// How the images were made (never [`Method::Auto`]).
    pub method: Method,
    /// Why [`Method::Auto`] chose it, or why the mesh could not be used.
    pub method_reason: String,
    /// Points of the scan (finite ones; for a mesh, those its triangles use).
    pub points: usize,
    /// Points of a mesh that no triangle uses, left out of the fit and its error.
    pub unused_points: usize,
    /// Points the geometry images were built from: for the ray methods, the scan's and those
    /// sampled on its triangles when it was sparse; for a large point cloud, its summary.
    pub image_points: usize,
    /// Points the reader dropped for a non-finite coordinate.
    pub dropped_points: usize,
    /// The parts fitted, largest first.
    pub parts: Vec<PartReport>,
    /// The parts left out: below the floor, or not to be made a surface.
    pub dropped_parts: Vec<DroppedPart>,
    /// The floor: the least share of the scan's area a part needs to be fitted.
    pub part_floor: f64,
    /// The image size of the largest part (rows, columns).
    pub image_size: (usize, usize),
    /// The fraction of rays from the centre that met several shells: the scan is not
    /// star-shaped about the centre there. Where [`SourceImage::follows_outer_shell`], the fit
    /// follows the outermost shell in those directions; otherwise it is only a description of
    /// the scan's shape (0 where no rays were cast).
    pub non_star_fraction: f64,
    /// The fraction of the largest part's image with no data, filled (holes).
    pub hole_fraction: f64,
    /// For [`Method::Contours`], the distinct located points per row.
    pub row_points: Option<RowPoints>,
    /// The scan's noise level as estimated for the regularisation ([`hi_scan::noise`]), when
    /// it was.
    pub noise: Option<hi_scan::noise::Noise>,
    /// The regularisation applied to the largest part.
    pub regularisation: RegularisationReport,
    /// The grid of the largest part's final surface (rows, columns).
    pub surface_size: (usize, usize),
    /// The error of the largest part's reduction, if one was made.
    pub reduction: Option<ReductionDeviation>,
    /// Distances from every scan point to the nearest surface, if measured.
    pub errors: Option<Distances>,
    /// Both ways, over every part, if measured (its scan → surface without the per-point
    /// distances, which are in [`FitReport::errors`]).
    pub both_ways: Option<FitErrors>,
    /// Both-way distances to the scan's mesh (thesis measurement with
    /// [`ErrorMeasure::Sampled`] on a mesh scan), if measured.
    pub hausdorff: Option<Hausdorff>,
}

/// One fitted part: its surface, images and mesh.
#[derive(Clone, Debug)]
pub struct FitPart {
    /// The harmonic surface; [`Domain`] says which (u, v) cover the part once.
    pub surface: HarmonicSurface<DVec3>,
    /// The raw geometry image with its diagnostic maps (before smoothing and reduction).
    pub source: SourceImage,
    /// The geometry image the surface interpolates (after smoothing, regularisation and
    /// reduction).
    pub image: GeometryImage,
    /// The domain of the image.
    pub domain: Domain,
    /// The mesh of the surface the error was measured on (and that `hi fit` writes), when
    /// the error was measured by [`ErrorMeasure::Fast`] or [`ErrorMeasure::Exact`].
    pub mesh: Option<LayoutMesh>,
}

/// The fitted parts of a scan with their report and stage times.
#[derive(Clone, Debug)]
pub struct Fit {
    /// The parts, largest first (the ray methods give one).
    pub parts: Vec<FitPart>,
    /// Diagnostics and errors: the same for the same input and options.
    pub report: FitReport,
    /// The stages, in order, with their wall-clock times (which differ from run to run, and
    /// so are kept out of the report); a stage of several parts is timed over all of them.
    pub stages: Vec<Stage>,
}

impl Fit {
    /// The largest part (every fit has one).
    #[must_use]
    pub fn largest(&self) -> &FitPart {
        &self.parts[0]
    }
}

/// The number of mesh samples per texel along each axis for the mesh of a fitted part that
/// holds `area_fraction` of the scan's area (and its error measured with
/// [`ErrorMeasure::Fast`]): enough for at least 192 · `area_fraction`^¼ samples around the
/// longer axis (192 for the whole scan), so that a coarse image still gives a mesh that follows
/// its surface, and 1 from there up, where the texels are as close as the scan's points. A mesh
/// of N samples across a part of size s strays from the surface by about s / N² (a chord over
/// curvature 1/s); a part of a fraction a of the area has s ∝ √a, so N ∝ a^¼ strays as far, as
/// a share of the scan's size, as the whole scan's mesh (a wheel of 0.1 % of an aeroplane's
/// area gets 34 samples around, not 192).
#[must_use]
pub fn mesh_oversample(surface: &HarmonicSurface<DVec3>, area_fraction: f64) -> usize {
    let share = if area_fraction.is_finite() { area_fraction.clamp(1e-6, 1.0) } else { 1.0 };
    #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "in [1, 192]")]
    let around = (MESH_SAMPLES as f64 * share.powf(0.25)).ceil().max(1.0) as usize;
    around.div_ceil(surface.m().max(surface.n()).max(1)).max(1)
}

/// Mesh samples around the longer axis of the whole scan's surface, at least
/// ([`mesh_oversample`]).
const MESH_SAMPLES: usize = 192;

/// A part of the scan with less than this share of its area is not fitted (it is named in
/// [`FitReport::dropped_parts`]): loose scraps and specks.
pub const PART_FLOOR: f64 = 0.0005;

/// A part of a point set's zero set with fewer vertices than this is not fitted.
pub const PART_MIN_VERTICES: usize = 12;

/// A part of a mesh with fewer vertices than this is not fitted: 4, the fewest a closed surface
/// has (the tetrahedron). A coarse mesh's few vertices are its corners (a cube's 8), where a
/// zero set's few vertices are a fragment of its grid.
pub const MESH_PART_MIN_VERTICES: usize = 4;

/// Below this share of the scan's area in the parts above the floor, [`Method::Auto`] does not
/// parameterise the mesh's parts but wraps its points: the scraps are most of the scan.
const MIN_AREA_KEPT: f64 = 0.5;

/// A scan point farther than this fraction of the diagonal from the surface is unreached.
pub const UNREACHED: f64 = 0.02;

/// Above this fraction of filled texels a fit is refused by default
/// ([`FitOptions::max_hole_fraction`]): the image is mostly guesswork.
pub const MAX_HOLE_FRACTION: f64 = 0.5;

/// The grids a point set's zero set is taken on, in multiples of
/// [`PointSurface::zero_set_cell`], until its parts
/// above the floor that can be made surfaces hold [`MIN_AREA_KEPT`] of its area (else the rays
/// are wrapped).
const ZERO_SET_COARSER: [f64; 2] = [1.0, 2.0];

/// A part of a point set's zero set is taken again on a grid of its own when its points are
/// sparse enough for a grid this many times as coarse as the one it was found on (see
/// `regrid_sparse_parts`).
const REGRID_RATIO: f64 = 1.5;

/// The grids a part of a point set's zero set is taken again on (see `retaken`), each this
/// times the cell of the one before.
const REGRID_STEP: f64 = 0.8;

/// The least share of its area a part of a point set's zero set taken again on a coarser grid
/// must keep (see `retaken`).
const REGRID_AREA: f64 = 0.9;

/// A part of a point set's zero set nearest to fewer points keeps the grid it was found on:
/// too few to say how densely the part is sampled.
const REGRID_MIN_POINTS: usize = 64;

/// A point set's zero set on a finer grid of [`ZERO_SET_COARSER`] is taken to have at least
/// this many times the handles of its zero set on the coarsest, which is taken first: when
/// that is more than [`MAX_HANDLES`] (the most a finer grid's parts may have), the finer grid is
/// not tried. Halving the cell resolves the tunnels between sheets half as far apart, and real
/// scans have more of those: on the bare vertices of the shared models and CGAL's building,
/// the finer grid's genus was 2× the coarser's (Hoppe's cessna, 20 and 10) to 6× (the spider,
/// 12 and 2); the head's was 48 and 22, the building's 122 and 47, where the finer grid was
/// taken and given up before.
const FINER_GENUS_GROWTH: f64 = 2.0;

/// The most handles cut on a point set's zero set on the coarsest grid of
/// [`ZERO_SET_COARSER`] (on the finer ones, [`MAX_HANDLES`]: a zero set with more is taken
/// again on a coarser grid, where the tunnels between near sheets mostly close). Beyond, the
/// rays are wrapped; their surface follows the points' outermost shell only, so cutting up to
/// this many handles is worth its time: CGAL's building (100 000 points, genus 47 on the
/// coarsest grid) fits with a mean error half the rays' and equal to screened Poisson's.
const COARSEST_GRID_HANDLES: usize = 64;

/// Points in each local quadric fit of a point set.
const NEIGHBOURS: usize = 16;

/// A cloud is summarised ([`hi_scan::cloud`]) to about this many points per distinct texel of
/// its images: enough for the local surface the texels settle on to follow what the image can
/// hold (a finer summary changes the fit by less than the scan's noise), few enough that the
/// zero set and its parameterisation cost what the image does.
const SUMMARY_POINTS: f64 = 0.5;

/// How far, in point spacings (of the summary, for a summarised cloud), a texel settled on the
/// points' patches may move when refined on the points themselves, and how far off its tangent
/// plane the points it is fitted to may lie (farther, they belong to another sheet).
const REFINE_BAND: f64 = 0.5;

/// A summary has at least this many points, however small the images (the zero set of the
/// points' signed distance and its topology do not depend on them).
const SUMMARY_MIN: usize = 50_000;

/// A cloud with more than this many times the points of its summary is summarised; a smaller
/// one is used as it is.
const SUMMARY_RATIO: f64 = 2.0;

/// The points its triangles use, the triangles renumbered, and how many were unused; a point
/// set as it is.
fn referenced(scan: &Scan) -> (Cow<'_, [DVec3]>, Vec<[u32; 3]>, usize) {
    if scan.triangles.is_empty() {
        return (Cow::Borrowed(&scan.points), Vec::new(), 0);
    }
    let mut index = vec![u32::MAX; scan.points.len()];
    let mut points = Vec::with_capacity(scan.points.len());
    let triangles: Vec<[u32; 3]> = scan
        .triangles
        .iter()
        .map(|t| {
            t.map(|k| {
                let k = k as usize;
                if index[k] == u32::MAX {
                    index[k] = u32::try_from(points.len()).unwrap_or(u32::MAX);
                    points.push(scan.points[k]);
                }
                index[k]
            })
        })
        .collect();
    let unused = scan.points.len() - points.len();
    (Cow::Owned(points), triangles, unused)
}

/// A point set's `points` each once, with the scan's normals (averaged over a point's
/// copies), and how many copies were merged: a point listed twice (a mesh's vertices written
/// triangle by triangle, as an STL file or a mesh's seams list them) is one point, or the
/// nearest neighbours about it would be fewer distinct points than the local fits need, and
/// the fit would change with the copies. A mesh's points (`triangles` not empty) as they are,
/// without normals.
#[expect(clippy::type_complexity, reason = "the three results named in the documentation")]
fn distinct<'a>(
    scan: &'a Scan,
    points: Cow<'a, [DVec3]>,
    triangles: &[[u32; 3]],
) -> Result<(Cow<'a, [DVec3]>, Option<Cow<'a, [DVec3]>>, usize), Error> {
    if !triangles.is_empty() {
        return Ok((points, None, 0));
    }
    let normals = scan.normals.as_deref();
    let merged = merge_duplicates(&points, normals)?;
    let repeats = points.len() - merged.points.len();
    if repeats == 0 {
        return Ok((points, normals.map(Cow::Borrowed), 0));
    }
    Ok((Cow::Owned(merged.points), merged.normals.map(Cow::Owned), repeats))
}

/// Times the stages of a fit and tells the progress display.
struct Clock<'a> {
    stages: Vec<Stage>,
    on_stage: &'a mut (dyn FnMut(Progress) + Send),
}

impl Clock<'_> {
    /// Runs `work` as `stage` of part `part` of `parts`, adding its time to the stage's.
    fn run<T>(
        &mut self,
        stage: StageKind,
        (part, parts): (usize, usize),
        work: impl FnOnce() -> T,
    ) -> T {
        (self.on_stage)(Progress { stage, part, parts });
        let start = Instant::now();
        let out = work();
        self.add(stage, start.elapsed().as_secs_f64());
        out
    }

    /// Runs `work` on each of `items` (the parts) as `stage`, in parallel, adding the time they
    /// take together to the stage's. The display is told of part 0 as they start, then of how
    /// many have ended as each ends (but the last), so that it counts them whatever order they
    /// end in; one at a time (without the `parallel` feature) that is what [`Clock::run`] tells.
    fn run_each<P: Send, T: Send>(
        &mut self,
        stage: StageKind,
        items: &mut [P],
        work: impl Fn(&mut P) -> T + Sync + Send,
    ) -> Vec<T> {
        let parts = items.len();
        (self.on_stage)(Progress { stage, part: 0, parts });
        let start = Instant::now();
        let ended = AtomicUsize::new(0);
        let on_stage = Mutex::new(&mut *self.on_stage);
        let out: Vec<T> = items
            .par_iter_mut()
            .map(|item| {
                let out = work(item);
                let part = ended.fetch_add(1, Ordering::Relaxed) + 1;
                if part < parts
                    && let Ok(mut tell) = on_stage.lock()
                {
                    (*tell)(Progress { stage, part, parts });
                }
                out
            })
            .collect();
        self.add(stage, start.elapsed().as_secs_f64());
        out
    }

    /// Adds `seconds` to `stage`'s time.
    fn add(&mut self, stage: StageKind, seconds: f64) {
        match self.stages.iter_mut().find(|s| s.kind == stage) {
            Some(s) => s.seconds += seconds,
            None => self.stages.push(Stage { kind: stage, seconds }),
        }
    }
}

/// The options [`fit`] checks before it starts.
fn check_options(options: &FitOptions) -> Result<(), Error> {
    if let Some(r) = options.reduce
        && !(r > 0.0 && r <= 1.0)
    {
        return Err(Error::InvalidOption {
            name: "reduce",
            value: r,
            expected: "0 < fraction ≤ 1",
        });
    }
    if !(0.0..=1.0).contains(&options.max_hole_fraction) {
        return Err(Error::InvalidOption {
            name: "max_hole_fraction",
            value: options.max_hole_fraction,
            expected: "0 ≤ fraction ≤ 1",
        });
    }
    if let Some((rows, cols)) = options.resolution {
        crate::image::check_resolution(rows, cols)?;
    }
    Ok(())
}

/// Refuses points that span no surface: all on a line (for any fit), or all on a plane when
/// every part must be closed (a closed surface needs a volume).
fn check_spread(points: &[DVec3], boundary: Boundary) -> Result<(), Error> {
    let n = points.len().max(1) as f64;
    let centre = points.iter().copied().sum::<DVec3>() / n;
    let mut m = glam::DMat3::ZERO;
    for p in points {
        let d = *p - centre;
        m += glam::DMat3::from_cols(d * d.x, d * d.y, d * d.z);
    }
    let m = m * (1.0 / n);
    // The covariance's eigenvalues λ₁ ≥ λ₂ ≥ λ₃ from its invariants.
    let trace = m.x_axis.x + m.y_axis.y + m.z_axis.z;
    let diagonal = bounding_diagonal(points);
    let tiny = (1e-9 * diagonal).powi(2);
    let a = m.to_cols_array();
    let minors = a[0] * a[4] - a[1] * a[3] + a[0] * a[8] - a[2] * a[6] + a[4] * a[8] - a[5] * a[7];
    // λ₂ + λ₃ is small iff the points lie near a line: minors ≈ λ₁(λ₂ + λ₃).
    if trace <= tiny || minors <= tiny * trace {
        return Err(Error::Degenerate { what: "the points lie on a line: they span no surface" });
    }
    if boundary == Boundary::Closed && m.determinant().abs() <= tiny * minors {
        return Err(Error::Degenerate {
            what: "the points lie on a plane: a closed surface needs a volume (fit them as an open sheet)",
        });
    }
    Ok(())
}

/// Fits a harmonic surface to each part of a scan; see the module documentation. `on_stage`
/// is told each stage as it starts, and of which part (for a progress display); the parts'
/// images are made in parallel, and it is told of each as the one before it ends (from any
/// thread, one call at a time).
///
/// # Errors
///
/// [`Error::InvalidOption`] for `reduce` outside (0, 1] or `max_hole_fraction` outside
/// [0, 1]; [`Error::InvalidResolution`] for a bad `resolution`; [`Error::TooFewPoints`] for a
/// scan with fewer than 4 points; [`Error::Degenerate`] for points all on a line, or all on a
/// plane with [`Boundary::Closed`]; [`Error::Topology`] when [`Method::Mesh`] is asked for and
/// no part of the mesh can be parameterised; [`Error::MostlyHoles`] when more than
/// [`FitOptions::max_hole_fraction`] of every part's image (or all of it) had no data; the
/// errors of the image builders, [`GeometryImage::smoothed`], [`regularise`] and
/// [`GeometryImage::resampled`].
pub fn fit(
    scan: &Scan,
    options: &FitOptions,
    on_stage: &mut (dyn FnMut(Progress) + Send),
) -> Result<Fit, Error> {
    check_options(options)?;
    let (points, triangles, unused_points) = referenced(scan);
    let listed = points.len();
    let (points, normals, repeats) = distinct(scan, points, &triangles)?;
    if points.len() < 4 {
        return Err(Error::TooFewPoints { found: points.len(), needed: 4 });
    }
    check_spread(&points, options.boundary)?;
    let size = options.resolution.unwrap_or_else(|| {
        if triangles.is_empty() {
            auto_resolution_points(points.len())
        } else {
            auto_resolution(points.len())
        }
    });
    let mut clock = Clock { stages: Vec::new(), on_stage };
    let mut sources =
        sources((&points, normals.as_deref(), &triangles), options, size, &mut clock)?;
    if repeats > 0 {
        sources.reason += &format!("; {repeats} points that repeat another exactly taken once");
    }
    leave_out_guesswork(&mut sources, options.max_hole_fraction)?;
    let Sources { parts: sourced, dropped, method, reason, image_points } = sources;
    let (how, noise) = regularisation_for(options, method, &image_points);
    let n = sourced.len();
    let mut surfaced = Vec::with_capacity(n);
    for (k, part) in sourced.iter().enumerate() {
        surfaced.push(surface_of(&part.source, options, how, (k, n), &mut clock)?);
    }
    let measured =
        measure_error(&sourced, &surfaced, (&points, &triangles), options, method, &mut clock)?;
    let (first, largest) = (&sourced[0], &surfaced[0]);
    let report = FitReport {
        method,
        method_reason: reason,
        points: listed,
        unused_points,
        image_points: image_points.len(),
        dropped_points: scan.dropped_points,
        image_size: (first.source.image().rows(), first.source.image().cols()),
        non_star_fraction: first.source.non_star_fraction(),
        hole_fraction: first.source.hole_fraction(),
        row_points: row_points(&first.source),
        noise,
        regularisation: largest.regularisation,
        surface_size: (largest.surface.m(), largest.surface.n()),
        reduction: largest.reduction,
        errors: measured.errors,
        both_ways: measured.both_ways,
        hausdorff: measured.hausdorff,
        parts: sourced
            .iter()
            .zip(&surfaced)
            .zip(measured.by_part)
            .map(|((p, s), e)| part_report(p, s, e))
            .collect(),
        dropped_parts: dropped,
        part_floor: PART_FLOOR,
    };
    let parts = sourced
        .into_iter()
        .zip(surfaced)
        .zip(measured.meshes)
        .map(|((p, s), mesh)| FitPart {
            surface: s.surface,
            source: p.source,
            image: s.image,
            domain: p.domain,
            mesh,
        })
        .collect();
    Ok(Fit { parts, report, stages: clock.stages })
}
