// SPDX-License-Identifier: MIT
//! The surface figures: 4.1 (parametric sphere and torus), 5.1 (the harmonic sphere and torus
//! of §5.1), 5.3–5.5 (harmonic surface subdivision, §5.2) and 5.31–5.43 (the test surfaces of
//! §5.9, parametric against harmonic, with Gaussian and mean curvature), as binary glTF models,
//! one file per panel; and two tables: the curvature comparison of §5.9 and the meshes and
//! colour scales of figures 5.31–5.43.
//!
//! Every model is a triangle mesh of `hi_surface` written by `hi_mesh::export::write_glb` and
//! read back with the `gltf` crate before it is accepted ([`super::glb`]). Images of the models
//! come with the ray tracer; the index page links the files.
//!
//! **Meshes.** Harmonic surfaces are meshed by `HarmonicSurface::to_mesh` (welded seams
//! where the window is a whole period, one vertex per pole). A parametric surface is meshed
//! here ([`parametric_mesh`]): an open (n + 1)×(n + 1) grid of f(u, v) with normals pᵤ × pᵥ from
//! `ParametricSurface::derivs`; triangles with two corners at one point (a pole) are dropped,
//! and where pᵤ × pᵥ vanishes the normal is the sum of the normals of the triangles around the
//! point. Subdivision stages are the control grids themselves as closed quad meshes, split into
//! triangles, with area-weighted face normals ([`control_mesh`]).
//!
//! **Colours.** K and H with their signs (the thesis shows |K| and |H|, blue for little
//! curvature and purple for much, which hides whether a point is elliptic or hyperbolic) on
//! Moreland's diverging cool–warm map: −a blue, 0 light grey, +a red, with one a per surface
//! and quantity shared by the parametric and the harmonic picture so that they compare: the
//! 95th percentile of the parametric surface's |values| weighted by area, so that the many
//! small triangles of a parameterisation near an apex or a pole do not set it (at least 10⁻⁶ of
//! the curvature of the surface's size, so that a flat surface is grey). Every picture must use
//! at least a quarter of its bar (from the least to the greatest of 0 and its 2 % and 98 % area
//! quantiles), or the figures are not drawn. Values beyond ±a take the end colours;
//! undefined values (poles) are mid grey. Each picture is an SVG: the render, and beside it a
//! colour bar with its values ([`colour_bar_svg`]).

mod colours;
mod curvature;
mod meshes;

use anyhow::{Context, Result, ensure};
use glam::DVec3;
use hi_surface::{CurvatureQuantity, HarmonicSurface, MeshOptions, test_surface};

use super::glb::{glb, glb_with_edges};
use super::{Figure, Format, Panel, Table};
use curvature::{comparison, curvature_table, mesh_table};
use hi_surface::{ParamRange, ParamWindow};
use meshes::{control_mesh, parametric_mesh, with_markers};

pub(crate) use colours::{colour_bar, colour_bar_svg, has_colour_bar};
pub(crate) use meshes::{ball, beads, geodesic};

/// The fraction of the parametric surface's area whose curvature the colour scale spans.
const COVERAGE: f64 = 0.95;

/// The least fraction of its colour bar a curvature picture must use ([`curvature::Comparison`]'s
/// `colour_use`): below it, `cargo xtask figures` fails rather than draw a grey picture.
const MIN_COLOUR_USE: f64 = 0.25;

/// The least colour-scale extent, relative to the curvature of the surface's size (1/r² for
/// K, 1/r for H).
const FLOOR: f64 = 1e-6;

/// The factor above the colour-scale extent from which the mesh table counts a value as
/// over it.
const OVER: f64 = 1.01;

/// Points compared per direction by the curvature table (cell centres of the window).
const TABLE_RES: usize = 64;

/// The subdivision level panel (d) of figures 5.3–5.5 shows (the thesis: 7).
const LAST_LEVEL: u32 = 4;

/// The level the thesis shows in panel (d), checked against [`LAST_LEVEL`].
const THESIS_LEVEL: u32 = 7;

/// The colour of surfaces that carry interpolation-point markers, in sRGB: light grey.
const SURFACE_SRGB: [f32; 3] = [0.8, 0.8, 0.8];

