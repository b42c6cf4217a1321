// SPDX-License-Identifier: MIT
//! `hi curve eval`: the curve, its derivatives, curvature and torsion at given parameters.

use glam::{DVec2, DVec3};
use hi_curve::{ControlPoint, HarmonicCurve, ParamCurve, PlaneCurve, SpaceCurve};
use serde::Serialize;

use crate::cli::EvalArgs;
use crate::error::Failure;
use crate::input::{Points, read_points};
use crate::output::{Derivatives, Json, coords, json};

/// `{"X": [...], "d1": [...], ..., "curvature": [...], "torsion": [...]}`.
///
/// # Errors
///
/// [`Failure::Input`] for unreadable or malformed input.
pub(crate) fn run(args: &EvalArgs) -> Result<Json, Failure> {
    let (ts, d) = (&args.t.0, args.derivatives);
    match read_points(&args.input.input)? {
        Points::One(p) => eval(p, ts, d),
        Points::Two(p) => eval(p, ts, d),
        Points::Three(p) => eval(p, ts, d),
    }
}

fn eval<P: Geometry>(points: Vec<P>, ts: &[f64], derivatives: usize) -> Result<Json, Failure> {
    let curve = HarmonicCurve::try_new(points)?;
    let at = |f: &dyn Fn(f64) -> P| ts.iter().map(|&t| coords(&f(t))).collect();
    let (curvature, torsion) = P::geometry(&curve, ts);
    json(&Values {
        x: at(&|t| curve.eval(t)),
        derivatives: Derivatives(
            (1..=derivatives).map(|order| at(&|t| curve.eval_deriv(t, order))).collect(),
        ),
        curvature,
        torsion,
    })
}

/// Coordinates of points.
type PointRows = Vec<Vec<f64>>;

/// Values that may be undefined (`null` at a singular point).
type Optional = Vec<Option<f64>>;

/// `{"X", "d1", …, "curvature", "torsion"}`: curvature in 2-D and 3-D, torsion in 3-D.
#[derive(Serialize)]
struct Values {
    #[serde(rename = "X")]
    x: PointRows,
    #[serde(flatten)]
    derivatives: Derivatives<PointRows>,
    #[serde(skip_serializing_if = "Option::is_none")]
    curvature: Option<Optional>,
    #[serde(skip_serializing_if = "Option::is_none")]
    torsion: Option<Optional>,
}

/// The differential geometry printed for each dimension.
trait Geometry: ControlPoint {
    /// The curvature and torsion of `curve` at `ts`, where the dimension has them.
    fn geometry(curve: &HarmonicCurve<Self>, ts: &[f64]) -> (Option<Optional>, Option<Optional>);
}

impl Geometry for f64 {
    /// Nothing: a 1-D curve has no curvature.
    fn geometry(_: &HarmonicCurve<Self>, _: &[f64]) -> (Option<Optional>, Option<Optional>) {
        (None, None)
    }
}

impl Geometry for DVec2 {
    /// The signed curvature.
    fn geometry(curve: &HarmonicCurve<Self>, ts: &[f64]) -> (Option<Optional>, Option<Optional>) {
        (Some(ts.iter().map(|&t| curve.signed_curvature(t)).collect()), None)
    }
}

impl Geometry for DVec3 {
    /// The unsigned curvature and the torsion.
    fn geometry(curve: &HarmonicCurve<Self>, ts: &[f64]) -> (Option<Optional>, Option<Optional>) {
        (
            Some(ts.iter().map(|&t| curve.curvature(t)).collect()),
            Some(ts.iter().map(|&t| curve.torsion(t)).collect()),
        )
    }
}
