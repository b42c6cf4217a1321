// SPDX-License-Identifier: MIT
//! Rendered images of the figures (§5.5, §5.6), drawn with `hi-raytrace` at 1200×900 and
//! written as lossless WebP: every glTF model of the figures is rendered beside it (read back
//! from the model's own bytes, so the picture shows what the file holds); the render-only
//! panels show a model close up or a scan's points; and figures 5.25 and 5.26 are renders of
//! the harmonic torus — the tessellated surface (the thesis's scanline rendering) and the
//! surface itself, ray traced by interval Newton (Krawczyk) with a sphere and a floor casting
//! shadows.
//!
//! Every render is deterministic: the sample positions are fixed and each pixel is computed on
//! its own, so the bytes are the same on every run and on every number of threads.

use std::f64::consts::PI;

use anyhow::{Context, Result, ensure};
use glam::{DVec2, DVec3};
use hi_mesh::TriangleMesh;
use hi_raytrace::testing::{TorusMethod, torus_scene};
use hi_raytrace::{
    Camera, EdgeStyle, Geometry, HarmonicObject, HarmonicOptions, IntervalMethod, Light,
    MeshObject, RenderOptions, Scene, SceneObject, SurfaceColor, render,
};
use hi_surface::{HarmonicSurface, sphere, torus};

use super::{Figure, Format, Panel};

/// The size of the renders.
pub(crate) const WIDTH: u32 = 1200;
pub(crate) const HEIGHT: u32 = 900;
/// Samples per pixel (anti-aliasing), in every pixel: the first points of a (0, 2)-sequence,
/// shifted per pixel.
const SPP: u32 = 16;
/// The share of the frame's width and height a model fills ([`Camera::fitting`]).
const FILL: f64 = 0.8;
/// The width of the edges a model's file draws (its lines), in pixels.
const EDGE_PIXELS: f64 = 1.3;
/// Their colour, linear RGB.
const EDGE_COLOR: [f32; 3] = [0.015, 0.02, 0.03];
/// The colour of the floor the models stand on (it takes their shadows).
const FLOOR_COLOR: [f32; 3] = [1.0, 1.0, 1.0];
/// The vertical field of view (radians).
const FOV: f64 = 0.6;

/// Each triangle of §5.9's models cut into this many squared on its PN patch
/// ([`render_models`]): a quad of the 48 × 16 grid spans up to about 60 pixels of the render,
/// and its outline in 4 cubic pieces shows no corner.
const PN_LEVEL: usize = 4;

/// The mesh a `.glb` file holds (one mesh, one triangle primitive, as the figures write) and
/// the edges of its second primitive of lines, if it has one.
fn mesh_from_glb(bytes: &[u8]) -> Result<(TriangleMesh, Vec<[u32; 2]>)> {
    let (document, buffers, _) = gltf::import_slice(bytes).context("parsing the model")?;
    let mesh = document.meshes().next().context("no mesh")?;
    let edges: Vec<[u32; 2]> = match mesh.primitives().nth(1) {
        Some(lines) if lines.mode() == gltf::mesh::Mode::Lines => {
            let reader = lines.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
            let k: Vec<u32> =
                reader.read_indices().context("no edge indices")?.into_u32().collect();
            k.chunks_exact(2).map(|e| [e[0], e[1]]).collect()
        }
        _ => Vec::new(),
    };
    let primitive = mesh.primitives().next().context("no primitive")?;
    let reader = primitive.reader(|b| buffers.get(b.index()).map(|d| &d.0[..]));
    let positions: Vec<DVec3> = reader
        .read_positions()
        .context("no POSITION")?
        .map(|p| DVec3::from(p.map(f64::from)))
        .collect();
    let normals: Vec<DVec3> = reader
        .read_normals()
        .context("no NORMAL")?
        .map(|n| DVec3::from(n.map(f64::from)).normalize_or(DVec3::Z))
        .collect();
    let uvs: Vec<DVec2> = match reader.read_tex_coords(0) {
        Some(t) => t.into_f32().map(|t| DVec2::from(t.map(f64::from))).collect(),
        None => vec![DVec2::ZERO; positions.len()],
    };
    let indices: Vec<u32> = reader.read_indices().context("no indices")?.into_u32().collect();
    let triangles: Vec<[u32; 3]> = indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    let out = TriangleMesh::try_new(positions, normals, uvs, triangles)?;
    let out = match reader.read_colors(0) {
        Some(c) => out.try_with_colors(c.into_rgb_f32().collect())?,
        None => out,
    };
    Ok((out, edges))
}

