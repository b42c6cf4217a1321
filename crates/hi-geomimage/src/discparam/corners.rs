// SPDX-License-Identifier: MIT
//! The four boundary vertices that go to the corners of the square (see the module
//! documentation of `discparam`), and the sides of the square a boundary vertex lies on.

use glam::DVec3;

/// The sides (a bit each, side m from corner m to corner m + 1) that loop position `rel`
/// (counted from corner 0) lies on, given the corners' positions.
pub(super) fn sides_of(rel: usize, corners: [usize; 4]) -> u8 {
    for (m, &c) in corners.iter().enumerate() {
        if rel == c {
            return (1 << m) | (1 << ((m + 3) % 4));
        }
    }
    let m = (0..4).rev().find(|&m| rel > corners[m]).unwrap_or(0);
    1 << m
}

/// The most checks of a dividing edge against a placement of the corners that
/// [`choose_corners`] makes (from every start up to this many divided by the dividing edges).
const CORNER_CHECKS: usize = 1 << 24;

/// For each vertex k of a boundary loop, `turning[k]` plus the turning at the vertices within
/// `reach` of it along the loop either way (by the arc lengths `s`, `s[b]` the loop's length;
/// fewer than half the loop's vertices each way; none for a negative `reach`): prefix sums and
/// windows that only move forward, so linear in the loop's length whatever the reach.
fn window_sums(turning: &[f64], s: &[f64], reach: f64) -> Vec<f64> {
    let b = turning.len();
    let total = s[b];
    // Over the loop twice: position i is vertex i mod b, at arc length `arc(i)`.
    let arc = |i: usize| if i < b { s[i] } else { s[i - b] + total };
    let mut acc = vec![0.0; 2 * b + 1];
    for i in 0..2 * b {
        acc[i + 1] = acc[i] + turning[i % b];
    }
    let most = (b / 2).saturating_sub(1);
    let (mut ahead, mut behind) = (0, 0);
    (0..b)
        .map(|k| {
            // The last position ahead of k, and the first behind it (as k + b), in reach.
            ahead = ahead.max(k);
            while ahead - k < most && arc(ahead + 1) - arc(k) <= reach {
                ahead += 1;
            }
            let back = k + b;
            behind = behind.max(back - most);
            while behind < back && arc(back) - arc(behind) > reach {
                behind += 1;
            }
            turning[k] + (acc[ahead + 1] - acc[k + 1]) + (acc[back] - acc[behind])
        })
        .collect()
}

/// The corners [`choose_corners`] tries after the evenly spaced ones: the four sharpest convex
/// windows of `corner` (each at the sharpest single `turning` within it), if each turns by 45°
/// or more and no side is shorter than L/8 or longer than 3L/8 (`s` the arc lengths).
fn sharpest_corners(corner: &[f64], turning: &[f64], s: &[f64]) -> Option<[usize; 4]> {
    let b = turning.len();
    let total = s[b];
    let apart = |j: usize, k: usize| {
        let d = (s[j] - s[k]).abs();
        d.min(total - d)
    };
    let mut order: Vec<usize> = (0..b).collect();
    order.sort_by(|&x, &y| corner[y].total_cmp(&corner[x]).then(x.cmp(&y)));
    let mut picked: Vec<usize> = Vec::with_capacity(4);
    for k in order {
        if picked.len() == 4 || corner[k] < std::f64::consts::FRAC_PI_4 {
            break;
        }
        if picked.iter().all(|&q| apart(k, q) > total / 16.0) {
            picked.push(k);
        }
    }
    // Each at the sharpest single turn of its window.
    for k in &mut picked {
        let centre = *k;
        *k = (0..b)
            .filter(|&j| apart(j, centre) <= total / 32.0)
            .max_by(|&x, &y| turning[x].total_cmp(&turning[y]).then(y.cmp(&x)))
            .unwrap_or(centre);
    }
    if picked.len() != 4 {
        return None;
    }
    picked.sort_unstable();
    picked.dedup();
    let sides_ok = picked.len() == 4
        && (0..4).all(|m| {
            let len = (s[picked[(m + 1) % 4]] - s[picked[m]]).rem_euclid(total);
            (total / 8.0..=3.0 * total / 8.0).contains(&len)
        });
    sides_ok.then(|| [picked[0], picked[1], picked[2], picked[3]])
}

