// SPDX-License-Identifier: MIT
//! A small plotting layer on top of plotters, so that every figure has the same look.
//!
//! A figure builds a [`Plot`] out of marks (curves, the faint polygon of the data points,
//! markers, point labels, guide lines) and [`Plot::render`] turns it into an SVG document:
//!
//! - [`Plot::function`]: a graph y(t) with labelled axes (the basis plots);
//! - [`Plot::plane`]: a plane curve with equal aspect ratio (a circle looks round);
//! - [`Plot::projection`]: a 3-D curve after an [`Oblique`] projection, with no axes.
//!
//! Everything is drawn at [`SCALE`] times the declared size and the SVG header is then set to
//! the declared size, so curves are placed to a fraction of a pixel although plotters rounds to
//! integer coordinates. The output depends on nothing but the marks: no time stamps, no
//! hash-map order.

use anyhow::{Result, bail};
use glam::{DVec2, DVec3};
use plotters::coord::Shift;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged, ValueFormatter};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Drawing units per SVG pixel: coordinates are placed to 0.01 px.
const SCALE: u32 = 100;

/// Size in pixels of a function plot (wide: t runs along x).
const FUNCTION_SIZE: (u32, u32) = (560, 360);
/// Size in pixels of a plane-curve plot.
const PLANE_SIZE: (u32, u32) = (480, 420);

/// Margin around the chart, in pixels.
const MARGIN: u32 = 10;
/// Height of the area under the x axis (tick labels and axis name), in pixels.
const X_LABEL_AREA: u32 = 36;
/// Width of the area left of the y axis, in pixels.
const Y_LABEL_AREA: u32 = 48;

/// Legend text size, in pixels.
const LEGEND_FONT: f64 = 12.0;
/// Height of a legend row, in pixels.
const LEGEND_ROW: f64 = 18.0;
/// Padding inside the legend box, in pixels.
const LEGEND_PAD: f64 = 6.0;
/// Width of a legend's sample line plus the gap after it, in pixels.
const LEGEND_SAMPLE: f64 = 30.0;
/// Distance of the legend box from the plotting area's edges, in pixels.
const LEGEND_INSET: f64 = 6.0;

/// Okabe–Ito blue.
pub(crate) const BLUE: RGBColor = RGBColor(0, 114, 178);
/// Okabe–Ito vermilion.
pub(crate) const VERMILION: RGBColor = RGBColor(213, 94, 0);
/// Okabe–Ito bluish green.
pub(crate) const GREEN: RGBColor = RGBColor(0, 158, 115);
/// Okabe–Ito orange.
pub(crate) const ORANGE: RGBColor = RGBColor(230, 159, 0);
/// Okabe–Ito reddish purple.
pub(crate) const PURPLE: RGBColor = RGBColor(204, 121, 167);
/// Okabe–Ito sky blue.
pub(crate) const SKY: RGBColor = RGBColor(86, 180, 233);
/// Near-black, for data points and labels.
pub(crate) const INK: RGBColor = RGBColor(30, 30, 30);
/// Grey, for reference curves drawn behind the main one.
pub(crate) const GREY: RGBColor = RGBColor(150, 150, 150);
/// The colours of a family of curves (basis functions), in order.
pub(crate) const PALETTE: [RGBColor; 6] = [BLUE, VERMILION, GREEN, ORANGE, PURPLE, SKY];

/// Colour of the polygon through the data points.
const POLYGON: RGBColor = RGBColor(170, 170, 170);
/// Colour of grid lines.
const GRID: RGBColor = RGBColor(232, 232, 232);
/// Colour of guide lines (t = k/n, y = 0).
const GUIDE: RGBColor = RGBColor(200, 200, 200);
/// Colour of the axes and tick labels.
const AXIS: RGBColor = RGBColor(90, 90, 90);

/// How a line is drawn: colour, width and an optional dash pattern (lengths in pixels).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pen {
    color: RGBColor,
    width: f64,
    dash: Option<(f64, f64)>,
}

