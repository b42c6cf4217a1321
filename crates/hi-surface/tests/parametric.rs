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
