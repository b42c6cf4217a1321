// SPDX-License-Identifier: MIT
//! Plots side by side under one title, and the titles and panel letters above them.

use anyhow::{Result, bail};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::{INK, Plot, SCALE, font, px};

/// Several plots side by side in one SVG document under `title`, each with its own title as a
/// sub-caption (a curve beside its curvature plot).
///
/// # Errors
///
/// As [`Plot::render`].
pub(crate) fn render_row(title: &str, plots: &[&Plot]) -> Result<Vec<u8>> {
    render_grid(title, plots, plots.len())
}

/// Several plots in rows of `columns` (the last row may be shorter), left to right and top to
/// bottom, in one SVG document under `title`, each with its own title as a sub-caption: stages
/// that would be too small to read in one row.
///
/// # Errors
///
/// As [`Plot::render`]; also if `columns` is 0.
pub(crate) fn render_grid(title: &str, plots: &[&Plot], columns: usize) -> Result<Vec<u8>> {
    if columns == 0 {
        bail!("a grid of plots needs at least one column");
    }
    let rows: Vec<&[&Plot]> = plots.chunks(columns).collect();
    let row_size = |row: &[&Plot]| {
        let sizes = row.iter().map(|p| p.size());
        (sizes.clone().map(|s| s.0).sum::<u32>(), sizes.map(|s| s.1).max().unwrap_or(0))
    };
    let size = (
        rows.iter().map(|r| row_size(r).0).max().unwrap_or(0),
        rows.iter().map(|r| row_size(r).1 + TITLE_SPACE).sum::<u32>(),
    );
    let mut svg = String::new();
    {
        let root =
            SVGBackend::with_string(&mut svg, (size.0 * SCALE, size.1 * SCALE)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut below = draw_panel_letter(&root, title)?;
        for (i, row) in rows.iter().enumerate() {
            // The last row takes what is left (less the panel letter's line, if any).
            let mut right = if i + 1 < rows.len() {
                let (line, rest) = below.split_vertically((row_size(row).1 + TITLE_SPACE) * SCALE);
                below = rest;
                line
            } else {
                below.clone()
            };
            for plot in *row {
                let (cell, rest) = right.split_horizontally(plot.size().0 * SCALE);
                let chart = draw_title(&cell, &plot.title)?;
                plot.draw_chart(&chart)?;
                right = rest;
            }
        }
        root.present()?;
    }
    unscale(svg, size)
}

/// Extra height in pixels of a row of plots, for the second title line.
const TITLE_SPACE: u32 = 24;

/// Sets the header of an SVG document drawn at [`SCALE`] times `size` to `size`.
pub(super) fn unscale(svg: String, size: (u32, u32)) -> Result<Vec<u8>> {
    let header = format!("<svg width=\"{}\" height=\"{}\"", size.0 * SCALE, size.1 * SCALE);
    if !svg.starts_with(&header) {
        bail!("unexpected SVG header from plotters: {:?}", svg.get(..60));
    }
    let svg = svg.replacen(&header, &format!("<svg width=\"{}\" height=\"{}\"", size.0, size.1), 1);
    Ok(svg.into_bytes())
}

/// The panel letter of a figure's title: "(b)" of "Figure 2.5 (b) G1 with s = 0.6"; none for
/// a figure of one panel.
pub(super) fn panel_letter(title: &str) -> Option<&str> {
    let mut words = title.strip_prefix("Figure ")?.split(' ');
    words.next()?;
    let letter = words.next()?;
    let inner = letter.strip_prefix('(')?.strip_suffix(')')?;
    (!inner.is_empty() && inner.chars().all(|c| c.is_ascii_lowercase())).then_some(letter)
}

/// The figure's panel letter, bold at the top left of `root` (the title itself is the gallery's
/// caption), and the area below it; all of `root` for a figure of one panel.
pub(super) fn draw_panel_letter<'a>(
    root: &DrawingArea<SVGBackend<'a>, Shift>,
    title: &str,
) -> Result<DrawingArea<SVGBackend<'a>, Shift>> {
    const SIZE: f64 = 16.0;
    let Some(letter) = panel_letter(title) else {
        return Ok(root.clone());
    };
    let (top, rest) = root.split_vertically(px(8.0 + 1.3 * SIZE));
    let style = TextStyle::from(("sans-serif", font(SIZE), FontStyle::Bold).into_font())
        .color(&INK)
        .pos(Pos::new(HPos::Left, VPos::Center));
    let at = (px(10.0) as i32, px(4.0 + 0.65 * SIZE) as i32);
    top.draw(&Text::new(letter.to_owned(), at, style))?;
    Ok(rest)
}

/// Writes `title` centred at the top of `root`, wrapped onto more lines if it is too wide,
/// and returns the area below it.
fn draw_title<'a>(
    root: &DrawingArea<SVGBackend<'a>, Shift>,
    title: &str,
) -> Result<DrawingArea<SVGBackend<'a>, Shift>> {
    const SIZE: f64 = 14.0;
    let (w, _) = root.dim_in_pixel();
    // About 0.52 em per character in a sans-serif font.
    let max_chars = ((f64::from(w / SCALE) - 24.0) / (0.52 * SIZE)) as usize;
    let mut lines: Vec<String> = Vec::new();
    for word in title.split(' ') {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 1 + word.chars().count() <= max_chars => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_owned()),
        }
    }
    let line_h = 1.3 * SIZE;
    let height = px(6.0 + line_h * lines.len() as f64 + 2.0);
    let (top, rest) = root.split_vertically(height);
    let style = TextStyle::from(("sans-serif", font(SIZE)).into_font())
        .color(&INK)
        .pos(Pos::new(HPos::Center, VPos::Center));
    for (i, line) in lines.into_iter().enumerate() {
        let y = px(6.0 + line_h * (i as f64 + 0.5));
        top.draw(&Text::new(line, ((w / 2) as i32, y as i32), style.clone()))?;
    }
    Ok(rest)
}
