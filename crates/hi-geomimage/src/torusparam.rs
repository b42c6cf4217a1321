// SPDX-License-Identifier: MIT
//! A parameterisation of a closed genus-1 mesh over the flat torus R²/Z², and the geometry
//! image sampled from it (beyond §5.3: a harmonic tensor-product surface is periodic in u and
//! v, so it *is* a torus; a genus-1 scan mapped onto the flat torus is fitted whole, with no cut
//! and no crack).
//!
//! **The map** (Gortler, Gotsman and Thurston 2006, "Discrete one-forms on meshes and
//! applications to 3D mesh parameterization"):
//! 1. a homology basis by tree–cotree (Eppstein 2003, "Dynamic generators of topologically
//!    embedded graphs"; Erickson and Whittlesey 2005, "Greedy optimal homotopy and homology
//!    generators"): a spanning tree T of the mesh's edges, a spanning tree C of the dual graph
//!    through edges not in T; exactly 2g = 2 edges e₁, e₂ are in neither, and γᵢ, eᵢ closed by
//!    the path through T, are the generators;
//! 2. the dual integer cohomology basis: the closed 1-forms ζ₁, ζ₂ with ζᵢ(eⱼ) = δᵢⱼ, 0 on T,
//!    and on C whatever makes the sum around every triangle vanish (found from C's leaves
//!    inwards), so ∮γⱼ ζᵢ = δᵢⱼ; ω = (ζ₁, ζ₂) gives each edge ij an integer jump kᵢⱼ ∈ Z²;
//! 3. the harmonic map u : V → R² minimising Σ wᵢⱼ |uⱼ + kᵢⱼ − uᵢ|² over the edges, w the
//!    cotangent weights clamped positive (see the `laplace` module): L u = b with
//!    bᵢ = Σⱼ wᵢⱼ kᵢⱼ, one Laplacian solve with two right-hand sides, one vertex held. The
//!    1-form du + ω is harmonic with periods δᵢⱼ, so triangle ijk lifted to
//!    (uᵢ, uⱼ + kᵢⱼ, uₖ + kᵢₖ) tiles R² by the translates of Z²; with positive weights the
//!    map to R²/Z² is an embedding (Gortler et al., theorem 1.2) — checked, every triangle
//!    counter-clockwise, total area 1;
//! 4. the least sheared basis: a harmonic map is an affine image of the conformal one, whose
//!    periods a₁, a₂ have the Gram matrix ∝ G⁻¹, G the Gram matrix of the two harmonic forms
//!    under the Dirichlet inner product (G(a, b) = Σ wᵢⱼ hᵃᵢⱼ hᵇᵢⱼ over the edges). Gauss's
//!    reduction of G⁻¹ gives B ∈ SL₂(Z) with |a₁| ≤ |a₂| and |a₁·a₂| ≤ |a₁|²/2; u becomes
//!    B⁻¹u and the jumps B⁻¹k (still integers), the same torus seen through the shortest basis;
//! 5. orientation: a triangle wound counter-clockwise (outward normal) maps to a positively
//!    oriented (u, v) triangle — u and v are swapped first if the map came out the other
//!    way — so pᵤ × pᵥ of the harmonic surface through the image points the way the mesh's
//!    normals do.
//!
//! **The relaxation** (on by default) evens out the area the map gives each part of the
//! surface: a sphere with a thin handle (a mug, a kitten) is otherwise squeezed into a small
//! part of the image. The stretch is measured on the domain scaled to the image's shape,
//! (αu, v) with α the aspect below: an image of that shape has square texels, so what is left
//! is the map's own anisotropy and area distortion (a long thin tube is not penalised for being
//! long). First rounds of reweighting (Yoshizawa, Belyaev and Seidel 2004, "A fast and simple
//! stretch-minimizing mesh parameterization"): each triangle's weight factor divided by its
//! RMS stretch, then the same solve, warm-started (a multigrid hierarchy built for each
//! round's weights); each round's map is again harmonic for positive weights, so again an
//! embedding, and a round is kept only if it raises the L² stretch efficiency (the rounds end
//! after one that gains less than 2 %: the next tends to overshoot). The rounds' solves share
//! a budget of six times the iterations of the harmonic map's (192 at least): a round that
//! does not reach a map without folds within it is dropped and ends the rounds, the map kept
//! the last bijection that lowered the stretch (see below). Then Newton moves of single
//! vertices on the L² stretch (Sander, Snyder, Gortler and Hoppe 2001), which is a barrier
//! against folds, as [`sphereparam`](crate::sphereparam) does on the sphere. The map from the
//! surface to R²/Z² stays a bijection throughout (positively oriented triangles of total area
//! 1 cover the torus once). The basis is reduced once more by the mean metric of the final
//! map.
//!
//! **What a parameterisation costs, at most** (here and in [`discparam`](crate::discparam)).
//! The bounds matter on the meshes the fit takes apart, the zero sets of scans: slivers, holes
//! filled by fans of high valence, long thin parts. The harmonic map squeezes a long thin
//! part (a finger of a ragged sheet, a tentacle of a torus) exponentially along its length,
//! down to triangles 10⁻¹⁵ of the mean in area on a real scan, so that they fold at a
//! tolerance of 10⁻⁸ and the solve is pushed on to 10⁻¹² or further; conjugate gradients
//! preconditioned by multigrid (above 2000 free vertices) take a few iterations per decade of
//! the residual at any size. Then:
//! - the harmonic solve, fold tightening included, takes at most `max_iterations` iterations,
//!   else it is an error (there is no map to fall back to); what it took is
//!   [`FlatReport::harmonic_iterations`];
//! - the reweighting rounds share a budget of six times as many iterations (192 at least),
//!   each round's solve also capped by `max_iterations`. Each round builds a multigrid
//!   hierarchy for its own weights: they change by up to 10³ per triangle and round, unevenly
//!   where the map squeezes, and a hierarchy built for the first round's weights took a
//!   hundred times the iterations (tens of thousands on the largest part of a scan's zero
//!   set). A round whose solve does not reach a map without folds within what is left of the
//!   budget is dropped, and ends the rounds;
//! - however the rounds end ([`FlatReport::rounds_end`]), the map kept is the last that was a
//!   bijection and lowered the stretch: the harmonic map, a bijection for positive weights, if
//!   no round was kept;
//! - the Newton sweeps are `sweeps` passes over the vertices, each move a line search of at
//!   most 31 evaluations of the vertex's triangles (linear in its valence), and keep the map a
//!   bijection (the stretch is a barrier);
//! - the rest is about linear in the mesh's size (a disc's corners: at most 2²⁴ checks of a
//!   placement against an edge that cuts the boundary, however long the boundary).
//!
//! **The image.** [`TorusParam::aspect`] is the rows/cols that makes texels square on the
//! surface on average, √(∫|pᵤ|² / ∫|pᵥ|²) over the torus: for the conformal map
//! |a₁|/|a₂|. Texel (i, j) of [`TorusParam::image`] is the surface point at
//! (u, v) = (i/rows, j/cols): each lifted triangle is rasterised over the periodic texel grid,
//! each texel taken by the triangle it lies deepest in, and the position interpolated
//! barycentrically.

