// SPDX-License-Identifier: MIT
//! Ray tracing of harmonic surfaces (A. Hardy, *Harmonic interpolation for smooth curves and
//! surfaces*, 2005, §5.5 "Rendering", §5.6 "Ray tracing").
//!
//! A small renderer with three kinds of object:
//!
//! | object | intersection | where |
//! |---|---|---|
//! | harmonic surface | interval bisection or interval Newton (Krawczyk) on p(u, v) − (o + t·d) = 0, within cells found by a BVH over their interval enclosures (§5.6) | [`HarmonicObject`], [`IntervalMethod`] |
//! | Bézier patches | flat pieces (subdivision) in a BVH over their control boxes, Newton in (u, v, t) on the exact patch (§5.6, §5.7) | [`BezierObject`] |
//! | triangle mesh | BVH, watertight f64 ray–triangle test (§5.5); in a render, the camera rays and the shadow rays towards directional lights find their triangles by image bins and light-space grids instead (the same test, the same hits, a few times faster) | [`MeshObject`] |
//!
//! and a [`Camera`] (look-at, vertical field of view), a [`Scene`] with directional and point
//! [`Light`]s, Blinn–Phong shading with shadow rays whose origins are offset by the error bound
//! of the hit ([`offset_ray_origin`]) and which stop at the first hit ([`Scene::occluded`]), colours from curvature ([`SurfaceColor`]), vertex colours
//! or per-patch colours, supersampling and parallel tiles ([`render`]), and sRGB PNG output.
//!
//! # Examples
//!
//! ```
//! use glam::DVec3;
//! use hi_raytrace::{HarmonicObject, HarmonicOptions, Ray};
//!
//! // The exact harmonic sphere of radius 1 (a 4×4 grid), hit from z = 3.
//! let sphere = HarmonicObject::try_new(hi_surface::sphere(1.0), &HarmonicOptions::default())?;
//! let hit = sphere.intersect(&Ray::new(DVec3::new(0.6, 0.0, 3.0), -DVec3::Z)).unwrap();
//! assert!((hit.t - (3.0 - 0.8)).abs() < 1e-9); // z = √(1 − 0.6²) = 0.8
//! assert!(hit.proven); // Krawczyk's test proved the root unique in its box
//! # Ok::<(), hi_raytrace::Error>(())
//! ```
//!
//! # Feature flags
//!
//! | feature | default | adds |
//! |---|---|---|
//! | `parallel` | yes | image tiles rendered on all cores (rayon), and `hi-surface`'s parallel grids; without it one thread draws the same image |
//! | `png` | yes | PNG output: `Rendering::png_bytes`, `Rendering::write_png` (the `image` crate) |
//! | `serde` | no | `Serialize` and `Deserialize` for cameras, lights, materials, options, rays, hits and ray counts, in the form of `hi render`'s scene file: a camera is `{"eye", "target", "up", "fov"}` (field of view in degrees, `up` +Z by default), colours are sRGB in [0, 1] (`srgb`), lights `{"type": "directional" or "point", …}`; read back through the checked constructors; objects and scenes (which hold their BVHs) have no `serde` form |
//! | `schemars` | no | JSON schemas (`schemars::JsonSchema`) of the `serde` forms of cameras, lights and materials |

mod bezier;
mod bins;
mod bvh;
mod camera;
mod error;
mod harmonic;
mod mesh;
mod ray;
mod render;
mod scene;
#[cfg(feature = "serde")]
mod serde_impls;
#[cfg(feature = "testing")]
pub mod testing;

pub use bezier::{BezierHit, BezierObject, BezierOptions};
pub use camera::Camera;
pub use error::Error;
pub use harmonic::{HarmonicHit, HarmonicObject, HarmonicOptions, IntervalMethod, SurfaceColor};
pub use mesh::{EdgeStyle, MeshObject, TriangleHit, intersect_triangle};
pub use ray::{Hit, Ray, offset_ray_origin};
pub use render::{
    ADAPTIVE_SPREAD, MAX_SAMPLES, MAX_SIZE, Progress, RayCounts, RenderOptions, Rendering, render,
};
pub use scene::{DEFAULT_BACKGROUND, DEFAULT_VIEW, Geometry, Light, Material, Scene, SceneObject};
#[cfg(feature = "serde")]
pub use serde_impls::{DEFAULT_FOV_DEGREES, srgb};

/// The example of this crate's README, run as a doctest so that it stays true.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct CrateReadmeDoctests;
