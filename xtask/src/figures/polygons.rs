// SPDX-License-Identifier: MIT
//! Figures 3.7–3.12 and 3.15–3.18: harmonic interpolation of closed polygons beside METAPOST
//! (Hobby's closed curve, §2.14) and periodic cubic B-spline interpolation (§2.11), their
//! curvature plots (§3.5), and the fairness table of those curves.
//!
//! All three curves pass through xₖ at t = k/n here (METAPOST's time and the uniform spline
//! parameters scaled to [0, 1]), so the curvature plots share their parameter axis; the thesis
//! leaves that axis unmarked because its curves used different parameters.

use anyhow::Result;
use glam::DVec2;
use hi_compare::bspline_interp::{InterpolatingSpline, Parameters};
use hi_compare::fairness::{curvature_plot, fairness};
use hi_compare::hobby::{HobbyCurve, HobbyOptions};
use hi_curve::{HarmonicCurve, ParamCurve};

use super::curves::{closed, data_plot};
use super::data;
use super::plot::{BLUE, GREEN, INK, Marker, Pen, Plot, VERMILION, render_row};
use super::{Figure, Format, Panel, Table};

/// Samples of a curvature plot over one period.
const CURVATURE_SAMPLES: usize = 1200;

/// Samples behind the fairness numbers of the table.
const FAIRNESS_SAMPLES: usize = 8192;

/// The polygons of the figures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Polygon {
    /// Four points on a circle (figures 3.7, 3.8, 3.15).
    Circle,
    /// Seven points (3.9, 3.10, 3.16).
    Seven,
    /// Five points (3.11, 3.12, 3.17).
    Five,
    /// Eight points (3.18).
    Eight,
}

impl Polygon {
    const ALL: [Polygon; 4] = [Polygon::Circle, Polygon::Seven, Polygon::Five, Polygon::Eight];

    fn points(self) -> Vec<DVec2> {
        match self {
            Polygon::Circle => data::plane(&data::SQUARE),
            Polygon::Seven => data::plane(&data::HEPTAGON),
            Polygon::Five => data::plane(&data::PENTAGON),
            Polygon::Eight => data::plane(&data::OCTAGON),
        }
    }

    const fn name(self) -> &'static str {
        match self {
            Polygon::Circle => "circle (square, 4 points)",
            Polygon::Seven => "heptagon (7 points)",
            Polygon::Five => "pentagon (5 points)",
            Polygon::Eight => "octagon (8 points)",
        }
    }
}

/// The curves through a polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Method {
    /// The uniform harmonic curve.
    Harmonic,
    /// Periodic cubic B-spline interpolation with uniform parameters.
    BSpline,
    /// METAPOST's closed curve `z₀..z₁..…..cycle`.
    Metapost,
}

impl Method {
    const ALL: [Method; 3] = [Method::Harmonic, Method::BSpline, Method::Metapost];

    const fn name(self) -> &'static str {
        match self {
            Method::Harmonic => "harmonic",
            Method::BSpline => "periodic B-spline",
            Method::Metapost => "METAPOST (Hobby, closed)",
        }
    }

    /// The curve through `points`.
    fn curve(self, points: &[DVec2]) -> Result<Box<dyn ParamCurve<DVec2>>> {
        Ok(match self {
            Method::Harmonic => Box::new(HarmonicCurve::try_new(points.to_vec())?),
            Method::BSpline => {
                Box::new(InterpolatingSpline::try_periodic(points.to_vec(), Parameters::Uniform)?)
            }
            Method::Metapost => {
                Box::new(HobbyCurve::try_new(points.to_vec(), &HobbyOptions::closed())?)
            }
        })
    }
}

const STAND_IN_SQUARE: &str =
    "stand-in: the square (four points on the unit circle; the thesis's labels match it).";
const STAND_IN_HEPTAGON: &str = "stand-in: the heptagon.";
const STAND_IN_PENTAGON: &str =
    "stand-in: the pentagon (its harmonic curve has a cusp near x₃, as the thesis's does).";
const STAND_IN_OCTAGON: &str = "stand-in: the octagon.";

