// SPDX-License-Identifier: MIT
//! Figures 4.11–4.35 and Table 4.1: the subdivision schemes of §4.5 on the cube, the star and
//! a head, as binary glTF models, and the comparison of the schemes measured on them.
//!
//! Every stage is a [`PolyMesh`] from `hi_mesh::subdivision`, drawn flat (each face fanned
//! into triangles with its own normal) with its faces' edges as a second primitive of lines,
//! so that the refinement shows and a quad mesh differs from its triangulation
//! ([`super::glb::flat_with_edges`]); the limit
//! surfaces of Loop and Catmull-Clark put every vertex of the third step on the limit surface
//! with its exact limit normal ([`loop_limit`], [`catmull_clark_limit`]); the other schemes
//! have no closed-form limit, and their "limit" is the fourth step.

use std::f64::consts::PI;
use std::fmt::Write as _;

use anyhow::{Context, Result, ensure};
use glam::DVec3;
use hi_mesh::TriangleMesh;
use hi_mesh::subdivision::{
    LimitPoint, LoopWeights, PolyMesh, Scheme, catmull_clark_limit, loop_limit,
};

use super::glb::{flat_with_edges, glb, glb_with_edges};
use super::{Figure, Format, Panel, Table};

/// The control meshes of the figures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shape {
    /// [`PolyMesh::cube`]: six quads.
    Cube,
    /// [`PolyMesh::triangulated_cube`]: twelve triangles.
    TriCube,
    /// [`PolyMesh::sharp_star`]: fifty-four quads.
    Star,
    /// The sharp star split into 108 triangles ([`PolyMesh::triangulated`]).
    TriStar,
    /// [`head`]: a coarse closed triangle mesh of a head.
    Head,
}

impl Shape {
    fn mesh(self) -> Result<PolyMesh> {
        Ok(match self {
            Shape::Cube => PolyMesh::cube(),
            Shape::TriCube => PolyMesh::triangulated_cube(),
            Shape::Star => PolyMesh::sharp_star(),
            Shape::TriStar => PolyMesh::sharp_star().triangulated()?,
            Shape::Head => head()?,
        })
    }
}

/// Loop with Loop's β, as in the thesis.
const LOOP: Scheme = Scheme::Loop(LoopWeights::Loop);

/// The steps shown by the "first four steps" figures: the control mesh and three steps.
const LAST_STEP: usize = 3;

/// The steps of the "limit" of a scheme without a closed-form limit.
const LIMIT_STEPS: usize = 4;

/// The steps of the head of figure 4.35: one (its control mesh has 512 triangles; two steps of
/// each of six schemes would take 3 MB of the figures).
const HEAD_STEPS: usize = 1;

/// The mesh after `steps` steps of `scheme` on `shape`, checked: an interpolating scheme keeps
/// the control vertices (bit for bit, as the first vertices of the result).
fn refined(scheme: Scheme, shape: Shape, steps: usize) -> Result<PolyMesh> {
    let control = shape.mesh()?;
    let mesh = scheme.steps(&control, steps)?;
    if scheme.is_interpolating() {
        ensure!(
            mesh.positions()[..control.n_vertices()] == *control.positions(),
            "{} moved a control vertex of {shape:?}",
            scheme.name()
        );
    }
    Ok(mesh)
}

/// A stage of a "first four steps" figure: the mesh flat, with its polygons' edges.
fn stage(scheme: Scheme, shape: Shape, steps: usize) -> Result<Vec<u8>> {
    polygons_glb(&refined(scheme, shape, steps)?)
}

/// The `.glb` of a polygon mesh drawn flat with its edges ([`flat_with_edges`]).
fn polygons_glb(mesh: &PolyMesh) -> Result<Vec<u8>> {
    let p = mesh.positions();
    let polygons: Vec<Vec<DVec3>> =
        mesh.faces().map(|f| f.iter().map(|&k| p[k as usize]).collect()).collect();
    let (flat, edges) = flat_with_edges(&polygons)?;
    glb_with_edges(&flat, &edges)
}

