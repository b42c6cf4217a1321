// SPDX-License-Identifier: MIT
//! Figure 4.5: B-spline surface fitting through a curve network (§4.4, after Watt & Watt),
//! stage by stage, on built-in slices of a bumpy surface seen in an oblique projection.

use anyhow::{Result, ensure};
use glam::{DVec2, DVec3};
use hi_compare::bspline::BSplineCurve;
use hi_compare::bspline_fit::{BSplineFit, BSplineFitOptions};
use hi_compare::bspline_interp::{EndCondition, InterpolatingSpline, Parameters};

use super::plot::{BLUE, GREEN, Marker, Oblique, Pen, Plot, VERMILION};
use super::{Figure, Format, Panel};

/// The view: turned 35° about z, seen from 30° above.
const VIEW: Oblique = Oblique { azimuth: 35.0, elevation: 30.0 };

/// Samples per drawn curve.
const SAMPLES: usize = 160;

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[Figure {
    number: (4, 5),
    caption: "B-spline surface fitting: curve network (after [90])",
    drawn: "Watt & Watt's algorithm (`hi_compare::bspline_fit`). (a) the cubic U-curves through the five slices, \
            chord-length parameters, natural ends; (b) the same curves on the merged U-knot vector, its knots marked on \
            every curve (knot insertion leaves the curves unchanged); (c) V-curves across the slices through the U-curves' \
            points at the U-knots, each with its own chord-length parameters as the thesis describes; (d) the V-curves of \
            the surface, which share averaged chord-length parameters and so one V-knot vector (marked), so that the \
            network lies on one tensor-product surface through every data point; (e) the final curve network.",
    data: "stand-in: five slices of 5 to 8 unevenly spaced points on z = 0.6 sin(1.3x) cos(0.9y) + 0.1x, built in code.",
    format: Format::Svg,
    views: &[],
    panels: &[
        Panel {
            suffix: "a",
            title: "(a) U-curves through the slices",
            draw: |t| panel(t, Stage::UCurves),
        },
        Panel {
            suffix: "b",
            title: "(b) U-curves on the merged U-knot vector",
            draw: |t| panel(t, Stage::MergedU),
        },
        Panel {
            suffix: "c",
            title: "(c) V-curves through the U-curves at the U-knots",
            draw: |t| panel(t, Stage::VCurves),
        },
        Panel {
            suffix: "d",
            title: "(d) V-curves on one V-knot vector",
            draw: |t| panel(t, Stage::MergedV),
        },
        Panel { suffix: "e", title: "(e) The curve network", draw: |t| panel(t, Stage::Network) },
    ],
}];

/// The panels of figure 4.5.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stage {
    UCurves,
    MergedU,
    VCurves,
    MergedV,
    Network,
}

/// The slices: five cuts across a bump, of different lengths and uneven spacing.
fn slices() -> Vec<Vec<DVec3>> {
    (0..5)
        .map(|s| {
            let n = 5 + (s * 3) % 4;
            let y = s as f64 * 0.9;
            (0..n)
                .map(|k| {
                    let t = k as f64 / (n - 1) as f64;
                    let x = 4.0 * t + 0.2 * (2.0 * t + s as f64).sin();
                    let z = 0.6 * (1.3 * x).sin() * (0.9 * y).cos() + 0.1 * x;
                    DVec3::new(x, y + 0.08 * x, z)
                })
                .collect()
        })
        .collect()
}

fn view(p: DVec3) -> DVec2 {
    VIEW.project(p)
}

fn drawn(curve: &BSplineCurve<DVec3>) -> Vec<DVec2> {
    super::plot::sample(0.0, 1.0, SAMPLES, |t| view(curve.eval(t)))
}

/// Draws one stage of figure 4.5.
fn panel(title: &str, stage: Stage) -> Result<Vec<u8>> {
    let data = slices();
    let fit = BSplineFit::try_new(data.clone(), &BSplineFitOptions::default())?;
    let surface = fit.surface();
    // The network must lie on a surface through every point.
    for (s, slice) in data.iter().enumerate() {
        for (k, x) in slice.iter().enumerate() {
            let d = surface.eval(fit.u_params()[s][k], fit.v_params()[s]).distance(*x);
            ensure!(d < 1e-12, "slice {s}, point {k} is {d:e} off the surface");
        }
    }
    let points: Vec<DVec2> = data.iter().flatten().map(|p| view(*p)).collect();
    let u_knots = fit.u_knots();
    let mut plot = Plot::projection(title);
    let u_pen = if stage == Stage::VCurves || stage == Stage::MergedV {
        Pen::solid(BLUE).width(1.0)
    } else {
        Pen::solid(BLUE)
    };
    for (s, curve) in fit.u_curves().iter().enumerate() {
        plot = plot.curve(drawn(curve), u_pen, (s == 0).then_some("U-curves"));
    }
    match stage {
        Stage::UCurves | Stage::Network => {}
        Stage::MergedU => {
            let marks: Vec<DVec2> = fit
                .merged_u_curves()
                .iter()
                .flat_map(|c| u_knots.iter().map(|&u| view(c.eval(u))))
                .collect();
            plot = plot.points(&marks, Marker::small(VERMILION), Some("merged U-knots"));
        }
        Stage::VCurves => {
            // The thesis's V-curves: through Cₛ(ū) with each curve's own chord-length parameters.
            for (k, &u) in u_knots.iter().enumerate() {
                let through: Vec<DVec3> = fit.u_curves().iter().map(|c| c.eval(u)).collect();
                let curve = InterpolatingSpline::try_open(
                    through.clone(),
                    Parameters::ChordLength,
                    EndCondition::Natural,
                )?;
                plot = plot.curve(
                    drawn(curve.spline()),
                    Pen::solid(GREEN),
                    (k == 0).then_some("V-curves"),
                );
                let marks: Vec<DVec2> = through.iter().map(|p| view(*p)).collect();
                plot = plot.points(
                    &marks,
                    Marker::small(VERMILION),
                    (k == 0).then_some("their knots"),
                );
            }
        }
        Stage::MergedV => {
            for (k, curve) in fit.v_curves().iter().enumerate() {
                plot = plot.curve(drawn(curve), Pen::solid(GREEN), (k == 0).then_some("V-curves"));
                let marks: Vec<DVec2> =
                    fit.v_params().iter().map(|&v| view(curve.eval(v))).collect();
                plot = plot.points(&marks, Marker::small(VERMILION), (k == 0).then_some("V-knots"));
            }
        }
    }
    if stage == Stage::Network {
        for (k, curve) in fit.v_curves().iter().enumerate() {
            plot = plot.curve(drawn(curve), Pen::solid(GREEN), (k == 0).then_some("V-curves"));
        }
    }
    plot.points(&points, Marker::point(super::plot::INK), Some("data"))
        .legend(super::plot::Legend::UpperLeft)
        .render()
}
