// SPDX-License-Identifier: MIT
//! `cargo xtask figures`: the thesis figures, regenerated into `docs/figures/`.
//!
//! The figures are listed in a registry ([`registry`]): each [`Figure`] has the thesis's
//! number and caption, a line on what is drawn and on the data, and one or more [`Panel`]s, each
//! a file and a function that draws it. Topic modules hold the drawing functions and export their
//! figures as a `FIGURES` slice:
//!
//! | module | figures |
//! |---|---|
//! | [`intro`] | 1.1–1.3, 4.2–4.4, 4.6, 4.7: a polygon mesh, a Bézier curve, a point set; Bézier patches and triangles, Chaikin's and the 4-point scheme (chapter 1, §4.2–4.5) |
//! | [`bspline`] | 4.5: B-spline surface fitting through a curve network (§4.4) |
//! | [`chapter2`] | 2.1–2.18: Lagrange, Bézier, B-spline and METAPOST curves, curvature and torsion (chapter 2) |
//! | [`basis`] | 3.1–3.6, the functions σ and σₖ |
//! | [`curves`] | 3.13, 3.14, 3.19: uniform harmonic curves against other curves |
//! | [`polygons`] | 3.7–3.12, 3.15–3.18: polygons by METAPOST, B-spline and harmonic interpolation, curvature plots; the fairness table |
//! | [`nonuniform`] | 3.20–3.23, non-uniform harmonic interpolation (§3.10) |
//! | [`theorems`] | 5.2, 5.6: subdivision, rotation and insertion (chapter 5) |
//! | [`bezier`] | 5.27–5.30: harmonic surfaces as Bézier patches (§5.7); the tables of the schemes |
//! | [`sections`] | 5.7–5.9: surfaces fitted from cross-sections (algorithm 1), once well and twice badly |
//! | [`fitting`] | 5.12: a surface fitted to scattered points through a geometry image |
//! | [`scans`] | 5.10, 5.11, 5.13–5.24: stand-in scans through geometry images, as PNG images and glTF models; the table of their fits |
//! | [`surfaces`] | 4.1, 5.1, 5.3–5.5, 5.31–5.43: surfaces as glTF models; the §5.9 curvature tables |
//! | [`masks`] | 4.8–4.10, 4.14, 4.18, 4.19, 4.23, 4.24: subdivision masks read off one step of each scheme, and the face splits |
//! | [`subdivision`] | 4.11–4.35: subdivision schemes on the cube, the star and a head as glTF models; Table 4.1 |
//!
//! [`plot`] gives them a common look on top of plotters and [`data`] holds the point sets;
//! [`html`] writes the same registry as a static gallery, `index.html`.
//! To add a figure, write its drawing function in a topic module (a new one for a new topic) and
//! add a [`Figure`] to that module's `FIGURES`; the files, the index page `README.md` and the
//! check follow from the registry.
//!
//! Every file is a pure function of the code: `--check` regenerates in memory and fails, naming
//! the files, if anything committed differs, is missing or is left over. Both draw only the
//! figures whose inputs changed ([`inputs`]: the sources a figure can reach, its data and the
//! compiler, hashed, against the keys recorded in `docs/figures/inputs.json`) or whose files are
//! missing; `--all` draws every one. The test `committed_figures_are_current` and `cargo xtask
//! crosscheck` regenerate every file but the renders (1200×900, most of the work: minutes in a
//! release build), whose presence they check; CI runs `--check` as well.

mod basis;
mod bezier;
mod bspline;
mod chapter2;
mod curves;
mod data;
mod differences;
mod fitting;
pub(crate) mod glb;
mod html;
mod inputs;
mod intro;
mod masks;
mod nonuniform;
pub(crate) mod plot;
mod polygons;
mod renders;
pub(crate) mod scans;
mod sections;
mod subdivision;
mod surfaces;
mod theorems;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::IsTerminal;
use std::path::Path;

use anyhow::{Context, Result, bail};
use indicatif::{ProgressBar, ProgressStyle};

/// The folder of the generated files, relative to the workspace root.
const OUT_DIR: &str = "docs/figures";
/// The index page inside [`OUT_DIR`].
const INDEX: &str = "README.md";

