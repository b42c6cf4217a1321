// SPDX-License-Identifier: MIT
//! Algorithm 1 of §5.3 (Hardy 2005, pp. 143–146): a harmonic surface fitted to unorganised
//! points through cross-sections, with the measurements that show when it fails (figures
//! 5.7–5.9).
//!
//! The steps, as the thesis lists them, and what this module does for each:
//!
//! 1. *"The user decides which cross-sections are most appropriate by orienting the data"*:
//!    [`SectionOptions::axis`] is x, y, z or the principal axis of the points.
//! 2. *"The maximum bounds in the cross-section direction"*: the lowest and highest point
//!    along the axis.
//! 3. *"The volume is recursively subdivided in the cross-section direction until a
//!    termination criteria is met … the vertical distance between any two points in the cross
//!    section is less than the horizontal distance"*: with [`SectionOptions::slices`] `None`,
//!    a slab is halved while its points spread further along the axis than the median
//!    distance between neighbours along its contour; with `Some(K)`, K slabs of equal
//!    thickness. A section with fewer than 3 points is an error naming it
//!    ([`Error::SparseSlice`]); the thesis's remedy, merging sections, has no criterion there
//!    ("not easily determined"), so the caller chooses fewer slices. The thesis's variant that
//!    slices a projection onto a surrounding cylinder is not implemented.
//! 4. *"Ordering may be achieved using polar coordinates … One possibility is to use a nearest
//!    neighbour algorithm"*: [`ContourOrder`]. Points are moved along the axis onto the plane
//!    of their section, at their mean height (the thesis describes a section by "the mean
//!    vertical value"), unless [`SectionOptions::flatten`] is off. Multiple curves in a
//!    section are not handled, as in the thesis ("we will not consider multiple curves").
//! 5. *"A harmonic curve … from each cross-section"*: [`hi_curve::HarmonicCurve`] through the
//!    ordered points.
//! 6. *Insertion by Theorem 5.3* so that every contour has N points: N is the smallest even
//!    number above the largest section, so every contour gains at least one point. Even, so
//!    that the other side of a contour (step 8) is a grid point; above every section, so that
//!    the rotation of step 7 is exact (below).
//! 7. *Rotation by Theorem 5.1 "for the minimum total deviation"*: each contour is turned by
//!    an offset o, yⱼ = X(j/N + o), chosen to minimise the sum of squared distances between
//!    its points and those of the (already turned) contour below it — over the N whole steps,
//!    then refined continuously by golden-section search ([`Alignment`]). Because every
//!    inserted curve has degree below N/2, its alternating sum is 0 and Theorem 5.1 is exact
//!    even for even N (docs/math.md §2): the turned contour is the same curve, and the original
//!    points are still interpolated. For the same reason the total deviation between two
//!    contours depends only on the difference of their offsets, so turning each contour
//!    against the one below reaches the minimum of the total.
//! 8. *"To make the data periodic, we traverse the cross sections in reverse order on the
//!    other side of the object"*: the grid has 2K rows; row i < K is contour i and row
//!    2K − 1 − i is contour i turned by half a period (the point opposite). Every column is
//!    then a closed curve up one side and down the other, like a meridian circle, and the
//!    harmonic tensor-product surface ([`hi_surface::HarmonicSurface`]) through the grid covers
//!    the object twice, once for u in [`SectionFit::covering_window`].
//! 9. (Conversion to patches, §5.7, is elsewhere.)
//!
//! # How it fails, and how that is reported
//!
//! The thesis finds "the expense in quality … severe" on some inputs (figures 5.8, 5.9). Input
//! the algorithm cannot take at all is an [`Error`]; input it takes but fits badly gives a
//! surface together with measured [`Problem`]s in [`SectionReport::problems`]:
//! - [`Problem::ScrambledContour`]: the order of a section's points does not follow a curve —
//!   more than [`MISORDER_LIMIT`] of them have their nearest neighbour elsewhere in the order,
//!   or the polygon crosses itself. A section not star-shaped about its centroid scrambles the
//!   angular order (the polygon stays simple, but zigzags across the section); so does a
//!   section with several curves, or a slab so thick that its points form a band;
//! - [`Problem::LoopingContour`]: the polygon is simple but the harmonic curve through it
//!   crosses itself — unevenly spaced points ("the curves interpolate at different speeds");
//! - [`Problem::Overshoot`]: the contour strays from the chords between its points by more
//!   than [`OVERSHOOT_LIMIT`] of its radius ("very few points … the curve produced
//!   approximates the surface badly");
//! - [`Problem::StraysFromPoints`]: some of the surface lies further from every input point
//!   than [`STRAY_LIMIT`] times the sampling scale.

