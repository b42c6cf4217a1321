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

mod draw;
mod layout;
mod row;

use glam::{DVec2, DVec3};
use plotters::prelude::*;

pub(crate) use row::{render_grid, render_row};

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
/// Brown, the eighth colour of a family (Okabe–Ito's yellow is too faint on white).
const BROWN: RGBColor = RGBColor(136, 85, 40);
/// The colours of a family of curves (basis functions), in order: Okabe–Ito's six, then
/// near-black and brown, so that up to eight curves on one plot each have their own.
pub(crate) const PALETTE: [RGBColor; 8] = [BLUE, VERMILION, GREEN, ORANGE, PURPLE, SKY, INK, BROWN];

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

    /// A dot smaller still: one of thousands of points (a scan).
    pub(crate) const fn dot(color: RGBColor) -> Self {
        Self { color, radius: 1.6, filled: true }
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
    /// Its size in pixels instead of the kind's own.
    size: Option<(u32, u32)>,
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
            size: None,
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

    /// Draws the plot `width` × `height` pixels instead of its kind's size; the text keeps its
    /// size, so a smaller plot has relatively larger text (panels of a grid that is printed
    /// at the width of a page).
    pub(crate) fn sized(mut self, width: u32, height: u32) -> Self {
        self.size = Some((width, height));
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
    use super::draw::{dash, tick_label};
    use super::row::panel_letter;
    use super::*;

    #[test]
    fn the_palette_has_eight_distinct_colours() {
        // Figure 2.10 draws eight blending functions on one plot, each in its own colour.
        assert_eq!(PALETTE.len(), 8);
        for (i, a) in PALETTE.iter().enumerate() {
            for b in &PALETTE[i + 1..] {
                let d = [a.0.abs_diff(b.0), a.1.abs_diff(b.1), a.2.abs_diff(b.2)];
                assert!(d.iter().map(|&c| u32::from(c)).sum::<u32>() > 60, "{a:?} and {b:?}");
            }
        }
    }

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
    fn a_grid_stacks_rows_of_plots() {
        let plot = |title: &str| {
            Plot::plane(title).sized(400, 370).points(
                &[DVec2::ZERO, DVec2::ONE],
                Marker::point(INK),
                None,
            )
        };
        let plots = [plot("one"), plot("two"), plot("three")];
        let refs: Vec<&Plot> = plots.iter().collect();
        let svg =
            String::from_utf8(render_grid("test", &refs, 2).expect("renders")).expect("utf-8");
        // Two columns of 400 pixels; two rows (the second of one plot) of 370 and a title line
        // of 24 each.
        assert!(svg.starts_with("<svg width=\"800\" height=\"788\""), "{}", &svg[..60]);
        for title in ["one", "two", "three"] {
            assert!(svg.contains(&format!("\n{title}\n</text>")), "the sub-caption {title}");
        }
        let row = String::from_utf8(render_row("test", &refs).expect("renders")).expect("utf-8");
        assert!(row.starts_with("<svg width=\"1200\" height=\"394\""), "{}", &row[..60]);
        assert!(render_grid("test", &refs, 0).is_err(), "no columns");
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