/// A function that draws one panel, given the title to write above it, as the file's bytes.
type Draw = fn(&str) -> Result<Vec<u8>>;

/// One figure of the thesis.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Figure {
    /// Chapter and number: (3, 13) is figure 3.13.
    pub(crate) number: (u32, u32),
    /// The thesis's caption, as the thesis prints it.
    pub(crate) caption: &'static str,
    /// One line on what is drawn.
    pub(crate) drawn: &'static str,
    /// The data: exact, or which stand-in and why.
    pub(crate) data: &'static str,
    /// The kind of file every panel is.
    pub(crate) format: Format,
    /// The files of the figure: one, or one per panel.
    pub(crate) panels: &'static [Panel],
    /// Panels that are renders alone (`.webp`, drawn by their own function: a close-up of a
    /// model, a scan's points), shown among the panels in the order of their suffixes.
    pub(crate) views: &'static [Panel],
}

/// The kind of file a figure is drawn into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Format {
    /// A plot: SVG, shown inline on the index page.
    Svg,
    /// A 3-D model: binary glTF (`.glb`), linked from the index page, with a render of it beside
    /// it (`.webp`, the same stem, drawn by [`renders`] from the model's bytes) shown inline.
    Glb,
    /// An image: PNG (geometry images), shown inline on the index page.
    Png,
    /// A render: lossless WebP, shown inline on the index page.
    Webp,
}

impl Format {
    /// The file extension, without the dot.
    pub(crate) const fn extension(self) -> &'static str {
        match self {
            Self::Svg => "svg",
            Self::Glb => "glb",
            Self::Png => "png",
            Self::Webp => "webp",
        }
    }
}

/// A table of numbers written into the index page, after the figures.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Table {
    /// The anchor of its section ("fairness"), unique.
    pub(crate) anchor: &'static str,
    /// Its heading ("Fairness of the polygon curves").
    pub(crate) title: &'static str,
    /// A paragraph on what is measured and how.
    pub(crate) about: &'static str,
    /// Computes it as a markdown table (one line per row).
    pub(crate) make: fn() -> Result<String>,
}

/// One file of a figure.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Panel {
    /// Appended to the figure's file stem: "" for a single file, "a", "b", "a-thesis", ….
    pub(crate) suffix: &'static str,
    /// The panel's caption, "(a) Trigonometric interpolation"; "" to use the figure's caption.
    pub(crate) title: &'static str,
    /// Draws it.
    pub(crate) draw: Draw,
}

impl Figure {
    /// "3.13".
    fn label(&self) -> String {
        format!("{}.{}", self.number.0, self.number.1)
    }

    /// The file name of `panel`: `fig-3-13a.svg`, numbers padded so that names sort.
    fn file(&self, panel: &Panel) -> String {
        let (chapter, number) = self.number;
        format!("fig-{chapter}-{number:02}{}.{}", panel.suffix, self.format.extension())
    }

    /// The file name of the render of a `.glb` panel: `fig-5-10.webp`, or an SVG for a
    /// curvature picture, which has its colour bar beside the render.
    fn render_file(&self, panel: &Panel) -> String {
        let (chapter, number) = self.number;
        let extension =
            if surfaces::has_colour_bar(self.number, panel.suffix) { "svg" } else { "webp" };
        format!("fig-{chapter}-{number:02}{}.{extension}", panel.suffix)
    }

    /// The file name of a render-only panel ([`Figure::views`]): `fig-5-10a.webp`.
    fn view_file(&self, view: &Panel) -> String {
        let (chapter, number) = self.number;
        format!("fig-{chapter}-{number:02}{}.webp", view.suffix)
    }