const METAPOST_DRAWN: &str = "(a) METAPOST's closed curve through the points (`HobbyCurve`, tension 1, \
                              matching `mpost` to 1e-9), its Bézier control polygon faint as in the thesis; \
                              (b) the harmonic curve. The data polygon is dashed; both panels at one scale.";
const BSPLINE_DRAWN: &str = "(a) periodic cubic B-spline interpolation with uniform parameters (`InterpolatingSpline::try_periodic`, \
                             the cyclic system of §2.11, matching scipy to 1e-9), its B-spline control polygon faint; \
                             (b) the harmonic curve. The data polygon is dashed; both panels at one scale.";
const CURVATURE_DRAWN: &str = "Each panel: the curve, and its signed curvature κ(t) over one period (positive where it turns left), \
                               with the minimum and maximum written on the plot; (a) harmonic, (b) periodic cubic B-spline \
                               interpolation (uniform parameters). Unlike the thesis the t axis is marked: both curves pass \
                               through xₖ at t = k/n (faint guides). A ring marks where |κ| is largest. Both panels are drawn at one scale; \
                               where |κ| spans decades (a near-cusp) the κ axis is a symmetric logarithm, \
                               sign κ · log₁₀(1 + |κ|/c) with c the median |κ|.";

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (3, 7),
        caption: "A circle drawn by METAPOST and harmonic interpolation",
        drawn: "(a) METAPOST's closed curve through the four points (`HobbyCurve`), its Bézier control polygon faint: \
                four cubic pieces, close to the circle but not a circle; (b) the harmonic curve, exactly the circumcircle.",
        data: STAND_IN_SQUARE,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) METAPOST",
                draw: |t| side(t, Polygon::Circle, Method::Metapost, Method::Harmonic),
            },
            Panel {
                suffix: "b",
                title: "(b) Harmonic interpolation",
                draw: |t| side(t, Polygon::Circle, Method::Harmonic, Method::Metapost),
            },
        ],
    },
    Figure {
        number: (3, 8),
        caption: "A circle drawn by B-spline and harmonic interpolation",
        drawn: BSPLINE_DRAWN,
        data: STAND_IN_SQUARE,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) B-spline",
                draw: |t| side(t, Polygon::Circle, Method::BSpline, Method::Harmonic),
            },
            Panel {
                suffix: "b",
                title: "(b) Harmonic interpolation",
                draw: |t| side(t, Polygon::Circle, Method::Harmonic, Method::BSpline),
            },
        ],
    },
    Figure {
        number: (3, 9),
        caption: "A 7 sided polygon drawn by METAPOST and harmonic interpolation",
        drawn: METAPOST_DRAWN,
        data: STAND_IN_HEPTAGON,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) METAPOST",
                draw: |t| side(t, Polygon::Seven, Method::Metapost, Method::Harmonic),
            },
            Panel {
                suffix: "b",
                title: "(b) Harmonic interpolation",
                draw: |t| side(t, Polygon::Seven, Method::Harmonic, Method::Metapost),
            },
        ],
    },
    Figure {
        number: (3, 10),
        caption: "A 7 sided polygon drawn by B-spline and harmonic interpolation",
        drawn: BSPLINE_DRAWN,
        data: STAND_IN_HEPTAGON,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) B-spline",
                draw: |t| side(t, Polygon::Seven, Method::BSpline, Method::Harmonic),
            },
            Panel {
                suffix: "b",
                title: "(b) Harmonic interpolation",
                draw: |t| side(t, Polygon::Seven, Method::Harmonic, Method::BSpline),
            },
        ],
    },
    Figure {
        number: (3, 11),
        caption: "A 5 sided polygon drawn by METAPOST and harmonic interpolation",
        drawn: METAPOST_DRAWN,
        data: STAND_IN_PENTAGON,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) METAPOST",
                draw: |t| side(t, Polygon::Five, Method::Metapost, Method::Harmonic),
            },
            Panel {
                suffix: "b",
                title: "(b) Harmonic interpolation",
                draw: |t| side(t, Polygon::Five, Method::Harmonic, Method::Metapost),
            },
        ],
    },
    Figure {
        number: (3, 12),
        caption: "A 5 sided polygon drawn by B-spline and harmonic interpolation",
        drawn: BSPLINE_DRAWN,
        data: STAND_IN_PENTAGON,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) B-spline",
                draw: |t| side(t, Polygon::Five, Method::BSpline, Method::Harmonic),
            },
            Panel {
                suffix: "b",
                title: "(b) Harmonic interpolation",
                draw: |t| side(t, Polygon::Five, Method::Harmonic, Method::BSpline),
            },
        ],
    },
    Figure {
        number: (3, 15),
        caption: "Curvature plot of figure 3.8",
        drawn: CURVATURE_DRAWN,
        data: STAND_IN_SQUARE,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Harmonic interpolation",
                draw: |t| curvature(t, Polygon::Circle, Method::Harmonic, Method::BSpline),
            },
            Panel {
                suffix: "b",
                title: "(b) B-spline",
                draw: |t| curvature(t, Polygon::Circle, Method::BSpline, Method::Harmonic),
            },
        ],
    },
    Figure {
        number: (3, 16),
        caption: "Curvature plot of figure 3.10",
        drawn: CURVATURE_DRAWN,
        data: STAND_IN_HEPTAGON,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Harmonic interpolation",
                draw: |t| curvature(t, Polygon::Seven, Method::Harmonic, Method::BSpline),
            },
            Panel {
                suffix: "b",
                title: "(b) B-spline",
                draw: |t| curvature(t, Polygon::Seven, Method::BSpline, Method::Harmonic),
            },
        ],
    },
    Figure {
        number: (3, 17),
        caption: "Curvature plot of figure 3.12",
        drawn: CURVATURE_DRAWN,
        data: STAND_IN_PENTAGON,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Harmonic interpolation",
                draw: |t| curvature(t, Polygon::Five, Method::Harmonic, Method::BSpline),
            },
            Panel {
                suffix: "b",
                title: "(b) B-spline",
                draw: |t| curvature(t, Polygon::Five, Method::BSpline, Method::Harmonic),
            },
        ],
    },
    Figure {
        number: (3, 18),
        caption: "Curvature plot of an eight sided figure",
        drawn: CURVATURE_DRAWN,
        data: STAND_IN_OCTAGON,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Harmonic interpolation",
                draw: |t| curvature(t, Polygon::Eight, Method::Harmonic, Method::BSpline),
            },
            Panel {
                suffix: "b",
                title: "(b) B-spline",
                draw: |t| curvature(t, Polygon::Eight, Method::BSpline, Method::Harmonic),
            },
        ],
    },
];

