// SPDX-License-Identifier: MIT
//! Triangular Bézier patches (§4.3, figure 4.4) against the flat triangle, the explicit
//! trivariate Bernstein sum, quadratic polynomials written in Bézier form by blossoming, and
//! finite differences.

use glam::DVec3;
use hi_bezier::{Error, TriangularPatch};

fn factorial(n: usize) -> f64 {
    (1..=n).map(|x| x as f64).product()
}

/// Σ n!/(i!j!k!)·uⁱvʲwᵏ·xᵢⱼₖ, explicitly.
fn trivariate_sum(t: &TriangularPatch<DVec3>, u: f64, v: f64) -> DVec3 {
    let n = t.degree();
    let w = 1.0 - u - v;
    let mut res = DVec3::ZERO;
    for i in 0..=n {
        for j in 0..=n - i {
            let k = n - i - j;
            let b = factorial(n) / (factorial(i) * factorial(j) * factorial(k))
                * u.powi(i as i32)
                * v.powi(j as i32)
                * w.powi(k as i32);
            res += t.control_point(i, j, k).unwrap() * b;
        }
    }
    res
}

/// Figure 4.4's net: a degree-3 triangle (the thesis gives no coordinates; a stand-in).
fn figure_4_4() -> TriangularPatch<DVec3> {
    TriangularPatch::try_from_fn(3, |i, j, k| {
        let (a, b) = (i as f64 / 3.0, j as f64 / 3.0);
        DVec3::new(a + 0.5 * b, b * 0.866, (i * j * k) as f64 * 0.4 + 0.1 * k as f64)
    })
    .unwrap()
}

fn params() -> Vec<(f64, f64)> {
    let mut res = vec![];
    for a in 0..=8 {
        for b in 0..=8 - a {
            res.push((a as f64 / 8.0, b as f64 / 8.0));
        }
    }
    res
}

#[test]
fn degree_one_is_the_flat_triangle() {
    let (a, b, c) =
        (DVec3::new(1.0, 0.0, 2.0), DVec3::new(-1.0, 3.0, 0.5), DVec3::new(0.5, 0.5, -1.0));
    let tri = TriangularPatch::new(vec![c, b, a]); // order: x₀₀₁, x₀₁₀, x₁₀₀
    assert_eq!(tri.degree(), 1);
    let normal = (a - c).cross(b - c).normalize();
    for (u, v) in params() {
        let e = u * a + v * b + (1.0 - u - v) * c;
        assert!((tri.eval(u, v) - e).length() < 1e-15);
        assert!((tri.normal(u, v).unwrap() - normal).length() < 1e-15);
        assert!((tri.eval_deriv(u, v, 1, 0) - (a - c)).length() < 1e-15);
        assert!((tri.eval_deriv(u, v, 0, 1) - (b - c)).length() < 1e-15);
    }
    assert_eq!(tri.eval_deriv(0.2, 0.2, 1, 1), DVec3::ZERO);
}

#[test]
fn de_casteljau_equals_the_trivariate_sum() {
    let t = figure_4_4();
    assert_eq!(t.control_points().len(), 10);
    for (u, v) in params() {
        assert!((t.eval(u, v) - trivariate_sum(&t, u, v)).length() < 1e-14, "({u}, {v})");
    }
}

/// f(x) = a + b·x + xᵀCx over x = (u, v), as three coordinates of test data.
struct Quadratic {
    a: f64,
    b: [f64; 2],
    c: [[f64; 2]; 2],
}

impl Quadratic {
    fn eval(&self, x: [f64; 2]) -> f64 {
        self.a + self.b[0] * x[0] + self.b[1] * x[1] + bilinear(&self.c, x, x)
    }

