// SPDX-License-Identifier: MIT
//! Triangle meshes in a BVH (Hardy 2005, §5.5: the surface "converted to polygons"), with an exact
//! f64 ray–triangle test: pbrt-v4's watertight algorithm (Woop, Benthin and Wald), which never
//! lets a ray slip between two triangles sharing an edge, with its conservative bound on t and
//! its error bound of the hit point.

use glam::DVec3;
use hi_bezier::Aabb;
use hi_mesh::TriangleMesh;

use crate::Error;
use crate::bvh::Bvh;
use crate::ray::{Ray, gamma};

/// A triangle mesh ready for ray tracing: the mesh and a BVH over its triangles, and the
/// edges drawn over it, if any ([`MeshObject::with_edges`]).
#[derive(Clone, Debug)]
pub struct MeshObject {
    mesh: TriangleMesh,
    bvh: Bvh,
    /// Per triangle, bit k set when its edge from corner k to corner k + 1 is drawn.
    edge_flags: Vec<u8>,
    edge_style: Option<EdgeStyle>,
}

/// How [`MeshObject::with_edges`] draws edges: a colour, and a width as an angle seen from the
/// eye (so a line is as wide near as far: about `2·tan(fov/2)/height` radians per pixel).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EdgeStyle {
    /// Linear RGB.
    pub color: [f32; 3],
    /// Width in radians as seen along the ray.
    pub width: f64,
}

/// A hit on a triangle: parameter and barycentric coordinates (b₀ + b₁ + b₂ = 1, the point is
/// b₀·p₀ + b₁·p₁ + b₂·p₂).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TriangleHit {
    /// The ray parameter.
    pub t: f64,
    /// Barycentric coordinates of the hit.
    pub b: [f64; 3],
}