use glam::{DVec2, DVec3, IVec2};

use crate::flat::{
    self, FlatMap, Freedom, RelaxOptions, Relaxation, count_folds, form_rhs, inverse, reduce,
    solve_until_embedded,
};
pub use crate::flat::{FlatImage, FlatQuality, FlatReport, RoundsEnd};
use crate::laplace::{CgOptions, Laplacian, NONE, Topology, head};
use crate::{Error, MAX_TEXELS};

/// The settings of [`parameterise_torus`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TorusParamOptions {
    /// Reweighting rounds at most (one Laplacian solve each; the rounds stop at the first
    /// that does not lower the stretch, after one that lowers it by less than 2 %, or at the
    /// first whose solve runs out of the rounds' iteration budget, see `max_iterations`).
    /// Default 8; 0 with `sweeps` 0 keeps the harmonic map.
    pub rounds: usize,
    /// Newton sweeps over every vertex after the rounds. Default 2.
    pub sweeps: usize,
    /// The relative residual at which the harmonic map's Laplacian solve stops (pushed down
    /// to 10⁻¹⁴ while the map still folds; the relaxation rounds stop at 10⁻⁵ or this, if
    /// looser), in (0, 0.01]. Default 10⁻⁸.
    pub tolerance: f64,
    /// Conjugate-gradient iterations at most for the harmonic map's solve, fold tightening
    /// included (then an error), and for each reweighting round's; the rounds' solves share
    /// at most six times what the harmonic map's took (192 at least), and a round that runs
    /// out is dropped. Default 100 000.
    pub max_iterations: usize,
}

