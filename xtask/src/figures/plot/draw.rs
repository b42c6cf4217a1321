// SPDX-License-Identifier: MIT
//! Drawing a plot: the chart, its axes and its marks, in layers; dashes and point labels.

use anyhow::{Result, bail};
use glam::DVec2;
use plotters::coord::Shift;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged, ValueFormatter};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::row::{draw_panel_letter, unscale};
use super::{
    AXIS, FUNCTION_SIZE, GRID, GUIDE, INK, Kind, MARGIN, Mark, PLANE_SIZE, Plot, SCALE,
    X_LABEL_AREA, Y_LABEL_AREA, clear_of_point, font, px,
};

impl Plot {
    /// The SVG document.
    ///
    /// # Errors
    ///
    /// If plotters fails to draw or the plot has nothing to fit its ranges to.
    pub(crate) fn render(&self) -> Result<Vec<u8>> {
        let size = self.size();
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (size.0 * SCALE, size.1 * SCALE))
                .into_drawing_area();
            root.fill(&WHITE)?;
            let area = draw_panel_letter(&root, &self.title)?;
            self.draw_chart(&area)?;
            root.present()?;
        }
        unscale(svg, size)
    }

    /// The size in pixels of the plot on its own.
    pub(super) const fn size(&self) -> (u32, u32) {
        if let Some(size) = self.size {
            return size;
        }
        match self.kind {
            Kind::Function { .. } => FUNCTION_SIZE,
            Kind::Plane | Kind::Projection => PLANE_SIZE,
        }
    }

    pub(super) fn draw_chart(&self, area: &DrawingArea<SVGBackend<'_>, Shift>) -> Result<()> {
        let axes = !matches!(self.kind, Kind::Projection);
        let (x_area, y_area) = if axes { (X_LABEL_AREA, Y_LABEL_AREA) } else { (0, 0) };
        let (w, h) = area.dim_in_pixel();
        let plot_w = w.saturating_sub(2 * MARGIN * SCALE + y_area * SCALE);
        let plot_h = h.saturating_sub(2 * MARGIN * SCALE + x_area * SCALE);
        let (xr, yr) = self.ranges(f64::from(plot_w), f64::from(plot_h))?;
        let mut builder = ChartBuilder::on(area);
        builder
            .margin(MARGIN * SCALE)
            .x_label_area_size(x_area * SCALE)
            .y_label_area_size(y_area * SCALE);
        match &self.y_ticks {
            None => {
                let chart = builder.build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)?;
                self.draw_marks(chart, (xr, yr), (plot_w, plot_h), |v| tick_label(*v))
            }
            Some(ticks) => {
                let keys = ticks.iter().map(|t| t.0).collect();
                let y = KeyedAxis { inner: (yr.0..yr.1).into(), keys };
                let chart = builder.build_cartesian_2d(xr.0..xr.1, y)?;
                let label = |v: &f64| {
                    ticks.iter().find(|t| t.0 == *v).map_or_else(|| tick_label(*v), |t| t.1.clone())
                };
                self.draw_marks(chart, (xr, yr), (plot_w, plot_h), label)
            }
        }
    }

    /// Draws the axes, the marks and the legend on `chart`, whose y coordinate is plotters'
    /// own or one with given key points (labelled by `y_label`).
    fn draw_marks<Y: Ranged<ValueType = f64> + ValueFormatter<f64>>(
        &self,
        mut chart: Chart<'_, '_, Y>,
        (xr, yr): ((f64, f64), (f64, f64)),
        (plot_w, plot_h): (u32, u32),
        y_label: impl Fn(&f64) -> String,
    ) -> Result<()> {
        let axes = !matches!(self.kind, Kind::Projection);
        if chart.plotting_area().dim_in_pixel() != (plot_w, plot_h) {
            bail!(
                "plot area is {:?}, expected {:?}",
                chart.plotting_area().dim_in_pixel(),
                (plot_w, plot_h)
            );
        }
        // Data units per drawing unit along each axis, for dashes and label offsets.
        let unit = DVec2::new((xr.1 - xr.0) / f64::from(plot_w), (yr.1 - yr.0) / f64::from(plot_h));

        if axes {
            self.draw_axes(&mut chart, y_label)?;
        }

        // The rings (a peak marked on a curve), which point labels keep clear of too.
        let rings: Vec<(DVec2, f64)> = self
            .marks
            .iter()
            .filter_map(|m| match m {
                Mark::Points { points, marker, .. } if !marker.filled => {
                    Some(points.iter().map(move |p| (*p, marker.radius)))
                }
                _ => None,
            })
            .flatten()
            .collect();
        let mut marks: Vec<&Mark> = self.marks.iter().collect();
        marks.sort_by_key(|m| m.layer());
        for mark in marks {
            draw_mark(&mut chart, mark, (xr, yr), unit, &rings)?;
        }

        if let Some(position) = self.legend {
            self.draw_legend(&chart.plotting_area().strip_coord_spec(), position)?;
        }
        Ok(())
    }

    /// Draws the axes on `chart`: the grid, ticks and their labels (the y ones by `y_label`),
    /// and the axes' names.
    fn draw_axes<Y: Ranged<ValueType = f64> + ValueFormatter<f64>>(
        &self,
        chart: &mut Chart<'_, '_, Y>,
        y_label: impl Fn(&f64) -> String,
    ) -> Result<()> {
        let (x_desc, y_desc) = match &self.kind {
            Kind::Function { x_desc, y_desc } => (x_desc.as_str(), y_desc.as_str()),
            Kind::Plane | Kind::Projection => ("x", "y"),
        };
        let tick_font = ("sans-serif", font(12.0)).into_font().color(&AXIS);
        let desc_font = ("serif", font(15.0)).into_font().style(FontStyle::Italic).color(&INK);
        let formatter = |v: &f64| tick_label(*v);
        let y_formatter = |v: &f64| y_label(v);
        chart
            .configure_mesh()
            .x_desc(x_desc)
            .y_desc(y_desc)
            .x_labels(if matches!(self.kind, Kind::Function { .. }) { 11 } else { 7 })
            .y_labels(7)
            .max_light_lines(0)
            .bold_line_style(GRID.stroke_width(px(1.0)))
            .axis_style(AXIS.stroke_width(px(1.0)))
            .set_all_tick_mark_size(px(4.0))
            .label_style(tick_font)
            .axis_desc_style(desc_font)
            .x_label_formatter(&formatter)
            .y_label_formatter(&y_formatter)
            .draw()?;
        Ok(())
    }
}