/// Where the eye looks from, for figure `number`: the heads face +y, seen from in front, to
/// their +x side and above (Spock's, 5.11 and 5.30, nearly from the front, both pointed ears
/// against the background), everything else from the front left, above.
pub(crate) fn view(number: (u32, u32)) -> DVec3 {
    match number {
        (5, 11 | 30) => DVec3::new(0.3, 2.0, 0.6),
        (1, 1) | (4, 35) | (5, 10 | 14..=20 | 29) => DVec3::new(0.9, 2.0, 0.9),
        _ => DVec3::new(0.9, -2.0, 1.3),
    }
}

/// Renders `scene` through `camera` ([`SPP`] samples per pixel), as lossless WebP bytes (a
/// third of the PNG's size on these pictures).
fn webp(scene: &Scene, camera: &Camera) -> Result<Vec<u8>> {
    let settings = RenderOptions {
        width: WIDTH,
        height: HEIGHT,
        samples_per_pixel: SPP,
        tile_size: 16,
        first_pass: 0,
    };
    let out = render(scene, camera, &settings, None)?;
    ensure!(out.counts.hits > 0, "the render hit nothing");
    let raw: Vec<u8> = out.pixels.iter().flatten().copied().collect();
    let image = image::RgbImage::from_raw(out.width, out.height, raw)
        .context("the pixels do not fill the image")?;
    let mut bytes = Vec::new();
    image.write_to(&mut std::io::Cursor::new(&mut bytes), image::ImageFormat::WebP)?;
    Ok(bytes)
}

/// The renders of the models `glbs` (the panels of figure `number`, in order): each lit from
/// the front on a light floor that takes its shadow, on white, filling [`FILL`] of the frame.
/// When the panels show one object at about one size (every panel's bounding box at least half
/// the diagonal of all of theirs: a subdivision series, a surface and its curvature), one
/// camera frames them all, so that they compare; otherwise each panel is framed alone.
///
/// The models of §5.9's comparisons (5.31–5.43) and of 4.1, a coarse sampling of a smooth
/// surface with its exact normals, and the limit surfaces of chapter 4's subdivision schemes
/// (4.13, 4.17, 4.22, 4.29, 4.34), a few steps of the scheme with their vertex normals, are
/// drawn as curved PN triangles ([`TriangleMesh::curved`], [`PN_LEVEL`]): the same vertices
/// and normals, without the polygonal outline and shadows of their flat triangles. The steps
/// of a scheme (4.11, 4.12, …) stay the polyhedra they are.
pub(crate) fn render_models(number: (u32, u32), glbs: &[&[u8]]) -> Result<Vec<Vec<u8>>> {
    let (meshes, edges): (Vec<TriangleMesh>, Vec<Vec<[u32; 2]>>) = glbs
        .iter()
        .map(|g| {
            let (mesh, edges) = mesh_from_glb(g)?;
            Ok(match number {
                (4, 1 | 13 | 17 | 22 | 29 | 34) | (5, 31..=43) if edges.is_empty() => {
                    (mesh.curved(PN_LEVEL)?, edges)
                }
                _ => (mesh, edges),
            })
        })
        .collect::<Result<Vec<_>>>()?
        .into_iter()
        .unzip();
    let from = view(number);
    let aspect = f64::from(WIDTH) / f64::from(HEIGHT);
    let diagonal = |m: &TriangleMesh| {
        let hi_bezier::Aabb { min: lo, max: hi } = m.bounds();
        (hi - lo).length()
    };
    let all: Vec<DVec3> = meshes.iter().flat_map(|m| m.positions().iter().copied()).collect();
    let (lo, hi) = all
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let shared = meshes
        .iter()
        .all(|m| diagonal(m) >= 0.5 * (hi - lo).length())
        .then(|| Camera::fitting(&all, from, DVec3::Z, FOV, aspect, FILL))
        .transpose()?;
    meshes
        .into_iter()
        .zip(edges)
        .map(|(mesh, edges)| {
            let (camera, (lo, hi)) = match shared {
                Some(camera) => (camera, (lo, hi)),
                None => (
                    Camera::fitting(mesh.positions(), from, DVec3::Z, FOV, aspect, FILL)?,
                    (mesh.bounds().min, mesh.bounds().max),
                ),
            };
            render_mesh(mesh, &edges, &camera, Some((lo, hi)), from, MODEL_COLOR, WHITE)
        })
        .collect()
}