impl Default for TorusParamOptions {
    fn default() -> Self {
        Self { rounds: 8, sweeps: 2, tolerance: 1e-8, max_iterations: 100_000 }
    }
}

impl TorusParamOptions {
    /// The harmonic map alone: no relaxation.
    #[must_use]
    pub fn harmonic() -> Self {
        Self { rounds: 0, sweeps: 0, ..Self::default() }
    }

    pub(crate) fn check(&self) -> Result<CgOptions, Error> {
        if !(self.tolerance > 0.0 && self.tolerance <= 0.01) {
            return Err(Error::InvalidOption {
                name: "tolerance",
                value: self.tolerance,
                expected: "in (0, 0.01]",
            });
        }
        if self.max_iterations == 0 {
            return Err(Error::InvalidOption {
                name: "max_iterations",
                value: 0.0,
                expected: "at least 1",
            });
        }
        Ok(CgOptions::new(self.tolerance, self.max_iterations))
    }
}

/// A parameterisation of a genus-1 mesh over the flat torus R²/Z².
#[derive(Clone, Debug)]
pub struct TorusParam {
    positions: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    filled: Vec<bool>,
    map: FlatMap,
    aspect: f64,
    report: FlatReport,
}

/// The integer cohomology basis ω = (ζ₁, ζ₂) of a closed genus-1 mesh, one value per
/// half-edge (the twin's is its negative), by tree–cotree; see the module documentation.
pub(crate) fn cohomology_basis(
    topology: &Topology,
    triangles: &[[u32; 3]],
) -> Result<Vec<IVec2>, Error> {
    let n = topology.vertex_count();
    let halves = topology.twin.len();
    let twin = |h: u32| topology.twin[h as usize];
    // The primal tree, breadth first from vertex 0.
    let mut in_tree = vec![false; halves];
    let mut seen = vec![false; n];
    let mut queue = std::collections::VecDeque::with_capacity(n);
    seen[0] = true;
    queue.push_back(0u32);
    while let Some(v) = queue.pop_front() {
        for &h in topology.outgoing(v) {
            let w = head(triangles, h);
            if !seen[w as usize] {
                seen[w as usize] = true;
                in_tree[h as usize] = true;
                in_tree[twin(h) as usize] = true;
                queue.push_back(w);
            }
        }
    }
    // The dual tree through the other edges, breadth first from triangle 0.
    let faces = triangles.len();
    let mut in_cotree = vec![false; halves];
    let mut parent = vec![NONE; faces];
    let mut order = Vec::with_capacity(faces);
    let mut reached = vec![false; faces];
    reached[0] = true;
    order.push(0u32);
    let mut next = 0;
    while next < order.len() {
        let f = order[next];
        next += 1;
        for h in 3 * f..3 * f + 3 {
            if in_tree[h as usize] {
                continue;
            }
            let g = twin(h) / 3;
            if !reached[g as usize] {
                reached[g as usize] = true;
                in_cotree[h as usize] = true;
                in_cotree[twin(h) as usize] = true;
                parent[g as usize] = twin(h);
                order.push(g);
            }
        }
    }
    let left: Vec<u32> = (0..halves as u32)
        .filter(|&h| h < twin(h) && !in_tree[h as usize] && !in_cotree[h as usize])
        .collect();
    if left.len() != 2 {
        return Err(Error::Topology {
            what: format!("tree–cotree left {} edges over, where a torus leaves 2", left.len()),
        });
    }
    let mut form = vec![IVec2::ZERO; halves];
    for (h, e) in left.iter().zip([IVec2::X, IVec2::Y]) {
        form[*h as usize] = e;
        form[twin(*h) as usize] = -e;
    }
    // From the dual tree's leaves inwards: each triangle's edge to its parent closes it.
    for &g in order[1..].iter().rev() {
        let p = parent[g as usize];
        let mut sum = IVec2::ZERO;
        for h in 3 * g..3 * g + 3 {
            if h != p {
                sum += form[h as usize];
            }
        }
        form[p as usize] = -sum;
        form[twin(p) as usize] = sum;
    }
    Ok(form)
}

