// SPDX-License-Identifier: MIT
//! Binned ray queries for the triangle meshes of a render: the same exact f64 hit test as the
//! BVH's ([`ShearedRay::intersect`], pbrt-v4's watertight test), given the triangles from
//! structures that suit the render's two coherent sets of rays better than a tree does.
//!
//! - **Camera rays** ([`ScreenBins`]): every camera ray leaves the eye, so a triangle can only be
//!   met by the rays of the pixels its projection covers. Each triangle's projection is boxed in
//!   pixels (widened by 10⁻³ pixels, far above the projection's rounding) and listed in the
//!   square bins of the image it overlaps; a tile of the render then takes each of its
//!   triangles to the samples of the pixels in its box only, where three edge functions
//!   (homogeneous rasterisation) pass on the few samples whose rays may meet it to the exact
//!   test, and keeps each sample's nearest hit: a few cheap tests per sample instead of a tree
//!   walk per ray. A triangle with a corner behind the eye's plane is listed everywhere, its
//!   edge functions still choosing the samples; one wholly behind it no camera ray meets
//!   (every camera ray goes forward).
//! - **Shadow rays towards a directional light** ([`LightGrid`]): they are all parallel, so a
//!   triangle can only block those whose origins project, along the light, into its own
//!   projection. The triangles are listed in a uniform grid over the plane normal to the light,
//!   each cell's list ordered by how far its triangles reach towards the light; a shadow ray
//!   reads only its origin's cell, and there only the triangles reaching beyond its origin
//!   whose projections may hold it, and never the triangle it leaves. A mesh lying in a plane
//!   x, y or z = const (a floor) answers at once for a ray that starts off that plane and moves
//!   away from it: no triangle of it can be met at t > 0.
//!
//! Both give what the BVH gives: a candidate list holds every triangle the exact test could
//! accept (their boxes are widened well beyond rounding), and the test is the same. A camera
//! sample gets the same nearest hit (when two triangles give exactly the same parameter, at a
//! shared edge, either may be kept, as either may come first in the tree), a shadow ray the
//! same answer.

use glam::DVec3;

use crate::camera::Camera;
use crate::mesh::{MeshObject, ShearedRay, TriangleHit};
use crate::ray::Ray;
use crate::scene::{Geometry, Light, Scene};

/// The side of the square bins of the image, in pixels.
const BIN: u32 = 32;

/// Most cells of a light grid along either side.
const GRID_MAX_SIDE: usize = 4096;

/// Most entries (a triangle listed in a bin or a cell) a mesh's bins or a light grid may hold;
/// a mesh that would need more (thousands of triangles each spanning the whole image or the
/// whole grid: a pathological soup) keeps its BVH for those rays instead, so memory and the
/// `u32` offsets stay bounded.
const MAX_ENTRIES: u64 = 1 << 28;

/// Cells of a light grid per triangle of its mesh: cells smaller than the triangles, so that a
/// cell lists few more than the triangles over its centre.
const CELLS_PER_TRIANGLE: f64 = 4.0;

/// A triangle's box in pixels, inclusive: columns `x0..=x1`, rows `y0..=y1`, and its edges
/// for a first test of a sample's image position (`None`: no such test, for a triangle seen
/// edge-on).
#[derive(Clone, Copy, Debug)]
struct PixelBox {
    x0: u32,
    y0: u32,
    x1: u32,
    y1: u32,
    edges: Option<Edges>,
}

/// The three edge functions of a triangle as seen from the eye, in pixel units, each
/// `a·x + b·y + c`, and the slack each may fall below zero by for a sample that the exact test
/// could still find on the triangle.
///
/// Homogeneous rasterisation (Olano and Greer, 1997): with vₖ the corners less the eye and
/// d(x, y) the (unnormalised) direction of the camera ray through image point (x, y), affine in
/// x and y, the ray meets the triangle ahead of the eye exactly when the three (vₖ × vₖ₊₁)·d
/// have the sign of det(v₀, v₁, v₂); so these need no projection, and hold for a triangle
/// crossing the eye's plane as for any other. The slack is 10⁻⁹ of each function's scale, far
/// above the rounding of the functions and of the ray (10⁻¹⁵ or so) and far below a pixel.
#[derive(Clone, Copy, Debug)]
struct Edges {
    a: [f64; 3],
    b: [f64; 3],
    c: [f64; 3],
    slack: [f64; 3],
}

