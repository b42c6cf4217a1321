// SPDX-License-Identifier: MIT
//! Figures 1.1–1.3 and 4.2–4.4, 4.6, 4.7: the introductory figures of chapter 1 (a polygon
//! mesh, a Bézier curve and its control points, an unorganised point set) and of chapter 4's
//! survey of surfaces and subdivision (§4.2–§4.5): Bézier patches, a Bézier triangle, and
//! Chaikin's and the 4-point scheme on a closed polygon.

use anyhow::{Context, Result, ensure};
use glam::{DVec2, DVec3};
use hi_bezier::{BezierCurve, BezierPatch, TriangularPatch};
use hi_compare::corner_cutting::{DEFAULT_FOUR_POINT_WEIGHT, chaikin_step, four_point_step};
use hi_mesh::TriangleMesh;
use hi_mesh::subdivision::PolyMesh;
use hi_surface::bezier::SurfaceBezier;
use hi_surface::torus;

use super::data;
use super::glb::{flat_with_edges, glb, glb_with_edges};
use super::plot::{
    BLUE, GREY, INK, Legend, Marker, Oblique, Pen, Plot, VERMILION, names, render_grid, sample,
};
use super::scans::ensure_outward;
use super::subdivision::head;
use super::{Figure, Format, Panel};

/// Samples per curve.
const SAMPLES: usize = 600;

/// Samples per side of a patch in the meshes of figures 4.2 and 4.4.
const PATCH_SAMPLES: usize = 24;

/// Hoppe's point set of figure 1.3, in `fixtures/models`.
const HOPPE_POINTS: &str = "cactus.pts";

/// The view of Hoppe's cactus in figure 1.3: seen along x, its arms (along y, z up) across the
/// picture, from a little above; the trunk and arms are about x = ½, so the nearer half of
/// the points is the surface facing the viewer.
const HOPPE_VIEW: Oblique = Oblique { azimuth: 90.0, elevation: 20.0 };

/// The control points x₀ … x₃ of the cubic of figure 1.2 (the thesis labels four).
const CUBIC: [[f64; 2]; 4] = [[0.0, 0.0], [0.9, 2.6], [3.3, 2.8], [4.2, 0.2]];

/// Linear RGB colours of the patches of figure 4.2.
const PATCH_COLORS: [[f32; 3]; 2] = [[0.0, 0.17, 0.44], [0.67, 0.11, 0.0]];

/// A triangle mesh from its parts, one UV per vertex set to zero.
fn mesh(
    positions: Vec<DVec3>,
    normals: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
) -> Result<TriangleMesh> {
    let uvs = vec![DVec2::ZERO; positions.len()];
    Ok(TriangleMesh::try_new(positions, normals, uvs, triangles)?)
}

/// A vertex index as `u32`.
fn index(k: usize) -> Result<u32> {
    Ok(u32::try_from(k)?)
}

/// Figure 1.1: the head's control mesh, flat shaded.
fn polygonal_object() -> Result<Vec<u8>> {
    let head: PolyMesh = head()?;
    let p = head.positions();
    let polygons: Vec<Vec<DVec3>> =
        head.faces().map(|f| f.iter().map(|&k| p[k as usize]).collect()).collect();
    let (flat, edges) = flat_with_edges(&polygons)?;
    ensure_outward(&flat, 0.99, "the head")?;
    glb_with_edges(&flat, &edges)
}

/// Figure 1.2: a cubic Bézier curve, its control polygon and control points.
fn bezier_curve(title: &str) -> Result<Vec<u8>> {
    let curve = BezierCurve::try_new(data::plane(&CUBIC))?;
    let points = curve.control_points().to_vec();
    // The inner control points are off the curve: check it on a fine sample.
    let on_curve = sample(0.0, 1.0, 4 * SAMPLES, |t| curve.eval(t));
    for p in &points[1..points.len() - 1] {
        let d = on_curve.iter().map(|q| q.distance(*p)).fold(f64::INFINITY, f64::min);
        ensure!(d > 0.1, "control point {p} is on the curve");
    }
    Plot::plane(title)
        .polygon(&points, false)
        .curve(on_curve, Pen::solid(BLUE), Some("Bézier curve"))
        .points(&points, Marker::point(INK), Some("control points"))
        .labels(&points, names("x", points.len()), false)
        .legend(Legend::LowerRight)
        .render()
}