/// Where the close-ups of a face look from ([`render_close_up`]): in front of it, a little to
/// its +x side, so that the nose, eyes and mouth face the camera, and above by as much as the
/// other views (the floor's far edge stays above the frame).
const CLOSE_UP_VIEW: DVec3 = DVec3::new(0.45, 2.0, 0.9);

/// The colour of the models (linear RGB).
const MODEL_COLOR: [f32; 3] = [0.72, 0.74, 0.78];

/// The background of the renders (linear RGB), where no floor is seen.
const WHITE: [f32; 3] = [1.0; 3];

/// The render of `mesh` with its `edges` drawn, through `camera`, on a floor under the box
/// (`lo`, `hi`) (none for `None`), lit from `from` as [`render_models`] lights every model,
/// over `background` (linear RGB).
fn render_mesh(
    mesh: TriangleMesh,
    edges: &[[u32; 2]],
    camera: &Camera,
    floor_under: Option<(DVec3, DVec3)>,
    from: DVec3,
    color: [f32; 3],
    background: [f32; 3],
) -> Result<Vec<u8>> {
    // Edges [`EDGE_PIXELS`] wide, as seen.
    let style = EdgeStyle {
        color: EDGE_COLOR,
        width: EDGE_PIXELS * 2.0 * (0.5 * FOV).tan() / f64::from(HEIGHT),
    };
    let mut object = MeshObject::new(mesh);
    if !edges.is_empty() {
        object = object.with_edges(edges, style)?;
    }
    let mut object = SceneObject::new(Geometry::Mesh(object));
    object.material.color = color;
    let mut objects = vec![object];
    if let Some((lo, hi)) = floor_under {
        objects.push(floor(lo, hi)?);
    }
    let scene = Scene::try_new(objects, Light::key_and_fill(-from), background)?;
    webp(&scene, camera)
}

/// The colour (linear RGB) the floor of [`render_models`] takes lit from `from`: matt under
/// directional lights, the same everywhere it is not in shadow. The point sets are drawn on it
/// as their background, so that they sit on the grey of the models beside them without the
/// speckled shadow of their balls.
fn floor_shade(from: DVec3) -> Result<[f32; 3]> {
    let scene = Scene::try_new(
        vec![floor(DVec3::splat(-1.0), DVec3::splat(1.0))?],
        Light::key_and_fill(-from),
        [0.0; 3],
    )?;
    let camera = Camera::try_new(DVec3::new(0.0, 0.0, 5.0), DVec3::ZERO, DVec3::Y, 0.1)?;
    let settings =
        RenderOptions { width: 1, height: 1, samples_per_pixel: 1, tile_size: 16, first_pass: 0 };
    let out = render(&scene, &camera, &settings, None)?;
    let pixel = out.pixels.first().context("no pixel")?;
    let srgb = [pixel[0], pixel[1], pixel[2]].map(|c| f32::from(c) / 255.0);
    Ok(hi_mesh::srgb_to_linear_rgb(srgb))
}

/// A close-up of the model `glb`: a camera from nearer the front than
/// [`render_models`]'s ([`CLOSE_UP_VIEW`]) framing only the vertices for which `keep` holds
/// (the face of a head), the whole model in the scene.
pub(crate) fn render_close_up(glb: &[u8], keep: fn(DVec3) -> bool) -> Result<Vec<u8>> {
    let (mesh, edges) = mesh_from_glb(glb)?;
    let part: Vec<DVec3> = mesh.positions().iter().copied().filter(|p| keep(*p)).collect();
    ensure!(part.len() >= 3, "the close-up frames {} vertices", part.len());
    let from = CLOSE_UP_VIEW;
    let aspect = f64::from(WIDTH) / f64::from(HEIGHT);
    let camera = Camera::fitting(&part, from, DVec3::Z, FOV, aspect, FILL)?;
    let b = mesh.bounds();
    render_mesh(mesh, &edges, &camera, Some((b.min, b.max)), from, MODEL_COLOR, WHITE)
}

