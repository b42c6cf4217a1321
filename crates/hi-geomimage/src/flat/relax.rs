// SPDX-License-Identifier: MIT
//! The stretch relaxation of a flat map (Yoshizawa, Belyaev and Seidel 2004, then Newton moves
//! of single vertices with the stretch as a barrier).

use glam::{DVec2, DVec3};
use hi_par::*;

use super::quality::scaled;
use super::*;

/// N = ℓ₁ (b − a)·(c − a) + ℓ₂ (c − b)·(a − b) + ℓ₃ (a − c)·(b − c): with d = (b − a) × (c − a),
/// N / d² = σ₁² + σ₂² of the affine map from the plane triangle abc to a surface triangle
/// whose squared edge lengths opposite a, b, c are ℓ₁, ℓ₂, ℓ₃ (the cotangent formula).
pub(super) fn stretch_numerator(a: DVec2, b: DVec2, c: DVec2, l2: [f64; 3]) -> f64 {
    l2[0] * (b - a).dot(c - a) + l2[1] * (c - b).dot(a - b) + l2[2] * (a - c).dot(b - c)
}

/// The stretch energy ½ A N / d² of one triangle (see [`stretch_numerator`]) with its corner a
/// free, ∞ if the triangle is not wound counter-clockwise: a barrier against folds.
pub(super) fn face_energy(a: DVec2, b: DVec2, c: DVec2, area: f64, l2: [f64; 3]) -> f64 {
    let d = cross(b - a, c - a);
    if d <= 0.0 {
        return f64::INFINITY;
    }
    0.5 * area * stretch_numerator(a, b, c, l2) / (d * d)
}

/// [`face_energy`], its gradient and Hessian ([h₁₁, h₁₂, h₂₂]) with respect to a.
pub(super) fn face_energy_grad(
    a: DVec2,
    b: DVec2,
    c: DVec2,
    area: f64,
    l2: [f64; 3],
) -> (f64, DVec2, [f64; 3]) {
    let d = cross(b - a, c - a);
    if d <= 0.0 {
        return (f64::INFINITY, DVec2::ZERO, [0.0; 3]);
    }
    let num = stretch_numerator(a, b, c, l2);
    // ∇N = ℓ₁(2a − b − c) + (ℓ₂ − ℓ₃)(c − b), ∇²N = 2ℓ₁ I; d = a×b + b×c + c×a, so
    // ∇d = (b_y − c_y, c_x − b_x), ∇²d = 0.
    let dn = l2[0] * (2.0 * a - b - c) + (l2[1] - l2[2]) * (c - b);
    let dd = DVec2::new(b.y - c.y, c.x - b.x);
    let (i2, i3, i4) = (1.0 / (d * d), 1.0 / (d * d * d), 1.0 / (d * d * d * d));
    let k = 0.5 * area;
    let e = k * num * i2;
    let g = k * (dn * i2 - 2.0 * num * i3 * dd);
    // ∇²(N/d²) = 2ℓ₁ I/d² − 2(∇N ∇dᵀ + ∇d ∇Nᵀ)/d³ + 6 N ∇d ∇dᵀ/d⁴.
    let h = [
        k * (2.0 * l2[0] * i2 - 4.0 * dn.x * dd.x * i3 + 6.0 * num * dd.x * dd.x * i4),
        k * (-2.0 * (dn.x * dd.y + dd.x * dn.y) * i3 + 6.0 * num * dd.x * dd.y * i4),
        k * (2.0 * l2[0] * i2 - 4.0 * dn.y * dd.y * i3 + 6.0 * num * dd.y * dd.y * i4),
    ];
    (e, g, h)
}

/// How a vertex may move during the relaxation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Freedom {
    /// Anywhere (keeping its triangles wound counter-clockwise).
    Free,
    /// Along coordinate `axis` only, strictly between the values of `axis` at vertices `a`
    /// and `b` (its neighbours along a side of the square).
    Slide { axis: usize, a: u32, b: u32 },
    /// Not at all.
    Fixed,
}

/// The data of the relaxation.
pub(crate) struct Relaxation<'a> {
    pub(crate) positions: &'a [DVec3],
    pub(crate) triangles: &'a [[u32; 3]],
    pub(crate) topology: &'a Topology,
    pub(crate) freedom: Vec<Freedom>,
    /// Triangles left out of the energy (laid flat on a side).
    pub(crate) flat: Option<&'a [bool]>,
    /// Surface area (floored) and squared edge lengths of each triangle.
    area: Vec<f64>,
    l2: Vec<[f64; 3]>,
}

/// Settings of [`Relaxation::run`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct RelaxOptions {
    pub(crate) rounds: usize,
    pub(crate) sweeps: usize,
    pub(crate) cg: CgOptions,
    /// The iterations the harmonic map's solve took (see [`relaxation_budget`]).
    pub(crate) harmonic_iterations: usize,
}