/// The tables of this module.
pub(crate) const TABLES: &[Table] = &[Table {
    anchor: "fairness",
    title: "Fairness of the polygon curves",
    about: "The fairness measures of §2.15 and §3.5 (`hi_compare::fairness`) for the closed polygons of \
            figures 3.7–3.18, each through the harmonic curve, periodic cubic B-spline interpolation (uniform \
            parameters) and METAPOST's closed curve: the largest |κ|, the number of monotone pieces of κ around \
            the cycle (fewer is fairer; constant κ is 1), the bending energy ∫κ² ds over one period, and the \
            confinement, the area of the curve's convex hull over that of the points (1 would be the polygon's \
            hull; interpolating curves bulge out). From 8192 samples per curve. The curves differ in length, so \
            energies compare shapes of similar size only. The harmonic curve through the pentagon has a near-cusp at x₃ \
            (|X′| almost 0, marked): its largest |κ| and bending energy are huge but finite, and the globally \
            adaptive quadrature resolves them (an energy whose estimated error exceeds 10⁻⁶ of it would be shown \
            with ± that error).",
    make: fairness_table,
}];

/// The faint control polygon of `method`'s curve through `points`, if it has one: METAPOST's
/// Bézier control points (knot, post-control, pre-control, next knot, …) or the periodic
/// spline's B-spline control points, closed.
fn control_polygon(method: Method, points: &[DVec2]) -> Result<Option<Vec<DVec2>>> {
    Ok(match method {
        Method::Harmonic => None,
        Method::Metapost => {
            let curve = HobbyCurve::try_new(points.to_vec(), &HobbyOptions::closed())?;
            let knots = curve.knots();
            let mut polygon = Vec::with_capacity(3 * knots.len() + 1);
            for (k, knot) in knots.iter().enumerate() {
                let next = &knots[(k + 1) % knots.len()];
                polygon.extend([knot.point, knot.postcontrol, next.precontrol]);
            }
            polygon.push(knots[0].point);
            Some(polygon)
        }
        Method::BSpline => {
            let curve = InterpolatingSpline::try_periodic(points.to_vec(), Parameters::Uniform)?;
            let mut polygon = curve.spline().control_points().to_vec();
            polygon.push(polygon[0]);
            Some(polygon)
        }
    })
}