/// The mesh whose vertices are `limit`'s positions on `mesh`'s faces, with the limit normals.
fn limit_mesh(mesh: &PolyMesh, limit: &[LimitPoint]) -> Result<TriangleMesh> {
    let faces: Vec<Vec<u32>> = mesh.faces().map(<[u32]>::to_vec).collect();
    let on_limit = PolyMesh::try_new(limit.iter().map(|l| l.position).collect(), &faces)?;
    let fan = on_limit.to_triangle_mesh()?;
    let normals = limit.iter().zip(fan.normals()).map(|(l, &n)| l.normal.unwrap_or(n)).collect();
    Ok(TriangleMesh::try_new(
        fan.positions().to_vec(),
        normals,
        fan.uvs().to_vec(),
        fan.triangles().to_vec(),
    )?)
}

/// The limit surface of `scheme` on `shape`: the third step pushed to the limit (Loop,
/// Catmull-Clark) or the fourth step; for the cube, one step more ([`CUBE_EXTRA_STEP`]).
fn limit(scheme: Scheme, shape: Shape) -> Result<Vec<u8>> {
    let extra = if matches!(shape, Shape::Cube | Shape::TriCube) { CUBE_EXTRA_STEP } else { 0 };
    let mesh = match scheme {
        Scheme::Loop(w) => {
            let mesh = refined(scheme, shape, LAST_STEP + extra)?;
            limit_mesh(&mesh, &loop_limit(&mesh, w)?)?
        }
        Scheme::CatmullClark => {
            let mesh = refined(scheme, shape, LAST_STEP + extra)?;
            limit_mesh(&mesh, &catmull_clark_limit(&mesh)?)?
        }
        _ => refined(scheme, shape, LIMIT_STEPS + extra)?.to_triangle_mesh()?,
    };
    glb(&mesh)
}

/// Steps added to the cube's limit surfaces: rounded into a near-sphere, its silhouette shows
/// the facets of the steps that suffice for the star's spikes at the renders' 1200×900.
const CUBE_EXTRA_STEP: usize = 1;

/// The head of figure 4.35 after [`HEAD_STEPS`] steps of `scheme` (the control mesh for
/// `None`).
fn head_stage(scheme: Option<Scheme>) -> Result<Vec<u8>> {
    match scheme {
        Some(s) => stage(s, Shape::Head, HEAD_STEPS),
        None => polygons_glb(&Shape::Head.mesh()?),
    }
}

/// The head's control mesh (figures 1.1 and 4.35): a coarse closed triangle mesh of Lee
/// Perry-Smith's head scan ([`super::scans::head_control`]), so that the schemes differ.
pub(crate) fn head() -> Result<PolyMesh> {
    let (positions, faces) = super::scans::head_control()?;
    let mesh = PolyMesh::try_new(positions, &faces).context("the head mesh")?;
    ensure!(signed_volume(&mesh) > 0.0, "the head's faces point inwards");
    Ok(mesh)
}

/// The volume enclosed by a closed mesh, positive when its faces point outwards.
fn signed_volume(mesh: &PolyMesh) -> f64 {
    let p = mesh.positions();
    mesh.faces()
        .flat_map(|f| (1..f.len() - 1).map(move |i| [f[0], f[i], f[i + 1]]))
        .map(|[a, b, c]| p[a as usize].dot(p[b as usize].cross(p[c as usize])) / 6.0)
        .sum()
}

/// What every figure of steps draws.
const STEPS_DRAWN: &str = "(a) The control mesh and (b)–(d) the first three steps of the scheme (`hi_mesh::subdivision`), \
    each face drawn flat (a fan of triangles with the face's own normal) and its edges as a second primitive of lines \
    (dark in the renders, drawn by glTF viewers), so that a quad mesh and its triangulation differ; no colours. The \
    four panels share one camera, so the shrinking of an approximating scheme shows. The thesis's four panels \
    count the control mesh as the first.";

/// The data line of the cube figures.
const CUBE_DATA: &str = "the cube [0, 1]³ of six quads (`PolyMesh::cube`); triangulated: each quad (a, b, c, d) split \
    into (a, b, c), (a, c, d) (`PolyMesh::triangulated_cube`).";