/// Figure 1.3: Hoppe's cactus point set, every point projected; the half nearer the viewer
/// dark, the farther half grey.
fn point_set(title: &str) -> Result<Vec<u8>> {
    let path = crate::project_root().join("fixtures/models").join(HOPPE_POINTS);
    let scan =
        hi_scan::scan::read_scan(&path).with_context(|| format!("reading {HOPPE_POINTS}"))?;
    ensure!(
        scan.points.len() == 3318 && scan.triangles.is_empty(),
        "{HOPPE_POINTS}: {} points and {} triangles, not Hoppe's 3 318 points alone",
        scan.points.len(),
        scan.triangles.len()
    );
    let (sa, ca) = HOPPE_VIEW.azimuth.to_radians().sin_cos();
    let depth = |p: &DVec3| p.x * sa + p.y * ca;
    let mut depths: Vec<f64> = scan.points.iter().map(depth).collect();
    depths.sort_by(f64::total_cmp);
    let middle = depths[depths.len() / 2];
    let (near, far): (Vec<DVec3>, Vec<DVec3>) = scan.points.iter().partition(|p| depth(p) < middle);
    let project = |points: &[DVec3]| -> Vec<DVec2> {
        points.iter().map(|&p| HOPPE_VIEW.project(p)).collect()
    };
    Plot::projection(title)
        .points(&project(&far), Marker::dot(GREY), Some("far half"))
        .points(&project(&near), Marker::dot(BLUE), Some("near half"))
        .legend(Legend::LowerRight)
        .render()
}

/// A bicubic patch over the unit square shifted by `offset`, with the heights `z`.
fn height_patch(offset: DVec3, z: [[f64; 4]; 4]) -> Result<BezierPatch<DVec3>> {
    Ok(BezierPatch::try_from_fn(3, 3, |j, k| {
        offset + DVec3::new(j as f64 / 3.0 * 2.0, k as f64 / 3.0 * 2.0, z[j][k])
    })?)
}

/// `patch` sampled on a grid of `n` × `n` quads, normals from the partial derivatives.
fn patch_mesh(patch: &BezierPatch<DVec3>, n: usize) -> Result<TriangleMesh> {
    let (mut positions, mut normals, mut triangles) = (Vec::new(), Vec::new(), Vec::new());
    for i in 0..=n {
        for j in 0..=n {
            let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
            positions.push(patch.eval(u, v));
            let normal = patch.normal(u, v);
            normals.push(normal.ok_or_else(|| anyhow::anyhow!("degenerate patch at ({u}, {v})"))?);
        }
    }
    let at = |i: usize, j: usize| index(i * (n + 1) + j);
    for i in 0..n {
        for j in 0..n {
            let [a, b, c, d] = [at(i, j)?, at(i + 1, j)?, at(i + 1, j + 1)?, at(i, j + 1)?];
            triangles.extend([[a, b, c], [a, c, d]]);
        }
    }
    mesh(positions, normals, triangles)
}

/// Several meshes as one, vertex `colors` one per mesh.
fn combine(meshes: &[TriangleMesh], colors: &[[f32; 3]]) -> Result<TriangleMesh> {
    let (mut positions, mut normals, mut triangles, mut all_colors) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (m, color) in meshes.iter().zip(colors) {
        let base = index(positions.len())?;
        triangles.extend(m.triangles().iter().map(|t| t.map(|k| k + base)));
        positions.extend_from_slice(m.positions());
        normals.extend_from_slice(m.normals());
        all_colors.extend(std::iter::repeat_n(*color, m.n_vertices()));
    }
    Ok(mesh(positions, normals, triangles)?.try_with_colors(all_colors)?)
}

