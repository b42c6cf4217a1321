// SPDX-License-Identifier: MIT
//! The fit's error both ways: every scan point to its closest point on the fitted surface's
//! mesh (exactly, by a bounding-volume hierarchy, or refined onto the surface itself), and every
//! sample of that mesh to the scan (its triangles, or its nearest point), with the samples on
//! texels that bridge holes summarised apart.

use glam::DVec3;
use hi_scan::closest::{NearMesh, TriangleBvh};
use hi_scan::distance::{Distances, bounding_diagonal};
use hi_surface::HarmonicSurface;

use super::{ErrorMeasure, FitErrors, UNREACHED, mesh_oversample};
use crate::Error;
use crate::domain::Domain;
use crate::layout_mesh::{LayoutMesh, layout_mesh};

/// The both-way distances between a fitted surface (an image's harmonic surface over
/// `domain`: a [`crate::Layout`] of the sphere, or a [`Domain`]) and a scan (`points`, with
/// `triangles` if it is a mesh), as [`super::fit`] measures them with `measure`
/// ([`ErrorMeasure::Fast`] or [`ErrorMeasure::Exact`]; [`ErrorMeasure::Sampled`] uses that
/// many samples per texel for the mesh), and the mesh they were measured on. `filled` flags the
/// texels of the surface's grid that bridge holes in the scan: the mesh's samples there are
/// summarised apart.
///
/// # Errors
///
/// [`Error::InvalidOption`] for [`ErrorMeasure::Off`] or a `filled` mask of the wrong size;
/// the errors of [`layout_mesh`], [`TriangleBvh::try_new`] and [`NearMesh::try_new`].
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_geomimage::fit::{ErrorMeasure, measure_fit};
/// use hi_geomimage::Layout;
///
/// // The exact unit sphere, and points 0.1 outside it.
/// let sphere = hi_surface::sphere(1.0);
/// let points: Vec<DVec3> = [DVec3::X, DVec3::Y, DVec3::new(0.6, 0.0, 0.8)]
///     .map(|d| d * 1.1)
///     .to_vec();
/// let (e, _) = measure_fit(&sphere, Layout::Sphere, None, &points, &[], ErrorMeasure::Exact)
///     .unwrap();
/// assert!(e.scan_to_surface.per_point.iter().all(|d| (d - 0.1).abs() < 1e-6));
/// ```
pub fn measure_fit(
    surface: &HarmonicSurface<DVec3>,
    domain: impl Into<Domain>,
    filled: Option<&[bool]>,
    points: &[DVec3],
    triangles: &[[u32; 3]],
    measure: ErrorMeasure,
) -> Result<(FitErrors, LayoutMesh), Error> {
    let part = Measured {
        surface,
        domain: domain.into(),
        area_fraction: 1.0,
        filled,
        texels_on_scan: false,
    };
    let (all, _, mut meshes) = measure_parts(&[part], points, triangles, measure)?;
    let mesh = meshes.pop().ok_or(Error::InvalidOption {
        name: "parts",
        value: 0.0,
        expected: "at least one",
    })?;
    Ok((all, mesh))
}

/// A surface to measure ([`measure_parts`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Measured<'a> {
    /// The surface.
    pub(crate) surface: &'a HarmonicSurface<DVec3>,
    /// Its domain.
    pub(crate) domain: Domain,
    /// Its share of the scan's area (see [`mesh_oversample`]).
    pub(crate) area_fraction: f64,
    /// The texels of its grid that bridge holes, if known.
    pub(crate) filled: Option<&'a [bool]>,
    /// Whether its texels are points of the scan's triangles (an unsmoothed image of a mesh's
    /// parameterisation).
    pub(crate) texels_on_scan: bool,
}

/// One part's mesh and what its samples are.
struct PartMesh<'a> {
    part: Measured<'a>,
    mesh: LayoutMesh,
    per_texel: usize,
    /// The first of its triangles in the union of the parts' meshes.
    first_triangle: usize,
}

