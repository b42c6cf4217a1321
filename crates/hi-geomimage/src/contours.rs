// SPDX-License-Identifier: MIT
//! The geometry image of §5.8 ("combined results"): algorithm 2's rays, but each texel keeps
//! the scan point the ray located instead of a distance averaged over a sphere about it, and
//! each row of the image becomes a contour made rectangular by Theorem 5.3.
//!
//! For every ray the points about it are gathered as in [`crate::spherical`] (growing angle,
//! outermost shell when there are several), and the one nearest the ray in direction is the
//! located point. Along a row the located points are listed in the order the rays meet them,
//! each once (neighbouring rays often locate the same point; a row is a closed loop, so the
//! list is cyclic). The harmonic curve through a row's K points at t = k/K is the contour; it is
//! sampled at the image's N columns, t = l/N (Theorem 5.3: the same curve through N ≥ K points),
//! so that every row has N texels. The thesis then smooths the image and reduces it to about a
//! quarter by Theorem 5.3 ([`crate::FitOptions::smoothing`], [`crate::FitOptions::reduce`]).
//!
//! What this trades: the texels are scan points (the thesis's reason: no sphere approximation
//! near the located point), but a row's parameter follows the count of distinct points, not the
//! ray, so where a row meets few points its texels bunch along fewer, longer steps. The image
//! reports how many distinct points each row had ([`ContourImage::row_points`]).
//!
//! The doubled layouts keep their half-turn symmetry exactly: the rows past the middle are the
//! mirrors of the first half, and the two rows that are their own mirror are averaged with it.

use glam::DVec3;
use hi_curve::Fourier;
use hi_par::*;

use crate::Error;
use crate::image::GeometryImage;
use crate::spherical::{Caster, SphericalOptions, complete_by_symmetry, shells};

/// A §5.8 geometry image with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub struct ContourImage {
    /// The rectangular image: row i is the contour through row i's located points, sampled at
    /// the image's columns.
    pub image: GeometryImage,
    /// The centre of the rays.
    pub centre: DVec3,
    /// The input index of the point each ray located (row-major), `None` for a hole.
    pub located: Vec<Option<usize>>,
    /// The number of distinct located points of each row (the K of its contour).
    pub row_points: Vec<usize>,
    /// Rows that located no point at all, filled from the nearest rows that did.
    pub empty_rows: Vec<usize>,
    /// The fraction of the rays (each direction counted once) that met several shells.
    pub non_star_fraction: f64,
    /// The fraction of the rays that found too few points.
    pub hole_fraction: f64,
}

/// The point each ray located, and whether it saw several shells.
type Located = (Option<usize>, bool);

