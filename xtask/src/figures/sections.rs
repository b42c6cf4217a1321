// SPDX-License-Identifier: MIT
//! Figures 5.7–5.9: surfaces fitted by algorithm 1 (§5.3: cross-sections, a harmonic curve per
//! contour, insertion, rotation alignment, the reversed traversal), once well and twice badly,
//! as in the thesis, with built-in data. Each failure is checked to be one that the fit's own
//! report measures.

use std::f64::consts::{PI, TAU};

use anyhow::{Result, ensure};
use glam::DVec3;
use hi_geomimage::sections::{
    Problem, SectionFit, SectionOptions, fit_given_sections, fit_sections,
};
use hi_surface::MeshOptions;

use super::glb::glb;
use super::{Figure, Format, Panel};
use hi_surface::{ParamRange, ParamWindow};

/// Latitudes (M, poles included as M + 1 rows) and longitudes (N) of the data of figure 5.7.
const LAT_LONG: (usize, usize) = (12, 24);
/// Points of the random sphere of figure 5.8.
const RANDOM_POINTS: usize = 600;
/// Sections and points per section of the C-shaped solid of figure 5.9.
const C_SOLID: (usize, usize) = (12, 100);

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (5, 7),
        caption: "Sphere fitting using algorithm 1",
        drawn: "(b) The harmonic surface of algorithm 1 through the 13 latitude rows of a unit sphere \
                sampled at equally spaced spherical coordinates (eq. 4.1), given as cross-sections: each row's \
                harmonic curve, 24 points inserted to 26 (Theorem 5.3), turned for the least total deviation \
                (Theorem 5.1), and the rows traversed up one side and down the other (a 26×26 grid); meshed \
                over the half period that covers the sphere once. As in the thesis the result is acceptable \
                with some oscillation: each pole is a row of 24 equal points, met twice in a row by the \
                reversed traversal, so the meridians wobble near the poles (the surface is within 0.01 of the \
                sphere, and the fit reports no problem; both checked when the figure is generated). (a) The \
                data points (the 24 copies of each pole drawn once), as red beads.",
        data: "built-in: the unit sphere at polar angles iπ/12 (i = 0…12) and longitudes 2πj/24, poles repeated \
               24 times, as eq. 4.1 gives them.",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Data points",
                draw: |_| points_glb(&lat_long_sections().concat()),
            },
            Panel { suffix: "b", title: "(b) Surface", draw: |_| lat_long_fit() },
        ],
    },
    Figure {
        number: (5, 8),
        caption: "Failed sphere fitting using algorithm 1",
        drawn: "(b) Algorithm 1 on 600 uniformly random points of the unit sphere, cut by the thesis's \
                recursive subdivision (a slab is halved while its points spread further along z than their \
                neighbours lie apart). Each thin section holds a few points at uneven angles, so its \
                harmonic curve overshoots and loops (\"the curves interpolate at different speeds\"), and the \
                slabs near the poles hold bands rather than curves, which the polar angle orders into \
                zigzags: the surface wrinkles and strays far from the sphere. The fit's report measures this \
                (checked when the figure is generated): looping or scrambled contours, and a surface more \
                than 0.1 from the sphere. (a) The points, as red beads.",
        data: "built-in: 600 points uniform on the unit sphere (z and the longitude uniform, a fixed 64-bit LCG).",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Data points", draw: |_| points_glb(&random_points()) },
            Panel { suffix: "b", title: "(b) Surface", draw: |_| random_sphere_fit() },
        ],
    },
    Figure {
        number: (5, 9),
        caption: "Failed surface fitting using algorithm 1",
        drawn: "(b) Algorithm 1 on a bean-shaped solid whose 12 sections are C shapes (an annular sector of \
                ±135°, closed by half discs) shrinking towards its ends. The centroid of a C lies in its hole, \
                so the polar angle about it, the thesis's ordering, zigzags between the inner and outer arcs; \
                the harmonic curves through the zigzags loop, and the surface folds through itself. The \
                fit's report flags every section as scrambled (checked when the figure is generated); \
                ordering by nearest neighbours instead follows the Cs. (a) The points, as red beads.",
        data: "built-in: 12 C-shaped sections of 100 points each, evenly spaced by arc length, at the centres of \
               12 equal slabs of z ∈ [−1, 1], scaled by √(1 − 0.8 z²). The thesis's figure is of a scan not \
               named.",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Data points",
                draw: |_| points_glb(&c_solid_points()),
            },
            Panel { suffix: "b", title: "(b) Surface", draw: |_| c_solid_fit() },
        ],
    },
];

/// The surface of `fit` over the half period that covers the object once, with `per_row` quads
/// along u between neighbouring grid rows.
fn mesh(fit: &SectionFit, per_row: usize) -> Result<Vec<u8>> {
    let u = fit.covering_window();
    let options = MeshOptions {
        n_u: per_row * fit.rows.len(),
        n_v: 2 * fit.surface.n(),
        window: ParamWindow::new(u, ParamRange::UNIT),
        ..MeshOptions::default()
    };
    glb(&fit.surface.to_mesh(&options)?)
}

/// The largest | |p| − 1 | over the surface sampled 4 times finer than its grid.
fn off_unit_sphere(fit: &SectionFit) -> Result<f64> {
    let s = &fit.surface;
    let samples = s.sample_uniform(4 * s.m(), 4 * s.n(), 0, 0)?.values;
    Ok(samples.iter().map(|p| (p.length() - 1.0).abs()).fold(0.0, f64::max))
}