    /// Every panel and view with its file and the file shown for it (a model's render), in the
    /// order of their suffixes: (panel, file, shown, is a model).
    fn entries(&self) -> Vec<(&'static Panel, String, String, bool)> {
        let mut all: Vec<(&'static Panel, String, String, bool)> = self
            .panels
            .iter()
            .map(|p| {
                let file = self.file(p);
                if self.format == Format::Glb {
                    (p, file, self.render_file(p), true)
                } else {
                    (p, file.clone(), file, false)
                }
            })
            .chain(self.views.iter().map(|v| (v, self.view_file(v), self.view_file(v), false)))
            .collect();
        all.sort_by_key(|e| e.0.suffix);
        all
    }

    /// The title drawn above `panel`.
    fn title(&self, panel: &Panel) -> String {
        if panel.title.is_empty() {
            format!("Figure {}: {}", self.label(), self.caption)
        } else {
            format!("Figure {} {}", self.label(), panel.title)
        }
    }
}

/// The topic modules (by file or folder name) and their figures.
fn modules() -> [(&'static str, &'static [Figure]); 16] {
    [
        ("basis", basis::FIGURES),
        ("bezier", bezier::FIGURES),
        ("bspline", bspline::FIGURES),
        ("chapter2", chapter2::FIGURES),
        ("curves", curves::FIGURES),
        ("intro", intro::FIGURES),
        ("masks", masks::FIGURES),
        ("nonuniform", nonuniform::FIGURES),
        ("polygons", polygons::FIGURES),
        ("renders", renders::FIGURES),
        ("scans", scans::FIGURES),
        ("surfaces", surfaces::FIGURES),
        ("subdivision", subdivision::FIGURES),
        ("fitting", fitting::FIGURES),
        ("sections", sections::FIGURES),
        ("theorems", theorems::FIGURES),
    ]
}

/// Every figure, in the thesis's order.
fn registry() -> Vec<Figure> {
    let mut all: Vec<Figure> = modules().iter().flat_map(|(_, f)| f.iter().copied()).collect();
    all.sort_by_key(|f| f.number);
    all
}

/// Every table, in the order of the index page.
fn tables() -> Vec<Table> {
    let all: [&[Table]; 6] = [
        polygons::TABLES,
        subdivision::TABLES,
        surfaces::TABLES,
        bezier::TABLES,
        fitting::TABLES,
        scans::TABLES,
    ];
    all.concat()
}

/// A generated file: its name inside [`OUT_DIR`] and its bytes.
pub(crate) type Output = (String, Vec<u8>);

/// Whether [`generate`] renders the models.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Renders {
    /// Render every model (and the two rendered figures 5.25, 5.26).
    Draw,
    /// Leave the renders out: their names are listed, not drawn.
    Skip,
}

/// The files [`generate`] made, and the names of the renders it left out ([`Renders::Skip`]).
#[derive(Debug, Default)]
pub(crate) struct Generated {
    /// The files drawn.
    pub(crate) files: Vec<Output>,
    /// The renders not drawn.
    pub(crate) skipped: Vec<String>,
    /// The time each figure (or table) took, by label.
    pub(crate) times: Times,
}

/// Draws every figure (or, with `Some`, those `only` names: the others' files count as
/// skipped) and the index page, in memory, with a progress bar if `progress` and standard error
/// is a terminal; the renders only with [`Renders::Draw`].
pub(crate) fn generate(
    progress: bool,
    renders: Renders,
    only: Option<&[String]>,
) -> Result<Generated> {
    let figures = registry();
    if let Some(unknown) =
        only.unwrap_or_default().iter().find(|o| !figures.iter().any(|f| f.label() == **o))
    {
        bail!("--only {unknown}: no such figure (figures are numbered as 1.3 or 5.37)");
    }
    let chosen = |f: &Figure| only.is_none_or(|only| only.iter().any(|o| *o == f.label()));
    let count: usize =
        figures.iter().filter(|f| chosen(f)).map(|f| f.panels.len() + f.views.len()).sum();
    let bar = if progress && std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(count as u64);
        bar.set_style(ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}")?);
        bar
    } else {
        ProgressBar::hidden()
    };
    // The tables (mostly one thread's work, a few seconds) are computed beside the figures,
    // whose renders keep every core busy but for their gaps.
    let (drawn, computed) = std::thread::scope(|scope| {
        let tables = scope.spawn(compute_tables);
        let drawn = draw_figures(&figures, &chosen, renders, &bar, count);
        bar.set_message("the tables");
        let computed = tables.join().map_err(|_| anyhow::anyhow!("computing the tables panicked"));
        (drawn, computed)
    });
    let (mut outputs, skipped, mut times) = drawn?;
    let (computed, table_times) = computed??;
    times.extend(table_times);
    bar.finish_and_clear();
    outputs.push((INDEX.to_owned(), index(&figures, &computed).into_bytes()));
    let sizes = image_sizes(&figures, &outputs);
    outputs
        .push((html::GALLERY.to_owned(), html::gallery(&figures, &computed, &sizes).into_bytes()));
    outputs.push((html::VIEWER.to_owned(), html::VIEWER_PAGE.as_bytes().to_vec()));
    Ok(Generated { files: outputs, skipped, times })
}

