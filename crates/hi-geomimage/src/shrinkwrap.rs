// SPDX-License-Identifier: MIT
//! A geometry image of a point set, shrink-wrapped onto its surface (beyond §5.3, whose texels
//! are distances along rays from a centre, and fail wherever a ray meets the surface twice).
//!
//! About every point a quadric height field is fitted once to its 16 nearest points (weighted
//! least squares, over the plane across the point's normal: the file's when it has one, else
//! the least principal axis of the neighbours, oriented consistently along a minimum spanning
//! tree of the neighbour graph as Hoppe et al. 1992 do). These patches are the point set's
//! surface. Then:
//!
//! 1. **The start**: the zero set of the signed height over the nearest point's patch (Hoppe et
//!    al.'s signed distance), meshed by [`crate::surfacenets`] on a grid of 1.5 point spacings,
//!    evaluated only near the points and only where a node's foot on the tangent plane is near
//!    its point, so that the surface ends at the rims of the scan's holes. That mesh is closed
//!    by [`crate::repair::close_mesh`] (its holes bridged) and parameterised over the sphere
//!    ([`crate::sphereparam`]); the image is sampled from the parameterisation, so its texels
//!    spread over every arm, ear and concavity whatever the rays would have seen.
//! 2. **The projection**: every texel moves onto the point set's surface: to the
//!    Gaussian-weighted blend of its projections onto the patches of its three nearest points
//!    that face its way (its normal across the grid's two directions), a move of at most 1.5
//!    point spacings (a longer one would cross to the other side of a part thinner than the
//!    grid; a texel with no point within 1.5 spacings, which has no sheet to cross, moves 1.5
//!    spacings towards its projection instead). Texels on the patches bridging holes, and
//!    texels farther than four point spacings from every point, stay where they are and are
//!    flagged [`ShrinkWrapImage::filled`].
//! 3. **The pull**: a point the surface passed by (more than 0.75 spacings off it along the
//!    normal of its nearest texel, within one spacing of that normal's line, its patch facing
//!    the same way, and within three spacings, beyond which it is taken for an outlier) pulls
//!    that texel onto it. This reaches into creases and slits narrower than the grid of step
//!    1, whose zero set bridges them; the count is [`ShrinkWrapImage::pulled`].
//!
//! Should the start fail (the zero set not of genus 0, or the points too sparse for a grid),
//! the radial image of algorithm 2 is wrapped instead, a few times over: each texel projected
//! as above (without the bound), then moved along the surface towards the mean of its four grid
//! neighbours (only the tangential part of that move) so that texels spread instead of piling up
//! where the rays crowded them; a texel with no point near moves halfway between its
//! neighbours' mean and its projection (a membrane shrinking onto the points). That coarse wrap
//! is parameterised over the sphere like the start above, projected again and pulled. The doubled
//! layouts' half-turn symmetry is restored after every step (each texel and its mirror take
//! their mean), so the result is a valid doubled image.
//!
//! The texels end on the surface of the points (the last step is a projection), so the harmonic
//! surface through them is accurate where they are dense; [`crate::fit()`] then regularises it to
//! the points' noise level.

use std::num::NonZero;

use crate::par::*;
use glam::{DMat3, DVec3};
use kiddo::{ImmutableKdTree, SquaredEuclidean};

use crate::spherical::{Layout, SphericalOptions, spherical_image};
use crate::{Error, GeometryImage, NonFiniteInput};

/// The settings of [`shrink_wrap`].
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ShrinkWrapOptions {
    /// The layout of the image. Default [`Layout::FlatOctahedron`].
    pub layout: Layout,
    /// Rows (even for the doubled layouts). Default 256.
    pub rows: usize,
    /// Columns. Default 256.
    pub cols: usize,
    /// The centre of the rays (the diagnostic [`ShrinkWrapImage::non_star_fraction`] and the
    /// fallback's start); `None` for the mean of the points.
    pub centre: Option<DVec3>,
    /// Rounds of projection and spreading of the fallback's coarse wrap. Default 4.
    pub iterations: usize,
    /// Points in each local quadric fit. Default 16.
    pub neighbours: usize,
}

impl Default for ShrinkWrapOptions {
    fn default() -> Self {
        Self {
            layout: Layout::FlatOctahedron,
            rows: 256,
            cols: 256,
            centre: None,
            iterations: 4,
            neighbours: 16,
        }
    }
}