/// The data line of the star figures.
const STAR_DATA: &str = "stand-in (the thesis does not give its star): the cube [−1, 1]³ with a long spike on \
    each face, narrowing at a neck 0.9 out to a tip 3.2 out, 54 quads (`PolyMesh::sharp_star`); triangulated: each \
    quad split into a fan of two triangles, 108 triangles (`PolyMesh::triangulated`).";

/// A "first four steps" figure.
macro_rules! steps {
    ($number:literal, $caption:literal, $scheme:expr, $shape:expr, $data:expr) => {
        Figure {
            number: (4, $number),
            caption: $caption,
            drawn: STEPS_DRAWN,
            data: $data,
            format: Format::Glb,
            views: &[],
            panels: &[
                Panel {
                    suffix: "a",
                    title: "(a) Control mesh",
                    draw: |_| stage($scheme, $shape, 0),
                },
                Panel { suffix: "b", title: "(b) One step", draw: |_| stage($scheme, $shape, 1) },
                Panel { suffix: "c", title: "(c) Two steps", draw: |_| stage($scheme, $shape, 2) },
                Panel {
                    suffix: "d",
                    title: "(d) Three steps",
                    draw: |_| stage($scheme, $shape, LAST_STEP),
                },
            ],
        }
    };
}

/// A "limit surfaces" figure: the cube and the star.
macro_rules! limits {
    ($number:literal, $caption:literal, $scheme:expr, $cube:expr, $star:expr, $drawn:literal, $data:expr) => {
        Figure {
            number: (4, $number),
            caption: $caption,
            drawn: $drawn,
            data: $data,
            format: Format::Glb,
            views: &[],
            panels: &[
                Panel { suffix: "a", title: "(a) Cube mesh", draw: |_| limit($scheme, $cube) },
                Panel { suffix: "b", title: "(b) Star mesh", draw: |_| limit($scheme, $star) },
            ],
        }
    };
}

/// A "limit surfaces" figure of a scheme for any polygons (Catmull-Clark, Doo-Sabin): the quad
/// cube and star, then the triangulated ones, as the thesis's four panels.
macro_rules! limits_both {
    ($number:literal, $caption:literal, $scheme:expr, $drawn:literal) => {
        Figure {
            number: (4, $number),
            caption: $caption,
            drawn: $drawn,
            data: BOTH_DATA,
            format: Format::Glb,
            views: &[],
            panels: &[
                Panel {
                    suffix: "a",
                    title: "(a) Cube mesh (quadrilaterals)",
                    draw: |_| limit($scheme, Shape::Cube),
                },
                Panel {
                    suffix: "b",
                    title: "(b) Star mesh (quadrilaterals)",
                    draw: |_| limit($scheme, Shape::Star),
                },
                Panel {
                    suffix: "c",
                    title: "(c) Cube mesh (triangles)",
                    draw: |_| limit($scheme, Shape::TriCube),
                },
                Panel {
                    suffix: "d",
                    title: "(d) Star mesh (triangles)",
                    draw: |_| limit($scheme, Shape::TriStar),
                },
            ],
        }
    };
}

