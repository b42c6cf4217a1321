// SPDX-License-Identifier: MIT
//! Figures 4.8–4.10, 4.14, 4.18, 4.19, 4.23 and 4.24: the masks (stencils) of the subdivision
//! schemes of §4.5 and how Loop, √3 and Catmull-Clark subdivision split the faces.
//!
//! The weights drawn are read off the library, never typed in. One step of
//! `hi_mesh::subdivision` is linear in the vertex positions, so with x = 1 at one old
//! vertex j and x = 0 at the others (y and z keep the mesh's own coordinates), the x coordinate
//! of every new vertex is the weight of j in that vertex's mask. One step per old vertex gives
//! the whole subdivision matrix ([`Step`]) of a closed mesh: a torus for the regular masks
//! ([`tri_torus`], [`quad_torus`]) and, for a vertex of valence n whose neighbours are regular,
//! a bipyramid after one Loop step or a prism after one Catmull-Clark step ([`cone`]). The new
//! vertex of a mask is found by its connectivity in the refined mesh (an edge point is the new
//! vertex joined to both ends of its edge, a √3 face point the one joined to the three
//! corners, …), and every row drawn is checked, over all old vertices, against the textbook
//! formula computed here ([`loop_beta`], [`butterfly_weights`], [`sqrt3_alpha`],
//! [`labsik_greiner`], the Catmull-Clark rules) to [`TOL`], in the drawing function and in the
//! tests. A weight is written as a fraction when one with a denominator up to 1000 matches it
//! to [`TOL`], otherwise to four decimals.

use std::collections::BTreeSet;
use std::f64::consts::PI;

use anyhow::{Context, Result, bail, ensure};
use glam::{DVec2, DVec3};
use hi_mesh::subdivision::{LoopWeights, PolyMesh, Scheme};

use super::plot::{
    BLUE, GREEN, GREY, INK, Legend, Marker, ORANGE, Pen, Plot, VERMILION, clear_of_point,
    render_row, sub,
};
use super::{Figure, Format, Panel};

/// Largest difference allowed between a weight read off the library and its formula.
const TOL: f64 = 1e-12;

/// Vertices along each direction of the tori.
const TORUS: u32 = 8;

/// Loop with Loop's β, as in the thesis.
const LOOP: Scheme = Scheme::Loop(LoopWeights::Loop);