/// A shrink-wrapped geometry image with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub struct ShrinkWrapImage {
    /// The image: texels on the point set's surface, or bridging holes in it.
    pub image: GeometryImage,
    /// Texels with no point near them or on a patch bridging a hole of the scan (row-major).
    pub filled: Vec<bool>,
    /// The fraction of the distinct texels flagged in [`ShrinkWrapImage::filled`].
    pub filled_fraction: f64,
    /// The fraction of the rays from the centre (a coarse radial image) that met several shells.
    pub non_star_fraction: f64,
    /// Whether the wrap started from the zero set of the points' signed distance (else from
    /// the rays, when that surface could not be closed to genus 0 and parameterised).
    pub implicit_start: bool,
    /// Whether the final image was sampled from a spherical parameterisation (of the implicit
    /// surface or of the coarse wrap; else from rays, when neither could be parameterised).
    pub reparameterised: bool,
    /// The root mean square distance the texels moved from the image first sampled (of the
    /// implicit surface or the coarse wrap) to the end.
    pub rms_move: f64,
    /// Texels pulled onto points the wrap had left off the surface (step 3 of the module
    /// documentation), each counted once however many copies the layout holds.
    pub pulled: usize,
}

/// A local quadric patch about one point: a frame (origin, tangents, normal) and the height
/// h(x, y) = c₀ + c₁x + c₂y + c₃x² + c₄xy + c₅y² over its tangent plane, fitted by least
/// squares to the point's neighbours.
#[derive(Clone, Copy, Debug)]
struct Patch {
    origin: DVec3,
    e1: DVec3,
    e2: DVec3,
    normal: DVec3,
    c: [f64; 6],
}

impl Patch {
    /// The same patch seen from the other side: the normal and second tangent reversed,
    /// h(x, y) ↦ −h(x, −y).
    fn flip(&mut self) {
        self.normal = -self.normal;
        self.e2 = -self.e2;
        let c = self.c;
        self.c = [-c[0], -c[1], c[2], -c[3], c[4], -c[5]];
    }

    /// The point of the patch over x's foot on the tangent plane.
    fn project(&self, x: DVec3) -> DVec3 {
        let d = x - self.origin;
        let (u, v) = (d.dot(self.e1), d.dot(self.e2));
        let c = &self.c;
        let h = c[0] + c[1] * u + c[2] * v + c[3] * u * u + c[4] * u * v + c[5] * v * v;
        self.origin + self.e1 * u + self.e2 * v + self.normal * h
    }
}

/// The point set's local surface: a kd-tree over the points, a quadric patch about each, and
/// the median spacing of the points.
struct Patches {
    tree: ImmutableKdTree<f64, 3>,
    patches: Vec<Patch>,
    spacing: f64,
}

/// Patches blended per projection.
const BLEND: usize = 3;

/// Nearest points examined per projection, for patches that face the texel's way.
const CANDIDATES: usize = 8;

impl Patches {
    fn new(points: &[DVec3], normals: Option<&[DVec3]>, k: usize) -> Result<Self, Error> {
        let tree: ImmutableKdTree<f64, 3> = ImmutableKdTree::new_from_slice(
            &points.iter().map(|p| p.to_array()).collect::<Vec<_>>(),
        )
        .map_err(|_| Error::Degenerate { what: "the points do not form a kd-tree" })?;
        let k = NonZero::new(k.max(8)).unwrap_or(NonZero::<usize>::MIN);
        let given = normals.filter(|n| n.len() == points.len());
        let fitted: Vec<(Patch, f64)> = points
            .par_iter()
            .enumerate()
            .map(|(i, p)| {
                let near =
                    tree.query(&p.to_array()).nearest_n::<SquaredEuclidean<f64>>(k).execute();
                let spacing = near.get(1).map_or(0.0, |n| n.distance.sqrt());
                let hood: Vec<DVec3> = near.iter().map(|n| points[n.item as usize]).collect();
                let normal = given
                    .and_then(|n| n[i].try_normalize())
                    .or_else(|| least_axis(&hood))
                    .unwrap_or(DVec3::Z);
                (fit_patch(*p, normal, &hood), spacing)
            })
            .collect();
        let mut spacings: Vec<f64> = fitted.iter().map(|f| f.1).collect();
        spacings.sort_by(f64::total_cmp);
        let spacing = spacings[spacings.len() / 2].max(f64::MIN_POSITIVE);
        let mut patches: Vec<Patch> = fitted.into_iter().map(|f| f.0).collect();
        if given.is_none() {
            // A first guess: away from the centroid (corrected by `orient` once a surface is
            // wrapped round the points).
            let centre = points.iter().copied().sum::<DVec3>() / points.len().max(1) as f64;
            for p in &mut patches {
                if p.normal.dot(p.origin - centre) < 0.0 {
                    p.flip();
                }
            }
        }
        Ok(Self { tree, patches, spacing })
    }

