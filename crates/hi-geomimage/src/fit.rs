// SPDX-License-Identifier: MIT
//! The whole fitting pipeline: scan → geometry image → (smoothing, regularisation) →
//! (reduction by Theorem 5.3) → harmonic surface → a closed mesh of it, timed stage by stage,
//! with the diagnostics and the fit's error both ways (§5.3–§5.4, §5.8, and past them).
//!
//! How the geometry image is made ([`Method`]):
//!
//! | method | from | texels | when [`Method::Auto`] picks it |
//! |---|---|---|---|
//! | [`Method::Mesh`] | a mesh | the surface point each texel's direction falls on under a spherical parameterisation of the mesh ([`crate::sphereparam`]) | the scan has triangles, closes to genus 0 ([`hi_scan::repair`]), and its largest part holds at least half its area |
//! | [`Method::ShrinkWrap`] | points | the zero set of the points' signed distance parameterised over the sphere, projected onto the points and pulled into the creases it bridged ([`crate::shrinkwrap`]) | otherwise: point sets, and meshes the mesh method cannot take |
//! | [`Method::Radial`] | points | the distance along each ray from a centre (algorithm 2, [`crate::spherical`]) | never (the thesis's algorithm 2) |
//! | [`Method::Contours`] | points | the scan point each ray located, rows made contours (§5.8, [`crate::contours`]) | never (the thesis's §5.8) |
//!
//! Then the thesis's optional Gaussian smoothing, the regularisation ([`Regularisation`]:
//! by default, for images made from points, a thin-plate penalty weighed so that the surface
//! departs from the texels by the scan's own noise level ([`hi_scan::noise`]), and none for
//! images sampled from a mesh, whose texels lie exactly on the scan's surface), the optional
//! reduction, and the harmonic surface through the result.
//!
//! The defaults ([`FitOptions::default`]) are the best this crate knows; [`FitOptions::thesis`]
//! reproduces the thesis's algorithm 2 (a 128² latitude–longitude image, no regularisation).

use std::time::Instant;

use glam::DVec3;
use hi_curve::ReductionError;
use hi_surface::HarmonicSurface;

use crate::contours::{ContourImage, contour_image};
use crate::distance::{Hausdorff, distances_to_surface, hausdorff};
use crate::layout_mesh::{LayoutMesh, layout_mesh};
use crate::regularise::{Regularisation, RegularisationReport, regularise};
use crate::shrinkwrap::{ShrinkWrapImage, ShrinkWrapOptions, shrink_wrap};
use crate::sphereparam::{ParamQuality, SphereParamOptions, parameterise};
use crate::spherical::{Layout, SphericalImage, SphericalOptions, spherical_image};
use crate::{Error, GeometryImage, Smoothing};
use hi_scan::closest::{NearMesh, TriangleBvh};
use hi_scan::distance::{Distances, bounding_diagonal};
use hi_scan::repair::{Repair, close_mesh};
use hi_scan::scan::Scan;

/// How the geometry image is made; see the module documentation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Method {
    /// The spherical parameterisation for a mesh that closes to genus 0 with one dominant part,
    /// the shrink-wrap otherwise.
    #[default]
    Auto,
    /// A spherical parameterisation of the scan's mesh.
    Mesh,
    /// A surface wrapped onto the points ([`crate::shrinkwrap`]): the zero set of their signed
    /// distance parameterised over the sphere, its texels projected onto them and pulled into
    /// the creases it bridged.
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
    /// Both ways against the closed mesh the fit is written as ([`Fit::mesh`], sampled
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
    /// a size from the scan ([`auto_resolution`]). Default `None`.
    pub resolution: Option<(usize, usize)>,
    /// The centre of the rays; `None` for the mean of the points.
    pub centre: Option<DVec3>,
    /// A smoothing filter applied to the geometry image (§5.4), if any.
    pub smoothing: Option<Smoothing>,
    /// The regularisation of the surface through the image. Default
    /// [`Regularisation::Auto`]: to the scan's noise level for images made from points, none
    /// for images sampled from a mesh.
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
    /// Refuse a fit whose image has more than this fraction of filled texels (texels no scan
    /// data reached), with [`Error::MostlyHoles`]: such a surface is mostly guesswork.
    /// Default [`MAX_HOLE_FRACTION`]; 1 accepts any image with at least one measured texel
    /// (an image with none is always refused).
    pub max_hole_fraction: f64,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            method: Method::Auto,
            layout: Layout::FlatOctahedron,
            resolution: None,
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

/// The image size [`fit`] picks for a scan of `points` points: square, a multiple of 32, with
/// about eight distinct texels per point (half the texels of a doubled layout), from 64² to
/// 512². Even a good parameterisation samples some parts of a surface a few times more
/// densely than others, and the sparsest parts must still see every point of the scan.
///
/// # Examples
///
/// ```
/// use hi_geomimage::fit::auto_resolution;
///
/// assert_eq!(auto_resolution(100), (64, 64));
/// assert_eq!(auto_resolution(3_000), (224, 224));
/// assert_eq!(auto_resolution(10_000), (416, 416));
/// assert_eq!(auto_resolution(35_000), (512, 512));
/// ```
#[must_use]
pub fn auto_resolution(points: usize) -> (usize, usize) {
    // side²/2 ≈ 8·points.
    let side = (16.0 * points as f64).sqrt();
    #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "clamped")]
    let side = ((side / 32.0).ceil() as usize * 32).clamp(64, 512);
    (side, side)
}