/// The figures of this module.
pub(crate) const FIGURES: &[Figure] = &[
    Figure {
        number: (4, 8),
        caption: "Notation for Loop subdivision",
        drawn: "(a) a vertex xᵏ of valence n = 6 with its neighbours y₀ᵏ … yₙ₋₁ᵏ; (b) the same fan after one \
                step of `loop_step` (Loop's β), at the positions the library computes: the vertex xᵏ⁺¹ and \
                the edge points x₀ᵏ⁺¹ … xₙ₋₁ᵏ⁺¹ (grey: the boundary vertices and edge points, under the \
                boundary rules).",
        data: "exact",
        format: Format::Svg,
        views: &[],
        panels: &[Panel { suffix: "", title: "", draw: notation }],
    },
    Figure {
        number: (4, 9),
        caption: "Triangle subdivision for Loop subdivision (after [45])",
        drawn: "A hexagon of six triangles of a triangulated torus: (a) the mesh; (b) the new edge points; \
                (c) the triangles of one `loop_step`, each triangle split into four (connectivity from the \
                library; vertices drawn at the old vertices and the edge midpoints).",
        data: "exact",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) the mesh", draw: |t| split(t, SplitKind::Loop, 0) },
            Panel {
                suffix: "b",
                title: "(b) new edge points",
                draw: |t| split(t, SplitKind::Loop, 1),
            },
            Panel {
                suffix: "c",
                title: "(c) after subdivision",
                draw: |t| split(t, SplitKind::Loop, 2),
            },
        ],
    },
    Figure {
        number: (4, 10),
        caption: "Masks for Loop subdivision",
        drawn: "The vertex mask 1 − nβ, β (n = 6 and n = 5, Loop's β = (1/n)(5/8 − (3/8 + ¼cos(2π/n))²), and \
                n = 5 with Warren's β = 3/(8n)), the edge mask 3/8, 3/8, 1/8, 1/8 and the boundary masks of \
                Hoppe et al. (3/4, 1/8, 1/8 and 1/2, 1/2); the red ring is the new point. The weights were \
                read off one step of `hi_mesh::subdivision` (x = 1 at one old vertex of a closed mesh, 0 \
                at the others; the x coordinates of the new vertices are that vertex's weights) and \
                checked to 1e-12 against the formulas; the boundary masks on a flat open patch.",
        data: "exact",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Vertex mask, n = 6",
                draw: |t| draw_mask(t, loop_vertex(LoopWeights::Loop, 6)),
            },
            Panel { suffix: "b", title: "(b) Edge mask", draw: |t| draw_mask(t, loop_edge()) },
            Panel {
                suffix: "c",
                title: "(c) Vertex mask, n = 5 (Loop's β)",
                draw: |t| draw_mask(t, loop_vertex(LoopWeights::Loop, 5)),
            },
            Panel {
                suffix: "d",
                title: "(d) Vertex mask, n = 5 (Warren's β)",
                draw: |t| draw_mask(t, loop_vertex(LoopWeights::Warren, 5)),
            },
            Panel {
                suffix: "e",
                title: "(e) Boundary vertex mask",
                draw: |t| draw_mask(t, loop_boundary(false)),
            },
            Panel {
                suffix: "f",
                title: "(f) Boundary edge mask",
                draw: |t| draw_mask(t, loop_boundary(true)),
            },
        ],
    },
    Figure {
        number: (4, 14),
        caption: "Masks for modified butterfly subdivision (after [1])",
        drawn: "(a) The regular 10-point edge mask of Zorin et al. with tension w = 0 (1/2, 1/8, −1/16; the \
                two outer points weigh w = 0); (b)–(d) the semiregular masks for an end of valence K = 3, \
                4, 5 (3/4 at that end, sⱼ on its neighbours, s₀ on the other end; sⱼ = (1/4 + cos(2πj/K) + \
                ½cos(4πj/K))/K for K ≥ 5); the red ring is the new point. The weights were read off one \
                step of `hi_mesh::subdivision` (x = 1 at one old vertex of a closed mesh, 0 at the \
                others; the x coordinates of the new vertices are that vertex's weights) and checked to \
                1e-12 against the formulas.",
        data: "exact",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Regular setting",
                draw: |t| draw_mask(t, butterfly_regular()),
            },
            Panel {
                suffix: "b",
                title: "(b) Semiregular setting, K = 3",
                draw: |t| draw_mask(t, butterfly_extraordinary(3)),
            },
            Panel {
                suffix: "c",
                title: "(c) Semiregular setting, K = 4",
                draw: |t| draw_mask(t, butterfly_extraordinary(4)),
            },
            Panel {
                suffix: "d",
                title: "(d) Semiregular setting, K = 5",
                draw: |t| draw_mask(t, butterfly_extraordinary(5)),
            },
        ],
    },
    Figure {
        number: (4, 18),
        caption: "Masks for √3 subdivision (after [1])",
        drawn: "Kobbelt's vertex mask 1 − αₙ, αₙ/n with αₙ = (4 − 2cos(2π/n))/9 (n = 6 and n = 5) and the face \
                mask 1/3, 1/3, 1/3; the red ring is the new point. The weights were read off one step of \
                `hi_mesh::subdivision` (x = 1 at one old vertex of a closed mesh, 0 at the others; the x \
                coordinates of the new vertices are that vertex's weights) and checked to 1e-12 against \
                the formulas.",
        data: "exact",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Vertex mask, n = 6",
                draw: |t| draw_mask(t, sqrt3_vertex(6)),
            },
            Panel { suffix: "b", title: "(b) Face mask", draw: |t| draw_mask(t, sqrt3_face()) },
            Panel {
                suffix: "c",
                title: "(c) Vertex mask, n = 5",
                draw: |t| draw_mask(t, sqrt3_vertex(5)),
            },
        ],
    },
    Figure {
        number: (4, 19),
        caption: "Triangle subdivision for √3 subdivision (after [45])",
        drawn: "Triangles of a triangulated torus: (a) the mesh; (b) the new face points; (c) each face point \
                joined to its triangle's corners (drawn here, the library does not stop there); (d) the \
                triangles of one `sqrt3_step`, old edges flipped (dashed: the old mesh): the new mesh is \
                the old one turned by 30° and shrunk by √3. Connectivity from the library; vertices drawn \
                at the old vertices and the face centroids.",
        data: "exact",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel { suffix: "a", title: "(a) the mesh", draw: |t| split(t, SplitKind::Sqrt3, 0) },
            Panel {
                suffix: "b",
                title: "(b) new face points",
                draw: |t| split(t, SplitKind::Sqrt3, 1),
            },
            Panel {
                suffix: "c",
                title: "(c) joined to the corners",
                draw: |t| split(t, SplitKind::Sqrt3, 2),
            },
            Panel {
                suffix: "d",
                title: "(d) old edges flipped",
                draw: |t| split(t, SplitKind::Sqrt3, 3),
            },
        ],
    },
    Figure {
        number: (4, 23),
        caption: "Masks for interpolating √3 subdivision",
        drawn: "(a) The regular 12-point face mask of Labsik and Greiner (32/81 at the corners, −1/81 at the \
                tips of the neighbouring triangles, −2/81 at the other six); (b)–(d) the semiregular masks \
                for a corner of valence K = 3, 4, 5 (K ≥ 5: with a = ⅔cos(π/K), 1 − a² at the corner and \
                (a² + 2a·cos θ + 2a²·cos 2θ)/K on a neighbour at angle θ from the face); the red ring is the \
                new point. The weights were read off one step of `hi_mesh::subdivision` (x = 1 at one \
                old vertex of a closed mesh, 0 at the others; the x coordinates of the new vertices are \
                that vertex's weights) and checked to 1e-12 against the formulas.",
        data: "exact",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) Regular setting",
                draw: |t| draw_mask(t, labsik_greiner_regular()),
            },
            Panel {
                suffix: "b",
                title: "(b) Semiregular setting, K = 3",
                draw: |t| draw_mask(t, labsik_greiner_extraordinary(3)),
            },
            Panel {
                suffix: "c",
                title: "(c) Semiregular setting, K = 4",
                draw: |t| draw_mask(t, labsik_greiner_extraordinary(4)),
            },
            Panel {
                suffix: "d",
                title: "(d) Semiregular setting, K = 5",
                draw: |t| draw_mask(t, labsik_greiner_extraordinary(5)),
            },
        ],
    },
    Figure {
        number: (4, 24),
        caption: "Subdivision for the Catmull-Clark scheme (after [1])",
        drawn: "(a)–(c) Quads of a quad torus, the face, edge and vertex points (drawn at the face centres, \
                edge midpoints and old vertices) and the quads of one `catmull_clark_step` (connectivity \
                from the library); (d)–(g) the masks: face 1/4 each, edge ¼(v + v′ + f + f′) = 3/8, 3/8, \
                1/16 × 4, vertex (n − 2)/n·v + 1/n²·Σeᵢ + 1/n²·Σfᵢ for n = 4, 3, 5; the red ring is the new \
                point. The weights were read off one step of `hi_mesh::subdivision` (x = 1 at one old \
                vertex of a closed mesh, 0 at the others; the x coordinates of the new vertices are that \
                vertex's weights) and checked to 1e-12 against the formulas.",
        data: "exact",
        format: Format::Svg,
        views: &[],
        panels: &[
            Panel {
                suffix: "a",
                title: "(a) the mesh",
                draw: |t| split(t, SplitKind::CatmullClark, 0),
            },
            Panel {
                suffix: "b",
                title: "(b) face, edge and vertex points",
                draw: |t| split(t, SplitKind::CatmullClark, 1),
            },
            Panel {
                suffix: "c",
                title: "(c) new quads",
                draw: |t| split(t, SplitKind::CatmullClark, 2),
            },
            Panel {
                suffix: "d",
                title: "(d) Face mask",
                draw: |t| draw_mask(t, catmull_clark_face()),
            },
            Panel {
                suffix: "e",
                title: "(e) Edge mask",
                draw: |t| draw_mask(t, catmull_clark_edge()),
            },
            Panel {
                suffix: "f",
                title: "(f) Vertex mask, n = 4",
                draw: |t| draw_mask(t, catmull_clark_vertex(4)),
            },
            Panel {
                suffix: "g",
                title: "(g) Vertex mask, n = 3",
                draw: |t| draw_mask(t, catmull_clark_vertex(3)),
            },
            Panel {
                suffix: "h",
                title: "(h) Vertex mask, n = 5",
                draw: |t| draw_mask(t, catmull_clark_vertex(5)),
            },
        ],
    },
];

// ---------------------------------------------------------------------------------------------
// Meshes.

/// A closed mesh and where its vertices are drawn (the torus unrolled about its centre vertex).
#[derive(Clone, Debug)]
struct Sample {
    /// The mesh.
    mesh: PolyMesh,
    /// Plane position of every vertex.
    layout: Vec<DVec2>,
    /// The vertex drawn at the origin.
    centre: u32,
}

impl Sample {
    /// The vertex drawn at `p`.
    fn vertex_at(&self, p: DVec2) -> Result<u32> {
        let found = self.layout.iter().position(|q| q.distance(p) < 1e-9);
        let v = found.with_context(|| format!("no vertex is drawn at {p}"))?;
        Ok(u32::try_from(v)?)
    }
}

/// A point of the torus with radii 3 and 1 at angles 2πi/`n`, 2πj/`n`.
fn torus_point(i: u32, j: u32, n: u32) -> DVec3 {
    let (su, cu) = (2.0 * PI * f64::from(i) / f64::from(n)).sin_cos();
    let (sv, cv) = (2.0 * PI * f64::from(j) / f64::from(n)).sin_cos();
    DVec3::new((3.0 + cv) * cu, (3.0 + cv) * su, sv)
}

