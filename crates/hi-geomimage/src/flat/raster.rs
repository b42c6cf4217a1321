// SPDX-License-Identifier: MIT
//! The rasteriser that samples a geometry image from a flat map.

use glam::{DVec2, DVec3};
use hi_par::*;

use super::*;

/// The geometry image of a map: texel (i, j) is the surface point at
/// (u, v) = (i / su, j / sv), with su = rows, sv = cols on the torus (`periodic`, indices
/// wrapping) and su = rows − 1, sv = cols − 1 on the square. Each texel takes the triangle in
/// which it lies deepest (the largest smallest barycentric coordinate; on an edge or vertex
/// the lower triangle index among equals), so every texel is covered exactly once whatever
/// the rounding; barycentric interpolation of the positions.
#[expect(clippy::too_many_arguments, reason = "one private helper of two public callers")]
pub(crate) fn rasterise(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    filled: &[bool],
    map: &FlatMap,
    skip: Option<&[bool]>,
    rows: usize,
    cols: usize,
    periodic: bool,
) -> Result<FlatImage, Error> {
    crate::image::check_resolution(rows, cols)?;
    let (su, sv) =
        if periodic { (rows as f64, cols as f64) } else { ((rows - 1) as f64, (cols - 1) as f64) };
    let texel_corners =
        |f: usize| map.corners(triangles, f).map(|c| DVec2::new(c.x * su, c.y * sv));
    let buckets = row_buckets(triangles, skip, &texel_corners, rows, periodic);
    let point = |f: usize, l: [f64; 3]| {
        let l = l.map(|x| x.max(0.0));
        let s = l[0] + l[1] + l[2];
        let l = if s > 0.0 { l.map(|x| x / s) } else { [1.0 / 3.0; 3] };
        let t = triangles[f];
        positions[t[0] as usize] * l[0]
            + positions[t[1] as usize] * l[1]
            + positions[t[2] as usize] * l[2]
    };
    let rows_out: Vec<Vec<(f64, u32, [f64; 3])>> = (0..rows)
        .into_par_iter()
        .map(|r| best_in_row(&buckets[r], &texel_corners, cols, periodic))
        .collect();
    let mut texels = Vec::with_capacity(rows * cols);
    let mut flags = Vec::with_capacity(rows * cols);
    for (i, row) in rows_out.iter().enumerate() {
        for (j, &(_, f, l)) in row.iter().enumerate() {
            let (f, l) = if f == NONE {
                // Only a map that does not cover its domain leaves a texel to this.
                nearest(
                    triangles,
                    &texel_corners,
                    skip,
                    DVec2::new(i as f64, j as f64),
                    periodic.then_some((su, sv)),
                    &barycentric,
                )
            } else {
                (f as usize, l)
            };
            texels.push(point(f, l));
            flags.push(filled.get(f).copied().unwrap_or(false));
        }
    }
    let filled_fraction = flags.iter().filter(|&&x| x).count() as f64 / flags.len() as f64;
    Ok(FlatImage {
        image: GeometryImage::try_new(rows, cols, texels)?,
        filled: flags,
        filled_fraction,
    })
}

/// The first stage of [`rasterise`]: each triangle (not skipped, not folded) in the bucket of
/// every row it may touch, with that row's unwrapped index.
fn row_buckets(
    triangles: &[[u32; 3]],
    skip: Option<&[bool]>,
    texel_corners: &dyn Fn(usize) -> [DVec2; 3],
    rows: usize,
    periodic: bool,
) -> Vec<Vec<(u32, i64)>> {
    let ri = rows as i64;
    let mut buckets: Vec<Vec<(u32, i64)>> = vec![Vec::new(); rows];
    for f in 0..triangles.len() {
        if skip.is_some_and(|m| m[f]) {
            continue;
        }
        let c = texel_corners(f);
        if cross(c[1] - c[0], c[2] - c[0]) <= 0.0 {
            continue;
        }
        let lo = c.iter().map(|p| p.x).fold(f64::INFINITY, f64::min).floor() as i64;
        let hi = c.iter().map(|p| p.x).fold(f64::NEG_INFINITY, f64::max).ceil() as i64;
        let (lo, hi) =
            if periodic { (lo, hi.min(lo + ri - 1)) } else { (lo.max(0), hi.min(ri - 1)) };
        for i in lo..=hi {
            buckets[i.rem_euclid(ri) as usize].push((f as u32, i));
        }
    }
    buckets
}