mod align;
mod diagnose;
mod slice;

use std::time::Instant;

use glam::{DVec2, DVec3};
use hi_curve::HarmonicCurve;
use hi_par::*;
use hi_surface::{HarmonicSurface, ParamRange};
use kiddo::{ImmutableKdTree, SquaredEuclidean};

use crate::distance::distances_to_surface;
use crate::fit::{Stage, StageKind};
use crate::{Error, MAX_TEXELS, NonFiniteInput};
use align::{rotate_rows, squared_deviation};
use hi_scan::distance::Distances;
use slice::{Frame, MIN_SLICE_POINTS, Slab, axis_of, equal_slabs, order_contour, recursive_slabs};

/// A section more than this fraction of whose points have their nearest neighbour elsewhere
/// in the order than next to them is reported as [`Problem::ScrambledContour`].
pub const MISORDER_LIMIT: f64 = 0.1;

/// A contour whose harmonic curve strays from its chords by more than this fraction of its
/// radius is reported as [`Problem::Overshoot`].
pub const OVERSHOOT_LIMIT: f64 = 0.25;

/// A surface point further than this many times [`SectionReport::sampling_scale`] from every
/// input point is reported as [`Problem::StraysFromPoints`].
pub const STRAY_LIMIT: f64 = 1.5;

/// The most sections [`fit_sections`] accepts.
pub const MAX_SLICES: usize = 1 << 16;

/// The direction the sections are cut across (step 1 of algorithm 1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SliceAxis {
    /// Sections perpendicular to x.
    X,
    /// Sections perpendicular to y.
    Y,
    /// Sections perpendicular to z.
    #[default]
    Z,
    /// Sections perpendicular to the direction in which the points vary most (the leading
    /// eigenvector of their covariance).
    Principal,
}

/// How the points of a section are put in order along its contour (step 4 of algorithm 1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum ContourOrder {
    /// By polar angle about the section's centroid: right exactly when the section is
    /// star-shaped about its centroid.
    #[default]
    Angular,
    /// From the point of least polar angle, always on to the nearest point not yet visited,
    /// counter-clockwise. Follows concave sections that the angle scrambles, as long as
    /// the points are denser along the contour than across its gaps.
    NearestNeighbour,
}

/// How the contours are turned against each other (step 7 of algorithm 1, Theorem 5.1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Alignment {
    /// Not at all: every contour starts at its first ordered point.
    None,
    /// By the whole number of steps (of 1/N) with the least deviation.
    Steps,
    /// By the best whole number of steps, then refined continuously (golden-section search
    /// within a step either side).
    #[default]
    Continuous,
}

/// The settings of [`fit_sections`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SectionOptions {
    /// The direction across the sections. Default z.
    pub axis: SliceAxis,
    /// `Some(K)`: K sections of equal thickness (2 ≤ K ≤ [`MAX_SLICES`]); `None` (the
    /// default): the thesis's recursive subdivision (step 3).
    pub slices: Option<usize>,
    /// The order of the points along each contour. Default [`ContourOrder::Angular`].
    pub order: ContourOrder,
    /// How the contours are turned against each other. Default [`Alignment::Continuous`].
    pub alignment: Alignment,
    /// Move each section's points along the axis onto the plane at their mean height.
    /// Default true.
    pub flatten: bool,
    /// Measure the fit on the surface sampled this many times finer than its grid (distances
    /// both ways between the points and the surface); 0 skips the measurement. Default 4.
    pub error_oversample: usize,
}

