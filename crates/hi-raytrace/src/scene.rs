// SPDX-License-Identifier: MIT
//! Scenes (Hardy 2005, §5.6, figure 5.26: "the torus … was raytraced along with a few other
//! objects"): objects of three kinds — triangle meshes, Bézier patches, harmonic surfaces —
//! with materials, directional and point lights, Blinn–Phong shading and shadow rays.

use glam::DVec3;
use hi_bezier::Aabb;

use crate::bezier::BezierObject;
use crate::error::{Error, check_finite};
use crate::harmonic::HarmonicObject;
use crate::mesh::{MeshObject, TriangleHit};
use crate::ray::{Hit, Ray, offset_ray_origin};

/// The geometry of an object.
#[derive(Clone, Debug)]
pub enum Geometry {
    /// A triangle mesh in a BVH.
    Mesh(MeshObject),
    /// Bézier patches in a BVH.
    Bezier(BezierObject),
    /// A harmonic surface, intersected by interval methods.
    Harmonic(HarmonicObject),
}

impl Geometry {
    /// The box of the geometry.
    #[must_use]
    pub fn bounds(&self) -> Aabb<DVec3> {
        match self {
            Geometry::Mesh(m) => m.bounds(),
            Geometry::Bezier(b) => b.bounds(),
            Geometry::Harmonic(h) => h.bounds(),
        }
    }

    /// Whether the geometry meets `ray` in its (`t_min`, `t_max`) (a shadow ray's any-hit
    /// query).
    pub(crate) fn occluded(&self, ray: &Ray) -> bool {
        match self {
            Geometry::Mesh(m) => m.occluded(ray),
            Geometry::Bezier(b) => b.occluded(ray),
            Geometry::Harmonic(s) => s.occluded(ray),
        }
    }
}

/// How a surface reflects light (Blinn–Phong): the colour of a mesh without vertex colours,
/// and the diffuse and specular weights.
///
/// Its `serde` form (feature `serde`) is `{"color", "diffuse", "specular", "shininess"}`, each
/// optional, with the colour in sRGB (see `hi_raytrace::srgb`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Colour (linear RGB) of meshes without vertex colours; Bézier patches and harmonic surfaces
    /// carry their own colours.
    pub color: [f32; 3],
    /// Weight of the Lambert term.
    pub diffuse: f32,
    /// Weight of the specular term.
    pub specular: f32,
    /// Blinn–Phong exponent.
    pub shininess: f32,
}

impl Default for Material {
    /// Light grey, diffuse 0.85, specular 0.25, shininess 40.
    fn default() -> Self {
        Material { color: [0.7, 0.7, 0.7], diffuse: 0.85, specular: 0.25, shininess: 40.0 }
    }
}

/// An object of a scene.
#[derive(Clone, Debug)]
pub struct SceneObject {
    /// Its geometry.
    pub geometry: Geometry,
    /// Its material.
    pub material: Material,
}

impl SceneObject {
    /// The geometry with the default material.
    #[must_use]
    pub fn new(geometry: Geometry) -> Self {
        SceneObject { geometry, material: Material::default() }
    }
}

/// A light source; intensities are linear RGB.
///
/// Its `serde` form (feature `serde`) is `{"type": "directional", "direction", "intensity"}`,
/// `{"type": "fill", "direction", "intensity"}` or `{"type": "point", "position", "intensity"}`,
/// the intensity a number (grey) or `[r, g, b]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light {
    /// Light from a direction (the sun).
    Directional {
        /// Direction towards the light (need not be unit length).
        direction: DVec3,
        /// Irradiance on a surface facing the light.
        intensity: [f32; 3],
    },
    /// Light from a direction that casts no shadow: the fill light of a studio set-up, which
    /// lightens the side the key light leaves dark without drawing a second shadow (one
    /// light, one shadow). It sends no shadow rays.
    Fill {
        /// Direction towards the light (need not be unit length).
        direction: DVec3,
        /// Irradiance on a surface facing the light.
        intensity: [f32; 3],
    },
    /// Light from a point, falling off with the squared distance.
    Point {
        /// Position of the light.
        position: DVec3,
        /// Radiant intensity: the irradiance at distance 1.
        intensity: [f32; 3],
    },
}

/// The default direction from the centre of a scene to the eye (in front, to the left and
/// above), for a scene that gives no camera: `hi render`'s and the Python package's.
pub const DEFAULT_VIEW: DVec3 = DVec3::new(0.9, -2.0, 1.3);

