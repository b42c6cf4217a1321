// SPDX-License-Identifier: MIT
//! The colours of the §5.9 pictures: signed curvature on a cool–warm map, and the colour
//! bar beside each render.

use anyhow::{Context, Result};
use hi_mesh::{ColorLegend, ColorMap, ColorScale, Palette, TriangleMesh};
use hi_surface::CurvatureQuantity;

use super::curvature::Comparison;
use super::{SPECS, Side};

/// The colour map of the §5.9 pictures: cool–warm from −`extent` to `extent`.
fn signed_map(extent: f64) -> ColorMap {
    ColorMap {
        scale: ColorScale::Fixed { min: -extent, max: extent },
        coverage: 1.0,
        palette: Palette::CoolWarm,
    }
}

/// `mesh` coloured by `values` (one per vertex) on [`signed_map`]; NaN grey.
pub(super) fn colored(mesh: TriangleMesh, values: &[f64], extent: f64) -> Result<TriangleMesh> {
    Ok(mesh.try_with_colors(signed_map(extent).try_apply(values)?.colors)?)
}

/// Whether panel `suffix` of figure `number` is a §5.9 curvature picture (with a colour bar).
pub(crate) fn has_colour_bar(number: (u32, u32), suffix: &str) -> bool {
    number.0 == 5
        && (31..=43).contains(&number.1)
        && (suffix.ends_with("-K") || suffix.ends_with("-H"))
}

/// The legend of panel `suffix` of figure `number` (see [`has_colour_bar`]) and its symbol.
pub(crate) fn colour_bar(number: (u32, u32), suffix: &str) -> Result<(ColorLegend, &'static str)> {
    let label = format!("{}.{}", number.0, number.1);
    let spec = SPECS.iter().find(|s| s.figure == label).context("not a §5.9 figure")?;
    let quantity =
        if suffix.ends_with("-K") { CurvatureQuantity::Gaussian } else { CurvatureQuantity::Mean };
    let c = Comparison::new(spec)?;
    let side = if suffix.contains("harmonic") { Side::Harmonic } else { Side::Parametric };
    let legend = signed_map(c.extent(quantity)?).try_apply(&c.values(side, quantity))?.legend;
    Ok((legend, quantity.symbol()))
}

/// A number for a colour bar: three significant digits, a true minus sign.
pub(super) fn tick(x: f64) -> String {
    // Rounded to three significant digits first, so that 0.99996 is 1.00, not 1.000.
    let x: f64 = format!("{x:.2e}").parse().unwrap_or(x);
    let a = x.abs();
    let s = if x == 0.0 {
        "0".to_owned()
    } else if (0.01..1000.0).contains(&a) {
        let digits = (2 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.digits$}")
    } else {
        let e = a.log10().floor() as i32;
        format!("{:.2}·10{}", x / 10f64.powi(e), superscript(e))
    };
    s.replace('-', "−")
}

/// An exponent in superscript digits.
fn superscript(e: i32) -> String {
    e.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']
                [d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect()
}

/// The render `image` (JPEG, `width`×`height` pixels) with a colour bar of `legend` at
/// its right, laid out in units of a third of a pixel so that its text keeps its size beside a
/// 400×300 picture and the render shows at full resolution: the
/// palette from the legend's low end (bottom) to its high end (top), ticks at −a, −a/2, 0, a/2
/// and a labelled with their values, the quantity's `symbol` above, and below it how many
/// values the ends of the bar stand in for and how many were undefined.
pub(crate) fn colour_bar_svg(
    image: &[u8],
    (pixels_x, pixels_y): (u32, u32),
    legend: &ColorLegend,
    symbol: &str,
) -> String {
    let (width, height) = (pixels_x / 3, pixels_y / 3);
    let bar_x = width + 16;
    let (top, bottom) = (40.0, f64::from(height) - 50.0);
    let total = width + 140;
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{pixels_y}\" \
         viewBox=\"0 0 {total} {height}\" font-family=\"sans-serif\" font-size=\"13\">\n\
         <rect width=\"{total}\" height=\"{height}\" fill=\"#fff\"/>\n\
         <image width=\"{width}\" height=\"{height}\" href=\"data:image/jpeg;base64,{}\"/>\n\
         <defs><linearGradient id=\"bar\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">\n",
        3 * total,
        base64::encode(image)
    );
    let colour = |c: [f32; 3]| {
        let [r, g, b] = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
        format!("#{r:02x}{g:02x}{b:02x}")
    };
    for k in 0..=16 {
        let t = f64::from(k) / 16.0;
        let value = legend.min + t * (legend.max - legend.min);
        s += &format!(
            "<stop offset=\"{t:.4}\" stop-color=\"{}\"/>\n",
            colour(legend.srgb_at(value))
        );
    }
    s += "</linearGradient></defs>\n";
    s += &format!(
        "<text x=\"{}\" y=\"{:.2}\" font-style=\"italic\" font-family=\"serif\" font-size=\"17\">{symbol}</text>\n\
         <rect x=\"{bar_x}\" y=\"{top:.2}\" width=\"18\" height=\"{:.2}\" fill=\"url(#bar)\" stroke=\"#555\"/>\n",
        bar_x + 3,
        top - 12.0,
        bottom - top
    );
    for k in 0..=4 {
        let t = f64::from(k) / 4.0;
        let value = legend.min + t * (legend.max - legend.min);
        let y = bottom - t * (bottom - top);
        s += &format!(
            "<line x1=\"{}\" y1=\"{y:.2}\" x2=\"{}\" y2=\"{y:.2}\" stroke=\"#555\"/>\n\
             <text x=\"{}\" y=\"{:.2}\">{}</text>\n",
            bar_x + 18,
            bar_x + 23,
            bar_x + 26,
            y + 4.5,
            tick(value)
        );
    }
    let mut notes = Vec::new();
    if legend.n_clamped > 0 {
        notes.push(format!("{} beyond the ends", legend.n_clamped));
    }
    if legend.n_invalid > 0 {
        notes.push(format!("{} undefined (grey)", legend.n_invalid));
    }
    for (k, note) in notes.iter().enumerate() {
        s += &format!(
            "<text x=\"{}\" y=\"{:.2}\" font-size=\"11\" fill=\"#444\">{note}</text>\n",
            width + 4,
            bottom + 22.0 + 14.0 * k as f64
        );
    }
    s += "</svg>\n";
    s
}
