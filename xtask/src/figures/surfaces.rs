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
//! 95th percentile of the parametric surface's |values| (at least 10⁻⁶ of the curvature of the
//! surface's size, so that a flat surface is grey). Values beyond ±a take the end colours;
//! undefined values (poles) are mid grey. Each picture is an SVG: the render, and beside it a
//! colour bar with its values ([`colour_bar_svg`]).

use anyhow::{Context, Result, ensure};
use glam::{DVec2, DVec3};
use hi_mesh::{ColorLegend, ColorMap, ColorScale, Palette, TriangleMesh, srgb_to_linear_rgb};
use hi_surface::{
    CurvatureQuantity, HarmonicSurface, MeshOptions, ParametricSurface, SurfaceDerivs,
    compare_curvature, test_surface, test_surfaces,
};

use super::glb::{glb, glb_with_edges};
use super::{Figure, Format, Panel, Table};
use hi_surface::{ParamRange, ParamWindow};

/// The fraction of the parametric surface's curvature values the colour scale spans.
const COVERAGE: f64 = 0.95;

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
/// sample and 12 around the tubes of the knots.
const SPECS: [Spec; 13] = [
    Spec { name: "plane", figure: "5.31", n_u: 48, n_v: 16 },
    Spec { name: "partial-sphere", figure: "5.32", n_u: 48, n_v: 16 },
    Spec { name: "torus", figure: "5.33", n_u: 48, n_v: 16 },
    Spec { name: "sphere", figure: "5.34", n_u: 48, n_v: 16 },
    Spec { name: "mobius", figure: "5.35", n_u: 48, n_v: 16 },
    Spec { name: "revolution", figure: "5.36", n_u: 48, n_v: 16 },
    Spec { name: "shell", figure: "5.37", n_u: 48, n_v: 16 },
    Spec { name: "shell2", figure: "5.38", n_u: 48, n_v: 16 },
    Spec { name: "klein", figure: "5.39", n_u: 48, n_v: 16 },
    Spec { name: "overhand", figure: "5.40", n_u: 72, n_v: 12 },
    Spec { name: "solomon", figure: "5.41", n_u: 72, n_v: 12 },
    Spec { name: "solomon-fine", figure: "5.42", n_u: 96, n_v: 12 },
    Spec { name: "revolution-periodic", figure: "5.43", n_u: 48, n_v: 16 },
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
    the samples are drawn in (d), which passes through them, as small red octahedra on a light grey surface (not in \
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
                16 interpolation points overlaid as small red octahedra (the sphere's 4 points at each pole are one).",
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
        "§5.9 surface `mobius` of `hi_surface::parametric`: the doubled Möbius strip (twice round, so periodic in u), sampled at 24×4 points."
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

/// A triangle mesh of a parametric surface, given by its derivatives, over `window` with
/// `n_u`×`n_v` quads (see the module notes), and the parameters (u, v) of its vertices.
fn parametric_mesh(
    derivs: &dyn Fn(f64, f64) -> SurfaceDerivs,
    scale: f64,
    window: ParamWindow,
    (n_u, n_v): (usize, usize),
) -> Result<(TriangleMesh, Vec<DVec2>)> {
    let ParamWindow { u: ParamRange { start: u0, end: u1 }, v: ParamRange { start: v0, end: v1 } } =
        window;
    let cols = n_v + 1;
    let mut params = Vec::with_capacity((n_u + 1) * cols);
    for i in 0..=n_u {
        for l in 0..=n_v {
            params.push(DVec2::new(
                u0 + (u1 - u0) * i as f64 / n_u as f64,
                v0 + (v1 - v0) * l as f64 / n_v as f64,
            ));
        }
    }
    let samples: Vec<SurfaceDerivs> = params.iter().map(|t| derivs(t.x, t.y)).collect();
    let size = samples.iter().map(|d| d.p.length()).fold(scale, f64::max);
    let tol = 1e-9 * size;
    let at = |i: usize, l: usize| (i * cols + l) as u32;
    let position = |k: u32| samples[k as usize].p;
    let mut triangles = Vec::with_capacity(2 * n_u * n_v);
    for i in 0..n_u {
        for l in 0..n_v {
            let (a, b, c, d) = (at(i, l), at(i + 1, l), at(i + 1, l + 1), at(i, l + 1));
            for t in [[a, b, c], [a, c, d]] {
                let [pa, pb, pc] = t.map(position);
                if pa.distance(pb) > tol && pb.distance(pc) > tol && pa.distance(pc) > tol {
                    triangles.push(t);
                }
            }
        }
    }
    // Keep the vertices triangles use, in grid order.
    let mut new_index = vec![u32::MAX; samples.len()];
    for &k in triangles.iter().flatten() {
        new_index[k as usize] = 0;
    }
    let mut used = Vec::with_capacity(samples.len());
    for (k, slot) in new_index.iter_mut().enumerate() {
        if *slot == 0 {
            *slot = used.len() as u32;
            used.push(k);
        }
    }
    let positions: Vec<DVec3> = used.iter().map(|&k| samples[k].p).collect();
    // The area-weighted normal of the triangles at each vertex: a vertex normal points to its
    // side (where the parameterisation folds, ∂u × ∂v turns against the triangles' winding,
    // and a renderer would shade those triangles from behind).
    let mut winding = vec![DVec3::ZERO; samples.len()];
    for t in &triangles {
        let [a, b, c] = t.map(position);
        let n = (b - a).cross(c - a);
        for &k in t {
            winding[k as usize] += n;
        }
    }
    let normals: Vec<DVec3> = used
        .iter()
        .map(|&k| {
            let n = samples[k].normal(scale).unwrap_or_else(|| {
                // The sum of the normals of the triangles at this point.
                let here = samples[k].p;
                let sum: DVec3 = triangles
                    .iter()
                    .filter(|t| t.iter().any(|&g| position(g).distance(here) <= tol))
                    .map(|t| {
                        let [a, b, c] = t.map(position);
                        (b - a).cross(c - a)
                    })
                    .sum();
                sum.try_normalize().unwrap_or(DVec3::Z)
            });
            if n.dot(winding[k]) < 0.0 { -n } else { n }
        })
        .collect();
    let uvs: Vec<DVec2> = used
        .iter()
        .map(|&k| DVec2::new((k / cols) as f64 / n_u as f64, (k % cols) as f64 / n_v as f64))
        .collect();
    let triangles: Vec<[u32; 3]> =
        triangles.into_iter().map(|t| t.map(|k| new_index[k as usize])).collect();
    let params = used.iter().map(|&k| params[k]).collect();
    Ok((TriangleMesh::try_new(positions, normals, uvs, triangles)?, params))
}

/// The control grid of `surface` as a closed mesh: each quad split into two triangles,
/// area-weighted face normals, UVs (j/m, k/n).
fn control_mesh(surface: &HarmonicSurface<DVec3>) -> Result<TriangleMesh> {
    let (m, n) = (surface.m(), surface.n());
    let at = |j: usize, k: usize| ((j % m) * n + k % n) as u32;
    let positions = surface.points().to_vec();
    let mut triangles = Vec::with_capacity(2 * m * n);
    for j in 0..m {
        for k in 0..n {
            let (a, b, c, d) = (at(j, k), at(j + 1, k), at(j + 1, k + 1), at(j, k + 1));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    let mut sums = vec![DVec3::ZERO; positions.len()];
    for t in &triangles {
        let [a, b, c] = t.map(|k| positions[k as usize]);
        let face = (b - a).cross(c - a);
        for &k in t {
            sums[k as usize] += face;
        }
    }
    let normals = sums.into_iter().map(|s| s.try_normalize().unwrap_or(DVec3::Z)).collect();
    let uvs = (0..m * n).map(|g| DVec2::new((g / n) as f64 / m as f64, (g % n) as f64 / n as f64));
    Ok(TriangleMesh::try_new(positions, normals, uvs.collect(), triangles)?)
}

/// `mesh` with a small red octahedron of radius `radius` at each of the distinct `points`;
/// the mesh keeps its colours, or becomes light grey if it had none.
fn with_markers(mesh: &TriangleMesh, points: &[DVec3], radius: f64) -> Result<TriangleMesh> {
    let mut positions = mesh.positions().to_vec();
    let mut normals = mesh.normals().to_vec();
    let mut uvs = mesh.uvs().to_vec();
    let mut triangles = mesh.triangles().to_vec();
    let mut colors = mesh.colors().map_or_else(
        || vec![srgb_to_linear_rgb(SURFACE_SRGB); mesh.n_vertices()],
        <[[f32; 3]]>::to_vec,
    );
    push_octahedra(
        (&mut positions, &mut normals, &mut uvs, &mut triangles, &mut colors),
        points,
        radius,
    )?;
    Ok(TriangleMesh::try_new(positions, normals, uvs, triangles)?.try_with_colors(colors)?)
}

/// Data points drawn alone as red octahedra ("beads") of `radius`, one per distinct point.
///
/// # Errors
///
/// If there is no point or more than 2³² corners.
pub(crate) fn beads(points: &[DVec3], radius: f64) -> Result<TriangleMesh> {
    let mut parts = (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    push_octahedra(
        (&mut parts.0, &mut parts.1, &mut parts.2, &mut parts.3, &mut parts.4),
        points,
        radius,
    )?;
    let (positions, normals, uvs, triangles, colors) = parts;
    ensure!(!triangles.is_empty(), "no points to draw");
    Ok(TriangleMesh::try_new(positions, normals, uvs, triangles)?.try_with_colors(colors)?)
}

/// The parts of a mesh being built: positions, normals, UVs, triangles and colours.
type Parts<'a> = (
    &'a mut Vec<DVec3>,
    &'a mut Vec<DVec3>,
    &'a mut Vec<DVec2>,
    &'a mut Vec<[u32; 3]>,
    &'a mut Vec<[f32; 3]>,
);

/// Appends a red octahedron of `radius` at each distinct point of `points` (points within a
/// thousandth of the radius of one already drawn are drawn once).
fn push_octahedra(
    (positions, normals, uvs, triangles, colors): Parts<'_>,
    points: &[DVec3],
    radius: f64,
) -> Result<()> {
    let mut distinct: Vec<DVec3> = Vec::new();
    for &p in points {
        if distinct.iter().all(|q| q.distance(p) > 1e-3 * radius) {
            distinct.push(p);
        }
    }
    let axes = [DVec3::X, DVec3::NEG_X, DVec3::Y, DVec3::NEG_Y, DVec3::Z, DVec3::NEG_Z];
    for p in distinct {
        let base = u32::try_from(positions.len())?;
        for e in axes {
            positions.push(p + radius * e);
            normals.push(e);
            uvs.push(DVec2::ZERO);
            colors.push(srgb_to_linear_rgb(MARKER_SRGB));
        }
        // One face per octant, counter-clockwise seen from outside.
        for (sx, sy, sz) in [(0, 0, 0), (0, 0, 1), (0, 1, 0), (0, 1, 1)]
            .into_iter()
            .flat_map(|(x, y, z)| [(x, y, z), (1 - x, 1 - y, 1 - z)])
        {
            let (x, y, z) = (base + sx, base + 2 + sy, base + 4 + sz);
            triangles.push(if (sx + sy + sz) % 2 == 0 { [x, y, z] } else { [x, z, y] });
        }
    }
    Ok(())
}

/// The colour map of the §5.9 pictures: cool–warm from −`extent` to `extent`.
fn signed_map(extent: f64) -> ColorMap {
    ColorMap {
        scale: ColorScale::Fixed { min: -extent, max: extent },
        coverage: 1.0,
        palette: Palette::CoolWarm,
    }
}

/// `mesh` coloured by `values` (one per vertex) on [`signed_map`]; NaN grey.
fn colored(mesh: TriangleMesh, values: &[f64], extent: f64) -> Result<TriangleMesh> {
    Ok(mesh.try_with_colors(signed_map(extent).try_apply(values)?.colors)?)
}

/// Whether panel `suffix` of figure `number` is a §5.9 curvature picture (with a colour bar).
pub(crate) fn has_colour_bar(number: (u32, u32), suffix: &str) -> bool {
    number.0 == 5
        && (31..=43).contains(&number.1)
        && (suffix.ends_with("-K") || suffix.ends_with("-H"))
}

/// The legend of panel `suffix` of figure `number` (see [`has_colour_bar`]) and its symbol.
pub(crate) fn colour_bar(number: (u32, u32), suffix: &str) -> Result<(ColorLegend, &'static str)> {
    let label = format!("{}.{}", number.0, number.1);
    let spec = SPECS.iter().find(|s| s.figure == label).context("not a §5.9 figure")?;
    let quantity =
        if suffix.ends_with("-K") { CurvatureQuantity::Gaussian } else { CurvatureQuantity::Mean };
    let c = Comparison::new(spec)?;
    let side = if suffix.contains("harmonic") { Side::Harmonic } else { Side::Parametric };
    let legend = signed_map(c.extent(quantity)?).try_apply(&c.values(side, quantity))?.legend;
    Ok((legend, quantity.symbol()))
}

/// A number for a colour bar: three significant digits, a true minus sign.
fn tick(x: f64) -> String {
    // Rounded to three significant digits first, so that 0.99996 is 1.00, not 1.000.
    let x: f64 = format!("{x:.2e}").parse().unwrap_or(x);
    let a = x.abs();
    let s = if x == 0.0 {
        "0".to_owned()
    } else if (0.01..1000.0).contains(&a) {
        let digits = (2 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.digits$}")
    } else {
        let e = a.log10().floor() as i32;
        format!("{:.2}·10{}", x / 10f64.powi(e), superscript(e))
    };
    s.replace('-', "−")
}

/// An exponent in superscript digits.
fn superscript(e: i32) -> String {
    e.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹']
                [d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect()
}

/// The render `image` (JPEG, `width`×`height` pixels) with a colour bar of `legend` at
/// its right, laid out in units of a third of a pixel so that its text keeps its size beside a
/// 400×300 picture and the render shows at full resolution: the
/// palette from the legend's low end (bottom) to its high end (top), ticks at −a, −a/2, 0, a/2
/// and a labelled with their values, the quantity's `symbol` above, and below it how many
/// values the ends of the bar stand in for and how many were undefined.
pub(crate) fn colour_bar_svg(
    image: &[u8],
    (pixels_x, pixels_y): (u32, u32),
    legend: &ColorLegend,
    symbol: &str,
) -> String {
    let (width, height) = (pixels_x / 3, pixels_y / 3);
    let bar_x = width + 16;
    let (top, bottom) = (40.0, f64::from(height) - 50.0);
    let total = width + 140;
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{pixels_y}\" \
         viewBox=\"0 0 {total} {height}\" font-family=\"sans-serif\" font-size=\"13\">\n\
         <rect width=\"{total}\" height=\"{height}\" fill=\"#fff\"/>\n\
         <image width=\"{width}\" height=\"{height}\" href=\"data:image/jpeg;base64,{}\"/>\n\
         <defs><linearGradient id=\"bar\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">\n",
        3 * total,
        base64::encode(image)
    );
    let colour = |c: [f32; 3]| {
        let [r, g, b] = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
        format!("#{r:02x}{g:02x}{b:02x}")
    };
    for k in 0..=16 {
        let t = f64::from(k) / 16.0;
        let value = legend.min + t * (legend.max - legend.min);
        s += &format!(
            "<stop offset=\"{t:.4}\" stop-color=\"{}\"/>\n",
            colour(legend.srgb_at(value))
        );
    }
    s += "</linearGradient></defs>\n";
    s += &format!(
        "<text x=\"{}\" y=\"{:.2}\" font-style=\"italic\" font-family=\"serif\" font-size=\"17\">{symbol}</text>\n\
         <rect x=\"{bar_x}\" y=\"{top:.2}\" width=\"18\" height=\"{:.2}\" fill=\"url(#bar)\" stroke=\"#555\"/>\n",
        bar_x + 3,
        top - 12.0,
        bottom - top
    );
    for k in 0..=4 {
        let t = f64::from(k) / 4.0;
        let value = legend.min + t * (legend.max - legend.min);
        let y = bottom - t * (bottom - top);
        s += &format!(
            "<line x1=\"{}\" y1=\"{y:.2}\" x2=\"{}\" y2=\"{y:.2}\" stroke=\"#555\"/>\n\
             <text x=\"{}\" y=\"{:.2}\">{}</text>\n",
            bar_x + 18,
            bar_x + 23,
            bar_x + 26,
            y + 4.5,
            tick(value)
        );
    }
    let mut notes = Vec::new();
    if legend.n_clamped > 0 {
        notes.push(format!("{} beyond the ends", legend.n_clamped));
    }
    if legend.n_invalid > 0 {
        notes.push(format!("{} undefined (grey)", legend.n_invalid));
    }
    for (k, note) in notes.iter().enumerate() {
        s += &format!(
            "<text x=\"{}\" y=\"{:.2}\" font-size=\"11\" fill=\"#444\">{note}</text>\n",
            width + 4,
            bottom + 22.0 + 14.0 * k as f64
        );
    }
    s += "</svg>\n";
    s
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

/// A §5.9 comparison: the surface, its harmonic surface and both meshes.
struct Comparison {
    surface: ParametricSurface,
    harmonic: HarmonicSurface<DVec3>,
    /// The curvature scale (the harmonic surface's radius).
    scale: f64,
    /// The mesh of the parametric surface and the parameters of its vertices.
    parametric_mesh: (TriangleMesh, Vec<DVec2>),
    /// The mesh of the harmonic surface and the parameters of its vertices.
    harmonic_mesh: (TriangleMesh, Vec<DVec2>),
}

impl Comparison {
    fn new(spec: &Spec) -> Result<Self> {
        let surface =
            test_surface(spec.name).with_context(|| format!("no §5.9 surface {}", spec.name))?;
        ensure!(
            surface.figure == spec.figure,
            "surface {} is figure {}, not {}",
            spec.name,
            surface.figure,
            spec.figure
        );
        let harmonic = surface.harmonic();
        let scale = harmonic.radius();
        let window = surface.window;
        let parametric_mesh =
            parametric_mesh(&|u, v| surface.derivs(u, v), scale, window, (spec.n_u, spec.n_v))?;
        let options = MeshOptions { n_u: spec.n_u, n_v: spec.n_v, window, ..Default::default() };
        let mesh = harmonic.to_mesh(&options)?;
        let params = mesh.uvs().iter().map(|t| DVec2::from(window.lerp(t.x, t.y))).collect();
        Ok(Comparison { surface, harmonic, scale, parametric_mesh, harmonic_mesh: (mesh, params) })
    }

    /// The mesh of one side and the parameters of its vertices.
    fn mesh(&self, side: Side) -> &(TriangleMesh, Vec<DVec2>) {
        match side {
            Side::Parametric => &self.parametric_mesh,
            Side::Harmonic => &self.harmonic_mesh,
        }
    }

    /// `quantity` at the vertices of one side's mesh; NaN where undefined.
    fn values(&self, side: Side, quantity: CurvatureQuantity) -> Vec<f64> {
        let curvature = |t: &DVec2| match side {
            Side::Parametric => self.surface.curvature(t.x, t.y, self.scale),
            Side::Harmonic => self.harmonic.curvature(t.x, t.y),
        };
        self.mesh(side)
            .1
            .iter()
            .map(|t| curvature(t).map_or(f64::NAN, |c| quantity.of(&c)))
            .collect()
    }

    /// The colour-scale extent of `quantity` (see the module notes).
    fn extent(&self, quantity: CurvatureQuantity) -> Result<f64> {
        let map =
            ColorMap { scale: ColorScale::Magnitude, coverage: COVERAGE, palette: Palette::Thesis };
        let a = map.try_apply(&self.values(Side::Parametric, quantity))?.legend.max;
        let floor = match quantity {
            CurvatureQuantity::Gaussian => FLOOR / (self.scale * self.scale),
            _ => FLOOR / self.scale,
        };
        Ok(if a.is_finite() { a.max(floor) } else { floor })
    }
}

/// One panel of figures 5.31–5.43: a side, plain (the harmonic one with its samples marked) or
/// coloured by the magnitude of a curvature.
fn comparison(spec: &Spec, side: Side, show: Option<CurvatureQuantity>) -> Result<Vec<u8>> {
    let c = Comparison::new(spec)?;
    let mesh = &c.mesh(side).0;
    let mesh = match show {
        Some(quantity) => colored(mesh.clone(), &c.values(side, quantity), c.extent(quantity)?)?,
        None if side == Side::Harmonic => {
            with_markers(mesh, c.harmonic.points(), MARKER_SIZE * c.scale)?
        }
        None => mesh.clone(),
    };
    glb(&mesh)
}

/// The curvature comparison of §5.9, one row per surface.
fn curvature_table() -> Result<String> {
    let mut s = String::from(
        "| fig | surface | samples | points | max ΔK | RMS ΔK | max \\|K\\| | max ΔH | RMS ΔH | max \\|H\\| |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    for surface in test_surfaces() {
        let c = compare_curvature(&surface, TABLE_RES);
        s += &format!(
            "| {} | {} | {}×{} | {} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} |\n",
            surface.figure,
            surface.title,
            surface.samples.0,
            surface.samples.1,
            c.n_points,
            c.gaussian_max,
            c.gaussian_rms,
            c.gaussian_scale,
            c.mean_max,
            c.mean_rms,
            c.mean_scale
        );
    }
    Ok(s)
}

/// The meshes and colour scales of figures 5.31–5.43.
fn mesh_table() -> Result<String> {
    let mut s = String::from(
        "| fig | surface | window (u0, u1, v0, v1) | quads | vertices (parametric, harmonic) | a for \\|K\\| | over a | a for \\|H\\| | over a |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for spec in &SPECS {
        let c = Comparison::new(spec)?;
        let over = |quantity| -> Result<(f64, usize)> {
            let a = c.extent(quantity)?;
            let n =
                c.values(Side::Harmonic, quantity).iter().filter(|x| x.abs() > OVER * a).count();
            Ok((a, n))
        };
        let ((ak, nk), (ah, nh)) =
            (over(CurvatureQuantity::Gaussian)?, over(CurvatureQuantity::Mean)?);
        let w = c.surface.window;
        let (u0, u1, v0, v1) = (w.u.start, w.u.end, w.v.start, w.v.end);
        s += &format!(
            "| {} | {} | ({u0}, {u1}, {v0}, {v1}) | {}×{} | {}, {} | {ak:.3e} | {nk} | {ah:.3e} | {nh} |\n",
            spec.figure,
            c.surface.title,
            spec.n_u,
            spec.n_v,
            c.parametric_mesh.0.n_vertices(),
            c.harmonic_mesh.0.n_vertices(),
        );
    }
    Ok(s)
}

#[cfg(test)]
mod tests {
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
    fn markers_are_closed_outward_octahedra() {
        let mesh = control_mesh(&hi_surface::torus(2.0, 1.0)).expect("meshes");
        let marked = with_markers(&mesh, &[DVec3::ZERO, DVec3::ZERO], 0.5).expect("marks");
        assert_eq!(marked.n_vertices(), mesh.n_vertices() + 6, "one octahedron");
        for t in &marked.triangles()[mesh.n_triangles()..] {
            let [a, b, c] = t.map(|k| marked.positions()[k as usize]);
            assert!((b - a).cross(c - a).dot(a + b + c) > 0.0, "face {t:?} points inward");
        }
    }
}