impl PartMesh<'_> {
    /// Surface → scan samples: every vertex of the mesh, and the centroid of every other
    /// triangle (one per grid quad, away from the texels: for the mesh of a parameterisation,
    /// the vertices at the texels lie on the scan).
    fn samples(&self) -> Vec<DVec3> {
        let m = &self.mesh.mesh;
        let centroids = m
            .triangles()
            .iter()
            .step_by(2)
            .map(|t| t.iter().map(|&k| m.positions()[k as usize]).sum::<DVec3>() / 3.0);
        m.positions().iter().copied().chain(centroids).collect()
    }

    /// Whether sample `v` is a vertex at a texel sampled on the scan's own triangles: a point
    /// of the scan, at distance 0 (to rounding), not queried.
    fn on_scan(&self, v: usize) -> bool {
        self.part.texels_on_scan
            && self.per_texel == 1
            && v < self.mesh.mesh.positions().len()
            && !self.on_fill(v)
    }

    /// Whether sample `s` lies on filled texels (a centroid if any of its corners does).
    fn on_fill(&self, s: usize) -> bool {
        let n_vertices = self.mesh.mesh.positions().len();
        self.part.filled.is_some_and(|f| {
            let is_filled = |v: usize| f.get(self.mesh.texel[v] as usize).copied().unwrap_or(false);
            if s < n_vertices {
                is_filled(s)
            } else {
                self.mesh.mesh.triangles()[2 * (s - n_vertices)]
                    .iter()
                    .any(|&k| is_filled(k as usize))
            }
        })
    }
}

