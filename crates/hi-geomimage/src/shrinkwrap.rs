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
//!    al.'s signed distance), meshed by [`hi_scan::surfacenets`] on a grid of 1.5 point spacings
//!    (of the spacing of the scan's denser parts, [`PointSurface::fine_spacing`]),
//!    evaluated only near the points and only where a node's foot on the tangent plane is near
//!    its point, so that the surface ends at the rims of the scan's holes. That mesh is closed
//!    by [`hi_scan::repair::close_mesh`] (its holes bridged) and parameterised over the sphere
//!    ([`crate::sphereparam`]), its stretch weighed by the points' density so that where the
//!    points are dense the texels are too (see `point_density_weights`); the image is sampled
//!    from the parameterisation, so its texels spread over every arm, ear and concavity
//!    whatever the rays would have seen.
//! 2. **The projection**: every texel moves onto the point set's surface: to the
//!    Gaussian-weighted blend of its projections onto the patches of its three nearest points
//!    that face its way (its normal across the grid's two directions), a move of at most 1.5
//!    point spacings (a longer one would cross to the other side of a part thinner than the
//!    grid; a texel with no point within 1.5 spacings, which has no sheet to cross, moves 1.5
//!    spacings towards its projection instead). Texels on the patches bridging holes, and
//!    texels farther than four point spacings from every point, stay where they are and are
//!    flagged [`ShrinkWrapImage::filled`].
//! 3. **The pull**: a point the surface passed by (more than 0.75 spacings off it along the
//!    normal of its nearest texel, the spacing of the points about it where they are denser
//!    than the median; its nearest texel within three spacings, beyond which the point is
//!    taken for an outlier) pulls onto it the one of its four nearest texels whose normal's line
//!    passes nearest to it, within one spacing, its patch facing the same way (the nearest
//!    texel may lie beside a crease, its normal missing the point). This reaches into creases
//!    and slits narrower than the grid of step
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

use glam::DVec3;
use hi_par::*;
use hi_scan::implicit::{MovingLeastSquares, PointSurface, vertex_normals};
use hi_scan::repair::ClosedMesh;
use kiddo::{ImmutableKdTree, SquaredEuclidean};

use crate::domain::Domain;
use crate::sphereparam::density_weight;
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
    let mut patches = PointSurface::try_new(points, normals, neighbours)?;
    // The rays from the centre, for the diagnostic and as the fallback's start.
    let (cr, cc) = (rows.min(COARSE), cols.min(COARSE));
    let start = spherical_image(
        points,
        &SphericalOptions { layout, rows: cr, cols: cc, centre, ..SphericalOptions::default() },
    )?;
    let param_options = crate::sphereparam::SphereParamOptions::default();
    // The start: the zero set of the points' signed distance, parameterised over the sphere.
    let implicit = implicit_surface(&patches)
        .and_then(|closed| {
            patches.orient_to(
                &closed.positions,
                &vertex_normals(&closed.positions, &closed.triangles),
            );
            let weights = point_density_weights(&patches, &closed);
            crate::sphereparam::parameterise_weighted(&closed, &weights, &param_options)
        })
        .and_then(|param| param.image(layout, rows, cols));
    let (first, reparameterised, implicit_start, on_fills) = if let Ok(image) = implicit {
        (image.image.texels().to_vec(), true, true, Some(image.filled))
    } else {
        // Else the coarse radial image wrapped, then its mesh parameterised: the texels of the
        // final image spread over the wrapped surface evenly, however the rays crowded them.
        let (coarse, _) =
            wrap(&patches, start.image.texels().to_vec(), None, layout.into(), cr, cc, iterations);
        // Every patch faces out as the wrapped surface does.
        patches.orient_to(&coarse, &grid_normals(&coarse, cr, cc));
        let resampled = GeometryImage::try_new(cr, cc, coarse)
            .and_then(|image| image.surface())
            .and_then(|surface| crate::layout_mesh::layout_mesh(&surface, layout, 1))
            .and_then(|m| Ok(hi_scan::repair::close_mesh(m.mesh.positions(), m.mesh.triangles())?))
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
    let settled = settle(
        &patches,
        points,
        first,
        on_fills.as_deref(),
        Domain::Sphere(layout),
        (rows, cols),
        rounds,
    );
    Ok(ShrinkWrapImage {
        image: GeometryImage::try_new(rows, cols, settled.texels)?,
        filled: settled.filled,
        filled_fraction: settled.filled_fraction,
        non_star_fraction: start.non_star_fraction,
        implicit_start,
        reparameterised,
        rms_move: settled.rms_move,
        pulled: settled.pulled,
    })
}

