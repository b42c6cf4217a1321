// SPDX-License-Identifier: MIT
//! The surface a point set samples, locally: a quadric height field fitted about every point
//! to its nearest neighbours (weighted least squares over the plane across the point's normal:
//! the file's when it has one, else the least principal axis of the neighbours, oriented
//! consistently along a minimum spanning tree of the neighbour graph as Hoppe et al. do in
//! "Surface reconstruction from unorganized points",
//! SIGGRAPH 1992, §3.3). On it:
//!
//! - [`PointSurface::project`]: the projection of a point onto the sheet facing its way (the
//!   patches of its nearest points, blended by a Gaussian of their distance);
//! - [`PointSurface::signed_distance`]: Hoppe et al.'s signed distance, the height over the
//!   patch of the nearest point;
//! - [`PointSurface::zero_set`]: the zero set of that signed distance meshed by
//!   [`crate::surfacenets`] near the points only, so that it ends at the rims of the scan's
//!   holes rather than running on along tangent planes.

use std::f64::consts::PI;
use std::num::NonZero;

use glam::{DMat3, DVec3};
use hi_par::*;
use kiddo::{ImmutableKdTree, SquaredEuclidean};

use crate::repair::find_root;
use crate::{Error, NonFiniteInput};

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
    /// The point's own spacing (see [`PointSurface::spacing`]), where the points about it are
    /// denser or sparser than the median.
    local: f64,
    /// The area per point of the disc through the point's farthest fitted neighbour, π r²/k
    /// (see [`PointSurface::relative_density`]).
    area: f64,
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

    /// The point of the patch over x's foot on the tangent plane; beyond [`PATCH_REACH`] of its
    /// own spacings from its origin (farther than the points it was fitted to), the height of
    /// the patch's edge in that direction, so that a point far from every point (a texel over
    /// a wide gap in a scan) is not sent off along the quadric's growth.
    fn project(&self, x: DVec3) -> DVec3 {
        let d = x - self.origin;
        let (u, v) = (d.dot(self.e1), d.dot(self.e2));
        let reach = PATCH_REACH * self.local;
        let r = u.hypot(v);
        let (a, b) = if r > reach && reach > 0.0 { (u * reach / r, v * reach / r) } else { (u, v) };
        let c = &self.c;
        let h = c[0] + c[1] * a + c[2] * b + c[3] * a * a + c[4] * a * b + c[5] * b * b;
        self.origin + self.e1 * u + self.e2 * v + self.normal * h
    }
}

/// How far, in its point's own spacings, a patch's height is taken as fitted (its quadric
/// was fitted to the point's 16 nearest neighbours, about 2.3 spacings away): beyond, the
/// height at this distance ([`Patch::project`]).
const PATCH_REACH: f64 = 4.0;

/// A point set's local surface: a kd-tree over the points, a quadric patch about each, and
/// the median spacing of the points (see the module documentation).
#[derive(Debug)]
pub struct PointSurface {
    tree: ImmutableKdTree<f64, 3>,
    patches: Vec<Patch>,
    spacing: f64,
    fine: f64,
    /// The median of the patches' areas per point.
    area: f64,
}

/// The neighbours whose disc gives a point's spacing ([`PointSurface::spacing`]).
const SPACING_NEIGHBOURS: usize = 8;

/// The ratio of the 10th percentile of the spacings of points scattered at random over a
/// surface to their median (measured on uniform random samples of meshes: 0.77–0.78).
const RANDOM_TENTH: f64 = 0.78;

/// [`PointSurface::fine_spacing`] is at least this fraction of the median spacing.
const FINE_MIN: f64 = 0.5;

/// A point set whose denser tenth is spaced at least this fraction of a random sample's (the
/// 10th percentile of its spacings over 0.78 of their median) is evenly dense: its zero set's
/// grid follows the median spacing. Scanners' point sets lie at 0.85–0.93 (their density
/// varies with the angle of view, not with the detail: Hoppe's cactus, distcap and duck), and
/// the vertices of scanned meshes near 1 or above (bunny, horse, nefertiti); the vertices of
/// meshes modelled by hand, dense where they have detail and sparse on their broad faces, at
/// 0.3–0.7 (spot, cow, wuson, an aeroplane, a spider). A range scan whose density follows its
/// scan lines may lie as low (CGAL's `radar.xyz`, 0.54); `hi-geomimage`'s fit takes the median
/// spacing's grid again where the finer grid's zero set cannot be parameterised.
const EVEN: f64 = 0.8;