/// The colour of the interpolation points, in sRGB: red, as the thesis's spheres.
const MARKER_SRGB: [f32; 3] = [0.85, 0.1, 0.08];

/// Radius of a marker (an octahedron), relative to the surface's radius.
const MARKER_SIZE: f64 = 0.04;

/// One comparison of §5.9: the surface's name in `hi_surface::test_surfaces` and the mesh.
#[derive(Clone, Copy, Debug)]
struct Spec {
    /// Name of the surface.
    name: &'static str,
    /// The figure, "5.31".
    figure: &'static str,
    /// Quads along u.
    n_u: usize,
    /// Quads along v.
    n_v: usize,
}

/// The comparisons of figures 5.31–5.43 and their mesh resolutions: two quads per sample along
/// u and four along v (the harmonic surface varies slowly in v, through 4 samples), three per
/// sample and 12 around the tubes of the knots; the flat Möbius strip four per sample along u
/// (its rim is curved within its plane, where curved triangles cannot round it; half its v
/// range drawn, at the same density); eight along v for the second shell (its cross-sections
/// twist, and its opening is one of them) and for the open tubes of 5.36, 5.39 and 5.43 (their
/// ends are cross-sections, circles that a curved triangle rounds only where the surface's
/// normal leans towards the circle's centre).
const SPECS: [Spec; 13] = [
    Spec { name: "plane", figure: "5.31", n_u: 48, n_v: 16 },
    Spec { name: "partial-sphere", figure: "5.32", n_u: 48, n_v: 16 },
    Spec { name: "torus", figure: "5.33", n_u: 48, n_v: 16 },
    Spec { name: "sphere", figure: "5.34", n_u: 48, n_v: 16 },
    Spec { name: "mobius", figure: "5.35", n_u: 96, n_v: 8 },
    Spec { name: "revolution", figure: "5.36", n_u: 48, n_v: 32 },
    Spec { name: "shell", figure: "5.37", n_u: 48, n_v: 16 },
    Spec { name: "shell2", figure: "5.38", n_u: 48, n_v: 32 },
    Spec { name: "klein", figure: "5.39", n_u: 48, n_v: 32 },
    Spec { name: "overhand", figure: "5.40", n_u: 72, n_v: 12 },
    Spec { name: "solomon", figure: "5.41", n_u: 72, n_v: 12 },
    Spec { name: "solomon-fine", figure: "5.42", n_u: 96, n_v: 12 },
    Spec { name: "revolution-periodic", figure: "5.43", n_u: 48, n_v: 32 },
];

/// What figures 5.31–5.43 draw.
const COMPARISON_DRAWN: &str = "Six models, as the thesis's six pictures: (a) the parametric surface, \
    (b) its Gaussian curvature K and (c) its mean curvature H, computed numerically (fourth-order differences, \
    `ParametricSurface::curvature`); (d) the harmonic surface through the samples, (e) its K and (f) its H, \
    exact (`HarmonicSurface::curvature`). Triangle meshes over the thesis's parameter window, resolution per surface \
    in [Meshes and colour scales](#surface-meshes); colours (vertex `COLOR_0`, linear RGB) with their signs, on \
    Moreland's diverging cool–warm map: −a blue, 0 light grey, +a red, one a per surface and quantity shared by (b, e) \
    and (c, f): the 95th percentile of the parametric surface's \\|values\\| (listed in the table); values beyond ±a \
    take the end colours, undefined values (poles) mid grey. Each curvature picture has its colour bar with its values \
    beside the render, and says how many values lie beyond its ends. The thesis's red spheres at \
    the samples are drawn in (d), which passes through them, as small red balls on a light grey surface (not in \
    (a), to keep the files small).";

