// SPDX-License-Identifier: MIT
//! `hi render`: ray tracing of harmonic surfaces, Bézier patches and meshes to a PNG image
//! (Hardy 2005, §5.5, §5.6).

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use glam::DVec3;
use hi_bezier::BezierPatch;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_mesh::{TriangleMesh, srgb_to_linear_rgb};
use hi_raytrace::{
    BezierObject, BezierOptions, Camera, Geometry, HarmonicObject, HarmonicOptions, IntervalMethod,
    Light, MeshObject, RayCounts, RenderOptions, Scene, SceneObject, SurfaceColor, render,
};
use hi_surface::{CurvatureColoring, CurvatureQuantity, HarmonicSurface, MeshOptions};
use indicatif::{ProgressBar, ProgressStyle};
use serde::Serialize;
use serde_json::Value;

use crate::cli::{ColorBy, PaletteName, RenderArgs, RenderMethod};
use crate::error::Failure;
use crate::input::parse_grid;
use crate::output::{Json, check_writable, file_names, json};

/// Default image size and samples per pixel.
const DEFAULT_SIZE: usize = 512;
const DEFAULT_SPP: usize = 4;

/// Default vertical field of view, degrees.
const DEFAULT_FOV: f64 = 40.0;

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
        (None, Some(scene)) => read_scene(scene)?,
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
struct Loaded {
    scene: Scene,
    camera: Camera,
    /// Width, height and samples per pixel from the scene file.
    size: (Option<usize>, Option<usize>, Option<usize>),
}

/// The default lights: a key light above and to the left, a weaker fill from the right.
fn default_lights(view: DVec3) -> Vec<Light> {
    let side = view.cross(DVec3::Z).try_normalize().unwrap_or(DVec3::X);
    vec![
        Light::Directional { direction: -view + DVec3::Z * 1.5 - side, intensity: [0.85; 3] },
        Light::Directional { direction: -view + side, intensity: [0.3; 3] },
    ]
}

/// The default direction from the centre of a scene to the eye.
const DEFAULT_VIEW: DVec3 = DVec3::new(0.9, -2.0, 1.3);

/// A camera framing everything in `scene`.
fn frame(scene: &Scene, from: DVec3, up: DVec3, fov: f64) -> Result<Camera, Failure> {
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
    let scene = Scene::try_new(vec![object], default_lights(-DEFAULT_VIEW), [0.04, 0.05, 0.07])
        .map_err(|e| Failure::input(format!("{name}: {e}")))?;
    let camera = frame(&scene, DEFAULT_VIEW, DVec3::Z, DEFAULT_FOV.to_radians())?;
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
            let value: Value = serde_json::from_str(&text).map_err(|e| format!("not JSON: {e}"))?;
            if value.get("patches").is_some() {
                Ok(FileKind::Patches(parse_patches(&value)?))
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

/// The patches of a `hi surface bezier` JSON file.
fn parse_patches(value: &Value) -> Result<Vec<BezierPatch<DVec3>>, String> {
    let patches = value["patches"].as_array().ok_or("\"patches\" is not an array")?;
    patches
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let rows = p["control"]
                .as_array()
                .ok_or(format!("patch {i}: \"control\" is not an array of rows"))?
                .iter()
                .map(|row| {
                    row.as_array()
                        .ok_or(format!("patch {i}: a control row is not an array"))?
                        .iter()
                        .map(|pt| vec3(pt).map_err(|e| format!("patch {i}: {e}")))
                        .collect::<Result<Vec<DVec3>, String>>()
                })
                .collect::<Result<Vec<_>, String>>()?;
            BezierPatch::try_new(rows).map_err(|e| format!("patch {i}: {e}"))
        })
        .collect()
}

/// A point `[x, y, z]` of finite numbers.
fn vec3(v: &Value) -> Result<DVec3, String> {
    let a = v.as_array().filter(|a| a.len() == 3).ok_or(format!("{v} is not a point [x, y, z]"))?;
    let c: Vec<f64> = a.iter().filter_map(Value::as_f64).filter(|x| x.is_finite()).collect();
    if c.len() == 3 {
        Ok(DVec3::new(c[0], c[1], c[2]))
    } else {
        Err(format!("{v} is not a finite point"))
    }
}