/// The median of `spacings` (points' own spacings, reordered) and the spacing of their denser
/// parts ([`PointSurface::fine_spacing`]): the 10th percentile over [`RANDOM_TENTH`], at least
/// [`FINE_MIN`] of the median, or the median itself when that ratio is [`EVEN`] of it or more.
/// Both are at least the least positive number; `spacings` must not be empty.
fn median_and_fine(spacings: &mut [f64]) -> (f64, f64) {
    spacings.sort_by(f64::total_cmp);
    let spacing = spacings[spacings.len() / 2].max(f64::MIN_POSITIVE);
    // The denser tenth against a random sample's: evenly dense above EVEN.
    let evenness = spacings[spacings.len() / 10] / (RANDOM_TENTH * spacing);
    let fine = if evenness >= EVEN { spacing } else { evenness.max(FINE_MIN) * spacing };
    (spacing, fine.max(f64::MIN_POSITIVE))
}

/// Patches blended per projection.
const BLEND: usize = 3;

/// Nearest points examined per projection, for patches that face the texel's way.
const CANDIDATES: usize = 8;

impl PointSurface {
    /// The local surface of `points`: a quadric patch about each, fitted to its `neighbours`
    /// nearest points (at least 8), across its normal in `normals` when they are given (one per
    /// point, not necessarily of unit length), else across the least principal axis of its
    /// neighbours. The sides are made to agree along a minimum spanning tree of the neighbour
    /// graph (Hoppe et al. 1992, §3.3), each connected part facing +z at its highest point;
    /// given normals keep their own sides instead when those are one orientation (they agree
    /// with the tree's on at least 80 % of the points, or disagree on as many). Normals whose
    /// sides are mixed at random, as a scanner's or a program's that estimated their directions
    /// only may be (CGAL's `cube.pwn`, half of them facing in), would make the signed distance
    /// change sign from one point to the next. [`PointSurface::orient_to`] turns them to face
    /// as a surface wrapped round the points does.
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`] for a non-finite point; [`Error::TooFewPoints`] for fewer points
    /// than `neighbours` (or 8); [`Error::InvalidOption`] for a normal count other than the
    /// point count.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_scan::implicit::PointSurface;
    ///
    /// // A grid of points on the plane z = 1: every point projects onto the plane.
    /// let points: Vec<DVec3> =
    ///     (0..400).map(|k| DVec3::new((k % 20) as f64, (k / 20) as f64, 1.0)).collect();
    /// let surface = PointSurface::try_new(&points, None, 16).unwrap();
    /// let (q, _) = surface.project(DVec3::new(7.3, 9.6, 3.0), DVec3::Z);
    /// assert!((q - DVec3::new(7.3, 9.6, 1.0)).length() < 1e-9);
    /// // The 8th neighbour on the unit grid is √2 away: a spacing of 1.
    /// assert!((surface.spacing() - 1.0).abs() < 1e-12);
    /// ```
    pub fn try_new(
        points: &[DVec3],
        normals: Option<&[DVec3]>,
        neighbours: usize,
    ) -> Result<Self, Error> {
        crate::error::check_points(points, normals)?;
        if points.len() < neighbours.max(8) {
            return Err(Error::TooFewPoints { found: points.len(), needed: neighbours.max(8) });
        }
        let (mut surface, nearest) = Self::fitted(points, normals, neighbours)?;
        let given: Vec<DVec3> = surface.patches.iter().map(|p| p.normal).collect();
        surface.orient_by_tree(points, &nearest);
        if normals.is_some() {
            // The file's sides, unless they disagree with the tree's on too many points to be
            // one orientation (normals whose directions were estimated but not their sides).
            let agree =
                given.iter().zip(&surface.patches).filter(|(g, p)| g.dot(p.normal) > 0.0).count()
                    as f64
                    / given.len().max(1) as f64;
            if (agree - 0.5).abs() >= ORIENTED - 0.5 {
                for (g, p) in given.iter().zip(&mut surface.patches) {
                    if g.dot(p.normal) < 0.0 {
                        p.flip();
                    }
                }
            }
        }
        Ok(surface)
    }

