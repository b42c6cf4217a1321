// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`).
//!
//! The forms are listed in the crate documentation (Feature flags).

use serde::de::{Deserialize, DeserializeOwned, Deserializer, Error as _};
use serde::ser::{Serialize, Serializer};
use serde::{Deserialize as DeriveDeserialize, Serialize as DeriveSerialize};

use crate::{
    BezierCurve, BezierPatch, ControlPoint, PiecewiseBezier, RationalBezierCurve,
    RationalBezierPatch, TriangularPatch,
};

/// Row-major values written as rows of `cols` entries.
struct Rows<'a, T>(&'a [T], usize);

impl<T: Serialize> Serialize for Rows<'_, T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.0.chunks(self.1.max(1)))
    }
}

#[derive(DeriveSerialize)]
struct ControlRef<'a, P> {
    control: &'a [P],
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct ControlOwned<P> {
    control: Vec<P>,
}

impl<P: ControlPoint + Serialize> Serialize for BezierCurve<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        ControlRef { control: self.control_points() }.serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for BezierCurve<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = ControlOwned::<P>::deserialize(deserializer)?;
        BezierCurve::try_new(raw.control).map_err(D::Error::custom)
    }
}

#[derive(DeriveSerialize)]
struct SegmentsRef<'a, P: ControlPoint + Serialize> {
    segments: &'a [BezierCurve<P>],
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields, bound = "P: ControlPoint + DeserializeOwned")]
struct SegmentsOwned<P: ControlPoint> {
    segments: Vec<BezierCurve<P>>,
}

impl<P: ControlPoint + Serialize> Serialize for PiecewiseBezier<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        SegmentsRef { segments: self.segments() }.serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for PiecewiseBezier<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = SegmentsOwned::<P>::deserialize(deserializer)?;
        PiecewiseBezier::try_new(raw.segments).map_err(D::Error::custom)
    }
}

#[derive(DeriveSerialize)]
struct WeightedRef<'a, P> {
    points: &'a [P],
    weights: &'a [f64],
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct WeightedOwned<P> {
    points: Vec<P>,
    weights: Vec<f64>,
}

impl<P: ControlPoint + Serialize> Serialize for RationalBezierCurve<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        WeightedRef { points: self.control_points(), weights: self.weights() }.serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for RationalBezierCurve<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = WeightedOwned::<P>::deserialize(deserializer)?;
        RationalBezierCurve::try_new(raw.points, raw.weights).map_err(D::Error::custom)
    }
}

#[derive(DeriveSerialize)]
struct RowsRef<'a, P: Serialize> {
    rows: Rows<'a, P>,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct RowsOwned<P> {
    rows: Vec<Vec<P>>,
}

impl<P: ControlPoint + Serialize> Serialize for BezierPatch<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        RowsRef { rows: Rows(self.control_points(), self.degree_v() + 1) }.serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for BezierPatch<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = RowsOwned::<P>::deserialize(deserializer)?;
        BezierPatch::try_new(raw.rows).map_err(D::Error::custom)
    }
}

#[derive(DeriveSerialize)]
struct WeightedRowsRef<'a, P: Serialize> {
    rows: Rows<'a, P>,
    weights: Rows<'a, f64>,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct WeightedRowsOwned<P> {
    rows: Vec<Vec<P>>,
    weights: Vec<Vec<f64>>,
}

impl<P: ControlPoint + Serialize> Serialize for RationalBezierPatch<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let cols = self.degree_v() + 1;
        WeightedRowsRef {
            rows: Rows(self.control_points(), cols),
            weights: Rows(self.weights(), cols),
        }
        .serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for RationalBezierPatch<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = WeightedRowsOwned::<P>::deserialize(deserializer)?;
        RationalBezierPatch::try_new(raw.rows, raw.weights).map_err(D::Error::custom)
    }
}

#[derive(DeriveSerialize)]
struct PointsRef<'a, P> {
    points: &'a [P],
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct PointsOwned<P> {
    points: Vec<P>,
}

impl<P: ControlPoint + Serialize> Serialize for TriangularPatch<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        PointsRef { points: self.control_points() }.serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for TriangularPatch<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = PointsOwned::<P>::deserialize(deserializer)?;
        TriangularPatch::try_new(raw.points).map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use glam::{DVec2, DVec3};

    use super::*;
    use crate::{Aabb, Bernstein};

    fn round_trip<T: Serialize + DeserializeOwned>(value: &T) -> T {
        serde_json::from_str(&serde_json::to_string(value).unwrap()).unwrap()
    }

    #[test]
    fn curves_and_patches_read_back_equal() {
        let curve = BezierCurve::new(vec![DVec2::ZERO, DVec2::new(0.1, 1.0), DVec2::X]);
        assert_eq!(round_trip(&curve), curve);
        assert_eq!(
            serde_json::to_string(&curve).unwrap(),
            r#"{"control":[[0.0,0.0],[0.1,1.0],[1.0,0.0]]}"#
        );
        let (a, b) = curve.split(0.3);
        let piecewise = PiecewiseBezier::new(vec![a, b]);
        assert_eq!(round_trip(&piecewise), piecewise);
        let rational = RationalBezierCurve::new(vec![1.0, 2.0, 4.0], vec![1.0, 0.5, 2.0]);
        assert_eq!(round_trip(&rational), rational);
        let patch = BezierPatch::new(vec![
            vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            vec![DVec3::Z, DVec3::ONE, -DVec3::X],
        ]);
        assert_eq!(round_trip(&patch), patch);
        assert_eq!(
            serde_json::to_string(&patch).unwrap(),
            r#"{"rows":[[[0.0,0.0,0.0],[1.0,0.0,0.0],[0.0,1.0,0.0]],[[0.0,0.0,1.0],[1.0,1.0,1.0],[-1.0,-0.0,-0.0]]]}"#
        );
        let weighted = RationalBezierPatch::new(
            vec![vec![0.0, 1.0], vec![2.0, 3.0]],
            vec![vec![1.0, 2.0], vec![0.5, 1.0]],
        );
        assert_eq!(round_trip(&weighted), weighted);
        let triangle = TriangularPatch::new(vec![DVec2::ZERO, DVec2::X, DVec2::Y]);
        assert_eq!(round_trip(&triangle), triangle);
        let bounds = Aabb::from_points(&[DVec3::ZERO, DVec3::ONE]).unwrap();
        assert_eq!(round_trip(&bounds), bounds);
        assert_eq!(round_trip(&Bernstein::new(4)), Bernstein::new(4));
    }

    #[test]
    fn invalid_control_data_is_an_error() {
        for (text, what) in [
            (r#"{"control":[]}"#, "no control points"),
            (r#"{"control":[1.0],"degree":3}"#, "an unknown field"),
        ] {
            assert!(serde_json::from_str::<BezierCurve<f64>>(text).is_err(), "{what}");
        }
        assert!(serde_json::from_str::<BezierPatch<f64>>(r#"{"rows":[[1.0,2.0],[3.0]]}"#).is_err());
        assert!(
            serde_json::from_str::<RationalBezierCurve<f64>>(
                r#"{"points":[1.0],"weights":[-1.0]}"#
            )
            .is_err()
        );
        assert!(serde_json::from_str::<TriangularPatch<f64>>(r#"{"points":[1.0,2.0]}"#).is_err());
        assert!(serde_json::from_str::<PiecewiseBezier<f64>>(r#"{"segments":[]}"#).is_err());
    }
}
