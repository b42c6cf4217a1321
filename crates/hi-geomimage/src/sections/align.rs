// SPDX-License-Identifier: MIT
//! Step 7 of algorithm 1: each contour turned against the one below for the least total
//! deviation (Theorem 5.1).

use glam::DVec3;
use hi_curve::HarmonicCurve;

use super::Alignment;
use crate::Error;

/// Step 7 for every section: the rows of the grid, each inserted contour turned against the
/// row below it, and the offsets.
pub(super) fn rotate_rows(
    inserted: &[HarmonicCurve<DVec3>],
    alignment: Alignment,
) -> Result<(Vec<Vec<DVec3>>, Vec<f64>), Error> {
    let k = inserted.len();
    let mut rows: Vec<Vec<DVec3>> = Vec::with_capacity(k);
    let mut rotations = Vec::with_capacity(k);
    for curve in inserted {
        let (offset, row) = match rows.last() {
            None => (0.0, curve.points().to_vec()),
            Some(below) => align(curve, below, alignment)?,
        };
        rotations.push(offset);
        rows.push(row);
    }
    Ok((rows, rotations))
}

/// Σⱼ |aⱼ − bⱼ|².
pub(super) fn squared_deviation(a: &[DVec3], b: &[DVec3]) -> f64 {
    a.iter().zip(b).map(|(p, q)| p.distance_squared(*q)).sum()
}

/// Turns `curve` (N points) against the contour `below` (N points) for the least squared
/// deviation: the offset in [0, 1) and the turned points X(j/N + o) (Theorem 5.1).
fn align(
    curve: &HarmonicCurve<DVec3>,
    below: &[DVec3],
    alignment: Alignment,
) -> Result<(f64, Vec<DVec3>), Error> {
    let n = curve.n();
    let x = curve.points();
    if alignment == Alignment::None {
        return Ok((0.0, x.to_vec()));
    }
    // Whole steps: D(s/N) = Σⱼ |x_{j+s} − bⱼ|².
    let step_deviation =
        |s: usize| -> f64 { (0..n).map(|j| x[(j + s) % n].distance_squared(below[j])).sum() };
    let best_step = (0..n)
        .map(|s| (step_deviation(s), s))
        .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)))
        .map_or(0, |(_, s)| s);
    let mut offset = best_step as f64 / n as f64;
    if alignment == Alignment::Continuous {
        // D(o) = Σⱼ |X(j/N + o) − bⱼ|², a trigonometric polynomial in o, over a step either side.
        let fourier = curve.fourier();
        let deviation =
            |o: f64| -> f64 { squared_deviation(&fourier.shifted(o).sample_uniform(n), below) };
        let step = 1.0 / n as f64;
        let (mut a, mut b) = (offset - step, offset + step);
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        let (mut c, mut d) = (b - ratio * (b - a), a + ratio * (b - a));
        let (mut fc, mut fd) = (deviation(c), deviation(d));
        for _ in 0..60 {
            if fc < fd {
                (b, d, fd) = (d, c, fc);
                c = b - ratio * (b - a);
                fc = deviation(c);
            } else {
                (a, c, fc) = (c, d, fd);
                d = a + ratio * (b - a);
                fd = deviation(d);
            }
            if b - a < 1e-12 {
                break;
            }
        }
        let refined = 0.5 * (a + b);
        if deviation(refined) < step_deviation(best_step) {
            offset = refined;
        }
    }
    let offset = offset.rem_euclid(1.0);
    let turned = curve.rotate_theorem_5_1(offset).map_err(Error::from)?;
    Ok((offset, turned.points().to_vec()))
}
