// SPDX-License-Identifier: MIT
use super::relax::{face_energy, face_energy_grad, relaxation_budget, stretch_numerator};
use super::*;
use crate::laplace::tail;

/// A bumpy 12 × 12 height field over the unit square and its harmonic map onto the square
/// (the boundary held where it lies): positions, triangles, connectivity, Laplacian,
/// held vertices, the map and the iterations it took.
#[expect(clippy::type_complexity, reason = "one test helper")]
fn bumpy_square() -> (Vec<DVec3>, Vec<[u32; 3]>, Topology, Laplacian, Vec<bool>, FlatMap, usize) {
    let n = 12;
    let p: Vec<DVec3> = (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64 / (n - 1) as f64, (k / n) as f64 / (n - 1) as f64);
            DVec3::new(x, y, 0.4 * (5.0 * x).sin() * (4.0 * y).cos())
        })
        .collect();
    let mut t = Vec::new();
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            let a = (i * n + j) as u32;
            t.extend([[a, a + 1, a + n as u32 + 1], [a, a + n as u32 + 1, a + n as u32]]);
        }
    }
    let topology = Topology::new(p.len(), &t).unwrap();
    let mut fixed = vec![false; p.len()];
    for &h in &topology.boundary {
        fixed[tail(&t, h) as usize] = true;
    }
    let mut lap = Laplacian::new(&topology, &t);
    lap.set_cotangent_weights(&p, &t, None);
    let mut x: Vec<[f64; 2]> = p.iter().map(|q| [q.x, q.y]).collect();
    let cg = CgOptions::new(1e-10, 1000);
    let (iterations, solved) =
        solve_until_embedded(&lap, Some(&fixed), &vec![[0.0; 2]; p.len()], &mut x, cg, None, |_| 0);
    assert_eq!(solved.unwrap().folds, 0, "the harmonic map");
    let map = FlatMap {
        uv: x.iter().map(|q| DVec2::from_array(*q)).collect(),
        offsets: vec![[IVec2::ZERO; 3]; t.len()],
    };
    (p, t, topology, lap, fixed, map, iterations)
}

/// The rounds' solves share a budget: with iterations to spare they lower the stretch;
/// with one iteration per solve the first round cannot be solved, is dropped, and leaves
/// the map as it was.
#[test]
fn rounds_keep_to_their_budget() {
    let (p, t, topology, mut lap, fixed, harmonic, iterations) = bumpy_square();
    let freedom: Vec<Freedom> =
        fixed.iter().map(|&f| if f { Freedom::Fixed } else { Freedom::Free }).collect();
    let relaxation = Relaxation::new(&p, &t, &topology, freedom, None);
    let zero = vec![[0.0; 2]; p.len()];
    let before = quality(&p, &t, &harmonic, None).0.stretch_efficiency;
    let options = RelaxOptions {
        rounds: 8,
        sweeps: 0,
        cg: CgOptions::new(1e-8, 100_000),
        harmonic_iterations: iterations,
    };
    let mut map = harmonic.clone();
    let done =
        relaxation.run(&mut lap, Some(&fixed), &|_: &Laplacian| zero.clone(), &mut map, options);
    let after = quality(&p, &t, &map, None).0.stretch_efficiency;
    println!("{done:?}: efficiency {before} → {after}");
    assert!(done.rounds >= 1 && after > before, "{done:?}");
    assert!(done.iterations <= relaxation_budget(iterations), "{done:?}");
    assert_ne!(done.end, RoundsEnd::Unsolved, "{done:?}");
    // One iteration per solve: the first round is dropped, the map kept as it was.
    let mut map = harmonic.clone();
    let starved = RelaxOptions { cg: CgOptions::new(1e-8, 1), ..options };
    let done =
        relaxation.run(&mut lap, Some(&fixed), &|_: &Laplacian| zero.clone(), &mut map, starved);
    assert_eq!((done.rounds, done.end, done.iterations), (0, RoundsEnd::Unsolved, 1), "{done:?}");
    assert_eq!(map.uv, harmonic.uv, "the harmonic map kept");
    // No rounds asked for.
    let none = RelaxOptions { rounds: 0, ..options };
    let done =
        relaxation.run(&mut lap, Some(&fixed), &|_: &Laplacian| zero.clone(), &mut map, none);
    assert_eq!((done.rounds, done.end, done.iterations), (0, RoundsEnd::NotAsked, 0), "{done:?}");
}