/// Each corner's translation from a form: corner 0 at 0, the others by the form along the
/// triangle's edges.
fn offsets_from_form(triangles: &[[u32; 3]], form: &[IVec2]) -> Vec<[IVec2; 3]> {
    (0..triangles.len())
        .map(|f| {
            let a = form[3 * f];
            [IVec2::ZERO, a, a + form[3 * f + 1]]
        })
        .collect()
}

/// Parameterises a closed, oriented, genus-1 mesh over the flat torus; see the module
/// documentation. `filled` flags the triangles that were added to close holes (carried into
/// the image's mask).
///
/// # Examples
///
/// ```
/// use std::f64::consts::TAU;
/// use glam::DVec3;
/// use hi_geomimage::torusparam::{TorusParamOptions, parameterise_torus};
///
/// // A torus of revolution, radii 1 and 0.4, as a 24 × 12 grid wound outward.
/// let (m, n) = (24, 12);
/// let mut p = Vec::new();
/// for i in 0..m {
///     for j in 0..n {
///         let (a, b) = (TAU * i as f64 / m as f64, TAU * j as f64 / n as f64);
///         let rho = 1.0 + 0.4 * b.cos();
///         p.push(DVec3::new(rho * a.cos(), rho * a.sin(), 0.4 * b.sin()));
///     }
/// }
/// let at = |i: usize, j: usize| ((i % m) * n + j % n) as u32;
/// let mut t = Vec::new();
/// for i in 0..m {
///     for j in 0..n {
///         t.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
///         t.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
///     }
/// }
/// let param = parameterise_torus(&p, &t, &vec![false; t.len()], &TorusParamOptions::default())?;
/// assert_eq!(param.quality().folded_triangles, 0);
/// // The short period goes around the tube: fewer rows than columns.
/// assert!(param.aspect() < 1.0);
/// // Every texel lies on the mesh, so near the torus (within the grid's chord error).
/// let image = param.image(16, 40)?;
/// for x in image.image.texels() {
///     let tube = (x.x.hypot(x.y) - 1.0).hypot(x.z);
///     assert!((tube - 0.4).abs() < 0.04);
/// }
/// # Ok::<(), hi_geomimage::Error>(())
/// ```
///
/// # Errors
///
/// [`Error::Topology`] with a one-line reason if `filled` does not have one flag per
/// triangle, there are fewer than 14 triangles (the fewest a torus takes), the mesh is not
/// closed, not 2-manifold or not consistently oriented, has more than one part, or is not of
/// genus 1 (the genus found is named), or if a Laplacian solve fails;
/// [`Error::NonFinite`] for a vertex with a NaN or infinite coordinate;
/// [`Error::InvalidOption`] for a tolerance outside (0, 0.01] or no iterations.
pub fn parameterise_torus(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    filled: &[bool],
    options: &TorusParamOptions,
) -> Result<TorusParam, Error> {
    let cg = options.check()?;
    let topology = flat::check_input(positions, triangles, filled, 14, "torus")?;
    check_torus(&topology)?;
    let n = positions.len();
    let mut form = cohomology_basis(&topology, triangles)?;
    let mut lap = Laplacian::new(&topology, triangles);
    lap.set_cotangent_weights(positions, triangles, None);
    let fixed: Vec<bool> = (0..n).map(|i| i == 0).collect();
    let b = form_rhs(&lap, &form);
    let mut x = vec![[0.0; 2]; n];
    let offsets = offsets_from_form(triangles, &form);
    // Folds against the map's own orientation (it may come out clockwise).
    let folds = |x: &[[f64; 2]]| oriented_folds(triangles, &offsets, x);
    let (harmonic_iterations, solved) = solve_until_embedded(
        &lap,
        Some(&fixed),
        &b,
        &mut x,
        cg,
        lap.preconditioner(Some(&fixed), cg).as_ref(),
        folds,
    );
    let mut residual = solved?.residual;
    let mut iterations = harmonic_iterations;
    let mut map = FlatMap { uv: x.iter().map(|p| DVec2::from_array(*p)).collect(), offsets };
    let area: f64 = (0..triangles.len()).map(|f| 0.5 * flat::det(map.corners(triangles, f))).sum();
    if area < 0.0 {
        // Clockwise: swap u and v.
        let swap = [[0, 1], [1, 0]];
        map.transform(swap);
        form.iter_mut().for_each(|k| *k = IVec2::new(k.y, k.x));
    }
    let folded = count_folds(triangles, &map, None);
    if folded > 0 || (area.abs() - 1.0).abs() > 1e-6 {
        return Err(Error::Topology {
            what: format!(
                "the harmonic map is not an embedding: {folded} triangles fold over, (u, v) area {:.6} instead of 1",
                area.abs()
            ),
        });
    }
    // The Gram matrix of the two harmonic forms, and the reduction of the periods' form G⁻¹.
    let gram = form_gram(&lap, &map, &form);
    let periods = [gram[2], -gram[1], gram[0]];
    let basis = reduce(periods);
    apply_basis(&mut map, &mut form, basis);
    let (harmonic, _) = flat::quality(positions, triangles, &map, None);
    let relaxation = Relaxation::new(positions, triangles, &topology, vec![Freedom::Free; n], None);
    let settings =
        RelaxOptions { rounds: options.rounds, sweeps: options.sweeps, cg, harmonic_iterations };
    let done = relaxation.run(
        &mut lap,
        Some(&fixed),
        &|lap: &Laplacian| form_rhs(lap, &form),
        &mut map,
        settings,
    );
    iterations += done.iterations;
    if let Some(r) = done.residual {
        residual = r;
    }
    let (_, metric) = flat::quality(positions, triangles, &map, None);
    let basis = reduce(metric);
    apply_basis(&mut map, &mut form, basis);
    let (relaxed, metric) = flat::quality(positions, triangles, &map, None);
    if relaxed.folded_triangles > 0 {
        return Err(Error::Topology {
            what: format!("the relaxed map folds {} triangles over", relaxed.folded_triangles),
        });
    }
    map.wrap(triangles);
    Ok(TorusParam {
        positions: positions.to_vec(),
        triangles: triangles.to_vec(),
        filled: filled.to_vec(),
        map,
        aspect: flat::aspect_of(metric),
        report: FlatReport {
            harmonic,
            relaxed,
            rounds: done.rounds,
            rounds_end: done.end,
            sweeps: done.sweeps,
            solve_iterations: iterations,
            harmonic_iterations,
            solve_residual: residual,
        },
    })
}