/// The radius of the beads that draw the data points, panels (a).
const BEAD: f64 = 0.025;

/// Panel (a): the data points as beads.
fn points_glb(points: &[DVec3]) -> Result<Vec<u8>> {
    glb(&super::surfaces::beads(points, BEAD)?)
}

/// The data of figure 5.7: the sphere's latitude rows (eq. 4.1).
fn lat_long_sections() -> Vec<Vec<DVec3>> {
    let (m, n) = LAT_LONG;
    (0..=m)
        .map(|i| {
            let u = PI * i as f64 / m as f64;
            (0..n)
                .map(|j| {
                    let v = TAU * j as f64 / n as f64;
                    DVec3::new(u.sin() * v.cos(), u.sin() * v.sin(), -u.cos())
                })
                .collect()
        })
        .collect()
}

/// Figure 5.7(b).
fn lat_long_fit() -> Result<Vec<u8>> {
    let sections = lat_long_sections();
    let fit = fit_given_sections(&sections, &SectionOptions::default())?;
    let off = off_unit_sphere(&fit)?;
    ensure!(off < 0.01, "the surface is {off} off the sphere");
    ensure!(fit.report.problems.is_empty(), "problems: {:?}", fit.report.problems);
    mesh(&fit, 2)
}

/// A fixed 64-bit LCG in [0, 1).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 =
            self.0.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The data of figure 5.8: random points on the unit sphere.
fn random_points() -> Vec<DVec3> {
    let mut rng = Lcg(5);
    (0..RANDOM_POINTS)
        .map(|_| {
            let z = 2.0 * rng.next() - 1.0;
            let a = TAU * rng.next();
            let s = (1.0 - z * z).sqrt();
            DVec3::new(s * a.cos(), s * a.sin(), z)
        })
        .collect()
}

/// Figure 5.8(b).
fn random_sphere_fit() -> Result<Vec<u8>> {
    let points = random_points();
    let fit = fit_sections(&points, &SectionOptions::default())?;
    let off = off_unit_sphere(&fit)?;
    ensure!(off > 0.1, "the surface is only {off} off the sphere");
    ensure!(
        fit.report.problems.iter().any(|p| matches!(
            p,
            Problem::LoopingContour { .. } | Problem::ScrambledContour { .. }
        )),
        "no looping or scrambled contour: {:?}",
        fit.report.problems
    );
    mesh(&fit, 2)
}

/// `n` points evenly spaced by arc length round a C (an annular sector of radii 0.6 and 1 over
/// ±135°, closed by half discs), scaled by `s`, at height `z`.
fn c_section(n: usize, s: f64, z: f64) -> Vec<DVec3> {
    let alpha = 0.75 * PI;
    let at = |r: f64, a: f64| DVec3::new(r * a.cos(), r * a.sin(), 0.0);
    let fine = 2000;
    let mut path = Vec::new();
    path.extend((0..fine).map(|i| at(1.0, -alpha + 2.0 * alpha * i as f64 / fine as f64)));
    path.extend((0..fine / 4).map(|i| {
        let b = PI * i as f64 / (fine / 4) as f64;
        at(0.8, alpha) + 0.2 * (at(1.0, alpha) * b.cos() + at(1.0, alpha + 0.5 * PI) * b.sin())
    }));
    path.extend((0..fine).map(|i| at(0.6, alpha - 2.0 * alpha * i as f64 / fine as f64)));
    path.extend((0..fine / 4).map(|i| {
        let b = PI * i as f64 / (fine / 4) as f64;
        at(0.8, -alpha) - 0.2 * (at(1.0, -alpha) * b.cos() + at(1.0, -alpha + 0.5 * PI) * b.sin())
    }));
    let m = path.len();
    let mut lengths = vec![0.0];
    for i in 0..m {
        lengths.push(lengths[i] + path[i].distance(path[(i + 1) % m]));
    }
    let mut seg = 0;
    (0..n)
        .map(|j| {
            let target = lengths[m] * j as f64 / n as f64;
            while lengths[seg + 1] < target {
                seg += 1;
            }
            let t = (target - lengths[seg]) / (lengths[seg + 1] - lengths[seg]);
            let p = path[seg].lerp(path[(seg + 1) % m], t);
            DVec3::new(s * p.x, s * p.y, z)
        })
        .collect()
}

/// The data of figure 5.9: the C-shaped sections of the bean.
fn c_solid_points() -> Vec<DVec3> {
    let (k, per_section) = C_SOLID;
    (0..k)
        .flat_map(|i| {
            let z = (2 * i + 1) as f64 / k as f64 - 1.0;
            c_section(per_section, (1.0 - 0.8 * z * z).sqrt(), z)
        })
        .collect()
}

/// Figure 5.9(b).
fn c_solid_fit() -> Result<Vec<u8>> {
    let k = C_SOLID.0;
    let points = c_solid_points();
    let options = SectionOptions { slices: Some(k), ..SectionOptions::default() };
    let fit = fit_sections(&points, &options)?;
    let scrambled = fit
        .report
        .problems
        .iter()
        .filter(|p| matches!(p, Problem::ScrambledContour { .. }))
        .count();
    ensure!(scrambled == k, "{scrambled} of {k} sections scrambled: {:?}", fit.report.problems);
    mesh(&fit, 2)
}