/// The time each figure or table took, by label.
type Times = Vec<(String, std::time::Duration)>;

/// Every table, with the time each took.
fn compute_tables() -> Result<(Vec<(Table, String)>, Times)> {
    let mut computed = Vec::new();
    let mut times = Vec::new();
    for table in tables() {
        let start = std::time::Instant::now();
        let body = (table.make)().with_context(|| format!("computing table {}", table.anchor))?;
        computed.push((table, body));
        times.push((format!("table {}", table.anchor), start.elapsed()));
    }
    Ok((computed, times))
}

/// The files of the `chosen` figures (`count` panels and views), the names of those left out,
/// and the time each figure took; the renders only with [`Renders::Draw`].
fn draw_figures(
    figures: &[Figure],
    chosen: &dyn Fn(&Figure) -> bool,
    renders: Renders,
    bar: &ProgressBar,
    count: usize,
) -> Result<(Vec<Output>, Vec<String>, Times)> {
    let mut outputs = Vec::with_capacity(count + 3);
    let mut skipped = Vec::new();
    let mut times = Vec::new();
    for figure in figures {
        let start = std::time::Instant::now();
        if !chosen(figure) {
            skipped.extend(figure.entries().into_iter().flat_map(|(_, file, shown, model)| {
                if model { vec![file, shown] } else { vec![file] }
            }));
            continue;
        }
        let mut drawn = Vec::with_capacity(figure.panels.len());
        for panel in figure.panels {
            let file = figure.file(panel);
            if renders == Renders::Skip && figure.format == Format::Webp {
                skipped.push(file);
                bar.inc(1);
                continue;
            }
            bar.set_message(file.clone());
            let bytes =
                (panel.draw)(&figure.title(panel)).with_context(|| format!("drawing {file}"))?;
            drawn.push((file, bytes));
            bar.inc(1);
        }
        if figure.format == Format::Glb && renders == Renders::Skip {
            skipped.extend(figure.panels.iter().map(|p| figure.render_file(p)));
        } else if figure.format == Format::Glb {
            // The panels' renders, framed together when they show one object.
            bar.set_message(format!("rendering figure {}", figure.label()));
            let glbs: Vec<&[u8]> = drawn.iter().map(|(_, b)| b.as_slice()).collect();
            let images = renders::render_models(figure.number, &glbs)
                .with_context(|| format!("rendering figure {}", figure.label()))?;
            for (panel, image) in figure.panels.iter().zip(images) {
                let picture = if surfaces::has_colour_bar(figure.number, panel.suffix) {
                    let (legend, symbol) = surfaces::colour_bar(figure.number, panel.suffix)?;
                    let size = (renders::WIDTH, renders::HEIGHT);
                    let jpeg = renders::to_jpeg(&image)?;
                    surfaces::colour_bar_svg(&jpeg, size, &legend, symbol).into_bytes()
                } else {
                    image
                };
                outputs.push((figure.render_file(panel), picture));
            }
        }
        outputs.extend(drawn);
        for view in figure.views {
            let file = figure.view_file(view);
            if renders == Renders::Skip {
                skipped.push(file);
            } else {
                bar.set_message(file.clone());
                let bytes =
                    (view.draw)(&figure.title(view)).with_context(|| format!("drawing {file}"))?;
                outputs.push((file, bytes));
            }
            bar.inc(1);
        }
        times.push((figure.label(), start.elapsed()));
    }
    Ok((outputs, skipped, times))
}

