// SPDX-License-Identifier: MIT
//! Figures 4.8–4.10, 4.14, 4.18, 4.19, 4.23 and 4.24: the masks (stencils) of the subdivision
//! schemes of §4.5 and how Loop, √3 and Catmull-Clark subdivision split the faces.
//!
//! The weights drawn are read off the library, never typed in. One step of `hi_mesh::subdivision`
//! is linear in the vertex positions, so with x = 1 at one old vertex j and x = 0 at the others (y
//! and z keep the mesh's own coordinates), the x coordinate of every new vertex is the weight of j
//! in that vertex's mask. One step per old vertex gives the whole subdivision matrix
//! ([`Step`](library::Step)) of a closed mesh: a torus for the regular masks
//! ([`tri_torus`](meshes::tri_torus), [`quad_torus`](meshes::quad_torus)) and, for a vertex of
//! valence n whose neighbours are regular, a bipyramid after one Loop step or a prism after one
//! Catmull-Clark step ([`cone`](meshes::cone)). The new vertex of a mask is found by its
//! connectivity in the refined mesh (an edge point is the new vertex joined to both ends of its
//! edge, a √3 face point the one joined to the three corners, …), and every row drawn is checked,
//! over all old vertices, against the textbook formula computed here
//! ([`loop_beta`](formulas::loop_beta), [`butterfly_weights`](formulas::butterfly_weights),
//! [`sqrt3_alpha`](formulas::sqrt3_alpha), [`labsik_greiner`](formulas::labsik_greiner), the
//! Catmull-Clark rules) to [`TOL`], in the drawing function and in the tests. A weight is written
//! as a fraction when one with a denominator up to 1000 matches it to [`TOL`], otherwise to four
//! decimals.

mod drawing;
mod formulas;
mod library;
mod meshes;
mod splits;
mod stencils;

use hi_mesh::subdivision::{LoopWeights, Scheme};

use super::{Figure, Format, Panel};
use drawing::draw_mask;
use splits::{SplitKind, notation, split};
use stencils::{
    butterfly_extraordinary, butterfly_regular, catmull_clark_edge, catmull_clark_face,
    catmull_clark_vertex, labsik_greiner_extraordinary, labsik_greiner_regular, loop_boundary,
    loop_edge, loop_vertex, sqrt3_face, sqrt3_vertex,
};

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

#[cfg(test)]
mod tests {
    use super::drawing::fraction;
    use super::formulas::{butterfly_weights, loop_beta, sqrt3_alpha};
    use glam::DVec2;

    use super::library::{Step, mask};
    use super::meshes::tri_torus;
    use super::stencils::at_layout;
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