impl Pen {
    /// A solid line of the standard width for curves.
    pub(crate) const fn solid(color: RGBColor) -> Self {
        Self { color, width: 2.0, dash: None }
    }

    /// A dashed line of the standard width for curves.
    pub(crate) const fn dashed(color: RGBColor) -> Self {
        Self { color, width: 2.0, dash: Some((7.0, 4.0)) }
    }

    /// The same pen with another width in pixels.
    pub(crate) const fn width(self, width: f64) -> Self {
        Self { width, ..self }
    }

    fn style(self) -> ShapeStyle {
        self.color.stroke_width(px(self.width))
    }
}

/// How data points are marked.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Marker {
    color: RGBColor,
    radius: f64,
    filled: bool,
}

impl Marker {
    /// A filled disc: the data points of a figure.
    pub(crate) const fn point(color: RGBColor) -> Self {
        Self { color, radius: 3.5, filled: true }
    }

    /// A small filled disc: points added by a construction (subdivision).
    pub(crate) const fn small(color: RGBColor) -> Self {
        Self { color, radius: 2.5, filled: true }
    }

    /// A ring: points shown for reference (the data before a change).
    pub(crate) const fn ring(color: RGBColor) -> Self {
        Self { color, radius: 5.0, filled: false }
    }

    fn style(self) -> ShapeStyle {
        let style = self.color.stroke_width(px(1.5));
        if self.filled { style.filled() } else { style }
    }
}

/// Where the legend goes.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Legend {
    /// Top left corner of the plotting area.
    UpperLeft,
    /// Top right corner.
    UpperRight,
    /// Bottom left corner.
    LowerLeft,
    /// Bottom right corner.
    LowerRight,
}

/// A fixed orthographic view of 3-D space, for drawing space curves in a plane.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Oblique {
    /// Rotation about the z axis, in degrees.
    pub(crate) azimuth: f64,
    /// Angle of the line of sight above the xy plane, in degrees.
    pub(crate) elevation: f64,
}

impl Oblique {
    /// The screen position of `p`: x to the right, z up, y into the picture.
    pub(crate) fn project(self, p: DVec3) -> DVec2 {
        let (sa, ca) = self.azimuth.to_radians().sin_cos();
        let (se, ce) = self.elevation.to_radians().sin_cos();
        let across = p.x * ca - p.y * sa;
        let depth = p.x * sa + p.y * ca;
        DVec2::new(across, p.z * ce + depth * se)
    }
}

/// What a legend entry shows.
#[derive(Clone, Copy, Debug)]
enum Sample {
    Line(Pen),
    Marker(Marker),
}

/// Which kind of chart a plot is.
#[derive(Clone, Debug)]
enum Kind {
    /// y against t, with named axes.
    Function { x_desc: String, y_desc: String },
    /// A plane curve with equal aspect ratio and coordinate axes.
    Plane,
    /// A projected 3-D curve: equal aspect ratio, no axes.
    Projection,
}

/// One thing drawn on a plot.
#[derive(Clone, Debug)]
enum Mark {
    Line {
        points: Vec<DVec2>,
        pen: Pen,
        label: Option<String>,
        layer: u8,
    },
    Points {
        points: Vec<DVec2>,
        marker: Marker,
        label: Option<String>,
    },
    Labels {
        points: Vec<DVec2>,
        names: Vec<String>,
        closed: bool,
    },
    Guide {
        vertical: bool,
        at: f64,
    },
    Note {
        at: DVec2,
        text: String,
        offset: (f64, f64),
        color: RGBColor,
    },
    /// Points the ranges hold but nothing draws (the extent of a compared panel).
    Extent {
        points: Vec<DVec2>,
    },
}

impl Mark {
    /// The points the ranges are fitted to.
    fn fitted_points(&self) -> &[DVec2] {
        match self {
            Mark::Line { points, .. }
            | Mark::Points { points, .. }
            | Mark::Labels { points, .. }
            | Mark::Extent { points } => points,
            Mark::Guide { .. } | Mark::Note { .. } => &[],
        }
    }

