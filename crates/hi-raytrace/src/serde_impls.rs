// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`), in the units a scene file is written in by hand (the form
//! of `hi render`'s scene file, Hardy 2005, §5.6):
//!
//! * a [`Camera`] is `{"eye", "target", "up", "fov"}`: `target` is a point it looks at
//!   (written as `eye + forward`), `up` may be left out (+Z), `fov` is the vertical field of
//!   view in **degrees** (40 when left out); it is read back through [`Camera::try_new`];
//! * a [`Material`] is `{"color", "diffuse", "specular", "shininess"}`, each optional (the
//!   [`Material::default`] values), its `color` **sRGB** components in [0, 1] (the linear
//!   value held in memory is converted by [`hi_mesh::srgb_to_linear_rgb`] and back by
//!   [`hi_mesh::linear_to_srgb_rgb`]); the weights must be finite and non-negative;
//! * a [`Light`] is `{"type": "directional", "direction", "intensity"}` or
//!   `{"type": "point", "position", "intensity"}`; the intensity is linear, a number (grey) or
//!   `[r, g, b]`, 1 when left out; read back through the checks of [`Scene::try_new`].
//!
//! The feature `schemars` gives the JSON schemas of these forms.

use glam::DVec3;
use serde::de::{Deserialize, Deserializer, Error as _};
use serde::ser::{Serialize, Serializer};
use serde::{Deserialize as DeriveDeserialize, Serialize as DeriveSerialize};

#[cfg(doc)]
use crate::Scene;
use crate::scene::check_light;
use crate::{Camera, Light, Material, scene::check_material};

/// The vertical field of view of a camera whose `fov` is left out, degrees.
pub const DEFAULT_FOV_DEGREES: f64 = 40.0;

fn default_up() -> DVec3 {
    DVec3::Z
}

fn default_fov() -> f64 {
    DEFAULT_FOV_DEGREES
}

/// A camera looking from `eye` at `target`.
#[derive(DeriveSerialize, DeriveDeserialize)]
#[cfg_attr(feature = "schemars", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "schemars", schemars(rename = "Camera"))]
#[serde(deny_unknown_fields)]
struct CameraForm {
    /// The eye point [x, y, z].
    #[cfg_attr(feature = "schemars", schemars(with = "[f64; 3]"))]
    eye: DVec3,
    /// The point looked at [x, y, z] (not the eye).
    #[cfg_attr(feature = "schemars", schemars(with = "[f64; 3]"))]
    target: DVec3,
    /// The direction that is up in the image (not along the view); default [0, 0, 1].
    #[serde(default = "default_up")]
    #[cfg_attr(feature = "schemars", schemars(with = "[f64; 3]"))]
    up: DVec3,
    /// The vertical field of view in degrees, in (0, 180); default 40.
    #[serde(default = "default_fov")]
    #[cfg_attr(feature = "schemars", schemars(range(min = 0.0, max = 180.0)))]
    fov: f64,
}

impl Serialize for Camera {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        CameraForm {
            eye: self.eye(),
            target: self.eye() + self.forward(),
            up: self.up(),
            fov: self.fov_y().to_degrees(),
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Camera {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let f = CameraForm::deserialize(deserializer)?;
        Camera::try_new(f.eye, f.target, f.up, f.fov.to_radians()).map_err(D::Error::custom)
    }
}

/// `serde` of a linear RGB colour as its sRGB components in [0, 1], for `#[serde(with)]`:
/// the form of the colours of a scene file (a material's colour, `hi render`'s background and
/// ambient light). Reading checks that each component is a number in [0, 1] and converts it
/// by [`hi_mesh::srgb_to_linear_rgb`]; writing converts back by
/// [`hi_mesh::linear_to_srgb_rgb`] (so a linear value above 1 is written as 1).
///
/// # Examples
///
/// ```
/// #[derive(serde::Deserialize)]
/// struct Paint {
///     #[serde(with = "hi_raytrace::srgb")]
///     color: [f32; 3],
/// }
/// let paint: Paint = serde_json::from_str(r#"{"color": [0.5, 0, 1]}"#)?;
/// // sRGB 0.5 is linear ((0.5 + 0.055) / 1.055)^2.4 = 0.21404114.
/// assert!((paint.color[0] - 0.214_041_14).abs() < 1e-7);
/// assert_eq!(&paint.color[1..], &[0.0, 1.0]);
/// assert!(serde_json::from_str::<Paint>(r#"{"color": [1.5, 0, 0]}"#).is_err());
/// # Ok::<(), serde_json::Error>(())
/// ```
pub mod srgb {
    use serde::de::{Deserialize, Deserializer, Error as _};
    use serde::ser::{Serialize, Serializer};

