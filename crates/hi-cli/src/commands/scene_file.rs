// SPDX-License-Identifier: MIT
//! The scene file of `hi render` (Hardy 2005, §5.6): the camera, lights and materials are the
//! `serde` forms of `hi-raytrace`'s own types (degrees, sRGB colours, linear intensities);
//! only what is the command's own — the object files, how a grid is drawn, its curvature
//! colouring, the image size, the background and ambient light of the scene — is declared
//! here. Its JSON schema is `docs/schemas/scene.schema.json`.

use std::path::{Path, PathBuf};

use glam::DVec3;
use hi_raytrace::{
    Camera, DEFAULT_BACKGROUND, DEFAULT_VIEW, Geometry, Light, Material, Scene, SceneObject,
    SurfaceColor,
};
use schemars::JsonSchema;
use serde::Deserialize;
use serde_json::Value;

use super::render::{Loaded, frame, load_object};
use crate::cli::{ColorBy, PaletteName, RenderMethod};
use crate::error::Failure;

/// `hi render`'s scene file. File names are relative to the scene file.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub(crate) struct SceneFile {
    /// The camera (`hi_raytrace::Camera`): `{"eye", "target", "up", "fov"}`, the field of view
    /// in degrees (default 40), `up` by default [0, 0, 1]. Without it the scene is framed from
    /// the front, above and to the side.
    #[serde(default)]
    camera: Option<Camera>,
    /// The image size and samples per pixel (the command line's flags win).
    #[serde(default)]
    image: ImageSize,
    /// The background colour, sRGB [r, g, b] in [0, 1] (default a dark blue-grey).
    #[serde(default)]
    #[schemars(with = "Option<hi_raytrace::srgb::Schema>")]
    background: Option<Srgb>,
    /// The ambient light, sRGB [r, g, b] in [0, 1] (default 0.31, linear 0.08).
    #[serde(default)]
    #[schemars(with = "Option<hi_raytrace::srgb::Schema>")]
    ambient: Option<Srgb>,
    /// The lights (`hi_raytrace::Light`); without the key, a key light and a fill light placed
    /// about the view direction; `[]` for none.
    #[serde(default)]
    lights: Option<Vec<Light>>,
    /// The objects (at least one).
    objects: Vec<ObjectSpec>,
}

/// The image size of a scene file.
#[derive(Debug, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
struct ImageSize {
    /// Width in pixels (default 512).
    width: Option<u32>,
    /// Height in pixels (default 512).
    height: Option<u32>,
    /// Samples per pixel (default 4).
    spp: Option<u32>,
}

/// A colour given as sRGB [r, g, b] in [0, 1], held linear.
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(transparent)]
struct Srgb(#[serde(with = "hi_raytrace::srgb")] [f32; 3]);

/// What an object file holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
enum ObjectKind {
    /// A grid file (as `hi surface example` writes), a harmonic surface.
    Harmonic,
    /// A triangle mesh: .obj, .gltf or .glb.
    Mesh,
    /// The patches file of `hi surface bezier -o patches.json`.
    Bezier,
}

impl ObjectKind {
    fn name(self) -> &'static str {
        match self {
            ObjectKind::Harmonic => "harmonic",
            ObjectKind::Mesh => "mesh",
            ObjectKind::Bezier => "bezier",
        }
    }
}

/// An object of a scene file.
#[derive(Debug, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
struct ObjectSpec {
    /// What the file holds.
    #[serde(rename = "type")]
    kind: ObjectKind,
    /// The file, relative to the scene file.
    file: PathBuf,
    /// How a harmonic grid is drawn (default krawczyk).
    #[serde(default = "default_method")]
    method: RenderMethod,
    /// Colour a harmonic grid by this curvature.
    #[serde(default)]
    curvature: Option<ColorBy>,
    /// The colours of the curvature (default thesis).
    #[serde(default)]
    palette: PaletteName,
    /// The material (`hi_raytrace::Material`); its colour, when given, is also that of a Bézier
    /// or (uncoloured) harmonic object.
    #[serde(default)]
    material: Option<Material>,
}

fn default_method() -> RenderMethod {
    RenderMethod::Krawczyk
}

/// Reads the scene file at `path`: one line naming the file, the field's path and the problem
/// if it is bad (`scene.json: objects[1].material.color: …`).
pub(super) fn read_scene(path: &Path) -> Result<Loaded, Failure> {
    let name = path.display().to_string();
    let fail = |what: &str, e: &dyn std::fmt::Display| {
        Failure::input(if what.is_empty() || what == "." {
            format!("{name}: {e}")
        } else {
            format!("{name}: {what}: {e}")
        })
    };
    let text = std::fs::read_to_string(path).map_err(|e| fail("", &format!("cannot read: {e}")))?;
    let value: Value =
        serde_json::from_str(&text).map_err(|e| fail("", &format!("invalid JSON: {e}")))?;
    let file: SceneFile = serde_path_to_error::deserialize(&value)
        .map_err(|e| fail(&e.path().to_string(), e.inner()))?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut objects = Vec::with_capacity(file.objects.len());
    for (i, spec) in file.objects.iter().enumerate() {
        let colored = value["objects"][i]["material"].get("color").is_some();
        let object =
            scene_object(&dir, spec, colored).map_err(|e| fail(&format!("objects[{i}]"), &e))?;
        objects.push(object);
    }
    let view = file.camera.map_or(DEFAULT_VIEW, |c| -c.forward() * DEFAULT_VIEW.length());
    let lights = file.lights.unwrap_or_else(|| Light::key_and_fill(-view));
    let background = file.background.map_or(DEFAULT_BACKGROUND, |c| c.0);
    let mut scene = Scene::try_new(objects, lights, background).map_err(|e| fail("", &e))?;
    if let Some(Srgb(ambient)) = file.ambient {
        scene = scene.with_ambient(ambient).map_err(|e| fail("ambient", &e))?;
    }
    let camera = match file.camera {
        Some(camera) => camera,
        None => frame(&scene, view, DVec3::Z, hi_raytrace::DEFAULT_FOV_DEGREES.to_radians())?,
    };
    let count = |n: Option<u32>| n.map(|n| n as usize);
    let ImageSize { width, height, spp } = file.image;
    Ok(Loaded { scene, camera, size: (count(width), count(height), count(spp)) })
}

