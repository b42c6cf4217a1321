// SPDX-License-Identifier: MIT
//! A spherical parameterisation of a closed genus-0 mesh, and the geometry image sampled from
//! it (beyond §5.3: the thesis casts rays from a centre, which needs a star-shaped object; here
//! any genus-0 surface works, as in Praun and Hoppe, "Spherical parametrization and
//! remeshing", SIGGRAPH 2003).
//!
//! **The map.** Every vertex of a [`ClosedMesh`] gets a point on the unit sphere so that every
//! triangle, taken as the flat triangle between its three sphere points, is wound
//! counter-clockwise seen from outside (a·(b × c) > 0): the triangles tile the sphere once,
//! with no fold. The piecewise-linear map from those triangles to the mesh's triangles is then
//! one-to-one, and a texel that looks along direction d (any [`Layout`](crate::Layout)) holds
//! the point of the mesh that d falls on. Texels hold x, y, z of the surface itself, not a distance along a
//! ray, so ears, limbs and overhangs are sampled like everything else.
//!
//! **How.** As Praun and Hoppe do, coarse to fine:
//! 1. the mesh is simplified to a tetrahedron by half-edge collapses (a vertex merged into a
//!    neighbour, which keeps its position), in rounds that each remove an independent set of
//!    vertices, cheapest first by the quadric error of Garland and Heckbert; a collapse must
//!    keep the mesh a 2-manifold (the link condition: the edge's ends share exactly two
//!    neighbours) and, while possible, not turn a triangle over;
//! 2. the tetrahedron goes onto the sphere as the regular one;
//! 3. the collapses are undone in reverse; each vertex that comes back is placed in the kernel
//!    of its ring of neighbours (where all its triangles are wound correctly): at the deepest
//!    point of the kernel (the centre of its largest inscribed circle), or, on the fine levels,
//!    at its neighbours' centroid when that is in the kernel; the kernel is never empty next to
//!    the vertex it had been merged into, where the last fallback puts it;
//! 4. vertices are moved to lower the L² stretch of the map from the sphere to the surface
//!    (Sander, Snyder, Gortler and Hoppe 2001), E = Σ A (σ₁² + σ₂²)/2 over the triangles,
//!    A the triangle's area on the surface and σ the singular values of the map's Jacobian:
//!    each vertex just placed (and, on the coarse levels, the one it split from), every vertex
//!    each time the mesh has grown by half while it is coarse, and every vertex of the
//!    finished map. Minimising E spreads the surface evenly over the sphere (no part
//!    undersampled in the image). Each move is a Newton step on the sphere, halved until it
//!    lowers E with every triangle of the vertex wound correctly; as the set of such positions
//!    is convex (an intersection of hemispheres), the map stays one-to-one throughout. E is
//!    made a barrier against every way a triangle can degenerate on the sphere, and a small
//!    shape term keeps triangles that are slivers on the surface from becoming slivers on the
//!    sphere (see `face_energy`). The vertices of each colour of a greedy colouring move in
//!    parallel.
//!
//! **Weights.** [`parameterise_weighted`] minimises Σ w A (σ₁² + σ₂²)/2 instead, w a triangle's
//! weight (the mean of its corners'), as the signal-specialised stretch of Sander, Gortler,
//! Snyder and Hoppe (2002) weighs its triangles by the signal's variation. A region's share of
//! the sphere, and so of the image's texels, grows as √w: for a triangle of surface area A
//! given sphere area a, σ₁² + σ₂² ≈ 2A/a, and Σ w A²/a over a fixed Σ a is least at a ∝ A√w
//! (Lagrange's condition w A²/a² = constant; the map's anisotropy, which this leaves out, holds
//! the share a little closer to even). [`density_weight`] weighs a region by the density of
//! the scan's samples there.
//!
//! **The image.** For each texel, the triangle containing its direction is found by walking
//! across triangle edges from the texel before it, and the texel is the surface point at the
//! barycentric coordinates of the direction's intersection with the triangle's plane (continuous
//! across edges). Texels in triangles that closed a hole are flagged.

