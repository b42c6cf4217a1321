// SPDX-License-Identifier: MIT
//! Figures 2.1–2.18: the background curves of chapter 2, drawn with `hi-bezier` and
//! `hi_compare`: Lagrange interpolation (§2.4), Bézier curves and their properties
//! (§2.5), B-splines (§2.9–2.11), METAPOST (§2.14), and curvature and torsion (§2.15).

use anyhow::Result;
use glam::{DVec2, DVec3};
use hi_bezier::{Bernstein, BezierCurve, PiecewiseBezier, RationalBezierCurve};
use hi_compare::ParamRange;
use hi_compare::bspline::{BSplineBasis, BSplineCurve};
use hi_compare::bspline_interp::{EndCondition, InterpolatingSpline, Parameters};
use hi_compare::hobby::{HobbyCurve, HobbyOptions};
use hi_compare::lagrange::{LagrangeBasis, LagrangeCurve};
use hi_curve::{ParamCurve, PlaneCurve, SpaceCurve};

use super::data;
use super::plot::{
    BLUE, GREEN, GREY, INK, Legend, Marker, Oblique, PALETTE, Pen, Plot, VERMILION, clear_of_point,
    names, sample, sub,
};
use super::{Figure, Format, Panel};

/// Samples per curve.
const SAMPLES: usize = 600;

const EXACT: &str = "none needed (exact functions).";

