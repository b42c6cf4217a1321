// SPDX-License-Identifier: MIT
//! The whole fitting pipeline of §5.3–§5.4 and §5.8: scan → geometry image → (smoothing) →
//! (reduction by Theorem 5.3) → harmonic surface, timed stage by stage, with the diagnostics
//! and the fit's error against the scan.

use std::time::Instant;

use glam::DVec3;
use hi_curve::ReductionError;
use hi_surface::HarmonicSurface;

use crate::contours::{ContourImage, contour_image};
use crate::distance::{Distances, Hausdorff, distances_to_surface, hausdorff};
use crate::scan::Scan;
use crate::spherical::{Layout, SphericalImage, SphericalOptions, spherical_image};
use crate::{Error, GeometryImage, Smoothing};

/// The settings of [`fit`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitOptions {
    /// The parameterisation of the geometry image: spherical (algorithm 2), octahedral or
    /// flattened octahedral (§5.3).
    pub layout: Layout,
    /// What a texel holds: the distance along its ray (algorithm 2) or the scan point it
    /// located, rows made into contours (§5.8). Default [`Texels::Radial`].
    pub texels: Texels,
    /// Geometry image rows (even). Default 128.
    pub rows: usize,
    /// Geometry image columns. Default 128.
    pub cols: usize,
    /// The centre of the rays; `None` for the mean of the points.
    pub centre: Option<DVec3>,
    /// A smoothing filter applied to the geometry image (§5.4), if any.
    pub smoothing: Option<Smoothing>,
    /// Keep about this fraction of the texels by Theorem 5.3 (each side scaled by its square
    /// root; §5.8 keeps 0.25), if any. In (0, 1].
    pub reduce: Option<f64>,
    /// A mesh with fewer points than this gets more, sampled on its triangles
    /// ([`crate::sampling::densify`]), for the geometry image (errors are still measured
    /// against the scan's own points and mesh). Default 200 000; 0 turns it off.
    pub densify: usize,
    /// Measure the fit error on the surface sampled this many times finer than its grid; 0
    /// skips the measurement. Default 4.
    pub error_oversample: usize,
}

impl Default for FitOptions {
    fn default() -> Self {
        Self {
            layout: Layout::Sphere,
            texels: Texels::Radial,
            rows: 128,
            cols: 128,
            centre: None,
            smoothing: None,
            reduce: None,
            densify: 200_000,
            error_oversample: 4,
        }
    }
}

/// What each texel of the geometry image holds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Texels {
    /// The point at the distance along the ray averaged over the points about it (algorithm 2,
    /// [`spherical_image`]).
    #[default]
    Radial,
    /// The scan point the ray located; each row a contour through its distinct located points,
    /// resampled to the columns by Theorem 5.3 (§5.8 "combined results",
    /// [`contour_image`]).
    Contours,
}

/// The ray-cast geometry image a fit started from, with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub enum SourceImage {
    /// Algorithm 2's image.
    Radial(SphericalImage),
    /// §5.8's image of contours.
    Contours(ContourImage),
}

impl SourceImage {
    /// The image, before smoothing and reduction.
    #[must_use]
    pub const fn image(&self) -> &GeometryImage {
        match self {
            Self::Radial(s) => &s.image,
            Self::Contours(c) => &c.image,
        }
    }

    /// The fraction of the rays that met several shells.
    #[must_use]
    pub const fn non_star_fraction(&self) -> f64 {
        match self {
            Self::Radial(s) => s.non_star_fraction,
            Self::Contours(c) => c.non_star_fraction,
        }
    }

    /// The fraction of the rays that found too few points.
    #[must_use]
    pub const fn hole_fraction(&self) -> f64 {
        match self {
            Self::Radial(s) => s.hole_fraction,
            Self::Contours(c) => c.hole_fraction,
        }
    }
}

/// How many distinct located points the rows of a §5.8 image had.
#[derive(Clone, Copy, Debug, PartialEq)]
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

/// The time one stage took.
#[derive(Clone, Debug, PartialEq)]
pub struct Stage {
    /// Its name: "geometry image", "smoothing", "reduction", "harmonic surface",
    /// "rasterisation (4×)", "fit error".
    pub name: &'static str,
    /// Wall-clock seconds.
    pub seconds: f64,
}