/// What the relaxation did.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RelaxReport {
    pub(crate) rounds: usize,
    pub(crate) end: RoundsEnd,
    pub(crate) sweeps: usize,
    pub(crate) iterations: usize,
    pub(crate) residual: Option<f64>,
}

/// A reweighting round that raises the stretch efficiency by less than this fraction is the
/// last: the rounds have about converged, and the next one tends to overshoot (on the tori of
/// the tests the third round lowers the efficiency again).
const SMALL_GAIN: f64 = 0.02;

/// The relative residual the reweighting rounds solve to (or the caller's, if looser): each
/// round's map only guides the next weights, and is checked for folds before it is kept.
const ROUND_TOLERANCE: f64 = 1e-5;

/// The reweighting rounds' solves together may take this many times the iterations of the
/// harmonic map's solve ([`RELAXATION_BUDGET_MIN`] at least). A round's solve is warm-started,
/// to a looser tolerance, with a hierarchy built for its own weights: on the meshes of the
/// tests all the rounds together take from a tenth to once the harmonic solve's iterations;
/// on the zero sets of scans, whose long thin parts the map squeezes so much that their
/// triangles fold until the solve is pushed to 10⁻⁹ or 10⁻¹³, two to five times.
const RELAXATION_BUDGET_FACTOR: usize = 6;

/// The fewest iterations the reweighting rounds' solves are allowed together.
const RELAXATION_BUDGET_MIN: usize = 192;

/// The conjugate-gradient iterations the reweighting rounds' solves may take together, fold
/// tightening included, when the harmonic map's took `harmonic` (see
/// [`RELAXATION_BUDGET_FACTOR`]).
pub(super) fn relaxation_budget(harmonic: usize) -> usize {
    (RELAXATION_BUDGET_FACTOR * harmonic).max(RELAXATION_BUDGET_MIN)
}

/// The tightest tolerance a solve is pushed to when its map still folds.
pub(super) const TIGHTEST: f64 = 1e-14;