/// The image size [`fit`] picks for a point set of `points` points: square, a multiple of 32,
/// about two distinct texels per point (half the texels of a doubled layout), from 64² to 512².
/// A point set's texels are projections onto the surface its points sample, no denser than
/// the points themselves can support.
///
/// # Examples
///
/// ```
/// use hi_geomimage::fit::auto_resolution_points;
///
/// assert_eq!(auto_resolution_points(3_000), (128, 128));
/// assert_eq!(auto_resolution_points(18_000), (288, 288));
/// ```
#[must_use]
pub fn auto_resolution_points(points: usize) -> (usize, usize) {
    auto_resolution(points / 4)
}

/// The geometry image a fit started from, with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub enum SourceImage {
    /// Algorithm 2's image.
    Radial(SphericalImage),
    /// §5.8's image of contours.
    Contours(ContourImage),
    /// The image of a spherical parameterisation of the scan's mesh.
    Mesh(MeshSource),
    /// A surface wrapped onto the points: the zero set of their signed distance, or where that
    /// is not one genus-0 surface the radial image, projected onto them.
    ShrinkWrap(ShrinkWrapImage),
}

/// What the parameterisation of a mesh did.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshSource {
    /// The image.
    pub image: GeometryImage,
    /// What was repaired to make the mesh a closed genus-0 surface.
    pub repair: Repair,
    /// The share of the scan's triangle area in the part that was parameterised.
    pub area_kept: f64,
    /// The quality of the spherical map.
    pub quality: ParamQuality,
    /// Texels that fell in closed holes (row-major).
    pub filled: Vec<bool>,
    /// The fraction of the distinct texels that fell in closed holes.
    pub filled_fraction: f64,
}

impl SourceImage {
    /// The image, before smoothing and reduction.
    #[must_use]
    pub const fn image(&self) -> &GeometryImage {
        match self {
            Self::Radial(s) => &s.image,
            Self::Contours(c) => &c.image,
            Self::Mesh(m) => &m.image,
            Self::ShrinkWrap(w) => &w.image,
        }
    }

    /// The fraction of the rays that met several shells (0 for a mesh parameterisation, which
    /// casts no rays).
    #[must_use]
    pub const fn non_star_fraction(&self) -> f64 {
        match self {
            Self::Radial(s) => s.non_star_fraction,
            Self::Contours(c) => c.non_star_fraction,
            Self::Mesh(_) => 0.0,
            Self::ShrinkWrap(w) => w.non_star_fraction,
        }
    }

    /// Whether the surface follows the outermost shell the rays from the centre met, so that
    /// [`SourceImage::non_star_fraction`] is the share of directions where it cannot reach the
    /// scan's inner shells: the ray methods, and a shrink-wrap that started from the rays. A
    /// mesh parameterisation and a shrink-wrap started from the zero set of the signed
    /// distance follow the scan's surface itself, whatever the rays met
    /// ([`FitErrors::unreached_fraction`] says what they missed).
    #[must_use]
    pub const fn follows_outer_shell(&self) -> bool {
        match self {
            Self::Radial(_) | Self::Contours(_) => true,
            Self::Mesh(_) => false,
            Self::ShrinkWrap(w) => !w.implicit_start,
        }
    }

    /// The fraction of the image with no scan data, filled: rays that found too few points,
    /// or texels on closed holes of a mesh.
    #[must_use]
    pub const fn hole_fraction(&self) -> f64 {
        match self {
            Self::Radial(s) => s.hole_fraction,
            Self::Contours(c) => c.hole_fraction,
            Self::Mesh(m) => m.filled_fraction,
            Self::ShrinkWrap(w) => w.filled_fraction,
        }
    }

    /// Which texels were filled rather than measured (row-major), if known.
    #[must_use]
    pub fn filled(&self) -> Option<&[bool]> {
        match self {
            Self::Radial(s) => Some(&s.holes),
            Self::Contours(_) => None,
            Self::Mesh(m) => Some(&m.filled),
            Self::ShrinkWrap(w) => Some(&w.filled),
        }
    }
}

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

/// A stage of a fit, as a progress display and the stage times name it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum StageKind {
    /// The geometry image (§5.3, §5.4, or the mesh's parameterisation).
    GeometryImage,
    /// Smoothing of the image.
    Smoothing,
    /// The spectral regularisation.
    Regularisation,
    /// Reduction of the image (Theorem 5.3).
    Reduction,
    /// The harmonic surface through the image or the grid.
    HarmonicSurface,
    /// The 4× rasterisation of the surface for the error.
    Rasterisation,
    /// The fit's error, measured both ways.
    FitError,
    /// Algorithm 1: the sections across the axis.
    Slicing,
    /// Algorithm 1: each section's points in contour order.
    Ordering,
    /// Algorithm 1: a harmonic curve through each contour.
    HarmonicCurves,
    /// Algorithm 1: insertion to equal counts (Theorem 5.3).
    Insertion,
    /// Algorithm 1: rotation for the least deviation (Theorem 5.1).
    Rotation,
    /// Algorithm 1: the measured problems of the sections.
    Diagnostics,
}

