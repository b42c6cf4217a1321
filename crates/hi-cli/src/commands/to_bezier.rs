// SPDX-License-Identifier: MIT
//! `hi curve to-bezier`: the piecewise Bézier form of a piecewise polynomial curve.

use hi_curve::ControlPoint;
use hi_curve::compare::CurveKind;

use crate::cli::ToBezierArgs;
use crate::error::Failure;
use crate::input::{Points, read_points};
use crate::output::{Json, Object};

/// `{"segments": [[p0, p1, p2, p3], ...]}`: the control points of each Bézier segment.
///
/// # Errors
///
/// [`Failure::Input`] for bad input, too few points for the kind, or a kind that is not
/// piecewise polynomial.
pub(crate) fn run(args: &ToBezierArgs) -> Result<Json, Failure> {
    match read_points(&args.input.input)? {
        Points::One(p) => to_bezier(p, args.kind),
        Points::Two(p) => to_bezier(p, args.kind),
        Points::Three(p) => to_bezier(p, args.kind),
    }
}

fn to_bezier<P: ControlPoint>(points: Vec<P>, kind: CurveKind) -> Result<Json, Failure> {
    let bezier = kind.build(points)?.to_bezier().map_err(|e| Failure::input(e.to_string()))?;
    let segments = bezier.segments().iter().map(|s| Json::points(s.control_points())).collect();
    Ok(Object::new().field("segments", Json::Array(segments)).build())
}