impl Default for SectionOptions {
    fn default() -> Self {
        Self {
            axis: SliceAxis::Z,
            slices: None,
            order: ContourOrder::Angular,
            alignment: Alignment::Continuous,
            flatten: true,
            error_oversample: 4,
        }
    }
}

/// What happened to one section.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SliceReport {
    /// The slab of heights along the axis the section was cut from.
    pub range: (f64, f64),
    /// The mean height of its points: the plane of the section.
    pub height: f64,
    /// Its points.
    pub points: usize,
    /// The mean distance of its points from their centroid, in the plane.
    pub radius: f64,
    /// Proper self-crossings of the polygon of its ordered points (0 when ordered right; the
    /// angular order always gives a simple polygon, right or wrong).
    pub polygon_crossings: usize,
    /// The fraction of its points whose nearest other point (in the plane) is strictly nearer
    /// than both their neighbours in the order: near 0 when the order follows the contour.
    pub misordered: f64,
    /// Self-crossings of its harmonic curve, sampled 8 times per span.
    pub curve_crossings: usize,
    /// The largest distance of the harmonic curve from the chord between the two points it
    /// passes between, divided by [`SliceReport::radius`] (0 for a contour that is a point,
    /// within 10⁻⁹ of the points' bounding diagonal).
    pub overshoot: f64,
    /// The rotation offset o of Theorem 5.1 applied to the contour, in periods, in [0, 1).
    pub rotation: f64,
    /// Root-mean-square distance between its N points and those of the contour below, after
    /// alignment (0 for the lowest section).
    pub deviation: f64,
    /// The same without alignment (each contour starting at its first ordered point).
    pub deviation_unaligned: f64,
}

/// A measured sign that the fit failed (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Problem {
    /// The order of a section's points does not follow a curve.
    ScrambledContour {
        /// The section, from the lowest (0).
        slice: usize,
        /// [`SliceReport::misordered`].
        misordered: f64,
        /// [`SliceReport::polygon_crossings`].
        crossings: usize,
    },
    /// The polygon of a section is simple, but the harmonic curve through it crosses itself.
    LoopingContour {
        /// The section.
        slice: usize,
        /// The curve's self-crossings.
        crossings: usize,
    },
    /// A contour strays from its chords by more than [`OVERSHOOT_LIMIT`] of its radius.
    Overshoot {
        /// The section.
        slice: usize,
        /// [`SliceReport::overshoot`].
        ratio: f64,
    },
    /// The surface strays from the points by more than [`STRAY_LIMIT`] times the sampling
    /// scale.
    StraysFromPoints {
        /// The largest distance from a surface sample to the nearest input point.
        distance: f64,
        /// [`SectionReport::sampling_scale`].
        scale: f64,
    },
}

impl std::fmt::Display for Problem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::ScrambledContour { slice, misordered, crossings } => write!(
                f,
                "section {slice}: the order of its points jumps across it ({:.0}% have their nearest neighbour elsewhere, {crossings} self-crossings): not star-shaped about its centroid, several curves, or too thick a slab",
                100.0 * misordered
            ),
            Self::LoopingContour { slice, crossings } => write!(
                f,
                "section {slice}: the harmonic curve through its points crosses itself {crossings} times (unevenly spaced points)"
            ),
            Self::Overshoot { slice, ratio } => write!(
                f,
                "section {slice}: the harmonic curve strays {:.0}% of its radius from its points",
                100.0 * ratio
            ),
            Self::StraysFromPoints { distance, scale } => write!(
                f,
                "the surface strays {distance:.3e} from the nearest point, {:.1} times the sampling scale {scale:.3e}",
                distance / scale
            ),
        }
    }
}