/// The object of `spec`, its file relative to `dir`; `colored`: the material gives a colour.
fn scene_object(dir: &Path, spec: &ObjectSpec, colored: bool) -> Result<SceneObject, String> {
    let curvature = spec.curvature.map(|c| (c, spec.palette));
    let file = dir.join(&spec.file);
    let mut geometry = load_object(&file, Some(spec.kind.name()), spec.method, curvature)
        .map_err(|e| format!("{}: {e}", spec.file.display()))?;
    let material = spec.material.unwrap_or_default();
    if colored {
        let c = material.color;
        geometry = match geometry {
            Geometry::Bezier(b) => Geometry::Bezier(b.with_uniform_color(c)),
            Geometry::Harmonic(h) if curvature.is_none() => Geometry::Harmonic(
                h.with_color(SurfaceColor::Uniform(c)).map_err(|e| e.to_string())?,
            ),
            g => g,
        };
    }
    Ok(SceneObject { geometry, material })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The library's serde forms are the file's: a camera, lights and a material written by
    /// `hi-raytrace` make a scene file that reads back to the same values.
    #[test]
    fn the_library_forms_are_the_file_form() {
        let camera =
            Camera::try_new(DVec3::new(0.0, -14.0, 9.0), DVec3::ZERO, DVec3::Z, 0.75).unwrap();
        let lights = vec![
            Light::Directional { direction: DVec3::new(1.0, -1.0, 2.0), intensity: [0.9; 3] },
            Light::Point { position: DVec3::new(4.0, -4.0, 6.0), intensity: [20.0, 18.0, 16.0] },
            Light::Fill { direction: DVec3::new(-1.0, -0.5, 0.5), intensity: [0.3; 3] },
        ];
        let material = Material { color: [0.5, 0.25, 0.125], ..Material::default() };
        let text = serde_json::json!({
            "camera": camera,
            "lights": lights,
            "objects": [{"type": "mesh", "file": "a.obj", "material": material}],
        })
        .to_string();
        let file: SceneFile = serde_json::from_str(&text).unwrap();
        let back = file.camera.unwrap();
        assert!((back.eye() - camera.eye()).length() < 1e-12, "eye");
        assert!((back.forward() - camera.forward()).length() < 1e-12, "forward");
        assert!((back.up() - camera.up()).length() < 1e-12, "up");
        assert!((back.fov_y() - 0.75).abs() < 1e-14, "fov");
        assert_eq!(file.lights.unwrap(), lights);
        let m = file.objects[0].material.unwrap();
        for (a, b) in m.color.iter().zip(material.color) {
            assert!((a - b).abs() < 1e-6, "{a} {b}");
        }
        assert_eq!((m.diffuse, m.specular, m.shininess), (0.85, 0.25, 40.0), "weights");
        assert_eq!(file.objects[0].method, RenderMethod::Krawczyk, "the default method");
    }

    /// A hand-written file in degrees and sRGB, and a bad field named by its path.
    #[test]
    fn hand_written_files_and_bad_fields() {
        let text = r#"{"camera": {"eye": [0, -5, 0], "target": [0, 0, 0], "fov": 60},
            "background": [0.5, 0.5, 0.5], "lights": [{"type": "point", "position": [0, 0, 3]}],
            "objects": [{"type": "harmonic", "file": "g.json", "method": "interval"}]}"#;
        let file: SceneFile = serde_json::from_str(text).unwrap();
        let camera = file.camera.unwrap();
        assert!((camera.fov_y() - std::f64::consts::FRAC_PI_3).abs() < 1e-15, "60° = π/3");
        assert_eq!(camera.up(), DVec3::Z, "up +Z by default");
        // sRGB 0.5 is linear ((0.5 + 0.055)/1.055)^2.4 = 0.21404114.
        assert!((file.background.unwrap().0[0] - 0.214_041_14).abs() < 1e-7, "sRGB");
        assert_eq!(file.objects[0].method, RenderMethod::Krawczyk, "interval: the alias");
        let bad = r#"{"objects": [{"type": "mesh", "file": "a.obj"},
            {"type": "mesh", "file": "b.obj", "material": {"color": [1, 0, -0.5]}}]}"#;
        let err = serde_path_to_error::deserialize::<_, SceneFile>(
            &mut serde_json::Deserializer::from_str(bad),
        )
        .unwrap_err();
        assert_eq!(err.path().to_string(), "objects[1].material.color");
        assert!(err.inner().to_string().contains("must be in [0, 1]"), "{err}");
    }
}
