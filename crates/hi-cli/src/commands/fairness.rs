// SPDX-License-Identifier: MIT
//! `hi curve fairness`: the fairness measures of a plane curve (Hardy 2005, §2.4, §2.15, §3.5).

use hi_compare::fairness::fairness;

use crate::cli::FairnessArgs;
use crate::error::{Failure, context};
use crate::input::{Points, read_points};
use crate::output::{Json, json};

/// `{"max_curvature", "max_curvature_at", "monotone_pieces", "bending_energy",
/// "bending_energy_error", "length",
/// "confinement"}` of the curve of `--kind` through the points.
///
/// # Errors
///
/// [`Failure::Input`] for bad input, points that are not 2-D, too few points for the kind, or
/// fewer than 3 samples.
pub(crate) fn run(args: &FairnessArgs) -> Result<Json, Failure> {
    let points = match read_points(&args.input.input)? {
        Points::Two(p) => p,
        Points::One(_) => return Err(not_planar(1)),
        Points::Three(_) => return Err(not_planar(3)),
    };
    let curve = args.kind.build(points)?;
    let f = fairness(&curve, curve.points(), args.samples).map_err(context("--samples"))?;
    json(&f)
}

fn not_planar(dim: usize) -> Failure {
    Failure::input(format!(
        "the fairness measures need 2-D points (signed curvature, hull areas), got {dim}-D points"
    ))
}
