// SPDX-License-Identifier: MIT
//! Figure 5.12: a harmonic surface fitted to scattered points on a sphere through a
//! geometry image (algorithm 2, §5.3), with built-in data.

use anyhow::{Result, ensure};
use glam::DVec3;
use hi_geomimage::{ErrorMeasure, FitOptions, Layout, fit};
use hi_scan::scan::Scan;
use hi_surface::MeshOptions;

use super::glb::glb;
use super::{Figure, Format, Panel, Table};
use hi_surface::{ParamRange, ParamWindow};

/// Table 5.1 holds timings, which differ from run to run: it lives in the benchmark report, and
/// this page points to it.
pub(crate) const TABLES: &[Table] = &[Table {
    anchor: "table-5-1",
    title: "Table 5.1: Time to fit the models",
    about: "Regenerated on this machine by `cargo xtask bench fit` (points, time for the geometry image, time for \
        harmonic interpolation at 4× the image, the whole fit and its error, for built-in scans and the real models \
        of `shared/data/models` when present), beside screened Poisson reconstruction and scipy's resampling. \
        Timings change from run to run, so they are in the benchmark report rather than on this page, which is \
        regenerated bit for bit. The same run fits the shared models with `hi fit` and with screened Poisson \
        as whole commands and measures both with trimesh ([the table](../performance.md#against-screened-poisson-whole-commands)); \
        each model as scan, Poisson and ours, from that run: \
        ![Each model as the scan, screened Poisson's surface and ours](../fit-vs-poisson.png)",
    make: || {
        Ok("| table | where |\n|---|---|\n| Table 5.1, regenerated | \
            [docs/performance.md](../performance.md#table-51-regenerated) |\n\
            | Against screened Poisson, whole commands | \
            [docs/performance.md](../performance.md#against-screened-poisson-whole-commands) |\n"
            .to_owned())
    },
}];

/// Points of the built-in scan.
const SCAN_POINTS: usize = 5000;

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[Figure {
    number: (5, 12),
    caption: "Surface fitting using harmonic tensor product surfaces (sphere)",
    drawn: "(b) The harmonic surface through a 32×32 spherical geometry image (algorithm 2) of 5000 scattered \
            points on the unit sphere, meshed over u ∈ [0, ½] with 32×64 quads. As in the thesis the result \
            has no visible blemish: every texel lies on the sphere (checked to 1e-12 when the figure is \
            generated), and the texels of a latitude–longitude grid on a sphere make the harmonic surface the \
            sphere itself. (a) The points, each drawn as a small ball.",
    data: "built-in: a Fibonacci lattice of 5000 points on the unit sphere (not on the image's rays).",
    format: Format::Glb,
    views: &[Panel {
        suffix: "a",
        title: "(a) Data points",
        draw: |_| super::renders::render_points((5, 12), &fibonacci(SCAN_POINTS), 0.004),
    }],
    panels: &[Panel { suffix: "b", title: "(b) Surface", draw: |_| sphere_fit() }],
}];

/// `n` points spread evenly over the unit sphere ([`hi_testkit::fibonacci_sphere`]).
fn fibonacci(n: usize) -> Vec<DVec3> {
    hi_testkit::fibonacci_sphere(n).map(DVec3::from).collect()
}

/// Figure 5.12(b).
fn sphere_fit() -> Result<Vec<u8>> {
    let scan = Scan { points: fibonacci(SCAN_POINTS), ..Scan::default() };
    let options = FitOptions {
        layout: Layout::Sphere,
        resolution: Some((32, 32)),
        centre: Some(DVec3::ZERO),
        error: ErrorMeasure::Off,
        ..FitOptions::thesis()
    };
    let result = fit(&scan, &options, &mut |_| {})?;
    let worst = result
        .largest()
        .image
        .texels()
        .iter()
        .map(|p| (p.length() - 1.0).abs())
        .fold(0.0, f64::max);
    ensure!(worst < 1e-12, "a texel is {worst} off the sphere");
    let u = Layout::Sphere.covering_window();
    let mesh_options = MeshOptions {
        n_u: 32,
        n_v: 64,
        window: ParamWindow::new(u, ParamRange::UNIT),
        ..MeshOptions::default()
    };
    glb(&result.largest().surface.to_mesh(&mesh_options)?)
}