/// The data line of the limit figures.
const BOTH_DATA: &str =
    "the cube and the star of the figures before (the star is a stand-in: `PolyMesh::sharp_star`).";

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    steps!(
        11,
        "First four steps of a cube subdivided with Loop subdivision",
        LOOP,
        Shape::TriCube,
        CUBE_DATA
    ),
    steps!(
        12,
        "First four steps of a star shape subdivided with Loop subdivision",
        LOOP,
        Shape::TriStar,
        STAR_DATA
    ),
    limits!(
        13,
        "Limit surfaces (Loop subdivision)",
        LOOP,
        Shape::TriCube,
        Shape::TriStar,
        "The triangulated cube and star after four and three Loop steps (the cube one more, so that its round \
         silhouette shows no facets) with every vertex moved to its limit position and given its exact limit normal \
         (`loop_limit`: Loop's limit masks), so every vertex lies on the limit surface.",
        BOTH_DATA
    ),
    steps!(
        15,
        "First four steps of a cube subdivided with modified butterfly subdivision",
        Scheme::Butterfly,
        Shape::TriCube,
        CUBE_DATA
    ),
    steps!(
        16,
        "First four steps of a star shape subdivided with modified butterfly subdivision",
        Scheme::Butterfly,
        Shape::TriStar,
        STAR_DATA
    ),
    limits!(
        17,
        "Limit surfaces (Modified butterfly subdivision)",
        Scheme::Butterfly,
        Shape::TriCube,
        Shape::TriStar,
        "The triangulated cube and star after five and four steps of the modified butterfly scheme (the cube one \
         more, so that its round silhouette shows no facets; it has no closed-form limit; four steps are 256 \
         triangles per control triangle). The control vertices are kept: checked when the \
         figure is made.",
        BOTH_DATA
    ),
    steps!(
        20,
        "First four steps of a cube subdivided with √3 subdivision",
        Scheme::Sqrt3,
        Shape::TriCube,
        CUBE_DATA
    ),
    steps!(
        21,
        "First four steps of a star shape subdivided with √3 subdivision",
        Scheme::Sqrt3,
        Shape::TriStar,
        STAR_DATA
    ),
    limits!(
        22,
        "Limit surfaces (√3 subdivision)",
        Scheme::Sqrt3,
        Shape::TriCube,
        Shape::TriStar,
        "The triangulated cube and star after five and four √3 steps (the cube one more, so that its round \
         silhouette shows no facets; four steps are 81 triangles per control triangle; no closed-form limit is \
         used).",
        BOTH_DATA
    ),
    steps!(
        25,
        "First four steps of a triangulated cube subdivided with Catmull-Clark subdivision",
        Scheme::CatmullClark,
        Shape::TriCube,
        CUBE_DATA
    ),
    steps!(
        26,
        "First four steps of a cube subdivided with Catmull-Clark subdivision",
        Scheme::CatmullClark,
        Shape::Cube,
        CUBE_DATA
    ),
    steps!(
        27,
        "First four steps of a triangulated star shape subdivided with Catmull-Clark subdivision",
        Scheme::CatmullClark,
        Shape::TriStar,
        STAR_DATA
    ),
    steps!(
        28,
        "First four steps of a star shape subdivided with Catmull-Clark subdivision",
        Scheme::CatmullClark,
        Shape::Star,
        STAR_DATA
    ),
    limits_both!(
        29,
        "Limit surfaces (Catmull-Clark subdivision)",
        Scheme::CatmullClark,
        "The cube and star, (a), (b) of quads and (c), (d) triangulated, after three Catmull-Clark steps (four for \
         the cube, so that its round silhouette shows no facets) with every vertex moved to its limit position and given its exact limit normal (`catmull_clark_limit`), so every \
         vertex lies on the limit surface. The thesis's two pairs of panels, both lettered (a), (b), are lettered \
         (a)–(d) here."
    ),
    steps!(
        30,
        "First four steps of a triangulated cube subdivided with Doo-Sabin subdivision",
        Scheme::DooSabin,
        Shape::TriCube,
        CUBE_DATA
    ),
    steps!(
        31,
        "First four steps of a cube subdivided with Doo-Sabin subdivision",
        Scheme::DooSabin,
        Shape::Cube,
        CUBE_DATA
    ),
    steps!(
        32,
        "First four steps of a triangulated star shape subdivided with Doo-Sabin subdivision",
        Scheme::DooSabin,
        Shape::TriStar,
        STAR_DATA
    ),
    steps!(
        33,
        "First four steps of a star shape subdivided with Doo-Sabin subdivision",
        Scheme::DooSabin,
        Shape::Star,
        STAR_DATA
    ),
    limits_both!(
        34,
        "Limit surfaces (Doo-Sabin subdivision)",
        Scheme::DooSabin,
        "The cube and star, (a), (b) of quads and (c), (d) triangulated, after four Doo-Sabin steps (five for the \
         cube, so that its round silhouette shows no facets; no closed-form limit is used). The thesis's two pairs of panels, both lettered (a), (b), are lettered \
         (a)–(d) here."
    ),
    Figure {
        number: (4, 35),
        caption: "Subdivision of the mannequin head",
        drawn: "(a) The control mesh; (b)–(g) one step of each scheme on it, triangles for every scheme as in the \
                thesis, each drawn flat with its edges; (e), interpolating √3, is not in the thesis.",
        data: "stand-in for Hoppe's mannequin head (not available): Lee Perry-Smith's head scan (`fixtures/models`, \
               CC BY 3.0, as in figures 5.10–5.20) as a closed control mesh of 512 triangles, 258 vertices: the octahedron \
               cut three times, its directions drawn towards the face by a conformal zoom (the face's vertices 2.8 times \
               as dense), each vertex on the scan's surface along its direction (`xtask/src/figures/scans.rs`, `head_control`).",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Control mesh", draw: |_| head_stage(None) },
            Panel { suffix: "b", title: "(b) Loop", draw: |_| head_stage(Some(LOOP)) },
            Panel {
                suffix: "c",
                title: "(c) Modified butterfly",
                draw: |_| head_stage(Some(Scheme::Butterfly)),
            },
            Panel { suffix: "d", title: "(d) √3", draw: |_| head_stage(Some(Scheme::Sqrt3)) },
            Panel {
                suffix: "e",
                title: "(e) Interpolating √3",
                draw: |_| head_stage(Some(Scheme::InterpolatingSqrt3)),
            },
            Panel {
                suffix: "f",
                title: "(f) Catmull-Clark",
                draw: |_| head_stage(Some(Scheme::CatmullClark)),
            },
            Panel {
                suffix: "g",
                title: "(g) Doo-Sabin",
                draw: |_| head_stage(Some(Scheme::DooSabin)),
            },
        ],
    },
];