impl Edges {
    /// The edges of the triangle `p` seen by `camera` in a `width` × `height` image; `None`
    /// when it is seen edge-on (its plane passes through the eye, up to rounding).
    fn new(p: [DVec3; 3], camera: &Camera, width: u32, height: u32) -> Option<Self> {
        let v = p.map(|q| q - camera.eye());
        let det = v[0].cross(v[1]).dot(v[2]);
        let scale = v[0].length() * v[1].length() * v[2].length();
        if det.abs() <= 1e-9 * scale || det.is_nan() {
            return None;
        }
        let sign = det.signum();
        let (w, h) = (f64::from(width), f64::from(height));
        let t = camera.tan_half();
        let aspect = w / h;
        // d(x, y) = forward + right·sx + up·sy with sx = (2x/w − 1)·t·aspect and
        // sy = (1 − 2y/h)·t (`Camera::ray`).
        let d_max = (1.0 + (t * aspect).powi(2) + t * t).sqrt();
        let (mut a, mut b, mut c, mut slack) = ([0.0; 3], [0.0; 3], [0.0; 3], [0.0; 3]);
        for k in 0..3 {
            let n = v[k].cross(v[(k + 1) % 3]) * sign;
            let (nr, nu, nf) = (n.dot(camera.right()), n.dot(camera.up()), n.dot(camera.forward()));
            a[k] = nr * 2.0 * t * aspect / w;
            b[k] = -nu * 2.0 * t / h;
            c[k] = nf - nr * t * aspect + nu * t;
            slack[k] = 1e-9 * n.length() * d_max;
        }
        Some(Edges { a, b, c, slack })
    }

    /// Whether the camera ray through image point (`x`, `y`) may meet the triangle.
    #[inline]
    fn may_contain(&self, x: f64, y: f64) -> bool {
        (0..3).all(|k| self.a[k] * x + self.b[k] * y + self.c[k] >= -self.slack[k])
    }
}

/// The triangles of one mesh listed by the image bins their projections overlap.
#[derive(Debug)]
struct MeshBins {
    /// Per bin (row-major), the range of `triangles` holding its list.
    offsets: Vec<u32>,
    /// The lists, each in increasing triangle order.
    triangles: Vec<u32>,
    /// Per triangle, its box in pixels (`None`: no camera ray meets it).
    boxes: Vec<Option<PixelBox>>,
}

/// The camera-ray bins of every mesh object of a scene, for one camera and image size.
#[derive(Debug)]
pub(crate) struct ScreenBins {
    /// Per scene object, its bins if it is a mesh.
    objects: Vec<Option<MeshBins>>,
    /// Bins across and down.
    columns: u32,
    rows: u32,
}

/// The nearest mesh hit of one camera sample: the object, its triangle and the hit.
pub(crate) type MeshHit = (usize, usize, TriangleHit);

impl ScreenBins {
    /// The bins of the meshes of `scene` seen through `camera` in a `width` × `height` image.
    pub(crate) fn new(scene: &Scene, camera: &Camera, width: u32, height: u32) -> Self {
        let (columns, rows) = (width.div_ceil(BIN), height.div_ceil(BIN));
        let objects = scene
            .objects()
            .iter()
            .map(|object| match &object.geometry {
                Geometry::Mesh(mesh) => {
                    mesh_bins(mesh, camera, (width, height), (columns, rows), MAX_ENTRIES)
                }
                _ => None,
            })
            .collect();
        ScreenBins { objects, columns, rows }
    }

    /// Whether the scene has a mesh (otherwise the bins give nothing).
    pub(crate) fn any(&self) -> bool {
        self.objects.iter().any(Option::is_some)
    }

    /// Whether object `index` is a mesh with bins (its camera rays are answered by
    /// [`ScreenBins::nearest`]; any other object's by its own structure).
    pub(crate) fn binned(&self, index: usize) -> bool {
        self.objects.get(index).is_some_and(Option::is_some)
    }