/// A [`TORUS`] × [`TORUS`] grid of vertices (i, j) ↦ i + `TORUS`·j on a torus (or, if not
/// `closed`, a flat open patch), with `cell` giving the faces of cell (i, j) and `plane` the
/// drawing position of the offset (i, j) from the centre (`TORUS`/2, `TORUS`/2).
fn grid(
    closed: bool,
    cell: impl Fn(&dyn Fn(u32, u32) -> u32, u32, u32) -> Vec<Vec<u32>>,
    plane: impl Fn(f64, f64) -> DVec2,
) -> Result<Sample> {
    let n = TORUS;
    let idx = |i: u32, j: u32| (i % n) + n * (j % n);
    let mut positions = Vec::new();
    let mut layout = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (di, dj) = (f64::from(i) - f64::from(n / 2), f64::from(j) - f64::from(n / 2));
            let at = plane(di, dj);
            positions.push(if closed { torus_point(i, j, n) } else { at.extend(0.0) });
            layout.push(at);
        }
    }
    let cells = if closed { n } else { n - 1 };
    let mut faces = Vec::new();
    for j in 0..cells {
        for i in 0..cells {
            faces.extend(cell(&idx, i, j));
        }
    }
    let mesh = PolyMesh::try_new(positions, &faces)?;
    Ok(Sample { mesh, layout, centre: idx(n / 2, n / 2) })
}

/// The triangulated torus (every vertex of valence 6), drawn on the triangular lattice; or, if
/// not `closed`, the same triangulation of a flat open patch.
fn tri_grid(closed: bool) -> Result<Sample> {
    grid(
        closed,
        |idx, i, j| {
            vec![
                vec![idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)],
                vec![idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)],
            ]
        },
        |di, dj| DVec2::new(di - dj / 2.0, dj * 3.0_f64.sqrt() / 2.0),
    )
}

/// The triangulated torus: every vertex has valence 6.
fn tri_torus() -> Result<Sample> {
    tri_grid(true)
}

/// The quad torus (every vertex of valence 4), drawn on the square lattice.
fn quad_torus() -> Result<Sample> {
    grid(
        true,
        |idx, i, j| vec![vec![idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]],
        DVec2::new,
    )
}

/// A closed mesh with a vertex of valence `n` (returned) whose faces are triangles with corners
/// of valence 6 (`quads` false: the bipyramid over an n-gon after one Loop step, the vertex its
/// apex) or quads (`quads` true: the prism over an n-gon after one Catmull-Clark step, the
/// vertex the face point of a cap).
fn cone(n: u32, quads: bool) -> Result<(PolyMesh, u32)> {
    let ring = |k: u32| {
        let (s, c) = (2.0 * PI * f64::from(k) / f64::from(n)).sin_cos();
        DVec3::new(c, s, 0.0)
    };
    if quads {
        let mut positions: Vec<DVec3> = (0..n).map(ring).collect();
        positions.extend((0..n).map(|k| ring(k) + DVec3::Z));
        let mut faces: Vec<Vec<u32>> = vec![(0..n).rev().collect(), (n..2 * n).collect()];
        for k in 0..n {
            let l = (k + 1) % n;
            faces.push(vec![k, l, n + l, n + k]);
        }
        let mesh = Scheme::CatmullClark.step(&PolyMesh::try_new(positions, &faces)?)?;
        let v = (2 * n as usize..mesh.n_vertices())
            .find(|&v| {
                mesh.valence(v) == n as usize
                    && mesh.faces().filter(|f| f.contains(&(v as u32))).all(|f| f.len() == 4)
            })
            .context("the refined prism has no vertex of valence n")?;
        Ok((mesh, u32::try_from(v)?))
    } else {
        let mut positions = vec![DVec3::Z, -DVec3::Z];
        positions.extend((0..n).map(ring));
        let mut faces = Vec::new();
        for k in 0..n {
            let l = (k + 1) % n;
            faces.push([2 + k, 2 + l, 0]);
            faces.push([2 + l, 2 + k, 1]);
        }
        let mesh = LOOP.step(&PolyMesh::try_new(positions, &faces)?)?;
        let ring_ok = mesh.neighbors(0).iter().all(|&r| mesh.valence(r as usize) == 6);
        ensure!(
            mesh.valence(0) == n as usize && ring_ok,
            "the refined bipyramid is not as expected"
        );
        Ok((mesh, 0))
    }
}

// ---------------------------------------------------------------------------------------------
// Reading the weights off the library.

/// One step of a scheme on a mesh and its subdivision matrix.
#[derive(Clone, Debug)]
struct Step {
    /// The number of old vertices.
    n_old: usize,
    /// The refined mesh of the unperturbed step.
    refined: PolyMesh,
    /// `rows[i][j]`: the weight of old vertex j in new vertex i.
    rows: Vec<Vec<f64>>,
}

impl Step {
    /// Applies `scheme` once to `mesh` and once more per old vertex j, with x = 1 at j and
    /// x = 0 elsewhere, reading the weights of j off the new x coordinates.
    fn new(scheme: Scheme, mesh: &PolyMesh) -> Result<Self> {
        let refined = scheme.step(mesh)?;
        let faces: Vec<Vec<u32>> = mesh.faces().map(<[u32]>::to_vec).collect();
        let n_old = mesh.n_vertices();
        let mut rows = vec![vec![0.0; n_old]; refined.n_vertices()];
        for j in 0..n_old {
            let positions = mesh
                .positions()
                .iter()
                .enumerate()
                .map(|(i, p)| DVec3::new(if i == j { 1.0 } else { 0.0 }, p.y, p.z))
                .collect();
            let impulse = scheme.step(&PolyMesh::try_new(positions, &faces)?)?;
            ensure!(
                impulse.n_vertices() == refined.n_vertices() && impulse.faces().eq(refined.faces()),
                "{}: the refined connectivity depends on the positions",
                scheme.name()
            );
            for (row, p) in rows.iter_mut().zip(impulse.positions()) {
                row[j] = p.x;
            }
        }
        Ok(Self { n_old, refined, rows })
    }

    /// The new vertex joined by an edge to every old vertex of `olds` (an edge point, a √3 face
    /// point).
    fn joined_to(&self, olds: &[u32]) -> Result<usize> {
        let found: Vec<usize> = (self.n_old..self.refined.n_vertices())
            .filter(|&w| {
                let ring = self.refined.neighbors(w);
                olds.iter().all(|o| ring.contains(o))
            })
            .collect();
        match found[..] {
            [w] => Ok(w),
            _ => bail!("{} new vertices are joined to {olds:?}", found.len()),
        }
    }

    /// The new vertex that shares a refined face with every old vertex of `corners` (the
    /// Catmull-Clark face point).
    fn in_faces_with(&self, corners: &[u32]) -> Result<usize> {
        let found: Vec<usize> = (self.n_old..self.refined.n_vertices())
            .filter(|&w| {
                corners
                    .iter()
                    .all(|c| self.refined.faces().any(|f| f.contains(c) && f.contains(&(w as u32))))
            })
            .collect();
        match found[..] {
            [w] => Ok(w),
            _ => bail!("{} new vertices share faces with {corners:?}", found.len()),
        }
    }