/// The loop positions of the four corners (see the module documentation), or `None` if no
/// placement gives four distinct corners in order. `normals` holds the surface's normal at each
/// boundary vertex, in loop order, to tell convex corners (turning towards the surface) from
/// concave ones.
pub(super) fn choose_corners(
    positions: &[DVec3],
    ring: &[u32],
    normals: &[DVec3],
    dividing: &[(usize, usize)],
) -> Option<[usize; 4]> {
    let b = ring.len();
    let p = |k: usize| positions[ring[k % b] as usize];
    let mut s = vec![0.0; b + 1];
    for k in 0..b {
        s[k + 1] = s[k] + (p(k + 1) - p(k)).length();
    }
    let total = s[b];
    let measured = total.is_finite() && total > 0.0;
    // The signed turning at each vertex, summed over the vertices within L/32 along the
    // boundary (so that a corner cut by a short edge still counts whole, and jagged noise
    // cancels).
    let turning: Vec<f64> = (0..b)
        .map(|k| {
            let (a, c) = (p(k) - p(k + b - 1), p(k + 1) - p(k));
            let d = (a.length() * c.length()).max(f64::MIN_POSITIVE);
            let angle = (a.dot(c) / d).clamp(-1.0, 1.0).acos();
            if a.cross(c).dot(normals[k]) < 0.0 { -angle } else { angle }
        })
        .collect();
    let corner = window_sums(&turning, &s, if measured { total / 32.0 } else { -1.0 });
    let mut best: Option<(usize, f64, [usize; 4])> = None;
    let mut consider = |c: [usize; 4]| {
        let rel = c.map(|x| (x + b - c[0]) % b);
        if !(rel[1] > 0 && rel[1] < rel[2] && rel[2] < rel[3]) {
            return;
        }
        let bad = dividing
            .iter()
            .filter(|&&(x, y)| {
                sides_of((x + b - c[0]) % b, rel) & sides_of((y + b - c[0]) % b, rel) != 0
            })
            .count();
        let score: f64 = c.iter().map(|&k| corner[k]).sum();
        if best.is_none_or(|(bb, bs, _)| bad < bb || (bad == bb && score > bs)) {
            best = Some((bad, score, c));
        }
    };
    // Corners a quarter of the boundary apart, from every start.
    let nearest = |x: f64, start: usize, m: usize| -> usize {
        if !measured {
            return (start + m * b / 4) % b;
        }
        let x = x.rem_euclid(total);
        let k = s.partition_point(|&y| y <= x).saturating_sub(1).min(b - 1);
        if (x - s[k]) <= (s[k + 1] - x) { k } else { (k + 1) % b }
    };
    // Every placement is checked against every dividing edge: on a long boundary with many
    // (a ribbon two triangles wide has as many as it has vertices) only some starts, evenly
    // spaced, so that the check stays within CORNER_CHECKS.
    let starts = b.min((CORNER_CHECKS / dividing.len().max(1)).max(64));
    for start in (0..b).step_by(b.div_ceil(starts)) {
        let from = s[start];
        consider(std::array::from_fn(|m| {
            if m == 0 { start } else { nearest(from + total * m as f64 / 4.0, start, m) }
        }));
    }
    // The four sharpest convex corners, if each turns by 45° or more and no side is shorter
    // than L/8 or longer than 3L/8.
    if measured && let Some(picked) = sharpest_corners(&corner, &turning, &s) {
        consider(picked);
    }
    best.map(|x| x.2)
}