/// Figure 4.2: two bicubic patches, a dome and a saddle.
fn example_patches() -> Result<Vec<u8>> {
    let dome = height_patch(
        DVec3::new(-2.4, -1.0, 0.0),
        [[0.0, 0.3, 0.3, 0.0], [0.3, 1.4, 1.4, 0.3], [0.3, 1.4, 1.4, 0.3], [0.0, 0.3, 0.3, 0.0]],
    )?;
    let saddle = height_patch(
        DVec3::new(0.4, -1.0, 0.0),
        [
            [0.9, 0.3, 0.3, -0.9],
            [0.3, 0.1, -0.1, -0.3],
            [0.3, 0.1, -0.1, -0.3],
            [-0.9, -0.3, 0.3, 0.9],
        ],
    )?;
    let meshes = [patch_mesh(&dome, PATCH_SAMPLES)?, patch_mesh(&saddle, PATCH_SAMPLES)?];
    glb(&combine(&meshes, &PATCH_COLORS)?)
}

/// Figure 4.3: a torus as the thesis's C0 bicubic patches (§5.7), one colour per patch.
fn piecewise_patches() -> Result<Vec<u8>> {
    let b: SurfaceBezier<DVec3> = torus(2.5, 1.0).to_bezier(
        hi_curve::bezier::BezierScheme::ThesisCubic,
        hi_curve::bezier::DEFAULT_TOLERANCE,
    )?;
    ensure!(b.report.patches == 16, "the 16 patches of the 4×4 grid");
    let all: Vec<usize> = (0..b.patches.len()).collect();
    let m = b.to_triangle_mesh_of(8, &all)?;
    let p = m.positions();
    let centre = p.iter().sum::<DVec3>() / p.len() as f64;
    ensure!(m.colors().is_some(), "the patches are coloured");
    // A torus has no centre outside which all of it faces: check against the tube's circle.
    let outward = m
        .triangles()
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|k| p[k as usize]);
            let mid = (a + b + c) / 3.0 - centre;
            let ring = DVec3::new(mid.x, mid.y, 0.0).normalize_or_zero() * 2.5;
            (b - a).cross(c - a).dot(mid - ring) > 0.0
        })
        .count();
    ensure!(
        outward as f64 > 0.99 * m.triangles().len() as f64,
        "the torus's triangles do not face outwards"
    );
    glb(&m)
}

/// The cubic Bézier triangle of figure 4.4: corners on an equilateral triangle, the edge
/// points raised a little and the centre point (1, 1, 1) raised most.
fn bezier_triangle() -> Result<TriangularPatch<DVec3>> {
    let corners =
        [DVec3::new(2.0, -1.15, 0.0), DVec3::new(0.0, 2.3, 0.0), DVec3::new(-2.0, -1.15, 0.0)];
    Ok(TriangularPatch::try_from_fn(3, |i, j, k| {
        let flat = (i as f64 * corners[0] + j as f64 * corners[1] + k as f64 * corners[2]) / 3.0;
        let height = match (i, j, k) {
            (1, 1, 1) => 1.6,
            _ if i == 3 || j == 3 || k == 3 => 0.0,
            _ => 0.45 + 0.15 * i as f64,
        };
        flat + DVec3::Z * height
    })?)
}

/// Figure 4.4(a): the control net of [`bezier_triangle`], flat shaded.
fn triangle_net() -> Result<Vec<u8>> {
    let patch = bezier_triangle()?;
    let n = patch.degree();
    let x = |i: usize, j: usize| {
        patch.control_point(i, j, n - i - j).ok_or_else(|| anyhow::anyhow!("no point ({i}, {j})"))
    };
    let mut polygons = Vec::new();
    for i in 0..n {
        for j in 0..n - i {
            polygons.push(vec![x(i, j)?, x(i + 1, j)?, x(i, j + 1)?]);
            if i + j + 2 <= n {
                polygons.push(vec![x(i + 1, j)?, x(i + 1, j + 1)?, x(i, j + 1)?]);
            }
        }
    }
    let (net, edges) = flat_with_edges(&polygons)?;
    ensure!(net.n_triangles() == n * n, "the net has n² triangles");
    ensure!(net.normals().iter().all(|v| v.z > 0.0), "the net faces up");
    glb_with_edges(&net, &edges)
}