    /// The new position of old vertex `v` (it keeps its index), checked to keep its valence.
    fn vertex_point(&self, mesh: &PolyMesh, v: u32) -> Result<usize> {
        let v = v as usize;
        ensure!(
            self.refined.valence(v) == mesh.valence(v),
            "vertex {v} changed its valence: it is not the vertex point"
        );
        Ok(v)
    }
}

/// A mask ready to draw: the old vertices of its stencil, where they are drawn and their
/// weights as read off the library, the mesh edges between them and the new point.
#[derive(Clone, Debug)]
struct Mask {
    /// Drawing positions of the stencil's vertices.
    at: Vec<DVec2>,
    /// Their weights, read off the library.
    weights: Vec<f64>,
    /// Mesh edges between stencil vertices.
    edges: Vec<[DVec2; 2]>,
    /// Where the new point is drawn.
    new_point: DVec2,
}

/// The mask of new vertex `new` of `step`: checks every old vertex's weight against
/// `expected` (stencil vertex, drawing position, formula weight; vertices not listed must weigh
/// 0) and keeps the listed vertices for drawing.
fn mask(
    step: &Step,
    mesh: &PolyMesh,
    new: usize,
    expected: &[(u32, DVec2, f64)],
    new_point: DVec2,
    what: &str,
) -> Result<Mask> {
    let row = &step.rows[new];
    for (j, &got) in row.iter().enumerate() {
        let listed: Vec<f64> = expected.iter().filter(|e| e.0 as usize == j).map(|e| e.2).collect();
        ensure!(listed.len() <= 1, "{what}: vertex {j} is listed twice");
        let want = listed.first().copied().unwrap_or(0.0);
        ensure!(
            (got - want).abs() <= TOL,
            "{what}: old vertex {j} weighs {got} in the library, {want} by the formula"
        );
    }
    let mut edges = Vec::new();
    for (a, pa, _) in expected {
        let ring = mesh.neighbors(*a as usize);
        for (b, pb, _) in expected {
            if a < b && ring.contains(b) {
                edges.push([*pa, *pb]);
            }
        }
    }
    Ok(Mask {
        at: expected.iter().map(|e| e.1).collect(),
        weights: expected.iter().map(|e| row[e.0 as usize]).collect(),
        edges,
        new_point,
    })
}

/// The neighbours of `v` (counter-clockwise) on the unit circle, the first at angle 0.
fn ring_layout(mesh: &PolyMesh, v: u32) -> Vec<(u32, DVec2)> {
    let ring = mesh.neighbors(v as usize);
    let n = ring.len() as f64;
    ring.iter()
        .enumerate()
        .map(|(i, &r)| {
            let (s, c) = (2.0 * PI * i as f64 / n).sin_cos();
            (r, DVec2::new(c, s))
        })
        .collect()
}

// ---------------------------------------------------------------------------------------------
// The textbook formulas.

/// β of the Loop vertex mask for valence n: Loop's (1/n)(5/8 − (3 + 2cos(2π/n))²/64), or
/// Warren's 3/(8n) (3/16 for n = 3).
fn loop_beta(weights: LoopWeights, n: u32) -> f64 {
    let n = f64::from(n);
    match weights {
        LoopWeights::Loop => {
            let c = 3.0 + 2.0 * (2.0 * PI / n).cos();
            (5.0 / 8.0 - c * c / 64.0) / n
        }
        LoopWeights::Warren if n == 3.0 => 3.0 / 16.0,
        LoopWeights::Warren => 3.0 / (8.0 * n),
    }
}

/// Zorin et al.'s weights s₀ … s_{K−1} of the neighbours of an end of valence K ≠ 6, s₀ at the
/// other end of the edge (the end itself weighs 3/4).
fn butterfly_weights(k: u32) -> Vec<f64> {
    match k {
        3 => vec![5.0 / 12.0, -1.0 / 12.0, -1.0 / 12.0],
        4 => vec![3.0 / 8.0, 0.0, -1.0 / 8.0, 0.0],
        _ => (0..k)
            .map(|j| {
                let t = 2.0 * PI * f64::from(j) / f64::from(k);
                (0.25 + t.cos() + 0.5 * (2.0 * t).cos()) / f64::from(k)
            })
            .collect(),
    }
}

/// Kobbelt's αₙ = (4 − 2cos(2π/n))/9.
fn sqrt3_alpha(n: u32) -> f64 {
    (4.0 - 2.0 * (2.0 * PI / f64::from(n)).cos()) / 9.0
}