/// Figures 5.31–5.43, one per entry of [`SPECS`]: `$i` is the index, `$a` the title of panel (a).
macro_rules! comparison {
    ($number:literal, $i:literal, $caption:literal, $a:literal, $data:literal) => {
        Figure {
            number: (5, $number),
            caption: $caption,
            drawn: COMPARISON_DRAWN,
            data: $data,
            format: Format::Glb,
            views: &[],
            panels: &[
                Panel {
                    suffix: "a-parametric",
                    title: $a,
                    draw: |_| comparison(&SPECS[$i], Side::Parametric, None),
                },
                Panel {
                    suffix: "b-parametric-K",
                    title: "(b) Gaussian curvature",
                    draw: |_| {
                        comparison(&SPECS[$i], Side::Parametric, Some(CurvatureQuantity::Gaussian))
                    },
                },
                Panel {
                    suffix: "c-parametric-H",
                    title: "(c) Mean curvature",
                    draw: |_| {
                        comparison(&SPECS[$i], Side::Parametric, Some(CurvatureQuantity::Mean))
                    },
                },
                Panel {
                    suffix: "d-harmonic",
                    title: "(d) Harmonic surface",
                    draw: |_| comparison(&SPECS[$i], Side::Harmonic, None),
                },
                Panel {
                    suffix: "e-harmonic-K",
                    title: "(e) Gaussian curvature",
                    draw: |_| {
                        comparison(&SPECS[$i], Side::Harmonic, Some(CurvatureQuantity::Gaussian))
                    },
                },
                Panel {
                    suffix: "f-harmonic-H",
                    title: "(f) Mean curvature",
                    draw: |_| comparison(&SPECS[$i], Side::Harmonic, Some(CurvatureQuantity::Mean)),
                },
            ],
        }
    };
}

