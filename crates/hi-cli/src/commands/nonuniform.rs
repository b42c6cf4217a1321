// SPDX-License-Identifier: MIT
//! `hi curve nonuniform`: interpolation at non-uniform parameters (§3.10).

use hi_curve::{ControlPoint, Error, NonUniformCurve, chord_length_params};
use serde::Serialize;

use crate::cli::{NonUniformArgs, Variant};
use crate::error::{Failure, context};
use crate::input::{Points, read_points};
use crate::output::{Json, coords, json};

/// `{"params": [...], "X": [...], "condition": c}`, plus `"matrix_condition"` for the thesis
/// variant.
///
/// # Errors
///
/// [`Failure::Input`] for bad input, bad `--params`, coinciding consecutive points (without
/// `--params`) or a singular system (thesis variant).
pub(crate) fn run(args: &NonUniformArgs) -> Result<Json, Failure> {
    let (ts, variant, params) = (&args.t.0, args.variant, args.params.as_ref().map(|p| &p.0[..]));
    match read_points(&args.input.input)? {
        Points::One(p) => nonuniform(p, ts, variant, params),
        Points::Two(p) => nonuniform(p, ts, variant, params),
        Points::Three(p) => nonuniform(p, ts, variant, params),
    }
}

fn nonuniform<P: ControlPoint>(
    points: Vec<P>,
    ts: &[f64],
    variant: Variant,
    params: Option<&[f64]>,
) -> Result<Json, Failure> {
    let curve = match params {
        Some(params) => NonUniformCurve::try_with_params(points, params.to_vec(), variant.into())
            .map_err(|e| match e {
            Error::Singular { .. } => Failure::from(e),
            _ => context("--params")(e),
        })?,
        None => {
            let params = chord_length_params(&points).map_err(chord_length_error)?;
            NonUniformCurve::try_with_params(points, params, variant.into())?
        }
    };
    /// `{"params", "X", "condition"}`, and `"matrix_condition"` for the thesis variant.
    #[derive(Serialize)]
    struct Output<'a> {
        params: &'a [f64],
        #[serde(rename = "X")]
        x: Vec<Vec<f64>>,
        condition: f64,
        #[serde(skip_serializing_if = "Option::is_none")]
        matrix_condition: Option<f64>,
    }
    json(&Output {
        params: curve.params(),
        x: ts.iter().map(|&t| coords(&curve.eval(t))).collect(),
        condition: curve.condition(),
        matrix_condition: curve.matrix_condition(),
    })
}

/// Explains a failure of the chord-length parameters in terms of the points.
fn chord_length_error(e: Error) -> Failure {
    match e {
        Error::CoincidentPoints { first, second } => Failure::input(format!(
            "points {first} and {second} coincide, so their chord-length parameters do too: \
             remove the repeated point or give --params"
        )),
        Error::ZeroLengthPolygon => Failure::input(
            "all points coincide, so chord-length parameters are undefined: give --params",
        ),
        e => Failure::from(e),
    }
}