/// Labsik and Greiner's semiregular mask for a corner of valence K: the corner's weight, and
/// the weight of a neighbour at angle θ from the bisector of the face (θ = ±π/K for the other
/// two corners). K = 3: 8/9, and 4/27 for the face's corners, −5/27 for the third neighbour;
/// K = 4: 7/9, 2/9 and −1/9; K ≥ 5: with a = ⅔cos(π/K), 1 − a² and
/// (a² + 2a·cos θ + 2a²·cos 2θ)/K.
fn labsik_greiner(k: u32, theta: f64) -> (f64, f64) {
    let near_face = theta.cos() > (PI / f64::from(k)).cos() - 1e-9;
    match k {
        3 => (8.0 / 9.0, if near_face { 4.0 / 27.0 } else { -5.0 / 27.0 }),
        4 => (7.0 / 9.0, if near_face { 2.0 / 9.0 } else { -1.0 / 9.0 }),
        _ => {
            let a = 2.0 * (PI / f64::from(k)).cos() / 3.0;
            let w =
                (a * a + 2.0 * a * theta.cos() + 2.0 * a * a * (2.0 * theta).cos()) / f64::from(k);
            (1.0 - a * a, w)
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The masks.

/// Loop's vertex mask for valence `n` with `weights`.
fn loop_vertex(weights: LoopWeights, n: u32) -> Result<Mask> {
    let (mesh, v) = if n == 6 {
        let s = tri_torus()?;
        (s.mesh, s.centre)
    } else {
        cone(n, false)?
    };
    let step = Step::new(Scheme::Loop(weights), &mesh)?;
    let new = step.vertex_point(&mesh, v)?;
    let beta = loop_beta(weights, n);
    let mut expected = vec![(v, DVec2::ZERO, 1.0 - f64::from(n) * beta)];
    expected.extend(ring_layout(&mesh, v).into_iter().map(|(r, p)| (r, p, beta)));
    mask(&step, &mesh, new, &expected, DVec2::ZERO, &format!("Loop vertex mask, n = {n}"))
}

/// Loop's edge mask, on the torus.
fn loop_edge() -> Result<Mask> {
    let s = tri_torus()?;
    let h = 3.0_f64.sqrt() / 2.0;
    let spec = [
        ((0.0, 0.0), 3.0 / 8.0),
        ((1.0, 0.0), 3.0 / 8.0),
        ((0.5, h), 1.0 / 8.0),
        ((0.5, -h), 1.0 / 8.0),
    ];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(LOOP, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, 0.0), "Loop edge mask")
}

/// Loop's boundary masks (Hoppe et al. 1994) on a flat open patch: the vertex mask 3/4, 1/8,
/// 1/8 (the interior neighbours weigh 0), or, if `edge`, the edge mask 1/2, 1/2 (the opposite
/// vertex weighs 0).
fn loop_boundary(edge: bool) -> Result<Mask> {
    let s = tri_grid(false)?;
    let y = -f64::from(TORUS / 2) * 3.0_f64.sqrt() / 2.0;
    let h = 3.0_f64.sqrt() / 2.0;
    let x0 = -y / 3.0_f64.sqrt();
    let spec: Vec<((f64, f64), f64)> = if edge {
        vec![((x0, y), 0.5), ((x0 + 1.0, y), 0.5), ((x0 + 0.5, y + h), 0.0)]
    } else {
        vec![
            ((x0, y), 0.75),
            ((x0 - 1.0, y), 0.125),
            ((x0 + 1.0, y), 0.125),
            ((x0 - 0.5, y + h), 0.0),
            ((x0 + 0.5, y + h), 0.0),
        ]
    };
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(LOOP, &s.mesh)?;
    ensure!(
        s.mesh.is_boundary_vertex(expected[0].0 as usize),
        "the patch's vertex is not on the boundary"
    );
    let (new, new_point) = if edge {
        (step.joined_to(&[expected[0].0, expected[1].0])?, DVec2::new(x0 + 0.5, y))
    } else {
        (step.vertex_point(&s.mesh, expected[0].0)?, DVec2::new(x0, y))
    };
    mask(&step, &s.mesh, new, &expected, new_point, "Loop boundary mask")
}

/// The stencil vertices drawn at the given layout positions, with their weights.
fn at_layout(s: &Sample, spec: &[((f64, f64), f64)]) -> Result<Vec<(u32, DVec2, f64)>> {
    spec.iter()
        .map(|&((x, y), w)| {
            let p = DVec2::new(x, y);
            Ok((s.vertex_at(p)?, p, w))
        })
        .collect()
}

/// The regular 10-point butterfly mask (tension w = 0) on the torus.
fn butterfly_regular() -> Result<Mask> {
    let s = tri_torus()?;
    let h = 3.0_f64.sqrt() / 2.0;
    let e = -1.0 / 16.0;
    let spec = [
        ((0.0, 0.0), 0.5),
        ((1.0, 0.0), 0.5),
        ((0.5, h), 1.0 / 8.0),
        ((0.5, -h), 1.0 / 8.0),
        ((-0.5, h), e),
        ((1.5, h), e),
        ((-0.5, -h), e),
        ((1.5, -h), e),
        ((-1.0, 0.0), 0.0),
        ((2.0, 0.0), 0.0),
    ];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(Scheme::Butterfly, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, 0.0), "regular butterfly mask")
}

/// The butterfly mask of an edge from a vertex of valence `k` ≠ 6 to a regular one.
fn butterfly_extraordinary(k: u32) -> Result<Mask> {
    let (mesh, v) = cone(k, false)?;
    let ring = ring_layout(&mesh, v);
    let s = butterfly_weights(k);
    let step = Step::new(Scheme::Butterfly, &mesh)?;
    let new = step.joined_to(&[v, ring[0].0])?;
    let mut expected = vec![(v, DVec2::ZERO, 0.75)];
    expected.extend(ring.iter().zip(&s).map(|(&(r, p), &w)| (r, p, w)));
    mask(&step, &mesh, new, &expected, ring[0].1 / 2.0, &format!("butterfly mask, K = {k}"))
}

/// Kobbelt's √3 vertex mask for valence `n`.
fn sqrt3_vertex(n: u32) -> Result<Mask> {
    let (mesh, v) = if n == 6 {
        let s = tri_torus()?;
        (s.mesh, s.centre)
    } else {
        cone(n, false)?
    };
    let step = Step::new(Scheme::Sqrt3, &mesh)?;
    let new = step.vertex_point(&mesh, v)?;
    let alpha = sqrt3_alpha(n);
    let mut expected = vec![(v, DVec2::ZERO, 1.0 - alpha)];
    expected.extend(ring_layout(&mesh, v).into_iter().map(|(r, p)| (r, p, alpha / f64::from(n))));
    mask(&step, &mesh, new, &expected, DVec2::ZERO, &format!("√3 vertex mask, n = {n}"))
}

/// Kobbelt's √3 face mask, on the torus.
fn sqrt3_face() -> Result<Mask> {
    let s = tri_torus()?;
    let h = 3.0_f64.sqrt() / 2.0;
    let third = 1.0 / 3.0;
    let expected = at_layout(&s, &[((0.0, 0.0), third), ((1.0, 0.0), third), ((0.5, h), third)])?;
    let step = Step::new(Scheme::Sqrt3, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0, expected[2].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, h / 3.0), "√3 face mask")
}

/// The regular 12-point mask of Labsik and Greiner, on the torus.
fn labsik_greiner_regular() -> Result<Mask> {
    let s = tri_torus()?;
    let h = 3.0_f64.sqrt() / 2.0;
    let (corner, tip, other) = (32.0 / 81.0, -1.0 / 81.0, -2.0 / 81.0);
    let spec = [
        ((0.0, 0.0), corner),
        ((1.0, 0.0), corner),
        ((0.5, h), corner),
        ((0.5, -h), tip),
        ((1.5, h), tip),
        ((-0.5, h), tip),
        ((-1.0, 0.0), other),
        ((-0.5, -h), other),
        ((2.0, 0.0), other),
        ((1.5, -h), other),
        ((1.0, 2.0 * h), other),
        ((0.0, 2.0 * h), other),
    ];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(Scheme::InterpolatingSqrt3, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0, expected[2].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, h / 3.0), "regular interpolating √3 mask")
}

/// The Labsik–Greiner mask of a face with one corner of valence `k` ≠ 6.
fn labsik_greiner_extraordinary(k: u32) -> Result<Mask> {
    let (mesh, v) = cone(k, false)?;
    let ring = ring_layout(&mesh, v);
    let step = Step::new(Scheme::InterpolatingSqrt3, &mesh)?;
    let new = step.joined_to(&[v, ring[0].0, ring[1].0])?;
    // The face (v, r₀, r₁) lies about the direction π/K.
    let bisector = PI / f64::from(k);
    let mut expected = vec![(v, DVec2::ZERO, labsik_greiner(k, 0.0).0)];
    expected
        .extend(ring.iter().map(|&(r, p)| (r, p, labsik_greiner(k, p.y.atan2(p.x) - bisector).1)));
    let new_point = (ring[0].1 + ring[1].1) / 3.0;
    mask(&step, &mesh, new, &expected, new_point, &format!("interpolating √3 mask, K = {k}"))
}

