// SPDX-License-Identifier: MIT
//! A parameterisation of an open mesh that is a topological disc over the unit square
//! [0, 1]², the whole-sample geometry image sampled from it, and its mirror doubling into a
//! doubly periodic image (beyond §5.3: an open, single-sheet scan — a face, a terrain, a part
//! of a body — as a harmonic surface).
//!
//! **The map** (Tutte 1963, "How to draw a graph"; Floater 1997, "Parametrization and smooth
//! approximation of surface triangulations", and 2003, "One-to-one piecewise linear mappings
//! over triangulations"):
//! 1. four boundary vertices become the square's corners, so the boundary splits into four
//!    arcs of about equal length. Two kinds of placement are weighed: corners a quarter of the
//!    boundary's length L apart (from every starting vertex, each snapped to the nearest
//!    vertex), and, where the boundary has them, its four sharpest convex corners (the turning
//!    summed over L/32 of boundary either way at least 45°, no arc shorter than L/8 or longer
//!    than 3L/8). Of these the placement is taken that leaves fewest interior edges with both
//!    ends on one side (such an edge flattens what it cuts off, see below), then the one that
//!    turns most at its corners: a rectangle keeps its corners at the square's, a round or
//!    ragged boundary gets arcs of equal length;
//! 2. each arc goes onto a side of the square by arc length, counter-clockwise: corner 0 at
//!    (0, 0), 1 at (1, 0), 2 at (1, 1), 3 at (0, 1), as the boundary runs with the mesh on its
//!    left (counter-clockwise seen from the side the normals point to);
//! 3. the interior vertices solve L u = 0 with the boundary held, L the cotangent Laplacian
//!    with weights clamped positive (see the `laplace` module); by Floater's theorem each
//!    interior vertex is a convex combination of its neighbours and the map is one-to-one onto
//!    the square, every triangle counter-clockwise, so pᵤ × pᵥ of the surface through the
//!    image points the way the mesh's normals do. The one exception is an interior edge
//!    joining two vertices of one side: the part of the mesh it cuts off lies flat on that side
//!    (reported as `flat_triangles`, left out of the image);
//! 4. the stretch relaxation of [`torusparam`](crate::torusparam) (reweighting rounds with
//!    the boundary held, then Newton moves with the boundary vertices sliding along their
//!    sides between their neighbours, the corners fixed) evens out the area distortion, within
//!    the same iteration budget, keeping the last map that was a bijection (see
//!    [`torusparam`](crate::torusparam) for what a parameterisation costs at most).
//!
//! A ragged boundary defeats the fixed square where it reaches out in long thin fingers: each
//! finger's boundary lies on one side of the square, and the harmonic map squeezes the
//! finger against that side exponentially along its length (on the largest part of the zero
//! set of a real scan, triangles 10⁻¹⁵ of the mean in (u, v) area, a stretch efficiency of
//! 10⁻¹⁵ that the relaxation raises to 10⁻⁶); the map stays a bijection, but the image gives
//! such fingers next to no texels.
//!
//! **The image.** Texel (i, j) of [`DiscParam::image`] is the surface point at
//! (u, v) = (i/(rows − 1), j/(cols − 1)): whole-sample, its first and last rows and columns lie
//! on the mesh's boundary. [`reflect_periodic`] doubles it into a periodic
//! 2(rows − 1) × 2(cols − 1) image by even reflection — the thesis's own trick for its
//! flattened octahedron — whose harmonic surface is periodic, symmetric about u = ½ and
//! v = ½, and on the quarter u, v ∈ [0, ½] is the open sheet.

mod corners;

use glam::{DVec2, DVec3, IVec2};

use crate::flat::{
    self, Embedded, FlatMap, Freedom, RelaxOptions, Relaxation, solve_until_embedded,
};
pub use crate::flat::{FlatImage, FlatQuality, FlatReport, RoundsEnd};
use crate::laplace::{CgOptions, Laplacian, NONE, Topology, head, tail};
use crate::{Error, GeometryImage, MAX_TEXELS};
use corners::{choose_corners, sides_of};