/// An image settled onto a point set's surface ([`settle`]).
pub(crate) struct Settled {
    /// The texels.
    pub(crate) texels: Vec<DVec3>,
    /// Texels with no point near, or on a patch bridging a hole.
    pub(crate) filled: Vec<bool>,
    /// The fraction of the distinct texels filled.
    pub(crate) filled_fraction: f64,
    /// The root mean square move of the texels.
    pub(crate) rms_move: f64,
    /// Texels pulled onto points (each once).
    pub(crate) pulled: usize,
}

/// Steps 2 and 3 of the module documentation on the texels `first` of a `rows × cols` image
/// over `domain`: `rounds` of projection and spreading onto the local surface `patches` of
/// `points` (0 for an image sampled from a parameterisation of their zero set, whose texels
/// `on_fills` flags those on the patches closing holes; each move then at most [`MAX_MOVE`]
/// point spacings), then the pull into the creases the texels passed by.
pub(crate) fn settle(
    patches: &PointSurface,
    points: &[DVec3],
    first: Vec<DVec3>,
    on_fills: Option<&[bool]>,
    domain: Domain,
    (rows, cols): (usize, usize),
    rounds: usize,
) -> Settled {
    let (mut x, filled) = wrap(patches, first.clone(), on_fills, domain, rows, cols, rounds);
    let pulled = pull(patches, points, &mut x, &filled, domain, rows, cols);
    // Each point of the object once, for the fractions.
    let owner = domain.owners(rows, cols);
    let distinct = owner.iter().enumerate().filter(|&(t, &o)| o == t).count().max(1);
    let filled_fraction = owner.iter().enumerate().filter(|&(t, &o)| o == t && filled[t]).count()
        as f64
        / distinct as f64;
    let rms_move = (x.iter().zip(&first).map(|(a, b)| a.distance_squared(*b)).sum::<f64>()
        / x.len().max(1) as f64)
        .sqrt();
    Settled { texels: x, filled, filled_fraction, rms_move, pulled }
}

/// Moves every texel of a `rows × cols` image over `domain` not flagged `filled` to its
/// moving least-squares projection onto the points of `mls` along its normal across the grid
/// ([`MovingLeastSquares::project`], the points within `band` of its tangent plane), by at most
/// `band`; a texel whose projection fails stays. The image's copies of a texel follow it (and
/// each pole row of the latitude–longitude sphere stays one point).
pub(crate) fn refine(
    mls: &MovingLeastSquares<'_>,
    x: &mut [DVec3],
    filled: &[bool],
    domain: Domain,
    (rows, cols): (usize, usize),
    band: f64,
) {
    let owner = domain.owners(rows, cols);
    let normals = grid_normals(x, rows, cols);
    let moved: Vec<DVec3> = (0..rows * cols)
        .into_par_iter()
        .map(|t| {
            if owner[t] != t || filled[t] {
                return x[t];
            }
            mls.project(x[t], normals[t], band).filter(|q| q.distance(x[t]) <= band).unwrap_or(x[t])
        })
        .collect();
    for (t, texel) in x.iter_mut().enumerate() {
        *texel = moved[owner[t]];
    }
    // The latitude–longitude sphere's pole rows one point again.
    symmetrise(x, &owner, domain, rows, cols);
}