    /// The projection of x onto the surface (the patches of its nearest points facing the way
    /// `normal` does, if it is given and any do, blended by a Gaussian of their distance), and
    /// the distance from x to its nearest point.
    fn project(&self, x: DVec3, normal: DVec3) -> (DVec3, f64) {
        let k = NonZero::new(CANDIDATES).unwrap_or(NonZero::<usize>::MIN);
        let near = self.tree.query(&x.to_array()).nearest_n::<SquaredEuclidean<f64>>(k).execute();
        let nearest = near.first().map_or(f64::INFINITY, |n| n.distance.sqrt());
        // Where two sheets lie close (the two sides of a thin part), only the sheet the texel
        // belongs to.
        let facing: Vec<_> = near
            .iter()
            .filter(|n| self.patches[n.item as usize].normal.dot(normal) > 0.0)
            .take(BLEND)
            .collect();
        let chosen: Vec<_> =
            if facing.is_empty() { near.iter().take(BLEND).collect() } else { facing };
        let h2 = chosen.last().map_or(0.0, |n| n.distance).max(self.spacing * self.spacing);
        let (mut q, mut w) = (DVec3::ZERO, 0.0);
        for n in chosen {
            let wi = (-n.distance / h2).exp();
            q += self.patches[n.item as usize].project(x) * wi;
            w += wi;
        }
        (if w > 0.0 { q / w } else { x }, nearest)
    }

    /// Orients the patches consistently (Hoppe et al. 1992, §3.3): along a minimum spanning
    /// tree of the graph joining each point to its `k` nearest, weighted by 1 − |nᵢ·nⱼ| so that
    /// the orientation passes first between nearly parallel planes, each patch turned to agree
    /// with the one it is reached from; each connected part starts from its highest point,
    /// whose normal points up (the top of a closed surface faces +z).
    fn orient_by_tree(&mut self, points: &[DVec3], k: usize) {
        use std::cmp::Reverse;
        use std::collections::BinaryHeap;
        let n = points.len();
        let k = NonZero::new(k + 1).unwrap_or(NonZero::<usize>::MIN);
        let near: Vec<Vec<u32>> = points
            .par_iter()
            .map(|p| {
                self.tree
                    .query(&p.to_array())
                    .nearest_n::<SquaredEuclidean<f64>>(k)
                    .execute()
                    .iter()
                    .map(|q| q.item)
                    .collect()
            })
            .collect();
        // The graph, symmetric.
        let mut adjacency: Vec<Vec<u32>> = near.clone();
        for (i, list) in near.iter().enumerate() {
            for &j in list {
                if j as usize != i {
                    adjacency[j as usize].push(i as u32);
                }
            }
        }
        let mut done = vec![false; n];
        let mut by_height: Vec<u32> = (0..n as u32).collect();
        by_height.sort_by(|&a, &b| points[b as usize].z.total_cmp(&points[a as usize].z));
        // Weights in [0, 1]: their bits order as the numbers do.
        let mut heap: BinaryHeap<Reverse<(u64, u32, u32)>> = BinaryHeap::new();
        for root in by_height {
            if done[root as usize] {
                continue;
            }
            if self.patches[root as usize].normal.z < 0.0 {
                self.patches[root as usize].flip();
            }
            heap.push(Reverse((0, root, root)));
            while let Some(Reverse((_, from, to))) = heap.pop() {
                if done[to as usize] {
                    continue;
                }
                done[to as usize] = true;
                let reference = self.patches[from as usize].normal;
                if self.patches[to as usize].normal.dot(reference) < 0.0 {
                    self.patches[to as usize].flip();
                }
                let normal = self.patches[to as usize].normal;
                for &next in &adjacency[to as usize] {
                    if !done[next as usize] {
                        let w = 1.0 - normal.dot(self.patches[next as usize].normal).abs();
                        heap.push(Reverse((w.max(0.0).to_bits(), to, next)));
                    }
                }
            }
        }
    }