/// The width and height of every image the gallery shows, from its bytes among `outputs`, or
/// for a render not drawn this time, from the committed file (which `--check` compares with a
/// fresh render): the gallery gives them to the browser so that the page does not reflow as
/// lazily loaded images arrive.
fn image_sizes(figures: &[Figure], outputs: &[Output]) -> BTreeMap<String, (u32, u32)> {
    let drawn: BTreeMap<&str, &[u8]> =
        outputs.iter().map(|(name, bytes)| (name.as_str(), bytes.as_slice())).collect();
    let dir = crate::project_root().join(OUT_DIR);
    let mut sizes = BTreeMap::new();
    for f in figures {
        for (_, _, shown, _) in f.entries() {
            let size = match drawn.get(shown.as_str()) {
                Some(bytes) => image_size(&shown, bytes),
                None => std::fs::read(dir.join(&shown)).ok().and_then(|b| image_size(&shown, &b)),
            };
            if let Some(size) = size {
                sizes.insert(shown, size);
            }
        }
    }
    sizes
}

/// The size of an image file: an SVG's `width` and `height` attributes (in pixels), or the
/// header of a PNG, WebP or JPEG.
fn image_size(name: &str, bytes: &[u8]) -> Option<(u32, u32)> {
    if name.ends_with(".svg") {
        let text = std::str::from_utf8(bytes).ok()?;
        let root = &text[text.find("<svg")?..];
        let root = &root[..root.find('>')?];
        let attribute = |key: &str| -> Option<u32> {
            let start = root.find(&format!(" {key}=\""))? + key.len() + 3;
            let value = &root[start..];
            let value = value[..value.find('"')?].trim_end_matches("px");
            value.parse::<f64>().ok().map(|v| v.round() as u32)
        };
        return Some((attribute("width")?, attribute("height")?));
    }
    image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .ok()?
        .into_dimensions()
        .ok()
}

/// `text` as the cell of a Markdown table: its `|` (as in |κ|) escaped, so that it does not
/// end the cell.
fn cell(text: &str) -> String {
    text.replace('|', "\\|")
}

/// The index page: every figure with its files, caption and notes, the tables, then the
/// stand-in data.
fn index(figures: &[Figure], tables: &[(Table, String)]) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# Figures of the thesis\n");
    let _ = writeln!(
        s,
        "Figures of A. Hardy, *Harmonic interpolation for smooth curves and surfaces* (2005), \
         drawn with `hi-bezier` and `hi-curve` as SVG; geometry images as PNG; surfaces made with `hi-surface` as \
         binary glTF models (`.glb`, linked: open them in any glTF viewer, or turn them in \
         [viewer.html](viewer.html), a page of this folder that needs no network; rendered images come \
         with the ray tracer: 1200×900 lossless WebP, 16 samples per pixel).\n\
         Generated by `cargo xtask figures` from `xtask/src/figures/`: do not edit by hand. \
         `cargo xtask figures --check` (and `cargo test -p xtask`) fails when a file here is stale. \
         The same figures as a page with the images inline: [index.html](index.html).\n\n\
         The thesis does not print its figures' point coordinates: where a figure needs points, a \
         stand-in is used and named below (coordinates in [Stand-in data](#stand-in-data)). The \
         last column says where a result differs from the thesis's and why (\"–\": it does not, \
         beyond the data).\n"
    );
    let _ = writeln!(
        s,
        "| figure | caption | files | what is drawn | data | differs from the thesis |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|");
    for f in figures {
        let files: Vec<String> =
            f.entries().into_iter().map(|(_, file, _, _)| format!("[{file}]({file})")).collect();
        let _ = writeln!(
            s,
            "| [{}](#figure-{}) | {} | {} | {} | {} | {} |",
            f.label(),
            f.label().replace('.', ""),
            cell(f.caption),
            files.join("<br>"),
            cell(f.drawn),
            cell(f.data),
            cell(differences::differs(f.number).unwrap_or("–"))
        );
    }
    let _ = writeln!(s);
    for f in figures {
        let _ = writeln!(s, "## Figure {}\n", f.label());
        let _ = writeln!(s, "*{}.* {} Data: {}\n", f.caption, f.drawn, f.data);
        if let Some(note) = differences::differs(f.number) {
            let _ = writeln!(s, "Differs from the thesis: {note}\n");
        }
        for (p, file, shown, model) in f.entries() {
            if !p.title.is_empty() {
                let _ = writeln!(s, "{}: `{file}`\n", p.title);
            }
            if model {
                let _ = writeln!(
                    s,
                    "![{}]({shown})\n\n{}: 3-D model [{file}]({file})\n",
                    f.title(p),
                    f.title(p)
                );
            } else {
                let _ = writeln!(s, "![{}]({file})\n", f.title(p));
            }
        }
    }
    if !tables.is_empty() {
        let _ = writeln!(s, "## Tables\n");
        for (t, body) in tables {
            let _ = writeln!(
                s,
                "### {}\n\n<a id=\"{}\"></a>{}\n\n{}",
                t.title, t.anchor, t.about, body
            );
        }
    }
    let _ = writeln!(s, "## Stand-in data\n");
    for d in data::STAND_INS {
        let points: Vec<String> = (d.points)()
            .iter()
            .map(|p| {
                if d.space {
                    format!("({}, {}, {})", p.x, p.y, p.z)
                } else {
                    format!("({}, {})", p.x, p.y)
                }
            })
            .collect();
        let (first, second) = (plot::sub(d.letter, 0), plot::sub(d.letter, 1));
        let _ = writeln!(
            s,
            "- **{}**: {}.\n  Points {first}, {second}, …: {}.",
            d.name,
            d.about,
            points.join(", ")
        );
    }
    s
}

