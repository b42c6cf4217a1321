// SPDX-License-Identifier: MIT
//! How noisy a scan is: the scatter of its points about the smooth surface they sample,
//! estimated from the points alone (for the regularisation of `hi-geomimage`'s geometry images).
//!
//! About each of up to 2 000 points spread over the scan, its k nearest neighbours are fitted,
//! in the frame of their principal axes, by a quadric height field
//! h(x, y) = a + bx + cy + dx² + exy + fy² (least squares), at four scales k = 8, 12, 16 and 24
//! (the nearest k of the same 24); the residual's root mean square, corrected for the six
//! fitted parameters (× √(k / (k − 6))), is that neighbourhood's scatter at scale k. Each
//! scale's median over the neighbourhoods (which ignores the few that straddle an edge or two
//! sheets), divided by the median of √(χ²ᵥ/ν) for ν = k − 6 degrees of freedom
//! (Wilson–Hilferty), estimates sₖ² = σ² + mₖ², where σ is the noise and mₖ the part of the
//! surface no quadric follows. The noise is the same at every scale; the surface's part grows
//! with the neighbourhood: as r³ on a smooth, evenly sampled surface (mₖ² ∝ k³, the radius r
//! growing as √k), as r at a crease (mₖ² ∝ k), and in between where the sampling is uneven, as
//! in the vertices of a mesh refined where it curves. So sₖ² = σ² + c kᵖ is fitted to the four
//! scales for each p = 1, 1.25, …, 3 (least squares weighted by 1/sₖ², with σ², c ≥ 0), and
//! the best fit's σ is the noise, at most s₈. A clean sample of a smooth surface thus gives
//! nearly 0 however sparse or uneven it is (a quadric over 24 of a mesh's few thousand vertices
//! misses the curvature by far more than its rounding), and a noisy one its noise, the floor
//! that sₖ levels off to at the small scales. Noise well below the surface's own departure at
//! the smallest scale (a sparse sample, noise of a tenth of its spacing or less) cannot be told
//! from the shape and is not seen: then the estimate is low rather than high, and the
//! regularisation it sets smooths less, not away the detail of a clean sparse scan.
//!
//! Noise as large as the points' spacing or larger (a scan as thick as its points are far
//! apart) is the other end: 24 neighbours then make a lump as thick as it is wide, whose
//! principal axes and quadric follow the scatter itself, so that every small scale finds a
//! fraction of the noise (two fifths to nine tenths), the less the smaller the scale. Such a scan
//! shows itself by its thickness, the residual over the neighbourhood's radius: over
//! [`LUMPY`] at the smallest scale, over [`THIN`] at the largest and not much more than at the
//! smallest (a clean curved surface grows thicker with the scale, as r²). Its neighbourhoods
//! are then widened (48, 96, … up to 768 points) until one is thinner than [`THIN`], where the
//! scatter of a noisy sphere is found to within a few per cent (the residual rises to the noise
//! as the lump flattens into a slab), and that scale's residual is the noise. Points that fill
//! a volume (a cube's or a blob's, as some point sets are, made for other uses) are as thick at
//! every scale, and so is noise so large that no surface shows through it: should no wider
//! neighbourhood be thin, the small scales' estimate stands and the points are said to fill a
//! volume ([`Noise::volume`]); should one grow thicker than the one before it (the surface's
//! curvature showing), the small scales' estimate stands. The residual at the thin scale
//! includes the surface's own departure from a quadric there, so the estimate errs high rather
//! than low, and smooths what is noise.
use std::num::NonZero;

use glam::{DMat3, DVec3};
use hi_par::*;
use kiddo::{ImmutableKdTree, SquaredEuclidean};

/// The scales: neighbours per local fit, the largest last.
const SCALES: [usize; 4] = [8, 12, 16, 24];

/// Neighbours per local fit at the largest scale.
const K: usize = SCALES[SCALES.len() - 1];

/// Neighbourhoods examined at most.
const SAMPLES: usize = 2000;

/// A neighbourhood is thin, its principal plane and quadric set by the surface rather than by
/// the noise, when its residual is under this fraction of its radius (its thickness). Measured
/// at 24 neighbours: a cloud's own noise of 10⁻⁴ of its diagonal at 2·10⁵ points, a mesh's
/// vertices, and scanners' point sets at 0.01–0.12; a sphere's points displaced by their
/// spacing or twice it at 0.3. Under 0.16, the residual is within 3 % of the noise on a sphere
/// and 10 % on a torus whose tube's radius is 7.5 times the noise.
pub const THIN: f64 = 0.16;

