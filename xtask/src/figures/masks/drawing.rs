// SPDX-License-Identifier: MIT
//! Drawing a mask: each weight (a fraction where one matches) beside its vertex, clear of
//! the edges.

use std::f64::consts::PI;

use anyhow::Result;
use glam::DVec2;

use super::super::plot::{BLUE, GREY, INK, Marker, Pen, Plot, VERMILION, clear_of_point};
use super::TOL;
use super::library::Mask;

/// `w` as a fraction p/q (q ≤ 1000) if one matches it to [`TOL`], otherwise to four decimals;
/// a minus sign for negative values.
pub(super) fn fraction(w: f64) -> String {
    let text = (1..=1000_u32)
        .find_map(|q| {
            let p = (w * f64::from(q)).round();
            ((w - p / f64::from(q)).abs() <= TOL)
                .then(|| if q == 1 { format!("{}", p.abs()) } else { format!("{}/{q}", p.abs()) })
        })
        .unwrap_or_else(|| format!("{:.4}", w.abs()));
    if w < 0.0 && text != "0" { format!("−{text}") } else { text }
}

/// Draws a mask: the stencil's edges and vertices, the new point ringed in red, each weight
/// beside its vertex (blue, red if negative, grey if zero).
pub(super) fn draw_mask(title: &str, mask: Result<Mask>) -> Result<Vec<u8>> {
    let mask = mask?;
    let mut plot = Plot::projection(title);
    for [a, b] in &mask.edges {
        plot = plot.curve(vec![*a, *b], Pen::solid(GREY).width(1.0), None);
    }
    plot = plot.points(&mask.at, Marker::point(INK), None).points(
        &[mask.new_point],
        Marker::ring(VERMILION),
        None,
    );
    let centre = mask.at.iter().sum::<DVec2>() / mask.at.len() as f64;
    for (p, &w) in mask.at.iter().zip(&mask.weights) {
        let text = fraction(w);
        // Outward from the stencil's centre (up and right for the centre itself), clear of
        // the vertex's marker (y up here, down on the screen).
        let size = mask.at.iter().map(|q| q.distance(centre)).fold(0.0, f64::max);
        let away = *p - centre;
        let offset = if away.length() > 1e-6 * size {
            let d = away.normalize();
            let off = clear_of_point(DVec2::new(d.x, -d.y), text.chars().count());
            (off.x, -off.y)
        } else {
            // The centre: inside the widest angle between its edges, clear of both.
            let (d, half_angle) = widest_gap(&mask.edges, *p);
            let off = d * inside_wedge(d, half_angle, text.chars().count());
            (off.x, off.y)
        };
        let color = if w.abs() <= TOL {
            GREY
        } else if w < 0.0 {
            VERMILION
        } else {
            BLUE
        };
        plot = plot.note(*p, &text, offset, color);
    }
    plot.render()
}

/// The direction from `p` into the widest angle between the edges of `edges` that end at
/// `p`, and half that angle (up and right, a right angle, if no edge does): where a label at
/// `p` crosses no edge.
fn widest_gap(edges: &[[DVec2; 2]], p: DVec2) -> (DVec2, f64) {
    let mut angles: Vec<f64> = edges
        .iter()
        .filter_map(|[a, b]| {
            let scale = 1e-9 * (1.0 + a.length() + b.length());
            if a.distance(p) < scale {
                Some(*b - p)
            } else if b.distance(p) < scale {
                Some(*a - p)
            } else {
                None
            }
        })
        .map(|d| d.y.atan2(d.x))
        .collect();
    angles.sort_by(f64::total_cmp);
    let Some(&first) = angles.first() else { return (DVec2::new(0.6, 0.8), 0.5 * PI) };
    let mut best = (0.0, 0.0);
    for (k, &a) in angles.iter().enumerate() {
        let next = angles.get(k + 1).copied().unwrap_or(first + 2.0 * PI);
        if next - a > best.0 {
            best = (next - a, a + 0.5 * (next - a));
        }
    }
    (DVec2::from_angle(best.1), 0.5 * best.0)
}

/// How far in pixels along `dir` (y up) a label of `chars` characters goes so that its box
/// (as in [`clear_of_point`]) lies inside the wedge of half-angle `half_angle` about `dir`.
fn inside_wedge(dir: DVec2, half_angle: f64, chars: usize) -> f64 {
    let (half_w, half_h) = (3.75 * chars as f64 + 2.0, 8.0);
    let tan = half_angle.min(0.49 * PI).tan();
    let fits = |s: f64| {
        [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)].iter().all(|&(a, b)| {
            let corner = dir * s + DVec2::new(a * half_w, b * half_h);
            corner.dot(dir) > 0.0 && corner.perp_dot(dir).abs() <= tan * corner.dot(dir)
        })
    };
    let start = clear_of_point(dir, chars).length();
    (0..200).map(|k| start + 0.5 * f64::from(k)).find(|&s| fits(s)).unwrap_or(start + 100.0)
}