impl StageKind {
    /// Its name in words: "geometry image", "rasterisation (4×)", "rotation (Theorem 5.1)", ….
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            StageKind::GeometryImage => "geometry image",
            StageKind::Smoothing => "smoothing",
            StageKind::Regularisation => "regularisation",
            StageKind::Reduction => "reduction",
            StageKind::HarmonicSurface => "harmonic surface",
            StageKind::Rasterisation => "rasterisation (4×)",
            StageKind::FitError => "fit error",
            StageKind::Slicing => "slicing",
            StageKind::Ordering => "ordering",
            StageKind::HarmonicCurves => "harmonic curves",
            StageKind::Insertion => "insertion (Theorem 5.3)",
            StageKind::Rotation => "rotation (Theorem 5.1)",
            StageKind::Diagnostics => "diagnostics",
        }
    }
}

impl std::fmt::Display for StageKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The time one stage took.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Stage {
    /// Which stage.
    pub kind: StageKind,
    /// Wall-clock seconds.
    pub seconds: f64,
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

/// What [`fit`] did and how well the result fits.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FitReport {
    /// How the image was made (never [`Method::Auto`]).
    pub method: Method,
    /// Why [`Method::Auto`] chose it, or why the mesh could not be used.
    pub method_reason: String,
    /// Points of the scan (finite ones; for a mesh, those its triangles use).
    pub points: usize,
    /// Points of a mesh that no triangle uses, left out of the fit and its error.
    pub unused_points: usize,
    /// Points the geometry image was built from (for the ray methods: the scan's, and those
    /// sampled on its triangles when it was sparse).
    pub image_points: usize,
    /// Points the reader dropped for a non-finite coordinate.
    pub dropped_points: usize,
    /// The image size (rows, columns).
    pub image_size: (usize, usize),
    /// The fraction of rays from the centre that met several shells: the scan is not
    /// star-shaped about the centre there. Where [`SourceImage::follows_outer_shell`], the fit
    /// follows the outermost shell in those directions; otherwise it is only a description of
    /// the scan's shape (0 for a mesh parameterisation, which casts no rays).
    pub non_star_fraction: f64,
    /// The fraction of the image with no data, filled (holes).
    pub hole_fraction: f64,
    /// For [`Method::Contours`], the distinct located points per row.
    pub row_points: Option<RowPoints>,
    /// The scan's noise level as estimated for the regularisation ([`hi_scan::noise`]), when
    /// it was.
    pub noise: Option<f64>,
    /// The regularisation applied.
    pub regularisation: RegularisationReport,
    /// The grid of the final surface (rows, columns).
    pub surface_size: (usize, usize),
    /// The error of the reduction, if one was made.
    pub reduction: Option<ReductionError>,
    /// Distances from every scan point to the surface, if measured.
    pub errors: Option<Distances>,
    /// Both ways, if measured.
    pub both_ways: Option<FitErrors>,
    /// Both-way distances to the scan's mesh (thesis measurement with
    /// [`ErrorMeasure::Sampled`] on a mesh scan), if measured.
    pub hausdorff: Option<Hausdorff>,
}

/// A fitted surface with its geometry images, report and stage times.
#[derive(Clone, Debug)]
pub struct Fit {
    /// The harmonic surface; [`Layout::covering_window`] says which u cover the object once.
    pub surface: HarmonicSurface<DVec3>,
    /// The raw geometry image with its diagnostic maps (before smoothing and reduction).
    pub source: SourceImage,
    /// The geometry image the surface interpolates (after smoothing, regularisation and
    /// reduction).
    pub image: GeometryImage,
    /// The layout of the image.
    pub layout: Layout,
    /// The closed mesh of the surface the error was measured on (and that `hi fit` writes),
    /// when the error was measured by [`ErrorMeasure::Fast`] or [`ErrorMeasure::Exact`].
    pub mesh: Option<LayoutMesh>,
    /// Diagnostics and errors: the same for the same input and options.
    pub report: FitReport,
    /// The stages, in order, with their wall-clock times (which differ from run to run, and
    /// so are kept out of the report).
    pub stages: Vec<Stage>,
}

/// The number of mesh samples per texel along each axis for the mesh of a fitted surface
/// (and its error measured with [`ErrorMeasure::Fast`]): enough for at least 192 samples
/// around the longer axis, so that a coarse image still gives a mesh that follows its surface,
/// and 1 from 192² up, where the texels are as close as the scan's points.
#[must_use]
pub fn mesh_oversample(surface: &HarmonicSurface<DVec3>) -> usize {
    192usize.div_ceil(surface.m().max(surface.n()).max(1)).max(1)
}

/// Below this share of the scan's area in its largest part, [`Method::Auto`] does not
/// parameterise the mesh: the other parts, which would be lost, are most of the scan.
const MIN_AREA_KEPT: f64 = 0.5;

/// A scan point farther than this fraction of the diagonal from the surface is unreached.
pub const UNREACHED: f64 = 0.02;

/// Above this fraction of filled texels a fit is refused by default
/// ([`FitOptions::max_hole_fraction`]): the image is mostly guesswork.
pub const MAX_HOLE_FRACTION: f64 = 0.5;