/// The view of the helix: turned 30° about z, seen from 20° above.
const HELIX_VIEW: Oblique = Oblique { azimuth: 30.0, elevation: 20.0 };

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (2, 1),
        caption: "Basis functions for uniform Lagrange interpolation of degree 3",
        drawn: "L₀, …, L₃ on the nodes 0, 1, 2, 3 (`LagrangeBasis`), u ∈ [0, 3]; they are cardinal and sum to 1 but go negative.",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: lagrange_basis }],
    },
    Figure {
        number: (2, 2),
        caption: "Uniform Lagrange interpolation of 4 points",
        drawn: "The cubic through x₀, …, x₃ at the nodes 0, 1, 2, 3 (`LagrangeCurve`, Neville's algorithm); the faint dashed line is the polygon.",
        data: "stand-in: the Lagrange quadrilateral (x₀, x₁, x₂ from example 2.1, x₃ chosen).",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: lagrange_curve }],
    },
    Figure {
        number: (2, 3),
        caption: "Basis functions for Bézier curves of degree 3",
        drawn: "The Bernstein polynomials B³₀, …, B³₃ over t ∈ [0, 1] (`hi_bezier::Bernstein`).",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: bernstein }],
    },
    Figure {
        number: (2, 4),
        caption: "A Bézier curve and its convex hull",
        drawn: "(a) the cubic Bézier curve with its control polygon (dashed); (b) the same with the convex hull of the control points \
                (`BezierCurve::control_hull`), which holds the curve.",
        data: "stand-in: the Bézier quadrilateral.",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) The curve", draw: |t| bezier_hull(t, false) },
            Panel { suffix: "b", title: "(b) The convex hull", draw: |t| bezier_hull(t, true) },
        ],
    },
    Figure {
        number: (2, 5),
        caption: "Piecewise continuous Bézier curves: (a) C1, (b) G1 with s = 0.6",
        drawn: "Two cubic pieces p₀…p₃ and s₀…s₃ with s₀ = p₃ (`PiecewiseBezier::c1_chain` and `g1_chain`): (a) s₁ − s₀ = p₃ − p₂; \
                (b) p₃ − p₂ = s(s₁ − s₀) with s = 0.6, the same direction and a longer second arm.",
        data: "stand-in: control points chosen here (p₀ = (0, 0), p₁ = (1, 2), p₂ = (2.5, 2), p₃ = (3, 0.5), s₂ = (5.5, −1.5), s₃ = (6.5, 1)).",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) C1", draw: |t| joins(t, 1.0) },
            Panel { suffix: "b", title: "(b) G1 with s = 0.6", draw: |t| joins(t, 0.6) },
        ],
    },
    Figure {
        number: (2, 6),
        caption: "de Casteljau's method (degree 3, t = 0.3)",
        drawn: "The levels of de Casteljau's scheme at t = 0.3 (`BezierCurve::de_casteljau_levels`): the control polygon dashed, \
                the repeated linear interpolations darker, and the point q(0.3) on the curve.",
        data: "stand-in: the Bézier quadrilateral.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: de_casteljau }],
    },
    Figure {
        number: (2, 7),
        caption: "Subdivision of figure 2.4 into two Bézier curves",
        drawn: "The curve of figure 2.4 split at t = ½ (`BezierCurve::split`, Theorem 2.2): the halves with their control polygons \
                p⁰₀, p¹₀, p²₀, p³₀ and p³₀, p²₁, p¹₂, p⁰₃ (pʳᵢ of eq. 2.6).",
        data: "stand-in: the Bézier quadrilateral.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: split }],
    },
    Figure {
        number: (2, 8),
        caption: "Section of a circle, drawn with a rational Bézier curve",
        drawn: "The rational cubic with x₀ = (0, 1), x₁ = (2, 1), x₂ = (2, −1), x₃ = (0, −1) and weights 1, ⅓, ⅓, 1 \
                (`RationalBezierCurve`): exactly the right half of the unit circle (the full circle faint for comparison).",
        data: "exact: the thesis's control points and weights.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: rational_arc }],
    },
    Figure {
        number: (2, 9),
        caption: "The basis functions of B-splines of degree 3",
        drawn: "The four cubic pieces B₀, …, B₃ of one segment of a uniform cubic B-spline over t ∈ [0, 1] (§2.9), evaluated as \
                N₀, …, N₃ on the span [3, 4] of the uniform basis (`BSplineBasis`).",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: bspline_pieces }],
    },
    Figure {
        number: (2, 10),
        caption: "The blending functions of B-splines of degree 3",
        drawn: "The uniform cubic blending functions N₀, …, N₇ on the knots 0, 1, …, 11 (`BSplineBasis::uniform`), translates of \
                one another, each with support of four intervals; they sum to 1 on the domain [3, 8] (faint guides).",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: blending }],
    },
    Figure {
        number: (2, 11),
        caption: "A Bézier curve of degree 8",
        drawn: "The Bézier curve of the nine control points (`BezierCurve` of degree 8): it follows the polygon only loosely.",
        data: "stand-in: the zigzag.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: degree_eight }],
    },
    Figure {
        number: (2, 12),
        caption: "A B-spline curve of degree 3, using the same control points as figure 2.11",
        drawn: "The uniform cubic B-spline of §2.9 on the nine control points (`BSplineCurve::try_uniform_open`, knots 0, …, 12, \
                six segments); as in the thesis's uniform construction it does not reach x₀ and x₈.",
        data: "stand-in: the zigzag.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: uniform_bspline }],
    },
    Figure {
        number: (2, 13),
        caption: "Interpolation using B-splines",
        drawn: "The open cubic spline through p₀, …, p₈ of §2.11 (`InterpolatingSpline::try_open`, uniform parameters, coincident \
                end control points x₀ = x₁, xₙ = xₙ₋₁ as eq. 2.9), its B-spline control polygon faint.",
        data: "stand-in: the zigzag.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: open_interpolation }],
    },
    Figure {
        number: (2, 14),
        caption: "Periodic interpolation using B-splines",
        drawn: "The periodic cubic spline through x₀, …, x₄ (`InterpolatingSpline::try_periodic`, uniform parameters, the cyclic \
                system of §2.11, checked against scipy), its B-spline control polygon faint.",
        data: "stand-in: the peer pentagon.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: periodic_interpolation }],
    },
    Figure {
        number: (2, 15),
        caption: "Interpolation using METAPOST",
        drawn: "METAPOST's open path x₀..x₁..….x₈ (`HobbyCurve`, curl 1 at the ends, tension 1, checked against `mpost`), \
                its Bézier control polygon faint.",
        data: "stand-in: the zigzag (the points of figure 2.13, as in the thesis).",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| metapost(t, false) }],
    },
    Figure {
        number: (2, 16),
        caption: "Periodic interpolation using METAPOST",
        drawn: "METAPOST's closed path x₀..x₁..….x₄..cycle (`HobbyCurve`), its Bézier control polygon faint.",
        data: "stand-in: the peer pentagon (the points of figure 2.14, as in the thesis).",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| metapost(t, true) }],
    },
    Figure {
        number: (2, 17),
        caption: "The catenary and its curvature",
        drawn: "(a) the catenary x(t) = (t, cosh t), t ∈ [−1.5, 1.5], with its tangent at t = 0.5; (b) its curvature over t ∈ [0, 1] \
                computed by `PlaneCurve::signed_curvature`, on the analytic 1/cosh² t (grey dashed). The thesis's tangent \
                parameter is illegible in the extracted text: t = 0.5 is chosen here.",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Catenary", draw: catenary },
            Panel { suffix: "b", title: "(b) Curvature", draw: catenary_curvature },
        ],
    },
    Figure {
        number: (2, 18),
        caption: "A spiral curve",
        drawn: "The helix (a cos t, a sin t, bt), a = 1, b = 0.15, t ∈ [0, 6π], in an oblique view (turned 30° about z, seen \
                from 20° above) with the axes faint; `SpaceCurve` gives κ = a/(a² + b²) and τ = b/(a² + b²), written on the plot.",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: helix }],
    },
];