/// The both-way distances between several fitted surfaces and a scan: each scan point to the
/// nearest surface, each surface's samples to the scan. Returns the measure over them all, the
/// measure of each part (the scan points nearest it, its own samples; summaries, without the
/// per-point distances), and each part's mesh.
pub(crate) fn measure_parts(
    parts: &[Measured<'_>],
    points: &[DVec3],
    triangles: &[[u32; 3]],
    measure: ErrorMeasure,
) -> Result<(FitErrors, Vec<FitErrors>, Vec<LayoutMesh>), Error> {
    let meshes = part_meshes(parts, measure)?;
    let first_triangle =
        meshes.last().map_or(0, |m| m.first_triangle + m.mesh.mesh.triangles().len());
    let diagonal = bounding_diagonal(points);
    // The union of the parts' meshes, and the part of each triangle.
    let mut positions = Vec::new();
    let mut all_triangles = Vec::with_capacity(first_triangle);
    for m in &meshes {
        let offset = u32::try_from(positions.len()).unwrap_or(u32::MAX);
        positions.extend_from_slice(m.mesh.mesh.positions());
        all_triangles.extend(m.mesh.mesh.triangles().iter().map(|t| t.map(|k| k + offset)));
    }
    let exact = measure == ErrorMeasure::Exact;
    // Scan → surface: each point's distance and the part it is nearest.
    let forward = || scan_to_surface(&meshes, (&positions, &all_triangles), points, exact);
    // Surface → scan.
    let samples: Vec<Vec<DVec3>> = meshes.iter().map(PartMesh::samples).collect();
    let queried: Vec<DVec3> = meshes
        .iter()
        .zip(&samples)
        .flat_map(|(m, s)| s.iter().enumerate().filter(|(v, _)| !m.on_scan(*v)).map(|(_, x)| *x))
        .collect();
    let backward = || -> Result<Vec<f64>, Error> {
        if triangles.is_empty() {
            Ok(hi_scan::distance::nearest_point_distances(&queried, points)?)
        } else {
            // The scan's triangles can be long and thin (scanners leave slivers at folds and
            // holes), which the nearest-vertex query misjudges: this side is always exact.
            Ok(TriangleBvh::try_new(points, triangles)?.distances(&queried))
        }
    };
    // Both ways at once (each builds its search structure on one thread).
    let (forward, measured) = hi_par::join(forward, backward);
    let forward = forward?;
    let mut measured = measured?.into_iter();
    let (kept_by_part, filled_max_by_part) = split_samples(&meshes, &samples, &mut measured);
    let unreached = |d: &[f64]| {
        d.iter().filter(|&&x| x > UNREACHED * diagonal).count() as f64 / d.len().max(1) as f64
    };
    // Each part's measure summarised (its points' distances are in the whole's).
    let by_part: Vec<FitErrors> = (0..meshes.len())
        .map(|k| {
            let mine = || forward.iter().filter(move |f| f.1 as usize == k).map(|f| f.0);
            let count = mine().count();
            let far = mine().filter(|&d| d > UNREACHED * diagonal).count();
            FitErrors {
                unreached_fraction: far as f64 / count.max(1) as f64,
                scan_to_surface: Distances::summary_of(mine(), diagonal),
                surface_to_scan: Distances::summary_of(kept_by_part[k].iter().copied(), diagonal),
                filled_to_scan_max: filled_max_by_part[k],
            }
        })
        .collect();
    let per_point: Vec<f64> = forward.into_iter().map(|f| f.0).collect();
    let all = FitErrors {
        unreached_fraction: unreached(&per_point),
        scan_to_surface: Distances::from_values(per_point, diagonal),
        surface_to_scan: Distances::from_values(kept_by_part.concat(), diagonal),
        filled_to_scan_max: filled_max_by_part.iter().copied().fold(0.0, f64::max),
    };
    Ok((all, by_part, meshes.into_iter().map(|m| m.mesh).collect()))
}

/// The first stage of [`measure_parts`]: each part's mesh, refined as `measure` asks, with the
/// index of its first triangle in the union of them all.
fn part_meshes<'a>(
    parts: &[Measured<'a>],
    measure: ErrorMeasure,
) -> Result<Vec<PartMesh<'a>>, Error> {
    let mut meshes = Vec::with_capacity(parts.len());
    let mut first_triangle = 0;
    for part in parts {
        let per_texel = match measure {
            ErrorMeasure::Off => {
                return Err(Error::InvalidOption {
                    name: "error measure",
                    value: 0.0,
                    expected: "a measure other than Off",
                });
            }
            ErrorMeasure::Sampled(k) => k.max(1),
            _ => mesh_oversample(part.surface, part.area_fraction),
        };
        if let Some(f) = part.filled
            && f.len() != part.surface.m() * part.surface.n()
        {
            return Err(Error::InvalidOption {
                name: "filled texels",
                value: f.len() as f64,
                expected: "one flag per texel of the surface's grid",
            });
        }
        // The plain octahedron's mesh needs an even refinement.
        let per_texel = if part.domain == Domain::Sphere(crate::Layout::Octahedron) {
            per_texel.next_multiple_of(2)
        } else {
            per_texel
        };
        let mesh = layout_mesh(part.surface, part.domain, per_texel)?;
        let n = mesh.mesh.triangles().len();
        meshes.push(PartMesh { part: *part, mesh, per_texel, first_triangle });
        first_triangle += n;
    }
    Ok(meshes)
}