/// The analytic gradient and Hessian of a face's energy against central differences.
#[test]
fn face_energy_derivatives_match_differences() {
    let (a, b, c) = (DVec2::new(0.1, 0.05), DVec2::new(0.9, 0.1), DVec2::new(0.3, 0.7));
    let (area, l2) = (0.7, [0.9, 1.3, 0.6]);
    let (e, g, hs) = face_energy_grad(a, b, c, area, l2);
    assert!((e - face_energy(a, b, c, area, l2)).abs() < 1e-12 * e, "energy");
    let h = 1e-6;
    for (axis, col) in [(DVec2::X, [hs[0], hs[1]]), (DVec2::Y, [hs[1], hs[2]])] {
        let (ep, gp, _) = face_energy_grad(a + h * axis, b, c, area, l2);
        let (em, gm, _) = face_energy_grad(a - h * axis, b, c, area, l2);
        let dg = (ep - em) / (2.0 * h);
        assert!((dg - g.dot(axis)).abs() < 1e-6 * g.length(), "gradient {dg} vs {g}");
        let dh = (gp - gm) / (2.0 * h);
        let col = DVec2::from_array(col);
        assert!((dh - col).length() < 1e-5 * col.length().max(1.0), "Hessian {dh} vs {col}");
    }
    assert_eq!(face_energy(a, c, b, area, l2), f64::INFINITY, "wound the wrong way");
}

/// σ₁² + σ₂² of an affine map, against its Jacobian computed directly.
#[test]
fn stretch_numerator_is_the_frobenius_norm() {
    let (a, b, c) = (DVec2::new(0.2, 0.1), DVec2::new(1.1, 0.3), DVec2::new(0.4, 0.9));
    // The map (u, v) ↦ J (u, v) with J 3×2.
    let j = [DVec3::new(1.0, 0.5, -0.3), DVec3::new(-0.2, 0.8, 0.6)];
    let map = |p: DVec2| j[0] * p.x + j[1] * p.y;
    let (pa, pb, pc) = (map(a), map(b), map(c));
    let l2 = [(pb - pc).length_squared(), (pc - pa).length_squared(), (pa - pb).length_squared()];
    let d = cross(b - a, c - a);
    let frob = j[0].length_squared() + j[1].length_squared();
    assert!((stretch_numerator(a, b, c, l2) / (d * d) - frob).abs() < 1e-12, "‖J‖²");
}

#[test]
fn reduction_gives_a_short_basis() {
    // The lattice of (1, 0) and (7, 1) under the Euclidean form is Z²; the form of the
    // basis B₀ = ((1, 0), (7, 1)) is B₀ᵀB₀.
    let q = [1.0, 7.0, 50.0];
    let b = reduce(q);
    let form = |x: [i32; 2], y: [i32; 2]| {
        q[0] * f64::from(x[0] * y[0])
            + q[1] * f64::from(x[0] * y[1] + x[1] * y[0])
            + q[2] * f64::from(x[1] * y[1])
    };
    assert_eq!(b[0][0] * b[1][1] - b[0][1] * b[1][0], 1, "determinant 1");
    assert!(form(b[0], b[0]) <= form(b[1], b[1]), "ordered");
    assert!(2.0 * form(b[0], b[1]).abs() <= form(b[0], b[0]), "reduced");
    // Both reduced vectors have length 1 in the original lattice.
    assert_eq!(form(b[0], b[0]), 1.0);
    assert_eq!(form(b[1], b[1]), 1.0);
    let inv = inverse(b);
    let prod = |x: [[i32; 2]; 2], y: [[i32; 2]; 2]| {
        [0, 1].map(|c| [0, 1].map(|r| x[0][r] * y[c][0] + x[1][r] * y[c][1]))
    };
    assert_eq!(prod(b, inv), [[1, 0], [0, 1]]);
}
