// SPDX-License-Identifier: MIT
//! `serde` support (feature `serde`): each curve is written as the data its constructor takes
//! and read back through that constructor; the forms are listed in the crate documentation.

use serde::de::{Deserialize, DeserializeOwned, Deserializer, Error as _};
use serde::ser::{Serialize, Serializer};
use serde::{Deserialize as DeriveDeserialize, Serialize as DeriveSerialize};

use crate::bspline::{BSplineBasis, BSplineCurve};
use crate::bspline_interp::{EndCondition, InterpolatingSpline, Parameters};
use crate::corner_cutting::{ChaikinCurve, FourPointCurve};
use crate::lagrange::{LagrangeBasis, LagrangeCurve};
use crate::nurbs::NurbsCurve;
use crate::{AnyCurve, ControlPoint, CurveKind};

/// Implements `Serialize` through a borrowed form and `Deserialize` through an owned form and
/// a checked constructor, for a type generic over its point type `P`.
macro_rules! through_constructor {
    ($ty:ident, $borrowed:ident, $owned:ident, |$s:ident| $to:expr, |$raw:ident| $from:expr) => {
        impl<P: ControlPoint + Serialize> Serialize for $ty<P> {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                let $s = self;
                $to.serialize(serializer)
            }
        }

        impl<'de, P: ControlPoint + DeserializeOwned> Deserialize<'de> for $ty<P> {
            fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                let $raw = $owned::<P>::deserialize(deserializer)?;
                $from.map_err(D::Error::custom)
            }
        }
    };
}

#[derive(DeriveSerialize)]
struct SplineRef<'a, P> {
    degree: usize,
    knots: &'a [f64],
    control: &'a [P],
    closed: bool,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct SplineOwned<P> {
    degree: usize,
    knots: Vec<f64>,
    control: Vec<P>,
    #[serde(default)]
    closed: bool,
}

through_constructor!(
    BSplineCurve,
    SplineRef,
    SplineOwned,
    |c| SplineRef {
        degree: c.degree(),
        knots: c.knots(),
        control: c.control_points(),
        closed: c.is_closed()
    },
    |raw| if raw.closed {
        BSplineCurve::try_new_periodic(raw.degree, raw.knots, raw.control)
    } else {
        BSplineCurve::try_new(raw.degree, raw.knots, raw.control)
    }
);

#[derive(DeriveSerialize)]
struct NurbsRef<'a, P> {
    degree: usize,
    knots: &'a [f64],
    control: &'a [P],
    weights: &'a [f64],
    closed: bool,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct NurbsOwned<P> {
    degree: usize,
    knots: Vec<f64>,
    control: Vec<P>,
    weights: Vec<f64>,
    #[serde(default)]
    closed: bool,
}

through_constructor!(
    NurbsCurve,
    NurbsRef,
    NurbsOwned,
    |c| NurbsRef {
        degree: c.degree(),
        knots: c.knots(),
        control: c.control_points(),
        weights: c.weights(),
        closed: c.is_closed()
    },
    |raw| if raw.closed {
        NurbsCurve::try_new_periodic(raw.degree, raw.knots, raw.control, raw.weights)
    } else {
        NurbsCurve::try_new(raw.degree, raw.knots, raw.control, raw.weights)
    }
);

#[derive(DeriveSerialize)]
struct NodesRef<'a, P> {
    points: &'a [P],
    params: &'a [f64],
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct NodesOwned<P> {
    points: Vec<P>,
    params: Vec<f64>,
}

through_constructor!(
    LagrangeCurve,
    NodesRef,
    NodesOwned,
    |c| NodesRef { points: c.points(), params: c.basis().nodes() },
    |raw| LagrangeCurve::try_with_params(raw.points, raw.params)
);

#[derive(DeriveSerialize)]
struct CornerRef<'a, P> {
    points: &'a [P],
    closed: bool,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct CornerOwned<P> {
    points: Vec<P>,
    closed: bool,
}

through_constructor!(
    ChaikinCurve,
    CornerRef,
    CornerOwned,
    |c| CornerRef { points: c.points(), closed: c.is_closed() },
    |raw| ChaikinCurve::try_new(raw.points, raw.closed)
);

#[derive(DeriveSerialize)]
struct FourPointRef<'a, P> {
    points: &'a [P],
    closed: bool,
    weight: f64,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct FourPointOwned<P> {
    points: Vec<P>,
    closed: bool,
    weight: f64,
}

through_constructor!(
    FourPointCurve,
    FourPointRef,
    FourPointOwned,
    |c| FourPointRef { points: c.points(), closed: c.is_closed(), weight: c.weight() },
    |raw| FourPointCurve::try_with_weight(raw.points, raw.closed, raw.weight)
);

#[derive(DeriveSerialize)]
struct InterpolatingRef<'a, P> {
    points: &'a [P],
    params: &'a [f64],
    end: Option<EndCondition>,
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct InterpolatingOwned<P> {
    points: Vec<P>,
    params: Vec<f64>,
    end: Option<EndCondition>,
}