/// The tables of this module.
pub(crate) const TABLES: &[Table] = &[Table {
    anchor: "subdivision-schemes",
    title: "Table 4.1: Comparison of subdivision schemes",
    about: "The thesis's columns (triangles, polygons, interpolating, continuity) next to what we measure. \
        *Triangles* and *polygons*: one step on the triangulated cube and on a pentagonal prism (two pentagons, five \
        quads), accepted or refused with an error. *Interpolating*: the largest distance from a control vertex of \
        the triangulated star (of the quad star for the polygon schemes) to the mesh after three steps (nearest point \
        on its triangles), relative to the control mesh's bounding-box diagonal. *Continuity*: as stated by the \
        schemes' authors for the limit surface at regular vertices (at extraordinary vertices the triangle schemes \
        and Catmull-Clark are C¹). *V / F*: vertices and faces of the control mesh and after 1, 2, 3 steps. The \
        harmonic row subdivides the 4×4 torus grid (§5.2; the \"faces\" are the grid's quads); the B-spline row \
        fits eight closed slices of a torus with 6 to 9 points each (§4.4). Time per step is \
        measured by `cargo xtask bench subdivision` and reported in `docs/performance.md`, not here: this page is \
        regenerated bit for bit.",
    make: scheme_table,
}];

/// A pentagonal prism: two pentagons and five quads (a closed mesh that is neither all
/// triangles nor all quads).
fn prism() -> Result<PolyMesh> {
    let mut positions = Vec::new();
    for z in [0.0, 1.0] {
        for k in 0..5 {
            let a = 2.0 * PI * f64::from(k) / 5.0;
            positions.push(DVec3::new(a.cos(), a.sin(), z));
        }
    }
    let mut faces: Vec<Vec<u32>> = vec![vec![4, 3, 2, 1, 0], vec![5, 6, 7, 8, 9]];
    for k in 0..5u32 {
        let j = (k + 1) % 5;
        faces.push(vec![k, j, j + 5, k + 5]);
    }
    let mesh = PolyMesh::try_new(positions, &faces)?;
    ensure!(signed_volume(&mesh) > 0.0, "the prism's faces point inwards");
    Ok(mesh)
}

/// "yes" if one step of `scheme` accepts `mesh`, else "no".
fn accepts(scheme: Scheme, mesh: &PolyMesh) -> &'static str {
    if scheme.step(mesh).is_ok() { "yes" } else { "no" }
}