impl MeshObject {
    /// The mesh with a BVH over its triangles (a valid [`TriangleMesh`] has at least one).
    #[must_use]
    pub fn new(mesh: TriangleMesh) -> Self {
        let p = mesh.positions();
        let boxes: Vec<Aabb<DVec3>> = mesh
            .triangles()
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| p[i as usize]);
                Aabb { min: a.min(b).min(c), max: a.max(b).max(c) }
            })
            .collect();
        let bvh = Bvh::build(&boxes);
        MeshObject { mesh, bvh, edge_flags: Vec::new(), edge_style: None }
    }

    /// The mesh with `edges` (pairs of vertex indices, in either order) drawn over it in
    /// `style`: a triangle side that is one of them is a line, where the hit lies within half
    /// the width of it (the distance from the side being the opposite barycentric coordinate
    /// times the triangle's height over that side). Sides not listed (a quad's diagonal) are
    /// not drawn; an edge that is no triangle's side draws nothing.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidValue`] for a vertex index out of range or a width that is not positive
    /// and finite.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::{DVec2, DVec3};
    /// use hi_raytrace::{EdgeStyle, MeshObject, Ray};
    /// use hi_mesh::TriangleMesh;
    ///
    /// // A unit square of two triangles; its outline drawn, not its diagonal.
    /// let p = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
    /// let mesh = TriangleMesh::try_new(p, vec![DVec3::Z; 4], vec![DVec2::ZERO; 4], vec![[0, 1, 2], [0, 2, 3]])?;
    /// let style = EdgeStyle { color: [0.0; 3], width: 0.02 };
    /// let square = MeshObject::new(mesh).with_edges(&[[0, 1], [1, 2], [2, 3], [3, 0]], style)?;
    /// let down = |x: f64, y: f64| Ray::new(DVec3::new(x, y, 1.0), -DVec3::Z);
    /// let on = |r: Ray| { let (tri, h) = square.intersect(&r).unwrap(); square.edge_color(tri, &h, &r).is_some() };
    /// assert!(on(down(0.5, 0.005))); // beside the side y = 0
    /// assert!(!on(down(0.5, 0.5))); // in the middle
    /// assert!(!on(down(0.3, 0.3))); // on the diagonal
    /// # Ok::<(), hi_raytrace::Error>(())
    /// ```
    pub fn with_edges(mut self, edges: &[[u32; 2]], style: EdgeStyle) -> Result<Self, Error> {
        let n = self.mesh.n_vertices();
        if let Some(&bad) = edges.iter().flatten().find(|&&k| k as usize >= n) {
            return Err(Error::InvalidValue {
                what: "edge vertex index",
                value: f64::from(bad),
                expected: "less than the number of vertices",
            });
        }
        if !(style.width > 0.0 && style.width.is_finite()) {
            return Err(Error::InvalidValue {
                what: "edge width",
                value: style.width,
                expected: "a positive angle in radians",
            });
        }
        let mut keys: Vec<(u32, u32)> = edges.iter().map(|&[a, b]| (a.min(b), a.max(b))).collect();
        keys.sort_unstable();
        keys.dedup();
        self.edge_flags = self
            .mesh
            .triangles()
            .iter()
            .map(|t| {
                (0..3).fold(0u8, |flags, k| {
                    let (a, b) = (t[k], t[(k + 1) % 3]);
                    let drawn = keys.binary_search(&(a.min(b), a.max(b))).is_ok();
                    flags | (u8::from(drawn) << k)
                })
            })
            .collect();
        self.edge_style = Some(style);
        Ok(self)
    }

    /// The colour of the edge that the hit `h` on triangle `tri` by `ray` lies on, if it lies
    /// on one drawn by [`MeshObject::with_edges`].
    #[must_use]
    pub fn edge_color(&self, tri: usize, h: &TriangleHit, ray: &Ray) -> Option<[f32; 3]> {
        let style = self.edge_style?;
        let flags = *self.edge_flags.get(tri)?;
        if flags == 0 {
            return None;
        }
        let p = self.mesh.triangles()[tri].map(|k| self.mesh.positions()[k as usize]);
        let twice_area = (p[1] - p[0]).cross(p[2] - p[0]).length();
        let half = 0.5 * style.width * h.t * ray.dir.length();
        (0..3)
            .filter(|k| flags >> k & 1 == 1)
            .any(|k| {
                // The side from corner k to k + 1 is opposite corner k + 2.
                let j = (k + 2) % 3;
                let side = (p[(k + 1) % 3] - p[k]).length();
                side > 0.0 && h.b[j] * twice_area / side <= half
            })
            .then_some(style.color)
    }

    /// The mesh.
    #[must_use]
    pub fn mesh(&self) -> &TriangleMesh {
        &self.mesh
    }

    /// The box of the mesh (padded).
    #[must_use]
    pub fn bounds(&self) -> Aabb<DVec3> {
        self.bvh.bounds()
    }

    /// The nearest hit in [`Ray::t_min`], [`Ray::t_max`] and the triangle's index, by the BVH.
    #[must_use]
    pub fn intersect(&self, ray: &Ray) -> Option<(usize, TriangleHit)> {
        let p = self.mesh.positions();
        let tris = self.mesh.triangles();
        let sheared = ShearedRay::new(ray)?;
        self.bvh
            .traverse(ray, |i, t_max| {
                let [a, b, c] = tris[i].map(|k| p[k as usize]);
                sheared.intersect(a, b, c, t_max).map(|h| (h.t, (i, h)))
            })
            .map(|(_, hit)| hit)
    }

    /// Whether any triangle meets the ray in [`Ray::t_min`], [`Ray::t_max`] (a shadow ray's
    /// any-hit query: the BVH stops at the first triangle hit).
    #[must_use]
    pub fn occluded(&self, ray: &Ray) -> bool {
        let p = self.mesh.positions();
        let tris = self.mesh.triangles();
        let Some(sheared) = ShearedRay::new(ray) else {
            return false;
        };
        self.bvh.any(ray, |i| {
            let [a, b, c] = tris[i].map(|k| p[k as usize]);
            sheared.intersect(a, b, c, ray.t_max).is_some_and(|h| h.t < ray.t_max)
        })
    }

    /// Shading data of a hit on triangle `tri`: point, error bound, geometric normal (facing
    /// the interpolated normal), interpolated unit normal and colour (if the mesh has colours).
    pub(crate) fn surface_at(
        &self,
        tri: usize,
        h: &TriangleHit,
    ) -> (DVec3, DVec3, DVec3, DVec3, Option<[f32; 3]>) {
        let idx = self.mesh.triangles()[tri].map(|k| k as usize);
        let p = idx.map(|k| self.mesh.positions()[k]);
        let n = idx.map(|k| self.mesh.normals()[k]);
        let [b0, b1, b2] = h.b;
        let point = p[0] * b0 + p[1] * b1 + p[2] * b2;
        // pbrt-v4: the barycentric interpolation's error.
        let error = ((p[0] * b0).abs() + (p[1] * b1).abs() + (p[2] * b2).abs()) * gamma(7);
        let shading = (n[0] * b0 + n[1] * b1 + n[2] * b2).try_normalize();
        let mut geometric = (p[1] - p[0]).cross(p[2] - p[0]).try_normalize().unwrap_or(DVec3::Z);
        let shading = shading.unwrap_or(geometric);
        if geometric.dot(shading) < 0.0 {
            geometric = -geometric;
        }
        let color = self.mesh.colors().map(|c| {
            let c = idx.map(|k| c[k]);
            let mix = |j: usize| {
                (f64::from(c[0][j]) * b0 + f64::from(c[1][j]) * b1 + f64::from(c[2][j]) * b2) as f32
            };
            [mix(0), mix(1), mix(2)]
        });
        (point, error, geometric, shading, color)
    }
}