/// The settings of [`parameterise_disc`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DiscParamOptions {
    /// Reweighting rounds at most (one Laplacian solve each, the boundary held; the rounds
    /// stop at the first that does not lower the stretch, after one that lowers it by less
    /// than 2 %, or at the first whose solve runs out of the rounds' iteration budget, see
    /// `max_iterations`). Default 8; 0 with `sweeps` 0 keeps the harmonic map.
    pub rounds: usize,
    /// Newton sweeps over every vertex after the rounds, boundary vertices sliding along their
    /// sides. Default 2.
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

impl Default for DiscParamOptions {
    fn default() -> Self {
        Self { rounds: 8, sweeps: 2, tolerance: 1e-8, max_iterations: 100_000 }
    }
}

impl DiscParamOptions {
    /// The harmonic (Tutte–Floater) map alone: no relaxation.
    #[must_use]
    pub fn harmonic() -> Self {
        Self { rounds: 0, sweeps: 0, ..Self::default() }
    }

    fn check(&self) -> Result<CgOptions, Error> {
        crate::torusparam::TorusParamOptions {
            rounds: self.rounds,
            sweeps: self.sweeps,
            tolerance: self.tolerance,
            max_iterations: self.max_iterations,
        }
        .check()
    }
}

/// A parameterisation of a disc-like mesh over the unit square.
#[derive(Clone, Debug)]
pub struct DiscParam {
    positions: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    filled: Vec<bool>,
    map: FlatMap,
    flat: Option<Vec<bool>>,
    corners: [u32; 4],
    aspect: f64,
    report: FlatReport,
}