/// The default background (linear RGB), for a scene that gives none.
pub const DEFAULT_BACKGROUND: [f32; 3] = [0.04, 0.05, 0.07];

impl Light {
    /// The default lights of a scene that gives none, for the direction `view` (as
    /// [`DEFAULT_VIEW`], negated): a key light above and to one side, which casts the
    /// shadows, and a weaker [`Light::Fill`] from the other side, which casts none.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_raytrace::{DEFAULT_VIEW, Light};
    /// let lights = Light::key_and_fill(-DEFAULT_VIEW);
    /// assert!(matches!(lights[..], [Light::Directional { .. }, Light::Fill { .. }]));
    /// ```
    #[must_use]
    pub fn key_and_fill(view: DVec3) -> Vec<Light> {
        let side = view.cross(DVec3::Z).try_normalize().unwrap_or(DVec3::X);
        vec![
            Light::Directional { direction: -view + DVec3::Z * 1.5 - side, intensity: [0.85; 3] },
            Light::Fill { direction: -view + side, intensity: [0.3; 3] },
        ]
    }
}

/// Objects, lights and background.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_raytrace::{Geometry, HarmonicObject, HarmonicOptions, Light, Ray, Scene, SceneObject};
///
/// let sphere = HarmonicObject::try_new(hi_surface::sphere(1.0), &HarmonicOptions::default())?;
/// let light = Light::Directional { direction: DVec3::Z, intensity: [1.0; 3] };
/// let scene = Scene::try_new(vec![SceneObject::new(Geometry::Harmonic(sphere))], vec![light], [0.0; 3])?;
/// let hit = scene.intersect(&Ray::new(DVec3::new(0.6, 0.0, 3.0), -DVec3::Z)).unwrap();
/// assert!((hit.t - (3.0 - 0.8)).abs() < 1e-9); // z = √(1 − 0.6²) = 0.8
/// assert!(Scene::try_new(vec![], vec![], [0.0; 3]).is_err()); // no objects
/// # Ok::<(), hi_raytrace::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Scene {
    // Invariant: at least one object; lights and colours finite.
    objects: Vec<SceneObject>,
    lights: Vec<Light>,
    /// Each directional or fill light's unit direction (zero for a point light), normalised
    /// once rather than for every shaded sample.
    units: Vec<DVec3>,
    background: [f32; 3],
    ambient: [f32; 3],
}

/// Ambient light of a new scene (linear RGB).
const DEFAULT_AMBIENT: [f32; 3] = [0.08, 0.08, 0.08];

/// `Ok` if all components are finite and non-negative.
fn check_color(what: &'static str, c: [f32; 3]) -> Result<(), Error> {
    if c.iter().all(|x| x.is_finite()) {
        if let Some(&x) = c.iter().find(|x| **x < 0.0) {
            return Err(Error::InvalidValue {
                what,
                value: f64::from(x),
                expected: "non-negative",
            });
        }
        Ok(())
    } else {
        Err(Error::NonFinite { what })
    }
}

/// `Ok` if the material's colour and weights are finite and non-negative.
pub(crate) fn check_material(m: &Material) -> Result<(), Error> {
    check_color("material colour", m.color)?;
    check_color("material weights", [m.diffuse, m.specular, m.shininess])
}

/// `Ok` if the light's position or (non-zero) direction and its intensity are finite, the
/// intensity non-negative.
pub(crate) fn check_light(light: &Light) -> Result<(), Error> {
    match *light {
        Light::Directional { direction, intensity } | Light::Fill { direction, intensity } => {
            check_finite("light direction", direction)?;
            if direction.length_squared() == 0.0 {
                return Err(Error::InvalidValue {
                    what: "length of light direction",
                    value: 0.0,
                    expected: "a non-zero vector",
                });
            }
            check_color("light intensity", intensity)
        }
        Light::Point { position, intensity } => {
            check_finite("light position", position)?;
            check_color("light intensity", intensity)
        }
    }
}

