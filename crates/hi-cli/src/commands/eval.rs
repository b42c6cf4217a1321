// SPDX-License-Identifier: MIT
//! `hi curve eval`: the curve, its derivatives, curvature and torsion at given parameters.

use glam::{DVec2, DVec3};
use hi_curve::{ControlPoint, HarmonicCurve, ParamCurve, PlaneCurve, SpaceCurve};

use crate::cli::EvalArgs;
use crate::error::Failure;
use crate::input::{Points, read_points};
use crate::output::{Json, Object};

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
    let at = |f: &dyn Fn(f64) -> P| Json::Array(ts.iter().map(|&t| Json::point(&f(t))).collect());
    let mut out = Object::new().field("X", at(&|t| curve.eval(t)));
    for order in 1..=derivatives {
        out.push(format!("d{order}"), at(&|t| curve.eval_deriv(t, order)));
    }
    P::geometry(&curve, ts, &mut out);
    Ok(out.build())
}

/// The differential geometry printed for each dimension.
trait Geometry: ControlPoint {
    /// Adds the curvature (and torsion) arrays of `curve` at `ts` to `out`.
    fn geometry(curve: &HarmonicCurve<Self>, ts: &[f64], out: &mut Object);
}

impl Geometry for f64 {
    /// Nothing: a 1-D curve has no curvature.
    fn geometry(_: &HarmonicCurve<Self>, _: &[f64], _: &mut Object) {}
}

impl Geometry for DVec2 {
    /// The signed curvature.
    fn geometry(curve: &HarmonicCurve<Self>, ts: &[f64], out: &mut Object) {
        out.push(
            "curvature",
            Json::optional_numbers(ts.iter().map(|&t| curve.signed_curvature(t))),
        );
    }
}

impl Geometry for DVec3 {
    /// The unsigned curvature and the torsion.
    fn geometry(curve: &HarmonicCurve<Self>, ts: &[f64], out: &mut Object) {
        out.push("curvature", Json::optional_numbers(ts.iter().map(|&t| curve.curvature(t))));
        out.push("torsion", Json::optional_numbers(ts.iter().map(|&t| curve.torsion(t))));
    }
}