/// The points of `set` with the faint open polygon, markers and labels `letter`ₖ.
fn open_plot(title: &str, points: &[DVec2], letter: &str) -> Plot {
    Plot::plane(title).polygon(points, false).points(points, Marker::point(INK), None).labels(
        points,
        names(letter, points.len()),
        false,
    )
}

/// The points with the faint closed polygon, markers and labels xₖ.
fn closed_plot(title: &str, points: &[DVec2]) -> Plot {
    Plot::plane(title).polygon(points, true).points(points, Marker::point(INK), None).labels(
        points,
        names("x", points.len()),
        true,
    )
}

/// A family of functions on one graph, in the palette's colours, named in the legend.
fn family(
    title: &str,
    x_desc: &str,
    range: (f64, f64),
    labels: &[String],
    f: impl Fn(usize, f64) -> f64,
) -> Plot {
    let mut plot = Plot::function(title, x_desc, "y").x_range(range.0, range.1).hguide(0.0);
    for (k, label) in labels.iter().enumerate() {
        let points = sample(range.0, range.1, SAMPLES, |u| DVec2::new(u, f(k, u)));
        plot = plot.curve(points, Pen::solid(PALETTE[k % PALETTE.len()]), Some(label));
    }
    plot
}

/// Figure 2.1.
fn lagrange_basis(title: &str) -> Result<Vec<u8>> {
    let basis = LagrangeBasis::try_new(vec![0.0, 1.0, 2.0, 3.0])?;
    let mut plot = family(title, "u", (0.0, 3.0), &names("L", 4), |k, u| basis.eval(k, u));
    for node in 1..3 {
        plot = plot.vguide(f64::from(node));
    }
    plot.hguide(1.0).legend(Legend::UpperRight).render()
}

/// Figure 2.2.
fn lagrange_curve(title: &str) -> Result<Vec<u8>> {
    let points = data::plane(&data::LAGRANGE);
    let curve = LagrangeCurve::try_new(points.clone())?;
    open_plot(title, &points, "x")
        .curve(sample(0.0, 1.0, SAMPLES, |t| curve.eval(t)), Pen::solid(BLUE), None)
        .render()
}

/// Figure 2.3.
fn bernstein(title: &str) -> Result<Vec<u8>> {
    let b = Bernstein::new(3);
    let labels: Vec<String> = (0..4).map(|k| format!("{}³", sub("B", k))).collect();
    family(title, "t", (0.0, 1.0), &labels, |k, t| b.eval(k, t)).legend(Legend::UpperRight).render()
}

/// The Bézier curve of figures 2.4, 2.6, 2.7.
fn quad_bezier() -> Result<BezierCurve<DVec2>> {
    Ok(BezierCurve::try_new(data::plane(&data::BEZIER))?)
}

/// Figure 2.4: the curve (a), with its convex hull (b).
fn bezier_hull(title: &str, hull: bool) -> Result<Vec<u8>> {
    let curve = quad_bezier()?;
    let points = curve.control_points().to_vec();
    let mut plot = open_plot(title, &points, "x").curve(
        sample(0.0, 1.0, SAMPLES, |t| curve.eval(t)),
        Pen::solid(BLUE),
        None,
    );
    if hull {
        let mut outline = curve.control_hull();
        outline.push(outline[0]);
        plot = plot
            .curve(outline, Pen::solid(GREEN).width(1.5), Some("convex hull"))
            .legend(Legend::LowerRight);
    }
    plot.render()
}