/// The names of the files in `dir` that differ from the files `generated`, are missing (a
/// skipped render included), or are figures (`fig-*`) that nothing generates any more.
pub(crate) fn stale_files(dir: &Path, generated: &Generated) -> Result<Vec<String>> {
    let mut stale = Vec::new();
    for (name, bytes) in &generated.files {
        match std::fs::read(dir.join(name)) {
            Ok(on_disk) if on_disk == *bytes => {}
            Ok(_) => stale.push(format!("{name} (differs)")),
            Err(_) => stale.push(format!("{name} (missing)")),
        }
    }
    for name in &generated.skipped {
        if !dir.join(name).is_file() {
            stale.push(format!("{name} (missing)"));
        }
    }
    for name in orphans(dir, generated)? {
        stale.push(format!("{name} (no longer generated)"));
    }
    Ok(stale)
}

/// The `fig-*` files in `dir` that are neither among the files `generated` nor its skipped
/// renders, sorted.
fn orphans(dir: &Path, generated: &Generated) -> Result<Vec<String>> {
    if !dir.exists() {
        return Ok(Vec::new());
    }
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).with_context(|| format!("reading {}", dir.display()))? {
        let name = entry?.file_name().to_string_lossy().into_owned();
        let known =
            generated.files.iter().any(|(n, _)| *n == name) || generated.skipped.contains(&name);
        if name.starts_with("fig-") && !known {
            found.push(name);
        }
    }
    found.sort();
    Ok(found)
}