/// The chart the marks are drawn on: plotters' own x coordinate, and the y coordinate `Y`.
type Chart<'a, 'b, Y> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, Y>>;

/// Draws one mark on `chart`, whose ranges are `(xr, yr)` and whose data units per drawing
/// unit are `unit`; `rings` (centre, radius in pixels) are the plot's ring markers, which
/// labels keep clear of.
fn draw_mark<Y: Ranged<ValueType = f64> + ValueFormatter<f64>>(
    chart: &mut Chart<'_, '_, Y>,
    mark: &Mark,
    (xr, yr): ((f64, f64), (f64, f64)),
    unit: DVec2,
    rings: &[(DVec2, f64)],
) -> Result<()> {
    match mark {
        Mark::Extent { .. } => {}
        Mark::Guide { vertical, at } => {
            let line = if *vertical {
                vec![(*at, yr.0), (*at, yr.1)]
            } else {
                vec![(xr.0, *at), (xr.1, *at)]
            };
            chart.draw_series(std::iter::once(PathElement::new(
                line,
                GUIDE.stroke_width(px(1.0)),
            )))?;
        }
        Mark::Line { points, pen, .. } => {
            let pieces = match pen.dash {
                Some((on, off)) => dash(points, f64::from(px(on)), f64::from(px(off)), unit),
                None => vec![points.clone()],
            };
            let style = pen.style();
            let series = pieces.into_iter().map(move |piece| {
                PathElement::new(piece.into_iter().map(|p| (p.x, p.y)).collect::<Vec<_>>(), style)
            });
            chart.draw_series(series)?;
        }
        Mark::Points { points, marker, .. } => {
            let style = marker.style();
            let radius = px(marker.radius);
            chart
                .draw_series(points.iter().map(move |p| Circle::new((p.x, p.y), radius, style)))?;
        }
        Mark::Labels { points, names, closed } => {
            let style = TextStyle::from(("serif", font(15.0)).into_font().style(FontStyle::Italic))
                .color(&INK)
                .pos(Pos::new(HPos::Center, VPos::Center));
            let offsets = label_offsets(points, names, *closed, unit, rings);
            let texts = points.iter().zip(names).zip(offsets).map(|((p, name), off)| {
                EmptyElement::at((p.x, p.y))
                    + Text::new(name.clone(), (off.0, off.1), style.clone())
            });
            chart.draw_series(texts)?;
        }
        Mark::Note { at, text, offset, color } => {
            let style = TextStyle::from(("serif", font(15.0)).into_font().style(FontStyle::Italic))
                .color(color)
                .pos(Pos::new(HPos::Center, VPos::Center));
            let scale = f64::from(SCALE);
            let off = ((offset.0 * scale).round() as i32, (-offset.1 * scale).round() as i32);
            chart.draw_series(std::iter::once(
                EmptyElement::at((at.x, at.y)) + Text::new(text.clone(), off, style),
            ))?;
        }
    }
    Ok(())
}