/// The pen a method's curve is drawn with.
const fn pen(method: Method) -> Pen {
    match method {
        Method::Harmonic => Pen::solid(BLUE),
        Method::BSpline => Pen::solid(GREEN),
        Method::Metapost => Pen::solid(VERMILION),
    }
}

/// The plane plot of `method`'s curve through `polygon`, with its control polygon faint.
fn curve_plot(title: &str, polygon: Polygon, method: Method) -> Result<Plot> {
    let points = polygon.points();
    let curve = method.curve(&points)?;
    let mut plot = data_plot(title, &points);
    if let Some(control) = control_polygon(method, &points)? {
        plot = plot.control_polygon(&control, &points);
    }
    Ok(plot.curve(closed(|t| curve.eval(t)), pen(method), None))
}

/// Figures 3.7–3.12: one panel, `method`'s curve through `polygon`, at the scale of the
/// figure's other panel (`partner`'s curve) so that the two compare.
fn side(title: &str, polygon: Polygon, method: Method, partner: Method) -> Result<Vec<u8>> {
    let other = curve_plot("", polygon, partner)?;
    curve_plot(title, polygon, method)?.include(&other.extent()).render()
}

/// Samples (t, κ(t)) of a curvature plot, `None` where the curve is singular.
type KappaGraph = Vec<(f64, Option<f64>)>;

/// The signed curvature of `curve` (`method`'s through `polygon`) over one period, closed (the
/// first sample again at t = 1; `None` where it is singular), and its least and largest values.
fn kappa_graph(
    curve: &dyn ParamCurve<DVec2>,
    polygon: Polygon,
    method: Method,
) -> Result<(KappaGraph, f64, f64)> {
    let samples = curvature_plot(curve, CURVATURE_SAMPLES)?;
    let mut graph: Vec<(f64, Option<f64>)> = samples.iter().map(|s| (s.t, s.curvature)).collect();
    graph.push((1.0, samples[0].curvature));
    let kappas = graph.iter().filter_map(|&(_, k)| k);
    let lo = kappas.clone().fold(f64::INFINITY, f64::min);
    let hi = kappas.fold(f64::NEG_INFINITY, f64::max);
    if !(lo.is_finite() && hi.is_finite()) {
        anyhow::bail!("{} through the {}: no curvature", method.name(), polygon.name());
    }
    Ok((graph, lo, hi))
}

/// The κ axis of a curvature figure: linear, or a symmetric logarithm where the values span
/// decades (a near-cusp), y = sign κ · log₁₀(1 + |κ|/c) with c the median |κ|.
#[derive(Clone, Copy, Debug)]
enum KappaAxis {
    Linear,
    SymLog(f64),
}

impl KappaAxis {
    /// The axis for curvatures `values` (both panels'): a symmetric log when the largest |κ|
    /// is over 100 times the median.
    fn for_values(values: &[f64]) -> Self {
        let mut abs: Vec<f64> = values.iter().map(|k| k.abs()).collect();
        abs.sort_by(f64::total_cmp);
        let median = abs.get(abs.len() / 2).copied().unwrap_or(0.0);
        let max = abs.last().copied().unwrap_or(0.0);
        if median > 0.0 && max > 100.0 * median { Self::SymLog(median) } else { Self::Linear }
    }