    /// Marks are drawn in layers, whatever order they were added in: guides and polygons,
    /// then curves, then markers, then text.
    fn layer(&self) -> u8 {
        match self {
            Mark::Guide { .. } => 0,
            Mark::Line { layer, .. } => *layer,
            Mark::Points { .. } => 2,
            Mark::Labels { .. } | Mark::Note { .. } | Mark::Extent { .. } => 3,
        }
    }
}

/// A plot under construction: a title, a kind of chart and the marks on it.
#[derive(Clone, Debug)]
pub(crate) struct Plot {
    title: String,
    kind: Kind,
    x_range: Option<(f64, f64)>,
    y_range: Option<(f64, f64)>,
    marks: Vec<Mark>,
    legend: Option<Legend>,
    /// Tick positions on the y axis and their labels, instead of plotters' own (an axis whose
    /// values are transformed, such as a symmetric log).
    y_ticks: Option<Vec<(f64, String)>>,
}

impl Plot {
    fn new(title: &str, kind: Kind) -> Self {
        Self {
            title: title.to_owned(),
            kind,
            x_range: None,
            y_range: None,
            marks: Vec::new(),
            legend: None,
            y_ticks: None,
        }
    }

    /// A graph of functions of t, the axes named `x_desc` and `y_desc`.
    pub(crate) fn function(title: &str, x_desc: &str, y_desc: &str) -> Self {
        Self::new(title, Kind::Function { x_desc: x_desc.to_owned(), y_desc: y_desc.to_owned() })
    }

    /// A plane-curve plot with equal aspect ratio.
    pub(crate) fn plane(title: &str) -> Self {
        Self::new(title, Kind::Plane)
    }

    /// A plot of projected 3-D curves, equal aspect ratio and no axes.
    pub(crate) fn projection(title: &str) -> Self {
        Self::new(title, Kind::Projection)
    }

    /// Fixes the range of the x axis (otherwise it is fitted to the marks).
    pub(crate) fn x_range(mut self, lo: f64, hi: f64) -> Self {
        self.x_range = Some((lo, hi));
        self
    }

    /// Fixes the range of the y axis (otherwise it is fitted to the marks).
    pub(crate) fn y_range(mut self, lo: f64, hi: f64) -> Self {
        self.y_range = Some((lo, hi));
        self
    }

    /// Ticks at these y positions with these labels instead of the automatic ones.
    pub(crate) fn y_ticks(mut self, ticks: Vec<(f64, String)>) -> Self {
        self.y_ticks = Some(ticks);
        self
    }

    /// Makes the fitted ranges hold `points` too, without drawing them: two panels that are
    /// compared get the same extent.
    pub(crate) fn include(mut self, points: &[DVec2]) -> Self {
        self.marks.push(Mark::Extent { points: points.to_vec() });
        self
    }