    /// The signed height of x over the patch of its nearest point (negative inside, once the
    /// patches face out), and the distance from that point to x's foot on its tangent plane.
    fn signed(&self, x: DVec3) -> (f64, f64) {
        let nearest =
            self.tree.query(&x.to_array()).nearest_one::<SquaredEuclidean<f64>>().execute();
        let patch = &self.patches[nearest.item as usize];
        let d = x - patch.origin;
        let (u, v) = (d.dot(patch.e1), d.dot(patch.e2));
        let c = &patch.c;
        let h = c[0] + c[1] * u + c[2] * v + c[3] * u * u + c[4] * u * v + c[5] * v * v;
        (d.dot(patch.normal) - h, (d - patch.normal * d.dot(patch.normal)).length())
    }

    /// Turns each patch to face as the nearest of `samples` (points of a surface wrapped round
    /// the point set, with their outward `normals`) does.
    fn orient(&mut self, samples: &[DVec3], normals: &[DVec3]) {
        let Ok(tree): Result<ImmutableKdTree<f64, 3>, _> = ImmutableKdTree::new_from_slice(
            &samples.iter().map(|p| p.to_array()).collect::<Vec<_>>(),
        ) else {
            return;
        };
        self.patches.par_iter_mut().for_each(|patch| {
            let n = tree
                .query(&patch.origin.to_array())
                .nearest_one::<SquaredEuclidean<f64>>()
                .execute();
            if patch.normal.dot(normals[n.item as usize]) < 0.0 {
                patch.flip();
            }
        });
    }
}

/// The quadric patch about `p` across `normal`, fitted to `hood` (weights falling off with the
/// distance from p); a plane if the fit is degenerate.
fn fit_patch(p: DVec3, normal: DVec3, hood: &[DVec3]) -> Patch {
    let e1 = normal.any_orthonormal_vector();
    let e2 = normal.cross(e1);
    let h2 = hood.iter().map(|q| q.distance_squared(p)).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    let mut ata = [[0.0f64; 6]; 6];
    let mut atb = [0.0f64; 6];
    for q in hood {
        let d = *q - p;
        let (x, y, h) = (d.dot(e1), d.dot(e2), d.dot(normal));
        let w = (-d.length_squared() / h2).exp();
        let r = [1.0, x, y, x * x, x * y, y * y];
        for i in 0..6 {
            for j in 0..6 {
                ata[i][j] += w * r[i] * r[j];
            }
            atb[i] += w * r[i] * h;
        }
    }
    let c = crate::noise::solve6(ata, atb).unwrap_or([0.0; 6]);
    Patch { origin: p, e1, e2, normal, c }
}

/// The unit eigenvector of the least eigenvalue of the points' covariance.
fn least_axis(hood: &[DVec3]) -> Option<DVec3> {
    let c = hood.iter().copied().sum::<DVec3>() / hood.len().max(1) as f64;
    let mut m = DMat3::ZERO;
    for p in hood {
        let d = *p - c;
        m += DMat3::from_cols(d * d.x, d * d.y, d * d.z);
    }
    crate::noise::smallest_eigenvector(m)
}