/// A linear axis whose ticks are given rather than chosen by plotters.
struct KeyedAxis {
    inner: RangedCoordf64,
    keys: Vec<f64>,
}

impl Ranged for KeyedAxis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }

    fn key_points<Hint: KeyPointHint>(&self, _hint: Hint) -> Vec<f64> {
        self.keys.clone()
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.inner.range()
    }
}

/// A tick label: at most three decimals, no trailing zeros, no "-0".
pub(super) fn tick_label(v: f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".to_owned() } else { s.to_owned() }
}

/// Cuts a polyline into dashes `on` drawing units long with gaps `off` long; `unit` is the size
/// of a drawing unit in data coordinates along each axis.
pub(super) fn dash(points: &[DVec2], on: f64, off: f64, unit: DVec2) -> Vec<Vec<DVec2>> {
    let mut out = Vec::new();
    let Some(&first) = points.first() else { return out };
    let mut current = vec![first];
    let mut drawing = true;
    let mut left = on;
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        let len = ((b - a) / unit).length();
        let mut pos = 0.0;
        while len - pos > left {
            pos += left;
            let q = a + (b - a) * (pos / len);
            if drawing {
                current.push(q);
                out.push(std::mem::take(&mut current));
            } else {
                current = vec![q];
            }
            drawing = !drawing;
            left = if drawing { on } else { off };
        }
        left -= len - pos;
        if drawing {
            current.push(b);
        }
    }
    if drawing && current.len() > 1 {
        out.push(current);
    }
    out
}

/// Offsets in drawing units (y down) of the labels of `points`: away from both neighbours.
fn label_offsets(
    points: &[DVec2],
    names: &[String],
    closed: bool,
    unit: DVec2,
    rings: &[(DVec2, f64)],
) -> Vec<(i32, i32)> {
    let n = points.len();
    let screen = |p: DVec2| DVec2::new(p.x / unit.x, -p.y / unit.y);
    let centroid = points.iter().copied().sum::<DVec2>() / n.max(1) as f64;
    (0..n)
        .map(|i| {
            let p = screen(points[i]);
            let neighbour =
                |j: Option<usize>| j.map(|j| (p - screen(points[j])).normalize_or_zero());
            let prev = if i > 0 {
                Some(i - 1)
            } else if closed && n > 1 {
                Some(n - 1)
            } else {
                None
            };
            let next = if i + 1 < n {
                Some(i + 1)
            } else if closed && n > 1 {
                Some(0)
            } else {
                None
            };
            let (a, b) = (neighbour(prev).unwrap_or_default(), neighbour(next).unwrap_or_default());
            let mut dir = (a + b).normalize_or_zero();
            if dir == DVec2::ZERO {
                // Collinear neighbours (or none): go perpendicular, away from the centroid.
                let along = if a == DVec2::ZERO { b } else { a };
                dir = along.perp();
                if dir.dot(p - screen(centroid)) < 0.0 {
                    dir = -dir;
                }
                if dir == DVec2::ZERO {
                    dir = DVec2::new(0.0, -1.0);
                }
            }
            let chars = names.get(i).map_or(1, |s| s.chars().count());
            let scale = f64::from(SCALE);
            let mut off = clear_of_point(dir, chars);
            // Then further along the same way, a pixel at a time (at most 30), until the
            // label's box also clears every ring by 2 pixels.
            let half = DVec2::new(3.75 * chars as f64 + 2.0, 8.0);
            let touches = |off: DVec2| {
                rings.iter().any(|&(q, radius)| {
                    let centre = p / scale + off;
                    let q = screen(q) / scale;
                    let nearest = q.clamp(centre - half, centre + half);
                    nearest.distance(q) < radius + 2.0
                })
            };
            for _ in 0..30 {
                if !touches(off) {
                    break;
                }
                off += dir;
            }
            let off = off * scale;
            (off.x.round() as i32, off.y.round() as i32)
        })
        .collect()
}