through_constructor!(
    InterpolatingSpline,
    InterpolatingRef,
    InterpolatingOwned,
    |c| InterpolatingRef { points: c.points(), params: c.params(), end: c.end_condition() },
    |raw| match raw.end {
        Some(end) => InterpolatingSpline::try_open(raw.points, Parameters::Given(raw.params), end),
        None => InterpolatingSpline::try_periodic(raw.points, Parameters::Given(raw.params)),
    }
);

#[derive(DeriveSerialize)]
struct KindRef<'a, P> {
    kind: CurveKind,
    points: &'a [P],
}

#[derive(DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct KindOwned<P> {
    kind: CurveKind,
    points: Vec<P>,
}

through_constructor!(
    AnyCurve,
    KindRef,
    KindOwned,
    |c| KindRef { kind: c.kind(), points: c.points() },
    |raw| raw.kind.build(raw.points)
);

#[derive(DeriveSerialize, DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct BasisRaw {
    degree: usize,
    knots: Vec<f64>,
}

impl Serialize for BSplineBasis {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        BasisRaw { degree: self.degree(), knots: self.knots().to_vec() }.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for BSplineBasis {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = BasisRaw::deserialize(deserializer)?;
        BSplineBasis::try_new(raw.degree, raw.knots).map_err(D::Error::custom)
    }
}

#[derive(DeriveSerialize, DeriveDeserialize)]
#[serde(deny_unknown_fields)]
struct LagrangeBasisRaw {
    nodes: Vec<f64>,
}

impl Serialize for LagrangeBasis {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        LagrangeBasisRaw { nodes: self.nodes().to_vec() }.serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for LagrangeBasis {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let raw = LagrangeBasisRaw::deserialize(deserializer)?;
        LagrangeBasis::try_new(raw.nodes).map_err(D::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;

    fn round_trip<T: Serialize + DeserializeOwned>(value: &T) -> T {
        serde_json::from_str(&serde_json::to_string(value).unwrap()).unwrap()
    }

    fn pentagon() -> Vec<DVec2> {
        (0..5)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / 5.0;
                DVec2::new(a.cos(), 0.8 * a.sin())
            })
            .collect()
    }

    #[test]
    fn curves_read_back_equal() {
        let p = pentagon();
        let open = BSplineCurve::try_clamped(3, p.clone()).unwrap();
        assert_eq!(round_trip(&open), open);
        let closed = BSplineCurve::try_uniform_closed(3, p.clone()).unwrap();
        assert_eq!(round_trip(&closed), closed);
        let weights = vec![1.0, 2.0, 0.5, 1.0, 1.5];
        let nurbs =
            NurbsCurve::try_new(3, open.knots().to_vec(), p.clone(), weights.clone()).unwrap();
        assert_eq!(round_trip(&nurbs), nurbs);
        let nurbs_closed =
            NurbsCurve::try_new_periodic(3, closed.knots().to_vec(), p.clone(), weights).unwrap();
        assert_eq!(round_trip(&nurbs_closed), nurbs_closed);
        let lagrange = LagrangeCurve::try_new(p.clone()).unwrap();
        assert_eq!(round_trip(&lagrange), lagrange);
        assert_eq!(round_trip(lagrange.basis()), *lagrange.basis());
        let chaikin = ChaikinCurve::try_new(p.clone(), true).unwrap();
        assert_eq!(round_trip(&chaikin), chaikin);
        let four = FourPointCurve::try_with_weight(p.clone(), false, 0.1).unwrap();
        assert_eq!(round_trip(&four), four);
        let natural = InterpolatingSpline::try_open(
            p.clone(),
            Parameters::ChordLength,
            EndCondition::Natural,
        )
        .unwrap();
        assert_eq!(round_trip(&natural), natural);
        let periodic = InterpolatingSpline::try_periodic(p.clone(), Parameters::Uniform).unwrap();
        assert_eq!(round_trip(&periodic), periodic);
        let any = CurveKind::CatmullRom.build(p).unwrap();
        assert_eq!(round_trip(&any), any);
        assert!(serde_json::to_string(&any).unwrap().starts_with(r#"{"kind":"catmull_rom","#));
        let basis = BSplineBasis::try_new(2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]).unwrap();
        assert_eq!(round_trip(&basis), basis);
    }

    #[test]
    fn invalid_curves_are_errors() {
        for text in [
            r#"{"degree":3,"knots":[0,1],"control":[[0,0],[1,1]]}"#,
            r#"{"degree":1,"knots":[0,0,1,1],"control":[[0,0],[1,1]],"colour":1}"#,
        ] {
            assert!(serde_json::from_str::<BSplineCurve<DVec2>>(text).is_err(), "{text}");
        }
        let bad_weight = r#"{"degree":1,"knots":[0,0,1,1],"control":[0,1],"weights":[1,-1]}"#;
        assert!(serde_json::from_str::<NurbsCurve<f64>>(bad_weight).is_err());
        assert!(
            serde_json::from_str::<AnyCurve<f64>>(r#"{"kind":"harmonic","points":[]}"#).is_err()
        );
        let repeated = r#"{"points":[0.0,1.0],"params":[0.5,0.5]}"#;
        assert!(serde_json::from_str::<LagrangeCurve<f64>>(repeated).is_err());
    }
}
