// SPDX-License-Identifier: MIT
//! The quality of a flat map: its mean metric, L² stretch and efficiency (Sander, Snyder,
//! Gortler and Hoppe 2001; Praun and Hoppe 2003).

use glam::{DVec2, DVec3};
use hi_par::*;

use super::*;

/// The mean metric of a map: P = ∫ Jᵀ J over the (u, v) domain, J = (pᵤ, pᵥ), as
/// [P₁₁, P₁₂, P₂₂].
pub(crate) type Metric = [f64; 3];

/// Sums over a block of triangles for [`quality`](fn@quality).
#[derive(Clone, Copy)]
struct Sums {
    /// Surface area, (u, v) area, Σ A |pᵤ|², Σ A |pᵥ|² (A the surface area).
    area_p: f64,
    area_uv: f64,
    stretch_u: f64,
    stretch_v: f64,
    metric: Metric,
    lo: f64,
    hi: f64,
    folded: usize,
    flat: usize,
}

impl Sums {
    const ZERO: Self = Self {
        area_p: 0.0,
        area_uv: 0.0,
        stretch_u: 0.0,
        stretch_v: 0.0,
        metric: [0.0; 3],
        lo: f64::INFINITY,
        hi: 0.0,
        folded: 0,
        flat: 0,
    };

    fn add(&mut self, b: &Self) {
        self.area_p += b.area_p;
        self.area_uv += b.area_uv;
        self.stretch_u += b.stretch_u;
        self.stretch_v += b.stretch_v;
        for k in 0..3 {
            self.metric[k] += b.metric[k];
        }
        self.lo = self.lo.min(b.lo);
        self.hi = self.hi.max(b.hi);
        self.folded += b.folded;
        self.flat += b.flat;
    }
}

/// The quality of a map, measured on the domain scaled to its own image's shape (αu, v),
/// α = √(P₁₁/P₂₂) the aspect (an image of that shape has square texels, so the stretch
/// measures what is left of the map's anisotropy, and its area distortion), and its mean
/// metric. One pass: for each triangle Jᵀ J of its affine map from (u, v) to the surface, whose
/// stretch on the scaled domain is σ₁² + σ₂² = |pᵤ|²/α² + |pᵥ|²; sums per block of triangles,
/// the blocks added in order (the same result on any number of threads).
pub(crate) fn quality(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    map: &FlatMap,
    flat: Option<&[bool]>,
) -> (FlatQuality, Metric) {
    let area = |t: &[u32; 3]| {
        let [a, b, c] = t.map(|k| positions[k as usize]);
        0.5 * (b - a).cross(c - a).length()
    };
    let mean_area = triangles
        .par_chunks(BLOCK)
        .map(|ts| ts.iter().map(area).sum::<f64>())
        .collect::<Vec<f64>>()
        .iter()
        .sum::<f64>()
        / triangles.len().max(1) as f64;
    let blocks: Vec<Sums> = triangles
        .par_chunks(BLOCK)
        .enumerate()
        .map(|(blk, ts)| {
            let mut s = Sums::ZERO;
            for (o, t) in ts.iter().enumerate() {
                let f = blk * BLOCK + o;
                if flat.is_some_and(|m| m[f]) {
                    s.flat += 1;
                    continue;
                }
                let c = map.corners(triangles, f);
                let d = det(c);
                if d <= 0.0 {
                    s.folded += 1;
                    continue;
                }
                let ap = area(t);
                let m = metric_of(positions, t, c, d);
                s.area_p += ap;
                s.area_uv += 0.5 * d;
                s.stretch_u += ap * m[0];
                s.stretch_v += ap * m[2];
                for (acc, x) in s.metric.iter_mut().zip(m) {
                    *acc += 0.5 * d * x;
                }
                if ap > 1e-6 * mean_area {
                    let r = 0.5 * d / ap;
                    s.lo = s.lo.min(r);
                    s.hi = s.hi.max(r);
                }
            }
            s
        })
        .collect();
    let mut t = Sums::ZERO;
    for b in &blocks {
        t.add(b);
    }
    let alpha = aspect_of(t.metric);
    // E = Σ A (σ₁² + σ₂²)/2 on the scaled domain, whose area is α times the (u, v) area.
    let e = 0.5 * (t.stretch_u / (alpha * alpha) + t.stretch_v);
    let efficiency = if e > 0.0 && t.area_uv > 0.0 {
        (t.area_p * t.area_p / (alpha * t.area_uv) / e).min(1.0)
    } else {
        0.0
    };
    let shear = if t.metric[0] > 0.0 && t.metric[2] > 0.0 {
        t.metric[1] / (t.metric[0] * t.metric[2]).sqrt()
    } else {
        0.0
    };
    (
        FlatQuality {
            stretch_efficiency: efficiency,
            area_ratio: if t.lo > 0.0 { t.hi / t.lo } else { f64::INFINITY },
            folded_triangles: t.folded,
            flat_triangles: t.flat,
            shear,
        },
        t.metric,
    )
}

/// Jᵀ J = [|pᵤ|², pᵤ·pᵥ, |pᵥ|²] of the affine map from the plane triangle c (twice its signed
/// area d > 0) to the surface triangle t: with E = (c₁ − c₀, c₂ − c₀) and
/// Q = (p₁ − p₀, p₂ − p₀), J = Q E⁻¹ and Jᵀ J = E⁻ᵀ (Qᵀ Q) E⁻¹.
fn metric_of(positions: &[DVec3], t: &[u32; 3], c: [DVec2; 3], d: f64) -> Metric {
    let [pa, pb, pc] = t.map(|k| positions[k as usize]);
    let (e1, e2) = (c[1] - c[0], c[2] - c[0]);
    let (q1, q2) = (pb - pa, pc - pa);
    let g = [q1.dot(q1), q1.dot(q2), q2.dot(q2)];
    // The columns of E⁻¹ = (1/d) [[e2.y, −e2.x], [−e1.y, e1.x]].
    let m = [[e2.y / d, -e1.y / d], [-e2.x / d, e1.x / d]];
    let quad = |x: [f64; 2], y: [f64; 2]| {
        g[0] * x[0] * y[0] + g[1] * (x[0] * y[1] + x[1] * y[0]) + g[2] * x[1] * y[1]
    };
    [quad(m[0], m[0]), quad(m[0], m[1]), quad(m[1], m[1])]
}

/// (αu, v): a point of the domain scaled to the image's shape.
pub(super) fn scaled(p: DVec2, alpha: f64) -> DVec2 {
    DVec2::new(alpha * p.x, p.y)
}

/// rows / cols (or (rows − 1)/(cols − 1) for a whole-sample image) that makes texels square
/// on average: √(∫|pᵤ|² / ∫|pᵥ|²).
pub(crate) fn aspect_of(metric: Metric) -> f64 {
    if metric[0] > 0.0 && metric[2] > 0.0 { (metric[0] / metric[2]).sqrt() } else { 1.0 }
}