/// The Catmull-Clark face mask of a quad of the torus.
fn catmull_clark_face() -> Result<Mask> {
    let s = quad_torus()?;
    let spec = [((0.0, 0.0), 0.25), ((1.0, 0.0), 0.25), ((1.0, 1.0), 0.25), ((0.0, 1.0), 0.25)];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(Scheme::CatmullClark, &s.mesh)?;
    let corners: Vec<u32> = expected.iter().map(|e| e.0).collect();
    let new = step.in_faces_with(&corners)?;
    mask(&step, &s.mesh, new, &expected, DVec2::splat(0.5), "Catmull-Clark face mask")
}

/// The Catmull-Clark edge mask ¼(v + v′ + f + f′) on the torus: 3/8 at the ends, 1/16 at the
/// other corners of the two quads.
fn catmull_clark_edge() -> Result<Mask> {
    let s = quad_torus()?;
    let o = 1.0 / 16.0;
    let spec = [
        ((0.0, 0.0), 0.375),
        ((1.0, 0.0), 0.375),
        ((0.0, 1.0), o),
        ((1.0, 1.0), o),
        ((0.0, -1.0), o),
        ((1.0, -1.0), o),
    ];
    let expected = at_layout(&s, &spec)?;
    let step = Step::new(Scheme::CatmullClark, &s.mesh)?;
    let new = step.joined_to(&[expected[0].0, expected[1].0])?;
    mask(&step, &s.mesh, new, &expected, DVec2::new(0.5, 0.0), "Catmull-Clark edge mask")
}

/// The Catmull-Clark vertex mask (n − 2)/n·v + 1/n²·Σeᵢ + 1/n²·Σfᵢ for valence `n` among
/// quads: v weighs (n − 2)/n + 1/(4n), an edge neighbour 3/(2n²), a diagonal one 1/(4n²).
fn catmull_clark_vertex(n: u32) -> Result<Mask> {
    let (mesh, v) = if n == 4 {
        let s = quad_torus()?;
        (s.mesh, s.centre)
    } else {
        cone(n, true)?
    };
    let nf = f64::from(n);
    let ring = ring_layout(&mesh, v);
    let mut expected = vec![(v, DVec2::ZERO, (nf - 2.0) / nf + 1.0 / (4.0 * nf))];
    for (i, &(e, p)) in ring.iter().enumerate() {
        expected.push((e, p, 3.0 / (2.0 * nf * nf)));
        let (e2, p2) = ring[(i + 1) % ring.len()];
        let quad = mesh
            .faces()
            .find(|f| f.len() == 4 && f.contains(&v) && f.contains(&e) && f.contains(&e2))
            .context("no quad between two neighbours")?;
        let at = quad.iter().position(|&c| c == v).context("the quad lost its corner")?;
        expected.push((quad[(at + 2) % 4], p + p2, 1.0 / (4.0 * nf * nf)));
    }
    let step = Step::new(Scheme::CatmullClark, &mesh)?;
    let new = step.vertex_point(&mesh, v)?;
    mask(&step, &mesh, new, &expected, DVec2::ZERO, &format!("Catmull-Clark vertex mask, n = {n}"))
}

// ---------------------------------------------------------------------------------------------
// Drawing.

/// `w` as a fraction p/q (q ≤ 1000) if one matches it to [`TOL`], otherwise to four decimals;
/// a minus sign for negative values.
fn fraction(w: f64) -> String {
    let text = (1..=1000_u32)
        .find_map(|q| {
            let p = (w * f64::from(q)).round();
            ((w - p / f64::from(q)).abs() <= TOL)
                .then(|| if q == 1 { format!("{}", p.abs()) } else { format!("{}/{q}", p.abs()) })
        })
        .unwrap_or_else(|| format!("{:.4}", w.abs()));
    if w < 0.0 && text != "0" { format!("−{text}") } else { text }
}

/// Draws a mask: the stencil's edges and vertices, the new point ringed in red, each weight
/// beside its vertex (blue, red if negative, grey if zero).
fn draw_mask(title: &str, mask: Result<Mask>) -> Result<Vec<u8>> {
    let mask = mask?;
    let mut plot = Plot::projection(title);
    for [a, b] in &mask.edges {
        plot = plot.curve(vec![*a, *b], Pen::solid(GREY).width(1.0), None);
    }
    plot = plot.points(&mask.at, Marker::point(INK), None).points(
        &[mask.new_point],
        Marker::ring(VERMILION),
        None,
    );
    let centre = mask.at.iter().sum::<DVec2>() / mask.at.len() as f64;
    for (p, &w) in mask.at.iter().zip(&mask.weights) {
        let text = fraction(w);
        // Outward from the stencil's centre (up and right for the centre itself), clear of
        // the vertex's marker (y up here, down on the screen).
        let size = mask.at.iter().map(|q| q.distance(centre)).fold(0.0, f64::max);
        let away = *p - centre;
        let offset = if away.length() > 1e-6 * size {
            let d = away.normalize();
            let off = clear_of_point(DVec2::new(d.x, -d.y), text.chars().count());
            (off.x, -off.y)
        } else {
            // The centre: inside the widest angle between its edges, clear of both.
            let (d, half_angle) = widest_gap(&mask.edges, *p);
            let off = d * inside_wedge(d, half_angle, text.chars().count());
            (off.x, off.y)
        };
        let color = if w.abs() <= TOL {
            GREY
        } else if w < 0.0 {
            VERMILION
        } else {
            BLUE
        };
        plot = plot.note(*p, &text, offset, color);
    }
    plot.render()
}

/// The direction from `p` into the widest angle between the edges of `edges` that end at
/// `p`, and half that angle (up and right, a right angle, if no edge does): where a label at
/// `p` crosses no edge.
fn widest_gap(edges: &[[DVec2; 2]], p: DVec2) -> (DVec2, f64) {
    let mut angles: Vec<f64> = edges
        .iter()
        .filter_map(|[a, b]| {
            let scale = 1e-9 * (1.0 + a.length() + b.length());
            if a.distance(p) < scale {
                Some(*b - p)
            } else if b.distance(p) < scale {
                Some(*a - p)
            } else {
                None
            }
        })
        .map(|d| d.y.atan2(d.x))
        .collect();
    angles.sort_by(f64::total_cmp);
    let Some(&first) = angles.first() else { return (DVec2::new(0.6, 0.8), 0.5 * PI) };
    let mut best = (0.0, 0.0);
    for (k, &a) in angles.iter().enumerate() {
        let next = angles.get(k + 1).copied().unwrap_or(first + 2.0 * PI);
        if next - a > best.0 {
            best = (next - a, a + 0.5 * (next - a));
        }
    }
    (DVec2::from_angle(best.1), 0.5 * best.0)
}

/// How far in pixels along `dir` (y up) a label of `chars` characters goes so that its box
/// (as in [`clear_of_point`]) lies inside the wedge of half-angle `half_angle` about `dir`.
fn inside_wedge(dir: DVec2, half_angle: f64, chars: usize) -> f64 {
    let (half_w, half_h) = (3.75 * chars as f64 + 2.0, 8.0);
    let tan = half_angle.min(0.49 * PI).tan();
    let fits = |s: f64| {
        [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)].iter().all(|&(a, b)| {
            let corner = dir * s + DVec2::new(a * half_w, b * half_h);
            corner.dot(dir) > 0.0 && corner.perp_dot(dir).abs() <= tan * corner.dot(dir)
        })
    };
    let start = clear_of_point(dir, chars).length();
    (0..200).map(|k| start + 0.5 * f64::from(k)).find(|&s| fits(s)).unwrap_or(start + 100.0)
}