/// The first check of [`parameterise_torus`]: the mesh is closed and of genus 1.
fn check_torus(topology: &Topology) -> Result<(), Error> {
    if !topology.boundary.is_empty() {
        return Err(Error::Topology {
            what: format!(
                "the mesh is not closed: {} edges have a triangle on one side only, a torus has none",
                topology.boundary.len()
            ),
        });
    }
    let chi = topology.euler_characteristic();
    if chi != 0 {
        let genus = (2 - chi) as f64 / 2.0;
        return Err(Error::Topology {
            what: format!(
                "the mesh has genus {genus} (χ = V − E + F = {chi}); a torus has genus 1"
            ),
        });
    }
    Ok(())
}

/// The folds of the map with coordinates `x` and corner `offsets`, against the map's own
/// orientation (it may come out clockwise).
fn oriented_folds(triangles: &[[u32; 3]], offsets: &[[IVec2; 3]], x: &[[f64; 2]]) -> usize {
    let map = FlatMap {
        uv: x.iter().map(|p| DVec2::from_array(*p)).collect(),
        offsets: offsets.to_vec(),
    };
    let dets: Vec<f64> =
        (0..triangles.len()).map(|f| flat::det(map.corners(triangles, f))).collect();
    let sign = dets.iter().sum::<f64>().signum();
    dets.iter().filter(|&&d| d * sign <= 0.0).count()
}