    /// The patches, sides as given or as a first guess (away from the centroid), and each
    /// point's [`TREE_NEIGHBOURS`] nearest other points (for
    /// [`PointSurface::orient_by_tree`]).
    fn fitted(
        points: &[DVec3],
        normals: Option<&[DVec3]>,
        k: usize,
    ) -> Result<(Self, Vec<[u32; TREE_NEIGHBOURS]>), Error> {
        let tree: ImmutableKdTree<f64, 3> =
            ImmutableKdTree::new_from_slice(crate::distance::as_arrays(points))
                .map_err(|_| Error::Degenerate { what: "the points do not form a kd-tree" })?;
        let k = NonZero::new(k.max(8)).unwrap_or(NonZero::<usize>::MIN);
        let given = normals.filter(|n| n.len() == points.len());
        let fitted: Vec<(Patch, f64, [u32; TREE_NEIGHBOURS])> = points
            .par_iter()
            .enumerate()
            .map(|(i, p)| {
                let near =
                    tree.query(&p.to_array()).nearest_n::<SquaredEuclidean<f64>>(k).execute();
                // The nearest others for the orientation's graph (of the k nearest, the point
                // itself among them; slots left over keep u32::MAX).
                let mut others = [u32::MAX; TREE_NEIGHBOURS];
                let me = u32::try_from(i).unwrap_or(u32::MAX);
                for (slot, n) in others.iter_mut().zip(near.iter().filter(|n| n.item != me)) {
                    *slot = n.item;
                }
                // From the distance to the 8th nearest neighbour, which follows the density of
                // the points whether they lie on a grid or are scattered at random (whose
                // nearest neighbour is about half as far): the step of the square grid whose
                // 8th neighbour (a diagonal one) lies as far, r/√2.
                let spacing =
                    near.get(SPACING_NEIGHBOURS).map_or(0.0, |n| (n.distance / 2.0).sqrt());
                // The disc through the farthest of the k nearest (the point itself among them)
                // holds k points about the point, however they are arranged.
                let area = near.last().map_or(0.0, |n| PI * n.distance / near.len() as f64);
                let hood: Vec<DVec3> = near.iter().map(|n| points[n.item as usize]).collect();
                let normal = given
                    .and_then(|n| n[i].try_normalize())
                    .or_else(|| least_axis(&hood))
                    .unwrap_or(DVec3::Z);
                (Patch { local: spacing, area, ..fit_patch(*p, normal, &hood) }, spacing, others)
            })
            .collect();
        let mut spacings: Vec<f64> = fitted.iter().map(|f| f.1).collect();
        let (spacing, fine) = median_and_fine(&mut spacings);
        let (mut patches, nearest): (Vec<Patch>, Vec<[u32; TREE_NEIGHBOURS]>) =
            fitted.into_iter().map(|f| (f.0, f.2)).unzip();
        let mut areas: Vec<f64> = patches.iter().map(|p| p.area).collect();
        areas.sort_by(f64::total_cmp);
        let area = areas[areas.len() / 2];
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
        Ok((Self { tree, patches, spacing, fine, area }, nearest))
    }

    /// The points' spacing: the median over the points of r/√2, r the distance to a point's
    /// 8th nearest neighbour: the step of a square grid of points (whose 8th neighbour is a
    /// diagonal one), and 2/√(π·density) for points scattered at random at that density (whose
    /// nearest neighbours lie about half as far; the distance to the nearest would call them
    /// twice as dense as they are).
    #[must_use]
    pub const fn spacing(&self) -> f64 {
        self.spacing
    }

    /// The spacing of the points' denser parts: the 10th percentile of the points' own
    /// spacings over its ratio to the median for points scattered at random (0.78), at least
    /// half the median [`PointSurface::spacing`]; the median itself for a point set that is
    /// evenly dense (that ratio at least 0.8 of the median: a scanner's points, whose density
    /// varies with the angle of view). For a mesh's vertices, dense where the mesh has detail
    /// (a hand, an ear, a thin fin) and sparse on its broad faces, it is the spacing of the
    /// detail, so that the zero set's grid ([`PointSurface::zero_set_cell`]) resolves parts
    /// thinner than the median spacing.
    #[must_use]
    pub const fn fine_spacing(&self) -> f64 {
        self.fine
    }

    /// The grid spacing at which [`PointSurface::zero_set`] follows every detail the points
    /// resolve: [`CELL`] times [`PointSurface::fine_spacing`].
    #[must_use]
    pub fn zero_set_cell(&self) -> f64 {
        CELL * self.fine
    }

    /// The grid spacing at which [`PointSurface::zero_set_about`] follows every detail that the
    /// points `about` (indices) resolve: [`CELL`] times the [`PointSurface::fine_spacing`] of
    /// those points alone (from their own spacings, [`PointSurface::local_spacing`]); `None`
    /// when `about` is empty or names no point. A part of a scan sampled more sparsely than
    /// the rest (an aircraft's fuselage beside its finely sampled wings) gets a coarser grid
    /// than [`PointSurface::zero_set_cell`], which follows the densest parts.
    #[must_use]
    pub fn zero_set_cell_of(&self, about: &[u32]) -> Option<f64> {
        let mut spacings: Vec<f64> =
            about.iter().filter_map(|&k| self.patches.get(k as usize)).map(|p| p.local).collect();
        if spacings.is_empty() {
            return None;
        }
        Some(CELL * median_and_fine(&mut spacings).1)
    }

    /// The number of points (and patches).
    #[must_use]
    pub fn len(&self) -> usize {
        self.patches.len()
    }

