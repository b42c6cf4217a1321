// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`): a [`GeometryImage`] is `{"rows": [[t₀₀, …], …]}`, its
//! texels row by row, read back through [`GeometryImage::try_new`].

use glam::DVec3;
use serde::de::{Deserialize, Deserializer, Error as _};
use serde::ser::{Serialize, Serializer};
use serde::{Deserialize as DeriveDeserialize, Serialize as DeriveSerialize};

use crate::GeometryImage;

#[derive(DeriveSerialize)]
struct ImageRef<'a> {
    rows: Vec<&'a [DVec3]>,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct ImageOwned {
    rows: Vec<Vec<DVec3>>,
}

impl Serialize for GeometryImage {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        ImageRef { rows: self.texels().chunks(self.cols().max(1)).collect() }.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for GeometryImage {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = ImageOwned::deserialize(deserializer)?;
        let (rows, cols) = (raw.rows.len(), raw.rows.first().map_or(0, Vec::len));
        if let Some(i) = raw.rows.iter().position(|row| row.len() != cols) {
            return Err(D::Error::custom(format!(
                "row {i} of the geometry image has {} texels, row 0 has {cols}",
                raw.rows[i].len()
            )));
        }
        GeometryImage::try_new(rows, cols, raw.rows.into_iter().flatten().collect())
            .map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{FitOptions, Layout, Method, fit};
    use hi_scan::scan::Scan;

    #[test]
    fn images_read_back_equal_and_ragged_ones_are_errors() {
        let texels: Vec<DVec3> = (0..6).map(|i| DVec3::new(i as f64, 0.5, -1.0)).collect();
        let image = GeometryImage::try_new(2, 3, texels).unwrap();
        let text = serde_json::to_string(&image).unwrap();
        assert!(text.starts_with(r#"{"rows":[[[0.0,0.5,-1.0],[1.0,0.5,-1.0],"#), "{text}");
        assert_eq!(serde_json::from_str::<GeometryImage>(&text).unwrap(), image);
        let ragged = r#"{"rows":[[[0,0,0],[1,1,1]],[[0,0,0]]]}"#;
        let err = serde_json::from_str::<GeometryImage>(ragged).unwrap_err().to_string();
        assert!(err.contains("row 1"), "{err}");
    }

    #[test]
    fn a_fit_report_is_written_without_its_per_point_distances() {
        // Points on the unit sphere (a Fibonacci lattice).
        let n = 2000;
        let points: Vec<DVec3> = (0..n)
            .map(|i| {
                let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
                let a = i as f64 * std::f64::consts::PI * (3.0 - 5f64.sqrt());
                let r = (1.0 - z * z).sqrt();
                DVec3::new(r * a.cos(), r * a.sin(), z)
            })
            .collect();
        let scan = Scan { points, ..Scan::default() };
        let options = FitOptions {
            method: Method::Radial,
            layout: Layout::Sphere,
            resolution: Some((16, 16)),
            ..FitOptions::default()
        };
        let fitted = fit(&scan, &options, &mut |_| {}).unwrap();
        let json = serde_json::to_value(&fitted.report).unwrap();
        assert_eq!(json["method"], "radial");
        assert_eq!(json["points"], n);
        let both = &json["both_ways"]["scan_to_surface"];
        assert!(both["mean"].as_f64().unwrap() < 0.05, "{both}");
        assert!(both.get("per_point").is_none(), "{both}");
        let options_text = serde_json::to_string(&options).unwrap();
        assert_eq!(serde_json::from_str::<FitOptions>(&options_text).unwrap(), options);
    }
}