/// The barycentric coordinates of p in the triangle c.
fn barycentric(c: &[DVec2; 3], p: DVec2) -> [f64; 3] {
    let d = cross(c[1] - c[0], c[2] - c[0]);
    [cross(c[1] - p, c[2] - p) / d, cross(c[2] - p, c[0] - p) / d, cross(c[0] - p, c[1] - p) / d]
}

/// The second stage of [`rasterise`], one row: for each texel of the row the triangle of its
/// `bucket` in which it lies deepest (score, triangle or [`NONE`], barycentric coordinates).
fn best_in_row(
    bucket: &[(u32, i64)],
    texel_corners: &dyn Fn(usize) -> [DVec2; 3],
    cols: usize,
    periodic: bool,
) -> Vec<(f64, u32, [f64; 3])> {
    let ci = cols as i64;
    let mut best = vec![(f64::NEG_INFINITY, NONE, [0.0; 3]); cols];
    for &(f, i) in bucket {
        let c = texel_corners(f as usize);
        let x = i as f64;
        // The triangle's extent along the row's line, one texel wider each way.
        let (mut ylo, mut yhi) = (f64::INFINITY, f64::NEG_INFINITY);
        for k in 0..3 {
            let (p, q) = (c[k], c[(k + 1) % 3]);
            if (p.x - x) * (q.x - x) <= 0.0 {
                let y = if p.x == q.x {
                    p.y.min(q.y)
                } else {
                    p.y + (x - p.x) / (q.x - p.x) * (q.y - p.y)
                };
                let y2 = if p.x == q.x { p.y.max(q.y) } else { y };
                ylo = ylo.min(y);
                yhi = yhi.max(y2);
            }
        }
        if ylo > yhi {
            ylo = c.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
            yhi = c.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
        }
        let lo = ylo.floor() as i64 - 1;
        let hi = yhi.ceil() as i64 + 1;
        let (lo, hi) =
            if periodic { (lo, hi.min(lo + ci - 1)) } else { (lo.max(0), hi.min(ci - 1)) };
        for j in lo..=hi {
            let l = barycentric(&c, DVec2::new(x, j as f64));
            let score = l[0].min(l[1]).min(l[2]);
            let slot = &mut best[j.rem_euclid(ci) as usize];
            if score > slot.0 || (score == slot.0 && f < slot.1) {
                *slot = (score, f, l);
            }
        }
    }
    best
}

/// The triangle in which p lies deepest, over all triangles (translating p by whole periods
/// to the nearest copy on the torus).
fn nearest(
    triangles: &[[u32; 3]],
    texel_corners: &dyn Fn(usize) -> [DVec2; 3],
    skip: Option<&[bool]>,
    p: DVec2,
    periods: Option<(f64, f64)>,
    barycentric: &dyn Fn(&[DVec2; 3], DVec2) -> [f64; 3],
) -> (usize, [f64; 3]) {
    let mut best = (f64::NEG_INFINITY, 0usize, [1.0 / 3.0; 3]);
    for f in 0..triangles.len() {
        if skip.is_some_and(|m| m[f]) {
            continue;
        }
        let c = texel_corners(f);
        if cross(c[1] - c[0], c[2] - c[0]) <= 0.0 {
            continue;
        }
        let mut q = p;
        if let Some((su, sv)) = periods {
            let centre = (c[0] + c[1] + c[2]) / 3.0;
            q.x += ((centre.x - q.x) / su).round() * su;
            q.y += ((centre.y - q.y) / sv).round() * sv;
        }
        let l = barycentric(&c, q);
        let score = l[0].min(l[1]).min(l[2]);
        if score > best.0 {
            best = (score, f, l);
        }
    }
    (best.1, best.2)
}
