// SPDX-License-Identifier: MIT
//! What the flat parameterisations ([`torusparam`](crate::torusparam) and
//! [`discparam`](crate::discparam)) share: the checks of their input, the quality of a map
//! (Sander, Snyder, Gortler and Hoppe 2001, "Texture mapping progressive meshes": the L²
//! stretch; Praun and Hoppe 2003: its efficiency), the stretch relaxation (Yoshizawa, Belyaev
//! and Seidel 2004, "A fast and simple stretch-minimizing mesh parameterization", then Newton
//! moves of single vertices with the stretch as a barrier, as in [`sphereparam`](crate::sphereparam)),
//! Lagrange–Gauss reduction of a binary quadratic form, and the rasteriser that samples a
//! geometry image from a map.
//!
//! A map gives each vertex a point of the plane and each triangle corner an integer
//! translation, so that triangle f is the plane triangle with corners
//! uv[t[k]] + offset[f][k]: on the torus a triangle that crosses a seam of the unit square is
//! kept in one piece; on the square all offsets are zero.
//!
//! The relaxation's bounds (a budget of iterations shared by the reweighting rounds, a
//! multigrid hierarchy per round, the last bijection kept) are stated in the documentation of
//! [`torusparam`](crate::torusparam), under "What a parameterisation costs, at most".

use glam::{DVec2, DVec3, IVec2};

use crate::laplace::{BLOCK, CgOptions, Laplacian, Multigrid, NONE, Topology};
use crate::{Error, GeometryImage, NonFiniteInput};
use hi_par::*;

/// How good a flat parameterisation is: the measures of
/// [`ParamQuality`](crate::sphereparam::ParamQuality), on the plane.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FlatQuality {
    /// The L² stretch efficiency (Praun and Hoppe 2003): (surface area)² / (domain area · E)
    /// with E = Σ A (σ₁² + σ₂²)/2 over the triangles, A the triangle's surface area and σ the
    /// singular values of the map from the domain to the surface (Sander et al. 2001); 1 for a
    /// map with the same stretch everywhere, in (0, 1], higher is better. The domain is the
    /// image's: (u, v) scaled to (αu, v), α the map's aspect (rows/cols for square texels),
    /// so a shape that is simply long (a thin tube) is not counted as stretched.
    pub stretch_efficiency: f64,
    /// The ratio of the largest to the smallest ((u, v) area / surface area) over the
    /// triangles with a surface area above a millionth of the mean: how much denser the image
    /// samples one part of the surface than another.
    pub area_ratio: f64,
    /// Triangles with a (u, v) area ≤ 0 (0 for a valid map), those of `flat_triangles` apart.
    pub folded_triangles: usize,
    /// Triangles of a disc laid flat on a side of the square, because an edge inside the mesh
    /// joins two vertices of that side and cuts them off (Floater 2003: such an edge is the
    /// one obstacle to a bijection onto a convex polygon that is not strictly convex); always
    /// 0 on the torus.
    pub flat_triangles: usize,
    /// ∫ pᵤ·pᵥ / √(∫|pᵤ|² ∫|pᵥ|²) over the (u, v) domain, p the map from (u, v) to the
    /// surface: the mean cosine of the angle between the image's rows and columns on the
    /// surface (0 for no shear).
    pub shear: f64,
}

/// What a flat parameterisation took, and the quality before and after its relaxation.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FlatReport {
    /// The positive-weight harmonic map, before any relaxation.
    pub harmonic: FlatQuality,
    /// The final map (equal to `harmonic` when relaxation is off).
    pub relaxed: FlatQuality,
    /// Reweighting rounds kept (each lowered the stretch).
    pub rounds: usize,
    /// Why the reweighting rounds ended.
    pub rounds_end: RoundsEnd,
    /// Newton sweeps made.
    pub sweeps: usize,
    /// Conjugate-gradient iterations in all the Laplacian solves (those of rounds that were
    /// dropped included).
    pub solve_iterations: usize,
    /// Conjugate-gradient iterations of the harmonic map's solve alone (its fold tightening
    /// included); the reweighting rounds' solves together may take at most six times as many
    /// (192 at least).
    pub harmonic_iterations: usize,
    /// The relative residual of the last Laplacian solve kept.
    pub solve_residual: f64,
}