/// a·b − c·d with one rounding error less (Kahan's algorithm, pbrt-v4 `DifferenceOfProducts`),
/// where it matters: the plain difference is kept when it exceeds its own rounding error bound
/// (3 ulp of the larger product) by a wide margin, so that its sign and value agree with the
/// compensated one to an ulp, and the compensated form is computed only near cancellation.
fn difference_of_products(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let (ab, cd) = (a * b, c * d);
    let plain = ab - cd;
    if plain.abs() > 1e-12 * ab.abs().max(cd.abs()) {
        return plain;
    }
    let err = (-c).mul_add(d, cd);
    let dop = a.mul_add(b, -cd);
    dop + err
}

/// The per-ray part of the watertight test (pbrt-v4 §6.5.3): the axis permutation that makes
/// the direction's largest component z, and the shear that maps the direction onto +z. A
/// mesh computes it once per ray instead of once per triangle.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ShearedRay {
    origin: DVec3,
    t_min: f64,
    /// The axes taken as x, y, z.
    k: [usize; 3],
    /// `-d.x / d.z`, `-d.y / d.z` and `1 / d.z` for the direction d in the permuted axes.
    s: DVec3,
}

impl ShearedRay {
    /// The permutation and shear of `ray`; `None` for a zero direction.
    pub(crate) fn new(ray: &Ray) -> Option<Self> {
        let ad = ray.dir.abs();
        let kz = if ad.x > ad.y {
            if ad.x > ad.z { 0 } else { 2 }
        } else if ad.y > ad.z {
            1
        } else {
            2
        };
        let kx = if kz == 2 { 0 } else { kz + 1 };
        let ky = if kx == 2 { 0 } else { kx + 1 };
        let d = DVec3::new(ray.dir[kx], ray.dir[ky], ray.dir[kz]);
        if d.z == 0.0 {
            return None;
        }
        Some(ShearedRay {
            origin: ray.origin,
            t_min: ray.t_min,
            k: [kx, ky, kz],
            s: DVec3::new(-d.x / d.z, -d.y / d.z, 1.0 / d.z),
        })
    }