/// The points its triangles use, the triangles renumbered, and how many were unused; a point
/// set as it is.
fn referenced(scan: &Scan) -> (Vec<DVec3>, Vec<[u32; 3]>, usize) {
    if scan.triangles.is_empty() {
        return (scan.points.clone(), Vec::new(), 0);
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
    (points, triangles, unused)
}

fn triangle_area(p: &[DVec3], triangles: &[[u32; 3]]) -> f64 {
    triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|k| p[k as usize]);
            0.5 * (b - a).cross(c - a).length()
        })
        .sum()
}

/// Fits a harmonic surface to a scan; see the module documentation. `on_stage` is told each
/// stage as it starts (for a progress display).
///
/// # Errors
///
/// [`Error::InvalidOption`] for `reduce` outside (0, 1] or `max_hole_fraction` outside
/// [0, 1]; [`Error::TooFewPoints`] for a scan
/// with fewer than 4 points; [`Error::Topology`] when [`Method::Mesh`] is asked for and the
/// mesh cannot be parameterised; [`Error::MostlyHoles`] when more than
/// [`FitOptions::max_hole_fraction`] of the image (or all of it) had no data; the errors of the image builders,
/// [`GeometryImage::smoothed`], [`regularise`] and [`GeometryImage::resampled`].
pub fn fit(
    scan: &Scan,
    options: &FitOptions,
    on_stage: &mut dyn FnMut(StageKind),
) -> Result<Fit, Error> {
    let mut stages = Vec::new();
    let timed = |kind: StageKind, stages: &mut Vec<Stage>, start: Instant| {
        stages.push(Stage { kind, seconds: start.elapsed().as_secs_f64() });
    };
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
    let (points, triangles, unused_points) = referenced(scan);
    if points.len() < 4 {
        return Err(Error::TooFewPoints { found: points.len(), needed: 4 });
    }
    let (rows, cols) = options.resolution.unwrap_or_else(|| {
        if triangles.is_empty() {
            auto_resolution_points(points.len())
        } else {
            auto_resolution(points.len())
        }
    });
    crate::image::check_resolution(rows, cols)?;
    on_stage(StageKind::GeometryImage);
    let start = Instant::now();
    // The mesh path, when asked for or when it applies.
    let mut method = options.method;
    let mut reason = String::new();
    let mut source = None;
    if matches!(method, Method::Auto | Method::Mesh) {
        match mesh_image(&points, &triangles, options.layout, (rows, cols), method == Method::Mesh)
        {
            Ok(MeshOutcome::Image(m)) => {
                let (holes, handles) = (m.repair.holes, m.repair.handles_cut);
                let plural = |n: usize, one: &str, many: &str| {
                    if n == 1 { format!("its 1 {one}") } else { format!("its {n} {many}") }
                };
                reason = match (holes, handles) {
                    (0, 0) => "the scan's mesh is a closed surface of genus 0".to_owned(),
                    (_, 0) => format!(
                        "the scan's mesh closes to genus 0 once {} filled",
                        plural(holes, "hole is", "holes are")
                    ),
                    (0, _) => format!(
                        "the scan's mesh is closed, and of genus 0 once {} cut",
                        plural(handles, "handle is", "handles are")
                    ),
                    _ => format!(
                        "the scan's mesh closes to genus 0 once {} filled and {} cut",
                        plural(holes, "hole is", "holes are"),
                        plural(handles, "handle is", "handles are")
                    ),
                };
                if m.area_kept < 1.0 - 1e-9 {
                    reason.push_str(&format!(
                        "; its largest part holds {:.1} % of its area, the rest is left out",
                        100.0 * m.area_kept
                    ));
                }
                method = Method::Mesh;
                source = Some(SourceImage::Mesh(m));
            }
            Ok(MeshOutcome::SmallPart { components, area_kept }) => {
                reason = format!(
                    "the scan's mesh has {components} parts and the largest holds only {:.1} % of its area",
                    100.0 * area_kept
                );
            }
            Err(e) if method == Method::Mesh => return Err(e),
            Err(Error::TooFewPoints { .. }) => reason = "the scan has no triangles".to_owned(),
            Err(e) => reason = format!("the scan's mesh cannot be parameterised ({e})"),
        }
        if source.is_none() {
            method = Method::ShrinkWrap;
            reason.push_str("; the points shrink-wrapped instead");
        }
    }
    let mut image_points = points.len();
    let source = match source {
        Some(s) => s,
        None => {
            // Shrink-wrapping works on the scan's own points; the rays want many.
            let dense = if triangles.is_empty() || method == Method::ShrinkWrap {
                points.clone()
            } else {
                hi_scan::sampling::densify(
                    &Scan {
                        points: points.clone(),
                        triangles: triangles.clone(),
                        ..Scan::default()
                    },
                    options.densify,
                )
            };
            image_points = dense.len();
            let rays = SphericalOptions {
                layout: options.layout,
                rows,
                cols,
                centre: options.centre,
                ..SphericalOptions::default()
            };
            if reason.is_empty() {
                reason = format!("{} asked for", method.name());
            }
            match method {
                Method::Contours => SourceImage::Contours(contour_image(&dense, &rays)?),
                Method::ShrinkWrap => {
                    let wrap = ShrinkWrapOptions {
                        layout: options.layout,
                        rows,
                        cols,
                        centre: options.centre,
                        ..ShrinkWrapOptions::default()
                    };
                    let normals = if triangles.is_empty() { scan.normals.as_deref() } else { None };
                    SourceImage::ShrinkWrap(shrink_wrap(&points, normals, &wrap)?)
                }
                _ => SourceImage::Radial(spherical_image(&dense, &rays)?),
            }
        }
    };
    timed(StageKind::GeometryImage, &mut stages, start);
    if let SourceImage::ShrinkWrap(w) = &source {
        reason.push_str(if w.implicit_start {
            " (from the zero set of their signed distance, parameterised over the sphere)"
        } else {
            " (from the rays: the zero set of their signed distance is not one surface of genus 0)"
        });
    }
    if source.hole_fraction() > options.max_hole_fraction || source.hole_fraction() >= 1.0 {
        return Err(Error::MostlyHoles { fraction: source.hole_fraction() });
    }
    let mut image = source.image().clone();
    if let Some(filter) = options.smoothing {
        on_stage(StageKind::Smoothing);
        let start = Instant::now();
        image = image.smoothed(filter)?;
        timed(StageKind::Smoothing, &mut stages, start);
    }
    // Images sampled from a mesh lie on the scan's surface: nothing to smooth away. Images made
    // from points carry the points' scatter: smooth it away, and no more.
    let mut noise = None;
    let how = match (options.regularisation, method) {
        (Regularisation::Auto, Method::Mesh) => Regularisation::Off,
        (Regularisation::Auto, _) => {
            let sigma = hi_scan::noise::noise_estimate(&points);
            noise = Some(sigma);
            Regularisation::Noise(sigma)
        }
        (r, _) => r,
    };
    let regularisation = if how == Regularisation::Off {
        RegularisationReport { lambda: 0.0, kept: 1.0, rms_change: 0.0, max_change: 0.0 }
    } else {
        on_stage(StageKind::Regularisation);
        let start = Instant::now();
        let (smooth, report) = regularise(&image, how)?;
        image = smooth;
        timed(StageKind::Regularisation, &mut stages, start);
        report
    };
    let mut reduction = None;
    if let Some(fraction) = options.reduce.filter(|&f| f < 1.0) {
        on_stage(StageKind::Reduction);
        let start = Instant::now();
        let scale = fraction.sqrt();
        // Keep the rows even, so that both poles stay texels of a spherical image.
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "0 < scale < 1 times a size ≤ 2²⁶"
        )]
        let (rows, cols) = (
            (((image.rows() as f64 * scale) / 2.0).round() as usize * 2).max(2),
            ((image.cols() as f64 * scale).round() as usize).max(2),
        );
        let (reduced, error) = image.resampled(rows, cols)?;
        image = reduced;
        reduction = Some(error);
        timed(StageKind::Reduction, &mut stages, start);
    }
    on_stage(StageKind::HarmonicSurface);
    let start = Instant::now();
    let surface = image.surface()?;
    timed(StageKind::HarmonicSurface, &mut stages, start);
    if options.rasterise {
        on_stage(StageKind::Rasterisation);
        let start = Instant::now();
        let raster = surface.sample_uniform(2 * surface.m(), 2 * surface.n(), 0, 0)?;
        std::hint::black_box(&raster);
        timed(StageKind::Rasterisation, &mut stages, start);
    }
    let (mut errors, mut both_ways, mut both_mesh, mut fit_mesh) = (None, None, None, None);
    match options.error {
        ErrorMeasure::Off => {}
        ErrorMeasure::Sampled(oversample) if method != Method::Mesh => {
            // The thesis's measurement, as the figures of §5.3 report it.
            on_stage(StageKind::FitError);
            let start = Instant::now();
            if triangles.is_empty() {
                errors = Some(distances_to_surface(&surface, &points, oversample)?);
            } else {
                let h = hausdorff(&surface, &points, &triangles, oversample)?;
                errors = Some(h.scan_to_surface.clone());
                both_mesh = Some(h);
            }
            timed(StageKind::FitError, &mut stages, start);
        }
        measure => {
            on_stage(StageKind::FitError);
            let start = Instant::now();
            let filled = source.filled().map(|f| {
                // The texels of the surface's grid, in the source image's (they differ after a
                // reduction).
                let (rows, cols) = (source.image().rows(), source.image().cols());
                let (sm, sn) = (surface.m(), surface.n());
                (0..sm * sn)
                    .map(|t| f[(t / sn * rows / sm) * cols + (t % sn) * cols / sn])
                    .collect::<Vec<bool>>()
            });
            // An image of the mesh's parameterisation left as it was sampled has its texels on
            // the scan's triangles.
            let texels_on_scan = method == Method::Mesh
                && regularisation.lambda == 0.0
                && options.smoothing.is_none()
                && reduction.is_none();
            let (e, m) = measure_fit_with(
                &surface,
                options.layout,
                filled.as_deref(),
                &points,
                &triangles,
                measure,
                texels_on_scan,
            )?;
            errors = Some(e.scan_to_surface.clone());
            both_ways = Some(e);
            fit_mesh = Some(m);
            timed(StageKind::FitError, &mut stages, start);
        }
    }
    let report = FitReport {
        method,
        method_reason: reason,
        points: points.len(),
        unused_points,
        image_points,
        dropped_points: scan.dropped_points,
        image_size: (rows, cols),
        non_star_fraction: source.non_star_fraction(),
        hole_fraction: source.hole_fraction(),
        row_points: match &source {
            SourceImage::Contours(c) => Some(RowPoints {
                min: c.row_points.iter().copied().min().unwrap_or(0),
                mean: c.row_points.iter().sum::<usize>() as f64 / c.row_points.len().max(1) as f64,
                max: c.row_points.iter().copied().max().unwrap_or(0),
                empty_rows: c.empty_rows.len(),
            }),
            _ => None,
        },
        noise,
        regularisation,
        surface_size: (surface.m(), surface.n()),
        reduction,
        errors,
        both_ways,
        hausdorff: both_mesh,
    };
    Ok(Fit { surface, source, image, layout: options.layout, mesh: fit_mesh, report, stages })
}