/// The Gram matrix [G₁₁, G₁₂, G₂₂] of the two harmonic forms of the map (its coordinates
/// `map` plus the integer `form`) in the Laplacian's inner product.
fn form_gram(lap: &Laplacian, map: &FlatMap, form: &[IVec2]) -> [f64; 3] {
    let n = lap.size();
    let mut gram = [0.0; 3];
    for i in 0..n {
        let (cols, ws, sides) = lap.row(i);
        for ((&j, &w), s) in cols.iter().zip(ws).zip(sides) {
            if (j as usize) < i {
                continue;
            }
            let h = map.uv[j as usize] - map.uv[i] + form[s[0] as usize].as_dvec2();
            gram[0] += w * h.x * h.x;
            gram[1] += w * h.x * h.y;
            gram[2] += w * h.y * h.y;
        }
    }
    gram
}

/// Changes to the basis B (columns, determinant 1): u ↦ B⁻¹u, and the same for the jumps.
fn apply_basis(map: &mut FlatMap, form: &mut [IVec2], basis: [[i32; 2]; 2]) {
    if basis == [[1, 0], [0, 1]] {
        return;
    }
    let inv = inverse(basis);
    map.transform(inv);
    for k in form.iter_mut() {
        *k = IVec2::new(inv[0][0] * k.x + inv[1][0] * k.y, inv[0][1] * k.x + inv[1][1] * k.y);
    }
}

impl TorusParam {
    /// The vertex positions.
    #[must_use]
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// The triangles.
    #[must_use]
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Each vertex's (u, v), in [0, 1)².
    #[must_use]
    pub fn uv(&self) -> &[DVec2] {
        &self.map.uv
    }

    /// Each triangle corner's integer translation: triangle f's (u, v) triangle is
    /// `uv[t[k]] + offsets[f][k]` for k = 0, 1, 2, in one piece across the square's seams.
    #[must_use]
    pub fn offsets(&self) -> &[[IVec2; 3]] {
        &self.map.offsets
    }

    /// The flags of the triangles added to close holes, as given.
    #[must_use]
    pub fn filled(&self) -> &[bool] {
        &self.filled
    }

    /// Triangle f's (u, v) triangle, lifted in one piece (see [`TorusParam::offsets`]);
    /// counter-clockwise for every triangle of a valid map.
    ///
    /// # Panics
    ///
    /// If f is not a triangle index.
    #[must_use]
    pub fn uv_triangle(&self, f: usize) -> [DVec2; 3] {
        self.map.corners(&self.triangles, f)
    }

    /// rows / cols for texels that are square on the surface on average:
    /// √(∫|pᵤ|² / ∫|pᵥ|²) over the torus, p the map from (u, v) to the surface. Below 1
    /// (u follows the shorter period) for the reduced basis of a conformal map; for a torus of
    /// revolution with radii R > r, r/√(R² − r²) before the relaxation.
    #[must_use]
    pub const fn aspect(&self) -> f64 {
        self.aspect
    }

