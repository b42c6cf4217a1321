// SPDX-License-Identifier: MIT
//! Meshes: the subdivision schemes the thesis compares against (§4.5) and rendering (§5.5,
//! §5.6): a harmonic surface ray traced (its Bézier patches, or the surface itself by interval
//! Newton or bisection) or a triangle mesh, framed and lit as `hi render --quick` does.

use glam::DVec3;
use hi_curve::bezier::{BezierScheme, DEFAULT_TOLERANCE, HermiteDegree};
use hi_mesh::TriangleMesh;
use hi_mesh::subdivision::{LoopWeights, PolyMesh, Scheme};
use hi_raytrace::{
    BezierObject, BezierOptions, Camera, DEFAULT_BACKGROUND, DEFAULT_VIEW, Geometry,
    HarmonicObject, HarmonicOptions, IntervalMethod, Light, MeshObject, RenderOptions, Scene,
    SceneObject, render as trace,
};
use hi_surface::{HarmonicSurface, MeshOptions};
use numpy::IntoPyArray;
use numpy::ndarray::Array3;
use pyo3::prelude::*;

use crate::arrays::{from_faces, from_points, points3, triangles};
use crate::errors::value_error;
use crate::surface::PyHarmonicSurface;

/// Steps of subdivision at most (each multiplies the faces by 3 or 4).
const MAX_LEVELS: usize = 8;

/// The scheme of a name.
fn scheme(name: &str) -> PyResult<Scheme> {
    let all = Scheme::ALL.into_iter().chain([Scheme::Loop(LoopWeights::Warren)]);
    let found = all.clone().find(|s| s.name() == name);
    found.ok_or_else(|| {
        let names: Vec<&str> = all.map(Scheme::name).collect();
        value_error(format!("unknown scheme '{name}' (expected {})", names.join(", ")))
    })
}

/// Subdivides a polygon mesh `levels` times by a scheme of §4.5: `loop` (or `loop-warren`),
/// `butterfly`, `sqrt3`, `isqrt3` (triangles), `catmull-clark`, `doo-sabin` (any polygons).
/// `vertices` has shape (V, 3); `faces` is an (F, k) integer array or a list of polygons,
/// manifold and consistently oriented. Returns `(vertices, faces)`: faces as an (F, k) array
/// when all have k corners, else a list.
///
/// >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
/// >>> f = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
/// >>> v2, f2 = harmonic.subdivide(v, f, "loop", 2)
/// >>> v2.shape, f2.shape
/// ((34, 3), (64, 3))
#[pyfunction]
#[pyo3(signature = (vertices, faces, scheme, levels = 1))]
pub(crate) fn subdivide<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    scheme: &str,
    levels: usize,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    if levels > MAX_LEVELS {
        return Err(value_error(format!("levels: {levels} is too many (at most {MAX_LEVELS})")));
    }
    let scheme = self::scheme(scheme)?;
    let positions = points3(vertices, "vertices")?;
    let polygons = crate::arrays::faces(faces, "faces")?;
    let refined = py
        .detach(|| {
            let mesh = PolyMesh::try_new(positions, &polygons)?;
            scheme.steps(&mesh, levels)
        })
        .map_err(value_error)?;
    let out: Vec<Vec<u32>> = refined.faces().map(<[u32]>::to_vec).collect();
    Ok((from_points(py, refined.positions()).into_any(), from_faces(py, &out)?))
}

/// What `render` draws: a harmonic surface by a method, or a triangle mesh.
enum Object {
    Surface(HarmonicSurface<DVec3>, String),
    Mesh(TriangleMesh),
}

/// The object of `render`'s first argument.
fn object(value: &Bound<'_, PyAny>, method: &str) -> PyResult<Object> {
    if let Ok(surface) = value.cast::<PyHarmonicSurface>() {
        return Ok(Object::Surface(surface.get().inner.clone(), method.to_owned()));
    }
    let (vertices, faces_in): (Bound<'_, PyAny>, Bound<'_, PyAny>) =
        value.extract().map_err(|_| {
            pyo3::exceptions::PyTypeError::new_err(
                "render: expected a HarmonicSurface or a (vertices, faces) pair",
            )
        })?;
    let positions = points3(&vertices, "vertices")?;
    let tris = triangles(&faces_in, "faces")?;
    Ok(Object::Mesh(TriangleMesh::from_triangles(positions, tris).map_err(value_error)?))
}