    /// The plotted height of κ.
    fn map(self, k: f64) -> f64 {
        match self {
            Self::Linear => k,
            Self::SymLog(c) => k.signum() * (k.abs() / c).ln_1p() / std::f64::consts::LN_10,
        }
    }

    /// For the symmetric log: ticks at 0 and ±10ʲ in `(lo, hi)` (κ values), labelled.
    /// The range from `lo` to `hi` (lo ≤ 0 ≤ hi), on a symmetric logarithm widened to the
    /// next power of ten beyond each end that passes the linear part (|κ| above c); as it is
    /// on a linear axis.
    fn rounded_out(self, lo: f64, hi: f64) -> (f64, f64) {
        let Self::SymLog(c) = self else { return (lo, hi) };
        let out = |v: f64| {
            if v.abs() <= c { v } else { v.signum() * 10f64.powf(v.abs().log10().ceil()) }
        };
        (out(lo), out(hi))
    }

    fn ticks(self, lo: f64, hi: f64) -> Option<Vec<(f64, String)>> {
        let Self::SymLog(c) = self else { return None };
        let mut ticks = vec![(0.0, "0".to_owned())];
        // Powers of ten from c up: below c the axis is nearly linear and they would crowd 0.
        let first = c.log10().ceil() as i32;
        for j in first..=hi.abs().max(lo.abs()).log10().ceil() as i32 {
            let v = 10f64.powi(j);
            let label =
                if (-2..=2).contains(&j) { format!("{v}") } else { format!("10{}", sup(j)) };
            if v <= hi {
                ticks.push((self.map(v), label.clone()));
            }
            if -v >= lo {
                ticks.push((self.map(-v), format!("−{label}")));
            }
        }
        ticks.sort_by(|a, b| a.0.total_cmp(&b.0));
        Some(ticks)
    }
}

/// `j` in Unicode superscript digits.
fn sup(j: i32) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = if j < 0 { "⁻".to_owned() } else { String::new() };
    for d in j.unsigned_abs().to_string().bytes() {
        s.push(DIGITS[usize::from(d - b'0')]);
    }
    s
}

