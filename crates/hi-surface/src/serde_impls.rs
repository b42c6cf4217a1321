// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`): a [`HarmonicSurface`] is `{"rows": [[x₀₀, …], …]}`, the
//! grid it interpolates (row j at u = j/m), read back through [`HarmonicSurface::try_new`],
//! which rebuilds its spectrum.

use serde::de::{Deserialize, DeserializeOwned, Deserializer, Error as _};
use serde::ser::{Serialize, Serializer};
use serde::{Deserialize as DeriveDeserialize, Serialize as DeriveSerialize};

use hi_curve::ControlPoint;

use crate::HarmonicSurface;

/// The grid of a surface, written row by row without copying it.
struct Rows<'a, P>(&'a [P], usize);

impl<P: Serialize> Serialize for Rows<'_, P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.0.chunks(self.1.max(1)))
    }
}

#[derive(DeriveSerialize)]
struct SurfaceRef<'a, P: Serialize> {
    rows: Rows<'a, P>,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct SurfaceOwned<P> {
    rows: Vec<Vec<P>>,
}

impl<P: ControlPoint + Serialize> Serialize for HarmonicSurface<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        SurfaceRef { rows: Rows(self.points(), self.n()) }.serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for HarmonicSurface<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = SurfaceOwned::<P>::deserialize(deserializer)?;
        HarmonicSurface::try_new(raw.rows).map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::MeshOptions;

    #[test]
    fn surfaces_read_back_and_evaluate_the_same() {
        let rows: Vec<Vec<DVec3>> = (0..3)
            .map(|j| (0..4).map(|k| DVec3::new(j as f64, k as f64, 0.1 * (j * k) as f64)).collect())
            .collect();
        let surface = HarmonicSurface::new(rows);
        let text = serde_json::to_string(&surface).unwrap();
        assert!(text.starts_with(r#"{"rows":[[[0.0,0.0,0.0],[0.0,1.0,0.0],"#), "{text}");
        let back: HarmonicSurface<DVec3> = serde_json::from_str(&text).unwrap();
        assert_eq!(back, surface);
        assert_eq!(back.eval(0.3, 0.7), surface.eval(0.3, 0.7));
        let options = MeshOptions::default();
        let text = serde_json::to_string(&options).unwrap();
        assert_eq!(serde_json::from_str::<MeshOptions>(&text).unwrap(), options);
    }

    #[test]
    fn ragged_or_empty_grids_are_errors() {
        for text in [r#"{"rows":[]}"#, r#"{"rows":[[1.0,2.0],[3.0]]}"#, r#"{"grid":[[1.0]]}"#] {
            assert!(serde_json::from_str::<HarmonicSurface<f64>>(text).is_err(), "{text}");
        }
    }
}