    /// The blossom (polar form) for degree n: symmetric, affine in each argument, equal to f on
    /// the diagonal: F(x₁, …, xₙ) = a + b·(Σxᵢ)/n + 2/(n(n − 1))·Σᵢ<ⱼ xᵢᵀCxⱼ (n ≥ 2).
    fn blossom(&self, args: &[[f64; 2]]) -> f64 {
        let n = args.len() as f64;
        let mean = [
            args.iter().map(|x| x[0]).sum::<f64>() / n,
            args.iter().map(|x| x[1]).sum::<f64>() / n,
        ];
        let mut pairs = 0.0;
        for i in 0..args.len() {
            for j in i + 1..args.len() {
                pairs += bilinear(&self.c, args[i], args[j]);
            }
        }
        self.a + self.b[0] * mean[0] + self.b[1] * mean[1] + 2.0 / (n * (n - 1.0)) * pairs
    }

    fn gradient(&self, x: [f64; 2]) -> [f64; 2] {
        let c = &self.c;
        [
            self.b[0] + (c[0][0] + c[0][0]) * x[0] + (c[0][1] + c[1][0]) * x[1],
            self.b[1] + (c[0][1] + c[1][0]) * x[0] + (c[1][1] + c[1][1]) * x[1],
        ]
    }
}

fn bilinear(c: &[[f64; 2]; 2], x: [f64; 2], y: [f64; 2]) -> f64 {
    x[0] * (c[0][0] * y[0] + c[0][1] * y[1]) + x[1] * (c[1][0] * y[0] + c[1][1] * y[1])
}

#[test]
fn blossomed_quadratics_are_reproduced() {
    let fs = [
        Quadratic { a: 1.0, b: [2.0, -1.0], c: [[0.5, 0.25], [0.25, -1.5]] },
        Quadratic { a: -0.5, b: [0.0, 3.0], c: [[2.0, -1.0], [-1.0, 0.0]] },
        Quadratic { a: 0.0, b: [1.0, 1.0], c: [[-1.0, 0.7], [0.7, 1.0]] },
    ];
    // The parameter-triangle vertices: (u, v) = (1, 0) for i, (0, 1) for j, (0, 0) for k.
    let (e1, e2, e3) = ([1.0, 0.0], [0.0, 1.0], [0.0, 0.0]);
    for n in [2usize, 3, 5] {
        let tri = TriangularPatch::try_from_fn(n, |i, j, k| {
            let mut args = vec![e1; i];
            args.extend(vec![e2; j]);
            args.extend(vec![e3; k]);
            DVec3::new(fs[0].blossom(&args), fs[1].blossom(&args), fs[2].blossom(&args))
        })
        .unwrap();
        for (u, v) in params() {
            let x = [u, v];
            let e = DVec3::new(fs[0].eval(x), fs[1].eval(x), fs[2].eval(x));
            assert!((tri.eval(u, v) - e).length() < 1e-14, "n={n} ({u}, {v})");
            let g: Vec<[f64; 2]> = fs.iter().map(|f| f.gradient(x)).collect();
            let pu = DVec3::new(g[0][0], g[1][0], g[2][0]);
            let pv = DVec3::new(g[0][1], g[1][1], g[2][1]);
            assert!((tri.eval_deriv(u, v, 1, 0) - pu).length() < 1e-13, "∂u n={n}");
            assert!((tri.eval_deriv(u, v, 0, 1) - pv).length() < 1e-13, "∂v n={n}");
            // Along a direction d: ∇f·d; second derivative along d: 2dᵀCd.
            let d = (0.6, -1.1);
            let dd = tri.eval_directional(u, v, d, 1);
            assert!((dd - (pu * d.0 + pv * d.1)).length() < 1e-13);
            let second = DVec3::new(
                2.0 * bilinear(&fs[0].c, [d.0, d.1], [d.0, d.1]),
                2.0 * bilinear(&fs[1].c, [d.0, d.1], [d.0, d.1]),
                2.0 * bilinear(&fs[2].c, [d.0, d.1], [d.0, d.1]),
            );
            assert!((tri.eval_directional(u, v, d, 2) - second).length() < 1e-12);
            assert!(tri.eval_directional(u, v, d, 3).length() < 1e-11, "cubic term vanishes");
            let puv = DVec3::new(
                fs[0].c[0][1] + fs[0].c[1][0],
                fs[1].c[0][1] + fs[1].c[1][0],
                fs[2].c[0][1] + fs[2].c[1][0],
            );
            assert!((tri.eval_deriv(u, v, 1, 1) - puv).length() < 1e-12);
        }
    }
}

