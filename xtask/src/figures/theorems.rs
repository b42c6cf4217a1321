// SPDX-License-Identifier: MIT
//! Figures 5.2 and 5.6: harmonic subdivision (§5.2), rotation (Theorem 5.1) and insertion
//! (Theorem 5.3) on the heptagon of figure 3.9, and (beyond the thesis) why Theorem 5.1 is not
//! a rotation for even n (docs/math.md §2).

use anyhow::{Result, ensure};
use glam::DVec2;
use hi_curve::HarmonicCurve;

use super::curves::closed;
use super::data;
use super::plot::{BLUE, GREEN, GREY, INK, Legend, Marker, Pen, Plot, VERMILION, names, sub};
use super::{Figure, Format, Panel};

/// The parametric offset of figure 5.6(a): 0.4 of the node spacing 1/7.
const OFFSET_7: f64 = 0.4 / 7.0;

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (5, 2),
        caption: "Stages in harmonic subdivision",
        drawn: "The point sets P₀ (7 points), P₁ (14), P₂ (28), P₃ (56) of harmonic subdivision (`subdivision_stages`), \
                each with its polygon, over the limit curve, which is the harmonic curve of P₀; the original points are labelled.",
        data: "stand-in: the heptagon.",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) P₀", draw: |t| subdivision(t, 0) },
            Panel { suffix: "b", title: "(b) P₁", draw: |t| subdivision(t, 1) },
            Panel { suffix: "c", title: "(c) P₂", draw: |t| subdivision(t, 2) },
            Panel { suffix: "d", title: "(d) P₃", draw: |t| subdivision(t, 3) },
        ],
    },
    Figure {
        number: (5, 6),
        caption: "Application of theorems 5.1 and 5.3 (with m = 1)",
        drawn: "(a) Theorem 5.1 (`rotate_theorem_5_1`) with offset o = 0.4/7: the points yⱼ = X(j/7 + o) on the same curve \
                (odd n: an exact rotation); (b) Theorem 5.3 applied to (a) with m = 1 (`insert`): 8 points zⱼ on the same curve; \
                (c) not in the thesis: for even n = 6 and o = 1/12, the curve through the Theorem 5.1 points is NOT the \
                rotated curve (defect c·sin(πno)·sin(πnt)), while the exact `rotate` (7 points) is.",
        data: "stand-ins: the heptagon for (a), (b); the hexagon for (c).",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Application of theorem 5.1", draw: rotation },
            Panel { suffix: "b", title: "(b) Application of theorem 5.3", draw: insertion },
            Panel {
                suffix: "c",
                title: "(c) theorem 5.1 for even n (not in the thesis)",
                draw: even_rotation,
            },
        ],
    },
];

/// Figure 5.2: level `level` of harmonic subdivision of the heptagon.
fn subdivision(title: &str, level: u32) -> Result<Vec<u8>> {
    let points = data::plane(&data::HEPTAGON);
    let curve = HarmonicCurve::try_new(points.clone())?;
    let stages = curve.subdivision_stages(level)?;
    let stage = stages.last().map_or(&points, |s| s);
    let mut ring = stage.clone();
    ring.push(stage[0]);
    let name = format!("{} ({} points)", sub("P", level as usize), stage.len());
    Plot::plane(title)
        .curve(closed(|t| curve.eval(t)), Pen::solid(GREY).width(1.5), Some("limit curve"))
        .curve(ring, Pen::solid(VERMILION).width(1.0), Some(&name))
        .points(stage, Marker::small(VERMILION), None)
        .points(&points, Marker::point(INK), None)
        .labels(&points, names("x", points.len()), true)
        .legend(Legend::LowerRight)
        .render()
}

/// The heptagon's curve and its points after Theorem 5.1 with offset [`OFFSET_7`].
fn rotated_heptagon() -> Result<(Vec<DVec2>, HarmonicCurve<DVec2>, HarmonicCurve<DVec2>)> {
    let points = data::plane(&data::HEPTAGON);
    let curve = HarmonicCurve::try_new(points.clone())?;
    let rotated = curve.rotate_theorem_5_1(OFFSET_7)?;
    Ok((points, curve, rotated))
}