/// What [`fit_sections`] did, and how well.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SectionReport {
    /// The input points.
    pub points: usize,
    /// The unit axis across the sections.
    pub axis: DVec3,
    /// Each section, from the lowest.
    pub slices: Vec<SliceReport>,
    /// N: the points of every contour after insertion.
    pub contour_points: usize,
    /// The grid of the surface: (2K, N).
    pub surface_size: (usize, usize),
    /// Σ over neighbouring contours of the squared distances between their points, without
    /// alignment.
    pub deviation_unaligned: f64,
    /// The same after alignment (step 7 minimises it).
    pub deviation: f64,
    /// The distance at which the surface is expected to be from its nearest input point: the
    /// largest of the gaps between neighbouring section heights, the median distances between
    /// neighbouring contour points, and the radii of the lowest and highest sections (the
    /// caps the surface bridges without points).
    pub sampling_scale: f64,
    /// From each sample of the surface (the grid `error_oversample` times finer) to the nearest
    /// input point, if measured.
    pub surface_to_points: Option<Distances>,
    /// From each input point to the surface, if measured.
    pub points_to_surface: Option<Distances>,
    /// The measured signs of failure; empty for a fit without them.
    pub problems: Vec<Problem>,
}

/// A surface fitted by algorithm 1, with its contours, report and stage times.
#[derive(Clone, Debug)]
pub struct SectionFit {
    /// The harmonic surface through the 2K × N grid (step 8).
    pub surface: HarmonicSurface<DVec3>,
    /// The ordered points of each section (moved onto its plane if
    /// [`SectionOptions::flatten`]), before insertion: the contours of step 4.
    pub contours: Vec<Vec<DVec3>>,
    /// Each contour after insertion and rotation: N points, rows 0…K − 1 of the grid.
    pub rows: Vec<Vec<DVec3>>,
    /// Diagnostics: the same for the same input and options.
    pub report: SectionReport,
    /// The stages, in order, with their wall-clock times (kept out of the report).
    pub stages: Vec<Stage>,
}

impl SectionFit {
    /// The u window over which the surface covers the object once: from the middle of the
    /// bridge under the lowest section to the middle of the bridge over the highest, a half
    /// period (the other half is the same surface, reached from the other side).
    #[must_use]
    pub fn covering_window(&self) -> ParamRange {
        let quarter_row = 0.25 / self.rows.len() as f64;
        ParamRange::new(-quarter_row, 0.5 - quarter_row)
    }
}