impl<'a> Relaxation<'a> {
    pub(crate) fn new(
        positions: &'a [DVec3],
        triangles: &'a [[u32; 3]],
        topology: &'a Topology,
        freedom: Vec<Freedom>,
        flat: Option<&'a [bool]>,
    ) -> Self {
        let raw: Vec<(f64, [f64; 3])> = triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|k| positions[k as usize]);
                (
                    0.5 * (b - a).cross(c - a).length(),
                    [(b - c).length_squared(), (c - a).length_squared(), (a - b).length_squared()],
                )
            })
            .collect();
        let floor = 0.01 * raw.iter().map(|x| x.0).sum::<f64>() / triangles.len().max(1) as f64;
        Self {
            positions,
            triangles,
            topology,
            freedom,
            flat,
            area: raw.iter().map(|x| x.0.max(floor)).collect(),
            l2: raw.iter().map(|x| x.1).collect(),
        }
    }

    fn skip(&self, f: usize) -> bool {
        self.flat.is_some_and(|m| m[f])
    }

    /// The energy of v's triangles with v moved by `delta` (in the domain scaled by α).
    fn vertex_energy(&self, map: &FlatMap, v: u32, delta: DVec2, alpha: f64) -> f64 {
        let mut e = 0.0;
        for &h in self.topology.outgoing(v) {
            let (f, k) = ((h / 3) as usize, (h % 3) as usize);
            if self.skip(f) {
                continue;
            }
            let c = map.corners(self.triangles, f).map(|x| scaled(x, alpha));
            let l2 = self.l2[f];
            e += face_energy(
                c[k] + delta,
                c[(k + 1) % 3],
                c[(k + 2) % 3],
                self.area[f],
                [l2[k], l2[(k + 1) % 3], l2[(k + 2) % 3]],
            );
            if !e.is_finite() {
                return e;
            }
        }
        e
    }

    /// One stretch-lowering move of v: a Newton step (a gradient step where the Hessian is
    /// not positive), no longer than half the mean distance to its neighbours, halved until
    /// it lowers the energy with every triangle wound correctly.
    fn relax_vertex(&self, map: &FlatMap, v: u32, alpha: f64) -> Option<DVec2> {
        let freedom = self.freedom[v as usize];
        if freedom == Freedom::Fixed {
            return None;
        }
        let (mut e0, mut g, mut h) = (0.0, DVec2::ZERO, [0.0; 3]);
        let (mut reach, mut count) = (0.0, 0usize);
        for &he in self.topology.outgoing(v) {
            let (f, k) = ((he / 3) as usize, (he % 3) as usize);
            let c = map.corners(self.triangles, f).map(|x| scaled(x, alpha));
            reach += (c[(k + 1) % 3] - c[k]).length() + (c[(k + 2) % 3] - c[k]).length();
            count += 2;
            if self.skip(f) {
                continue;
            }
            let l2 = self.l2[f];
            let (fe, fg, fh) = face_energy_grad(
                c[k],
                c[(k + 1) % 3],
                c[(k + 2) % 3],
                self.area[f],
                [l2[k], l2[(k + 1) % 3], l2[(k + 2) % 3]],
            );
            e0 += fe;
            g += fg;
            for i in 0..3 {
                h[i] += fh[i];
            }
        }
        if !e0.is_finite() || count == 0 {
            return None;
        }
        reach /= count as f64;
        if reach.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let mut step = match freedom {
            Freedom::Free => {
                let d = h[0] * h[2] - h[1] * h[1];
                if h[0] > 0.0 && d > 0.0 {
                    DVec2::new(-(h[2] * g.x - h[1] * g.y) / d, -(-h[1] * g.x + h[0] * g.y) / d)
                } else {
                    -g * (0.5 * reach / g.length())
                }
            }
            Freedom::Slide { axis, .. } => {
                let (gs, hs) = (g[axis], h[if axis == 0 { 0 } else { 2 }]);
                let s = if hs > 0.0 { -gs / hs } else { -gs.signum() * 0.5 * reach };
                let mut d = DVec2::ZERO;
                d[axis] = s;
                d
            }
            Freedom::Fixed => return None,
        };
        if !step.is_finite() || step == DVec2::ZERO {
            return None;
        }
        let len = step.length();
        if len > 0.5 * reach {
            step *= 0.5 * reach / len;
        }
        for _ in 0..30 {
            // The step in (u, v).
            let delta = DVec2::new(step.x / alpha, step.y);
            let inside = match freedom {
                Freedom::Slide { axis, a, b } => {
                    let x = map.uv[v as usize][axis] + delta[axis];
                    let (p, q) = (map.uv[a as usize][axis], map.uv[b as usize][axis]);
                    x > p.min(q) && x < p.max(q)
                }
                _ => true,
            };
            if inside && self.vertex_energy(map, v, step, alpha) < e0 {
                return Some(delta);
            }
            step *= 0.5;
        }
        None
    }

    /// Newton sweeps over every vertex: Gauss–Seidel by colour classes (no two neighbours
    /// share a colour, so each class moves in parallel, each vertex against its neighbours'
    /// latest positions). A vertex is visited again only if it or a neighbour moved
    /// noticeably in the sweep before.
    fn sweeps(&self, classes: &[Vec<u32>], map: &mut FlatMap, sweeps: usize, alpha: f64) {
        let n = map.uv.len();
        let mut active = vec![true; n];
        let mut next = vec![false; n];
        for _ in 0..sweeps {
            for class in classes {
                let moves: Vec<(u32, DVec2)> = class
                    .par_iter()
                    .with_min_len(256)
                    .filter(|&&v| active[v as usize])
                    .filter_map(|&v| self.relax_vertex(map, v, alpha).map(|d| (v, d)))
                    .collect();
                for (v, d) in moves {
                    let before = map.uv[v as usize];
                    map.uv[v as usize] += d;
                    // Noticeable: a thousandth of the distance to the nearest neighbour.
                    let near = self
                        .topology
                        .outgoing(v)
                        .iter()
                        .map(|&h| {
                            let c = map.corners(self.triangles, (h / 3) as usize);
                            let k = (h % 3) as usize;
                            (c[(k + 1) % 3] - c[k]).length()
                        })
                        .fold(f64::INFINITY, f64::min);
                    if (map.uv[v as usize] - before).length() > 1e-3 * near {
                        for &h in self.topology.outgoing(v) {
                            for &k in &self.triangles[(h / 3) as usize] {
                                next[k as usize] = true;
                            }
                        }
                    }
                }
            }
            std::mem::swap(&mut active, &mut next);
            next.iter_mut().for_each(|x| *x = false);
        }
    }

    /// The per-triangle factor of the next reweighting round: the current one over the
    /// triangle's RMS stretch √((σ₁² + σ₂²)/2), normalised so that a map with the same stretch
    /// everywhere has 1 (Yoshizawa et al. 2004: where the map squeezes the surface, the
    /// weights drop and the triangles grow).
    fn reweight(&self, map: &FlatMap, scale: &mut [f64], alpha: f64) {
        let (mut area_uv, mut area_p) = (0.0, 0.0);
        let mut rms = vec![1.0; self.triangles.len()];
        for (f, t) in self.triangles.iter().enumerate() {
            if self.skip(f) {
                continue;
            }
            let c = map.corners(self.triangles, f).map(|x| scaled(x, alpha));
            let d = det(c);
            if d <= 0.0 {
                continue;
            }
            let [pa, pb, pc] = t.map(|k| self.positions[k as usize]);
            let ap = 0.5 * (pb - pa).cross(pc - pa).length();
            area_uv += 0.5 * d;
            area_p += ap;
            rms[f] = (0.5 * stretch_numerator(c[0], c[1], c[2], self.l2[f]) / (d * d)).sqrt();
        }
        if area_uv <= 0.0 || area_p <= 0.0 {
            return;
        }
        let unit = (area_p / area_uv).sqrt();
        for (s, r) in scale.iter_mut().zip(&rms) {
            let x = (r / unit).clamp(1e-3, 1e3);
            *s = (*s / x).clamp(1e-8, 1e8);
        }
    }

    /// The relaxation: reweighting rounds, each a Laplacian solve warm-started from the map
    /// (kept while it lowers the stretch and is a bijection), then Newton sweeps. `rhs` gives
    /// the right-hand sides for the Laplacian's current weights; `fixed` the vertices held in
    /// the solves.
    ///
    /// Each round's solve is preconditioned by a hierarchy built for its own weights; the
    /// rounds' solves share [`relaxation_budget`] iterations, fold tightening included, each
    /// also capped by the caller's cap per solve. A round that does not reach a map without
    /// folds within what is left is dropped and ends the rounds, `map` left at the last map
    /// kept. So the rounds cost at most `rounds` hierarchies and [`relaxation_budget`]
    /// iterations, and the sweeps `sweeps` passes over the vertices, each move a line search
    /// of at most 31 evaluations of the vertex's triangles.
    pub(crate) fn run(
        &self,
        lap: &mut Laplacian,
        fixed: Option<&[bool]>,
        rhs: &dyn Fn(&Laplacian) -> Vec<[f64; 2]>,
        map: &mut FlatMap,
        options: RelaxOptions,
    ) -> RelaxReport {
        let mut report = RelaxReport {
            rounds: 0,
            end: if options.rounds == 0 { RoundsEnd::NotAsked } else { RoundsEnd::AllMade },
            sweeps: 0,
            iterations: 0,
            residual: None,
        };
        let mut budget = relaxation_budget(options.harmonic_iterations);
        // Each map is measured on the domain of its own image's shape.
        let efficiency = |m: &FlatMap| {
            let (q, metric) = quality(self.positions, self.triangles, m, self.flat);
            (q.stretch_efficiency, aspect_of(metric))
        };
        let (mut best, mut alpha) = efficiency(map);
        let mut scale = vec![1.0; self.triangles.len()];
        for _ in 0..options.rounds {
            if budget == 0 {
                report.end = RoundsEnd::Unsolved;
                break;
            }
            self.reweight(map, &mut scale, alpha);
            lap.set_cotangent_weights(self.positions, self.triangles, Some(&scale));
            // A hierarchy for this round's weights: they differ from the last round's by a
            // factor per triangle of up to 10³ either way, not smoothly on a mesh with slivers
            // and squeezed parts, and a hierarchy built for other weights can take a hundred
            // times the iterations (on the zero set of a scan, thousands per round instead of
            // a dozen or two); building one costs about four.
            let multigrid = lap.preconditioner(fixed, options.cg);
            let b = rhs(lap);
            let mut trial = map.clone();
            let mut x: Vec<[f64; 2]> = trial.uv.iter().map(|p| p.to_array()).collect();
            let (iterations, solved) = solve_until_embedded(
                lap,
                fixed,
                &b,
                &mut x,
                CgOptions {
                    tolerance: options.cg.tolerance.max(ROUND_TOLERANCE),
                    max_iterations: budget.min(options.cg.max_iterations),
                    ..options.cg
                },
                multigrid.as_ref(),
                |x| {
                    let mut m = trial.clone();
                    m.uv = x.iter().map(|p| DVec2::from_array(*p)).collect();
                    count_folds(self.triangles, &m, self.flat)
                },
            );
            report.iterations += iterations;
            budget = budget.saturating_sub(iterations);
            let Ok(Embedded { residual, folds: 0 }) = solved else {
                report.end = RoundsEnd::Unsolved;
                break;
            };
            trial.uv = x.iter().map(|p| DVec2::from_array(*p)).collect();
            let (e, a) = efficiency(&trial);
            if e <= best {
                report.end = RoundsEnd::NoGain;
                break;
            }
            let small = e < best * (1.0 + SMALL_GAIN);
            (best, alpha) = (e, a);
            *map = trial;
            report.rounds += 1;
            report.residual = Some(residual);
            if small {
                report.end = RoundsEnd::SmallGain;
                break;
            }
        }
        if options.sweeps > 0 {
            let classes = lap.colour_classes();
            self.sweeps(&classes, map, options.sweeps, alpha);
            report.sweeps = options.sweeps;
        }
        report
    }
}