/// Figures 5.3–5.5: the four stages of subdivision of one control grid.
macro_rules! subdivision {
    ($number:literal, $caption:literal, $which:expr, $data:literal) => {
        Figure {
            number: (5, $number),
            caption: $caption,
            drawn: "The control meshes of harmonic surface subdivision (`HarmonicSurface::subdivide`, on u then v): \
                    (a) the 4×4 grid (16 vertices), (b) level 1 (8×8), (c) level 2 (16×16), (d) level 4 (64×64, \
                    4 096 vertices) where the thesis shows level 7 (512×512, 262 144 vertices: about 11 MB; every \
                    level lies on the same surface, so level 4 already shows it, and the generator checks that level 7 \
                    contains level 4). Each grid is closed in both directions and drawn as its quads split into two \
                    triangles, with area-weighted face normals and the quads' sides as a second primitive of lines, \
                    no colours.",
            data: $data,
            format: Format::Glb,
            views: &[],
            panels: &[
                Panel { suffix: "a", title: "(a) Original mesh", draw: |_| stage($which, 0) },
                Panel { suffix: "b", title: "(b) First subdivision step", draw: |_| stage($which, 1) },
                Panel { suffix: "c", title: "(c) Second subdivision step", draw: |_| stage($which, 2) },
                Panel {
                    suffix: "d",
                    title: "(d) Fourth subdivision step (the thesis shows the seventh)",
                    draw: |_| stage($which, LAST_LEVEL),
                },
            ],
        }
    };
}

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (4, 1),
        caption: "Example parametric surfaces",
        drawn: "(a) The sphere and (b) the torus as parametric surfaces (not harmonic): triangle meshes of 48×24 quads \
                (48 around the axis, 24 from pole to pole or around the tube) with normals pᵤ × pᵥ (numerical), no colours. \
                The thesis's dashed isocurves are a matter of rendering and are not in the models.",
        data: "the sphere of eq. 4.1 and the torus of eq. 4.2 with r₁ = 2, r₂ = 1 (the thesis gives no radii), as \
               defined for §5.9 (`hi_surface::test_surface(\"sphere\")` over its window v ∈ [0, ½], `\"torus\"`).",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Sphere",
                draw: |_| parametric_figure("sphere", 48, 24),
            },
            Panel { suffix: "b", title: "(b) Torus", draw: |_| parametric_figure("torus", 48, 24) },
        ],
    },
    Figure {
        number: (5, 1),
        caption: "Tensor product harmonic surfaces",
        drawn: "(a) The harmonic sphere over u ∈ [0, ½] and (b) the harmonic torus, meshed with 24×48 quads \
                (24 along the meridian or around the tube, 48 around the axis; one vertex per pole), light grey, with the \
                16 interpolation points overlaid as small red balls (the sphere's 4 points at each pole are one).",
        data: "the exact 4×4 grids of docs/math.md §3 (`hi_surface::sphere(1)`, `hi_surface::torus(2, 1)`): the diamond \
               of four points turned by 90° three times.",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Sphere", draw: |_| harmonic_figure(Exact::Sphere) },
            Panel { suffix: "b", title: "(b) Torus", draw: |_| harmonic_figure(Exact::Torus) },
        ],
    },
    subdivision!(
        3,
        "Stages in subdivision to produce a torus",
        Torus::Round,
        "the 4×4 torus grid of docs/math.md §3, `hi_surface::torus(2, 1)`."
    ),
    subdivision!(
        4,
        "Stages in subdivision to produce a deformed torus",
        Torus::Deformed,
        "stand-in (the thesis gives no points): the torus grid of figure 5.3 with x₁₀ pulled out radially by 1 \
         and x₀₂ raised by 0.75."
    ),
    subdivision!(
        5,
        "Stages in subdivision to produce a stretched torus",
        Torus::Stretched,
        "stand-in (the thesis gives no points): the torus grid of figure 5.3 stretched by 1.75 along x, so the \
         surface is the round torus stretched likewise."
    ),
    comparison!(
        31,
        0,
        "Comparison of plane and harmonic surface",
        "(a) Plane",
        "§5.9 surface `plane` of `hi_surface::parametric`, (3u − 1.5, 3v − 1.5, 0) (reconstructed), sampled at 24×4 points as in the thesis."
    ),
    comparison!(
        32,
        1,
        "Comparison of partial sphere and harmonic surface",
        "(a) Partial sphere",
        "§5.9 surface `partial-sphere` of `hi_surface::parametric` (ρ = 0.9(πv − π/2), θ = 2πu), sampled at 24×4 points."
    ),
    comparison!(
        33,
        2,
        "Comparison of torus and harmonic surface",
        "(a) Torus",
        "§5.9 surface `torus` of `hi_surface::parametric` (R = 2, r = 1: the text gives no radii), sampled at 24×4 points."
    ),
    comparison!(
        34,
        3,
        "Comparison of sphere and harmonic surface",
        "(a) Sphere",
        "§5.9 surface `sphere` of `hi_surface::parametric` (the meridian circle, periodic), sampled at 24×4 points; window v ∈ [0, ½] as in the thesis."
    ),
    comparison!(
        35,
        4,
        "Comparison of Moëbius strip and harmonic surface",
        "(a) Moëbius strip",
        "§5.9 surface `mobius` of `hi_surface::parametric`: the doubled Möbius strip (twice round, so periodic in u), sampled at 24×4 points; window v ∈ [0, ½], which covers the strip once (half its width on each round, the halves meeting along the centre line)."
    ),
    comparison!(
        36,
        5,
        "Comparison of surface of revolution and harmonic surface",
        "(a) Surface of revolution",
        "§5.9 surface `revolution` of `hi_surface::parametric` (not periodic in u), sampled at 24×4 points."
    ),
    comparison!(
        37,
        6,
        "Comparison of shell and harmonic surface",
        "(a) Shell",
        "§5.9 surface `shell` of `hi_surface::parametric` (third component reconstructed from the garbled text), sampled at 24×4 points."
    ),
    comparison!(
        38,
        7,
        "Comparison of another shell and harmonic surface",
        "(a) Another shell",
        "§5.9 surface `shell2` of `hi_surface::parametric` (read literally from the extracted text), sampled at 24×4 points."
    ),
    comparison!(
        39,
        8,
        "Comparison of partial Klein bottle and harmonic surface",
        "(a) Klein bottle",
        "§5.9 surface `klein` of `hi_surface::parametric` (the classic bottle parametrisation, half of it), sampled at 24×4 points."
    ),
    comparison!(
        40,
        9,
        "Comparison of overhand knot and harmonic surface",
        "(a) Overhand knot",
        "§5.9 surface `overhand` of `hi_surface::parametric`: a tube of radius 0.3 about a trefoil (reconstructed) in its Frenet frame, sampled at 24×4 points."
    ),
    comparison!(
        41,
        10,
        "Comparison of Solomon's Seal knot and harmonic surface",
        "(a) Solomon's Seal knot",
        "§5.9 surface `solomon` of `hi_surface::parametric`: a tube of radius 0.12 about the (2, 5) torus knot (reconstructed) in its Frenet frame, sampled at 24×4 points."
    ),
    comparison!(
        42,
        11,
        "Comparison of Solomon's Seal knot (higher sampling rate) and harmonic surface",
        "(a) Solomon's Seal knot",
        "§5.9 surface `solomon-fine` of `hi_surface::parametric`: the tube of figure 5.41 sampled at 48×4 points, as in the thesis."
    ),
    comparison!(
        43,
        12,
        "Comparison of periodic surface of revolution and harmonic surface",
        "(a) Surface of revolution",
        "§5.9 surface `revolution-periodic` of `hi_surface::parametric` (θ = 4πu − π, axis g(θ)), sampled at 24×4 points; window u ∈ [0, ½] as in the thesis."
    ),
];