/// What came of trying to parameterise the scan's mesh.
enum MeshOutcome {
    /// The image.
    Image(MeshSource),
    /// The largest part holds too little of the area to stand for the scan (not tried).
    SmallPart {
        /// Parts found.
        components: usize,
        /// The share of the area in the largest.
        area_kept: f64,
    },
}

/// The geometry image of a spherical parameterisation of the mesh (`points`, `triangles`);
/// unless `force`, only if its largest part holds [`MIN_AREA_KEPT`] of the area.
fn mesh_image(
    points: &[DVec3],
    triangles: &[[u32; 3]],
    layout: Layout,
    (rows, cols): (usize, usize),
    force: bool,
) -> Result<MeshOutcome, Error> {
    if triangles.is_empty() {
        return Err(Error::TooFewPoints { found: 0, needed: 1 });
    }
    let closed = close_mesh(points, triangles)?;
    let total = triangle_area(points, triangles);
    let scanned: Vec<[u32; 3]> = closed
        .triangles
        .iter()
        .zip(&closed.filled)
        .filter(|(_, f)| !**f)
        .map(|(t, _)| *t)
        .collect();
    let kept = triangle_area(&closed.positions, &scanned);
    let area_kept = if total > 0.0 { (kept / total).min(1.0) } else { 0.0 };
    if !force && area_kept < MIN_AREA_KEPT {
        return Ok(MeshOutcome::SmallPart { components: closed.repair.components, area_kept });
    }
    let param = parameterise(&closed, &SphereParamOptions::default())?;
    let image = param.image(layout, rows, cols)?;
    Ok(MeshOutcome::Image(MeshSource {
        image: image.image,
        repair: closed.repair,
        area_kept,
        quality: param.quality(),
        filled: image.filled,
        filled_fraction: image.filled_fraction,
    }))
}