/// A scan is taken as a lump of noise, its noise found at wider scales, when its thickness at
/// 8 neighbours is over this, and its thickness at 24 neighbours is over [`THIN`] and at most
/// [`LUMP`] times that at 8 (a sphere's points displaced by their spacing or twice it: 0.3 at
/// 8 neighbours; a sparse mesh's vertices displaced by a quarter of their spacing, whose
/// small scales find the noise: 0.22).
pub const LUMPY: f64 = 0.25;

/// How much thicker at 24 neighbours than at 8 a lump of noise ([`LUMPY`]) may be: a noisy
/// sphere's ratio is 0.9 to 1.04; a clean curved surface grows thicker as r², nine times at an
/// even density.
pub const LUMP: f64 = 1.25;

/// A wider neighbourhood more than this many times as thick as the one before it shows the
/// surface's curvature: the lump is a surface's, but its noise is not found (points that fill a
/// volume are as thick at every scale, to within a few per cent).
const THICKER: f64 = 1.1;

/// The neighbourhoods tried, smallest first, for a scan thicker than [`THIN`].
const WIDER: [usize; 5] = [48, 96, 192, 384, 768];

/// How noisy a scan is ([`noise_estimate`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Noise {
    /// The noise σ: the scatter of the points about their surface, in the units of the points.
    pub sigma: f64,
    /// Whether the scan is a lump of noise ([`LUMPY`]): noise of its spacing or more, found at
    /// wider scales. Quadric patches fitted to a few of its points then follow the scatter
    /// rather than average it away, as they do for a scan whose noise is under its spacing.
    pub lump: bool,
    /// Whether the points fill a volume, or scatter about their surface by more than can be
    /// told from it: as thick as a lump at 8 and 24 neighbours, and at every wider scale tried
    /// (up to 768 points, or all of them). `sigma` is then the small scales' estimate, and no
    /// surface through the points is what they are.
    pub volume: bool,
}

/// No noise found, and neither a lump nor a volume.
const NO_NOISE: Noise = Noise { sigma: 0.0, lump: false, volume: false };

/// The scan's noise: the scatter of its points about a local quadric at four scales, the
/// surface's own departure from a quadric, which grows with the scale, separated from it (see
/// the module documentation), in the units of the points; for a scan as thick as its points
/// are far apart (a lump), the residual of the first wider neighbourhood thinner than
/// [`THIN`], if one is; 0 for fewer than 24 points or a scan with no neighbourhood that can be
/// fitted.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::noise::noise_estimate;
///
/// // A sphere of radius 1 sampled cleanly, and with Gaussian noise of σ = 0.01 along the
/// // normal (Box–Muller on a linear congruential sequence).
/// let n = 20_000;
/// let mut seed = 1u64;
/// let mut uniform = move || {
///     seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
///     ((seed >> 11) as f64 + 0.5) / (1u64 << 53) as f64
/// };
/// let mut points = |sigma: f64| -> Vec<DVec3> {
///     (0..n)
///         .map(|k| {
///             let z = 1.0 - (2 * k + 1) as f64 / n as f64;
///             let phi = k as f64 * 2.399_963_229_728_653;
///             let s = (1.0 - z * z).sqrt();
///             let (u, v) = (uniform(), uniform());
///             let gaussian = (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos();
///             DVec3::new(s * phi.cos(), s * phi.sin(), z) * (1.0 + sigma * gaussian)
///         })
///         .collect()
/// };
/// assert!(noise_estimate(&points(0.0)).sigma < 1e-5);
/// let noisy = noise_estimate(&points(0.01));
/// assert!((noisy.sigma - 0.01).abs() < 0.002 && !noisy.lump, "{noisy:?}");
/// // Noise of twice the points' spacing (about 0.025): a lump, its noise found at the wider
/// // scales.
/// let thick = noise_estimate(&points(0.05));
/// assert!((thick.sigma / 0.05 - 1.0).abs() < 0.1 && thick.lump, "{thick:?}");
/// ```
#[must_use]
pub fn noise_estimate(points: &[DVec3]) -> Noise {
    if points.len() < K || points.iter().any(|p| !p.is_finite()) {
        return NO_NOISE;
    }
    let Ok(tree): Result<ImmutableKdTree<f64, 3>, _> =
        ImmutableKdTree::new_from_slice(crate::distance::as_arrays(points))
    else {
        return NO_NOISE;
    };
    let step = points.len().div_ceil(SAMPLES).max(1);
    let samples: Vec<usize> = (0..points.len()).step_by(step).collect();
    let Some(small) = scatter_at(&tree, points, &samples, &SCALES) else {
        return NO_NOISE;
    };
    let scatter: [f64; SCALES.len()] = std::array::from_fn(|s| small[s].0);
    // Thickness, the residual over the radius: a lump of noise is as thick at every small
    // scale, or thinner at the larger; a clean curved surface grows thicker with the scale
    // (as r²: nine times from 8 to 24 neighbours at an even density).
    let thickness = |(residual, radius): (f64, f64)| residual / radius;
    let (first, last) = (thickness(small[0]), thickness(small[SCALES.len() - 1]));
    let small_scales = Noise { sigma: noise_from_scales(&scatter), ..NO_NOISE };
    if !(first > LUMPY && last > THIN && last <= LUMP * first) {
        return small_scales;
    }
    // As thick as the points are far apart: wider neighbourhoods, until one is thin. Points
    // that fill a volume (or noise so large that no surface shows through it) stay as thick
    // at every scale, or grow thicker again with the surface's curvature: their small scales'
    // estimate stands.
    let mut previous = small[SCALES.len() - 1];
    let mut tried = 0;
    for k in WIDER.into_iter().take_while(|&k| k <= points.len()) {
        let Some(wider) = scatter_at(&tree, points, &samples, &[k]) else { break };
        let wider = wider[0];
        if thickness(wider) <= THIN {
            return Noise { sigma: wider.0, lump: true, volume: false };
        }
        if thickness(wider) > THICKER * thickness(previous) {
            return small_scales;
        }
        previous = wider;
        tried += 1;
    }
    Noise { volume: tried > 0, ..small_scales }
}

