// SPDX-License-Identifier: MIT
//! `hi render`: ray tracing of harmonic surfaces, Bézier patches and meshes to a PNG image
//! (Hardy 2005, §5.5, §5.6).

use std::io::IsTerminal;
use std::path::Path;

use glam::DVec3;
use hi_bezier::BezierPatch;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_mesh::TriangleMesh;
use hi_raytrace::{
    BezierObject, BezierOptions, Camera, DEFAULT_BACKGROUND, DEFAULT_VIEW, Geometry,
    HarmonicObject, HarmonicOptions, IntervalMethod, Light, MeshObject, RayCounts, RenderOptions,
    Scene, SceneObject, SurfaceColor, render,
};
use hi_surface::{CurvatureColoring, CurvatureQuantity, HarmonicSurface, MeshOptions};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use serde_json::Value;

use crate::cli::{ColorBy, PaletteName, RenderArgs, RenderMethod};
use crate::error::Failure;
use crate::input::{parse_grid, parse_patches};
use crate::output::{Json, check_writable, file_names, json};

/// Default image size and samples per pixel.
const DEFAULT_SIZE: usize = 512;
const DEFAULT_SPP: usize = 4;

/// Renders the scene (or the `--quick` file) and returns `{"files": [...], ...}`.
///
/// # Errors
///
/// [`Failure::Input`] for an unreadable or malformed scene or object file, a degenerate camera,
/// a bad image size, or an output file that cannot be written.
pub(crate) fn run(args: &RenderArgs) -> Result<Json, Failure> {
    let ext = args.output.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    if ext.as_deref() != Some("png") {
        return Err(Failure::input(format!("-o {}: expected a .png file", args.output.display())));
    }
    check_writable(&args.output, "-o")?;
    let loaded = match (&args.quick, &args.scene) {
        (Some(file), _) => {
            quick_scene(file, args.method, args.curvature.map(|c| (c, args.palette)))?
        }
        (None, Some(scene)) => super::scene_file::read_scene(scene)?,
        (None, None) => return Err(Failure::input("give a SCENE file or --quick FILE")),
    };
    let pick = |flag: Option<usize>, scene: Option<usize>, default: usize, what: &str| {
        let value = flag.or(scene).unwrap_or(default);
        u32::try_from(value).map_err(|_| Failure::input(format!("{what} {value}: too large")))
    };
    let settings = RenderOptions {
        width: pick(args.width, loaded.size.0, DEFAULT_SIZE, "--width")?,
        height: pick(args.height, loaded.size.1, DEFAULT_SIZE, "--height")?,
        samples_per_pixel: pick(args.spp, loaded.size.2, DEFAULT_SPP, "--spp")?,
        ..RenderOptions::default()
    };
    let bar = if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(0);
        if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} tiles {elapsed}") {
            bar.set_style(style);
        }
        bar
    } else {
        ProgressBar::hidden()
    };
    let report = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let result = render(&loaded.scene, &loaded.camera, &settings, Some(&report));
    bar.finish_and_clear();
    let out = result.map_err(|e| Failure::input(format!("hi render: {e}")))?;
    let fail = |e: String| Failure::input(format!("{}: cannot write: {e}", args.output.display()));
    let file = std::fs::File::create(&args.output).map_err(|e| fail(e.to_string()))?;
    out.write_png(std::io::BufWriter::new(file)).map_err(|e| fail(e.to_string()))?;
    /// `{"files", "width", "height", "spp", "rays", "seconds"}`.
    #[derive(Serialize)]
    struct Written<'a> {
        files: Vec<String>,
        width: u32,
        height: u32,
        spp: u32,
        rays: &'a RayCounts,
        seconds: f64,
    }
    json(&Written {
        files: file_names(std::slice::from_ref(&args.output)),
        width: settings.width,
        height: settings.height,
        spp: settings.samples_per_pixel,
        rays: &out.counts,
        seconds: out.elapsed.as_secs_f64(),
    })
}

/// A scene ready to render, with the image size it asks for.
pub(super) struct Loaded {
    pub(super) scene: Scene,
    pub(super) camera: Camera,
    /// Width, height and samples per pixel from the scene file.
    pub(super) size: (Option<usize>, Option<usize>, Option<usize>),
}

/// A camera framing everything in `scene`.
pub(super) fn frame(scene: &Scene, from: DVec3, up: DVec3, fov: f64) -> Result<Camera, Failure> {
    let hi_bezier::Aabb { min: lo, max: hi } = scene.bounds();
    let radius = 0.5 * (hi - lo).length();
    Camera::framing(0.5 * (lo + hi), radius.max(1e-9), from, up, fov)
        .map_err(|e| Failure::input(format!("camera: {e}")))
}