/// The both-way distances between a fitted surface (an image's harmonic surface in `layout`)
/// and a scan (`points`, with `triangles` if it is a mesh), as [`fit`] measures them with
/// `measure` ([`ErrorMeasure::Fast`] or [`ErrorMeasure::Exact`]; [`ErrorMeasure::Sampled`]
/// uses that many samples per texel for the mesh), and the closed mesh they were measured on.
/// `filled` flags the texels of the surface's grid that bridge holes in the scan: the mesh's
/// samples there are summarised apart.
///
/// # Errors
///
/// [`Error::InvalidOption`] for [`ErrorMeasure::Off`] or a `filled` mask of the wrong size;
/// the errors of [`layout_mesh`], [`TriangleBvh::try_new`] and [`NearMesh::try_new`].
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::fit::{ErrorMeasure, measure_fit};
/// use hi_geomimage::Layout;
///
/// // The exact unit sphere, and points 0.1 outside it.
/// let sphere = hi_surface::sphere(1.0);
/// let points: Vec<DVec3> = [DVec3::X, DVec3::Y, DVec3::new(0.6, 0.0, 0.8)]
///     .map(|d| d * 1.1)
///     .to_vec();
/// let (e, _) = measure_fit(&sphere, Layout::Sphere, None, &points, &[], ErrorMeasure::Exact)
///     .unwrap();
/// assert!(e.scan_to_surface.per_point.iter().all(|d| (d - 0.1).abs() < 1e-6));
/// ```
pub fn measure_fit(
    surface: &HarmonicSurface<DVec3>,
    layout: Layout,
    filled: Option<&[bool]>,
    points: &[DVec3],
    triangles: &[[u32; 3]],
    measure: ErrorMeasure,
) -> Result<(FitErrors, LayoutMesh), Error> {
    measure_fit_with(surface, layout, filled, points, triangles, measure, false)
}

/// [`measure_fit`], told whether the surface's texels are points of the scan's triangles.
fn measure_fit_with(
    surface: &HarmonicSurface<DVec3>,
    layout: Layout,
    filled: Option<&[bool]>,
    points: &[DVec3],
    triangles: &[[u32; 3]],
    measure: ErrorMeasure,
    texels_on_scan: bool,
) -> Result<(FitErrors, LayoutMesh), Error> {
    let per_texel = match measure {
        ErrorMeasure::Off => {
            return Err(Error::InvalidOption {
                name: "error measure",
                value: 0.0,
                expected: "a measure other than Off",
            });
        }
        ErrorMeasure::Sampled(k) => k.max(1),
        _ => mesh_oversample(surface),
    };
    if let Some(f) = filled
        && f.len() != surface.m() * surface.n()
    {
        return Err(Error::InvalidOption {
            name: "filled texels",
            value: f.len() as f64,
            expected: "one flag per texel of the surface's grid",
        });
    }
    // The plain octahedron's mesh needs an even refinement.
    let per_texel =
        if layout == Layout::Octahedron { per_texel.next_multiple_of(2) } else { per_texel };
    let m = layout_mesh(surface, layout, per_texel)?;
    let e = fit_errors(
        surface,
        &m,
        per_texel,
        filled,
        points,
        triangles,
        measure == ErrorMeasure::Exact,
        texels_on_scan,
    )?;
    Ok((e, m))
}

