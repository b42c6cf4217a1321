// SPDX-License-Identifier: MIT
//! The point sets the figures draw.
//!
//! The thesis does not print the coordinates of its figures' points, so most of these are
//! stand-ins chosen here: irregular polygons with the thesis's number of points (and roughly
//! its label layout), regular polygons where the thesis uses them. They are kept in one place
//! so that every figure of the same polygon (figures 3.9, 3.21, 5.2 and 5.6 all use the
//! heptagon) uses the same points, and so that the index page can list them ([`STAND_INS`]).

use glam::{DVec2, DVec3};

/// A named point set, listed on the index page.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StandIn {
    /// Short name used in the index.
    pub(crate) name: &'static str,
    /// What it is and why it was chosen.
    pub(crate) about: &'static str,
    /// The letter the figures label its points with (x₀, x₁, … or p₀, p₁, …).
    pub(crate) letter: &'static str,
    /// True for a set in space (listed with three coordinates).
    pub(crate) space: bool,
    /// The points (z = 0 for plane sets).
    pub(crate) points: fn() -> Vec<DVec3>,
}

/// Every point set used by the figures, in the order the index lists them.
pub(crate) const STAND_INS: &[StandIn] = &[
    StandIn {
        name: "square",
        about: "the vertices of the unit square as a diamond, xₖ = (cos kπ/2, sin kπ/2) (the thesis's labels in figures 3.7 and 3.13 have this layout; figures 3.7, 3.8, 3.13, 3.15)",
        letter: "x",
        space: false,
        points: || lift(&SQUARE),
    },
    StandIn {
        name: "quadrilateral",
        about: "an irregular convex quadrilateral (figure 3.19); the perturbed copy moves x₃ by 0.25 to the right",
        letter: "x",
        space: false,
        points: || lift(&QUADRILATERAL),
    },
    StandIn {
        name: "pentagon",
        about: "an irregular pentagon, x₄ placed so that the harmonic curve has a cusp near x₃, as the thesis's does (figures 3.11, 3.12, 3.17, 3.22)",
        letter: "x",
        space: false,
        points: || lift(&PENTAGON),
    },
    StandIn {
        name: "hexagon",
        about: "an irregular hexagon with a large alternating sum c = (1/n)Σ(−1)ᵏxₖ (figure 5.6(c), which is not in the thesis)",
        letter: "x",
        space: false,
        points: || lift(&HEXAGON),
    },
    StandIn {
        name: "heptagon",
        about: "an irregular heptagon with a dent at x₄ (figures 3.9, 3.10, 3.16, 3.20, 3.21, 5.2, 5.6)",
        letter: "x",
        space: false,
        points: || lift(&HEPTAGON),
    },
    StandIn {
        name: "octagon",
        about: "an irregular octagon with a notch at x₄ (figures 3.18, 3.23)",
        letter: "x",
        space: false,
        points: || lift(&OCTAGON),
    },
    StandIn {
        name: "Lagrange quadrilateral",
        about: "example 2.1 (figure 2.2): x₀, x₁, x₂ as the extracted thesis text prints them, (1, 1), (2, 3), (4, 1) (its minus signs are lost, so they are read as positive); x₃ is illegible there and chosen here",
        letter: "x",
        space: false,
        points: || lift(&LAGRANGE),
    },
    StandIn {
        name: "Bézier quadrilateral",
        about: "the four control points of figures 2.4, 2.6 and 2.7, a crossing polygon with the thesis's label layout (x₁ highest, x₂ lowest)",
        letter: "x",
        space: false,
        points: || lift(&BEZIER),
    },
    StandIn {
        name: "zigzag",
        about: "nine points in a wave, the control points of figures 2.11 and 2.12 and the data of figures 2.13 and 2.15, with the thesis's label layout (x₁, x₂, x₅, x₇ high)",
        letter: "x",
        space: false,
        points: || lift(&ZIGZAG),
    },
    StandIn {
        name: "peer pentagon",
        about: "the irregular pentagon of the METAPOST and scipy cross-checks (docs/peers.md §1, §2b), for figures 2.14 and 2.16",
        letter: "x",
        space: false,
        points: || lift(&PEER_PENTAGON),
    },
    StandIn {
        name: "cube tour",
        about: "the vertices of the unit cube in Gray-code order 000, 100, 110, 010, 011, 111, 101, 001 (figure 3.14)",
        letter: "p",
        space: true,
        points: cube_tour,
    },
];

/// Four points on the unit circle.
pub(crate) const SQUARE: [[f64; 2]; 4] = [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]];

/// An irregular convex quadrilateral.
pub(crate) const QUADRILATERAL: [[f64; 2]; 4] = [[1.6, 0.2], [0.1, 1.4], [-1.5, 0.5], [-0.4, -1.3]];