    /// The hit on triangle (`p0`, `p1`, `p2`) with t in (`t_min`, `t_max`), if any.
    pub(crate) fn intersect(
        &self,
        p0: DVec3,
        p1: DVec3,
        p2: DVec3,
        t_max: f64,
    ) -> Option<TriangleHit> {
        if (p2 - p0).cross(p1 - p0).length_squared() == 0.0 {
            return None;
        }
        let [kx, ky, kz] = self.k;
        let to_ray = |p: DVec3| {
            let v = p - self.origin;
            let z = v[kz];
            DVec3::new(v[kx] + self.s.x * z, v[ky] + self.s.y * z, z)
        };
        let (mut p0t, mut p1t, mut p2t) = (to_ray(p0), to_ray(p1), to_ray(p2));
        let e0 = difference_of_products(p1t.x, p2t.y, p1t.y, p2t.x);
        let e1 = difference_of_products(p2t.x, p0t.y, p2t.y, p0t.x);
        let e2 = difference_of_products(p0t.x, p1t.y, p0t.y, p1t.x);
        if (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0) {
            return None;
        }
        let det = e0 + e1 + e2;
        if det == 0.0 {
            return None;
        }
        let sz = self.s.z;
        p0t.z *= sz;
        p1t.z *= sz;
        p2t.z *= sz;
        let t_scaled = e0 * p0t.z + e1 * p1t.z + e2 * p2t.z;
        if det < 0.0 && (t_scaled >= self.t_min * det || t_scaled < t_max * det) {
            return None;
        }
        if det > 0.0 && (t_scaled <= self.t_min * det || t_scaled > t_max * det) {
            return None;
        }
        let inv_det = 1.0 / det;
        let (b0, b1, b2) = (e0 * inv_det, e1 * inv_det, e2 * inv_det);
        let t = t_scaled * inv_det;
        // pbrt-v4: make sure t is provably greater than zero.
        let max_zt = DVec3::new(p0t.z, p1t.z, p2t.z).abs().max_element();
        let delta_z = gamma(3) * max_zt;
        let max_xt = DVec3::new(p0t.x, p1t.x, p2t.x).abs().max_element();
        let max_yt = DVec3::new(p0t.y, p1t.y, p2t.y).abs().max_element();
        let delta_x = gamma(5) * (max_xt + max_zt);
        let delta_y = gamma(5) * (max_yt + max_zt);
        let delta_e = 2.0 * (gamma(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
        let max_e = DVec3::new(e0, e1, e2).abs().max_element();
        let delta_t =
            3.0 * (gamma(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) * inv_det.abs();
        if t <= delta_t.max(self.t_min) {
            return None;
        }
        Some(TriangleHit { t, b: [b0, b1, b2] })
    }
}

/// The watertight ray–triangle test of pbrt-v4 (§6.5.3) in f64: the hit with t in
/// (`ray.t_min`, `t_max`), if any. Hits with t not provably positive are rejected.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_raytrace::{Ray, intersect_triangle};
/// let ray = Ray::new(DVec3::new(0.2, 0.2, 1.0), -DVec3::Z);
/// let h = intersect_triangle(&ray, DVec3::ZERO, DVec3::X, DVec3::Y, f64::INFINITY).unwrap();
/// assert!((h.t - 1.0).abs() < 1e-15);
/// assert!((h.b[1] - 0.2).abs() < 1e-15 && (h.b[2] - 0.2).abs() < 1e-15);
/// ```
#[must_use]
pub fn intersect_triangle(
    ray: &Ray,
    p0: DVec3,
    p1: DVec3,
    p2: DVec3,
    t_max: f64,
) -> Option<TriangleHit> {
    ShearedRay::new(ray)?.intersect(p0, p1, p2, t_max)
}