    /// An image size of about `texels` texels with rows / cols ≈ [`TorusParam::aspect`]
    /// (each side at least 2).
    #[must_use]
    pub fn resolution(&self, texels: usize) -> (usize, usize) {
        resolution(self.aspect, texels.min(MAX_TEXELS) as f64, 0)
    }

    /// The quality of the final map.
    #[must_use]
    pub const fn quality(&self) -> FlatQuality {
        self.report.relaxed
    }

    /// The quality before and after the relaxation, and what the solves took.
    #[must_use]
    pub const fn report(&self) -> FlatReport {
        self.report
    }

    /// The geometry image: texel (i, j) is the surface point at (u, v) = (i/rows, j/cols).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidResolution`] for fewer than 2 rows or columns or more than
    /// [`MAX_TEXELS`] texels.
    pub fn image(&self, rows: usize, cols: usize) -> Result<FlatImage, Error> {
        flat::rasterise(
            &self.positions,
            &self.triangles,
            &self.filled,
            &self.map,
            None,
            rows,
            cols,
            true,
        )
    }
}

/// rows × cols ≈ texels with (rows − extra) / (cols − extra) ≈ aspect, each side at least 2.
pub(crate) fn resolution(aspect: f64, texels: f64, extra: usize) -> (usize, usize) {
    let e = extra as f64;
    let cols = (texels / aspect).sqrt().round().max(2.0);
    let rows = (aspect * (cols - e) + e).round().max(2.0);
    (rows as usize, cols as usize)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::laplace::tail;

    fn torus(m: usize, n: usize) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let tau = std::f64::consts::TAU;
        let mut p = Vec::new();
        for i in 0..m {
            for j in 0..n {
                let (a, b) = (tau * i as f64 / m as f64, tau * j as f64 / n as f64);
                let rho = 1.0 + 0.4 * b.cos();
                p.push(DVec3::new(rho * a.cos(), rho * a.sin(), 0.4 * b.sin()));
            }
        }
        let at = |i: usize, j: usize| ((i % m) * n + j % n) as u32;
        let mut t = Vec::new();
        for i in 0..m {
            for j in 0..n {
                t.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                t.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
        (p, t)
    }

    /// The vertices of half-edge h.
    fn ends(triangles: &[[u32; 3]], h: u32) -> (u32, u32) {
        (tail(triangles, h), head(triangles, h))
    }

    /// The tree–cotree forms are closed (they sum to 0 around every triangle), antisymmetric,
    /// and have the periods δᵢⱼ around the grid's two generating loops.
    #[test]
    fn cohomology_basis_is_closed_with_unit_periods() {
        let (m, n) = (9, 7);
        let (p, t) = torus(m, n);
        let topo = Topology::new(p.len(), &t).unwrap();
        let form = cohomology_basis(&topo, &t).unwrap();
        for f in 0..t.len() {
            assert_eq!(form[3 * f] + form[3 * f + 1] + form[3 * f + 2], IVec2::ZERO, "closed");
        }
        for h in 0..form.len() {
            assert_eq!(form[h], -form[topo.twin[h] as usize], "antisymmetric");
        }
        // The value of the form on the directed edge a → b.
        let along = |a: u32, b: u32| {
            let h = (0..form.len() as u32).find(|&h| ends(&t, h) == (a, b)).unwrap();
            form[h as usize]
        };
        let at = |i: usize, j: usize| ((i % m) * n + j % n) as u32;
        let around_axis: IVec2 = (0..m).map(|i| along(at(i, 0), at(i + 1, 0))).sum();
        let around_tube: IVec2 = (0..n).map(|j| along(at(0, j), at(0, j + 1))).sum();
        // The two periods form a basis of Z²: determinant ±1.
        let d = around_axis.x * around_tube.y - around_axis.y * around_tube.x;
        assert_eq!(d.abs(), 1, "periods {around_axis} and {around_tube}");
    }
}