/// Builds the shrink-wrapped image of `points` (with their `normals`, if given: one per point);
/// see the module documentation.
///
/// # Errors
///
/// The errors of [`spherical_image`] for the radial start (too few points, non-finite input,
/// bad resolution); [`Error::InvalidOption`] for a normal count other than the point count.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::shrinkwrap::{ShrinkWrapOptions, shrink_wrap};
///
/// // Points on a sphere of radius 2: every texel ends on it.
/// let points: Vec<DVec3> = (0..5000)
///     .map(|k| {
///         let z = 1.0 - (2 * k + 1) as f64 / 5000.0;
///         let phi = k as f64 * 2.399_963_229_728_653;
///         let s = (1.0 - z * z).sqrt();
///         DVec3::new(s * phi.cos(), s * phi.sin(), z) * 2.0
///     })
///     .collect();
/// let options = ShrinkWrapOptions { rows: 32, cols: 32, ..ShrinkWrapOptions::default() };
/// let wrapped = shrink_wrap(&points, None, &options).unwrap();
/// assert!(wrapped.image.texels().iter().all(|p| (p.length() - 2.0).abs() < 1e-3));
/// assert_eq!(wrapped.filled_fraction, 0.0);
/// ```
pub fn shrink_wrap(
    points: &[DVec3],
    normals: Option<&[DVec3]>,
    options: &ShrinkWrapOptions,
) -> Result<ShrinkWrapImage, Error> {
    let &ShrinkWrapOptions { layout, rows, cols, centre, iterations, neighbours } = options;
    if let Some(n) = normals
        && n.len() != points.len()
    {
        return Err(Error::InvalidOption {
            name: "normals",
            value: n.len() as f64,
            expected: "one normal per point",
        });
    }
    if let Some(k) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinite { what: NonFiniteInput::Point(k) });
    }
    if points.len() < neighbours.max(8) {
        return Err(Error::TooFewPoints { found: points.len(), needed: neighbours.max(8) });
    }
    crate::image::check_resolution(rows, cols)?;
    let mut patches = Patches::new(points, normals, neighbours)?;
    if normals.is_none() {
        patches.orient_by_tree(points, TREE_NEIGHBOURS);
    }
    // The rays from the centre, for the diagnostic and as the fallback's start.
    let (cr, cc) = (rows.min(COARSE), cols.min(COARSE));
    let start = spherical_image(
        points,
        &SphericalOptions { layout, rows: cr, cols: cc, centre, ..SphericalOptions::default() },
    )?;
    let param_options = crate::sphereparam::SphereParamOptions::default();
    // The start: the zero set of the points' signed distance, parameterised over the sphere.
    let implicit = implicit_surface(&patches, points)
        .and_then(|closed| {
            patches
                .orient(&closed.positions, &vertex_normals(&closed.positions, &closed.triangles));
            crate::sphereparam::parameterise(&closed, &param_options)
        })
        .and_then(|param| param.image(layout, rows, cols));
    let (first, reparameterised, implicit_start, on_fills) = if let Ok(image) = implicit {
        (image.image.texels().to_vec(), true, true, Some(image.filled))
    } else {
        // Else the coarse radial image wrapped, then its mesh parameterised: the texels of the
        // final image spread over the wrapped surface evenly, however the rays crowded them.
        let (coarse, _) =
            wrap(&patches, start.image.texels().to_vec(), None, layout, cr, cc, iterations);
        // Every patch faces out as the wrapped surface does.
        patches.orient(&coarse, &grid_normals(&coarse, cr, cc));
        let resampled = GeometryImage::try_new(cr, cc, coarse)
            .and_then(|image| image.surface())
            .and_then(|surface| crate::layout_mesh::layout_mesh(&surface, layout, 1))
            .and_then(|m| crate::repair::close_mesh(m.mesh.positions(), m.mesh.triangles()))
            .and_then(|closed| crate::sphereparam::parameterise(&closed, &param_options))
            .and_then(|param| param.image(layout, rows, cols));
        match resampled {
            Ok(image) => (image.image.texels().to_vec(), true, false, None),
            // Should the coarse surface fold too much to be parameterised, the rays at full
            // size.
            Err(_) => {
                let full = spherical_image(
                    points,
                    &SphericalOptions { layout, rows, cols, centre, ..SphericalOptions::default() },
                )?;
                (full.image.texels().to_vec(), false, false, None)
            }
        }
    };
    let rounds = if implicit_start {
        0
    } else if reparameterised {
        FINE_ROUNDS
    } else {
        iterations
    };
    let (mut x, filled) =
        wrap(&patches, first.clone(), on_fills.as_deref(), layout, rows, cols, rounds);
    let pulled = pull(&patches, points, &mut x, &filled, layout, rows, cols);
    // Each direction once, for the fractions.
    let distinct = match layout {
        Layout::Sphere | Layout::FlatOctahedron => rows / 2 * cols,
        Layout::Octahedron => rows * cols,
    };
    let filled_fraction =
        filled[..distinct].iter().filter(|&&f| f).count() as f64 / distinct as f64;
    let rms_move = (x.iter().zip(&first).map(|(a, b)| a.distance_squared(*b)).sum::<f64>()
        / x.len() as f64)
        .sqrt();
    Ok(ShrinkWrapImage {
        image: GeometryImage::try_new(rows, cols, x)?,
        filled,
        filled_fraction,
        non_star_fraction: start.non_star_fraction,
        implicit_start,
        reparameterised,
        rms_move,
        pulled,
    })
}