impl Scene {
    /// A scene of `objects` lit by `lights` in front of `background` (linear RGB).
    ///
    /// # Errors
    ///
    /// [`Error::EmptyScene`] for no objects; [`Error::NonFinite`] or [`Error::InvalidValue`] for
    /// a light, colour or material that is not finite or is negative, or a zero light direction.
    pub fn try_new(
        objects: Vec<SceneObject>,
        lights: Vec<Light>,
        background: [f32; 3],
    ) -> Result<Self, Error> {
        if objects.is_empty() {
            return Err(Error::EmptyScene);
        }
        check_color("background colour", background)?;
        for o in &objects {
            check_material(&o.material)?;
        }
        for l in &lights {
            check_light(l)?;
        }
        let units = lights
            .iter()
            .map(|l| match *l {
                Light::Directional { direction, .. } | Light::Fill { direction, .. } => {
                    direction.normalize()
                }
                Light::Point { .. } => DVec3::ZERO,
            })
            .collect();
        Ok(Scene { objects, lights, units, background, ambient: DEFAULT_AMBIENT })
    }

    /// The same scene with ambient light `ambient` (linear RGB).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`] or [`Error::InvalidValue`] for a bad colour.
    pub fn with_ambient(mut self, ambient: [f32; 3]) -> Result<Self, Error> {
        check_color("ambient light", ambient)?;
        self.ambient = ambient;
        Ok(self)
    }

    /// The objects.
    #[must_use]
    pub fn objects(&self) -> &[SceneObject] {
        &self.objects
    }

    /// The lights.
    #[must_use]
    pub fn lights(&self) -> &[Light] {
        &self.lights
    }

    /// The background colour (linear RGB).
    #[must_use]
    pub fn background(&self) -> [f32; 3] {
        self.background
    }

    /// The box of all objects.
    #[must_use]
    pub fn bounds(&self) -> Aabb<DVec3> {
        // A scene has an object (`Scene::try_new`).
        let mut boxes = self.objects.iter().map(|o| o.geometry.bounds());
        let first = boxes.next().unwrap_or(Aabb::from_point(DVec3::ZERO));
        boxes.fold(first, Aabb::union)
    }

    /// The nearest hit of `ray` on any object.
    #[must_use]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        self.intersect_after(ray, None, |_| true)
    }

    /// The nearest hit of `ray` on the objects for which `take` holds, each tried in turn with
    /// the ray cut at the nearest hit so far (starting from `best`) and kept only if strictly
    /// nearer.
    pub(crate) fn intersect_after(
        &self,
        ray: &Ray,
        mut best: Option<Hit>,
        take: impl Fn(usize) -> bool,
    ) -> Option<Hit> {
        for (index, object) in self.objects.iter().enumerate() {
            if !take(index) {
                continue;
            }
            let r = ray.with_t_max(best.map_or(ray.t_max, |b| b.t));
            let hit = match &object.geometry {
                Geometry::Mesh(m) => {
                    m.intersect(&r).map(|(tri, h)| self.mesh_hit(index, m, tri, &h, &r))
                }
                Geometry::Bezier(b) => b.intersect(&r).map(|h| {
                    let (point, error, normal, uv, color) = b.surface_at(&h);
                    Hit {
                        t: h.t,
                        point,
                        error,
                        geometric_normal: normal,
                        shading_normal: normal,
                        uv,
                        color,
                        object: index,
                    }
                }),
                Geometry::Harmonic(s) => s.intersect(&r).map(|h| {
                    let (point, normal, color) = s.surface_at(&r, &h);
                    Hit {
                        t: h.t,
                        point,
                        error: h.error,
                        geometric_normal: normal,
                        shading_normal: normal,
                        uv: (h.u, h.v),
                        color,
                        object: index,
                    }
                }),
            };
            if let Some(h) = hit
                && best.is_none_or(|b| h.t < b.t)
            {
                best = Some(h);
            }
        }
        best
    }

    /// The hit record of the hit `h` of `ray` on triangle `tri` of object `index`, the mesh `m`.
    pub(crate) fn mesh_hit(
        &self,
        index: usize,
        m: &MeshObject,
        tri: usize,
        h: &TriangleHit,
        ray: &Ray,
    ) -> Hit {
        let (point, error, geometric, shading, color) = m.surface_at(tri, h);
        let color = m.edge_color(tri, h, ray).or(color);
        Hit {
            t: h.t,
            point,
            error,
            geometric_normal: geometric,
            shading_normal: shading,
            uv: (h.b[1], h.b[2]),
            color: color.unwrap_or(self.objects[index].material.color),
            object: index,
        }
    }

    /// Whether anything lies on `ray` between its `t_min` and `t_max`: the any-hit query of
    /// shadow rays, which stops at the first hit found rather than the nearest.
    #[must_use]
    pub fn occluded(&self, ray: &Ray) -> bool {
        self.objects.iter().any(|object| object.geometry.occluded(ray))
    }

    /// The light leaving `hit` towards the eye of `ray` (linear RGB), with the number of shadow
    /// rays cast, and whether a light facing the surface was blocked. `occluded(k, ray)` answers
    /// the shadow ray towards light `k` (as [`Scene::occluded`] does).
    pub(crate) fn shade(
        &self,
        ray: &Ray,
        hit: &Hit,
        occluded: impl Fn(usize, &Ray) -> bool,
    ) -> ([f32; 3], usize, bool) {
        let material = &self.objects[hit.object].material;
        // Two-sided surfaces: the normals that face the viewer.
        let (mut n, mut ng) = (hit.shading_normal, hit.geometric_normal);
        if ng.dot(ray.dir) > 0.0 {
            ng = -ng;
        }
        if n.dot(ng) < 0.0 {
            n = -n;
        }
        let albedo = hit.color.map(f64::from);
        let mut out = [0.0f64; 3];
        for k in 0..3 {
            out[k] = f64::from(self.ambient[k]) * albedo[k];
        }
        let mut n_shadow = 0;
        let mut blocked = false;
        for (light_index, light) in self.lights.iter().enumerate() {
            let (l, dist, intensity) = match *light {
                Light::Directional { intensity, .. } | Light::Fill { intensity, .. } => {
                    (self.units[light_index], f64::INFINITY, intensity.map(f64::from))
                }
                Light::Point { position, intensity } => {
                    let to = position - hit.point;
                    let d = to.length();
                    if d == 0.0 {
                        continue;
                    }
                    let i = intensity.map(|x| f64::from(x) / (d * d));
                    (to / d, d, i)
                }
            };
            let cos = n.dot(l);
            if cos <= 0.0 {
                continue;
            }
            let origin = offset_ray_origin(hit.point, hit.error, ng, l);
            let t_max = if dist.is_finite() {
                (position_distance(origin, hit.point, l, dist)) * (1.0 - 1e-9)
            } else {
                f64::INFINITY
            };
            if !matches!(light, Light::Fill { .. }) {
                let shadow = Ray { origin, dir: l, t_min: 0.0, t_max };
                n_shadow += 1;
                if occluded(light_index, &shadow) {
                    blocked = true;
                    continue;
                }
            }
            // (No highlight to compute on a matt surface.)
            let spec = if material.specular > 0.0 {
                let view = -ray.dir.normalize();
                let h = (l + view).normalize_or_zero();
                f64::from(material.specular) * phong(n.dot(h), material.shininess)
            } else {
                0.0
            };
            for k in 0..3 {
                out[k] += intensity[k] * (f64::from(material.diffuse) * albedo[k] * cos + spec);
            }
        }
        (out.map(|x| x as f32), n_shadow, blocked)
    }
}

