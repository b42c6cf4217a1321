// SPDX-License-Identifier: MIT
//! Figures 3.20–3.23: non-uniform harmonic interpolation (§3.10) beside the uniform curve.
//!
//! The section can be read two ways (docs/math.md §5), and both are drawn, each named for what it
//! is: the thesis's final formula as printed ([`NonUniformVariant::Thesis`]: the chord-length
//! tⱼ act as frequencies, the curve passes through xₖ at t = k/(n−1) and is open, ending at
//! xₙ₋₁ "before the uniform curve does", as the thesis remarks) and true interpolation at the
//! chord-length nodes ([`NonUniformVariant::Nodes`]: X(tₖ) = xₖ, closed). The thesis's panels
//! (a) non-uniform and (b) uniform become three files: `a-thesis`, `a-nodes` and `b`.

use anyhow::Result;
use glam::DVec2;
use hi_curve::{HarmonicCurve, NonUniformCurve, NonUniformVariant};

use super::curves::{SAMPLES, closed, data_plot};
use super::data;
use super::plot::{BLUE, GREEN, GREY, Legend, Pen, VERMILION, sample};
use super::{Figure, Format, Panel};

/// Which curve through the points.
#[derive(Clone, Copy, Debug)]
enum Reading {
    /// The thesis's formula as printed.
    Thesis,
    /// Interpolation at the chord-length nodes.
    Nodes,
    /// The uniform harmonic curve.
    Uniform,
}

impl Reading {
    const fn pen(self) -> Pen {
        match self {
            Reading::Thesis => Pen::solid(VERMILION),
            Reading::Nodes => Pen::solid(GREEN),
            Reading::Uniform => Pen::solid(BLUE),
        }
    }

    const fn name(self) -> &'static str {
        match self {
            Reading::Thesis => "thesis formula: X(k/(n−1)) = xₖ, open",
            Reading::Nodes => "nodes: X(tₖ) = xₖ, closed",
            Reading::Uniform => "uniform harmonic: X(k/n) = xₖ",
        }
    }
}

const DRAWN: &str = "(a-thesis) the thesis's final formula as printed (`NonUniformVariant::Thesis`): \
                     chord-length tⱼ used as frequencies, passes through xₖ at t = k/(n−1), open curve; \
                     (a-nodes) true interpolation at the chord-length nodes tₖ (`NonUniformVariant::Nodes`), closed; \
                     (b) the uniform harmonic curve.";

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (3, 20),
        caption: "Nonuniform harmonic interpolation of seven points",
        drawn: "Both readings of §3.10 on one plot with chord-length parameters: the thesis's formula as printed \
                (vermilion, open, through xₖ at t = k/6), interpolation at the nodes tₖ (green, closed), and the \
                uniform harmonic curve (grey, dashed) for comparison.",
        data: "stand-in: the heptagon.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: overlay }],
    },
    Figure {
        number: (3, 21),
        caption: "A 7 sided polygon drawn by non-uniform and uniform harmonic interpolation",
        drawn: DRAWN,
        data: "stand-in: the heptagon.",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a-thesis",
                title: "(a) non-uniform, the thesis's formula",
                draw: |t| heptagon(t, Reading::Thesis),
            },
            Panel {
                suffix: "a-nodes",
                title: "(a) non-uniform, interpolating at the nodes tₖ",
                draw: |t| heptagon(t, Reading::Nodes),
            },
            Panel {
                suffix: "b",
                title: "(b) Harmonic interpolation",
                draw: |t| heptagon(t, Reading::Uniform),
            },
        ],
    },
    Figure {
        number: (3, 22),
        caption: "A 5 sided polygon drawn by non-uniform and uniform harmonic interpolation",
        drawn: DRAWN,
        data: "stand-in: the pentagon.",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a-thesis",
                title: "(a) non-uniform, the thesis's formula",
                draw: |t| pentagon(t, Reading::Thesis),
            },
            Panel {
                suffix: "a-nodes",
                title: "(a) non-uniform, interpolating at the nodes tₖ",
                draw: |t| pentagon(t, Reading::Nodes),
            },
            Panel {
                suffix: "b",
                title: "(b) Harmonic interpolation",
                draw: |t| pentagon(t, Reading::Uniform),
            },
        ],
    },
    Figure {
        number: (3, 23),
        caption: "An 8 sided polygon drawn by non-uniform and uniform harmonic interpolation",
        drawn: DRAWN,
        data: "stand-in: the octagon.",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a-thesis",
                title: "(a) non-uniform, the thesis's formula",
                draw: |t| octagon(t, Reading::Thesis),
            },
            Panel {
                suffix: "a-nodes",
                title: "(a) non-uniform, interpolating at the nodes tₖ",
                draw: |t| octagon(t, Reading::Nodes),
            },
            Panel {
                suffix: "b",
                title: "(b) Harmonic interpolation",
                draw: |t| octagon(t, Reading::Uniform),
            },
        ],
    },
];

/// The curve of `reading` through `points`, sampled (over [0, 1], closed where it is).
fn curve(points: &[DVec2], reading: Reading) -> Result<Vec<DVec2>> {
    Ok(match reading {
        Reading::Thesis => {
            let c = NonUniformCurve::try_new(points.to_vec(), NonUniformVariant::Thesis)?;
            sample(0.0, 1.0, SAMPLES, |t| c.eval(t))
        }
        Reading::Nodes => {
            let c = NonUniformCurve::try_new(points.to_vec(), NonUniformVariant::Nodes)?;
            closed(|t| c.eval(t))
        }
        Reading::Uniform => {
            let c = HarmonicCurve::try_new(points.to_vec())?;
            closed(|t| c.eval(t))
        }
    })
}

/// One curve through `points` with the legend naming the reading.
fn panel(title: &str, points: &[DVec2], reading: Reading, legend: Legend) -> Result<Vec<u8>> {
    data_plot(title, points)
        .curve(curve(points, reading)?, reading.pen(), Some(reading.name()))
        .legend(legend)
        .render()
}

fn heptagon(title: &str, reading: Reading) -> Result<Vec<u8>> {
    panel(title, &data::plane(&data::HEPTAGON), reading, Legend::LowerRight)
}

fn pentagon(title: &str, reading: Reading) -> Result<Vec<u8>> {
    panel(title, &data::plane(&data::PENTAGON), reading, Legend::UpperLeft)
}

fn octagon(title: &str, reading: Reading) -> Result<Vec<u8>> {
    panel(title, &data::plane(&data::OCTAGON), reading, Legend::LowerRight)
}

/// Figure 3.20: both readings and the uniform curve on one plot.
fn overlay(title: &str) -> Result<Vec<u8>> {
    let points = data::plane(&data::HEPTAGON);
    data_plot(title, &points)
        .curve(
            curve(&points, Reading::Uniform)?,
            Pen::dashed(GREY).width(1.5),
            Some(Reading::Uniform.name()),
        )
        .curve(curve(&points, Reading::Nodes)?, Reading::Nodes.pen(), Some(Reading::Nodes.name()))
        .curve(
            curve(&points, Reading::Thesis)?,
            Reading::Thesis.pen(),
            Some(Reading::Thesis.name()),
        )
        .legend(Legend::LowerRight)
        .render()
}