/// Both-way distances between the surface's closed mesh `m` and the scan (`points`, and its
/// `triangles` if any); samples on `filled` texels (of the surface's grid) are summarised
/// apart. With `exact`, each scan point's distance is refined onto the surface itself. With
/// `texels_on_scan`, the surface's texels are points of the scan's triangles (an unsmoothed
/// image of a mesh's parameterisation).
#[expect(clippy::too_many_arguments, reason = "one private call site each")]
fn fit_errors(
    surface: &HarmonicSurface<DVec3>,
    m: &LayoutMesh,
    per_texel: usize,
    filled: Option<&[bool]>,
    points: &[DVec3],
    triangles: &[[u32; 3]],
    exact: bool,
    texels_on_scan: bool,
) -> Result<FitErrors, Error> {
    let mesh = &m.mesh;
    let diagonal = bounding_diagonal(points);
    // Scan → surface.
    let forward = || -> Result<Vec<f64>, Error> {
        Ok(if exact {
            use crate::par::*;
            let bvh = TriangleBvh::try_new(mesh.positions(), mesh.triangles())?;
            let grid = HermiteGrid::of(surface, per_texel)?;
            points
                .par_iter()
                .map(|x| {
                    let c = bvh.closest(*x);
                    project(&grid, mesh, *x, c.triangle, c.point)
                })
                .collect()
        } else {
            NearMesh::try_new(mesh.positions(), mesh.triangles())?.distances(points)
        })
    };
    // Surface → scan: every vertex of the mesh, and the centroid of every other triangle (one
    // per grid quad, away from the texels: for the mesh of a parameterisation, the vertices at
    // the texels lie on the scan).
    let tri = mesh.triangles();
    let centroids: Vec<DVec3> = tri
        .iter()
        .step_by(2)
        .map(|t| t.iter().map(|&k| mesh.positions()[k as usize]).sum::<DVec3>() / 3.0)
        .collect();
    let samples: Vec<DVec3> = mesh.positions().iter().copied().chain(centroids).collect();
    let n_vertices = mesh.positions().len();
    // Vertices at texels that were sampled on the scan's own triangles are points of the scan:
    // their distance is 0 (to rounding) and is not queried.
    let on_scan = |v: usize| {
        texels_on_scan
            && per_texel == 1
            && v < n_vertices
            && !filled.is_some_and(|f| f.get(m.texel[v] as usize).copied().unwrap_or(false))
    };
    let queried: Vec<DVec3> =
        samples.iter().enumerate().filter(|(v, _)| !on_scan(*v)).map(|(_, x)| *x).collect();
    let backward = || -> Result<Vec<f64>, Error> {
        if triangles.is_empty() {
            Ok(hi_scan::distance::nearest_point_distances(&queried, points)?)
        } else {
            // The scan's triangles can be long and thin (scanners leave slivers at folds and
            // holes), which the nearest-vertex query misjudges: this side is always exact.
            Ok(TriangleBvh::try_new(points, triangles)?.distances(&queried))
        }
    };
    // Both ways at once (each builds its search structure on one thread).
    let (per_point, measured) = crate::par::join(forward, backward);
    let scan_to_surface = Distances::from_values(per_point?, diagonal);
    let mut measured = measured?.into_iter();
    let back: Vec<f64> = (0..samples.len())
        .map(|v| if on_scan(v) { 0.0 } else { measured.next().unwrap_or(0.0) })
        .collect();
    // A centroid is on a fill if any of its corners is.
    let on_fill = |s: usize| {
        filled.is_some_and(|f| {
            let is_filled = |v: usize| f.get(m.texel[v] as usize).copied().unwrap_or(false);
            if s < n_vertices {
                is_filled(s)
            } else {
                tri[2 * (s - n_vertices)].iter().any(|&k| is_filled(k as usize))
            }
        })
    };
    let (mut kept, mut filled_max) = (Vec::with_capacity(back.len()), 0.0f64);
    for (v, d) in back.into_iter().enumerate() {
        if on_fill(v) {
            filled_max = filled_max.max(d);
        } else {
            kept.push(d);
        }
    }
    let surface_to_scan = Distances::from_values(kept, diagonal);
    let unreached = scan_to_surface.per_point.iter().filter(|&&d| d > UNREACHED * diagonal).count()
        as f64
        / points.len().max(1) as f64;
    Ok(FitErrors {
        scan_to_surface,
        surface_to_scan,
        filled_to_scan_max: filled_max,
        unreached_fraction: unreached,
    })
}