/// Figure 4.8: the notation of Loop subdivision, before and after one step on a fan of n = 6
/// triangles.
fn notation(title: &str) -> Result<Vec<u8>> {
    const N: u32 = 6;
    let mut positions = vec![DVec3::ZERO];
    positions.extend((0..N).map(|k| {
        let (s, c) = (2.0 * PI * f64::from(k) / f64::from(N)).sin_cos();
        DVec3::new(c, s, 0.0)
    }));
    let faces: Vec<[u32; 3]> = (0..N).map(|k| [0, 1 + k, 1 + (k + 1) % N]).collect();
    let fan = PolyMesh::try_new(positions, &faces)?;
    let refined = LOOP.step(&fan)?;
    let step = Step { n_old: fan.n_vertices(), refined: refined.clone(), rows: Vec::new() };
    let flat = |p: &DVec3| p.truncate();
    let ring_name = |base: &str, k: u32, sup: &str| {
        if k == N - 1 {
            format!("{base}ₙ₋₁{sup}")
        } else {
            format!("{}{sup}", sub(base, k as usize))
        }
    };

    let old: Vec<DVec2> = fan.positions().iter().map(flat).collect();
    let mut before = Plot::projection("(a) xᵏ and its neighbours yᵢᵏ");
    for [a, b] in edges(fan.faces()) {
        before =
            before.curve(vec![old[a as usize], old[b as usize]], Pen::solid(GREY).width(1.0), None);
    }
    before = before.points(&old, Marker::point(INK), None).note(old[0], "xᵏ", (14.0, 12.0), INK);
    for k in 0..N {
        let p = old[1 + k as usize];
        before = before.note(p, &ring_name("y", k, "ᵏ"), (22.0 * p.x, 18.0 * p.y), INK);
    }

    let new: Vec<DVec2> = refined.positions().iter().map(flat).collect();
    let mut after = Plot::projection("(b) after one step: xᵏ⁺¹ and the edge points xᵢᵏ⁺¹");
    for [a, b] in edges(refined.faces()) {
        after =
            after.curve(vec![new[a as usize], new[b as usize]], Pen::solid(GREY).width(1.0), None);
    }
    let mut named = vec![new[0]];
    after = after.note(new[0], "xᵏ⁺¹", (16.0, 12.0), VERMILION);
    for k in 0..N {
        let e = step.joined_to(&[0, 1 + k])?;
        let p = new[e];
        named.push(p);
        // Between the spoke through the point and the next (the spoke itself runs on outward).
        let d = DVec2::from_angle(PI / f64::from(N)).rotate(p.normalize_or_zero());
        let name = ring_name("x", k, "ᵏ⁺¹");
        let off = clear_of_point(DVec2::new(d.x, -d.y), name.chars().count());
        after = after.note(p, &name, (off.x, -off.y), VERMILION);
    }
    let others: Vec<DVec2> =
        new.iter().copied().filter(|p| !named.iter().any(|q| q.distance(*p) < 1e-12)).collect();
    after = after.points(&others, Marker::small(GREY), None).points(
        &named,
        Marker::point(VERMILION),
        None,
    );
    render_row(title, &[&before, &after])
}

/// The undirected edges of `faces`, sorted.
fn edges<'a>(faces: impl Iterator<Item = &'a [u32]>) -> BTreeSet<[u32; 2]> {
    let mut set = BTreeSet::new();
    for f in faces {
        for (i, &a) in f.iter().enumerate() {
            let b = f[(i + 1) % f.len()];
            set.insert([a.min(b), a.max(b)]);
        }
    }
    set
}

/// Which face split [`split`] draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SplitKind {
    /// Loop's 1 → 4 split (figure 4.9).
    Loop,
    /// The √3 split and flip (figure 4.19).
    Sqrt3,
    /// Catmull-Clark's split of each k-gon into k quads (figure 4.24).
    CatmullClark,
}

/// Stage `stage` of the face split of figures 4.9, 4.19 and 4.24 on a window of a torus: 0 the
/// mesh, 1 with the new points, then (√3) the face points joined to the corners and the
/// library's refined mesh, or (Loop, Catmull-Clark) the library's refined mesh.
fn split(title: &str, kind: SplitKind, stage: u32) -> Result<Vec<u8>> {
    let (sample, scheme, radius) = match kind {
        SplitKind::Loop => (tri_torus()?, LOOP, 1.0),
        SplitKind::Sqrt3 => (tri_torus()?, Scheme::Sqrt3, 2.0),
        SplitKind::CatmullClark => (quad_torus()?, Scheme::CatmullClark, 2.0_f64.sqrt()),
    };
    let mesh = &sample.mesh;
    let inside = |v: u32| sample.layout[v as usize].length() <= radius + 1e-9;
    let window: Vec<Vec<u32>> =
        mesh.faces().filter(|f| f.iter().all(|&v| inside(v))).map(<[u32]>::to_vec).collect();
    let step = Step { n_old: mesh.n_vertices(), refined: scheme.step(mesh)?, rows: Vec::new() };
    let old_edges = edges(window.iter().map(Vec::as_slice));

    // The new vertices of the window and where they are drawn.
    let (face_points, edge_points) =
        split_points(kind, &sample.layout, &window, &old_edges, &step)?;
    let old_vertices: BTreeSet<u32> = window.iter().flatten().copied().collect();
    let mut drawn_at = vec![None; step.refined.n_vertices()];
    for &v in &old_vertices {
        drawn_at[v as usize] = Some(sample.layout[v as usize]);
    }
    for &(w, p) in face_points.iter().chain(&edge_points) {
        drawn_at[w] = Some(p);
    }

    let old_at: Vec<DVec2> = old_vertices.iter().map(|&v| sample.layout[v as usize]).collect();
    let face_at: Vec<DVec2> = face_points.iter().map(|f| f.1).collect();
    let edge_at: Vec<DVec2> = edge_points.iter().map(|e| e.1).collect();
    let segment = |[a, b]: [u32; 2], at: &dyn Fn(u32) -> Option<DVec2>| -> Option<Vec<DVec2>> {
        Some(vec![at(a)?, at(b)?])
    };
    let old_pos = |v: u32| Some(sample.layout[v as usize]);
    let new_pos = |v: u32| drawn_at[v as usize];
    let mut plot = Plot::projection(title);
    let last = if kind == SplitKind::Sqrt3 { 3 } else { 2 };
    if stage < last {
        for e in &old_edges {
            plot = plot.curve(
                segment(*e, &old_pos).context("an old edge")?,
                Pen::solid(INK).width(1.0),
                None,
            );
        }
    }
    if kind == SplitKind::Sqrt3 && stage == 2 {
        plot = sqrt3_joins(plot, &face_points, &window, &sample.layout);
    }
    if stage == last {
        if kind == SplitKind::Sqrt3 {
            for e in &old_edges {
                plot = plot.polygon(&segment(*e, &old_pos).context("an old edge")?, false);
            }
        }
        let kept =
            step.refined.faces().filter(|f| f.iter().all(|&v| drawn_at[v as usize].is_some()));
        for e in edges(kept) {
            plot = plot.curve(
                segment(e, &new_pos).context("a new edge")?,
                Pen::solid(BLUE).width(1.0),
                None,
            );
        }
    }
    plot = plot.points(&old_at, Marker::point(INK), None);
    if stage >= 1 {
        plot = split_markers(plot, kind, &old_at, &face_at, &edge_at);
    }
    plot.render()
}

