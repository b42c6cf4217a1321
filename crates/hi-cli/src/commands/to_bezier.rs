// SPDX-License-Identifier: MIT
//! `hi curve to-bezier`: the piecewise Bézier form of a piecewise polynomial curve.

use hi_compare::CurveKind;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_curve::{ControlPoint, HarmonicCurve};

use crate::cli::ToBezierArgs;
use crate::error::Failure;
use crate::input::{Points, read_points};
use crate::output::{Json, Object};

/// `{"segments": [[p0, p1, p2, p3], ...]}`: the control points of each Bézier segment; for
/// the harmonic curve also `"breaks"` (the segments' parameter windows) and `"report"`.
///
/// # Errors
///
/// [`Failure::Input`] for bad input, too few points for the kind, a kind that is not
/// piecewise polynomial, or `--scheme`/`--tolerance` with a kind other than harmonic.
pub(crate) fn run(args: &ToBezierArgs) -> Result<Json, Failure> {
    if args.kind != CurveKind::Harmonic && (args.scheme.is_some() || args.tolerance.is_some()) {
        return Err(Failure::Input(
            "--scheme and --tolerance apply to --kind harmonic only (the other kinds convert exactly)"
                .into(),
        ));
    }
    if args.kind == CurveKind::Harmonic {
        let scheme = args.scheme.unwrap_or(BezierScheme::Hermite(HermiteDegree::Cubic));
        return match read_points(&args.input.input)? {
            Points::One(p) => harmonic(p, scheme, args.tolerance),
            Points::Two(p) => harmonic(p, scheme, args.tolerance),
            Points::Three(p) => harmonic(p, scheme, args.tolerance),
        };
    }
    match read_points(&args.input.input)? {
        Points::One(p) => to_bezier(p, args.kind),
        Points::Two(p) => to_bezier(p, args.kind),
        Points::Three(p) => to_bezier(p, args.kind),
    }
}

/// The harmonic curve by a §5.7 scheme, with its breaks and report.
fn harmonic<P: ControlPoint>(
    points: Vec<P>,
    scheme: BezierScheme,
    tolerance: Option<f64>,
) -> Result<Json, Failure> {
    let curve = HarmonicCurve::try_new(points).map_err(|e| Failure::input(e.to_string()))?;
    let b = curve
        .to_bezier(
            scheme,
            tolerance
                .map_or(hi_curve::bezier::DEFAULT_TOLERANCE, hi_curve::bezier::Tolerance::Absolute),
        )
        .map_err(|e| Failure::input(e.to_string()))?;
    let segments = b.spline.segments().iter().map(|s| Json::points(s.control_points())).collect();
    let r = b.report;
    let report = Object::new()
        .field("scheme", Json::String(scheme.name().to_owned()))
        .field("pieces", Json::Count(r.pieces))
        .field("degree", Json::Count(r.degree))
        .field("max_deviation", Json::Number(r.max_deviation))
        .field("rms_deviation", Json::Number(r.rms_deviation))
        .field("bound", Json::Number(r.bound))
        .field("max_tangent_jump", Json::Number(r.max_tangent_jump))
        .build();
    Ok(Object::new()
        .field("segments", Json::Array(segments))
        .field("breaks", Json::numbers(b.spline.breaks().iter().copied()))
        .field("report", report)
        .build())
}

fn to_bezier<P: ControlPoint>(points: Vec<P>, kind: CurveKind) -> Result<Json, Failure> {
    let bezier = kind.build(points)?.to_bezier().map_err(|e| Failure::input(e.to_string()))?;
    let segments = bezier.segments().iter().map(|s| Json::points(s.control_points())).collect();
    Ok(Object::new().field("segments", Json::Array(segments)).build())
}