#[test]
fn linear_precision_and_partition_of_unity() {
    for n in [1usize, 2, 4, 7] {
        let constant = TriangularPatch::try_from_fn(n, |_, _, _| DVec3::splat(2.5)).unwrap();
        let linear = TriangularPatch::try_from_fn(n, |i, j, _| {
            DVec3::new(i as f64 / n as f64, j as f64 / n as f64, 0.0)
        })
        .unwrap();
        for (u, v) in params() {
            assert!((constant.eval(u, v) - DVec3::splat(2.5)).length() < 1e-14);
            assert!((linear.eval(u, v) - DVec3::new(u, v, 0.0)).length() < 1e-15);
        }
    }
}

#[test]
fn directional_derivatives_by_finite_differences() {
    let t = figure_4_4();
    let h = 1e-6;
    for &(u, v) in &[(0.2, 0.3), (0.5, 0.1), (0.1, 0.7)] {
        for d in [(1.0, 0.0), (0.0, 1.0), (-1.0, 1.0), (0.3, 0.8)] {
            let fd =
                (t.eval(u + h * d.0, v + h * d.1) - t.eval(u - h * d.0, v - h * d.1)) / (2.0 * h);
            assert!((t.eval_directional(u, v, d, 1) - fd).length() < 1e-8, "{d:?}");
            let fd2 = (t.eval_directional(u + h * d.0, v + h * d.1, d, 1)
                - t.eval_directional(u - h * d.0, v - h * d.1, d, 1))
                / (2.0 * h);
            assert!((t.eval_directional(u, v, d, 2) - fd2).length() < 1e-7, "{d:?}");
        }
        let nrm = t.normal(u, v).unwrap();
        assert!(nrm.dot(t.eval_deriv(u, v, 1, 0)).abs() < 1e-14);
    }
    assert_eq!(t.eval_directional(0.2, 0.2, (1.0, 0.0), 4), DVec3::ZERO);
}

#[test]
fn elevation_and_boundaries() {
    let t = figure_4_4();
    let e = t.elevate();
    assert_eq!(e.degree(), 4);
    for (u, v) in params() {
        assert!((e.eval(u, v) - t.eval(u, v)).length() < 1e-14);
    }
    let [v0, u0, w0] = t.boundary_curves();
    for s in [0.0, 0.25, 0.9] {
        assert!((v0.eval(s) - t.eval(s, 0.0)).length() < 1e-14);
        assert!((u0.eval(s) - t.eval(0.0, s)).length() < 1e-14);
        assert!((w0.eval(s) - t.eval(1.0 - s, s)).length() < 1e-14);
    }
    let b = t.control_bounding_box();
    for (u, v) in params() {
        assert!(b.contains(t.eval(u, v)));
    }
}

#[test]
fn validation() {
    assert_eq!(
        TriangularPatch::try_new(vec![DVec3::ZERO; 5]),
        Err(Error::TriangularCount { found: 5 })
    );
    assert_eq!(
        TriangularPatch::try_new(vec![DVec3::ZERO, DVec3::X, DVec3::NAN]),
        Err(Error::NonFinitePoint { index: 2 })
    );
    assert!(
        TriangularPatch::try_from_fn(2, |i, _, _| if i == 2 {
            DVec3::INFINITY
        } else {
            DVec3::ZERO
        })
        .is_err()
    );
}