    /// Whether there are no points (never, for a surface built by
    /// [`PointSurface::try_new`]).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.patches.is_empty()
    }

    /// The spacing of the points about point `k`: r/√2, r the distance to its 8th nearest
    /// neighbour (the median of these over the points is [`PointSurface::spacing`]); smaller
    /// than the median where the points are denser; 0 for a point with fewer than 8 others, or
    /// with 8 at its own place.
    ///
    /// # Panics
    ///
    /// If `k` is not below [`PointSurface::len`].
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_scan::implicit::PointSurface;
    ///
    /// // The plane z = 0 on a unit grid for x < 0 and on a grid of step 1/4 for x ≥ 0: the
    /// // spacing of a square grid is its step, far from the seam.
    /// let mut points = Vec::new();
    /// for j in 0..40 {
    ///     for i in 0..40 {
    ///         points.push(DVec3::new(i as f64 - 40.0, j as f64, 0.0));
    ///     }
    /// }
    /// for j in 0..160 {
    ///     for i in 0..160 {
    ///         points.push(DVec3::new(i as f64 / 4.0, j as f64 / 4.0, 0.0));
    ///     }
    /// }
    /// let surface = PointSurface::try_new(&points, None, 16).unwrap();
    /// let sparse = 20 * 40 + 20; // (−20, 20)
    /// let dense = 1600 + 80 * 160 + 80; // (20, 20)
    /// assert!((surface.local_spacing(sparse) - 1.0).abs() < 1e-12);
    /// assert!((surface.local_spacing(dense) - 0.25).abs() < 1e-12);
    /// ```
    #[must_use]
    pub fn local_spacing(&self, k: usize) -> f64 {
        self.patches[k].local
    }

    /// The unit normal of the patch about point `k` (the side it faces).
    ///
    /// # Panics
    ///
    /// If `k` is not below [`PointSurface::len`].
    #[must_use]
    pub fn normal(&self, k: usize) -> DVec3 {
        self.patches[k].normal
    }

    /// The projection of x onto the surface (the patches of its nearest points facing the way
    /// `normal` does, if it is given and any do, blended by a Gaussian of their distance), and
    /// the distance from x to its nearest point.
    #[must_use]
    pub fn project(&self, x: DVec3, normal: DVec3) -> (DVec3, f64) {
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
    /// tree of the graph joining each point to its `nearest` others (its [`TREE_NEIGHBOURS`]
    /// nearest, as `fitted` found them; `u32::MAX` for none), weighted by 1 − |nᵢ·nⱼ| so that
    /// the orientation passes first between nearly parallel planes, each patch turned to agree
    /// with the one it is reached from; each connected part starts from its highest point,
    /// whose normal points up (the top of a closed surface faces +z). The tree is Kruskal's (the
    /// graph's edges sorted by weight, each joining two trees kept), then walked from each
    /// part's highest point.
    fn orient_by_tree(&mut self, points: &[DVec3], nearest: &[[u32; TREE_NEIGHBOURS]]) {
        let n = points.len();
        let patches = &self.patches;
        // The graph's edges, each once as (weight, lower end, higher end): weights in [0, 1],
        // whose bits order as the numbers do.
        let mut edges: Vec<(u64, u32, u32)> = nearest
            .par_iter()
            .enumerate()
            .flat_map_iter(|(i, near)| {
                let i = u32::try_from(i).unwrap_or(u32::MAX);
                let normal = patches[i as usize].normal;
                near.iter().filter(|&&q| (q as usize) < n).map(move |&q| {
                    let w = 1.0 - normal.dot(patches[q as usize].normal).abs();
                    (w.max(0.0).to_bits(), i.min(q), i.max(q))
                })
            })
            .collect();
        edges.par_sort_unstable();
        edges.dedup();
        // The minimum spanning forest (Kruskal: the lightest edges first, each that joins two
        // trees), as each vertex's tree neighbours.
        let mut parent: Vec<u32> = (0..u32::try_from(n).unwrap_or(u32::MAX)).collect();
        let mut spanning: Vec<(u32, u32)> = Vec::with_capacity(2 * n);
        for &(_, a, b) in &edges {
            let (ra, rb) = (find_root(&mut parent, a), find_root(&mut parent, b));
            if ra != rb {
                parent[ra as usize] = rb;
                spanning.extend([(a, b), (b, a)]);
            }
        }
        drop(edges);
        spanning.par_sort_unstable();
        let mut start = vec![0usize; n + 1];
        for &(a, _) in &spanning {
            start[a as usize + 1] += 1;
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        // Each part from its highest point, facing up; each patch turned to agree with the
        // one it is reached from.
        let mut done = vec![false; n];
        let mut by_height: Vec<u32> = (0..u32::try_from(n).unwrap_or(u32::MAX)).collect();
        by_height.sort_by(|&a, &b| points[b as usize].z.total_cmp(&points[a as usize].z));
        let mut stack: Vec<u32> = Vec::new();
        for root in by_height {
            if done[root as usize] {
                continue;
            }
            if self.patches[root as usize].normal.z < 0.0 {
                self.patches[root as usize].flip();
            }
            done[root as usize] = true;
            stack.push(root);
            while let Some(from) = stack.pop() {
                let reference = self.patches[from as usize].normal;
                for &(_, to) in &spanning[start[from as usize]..start[from as usize + 1]] {
                    if !done[to as usize] {
                        done[to as usize] = true;
                        if self.patches[to as usize].normal.dot(reference) < 0.0 {
                            self.patches[to as usize].flip();
                        }
                        stack.push(to);
                    }
                }
            }
        }
    }

    /// The signed height of x over the patch of its nearest point (negative inside, once the
    /// patches face out), and the distance from that point to x's foot on its tangent plane.
    #[must_use]
    pub fn signed_distance(&self, x: DVec3) -> (f64, f64) {
        let (f, off, _) = self.signed_with_spacing(x);
        (f, off)
    }

    /// [`PointSurface::signed_distance`], and the nearest point's own spacing.
    fn signed_with_spacing(&self, x: DVec3) -> (f64, f64, f64) {
        let nearest =
            self.tree.query(&x.to_array()).nearest_one::<SquaredEuclidean<f64>>().execute();
        let patch = &self.patches[nearest.item as usize];
        let d = x - patch.origin;
        let (u, v) = (d.dot(patch.e1), d.dot(patch.e2));
        let c = &patch.c;
        let h = c[0] + c[1] * u + c[2] * v + c[3] * u * u + c[4] * u * v + c[5] * v * v;
        (d.dot(patch.normal) - h, (d - patch.normal * d.dot(patch.normal)).length(), patch.local)
    }

    /// How densely the points sample the surface at the point nearest to x, against their
    /// median density: the median over the points of π r²/k over the nearest point's, r the
    /// radius of the ball about a point that holds its k nearest points (itself among them; k
    /// the `neighbours` of [`PointSurface::try_new`]), so that π r²/k is the area of surface
    /// per point there. A disc of many points counts them however they are arranged (a grid,
    /// staggered rings, scattered at random), where the distance to one neighbour would not.
    /// ∞ where the points repeat (a ball of radius 0).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_scan::implicit::PointSurface;
    ///
    /// // The plane z = 0 sampled on a unit grid for x < 0 and on a grid of step 1/4 for x ≥ 0:
    /// // 16 times as dense there.
    /// let mut points = Vec::new();
    /// for j in 0..40 {
    ///     for i in 0..40 {
    ///         points.push(DVec3::new(i as f64 - 40.0, j as f64, 0.0));
    ///     }
    /// }
    /// for j in 0..160 {
    ///     for i in 0..160 {
    ///         points.push(DVec3::new(i as f64 / 4.0, j as f64 / 4.0, 0.0));
    ///     }
    /// }
    /// let surface = PointSurface::try_new(&points, None, 16).unwrap();
    /// let sparse = surface.relative_density(DVec3::new(-20.0, 20.0, 0.5));
    /// let dense = surface.relative_density(DVec3::new(20.0, 20.0, 0.5));
    /// assert!((dense / sparse - 16.0).abs() < 1e-9, "{}", dense / sparse);
    /// ```
    #[must_use]
    pub fn relative_density(&self, x: DVec3) -> f64 {
        let nearest =
            self.tree.query(&x.to_array()).nearest_one::<SquaredEuclidean<f64>>().execute();
        self.area / self.patches[nearest.item as usize].area
    }

    /// Turns each patch to face as the nearest of `samples` (points of a surface wrapped round
    /// the point set, with their outward `normals`, one per sample) does; nothing if there are
    /// no samples or the counts differ.
    pub fn orient_to(&mut self, samples: &[DVec3], normals: &[DVec3]) {
        if samples.len() != normals.len() {
            return;
        }
        let Ok(tree): Result<ImmutableKdTree<f64, 3>, _> =
            ImmutableKdTree::new_from_slice(crate::distance::as_arrays(samples))
        else {
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
    let c = fit_quadric(p, (e1, e2, normal), hood, 1.0).unwrap_or([0.0; 6]);
    Patch { origin: p, e1, e2, normal, c, local: 0.0, area: 0.0 }
}

/// The coefficients of the quadric height field h(x, y) about `p` in the frame `(e1, e2,
/// normal)`, fitted by least squares to `hood` weighted by exp(−s d²/R²) with s the
/// `sharpness`, d the distance from p and R the largest; `None` if the fit is degenerate.
fn fit_quadric(
    p: DVec3,
    (e1, e2, normal): (DVec3, DVec3, DVec3),
    hood: &[DVec3],
    sharpness: f64,
) -> Option<[f64; 6]> {
    let h2 = hood.iter().map(|q| q.distance_squared(p)).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    // In units of the neighbourhood's radius, so that the six columns are of one size whatever
    // the scan's units (in metres, a quadric term of a millimetre's neighbourhood is 10⁻⁶ of
    // the constant one, and the system would look singular).
    let radius = h2.sqrt();
    let mut ata = [[0.0f64; 6]; 6];
    let mut atb = [0.0f64; 6];
    for q in hood {
        let d = (*q - p) / radius;
        let (x, y, h) = (d.dot(e1), d.dot(e2), d.dot(normal));
        let w = (-sharpness * d.length_squared()).exp();
        let r = [1.0, x, y, x * x, x * y, y * y];
        for i in 0..6 {
            for j in 0..6 {
                ata[i][j] += w * r[i] * r[j];
            }
            atb[i] += w * r[i] * h;
        }
    }
    // Back to the scan's units: h = R·H(x/R, y/R).
    crate::noise::solve6(ata, atb)
        .map(|c| [c[0] * radius, c[1], c[2], c[3] / radius, c[4] / radius, c[5] / radius])
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

/// Neighbours joined to each point in the graph [`PointSurface::orient_by_tree`] spans.
const TREE_NEIGHBOURS: usize = 8;

/// A file's normals are taken with their sides when the sides the tree of
/// [`PointSurface::orient_by_tree`] gives them agree with theirs on at least this fraction of
/// the points, or disagree on as many (all turned: still one orientation); nearer half and
/// half, their sides are not one orientation and the tree's are taken.
const ORIENTED: f64 = 0.8;

/// The grid spacing of [`PointSurface::zero_set`] for points as dense as their surface's
/// detail, in point spacings.
pub const CELL: f64 = 1.5;

/// Grid cells about each point where the signed distance is evaluated, at least, and at most
/// (where the points about it are sparser than the grid).
const BAND: usize = 1;

/// The most grid cells about a point where the signed distance is evaluated.
const MAX_BAND: usize = 4;

/// A node counts only if its height over the nearest patch is within this many cells (or of
/// the nearest point's own spacings, where that is larger): farther, its sign says nothing of a
/// surface between it and its neighbours.
const NEAR: f64 = 2.0;

/// How far, in grid cells, a grid node's foot on the nearest point's tangent plane may lie
/// from that point for the signed distance to count (2 point spacings at [`CELL`]).
const REACH: f64 = 2.0 / CELL;

impl PointSurface {
    /// The zero set of the points' signed distance (Hoppe et al. 1992): the height over the
    /// patch of the nearest point, evaluated on a grid of spacing `cell` within one cell of a
    /// point (or 1.5 of its own spacing, where the points about it are sparser than the grid,
    /// up to four cells), and only where the node's foot on that patch's tangent plane is
    /// within 4/3 of a cell of the point, or twice its own spacing (so that the zero set ends at
    /// the rims of the scan's holes rather than running on along tangent planes, wherever the
    /// scan is sparser or denser), and whose height over it is within two cells (or two of the
    /// point's spacings: no surface appears midway between two sheets, where the nearest point
    /// passes from one to the other), meshed by [`crate::surfacenets`]: an open or closed
    /// mesh whose triangles wind counter-clockwise seen from the side the patches face.
    /// A cell of [`CELL`] point spacings follows every detail the points resolve; a coarser one
    /// gives a coarser mesh at less cost. Only the grid's band is stored (see
    /// [`crate::surfacenets`]): the memory grows with the surface, not with the volume.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidOption`] for a cell that is not positive and finite;
    /// [`Error::Degenerate`] when the grid would span more than
    /// [`crate::surfacenets::MAX_SPARSE_NODES`] nodes (a cell far finer than the points'
    /// extent).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_scan::implicit::{CELL, PointSurface};
    ///
    /// // 4000 points on the unit sphere (Fibonacci): a closed mesh near the sphere.
    /// let points: Vec<DVec3> = (0..4000)
    ///     .map(|k| {
    ///         let z = 1.0 - (2 * k + 1) as f64 / 4000.0;
    ///         let phi = k as f64 * 2.399_963_229_728_653;
    ///         let s = (1.0 - z * z).sqrt();
    ///         DVec3::new(s * phi.cos(), s * phi.sin(), z)
    ///     })
    ///     .collect();
    /// let surface = PointSurface::try_new(&points, None, 16).unwrap();
    /// let (vertices, triangles) = surface.zero_set(CELL * surface.spacing()).unwrap();
    /// assert!(vertices.iter().all(|p| (p.length() - 1.0).abs() < 0.01));
    /// // Closed and of genus 0: V − E + F = 2 with E = 3F/2.
    /// assert_eq!(vertices.len() as i64 - triangles.len() as i64 / 2, 2);
    /// ```
    pub fn zero_set(&self, cell: f64) -> Result<(Vec<DVec3>, Vec<[u32; 3]>), Error> {
        self.zero_set_of(cell, &self.patches.iter().collect::<Vec<_>>())
    }

    /// [`PointSurface::zero_set`] in the band about the points `about` (indices) only: the
    /// zero set of the same signed distance (every point's patch still counts where it is the
    /// nearest), on a grid that spans those points, so that a part of the scan can be taken
    /// again on a grid of its own ([`PointSurface::zero_set_cell_of`]). Indices beyond
    /// [`PointSurface::len`] are skipped.
    ///
    /// # Errors
    ///
    /// As [`PointSurface::zero_set`]'s; [`Error::Degenerate`] when `about` names no point.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_scan::implicit::PointSurface;
    ///
    /// // Two unit spheres 4 apart, 2000 points each (Fibonacci): the zero set about the
    /// // second's points is the second sphere alone.
    /// let sphere = |c: DVec3| {
    ///     (0..2000).map(move |k| {
    ///         let z = 1.0 - (2 * k + 1) as f64 / 2000.0;
    ///         let phi = k as f64 * 2.399_963_229_728_653;
    ///         let s = (1.0 - z * z).sqrt();
    ///         c + DVec3::new(s * phi.cos(), s * phi.sin(), z)
    ///     })
    /// };
    /// let points: Vec<DVec3> = sphere(DVec3::ZERO).chain(sphere(4.0 * DVec3::X)).collect();
    /// let surface = PointSurface::try_new(&points, None, 16).unwrap();
    /// let second: Vec<u32> = (2000..4000).collect();
    /// let cell = surface.zero_set_cell_of(&second).unwrap();
    /// let (vertices, _) = surface.zero_set_about(cell, &second).unwrap();
    /// assert!(vertices.iter().all(|p| ((*p - 4.0 * DVec3::X).length() - 1.0).abs() < 0.02));
    /// ```
    pub fn zero_set_about(
        &self,
        cell: f64,
        about: &[u32],
    ) -> Result<(Vec<DVec3>, Vec<[u32; 3]>), Error> {
        let seeds: Vec<&Patch> =
            about.iter().filter_map(|&k| self.patches.get(k as usize)).collect();
        if seeds.is_empty() {
            return Err(Error::Degenerate { what: "no point to take the zero set about" });
        }
        self.zero_set_of(cell, &seeds)
    }

    /// [`PointSurface::zero_set`] on the band about the patches `seeds`.
    fn zero_set_of(
        &self,
        cell: f64,
        seeds: &[&Patch],
    ) -> Result<(Vec<DVec3>, Vec<[u32; 3]>), Error> {
        if !(cell.is_finite() && cell > 0.0) {
            return Err(Error::InvalidOption {
                name: "zero-set cell",
                value: cell,
                expected: "positive and finite",
            });
        }
        let h = cell;
        let (lo, hi) = seeds
            .iter()
            .map(|p| p.origin)
            .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(p), hi.max(p)));
        let pad = (MAX_BAND + 2) as f64 * h;
        let origin = lo - DVec3::splat(pad);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "checked below"
        )]
        let dims = ((hi - lo + DVec3::splat(2.0 * pad)) / h)
            .ceil()
            .to_array()
            .map(|d| if d.is_finite() && d < 1e6 { d as usize + 1 } else { usize::MAX / 4 });
        let nodes = dims.iter().try_fold(1usize, |a, &d| a.checked_mul(d)).unwrap_or(usize::MAX);
        if nodes as u64 > crate::surfacenets::MAX_SPARSE_NODES {
            return Err(Error::Degenerate { what: "the points are too sparse for their extent" });
        }
        // The band's nodes are marked +∞, then given their value or NaN.
        let mut grid = crate::surfacenets::SparseGrid::new(origin, h, dims);
        for patch in seeds {
            let p = patch.origin;
            #[expect(clippy::cast_possible_truncation, reason = "inside the grid")]
            let c = ((p - origin) / h).floor().to_array().map(|x| x as isize);
            #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "clamped")]
            let b = ((1.5 * patch.local / h).ceil() as usize).clamp(BAND, MAX_BAND) as isize;
            for dk in -b..=b + 1 {
                for dj in -b..=b + 1 {
                    for di in -b..=b + 1 {
                        // The padding keeps these positive.
                        let at = [c[0] + di, c[1] + dj, c[2] + dk].map(isize::unsigned_abs);
                        grid.set(at[0], at[1], at[2], f64::INFINITY);
                    }
                }
            }
        }
        // Known within the band, where the node's foot on the nearest point's tangent plane is
        // near that point (Hoppe's test: the zero set stops where the points do, at the rims of
        // holes).
        let reach = REACH * h;
        grid.update(|x, value| {
            if *value != f64::INFINITY {
                return;
            }
            let (f, off, local) = self.signed_with_spacing(x);
            // A node much farther from the surface than a cell is no witness of where the
            // surface is: between two sheets, where the nearest point passes from one to
            // the other, the height jumps across zero without a surface there.
            let near = f.abs() <= NEAR * h.max(local);
            *value =
                if off <= reach.max(2.0 * local) && near && f.is_finite() { f } else { f64::NAN };
        });
        Ok(grid.surface_nets())
    }
}