    /// The nearest mesh hit of each sample of the pixels `x0..x1` × `y0..y1` (`region`):
    /// `rays` holds their camera rays, pixel by pixel row by row, `spp` per pixel, and `at`
    /// the samples' image positions in pixel units (the pixel's corner plus the sample's
    /// offset). Objects are taken in the scene's order and a later one's hit kept only if
    /// strictly nearer, as [`Scene::intersect`] does.
    pub(crate) fn nearest(
        &self,
        scene: &Scene,
        region: (u32, u32, u32, u32),
        spp: u32,
        rays: &[Ray],
        at: &[(f64, f64)],
    ) -> Vec<Option<MeshHit>> {
        let (x0, y0, x1, y1) = region;
        let width = (x1 - x0) as usize;
        let spp = spp as usize;
        let sheared: Vec<Option<ShearedRay>> = rays.iter().map(ShearedRay::new).collect();
        let mut best: Vec<Option<MeshHit>> = vec![None; rays.len()];
        let (bx0, by0) = (x0 / BIN, y0 / BIN);
        let (bx1, by1) = ((x1 - 1) / BIN, (y1 - 1) / BIN);
        for (index, object) in scene.objects().iter().enumerate() {
            let (Some(bins), Geometry::Mesh(mesh)) = (&self.objects[index], &object.geometry)
            else {
                continue;
            };
            let positions = mesh.mesh().positions();
            let triangles = mesh.mesh().triangles();
            for by in by0..=by1.min(self.rows - 1) {
                for bx in bx0..=bx1.min(self.columns - 1) {
                    let bin = (by * self.columns + bx) as usize;
                    let list =
                        &bins.triangles[bins.offsets[bin] as usize..bins.offsets[bin + 1] as usize];
                    for &tri in list {
                        let Some(b) = bins.boxes[tri as usize] else { continue };
                        // The pixels of the region in the triangle's box; the triangle is
                        // taken in the first of the region's bins that lists it only.
                        let (px0, py0) = (b.x0.max(x0), b.y0.max(y0));
                        let (px1, py1) = (b.x1.min(x1 - 1), b.y1.min(y1 - 1));
                        if px0 > px1 || py0 > py1 || px0 / BIN != bx || py0 / BIN != by {
                            continue;
                        }
                        let [p0, p1, p2] = triangles[tri as usize].map(|k| positions[k as usize]);
                        for py in py0..=py1 {
                            for px in px0..=px1 {
                                let first = ((py - y0) as usize * width + (px - x0) as usize) * spp;
                                for s in first..first + spp {
                                    if let Some(e) = &b.edges
                                        && !e.may_contain(at[s].0, at[s].1)
                                    {
                                        continue;
                                    }
                                    let Some(ray) = &sheared[s] else { continue };
                                    let t_max = best[s].map_or(rays[s].t_max, |h| h.2.t);
                                    if let Some(h) = ray.intersect(p0, p1, p2, t_max)
                                        && h.t < t_max
                                    {
                                        best[s] = Some((index, tri as usize, h));
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
        best
    }
}

/// The bins of one mesh (see [`ScreenBins`]) in a `width` × `height` image of `columns` ×
/// `rows` bins; `None` when they would hold more than `limit` entries ([`MAX_ENTRIES`]).
fn mesh_bins(
    mesh: &MeshObject,
    camera: &Camera,
    (width, height): (u32, u32),
    (columns, rows): (u32, u32),
    limit: u64,
) -> Option<MeshBins> {
    let positions = mesh.mesh().positions();
    let aspect = f64::from(width) / f64::from(height);
    let (w, h) = (f64::from(width), f64::from(height));
    let boxes: Vec<Option<PixelBox>> = mesh
        .mesh()
        .triangles()
        .iter()
        .map(|t| {
            let p = t.map(|k| positions[k as usize]);
            let corners = p.map(|q| camera.project(q, aspect));
            let ahead = corners.iter().filter(|c| c.is_some()).count();
            match ahead {
                0 => None,
                3 => {
                    let q = corners.map(|c| c.map_or((0.0, 0.0), |(x, y)| (x * w, y * h)));
                    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
                    for (x, y) in q {
                        lo = [lo[0].min(x), lo[1].min(y)];
                        hi = [hi[0].max(x), hi[1].max(y)];
                    }
                    // A sample at pixel p, offset o in [0, 1), is at p + o: the pixels from
                    // ⌊lo⌋ to ⌊hi⌋, widened by 10⁻³ pixels against rounding; clamped to the
                    // image (the corners are finite and ahead of the eye: no NaN).
                    const WIDEN: f64 = 1e-3;
                    if hi[0] < -WIDEN || hi[1] < -WIDEN || lo[0] > w + WIDEN || lo[1] > h + WIDEN {
                        return None;
                    }
                    let pixel = |v: f64, size: u32| {
                        (v.floor().max(0.0) as u64).min(u64::from(size - 1)) as u32
                    };
                    Some(PixelBox {
                        x0: pixel(lo[0] - WIDEN, width),
                        y0: pixel(lo[1] - WIDEN, height),
                        x1: pixel(hi[0] + WIDEN, width),
                        y1: pixel(hi[1] + WIDEN, height),
                        edges: Edges::new(p, camera, width, height),
                    })
                }
                // Crossing the eye's plane: every pixel, the edges still telling which samples.
                _ => Some(PixelBox {
                    x0: 0,
                    y0: 0,
                    x1: width - 1,
                    y1: height - 1,
                    edges: Edges::new(p, camera, width, height),
                }),
            }
        })
        .collect();
    let n_bins = (columns * rows) as usize;
    let bins_of = |b: &PixelBox| (b.x0 / BIN..=b.x1 / BIN, b.y0 / BIN..=b.y1 / BIN);
    let entries: u64 = boxes
        .iter()
        .flatten()
        .map(|b| u64::from(b.x1 / BIN - b.x0 / BIN + 1) * u64::from(b.y1 / BIN - b.y0 / BIN + 1))
        .sum();
    if entries > limit {
        return None;
    }
    let mut counts = vec![0u32; n_bins + 1];
    for b in boxes.iter().flatten() {
        let (xs, ys) = bins_of(b);
        for by in ys {
            for bx in xs.clone() {
                counts[(by * columns + bx) as usize + 1] += 1;
            }
        }
    }
    for i in 0..n_bins {
        counts[i + 1] += counts[i];
    }
    let offsets = counts;
    let mut fill = offsets.clone();
    let mut triangles = vec![0u32; offsets[n_bins] as usize];
    for (tri, b) in boxes.iter().enumerate() {
        let Some(b) = b else { continue };
        let (xs, ys) = bins_of(b);
        for by in ys {
            for bx in xs.clone() {
                let bin = (by * columns + bx) as usize;
                triangles[fill[bin] as usize] = tri as u32;
                fill[bin] += 1;
            }
        }
    }
    Some(MeshBins { offsets, triangles, boxes })
}

/// The triangles of one mesh listed in a uniform grid over the plane normal to a directional
/// light (see the module's notes): the candidates of a shadow ray towards that light.
#[derive(Debug)]
pub(crate) struct LightGrid {
    /// The light's unit direction (as the shading normalises it) and two unit axes normal to it.
    direction: DVec3,
    axes: [DVec3; 2],
    /// The grid's corner and cell size along the axes, and its cells along each.
    origin: [f64; 2],
    cell: [f64; 2],
    size: [usize; 2],
    /// Per cell (row-major), the range of `triangles` holding its list.
    offsets: Vec<u32>,
    /// The lists: each triangle with its corners' largest coordinate along the light.
    triangles: Vec<(f64, u32)>,
    /// Per vertex, its coordinates along the axes and along the light; per triangle, whether
    /// it is seen edge-on from the light (no 2-D test for it); and the slack of the first
    /// tests.
    flat: Vec<[f64; 3]>,
    edge_on: Vec<bool>,
    slack: f64,
    /// When every vertex has the same coordinate `z` along axis `k` (a floor): `(k, z)`.
    plane: Option<(usize, f64)>,
}

impl LightGrid {
    /// The grid of `mesh` for light rays along `direction` (not normalised, not zero: the
    /// scene checks its lights); `None` when it would hold more than [`MAX_ENTRIES`].
    pub(crate) fn new(mesh: &MeshObject, direction: DVec3) -> Option<Self> {
        Self::limited(mesh, direction, MAX_ENTRIES)
    }

    /// [`LightGrid::new`] with at most `limit` entries.
    fn limited(mesh: &MeshObject, direction: DVec3, limit: u64) -> Option<Self> {
        let triangles = mesh.mesh().triangles();
        let direction = direction.normalize();
        let a = direction.any_orthonormal_vector();
        let axes = [a, direction.cross(a)];
        let project = |p: DVec3| [p.dot(axes[0]), p.dot(axes[1]), p.dot(direction)];
        let flat: Vec<[f64; 3]> = mesh.mesh().positions().iter().map(|p| project(*p)).collect();
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        let mut magnitude = 0.0f64;
        let (mut depth_lo, mut depth_hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for q in &flat {
            for i in 0..2 {
                lo[i] = lo[i].min(q[i]);
                hi[i] = hi[i].max(q[i]);
            }
            depth_lo = depth_lo.min(q[2]);
            depth_hi = depth_hi.max(q[2]);
            magnitude = magnitude.max(q[0].abs()).max(q[1].abs()).max(q[2].abs());
        }
        // The widening of every triangle's box: far above the rounding of the projections and
        // of a ray's drift off its line (its direction's components along the axes are
        // rounding, at most a few 10⁻¹⁶ of its length).
        let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(depth_hi - depth_lo);
        let margin = 1e-9 * (extent + magnitude) + f64::MIN_POSITIVE;
        let span = [hi[0] - lo[0] + 2.0 * margin, hi[1] - lo[1] + 2.0 * margin];
        // About CELLS_PER_TRIANGLE cells per triangle, square cells.
        let n = CELLS_PER_TRIANGLE * triangles.len() as f64;
        let side = (span[0] * span[1] / n).sqrt().max(f64::MIN_POSITIVE);
        let size = span.map(|s| ((s / side).ceil() as usize).clamp(1, GRID_MAX_SIDE));
        let cell = [span[0] / size[0] as f64, span[1] / size[1] as f64];
        let origin = [lo[0] - margin, lo[1] - margin];
        let cell_of = |v: f64, i: usize| {
            (((v - origin[i]) / cell[i]).floor().max(0.0) as usize).min(size[i] - 1)
        };
        let ranges: Vec<[usize; 4]> = triangles
            .iter()
            .map(|t| {
                let q = t.map(|k| flat[k as usize]);
                let (a, b) = (q[0][0].min(q[1][0]).min(q[2][0]), q[0][0].max(q[1][0]).max(q[2][0]));
                let (c, d) = (q[0][1].min(q[1][1]).min(q[2][1]), q[0][1].max(q[1][1]).max(q[2][1]));
                [
                    cell_of(a - margin, 0),
                    cell_of(b + margin, 0),
                    cell_of(c - margin, 1),
                    cell_of(d + margin, 1),
                ]
            })
            .collect();
        let entries: u64 =
            ranges.iter().map(|r| ((r[1] - r[0] + 1) * (r[3] - r[2] + 1)) as u64).sum();
        if entries > limit {
            return None;
        }
        let n_cells = size[0] * size[1];
        let mut offsets = vec![0u32; n_cells + 1];
        for r in &ranges {
            for j in r[2]..=r[3] {
                for i in r[0]..=r[1] {
                    offsets[j * size[0] + i + 1] += 1;
                }
            }
        }
        for i in 0..n_cells {
            offsets[i + 1] += offsets[i];
        }
        let mut fill = offsets.clone();
        let mut list = vec![0u32; offsets[n_cells] as usize];
        for (tri, r) in ranges.iter().enumerate() {
            for j in r[2]..=r[3] {
                for i in r[0]..=r[1] {
                    let c = j * size[0] + i;
                    list[fill[c] as usize] = tri as u32;
                    fill[c] += 1;
                }
            }
        }
        // Each cell's list from the triangle reaching farthest towards the light to the one
        // reaching least far (ties by index): a shadow ray stops reading at the first triangle
        // wholly behind its origin, as all after it are.
        let far: Vec<f64> = triangles
            .iter()
            .map(|t| t.iter().map(|&k| flat[k as usize][2]).fold(f64::NEG_INFINITY, f64::max))
            .collect();
        let list: Vec<(f64, u32)> = (0..n_cells)
            .flat_map(|c| {
                let mut cell: Vec<(f64, u32)> = list[offsets[c] as usize..offsets[c + 1] as usize]
                    .iter()
                    .map(|&tri| (far[tri as usize], tri))
                    .collect();
                cell.sort_unstable_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
                cell
            })
            .collect();
        let slack = 1e-9 * (extent + magnitude);
        let edge_on = triangles
            .iter()
            .map(|t| {
                let q = t.map(|k| flat[k as usize]);
                let area = (q[1][0] - q[0][0]) * (q[2][1] - q[0][1])
                    - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
                area.abs() <= slack * extent
            })
            .collect();
        let positions = mesh.mesh().positions();
        let plane = (0..3).find_map(|k| {
            let z = positions.first()?[k];
            positions.iter().all(|p| p[k] == z).then_some((k, z))
        });
        Some(LightGrid {
            plane,
            direction,
            axes,
            origin,
            cell,
            size,
            offsets,
            triangles: list,
            flat,
            edge_on,
            slack,
        })
    }

    /// Whether the ray (along this grid's light) meets a triangle of `mesh` in its
    /// (`t_min`, `t_max`), as [`MeshObject::occluded`] answers it; triangle `skip`, if given, is
    /// the one the ray leaves, which its origin, moved off it by [`crate::offset_ray_origin`],
    /// cannot meet.
    pub(crate) fn occluded(&self, mesh: &MeshObject, ray: &Ray, skip: Option<usize>) -> bool {
        debug_assert!(ray.dir == self.direction, "a light grid's ray goes along its light");
        // A mesh in a plane z = const (a floor) cannot meet a ray that starts off that plane
        // and moves away from it: the exact test would put the meeting at t < 0.
        if let Some((k, z)) = self.plane
            && (ray.origin[k] - z) * ray.dir[k] > 0.0
        {
            return false;
        }
        let q = [ray.origin.dot(self.axes[0]), ray.origin.dot(self.axes[1])];
        let mut cell = [0usize; 2];
        for i in 0..2 {
            let c = (q[i] - self.origin[i]) / self.cell[i];
            if !(c >= 0.0 && c < self.size[i] as f64) {
                return false;
            }
            // (Truncation: the floor of a number not below 0.)
            cell[i] = c as usize;
        }
        let c = cell[1] * self.size[0] + cell[0];
        let list = &self.triangles[self.offsets[c] as usize..self.offsets[c + 1] as usize];
        if list.is_empty() {
            return false;
        }
        let Some(sheared) = ShearedRay::new(ray) else {
            return false;
        };
        let (positions, triangles) = (mesh.mesh().positions(), mesh.mesh().triangles());
        // The origin's coordinate along the light: a point at t on the ray has it plus t.
        let depth = ray.origin.dot(self.direction);
        // A triangle wholly behind the origin along the light (by more than a slack far above
        // rounding) cannot be met, nor can any after it in the list.
        let ahead = list.partition_point(|&(far, _)| far - depth >= -self.slack);
        list[..ahead].iter().any(|&(_, tri)| {
            if skip == Some(tri as usize) {
                return false;
            }
            let t = triangles[tri as usize];
            let p = t.map(|k| self.flat[k as usize]);
            // Nor one wholly beyond the ray's end.
            let near = p[0][2].min(p[1][2]).min(p[2][2]);
            if near - depth > ray.t_max + self.slack {
                return false;
            }
            // First in the plane of the grid: is the origin's projection outside the
            // triangle's, beyond a slack far above rounding, by the signs of the three edge
            // functions (strictly outside one edge and strictly inside another, whichever way
            // the triangle is wound)?
            if !self.edge_on[tri as usize] {
                let side = |a: [f64; 3], b: [f64; 3]| {
                    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
                    let e = ex * (q[1] - a[1]) - ey * (q[0] - a[0]);
                    let tolerance = self.slack * ex.abs().max(ey.abs());
                    (e > tolerance, e < -tolerance)
                };
                let s = [side(p[0], p[1]), side(p[1], p[2]), side(p[2], p[0])];
                if s.iter().any(|x| x.0) && s.iter().any(|x| x.1) {
                    return false;
                }
            }
            let [a, b, c] = t.map(|k| positions[k as usize]);
            sheared.intersect(a, b, c, ray.t_max).is_some_and(|h| h.t < ray.t_max)
        })
    }
}

/// The light grids of a scene: per light, per object, a grid where the light is directional
/// (a fill light casts no shadow) and the object is a mesh (not a pathological one, see
/// [`MAX_ENTRIES`]).
#[derive(Debug)]
pub(crate) struct LightGrids {
    grids: Vec<Vec<Option<LightGrid>>>,
}

impl LightGrids {
    /// The grids of `scene`.
    pub(crate) fn new(scene: &Scene) -> Self {
        let grids = scene
            .lights()
            .iter()
            .map(|light| match *light {
                Light::Directional { direction, .. } => scene
                    .objects()
                    .iter()
                    .map(|o| match &o.geometry {
                        Geometry::Mesh(mesh) => LightGrid::new(mesh, direction),
                        _ => None,
                    })
                    .collect(),
                Light::Fill { .. } | Light::Point { .. } => Vec::new(),
            })
            .collect();
        LightGrids { grids }
    }

    /// Whether the shadow ray towards light `light` meets an object of `scene` (as
    /// [`Scene::occluded`] answers it): by the grids where there are any, by each object's own
    /// structure otherwise. `from`, if given, is the object and triangle the ray leaves (see
    /// [`LightGrid::occluded`]).
    pub(crate) fn occluded(
        &self,
        scene: &Scene,
        light: usize,
        ray: &Ray,
        from: Option<(usize, usize)>,
    ) -> bool {
        let grids = &self.grids[light];
        scene.objects().iter().enumerate().any(|(index, object)| {
            match (grids.get(index).and_then(Option::as_ref), &object.geometry) {
                (Some(grid), Geometry::Mesh(mesh)) => {
                    let skip = from.and_then(|(o, tri)| (o == index).then_some(tri));
                    grid.occluded(mesh, ray, skip)
                }
                _ => object.geometry.occluded(ray),
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec2;
    use hi_mesh::TriangleMesh;

    use super::*;
    use crate::scene::SceneObject;

    /// A fixed stream of numbers in [0, 1).
    struct Lcg(u64);

    impl Lcg {
        fn next(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    fn mesh(positions: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> MeshObject {
        let n = positions.len();
        let normals = positions.iter().map(|p| p.normalize_or(DVec3::Z)).collect();
        MeshObject::new(
            TriangleMesh::try_new(positions, normals, vec![DVec2::ZERO; n], triangles).unwrap(),
        )
    }

    /// A bumpy sphere of 40 × 20 quads (many triangles sharing edges, some silhouettes
    /// folding over), a soup of random triangles through it and around the eye (some behind
    /// it, some crossing its plane), and a large floor crossing the eye's plane.
    fn scene() -> (Scene, Camera) {
        let (nu, nv) = (40u32, 20u32);
        let mut positions = Vec::new();
        for j in 0..=nv {
            for i in 0..nu {
                let (u, v) = (f64::from(i) / f64::from(nu), f64::from(j) / f64::from(nv));
                let (theta, phi) = (std::f64::consts::TAU * u, std::f64::consts::PI * v);
                let r = 1.0 + 0.15 * (5.0 * theta).sin() * (3.0 * phi).sin();
                positions.push(
                    r * DVec3::new(phi.sin() * theta.cos(), phi.sin() * theta.sin(), phi.cos()),
                );
            }
        }
        let mut triangles = Vec::new();
        for j in 0..nv {
            for i in 0..nu {
                let k = |i: u32, j: u32| j * nu + i % nu;
                triangles.push([k(i, j), k(i + 1, j), k(i + 1, j + 1)]);
                triangles.push([k(i, j), k(i + 1, j + 1), k(i, j + 1)]);
            }
        }
        let sphere = mesh(positions, triangles);
        let eye = DVec3::new(0.5, -4.0, 1.5);
        let mut rng = Lcg(7);
        let mut soup = Vec::new();
        for _ in 0..120 {
            let c =
                DVec3::new(rng.next() * 5.0 - 2.5, rng.next() * 7.0 - 5.0, rng.next() * 4.0 - 2.0);
            for _ in 0..3 {
                soup.push(
                    c + DVec3::new(rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5) * 1.2,
                );
            }
        }
        let soup_triangles = (0..120u32).map(|t| [3 * t, 3 * t + 1, 3 * t + 2]).collect();
        let soup = mesh(soup, soup_triangles);
        let s = 50.0;
        let floor = mesh(
            vec![
                DVec3::new(-s, -s, -1.3),
                DVec3::new(s, -s, -1.3),
                DVec3::new(s, s, -1.3),
                DVec3::new(-s, s, -1.3),
            ],
            vec![[0, 1, 2], [0, 2, 3]],
        );
        let objects = [sphere, soup, floor].map(|m| SceneObject::new(Geometry::Mesh(m))).to_vec();
        let lights = vec![
            Light::Directional { direction: DVec3::new(-0.7, -1.0, 2.0), intensity: [0.8; 3] },
            Light::Fill { direction: DVec3::new(1.0, -1.0, 0.5), intensity: [0.3; 3] },
            Light::Directional { direction: DVec3::new(0.3, 0.2, 1.0), intensity: [0.4; 3] },
        ];
        let scene = Scene::try_new(objects, lights, [1.0; 3]).unwrap();
        let camera = Camera::try_new(eye, DVec3::new(0.0, 0.0, -0.2), DVec3::Z, 0.9).unwrap();
        (scene, camera)
    }

    /// Every camera sample of a 160 × 120 image (4 per pixel, at random offsets) gets from the
    /// bins the nearest hit that the BVH gives: the same parameter, bit for bit, and the same
    /// object and triangle (or another triangle at exactly the same parameter, on a shared
    /// edge).
    #[test]
    fn camera_bins_find_the_hits_of_the_tree() {
        let (scene, camera) = scene();
        let (w, h, spp) = (160u32, 120u32, 4u32);
        let bins = ScreenBins::new(&scene, &camera, w, h);
        let mut rng = Lcg(11);
        let (mut hits, mut misses) = (0, 0);
        // The image in regions of 37 × 29 pixels (not a multiple of the bins' side).
        for (x0, y0) in (0..h).step_by(29).flat_map(|y| (0..w).step_by(37).map(move |x| (x, y))) {
            let (x1, y1) = ((x0 + 37).min(w), (y0 + 29).min(h));
            let mut at = Vec::new();
            for y in y0..y1 {
                for x in x0..x1 {
                    for _ in 0..spp {
                        at.push((f64::from(x) + rng.next(), f64::from(y) + rng.next()));
                    }
                }
            }
            let rays: Vec<Ray> = at
                .iter()
                .map(|&(x, y)| {
                    camera.ray(x / f64::from(w), y / f64::from(h), f64::from(w) / f64::from(h))
                })
                .collect();
            let found = bins.nearest(&scene, (x0, y0, x1, y1), spp, &rays, &at);
            for (ray, got) in rays.iter().zip(found) {
                let want = scene.intersect(ray);
                match (got, want) {
                    (None, None) => misses += 1,
                    (Some((object, tri, h)), Some(hit)) => {
                        hits += 1;
                        assert_eq!((object, h.t), (hit.object, hit.t), "ray {ray:?}");
                        let Geometry::Mesh(m) = &scene.objects()[object].geometry else { panic!() };
                        let (direct, _) = m.intersect(ray).unwrap();
                        assert!(
                            tri == direct
                                || m.intersect(&ray.with_t_max(h.t))
                                    .is_some_and(|(_, g)| g.t == h.t),
                            "ray {ray:?}: triangle {tri}, the tree's {direct}"
                        );
                    }
                    (got, want) => panic!("ray {ray:?}: bins {got:?}, tree {want:?}"),
                }
            }
        }
        // Both kinds are many: the test tests something.
        assert!(hits > 20_000 && misses > 5_000, "{hits} hits, {misses} misses");
    }

    /// Shadow rays towards each directional light, from points on every object (moved off
    /// them as the shading moves them) and from points anywhere: the grids answer as the BVH.
    #[test]
    fn light_grids_answer_as_the_tree() {
        let (scene, camera) = scene();
        let grids = LightGrids::new(&scene);
        let mut rng = Lcg(5);
        let (mut blocked, mut free) = (0, 0);
        for i in 0..40_000 {
            // Half from hits seen by the camera, half from random points.
            let ray = camera.ray(rng.next(), rng.next(), 4.0 / 3.0);
            let (origin, from) = if i % 2 == 0 {
                let Some(hit) = scene.intersect(&ray) else { continue };
                let tri = match &scene.objects()[hit.object].geometry {
                    Geometry::Mesh(m) => m.intersect(&ray).map(|(t, _)| t),
                    _ => None,
                };
                (hit, tri)
            } else {
                let p = DVec3::new(
                    rng.next() * 8.0 - 4.0,
                    rng.next() * 8.0 - 5.0,
                    rng.next() * 5.0 - 1.5,
                );
                let hit = crate::ray::Hit {
                    t: 1.0,
                    point: p,
                    error: DVec3::ZERO,
                    geometric_normal: DVec3::Z,
                    shading_normal: DVec3::Z,
                    uv: (0.0, 0.0),
                    color: [0.0; 3],
                    object: usize::MAX,
                };
                (hit, None)
            };
            for (light_index, light) in scene.lights().iter().enumerate() {
                let Light::Directional { direction, .. } = *light else { continue };
                let l = direction.normalize();
                let start = crate::ray::offset_ray_origin(
                    origin.point,
                    origin.error,
                    origin.geometric_normal,
                    l,
                );
                let shadow = Ray { origin: start, dir: l, t_min: 0.0, t_max: f64::INFINITY };
                let want = scene.occluded(&shadow);
                let skip = from.map(|tri| (origin.object, tri));
                let got = grids.occluded(&scene, light_index, &shadow, skip);
                assert_eq!(got, want, "shadow ray {shadow:?}");
                if want { blocked += 1 } else { free += 1 }
            }
        }
        assert!(blocked > 5_000 && free > 5_000, "{blocked} blocked, {free} free");
    }

    /// The floor of the test scene (z = −1.3) is known to be flat, the sphere not; a shadow
    /// ray leaving the floor's top is free of it at once, one from below it still meets it
    /// (and both answers are the exact test's).
    #[test]
    fn a_flat_mesh_frees_the_rays_that_leave_it() {
        let (scene, _) = scene();
        let grid = |i: usize| {
            let Geometry::Mesh(m) = &scene.objects()[i].geometry else { panic!() };
            (m, LightGrid::new(m, DVec3::new(-0.7, -1.0, 2.0)).unwrap())
        };
        let ((sphere, sphere_grid), (floor, floor_grid)) = (grid(0), grid(2));
        assert_eq!(floor_grid.plane, Some((2, -1.3)));
        assert_eq!(sphere_grid.plane, None);
        let dir = floor_grid.direction;
        for (z, blocked) in [(-1.3 + 1e-12, false), (-1.3 - 1e-6, true), (-1.0, false)] {
            let ray =
                Ray { origin: DVec3::new(0.1, 0.2, z), dir, t_min: 0.0, t_max: f64::INFINITY };
            assert_eq!(floor_grid.occluded(floor, &ray, None), blocked, "from z = {z}");
            assert_eq!(floor.occluded(&ray), blocked, "the exact test from z = {z}");
        }
        // The sphere's grid still reads its cells.
        let up = Ray { origin: DVec3::new(0.0, 0.0, -3.0), dir, t_min: 0.0, t_max: f64::INFINITY };
        assert_eq!(sphere_grid.occluded(sphere, &up, None), sphere.occluded(&up));
    }

    /// A mesh whose bins or grid would hold more entries than allowed gets none (and keeps its
    /// BVH); at the limit it gets them.
    #[test]
    fn too_many_entries_mean_no_bins() {
        let (scene, camera) = scene();
        let Geometry::Mesh(sphere) = &scene.objects()[0].geometry else { panic!() };
        let (size, bins) = ((160, 120), (5, 4));
        let full = mesh_bins(sphere, &camera, size, bins, MAX_ENTRIES).unwrap();
        let n = full.triangles.len() as u64;
        assert!(n > 1000);
        assert!(mesh_bins(sphere, &camera, size, bins, n).is_some());
        assert!(mesh_bins(sphere, &camera, size, bins, n - 1).is_none());
        let light = DVec3::new(-0.7, -1.0, 2.0);
        let grid = LightGrid::new(sphere, light).unwrap();
        let n = grid.triangles.len() as u64;
        assert!(LightGrid::limited(sphere, light, n).is_some());
        assert!(LightGrid::limited(sphere, light, n - 1).is_none());
        // The scene's meshes all have bins here.
        let screen = ScreenBins::new(&scene, &camera, 160, 120);
        assert!((0..3).all(|i| screen.binned(i)) && !screen.binned(3));
    }
}