/// Fits a harmonic surface to unorganised points by algorithm 1 (§5.3): sections across an
/// axis, a harmonic curve through each, insertion (Theorem 5.3) to equal counts, rotation
/// (Theorem 5.1) for the least total deviation, and the reversed traversal that closes the
/// tensor product. See the module documentation for each step and for the measured
/// [`Problem`]s of a bad fit.
///
/// # Errors
///
/// - [`Error::TooFewPoints`] for fewer than 6 points;
/// - [`Error::NonFinite`] naming the first point with a NaN or infinite coordinate;
/// - [`Error::InvalidOption`] for `slices` outside 2…[`MAX_SLICES`], or a grid over 2²⁶ points;
/// - [`Error::Degenerate`] when the points have no extent along the axis (or, for the
///   principal axis, all coincide);
/// - [`Error::SparseSlice`] naming a section with fewer than 3 points;
/// - errors of the surface layer, passed on.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::sections::{SectionOptions, fit_sections};
///
/// // Eight rings of twelve points on the unit sphere, at heights z = −7/8, −5/8, …, 7/8.
/// let mut points = Vec::new();
/// for i in 0..8 {
///     let z = (2 * i + 1) as f64 / 8.0 - 1.0;
///     let r = (1.0 - z * z).sqrt();
///     for k in 0..12 {
///         let a = std::f64::consts::TAU * (k as f64 + 0.3 * i as f64) / 12.0;
///         points.push(DVec3::new(r * a.cos(), r * a.sin(), z));
///     }
/// }
/// let options = SectionOptions { slices: Some(8), ..SectionOptions::default() };
/// let fit = fit_sections(&points, &options).unwrap();
/// assert_eq!(fit.report.surface_size, (16, 14)); // 2K rows; N = 14, even and above 12
/// // The grid's points lie on the sphere, and so does the surface through them, nearly.
/// assert!(fit.surface.points().iter().all(|p| (p.length() - 1.0).abs() < 1e-12));
/// assert!(fit.report.problems.is_empty());
/// ```
pub fn fit_sections(points: &[DVec3], options: &SectionOptions) -> Result<SectionFit, Error> {
    if points.len() < 2 * MIN_SLICE_POINTS {
        return Err(Error::TooFewPoints { found: points.len(), needed: 2 * MIN_SLICE_POINTS });
    }
    if let Some(k) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinite { what: NonFiniteInput::Point(k) });
    }
    if let Some(k) = options.slices
        && !(2..=MAX_SLICES).contains(&k)
    {
        return Err(Error::InvalidOption {
            name: "slices",
            value: k as f64,
            expected: "at least 2 and at most 65 536 sections",
        });
    }

    // Steps 1–3: the axis and the sections.
    let start = Instant::now();
    let axis = axis_of(options.axis, points)?;
    let frame = Frame::new(axis);
    let heights: Vec<f64> = points.iter().map(|p| frame.height(*p)).collect();
    let (lo, hi) =
        heights.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), h| (a.min(*h), b.max(*h)));
    let extent = points.iter().map(|p| p.length()).fold(0.0, f64::max);
    if hi - lo <= 1e-12 * extent {
        return Err(Error::Degenerate { what: "the points have no extent along the slicing axis" });
    }
    let slabs = match options.slices {
        Some(k) => equal_slabs(&heights, lo, hi, k)?,
        None => recursive_slabs(points, &heights, &frame, options.order, lo, hi)?,
    };
    let stages = vec![Stage { kind: StageKind::Slicing, seconds: start.elapsed().as_secs_f64() }];
    fit_slabs(points, &heights, &frame, &slabs, options, stages)
}

/// Algorithm 1 (§5.3) on data already arranged in cross-sections, "as is the case with CAT
/// scans" (step 3): `sections` in order along the axis, the points of each in any order. Steps
/// 4–8 are those of [`fit_sections`]; [`SectionOptions::slices`] is not used, and
/// [`SectionOptions::axis`] gives the planes the sections are flattened onto and ordered in.
///
/// # Errors
///
/// - [`Error::InvalidOption`] for fewer than 2 sections (or more than [`MAX_SLICES`]);
/// - [`Error::NonFinite`] naming the first point ("section 2, point 5") with a NaN or infinite
///   coordinate;
/// - [`Error::SparseSlice`] naming a section with fewer than 3 points;
/// - [`Error::Degenerate`] when, for the principal axis, all points coincide;
/// - and as [`fit_sections`] from step 4 on.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::sections::{SectionOptions, fit_given_sections};
///
/// // Five squares stacked along z, turned a little more each time: a twisted box.
/// let sections: Vec<Vec<DVec3>> = (0..5)
///     .map(|i| {
///         (0..4)
///             .map(|k| {
///                 let a = std::f64::consts::FRAC_PI_2 * k as f64 + 0.1 * i as f64;
///                 DVec3::new(a.cos(), a.sin(), i as f64)
///             })
///             .collect()
///     })
///     .collect();
/// let fit = fit_given_sections(&sections, &SectionOptions::default()).unwrap();
/// // Each square's harmonic curve is its circumcircle; insertion gives N = 6 points, and
/// // rotation alignment undoes the twist, so neighbouring contours differ by the unit step
/// // in height alone: 4 pairs of 6 points at distance 1.
/// assert_eq!(fit.report.surface_size, (10, 6));
/// assert!((fit.report.deviation - 24.0).abs() < 1e-9);
/// assert!(fit.report.deviation_unaligned > 24.1);
/// ```
pub fn fit_given_sections(
    sections: &[Vec<DVec3>],
    options: &SectionOptions,
) -> Result<SectionFit, Error> {
    if !(2..=MAX_SLICES).contains(&sections.len()) {
        return Err(Error::InvalidOption {
            name: "sections",
            value: sections.len() as f64,
            expected: "at least 2 and at most 65 536 sections",
        });
    }
    for (i, section) in sections.iter().enumerate() {
        if let Some(k) = section.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinite {
                what: NonFiniteInput::SectionPoint { section: i, point: k },
            });
        }
    }
    let start = Instant::now();
    let points: Vec<DVec3> = sections.iter().flatten().copied().collect();
    let axis = axis_of(options.axis, &points)?;
    let frame = Frame::new(axis);
    let heights: Vec<f64> = points.iter().map(|p| frame.height(*p)).collect();
    let mut slabs = Vec::with_capacity(sections.len());
    let mut first = 0;
    for section in sections {
        let members: Vec<usize> = (first..first + section.len()).collect();
        first += section.len();
        let (from, to) = members.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &i| {
            (a.min(heights[i]), b.max(heights[i]))
        });
        slabs.push(Slab { from, to, members });
    }
    slice::check_slabs(&slabs)?;
    let stages = vec![Stage { kind: StageKind::Slicing, seconds: start.elapsed().as_secs_f64() }];
    fit_slabs(&points, &heights, &frame, &slabs, options, stages)
}