/// New vertices of the refined mesh, each with where [`split`] draws it.
type Placed = Vec<(usize, DVec2)>;

/// The new points of [`split`] in the `window` of faces of a mesh drawn at `layout`, each
/// with where it is drawn: the face points (√3, Catmull-Clark) at their face's centroid, and
/// the edge points (Loop, Catmull-Clark) at the midpoints of the `old_edges`.
fn split_points(
    kind: SplitKind,
    layout: &[DVec2],
    window: &[Vec<u32>],
    old_edges: &BTreeSet<[u32; 2]>,
    step: &Step,
) -> Result<(Placed, Placed)> {
    let mut face_points = Vec::new();
    let mut edge_points = Vec::new();
    for f in window {
        let centroid = f.iter().map(|&v| layout[v as usize]).sum::<DVec2>() / f.len() as f64;
        match kind {
            SplitKind::Loop => {}
            SplitKind::Sqrt3 => face_points.push((step.joined_to(f)?, centroid)),
            SplitKind::CatmullClark => face_points.push((step.in_faces_with(f)?, centroid)),
        }
    }
    if kind != SplitKind::Sqrt3 {
        for [a, b] in old_edges {
            let mid = (layout[*a as usize] + layout[*b as usize]) / 2.0;
            edge_points.push((step.joined_to(&[*a, *b])?, mid));
        }
    }
    Ok((face_points, edge_points))
}

/// `plot` with each √3 face point joined to the corners of its face of the `window` (drawn
/// at `layout`).
fn sqrt3_joins(
    mut plot: Plot,
    face_points: &[(usize, DVec2)],
    window: &[Vec<u32>],
    layout: &[DVec2],
) -> Plot {
    for &(_, c) in face_points {
        for f in window {
            let centroid = f.iter().map(|&v| layout[v as usize]).sum::<DVec2>() / 3.0;
            if centroid.distance(c) < 1e-12 {
                for &v in f {
                    plot = plot.curve(
                        vec![c, layout[v as usize]],
                        Pen::solid(BLUE).width(1.0),
                        None,
                    );
                }
            }
        }
    }
    plot
}

/// `plot` with the new points of [`split`] marked: the vertex points (Catmull-Clark), the face
/// points and the edge points, with a legend for Catmull-Clark.
fn split_markers(
    mut plot: Plot,
    kind: SplitKind,
    old_at: &[DVec2],
    face_at: &[DVec2],
    edge_at: &[DVec2],
) -> Plot {
    let cc = kind == SplitKind::CatmullClark;
    if cc {
        plot = plot.points(old_at, Marker::ring(VERMILION), Some("vertex points"));
    }
    if !face_at.is_empty() {
        plot = plot.points(face_at, Marker::point(GREEN), cc.then_some("face points"));
    }
    if !edge_at.is_empty() {
        let color = if cc { ORANGE } else { VERMILION };
        plot = plot.points(edge_at, Marker::point(color), cc.then_some("edge points"));
    }
    if cc {
        plot = plot.legend(Legend::UpperRight);
    }
    plot
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_read_off_the_library_match_the_formulas() {
        for n in 3..=8 {
            for weights in [LoopWeights::Loop, LoopWeights::Warren] {
                loop_vertex(weights, n).expect("Loop vertex mask");
            }
            sqrt3_vertex(n).expect("√3 vertex mask");
            if n != 6 {
                butterfly_extraordinary(n).expect("butterfly mask");
                labsik_greiner_extraordinary(n).expect("interpolating √3 mask");
            }
            catmull_clark_vertex(n).expect("Catmull-Clark vertex mask");
        }
        loop_edge().expect("Loop edge mask");
        loop_boundary(false).expect("Loop boundary vertex mask");
        loop_boundary(true).expect("Loop boundary edge mask");
        butterfly_regular().expect("regular butterfly mask");
        sqrt3_face().expect("√3 face mask");
        labsik_greiner_regular().expect("regular interpolating √3 mask");
        catmull_clark_face().expect("Catmull-Clark face mask");
        catmull_clark_edge().expect("Catmull-Clark edge mask");
    }

    #[test]
    fn a_wrong_formula_is_caught() {
        let s = tri_torus().expect("torus");
        let step = Step::new(LOOP, &s.mesh).expect("step");
        let spec = [((0.0, 0.0), 0.375), ((1.0, 0.0), 0.375), ((0.5, 0.75_f64.sqrt()), 0.25)];
        let expected = at_layout(&s, &spec).expect("stencil");
        let new = step.joined_to(&[expected[0].0, expected[1].0]).expect("edge point");
        assert!(
            mask(&step, &s.mesh, new, &expected, DVec2::ZERO, "wrong").is_err(),
            "a wrong mask passed"
        );
    }

    #[test]
    fn known_textbook_values() {
        assert!((loop_beta(LoopWeights::Loop, 6) - 1.0 / 16.0).abs() < 1e-15, "Loop β₆ = 1/16");
        assert!((loop_beta(LoopWeights::Loop, 3) - 3.0 / 16.0).abs() < 1e-15, "Loop β₃ = 3/16");
        assert!((loop_beta(LoopWeights::Loop, 4) - 31.0 / 256.0).abs() < 1e-15, "Loop β₄ = 31/256");
        assert!((sqrt3_alpha(6) - 1.0 / 3.0).abs() < 1e-15, "α₆ = 1/3");
        for k in 3..12 {
            let s: f64 = butterfly_weights(k).iter().sum();
            assert!((s - 0.25).abs() < 1e-14, "butterfly weights sum to 1/4 for K = {k}");
        }
    }

    #[test]
    fn fractions_are_exact_or_four_digits() {
        assert_eq!(fraction(-1.0 / 16.0), "−1/16", "fraction of −1/16");
        assert_eq!(fraction(0.375), "3/8", "fraction of 3/8");
        assert_eq!(fraction(0.0), "0", "fraction of 0");
        assert_eq!(fraction(-0.0), "0", "fraction of 0");
        assert_eq!(fraction(1.0), "1", "fraction of 1");
        assert_eq!(fraction(32.0 / 81.0), "32/81", "fraction of 32/81");
        assert_eq!(fraction(sqrt3_alpha(5) / 5.0), "0.0752", "fraction of 0.0752");
    }
}