/// Why the reweighting rounds of a flat parameterisation ended. Whatever the reason, the map
/// kept is the last one that was a bijection and lowered the stretch: the harmonic map if no
/// round was kept.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum RoundsEnd {
    /// No round was asked for.
    NotAsked,
    /// Every round asked for was made and kept.
    AllMade,
    /// A round raised the stretch efficiency by less than 2 %: it was kept, and was the last
    /// (the rounds have about converged).
    SmallGain,
    /// A round did not raise the stretch efficiency: it was dropped (the rounds overshoot).
    NoGain,
    /// A round's solve did not reach a map without folds within what was left of the rounds'
    /// iteration budget, or broke down: it was dropped.
    Unsolved,
}

/// A geometry image sampled from a flat parameterisation.
#[derive(Clone, Debug, PartialEq)]
pub struct FlatImage {
    /// The image: each texel the surface point at its (u, v).
    pub image: GeometryImage,
    /// Texels that fell on a triangle flagged filled (added to close a hole), row-major.
    pub filled: Vec<bool>,
    /// The fraction of the texels that fell on filled triangles.
    pub filled_fraction: f64,
}

/// The checks every flat parameterisation makes, and the mesh's connectivity.
pub(crate) fn check_input(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    filled: &[bool],
    min_triangles: usize,
    shape: &str,
) -> Result<Topology, Error> {
    if filled.len() != triangles.len() {
        return Err(Error::Topology {
            what: format!(
                "{} filled flags given for {} triangles: one per triangle is needed",
                filled.len(),
                triangles.len()
            ),
        });
    }
    if triangles.len() < min_triangles {
        return Err(Error::Topology {
            what: format!(
                "{} triangle{} cannot make a {shape}: at least {min_triangles} are needed",
                triangles.len(),
                if triangles.len() == 1 { "" } else { "s" }
            ),
        });
    }
    if let Some(k) = positions.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinite { what: NonFiniteInput::Vertex(k) });
    }
    let topology = Topology::new(positions.len(), triangles)?;
    let parts = topology.components(triangles);
    if parts != 1 {
        return Err(Error::Topology {
            what: format!("the mesh has {parts} separate parts; a {shape} is one"),
        });
    }
    Ok(topology)
}

/// A map: a point per vertex and an integer translation per triangle corner.
#[derive(Clone, Debug)]
pub(crate) struct FlatMap {
    pub(crate) uv: Vec<DVec2>,
    pub(crate) offsets: Vec<[IVec2; 3]>,
}

impl FlatMap {
    /// The plane triangle of triangle f.
    pub(crate) fn corners(&self, triangles: &[[u32; 3]], f: usize) -> [DVec2; 3] {
        let t = triangles[f];
        std::array::from_fn(|k| self.uv[t[k] as usize] + self.offsets[f][k].as_dvec2())
    }

    /// Applies the integer matrix m (columns m[0], m[1]) to every point and offset.
    pub(crate) fn transform(&mut self, m: [[i32; 2]; 2]) {
        let apply = |p: DVec2| {
            DVec2::new(
                f64::from(m[0][0]) * p.x + f64::from(m[1][0]) * p.y,
                f64::from(m[0][1]) * p.x + f64::from(m[1][1]) * p.y,
            )
        };
        let apply_i =
            |p: IVec2| IVec2::new(m[0][0] * p.x + m[1][0] * p.y, m[0][1] * p.x + m[1][1] * p.y);
        self.uv.iter_mut().for_each(|p| *p = apply(*p));
        self.offsets.iter_mut().for_each(|o| *o = o.map(apply_i));
    }