/// Smooths the texels flagged `filled` (those of the caps over the scan's holes) of a
/// `rows × cols` image over `domain` as a membrane spanned by the others: [`FILL_SWEEPS`]
/// Jacobi sweeps, each filled texel to the mean of its four neighbours across the grid (the
/// image's copies of a texel following it). The texels on the points are held, and so are the
/// filled texels within [`FILL_HOLD`] point spacings of a point of `patches` (the rim of a cap,
/// which the points about it pin). A cap sampled from the closed zero set lies on its flat
/// triangles while the texels about it have moved onto the points: a step along the rim, which
/// the harmonic surface through the texels folds across.
pub(crate) fn smooth_fills(
    patches: &PointSurface,
    x: &mut [DVec3],
    filled: &[bool],
    domain: Domain,
    (rows, cols): (usize, usize),
) {
    let owner = domain.owners(rows, cols);
    let hold = FILL_HOLD * patches.spacing();
    let free: Vec<usize> = (0..rows * cols)
        .into_par_iter()
        .filter(|&t| owner[t] == t && filled[t] && patches.project(x[t], DVec3::ZERO).1 > hold)
        .collect();
    if free.is_empty() {
        return;
    }
    let copies: Vec<usize> =
        (0..rows * cols).filter(|&t| owner[t] != t && filled[owner[t]]).collect();
    for sweep in 0..FILL_SWEEPS {
        let moved: Vec<DVec3> = free
            .par_iter()
            .with_min_len(1024)
            .map(|&t| {
                let (i, j) = (t / cols, t % cols);
                (x[((i + rows - 1) % rows) * cols + j]
                    + x[((i + 1) % rows) * cols + j]
                    + x[i * cols + (j + cols - 1) % cols]
                    + x[i * cols + (j + 1) % cols])
                    / 4.0
            })
            .collect();
        for (&t, m) in free.iter().zip(moved) {
            x[t] = m;
        }
        for &t in &copies {
            x[t] = x[owner[t]];
        }
        // The copies of the texels moved follow them, and the others keep the symmetry the
        // first sweep gave them: after it, only the pole rows of the latitude–longitude
        // sphere need making one point again.
        if sweep == 0 {
            symmetrise(x, &owner, domain, rows, cols);
        } else {
            join_poles(x, domain, rows, cols);
        }
    }
}

/// The sweeps of [`smooth_fills`]. Measured on the bare vertices of the shared models and
/// CGAL's building (100 000 points, its caps over its open floor and windows a third of its
/// zero set): the edges of the building's output mesh folded by more than 120° fell from 11.3 %
/// to 5.1 % (Hoppe's mechanical part's from 4.1 % to 2.7 %, the cessna's from 6.3 % to 4.7 %,
/// screened Poisson's: 0.03 %), its mean error rising by 0.7 %; 16 sweeps (holding no texel)
/// left 1.2 times the folds of 64, and 256 as many as 64.
pub(crate) const FILL_SWEEPS: usize = 64;

/// How near, in point spacings, a point holds a filled texel in [`smooth_fills`]. Holding none
/// smoothed the building's caps a little more (3.7 % of its edges folded), but moved the texels
/// beside the points at their rims: its mean error 13 % higher; 2 spacings held more of the rim
/// ragged (6.4 %) for no lower error.
pub(crate) const FILL_HOLD: f64 = 1.0;

/// The zero set of the points' signed distance on the grid of
/// [`PointSurface::zero_set_cell`] ([`PointSurface::zero_set`]), its holes closed and the whole
/// made genus 0 by
/// [`hi_scan::repair::close_mesh`].
fn implicit_surface(patches: &PointSurface) -> Result<ClosedMesh, Error> {
    let (positions, triangles) = patches.zero_set(patches.zero_set_cell())?;
    Ok(hi_scan::repair::close_mesh(&positions, &triangles)?)
}

/// How far, in point spacings, a texel of the implicit start may move onto the points'
/// patches.
const MAX_MOVE: f64 = 1.5;

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

/// How far off the surface, in point spacings along the normal of its nearest texel, a point
/// must lie to pull that texel onto it (spacings of the points about it where they are denser
/// than the median). Against the median spacing alone, the mean error of the fit report fell
/// or stayed on every scan tried (the bare vertices of every shared model, CGAL's point sets,
/// the bench's clouds): by 27 % on spot's bare vertices, 10 % on the head scan's, 6 % on CGAL's
/// `elephant-with-holes` and `oni`, by 1 % or less on evenly sampled scans; the output meshes'
/// edges folded by more than 120° rose by 1–6 % of their number (spot's from 0.149 % to
/// 0.158 % of its edges).
const PULL_FROM: f64 = 0.75;