/// The tables of this module.
pub(crate) const TABLES: &[Table] = &[
    Table {
        anchor: "curvature-comparison",
        title: "Curvature of the §5.9 surfaces: parametric against harmonic",
        about: "For each test surface of §5.9 (figures 5.31–5.43), the Gaussian curvature K and the mean curvature \
                H = (κ₁ + κ₂)/2 of the parametric surface (numerical, fourth-order differences) against those of the \
                harmonic surface through the thesis's samples (analytic), at the 64×64 cell centres of the figure's \
                parameter window, by `hi_surface::compare_curvature` (the same numbers as \
                `cargo run -p hi-surface --example curvature_table`): max and RMS of the differences, and the largest \
                |K| and |H| of the parametric surface for scale. Points where either normal is undefined are skipped \
                (\"points\" counts those compared). The surfaces whose samples are not periodic (partial \
                sphere, revolution, shells, Klein bottle, knots) differ by far more than the torus, sphere and \
                periodic surface of revolution, which harmonic interpolation reproduces well, as the thesis finds; the \
                plane's samples all lie in z = 0, so its harmonic surface stays in the plane and K = H = 0 on both.",
        make: curvature_table,
    },
    Table {
        anchor: "surface-meshes",
        title: "Meshes and colour scales of figures 5.31–5.43",
        about: "The mesh of each comparison figure (quads along u × along v over the window; vertices of the \
                parametric and of the harmonic mesh, without markers) and the extent a of its colour scales: |K| \
                and |H| are drawn from 0 (blue) to a (purple) in panels (b, e) and (c, f), a being the 95th percentile \
                of the parametric surface's values (at least 10⁻⁶ of the curvature of the surface's size). \"over a\" \
                counts the vertices of the harmonic surface drawn purple because they exceed a by more than 1 %. \
                (For figure 5.43 the percentile leaves out the edge u = ½, where the axis g(θ) turns back: there the \
                numerical curvature of the parametric surface, whose differences straddle the turn, is meaningless.)",
        make: mesh_table,
    },
];

/// Which side of a §5.9 comparison a panel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    /// The parametric surface.
    Parametric,
    /// The harmonic surface through its samples.
    Harmonic,
}

/// The exact surfaces of figure 5.1.
#[derive(Clone, Copy, Debug)]
enum Exact {
    /// `hi_surface::sphere(1)`.
    Sphere,
    /// `hi_surface::torus(2, 1)`.
    Torus,
}

/// The control grids of figures 5.3–5.5.
#[derive(Clone, Copy, Debug)]
enum Torus {
    /// The exact torus grid.
    Round,
    /// Two points moved (stand-in).
    Deformed,
    /// Stretched along x (stand-in).
    Stretched,
}

/// Figure 4.1: the §5.9 surface `name` as a parametric mesh of `n_u`×`n_v` quads.
fn parametric_figure(name: &str, n_u: usize, n_v: usize) -> Result<Vec<u8>> {
    let surface = test_surface(name).with_context(|| format!("no §5.9 surface {name}"))?;
    let scale = surface.harmonic().radius();
    let (mesh, _) =
        parametric_mesh(&|u, v| surface.derivs(u, v), scale, surface.window, (n_u, n_v))?;
    glb(&mesh)
}