//!
//! **The code.** `simplify` holds the mesh hierarchy and the collapses (1), `splits` the base
//! tetrahedron and the placement of each vertex split (2, 3), `relax` the stretch energy and
//! the relaxation (4), and `sample` the walk across the map that samples the image.

mod relax;
mod sample;
mod simplify;
mod splits;

use glam::DVec3;
use hi_par::*;

use crate::{Error, GeometryImage};
use hi_scan::repair::ClosedMesh;

use relax::{relax, relax_vertex};
use sample::triangle_neighbours;
use simplify::Hierarchy;
use splits::{base, place};

/// The settings of [`parameterise`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SphereParamOptions {
    /// Relaxation sweeps over every vertex each time the mesh has grown by half during the
    /// refinement, while it has at most [`SphereParamOptions::fine_vertices`]. Default 4.
    pub sweeps: usize,
    /// Sweeps over every vertex of the finished map. Default 1.
    pub final_sweeps: usize,
    /// Above this many vertices the refinement only places vertices and relaxes each once
    /// (the coarse levels have shaped the map by then; the final sweeps adjust it locally).
    /// Default 10 000.
    pub fine_vertices: usize,
}

impl Default for SphereParamOptions {
    fn default() -> Self {
        Self { sweeps: 4, final_sweeps: 1, fine_vertices: 10_000 }
    }
}

/// How good a spherical parameterisation is.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ParamQuality {
    /// Rounds of collapses from the mesh to the tetrahedron.
    pub levels: usize,
    /// Collapses that had to turn a triangle over on the surface (none was left otherwise).
    pub forced_collapses: usize,
    /// The L² stretch efficiency of Praun and Hoppe: (area on the sphere / area on the
    /// surface) over E, scaled so that a map with the same stretch everywhere gives 1; in
    /// (0, 1], higher is better.
    pub stretch_efficiency: f64,
    /// The ratio of the largest to the smallest (area on the sphere / area on the surface)
    /// over the triangles with a surface area above a millionth of the mean: how much denser
    /// the image samples one part of the surface than another.
    pub area_ratio: f64,
    /// Triangles wound the wrong way on the sphere (0 for a valid map).
    pub folded_triangles: usize,
}

/// A spherical parameterisation: the mesh and one unit vector per vertex.
#[derive(Clone, Debug)]
pub struct SphereParam {
    mesh: ClosedMesh,
    sphere: Vec<DVec3>,
    across: Vec<[u32; 3]>,
    quality: ParamQuality,
}

/// A geometry image sampled from a [`SphereParam`].
#[derive(Clone, Debug, PartialEq)]
pub struct ParamImage {
    /// The image: texel (i, j) is the surface point that direction
    /// `layout.direction(i, j, rows, cols)` falls on.
    pub image: GeometryImage,
    /// Texels that fell on a triangle added to close a hole (row-major).
    pub filled: Vec<bool>,
    /// The fraction of the distinct texels (each direction once) that fell in a closed hole.
    pub filled_fraction: f64,
}

/// Above this many vertices a round's splits are placed together, in parallel (below it, one
/// at a time, each settled with the vertex it came from).
const BATCH_ABOVE: usize = 2000;

/// Parameterises a closed genus-0 mesh over the unit sphere; see the module documentation.
///
/// # Errors
///
/// [`Error::Topology`] if the mesh cannot be simplified to a tetrahedron or a vertex cannot be
/// placed without folding the map (neither happens for a valid [`ClosedMesh`] in exact
/// arithmetic; the error guards against rounding in extreme meshes); [`Error::InvalidOption`]
/// for 0 final sweeps.
pub fn parameterise(mesh: &ClosedMesh, options: &SphereParamOptions) -> Result<SphereParam, Error> {
    map(mesh, None, options)
}