/// For each k of `scales` (increasing), the median over the neighbourhoods of `samples` of the
/// corrected residual of the quadric fitted to the nearest k points, over the median of
/// √(χ²ᵥ/ν), and the median radius of those neighbourhoods; `None` if no neighbourhood can be
/// fitted.
fn scatter_at(
    tree: &ImmutableKdTree<f64, 3>,
    points: &[DVec3],
    samples: &[usize],
    scales: &[usize],
) -> Option<Vec<(f64, f64)>> {
    let k = NonZero::new(*scales.last()?)?;
    let fits: Vec<Vec<(f64, f64)>> = samples
        .par_iter()
        .filter_map(|&i| {
            let near =
                tree.query(&points[i].to_array()).nearest_n::<SquaredEuclidean<f64>>(k).execute();
            // Nearest first.
            let hood: Vec<DVec3> = near.iter().map(|n| points[n.item as usize]).collect();
            scales.iter().map(|&k| quadric_residual(hood.get(..k)?)).collect()
        })
        .collect();
    if fits.is_empty() {
        return None;
    }
    let mut column = vec![0.0; fits.len()];
    Some(
        (0..scales.len())
            .map(|s| {
                column.iter_mut().zip(&fits).for_each(|(c, fit)| *c = fit[s].0);
                let residual = median(&mut column) / chi_median_ratio(scales[s] - 6);
                column.iter_mut().zip(&fits).for_each(|(c, fit)| *c = fit[s].1);
                (residual, median(&mut column))
            })
            .collect(),
    )
}

/// σ from the median scatter sₖ at each of [`SCALES`]: the σ of the fit sₖ² = σ² + c kᵖ
/// (σ², c ≥ 0) with the least residual weighted by 1/sₖ², over p = 1, 1.25, …, 3; at most s₈.
fn noise_from_scales(scatter: &[f64; SCALES.len()]) -> f64 {
    let top = scatter.iter().copied().fold(0.0, f64::max);
    if scatter[0] <= 0.0 || !top.is_finite() {
        // A scatter of exactly 0 at the smallest scale: the points lie on quadrics.
        return 0.0;
    }
    // In units of the largest, so that the weights 1/sₖ² are of one size in any units.
    let s2: Vec<f64> = scatter.iter().map(|s| (s / top).powi(2)).collect();
    let mut best = (f64::INFINITY, 0.0);
    for step in 0..=8 {
        let p = 1.0 + 0.25 * f64::from(step);
        let kp: Vec<f64> = SCALES.iter().map(|&k| (k as f64).powf(p)).collect();
        // Weighted least squares for (σ², c), weights 1/sₖ², by the 2 × 2 normal equations;
        // a negative unknown is set to 0 and the other fitted alone.
        let (mut a11, mut a12, mut a22, mut b1, mut b2) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for (y, x) in s2.iter().zip(&kp) {
            let w = 1.0 / y;
            a11 += w;
            a12 += w * x;
            a22 += w * x * x;
            b1 += w * y;
            b2 += w * x * y;
        }
        let det = a11 * a22 - a12 * a12;
        let (mut sigma2, mut c) = ((b1 * a22 - b2 * a12) / det, (a11 * b2 - a12 * b1) / det);
        if !(det > 0.0 && sigma2.is_finite() && c.is_finite()) || c < 0.0 {
            (sigma2, c) = (b1 / a11, 0.0);
        }
        if sigma2 < 0.0 {
            (sigma2, c) = (0.0, b2 / a22);
        }
        let misfit: f64 = s2.iter().zip(&kp).map(|(y, x)| (sigma2 + c * x - y).powi(2) / y).sum();
        if misfit < best.0 {
            best = (misfit, sigma2);
        }
    }
    best.1.clamp(0.0, s2[0]).sqrt() * top
}