    /// Moves every vertex into [0, 1)² by an integer translation, moved into its corners'
    /// offsets.
    pub(crate) fn wrap(&mut self, triangles: &[[u32; 3]]) {
        let shifts: Vec<IVec2> = self
            .uv
            .iter_mut()
            .map(|p| {
                let mut s = p.floor();
                let mut q = *p - s;
                // −tiny − floor rounds to 1.
                for c in 0..2 {
                    if q[c] >= 1.0 {
                        q[c] -= 1.0;
                        s[c] += 1.0;
                    }
                }
                *p = q;
                s.as_ivec2()
            })
            .collect();
        for (o, t) in self.offsets.iter_mut().zip(triangles) {
            for k in 0..3 {
                o[k] += shifts[t[k] as usize];
            }
        }
    }
}

/// The 2-D cross product.
pub(crate) fn cross(a: DVec2, b: DVec2) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Twice the signed area of the plane triangle.
pub(crate) fn det(c: [DVec2; 3]) -> f64 {
    cross(c[1] - c[0], c[2] - c[0])
}

/// Triangles wound the wrong way or of zero area, those flagged in `flat` apart.
pub(crate) fn count_folds(triangles: &[[u32; 3]], map: &FlatMap, flat: Option<&[bool]>) -> usize {
    (0..triangles.len())
        .into_par_iter()
        .with_min_len(4096)
        .filter(|&f| !flat.is_some_and(|m| m[f]) && det(map.corners(triangles, f)) <= 0.0)
        .count()
}

/// The mean metric of a map: P = ∫ Jᵀ J over the (u, v) domain, J = (pᵤ, pᵥ), as
/// [P₁₁, P₁₂, P₂₂].
pub(crate) type Metric = [f64; 3];

/// Sums over a block of triangles for [`quality`].
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
fn scaled(p: DVec2, alpha: f64) -> DVec2 {
    DVec2::new(alpha * p.x, p.y)
}

/// rows / cols (or (rows − 1)/(cols − 1) for a whole-sample image) that makes texels square
/// on average: √(∫|pᵤ|² / ∫|pᵥ|²).
pub(crate) fn aspect_of(metric: Metric) -> f64 {
    if metric[0] > 0.0 && metric[2] > 0.0 { (metric[0] / metric[2]).sqrt() } else { 1.0 }
}

/// N = ℓ₁ (b − a)·(c − a) + ℓ₂ (c − b)·(a − b) + ℓ₃ (a − c)·(b − c): with d = (b − a) × (c − a),
/// N / d² = σ₁² + σ₂² of the affine map from the plane triangle abc to a surface triangle
/// whose squared edge lengths opposite a, b, c are ℓ₁, ℓ₂, ℓ₃ (the cotangent formula).
fn stretch_numerator(a: DVec2, b: DVec2, c: DVec2, l2: [f64; 3]) -> f64 {
    l2[0] * (b - a).dot(c - a) + l2[1] * (c - b).dot(a - b) + l2[2] * (a - c).dot(b - c)
}

/// The stretch energy ½ A N / d² of one triangle (see [`stretch_numerator`]) with its corner a
/// free, ∞ if the triangle is not wound counter-clockwise: a barrier against folds.
fn face_energy(a: DVec2, b: DVec2, c: DVec2, area: f64, l2: [f64; 3]) -> f64 {
    let d = cross(b - a, c - a);
    if d <= 0.0 {
        return f64::INFINITY;
    }
    0.5 * area * stretch_numerator(a, b, c, l2) / (d * d)
}