/// Figure 2.5: two cubic pieces joined C1 (s = 1) or G1 with shape factor `s`.
fn joins(title: &str, s: f64) -> Result<Vec<u8>> {
    let first = BezierCurve::try_new(vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 2.0),
        DVec2::new(2.5, 2.0),
        DVec2::new(3.0, 0.5),
    ])?;
    let tail = vec![vec![DVec2::new(5.5, -1.5), DVec2::new(6.5, 1.0)]];
    let chain = if s == 1.0 {
        PiecewiseBezier::c1_chain(first, &tail)?
    } else {
        PiecewiseBezier::g1_chain(first, &tail, s)?
    };
    let mut plot = Plot::plane(title);
    let mut all_points = Vec::new();
    let mut all_names = Vec::new();
    let mut join = None;
    for (segment, (letter, color)) in chain.segments().iter().zip([("p", BLUE), ("s", VERMILION)]) {
        let points = segment.control_points().to_vec();
        plot = plot.polygon(&points, false).curve(
            sample(0.0, 1.0, SAMPLES, |t| segment.eval(t)),
            Pen::solid(color),
            None,
        );
        for (k, &p) in points.iter().enumerate() {
            if letter == "s" && k == 0 {
                continue;
            }
            if letter == "p" && k == 3 {
                // The join: the curve arrives from the upper left and leaves to the lower right,
                // so its name goes to the right, where neither is.
                join = Some(p);
                continue;
            }
            all_points.push(p);
            all_names.push(sub(letter, k));
        }
    }
    let mut plot = plot.labels(&all_points, all_names, false);
    if let Some(p) = join {
        let name = "p₃ = s₀";
        let off = clear_of_point(DVec2::X, name.chars().count());
        plot = plot.points(&[p], Marker::point(INK), None).note(p, name, (off.x, 0.0), INK);
    }
    plot.points(&all_points, Marker::point(INK), None).render()
}

/// Figure 2.6: de Casteljau's construction at t = 0.3.
fn de_casteljau(title: &str) -> Result<Vec<u8>> {
    const T: f64 = 0.3;
    let curve = quad_bezier()?;
    let levels = curve.de_casteljau_levels(T);
    let points = levels[0].clone();
    let mut plot = open_plot(title, &points, "p").curve(
        sample(0.0, 1.0, SAMPLES, |t| curve.eval(t)),
        Pen::solid(BLUE),
        None,
    );
    for (r, level) in levels.iter().enumerate().skip(1) {
        if level.len() > 1 {
            plot = plot.curve(level.clone(), Pen::dashed(INK).width(1.2), None);
        }
        let marker = if level.len() == 1 { Marker::point(VERMILION) } else { Marker::small(INK) };
        plot = plot.points(level, marker, (r == 1).then_some("pʳᵢ(0.3)"));
    }
    let q = levels[levels.len() - 1][0];
    plot.note(q, "q(0.3)", (0.0, -16.0), VERMILION).legend(Legend::LowerRight).render()
}

/// Figure 2.7: the curve of figure 2.4 split at t = ½.
fn split(title: &str) -> Result<Vec<u8>> {
    let curve = quad_bezier()?;
    let (left, right) = curve.split(0.5);
    const SUPER: [char; 4] = ['⁰', '¹', '²', '³'];
    let mut plot = Plot::plane(title);
    let mut points = Vec::new();
    let mut labels = Vec::new();
    for (half, color, right_half) in [(&left, BLUE, false), (&right, VERMILION, true)] {
        let control = half.control_points().to_vec();
        plot = plot.polygon(&control, false).curve(
            sample(0.0, 1.0, SAMPLES, |t| half.eval(t)),
            Pen::solid(color),
            None,
        );
        for (k, &p) in control.iter().enumerate() {
            if right_half && k == 0 {
                continue;
            }
            // Left half: p^k_0; right half: p^{3−k}_k.
            let (r, i) = if right_half { (3 - k, k) } else { (k, 0) };
            points.push(p);
            labels.push(format!("p{}{}", SUPER[r], sub("", i)));
        }
    }
    plot.points(&points, Marker::point(INK), None).labels(&points, labels, false).render()
}