/// How far to the side of its nearest texel, in point spacings, a point may lie and pull it.
const PULL_SIDE: f64 = 1.0;

/// Beyond this many point spacings from its nearest texel a point is an outlier: it pulls
/// nothing.
const PULL_UNTIL: f64 = 3.0;

/// Texels nearest to a point that it may pull ([`pull`]).
const PULL_CANDIDATES: NonZero<usize> = NonZero::new(4).unwrap();

/// Step 3 of the module documentation: each point the surface `x` left more than [`PULL_FROM`]
/// spacings off it (the points' median spacing, or the spacing of the points about it where
/// that is smaller: [`PointSurface::local_spacing`]), along the normal of its nearest texel
/// (not flagged `filled`), pulls the one of its [`PULL_CANDIDATES`] nearest texels whose
/// normal's line passes nearest to it (within [`PULL_SIDE`] spacings, the point's patch facing
/// the texel's way) onto it, if its nearest texel is within [`PULL_UNTIL`] spacings (onto the
/// mean of the points pulling it, its mirror with it). Returns the number of texels moved.
fn pull(
    patches: &PointSurface,
    points: &[DVec3],
    x: &mut [DVec3],
    filled: &[bool],
    domain: Domain,
    rows: usize,
    cols: usize,
) -> usize {
    let owner = domain.owners(rows, cols);
    let owners: Vec<usize> = (0..rows * cols).filter(|&t| owner[t] == t && !filled[t]).collect();
    let Ok(tree): Result<ImmutableKdTree<f64, 3>, _> = ImmutableKdTree::new_from_slice(
        &owners.iter().map(|&t| x[t].to_array()).collect::<Vec<_>>(),
    ) else {
        return 0;
    };
    let normals = grid_normals(x, rows, cols);
    let spacing = patches.spacing();
    // A point outside the texels' box grown by PULL_UNTIL spacings (and a little, against
    // rounding) is farther than that from every texel: it pulls nothing, and is not looked up
    // (most of the points, for one part of many).
    let reach = DVec3::splat(PULL_UNTIL * spacing * (1.0 + 1e-6));
    let (lo, hi) = owners
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), &t| (lo.min(x[t]), hi.max(x[t])));
    let (lo, hi) = (lo - reach, hi + reach);
    let pulls: Vec<Option<(usize, DVec3)>> = points
        .par_iter()
        .enumerate()
        .filter(|(_, p)| p.cmpge(lo).all() && p.cmple(hi).all())
        .map(|(k, p)| {
            // The surface passed the point by: it lies off the nearest texel's tangent plane.
            // Of the nearest few texels, the one whose normal's line passes closest to the
            // point moves onto it (the nearest alone may lie beside the crease, its normal
            // missing the point).
            let near = tree
                .query(&p.to_array())
                .nearest_n::<SquaredEuclidean<f64>>(PULL_CANDIDATES)
                .execute();
            let first = near.first()?;
            let t = *owners.get(first.item as usize)?;
            let off = (*p - x[t]).dot(normals[t]);
            // Where the points are denser than the median (a crease or a rim sampled finely),
            // a point off the surface by most of their spacing there is detail it missed.
            // (A point with fewer than 8 others has no spacing of its own: the median's.)
            let local = patches.local_spacing(k);
            let from = PULL_FROM * if local > 0.0 { spacing.min(local) } else { spacing };
            if off.abs() <= from || first.distance.sqrt() >= PULL_UNTIL * spacing {
                return None;
            }
            near.iter()
                .filter_map(|near| {
                    let t = *owners.get(near.item as usize)?;
                    let (v, n) = (*p - x[t], normals[t]);
                    let side = (v - n * v.dot(n)).length();
                    (side <= PULL_SIDE * spacing && patches.normal(k).dot(n) > 0.0)
                        .then_some((side, t))
                })
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .map(|(_, t)| (t, *p))
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

/// Each texel and the copies of it a doubled image holds take their mean (the doubled images'
/// symmetry restored); on the latitude–longitude sphere each pole row becomes one point.
fn symmetrise(v: &mut [DVec3], owner: &[usize], domain: Domain, rows: usize, cols: usize) {
    join_poles(v, domain, rows, cols);
    let mut sum = vec![(DVec3::ZERO, 0u32); v.len()];
    for (t, x) in v.iter().enumerate() {
        sum[owner[t]].0 += *x;
        sum[owner[t]].1 += 1;
    }
    for (t, x) in v.iter_mut().enumerate() {
        let (total, count) = sum[owner[t]];
        if count > 1 {
            *x = total / f64::from(count);
        }
    }
}

/// On the latitude–longitude sphere, each pole row of the texels `v` of a `rows × cols` image
/// made one point, their mean (over the other domains, nothing).
fn join_poles(v: &mut [DVec3], domain: Domain, rows: usize, cols: usize) {
    if domain == Domain::Sphere(Layout::Sphere) {
        for i in [0, rows / 2] {
            let mean = v[i * cols..(i + 1) * cols].iter().copied().sum::<DVec3>() / cols as f64;
            v[i * cols..(i + 1) * cols].iter_mut().for_each(|x| *x = mean);
        }
    }
}

/// The side of the coarse wrap.
const COARSE: usize = 96;

/// Rounds of projection and spreading on the final image.
const FINE_ROUNDS: usize = 2;

/// `rounds` of projection and spreading of the texels `x` of a `rows × cols` image (the last
/// step a projection), with the doubled images' symmetry kept; the texels and which of them
/// had no point near. `on_fills` is given for an image of the implicit start: it flags the
/// texels on the patches that close the scan's holes, which have no data either (whatever
/// points are near the hole's rim), and every other texel moves at most [`MAX_MOVE`] point
/// spacings.
fn wrap(
    patches: &PointSurface,
    mut x: Vec<DVec3>,
    on_fills: Option<&[bool]>,
    domain: Domain,
    rows: usize,
    cols: usize,
    rounds: usize,
) -> (Vec<DVec3>, Vec<bool>) {
    // Beyond this from every point a texel has no data.
    let reach = 4.0 * patches.spacing();
    let owner = domain.owners(rows, cols);
    let symmetrise = |v: &mut [DVec3]| symmetrise(v, &owner, domain, rows, cols);
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
                let limit = MAX_MOVE * patches.spacing();
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

/// The weights of the stretch of `mesh`'s spherical map (a part of the points' zero set) for
/// [`parameterise_weighted`](crate::sphereparam::parameterise_weighted): at each vertex, the
/// [`density_weight`] of the points' density there ([`PointSurface::relative_density`]), where
/// the points are unevenly dense, and 1 where they are evenly dense
/// ([`PointSurface::fine_spacing`] is their median spacing). A mesh's vertices are dense where
/// the mesh has detail, and so are the texels then; a scanner's density varies with the angle
/// of view, not with the detail, and following it would take texels from the surfaces it saw
/// at a slant (a crease of Hoppe's duck, measured: its worst point 1.13 times farther).
pub(crate) fn point_density_weights(surface: &PointSurface, mesh: &ClosedMesh) -> Vec<f64> {
    if surface.fine_spacing() >= surface.spacing() {
        return vec![1.0; mesh.positions.len()];
    }
    mesh.positions.par_iter().map(|&x| density_weight(surface.relative_density(x))).collect()
}

/// The `weights` of [`point_density_weights`] for the closed zero set `mesh` of a point set's
/// part, with every vertex all of whose triangles were added to close a hole (the inside of a
/// cap, which has no point about it) given the weight of density 0, [`density_weight`]`(0)`, the
/// least, so that the texels go to the points rather than to the guess between them. Measured
/// with the fit on the bare vertices of the shared models and CGAL's building (100 000 points, a
/// third of whose zero set is caps over its open floor and windows): the building's filled
/// texels fell from 63 % to 55 % and its mean error by 12 %, Hoppe's mechanical part's by 13 %,
/// `wuson`'s by 10 %, Hoppe's cessna's by 6 %; the head's rose by 4 % and `spot`'s by 6 % (its
/// caps are 0.2 % of its texels: the change of any weight moves its map that much), the others'
/// moved by 2 % or less. A mesh's caps keep their weight
/// ([`mesh_density_weights`](crate::sphereparam::mesh_density_weights)): its texels lie on its
/// flat triangles, and on CGAL's `elephant-with-holes` thinning them over the caps raised the
/// mean error by 7 %. Nor does [`shrink_wrap`] use it: on the rubber duck's creases its worst
/// point went from 1.34 to 1.56 point spacings off.
pub(crate) fn with_empty_caps(mut weights: Vec<f64>, mesh: &ClosedMesh) -> Vec<f64> {
    let mut on_points = vec![false; mesh.positions.len()];
    for (t, _) in mesh.triangles.iter().zip(&mesh.filled).filter(|(_, filled)| !**filled) {
        for &k in t {
            on_points[k as usize] = true;
        }
    }
    for (w, _) in weights.iter_mut().zip(&on_points).filter(|(_, on)| !**on) {
        *w = density_weight(0.0);
    }
    weights
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sphereparam::DENSITY_WEIGHT_MAX;
    use hi_scan::repair::{ADDED_VERTEX, close_mesh};

    /// A tube (a sphere's band between 30° and 150° from its pole, 24 × 48 quads) closed by two
    /// caps: the caps' added centres, on no point, weigh the least ([`density_weight`] of
    /// density 0); the vertices on the points weigh more.
    #[test]
    fn a_cap_away_from_the_points_weighs_the_least() {
        let (rows, cols) = (24u32, 48u32);
        let at = |i: u32, j: u32| {
            let theta = std::f64::consts::PI * (1.0 + 4.0 * f64::from(i) / f64::from(rows)) / 6.0;
            let phi = std::f64::consts::TAU * f64::from(j) / f64::from(cols);
            DVec3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos())
        };
        let points: Vec<DVec3> =
            (0..=rows).flat_map(|i| (0..cols).map(move |j| at(i, j))).collect();
        let id = |i: u32, j: u32| i * cols + j % cols;
        let triangles: Vec<[u32; 3]> = (0..rows)
            .flat_map(|i| {
                (0..cols).flat_map(move |j| {
                    [
                        [id(i, j), id(i + 1, j), id(i + 1, j + 1)],
                        [id(i, j), id(i + 1, j + 1), id(i, j + 1)],
                    ]
                })
            })
            .collect();
        let closed = close_mesh(&points, &triangles).unwrap();
        assert!(closed.filled.iter().any(|&f| f), "two caps");
        let surface = PointSurface::try_new(&points, None, 16).unwrap();
        let weights = with_empty_caps(point_density_weights(&surface, &closed), &closed);
        let mut centres = 0;
        for (k, &w) in weights.iter().enumerate() {
            if closed.scan_vertex[k] == ADDED_VERTEX {
                centres += 1;
                assert_eq!(w, 1.0 / DENSITY_WEIGHT_MAX, "a cap's centre");
            } else {
                assert!(w > 1.0 / DENSITY_WEIGHT_MAX, "a point's vertex {k}: {w}");
            }
        }
        assert!(centres >= 2, "{centres}");
    }

    /// A 6 × 6 block of filled texels lifted 1 off a flat torus image of 24 × 24 texels, the
    /// others on points of the plane z = 0: the membrane they span is the plane (the discrete
    /// Dirichlet problem with zero boundary values has the solution 0, and Jacobi's sweeps
    /// reach it by a factor of cos(π/7) < 0.91 a sweep), so the block comes down to within
    /// 0.91⁶⁴ < 0.003 of it; the texels on the points do not move. A filled texel with a point
    /// beside it is held.
    #[test]
    fn a_cap_is_smoothed_to_the_membrane_its_rim_spans() {
        let n = 24usize;
        let block = |t: usize| (9..15).contains(&(t / n)) && (9..15).contains(&(t % n));
        let grid = |t: usize| DVec3::new((t / n) as f64, (t % n) as f64, 0.0);
        let points: Vec<DVec3> = (0..n * n).filter(|&t| !block(t)).map(grid).collect();
        let surface = PointSurface::try_new(&points, None, 16).unwrap();
        let lifted: Vec<DVec3> =
            (0..n * n).map(|t| grid(t) + DVec3::Z * f64::from(u8::from(block(t)))).collect();
        let filled: Vec<bool> = (0..n * n).map(block).collect();
        let mut x = lifted.clone();
        smooth_fills(&surface, &mut x, &filled, Domain::Torus, (n, n));
        for t in 0..n * n {
            if block(t) {
                assert!(x[t].z.abs() < 3e-3, "texel {t}: {}", x[t]);
            } else {
                assert_eq!(x[t], lifted[t], "texel {t} on a point");
            }
        }
        // A point under one of the block's texels holds it.
        let mut with_point = points.clone();
        with_point.push(grid(11 * n + 11) + DVec3::Z * 0.9);
        let surface = PointSurface::try_new(&with_point, None, 16).unwrap();
        let mut x = lifted.clone();
        smooth_fills(&surface, &mut x, &filled, Domain::Torus, (n, n));
        assert_eq!(x[11 * n + 11], lifted[11 * n + 11]);
        assert!(x[13 * n + 13].z < 0.5, "{}", x[13 * n + 13]);
    }

    /// The plane z = 0 sampled at unit spacing over [0, 16)², but for a patch of 8 × 8 points
    /// at spacing 1/4 about (11, 8), and a flat torus image of 64 × 64 texels on it (step 1/4).
    /// A point 0.4 above the dense patch, 1.6 of its spacings there, pulls the texel below it
    /// onto it (its own spacing, r₈/√2 with r₈ = √(2/16² + 0.4²), is 0.38, and 0.4 is beyond
    /// 0.75 of that); 0.4 above the sparse points, 0.4 of their spacing, it pulls nothing, and
    /// 0.9 above them, beyond 0.75 of it, it pulls.
    #[test]
    fn a_point_off_the_surface_pulls_by_the_spacing_of_the_points_about_it() {
        let dense = |x: f64, y: f64| (10.0..12.0).contains(&x) && (7.0..9.0).contains(&y);
        let mut points: Vec<DVec3> = (0..16 * 16)
            .map(|k| DVec3::new(f64::from(k % 16), f64::from(k / 16), 0.0))
            .filter(|p| !dense(p.x, p.y))
            .collect();
        points.extend(
            (0..64).map(|k| {
                DVec3::new(10.0 + f64::from(k % 8) / 4.0, 7.0 + f64::from(k / 8) / 4.0, 0.0)
            }),
        );
        let (above_dense, above_sparse, far_above_sparse) =
            (DVec3::new(11.0, 8.0, 0.4), DVec3::new(4.0, 8.0, 0.4), DVec3::new(4.0, 4.0, 0.9));
        points.extend([above_dense, above_sparse, far_above_sparse]);
        let surface = PointSurface::try_new(&points, None, 16).unwrap();
        assert!((surface.spacing() - 1.0).abs() < 1e-12, "{}", surface.spacing());
        let n = 64usize;
        let texel = |p: DVec3| (p.x * 4.0) as usize * n + (p.y * 4.0) as usize;
        let flat: Vec<DVec3> = (0..n * n)
            .map(|t| DVec3::new((t / n) as f64 / 4.0, (t % n) as f64 / 4.0, 0.0))
            .collect();
        let mut x = flat.clone();
        let pulled = pull(&surface, &points, &mut x, &vec![false; n * n], Domain::Torus, n, n);
        assert_eq!(pulled, 2);
        assert_eq!(x[texel(above_dense)], above_dense);
        assert_eq!(x[texel(far_above_sparse)], far_above_sparse);
        for t in (0..n * n).filter(|&t| t != texel(above_dense) && t != texel(far_above_sparse)) {
            assert_eq!(x[t], flat[t], "texel {t}");
        }
    }
}