/// Steps 4–8 of algorithm 1 and the diagnostics, on sections already cut.
fn fit_slabs(
    points: &[DVec3],
    heights: &[f64],
    frame: &Frame,
    slabs: &[Slab],
    options: &SectionOptions,
    mut stages: Vec<Stage>,
) -> Result<SectionFit, Error> {
    let timed = |kind: StageKind, stages: &mut Vec<Stage>, start: Instant| {
        stages.push(Stage { kind, seconds: start.elapsed().as_secs_f64() });
    };
    let axis = frame.axis;

    // Step 4: order each section's points along its contour.
    let start = Instant::now();
    let ordered: Vec<Ordered> =
        slabs.iter().map(|s| Ordered::new(points, heights, frame, s, options)).collect();
    timed(StageKind::Ordering, &mut stages, start);

    // Step 5: a harmonic curve through each, and what it tells of the section.
    let start = Instant::now();
    let curves = ordered
        .iter()
        .map(|o| HarmonicCurve::try_new(o.points.clone()).map_err(Error::from))
        .collect::<Result<Vec<_>, _>>()?;
    // A contour smaller than this is a point (a pole given as repeated points).
    let tiny = 1e-9 * hi_scan::distance::bounding_diagonal(points);
    let shapes = ordered
        .par_iter()
        .zip(&curves)
        .map(|(o, c)| o.shape(c, frame, tiny))
        .collect::<Result<Vec<_>, Error>>()?;
    timed(StageKind::HarmonicCurves, &mut stages, start);

    // Step 6: insertion (Theorem 5.3) to N points, even and above every section.
    let start = Instant::now();
    let largest = ordered.iter().map(|o| o.points.len()).max().unwrap_or(0);
    let n = (largest + 1).next_multiple_of(2);
    let k = slabs.len();
    if (2 * k).saturating_mul(n) > MAX_TEXELS {
        return Err(Error::InvalidOption {
            name: "grid points (2 × sections × contour points)",
            value: (2 * k * n) as f64,
            expected: "at most 2²⁶",
        });
    }
    let inserted = curves
        .iter()
        .map(|c| Ok(c.resample(n).map_err(Error::from)?.0))
        .collect::<Result<Vec<_>, Error>>()?;
    timed(StageKind::Insertion, &mut stages, start);

    // Step 7: rotation (Theorem 5.1) for the least total deviation.
    let start = Instant::now();
    let (rows, rotations) = rotate_rows(&inserted, options.alignment)?;
    timed(StageKind::Rotation, &mut stages, start);

    // Step 8: the reversed traversal on the other side, and the surface.
    let start = Instant::now();
    let mut grid = rows.clone();
    for row in rows.iter().rev() {
        let mut other_side = row.clone();
        other_side.rotate_left(n / 2);
        grid.push(other_side);
    }
    let surface = HarmonicSurface::try_new(grid)?;
    timed(StageKind::HarmonicSurface, &mut stages, start);

    // Diagnostics.
    let start = Instant::now();
    let (slices, deviation, deviation_unaligned) =
        slice_reports(slabs, &ordered, &shapes, &rows, &inserted, &rotations, n);
    let sampling_scale = sampling_scale(&slices, &shapes);
    timed(StageKind::Diagnostics, &mut stages, start);
    let (mut surface_to_points, mut points_to_surface) = (None, None);
    if options.error_oversample > 0 {
        let start = Instant::now();
        surface_to_points =
            Some(surface_to_nearest_point(&surface, points, options.error_oversample)?);
        points_to_surface = Some(distances_to_surface(&surface, points, options.error_oversample)?);
        timed(StageKind::FitError, &mut stages, start);
    }
    let problems = problems(&slices, surface_to_points.as_ref(), sampling_scale);
    let report = SectionReport {
        points: points.len(),
        axis,
        slices,
        contour_points: n,
        surface_size: (surface.m(), surface.n()),
        deviation_unaligned,
        deviation,
        sampling_scale,
        surface_to_points,
        points_to_surface,
        problems,
    };
    let contours = ordered.into_iter().map(|o| o.points).collect();
    Ok(SectionFit { surface, contours, rows, report, stages })
}

