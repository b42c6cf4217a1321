// SPDX-License-Identifier: MIT
//! What a conversion achieves: the tensor-product bound of the deviation, the deviation
//! measured on samples, and the normal jumps across patch edges.

use glam::DVec3;
use hi_bezier::{Aabb, BezierPatch, ControlPoint};
use hi_curve::bezier::BezierScheme;

use super::{SAMPLES_PER_SIDE, SurfaceBezier};
use crate::{Error, HarmonicSurface};

/// The tensor-product bound of a scheme on a surface (see the module documentation): the
/// scheme's remainder (c, r) and the spectral bounds Mᵤ, Mᵥ, Mᵤᵥ of ‖∂ᵤʳp‖, ‖∂ᵥʳp‖, ‖∂ᵤʳ∂ᵥʳp‖,
/// computed once.
pub(super) struct TensorBound {
    c: f64,
    r: i32,
    mu: f64,
    mv: f64,
    muv: f64,
}

impl TensorBound {
    pub(super) fn new<P: ControlPoint>(surface: &HarmonicSurface<P>, scheme: BezierScheme) -> Self {
        let (c, r) = scheme.remainder();
        let (mu, mv, muv) =
            (surface.deriv_bound(r, 0), surface.deriv_bound(0, r), surface.deriv_bound(r, r));
        Self { c, r: r as i32, mu, mv, muv }
    }

    /// On patches of 1/nᵤ × 1/nᵥ: the u term c·hᵤʳ·Mᵤ, the v term, and the whole bound (with a
    /// relative margin of 1e-9 for rounding).
    pub(super) fn on(&self, nu: usize, nv: usize) -> (f64, f64, f64) {
        let (hu, hv) = ((nu as f64).recip().powi(self.r), (nv as f64).recip().powi(self.r));
        let (eu, ev) = (self.c * hu, self.c * hv);
        let (tu, tv) = (eu * self.mu, ev * self.mv);
        (tu, tv, (tu + tv + eu * ev * self.muv) * (1.0 + 1e-9))
    }
}

impl<P: ControlPoint> HarmonicSurface<P> {
    /// Largest and RMS distance between the surface and the patches on every patch's
    /// (k + 1)² parameters, k = [`SAMPLES_PER_SIDE`] (half that beyond 2¹⁴ patches), the
    /// surface sampled by separable basis matrices.
    pub(super) fn measure(&self, b: &SurfaceBezier<P>) -> Result<(f64, f64), Error> {
        let k = if b.patches.len() > 1 << 14 { SAMPLES_PER_SIDE / 2 } else { SAMPLES_PER_SIDE };
        let params = |breaks: &[f64]| -> Vec<f64> {
            breaks
                .windows(2)
                .flat_map(|w| (0..=k).map(move |i| w[0] + (w[1] - w[0]) * i as f64 / k as f64))
                .collect()
        };
        let nv = b.v_breaks.len() - 1;
        // Patch (a, c) at (i/k, j/k), from the uniform grid by FFT when the breaks are
        // uniform, else from the separable sums at the parameters themselves.
        let on: Box<dyn Fn(usize, usize, usize, usize) -> P> =
            match (uniform_pieces(&b.u_breaks), uniform_pieces(&b.v_breaks)) {
                (Some(pu), Some(pv)) => {
                    let (ru, rv) = (pu * k, pv * k);
                    let grid = self.sample_uniform(ru, rv, 0, 0)?;
                    Box::new(move |a, c, i, j| {
                        grid.values[((a * k + i) % ru) * rv + (c * k + j) % rv]
                    })
                }
                _ => {
                    let (us, vs) = (params(&b.u_breaks), params(&b.v_breaks));
                    let samples = self.sample_params(&us, &vs, 0, 0)?;
                    Box::new(move |a, c, i, j| samples.get(a * (k + 1) + i, c * (k + 1) + j))
                }
            };
        let (mut max, mut sum, mut count) = (0.0_f64, 0.0, 0_usize);
        let local: Vec<f64> = (0..=k).map(|i| i as f64 / k as f64).collect();
        for (idx, patch) in b.patches.iter().enumerate() {
            let (a, c) = (idx / nv, idx % nv);
            let values = patch.eval_grid(&local, &local);
            for i in 0..=k {
                for j in 0..=k {
                    let d = (values[i * (k + 1) + j] - on(a, c, i, j)).norm();
                    max = max.max(d);
                    sum += d * d;
                    count += 1;
                }
            }
        }
        Ok((max, (sum / count.max(1) as f64).sqrt()))
    }
}

/// The number of pieces if `breaks` are the uniform 0, 1/p, …, 1 (to rounding), else `None`.
pub(super) fn uniform_pieces(breaks: &[f64]) -> Option<usize> {
    let p = breaks.len().checked_sub(1).filter(|&p| p > 0)?;
    breaks
        .iter()
        .enumerate()
        .all(|(i, &x)| (x - i as f64 / p as f64).abs() <= 4.0 * f64::EPSILON)
        .then_some(p)
}

/// The angle between unit vectors, accurate near 0.
pub(super) fn angle(a: DVec3, b: DVec3) -> f64 {
    2.0 * (a - b).length().atan2((a + b).length())
}

