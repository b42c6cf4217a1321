// SPDX-License-Identifier: MIT
//! `cargo xtask bench render`: the harmonic torus of §5.6 rendered by the four methods of
//! `hi-raytrace` side by side in one run — interval Newton (Krawczyk) and interval bisection on
//! the surface itself, C1 Bézier patches within 1e-4 (§5.7), and a tessellated mesh (§5.5) —
//! at 512×512 with one sample per pixel and shadows, with the thesis's "several hours" for its
//! interval-traced torus as the anchor; and how the render time grows with the number of pixels,
//! plotted on log axes (`docs/perf-render.svg`).

use std::fmt::Write as _;
use std::path::Path;
use std::time::Duration;

use anyhow::Result;
use hi_raytrace::RayCounts;
use hi_raytrace::testing::{TorusMethod, render_torus, torus_scene};
use indicatif::ProgressBar;

use super::{
    Growth, Headline, Section, growth_plot, machine, median, median_time, ms, progress_bar, table,
};

/// Image sides measured for the growth plot; the last is the table's size.
const SIDES: [u32; 4] = [64, 128, 256, 512];
/// Timed runs per measurement (after a warm-up for the preparation).
const RUNS: usize = 3;
/// The thesis's anchor: "several hours", taken at its lower end.
const SEVERAL_HOURS: Duration = Duration::from_secs(2 * 3600);
/// The plot, in `docs/`.
const PLOT: &str = "perf-render.svg";

/// Runs the measurements and returns the report's section.
pub(crate) fn run(root: &Path) -> Result<Section> {
    let bar = progress_bar((TorusMethod::ALL.len() * (SIDES.len() + 1)) as u64)?;
    let mut rows = Vec::new();
    let mut curves = Vec::new();
    let mut totals = Vec::new();
    for method in TorusMethod::ALL {
        let (preparation, points, last) = measure(method, &bar)?;
        if let Some((t, c)) = last {
            totals.push((method, t));
            let rays = c.camera + c.shadow;
            rows.push(vec![
                method.name().to_owned(),
                ms(preparation),
                ms(t),
                c.camera.to_string(),
                c.shadow.to_string(),
                format!("{:.2e}", rays as f64 / t.as_secs_f64()),
                format!("≥ {:.0}×", SEVERAL_HOURS.as_secs_f64() / (t + preparation).as_secs_f64()),
            ]);
        }
        curves.push(Growth { name: method.name().to_owned(), points });
    }
    bar.finish_and_clear();
    // Each time over the mesh's, and the interval Newton time over each, once all are timed.
    let time_of = |m: TorusMethod| totals.iter().find(|(x, _)| *x == m).map(|(_, t)| *t);
    let secs = |m| time_of(m).map_or(f64::NAN, |t: Duration| t.as_secs_f64());
    let (mesh_time, newton_time) = (secs(TorusMethod::Mesh), secs(TorusMethod::IntervalNewton));
    for (row, (_, t)) in rows.iter_mut().zip(&totals) {
        let t = t.as_secs_f64();
        row.insert(6, format!("{:.1}×", t / mesh_time));
        row.insert(7, format!("{:.2}×", newton_time / t));
    }
    let plot = growth_plot(
        root,
        PLOT,
        "Render time of the torus against image size (one sample per pixel)",
        "pixels",
        &curves,
    )?;
    let headlines = headlines(time_of(TorusMethod::IntervalNewton), time_of(TorusMethod::Bezier));
    Ok(Section { body: body(&rows, &plot), headlines, sub_headlines: Vec::new() })
}

/// One method's times: the preparation (building the scene), the render at each of [`SIDES`]
/// against its pixels, and the last (the table's size) with its rays.
type Timings = (Duration, Vec<(f64, Duration)>, Option<(Duration, RayCounts)>);

/// Times one method as [`Timings`] says.
fn measure(method: TorusMethod, bar: &ProgressBar) -> Result<Timings> {
    bar.set_message(format!("{}: preparation", method.name()));
    let preparation = median_time(RUNS, || {
        std::hint::black_box(torus_scene(method)?);
        Ok(())
    })?;
    bar.inc(1);
    let mut points = Vec::new();
    let mut last = None;
    for side in SIDES {
        bar.set_message(format!("{}: {side}×{side}", method.name()));
        let mut times = Vec::new();
        let mut counts = None;
        for _ in 0..RUNS {
            let out = render_torus(method, side, side, 1)?;
            times.push(out.elapsed);
            counts = Some(out.counts);
        }
        let t = median(times);
        points.push((f64::from(side * side), t));
        last = counts.map(|c| (t, c));
        bar.inc(1);
    }
    Ok((preparation, points, last))
}

/// The headlines: interval Newton against the thesis's "several hours", and the Bézier
/// patches against interval Newton (each when timed).
fn headlines(newton: Option<Duration>, bezier: Option<Duration>) -> Vec<Headline> {
    let mut headlines = Vec::new();
    if let Some(newton) = newton {
        headlines.push(Headline {
            what: "torus ray traced by interval Newton, 512², shadows".to_owned(),
            ours: newton,
            peer: "the thesis's \"several hours\" (≥ 2 h, 2005 hardware)".to_owned(),
            theirs: Some(SEVERAL_HOURS),
        });
        if let Some(bezier) = bezier {
            headlines.push(Headline {
                what: "torus ray traced through Bézier patches, 512², shadows".to_owned(),
                ours: bezier,
                peer: "interval Newton on the surface itself (our rigorous baseline)".to_owned(),
                theirs: Some(newton),
            });
        }
    }
    headlines
}

/// The section's text around its table of `rows` and its growth `plot`.
fn body(rows: &[Vec<String>], plot: &str) -> String {
    let mut s = String::new();
    let _ = write!(
        s,
        "## Rendering (§5.5, §5.6)\n\n\
         Machine: {}.\n\n\
         The harmonic torus through the 4×4 torus grid (R = 2, r = 1) at 512×512, one sample per pixel, \
         a directional and a point light with shadow rays (`hi_raytrace::testing::render_torus`, all cores), by each \
         method of `hi-raytrace`: interval Newton (Krawczyk) and interval bisection on the surface itself, C1 \
         Bézier patches within 1e-4 of it, and a mesh of 128×256 quads. Preparation is building the scene \
         (spectra, cell enclosures and BVH; patches; tessellation); render is the image. Times are medians \
         of {RUNS} runs in ms. The thesis's anchor is \"several hours\" for its interval-traced torus (2005 \
         hardware, no shadows stated), taken here as at least 2 hours.\n\n",
        machine()
    );
    s.push_str(&table(
        &[
            "method",
            "preparation",
            "render 512²",
            "camera rays",
            "shadow rays",
            "rays/s",
            "time / mesh",
            "interval Newton / this",
            "vs several hours",
        ],
        rows,
    ));
    let _ = write!(
        s,
        "\nHow the render time grows with the number of pixels (64² … 512², log axes):\n\n{plot}"
    );
    s
}