/// The largest distance from the vertices of `control` to the triangles of `refined`,
/// relative to `control`'s bounding-box diagonal.
fn interpolation_error(control: &PolyMesh, refined: &PolyMesh) -> Result<f64> {
    let tri = refined.to_triangle_mesh()?;
    let d = hi_scan::distance::distances_to_mesh(
        control.positions(),
        tri.positions(),
        tri.triangles(),
    )?;
    Ok(d.max / hi_scan::distance::bounding_diagonal(control.positions()))
}

/// Table 4.1, measured.
fn scheme_table() -> Result<String> {
    let tri_cube = PolyMesh::triangulated_cube();
    let prism = prism()?;
    let tri_star = Shape::TriStar.mesh()?;
    let quad_star = Shape::Star.mesh()?;
    let mut s = String::from(
        "| scheme | triangles (thesis) | triangles (measured) | polygons (thesis) | polygons (measured) | \
         interpolating (thesis) | control vertex to mesh after 3 steps | continuity | V / F of the star, steps 0–3 |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    let rows: [(Scheme, &str, &str, &str, &str); 7] = [
        (LOOP, "Loop", "no", "no", "C²"),
        (Scheme::Loop(LoopWeights::Warren), "Loop, Warren's β", "–", "–", "C²"),
        (Scheme::Butterfly, "Modified butterfly", "no", "yes", "C¹"),
        (Scheme::Sqrt3, "√3", "no", "no", "C²"),
        (Scheme::InterpolatingSqrt3, "Interpolating √3", "–", "–", "C¹"),
        (Scheme::CatmullClark, "Catmull-Clark", "yes", "no", "C²"),
        (Scheme::DooSabin, "Doo-Sabin", "yes", "no", "C¹"),
    ];
    for (scheme, name, polygons_thesis, interpolating_thesis, continuity) in rows {
        let triangles_thesis = if polygons_thesis == "–" { "–" } else { "yes" };
        let control = if accepts(scheme, &prism) == "yes" { &quad_star } else { &tri_star };
        let mut counts = vec![format!("{} / {}", control.n_vertices(), control.n_faces())];
        let mut mesh = control.clone();
        for _ in 0..LAST_STEP {
            mesh = scheme.step(&mesh)?;
            counts.push(format!("{} / {}", mesh.n_vertices(), mesh.n_faces()));
        }
        let err = interpolation_error(control, &mesh)?;
        let _ = writeln!(
            s,
            "| {name} | {triangles_thesis} | {} | {polygons_thesis} | {} | {interpolating_thesis} | {} | {continuity} | {} |",
            accepts(scheme, &tri_cube),
            accepts(scheme, &prism),
            format_error(err),
            counts.join(" → ")
        );
    }
    let _ = writeln!(s, "{}", harmonic_row()?);
    let _ = writeln!(s, "{}", bspline_row()?);
    Ok(s)
}

/// The row of the B-spline surface fit (§4.4): eight closed slices of a torus with 6 to 9
/// points each (so the U-knots must be merged), closed across the slices.
fn bspline_row() -> Result<String> {
    use hi_compare::bspline_fit::{BSplineFit, BSplineFitOptions};
    let slices: Vec<Vec<DVec3>> = (0..8)
        .map(|s| {
            let v = 2.0 * PI * f64::from(s) / 8.0;
            let count = 6 + s % 4;
            (0..count)
                .map(|k| {
                    let u = 2.0 * PI * f64::from(k) / f64::from(count);
                    let r = 2.0 + 0.8 * u.cos();
                    DVec3::new(r * v.cos(), r * v.sin(), 0.8 * u.sin())
                })
                .collect()
        })
        .collect();
    let points: Vec<DVec3> = slices.iter().flatten().copied().collect();
    let options = BSplineFitOptions { closed_u: true, closed_v: true, ..Default::default() };
    let fit = BSplineFit::try_new(slices.clone(), &options)?;
    let mut worst: f64 = 0.0;
    for (s, slice) in slices.iter().enumerate() {
        for (k, &x) in slice.iter().enumerate() {
            let p = fit.surface().eval(fit.u_params()[s][k], fit.v_params()[s]);
            worst = worst.max(p.distance(x));
        }
    }
    let err = worst / hi_scan::distance::bounding_diagonal(&points);
    ensure!(err < 1e-12, "the B-spline fit misses a data point by {err:e}");
    let (cu, cv) = fit.surface().n_control();
    Ok(format!(
        "| B-spline surface fit (§4.4) | – | no (point slices) | – | no (point slices) | – | {} | C² | {} slices of 6–9 points ({} in all) → a {cu}×{cv} bicubic control net |",
        if worst == 0.0 { "0 (kept)".to_owned() } else { format!("≤ {err:.0e} (rounding)") },
        slices.len(),
        points.len()
    ))
}

