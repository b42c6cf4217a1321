// SPDX-License-Identifier: MIT
//! References and demonstrations, for tests, benchmarks and the figures: the nearest hit on a
//! mesh by testing every triangle (the reference the BVH is tested against), and the torus of
//! Hardy 2005, figure 5.26, rendered by each method, for timing: "the process of raytracing
//! the image took several hours" (§5.6). A report generator calls [`render_torus`] at
//! 512 × 512 for each [`TorusMethod`]; the benchmarks do the same at a small size.
//!
//! Compiled only with the crate's `testing` feature.

use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_surface::{MeshOptions, torus};

use crate::bezier::{BezierObject, BezierOptions};
use crate::camera::Camera;
use crate::error::Error;
use crate::harmonic::{HarmonicObject, HarmonicOptions, IntervalMethod, SurfaceColor};
use crate::mesh::{MeshObject, TriangleHit, intersect_triangle};
use crate::ray::Ray;
use crate::render::{RenderOptions, Rendering, render};
use crate::scene::{Geometry, Light, Scene, SceneObject};

/// How the torus is intersected.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TorusMethod {
    /// The harmonic surface by interval Newton (Krawczyk).
    IntervalNewton,
    /// The harmonic surface by interval bisection.
    IntervalBisection,
    /// C1 Hermite Bézier patches within 1e-4 of the surface (§5.7), Newton on the patches.
    Bezier,
    /// A 256 × 128 quad mesh of the surface (§5.5).
    Mesh,
}

impl TorusMethod {
    /// All methods, in the order above.
    pub const ALL: [TorusMethod; 4] = [
        TorusMethod::IntervalNewton,
        TorusMethod::IntervalBisection,
        TorusMethod::Bezier,
        TorusMethod::Mesh,
    ];

    /// A short name: `interval-newton`, `interval-bisection`, `bezier`, `mesh`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            TorusMethod::IntervalNewton => "interval-newton",
            TorusMethod::IntervalBisection => "interval-bisection",
            TorusMethod::Bezier => "bezier",
            TorusMethod::Mesh => "mesh",
        }
    }
}

/// The torus scene (R = 2, r = 1, as §5.9's torus) for `method`, lit by a directional and a point
/// light, and its camera.
///
/// # Errors
///
/// Only if the fixed scene were invalid (never, for the fixed parameters).
pub fn torus_scene(method: TorusMethod) -> Result<(Scene, Camera), Error> {
    let surface = torus(2.0, 1.0);
    let color = [0.55, 0.62, 0.85];
    let geometry = match method {
        TorusMethod::IntervalNewton | TorusMethod::IntervalBisection => {
            let settings = HarmonicOptions {
                method: if method == TorusMethod::IntervalNewton {
                    IntervalMethod::Krawczyk
                } else {
                    IntervalMethod::Bisection
                },
                ..HarmonicOptions::default()
            };
            Geometry::Harmonic(
                HarmonicObject::try_new(surface, &settings)?
                    .with_color(SurfaceColor::Uniform(color))?,
            )
        }
        TorusMethod::Bezier => {
            let patches = surface.to_bezier(
                BezierScheme::Hermite(HermiteDegree::Cubic),
                hi_curve::bezier::Tolerance::Absolute(1e-4),
            )?;
            Geometry::Bezier(
                BezierObject::try_from_surface(&patches, &BezierOptions::default())?
                    .with_uniform_color(color),
            )
        }
        TorusMethod::Mesh => {
            let options = MeshOptions { n_u: 128, n_v: 256, ..MeshOptions::default() };
            Geometry::Mesh(MeshObject::new(surface.to_mesh(&options)?))
        }
    };
    let mut object = SceneObject::new(geometry);
    object.material.color = color;
    let lights = vec![
        Light::Directional { direction: DVec3::new(-1.0, -2.0, 3.0), intensity: [0.8, 0.8, 0.75] },
        Light::Point { position: DVec3::new(5.0, -4.0, 6.0), intensity: [30.0, 28.0, 26.0] },
    ];
    let scene = Scene::try_new(vec![object], lights, [0.05, 0.06, 0.08])?;
    let camera = Camera::try_new(DVec3::new(0.0, -7.5, 5.0), DVec3::ZERO, DVec3::Z, 0.75)?;
    Ok((scene, camera))
}

/// Renders the torus of [`torus_scene`] at `width` × `height` with `samples_per_pixel`, returning
/// the image, the ray counts and the time of the render (the scene's preparation not included).
///
/// # Errors
///
/// As [`render`] for bad sizes.
pub fn render_torus(
    method: TorusMethod,
    width: u32,
    height: u32,
    samples_per_pixel: u32,
) -> Result<Rendering, Error> {
    let (scene, camera) = torus_scene(method)?;
    let settings = RenderOptions { width, height, samples_per_pixel, ..RenderOptions::default() };
    render(&scene, &camera, &settings, None)
}

/// The nearest hit of `ray` on `mesh` by testing every triangle (no BVH): the reference for
/// the BVH of [`MeshObject`]. The triangle's index and the hit.
#[must_use]
pub fn intersect_brute_force(mesh: &MeshObject, ray: &Ray) -> Option<(usize, TriangleHit)> {
    let m = mesh.mesh();
    let p = m.positions();
    let mut best: Option<(usize, TriangleHit)> = None;
    for (i, tri) in m.triangles().iter().enumerate() {
        let t_max = best.map_or(ray.t_max, |(_, h)| h.t);
        let [a, b, c] = tri.map(|k| p[k as usize]);
        if let Some(h) = intersect_triangle(ray, a, b, c, t_max) {
            best = Some((i, h));
        }
    }
    best
}