/// Builds the §5.8 geometry image of `points`: located points per row, each row a contour
/// resampled to the image's columns by Theorem 5.3.
///
/// # Errors
///
/// As [`crate::spherical::spherical_image`]; [`Error::TooFewPoints`] when no ray locates a
/// point.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::Layout;
/// use hi_geomimage::contours::contour_image;
/// use hi_geomimage::spherical::SphericalOptions;
///
/// // Points on the unit sphere: every texel is a point of the sphere, so on the sphere.
/// let points: Vec<DVec3> = (0..20_000)
///     .map(|k| {
///         let z = 1.0 - (2 * k + 1) as f64 / 20_000.0;
///         let phi = k as f64 * 2.399_963_229_728_653; // the golden angle
///         let s = (1.0 - z * z).sqrt();
///         DVec3::new(s * phi.cos(), s * phi.sin(), z)
///     })
///     .collect();
/// let options = SphericalOptions {
///     layout: Layout::FlatOctahedron,
///     rows: 32,
///     cols: 32,
///     ..SphericalOptions::default()
/// };
/// let result = contour_image(&points, &options).unwrap();
/// assert!(result.row_points.iter().all(|&k| k >= 8));
/// // Between the located points the contours stay close to the sphere.
/// assert!(result.image.texels().iter().all(|p| (p.length() - 1.0).abs() < 0.05));
/// ```
pub fn contour_image(points: &[DVec3], options: &SphericalOptions) -> Result<ContourImage, Error> {
    let &SphericalOptions { layout, rows, cols, .. } = options;
    let caster = Caster::new(points, options)?;
    let mirror = layout.mirror(rows, cols);
    let cast_rows = if mirror.is_some() { rows / 2 + 1 } else { rows };
    let mut located: Vec<Located> = (0..cast_rows * cols)
        .into_par_iter()
        .map(|t| {
            let Some((_, found)) = caster.gather(layout.direction(t / cols, t % cols, rows, cols))
            else {
                return (None, false);
            };
            let groups = shells(
                &found.iter().map(|&(_, item)| caster.distances[item]).collect::<Vec<_>>(),
                caster.gap,
            );
            let outer_min = groups.last().and_then(|g| g.first().copied()).unwrap_or(0.0);
            let nearest = found
                .iter()
                .filter(|&&(_, item)| caster.distances[item] >= outer_min)
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .map(|&(_, item)| caster.index[item]);
            (nearest, groups.len() > 1)
        })
        .collect();
    // The distinct located points of each cast row, and its contour sampled at the columns.
    let lists: Vec<Vec<usize>> = (0..cast_rows)
        .map(|i| distinct_cyclic(located[i * cols..(i + 1) * cols].iter().map(|l| l.0)))
        .collect();
    let contours: Vec<Option<Vec<DVec3>>> = lists
        .par_iter()
        .map(|list| {
            (!list.is_empty()).then(|| {
                let row: Vec<DVec3> = list.iter().map(|&k| points[k]).collect();
                Fourier::from_points(&row).sample_uniform(cols)
            })
        })
        .collect();
    let mut row_points: Vec<usize> = lists.iter().map(Vec::len).collect();
    let empty_rows: Vec<usize> = (0..cast_rows).filter(|&i| contours[i].is_none()).collect();
    if empty_rows.len() == cast_rows {
        return Err(Error::TooFewPoints { found: 0, needed: 1 });
    }
    let mut texels: Vec<DVec3> = Vec::with_capacity(rows * cols);
    for i in 0..cast_rows {
        match &contours[i] {
            Some(row) => texels.extend_from_slice(row),
            None => texels.extend(nearest_rows(&contours, i, cols)),
        }
    }
    if let Some(mirror) = &mirror {
        // The rows that are their own mirror: averaged with it, so the symmetry is exact.
        for i in [0, rows / 2] {
            let row: Vec<DVec3> = texels[i * cols..(i + 1) * cols].to_vec();
            for (j, t) in texels[i * cols..(i + 1) * cols].iter_mut().enumerate() {
                let (_, b) = mirror(i, j);
                *t = 0.5 * (row[j] + row[b]);
            }
        }
        complete_by_symmetry(&mut texels, rows, cols, mirror);
        complete_by_symmetry(&mut located, rows, cols, mirror);
        for i in cast_rows..rows {
            row_points.push(row_points[mirror(i, 0).0]);
        }
    }
    // Each direction once, as in the spherical image.
    let distinct = if mirror.is_some() { rows / 2 * cols } else { rows * cols };
    let fraction = |f: &dyn Fn(&Located) -> bool| {
        located[..distinct].iter().filter(|l| f(l)).count() as f64 / distinct as f64
    };
    let non_star_fraction = fraction(&|l| l.1);
    let hole_fraction = fraction(&|l| l.0.is_none());
    Ok(ContourImage {
        image: GeometryImage::try_new(rows, cols, texels)?,
        centre: caster.centre,
        located: located.into_iter().map(|l| l.0).collect(),
        row_points,
        empty_rows,
        non_star_fraction,
        hole_fraction,
    })
}

/// The distinct values of a cyclic sequence in order, holes skipped: a run of equal values
/// counts once, and a run that wraps around the end joins the one at the start.
fn distinct_cyclic(values: impl Iterator<Item = Option<usize>>) -> Vec<usize> {
    let mut list: Vec<usize> = Vec::new();
    for v in values.flatten() {
        if list.last() != Some(&v) {
            list.push(v);
        }
    }
    while list.len() > 1 && list.last() == list.first() {
        list.pop();
    }
    list
}

/// The row for an empty cast row i: the nearest rows with contours, averaged when two are
/// equally near.
fn nearest_rows(contours: &[Option<Vec<DVec3>>], i: usize, cols: usize) -> Vec<DVec3> {
    for d in 1..contours.len() {
        let near: Vec<&Vec<DVec3>> = [i.checked_sub(d), Some(i + d)]
            .into_iter()
            .flatten()
            .filter_map(|a| contours.get(a).and_then(Option::as_ref))
            .collect();
        if !near.is_empty() {
            return (0..cols)
                .map(|j| near.iter().map(|r| r[j]).sum::<DVec3>() / near.len() as f64)
                .collect();
        }
    }
    vec![DVec3::ZERO; cols]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distinct_cyclic_merges_runs_and_the_wrap() {
        let list = |v: &[Option<usize>]| distinct_cyclic(v.iter().copied());
        assert_eq!(list(&[Some(3), Some(3), None, Some(4), Some(3)]), vec![3, 4]);
        assert_eq!(list(&[Some(1), Some(2), Some(2), Some(1), Some(1)]), vec![1, 2]);
        assert_eq!(list(&[Some(5), Some(5)]), vec![5]);
        assert_eq!(list(&[None, None]), Vec::<usize>::new());
        // A point met again later (not in a run) stays: a row may pass a point twice.
        assert_eq!(list(&[Some(1), Some(2), Some(1), Some(3)]), vec![1, 2, 1, 3]);
    }
}
