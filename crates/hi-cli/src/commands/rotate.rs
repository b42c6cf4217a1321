// SPDX-License-Identifier: MIT
//! `hi curve rotate`: Theorem 5.1, or the exact rotation.

use hi_curve::{ControlPoint, HarmonicCurve};

use crate::cli::RotateArgs;
use crate::error::{Failure, context};
use crate::input::{Points, read_points};
use crate::output::{Json, PointList, PointsOutput, json};

/// `{"points": [...]}`: the points of the rotated curve.
///
/// # Errors
///
/// [`Failure::Input`] for bad input.
pub(crate) fn run(args: &RotateArgs) -> Result<Json, Failure> {
    let (offset, exact) = (args.offset, args.exact);
    match read_points(&args.input.input)? {
        Points::One(p) => rotate(p, offset, exact),
        Points::Two(p) => rotate(p, offset, exact),
        Points::Three(p) => rotate(p, offset, exact),
    }
}

fn rotate<P: ControlPoint>(points: Vec<P>, offset: f64, exact: bool) -> Result<Json, Failure> {
    let curve = HarmonicCurve::try_new(points)?;
    let rotated = if exact { curve.rotate(offset) } else { curve.rotate_theorem_5_1(offset) };
    let rotated = rotated.map_err(context("--offset"))?;
    json(&PointsOutput { points: PointList(rotated.points()) })
}