/// [`parameterise`] with a weight per vertex of `mesh` in the stretch energy (see the module
/// documentation's **Weights**): the sphere's area, and so the image's texels, spent on a
/// region grows as the square root of its weight. The map's [`ParamQuality`] is measured
/// without the weights.
///
/// # Errors
///
/// Those of [`parameterise`], and [`Error::InvalidOption`] for a weight count other than the
/// vertex count or a weight that is not finite and positive.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::sphereparam::{SphereParamOptions, parameterise_weighted};
/// use hi_scan::repair::close_mesh;
///
/// // An octahedron, its upper vertex weighed 9 times as much as the others: a map with no
/// // fold. Weights must be one per vertex, finite and positive.
/// let positions = [DVec3::X, DVec3::Y, DVec3::NEG_X, DVec3::NEG_Y, DVec3::Z, DVec3::NEG_Z];
/// let triangles =
///     [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4], [1, 0, 5], [2, 1, 5], [3, 2, 5], [0, 3, 5]];
/// let mesh = close_mesh(&positions, &triangles).unwrap();
/// let weights: Vec<f64> = mesh.positions.iter().map(|p| if p.z > 0.5 { 9.0 } else { 1.0 }).collect();
/// let options = SphereParamOptions::default();
/// let param = parameterise_weighted(&mesh, &weights, &options).unwrap();
/// assert_eq!(param.quality().folded_triangles, 0);
/// assert!(parameterise_weighted(&mesh, &weights[1..], &options).is_err());
/// assert!(parameterise_weighted(&mesh, &[-1.0; 6], &options).is_err());
/// ```
pub fn parameterise_weighted(
    mesh: &ClosedMesh,
    weights: &[f64],
    options: &SphereParamOptions,
) -> Result<SphereParam, Error> {
    if weights.len() != mesh.positions.len() {
        return Err(Error::InvalidOption {
            name: "weights",
            value: weights.len() as f64,
            expected: "one weight per vertex of the mesh",
        });
    }
    if let Some(&w) = weights.iter().find(|w| !(w.is_finite() && **w > 0.0)) {
        return Err(Error::InvalidOption {
            name: "weights",
            value: w,
            expected: "finite and positive",
        });
    }
    map(mesh, Some(weights), options)
}

/// The most [`density_weight`] weighs a region against one sampled at the median density, and
/// 1 over it the least: densities 8 times the median's or more count as 8 times, so that a
/// cluster of repeated points, or a sliver of tiny triangles, does not take the whole sphere
/// (measured: 16 times does better on a head scan's vertices and worse on a spider's).
pub const DENSITY_WEIGHT_MAX: f64 = 64.0;

/// The weight for [`parameterise_weighted`] of a region where a scan's samples (its points,
/// or its mesh's vertices) are `density` times as dense as their median: density², within
/// [1/[`DENSITY_WEIGHT_MAX`], [`DENSITY_WEIGHT_MAX`]]. As a region's share of the sphere grows
/// as the square root of its weight (the module documentation's **Weights**), it gets texels
/// in proportion to its area times its density, its number of samples: each sample gets about
/// as many texels, and the dense samples of a scan's detail (a face's eyes, lips and ears) are
/// imaged as finely as the broad parts, not in proportion to their small area. (Weights of
/// the density itself, texels as area times √density, gave a larger mean error on 18 of the
/// 23 unevenly sampled scans tried, points and meshes.)
///
/// # Examples
///
/// ```
/// use hi_geomimage::sphereparam::{DENSITY_WEIGHT_MAX, density_weight};
///
/// assert_eq!(density_weight(2.0), 4.0);
/// assert_eq!(density_weight(0.5), 0.25);
/// assert_eq!(density_weight(f64::INFINITY), DENSITY_WEIGHT_MAX);
/// assert_eq!(density_weight(0.0), 1.0 / DENSITY_WEIGHT_MAX);
/// assert_eq!(density_weight(f64::NAN), 1.0);
/// ```
#[must_use]
pub fn density_weight(density: f64) -> f64 {
    if density.is_nan() {
        1.0
    } else {
        (density * density).clamp(1.0 / DENSITY_WEIGHT_MAX, DENSITY_WEIGHT_MAX)
    }
}

