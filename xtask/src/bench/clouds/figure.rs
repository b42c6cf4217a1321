// SPDX-License-Identifier: MIT
//! The figure: each row's input, Poisson's surface and ours, side by side.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use hi_scan::scan::read_scan;

use super::super::poisson::{View, compose, missing_panel, render_panels, scan_display};
use super::measure::{Measurement, RowResult};
use super::report::{cell_text, count_name};
use super::{BEADS, Case, PANEL, PER_LINE};

/// The panels of one row: the input, Poisson's surface, ours (a pale panel with a cross for a
/// side that failed).
pub(super) fn panels(
    root: &Path,
    out: &Path,
    c: &Case,
    m: &Measurement,
) -> (Vec<image::RgbImage>, Option<String>) {
    let stem = &c.stem;
    let (glb, ply) =
        (out.join(format!("{stem}-ours.glb")), out.join(format!("{stem}-poisson.ply")));
    let view = View { eye: c.eye, up: c.up, panel: PANEL };
    let drawn = read_scan(&c.ours_input)
        .map_err(|e| anyhow::anyhow!("{}: {e}", c.ours_input.display()))
        .and_then(|scan| {
            render_panels(
                &scan_display(&scan, BEADS),
                &[m.theirs.done().map(|_| ply.as_path()), m.ours.done().map(|_| glb.as_path())],
                view,
            )
        });
    match drawn {
        Ok(p) => (p, None),
        Err(e) => (
            vec![missing_panel(PANEL); 3],
            Some(format!("not drawn: {}", cell_text(&e.to_string(), root))),
        ),
    }
}

/// Writes the figure of the drawn rows into `docs` (`fit-clouds.png`) and returns its
/// paragraph, with the rows that could not be drawn; nothing when none was drawn.
pub(super) fn figure(docs: &Path, results: &[RowResult<'_>]) -> Result<String> {
    let mut s = String::new();
    let drawn: Vec<(&Case, &Vec<image::RgbImage>)> =
        results.iter().filter_map(|(c, _, p)| p.as_ref().map(|(p, _)| (*c, p))).collect();
    let not_drawn: Vec<String> = results
        .iter()
        .filter_map(|(c, _, p)| {
            p.as_ref().and_then(|(_, e)| e.as_ref()).map(|e| format!("{}: {e}", c.label))
        })
        .collect();
    if !drawn.is_empty() {
        let panels: Vec<Vec<image::RgbImage>> = drawn.iter().map(|(_, p)| (*p).clone()).collect();
        let png = compose(&panels, PANEL, PER_LINE)?;
        let path = docs.join("fit-clouds.png");
        std::fs::write(&path, png).with_context(|| format!("writing {}", path.display()))?;
        let order: Vec<String> = drawn.iter().map(|(c, _)| c.label.clone()).collect();
        let _ = write!(
            s,
            "\nEach input as three panels: the input (a point set as small beads, at most {} of \
             them), Poisson's surface, ours (every part of the file); a pale panel with a cross \
             where the command failed. {PER_LINE} inputs to a line, in the order of the tables: \
             {}.\n\n![each input, Poisson's surface and ours](fit-clouds.png)\n",
            count_name(BEADS),
            order.join("; "),
        );
        if !not_drawn.is_empty() {
            let _ = write!(s, "\nNot drawn: {}.\n", not_drawn.join("; "));
        }
    }
    Ok(s)
}