/// The geometry of an object for the ray tracer.
fn geometry(object: Object) -> Result<Geometry, String> {
    let text = |e: &dyn std::fmt::Display| e.to_string();
    Ok(match object {
        Object::Mesh(mesh) => Geometry::Mesh(MeshObject::new(mesh)),
        Object::Surface(surface, method) => match method.as_str() {
            "bezier" => {
                let scheme = BezierScheme::Hermite(HermiteDegree::Cubic);
                let patches = surface.to_bezier(scheme, DEFAULT_TOLERANCE).map_err(|e| text(&e))?;
                let options = BezierOptions::default();
                Geometry::Bezier(
                    BezierObject::try_from_surface(&patches, &options).map_err(|e| text(&e))?,
                )
            }
            "krawczyk" | "bisection" => {
                let settings = HarmonicOptions {
                    method: if method == "krawczyk" {
                        IntervalMethod::Krawczyk
                    } else {
                        IntervalMethod::Bisection
                    },
                    ..HarmonicOptions::default()
                };
                Geometry::Harmonic(
                    HarmonicObject::try_new(surface, &settings).map_err(|e| text(&e))?,
                )
            }
            "mesh" => {
                let options = MeshOptions { n_u: 256, n_v: 256, ..MeshOptions::default() };
                Geometry::Mesh(MeshObject::new(surface.to_mesh(&options).map_err(|e| text(&e))?))
            }
            other => {
                return Err(format!(
                    "unknown method '{other}' (expected bezier, krawczyk, bisection or mesh)"
                ));
            }
        },
    })
}

/// Ray traces a harmonic surface or a triangle mesh `(vertices, faces)`, framed from the front
/// and lit by two lights as `hi render --quick` does, into an (height, width, 3) `uint8` array
/// of sRGB pixels. A surface is drawn by `method`: `bezier` (C1 Hermite patches, the default),
/// `krawczyk` or `bisection` (the surface itself by interval arithmetic, §5.6), or `mesh`.
///
/// >>> image = harmonic.render(harmonic.example("sphere"), width=32, height=24, spp=1)
/// >>> image.shape, image.dtype.name
/// ((24, 32, 3), 'uint8')
#[pyfunction]
#[pyo3(signature = (obj, width = 512, height = 512, spp = 4, method = "bezier"))]
pub(crate) fn render<'py>(
    py: Python<'py>,
    obj: &Bound<'py, PyAny>,
    width: u32,
    height: u32,
    spp: u32,
    method: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let object = object(obj, method)?;
    let rendering = py
        .detach(|| -> Result<_, String> {
            let scene = Scene::try_new(
                vec![SceneObject::new(geometry(object)?)],
                Light::key_and_fill(-DEFAULT_VIEW),
                DEFAULT_BACKGROUND,
            )
            .map_err(|e| e.to_string())?;
            let hi_bezier::Aabb { min: lo, max: hi } = scene.bounds();
            let radius = (0.5 * (hi - lo).length()).max(1e-9);
            let fov = hi_raytrace::DEFAULT_FOV_DEGREES.to_radians();
            let camera = Camera::framing(0.5 * (lo + hi), radius, DEFAULT_VIEW, DVec3::Z, fov)
                .map_err(|e| format!("camera: {e}"))?;
            let options =
                RenderOptions { width, height, samples_per_pixel: spp, ..RenderOptions::default() };
            trace(&scene, &camera, &options, None).map_err(|e| e.to_string())
        })
        .map_err(value_error)?;
    let flat: Vec<u8> = rendering.pixels.iter().flatten().copied().collect();
    let (h, w) = (rendering.height as usize, rendering.width as usize);
    let image = Array3::from_shape_vec((h, w, 3), flat).map_err(value_error)?;
    Ok(image.into_pyarray(py).into_any())
}