/// Figure 2.8: the rational cubic half circle.
fn rational_arc(title: &str) -> Result<Vec<u8>> {
    let points = vec![
        DVec2::new(0.0, 1.0),
        DVec2::new(2.0, 1.0),
        DVec2::new(2.0, -1.0),
        DVec2::new(0.0, -1.0),
    ];
    let weights = vec![1.0, 1.0 / 3.0, 1.0 / 3.0, 1.0];
    let arc = RationalBezierCurve::try_new(points.clone(), weights)?;
    let labels = ["x₀, w₀ = 1", "x₁, w₁ = ⅓", "x₂, w₂ = ⅓", "x₃, w₃ = 1"];
    let mut plot = Plot::plane(title)
        .faint(sample(0.0, std::f64::consts::TAU, SAMPLES, |a| DVec2::new(a.cos(), a.sin())))
        .polygon(&points, false)
        .curve(sample(0.0, 1.0, SAMPLES, |t| arc.eval(t)), Pen::solid(BLUE), None)
        .points(&points, Marker::point(INK), None);
    for (p, label) in points.iter().zip(labels) {
        let dx = if p.x > 1.0 { -34.0 } else { 0.0 };
        plot = plot.note(*p, label, (dx, 14.0_f64.copysign(p.y)), INK);
    }
    plot.render()
}

/// Figure 2.9: the cubic pieces of one segment.
fn bspline_pieces(title: &str) -> Result<Vec<u8>> {
    let basis = BSplineBasis::uniform(3, 4);
    family(title, "t", (0.0, 1.0), &names("B", 4), |k, t| basis.eval(k, 3.0 + t))
        .legend(Legend::UpperRight)
        .render()
}

/// Figure 2.10: the blending functions, each named at its peak.
fn blending(title: &str) -> Result<Vec<u8>> {
    const N: usize = 8;
    let basis = BSplineBasis::uniform(3, N);
    let ParamRange { start: lo, end: hi } = basis.domain();
    let mut plot = Plot::function(title, "u", "y")
        .x_range(0.0, (N + 3) as f64)
        .y_range(0.0, 1.1)
        .hguide(0.0)
        .vguide(lo)
        .vguide(hi);
    for k in 0..N {
        let points = sample(0.0, (N + 3) as f64, SAMPLES, |u| DVec2::new(u, basis.eval(k, u)));
        let color = PALETTE[k % PALETTE.len()];
        let peak = DVec2::new(k as f64 + 2.0, basis.eval(k, k as f64 + 2.0));
        // A name whose peak lies on a guide of the domain's ends goes beside it, outside the
        // domain, clear of the line.
        let dx = if (peak.x - lo).abs() < 1e-9 {
            -11.0
        } else if (peak.x - hi).abs() < 1e-9 {
            11.0
        } else {
            0.0
        };
        plot =
            plot.curve(points, Pen::solid(color), None).note(peak, &sub("N", k), (dx, 12.0), color);
    }
    let sum = sample(lo, hi, SAMPLES, |u| DVec2::new(u, basis.eval_all(u).iter().sum()));
    plot.curve(sum, Pen::dashed(GREY).width(1.5), Some("Σ Nᵢ on [3, 8]"))
        .legend(Legend::UpperRight)
        .render()
}

/// Figure 2.11: the degree 8 Bézier curve.
fn degree_eight(title: &str) -> Result<Vec<u8>> {
    let points = data::plane(&data::ZIGZAG);
    let curve = BezierCurve::try_new(points.clone())?;
    open_plot(title, &points, "x")
        .curve(sample(0.0, 1.0, SAMPLES, |t| curve.eval(t)), Pen::solid(BLUE), None)
        .render()
}

/// Figure 2.12: the uniform cubic B-spline.
fn uniform_bspline(title: &str) -> Result<Vec<u8>> {
    let points = data::plane(&data::ZIGZAG);
    let curve = BSplineCurve::try_uniform_open(3, points.clone())?;
    open_plot(title, &points, "x")
        .curve(sample(0.0, 1.0, SAMPLES, |t| curve.eval(t)), Pen::solid(BLUE), None)
        .render()
}