/// Neighbours joined to each point in the graph [`Patches::orient_by_tree`] spans.
const TREE_NEIGHBOURS: usize = 8;

/// The implicit surface's grid spacing, in point spacings.
const CELL: f64 = 1.5;

/// Grid cells about each point where the signed distance is evaluated.
const BAND: usize = 1;

/// How far, in point spacings, a texel of the implicit start may move onto the points'
/// patches.
const MAX_MOVE: f64 = 1.5;

/// How far, in point spacings, a grid node's foot on the nearest point's tangent plane may lie
/// from that point for the signed distance to count.
const REACH: f64 = 2.0;

/// The zero set of the points' signed distance (Hoppe et al. 1992): the height over the patch
/// of the nearest point, evaluated on a grid of [`CELL`] point spacings within [`BAND`] cells of
/// a point, and only where the node's foot on that patch's tangent plane is within [`REACH`]
/// point spacings of the point (so that the zero set ends at the rims of the scan's holes
/// rather than running on along tangent planes). Its surface net, its holes closed and the
/// whole made genus 0 by [`crate::repair::close_mesh`].
fn implicit_surface(
    patches: &Patches,
    points: &[DVec3],
) -> Result<crate::repair::ClosedMesh, Error> {
    let h = CELL * patches.spacing;
    let (lo, hi) = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let pad = (BAND + 2) as f64 * h;
    let origin = lo - DVec3::splat(pad);
    #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "checked below")]
    let dims = ((hi - lo + DVec3::splat(2.0 * pad)) / h)
        .ceil()
        .to_array()
        .map(|d| if d.is_finite() && d < 1e6 { d as usize + 1 } else { usize::MAX / 4 });
    let nodes = dims.iter().try_fold(1usize, |a, &d| a.checked_mul(d)).unwrap_or(usize::MAX);
    if nodes > crate::surfacenets::MAX_NODES {
        return Err(Error::Degenerate { what: "the points are too sparse for their extent" });
    }
    let [nx, ny, _] = dims;
    let index = |i: usize, j: usize, k: usize| i + nx * (j + ny * k);
    let mut band = vec![false; nodes];
    let b = BAND as isize;
    for p in points {
        #[expect(clippy::cast_possible_truncation, reason = "inside the grid")]
        let c = ((*p - origin) / h).floor().to_array().map(|x| x as isize);
        for dk in -b..=b + 1 {
            for dj in -b..=b + 1 {
                for di in -b..=b + 1 {
                    // The padding keeps these positive.
                    let at = [c[0] + di, c[1] + dj, c[2] + dk].map(isize::unsigned_abs);
                    band[index(at[0], at[1], at[2])] = true;
                }
            }
        }
    }
    let node_at = |t: usize| {
        let (i, j, k) = (t % nx, t / nx % ny, t / nx / ny);
        origin + DVec3::new(i as f64, j as f64, k as f64) * h
    };
    // Known within the band, where the node's foot on the nearest point's tangent plane is near
    // that point (Hoppe's test: the zero set stops where the points do, at the rims of holes).
    let reach = REACH * patches.spacing;
    let values: Vec<f64> = band
        .par_iter()
        .enumerate()
        .map(|(t, &in_band)| {
            if !in_band {
                return f64::NAN;
            }
            let (f, off) = patches.signed(node_at(t));
            if off <= reach { f } else { f64::NAN }
        })
        .collect();
    let (positions, triangles) = crate::surfacenets::surface_nets(&crate::surfacenets::Grid {
        origin,
        spacing: h,
        dims,
        values: &values,
    })?;
    crate::repair::close_mesh(&positions, &triangles)
}

/// Area-weighted vertex normals of a triangle mesh.
fn vertex_normals(positions: &[DVec3], triangles: &[[u32; 3]]) -> Vec<DVec3> {
    let mut normals = vec![DVec3::ZERO; positions.len()];
    for t in triangles {
        let [a, b, c] = t.map(|k| positions[k as usize]);
        let n = (b - a).cross(c - a);
        for &k in t {
            normals[k as usize] += n;
        }
    }
    normals.iter().map(|n| n.normalize_or_zero()).collect()
}