/// The [`density_weight`] of each vertex of `mesh` from the density of the mesh's vertices
/// there, against their median density (the inverse of the mean area of its triangles, which
/// is the area per vertex over 2: a closed triangle mesh has twice as many triangles as
/// vertices, near enough), and at least 1: the texels are denser where the vertices are, and
/// no sparser than an even share where they are sparse. The texels of a mesh's image lie on
/// its flat triangles; thinned out over a region of broad triangles, their rows cross the
/// triangles' creases at a slant and show as ridges in the surface through them (measured on
/// the back of `wuson`, a modelled mesh whose vertices crowd at its head).
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::sphereparam::mesh_density_weights;
/// use hi_scan::repair::close_mesh;
///
/// // An octahedron whose top is pulled down to z = h: its upper triangles have area
/// // √(2h² + 1)/2, its lower ones √3/2. The top vertex's triangles are the smallest, the
/// // equator's mean area is the median, and the bottom vertex's triangles are the largest.
/// let h = 0.25;
/// let positions = [DVec3::X, DVec3::Y, DVec3::NEG_X, DVec3::NEG_Y, DVec3::Z * h, DVec3::NEG_Z];
/// let triangles =
///     [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4], [1, 0, 5], [2, 1, 5], [3, 2, 5], [0, 3, 5]];
/// let mesh = close_mesh(&positions, &triangles).unwrap();
/// let (up, down) = (0.5 * (2.0 * h * h + 1.0f64).sqrt(), 0.5 * 3f64.sqrt());
/// let median = 0.5 * (up + down);
/// for (p, w) in mesh.positions.iter().zip(mesh_density_weights(&mesh)) {
///     // Density is the inverse of the mean area; the weight its square, at least 1.
///     let expected = if p.z > 0.0 { (median / up).powi(2) } else { 1.0 };
///     assert!((w - expected).abs() < 1e-12, "{p}: {w} vs {expected}");
/// }
/// ```
#[must_use]
pub fn mesh_density_weights(mesh: &ClosedMesh) -> Vec<f64> {
    let n = mesh.positions.len();
    let (mut area, mut count) = (vec![0.0; n], vec![0usize; n]);
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|k| mesh.positions[k as usize]);
        let triangle = 0.5 * (b - a).cross(c - a).length();
        for &k in t {
            area[k as usize] += triangle;
            count[k as usize] += 1;
        }
    }
    let mean: Vec<f64> = (0..n).map(|k| area[k] / count[k].max(1) as f64).collect();
    let mut sorted = mean.clone();
    sorted.sort_by(f64::total_cmp);
    let median = sorted.get(n / 2).copied().unwrap_or(1.0);
    mean.iter().map(|&a| density_weight(median / a).max(1.0)).collect()
}

