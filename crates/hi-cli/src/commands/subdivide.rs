// SPDX-License-Identifier: MIT
//! `hi curve subdivide`: harmonic subdivision (§5.2).

use hi_curve::{ControlPoint, HarmonicCurve};

use crate::cli::SubdivideArgs;
use crate::error::{Failure, context};
use crate::input::{Points, read_points};
use crate::output::{Json, PointList, PointsOutput, json};

/// `{"points": [...]}`: the n·2ᴸ points after L levels.
///
/// # Errors
///
/// [`Failure::Input`] for bad input or n·2ᴸ > 2²⁸.
pub(crate) fn run(args: &SubdivideArgs) -> Result<Json, Failure> {
    match read_points(&args.input.input)? {
        Points::One(p) => subdivide(p, args.levels),
        Points::Two(p) => subdivide(p, args.levels),
        Points::Three(p) => subdivide(p, args.levels),
    }
}

fn subdivide<P: ControlPoint>(points: Vec<P>, levels: u32) -> Result<Json, Failure> {
    let curve = HarmonicCurve::try_new(points)?.subdivide(levels).map_err(context("--levels"))?;
    json(&PointsOutput { points: PointList(curve.points()) })
}
