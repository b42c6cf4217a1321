// SPDX-License-Identifier: MIT
//! Figures 3.1–3.6: the kernel σ(t) and the basis σₖ(t) for n = 3, 4, 7 and 16 (§3.4).
//!
//! Plotted over one period t ∈ [0, 1] as in the thesis, with faint guides at the nodes t = j/n,
//! where σₖ(j/n) = δⱼₖ (dots mark those values).

use anyhow::Result;
use glam::DVec2;
use hi_curve::Sigma;

use super::plot::{INK, Marker, PALETTE, Pen, Plot, sample, sub};
use super::{Figure, Format, Panel};

/// Samples per curve over [0, 1]: several per pixel even for n = 16.
const SAMPLES: usize = 800;

const EXACT: &str = "none needed (exact functions).";

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (3, 1),
        caption: "The σ(t) function for n = 3",
        drawn: "σ³(t) = sin 3πt / (3 sin πt) over t ∈ [0, 1]; dots at the nodes t = j/3 where it is 1 or 0.",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| kernel(t, 3) }],
    },
    Figure {
        number: (3, 2),
        caption: "The σₖ(t) basis functions for n = 3",
        drawn: "σ₀, σ₁, σ₂ for n = 3 over t ∈ [0, 1], each labelled at its peak; σₖ(j/3) = δⱼₖ.",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| family(t, 3) }],
    },
    Figure {
        number: (3, 3),
        caption: "The σ(t) function for n = 4",
        drawn: "σ⁴(t) = cos πt · sin 4πt / (4 sin πt) over t ∈ [0, 1] (the even kernel).",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| kernel(t, 4) }],
    },
    Figure {
        number: (3, 4),
        caption: "The σₖ(t) basis functions for n = 4",
        drawn: "σ₀, …, σ₃ for n = 4 over t ∈ [0, 1], each labelled at its peak.",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| family(t, 4) }],
    },
    Figure {
        number: (3, 5),
        caption: "The σ(t) function for n = 7",
        drawn: "σ⁷(t) over t ∈ [0, 1].",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| kernel(t, 7) }],
    },
    Figure {
        number: (3, 6),
        caption: "The σ(t) function for n = 16",
        drawn: "σ¹⁶(t) over t ∈ [0, 1].",
        data: EXACT,
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| kernel(t, 16) }],
    },
];

/// A plot over t ∈ [0, 1] with guides at the nodes j/n and the line σ = 0.
fn frame(title: &str, n: usize, y_desc: &str) -> Plot {
    let mut plot = Plot::function(title, "t", y_desc).x_range(0.0, 1.0).hguide(0.0);
    for j in 1..n {
        plot = plot.vguide(j as f64 / n as f64);
    }
    plot
}

/// σⁿ(t) = σⁿ₀(t) alone.
fn kernel(title: &str, n: usize) -> Result<Vec<u8>> {
    let sigma = Sigma::new(n);
    let nodes: Vec<DVec2> = (0..=n)
        .map(|j| DVec2::new(j as f64 / n as f64, sigma.kernel(j as f64 / n as f64)))
        .collect();
    frame(title, n, "σ(t)")
        .curve(
            sample(0.0, 1.0, SAMPLES, |t| DVec2::new(t, sigma.kernel(t))),
            Pen::solid(PALETTE[0]),
            None,
        )
        .points(&nodes, Marker::small(INK), None)
        .render()
}

/// All of σⁿ₀, …, σⁿₙ₋₁, each in its colour and named at its peak t = k/n (σ₀ at t = 1).
fn family(title: &str, n: usize) -> Result<Vec<u8>> {
    let sigma = Sigma::new(n);
    let mut plot = frame(title, n, "σₖ(t)");
    let mut lo = 0.0_f64;
    for k in 0..n {
        let color = PALETTE[k % PALETTE.len()];
        let curve = sample(0.0, 1.0, SAMPLES, |t| DVec2::new(t, sigma.eval(k, t)));
        lo = curve.iter().fold(lo, |lo, p| lo.min(p.y));
        let peak = if k == 0 { DVec2::new(1.0, 1.0) } else { DVec2::new(k as f64 / n as f64, 1.0) };
        let offset = if k == 0 { (-14.0, 12.0) } else { (0.0, 13.0) };
        plot = plot.curve(curve, Pen::solid(color), None).note(peak, &sub("σ", k), offset, color);
    }
    let nodes: Vec<DVec2> = (0..=n)
        .flat_map(|j| [DVec2::new(j as f64 / n as f64, 0.0), DVec2::new(j as f64 / n as f64, 1.0)])
        .collect();
    plot.points(&nodes, Marker::small(INK), None).y_range(lo - 0.08, 1.2).render()
}