/// Scan → surface in [`measure_parts`]: each point's distance to the union of the parts'
/// meshes (`positions`, `all_triangles`), projected onto the surface when `exact`, and the part
/// it is nearest.
fn scan_to_surface(
    meshes: &[PartMesh<'_>],
    (positions, all_triangles): (&[DVec3], &[[u32; 3]]),
    points: &[DVec3],
    exact: bool,
) -> Result<Vec<(f64, u32)>, Error> {
    let part_of = |t: u32| meshes.partition_point(|m| m.first_triangle <= t as usize) - 1;
    use hi_par::*;
    Ok(if exact {
        let bvh = TriangleBvh::try_new(positions, all_triangles)?;
        let grids = meshes
            .iter()
            .map(|m| HermiteGrid::of(m.part.surface, m.per_texel))
            .collect::<Result<Vec<_>, _>>()?;
        points
            .par_iter()
            .map(|x| {
                let c = bvh.closest(*x);
                let k = part_of(c.triangle);
                let local = c.triangle - meshes[k].first_triangle as u32;
                let d = project(&grids[k], &meshes[k].mesh.mesh, *x, local, c.point);
                (d, u32::try_from(k).unwrap_or(0))
            })
            .collect()
    } else {
        let near = NearMesh::try_new(positions, all_triangles)?;
        // In the order of a grid's cells, so that each query finds its neighbours in cache,
        // then back in the scan's order.
        let order = hi_scan::cloud::spatial_order(points);
        let found: Vec<(f64, u32)> = order
            .par_iter()
            .with_min_len(256)
            .map(|&i| {
                let c = near.closest(points[i as usize]);
                let k = if c.triangle == u32::MAX { 0 } else { part_of(c.triangle) };
                (c.distance, u32::try_from(k).unwrap_or(0))
            })
            .collect();
        drop(near);
        let mut out = vec![(0.0, 0); points.len()];
        for (&i, f) in order.iter().zip(found) {
            out[i as usize] = f;
        }
        out
    })
}

/// Each part's samples' distances to the scan in [`measure_parts`], those on fills apart:
/// the distances kept, and the largest on a fill (`measured` holds the distances of the
/// samples not on the scan, in order).
fn split_samples(
    meshes: &[PartMesh<'_>],
    samples: &[Vec<DVec3>],
    measured: &mut impl Iterator<Item = f64>,
) -> (Vec<Vec<f64>>, Vec<f64>) {
    let mut kept_by_part = Vec::with_capacity(meshes.len());
    let mut filled_max_by_part = Vec::with_capacity(meshes.len());
    for (m, s) in meshes.iter().zip(samples) {
        let (mut kept, mut filled_max) = (Vec::with_capacity(s.len()), 0.0f64);
        for v in 0..s.len() {
            let d = if m.on_scan(v) { 0.0 } else { measured.next().unwrap_or(0.0) };
            if m.on_fill(v) {
                filled_max = filled_max.max(d);
            } else {
                kept.push(d);
            }
        }
        kept_by_part.push(kept);
        filled_max_by_part.push(filled_max);
    }
    (kept_by_part, filled_max_by_part)
}

/// The harmonic surface near its grid, for Gauss–Newton projections: p and its derivatives
/// ∂u, ∂v and ∂u∂v sampled on the grid of the fit's mesh (by FFT), and between grid points the bicubic Hermite
/// interpolant of those, which differs from the surface by O(h⁴) (h the grid's spacing): far
/// below any distance this measures (the mesh's own departure from the surface is O(h²)).
struct HermiteGrid {
    m: usize,
    n: usize,
    p: Vec<DVec3>,
    pu: Vec<DVec3>,
    pv: Vec<DVec3>,
    puv: Vec<DVec3>,
}

impl HermiteGrid {
    /// The grid `per_texel` times finer than the surface's along each axis.
    fn of(surface: &HarmonicSurface<DVec3>, per_texel: usize) -> Result<Self, Error> {
        let (m, n) = (surface.m() * per_texel, surface.n() * per_texel);
        let s = |a, b| surface.sample_uniform(m, n, a, b).map(|g| g.values);
        Ok(Self { m, n, p: s(0, 0)?, pu: s(1, 0)?, pv: s(0, 1)?, puv: s(1, 1)? })
    }

    /// p and its derivatives in u and in v at (u, v).
    fn eval(&self, u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
        let (x, y) = (u.rem_euclid(1.0) * self.m as f64, v.rem_euclid(1.0) * self.n as f64);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "in 0..m, 0..n"
        )]
        let (i, j) = ((x.floor() as usize).min(self.m - 1), (y.floor() as usize).min(self.n - 1));
        let (s, t) = (x - i as f64, y - j as f64);
        let (hu, hv) = (1.0 / self.m as f64, 1.0 / self.n as f64);
        // Cubic Hermite basis [h00, h10, h01, h11] and its derivative.
        let basis = |s: f64| {
            let (s2, s3) = (s * s, s * s * s);
            (
                [2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s, -2.0 * s3 + 3.0 * s2, s3 - s2],
                [
                    6.0 * s2 - 6.0 * s,
                    3.0 * s2 - 4.0 * s + 1.0,
                    -6.0 * s2 + 6.0 * s,
                    3.0 * s2 - 2.0 * s,
                ],
            )
        };
        let ((bs, ds), (bt, dt)) = (basis(s), basis(t));
        let (mut p, mut ps, mut pt) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
        for (a, ia) in [(0usize, i), (1, (i + 1) % self.m)] {
            for (b, jb) in [(0usize, j), (1, (j + 1) % self.n)] {
                let k = ia * self.n + jb;
                // Value, u-slope, v-slope and twist at this corner, in cell units.
                let terms = [
                    (2 * a, 2 * b, self.p[k]),
                    (2 * a + 1, 2 * b, self.pu[k] * hu),
                    (2 * a, 2 * b + 1, self.pv[k] * hv),
                    (2 * a + 1, 2 * b + 1, self.puv[k] * (hu * hv)),
                ];
                for (ka, kb, c) in terms {
                    // Basis order [h00, h10, h01, h11]: corner 0 uses h00/h10, corner 1 h01/h11.
                    let (fa, fb) = ([0, 1, 2, 3][ka], [0, 1, 2, 3][kb]);
                    p += c * (bs[fa] * bt[fb]);
                    ps += c * (ds[fa] * bt[fb]);
                    pt += c * (bs[fa] * dt[fb]);
                }
            }
        }
        (p, ps / hu, pt / hv)
    }
}