/// The points themselves, for a moving least-squares projection (Levin, "Mesh-independent
/// surface interpolation", 2003; Alexa et al., "Computing and rendering point set surfaces",
/// 2003): a point x with a normal n goes to the height over its own tangent plane of the
/// quadric fitted to its nearest points, weighted by a Gaussian of their distance. Where
/// [`PointSurface::project`] blends patches fitted once about the points (or about a summary
/// of them), this fits afresh about every point projected, to the points as they are.
#[derive(Debug)]
pub struct MovingLeastSquares<'a> {
    tree: ImmutableKdTree<f64, 3>,
    points: &'a [DVec3],
}

/// Points fitted per projection by [`MovingLeastSquares::project`].
pub const MLS_NEIGHBOURS: usize = 16;

/// The sharpness s of the Gaussian weight exp(−s d²) of a neighbour at d neighbourhood radii
/// (the distance to the farthest of the [`MLS_NEIGHBOURS`]) in [`MovingLeastSquares::project`]:
/// σ = 1/√(2s) = 0.29 radii, so that the nearest few neighbours carry the fit and it follows
/// the points closely, where 1 (σ = 0.71 radii, as for the patches of [`PointSurface`]) nearly
/// averages them.
/// Chosen by the mean distance from the points to the fitted surface over the shared models'
/// bare vertices and clouds of 2·10⁵ noisy points: it fell from 1 to 6 on every one (by 2 to
/// 14 %), and rose again from 12 on the clouds (the noise followed too).
pub const MLS_SHARPNESS: f64 = 6.0;