/// A render of the point set `points` of figure `number`, each point a small ball of radius
/// `size` times the points' bounding-box diagonal (`surfaces::ball`: round as seen at the size the
/// points are drawn, with its normals from its centre), framed and lit as [`render_models`]
/// frames a model, with no floor (the speckled shadow of thousands of balls says nothing and
/// triples the file) but on the floor's colour ([`floor_shade`]).
pub(crate) fn render_points(number: (u32, u32), points: &[DVec3], size: f64) -> Result<Vec<u8>> {
    ensure!(!points.is_empty(), "no points to draw");
    let (lo, hi) = points
        .iter()
        .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let r = size * (hi - lo).length();
    let (unit, faces) = super::surfaces::ball();
    let mut positions = Vec::with_capacity(unit.len() * points.len());
    let mut normals = Vec::with_capacity(unit.len() * points.len());
    let mut triangles = Vec::with_capacity(faces.len() * points.len());
    for (k, p) in points.iter().enumerate() {
        let base = u32::try_from(unit.len() * k)?;
        positions.extend(unit.iter().map(|a| *p + *a * r));
        normals.extend(unit.iter().copied());
        triangles.extend(faces.iter().map(|f| f.map(|i| base + i)));
    }
    let uvs = vec![DVec2::ZERO; positions.len()];
    let mesh = TriangleMesh::try_new(positions, normals, uvs, triangles)?;
    let from = view(number);
    let aspect = f64::from(WIDTH) / f64::from(HEIGHT);
    let camera = Camera::fitting(points, from, DVec3::Z, FOV, aspect, FILL)?;
    render_mesh(mesh, &[], &camera, None, from, POINT_COLOR, floor_shade(from)?)
}

/// The colour of data points (linear RGB): a blue, as the point sets of the plots.
const POINT_COLOR: [f32; 3] = [0.12, 0.25, 0.62];

/// The JPEG quality of the renders embedded in the curvature pictures' SVGs.
const JPEG_QUALITY: u8 = 92;

/// The render `webp` (lossless) as a JPEG of quality [`JPEG_QUALITY`]: a fifth of the size
/// on the curvature maps' smooth colours, which a colour-bar SVG carries in base64.
pub(crate) fn to_jpeg(webp: &[u8]) -> Result<Vec<u8>> {
    let image = image::load_from_memory(webp)?.to_rgb8();
    let mut bytes = Vec::new();
    image::codecs::jpeg::JpegEncoder::new_with_quality(&mut bytes, JPEG_QUALITY)
        .encode_image(&image)?;
    Ok(bytes)
}

/// The render of one model `glb` of figure `number`, as [`render_models`] makes it.
pub(crate) fn render_model(number: (u32, u32), glb: &[u8]) -> Result<Vec<u8>> {
    render_models(number, &[glb])?.pop().context("no render")
}

/// A square floor under the box (`lo`, `hi`): just below its lowest point, matt and light,
/// and 80 times its size, so that its far edge is above the frame (every view looks down at
/// the model by more than half the field of view).
fn floor(lo: DVec3, hi: DVec3) -> Result<SceneObject> {
    let size = (hi - lo).length().max(1e-9);
    let (c, s) = (0.5 * (lo + hi), 40.0 * size);
    let z = lo.z - 0.02 * size;
    let corners =
        [(-s, -s), (s, -s), (s, s), (-s, s)].map(|(x, y)| DVec3::new(c.x + x, c.y + y, z));
    let mesh = TriangleMesh::try_new(
        corners.to_vec(),
        vec![DVec3::Z; 4],
        vec![DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y],
        vec![[0, 1, 2], [0, 2, 3]],
    )?;
    let mut floor = SceneObject::new(Geometry::Mesh(MeshObject::new(mesh)));
    floor.material.color = FLOOR_COLOR;
    floor.material.specular = 0.0;
    Ok(floor)
}