/// The median of `values` (reordered), which must not be empty.
fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// The median of √(χ²ᵥ/ν), the ratio of a sample's root mean square residual with ν degrees of
/// freedom to σ at its median, by the Wilson–Hilferty approximation of χ²ᵥ's median,
/// ν (1 − 2/(9ν))³.
fn chi_median_ratio(nu: usize) -> f64 {
    let nu = nu.max(1) as f64;
    (1.0 - 2.0 / (9.0 * nu)).powi(3).sqrt()
}

/// The corrected RMS residual of the least-squares quadric height field through `hood`, over
/// its principal plane, and the neighbourhood's radius (the farthest point from its centroid);
/// `None` if the fit is degenerate.
fn quadric_residual(hood: &[DVec3]) -> Option<(f64, f64)> {
    let n = hood.len();
    let centre = hood.iter().copied().sum::<DVec3>() / n as f64;
    let mut cov = DMat3::ZERO;
    for p in hood {
        let d = *p - centre;
        cov += DMat3::from_cols(d * d.x, d * d.y, d * d.z);
    }
    let normal = smallest_eigenvector(cov)?;
    let e1 = normal.any_orthonormal_vector();
    let e2 = normal.cross(e1);
    // In units of the neighbourhood's radius, so that the six columns are of one size whatever
    // the scan's units (see `implicit::fit_quadric`).
    let radius = hood.iter().map(|p| p.distance(centre)).fold(0.0, f64::max);
    if !(radius > 0.0 && radius.is_finite()) {
        return None;
    }
    // Normal equations of h = a + bx + cy + dx² + exy + fy², 6 × 6.
    let mut ata = [[0.0f64; 6]; 6];
    let mut atb = [0.0f64; 6];
    let mut rows = Vec::with_capacity(n);
    for p in hood {
        let d = (*p - centre) / radius;
        let (x, y, h) = (d.dot(e1), d.dot(e2), d.dot(normal));
        let r = [1.0, x, y, x * x, x * y, y * y];
        for i in 0..6 {
            for j in 0..6 {
                ata[i][j] += r[i] * r[j];
            }
            atb[i] += r[i] * h;
        }
        rows.push((r, h));
    }
    let coeffs = solve6(ata, atb)?;
    let ss: f64 = rows
        .iter()
        .map(|(r, h)| {
            let fit: f64 = r.iter().zip(&coeffs).map(|(a, b)| a * b).sum();
            (h - fit).powi(2)
        })
        .sum();
    Some((radius * (ss / (n as f64 - 6.0).max(1.0)).sqrt(), radius))
}

/// The unit eigenvector of the smallest eigenvalue of a symmetric 3 × 3 matrix, by inverse
/// iteration on the matrix shifted below its spectrum.
pub(crate) fn smallest_eigenvector(m: DMat3) -> Option<DVec3> {
    let scale = m
        .x_axis
        .abs()
        .max_element()
        .max(m.y_axis.abs().max_element())
        .max(m.z_axis.abs().max_element());
    if scale <= 0.0 || !scale.is_finite() {
        return None;
    }
    let shifted = m - DMat3::from_diagonal(DVec3::splat(-1e-9 * scale));
    if shifted.determinant().abs() <= f64::MIN_POSITIVE {
        return None;
    }
    let inv = shifted.inverse();
    let mut v = DVec3::new(0.577, 0.579, 0.575).normalize();
    for _ in 0..30 {
        let w = (inv * v).normalize_or_zero();
        if w == DVec3::ZERO {
            return None;
        }
        v = w;
    }
    Some(v)
}

/// Solves the 6 × 6 system by Gaussian elimination with partial pivoting.
pub(crate) fn solve6(mut a: [[f64; 6]; 6], mut b: [f64; 6]) -> Option<[f64; 6]> {
    let scale = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    for col in 0..6 {
        let pivot = (col..6).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs() <= 1e-12 * scale {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        let pivot_row = a[col];
        for row in col + 1..6 {
            let f = a[row][col] / pivot_row[col];
            for (x, p) in a[row][col..].iter_mut().zip(&pivot_row[col..]) {
                *x -= f * p;
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = [0.0; 6];
    for row in (0..6).rev() {
        let s: f64 = (row + 1..6).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    Some(x)
}