/// What [`fit`] did and how well the result fits.
#[derive(Clone, Debug, PartialEq)]
pub struct FitReport {
    /// Points of the scan (finite ones).
    pub points: usize,
    /// Points the geometry image was built from: the scan's, and those sampled on its
    /// triangles when it was sparse.
    pub image_points: usize,
    /// Points the reader dropped for a non-finite coordinate.
    pub dropped_points: usize,
    /// The stages, in order, with their times.
    pub stages: Vec<Stage>,
    /// The fraction of rays that met several shells: the scan is not star-shaped about the
    /// centre there, and the fit follows the outermost shell.
    pub non_star_fraction: f64,
    /// The fraction of rays that found too few points (filled from their neighbours).
    pub hole_fraction: f64,
    /// For [`Texels::Contours`], the distinct located points per row.
    pub row_points: Option<RowPoints>,
    /// The grid of the final surface (rows, columns).
    pub surface_size: (usize, usize),
    /// The error of the reduction, if one was made.
    pub reduction: Option<ReductionError>,
    /// Distances from every scan point to the surface, if measured.
    pub errors: Option<Distances>,
    /// Both-way distances to the scan's mesh, if measured and the scan has faces.
    pub hausdorff: Option<Hausdorff>,
}

/// A fitted surface with its geometry images and report.
#[derive(Clone, Debug, PartialEq)]
pub struct Fit {
    /// The harmonic surface; [`Layout::covering_window`] says which u cover the object once.
    pub surface: HarmonicSurface<DVec3>,
    /// The raw ray-cast image with its diagnostic maps (before smoothing and reduction).
    pub source: SourceImage,
    /// The geometry image the surface interpolates (after smoothing and reduction).
    pub image: GeometryImage,
    /// Stage times, diagnostics and errors.
    pub report: FitReport,
}

/// Fits a harmonic surface to a scan: the geometry image (algorithm 2), optional smoothing
/// and reduction (§5.4), the harmonic surface through the image (no linear system), the
/// 4× rasterisation the thesis times in Table 5.1, and the fit's error. `on_stage` is told the
/// name of each stage as it starts (for a progress display).
///
/// # Errors
///
/// The errors of [`spherical_image`], [`GeometryImage::smoothed`] and
/// [`GeometryImage::resampled`]; [`Error::InvalidOption`] for `reduce` outside (0, 1].
pub fn fit(
    scan: &Scan,
    options: &FitOptions,
    on_stage: &mut dyn FnMut(&'static str),
) -> Result<Fit, Error> {
    let mut stages = Vec::new();
    let timed = |name: &'static str, stages: &mut Vec<Stage>, start: Instant| {
        stages.push(Stage { name, seconds: start.elapsed().as_secs_f64() });
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
    on_stage("geometry image");
    let start = Instant::now();
    let points = crate::sampling::densify(scan, options.densify);
    let rays = SphericalOptions {
        layout: options.layout,
        rows: options.rows,
        cols: options.cols,
        centre: options.centre,
        ..SphericalOptions::default()
    };
    let source = match options.texels {
        Texels::Radial => SourceImage::Radial(spherical_image(&points, &rays)?),
        Texels::Contours => SourceImage::Contours(contour_image(&points, &rays)?),
    };
    timed("geometry image", &mut stages, start);
    let mut image = source.image().clone();
    if let Some(filter) = options.smoothing {
        on_stage("smoothing");
        let start = Instant::now();
        image = image.smoothed(filter)?;
        timed("smoothing", &mut stages, start);
    }
    let mut reduction = None;
    if let Some(fraction) = options.reduce.filter(|&f| f < 1.0) {
        on_stage("reduction");
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
        timed("reduction", &mut stages, start);
    }
    on_stage("harmonic surface");
    let start = Instant::now();
    let surface = image.surface()?;
    timed("harmonic surface", &mut stages, start);
    on_stage("rasterisation (4×)");
    let start = Instant::now();
    let raster = surface.sample_uniform(2 * surface.m(), 2 * surface.n(), 0, 0)?;
    std::hint::black_box(&raster);
    timed("rasterisation (4×)", &mut stages, start);
    let (mut errors, mut both_ways) = (None, None);
    if options.error_oversample > 0 {
        on_stage("fit error");
        let start = Instant::now();
        if scan.triangles.is_empty() {
            errors = Some(distances_to_surface(&surface, &scan.points, options.error_oversample)?);
        } else {
            let h = hausdorff(&surface, &scan.points, &scan.triangles, options.error_oversample)?;
            errors = Some(h.scan_to_surface.clone());
            both_ways = Some(h);
        }
        timed("fit error", &mut stages, start);
    }
    let report = FitReport {
        points: scan.points.len(),
        image_points: points.len(),
        dropped_points: scan.dropped_points,
        stages,
        non_star_fraction: source.non_star_fraction(),
        hole_fraction: source.hole_fraction(),
        row_points: match &source {
            SourceImage::Radial(_) => None,
            SourceImage::Contours(c) => Some(RowPoints {
                min: c.row_points.iter().copied().min().unwrap_or(0),
                mean: c.row_points.iter().sum::<usize>() as f64 / c.row_points.len().max(1) as f64,
                max: c.row_points.iter().copied().max().unwrap_or(0),
                empty_rows: c.empty_rows.len(),
            }),
        },
        surface_size: (surface.m(), surface.n()),
        reduction,
        errors,
        hausdorff: both_ways,
    };
    Ok(Fit { surface, source, image, report })
}