/// Figure 5.1: the exact sphere or torus with its interpolation points.
fn harmonic_figure(which: Exact) -> Result<Vec<u8>> {
    let (surface, u) = match which {
        Exact::Sphere => (hi_surface::sphere(1.0), ParamRange::new(0.0, 0.5)),
        Exact::Torus => (hi_surface::torus(2.0, 1.0), ParamRange::UNIT),
    };
    let window = ParamWindow::new(u, ParamRange::UNIT);
    let options = MeshOptions { n_u: 24, n_v: 48, window, ..Default::default() };
    let mesh = surface.to_mesh(&options)?;
    glb(&with_markers(&mesh, surface.points(), MARKER_SIZE * surface.radius())?)
}

/// The control grid of figure 5.3, 5.4 or 5.5.
fn control_grid(which: Torus) -> HarmonicSurface<DVec3> {
    let round = hi_surface::torus(2.0, 1.0);
    let mut rows = round.rows();
    match which {
        Torus::Round => return round,
        Torus::Deformed => {
            let p = rows[1][0];
            rows[1][0] = p + DVec3::new(p.x, p.y, 0.0).normalize();
            rows[0][2].z += 0.75;
        }
        Torus::Stretched => {
            for p in rows.iter_mut().flatten() {
                p.x *= 1.75;
            }
        }
    }
    HarmonicSurface::new(rows)
}

/// Figures 5.3–5.5: the control mesh after `level` subdivision steps, checked to lie on the
/// original surface (and, at [`LAST_LEVEL`], to be contained in the thesis's level 7).
fn stage(which: Torus, level: u32) -> Result<Vec<u8>> {
    let original = control_grid(which);
    let grid = original.subdivide(level)?;
    let (m, n) = (grid.m(), grid.n());
    ensure!(m == 4 << level && n == 4 << level, "level {level} is {m}×{n}");
    let tol = 1e-12 * original.radius().max(1.0) * 8.0;
    for j in 0..m {
        for k in 0..n {
            let on = original.eval(j as f64 / m as f64, k as f64 / n as f64);
            ensure!(
                grid.point(j, k).distance(on) <= tol,
                "level {level} point ({j}, {k}) is off the surface"
            );
        }
    }
    if level == LAST_LEVEL {
        let finest = original.subdivide(THESIS_LEVEL)?;
        let step = 1 << (THESIS_LEVEL - LAST_LEVEL);
        for j in 0..m {
            for k in 0..n {
                ensure!(
                    finest.point(step * j, step * k).distance(grid.point(j, k)) <= tol,
                    "level {THESIS_LEVEL} does not contain level {level} at ({j}, {k})"
                );
            }
        }
    }
    glb_with_edges(&control_mesh(&grid)?, &grid_edges(grid.m(), grid.n()))
}