/// Points within the band that a fit of [`MovingLeastSquares::project`] needs, at least.
const MLS_MIN: usize = 8;

impl<'a> MovingLeastSquares<'a> {
    /// The projector onto the surface of `points`.
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`] for a non-finite point; [`Error::TooFewPoints`] for fewer than
    /// [`MLS_NEIGHBOURS`].
    pub fn try_new(points: &'a [DVec3]) -> Result<Self, Error> {
        if let Some(k) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinite { what: NonFiniteInput::Point(k) });
        }
        if points.len() < MLS_NEIGHBOURS {
            return Err(Error::TooFewPoints { found: points.len(), needed: MLS_NEIGHBOURS });
        }
        let tree = ImmutableKdTree::new_from_slice(crate::distance::as_arrays(points))
            .map_err(|_| Error::Degenerate { what: "the points do not form a kd-tree" })?;
        Ok(Self { tree, points })
    }

    /// The projection of `x` along its unit `normal`: the height at x's foot of the quadric
    /// h(u, v) fitted by weighted least squares (weights of sharpness [`MLS_SHARPNESS`]), over
    /// the plane through x across `normal`, to those of its [`MLS_NEIGHBOURS`] nearest points
    /// whose height over that plane is within
    /// `band` (the points of another sheet, across a part thinner than that, left out); `None`
    /// when fewer than 8 are, or the fit is degenerate.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use hi_scan::implicit::MovingLeastSquares;
    ///
    /// // Points on the paraboloid z = x² + y²: a point above it goes onto it.
    /// let points: Vec<DVec3> = (0..441)
    ///     .map(|k| {
    ///         let (x, y) = ((k % 21) as f64 * 0.05 - 0.5, (k / 21) as f64 * 0.05 - 0.5);
    ///         DVec3::new(x, y, x * x + y * y)
    ///     })
    ///     .collect();
    /// let mls = MovingLeastSquares::try_new(&points).unwrap();
    /// let q = mls.project(DVec3::new(0.1, 0.05, 0.06), DVec3::Z, 0.1).unwrap();
    /// assert!((q - DVec3::new(0.1, 0.05, 0.0125)).length() < 1e-9);
    /// ```
    #[must_use]
    pub fn project(&self, x: DVec3, normal: DVec3, band: f64) -> Option<DVec3> {
        let normal = normal.try_normalize()?;
        let k = NonZero::new(MLS_NEIGHBOURS).unwrap_or(NonZero::<usize>::MIN);
        let near = self.tree.query(&x.to_array()).nearest_n::<SquaredEuclidean<f64>>(k).execute();
        let hood: Vec<DVec3> = near
            .iter()
            .map(|n| self.points[n.item as usize])
            .filter(|q| (*q - x).dot(normal).abs() <= band)
            .collect();
        if hood.len() < MLS_MIN {
            return None;
        }
        let e1 = normal.any_orthonormal_vector();
        let c = fit_quadric(x, (e1, normal.cross(e1), normal), &hood, MLS_SHARPNESS)?;
        // The frame is x's: the height at its foot is c₀.
        Some(x + normal * c[0])
    }
}

/// Area-weighted unit vertex normals of a triangle mesh (zero at a vertex whose triangles
/// cancel or that no triangle uses; a triangle with an index out of range is skipped).
#[must_use]
pub fn vertex_normals(positions: &[DVec3], triangles: &[[u32; 3]]) -> Vec<DVec3> {
    let mut normals = vec![DVec3::ZERO; positions.len()];
    for t in triangles {
        // A triangle with an index out of range has no normal to give.
        let Some([a, b, c]) = t
            .iter()
            .map(|&k| positions.get(k as usize).copied())
            .collect::<Option<Vec<_>>>()
            .and_then(|v| <[DVec3; 3]>::try_from(v).ok())
        else {
            continue;
        };
        let n = (b - a).cross(c - a);
        for &k in t {
            normals[k as usize] += n;
        }
    }
    normals.iter().map(|n| n.normalize_or_zero()).collect()
}