/// Figure 2.13: open interpolation.
fn open_interpolation(title: &str) -> Result<Vec<u8>> {
    let points = data::plane(&data::ZIGZAG);
    let curve = InterpolatingSpline::try_open(
        points.clone(),
        Parameters::Uniform,
        EndCondition::Coincident,
    )?;
    open_plot(title, &points, "p")
        .control_polygon(curve.spline().control_points(), &points)
        .curve(sample(0.0, 1.0, SAMPLES, |t| curve.eval(t)), Pen::solid(BLUE), None)
        .render()
}

/// Figure 2.14: periodic interpolation.
fn periodic_interpolation(title: &str) -> Result<Vec<u8>> {
    let points = data::plane(&data::PEER_PENTAGON);
    let curve = InterpolatingSpline::try_periodic(points.clone(), Parameters::Uniform)?;
    let mut polygon = curve.spline().control_points().to_vec();
    polygon.push(polygon[0]);
    closed_plot(title, &points)
        .control_polygon(&polygon, &points)
        .curve(sample(0.0, 1.0, SAMPLES, |t| curve.eval(t)), Pen::solid(BLUE), None)
        .render()
}

/// Figures 2.15 and 2.16: METAPOST open (zigzag) or closed (pentagon).
fn metapost(title: &str, closed: bool) -> Result<Vec<u8>> {
    let (points, config) = if closed {
        (data::plane(&data::PEER_PENTAGON), HobbyOptions::closed())
    } else {
        (data::plane(&data::ZIGZAG), HobbyOptions::open())
    };
    let curve = HobbyCurve::try_new(points.clone(), &config)?;
    let mut polygon = Vec::new();
    for k in 0..curve.n_segments() {
        if let Some([a, b, c, _]) = curve.segment(k) {
            polygon.extend([a, b, c]);
        }
    }
    if let Some(last) = curve.segment(curve.n_segments() - 1) {
        polygon.push(last[3]);
    }
    let plot = if closed { closed_plot(title, &points) } else { open_plot(title, &points, "x") };
    plot.control_polygon(&polygon, &points)
        .curve(sample(0.0, 1.0, SAMPLES, |t| curve.eval(t)), Pen::solid(VERMILION), None)
        .render()
}

/// The catenary x(t) = (t, cosh t), as a curve of `hi-curve`.
struct Catenary;

impl ParamCurve<DVec2> for Catenary {
    fn eval(&self, t: f64) -> DVec2 {
        DVec2::new(t, t.cosh())
    }

    fn is_periodic(&self) -> bool {
        false
    }

    fn eval_deriv(&self, t: f64, order: usize) -> DVec2 {
        match order {
            0 => self.eval(t),
            1 => DVec2::new(1.0, t.sinh()),
            k if k % 2 == 0 => DVec2::new(0.0, t.cosh()),
            _ => DVec2::new(0.0, t.sinh()),
        }
    }

    fn scale(&self) -> f64 {
        1.0
    }
}

/// Figure 2.17(a): the catenary with a tangent.
fn catenary(title: &str) -> Result<Vec<u8>> {
    const AT: f64 = 0.5;
    let c = Catenary;
    let p = c.eval(AT);
    let d = c.eval_deriv(AT, 1).normalize();
    Plot::plane(title)
        .hguide(0.0)
        .vguide(0.0)
        .curve(sample(-1.5, 1.5, SAMPLES, |t| c.eval(t)), Pen::solid(BLUE), Some("(t, cosh t)"))
        .curve(
            vec![p - 0.9 * d, p + 0.9 * d],
            Pen::solid(VERMILION).width(1.5),
            Some("tangent at t = 0.5"),
        )
        .points(&[p], Marker::point(INK), None)
        .points(&[DVec2::ZERO], Marker::small(INK), None)
        .note(DVec2::ZERO, "(0, 0)", (18.0, 10.0), INK)
        .legend(Legend::UpperLeft)
        .render()
}

