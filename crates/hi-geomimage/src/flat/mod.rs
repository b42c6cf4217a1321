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
//!
//! The quality of a map is in `quality`, the stretch relaxation in `relax`, the rasteriser in
//! `raster`.

mod quality;
mod raster;
mod relax;

use glam::{DVec2, DVec3, IVec2};

use crate::laplace::{BLOCK, CgOptions, Laplacian, Multigrid, NONE, Topology};
use crate::{Error, GeometryImage, NonFiniteInput};
use hi_par::*;

pub(crate) use quality::{Metric, aspect_of, quality};
pub(crate) use raster::rasterise;
use relax::TIGHTEST;
pub(crate) use relax::{Freedom, RelaxOptions, Relaxation};

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
mod tests;