    /// Writes the linear colour `linear` as sRGB `[r, g, b]`.
    ///
    /// # Errors
    ///
    /// The serializer's.
    pub fn serialize<S: Serializer>(linear: &[f32; 3], serializer: S) -> Result<S::Ok, S::Error> {
        hi_mesh::linear_to_srgb_rgb(*linear).serialize(serializer)
    }

    /// Reads sRGB `[r, g, b]` in [0, 1] as a linear colour.
    ///
    /// # Errors
    ///
    /// Not three numbers, or a component outside [0, 1].
    pub fn deserialize<'de, D: Deserializer<'de>>(deserializer: D) -> Result<[f32; 3], D::Error> {
        let c = <[f64; 3]>::deserialize(deserializer)?;
        if c.iter().any(|x| !(0.0..=1.0).contains(x)) {
            return Err(D::Error::custom(format!(
                "colour [{}, {}, {}]: sRGB components must be in [0, 1]",
                c[0], c[1], c[2]
            )));
        }
        Ok(hi_mesh::srgb_to_linear_rgb(c.map(|x| x as f32)))
    }

    /// The JSON schema of this form (feature `schemars`): `[r, g, b]`, each in [0, 1]; for
    /// `#[schemars(with = "hi_raytrace::srgb::Schema")]`.
    #[cfg(feature = "schemars")]
    #[derive(Debug, schemars::JsonSchema)]
    #[schemars(rename = "Srgb", description = "An sRGB colour [r, g, b], each in [0, 1].")]
    #[allow(dead_code, reason = "a schema only")]
    pub struct Schema([Component; 3]);

