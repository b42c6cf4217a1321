// SPDX-License-Identifier: MIT
//! `hi curve sample`: uniform samples by FFT.

use hi_curve::{ControlPoint, HarmonicCurve};

use crate::cli::SampleArgs;
use crate::error::{Failure, context};
use crate::input::{Points, read_points};
use crate::output::{Json, Object};

/// `{"X": [...]}` with X(l/N) for l = 0, …, N − 1.
///
/// # Errors
///
/// [`Failure::Input`] for bad input or N > 2²⁸.
pub(crate) fn run(args: &SampleArgs) -> Result<Json, Failure> {
    match read_points(&args.input.input)? {
        Points::One(p) => sample(p, args.count),
        Points::Two(p) => sample(p, args.count),
        Points::Three(p) => sample(p, args.count),
    }
}

fn sample<P: ControlPoint>(points: Vec<P>, count: usize) -> Result<Json, Failure> {
    let samples =
        HarmonicCurve::try_new(points)?.sample_uniform(count).map_err(context("--count"))?;
    Ok(Object::new().field("X", Json::points(&samples)).build())
}