/// Figures 3.15–3.18: `method`'s curve through `polygon` beside its curvature plot, the
/// minimum and maximum of κ written on the plot; both drawn at the scale of the figure's other
/// panel (`partner`'s), the κ axis a symmetric logarithm where the values span decades.
fn curvature(title: &str, polygon: Polygon, method: Method, partner: Method) -> Result<Vec<u8>> {
    let points = polygon.points();
    let curve = method.curve(&points)?;
    let (graph, lo, hi) = kappa_graph(curve.as_ref(), polygon, method)?;
    let other = partner.curve(&points)?;
    let (other_graph, other_lo, other_hi) = kappa_graph(other.as_ref(), polygon, partner)?;
    let both: Vec<f64> = graph.iter().chain(&other_graph).filter_map(|&(_, k)| k).collect();
    let axis = KappaAxis::for_values(&both);
    // The largest |κ|, marked on both plots.
    let peak = graph.iter().filter_map(|&(t, k)| k.map(|k| (t, k))).fold(
        (0.0, 0.0),
        |best: (f64, f64), (t, k)| if k.abs() > best.1.abs() { (t, k) } else { best },
    );

    let constant = hi - lo <= 1e-9 * hi.abs().max(1.0);
    let partner_shape = curve_plot("curve", polygon, partner)?;
    let mut shape = curve_plot("curve", polygon, method)?.include(&partner_shape.extent());
    if !constant {
        shape = shape.points(&[curve.eval(peak.0)], Marker::ring(INK), None);
    }

    // One κ range for both panels; on a logarithmic axis, out to the next power of ten each
    // way, so that the values have a labelled tick above (and below) them.
    let (k0, k1) = axis.rounded_out(lo.min(other_lo).min(0.0), hi.max(other_hi).max(0.0));
    let (y0, y1) = (axis.map(k0), axis.map(k1));
    let pad = 0.1 * (y1 - y0).max(1e-3 * y1.abs().max(y0.abs()).max(1.0));
    let heading = if matches!(axis, KappaAxis::SymLog(_)) {
        "signed curvature κ(t), symmetric log scale"
    } else {
        "signed curvature κ(t)"
    };
    let mut plot =
        Plot::function(heading, "t", "κ").x_range(0.0, 1.0).y_range(y0 - pad, y1 + pad).hguide(0.0);
    if let Some(ticks) = axis.ticks(k0, k1) {
        plot = plot.y_ticks(ticks);
    }
    let n = points.len();
    for k in 1..n {
        plot = plot.vguide(k as f64 / n as f64);
    }
    // One line per run of regular samples (a cusp breaks the line).
    let mut run = Vec::new();
    for &(t, k) in &graph {
        if let Some(k) = k {
            run.push(DVec2::new(t, axis.map(k)));
        } else if !run.is_empty() {
            plot = plot.curve(std::mem::take(&mut run), pen(method), None);
        }
    }
    if !run.is_empty() {
        plot = plot.curve(run, pen(method), None);
    }
    if !constant {
        plot = plot.points(&[DVec2::new(peak.0, axis.map(peak.1))], Marker::ring(INK), None);
    }
    // The extremes, written at the right end of their guide lines (the left end if the
    // curve is there).
    let at_x = |value: f64| {
        let near_right = graph.iter().rev().take(CURVATURE_SAMPLES / 8).any(|&(_, k)| {
            k.is_some_and(|k| (axis.map(k) - value).abs() < 0.08 * (y1 - y0 + 2.0 * pad))
        });
        if near_right { 0.14 } else { 0.86 }
    };
    let (hi_y, lo_y) = (axis.map(hi), axis.map(lo));
    if constant {
        plot = plot.hguide(hi_y).note(
            DVec2::new(0.5, hi_y),
            &format!("κ = {} (constant)", fixed(hi)),
            (0.0, 12.0),
            INK,
        );
    } else {
        plot = plot
            .hguide(hi_y)
            .hguide(lo_y)
            .note(DVec2::new(at_x(hi_y), hi_y), &format!("max κ = {}", fixed(hi)), (0.0, 11.0), INK)
            .note(
                DVec2::new(at_x(lo_y), lo_y),
                &format!("min κ = {}", fixed(lo)),
                (0.0, -11.0),
                INK,
            );
    }
    render_row(title, &[&shape, &plot])
}

/// A curvature value for a label: three significant digits, at most two decimals for large
/// values, and as "9.01·10⁵" from 10⁴ on (a near-cusp) rather than a row of digits.
fn fixed(v: f64) -> String {
    if v.abs() >= 1e4 {
        let s = scientific(v, 2);
        return if s.starts_with('-') { s.replacen('-', "−", 1) } else { s };
    }
    let digits = if v.abs() >= 100.0 {
        0
    } else if v.abs() >= 10.0 {
        1
    } else {
        2
    };
    let s = format!("{v:.digits$}");
    if s.starts_with('-') { s.replacen('-', "−", 1) } else { s }
}

/// |κ| times the size of the curve above which a curve counts as having a cusp.
const CUSP: f64 = 1e3;

/// The largest sampled |κ| of `curve` if it has a (near) cusp: |κ| above [`CUSP`] over its
/// size, or a singular sample.
fn near_cusp(curve: &dyn ParamCurve<DVec2>) -> Result<Option<f64>> {
    let plot = curvature_plot(curve, FAIRNESS_SAMPLES)?;
    let mut peak: f64 = 0.0;
    let mut singular = false;
    for s in &plot {
        match s.curvature {
            Some(k) => peak = peak.max(k.abs()),
            None => singular = true,
        }
    }
    Ok((singular || peak * curve.scale() > CUSP).then_some(peak))
}

/// `v` with 4 decimals, or as "2.5·10⁶" from 10⁴ on.
fn number(v: f64) -> String {
    if v.abs() >= 1e4 { scientific(v, 1) } else { format!("{v:.4}") }
}