/// The edges of the closed m×n control grid of [`control_mesh`]: each vertex to the next along
/// each direction (its quads' sides, not their diagonals).
fn grid_edges(m: usize, n: usize) -> Vec<[u32; 2]> {
    let at = |j: usize, k: usize| ((j % m) * n + k % n) as u32;
    (0..m)
        .flat_map(|j| {
            (0..n).flat_map(move |k| [[at(j, k), at(j + 1, k)], [at(j, k), at(j, k + 1)]])
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use hi_surface::test_surfaces;

    use super::colours::tick;
    use super::curvature::Comparison;
    use super::*;

    #[test]
    fn every_test_surface_has_its_figure() {
        let surfaces = test_surfaces();
        assert_eq!(surfaces.len(), SPECS.len(), "one figure per §5.9 surface");
        for (surface, spec) in surfaces.iter().zip(&SPECS) {
            assert_eq!(surface.name, spec.name, "figure {}", spec.figure);
            assert_eq!(surface.figure, spec.figure, "surface {}", spec.name);
            let figure = FIGURES
                .iter()
                .find(|f| format!("{}.{}", f.number.0, f.number.1) == spec.figure)
                .expect("registered");
            assert_eq!(figure.panels.len(), 6, "figure {}", spec.figure);
        }
    }

    #[test]
    fn notes_do_not_break_the_index_table() {
        for f in FIGURES {
            for text in [f.caption, f.drawn, f.data] {
                assert!(!text.replace("\\|", "").contains('|'), "unescaped | in {text}");
            }
        }
    }

    #[test]
    fn the_parametric_sphere_mesh_has_axis_normals_at_the_poles() {
        let surface = test_surface("sphere").expect("defined");
        let (mesh, params) =
            parametric_mesh(&|u, v| surface.derivs(u, v), 1.0, surface.window, (8, 6))
                .expect("meshes");
        assert_eq!(params.len(), mesh.n_vertices(), "one parameter per vertex");
        for (p, n) in mesh.positions().iter().zip(mesh.normals()) {
            if p.z.abs() > 1.0 - 1e-9 {
                assert!(n.cross(DVec3::Z).length() < 1e-9, "pole normal {n} at {p}");
            }
        }
        // Each pole quad gives one triangle.
        assert_eq!(mesh.n_triangles(), 2 * 8 * 6 - 2 * 8, "pole triangles dropped");
    }

    #[test]
    fn ticks_have_three_significant_digits() {
        assert_eq!(tick(0.99996), "1.00");
        assert_eq!(tick(-0.5), "−0.500");
        assert_eq!(tick(123.456), "123");
        assert_eq!(tick(0.0), "0");
        assert_eq!(tick(2.5e-4), "2.50·10⁻⁴");
        assert_eq!(tick(-31_400.0), "−3.14·10⁴");
    }

    #[test]
    fn vertex_normals_agree_with_the_winding() {
        // The parametric meshes built here; the harmonic ones carry the surface's own
        // ∂u × ∂v, which near a fold of the interpolant may lean past the chords' winding.
        for spec in &SPECS {
            let c = Comparison::new(spec).expect("builds");
            let mesh = &c.mesh(Side::Parametric).0;
            let mut winding = vec![DVec3::ZERO; mesh.n_vertices()];
            for t in mesh.triangles() {
                let [a, b, c] = t.map(|k| mesh.positions()[k as usize]);
                for &k in t {
                    winding[k as usize] += (b - a).cross(c - a);
                }
            }
            let against = mesh
                .normals()
                .iter()
                .zip(&winding)
                .filter(|(n, w)| n.dot(**w) < -1e-9 * w.length())
                .count();
            assert_eq!(against, 0, "figure {}: normals against the winding", spec.figure);
        }
    }

    #[test]
    fn markers_are_closed_outward_balls() {
        let mesh = control_mesh(&hi_surface::torus(2.0, 1.0)).expect("meshes");
        let marked = with_markers(&mesh, &[DVec3::ZERO, DVec3::ZERO], 0.5).expect("marks");
        // One ball: the octahedron's 6 corners and its 12 edges halved (12 more), its 8 faces
        // cut into 4: 18 vertices, 32 faces.
        assert_eq!(marked.n_vertices(), mesh.n_vertices() + 18, "one ball");
        let faces = &marked.triangles()[mesh.n_triangles()..];
        assert_eq!(faces.len(), 32);
        let mut edges = std::collections::BTreeMap::new();
        for t in faces {
            let [a, b, c] = t.map(|k| marked.positions()[k as usize]);
            // Outward, on the sphere of radius 0.5, and closed (each edge in two faces, once
            // each way).
            assert!((b - a).cross(c - a).dot(a + b + c) > 0.0, "face {t:?} points inward");
            for p in [a, b, c] {
                assert!((p.length() - 0.5).abs() < 1e-12);
            }
            for k in 0..3 {
                *edges.entry((t[k], t[(k + 1) % 3])).or_insert(0) += 1;
            }
        }
        assert!(edges.iter().all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1)));
        // Inscribed in the sphere, its area is below the sphere's (4π·0.25 = π) and, cut once,
        // above 80 % of it (the octahedron alone has 55 %).
        let area: f64 = faces
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|k| marked.positions()[k as usize]);
                0.5 * (b - a).cross(c - a).length()
            })
            .sum();
        let ratio = area / std::f64::consts::PI;
        assert!(ratio > 0.8 && ratio < 1.0, "area {area}");
    }
}