/// Figure 5.25: the harmonic torus tessellated (128×256 quads) and rendered as triangles.
fn scanline_torus() -> Result<Vec<u8>> {
    let (scene, camera) = torus_scene(TorusMethod::Mesh)?;
    webp(&scene, &camera)
}

/// Figure 5.26: the harmonic torus and a harmonic sphere ray traced directly (interval Newton,
/// Krawczyk, with bisection where it cannot decide), on a floor, with shadows.
fn raytraced_torus() -> Result<Vec<u8>> {
    let settings =
        HarmonicOptions { method: IntervalMethod::Krawczyk, ..HarmonicOptions::default() };
    let harmonic =
        |surface: HarmonicSurface<DVec3>, shift: DVec3, color: [f32; 3]| -> Result<SceneObject> {
            let moved = HarmonicSurface::try_from_flat(
                surface.m(),
                surface.n(),
                surface.points().iter().map(|p| *p + shift).collect(),
            )?;
            let mut object = SceneObject::new(Geometry::Harmonic(
                HarmonicObject::try_new(moved, &settings)?
                    .with_color(SurfaceColor::Uniform(color))?,
            ));
            object.material.color = color;
            object.material.specular = 0.35;
            Ok(object)
        };
    let torus = harmonic(torus(2.0, 1.0), DVec3::ZERO, [0.55, 0.62, 0.85])?;
    let ball = harmonic(sphere(1.0), DVec3::new(2.6, 2.4, 0.0), [0.85, 0.45, 0.35])?;
    // The floor: a square at z = −1, two triangles.
    let s = 7.0;
    let floor = TriangleMesh::try_new(
        vec![
            DVec3::new(-s, -s, -1.0),
            DVec3::new(s, -s, -1.0),
            DVec3::new(s, s, -1.0),
            DVec3::new(-s, s, -1.0),
        ],
        vec![DVec3::Z; 4],
        vec![DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y],
        vec![[0, 1, 2], [0, 2, 3]],
    )?;
    let mut floor = SceneObject::new(Geometry::Mesh(MeshObject::new(floor)));
    floor.material.color = [0.8, 0.8, 0.76];
    floor.material.specular = 0.0;
    let lights = vec![
        Light::Directional { direction: DVec3::new(-1.0, -2.0, 3.0), intensity: [0.8, 0.8, 0.75] },
        Light::Point { position: DVec3::new(5.0, -4.0, 6.0), intensity: [30.0, 28.0, 26.0] },
    ];
    let scene = Scene::try_new(vec![torus, ball, floor], lights, [0.05, 0.06, 0.08])?;
    let camera = Camera::try_new(
        DVec3::new(1.5, -9.0, 5.0),
        DVec3::new(0.6, 0.6, -0.3),
        DVec3::Z,
        PI / 5.0,
    )?;
    webp(&scene, &camera)
}

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (5, 25),
        caption: "A scanline-rendered harmonic surface (torus)",
        drawn: "The harmonic torus through the 4×4 torus grid (R = 2, r = 1), tessellated into 128×256 quads with \
                its exact normals and rendered as triangles (`hi_raytrace::MeshObject` in an obvhs BVH, the \
                renderer's stand-in for the thesis's scanline rendering), 1200×900, 16 samples per pixel, a \
                directional and a point light with shadows. `cargo xtask bench render` times it beside the direct \
                methods.",
        data: "the exact 4×4 torus grid of docs/math.md §3 (`hi_surface::torus(2, 1)`).",
        format: Format::Webp,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |_| scanline_torus() }],
    },
    Figure {
        number: (5, 26),
        caption: "A raytraced harmonic surface (torus)",
        drawn: "The harmonic torus and the harmonic sphere (each through its exact grid) ray traced directly: every \
                camera and shadow ray is intersected with the surfaces themselves by interval Newton (Krawczyk) \
                on p(u, v) − (o + t·d) = 0 in `hi-interval` arithmetic, with bisection where Krawczyk cannot \
                decide, over a floor of two triangles; 1200×900, 16 samples per pixel, shadows from a directional \
                and a point light. The thesis took several hours for its torus; this takes seconds.",
        data: "exact: `hi_surface::torus(2, 1)` and `hi_surface::sphere(1)` moved to (2.6, 2.4, 0).",
        format: Format::Webp,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |_| raytraced_torus() }],
    },
];