/// [`parameterise`], with `weights` (checked) when given.
fn map(
    mesh: &ClosedMesh,
    weights: Option<&[f64]>,
    options: &SphereParamOptions,
) -> Result<SphereParam, Error> {
    let mut h = Hierarchy::new(mesh, weights);
    h.simplify()?;
    let n = mesh.positions.len();
    let mut sphere = vec![DVec3::ZERO; n];
    base(&h, &mut sphere)?;
    relax(&h, &mut sphere, options.sweeps.max(1) * 4);
    let levels = h.level_starts.len();
    let mut present = 4usize;
    let mut last_relaxed = 4usize;
    let collapses = std::mem::take(&mut h.collapses);
    for level in (0..levels).rev() {
        let start = h.level_starts[level];
        let end = if level + 1 < levels { h.level_starts[level + 1] } else { collapses.len() };
        if present > BATCH_ABOVE {
            // A round's collapses were independent (no two of its vertices neighbours), so
            // its splits can all be made first and their vertices placed and settled in
            // parallel: each reads only its own ring, which no other vertex of the round is
            // in. (One split at a time would also settle the vertex each came from; here those
            // settle in the sweeps below.)
            let fine = present > options.fine_vertices;
            let batch = &collapses[start..end];
            for &c in batch.iter().rev() {
                h.split(c);
            }
            let placed: Vec<Option<DVec3>> = batch
                .par_iter()
                .with_min_len(64)
                .map(|c| place(&h, &sphere, c.v, c.u, fine))
                .collect();
            for (c, x) in batch.iter().zip(placed) {
                let Some(x) = x else {
                    return Err(Error::Topology {
                        what: "a vertex could not be placed on the sphere without a fold"
                            .to_owned(),
                    });
                };
                sphere[c.v as usize] = x;
            }
            for _ in 0..if fine { 1 } else { 3 } {
                let settled: Vec<Option<(DVec3, f64)>> = batch
                    .par_iter()
                    .with_min_len(64)
                    .map(|c| relax_vertex(&h, &sphere, c.v))
                    .collect();
                for (c, y) in batch.iter().zip(settled) {
                    if let Some((y, _)) = y {
                        sphere[c.v as usize] = y;
                    }
                }
            }
            present += batch.len();
            if fine {
                continue;
            }
        } else {
            for &c in collapses[start..end].iter().rev() {
                h.split(c);
                let fine = present > options.fine_vertices;
                let Some(x) = place(&h, &sphere, c.v, c.u, fine) else {
                    return Err(Error::Topology {
                        what: "a vertex could not be placed on the sphere without a fold"
                            .to_owned(),
                    });
                };
                sphere[c.v as usize] = x;
                // Settle the new vertex and the one it came from at once, so that no triangle
                // stays a sliver for the next splits to subdivide.
                let (iters, which) = if fine { (1, 1) } else { (3, 2) };
                for _ in 0..iters {
                    for &w in &[c.v, c.u][..which] {
                        if let Some((y, _)) = relax_vertex(&h, &sphere, w) {
                            sphere[w as usize] = y;
                        }
                    }
                }
                present += 1;
            }
        }
        if 2 * present >= 3 * last_relaxed {
            let sweeps = if present > options.fine_vertices { 0 } else { options.sweeps };
            relax(&h, &mut sphere, sweeps);
            last_relaxed = present;
        }
    }
    relax(&h, &mut sphere, options.final_sweeps);
    let quality = measure(mesh, &sphere, levels, h.forced);
    if quality.folded_triangles > 0 {
        return Err(Error::Topology {
            what: format!("the spherical map folds {} triangles over", quality.folded_triangles),
        });
    }
    let across = triangle_neighbours(&mesh.triangles);
    Ok(SphereParam { mesh: mesh.clone(), sphere, across, quality })
}

/// Stretch efficiency, area ratio and folds of a map.
fn measure(mesh: &ClosedMesh, sphere: &[DVec3], levels: usize, forced: usize) -> ParamQuality {
    let (mut e, mut area_s, mut area_p) = (0.0, 0.0, 0.0);
    let mut folded = 0;
    let mut ratios = Vec::with_capacity(mesh.triangles.len());
    let mean_area = mesh.area() / mesh.triangles.len().max(1) as f64;
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|k| sphere[k as usize]);
        let [pa, pb, pc] = t.map(|k| mesh.positions[k as usize]);
        let ap = 0.5 * (pb - pa).cross(pc - pa).length();
        let n = (b - a).cross(c - a);
        if n.dot(a + b + c) <= 0.0 || n.length_squared() == 0.0 {
            folded += 1;
            continue;
        }
        let as_ = 0.5 * n.length();
        let l2 =
            [(pb - pc).length_squared(), (pc - pa).length_squared(), (pa - pb).length_squared()];
        // The stretch of the map from the flat triangle abc itself (|n| rather than the
        // barrier's det).
        let num =
            l2[0] * (b - a).dot(c - a) + l2[1] * (c - b).dot(a - b) + l2[2] * (a - c).dot(b - c);
        e += 0.5 * ap * num / n.length_squared();
        area_s += as_;
        area_p += ap;
        if ap > 1e-6 * mean_area {
            ratios.push(as_ / ap);
        }
    }
    // A map with the same stretch everywhere has σ₁ = σ₂ = √(area_p / area_s), so E equals
    // area_p · area_p / area_s; the efficiency is that over E.
    let efficiency = if e > 0.0 { (area_p * area_p / area_s / e).min(1.0) } else { 0.0 };
    let (lo, hi) =
        ratios.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &r| (lo.min(r), hi.max(r)));
    ParamQuality {
        levels,
        forced_collapses: forced,
        stretch_efficiency: efficiency,
        area_ratio: if lo > 0.0 { hi / lo } else { f64::INFINITY },
        folded_triangles: folded,
    }
}