/// Parameterises an open, oriented, 2-manifold mesh with one boundary loop and χ = 1 (a
/// topological disc) over the unit square; see the module documentation. `filled` flags the
/// triangles that were added to close holes (carried into the image's mask).
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::discparam::{DiscParamOptions, parameterise_disc, reflect_periodic};
///
/// // A bumpy 9 × 9 height field over [0, 2] × [0, 1], wound counter-clockwise seen from +z.
/// let n = 9;
/// let p: Vec<DVec3> = (0..n * n)
///     .map(|k| {
///         let (x, y) = (2.0 * (k % n) as f64 / 8.0, (k / n) as f64 / 8.0);
///         DVec3::new(x, y, 0.1 * (x * y).sin())
///     })
///     .collect();
/// let mut t = Vec::new();
/// for i in 0..n - 1 {
///     for j in 0..n - 1 {
///         let a = (i * n + j) as u32;
///         let n = n as u32;
///         t.push([a, a + 1, a + n + 1]);
///         t.push([a, a + n + 1, a + n]);
///     }
/// }
/// let param = parameterise_disc(&p, &t, &vec![false; t.len()], &DiscParamOptions::default())?;
/// assert_eq!(param.quality().folded_triangles, 0);
/// // The corners of the square go to the corners of the grid.
/// let mut corners = param.corner_vertices();
/// corners.sort();
/// assert_eq!(corners, [0, 8, 72, 80]);
/// // Whole-sample: the image's corner texels are the grid's corners.
/// let image = param.image(9, 17)?;
/// let first = image.image.get(0, 0);
/// assert!(corners.iter().any(|&k| (p[k as usize] - first).length() < 1e-12));
/// // A 2 × 1 rectangle: square texels want twice as many samples along its long side.
/// let a = param.aspect();
/// assert!((a.max(1.0 / a) - 2.0).abs() < 0.05);
/// // Doubled by reflection into a periodic image.
/// let doubled = reflect_periodic(&image.image)?;
/// assert_eq!((doubled.rows(), doubled.cols()), (16, 32));
/// assert_eq!(doubled.get(15, 31), image.image.get(1, 1));
/// # Ok::<(), hi_geomimage::Error>(())
/// ```
///
/// # Errors
///
/// [`Error::Topology`] with a one-line reason if `filled` does not have one flag per
/// triangle, the mesh is closed, has more than one boundary loop (how many is named), is not
/// a disc (χ ≠ 1), has fewer than 4 boundary vertices, is not 2-manifold or not consistently
/// oriented, has more than one part, or if a Laplacian solve fails; [`Error::NonFinite`] for a
/// vertex with a NaN or infinite coordinate; [`Error::InvalidOption`] for a tolerance outside
/// (0, 0.01] or no iterations.
pub fn parameterise_disc(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    filled: &[bool],
    options: &DiscParamOptions,
) -> Result<DiscParam, Error> {
    let cg = options.check()?;
    let topology = flat::check_input(positions, triangles, filled, 2, "disc")?;
    let topo_err = |what: String| Err(Error::Topology { what });
    let ring = boundary_ring(&topology, triangles)?;
    let b = ring.len();
    let n = positions.len();
    let mut position_in_ring = ring_positions(&ring, n);
    let dividing = dividing_edges(&topology, triangles, &position_in_ring);
    let normals = boundary_normals(&topology, triangles, positions, &ring);
    let Some(corner_at) = choose_corners(positions, &ring, &normals, &dividing) else {
        return topo_err(
            "no four distinct boundary vertices can be the square's corners".to_owned(),
        );
    };
    // Rotate the ring so that corner 0 is first.
    let ring: Vec<u32> = (0..b).map(|k| ring[(k + corner_at[0]) % b]).collect();
    let rel = corner_at.map(|c| (c + b - corner_at[0]) % b);
    for (k, &v) in ring.iter().enumerate() {
        position_in_ring[v as usize] = k as u32;
    }
    let mut uv = vec![DVec2::splat(0.5); n];
    boundary_on_square(positions, &ring, rel, &mut uv);
    let side_bits = |v: u32| {
        let k = position_in_ring[v as usize];
        if k == NONE { 0 } else { sides_of(k as usize, rel) }
    };
    let flat_sides = collapsed(&topology, triangles, &dividing, &ring, &side_bits);
    let flat: Option<Vec<bool>> = flat_sides.as_ref().map(|s| s.iter().map(|&x| x != 0).collect());
    let mut fixed: Vec<bool> = (0..n).map(|v| position_in_ring[v] != NONE).collect();
    let mut lap = Laplacian::new(&topology, triangles);
    lap.set_cotangent_weights(positions, triangles, None);
    let zero = vec![[0.0; 2]; n];
    let (harmonic_iterations, solved, x, offsets) =
        harmonic_map(&lap, &fixed, &uv, triangles, flat.as_deref(), cg);
    let mut residual = solved?.residual;
    let mut iterations = harmonic_iterations;
    let mut map = FlatMap { uv: x.iter().map(|p| DVec2::from_array(*p)).collect(), offsets };
    let mut freedom = freedoms(&position_in_ring, &ring, rel);
    if let Some(sides) = &flat_sides {
        hold_cut_off(triangles, sides, &position_in_ring, &mut freedom, &mut fixed, &mut map);
    }
    let (harmonic, _) = flat::quality(positions, triangles, &map, flat.as_deref());
    if harmonic.folded_triangles > 0 {
        return topo_err(format!(
            "the harmonic map folds {} triangles over",
            harmonic.folded_triangles
        ));
    }
    let relaxation = Relaxation::new(positions, triangles, &topology, freedom, flat.as_deref());
    let settings =
        RelaxOptions { rounds: options.rounds, sweeps: options.sweeps, cg, harmonic_iterations };
    let done =
        relaxation.run(&mut lap, Some(&fixed), &|_: &Laplacian| zero.clone(), &mut map, settings);
    iterations += done.iterations;
    if let Some(r) = done.residual {
        residual = r;
    }
    let (relaxed, metric) = flat::quality(positions, triangles, &map, flat.as_deref());
    if relaxed.folded_triangles > 0 {
        return topo_err(format!(
            "the relaxed map folds {} triangles over",
            relaxed.folded_triangles
        ));
    }
    Ok(DiscParam {
        positions: positions.to_vec(),
        triangles: triangles.to_vec(),
        filled: filled.to_vec(),
        map,
        flat,
        corners: rel.map(|k| ring[k]),
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

/// Each ring vertex's position in `ring` ([`NONE`] for the interior), over `n` vertices.
fn ring_positions(ring: &[u32], n: usize) -> Vec<u32> {
    let mut position_in_ring = vec![NONE; n];
    for (k, &v) in ring.iter().enumerate() {
        position_in_ring[v as usize] = k as u32;
    }
    position_in_ring
}

/// The harmonic stage of [`parameterise_disc`]: the interior solved with the vertices `fixed`
/// held, from `uv`, until the map folds nothing off the cut-off triangles `flat`; the
/// iterations, the solve's outcome, the coordinates and the (zero) corner offsets.
#[expect(clippy::type_complexity, reason = "a private tuple of the stage's results")]
fn harmonic_map(
    lap: &Laplacian,
    fixed: &[bool],
    uv: &[DVec2],
    triangles: &[[u32; 3]],
    flat: Option<&[bool]>,
    cg: CgOptions,
) -> (usize, Result<Embedded, Error>, Vec<[f64; 2]>, Vec<[IVec2; 3]>) {
    let zero = vec![[0.0; 2]; uv.len()];
    let mut x: Vec<[f64; 2]> = uv.iter().map(|p| p.to_array()).collect();
    let offsets = vec![[IVec2::ZERO; 3]; triangles.len()];
    let folds = |x: &[[f64; 2]]| {
        let map = FlatMap {
            uv: x.iter().map(|p| DVec2::from_array(*p)).collect(),
            offsets: offsets.clone(),
        };
        flat::count_folds(triangles, &map, flat)
    };
    let (harmonic_iterations, solved) = solve_until_embedded(
        lap,
        Some(fixed),
        &zero,
        &mut x,
        cg,
        lap.preconditioner(Some(fixed), cg).as_ref(),
        folds,
    );
    (harmonic_iterations, solved, x, offsets)
}

/// The first stage of [`parameterise_disc`]: the mesh's one boundary loop as a ring of
/// vertices, or an error naming why the mesh is not a disc with at least 4 boundary vertices.
fn boundary_ring(topology: &Topology, triangles: &[[u32; 3]]) -> Result<Vec<u32>, Error> {
    let topo_err = |what: String| Err(Error::Topology { what });
    if topology.boundary.is_empty() {
        return topo_err(
            "the mesh is closed (no boundary edge); a disc has one boundary loop".to_owned(),
        );
    }
    let loops = topology.boundary_loops(triangles);
    if loops.len() != 1 {
        return topo_err(format!(
            "the mesh has {} boundary loops; a disc has exactly one",
            loops.len()
        ));
    }
    let chi = topology.euler_characteristic();
    if chi != 1 {
        return topo_err(format!(
            "the mesh is not a disc: χ = V − E + F = {chi} with one boundary loop (genus {}), a disc has χ = 1",
            (1 - chi) as f64 / 2.0
        ));
    }
    let ring: Vec<u32> = loops[0].iter().map(|&h| tail(triangles, h)).collect();
    let b = ring.len();
    if b < 4 {
        return topo_err(format!(
            "the boundary has {b} vertices; the square's four corners need at least 4"
        ));
    }
    Ok(ring)
}

/// Interior edges with both ends on the boundary, as pairs of positions in the ring.
fn dividing_edges(
    topology: &Topology,
    triangles: &[[u32; 3]],
    position_in_ring: &[u32],
) -> Vec<(usize, usize)> {
    (0..topology.twin.len() as u32)
        .filter(|&h| {
            let t = topology.twin[h as usize];
            t != NONE
                && h < t
                && position_in_ring[tail(triangles, h) as usize] != NONE
                && position_in_ring[head(triangles, h) as usize] != NONE
        })
        .map(|h| {
            (
                position_in_ring[tail(triangles, h) as usize] as usize,
                position_in_ring[head(triangles, h) as usize] as usize,
            )
        })
        .collect()
}

/// The surface's normal at each boundary vertex (its triangles' normals, by area).
fn boundary_normals(
    topology: &Topology,
    triangles: &[[u32; 3]],
    positions: &[DVec3],
    ring: &[u32],
) -> Vec<DVec3> {
    ring.iter()
        .map(|&v| {
            topology
                .outgoing(v)
                .iter()
                .map(|&h| {
                    let [a, b, c] = triangles[(h / 3) as usize].map(|k| positions[k as usize]);
                    (b - a).cross(c - a)
                })
                .sum()
        })
        .collect()
}

/// The boundary on the square by arc length along each side (corner m of the square at ring
/// position `rel[m]`), into `uv`.
fn boundary_on_square(positions: &[DVec3], ring: &[u32], rel: [usize; 4], uv: &mut [DVec2]) {
    let b = ring.len();
    let square = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y];
    for m in 0..4 {
        let (from, to) = (rel[m], if m == 3 { b } else { rel[m + 1] });
        let mut lengths = vec![0.0];
        for k in from..to {
            let step =
                (positions[ring[(k + 1) % b] as usize] - positions[ring[k] as usize]).length();
            lengths.push(lengths[lengths.len() - 1] + step);
        }
        let total = lengths[lengths.len() - 1];
        for k in from..to {
            let t = if total > 0.0 {
                lengths[k - from] / total
            } else {
                (k - from) as f64 / (to - from) as f64
            };
            let (a, c) = (square[m], square[(m + 1) % 4]);
            // Exactly on the side: the coordinate the side fixes is copied, not interpolated.
            let mut q = a + (c - a) * t;
            if m % 2 == 0 {
                q.y = a.y;
            } else {
                q.x = a.x;
            }
            uv[ring[k] as usize] = q;
        }
    }
}

/// How each vertex may move in the relaxation: the corners fixed, the other boundary vertices
/// sliding along their side, the interior free.
fn freedoms(position_in_ring: &[u32], ring: &[u32], rel: [usize; 4]) -> Vec<Freedom> {
    let b = ring.len();
    (0..position_in_ring.len())
        .map(|v| {
            let k = position_in_ring[v];
            if k == NONE {
                return Freedom::Free;
            }
            let k = k as usize;
            if rel.contains(&k) {
                return Freedom::Fixed;
            }
            let bits = sides_of(k, rel);
            let axis = if bits & 0b0101 != 0 { 0 } else { 1 };
            Freedom::Slide { axis, a: ring[(k + b - 1) % b], b: ring[(k + 1) % b] }
        })
        .collect()
}

/// What an edge cut off lies on its side: exactly there, and it stays (held in the
/// relaxation's solves too).
fn hold_cut_off(
    triangles: &[[u32; 3]],
    sides: &[u8],
    position_in_ring: &[u32],
    freedom: &mut [Freedom],
    fixed: &mut [bool],
    map: &mut FlatMap,
) {
    for (f, t) in triangles.iter().enumerate() {
        if sides[f] == 0 {
            continue;
        }
        for &v in t {
            freedom[v as usize] = Freedom::Fixed;
            fixed[v as usize] = true;
            if position_in_ring[v as usize] == NONE {
                let q = &mut map.uv[v as usize];
                *q = q.clamp(DVec2::ZERO, DVec2::ONE);
                match sides[f].trailing_zeros() {
                    0 => q.y = 0.0,
                    1 => q.x = 1.0,
                    2 => q.y = 1.0,
                    _ => q.x = 0.0,
                }
            }
        }
    }
}

/// The triangles cut off by an interior edge joining two vertices of one side (they lie flat
/// on it): the parts of the mesh, split along those edges, whose boundary vertices all share a
/// side. For each triangle the side it lies flat on (a bit, as [`sides_of`]), 0 if none;
/// `None` if there are none.
fn collapsed(
    topology: &Topology,
    triangles: &[[u32; 3]],
    dividing: &[(usize, usize)],
    ring: &[u32],
    side_bits: &dyn Fn(u32) -> u8,
) -> Option<Vec<u8>> {
    let on_one_side = |h: u32| {
        let (sx, sy) = (side_bits(tail(triangles, h)), side_bits(head(triangles, h)));
        sx & sy != 0
    };
    if !dividing.iter().any(|&(x, y)| side_bits(ring[x]) & side_bits(ring[y]) != 0) {
        return None;
    }
    // Union–find over the triangles, across every interior edge but those.
    fn find(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            parent[x as usize] = parent[parent[x as usize] as usize];
            x = parent[x as usize];
        }
        x
    }
    let mut parent: Vec<u32> = (0..triangles.len() as u32).collect();
    for h in 0..topology.twin.len() as u32 {
        let t = topology.twin[h as usize];
        if t == NONE || t < h || on_one_side(h) {
            continue;
        }
        let (a, c) = (find(&mut parent, h / 3), find(&mut parent, t / 3));
        if a != c {
            parent[a.max(c) as usize] = a.min(c);
        }
    }
    let mut common = vec![0b1111u8; triangles.len()];
    for (f, t) in triangles.iter().enumerate() {
        let r = find(&mut parent, f as u32) as usize;
        for &v in t {
            let s = side_bits(v);
            if s != 0 {
                common[r] &= s;
            }
        }
    }
    // A part on one side lies on one side only (it is cut off from the corners' other side).
    let sides: Vec<u8> = (0..triangles.len())
        .map(|f| {
            let c = common[find(&mut parent, f as u32) as usize];
            if c == 0 { 0 } else { 1 << c.trailing_zeros() }
        })
        .collect();
    sides.iter().any(|&x| x != 0).then_some(sides)
}

impl DiscParam {
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

    /// Each vertex's (u, v), in [0, 1]²; boundary vertices on the square's boundary.
    #[must_use]
    pub fn uv(&self) -> &[DVec2] {
        &self.map.uv
    }

    /// Triangle f's (u, v) triangle: counter-clockwise for every triangle of a valid map but
    /// those laid flat on a side ([`FlatQuality::flat_triangles`]).
    ///
    /// # Panics
    ///
    /// If f is not a triangle index.
    #[must_use]
    pub fn uv_triangle(&self, f: usize) -> [DVec2; 3] {
        self.map.corners(&self.triangles, f)
    }

    /// The flags of the triangles added to close holes, as given.
    #[must_use]
    pub fn filled(&self) -> &[bool] {
        &self.filled
    }

    /// The vertices at the square's corners (0, 0), (1, 0), (1, 1) and (0, 1).
    #[must_use]
    pub const fn corner_vertices(&self) -> [u32; 4] {
        self.corners
    }

    /// (rows − 1) / (cols − 1) for texels that are square on the surface on average:
    /// √(∫|pᵤ|² / ∫|pᵥ|²) over the square, p the map from (u, v) to the surface.
    #[must_use]
    pub const fn aspect(&self) -> f64 {
        self.aspect
    }

    /// A whole-sample image size of about `texels` texels with
    /// (rows − 1) / (cols − 1) ≈ [`DiscParam::aspect`] (each side at least 2).
    #[must_use]
    pub fn resolution(&self, texels: usize) -> (usize, usize) {
        crate::torusparam::resolution(self.aspect, texels.min(MAX_TEXELS) as f64, 1)
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

    /// The whole-sample geometry image: texel (i, j) is the surface point at
    /// (u, v) = (i/(rows − 1), j/(cols − 1)), so the first and last rows and columns lie on the
    /// mesh's boundary. It is not periodic: double it with [`reflect_periodic`] before taking
    /// its harmonic surface.
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
            self.flat.as_deref(),
            rows,
            cols,
            false,
        )
    }
}