/// The relative distance of a control vertex, "0" when exactly zero.
fn format_error(e: f64) -> String {
    if e == 0.0 { "0 (kept)".to_owned() } else { format!("{e:.2e}") }
}

/// The row of harmonic tensor-product subdivision (§5.2) on the 4×4 torus grid.
fn harmonic_row() -> Result<String> {
    let torus = hi_surface::torus(2.0, 1.0);
    let (m, n) = (torus.m(), torus.n());
    let mut counts = vec![format!("{} / {}", m * n, m * n)];
    let mut worst: f64 = 0.0;
    let mut grid = torus.clone();
    for level in 1..=LAST_STEP as u32 {
        grid = torus.subdivide(level)?;
        counts.push(format!("{} / {}", grid.m() * grid.n(), grid.m() * grid.n()));
    }
    // The control points are the grid points (2ᵏj, 2ᵏk) of level k; the distance to the
    // refined mesh is at most the distance to that vertex.
    let step = 1 << LAST_STEP;
    for j in 0..m {
        for k in 0..n {
            worst = worst.max(torus.point(j, k).distance(grid.point(step * j, step * k)));
        }
    }
    let diagonal = hi_scan::distance::bounding_diagonal(torus.points());
    let err = worst / diagonal;
    ensure!(err < 1e-14, "harmonic subdivision moved a control point by {err:e}");
    Ok(format!(
        "| Harmonic tensor product (§5.2) | – | no (grids) | – | no (grids) | – | {} | C^∞ | {} |",
        if worst == 0.0 { "0 (kept)".to_owned() } else { format!("≤ {err:.0e} (rounding)") },
        counts.join(" → ")
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_head_is_closed_and_outward() {
        let head = head().expect("valid");
        assert!(head.is_closed(), "closed");
        assert_eq!(head.n_faces(), 512, "the octahedron's 8 faces cut into 4 three times");
        assert_eq!(head.n_vertices(), 258, "V = F/2 + 2");
        assert!(signed_volume(&head) > 0.0, "outward");
        // The zoom takes the half of the sphere facing +y from the stereographic disc of
        // radius 1/0.6 about the face, the cap y > (1 − r²)/(1 + r²) = −0.47 of the sphere's
        // directions: about 74 % of evenly spread vertices lie in front of the head's centre.
        let front = head.positions().iter().filter(|p| p.y > 0.0).count() as f64 / 258.0;
        assert!((0.68..0.80).contains(&front), "{front}");
    }

    #[test]
    fn the_prism_is_refused_by_the_triangle_schemes_only() {
        let prism = prism().expect("valid");
        for scheme in Scheme::ALL {
            let polygons = matches!(scheme, Scheme::CatmullClark | Scheme::DooSabin);
            assert_eq!(accepts(scheme, &prism) == "yes", polygons, "{}", scheme.name());
        }
    }

    #[test]
    fn a_kept_vertex_is_at_distance_zero_and_a_moved_one_is_not() {
        let star = Shape::TriStar.mesh().expect("star");
        let butterfly = Scheme::Butterfly.steps(&star, 1).expect("step");
        assert_eq!(interpolation_error(&star, &butterfly).expect("distance"), 0.0, "kept");
        let loop_mesh = LOOP.steps(&star, 1).expect("step");
        assert!(
            interpolation_error(&star, &loop_mesh).expect("distance") > 1e-3,
            "Loop moves the tips"
        );
    }
}
