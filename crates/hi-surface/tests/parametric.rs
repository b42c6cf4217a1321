// SPDX-License-Identifier: MIT
//! The §5.9 test surfaces: well defined, and their curvature comparison behaves as the thesis
//! reports (exact where the data is a low-degree periodic trigonometric polynomial, better with
//! more samples or a periodic parametrisation).

use hi_surface::{compare_curvature, test_surface, test_surfaces, torus};

#[test]
fn thirteen_surfaces_with_finite_samples() {
    let all = test_surfaces();
    assert_eq!(all.len(), 13);
    let figures: Vec<&str> = all.iter().map(|s| s.figure).collect();
    assert_eq!(
        figures,
        [
            "5.31", "5.32", "5.33", "5.34", "5.35", "5.36", "5.37", "5.38", "5.39", "5.40", "5.41",
            "5.42", "5.43"
        ]
    );
    for s in &all {
        let grid = s.sample_grid(s.samples.0, s.samples.1);
        assert!(grid.iter().flatten().all(|p| p.is_finite()), "{}", s.name);
        // The harmonic surface interpolates the samples.
        let h = s.harmonic();
        let p = h.eval(3.0 / s.samples.0 as f64, 1.0 / s.samples.1 as f64);
        assert!((p - grid[3][1]).length() < 1e-12 * (1.0 + p.length()), "{}", s.name);
    }
}

#[test]
fn numerical_curvature_of_the_parametric_torus_is_right() {
    // The parametric torus of §5.9 (R = 2, r = 1) against the closed form K = cos ρ/(r(R + r cos ρ)).
    let s = test_surface("torus").unwrap();
    for (u, v) in [(0.1, 0.1), (0.4, 0.35), (0.7, 0.8)] {
        let c = s.curvature(u, v, 3.0).unwrap();
        let rho = std::f64::consts::TAU * v;
        let k = rho.cos() / (2.0 + rho.cos());
        assert!((c.gaussian - k).abs() < 1e-6, "K {} vs {k}", c.gaussian);
    }
    // And the exact harmonic torus agrees analytically with the same closed form.
    let t = torus(2.0, 1.0).curvature(0.3, 0.1).unwrap();
    let theta = std::f64::consts::TAU * 0.3;
    assert!((t.gaussian - theta.sin() / (2.0 + theta.sin())).abs() < 1e-12);
}

#[test]
fn comparison_matches_the_thesis_findings() {
    let cmp = |name| compare_curvature(&test_surface(name).unwrap(), 64);
    // Torus and sphere are trigonometric polynomials of degree 1 in each parameter: the
    // harmonic surface is exact, up to the numerical derivatives of the reference.
    for name in ["torus", "sphere"] {
        let c = cmp(name);
        assert!(c.gaussian_max < 1e-6 && c.mean_max < 1e-6, "{name}: {c:?}");
    }
    // The plane stays flat.
    let c = cmp("plane");
    assert!(c.gaussian_max < 1e-9 && c.mean_max < 1e-9, "plane: {c:?}");
    // More samples help the knot tube; a periodic parametrisation helps the surface of revolution.
    assert!(cmp("solomon-fine").gaussian_rms < 0.5 * cmp("solomon").gaussian_rms);
    assert!(cmp("revolution-periodic").gaussian_rms < 0.1 * cmp("revolution").gaussian_rms);
    // Non-periodic data is where harmonic interpolation fails (figures 5.36–5.39).
    assert!(cmp("revolution").gaussian_max > 10.0);
}

/// The doubled Möbius strip's window v ∈ [0, ½] covers the strip once: (u + ½, v) is the point
/// (u, 1 − v), and the two halves of the window meet along the centre line v = ½, which the
/// harmonic surface reproduces exactly (that row of samples is the circle of radius 2 twice
/// round, a trigonometric polynomial of degree 2 in u), so they meet with no gap.
#[test]
fn the_moebius_window_covers_the_strip_once_with_no_gap() {
    let s = test_surface("mobius").unwrap();
    assert_eq!((s.window.v.start, s.window.v.end), (0.0, 0.5));
    let h = s.harmonic();
    for k in 0..50 {
        let u = f64::from(k) / 100.0 + 0.003;
        for v in [0.1, 0.3, 0.45] {
            assert!((s.eval(u + 0.5, v) - s.eval(u, 1.0 - v)).length() < 1e-12, "{u} {v}");
        }
        let (a, b) = (h.eval(u, 0.5), h.eval(u + 0.5, 0.5));
        assert!((a - b).length() < 1e-9, "{u}: {a} and {b}");
        assert!((a.length() - 2.0).abs() < 1e-9 && a.z.abs() < 1e-9, "{u}: {a}");
    }
}

/// Another shell (figure 5.38), as reconstructed: a whorl about the x axis whose cross-section
/// turns by θ − cos 2ρ, so that a cross-section's angle about the axis stays within a radian
/// of θ (where the literal product θ·cos 2ρ would sweep ±6π), and whose size grows as eᵘ − 1.
#[test]
fn another_shell_is_a_whorl() {
    let s = test_surface("shell2").unwrap();
    for k in 1..40 {
        let u = f64::from(k) / 40.0;
        let theta = 6.0 * std::f64::consts::PI * u;
        for j in 0..16 {
            let v = (f64::from(j) + 0.25) / 16.0;
            let p = s.eval(u, v);
            let rho = std::f64::consts::TAU * v;
            let a = u.exp() - 1.0;
            // Distance from the axis and along it: the circle of radius a through the axis.
            assert!((p.x - a * rho.sin()).abs() < 1e-12);
            assert!(((p.y * p.y + p.z * p.z).sqrt() - a * (1.0 + rho.cos())).abs() < 1e-12);
            // The angle about the axis, within a radian of θ.
            let turn = (p.y.atan2(p.z) - theta).rem_euclid(std::f64::consts::TAU);
            let off = turn.min(std::f64::consts::TAU - turn);
            assert!(off <= 1.0 + 1e-9, "{u} {v}: {off}");
        }
    }
}
