// SPDX-License-Identifier: MIT
//! Figures 3.13, 3.14 and 3.19: uniform harmonic curves beside trigonometric interpolation
//! (§2.13), in the plane and in space, and the stability of the curve under a small change.

use anyhow::Result;
use glam::{DVec2, DVec3};
use hi_curve::{HarmonicCurve, TrigonometricCurve};

use super::data;
use super::plot::{BLUE, GREY, INK, Legend, Marker, Oblique, Pen, Plot, VERMILION, names, sample};
use super::{Figure, Format, Panel};

/// Samples per closed curve.
pub(crate) const SAMPLES: usize = 600;

/// The view of the cube in figure 3.14: turned 30° about z, seen from 20° above.
const CUBE_VIEW: Oblique = Oblique { azimuth: 30.0, elevation: 20.0 };

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (3, 13),
        caption: "A 4 point polygon drawn with trigonometric and harmonic interpolation",
        drawn: "(a) Re of the §2.13 trigonometric interpolant (frequencies 0…3, `TrigonometricCurve`); \
                (b) the harmonic curve, which for this square is exactly its circumcircle.",
        data: "stand-in: the square (the thesis's labels match it).",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Trigonometric interpolation",
                draw: |t| square(t, false),
            },
            Panel { suffix: "b", title: "(b) Harmonic interpolation", draw: |t| square(t, true) },
        ],
    },
    Figure {
        number: (3, 14),
        caption: "3D curves drawn with trigonometric and harmonic interpolation",
        drawn: "Space curves through the 8 cube vertices p₀…p₇, (a) trigonometric (§2.13), (b) harmonic, \
                in a fixed oblique projection (turned 30° about z, seen from 20° above) with the cube's edges faint.",
        data: "stand-in: the cube tour in Gray-code order 000, 100, 110, 010, 011, 111, 101, 001 (xyz).",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Trigonometric interpolation",
                draw: |t| cube(t, false),
            },
            Panel { suffix: "b", title: "(b) Harmonic interpolation", draw: |t| cube(t, true) },
        ],
    },
    Figure {
        number: (3, 19),
        caption: "Stability of harmonic interpolation",
        drawn: "(a) the harmonic curve through four points; (b) x₃ moved 0.25 to the right: the new curve, \
                with the curve of (a) dashed for comparison.",
        data: "stand-in: the irregular quadrilateral.",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) four points", draw: |t| stability(t, false) },
            Panel {
                suffix: "b",
                title: "(b) x₃ moved slightly to the right",
                draw: |t| stability(t, true),
            },
        ],
    },
];

/// The samples of a closed plane curve over one period, end point included.
pub(crate) fn closed(f: impl Fn(f64) -> DVec2) -> Vec<DVec2> {
    sample(0.0, 1.0, SAMPLES, f)
}

/// A plane plot of data points: the faint closed polygon, the points and their labels xₖ.
pub(crate) fn data_plot(title: &str, points: &[DVec2]) -> Plot {
    Plot::plane(title).polygon(points, true).points(points, Marker::point(INK), None).labels(
        points,
        names("x", points.len()),
        true,
    )
}

/// Figure 3.13: the square through trigonometric (a) or harmonic (b) interpolation.
fn square(title: &str, harmonic: bool) -> Result<Vec<u8>> {
    let points = data::plane(&data::SQUARE);
    let curve = if harmonic {
        let c = HarmonicCurve::try_new(points.clone())?;
        closed(|t| c.eval(t))
    } else {
        let c = TrigonometricCurve::try_new(points.clone())?;
        closed(|t| c.eval(t))
    };
    data_plot(title, &points).curve(curve, Pen::solid(BLUE), None).render()
}

/// Figure 3.14: the cube tour through trigonometric (a) or harmonic (b) interpolation.
fn cube(title: &str, harmonic: bool) -> Result<Vec<u8>> {
    let tour = data::cube_tour();
    let eval: Box<dyn Fn(f64) -> DVec3> = if harmonic {
        let c = HarmonicCurve::try_new(tour.clone())?;
        Box::new(move |t| c.eval(t))
    } else {
        let c = TrigonometricCurve::try_new(tour.clone())?;
        Box::new(move |t| c.eval(t))
    };
    let view = |p: DVec3| CUBE_VIEW.project(p);
    let shown: Vec<DVec2> = tour.iter().map(|&p| view(p)).collect();
    let mut plot = Plot::projection(title);
    for [a, b] in data::cube_edges() {
        plot = plot.faint(vec![view(a), view(b)]);
    }
    plot.polygon(&shown, true)
        .curve(closed(|t| view(eval(t))), Pen::solid(BLUE), None)
        .points(&shown, Marker::point(INK), None)
        .labels(&shown, names("p", shown.len()), true)
        .render()
}

/// Figure 3.19: the quadrilateral (a), and with x₃ nudged to the right (b).
fn stability(title: &str, nudged: bool) -> Result<Vec<u8>> {
    let original = data::plane(&data::QUADRILATERAL);
    let before = HarmonicCurve::try_new(original.clone())?;
    let mut moved = original.clone();
    moved[3].x += data::QUADRILATERAL_NUDGE;
    let after = HarmonicCurve::try_new(moved.clone())?;
    if !nudged {
        // At the scale of (b), which holds the moved point and its curve too.
        let mut extent = moved.clone();
        extent.extend(closed(|t| after.eval(t)));
        return data_plot(title, &original)
            .curve(closed(|t| before.eval(t)), Pen::solid(BLUE), None)
            .include(&extent)
            .render();
    }
    data_plot(title, &moved)
        .curve(closed(|t| before.eval(t)), Pen::dashed(GREY).width(1.5), Some("curve of (a)"))
        .curve(closed(|t| after.eval(t)), Pen::solid(BLUE), Some("x₃ moved by 0.25"))
        .points(&original[3..4], Marker::ring(VERMILION), Some("x₃ of (a)"))
        .legend(Legend::UpperRight)
        .render()
}