    /// One sRGB component.
    #[cfg(feature = "schemars")]
    #[derive(Debug, schemars::JsonSchema)]
    #[schemars(rename = "SrgbComponent")]
    #[allow(dead_code, reason = "a schema only")]
    struct Component(#[schemars(range(min = 0.0, max = 1.0))] f32);
}

/// How a surface reflects light (Blinn–Phong); every field optional.
#[derive(DeriveSerialize, DeriveDeserialize)]
#[cfg_attr(feature = "schemars", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "schemars", schemars(rename = "Material"))]
#[serde(deny_unknown_fields, default)]
struct MaterialForm {
    /// sRGB colour [r, g, b] in [0, 1] of a mesh without vertex colours (and of a Bézier or
    /// harmonic object when given); default light grey.
    #[serde(with = "srgb")]
    #[cfg_attr(feature = "schemars", schemars(with = "srgb::Schema"))]
    color: [f32; 3],
    /// Weight of the Lambert term (default 0.85).
    #[cfg_attr(feature = "schemars", schemars(range(min = 0.0)))]
    diffuse: f32,
    /// Weight of the specular term (default 0.25).
    #[cfg_attr(feature = "schemars", schemars(range(min = 0.0)))]
    specular: f32,
    /// Blinn–Phong exponent (default 40).
    #[cfg_attr(feature = "schemars", schemars(range(min = 0.0)))]
    shininess: f32,
}

impl Default for MaterialForm {
    fn default() -> Self {
        let Material { color, diffuse, specular, shininess } = Material::default();
        MaterialForm { color, diffuse, specular, shininess }
    }
}

impl Serialize for Material {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let Material { color, diffuse, specular, shininess } = *self;
        MaterialForm { color, diffuse, specular, shininess }.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Material {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let MaterialForm { color, diffuse, specular, shininess } =
            MaterialForm::deserialize(deserializer)?;
        let material = Material { color, diffuse, specular, shininess };
        check_material(&material).map_err(D::Error::custom)?;
        Ok(material)
    }
}

/// A light's intensity: a number (grey) or `[r, g, b]`.
#[derive(DeriveSerialize, DeriveDeserialize)]
#[cfg_attr(feature = "schemars", derive(schemars::JsonSchema))]
#[serde(untagged, expecting = "a number or [r, g, b]")]
enum Intensity {
    /// Grey.
    Grey(#[cfg_attr(feature = "schemars", schemars(range(min = 0.0)))] f32),
    /// Red, green and blue.
    Rgb([f32; 3]),
}

fn default_intensity() -> Intensity {
    Intensity::Grey(1.0)
}

impl Intensity {
    fn rgb(&self) -> [f32; 3] {
        match *self {
            Intensity::Grey(x) => [x; 3],
            Intensity::Rgb(c) => c,
        }
    }
}

/// A light; its intensity is linear.
#[derive(DeriveSerialize, DeriveDeserialize)]
#[cfg_attr(feature = "schemars", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "schemars", schemars(rename = "Light"))]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
enum LightForm {
    /// Light from a direction (the sun).
    Directional {
        /// Direction towards the light [x, y, z] (not zero).
        #[cfg_attr(feature = "schemars", schemars(with = "[f64; 3]"))]
        direction: DVec3,
        /// Linear irradiance on a surface facing the light: a number or [r, g, b]; default 1.
        #[serde(default = "default_intensity")]
        intensity: Intensity,
    },
    /// Light from a direction that casts no shadow (a fill light).
    Fill {
        /// Direction towards the light [x, y, z] (not zero).
        #[cfg_attr(feature = "schemars", schemars(with = "[f64; 3]"))]
        direction: DVec3,
        /// Linear irradiance on a surface facing the light: a number or [r, g, b]; default 1.
        #[serde(default = "default_intensity")]
        intensity: Intensity,
    },
    /// Light from a point, falling off with the squared distance.
    Point {
        /// Position of the light [x, y, z].
        #[cfg_attr(feature = "schemars", schemars(with = "[f64; 3]"))]
        position: DVec3,
        /// Linear radiant intensity (the irradiance at distance 1): a number or [r, g, b];
        /// default 1.
        #[serde(default = "default_intensity")]
        intensity: Intensity,
    },
}

impl Serialize for Light {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match *self {
            Light::Directional { direction, intensity } => {
                LightForm::Directional { direction, intensity: Intensity::Rgb(intensity) }
            }
            Light::Fill { direction, intensity } => {
                LightForm::Fill { direction, intensity: Intensity::Rgb(intensity) }
            }
            Light::Point { position, intensity } => {
                LightForm::Point { position, intensity: Intensity::Rgb(intensity) }
            }
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Light {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let light = match LightForm::deserialize(deserializer)? {
            LightForm::Directional { direction, intensity } => {
                Light::Directional { direction, intensity: intensity.rgb() }
            }
            LightForm::Fill { direction, intensity } => {
                Light::Fill { direction, intensity: intensity.rgb() }
            }
            LightForm::Point { position, intensity } => {
                Light::Point { position, intensity: intensity.rgb() }
            }
        };
        check_light(&light).map_err(D::Error::custom)?;
        Ok(light)
    }
}

/// The JSON schemas (feature `schemars`): those of the serde forms above.
#[cfg(feature = "schemars")]
mod schemas {
    use std::borrow::Cow;

    use schemars::{JsonSchema, Schema, SchemaGenerator};

    use super::{CameraForm, LightForm, MaterialForm};
    use crate::{Camera, Light, Material};

    macro_rules! schema_of_form {
        ($public:ty, $form:ty, $name:literal) => {
            impl JsonSchema for $public {
                fn schema_name() -> Cow<'static, str> {
                    Cow::Borrowed($name)
                }
                fn json_schema(generator: &mut SchemaGenerator) -> Schema {
                    <$form>::json_schema(generator)
                }
            }
        };
    }

    schema_of_form!(Camera, CameraForm, "Camera");
    schema_of_form!(Material, MaterialForm, "Material");
    schema_of_form!(Light, LightForm, "Light");
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::RenderOptions;