/// The distance from x to the surface near the point `q` of mesh triangle `t`: from the (u, v)
/// of q (barycentric in the triangle's UVs, unwrapped across the period), Gauss–Newton steps
/// on |p(u, v) − x|², the least distance seen (every iterate is a point of the surface).
fn project(grid: &HermiteGrid, mesh: &hi_mesh::TriangleMesh, x: DVec3, t: u32, q: DVec3) -> f64 {
    let tri = mesh.triangles()[t as usize];
    let [a, b, c] = tri.map(|k| mesh.positions()[k as usize]);
    let [ua, ub, uc] = tri.map(|k| mesh.uvs()[k as usize]);
    let unwrap = |w: glam::DVec2| w - (w - ua).round();
    let (ub, uc) = (unwrap(ub), unwrap(uc));
    // Barycentric coordinates of q in abc.
    let (e1, e2, f) = (b - a, c - a, q - a);
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let det = d11 * d22 - d12 * d12;
    let (mut uv, mut best) = (ua, f64::INFINITY);
    if det > 0.0 {
        let (r1, r2) = (f.dot(e1), f.dot(e2));
        let s = (d22 * r1 - d12 * r2) / det;
        let r = (d11 * r2 - d12 * r1) / det;
        uv = ua + (ub - ua) * s + (uc - ua) * r;
    }
    for _ in 0..8 {
        let (p, pu, pv) = grid.eval(uv.x, uv.y);
        let d = p - x;
        best = best.min(d.length());
        let (g11, g12, g22) = (pu.dot(pu), pu.dot(pv), pv.dot(pv));
        let det = g11 * g22 - g12 * g12;
        if det.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            break;
        }
        let (r1, r2) = (d.dot(pu), d.dot(pv));
        let step = glam::DVec2::new((g22 * r1 - g12 * r2) / det, (g11 * r2 - g12 * r1) / det);
        uv -= step;
        if step.length() < 1e-12 {
            break;
        }
    }
    best.min(grid.eval(uv.x, uv.y).0.distance(x))
}
