// SPDX-License-Identifier: MIT
//! `hi curve resample`: insertion and reduction (Theorem 5.3).

use hi_curve::{ControlPoint, HarmonicCurve};
use serde::Serialize;

use crate::cli::ResampleArgs;
use crate::error::{Failure, context};
use crate::input::{Points, read_points};
use crate::output::{Json, PointList, json};

/// `{"points": [...], "max_error": e, "error_bound": b}`.
///
/// # Errors
///
/// [`Failure::Input`] for bad input or N > 2²⁸.
pub(crate) fn run(args: &ResampleArgs) -> Result<Json, Failure> {
    match read_points(&args.input.input)? {
        Points::One(p) => resample(p, args.count),
        Points::Two(p) => resample(p, args.count),
        Points::Three(p) => resample(p, args.count),
    }
}

fn resample<P: ControlPoint>(points: Vec<P>, count: usize) -> Result<Json, Failure> {
    let (curve, error) =
        HarmonicCurve::try_new(points)?.resample(count).map_err(context("--count"))?;
    /// `{"points", "max_error", "error_bound"}`.
    #[derive(Serialize)]
    #[serde(bound = "P: ControlPoint")]
    struct Output<'a, P: ControlPoint> {
        points: PointList<'a, P>,
        max_error: f64,
        error_bound: f64,
    }
    json(&Output {
        points: PointList(curve.points()),
        max_error: error.max_deviation,
        error_bound: error.upper_bound,
    })
}