/// The diagnostics stage of [`fit_slabs`]: each section's report, and the total squared
/// deviation between consecutive rows after and before their rotation.
fn slice_reports(
    slabs: &[Slab],
    ordered: &[Ordered],
    shapes: &[Shape],
    rows: &[Vec<DVec3>],
    inserted: &[HarmonicCurve<DVec3>],
    rotations: &[f64],
    n: usize,
) -> (Vec<SliceReport>, f64, f64) {
    let k = slabs.len();
    let mut slices = Vec::with_capacity(k);
    let (mut deviation, mut deviation_unaligned) = (0.0, 0.0);
    for i in 0..k {
        let (d, d0) = if i == 0 {
            (0.0, 0.0)
        } else {
            (
                squared_deviation(&rows[i], &rows[i - 1]),
                squared_deviation(inserted[i].points(), inserted[i - 1].points()),
            )
        };
        deviation += d;
        deviation_unaligned += d0;
        slices.push(SliceReport {
            range: (slabs[i].from, slabs[i].to),
            height: ordered[i].height,
            points: ordered[i].points.len(),
            radius: shapes[i].radius,
            polygon_crossings: shapes[i].polygon_crossings,
            misordered: shapes[i].misordered,
            curve_crossings: shapes[i].curve_crossings,
            overshoot: shapes[i].overshoot,
            rotation: rotations[i],
            deviation: (d / n as f64).sqrt(),
            deviation_unaligned: (d0 / n as f64).sqrt(),
        });
    }
    (slices, deviation, deviation_unaligned)
}

/// The points of one section in contour order, with the plane they were put on.
struct Ordered {
    height: f64,
    points: Vec<DVec3>,
}

/// What a section's contour looks like in its plane.
struct Shape {
    radius: f64,
    median_edge: f64,
    polygon_crossings: usize,
    misordered: f64,
    curve_crossings: usize,
    overshoot: f64,
}

impl Ordered {
    fn new(
        points: &[DVec3],
        heights: &[f64],
        frame: &Frame,
        slab: &Slab,
        options: &SectionOptions,
    ) -> Self {
        let height =
            slab.members.iter().map(|&i| heights[i]).sum::<f64>() / slab.members.len() as f64;
        let plane: Vec<DVec2> = slab.members.iter().map(|&i| frame.plane(points[i])).collect();
        let order = order_contour(&plane, options.order);
        let points = order
            .iter()
            .map(|&o| {
                let i = slab.members[o];
                if options.flatten {
                    points[i] + (height - heights[i]) * frame.axis
                } else {
                    points[i]
                }
            })
            .collect();
        Self { height, points }
    }

