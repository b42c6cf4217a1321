// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`): a [`Camera`] is `{"eye", "forward", "up", "fov_y"}`,
//! read back through [`Camera::try_new`] (so the frame is orthonormal again).

use glam::DVec3;
use serde::de::{Deserialize, Deserializer, Error as _};
use serde::ser::{Serialize, Serializer};
use serde::{Deserialize as DeriveDeserialize, Serialize as DeriveSerialize};

use crate::Camera;

#[derive(DeriveSerialize, DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct CameraRaw {
    eye: DVec3,
    forward: DVec3,
    up: DVec3,
    fov_y: f64,
}

impl Serialize for Camera {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        CameraRaw { eye: self.eye(), forward: self.forward(), up: self.up(), fov_y: self.fov_y() }
            .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Camera {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = CameraRaw::deserialize(deserializer)?;
        Camera::try_new(raw.eye, raw.eye + raw.forward, raw.up, raw.fov_y).map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Light, Material, RenderOptions};

    #[test]
    fn cameras_and_options_read_back() {
        let camera =
            Camera::try_new(DVec3::new(3.0, 2.0, 5.0), DVec3::ZERO, DVec3::Y, 0.7).unwrap();
        let back: Camera = serde_json::from_str(&serde_json::to_string(&camera).unwrap()).unwrap();
        for (a, b) in [
            (back.eye(), camera.eye()),
            (back.forward(), camera.forward()),
            (back.right(), camera.right()),
            (back.up(), camera.up()),
        ] {
            assert!((a - b).length() < 1e-15, "{a} {b}");
        }
        assert_eq!(back.fov_y(), camera.fov_y());
        let degenerate = r#"{"eye":[0,0,0],"forward":[0,1,0],"up":[0,1,0],"fov_y":0.7}"#;
        assert!(serde_json::from_str::<Camera>(degenerate).is_err());
        let options = RenderOptions::default();
        let text = serde_json::to_string(&options).unwrap();
        assert_eq!(serde_json::from_str::<RenderOptions>(&text).unwrap(), options);
        let light = Light::Directional { direction: DVec3::NEG_Y, intensity: [1.0, 0.9, 0.8] };
        let text = serde_json::to_string(&light).unwrap();
        assert!(text.starts_with(r#"{"directional":{"direction":[0.0,-1.0,0.0]"#), "{text}");
        assert_eq!(serde_json::from_str::<Light>(&text).unwrap(), light);
        let material = Material::default();
        let text = serde_json::to_string(&material).unwrap();
        assert_eq!(serde_json::from_str::<Material>(&text).unwrap(), material);
    }
}