/// Figure 5.6(a): Theorem 5.1 on the heptagon.
fn rotation(title: &str) -> Result<Vec<u8>> {
    let (points, curve, rotated) = rotated_heptagon()?;
    let ys = rotated.points();
    Plot::plane(title)
        .polygon(ys, true)
        .curve(closed(|t| curve.eval(t)), Pen::solid(BLUE), Some("X, through xₖ and yⱼ"))
        .points(&points, Marker::ring(GREY), Some("xₖ (original)"))
        .points(ys, Marker::point(INK), Some("yⱼ = X(j/7 + 0.4/7)"))
        .labels(ys, names("y", ys.len()), true)
        .legend(Legend::LowerRight)
        .render()
}

/// Figure 5.6(b): Theorem 5.3 with m = 1 on the points of 5.6(a).
fn insertion(title: &str) -> Result<Vec<u8>> {
    let (_, curve, rotated) = rotated_heptagon()?;
    let inserted = rotated.insert(1)?;
    // The figure claims the curve through the 8 points is the rotated curve of (a): check it.
    let err = (0..64)
        .map(|i| i as f64 / 64.0)
        .map(|t| (inserted.eval(t) - curve.eval(t + OFFSET_7)).length())
        .fold(0.0, f64::max);
    ensure!(err < 1e-9, "theorem 5.3 moved the curve by {err}");
    let zs = inserted.points();
    Plot::plane(title)
        .polygon(zs, true)
        .curve(closed(|t| inserted.eval(t)), Pen::solid(BLUE), Some("X, through yⱼ and zⱼ"))
        .points(rotated.points(), Marker::ring(GREY), Some("yⱼ of (a)"))
        .points(zs, Marker::point(INK), Some("zⱼ = Y(j/8), Thm 5.3"))
        .labels(zs, names("z", zs.len()), true)
        .legend(Legend::LowerRight)
        .render()
}

/// Figure 5.6(c): Theorem 5.1 on the hexagon, against the exact rotation.
fn even_rotation(title: &str) -> Result<Vec<u8>> {
    let points = data::plane(&data::HEXAGON);
    let n = points.len();
    let offset = 0.5 / n as f64;
    let curve = HarmonicCurve::try_new(points.clone())?;
    let thesis = curve.rotate_theorem_5_1(offset)?;
    let exact = curve.rotate(offset)?;
    // How far each is from the rotated curve X(t + o).
    let defect = |c: &HarmonicCurve<DVec2>| {
        (0..1024)
            .map(|i| i as f64 / 1024.0)
            .map(|t| (c.eval(t) - curve.eval(t + offset)).length())
            .fold(0.0, f64::max)
    };
    let thesis_label = format!("through yⱼ: Thm 5.1 curve, off by {:.2}", defect(&thesis));
    let exact_error = defect(&exact);
    ensure!(exact_error < 1e-9, "the exact rotation is off by {exact_error}");
    let exact_label = "exact rotate (7 points), off by < 1e-9";
    Plot::plane(title)
        .polygon(&points, true)
        .curve(
            closed(|t| curve.eval(t)),
            Pen::solid(BLUE),
            Some("X through xₖ; X(t + o) draws the same"),
        )
        .curve(closed(|t| thesis.eval(t)), Pen::solid(VERMILION), Some(&thesis_label))
        .curve(closed(|t| exact.eval(t)), Pen::dashed(GREEN), Some(exact_label))
        .points(&points, Marker::ring(GREY), None)
        .points(thesis.points(), Marker::point(INK), Some("yⱼ = X(j/6 + 1/12)"))
        .points(exact.points(), Marker::small(GREEN), None)
        .labels(&points, names("x", n), true)
        .legend(Legend::LowerLeft)
        .render()
}