/// Figure 4.4(b): the surface of [`bezier_triangle`], sampled on a triangular grid.
fn triangle_surface() -> Result<Vec<u8>> {
    let patch = bezier_triangle()?;
    let n = PATCH_SAMPLES;
    let (mut positions, mut normals, mut at) = (Vec::new(), Vec::new(), Vec::new());
    for i in 0..=n {
        at.push(Vec::new());
        for j in 0..=n - i {
            let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
            at[i].push(index(positions.len())?);
            positions.push(patch.eval(u, v));
            normals.push(
                patch.normal(u, v).ok_or_else(|| anyhow::anyhow!("degenerate at ({u}, {v})"))?,
            );
        }
    }
    let mut triangles = Vec::new();
    for i in 0..n {
        for j in 0..n - i {
            triangles.push([at[i][j], at[i + 1][j], at[i][j + 1]]);
            if i + j + 2 <= n {
                triangles.push([at[i + 1][j], at[i + 1][j + 1], at[i][j + 1]]);
            }
        }
    }
    ensure!(normals.iter().all(|v| v.z > 0.0), "the surface faces up");
    glb(&mesh(positions, normals, triangles)?)
}

/// The closed polygon of figures 4.6 and 4.7.
fn stages_polygon() -> Vec<DVec2> {
    data::plane(&data::HEPTAGON)
}

/// Size in pixels of a panel of figures 4.6 and 4.7: smaller than a plane plot on its own, so
/// that the text stays legible when the two by two grid is printed at the width of a page.
const STAGE_PANEL: (u32, u32) = (400, 370);

/// Figures 4.6 and 4.7: the polygon and three steps of `step`, two by two (in one row the
/// four panels would be too small to read on a page).
fn stages(title: &str, step: fn(&[DVec2]) -> Vec<DVec2>) -> Result<Vec<u8>> {
    let polygon = stages_polygon();
    let (w, h) = STAGE_PANEL;
    // Room below the polygon for the legend, in every panel alike.
    let room = [DVec2::new(0.0, -1.2)];
    let mut plots = vec![
        Plot::plane("control polygon")
            .sized(w, h)
            .include(&room)
            .polygon(&polygon, true)
            .points(&polygon, Marker::point(INK), Some("control points"))
            .legend(Legend::LowerRight),
    ];
    let mut current = polygon.clone();
    for k in 1..=3 {
        current = step(&current);
        let mut closed = current.clone();
        closed.push(current[0]);
        let mut plot = Plot::plane(&format!("{k} step{}", if k == 1 { "" } else { "s" }))
            .sized(w, h)
            .include(&room)
            .polygon(&polygon, true)
            .curve(closed, Pen::solid(BLUE), None);
        plot = if k == 1 {
            plot.points(&current, Marker::small(VERMILION), Some("points after the step"))
                .legend(Legend::LowerRight)
        } else {
            plot.points(&current, Marker::small(VERMILION), None)
        };
        plots.push(plot.points(&polygon, Marker::point(INK), None));
    }
    let refs: Vec<&Plot> = plots.iter().collect();
    render_grid(title, &refs, 2)
}

/// One step of Chaikin's scheme on a closed polygon.
fn chaikin(polygon: &[DVec2]) -> Vec<DVec2> {
    chaikin_step(polygon, true)
}