/// The even reflection of a rows × cols whole-sample grid: 2(rows − 1) × 2(cols − 1) values,
/// (i, j) taken from (r(i), c(j)), r(i) = i for i < rows and 2(rows − 1) − i after.
fn reflect<T: Copy>(data: &[T], rows: usize, cols: usize) -> Vec<T> {
    let (big_r, big_c) = (2 * (rows - 1), 2 * (cols - 1));
    let fold = |i: usize, n: usize| if i < n { i } else { 2 * (n - 1) - i };
    let mut out = Vec::with_capacity(big_r * big_c);
    for i in 0..big_r {
        let r = fold(i, rows);
        for j in 0..big_c {
            out.push(data[r * cols + fold(j, cols)]);
        }
    }
    out
}

/// The even (mirror) extension of a rows × cols whole-sample image (such as
/// [`DiscParam::image`]'s) to a doubly periodic 2(rows − 1) × 2(cols − 1) geometry image:
/// texel (i, j) is the square's texel (r(i), c(j)), r(i) = i for i < rows and 2(rows − 1) − i
/// after (c likewise) — the doubling the thesis uses for its flattened octahedron.
///
/// The harmonic surface through it (§5.1) is periodic and even about u = 0 and u = ½ (and
/// v = 0, v = ½): p(½ + s, v) = p(½ − s, v). Its quarter u, v ∈ [0, ½] passes through the
/// square's texels at (u, v) = (i/(2(rows − 1)), j/(2(cols − 1))) and is the open sheet;
/// across the sheet's boundary the surface turns back on itself, its derivative across the
/// boundary (pᵤ on u = 0 and u = ½, pᵥ on v = 0 and v = ½) vanishing there.
///
/// # Errors
///
/// [`Error::InvalidResolution`] if the doubled image would exceed [`MAX_TEXELS`].
pub fn reflect_periodic(square: &GeometryImage) -> Result<GeometryImage, Error> {
    let (rows, cols) = (square.rows(), square.cols());
    GeometryImage::try_new(2 * (rows - 1), 2 * (cols - 1), reflect(square.texels(), rows, cols))
}