/// The normal of each texel of a `rows × cols` image, across the grid's directions to its
/// neighbours (zero where they are degenerate).
fn grid_normals(x: &[DVec3], rows: usize, cols: usize) -> Vec<DVec3> {
    (0..rows * cols)
        .into_par_iter()
        .map(|t| {
            let (i, j) = (t / cols, t % cols);
            let up = x[((i + rows - 1) % rows) * cols + j];
            let down = x[((i + 1) % rows) * cols + j];
            let left = x[i * cols + (j + cols - 1) % cols];
            let right = x[i * cols + (j + 1) % cols];
            (down - up).cross(right - left).normalize_or_zero()
        })
        .collect()
}

/// Each texel's representative in a `rows × cols` image of `layout`: itself, or its mirror
/// where that comes first (the doubled layouts look along each direction twice).
fn owners(layout: Layout, rows: usize, cols: usize) -> Vec<usize> {
    let mirror = layout.mirror(rows, cols);
    (0..rows * cols)
        .map(|t| {
            mirror.as_ref().map_or(t, |m| {
                let (a, b) = m(t / cols, t % cols);
                t.min(a * cols + b)
            })
        })
        .collect()
}

/// How far off the surface, in point spacings along the normal of its nearest texel, a point
/// must lie to pull that texel onto it.
const PULL_FROM: f64 = 0.75;

/// How far to the side of its nearest texel, in point spacings, a point may lie and pull it.
const PULL_SIDE: f64 = 1.0;

/// Beyond this many point spacings from its nearest texel a point is an outlier: it pulls
/// nothing.
const PULL_UNTIL: f64 = 3.0;

/// Step 3 of the module documentation: each point the surface `x` left more than [`PULL_FROM`]
/// spacings off it, along the normal of the point's nearest texel (not flagged `filled`), and
/// within [`PULL_SIDE`] spacings of that normal's line, whose patch faces the texel's way and
/// which is within [`PULL_UNTIL`] spacings, pulls the texel onto it (onto the mean of the points
/// pulling it, its mirror with it). Returns the number of texels moved.
fn pull(
    patches: &Patches,
    points: &[DVec3],
    x: &mut [DVec3],
    filled: &[bool],
    layout: Layout,
    rows: usize,
    cols: usize,
) -> usize {
    let owner = owners(layout, rows, cols);
    let owners: Vec<usize> = (0..rows * cols).filter(|&t| owner[t] == t && !filled[t]).collect();
    let Ok(tree): Result<ImmutableKdTree<f64, 3>, _> = ImmutableKdTree::new_from_slice(
        &owners.iter().map(|&t| x[t].to_array()).collect::<Vec<_>>(),
    ) else {
        return 0;
    };
    let normals = grid_normals(x, rows, cols);
    let spacing = patches.spacing;
    let pulls: Vec<Option<(usize, DVec3)>> = points
        .par_iter()
        .zip(&patches.patches)
        .map(|(p, patch)| {
            let near = tree.query(&p.to_array()).nearest_one::<SquaredEuclidean<f64>>().execute();
            let t = *owners.get(near.item as usize)?;
            let (v, n) = (*p - x[t], normals[t]);
            let off = v.dot(n);
            let side = (v - n * off).length();
            (off.abs() > PULL_FROM * spacing
                && side <= PULL_SIDE * spacing
                && near.distance.sqrt() < PULL_UNTIL * spacing
                && patch.normal.dot(n) > 0.0)
                .then_some((t, *p))
        })
        .collect();
    let mut sum = vec![(DVec3::ZERO, 0u32); rows * cols];
    for (t, p) in pulls.into_iter().flatten() {
        sum[t].0 += p;
        sum[t].1 += 1;
    }
    for (t, texel) in x.iter_mut().enumerate() {
        let (total, count) = sum[owner[t]];
        if count > 0 {
            *texel = total / f64::from(count);
        }
    }
    sum.iter().filter(|s| s.1 > 0).count()
}

/// The side of the coarse wrap.
const COARSE: usize = 96;

/// Rounds of projection and spreading on the final image.
const FINE_ROUNDS: usize = 2;

