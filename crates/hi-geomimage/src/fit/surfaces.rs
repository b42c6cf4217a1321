// SPDX-License-Identifier: MIT
//! A part's surface from its image: smoothing, regularisation and reduction.

use super::*;

/// A part's surface, from its image through smoothing, regularisation and reduction.
pub(super) struct Surfaced {
    pub(super) surface: HarmonicSurface<DVec3>,
    pub(super) image: GeometryImage,
    pub(super) regularisation: RegularisationReport,
    pub(super) reduction: Option<ReductionDeviation>,
}

/// Smoothing, regularisation (`how`) and reduction of a part's image, and its surface.
pub(super) fn surface_of(
    source: &SourceImage,
    options: &FitOptions,
    how: Regularisation,
    part: (usize, usize),
    clock: &mut Clock<'_>,
) -> Result<Surfaced, Error> {
    let mut image = source.image().clone();
    if let Some(filter) = options.smoothing {
        image = clock.run(StageKind::Smoothing, part, || image.smoothed(filter))?;
    }
    let regularisation = if how == Regularisation::Off {
        RegularisationReport { lambda: 0.0, kept: 1.0, rms_change: 0.0, max_change: 0.0 }
    } else {
        let (smooth, report) =
            clock.run(StageKind::Regularisation, part, || regularise(&image, how))?;
        image = smooth;
        report
    };
    let mut reduction = None;
    if let Some(fraction) = options.reduce.filter(|&f| f < 1.0) {
        let scale = fraction.sqrt();
        // Keep the rows even, so that both poles stay texels of a spherical image.
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "0 < scale < 1 times a size ≤ 2²⁶"
        )]
        let (rows, cols) = (
            (((image.rows() as f64 * scale) / 2.0).round() as usize * 2).max(2),
            (((image.cols() as f64 * scale) / 2.0).round() as usize * 2).max(2),
        );
        let (reduced, error) =
            clock.run(StageKind::Reduction, part, || image.resampled(rows, cols))?;
        image = reduced;
        reduction = Some(error);
    }
    let surface = clock.run(StageKind::HarmonicSurface, part, || image.surface())?;
    if options.rasterise {
        clock.run(StageKind::Rasterisation, part, || -> Result<(), Error> {
            let raster = surface.sample_uniform(2 * surface.m(), 2 * surface.n(), 0, 0)?;
            std::hint::black_box(&raster);
            Ok(())
        })?;
    }
    Ok(Surfaced { surface, image, regularisation, reduction })
}

/// The flags of the source image's filled texels on the surface's grid (they differ after a
/// reduction).
pub(super) fn filled_on_grid(
    source: &SourceImage,
    surface: &HarmonicSurface<DVec3>,
) -> Option<Vec<bool>> {
    source.filled().map(|f| {
        let (rows, cols) = (source.image().rows(), source.image().cols());
        let (sm, sn) = (surface.m(), surface.n());
        (0..sm * sn).map(|t| f[(t / sn * rows / sm) * cols + (t % sn) * cols / sn]).collect()
    })
}

/// The noise of a point set's texels over the noise of its points: a texel lies on quadric
/// patches fitted by least squares to [`NEIGHBOURS`] points, whose fitted values scatter by
/// σ √(p/k) on average (the mean leverage p/k of a fit of p = 6 parameters to k points).
const TEXEL_NOISE: f64 = 0.612_372_435_695_794_5; // √(6/16)

/// [`TEXEL_NOISE`] for a lump of noise ([`hi_scan::noise::Noise::lump`]): patches fitted to a
/// few points of a scan as thick as they are far apart lie in planes the scatter sets, and
/// follow it rather than average it: the texels keep the points' noise (0.92 σ, measured on
/// CGAL's `sphere_20k.xyz` fitted with no regularisation).
const LUMP_TEXEL_NOISE: f64 = 1.0;

/// The regularisation of the parts' images, and the noise estimated for it: images sampled
/// from a mesh lie on the scan's surface, with nothing to smooth away; images made from points
/// carry what is left of the points' scatter once the quadric patches have averaged it
/// ([`TEXEL_NOISE`] of it, or all of it for a lump of noise, [`LUMP_TEXEL_NOISE`]): smooth that
/// away, and no more.
pub(super) fn regularisation_for(
    options: &FitOptions,
    method: Method,
    image_points: &[DVec3],
) -> (Regularisation, Option<hi_scan::noise::Noise>) {
    match (options.regularisation, method) {
        (Regularisation::Auto, Method::Mesh) => (Regularisation::Off, None),
        (Regularisation::Auto, _) => {
            let noise = hi_scan::noise::noise_estimate(image_points);
            let texels = if noise.lump { LUMP_TEXEL_NOISE } else { TEXEL_NOISE };
            (Regularisation::Noise(texels * noise.sigma), Some(noise))
        }
        (r, _) => (r, None),
    }
}