    #[test]
    fn cameras_read_back_in_the_file_form() {
        let camera =
            Camera::try_new(DVec3::new(3.0, 2.0, 5.0), DVec3::ZERO, DVec3::Y, 0.7).unwrap();
        let text = serde_json::to_string(&camera).unwrap();
        assert!(text.starts_with(r#"{"eye":[3.0,2.0,5.0],"target":["#), "{text}");
        let back: Camera = serde_json::from_str(&text).unwrap();
        for (a, b) in [
            (back.eye(), camera.eye()),
            (back.forward(), camera.forward()),
            (back.right(), camera.right()),
            (back.up(), camera.up()),
        ] {
            assert!((a - b).length() < 1e-15, "{a} {b}");
        }
        assert!((back.fov_y() - camera.fov_y()).abs() < 1e-15, "fov");
        // Degrees, up +Z by default: 90° is π/2.
        let by_hand: Camera =
            serde_json::from_str(r#"{"eye":[0,-5,0],"target":[0,0,0],"fov":90}"#).unwrap();
        assert!((by_hand.fov_y() - std::f64::consts::FRAC_PI_2).abs() < 1e-15, "degrees");
        assert_eq!(by_hand.up(), DVec3::Z, "up defaults to +Z");
        let by_default: Camera =
            serde_json::from_str(r#"{"eye":[0,-5,0],"target":[0,0,0]}"#).unwrap();
        assert!((by_default.fov_y() - 40f64.to_radians()).abs() < 1e-15, "40° by default");
        let degenerate = r#"{"eye":[0,0,0],"target":[0,1,0],"up":[0,1,0]}"#;
        let err = serde_json::from_str::<Camera>(degenerate).unwrap_err().to_string();
        assert!(err.contains("parallel"), "{err}");
        let old = r#"{"eye":[0,0,0],"forward":[0,1,0],"up":[0,0,1],"fov_y":0.7}"#;
        assert!(serde_json::from_str::<Camera>(old).is_err(), "the old form is refused");
        let options = RenderOptions::default();
        let text = serde_json::to_string(&options).unwrap();
        assert_eq!(serde_json::from_str::<RenderOptions>(&text).unwrap(), options);
    }

    #[test]
    fn materials_are_srgb_and_lights_linear() {
        // sRGB 0.5 → linear ((0.5 + 0.055)/1.055)^2.4 = 0.214041140…; sRGB 0.04 → 0.04/12.92.
        let material: Material = serde_json::from_str(r#"{"color":[0.5,0.04,1]}"#).unwrap();
        let expected = [0.214_041_14_f32, 0.04 / 12.92, 1.0];
        for (a, b) in material.color.iter().zip(expected) {
            assert!((a - b).abs() < 1e-7, "{a} {b}");
        }
        assert_eq!(material.specular, Material::default().specular, "defaults fill the rest");
        let text = serde_json::to_string(&material).unwrap();
        let back: Material = serde_json::from_str(&text).unwrap();
        for (a, b) in back.color.iter().zip(material.color) {
            assert!((a - b).abs() < 1e-7, "{a} {b}");
        }
        let err = serde_json::from_str::<Material>(r#"{"color":[0,2,0]}"#).unwrap_err();
        assert!(err.to_string().contains("[0, 1]"), "{err}");
        assert!(serde_json::from_str::<Material>(r#"{"specular":-1}"#).is_err(), "negative");
        let light: Light =
            serde_json::from_str(r#"{"type":"point","position":[1,2,3],"intensity":20}"#).unwrap();
        assert_eq!(
            light,
            Light::Point { position: DVec3::new(1.0, 2.0, 3.0), intensity: [20.0; 3] }
        );
        let light = Light::Directional { direction: DVec3::NEG_Y, intensity: [1.0, 0.9, 0.8] };
        let text = serde_json::to_string(&light).unwrap();
        assert!(text.starts_with(r#"{"type":"directional","direction":[0.0,-1.0,0.0]"#), "{text}");
        assert_eq!(serde_json::from_str::<Light>(&text).unwrap(), light);
        let white: Light =
            serde_json::from_str(r#"{"type":"directional","direction":[0,0,1]}"#).unwrap();
        assert_eq!(white, Light::Directional { direction: DVec3::Z, intensity: [1.0; 3] });
        let fill: Light =
            serde_json::from_str(r#"{"type":"fill","direction":[0,0,2],"intensity":0.3}"#).unwrap();
        assert_eq!(fill, Light::Fill { direction: DVec3::new(0.0, 0.0, 2.0), intensity: [0.3; 3] });
        assert_eq!(
            serde_json::from_str::<Light>(&serde_json::to_string(&fill).unwrap()).unwrap(),
            fill
        );
        for bad in [
            r#"{"type":"directional","direction":[0,0,0]}"#,
            r#"{"type":"fill","direction":[0,0,0]}"#,
            r#"{"type":"point","position":[0,0,0],"intensity":-1}"#,
            r#"{"type":"spot","position":[0,0,0]}"#,
        ] {
            assert!(serde_json::from_str::<Light>(bad).is_err(), "{bad}");
        }
    }
}