/// The harmonic surface near its grid, for Gauss–Newton projections: p and its derivatives
/// ∂u, ∂v and ∂u∂v sampled on the grid of the fit's mesh (by FFT), and between grid points the bicubic Hermite
/// interpolant of those, which differs from the surface by O(h⁴) (h the grid's spacing): far
/// below any distance this measures (the mesh's own departure from the surface is O(h²)).
struct HermiteGrid {
    m: usize,
    n: usize,
    p: Vec<DVec3>,
    pu: Vec<DVec3>,
    pv: Vec<DVec3>,
    puv: Vec<DVec3>,
}

impl HermiteGrid {
    /// The grid `per_texel` times finer than the surface's along each axis.
    fn of(surface: &HarmonicSurface<DVec3>, per_texel: usize) -> Result<Self, Error> {
        let (m, n) = (surface.m() * per_texel, surface.n() * per_texel);
        let s = |a, b| surface.sample_uniform(m, n, a, b).map(|g| g.values);
        Ok(Self { m, n, p: s(0, 0)?, pu: s(1, 0)?, pv: s(0, 1)?, puv: s(1, 1)? })
    }

    /// p and its derivatives in u and in v at (u, v).
    fn eval(&self, u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
        let (x, y) = (u.rem_euclid(1.0) * self.m as f64, v.rem_euclid(1.0) * self.n as f64);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "in 0..m, 0..n"
        )]
        let (i, j) = ((x.floor() as usize).min(self.m - 1), (y.floor() as usize).min(self.n - 1));
        let (s, t) = (x - i as f64, y - j as f64);
        let (hu, hv) = (1.0 / self.m as f64, 1.0 / self.n as f64);
        // Cubic Hermite basis [h00, h10, h01, h11] and its derivative.
        let basis = |s: f64| {
            let (s2, s3) = (s * s, s * s * s);
            (
                [2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s, -2.0 * s3 + 3.0 * s2, s3 - s2],
                [
                    6.0 * s2 - 6.0 * s,
                    3.0 * s2 - 4.0 * s + 1.0,
                    -6.0 * s2 + 6.0 * s,
                    3.0 * s2 - 2.0 * s,
                ],
            )
        };
        let ((bs, ds), (bt, dt)) = (basis(s), basis(t));
        let (mut p, mut ps, mut pt) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
        for (a, ia) in [(0usize, i), (1, (i + 1) % self.m)] {
            for (b, jb) in [(0usize, j), (1, (j + 1) % self.n)] {
                let k = ia * self.n + jb;
                // Value, u-slope, v-slope and twist at this corner, in cell units.
                let terms = [
                    (2 * a, 2 * b, self.p[k]),
                    (2 * a + 1, 2 * b, self.pu[k] * hu),
                    (2 * a, 2 * b + 1, self.pv[k] * hv),
                    (2 * a + 1, 2 * b + 1, self.puv[k] * (hu * hv)),
                ];
                for (ka, kb, c) in terms {
                    // Basis order [h00, h10, h01, h11]: corner 0 uses h00/h10, corner 1 h01/h11.
                    let (fa, fb) = ([0, 1, 2, 3][ka], [0, 1, 2, 3][kb]);
                    p += c * (bs[fa] * bt[fb]);
                    ps += c * (ds[fa] * bt[fb]);
                    pt += c * (bs[fa] * dt[fb]);
                }
            }
        }
        (p, ps / hu, pt / hv)
    }
}

/// The distance from x to the surface near the point `q` of mesh triangle `t`: from the (u, v)
/// of q (barycentric in the triangle's UVs, unwrapped across the period), Gauss–Newton steps
/// on |p(u, v) − x|², the least distance seen (every iterate is a point of the surface).
fn project(grid: &HermiteGrid, mesh: &hi_mesh::TriangleMesh, x: DVec3, t: u32, q: DVec3) -> f64 {
    let tri = mesh.triangles()[t as usize];
    let [a, b, c] = tri.map(|k| mesh.positions()[k as usize]);
    let [ua, ub, uc] = tri.map(|k| mesh.uvs()[k as usize]);
    let unwrap = |w: glam::DVec2| w - (w - ua).round();
    let (ub, uc) = (unwrap(ub), unwrap(uc));
    // Barycentric coordinates of q in abc.
    let (e1, e2, f) = (b - a, c - a, q - a);
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let det = d11 * d22 - d12 * d12;
    let (mut uv, mut best) = (ua, f64::INFINITY);
    if det > 0.0 {
        let (r1, r2) = (f.dot(e1), f.dot(e2));
        let s = (d22 * r1 - d12 * r2) / det;
        let r = (d11 * r2 - d12 * r1) / det;
        uv = ua + (ub - ua) * s + (uc - ua) * r;
    }
    for _ in 0..8 {
        let (p, pu, pv) = grid.eval(uv.x, uv.y);
        let d = p - x;
        best = best.min(d.length());
        let (g11, g12, g22) = (pu.dot(pu), pu.dot(pv), pv.dot(pv));
        let det = g11 * g22 - g12 * g12;
        if det.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            break;
        }
        let (r1, r2) = (d.dot(pu), d.dot(pv));
        let step = glam::DVec2::new((g22 * r1 - g12 * r2) / det, (g11 * r2 - g12 * r1) / det);
        uv -= step;
        if step.length() < 1e-12 {
            break;
        }
    }
    best.min(grid.eval(uv.x, uv.y).0.distance(x))
}