/// [`reflect_periodic`] for a row-major mask of rows × cols flags (such as
/// [`FlatImage::filled`]).
///
/// # Errors
///
/// [`Error::InvalidResolution`] if the mask does not have rows × cols flags, a side is below 2,
/// or the doubled mask would exceed [`MAX_TEXELS`].
pub fn reflect_periodic_mask(mask: &[bool], rows: usize, cols: usize) -> Result<Vec<bool>, Error> {
    crate::image::check_resolution(rows, cols)?;
    if mask.len() != rows * cols {
        return Err(Error::InvalidResolution {
            rows,
            cols,
            expected: "the mask must have rows × cols flags",
        });
    }
    crate::image::check_resolution(2 * (rows - 1), 2 * (cols - 1))?;
    Ok(reflect(mask, rows, cols))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sides_of_corners_and_arcs() {
        let c = [0, 3, 5, 9];
        assert_eq!(sides_of(0, c), 0b1001);
        assert_eq!(sides_of(1, c), 0b0001);
        assert_eq!(sides_of(3, c), 0b0011);
        assert_eq!(sides_of(4, c), 0b0010);
        assert_eq!(sides_of(9, c), 0b1100);
        assert_eq!(sides_of(11, c), 0b1000);
    }

    #[test]
    fn reflection_is_even() {
        let data: Vec<usize> = (0..12).collect();
        let (rows, cols) = (3, 4);
        let out = reflect(&data, rows, cols);
        assert_eq!(out.len(), 4 * 6);
        // Row 3 mirrors row 1; column 4 mirrors column 2, column 5 column 1.
        assert_eq!(out[3 * 6], data[cols]);
        assert_eq!(out[4], data[2]);
        assert_eq!(out[5], data[1]);
        assert_eq!(out[3 * 6 + 5], data[cols + 1]);
    }
}