impl SphereParam {
    /// The mesh parameterised.
    #[must_use]
    pub const fn mesh(&self) -> &ClosedMesh {
        &self.mesh
    }

    /// The point on the unit sphere of each vertex.
    #[must_use]
    pub fn sphere(&self) -> &[DVec3] {
        &self.sphere
    }

    /// How good the map is.
    #[must_use]
    pub const fn quality(&self) -> ParamQuality {
        self.quality
    }
}

#[cfg(test)]
mod tests {
    use super::relax::{face_energy, face_energy_grad};
    use super::*;

    /// The analytic gradient and Hessian of a face's energy against central differences.
    #[test]
    fn face_energy_derivatives_match_differences() {
        let a = DVec3::new(0.1, 0.05, 1.0).normalize();
        let b = DVec3::new(0.4, 0.0, 1.0).normalize();
        let c = DVec3::new(0.1, 0.35, 1.0).normalize();
        let (area, l2, shape) = (0.7, [0.9, 1.3, 0.6], 0.2);
        let (e, g, hess) = face_energy_grad(a, b, c, area, l2, shape);
        assert!((e - face_energy(a, b, c, area, l2, shape)).abs() < 1e-12 * e, "energy");
        let h = 1e-6;
        for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
            let (ep, gp, _) = face_energy_grad(a + h * axis, b, c, area, l2, shape);
            let (em, gm, _) = face_energy_grad(a - h * axis, b, c, area, l2, shape);
            let dg = (ep - em) / (2.0 * h);
            assert!(
                (dg - g.dot(axis)).abs() < 1e-6 * g.length(),
                "gradient along {axis}: {dg} vs {}",
                g.dot(axis)
            );
            let dh = (gp - gm) / (2.0 * h);
            let column = hess * axis;
            assert!(
                (dh - column).length() < 1e-5 * column.length().max(1.0),
                "Hessian column {axis}: {dh} vs {column}"
            );
        }
        // Wound the wrong way: infinite.
        assert_eq!(face_energy(a, c, b, area, l2, shape), f64::INFINITY);
    }

    /// A map whose triangles keep the surface's shape and have areas in proportion has
    /// stretch efficiency 1.
    #[test]
    fn uniform_stretch_has_efficiency_one() {
        // The regular octahedron on the unit sphere is its own map.
        let p = [DVec3::X, DVec3::Y, DVec3::Z, DVec3::NEG_X, DVec3::NEG_Y, DVec3::NEG_Z];
        let t = vec![
            [0, 1, 2],
            [1, 3, 2],
            [3, 4, 2],
            [4, 0, 2],
            [1, 0, 5],
            [3, 1, 5],
            [4, 3, 5],
            [0, 4, 5],
        ];
        let mesh = ClosedMesh {
            positions: p.iter().map(|x| *x * 3.0).collect(),
            triangles: t,
            scan_vertex: (0..6).collect(),
            filled: vec![false; 8],
            repair: hi_scan::repair::Repair::default(),
        };
        let q = measure(&mesh, &p, 0, 0);
        assert!((q.stretch_efficiency - 1.0).abs() < 1e-12, "{q:?}");
        assert!((q.area_ratio - 1.0).abs() < 1e-12, "{q:?}");
        assert_eq!(q.folded_triangles, 0);
    }
}