    fn shape(
        &self,
        curve: &HarmonicCurve<DVec3>,
        frame: &Frame,
        tiny: f64,
    ) -> Result<Shape, Error> {
        let plane: Vec<DVec2> = self.points.iter().map(|p| frame.plane(*p)).collect();
        let centroid = plane.iter().copied().sum::<DVec2>() / plane.len() as f64;
        let radius = plane.iter().map(|p| p.distance(centroid)).sum::<f64>() / plane.len() as f64;
        let n = plane.len();
        let mut edges: Vec<f64> = (0..n).map(|k| plane[k].distance(plane[(k + 1) % n])).collect();
        edges.sort_by(f64::total_cmp);
        let (dense, overshoot) = diagnose::dense_and_overshoot(curve)?;
        let dense_plane: Vec<DVec2> = dense.iter().map(|p| frame.plane(*p)).collect();
        Ok(Shape {
            radius,
            median_edge: edges[n / 2],
            polygon_crossings: diagnose::crossings(&plane),
            misordered: diagnose::misordered(&plane)?,
            curve_crossings: diagnose::crossings(&dense_plane),
            overshoot: if radius > tiny { overshoot / radius } else { 0.0 },
        })
    }
}

/// See [`SectionReport::sampling_scale`].
fn sampling_scale(slices: &[SliceReport], shapes: &[Shape]) -> f64 {
    let gaps = slices.windows(2).map(|w| (w[1].height - w[0].height).abs());
    let edges = shapes.iter().map(|s| s.median_edge);
    let caps = [slices.first(), slices.last()].into_iter().flatten().map(|s| s.radius);
    gaps.chain(edges).chain(caps).fold(0.0, f64::max)
}

/// From every sample of the surface (oversampled over its whole period) to the nearest of
/// `points`.
fn surface_to_nearest_point(
    surface: &HarmonicSurface<DVec3>,
    points: &[DVec3],
    oversample: usize,
) -> Result<Distances, Error> {
    let (rows, cols) = (surface.m() * oversample, surface.n() * oversample);
    if rows.saturating_mul(cols) > MAX_TEXELS {
        return Err(Error::InvalidOption {
            name: "error_oversample",
            value: oversample as f64,
            expected: "at most 2²⁶ samples in all",
        });
    }
    let samples = surface.sample_uniform(rows, cols, 0, 0)?.values;
    let tree: ImmutableKdTree<f64, 3> =
        ImmutableKdTree::new_from_slice(&points.iter().map(|p| p.to_array()).collect::<Vec<_>>())
            .map_err(|_| Error::Degenerate { what: "the points do not form a kd-tree" })?;
    let per_point: Vec<f64> = samples
        .par_iter()
        .map(|p| {
            tree.query(&p.to_array())
                .nearest_one::<SquaredEuclidean<f64>>()
                .execute()
                .distance
                .sqrt()
        })
        .collect();
    Ok(Distances::from_values(per_point, hi_scan::distance::bounding_diagonal(points)))
}

/// The measured [`Problem`]s of a fit.
fn problems(slices: &[SliceReport], strays: Option<&Distances>, scale: f64) -> Vec<Problem> {
    let mut res = Vec::new();
    for (slice, s) in slices.iter().enumerate() {
        if s.polygon_crossings > 0 || s.misordered > MISORDER_LIMIT {
            res.push(Problem::ScrambledContour {
                slice,
                misordered: s.misordered,
                crossings: s.polygon_crossings,
            });
        } else if s.curve_crossings > 0 {
            res.push(Problem::LoopingContour { slice, crossings: s.curve_crossings });
        }
        if s.overshoot > OVERSHOOT_LIMIT {
            res.push(Problem::Overshoot { slice, ratio: s.overshoot });
        }
    }
    if let Some(d) = strays
        && d.max > STRAY_LIMIT * scale
    {
        res.push(Problem::StraysFromPoints { distance: d.max, scale });
    }
    res
}
