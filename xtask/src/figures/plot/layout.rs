// SPDX-License-Identifier: MIT
//! Where things go on a plot: the ranges fitted to the marks, and the legend, kept clear of them.

use anyhow::{Result, bail};
use glam::DVec2;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::draw::dash;
use super::{
    INK, Kind, LEGEND_FONT, LEGEND_INSET, LEGEND_PAD, LEGEND_ROW, LEGEND_SAMPLE, Legend, Mark,
    Plot, SCALE, Sample, font, px,
};

impl Plot {
    /// The labelled marks, in the order they were added.
    fn legend_entries(&self) -> Vec<(Sample, &str)> {
        self.marks
            .iter()
            .filter_map(|m| match m {
                Mark::Line { pen, label: Some(label), .. } => {
                    Some((Sample::Line(*pen), label.as_str()))
                }
                Mark::Points { marker, label: Some(label), .. } => {
                    Some((Sample::Marker(*marker), label.as_str()))
                }
                _ => None,
            })
            .collect()
    }

    /// Width and height of the legend box in drawing units (0 × 0 without a legend).
    fn legend_size(&self) -> (f64, f64) {
        let entries = self.legend_entries();
        if self.legend.is_none() || entries.is_empty() {
            return (0.0, 0.0);
        }
        // About 0.58 em per character in a sans-serif font.
        let text = entries.iter().map(|(_, l)| l.chars().count()).max().unwrap_or(0) as f64
            * 0.58
            * LEGEND_FONT;
        let w = 2.0 * LEGEND_PAD + LEGEND_SAMPLE + text;
        let h = 2.0 * LEGEND_PAD + LEGEND_ROW * entries.len() as f64;
        (w * f64::from(SCALE), h * f64::from(SCALE))
    }

    /// Draws the legend box in a corner of the plotting area (pixel coordinates).
    pub(super) fn draw_legend(
        &self,
        area: &DrawingArea<SVGBackend<'_>, Shift>,
        position: Legend,
    ) -> Result<()> {
        let entries = self.legend_entries();
        if entries.is_empty() {
            return Ok(());
        }
        let (w, h) = self.legend_size();
        let (aw, ah) = area.dim_in_pixel();
        let inset = f64::from(px(LEGEND_INSET));
        let left = match position {
            Legend::UpperLeft | Legend::LowerLeft => inset,
            Legend::UpperRight | Legend::LowerRight => f64::from(aw) - inset - w,
        };
        let top = match position {
            Legend::UpperLeft | Legend::UpperRight => inset,
            Legend::LowerLeft | Legend::LowerRight => f64::from(ah) - inset - h,
        };
        let at = |x: f64, y: f64| {
            (
                (left + x * f64::from(SCALE)).round() as i32,
                (top + y * f64::from(SCALE)).round() as i32,
            )
        };
        let corner = at(0.0, 0.0);
        let far = ((left + w).round() as i32, (top + h).round() as i32);
        area.draw(&Rectangle::new([corner, far], WHITE.mix(0.92).filled()))?;
        area.draw(&Rectangle::new([corner, far], RGBColor(200, 200, 200).stroke_width(px(1.0))))?;
        let text_style = TextStyle::from(("sans-serif", font(LEGEND_FONT)).into_font())
            .color(&INK)
            .pos(Pos::new(HPos::Left, VPos::Center));
        for (i, (sample, label)) in entries.into_iter().enumerate() {
            let y = LEGEND_PAD + LEGEND_ROW * (i as f64 + 0.5);
            let (x0, x1) = (LEGEND_PAD, LEGEND_PAD + LEGEND_SAMPLE - 6.0);
            match sample {
                Sample::Line(pen) => {
                    let line = [DVec2::new(x0, y), DVec2::new(x1, y)];
                    let pieces = match pen.dash {
                        Some((on, off)) => dash(&line, on, off, DVec2::ONE),
                        None => vec![line.to_vec()],
                    };
                    for piece in pieces {
                        let path: Vec<(i32, i32)> = piece.iter().map(|p| at(p.x, p.y)).collect();
                        area.draw(&PathElement::new(path, pen.style()))?;
                    }
                }
                Sample::Marker(marker) => {
                    area.draw(&Circle::new(
                        at((x0 + x1) / 2.0, y),
                        px(marker.radius),
                        marker.style(),
                    ))?;
                }
            }
            area.draw(&Text::new(
                label.to_owned(),
                at(LEGEND_PAD + LEGEND_SAMPLE, y),
                text_style.clone(),
            ))?;
        }
        Ok(())
    }

