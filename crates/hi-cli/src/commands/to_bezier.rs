// SPDX-License-Identifier: MIT
//! `hi curve to-bezier`: the piecewise Bézier form of a piecewise polynomial curve.

use hi_compare::CurveKind;
use hi_curve::bezier::{BezierReport, BezierScheme, HermiteDegree};
use hi_curve::{ControlPoint, HarmonicCurve};

use crate::cli::ToBezierArgs;
use crate::error::Failure;
use crate::input::{Points, read_points};
use serde::Serialize;

use crate::output::{Json, PointList, json};

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
    /// The scheme's name and the conversion's report.
    #[derive(Serialize)]
    struct Report<'a> {
        scheme: &'static str,
        #[serde(flatten)]
        report: &'a BezierReport,
    }
    /// `{"segments", "breaks", "report"}`.
    #[derive(Serialize)]
    #[serde(bound = "P: ControlPoint")]
    struct Output<'a, P: ControlPoint> {
        segments: Vec<PointList<'a, P>>,
        breaks: &'a [f64],
        report: Report<'a>,
    }
    json(&Output {
        segments: b.spline.segments().iter().map(|s| PointList(s.control_points())).collect(),
        breaks: b.spline.breaks(),
        report: Report { scheme: scheme.name(), report: &b.report },
    })
}

fn to_bezier<P: ControlPoint>(points: Vec<P>, kind: CurveKind) -> Result<Json, Failure> {
    let bezier = kind.build(points)?.to_bezier().map_err(|e| Failure::input(e.to_string()))?;
    /// `{"segments"}`.
    #[derive(Serialize)]
    #[serde(bound = "P: ControlPoint")]
    struct Output<'a, P: ControlPoint> {
        segments: Vec<PointList<'a, P>>,
    }
    json(&Output {
        segments: bezier.segments().iter().map(|s| PointList(s.control_points())).collect(),
    })
}