/// `v` as "2.5·10⁶", the mantissa with `decimals` decimals.
fn scientific(v: f64, decimals: usize) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut exponent = v.abs().log10().floor() as i32;
    let mut mantissa = v / 10f64.powi(exponent);
    // 9.996·10⁵ to two decimals is 1.00·10⁶, not 10.00·10⁵.
    let unit = 10f64.powi(i32::try_from(decimals).unwrap_or(i32::MAX).min(15));
    if (mantissa.abs() * unit).round() >= 10.0 * unit {
        exponent += 1;
        mantissa /= 10.0;
    }
    let power: String = exponent
        .to_string()
        .bytes()
        .map(|d| if d == b'-' { '⁻' } else { DIGITS[usize::from(d - b'0')] })
        .collect();
    format!("{mantissa:.decimals$}·10{power}")
}

/// The fairness table: one row per polygon and curve.
fn fairness_table() -> Result<String> {
    let mut s = String::from(
        "| polygon | curve | max \\|κ\\| | monotone pieces of κ | bending energy ∫κ² ds | length | confinement |\n\
         |---|---|---:|---:|---:|---:|---:|\n",
    );
    for polygon in Polygon::ALL {
        let points = polygon.points();
        for method in Method::ALL {
            let curve = method.curve(&points)?;
            let f = fairness(curve.as_ref(), &points, FAIRNESS_SAMPLES)?;
            let cusp = if near_cusp(curve.as_ref())?.is_some() { " (near-cusp)" } else { "" };
            let confinement = f.confinement.map_or_else(|| "–".to_owned(), |c| format!("{c:.4}"));
            let energy = if f.bending_energy_error > 1e-6 * f.bending_energy {
                format!("{} ± {}", number(f.bending_energy), number(f.bending_energy_error))
            } else {
                number(f.bending_energy)
            };
            let row = format!(
                "| {}{cusp} | {} | {energy} | {:.4} | {} |",
                number(f.max_curvature),
                f.monotone_pieces,
                f.length,
                confinement
            );
            s.push_str(&format!("| {} | {} {row}\n", polygon.name(), method.name()));
        }
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_harmonic_circle_has_constant_curvature_in_the_table() {
        // Four points on the unit circle: the harmonic curve is the circle itself, κ ≡ 1,
        // one monotone piece, energy 2π, hull area π over the square's 2.
        let points = Polygon::Circle.points();
        let curve = Method::Harmonic.curve(&points).expect("a curve");
        let f = fairness(curve.as_ref(), &points, FAIRNESS_SAMPLES).expect("fairness");
        assert!((f.max_curvature - 1.0).abs() < 1e-12, "{f:?}");
        assert_eq!(f.monotone_pieces, 1, "{f:?}");
        assert!((f.bending_energy - std::f64::consts::TAU).abs() < 1e-10, "{f:?}");
        let confinement = f.confinement.expect("the square has area");
        assert!((confinement - std::f64::consts::FRAC_PI_2).abs() < 1e-6, "{f:?}");
        // The piecewise cubic curves only approximate the circle: their curvature varies.
        for method in [Method::BSpline, Method::Metapost] {
            let other = method.curve(&points).expect("a curve");
            let g = fairness(other.as_ref(), &points, FAIRNESS_SAMPLES).expect("fairness");
            assert!(g.max_curvature > 1.0 && g.monotone_pieces > 1, "{method:?}: {g:?}");
        }
    }

    #[test]
    fn curvature_labels_are_short() {
        assert_eq!(fixed(901_314.2), "9.01·10⁵");
        assert_eq!(fixed(-12_345.0), "−1.23·10⁴");
        assert_eq!(fixed(999_700.0), "1.00·10⁶");
        assert_eq!(fixed(-12.61), "−12.6");
        assert_eq!(fixed(0.784), "0.78");
        assert_eq!(fixed(250.4), "250");
    }

    #[test]
    fn the_table_has_a_row_per_polygon_and_curve() {
        let table = fairness_table().expect("the table");
        assert_eq!(table.lines().count(), 2 + Polygon::ALL.len() * Method::ALL.len(), "{table}");
        assert!(
            table.contains("| circle (square, 4 points) | harmonic | 1.0000 | 1 | 6.2832 |"),
            "{table}"
        );
    }
}