/// `rounds` of projection and spreading of the texels `x` of a `rows × cols` image (the last
/// step a projection), with the doubled layouts' symmetry kept; the texels and which of them
/// had no point near. `on_fills` is given for an image of the implicit start: it flags the
/// texels on the patches that close the scan's holes, which have no data either (whatever
/// points are near the hole's rim), and every other texel moves at most [`MAX_MOVE`] point
/// spacings.
fn wrap(
    patches: &Patches,
    mut x: Vec<DVec3>,
    on_fills: Option<&[bool]>,
    layout: Layout,
    rows: usize,
    cols: usize,
    rounds: usize,
) -> (Vec<DVec3>, Vec<bool>) {
    // Beyond this from every point a texel has no data.
    let reach = 4.0 * patches.spacing;
    let mirror = layout.mirror(rows, cols);
    let symmetrise = |v: &mut [DVec3]| {
        if layout == Layout::Sphere {
            // The pole rows are one point each.
            for i in [0, rows / 2] {
                let mean = v[i * cols..(i + 1) * cols].iter().copied().sum::<DVec3>() / cols as f64;
                v[i * cols..(i + 1) * cols].iter_mut().for_each(|x| *x = mean);
            }
        }
        if let Some(mirror) = &mirror {
            for i in 0..rows {
                for j in 0..cols {
                    let (a, b) = mirror(i, j);
                    let (s, t) = (i * cols + j, a * cols + b);
                    if s < t {
                        let mean = 0.5 * (v[s] + v[t]);
                        v[s] = mean;
                        v[t] = mean;
                    }
                }
            }
        }
    };
    let owner = owners(layout, rows, cols);
    let mut filled = vec![false; rows * cols];
    let neighbours_of = |t: usize| {
        let (i, j) = (t / cols, t % cols);
        [
            ((i + rows - 1) % rows) * cols + j,
            ((i + 1) % rows) * cols + j,
            i * cols + (j + cols - 1) % cols,
            i * cols + (j + 1) % cols,
        ]
    };
    for round in 0..=rounds {
        // Onto the surface, each texel onto the sheet facing its way (its normal across the
        // grid's two directions, outward in every layout).
        let normals = grid_normals(&x, rows, cols);
        let mut projected: Vec<(DVec3, f64)> = (0..rows * cols)
            .into_par_iter()
            .map(|t| {
                if owner[t] != t {
                    // Its mirror's, below.
                    return (x[t], 0.0);
                }
                let (p, n) = (x[t], normals[t]);
                let (q, d) = patches.project(p, n);
                // A texel of the implicit start lies within a grid cell of its sheet: a longer
                // move went to another sheet (of a part thinner than the cell) and is refused.
                let limit = MAX_MOVE * patches.spacing;
                if on_fills.is_some() && q.distance(p) > limit {
                    if d > limit {
                        // No point within the limit: no sheet to cross on the way.
                        (p + (q - p).normalize_or_zero() * limit, d)
                    } else {
                        (p, d)
                    }
                } else {
                    (q, d)
                }
            })
            .collect();
        for t in 0..rows * cols {
            projected[t] = projected[owner[t]];
        }
        let mut target = vec![DVec3::ZERO; rows * cols];
        for (t, (q, d)) in projected.iter().enumerate() {
            filled[t] = *d > reach || on_fills.is_some_and(|f| f[t]);
            target[t] = *q;
            if !filled[t] {
                x[t] = *q;
            }
        }
        symmetrise(&mut x);
        if round == rounds {
            break;
        }
        // Along it, towards the neighbours' mean; filled texels follow it wholly.
        let spread: Vec<DVec3> = (0..rows * cols)
            .into_par_iter()
            .map(|t| {
                let around = neighbours_of(t).map(|s| x[s]);
                let mean = around.iter().copied().sum::<DVec3>() / 4.0;
                if filled[t] {
                    // Far from every point: shrink towards the surface, smoothly.
                    return 0.5 * (mean + target[t]);
                }
                let step = mean - x[t];
                // The surface's normal here: across the two grid directions.
                let [up, down, left, right] = around;
                let n = (down - up).cross(right - left).try_normalize().unwrap_or(DVec3::ZERO);
                x[t] + 0.5 * (step - n * step.dot(n))
            })
            .collect();
        x = spread;
        symmetrise(&mut x);
    }
    (x, filled)
}
