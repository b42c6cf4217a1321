// SPDX-License-Identifier: MIT
//! The textbook formulas the weights read off the library are checked against.

use std::f64::consts::PI;

use hi_mesh::subdivision::LoopWeights;

/// β of the Loop vertex mask for valence n: Loop's (1/n)(5/8 − (3 + 2cos(2π/n))²/64), or
/// Warren's 3/(8n) (3/16 for n = 3).
pub(super) fn loop_beta(weights: LoopWeights, n: u32) -> f64 {
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
pub(super) fn butterfly_weights(k: u32) -> Vec<f64> {
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
pub(super) fn sqrt3_alpha(n: u32) -> f64 {
    (4.0 - 2.0 * (2.0 * PI / f64::from(n)).cos()) / 9.0
}

/// Labsik and Greiner's semiregular mask for a corner of valence K: the corner's weight, and
/// the weight of a neighbour at angle θ from the bisector of the face (θ = ±π/K for the other
/// two corners). K = 3: 8/9, and 4/27 for the face's corners, −5/27 for the third neighbour;
/// K = 4: 7/9, 2/9 and −1/9; K ≥ 5: with a = ⅔cos(π/K), 1 − a² and
/// (a² + 2a·cos θ + 2a²·cos 2θ)/K.
pub(super) fn labsik_greiner(k: u32, theta: f64) -> (f64, f64) {
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