/// Writes every figure and the index into `docs/figures/` (or, with `check`, verifies that the
/// committed ones are current, writing nothing); the renders only with [`Renders::Draw`] (with
/// [`Renders::Skip`] they are left as they are, and only checked to be there).
///
/// # Errors
///
/// If a figure fails to draw, a file cannot be read or written, or (with `check`) a file is
/// stale; the error names the stale files.
pub(crate) fn run(root: &Path, check: bool, renders: Renders, select: &Select) -> Result<()> {
    let dir = root.join(OUT_DIR);
    let start = std::time::Instant::now();
    let keys = keys(root)?;
    let recorded = inputs::recorded(&dir.join(inputs::MANIFEST));
    let changed: Vec<String> = registry()
        .iter()
        .filter(|f| {
            recorded.get(&f.label()) != keys.get(&f.label())
                || f.entries().iter().any(|(_, file, shown, _)| {
                    !dir.join(file).is_file() || !dir.join(shown).is_file()
                })
        })
        .map(Figure::label)
        .collect();
    let only: Option<&[String]> = match select {
        Select::Changed if renders == Renders::Draw => {
            let count = registry().len();
            println!(
                "figures: {} of {count} unchanged since {OUT_DIR}/{} (the same inputs), {} to draw{}",
                count - changed.len(),
                inputs::MANIFEST,
                changed.len(),
                if changed.is_empty() {
                    String::new()
                } else {
                    format!(": {}", changed.join(", "))
                }
            );
            Some(&changed)
        }
        Select::Only(only) => Some(only),
        _ => None,
    };
    let generated = generate(true, renders, only)?;
    print_times(&generated.times, start.elapsed());
    if check {
        let stale = stale_files(&dir, &generated)?;
        if !stale.is_empty() {
            bail!(
                "{} file(s) in {OUT_DIR} are stale; run `cargo xtask figures`:\n  {}",
                stale.len(),
                stale.join("\n  ")
            );
        }
        println!("figures: {} files in {OUT_DIR} are current", generated.files.len());
        match html::check_gallery(&dir)? {
            Some(summary) => println!("figures: {summary}"),
            None => {
                println!("figures: gallery not opened in a browser (Chromium is not installed)")
            }
        }
        return Ok(());
    }
    std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    // The keys of the figures drawn whole now (a figure with renders counts only when they
    // were drawn); the others keep the key they had.
    let drawn_whole = |f: &Figure| {
        only.is_none_or(|o| o.contains(&f.label()))
            && (renders == Renders::Draw
                || (f.format != Format::Glb && f.format != Format::Webp && f.views.is_empty()))
    };
    let mut manifest = recorded.clone();
    for f in registry().iter().filter(|f| drawn_whole(f)) {
        if let Some(key) = keys.get(&f.label()) {
            manifest.insert(f.label(), key.clone());
        }
    }
    manifest.retain(|label, _| keys.contains_key(label));
    std::fs::write(dir.join(inputs::MANIFEST), inputs::manifest(&manifest))
        .context("writing the manifest of the figures' inputs")?;
    let mut written = 0;
    for (name, bytes) in &generated.files {
        let path = dir.join(name);
        if std::fs::read(&path).ok().as_deref() != Some(bytes.as_slice()) {
            std::fs::write(&path, bytes).with_context(|| format!("writing {}", path.display()))?;
            written += 1;
        }
    }
    for name in orphans(&dir, &generated)? {
        std::fs::remove_file(dir.join(&name)).with_context(|| format!("removing {name}"))?;
        println!("figures: removed {name}, which nothing generates any more");
    }
    println!("figures: {} files in {OUT_DIR}, {written} rewritten", generated.files.len());
    Ok(())
}

/// Which figures [`run`] draws.
#[derive(Clone, Debug)]
pub(crate) enum Select {
    /// Those whose inputs changed since the manifest was written, or whose files are missing
    /// (every figure with [`Renders::Skip`], which records no render).
    Changed,
    /// Every figure.
    All,
    /// These figures (their numbers).
    Only(Vec<String>),
}

/// The key of every figure's inputs, by number ([`inputs`]).
fn keys(root: &Path) -> Result<BTreeMap<String, String>> {
    let mut inputs = inputs::Inputs::read(root)?;
    let mut keys = BTreeMap::new();
    for (module, figures) in modules() {
        for figure in figures {
            keys.insert(figure.label(), inputs.key(figure, module)?);
        }
    }
    Ok(keys)
}