/// [`face_energy`], its gradient and Hessian ([h₁₁, h₁₂, h₂₂]) with respect to a.
fn face_energy_grad(
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
fn relaxation_budget(harmonic: usize) -> usize {
    (RELAXATION_BUDGET_FACTOR * harmonic).max(RELAXATION_BUDGET_MIN)
}

/// The tightest tolerance a solve is pushed to when its map still folds.
const TIGHTEST: f64 = 1e-14;

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
        settings: RelaxOptions,
    ) -> RelaxReport {
        let mut report = RelaxReport {
            rounds: 0,
            end: if settings.rounds == 0 { RoundsEnd::NotAsked } else { RoundsEnd::AllMade },
            sweeps: 0,
            iterations: 0,
            residual: None,
        };
        let mut budget = relaxation_budget(settings.harmonic_iterations);
        // Each map is measured on the domain of its own image's shape.
        let efficiency = |m: &FlatMap| {
            let (q, metric) = quality(self.positions, self.triangles, m, self.flat);
            (q.stretch_efficiency, aspect_of(metric))
        };
        let (mut best, mut alpha) = efficiency(map);
        let mut scale = vec![1.0; self.triangles.len()];
        for _ in 0..settings.rounds {
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
            let multigrid = lap.preconditioner(fixed, settings.cg);
            let b = rhs(lap);
            let mut trial = map.clone();
            let mut x: Vec<[f64; 2]> = trial.uv.iter().map(|p| p.to_array()).collect();
            let (iterations, solved) = solve_until_embedded(
                lap,
                fixed,
                &b,
                &mut x,
                CgOptions {
                    tolerance: settings.cg.tolerance.max(ROUND_TOLERANCE),
                    max_iterations: budget.min(settings.cg.max_iterations),
                    ..settings.cg
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
        if settings.sweeps > 0 {
            let classes = lap.colour_classes();
            self.sweeps(&classes, map, settings.sweeps, alpha);
            report.sweeps = settings.sweeps;
        }
        report
    }
}

/// The end of [`solve_until_embedded`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Embedded {
    /// The relative residual of the last solve.
    pub(crate) residual: f64,
    /// The triangles still folded (at the tightest tolerance), 0 for an embedding.
    pub(crate) folds: usize,
}

/// Solves (preconditioned by `multigrid`, see [`Laplacian::solve`]), then, while `folds`
/// finds folded triangles, solves on from there to a tolerance a hundred times tighter, down
/// to 10⁻¹⁴; `cg.max_iterations` caps the iterations of all these solves together (the
/// positions of the vertices of an exponentially squeezed part of the map, such as a long
/// finger of a disc, differ by less than a tolerance of 10⁻⁸ resolves). Returns the
/// iterations (those of a solve that failed counted as all it was allowed), and the last
/// residual with the folds left (at the tightest tolerance or the cap), or the failure (the
/// cap reached before the tolerance, a breakdown).
pub(crate) fn solve_until_embedded(
    lap: &Laplacian,
    fixed: Option<&[bool]>,
    b: &[[f64; 2]],
    x: &mut [[f64; 2]],
    cg: CgOptions,
    multigrid: Option<&Multigrid>,
    folds: impl Fn(&[[f64; 2]]) -> usize,
) -> (usize, Result<Embedded, Error>) {
    let mut options = cg;
    let mut iterations = 0;
    loop {
        // Below the cap here: it is at least 1, and reaching it returns.
        options.max_iterations = cg.max_iterations - iterations;
        let report = match lap.solve(fixed, b, x, options, multigrid) {
            Ok(r) => r,
            Err(e) => return (iterations + options.max_iterations, Err(e)),
        };
        iterations += report.iterations;
        let left = folds(x);
        if left == 0 || options.tolerance <= TIGHTEST || iterations >= cg.max_iterations {
            return (iterations, Ok(Embedded { residual: report.residual, folds: left }));
        }
        options.tolerance = (options.tolerance * 1e-2).max(TIGHTEST);
    }
}

/// Lagrange–Gauss reduction of the positive definite form q = [q₁₁, q₁₂, q₂₂]: an integer
/// matrix B = (b₁ b₂) of determinant +1 with q(b₁) ≤ q(b₂) and |q(b₁, b₂)| ≤ q(b₁)/2 (Gauss,
/// Disquisitiones Arithmeticae, 1801, art. 171; in lattice terms the shortest basis, Lagrange
/// 1773). Returned as columns: `[b₁, b₂]`.
pub(crate) fn reduce(q: Metric) -> [[i32; 2]; 2] {
    let form = |x: [i64; 2], y: [i64; 2]| {
        let (x0, x1, y0, y1) = (x[0] as f64, x[1] as f64, y[0] as f64, y[1] as f64);
        q[0] * x0 * y0 + q[1] * (x0 * y1 + x1 * y0) + q[2] * x1 * y1
    };
    let (mut b1, mut b2) = ([1i64, 0], [0i64, 1]);
    for _ in 0..200 {
        if form(b1, b1) > form(b2, b2) {
            std::mem::swap(&mut b1, &mut b2);
        }
        let n1 = form(b1, b1);
        if n1.is_nan() || n1 <= 0.0 {
            break;
        }
        let mu = (form(b1, b2) / n1).round();
        if mu == 0.0 || !mu.is_finite() || mu.abs() > 1e9 {
            break;
        }
        let mu = mu as i64;
        b2 = [b2[0] - mu * b1[0], b2[1] - mu * b1[1]];
    }
    if b1[0] * b2[1] - b1[1] * b2[0] < 0 {
        b2 = [-b2[0], -b2[1]];
    }
    match [b1[0], b1[1], b2[0], b2[1]].map(i32::try_from) {
        [Ok(a), Ok(b), Ok(c), Ok(d)] => [[a, b], [c, d]],
        // Beyond any mesh: keep the basis.
        _ => [[1, 0], [0, 1]],
    }
}

/// The inverse of an integer matrix of determinant 1 (columns).
pub(crate) fn inverse(m: [[i32; 2]; 2]) -> [[i32; 2]; 2] {
    // m = [[a, b], [c, d]] in rows, columns (a, c), (b, d); inverse rows [[d, −b], [−c, a]].
    let (a, c, b, d) = (m[0][0], m[0][1], m[1][0], m[1][1]);
    [[d, -c], [-b, a]]
}

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
    // Each triangle in the bucket of every row it may touch, with that row's unwrapped index.
    let (ri, ci) = (rows as i64, cols as i64);
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
    let barycentric = |c: &[DVec2; 3], p: DVec2| {
        let d = cross(c[1] - c[0], c[2] - c[0]);
        [
            cross(c[1] - p, c[2] - p) / d,
            cross(c[2] - p, c[0] - p) / d,
            cross(c[0] - p, c[1] - p) / d,
        ]
    };
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
        .map(|r| {
            let mut best = vec![(f64::NEG_INFINITY, NONE, [0.0; 3]); cols];
            for &(f, i) in &buckets[r] {
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
        })
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

/// For each entry (i, j) of the Laplacian's rows, the value of an integer 1-form on the
/// half-edge i → j (from its half-edge there, or minus the one j → i).
pub(crate) fn form_rhs(lap: &Laplacian, form: &[IVec2]) -> Vec<[f64; 2]> {
    (0..lap.size())
        .into_par_iter()
        .with_min_len(4096)
        .map(|i| {
            let (_, ws, sides) = lap.row(i);
            let mut b = DVec2::ZERO;
            for (&w, s) in ws.iter().zip(sides) {
                let o = if s[0] != NONE { form[s[0] as usize] } else { -form[s[1] as usize] };
                b += w * o.as_dvec2();
            }
            b.to_array()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::laplace::tail;

    /// A bumpy 12 × 12 height field over the unit square and its harmonic map onto the square
    /// (the boundary held where it lies): positions, triangles, connectivity, Laplacian,
    /// held vertices, the map and the iterations it took.
    #[expect(clippy::type_complexity, reason = "one test helper")]
    fn bumpy_square() -> (Vec<DVec3>, Vec<[u32; 3]>, Topology, Laplacian, Vec<bool>, FlatMap, usize)
    {
        let n = 12;
        let p: Vec<DVec3> = (0..n * n)
            .map(|k| {
                let (x, y) = ((k % n) as f64 / (n - 1) as f64, (k / n) as f64 / (n - 1) as f64);
                DVec3::new(x, y, 0.4 * (5.0 * x).sin() * (4.0 * y).cos())
            })
            .collect();
        let mut t = Vec::new();
        for i in 0..n - 1 {
            for j in 0..n - 1 {
                let a = (i * n + j) as u32;
                t.extend([[a, a + 1, a + n as u32 + 1], [a, a + n as u32 + 1, a + n as u32]]);
            }
        }
        let topology = Topology::new(p.len(), &t).unwrap();
        let mut fixed = vec![false; p.len()];
        for &h in &topology.boundary {
            fixed[tail(&t, h) as usize] = true;
        }
        let mut lap = Laplacian::new(&topology, &t);
        lap.set_cotangent_weights(&p, &t, None);
        let mut x: Vec<[f64; 2]> = p.iter().map(|q| [q.x, q.y]).collect();
        let cg = CgOptions::new(1e-10, 1000);
        let (iterations, solved) = solve_until_embedded(
            &lap,
            Some(&fixed),
            &vec![[0.0; 2]; p.len()],
            &mut x,
            cg,
            None,
            |_| 0,
        );
        assert_eq!(solved.unwrap().folds, 0, "the harmonic map");
        let map = FlatMap {
            uv: x.iter().map(|q| DVec2::from_array(*q)).collect(),
            offsets: vec![[IVec2::ZERO; 3]; t.len()],
        };
        (p, t, topology, lap, fixed, map, iterations)
    }

    /// The rounds' solves share a budget: with iterations to spare they lower the stretch;
    /// with one iteration per solve the first round cannot be solved, is dropped, and leaves
    /// the map as it was.
    #[test]
    fn rounds_keep_to_their_budget() {
        let (p, t, topology, mut lap, fixed, harmonic, iterations) = bumpy_square();
        let freedom: Vec<Freedom> =
            fixed.iter().map(|&f| if f { Freedom::Fixed } else { Freedom::Free }).collect();
        let relaxation = Relaxation::new(&p, &t, &topology, freedom, None);
        let zero = vec![[0.0; 2]; p.len()];
        let before = quality(&p, &t, &harmonic, None).0.stretch_efficiency;
        let settings = RelaxOptions {
            rounds: 8,
            sweeps: 0,
            cg: CgOptions::new(1e-8, 100_000),
            harmonic_iterations: iterations,
        };
        let mut map = harmonic.clone();
        let done = relaxation.run(
            &mut lap,
            Some(&fixed),
            &|_: &Laplacian| zero.clone(),
            &mut map,
            settings,
        );
        let after = quality(&p, &t, &map, None).0.stretch_efficiency;
        println!("{done:?}: efficiency {before} → {after}");
        assert!(done.rounds >= 1 && after > before, "{done:?}");
        assert!(done.iterations <= relaxation_budget(iterations), "{done:?}");
        assert_ne!(done.end, RoundsEnd::Unsolved, "{done:?}");
        // One iteration per solve: the first round is dropped, the map kept as it was.
        let mut map = harmonic.clone();
        let starved = RelaxOptions { cg: CgOptions::new(1e-8, 1), ..settings };
        let done = relaxation.run(
            &mut lap,
            Some(&fixed),
            &|_: &Laplacian| zero.clone(),
            &mut map,
            starved,
        );
        assert_eq!(
            (done.rounds, done.end, done.iterations),
            (0, RoundsEnd::Unsolved, 1),
            "{done:?}"
        );
        assert_eq!(map.uv, harmonic.uv, "the harmonic map kept");
        // No rounds asked for.
        let none = RelaxOptions { rounds: 0, ..settings };
        let done =
            relaxation.run(&mut lap, Some(&fixed), &|_: &Laplacian| zero.clone(), &mut map, none);
        assert_eq!(
            (done.rounds, done.end, done.iterations),
            (0, RoundsEnd::NotAsked, 0),
            "{done:?}"
        );
    }

    /// The analytic gradient and Hessian of a face's energy against central differences.
    #[test]
    fn face_energy_derivatives_match_differences() {
        let (a, b, c) = (DVec2::new(0.1, 0.05), DVec2::new(0.9, 0.1), DVec2::new(0.3, 0.7));
        let (area, l2) = (0.7, [0.9, 1.3, 0.6]);
        let (e, g, hs) = face_energy_grad(a, b, c, area, l2);
        assert!((e - face_energy(a, b, c, area, l2)).abs() < 1e-12 * e, "energy");
        let h = 1e-6;
        for (axis, col) in [(DVec2::X, [hs[0], hs[1]]), (DVec2::Y, [hs[1], hs[2]])] {
            let (ep, gp, _) = face_energy_grad(a + h * axis, b, c, area, l2);
            let (em, gm, _) = face_energy_grad(a - h * axis, b, c, area, l2);
            let dg = (ep - em) / (2.0 * h);
            assert!((dg - g.dot(axis)).abs() < 1e-6 * g.length(), "gradient {dg} vs {g}");
            let dh = (gp - gm) / (2.0 * h);
            let col = DVec2::from_array(col);
            assert!((dh - col).length() < 1e-5 * col.length().max(1.0), "Hessian {dh} vs {col}");
        }
        assert_eq!(face_energy(a, c, b, area, l2), f64::INFINITY, "wound the wrong way");
    }

    /// σ₁² + σ₂² of an affine map, against its Jacobian computed directly.
    #[test]
    fn stretch_numerator_is_the_frobenius_norm() {
        let (a, b, c) = (DVec2::new(0.2, 0.1), DVec2::new(1.1, 0.3), DVec2::new(0.4, 0.9));
        // The map (u, v) ↦ J (u, v) with J 3×2.
        let j = [DVec3::new(1.0, 0.5, -0.3), DVec3::new(-0.2, 0.8, 0.6)];
        let map = |p: DVec2| j[0] * p.x + j[1] * p.y;
        let (pa, pb, pc) = (map(a), map(b), map(c));
        let l2 =
            [(pb - pc).length_squared(), (pc - pa).length_squared(), (pa - pb).length_squared()];
        let d = cross(b - a, c - a);
        let frob = j[0].length_squared() + j[1].length_squared();
        assert!((stretch_numerator(a, b, c, l2) / (d * d) - frob).abs() < 1e-12, "‖J‖²");
    }

    #[test]
    fn reduction_gives_a_short_basis() {
        // The lattice of (1, 0) and (7, 1) under the Euclidean form is Z²; the form of the
        // basis B₀ = ((1, 0), (7, 1)) is B₀ᵀB₀.
        let q = [1.0, 7.0, 50.0];
        let b = reduce(q);
        let form = |x: [i32; 2], y: [i32; 2]| {
            q[0] * f64::from(x[0] * y[0])
                + q[1] * f64::from(x[0] * y[1] + x[1] * y[0])
                + q[2] * f64::from(x[1] * y[1])
        };
        assert_eq!(b[0][0] * b[1][1] - b[0][1] * b[1][0], 1, "determinant 1");
        assert!(form(b[0], b[0]) <= form(b[1], b[1]), "ordered");
        assert!(2.0 * form(b[0], b[1]).abs() <= form(b[0], b[0]), "reduced");
        // Both reduced vectors have length 1 in the original lattice.
        assert_eq!(form(b[0], b[0]), 1.0);
        assert_eq!(form(b[1], b[1]), 1.0);
        let inv = inverse(b);
        let prod = |x: [[i32; 2]; 2], y: [[i32; 2]; 2]| {
            [0, 1].map(|c| [0, 1].map(|r| x[0][r] * y[c][0] + x[1][r] * y[c][1]))
        };
        assert_eq!(prod(b, inv), [[1, 0], [0, 1]]);
    }
}