/// One step of the 4-point scheme (w = 1/16) on a closed polygon.
fn four_point(polygon: &[DVec2]) -> Vec<DVec2> {
    four_point_step(polygon, true, DEFAULT_FOUR_POINT_WEIGHT)
}

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (1, 1),
        caption: "An example of a polygonal object",
        drawn: "The control mesh of the head of figure 4.35 (512 triangles on Lee Perry-Smith's head scan), \
                flat shaded (every face keeps its own vertices and one normal), with its edges as a \
                second primitive of lines.",
        data: "stand-in for the thesis's polygonal object (not available): the head control mesh of figure 4.35.",
        format: Format::Glb,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |_| polygonal_object() }],
    },
    Figure {
        number: (1, 2),
        caption: "A Bézier curve does not interpolate all of its control points",
        drawn: "A cubic Bézier curve (de Casteljau, `hi_bezier::BezierCurve`) with its control polygon (dashed) \
                and control points x₀ … x₃, labelled as in the thesis: it passes through x₀ and x₃ only.",
        data: "four control points chosen for the figure (exact).",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: bezier_curve }],
    },
    Figure {
        number: (1, 3),
        caption: "An unorganised set of points provided by Hoppe [35]",
        drawn: "All 3 318 points of Hoppe's cactus, projected orthographically (its arms across the picture, seen \
                a little from above), the half nearer the viewer blue and the farther half grey.",
        data: "Hoppe's own point set: the cactus of Hoppe et al., \"Surface reconstruction from unorganized points\" \
               (1992), `fixtures/models/cactus.pts` (MIT, from his Mesh-processing-library). The thesis does not say \
               which of Hoppe's sets it shows; the mannequin and Spock scans it uses in chapter 5 are not available.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: point_set }],
    },
    Figure {
        number: (4, 2),
        caption: "Example Bézier surface patches",
        drawn: "Two bicubic Bézier patches (`hi_bezier::BezierPatch`), a dome and a saddle, each sampled on a 25×25 \
                grid with normals from the partial derivatives.",
        data: "control points chosen for the figure (exact).",
        format: Format::Glb,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |_| example_patches() }],
    },
    Figure {
        number: (4, 3),
        caption: "A surface constructed from piecewise continuous Bézier patches [13]",
        drawn: "A torus as 16 bicubic Bézier patches joined with C0 continuity (the harmonic torus through a 4×4 grid \
                converted by the thesis's cubic scheme of §5.7), one colour per patch, each sampled 9×9.",
        data: "stand-in for the surface of [13] (not available): the 4×4 torus grid `hi_surface::torus(2.5, 1)`.",
        format: Format::Glb,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |_| piecewise_patches() }],
    },
    Figure {
        number: (4, 4),
        caption: "A Bézier triangle control mesh",
        drawn: "(a) The control net of a cubic Bézier triangle (`hi_bezier::TriangularPatch`): its 10 control points \
                joined into 9 flat triangles, with their edges; (b) the triangle patch it defines, sampled on a triangular grid of \
                24 steps a side.",
        data: "control points chosen for the figure (exact).",
        format: Format::Glb,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) Control mesh", draw: |_| triangle_net() },
            Panel { suffix: "b", title: "(b) Bézier triangle", draw: |_| triangle_surface() },
        ],
    },
    Figure {
        number: (4, 6),
        caption: "Stages in subdivision using Chaikin's scheme",
        drawn: "A closed heptagon (dashed) and the polygons after one, two and three steps of Chaikin's corner \
                cutting (the ¼ and ¾ points of every edge): the old points are cut away.",
        data: "stand-in for the thesis's polygon: the heptagon of figure 3.9.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| stages(t, chaikin) }],
    },
    Figure {
        number: (4, 7),
        caption: "Stages in interpolatory subdivision using the 4-point scheme",
        drawn: "The heptagon of figure 4.6 (dashed) and the polygons after one, two and three steps of the 4-point \
                scheme with w = 1/16: every step keeps the old points and adds one in every edge.",
        data: "stand-in for the thesis's polygon: the heptagon of figure 3.9.",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: |t| stages(t, four_point) }],
    },
];