/// The largest normal jump across the edges between neighbouring patches (both directions,
/// wrapping around), sampled at `SAMPLES_PER_SIDE + 1` points per edge; 0 for points that are
/// not 3-D.
///
/// On an edge u = 0 or 1 a patch's partials are curves of its boundary rows: ∂p/∂v is the
/// derivative of the boundary row and ∂p/∂u is m times the difference of the last two rows
/// (§4.3), so the normals along every edge come from Bernstein tables at the sample points
/// shared by all patches of one degree.
pub(super) fn max_normal_jump<P: ControlPoint>(b: &SurfaceBezier<P>) -> f64 {
    if P::DIM != 3 {
        return 0.0;
    }
    let (nu, nv) = (b.u_breaks.len() - 1, b.v_breaks.len() - 1);
    let patch = |a: usize, c: usize| &b.patches[(a % nu) * nv + (c % nv)];
    let mut worst: f64 = 0.0;
    let mut tables = EdgeTables::default();
    for a in 0..nu {
        for c in 0..nv {
            let here = patch(a, c);
            // The edge u = end of patch a, between (a, c) and (a + 1, c).
            let (l, r) =
                (tables.normals(here, Edge::UEnd), tables.normals(patch(a + 1, c), Edge::UStart));
            // The edge v = end of patch c, between (a, c) and (a, c + 1).
            let (lv, rv) =
                (tables.normals(here, Edge::VEnd), tables.normals(patch(a, c + 1), Edge::VStart));
            for (x, y) in l.iter().zip(&r).chain(lv.iter().zip(&rv)) {
                if let (Some(x), Some(y)) = (x, y) {
                    worst = worst.max(angle(*x, *y));
                }
            }
        }
    }
    worst
}

/// A side of a patch's parameter square.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Edge {
    /// u = 0.
    UStart,
    /// u = 1.
    UEnd,
    /// v = 0.
    VStart,
    /// v = 1.
    VEnd,
}

/// Bernstein values and first derivatives at the edge samples i/`SAMPLES_PER_SIDE`, by degree.
#[derive(Default)]
struct EdgeTables {
    by_degree: Vec<DegreeTable>,
}

/// The tables of one degree.
struct DegreeTable {
    degree: usize,
    /// `values[sample][i]`: Bᵢ at the sample.
    values: Vec<Vec<f64>>,
    /// `derivs[sample][i]`: Bᵢ′ at the sample.
    derivs: Vec<Vec<f64>>,
}

impl EdgeTables {
    /// The tables of `degree`, made on first use.
    fn get(&mut self, degree: usize) -> (&[Vec<f64>], &[Vec<f64>]) {
        let at = match self.by_degree.iter().position(|t| t.degree == degree) {
            Some(at) => at,
            None => {
                let basis = hi_bezier::Bernstein::new(degree);
                let xs = (0..=SAMPLES_PER_SIDE).map(|i| i as f64 / SAMPLES_PER_SIDE as f64);
                let values = xs.clone().map(|x| basis.values(x)).collect();
                let derivs = xs.map(|x| basis.derivs(x, 1)).collect();
                self.by_degree.push(DegreeTable { degree, values, derivs });
                self.by_degree.len() - 1
            }
        };
        let table = &self.by_degree[at];
        (&table.values, &table.derivs)
    }

    /// The unit normals pᵤ × pᵥ along `edge` of `patch` at the samples (`None` where the
    /// partials are parallel).
    fn normals<P: ControlPoint>(
        &mut self,
        patch: &BezierPatch<P>,
        edge: Edge,
    ) -> Vec<Option<DVec3>> {
        let (du, dv) = (patch.degree_u(), patch.degree_v());
        let x = |j: usize, k: usize| {
            let p = patch.control_point(j, k).unwrap_or(P::ZERO);
            DVec3::new(p.coord(0), p.coord(1), p.coord(2))
        };
        // The boundary line and its neighbour inside, with the degree across the edge and the
        // sign that makes the difference a derivative in increasing parameter.
        let (along, line, inner, across, sign): (usize, Vec<DVec3>, Vec<DVec3>, usize, f64) =
            match edge {
                Edge::UStart => (
                    dv,
                    (0..=dv).map(|k| x(0, k)).collect(),
                    (0..=dv).map(|k| x(1.min(du), k)).collect(),
                    du,
                    -1.0,
                ),
                Edge::UEnd => (
                    dv,
                    (0..=dv).map(|k| x(du, k)).collect(),
                    (0..=dv).map(|k| x(du.saturating_sub(1), k)).collect(),
                    du,
                    1.0,
                ),
                Edge::VStart => (
                    du,
                    (0..=du).map(|j| x(j, 0)).collect(),
                    (0..=du).map(|j| x(j, 1.min(dv))).collect(),
                    dv,
                    -1.0,
                ),
                Edge::VEnd => (
                    du,
                    (0..=du).map(|j| x(j, dv)).collect(),
                    (0..=du).map(|j| x(j, dv.saturating_sub(1))).collect(),
                    dv,
                    1.0,
                ),
            };
        let (values, derivs) = self.get(along);
        values
            .iter()
            .zip(derivs)
            .map(|(w, dw)| {
                // The derivative along the edge, and the one across it.
                let d_along = line.iter().zip(dw).fold(DVec3::ZERO, |acc, (p, w)| acc + *p * *w);
                let d_across = line
                    .iter()
                    .zip(&inner)
                    .zip(w)
                    .fold(DVec3::ZERO, |acc, ((p, q), w)| acc + (*p - *q) * *w)
                    * (sign * across as f64);
                let (pu, pv) = match edge {
                    Edge::UStart | Edge::UEnd => (d_across, d_along),
                    Edge::VStart | Edge::VEnd => (d_along, d_across),
                };
                pu.cross(pv).try_normalize()
            })
            .collect()
    }
}

/// The diagonal of the bounding box of `points` (0 for none).
pub(super) fn bounding_diagonal<P: ControlPoint>(points: &[P]) -> f64 {
    Aabb::from_points(points).map_or(0.0, |b| b.size().norm())
}
