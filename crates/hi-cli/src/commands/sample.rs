// SPDX-License-Identifier: MIT
//! `hi curve sample`: uniform samples of the curve of a kind (the harmonic one by FFT).

use hi_compare::CurveKind;
use hi_curve::ControlPoint;
use serde::Serialize;

use crate::cli::SampleArgs;
use crate::error::{Failure, context};
use crate::input::{Points, read_points};
use crate::output::{Json, PointList, json};

/// `{"X": [...]}` with X(l/N) for l = 0, …, N − 1 (closed kinds) or X(l/(N − 1)) (open kinds).
///
/// # Errors
///
/// [`Failure::Input`] for bad input, too few points for the kind, or N > 2²⁸.
pub(crate) fn run(args: &SampleArgs) -> Result<Json, Failure> {
    match read_points(&args.input.input)? {
        Points::One(p) => sample(p, args.kind, args.count),
        Points::Two(p) => sample(p, args.kind, args.count),
        Points::Three(p) => sample(p, args.kind, args.count),
    }
}

fn sample<P: ControlPoint>(points: Vec<P>, kind: CurveKind, count: usize) -> Result<Json, Failure> {
    let samples = kind.build(points)?.sample(count).map_err(context("--count"))?;
    /// `{"X": [...]}`.
    #[derive(Serialize)]
    #[serde(bound = "P: ControlPoint")]
    struct Samples<'a, P: ControlPoint> {
        #[serde(rename = "X")]
        x: PointList<'a, P>,
    }
    json(&Samples { x: PointList(&samples) })
}