/// Figure 2.17(b): its curvature over [0, 1].
fn catenary_curvature(title: &str) -> Result<Vec<u8>> {
    let c = Catenary;
    let mut measured = Vec::with_capacity(SAMPLES + 1);
    for j in 0..=SAMPLES {
        let t = j as f64 / SAMPLES as f64;
        let k = c.signed_curvature(t).ok_or_else(|| anyhow::anyhow!("catenary singular at {t}"))?;
        measured.push(DVec2::new(t, k));
    }
    let exact = sample(0.0, 1.0, SAMPLES, |t| DVec2::new(t, 1.0 / (t.cosh() * t.cosh())));
    Plot::function(title, "t", "κ")
        .x_range(0.0, 1.0)
        .y_range(0.0, 1.05)
        .curve(measured, Pen::solid(BLUE).width(3.0), Some("κ(t) from the curve"))
        .curve(exact, Pen::dashed(GREY).width(1.5), Some("1/cosh² t"))
        .legend(Legend::LowerLeft)
        .render()
}

/// The helix of figure 2.18.
struct Helix {
    a: f64,
    b: f64,
    turns: f64,
}

impl ParamCurve<DVec3> for Helix {
    fn eval(&self, t: f64) -> DVec3 {
        self.eval_deriv(t, 0)
    }

    fn is_periodic(&self) -> bool {
        false
    }

    /// Derivatives in t ∈ [0, 1], the angle being 2π·turns·t.
    fn eval_deriv(&self, t: f64, order: usize) -> DVec3 {
        let w = std::f64::consts::TAU * self.turns;
        let angle = w * t;
        let scale = w.powi(order as i32);
        // dⁿ/dθⁿ of (cos θ, sin θ) is a rotation by nπ/2.
        let phase = angle + order as f64 * std::f64::consts::FRAC_PI_2;
        let z = match order {
            0 => self.b * angle,
            1 => self.b * w,
            _ => 0.0,
        };
        DVec3::new(self.a * scale * phase.cos(), self.a * scale * phase.sin(), z)
    }

    fn scale(&self) -> f64 {
        self.a
    }
}

/// Figure 2.18: a helix.
fn helix(title: &str) -> Result<Vec<u8>> {
    let h = Helix { a: 1.0, b: 0.15, turns: 3.0 };
    let view = |p: DVec3| HELIX_VIEW.project(p);
    let top = h.eval(1.0).z;
    let kappa = h.curvature(0.3).ok_or_else(|| anyhow::anyhow!("helix singular"))?;
    let tau = h.torsion(0.3).ok_or_else(|| anyhow::anyhow!("helix has no torsion"))?;
    // The x and y axes reach past the helix (radius a = 1) so that their names stand clear of
    // it, each written beyond its axis's end.
    let axes = [(DVec3::X * 2.2, "x"), (DVec3::Y * 2.2, "y"), (DVec3::Z * (top + 0.5), "z")];
    let mut plot = Plot::projection(title);
    for (end, name) in axes {
        let out = view(end).normalize_or_zero() * 11.0;
        plot = plot.faint(vec![view(DVec3::ZERO), view(end)]).note(
            view(end),
            name,
            (out.x, out.y),
            GREY,
        );
    }
    plot.curve(sample(0.0, 1.0, SAMPLES, |t| view(h.eval(t))), Pen::solid(BLUE), None)
        .note(
            view(DVec3::new(0.0, 0.0, top + 0.5)),
            &format!("κ = {kappa:.4}, τ = {tau:.4}"),
            (110.0, 0.0),
            INK,
        )
        .render()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_helix_and_catenary_have_the_thesis_curvatures() {
        // §2.15: κ = a/(a² + b²), τ = b/(a² + b²) for the helix; 1/cosh² t for the catenary.
        let h = Helix { a: 1.0, b: 0.15, turns: 3.0 };
        let d = 1.0 + 0.15 * 0.15;
        for t in [0.0, 0.37, 0.9] {
            assert!((h.curvature(t).expect("regular") - 1.0 / d).abs() < 1e-12);
            assert!((h.torsion(t).expect("twisted") - 0.15 / d).abs() < 1e-12);
            let k = Catenary.signed_curvature(t).expect("regular");
            assert!((k - 1.0 / (t.cosh() * t.cosh())).abs() < 1e-14, "t = {t}");
        }
    }
}