/// `hi render --quick FILE`: one object, framed, default lights.
fn quick_scene(
    file: &Path,
    method: RenderMethod,
    curvature: Option<(ColorBy, PaletteName)>,
) -> Result<Loaded, Failure> {
    let name = file.display().to_string();
    let geometry = load_object(file, None, method, curvature)
        .map_err(|e| Failure::input(format!("{name}: {e}")))?;
    let object = SceneObject::new(geometry);
    let scene =
        Scene::try_new(vec![object], Light::key_and_fill(-DEFAULT_VIEW), DEFAULT_BACKGROUND)
            .map_err(|e| Failure::input(format!("{name}: {e}")))?;
    let camera =
        frame(&scene, DEFAULT_VIEW, DVec3::Z, hi_raytrace::DEFAULT_FOV_DEGREES.to_radians())?;
    Ok(Loaded { scene, camera, size: (None, None, None) })
}

/// What kind of object a file holds, from its extension and (for JSON) its contents.
enum FileKind {
    Grid(HarmonicSurface<DVec3>),
    Patches(Vec<BezierPatch<DVec3>>),
    Mesh,
}

fn file_kind(path: &Path) -> Result<FileKind, String> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("obj" | "gltf" | "glb") => Ok(FileKind::Mesh),
        Some("json") => {
            let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read: {e}"))?;
            let value: Value =
                serde_json::from_str(&text).map_err(|e| format!("invalid JSON: {e}"))?;
            if value.get("patches").is_some() {
                Ok(FileKind::Patches(parse_patches(value)?))
            } else {
                let grid = parse_grid(&text)?;
                HarmonicSurface::try_new(grid).map(FileKind::Grid).map_err(|e| e.to_string())
            }
        }
        _ => {
            Err("unknown extension, expected .json (a grid or patches), .obj, .gltf or .glb".into())
        }
    }
}

/// The curvature quantity of `--curvature` or `"curvature"`.
fn quantity(c: ColorBy) -> CurvatureQuantity {
    match c {
        ColorBy::Gaussian => CurvatureQuantity::Gaussian,
        ColorBy::Mean => CurvatureQuantity::Mean,
    }
}

/// The object in `file`: a grid drawn by `method`, patches, or a mesh.
pub(super) fn load_object(
    file: &Path,
    want: Option<&str>,
    method: RenderMethod,
    curvature: Option<(ColorBy, PaletteName)>,
) -> Result<Geometry, String> {
    let kind = file_kind(file)?;
    let mismatch = |found: &str| match want {
        Some(w) if w != found => Err(format!("the file holds a {found}, not a {w}")),
        _ => Ok(()),
    };
    match kind {
        FileKind::Mesh => {
            mismatch("mesh")?;
            Ok(Geometry::Mesh(MeshObject::new(read_mesh(file)?)))
        }
        FileKind::Patches(patches) => {
            mismatch("bezier")?;
            let object = BezierObject::try_new(patches, &BezierOptions::default())
                .map_err(|e| e.to_string())?;
            Ok(Geometry::Bezier(object))
        }
        FileKind::Grid(surface) => {
            mismatch("harmonic")?;
            harmonic_geometry(surface, method, curvature).map_err(|e| e.to_string())
        }
    }
}

/// A harmonic surface drawn by `method`.
fn harmonic_geometry(
    surface: HarmonicSurface<DVec3>,
    method: RenderMethod,
    curvature: Option<(ColorBy, PaletteName)>,
) -> Result<Geometry, Box<dyn std::error::Error>> {
    let coloring = curvature.map(|(c, p)| (quantity(c), p.color_map()));
    Ok(match method {
        RenderMethod::Krawczyk | RenderMethod::Bisection => {
            let settings = HarmonicOptions {
                method: if method == RenderMethod::Krawczyk {
                    IntervalMethod::Krawczyk
                } else {
                    IntervalMethod::Bisection
                },
                ..HarmonicOptions::default()
            };
            let mut object = HarmonicObject::try_new(surface, &settings)?;
            if let Some((quantity, map)) = coloring {
                object = object.with_color(SurfaceColor::Curvature { quantity, map })?;
            }
            Geometry::Harmonic(object)
        }
        RenderMethod::Bezier => {
            let patches = surface.to_bezier(
                BezierScheme::Hermite(HermiteDegree::Cubic),
                hi_curve::bezier::DEFAULT_TOLERANCE,
            )?;
            Geometry::Bezier(BezierObject::try_from_surface(&patches, &BezierOptions::default())?)
        }
        RenderMethod::Mesh => {
            let color = coloring.map(|(quantity, map)| CurvatureColoring { quantity, map });
            let options = MeshOptions { n_u: 256, n_v: 256, color, ..MeshOptions::default() };
            Geometry::Mesh(MeshObject::new(surface.to_mesh(&options)?))
        }
    })
}

/// A triangle mesh from an OBJ or glTF file (`hi_mesh::export::load`: as `hi surface mesh`
/// writes them, or an OBJ of bare positions and faces with normals from its faces).
fn read_mesh(path: &Path) -> Result<TriangleMesh, String> {
    hi_mesh::export::load(path).map_err(|e| {
        // The caller names the file: the message without the path it may start with.
        let message = e.to_string();
        let named = format!("{}: ", path.display());
        message.strip_prefix(&named).map_or(message.clone(), str::to_owned)
    })
}