/// Prints the time the figures took, the ten slowest figures, and the tables' time (computed
/// beside the figures, so that their time overlaps theirs).
fn print_times(times: &[(String, std::time::Duration)], total: std::time::Duration) {
    let (tables, figures): (Vec<_>, Vec<_>) =
        times.iter().partition(|(label, _)| label.starts_with("table "));
    let mut slowest = figures;
    slowest.sort_by_key(|t| std::cmp::Reverse(t.1));
    let list: Vec<String> = slowest
        .iter()
        .take(10)
        .map(|(label, time)| format!("{label} {:.1} s", time.as_secs_f64()))
        .collect();
    let tables: f64 = tables.iter().map(|(_, t)| t.as_secs_f64()).sum();
    let slowest =
        if list.is_empty() { String::new() } else { format!("; the slowest: {}", list.join(", ")) };
    println!(
        "figures: drawn in {:.0} s{slowest}; the tables, alongside: {tables:.0} s",
        total.as_secs_f64()
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every row of the index's table has its six cells: a `|` in a caption (as in |κ|) is
    /// escaped rather than ending the cell.
    #[test]
    fn index_rows_have_six_cells() {
        let page = index(&registry(), &[]);
        let rows: Vec<&str> = page.lines().filter(|l| l.starts_with("| [")).collect();
        assert!(rows.len() > 100, "{} rows", rows.len());
        assert!(rows.iter().any(|r| r.contains("\\|κ\\|")), "a row with |κ| in it");
        for row in rows {
            let separators = row.match_indices('|').filter(|(i, _)| !row[..*i].ends_with('\\'));
            assert_eq!(separators.count(), 7, "{row}");
        }
    }

    #[test]
    fn committed_figures_are_current() {
        // Every file but the renders, which `cargo xtask figures --check` compares.
        let dir = crate::project_root().join(OUT_DIR);
        let generated = generate(false, Renders::Skip, None).expect("every figure draws");
        assert!(generated.skipped.len() > 100, "{} renders skipped", generated.skipped.len());
        let stale = stale_files(&dir, &generated).expect("docs/figures is readable");
        assert!(stale.is_empty(), "stale figures, run `cargo xtask figures`: {stale:?}");
    }

    /// Every committed figure file holds what its extension says (a render written into a
    /// `.png` panel once held WebP bytes).
    #[test]
    fn committed_files_are_what_their_extensions_say() {
        let dir = crate::project_root().join(OUT_DIR);
        let mut checked = 0;
        for entry in std::fs::read_dir(&dir).expect("docs/figures is readable") {
            let path = entry.expect("an entry").path();
            let Some(ext) = path.extension().and_then(|e| e.to_str()) else { continue };
            let bytes = std::fs::read(&path).expect("a figure file");
            let ok = match ext {
                "png" => bytes.starts_with(b"\x89PNG\r\n\x1a\n"),
                "webp" => bytes.starts_with(b"RIFF") && bytes.get(8..12) == Some(b"WEBP"),
                "glb" => bytes.starts_with(b"glTF"),
                "svg" => bytes.starts_with(b"<svg") || bytes.starts_with(b"<?xml"),
                _ => continue,
            };
            assert!(ok, "{} does not hold a {ext} file", path.display());
            checked += 1;
        }
        assert!(checked > 400, "{checked} files checked");
    }

    #[test]
    fn the_registry_is_ordered_and_names_are_unique() {
        let figures = registry();
        for w in figures.windows(2) {
            assert!(
                w[0].number < w[1].number,
                "figure {} is listed twice or out of order",
                w[1].label()
            );
        }
        let mut files: Vec<String> = figures
            .iter()
            .flat_map(|f| f.entries().into_iter().flat_map(|(_, file, shown, _)| [file, shown]))
            .collect();
        files.dedup();
        let count = files.len();
        files.sort();
        files.dedup();
        assert_eq!(files.len(), count, "two panels share a file name");
        let mut anchors: Vec<&str> = tables().iter().map(|t| t.anchor).collect();
        let count = anchors.len();
        anchors.sort_unstable();
        anchors.dedup();
        assert_eq!(anchors.len(), count, "two tables share an anchor");
        for n in differences::numbers() {
            assert!(
                figures.iter().any(|f| f.number == n),
                "a difference is noted for figure {}.{}, which is not in the registry",
                n.0,
                n.1
            );
        }
        for f in &figures {
            assert!(!f.panels.is_empty(), "figure {} has no file", f.label());
            if f.panels.len() + f.views.len() > 1 {
                assert!(
                    f.panels.iter().chain(f.views).all(|p| !p.title.is_empty()),
                    "figure {}: panels need titles",
                    f.label()
                );
            }
        }
    }

    #[test]
    fn drawing_is_deterministic() {
        let figure = registry()[0];
        let panel = &figure.panels[0];
        let title = figure.title(panel);
        let first = (panel.draw)(&title).expect("draws");
        let second = (panel.draw)(&title).expect("draws");
        assert!(first == second, "two drawings of {} differ", figure.file(panel));
    }
}