/// How far figure 3.19(b) moves x₃ to the right.
pub(crate) const QUADRILATERAL_NUDGE: f64 = 0.25;

/// An irregular pentagon whose harmonic curve has a cusp near x₃.
pub(crate) const PENTAGON: [[f64; 2]; 5] =
    [[0.0, 2.0], [-1.7, 0.3], [-0.9, -1.5], [1.1, -1.4], [0.8, -0.6]];

/// An irregular hexagon whose alternating sum is far from zero.
pub(crate) const HEXAGON: [[f64; 2]; 6] =
    [[2.2, 0.0], [1.0, 1.3], [-0.2, 1.0], [-1.8, 0.9], [-1.0, -0.6], [0.6, -1.5]];

/// An irregular heptagon with a notch.
pub(crate) const HEPTAGON: [[f64; 2]; 7] =
    [[0.4, 3.0], [0.0, 0.6], [2.2, 0.0], [3.8, 1.0], [3.0, 1.9], [3.9, 2.8], [2.4, 3.5]];

/// An irregular octagon with a notch.
pub(crate) const OCTAGON: [[f64; 2]; 8] = [
    [0.2, 3.0],
    [-0.3, 0.6],
    [1.0, -0.4],
    [2.6, 0.0],
    [2.2, 1.4],
    [3.3, 1.6],
    [3.8, 2.6],
    [2.4, 3.4],
];

/// Example 2.1's points, x₃ a stand-in.
pub(crate) const LAGRANGE: [[f64; 2]; 4] = [[1.0, 1.0], [2.0, 3.0], [4.0, 1.0], [5.0, 3.0]];

/// The control points of the cubic Bézier curve of figures 2.4, 2.6 and 2.7.
pub(crate) const BEZIER: [[f64; 2]; 4] = [[0.0, 0.5], [1.0, 2.0], [3.0, -0.5], [4.0, 1.0]];

/// Nine points in a wave (figures 2.11–2.13, 2.15).
pub(crate) const ZIGZAG: [[f64; 2]; 9] = [
    [0.0, 0.0],
    [1.0, 2.0],
    [2.5, 2.2],
    [3.0, 0.3],
    [4.5, 0.0],
    [5.5, 2.0],
    [6.8, 0.4],
    [8.0, 2.1],
    [9.5, 1.2],
];

/// The pentagon of the peer cross-checks (figures 2.14, 2.16).
pub(crate) const PEER_PENTAGON: [[f64; 2]; 5] =
    [[0.0, 0.0], [3.0, 1.0], [4.0, 4.0], [1.0, 5.0], [-1.0, 2.0]];

/// The points of a plane set.
pub(crate) fn plane(points: &[[f64; 2]]) -> Vec<DVec2> {
    points.iter().map(|&[x, y]| DVec2::new(x, y)).collect()
}

/// The points of a plane set in space, z = 0.
fn lift(points: &[[f64; 2]]) -> Vec<DVec3> {
    points.iter().map(|&[x, y]| DVec3::new(x, y, 0.0)).collect()
}

/// The cube's vertices in Gray-code order: bit 0 is x, bit 1 is y, bit 2 is z.
pub(crate) fn cube_tour() -> Vec<DVec3> {
    [0b000_u8, 0b001, 0b011, 0b010, 0b110, 0b111, 0b101, 0b100]
        .iter()
        .map(|&g| DVec3::new(f64::from(g & 1), f64::from((g >> 1) & 1), f64::from((g >> 2) & 1)))
        .collect()
}

/// The 12 edges of the unit cube, each as its two end points.
pub(crate) fn cube_edges() -> Vec<[DVec3; 2]> {
    let corner =
        |g: u8| DVec3::new(f64::from(g & 1), f64::from((g >> 1) & 1), f64::from((g >> 2) & 1));
    let mut edges = Vec::with_capacity(12);
    for g in 0..8_u8 {
        for bit in [1_u8, 2, 4] {
            if g & bit == 0 {
                edges.push([corner(g), corner(g | bit)]);
            }
        }
    }
    edges
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cube_tour_is_the_gray_code_order() {
        // 000, 100, 110, 010, 011, 111, 101, 001 written as (x, y, z).
        let expected = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 1.0, 1.0],
            [1.0, 1.0, 1.0],
            [1.0, 0.0, 1.0],
            [0.0, 0.0, 1.0],
        ];
        let tour = cube_tour();
        for (p, e) in tour.iter().zip(expected) {
            assert_eq!(p.to_array(), e, "tour {tour:?}");
        }
        // Consecutive vertices (cyclically) share an edge.
        for k in 0..8 {
            assert_eq!((tour[(k + 1) % 8] - tour[k]).length(), 1.0, "step {k}");
        }
        assert_eq!(cube_edges().len(), 12, "a cube has 12 edges");
    }
}