    /// The x and y ranges: fixed ones as given, the others fitted to the marks with a margin,
    /// then widened (for plane and projection plots) to equal scales on both axes. If the
    /// legend would cover a mark, a band for it is added above (or below) the marks.
    pub(super) fn ranges(&self, plot_w: f64, plot_h: f64) -> Result<((f64, f64), (f64, f64))> {
        let first = self.ranges_with_band(plot_w, plot_h, 0.0)?;
        let (w, h) = self.legend_size();
        if h == 0.0 || self.legend_is_clear(first, plot_w, plot_h, (w, h)) {
            return Ok(first);
        }
        self.ranges_with_band(plot_w, plot_h, h + f64::from(px(LEGEND_INSET + 4.0)))
    }

    /// The ranges with `band` drawing units kept free above the marks (below for a lower
    /// legend).
    fn ranges_with_band(
        &self,
        plot_w: f64,
        plot_h: f64,
        band: f64,
    ) -> Result<((f64, f64), (f64, f64))> {
        let mut lo = DVec2::splat(f64::INFINITY);
        let mut hi = DVec2::splat(f64::NEG_INFINITY);
        let mut labelled = false;
        for mark in &self.marks {
            labelled |= matches!(mark, Mark::Labels { .. });
            for p in mark.fitted_points() {
                lo = lo.min(*p);
                hi = hi.max(*p);
            }
        }
        if !(lo.is_finite() && hi.is_finite()) {
            bail!("plot {:?} has no finite data to fit", self.title);
        }
        let extent = (hi - lo).max(DVec2::splat(1e-9));
        let fit = |fixed: Option<(f64, f64)>, lo: f64, hi: f64, pad: f64| {
            fixed.unwrap_or((lo - pad, hi + pad))
        };
        let upper = matches!(self.legend, Some(Legend::UpperLeft | Legend::UpperRight));
        // Widens (y0, y1), which fills `plot_h - band` drawing units, to fill `plot_h`, the
        // extra on the legend's side.
        let make_room = |(y0, y1): (f64, f64), total: f64| {
            let extra = total - (y1 - y0);
            if upper { (y0, y1 + extra) } else { (y0 - extra, y1) }
        };
        match self.kind {
            Kind::Function { .. } => {
                let (y0, y1) = fit(self.y_range, lo.y, hi.y, 0.06 * extent.y);
                let total = (y1 - y0) * plot_h / (plot_h - band).max(1.0);
                Ok((fit(self.x_range, lo.x, hi.x, 0.0), make_room((y0, y1), total)))
            }
            Kind::Plane | Kind::Projection => {
                // Room for the point labels (about 24 pixels) and a little air.
                let pad = extent.max_element() * if labelled { 0.12 } else { 0.06 };
                let (x0, x1) = fit(self.x_range, lo.x, hi.x, pad);
                let (y0, y1) = fit(self.y_range, lo.y, hi.y, pad);
                let scale = ((x1 - x0) / plot_w).max((y1 - y0) / (plot_h - band).max(1.0));
                let (hw, cy) = (scale * plot_w / 2.0, (y0 + y1) / 2.0);
                let free_h = scale * (plot_h - band);
                let y = make_room((cy - free_h / 2.0, cy + free_h / 2.0), scale * plot_h);
                Ok((((x0 + x1) / 2.0 - hw, (x0 + x1) / 2.0 + hw), y))
            }
        }
    }

    /// True if no mark comes within a few pixels of the legend box (point labels within their
    /// offset) when the plot has `ranges`.
    fn legend_is_clear(
        &self,
        ranges: ((f64, f64), (f64, f64)),
        plot_w: f64,
        plot_h: f64,
        size: (f64, f64),
    ) -> bool {
        let ((x0, x1), (y0, y1)) = ranges;
        let unit = DVec2::new((x1 - x0) / plot_w, (y1 - y0) / plot_h);
        let inset = f64::from(px(LEGEND_INSET));
        // The box in drawing units from the bottom-left corner of the plotting area, y up.
        let left = match self.legend {
            Some(Legend::UpperRight | Legend::LowerRight) => plot_w - inset - size.0,
            _ => inset,
        };
        let bottom = match self.legend {
            Some(Legend::UpperLeft | Legend::UpperRight) => plot_h - inset - size.1,
            _ => inset,
        };
        let near = |p: &DVec2, margin: f64| {
            let q = (*p - DVec2::new(x0, y0)) / unit;
            q.x > left - margin
                && q.x < left + size.0 + margin
                && q.y > bottom - margin
                && q.y < bottom + size.1 + margin
        };
        self.marks.iter().all(|mark| match mark {
            Mark::Line { points, .. } | Mark::Points { points, .. } => {
                !points.iter().any(|p| near(p, f64::from(px(4.0))))
            }
            Mark::Labels { points, .. } => !points.iter().any(|p| near(p, f64::from(px(24.0)))),
            Mark::Note { at, .. } => !near(at, f64::from(px(16.0))),
            Mark::Guide { .. } | Mark::Extent { .. } => true,
        })
    }
}