/// A colour `[r, g, b]` in [0, 1], sRGB, made linear.
fn color(v: &Value) -> Result<[f32; 3], String> {
    let c = vec3(v)?;
    if c.min_element() < 0.0 || c.max_element() > 1.0 {
        return Err(format!("colour {v}: components must be in [0, 1]"));
    }
    Ok(srgb_to_linear_rgb(c.as_vec3().to_array()))
}

/// An intensity: a number or `[r, g, b]`, finite and non-negative.
fn intensity(v: &Value) -> Result<[f32; 3], String> {
    let c = match v.as_f64() {
        Some(x) => DVec3::splat(x),
        None => vec3(v)?,
    };
    if !c.is_finite() || c.min_element() < 0.0 {
        return Err(format!("intensity {v}: expected a non-negative number or [r, g, b]"));
    }
    Ok(c.as_vec3().to_array())
}

/// The curvature quantity of `--curvature` or `"curvature"`.
fn quantity(c: ColorBy) -> CurvatureQuantity {
    match c {
        ColorBy::Gaussian => CurvatureQuantity::Gaussian,
        ColorBy::Mean => CurvatureQuantity::Mean,
    }
}

/// The object in `file`: a grid drawn by `method`, patches, or a mesh.
fn load_object(
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
        RenderMethod::Interval | RenderMethod::Bisection => {
            let settings = HarmonicOptions {
                method: if method == RenderMethod::Interval {
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

/// Reads a scene file.
fn read_scene(path: &Path) -> Result<Loaded, Failure> {
    let name = path.display().to_string();
    let at = |what: &str| {
        let name = name.clone();
        let what = what.to_owned();
        move |e: String| Failure::input(format!("{name}: {what}{e}"))
    };
    let text = std::fs::read_to_string(path).map_err(|e| at("")(format!("cannot read: {e}")))?;
    let value: Value = serde_json::from_str(&text).map_err(|e| at("")(format!("not JSON: {e}")))?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let objects_json =
        value["objects"].as_array().ok_or_else(|| at("")("\"objects\" must be an array".into()))?;
    let mut objects = Vec::new();
    for (i, o) in objects_json.iter().enumerate() {
        let ctx = at(&format!("objects[{i}]: "));
        let kind = o["type"]
            .as_str()
            .ok_or_else(|| ctx("\"type\" must be harmonic, mesh or bezier".into()))?;
        if !matches!(kind, "harmonic" | "mesh" | "bezier") {
            return Err(ctx(format!("unknown type '{kind}': expected harmonic, mesh or bezier")));
        }
        let file = o["file"].as_str().ok_or_else(|| ctx("\"file\" is missing".into()))?;
        let file_path: PathBuf = dir.join(file);
        let method = match o["method"].as_str().unwrap_or("interval") {
            "interval" => RenderMethod::Interval,
            "bisection" => RenderMethod::Bisection,
            "bezier" => RenderMethod::Bezier,
            "mesh" => RenderMethod::Mesh,
            other => {
                return Err(ctx(format!(
                    "unknown method '{other}': expected interval, bisection, bezier or mesh"
                )));
            }
        };
        let palette = match o["palette"].as_str() {
            None | Some("thesis") => PaletteName::Thesis,
            Some("viridis") => PaletteName::Viridis,
            Some("coolwarm") => PaletteName::Coolwarm,
            Some(other) => {
                return Err(ctx(format!(
                    "unknown palette '{other}': expected thesis, viridis or coolwarm"
                )));
            }
        };
        let curvature = match o["curvature"].as_str() {
            None => None,
            Some("gaussian") => Some((ColorBy::Gaussian, palette)),
            Some("mean") => Some((ColorBy::Mean, palette)),
            Some(other) => {
                return Err(ctx(format!("unknown curvature '{other}': expected gaussian or mean")));
            }
        };
        let mut geometry = load_object(&file_path, Some(kind), method, curvature)
            .map_err(|e| ctx(format!("{file}: {e}")))?;
        let mut object_color = None;
        if !o["color"].is_null() {
            let c = color(&o["color"]).map_err(&ctx)?;
            object_color = Some(c);
            geometry = match geometry {
                Geometry::Bezier(b) => Geometry::Bezier(b.with_uniform_color(c)),
                Geometry::Harmonic(h) if curvature.is_none() => Geometry::Harmonic(
                    h.with_color(SurfaceColor::Uniform(c)).map_err(|e| ctx(e.to_string()))?,
                ),
                g => g,
            };
        }
        let mut object = SceneObject::new(geometry);
        if let Some(c) = object_color {
            object.material.color = c;
        }
        if let Some(s) = o["specular"].as_f64() {
            if !(0.0..=1.0).contains(&s) {
                return Err(ctx(format!("specular {s}: expected 0 to 1")));
            }
            object.material.specular = s as f32;
        }
        objects.push(object);
    }
    let mut lights = Vec::new();
    if let Some(list) = value["lights"].as_array() {
        for (i, l) in list.iter().enumerate() {
            let ctx = at(&format!("lights[{i}]: "));
            let power = if l["intensity"].is_null() {
                [1.0; 3]
            } else {
                intensity(&l["intensity"]).map_err(&ctx)?
            };
            lights.push(match l["type"].as_str() {
                Some("directional") => Light::Directional {
                    direction: vec3(&l["direction"]).map_err(&ctx)?,
                    intensity: power,
                },
                Some("point") => {
                    Light::Point { position: vec3(&l["position"]).map_err(&ctx)?, intensity: power }
                }
                _ => return Err(ctx("\"type\" must be directional or point".into())),
            });
        }
    }
    let camera_json = &value["camera"];
    let (view, up, fov) = if camera_json.is_null() {
        (DEFAULT_VIEW, DVec3::Z, DEFAULT_FOV)
    } else {
        let ctx = at("camera: ");
        let eye = vec3(&camera_json["eye"]).map_err(&ctx)?;
        let target = vec3(&camera_json["target"]).map_err(&ctx)?;
        let up = if camera_json["up"].is_null() {
            DVec3::Z
        } else {
            vec3(&camera_json["up"]).map_err(&ctx)?
        };
        let fov = if camera_json["fov"].is_null() {
            DEFAULT_FOV
        } else {
            camera_json["fov"]
                .as_f64()
                .ok_or_else(|| ctx("\"fov\" must be a number of degrees".into()))?
        };
        (eye - target, up, fov)
    };
    if lights.is_empty() && value["lights"].is_null() {
        lights = default_lights(-view);
    }
    let background = if value["background"].is_null() {
        [0.04, 0.05, 0.07]
    } else {
        color(&value["background"]).map_err(at("background: "))?
    };
    let mut scene =
        Scene::try_new(objects, lights, background).map_err(|e| at("")(e.to_string()))?;
    if !value["ambient"].is_null() {
        let ambient = color(&value["ambient"]).map_err(at("ambient: "))?;
        scene = scene.with_ambient(ambient).map_err(|e| at("ambient: ")(e.to_string()))?;
    }
    let camera = if camera_json.is_null() {
        frame(&scene, view, up, fov.to_radians())?
    } else {
        let target = vec3(&camera_json["target"]).map_err(at("camera: "))?;
        Camera::try_new(target + view, target, up, fov.to_radians())
            .map_err(|e| at("camera: ")(e.to_string()))?
    };
    let image = &value["image"];
    let count = |key: &str| -> Result<Option<usize>, Failure> {
        match &image[key] {
            Value::Null => Ok(None),
            v => v
                .as_u64()
                .map(|x| Some(x as usize))
                .ok_or_else(|| at("image: ")(format!("\"{key}\" must be a whole number"))),
        }
    };
    Ok(Loaded { scene, camera, size: (count("width")?, count("height")?, count("spp")?) })
}