/// The Blinn–Phong lobe max(c, 0)^`shininess`: by repeated multiplication for a whole
/// exponent up to 256 (the default 40 among them: a few products instead of a `pow`; each
/// squaring doubles the relative error so far, so 40 leaves about 40 units of roundoff, some
/// 10⁻¹⁴, far below an 8-bit pixel), by `powf` otherwise.
fn phong(c: f64, shininess: f32) -> f64 {
    let s = f64::from(shininess);
    if c <= 0.0 {
        // 0⁰ = 1, as `powf` has it.
        return if s == 0.0 { 1.0 } else { 0.0 };
    }
    if s.fract() == 0.0 && (0.0..=256.0).contains(&s) { c.powi(s as i32) } else { c.powf(s) }
}

/// The distance from `origin` to the light at `dist` from `point` along `l`.
fn position_distance(origin: DVec3, point: DVec3, l: DVec3, dist: f64) -> f64 {
    (point + l * dist - origin).length()
}

#[cfg(test)]
mod tests {
    use super::phong;

    /// The highlight by repeated products is `powf`'s to a relative 10⁻¹³ (rounding grows about
    /// like the exponent times the unit roundoff), and so is it where it falls back to `powf`;
    /// on the dark side it is 0, or 1 for the exponent 0 (0⁰ = 1).
    #[test]
    fn the_highlight_by_products_is_powf() {
        for s in [0.0f32, 1.0, 2.0, 7.0, 40.0, 256.0, 2.5, 300.0] {
            for i in -20..=200 {
                let c = f64::from(i) / 200.0;
                let want = c.max(0.0).powf(f64::from(s));
                let got = phong(c, s);
                assert!((got - want).abs() <= 1e-13 * want, "{c}^{s}: {got} against {want}");
            }
        }
    }
}