    /// The corners of the box of every point the plot's ranges are fitted to (none for a plot
    /// without data).
    pub(crate) fn extent(&self) -> Vec<DVec2> {
        let mut lo = DVec2::splat(f64::INFINITY);
        let mut hi = DVec2::splat(f64::NEG_INFINITY);
        for p in self.marks.iter().flat_map(Mark::fitted_points) {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        if lo.is_finite() && hi.is_finite() { vec![lo, hi] } else { Vec::new() }
    }

    /// Shows a legend of the labelled marks at `position`.
    pub(crate) fn legend(mut self, position: Legend) -> Self {
        self.legend = Some(position);
        self
    }

    /// A curve through `points`, named `label` in the legend if given.
    pub(crate) fn curve(mut self, points: Vec<DVec2>, pen: Pen, label: Option<&str>) -> Self {
        self.marks.push(Mark::Line { points, pen, label: label.map(str::to_owned), layer: 1 });
        self
    }

    /// A thin faint solid line through `points`, behind the curves (context such as the edges
    /// of a cube).
    pub(crate) fn faint(mut self, points: Vec<DVec2>) -> Self {
        let pen = Pen { color: GUIDE, width: 1.0, dash: None };
        self.marks.push(Mark::Line { points, pen, label: None, layer: 0 });
        self
    }

    /// A construction's control polygon: a thin faint line through `polygon` with small grey
    /// markers on its vertices, except those among `data` (marked as data points already).
    pub(crate) fn control_polygon(self, polygon: &[DVec2], data: &[DVec2]) -> Self {
        let extra: Vec<DVec2> = polygon
            .iter()
            .copied()
            .filter(|p| !data.iter().any(|d| d.distance(*p) <= 1e-12 * (1.0 + d.length())))
            .collect();
        self.faint(polygon.to_vec()).points(&extra, Marker::small(GREY), None)
    }

    /// The polygon through the data points, drawn faintly and dashed (closed if `closed`).
    pub(crate) fn polygon(mut self, points: &[DVec2], closed: bool) -> Self {
        let mut points = points.to_vec();
        if closed && let Some(&first) = points.first() {
            points.push(first);
        }
        let pen = Pen { color: POLYGON, width: 1.0, dash: Some((4.0, 3.0)) };
        self.marks.push(Mark::Line { points, pen, label: None, layer: 0 });
        self
    }

    /// Markers at `points`, named `label` in the legend if given.
    pub(crate) fn points(mut self, points: &[DVec2], marker: Marker, label: Option<&str>) -> Self {
        self.marks.push(Mark::Points {
            points: points.to_vec(),
            marker,
            label: label.map(str::to_owned),
        });
        self
    }

    /// Names written beside `points`, each pushed away from its two neighbours in the sequence
    /// (cyclic if `closed`), which keeps it off the polygon and the curve through the points.
    pub(crate) fn labels(mut self, points: &[DVec2], names: Vec<String>, closed: bool) -> Self {
        self.marks.push(Mark::Labels { points: points.to_vec(), names, closed });
        self
    }

    /// `text` near `at`, moved by `offset` pixels (x right, y up), centred there.
    pub(crate) fn note(
        mut self,
        at: DVec2,
        text: &str,
        offset: (f64, f64),
        color: RGBColor,
    ) -> Self {
        self.marks.push(Mark::Note { at, text: text.to_owned(), offset, color });
        self
    }

    /// A faint vertical guide line at x = `at`.
    pub(crate) fn vguide(mut self, at: f64) -> Self {
        self.marks.push(Mark::Guide { vertical: true, at });
        self
    }

    /// A faint horizontal guide line at y = `at`.
    pub(crate) fn hguide(mut self, at: f64) -> Self {
        self.marks.push(Mark::Guide { vertical: false, at });
        self
    }

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
    const fn size(&self) -> (u32, u32) {
        match self.kind {
            Kind::Function { .. } => FUNCTION_SIZE,
            Kind::Plane | Kind::Projection => PLANE_SIZE,
        }
    }

    fn draw_chart(&self, area: &DrawingArea<SVGBackend<'_>, Shift>) -> Result<()> {
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

        let mut marks: Vec<&Mark> = self.marks.iter().collect();
        marks.sort_by_key(|m| m.layer());
        for mark in marks {
            draw_mark(&mut chart, mark, (xr, yr), unit)?;
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
    fn draw_legend(
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
    fn ranges(&self, plot_w: f64, plot_h: f64) -> Result<((f64, f64), (f64, f64))> {
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

/// The chart the marks are drawn on: plotters' own x coordinate, and the y coordinate `Y`.
type Chart<'a, 'b, Y> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, Y>>;

/// Draws one mark on `chart`, whose ranges are `(xr, yr)` and whose data units per drawing
/// unit are `unit`.
fn draw_mark<Y: Ranged<ValueType = f64> + ValueFormatter<f64>>(
    chart: &mut Chart<'_, '_, Y>,
    mark: &Mark,
    (xr, yr): ((f64, f64), (f64, f64)),
    unit: DVec2,
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
            let offsets = label_offsets(points, names, *closed, unit);
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

/// Several plots side by side in one SVG document under `title`, each with its own title as a
/// sub-caption (a curve beside its curvature plot).
///
/// # Errors
///
/// As [`Plot::render`].
pub(crate) fn render_row(title: &str, plots: &[&Plot]) -> Result<Vec<u8>> {
    let sizes: Vec<(u32, u32)> = plots.iter().map(|p| p.size()).collect();
    let size = (
        sizes.iter().map(|s| s.0).sum::<u32>(),
        sizes.iter().map(|s| s.1).max().unwrap_or(0) + TITLE_SPACE,
    );
    let mut svg = String::new();
    {
        let root =
            SVGBackend::with_string(&mut svg, (size.0 * SCALE, size.1 * SCALE)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut rest = draw_panel_letter(&root, title)?;
        for (plot, own) in plots.iter().zip(&sizes) {
            let (cell, right) = rest.split_horizontally(own.0 * SCALE);
            let chart = draw_title(&cell, &plot.title)?;
            plot.draw_chart(&chart)?;
            rest = right;
        }
        root.present()?;
    }
    unscale(svg, size)
}

/// Extra height in pixels of a row of plots, for the second title line.
const TITLE_SPACE: u32 = 24;

/// Sets the header of an SVG document drawn at [`SCALE`] times `size` to `size`.
fn unscale(svg: String, size: (u32, u32)) -> Result<Vec<u8>> {
    let header = format!("<svg width=\"{}\" height=\"{}\"", size.0 * SCALE, size.1 * SCALE);
    if !svg.starts_with(&header) {
        bail!("unexpected SVG header from plotters: {:?}", svg.get(..60));
    }
    let svg = svg.replacen(&header, &format!("<svg width=\"{}\" height=\"{}\"", size.0, size.1), 1);
    Ok(svg.into_bytes())
}

/// The panel letter of a figure's title: "(b)" of "Figure 2.5 (b) G1 with s = 0.6"; none for
/// a figure of one panel.
fn panel_letter(title: &str) -> Option<&str> {
    let mut words = title.strip_prefix("Figure ")?.split(' ');
    words.next()?;
    let letter = words.next()?;
    let inner = letter.strip_prefix('(')?.strip_suffix(')')?;
    (!inner.is_empty() && inner.chars().all(|c| c.is_ascii_lowercase())).then_some(letter)
}

/// The figure's panel letter, bold at the top left of `root` (the title itself is the gallery's
/// caption), and the area below it; all of `root` for a figure of one panel.
fn draw_panel_letter<'a>(
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

/// Samples `f` at `count + 1` equally spaced parameters from `t0` to `t1` inclusive.
pub(crate) fn sample(t0: f64, t1: f64, count: usize, f: impl Fn(f64) -> DVec2) -> Vec<DVec2> {
    (0..=count).map(|i| f(t0 + (t1 - t0) * i as f64 / count as f64)).collect()
}

/// `base` with the subscript `k` in Unicode subscript digits: `sub("x", 12)` is "x₁₂".
pub(crate) fn sub(base: &str, k: usize) -> String {
    const DIGITS: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];
    let mut s = base.to_owned();
    for d in k.to_string().bytes() {
        s.push(DIGITS[usize::from(d - b'0')]);
    }
    s
}

/// The names `base₀`, …, `base₍ₙ₋₁₎`.
pub(crate) fn names(base: &str, n: usize) -> Vec<String> {
    (0..n).map(|k| sub(base, k)).collect()
}

/// A length of `pixels` SVG pixels in drawing units.
fn px(pixels: f64) -> u32 {
    (pixels * f64::from(SCALE)).round() as u32
}

/// The plotters font size that gives `pixels`-pixel text in the SVG (its backend divides the
/// size by 1.24).
fn font(pixels: f64) -> f64 {
    pixels * f64::from(SCALE) * 1.24
}

/// A tick label: at most three decimals, no trailing zeros, no "-0".
fn tick_label(v: f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".to_owned() } else { s.to_owned() }
}

/// Cuts a polyline into dashes `on` drawing units long with gaps `off` long; `unit` is the size
/// of a drawing unit in data coordinates along each axis.
fn dash(points: &[DVec2], on: f64, off: f64, unit: DVec2) -> Vec<Vec<DVec2>> {
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
fn label_offsets(points: &[DVec2], names: &[String], closed: bool, unit: DVec2) -> Vec<(i32, i32)> {
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
            let off = clear_of_point(dir, chars) * f64::from(SCALE);
            (off.x.round() as i32, off.y.round() as i32)
        })
        .collect()
}

/// The offset in pixels, along the unit direction `dir` (y down), that puts a label of
/// `chars` characters of 15-pixel italic text just clear of a data point's marker: its box
/// (about 7.5 pixels a character by 16) and a disc of 5 pixels about the point do not meet.
pub(crate) fn clear_of_point(dir: DVec2, chars: usize) -> DVec2 {
    const CLEAR: f64 = 5.0;
    let (half_w, half_h) = (3.75 * chars as f64 + 2.0, 8.0);
    let along_x = if dir.x.abs() > 1e-9 { (half_w + CLEAR) / dir.x.abs() } else { f64::INFINITY };
    let along_y = if dir.y.abs() > 1e-9 { (half_h + CLEAR) / dir.y.abs() } else { f64::INFINITY };
    dir * along_x.min(along_y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subscripts() {
        assert_eq!(sub("x", 0), "x₀");
        assert_eq!(sub("p", 12), "p₁₂");
        assert_eq!(names("y", 2), vec!["y₀".to_owned(), "y₁".to_owned()]);
    }

    #[test]
    fn panel_letters_come_from_the_title() {
        assert_eq!(panel_letter("Figure 2.5 (b) G1 with s = 0.6"), Some("(b)"));
        assert_eq!(panel_letter("Figure 3.17 (a) Harmonic interpolation"), Some("(a)"));
        assert_eq!(panel_letter("Figure 1.2 A cubic through four points"), None);
        assert_eq!(panel_letter("Figure 4.8 (σ) notation"), None);
        assert_eq!(panel_letter("test"), None);
    }

    #[test]
    fn labels_clear_their_point() {
        // Straight up: the half height and the gap; sideways: the half width and the gap.
        assert_eq!(clear_of_point(DVec2::new(0.0, -1.0), 2), DVec2::new(0.0, -13.0));
        assert_eq!(clear_of_point(DVec2::new(1.0, 0.0), 2), DVec2::new(14.5, 0.0));
        // Diagonally, whichever side clears first.
        let d = DVec2::new(1.0, 1.0).normalize();
        let off = clear_of_point(d, 7);
        assert!((off.y - 13.0).abs() < 1e-9 && off.x < 3.75 * 7.0 + 7.0, "{off}");
    }

    #[test]
    fn tick_labels_are_short() {
        assert_eq!(tick_label(0.30000000000000004), "0.3");
        assert_eq!(tick_label(-0.0), "0");
        assert_eq!(tick_label(2.0), "2");
        assert_eq!(tick_label(-0.125), "-0.125");
    }

    #[test]
    fn dashes_cover_the_line() {
        let line = [DVec2::ZERO, DVec2::new(10.0, 0.0)];
        let dashes = dash(&line, 2.0, 1.0, DVec2::ONE);
        // 0–2, 3–5, 6–8, 9–10.
        assert_eq!(dashes.len(), 4, "{dashes:?}");
        assert_eq!(dashes[1], vec![DVec2::new(3.0, 0.0), DVec2::new(5.0, 0.0)]);
        assert_eq!(dashes[3], vec![DVec2::new(9.0, 0.0), DVec2::new(10.0, 0.0)]);
    }

    #[test]
    fn a_plane_plot_renders() {
        let square = [DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
        let svg = Plot::plane("test")
            .polygon(&square, true)
            .points(&square, Marker::point(INK), Some("points"))
            .labels(&square, names("x", 4), true)
            .legend(Legend::UpperLeft)
            .render()
            .expect("renders");
        let svg = String::from_utf8(svg).expect("utf-8");
        assert!(
            svg.starts_with("<svg width=\"480\" height=\"420\" viewBox=\"0 0 48000 42000\""),
            "{}",
            &svg[..80]
        );
        assert!(!svg.contains(">test<"), "the title is the gallery's caption, not in the picture");
        assert!(svg.contains("x₃"), "labels are written");
    }
}
