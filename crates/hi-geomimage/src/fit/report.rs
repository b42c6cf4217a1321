// SPDX-License-Identifier: MIT
//! The fit's error and the report of each part.

use super::*;

/// The fit's error, as [`FitOptions::error`] asks.
#[derive(Default)]
pub(super) struct Measurement {
    /// Every scan point to the nearest surface.
    pub(super) errors: Option<Distances>,
    /// Both ways over every part.
    pub(super) both_ways: Option<FitErrors>,
    /// The thesis's measurement against a scan's mesh.
    pub(super) hausdorff: Option<Hausdorff>,
    /// Each part's, both ways.
    pub(super) by_part: Vec<Option<FitErrors>>,
    /// Each part's mesh, measured on.
    pub(super) meshes: Vec<Option<LayoutMesh>>,
}

/// Measures the fit of the parts' surfaces to the scan (`points`, `triangles`).
pub(super) fn measure_error(
    sourced: &[Sourced],
    surfaced: &[Surfaced],
    (points, triangles): (&[DVec3], &[[u32; 3]]),
    options: &FitOptions,
    method: Method,
    clock: &mut Clock<'_>,
) -> Result<Measurement, Error> {
    let n = sourced.len();
    let mut out =
        Measurement { by_part: vec![None; n], meshes: vec![None; n], ..Measurement::default() };
    match options.error {
        ErrorMeasure::Off => {}
        ErrorMeasure::Sampled(oversample) if method != Method::Mesh && n == 1 => {
            // The thesis's measurement, as the figures of §5.3 report it.
            let surface = &surfaced[0].surface;
            clock.run(StageKind::FitError, (0, 1), || -> Result<(), Error> {
                if triangles.is_empty() {
                    out.errors = Some(distances_to_surface(surface, points, oversample)?);
                } else {
                    let h = hausdorff(surface, points, triangles, oversample)?;
                    out.errors = Some(h.scan_to_surface.clone());
                    out.hausdorff = Some(h);
                }
                Ok(())
            })?;
        }
        measure => {
            let filled: Vec<Option<Vec<bool>>> = sourced
                .iter()
                .zip(surfaced)
                .map(|(p, s)| filled_on_grid(&p.source, &s.surface))
                .collect();
            let measured: Vec<measure::Measured<'_>> = sourced
                .iter()
                .zip(surfaced)
                .zip(&filled)
                .map(|((p, s), f)| measure::Measured {
                    surface: &s.surface,
                    domain: p.domain,
                    area_fraction: p.area_fraction,
                    filled: f.as_deref(),
                    // An image of a mesh's parameterisation left as it was sampled has its
                    // texels on the scan's triangles.
                    texels_on_scan: method == Method::Mesh
                        && s.regularisation.lambda == 0.0
                        && options.smoothing.is_none()
                        && s.reduction.is_none(),
                })
                .collect();
            let (mut all, each, meshes) = clock.run(StageKind::FitError, (0, 1), || {
                measure::measure_parts(&measured, points, triangles, measure)
            })?;
            // The per-point distances once, in `errors`.
            let per_point = std::mem::take(&mut all.scan_to_surface.per_point);
            out.errors = Some(Distances { per_point, ..all.scan_to_surface.clone() });
            out.both_ways = Some(all);
            out.by_part = each.into_iter().map(Some).collect();
            out.meshes = meshes.into_iter().map(Some).collect();
        }
    }
    Ok(out)
}

/// The report of one part.
pub(super) fn part_report(p: &Sourced, s: &Surfaced, errors: Option<FitErrors>) -> PartReport {
    PartReport {
        name: p.name.clone(),
        domain: p.domain,
        why: p.why.clone(),
        area_fraction: p.area_fraction,
        genus: p.genus,
        boundary_loops: p.boundary_loops,
        repair: p.repair,
        image_size: (p.source.image().rows(), p.source.image().cols()),
        surface_size: (s.surface.m(), s.surface.n()),
        non_star_fraction: p.source.non_star_fraction(),
        hole_fraction: p.source.hole_fraction(),
        regularisation: s.regularisation,
        reduction: s.reduction,
        errors,
    }
}

/// For §5.8's image, the distinct located points per row.
pub(super) fn row_points(source: &SourceImage) -> Option<RowPoints> {
    match source {
        SourceImage::Contours(c) => Some(RowPoints {
            min: c.row_points.iter().copied().min().unwrap_or(0),
            mean: c.row_points.iter().sum::<usize>() as f64 / c.row_points.len().max(1) as f64,
            max: c.row_points.iter().copied().max().unwrap_or(0),
            empty_rows: c.empty_rows.len(),
        }),
        _ => None,
    }
}
