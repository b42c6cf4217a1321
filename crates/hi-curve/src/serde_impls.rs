// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`): curves are written as the data they interpolate and read
//! back through their checked constructors, which rebuild everything derived from it (spectra,
//! solved systems); the forms are listed in the crate documentation.

use serde::de::{Deserialize, DeserializeOwned, Deserializer, Error as _};
use serde::ser::{Serialize, SerializeStruct, Serializer};
use serde::{Deserialize as DeriveDeserialize, Serialize as DeriveSerialize};

use crate::{
    ControlPoint, Fourier, HarmonicCurve, NonUniformCurve, NonUniformVariant, Sigma,
    TrigonometricCurve,
};

#[derive(DeriveSerialize)]
struct PointsRef<'a, P> {
    points: &'a [P],
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct PointsOwned<P> {
    points: Vec<P>,
}

impl<P: ControlPoint + Serialize> Serialize for HarmonicCurve<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        PointsRef { points: self.points() }.serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for HarmonicCurve<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = PointsOwned::<P>::deserialize(deserializer)?;
        HarmonicCurve::try_new(raw.points).map_err(D::Error::custom)
    }
}

impl<P: ControlPoint + Serialize> Serialize for TrigonometricCurve<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        PointsRef { points: self.points() }.serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for TrigonometricCurve<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = PointsOwned::<P>::deserialize(deserializer)?;
        TrigonometricCurve::try_new(raw.points).map_err(D::Error::custom)
    }
}

#[derive(DeriveSerialize)]
struct NonUniformRef<'a, P> {
    points: &'a [P],
    params: &'a [f64],
    variant: NonUniformVariant,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct NonUniformOwned<P> {
    points: Vec<P>,
    params: Vec<f64>,
    variant: NonUniformVariant,
}

impl<P: ControlPoint + Serialize> Serialize for NonUniformCurve<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        NonUniformRef { points: self.points(), params: self.params(), variant: self.variant() }
            .serialize(serializer)
    }
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for NonUniformCurve<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = NonUniformOwned::<P>::deserialize(deserializer)?;
        NonUniformCurve::try_with_params(raw.points, raw.params, raw.variant)
            .map_err(D::Error::custom)
    }
}

impl<P: ControlPoint + Serialize> Serialize for Fourier<P> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut s = serializer.serialize_struct("Fourier", 2)?;
        s.serialize_field("cos", self.cos_coeffs())?;
        s.serialize_field("sin", self.sin_coeffs())?;
        s.end()
    }
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct FourierOwned<P> {
    cos: Vec<P>,
    sin: Vec<P>,
}

impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for Fourier<P> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = FourierOwned::<P>::deserialize(deserializer)?;
        let (n_cos, n_sin) = (raw.cos.len(), raw.sin.len());
        Fourier::from_coeffs(raw.cos, raw.sin).ok_or_else(|| {
            D::Error::custom(format!(
                "a trigonometric polynomial needs as many sine as cosine coefficients, at least one: {n_cos} and {n_sin} given"
            ))
        })
    }
}

#[derive(DeriveSerialize, DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct SigmaRaw {
    n: usize,
}

impl Serialize for Sigma {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        SigmaRaw { n: self.n() }.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Sigma {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        Sigma::try_new(SigmaRaw::deserialize(deserializer)?.n).map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;
    use crate::bezier::{BezierScheme, DEFAULT_TOLERANCE};

    fn round_trip<T: Serialize + DeserializeOwned>(value: &T) -> T {
        serde_json::from_str(&serde_json::to_string(value).unwrap()).unwrap()
    }

    fn square() -> Vec<DVec2> {
        vec![DVec2::ZERO, DVec2::new(1.0, 0.1), DVec2::ONE, DVec2::new(0.2, 1.0)]
    }

    #[test]
    fn curves_read_back_and_evaluate_the_same() {
        let curve = HarmonicCurve::new(square());
        let back = round_trip(&curve);
        assert_eq!(back, curve);
        assert_eq!(back.eval(0.3), curve.eval(0.3));
        assert_eq!(
            serde_json::to_string(&curve).unwrap(),
            r#"{"points":[[0.0,0.0],[1.0,0.1],[1.0,1.0],[0.2,1.0]]}"#
        );
        let trig = TrigonometricCurve::try_new(square()).unwrap();
        assert_eq!(round_trip(&trig), trig);
        for variant in [NonUniformVariant::Thesis, NonUniformVariant::Nodes] {
            let nonuniform = NonUniformCurve::try_new(square(), variant).unwrap();
            assert_eq!(round_trip(&nonuniform), nonuniform);
        }
        assert_eq!(round_trip(curve.fourier()), *curve.fourier());
        assert_eq!(round_trip(&Sigma::new(5)), Sigma::new(5));
        let bezier = curve.to_bezier(BezierScheme::ThesisCubic, DEFAULT_TOLERANCE).unwrap();
        let text = serde_json::to_string(&bezier).unwrap();
        assert!(text.starts_with(r#"{"spline":{"breaks":[0.0,"#), "{text}");
    }

    #[test]
    fn invalid_curves_are_errors() {
        assert!(serde_json::from_str::<HarmonicCurve<f64>>(r#"{"points":[]}"#).is_err());
        assert!(serde_json::from_str::<Sigma>(r#"{"n":0}"#).is_err());
        assert!(serde_json::from_str::<Fourier<f64>>(r#"{"cos":[1.0],"sin":[]}"#).is_err());
        let repeated = r#"{"points":[0.0,1.0],"params":[0.5,0.5],"variant":"nodes"}"#;
        assert!(serde_json::from_str::<NonUniformCurve<f64>>(repeated).is_err());
    }
}
