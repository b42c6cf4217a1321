// SPDX-License-Identifier: MIT
//! Fairness measures (Hardy 2005, §2.15, §3.5, §2.4) on curves with known answers: circles,
//! ellipses, the harmonic curve of a square, and piecewise cubic Hobby curves checked against
//! an independent quadrature over their segments.

use hi_curve::Error as CurveError;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

use glam::{DVec2, DVec3};
use hi_compare::Error;
use hi_compare::corner_cutting::ChaikinCurve;
use hi_compare::fairness::{
    bending_energy, curvature_plot, fairness, monotone_pieces, space_curvature_plot,
};
use hi_compare::hobby::{HobbyCurve, HobbyOptions};
use hi_curve::{HarmonicCurve, ParamCurve};

/// The ellipse (a cos(2πt + φ), b sin(2πt + φ)); a circle when a = b.
struct Ellipse {
    a: f64,
    b: f64,
    phase: f64,
}

impl ParamCurve<DVec2> for Ellipse {
    fn eval(&self, t: f64) -> DVec2 {
        self.eval_deriv(t, 0)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> DVec2 {
        let angle = TAU * t + self.phase + order as f64 * FRAC_PI_2;
        let scale = TAU.powi(order as i32);
        DVec2::new(self.a * scale * angle.cos(), self.b * scale * angle.sin())
    }

    fn scale(&self) -> f64 {
        self.a.max(self.b)
    }

    fn is_periodic(&self) -> bool {
        true
    }
}

/// ∫₀¹ f by composite Simpson's rule with `n` (even) intervals.
fn simpson(f: impl Fn(f64) -> f64, n: usize) -> f64 {
    let h = 1.0 / n as f64;
    let inner: f64 =
        (1..n).map(|i| f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 }).sum::<f64>();
    (f(0.0) + inner + f(1.0)) * h / 3.0
}

#[test]
fn circle_has_constant_curvature_and_energy_two_pi_over_r() {
    let r = 2.0;
    let circle = Ellipse { a: r, b: r, phase: 0.0 };
    let square =
        vec![DVec2::new(r, 0.0), DVec2::new(0.0, r), DVec2::new(-r, 0.0), DVec2::new(0.0, -r)];
    let f = fairness(&circle, &square, 20_000).unwrap();
    assert!((f.max_curvature - 1.0 / r).abs() < 1e-14, "{f:?}");
    assert_eq!(f.monotone_pieces, 1);
    assert!((f.bending_energy - TAU / r).abs() < 1e-13, "{f:?}");
    assert!((f.length - TAU * r).abs() < 1e-13, "{f:?}");
    // The circle through a square's vertices over the square: π/2, less the sampling error
    // (2π/N)²/6 of an inscribed regular N-gon.
    let confinement = f.confinement.unwrap();
    assert!(confinement < FRAC_PI_2 && FRAC_PI_2 - confinement < 3e-8, "{confinement}");
    let plot = curvature_plot(&circle, 5).unwrap();
    assert_eq!(plot.iter().map(|s| s.t).collect::<Vec<_>>(), vec![0.0, 0.2, 0.4, 0.6, 0.8]);
    assert!(plot.iter().all(|s| (s.curvature.unwrap() - 0.5).abs() < 1e-15));
}

#[test]
fn ellipse_matches_independent_quadrature() {
    let (a, b) = (3.0, 1.0);
    // κ(θ) = ab/(a² sin²θ + b² cos²θ)^{3/2}, ds = 2π·(a² sin²θ + b² cos²θ)^{1/2} dt.
    let q = |t: f64| {
        let (s, c) = (TAU * t).sin_cos();
        a * a * s * s + b * b * c * c
    };
    let energy = simpson(|t| (a * b).powi(2) / q(t).powi(3) * TAU * q(t).sqrt(), 200_000);
    let length = simpson(|t| TAU * q(t).sqrt(), 200_000);
    let points =
        vec![DVec2::new(a, 0.0), DVec2::new(0.0, b), DVec2::new(-a, 0.0), DVec2::new(0.0, -b)];
    for phase in [0.0, 0.1234] {
        let ellipse = Ellipse { a, b, phase };
        let f = fairness(&ellipse, &points, 1000).unwrap();
        // The largest curvature a/b² at the ends of the major axis, found between samples when
        // the phase moves it off them.
        assert!((f.max_curvature - a / (b * b)).abs() < 1e-9, "phase {phase}: {f:?}");
        let expected_t = (-phase / TAU).rem_euclid(0.5);
        assert!(
            ((f.max_curvature_at - expected_t + 0.25).rem_euclid(0.5) - 0.25).abs() < 1e-5,
            "phase {phase}: at {}",
            f.max_curvature_at
        );
        // κ rises and falls twice around the ellipse.
        assert_eq!(f.monotone_pieces, 4, "phase {phase}");
        assert!(
            (f.bending_energy - energy).abs() < 1e-10 * energy,
            "{} vs {energy}",
            f.bending_energy
        );
        assert!((f.length - length).abs() < 1e-10 * length, "{} vs {length}", f.length);
        let confinement = f.confinement.unwrap();
        assert!((confinement - FRAC_PI_2).abs() < 2e-5, "{confinement}");
    }
}

#[test]
fn harmonic_curve_of_a_square_is_a_circle() {
    let square = vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
    let curve = HarmonicCurve::new(square.clone());
    let f = fairness(&curve, &square, 8192).unwrap();
    assert!((f.max_curvature - 1.0).abs() < 1e-12, "{f:?}");
    assert_eq!(f.monotone_pieces, 1);
    assert!((f.bending_energy - TAU).abs() < 1e-11, "{f:?}");
    assert!((f.length - TAU).abs() < 1e-12, "{f:?}");
    assert!((f.confinement.unwrap() - FRAC_PI_2).abs() < 2e-7, "{f:?}");
}

/// ∫ κ² ds and ∫ ds of a Hobby curve segment by segment, from the Bézier control points, with
/// 20-point Gauss–Legendre on 64 pieces of each segment: independent of the crate's
/// quadrature and of the parametrisation.
fn segmentwise(curve: &HobbyCurve) -> (f64, f64) {
    // Gauss–Legendre nodes and weights on [−1, 1] by Newton's method on P₂₀.
    let m = 20;
    let mut rule = Vec::new();
    for i in 0..m {
        let mut x = (PI * (i as f64 + 0.75) / (m as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=m {
                let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            dp = m as f64 * (x * p1 - p0) / (x * x - 1.0);
            x -= p1 / dp;
        }
        rule.push((x, 2.0 / ((1.0 - x * x) * dp * dp)));
    }
    let (mut energy, mut length) = (0.0, 0.0);
    for k in 0..curve.n_segments() {
        let [p0, p1, p2, p3] = curve.segment(k).unwrap();
        let d1 = |s: f64| {
            3.0 * ((p1 - p0) * (1.0 - s) * (1.0 - s)
                + (p2 - p1) * 2.0 * s * (1.0 - s)
                + (p3 - p2) * s * s)
        };
        let d2 = |s: f64| 6.0 * ((p2 - p1 * 2.0 + p0) * (1.0 - s) + (p3 - p2 * 2.0 + p1) * s);
        let pieces = 64;
        for j in 0..pieces {
            let (lo, hi) = (j as f64 / pieces as f64, (j + 1) as f64 / pieces as f64);
            for &(x, w) in &rule {
                let s = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x;
                let (v, acc) = (d1(s), d2(s));
                let speed = v.length();
                let kappa = v.perp_dot(acc) / speed.powi(3);
                energy += 0.5 * (hi - lo) * w * kappa * kappa * speed;
                length += 0.5 * (hi - lo) * w * speed;
            }
        }
    }
    (energy, length)
}

#[test]
fn piecewise_cubic_energy_matches_segmentwise_quadrature() {
    let pentagon = vec![
        DVec2::new(0.0, 0.0),
        DVec2::new(3.0, 1.0),
        DVec2::new(4.0, 4.0),
        DVec2::new(1.0, 5.0),
        DVec2::new(-1.0, 2.0),
    ];
    for config in [HobbyOptions::closed(), HobbyOptions::open()] {
        let curve = HobbyCurve::new(pentagon.clone(), &config);
        let (energy, length) = segmentwise(&curve);
        // Sample counts that do and do not put samples on the knots.
        for samples in [20, 37, 400] {
            let f = fairness(&curve, &pentagon, samples).unwrap();
            assert!(
                (f.bending_energy - energy).abs() < 1e-10 * energy,
                "closed = {}, {samples} samples: {} vs {energy}",
                config.closed,
                f.bending_energy
            );
            assert!((f.length - length).abs() < 1e-11 * length, "{} vs {length}", f.length);
            let confinement = f.confinement.unwrap();
            assert!(confinement > 1.0, "the curve bulges out of the pentagon: {confinement}");
        }
    }
}

#[test]
fn hobby_heptagon_curvature_has_four_extrema_per_segment() {
    // Regular heptagon: by symmetry κ is continuous at the knots and even about each segment's
    // middle. It has minima at the knots (0.99755) and at the middles (0.99936), maxima
    // (1.00087) near a fifth of the way in from each end: 28 monotone pieces. The energy is
    // close to the circle's 2π.
    let points: Vec<DVec2> = (0..7).map(|k| DVec2::from_angle(TAU * k as f64 / 7.0)).collect();
    let curve = HobbyCurve::new(points.clone(), &HobbyOptions::closed());
    let f = fairness(&curve, &points, 7 * 64).unwrap();
    assert_eq!(f.monotone_pieces, 28, "{f:?}");
    assert!((f.bending_energy - TAU).abs() < 1e-3 * TAU, "{f:?}");
    assert!((f.length - TAU).abs() < 1e-3 * TAU, "{f:?}");
    let (energy, length) = segmentwise(&curve);
    assert!((f.bending_energy - energy).abs() < 1e-10 * energy);
    assert!((f.length - length).abs() < 1e-11 * length);
}

#[test]
fn straight_curve_has_no_bending_and_no_confinement() {
    let points = vec![DVec2::ZERO, DVec2::new(1.0, 1.0), DVec2::new(3.0, 3.0)];
    let curve = ChaikinCurve::new(points.clone(), false);
    let f = fairness(&curve, &points, 101).unwrap();
    assert_eq!(f.max_curvature, 0.0);
    assert_eq!(f.monotone_pieces, 1);
    assert!(f.bending_energy.abs() < 1e-20);
    // The documented accuracy: 10⁻¹² relative.
    assert!((f.length - 3.0 * 2f64.sqrt()).abs() < 1e-12 * f.length, "{}", f.length);
    assert_eq!(f.confinement, None);
    let (energy, length) = bending_energy(&curve, 11).unwrap();
    assert!(energy.abs() < 1e-20 && (length - f.length).abs() < 2e-12 * length);
}

#[test]
fn rejects_bad_input() {
    let circle = Ellipse { a: 1.0, b: 1.0, phase: 0.0 };
    assert!(matches!(
        fairness(&circle, &[DVec2::X], 2),
        Err(Error::Curve(CurveError::InvalidCount { value: 2, .. }))
    ));
    assert_eq!(fairness(&circle, &[], 100), Err(Error::Curve(CurveError::Empty)));
    assert_eq!(
        fairness(&circle, &[DVec2::NAN], 100),
        Err(Error::Curve(CurveError::NonFinitePoint { index: 0 }))
    );
    assert!(curvature_plot(&circle, 1).is_err());
    // A single point: no hull, no confinement.
    assert_eq!(fairness(&circle, &[DVec2::X], 100).unwrap().confinement, None);
}

/// A helix (r cos 2πt, r sin 2πt, h t): κ = r/(r² + c²), τ = c/(r² + c²) with c = h/2π.
struct Helix {
    r: f64,
    h: f64,
}

impl ParamCurve<DVec3> for Helix {
    fn eval(&self, t: f64) -> DVec3 {
        self.eval_deriv(t, 0)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> DVec3 {
        let angle = TAU * t + order as f64 * FRAC_PI_2;
        let scale = self.r * TAU.powi(order as i32);
        let z = match order {
            0 => self.h * t,
            1 => self.h,
            _ => 0.0,
        };
        DVec3::new(scale * angle.cos(), scale * angle.sin(), z)
    }

    fn scale(&self) -> f64 {
        self.r
    }

    fn is_periodic(&self) -> bool {
        false
    }
}

#[test]
fn helix_curvature_and_torsion_plots_are_constant() {
    let helix = Helix { r: 2.0, h: 3.0 };
    let c = 3.0 / TAU;
    let plot = space_curvature_plot(&helix, 9).unwrap();
    assert_eq!(plot.len(), 9);
    assert_eq!((plot[0].t, plot[8].t), (0.0, 1.0));
    for s in plot {
        assert!((s.curvature.unwrap() - 2.0 / (4.0 + c * c)).abs() < 1e-14);
        assert!((s.torsion.unwrap() - c / (4.0 + c * c)).abs() < 1e-14);
    }
}

#[test]
fn monotone_pieces_wraps_around_periodic_samples() {
    // One bump starting mid-rise: open sees rise, fall, rise; the cycle has one max, one min.
    let values: Vec<f64> = (0..100).map(|j| (TAU * j as f64 / 100.0 + 1.0).sin()).collect();
    assert_eq!(monotone_pieces(&values, false, 1e-9), 3);
    assert_eq!(monotone_pieces(&values, true, 1e-9), 2);
    // Noise of 1e-12 on a constant is one piece; with zero tolerance it is many.
    let noisy: Vec<f64> = (0..50).map(|j| 1.0 + 1e-12 * ((j * 7919) % 13) as f64).collect();
    assert_eq!(monotone_pieces(&noisy, true, 1e-9), 1);
    assert!(monotone_pieces(&noisy, true, 0.0) > 10);
}

/// Near a cusp κ² ds is sharply peaked (and at a true cusp not integrable); the quadrature
/// must end in its budget, and here, where κ stays finite, converge.
#[test]
fn a_near_cusp_ends_and_converges() {
    // The harmonic curve through these five points (the pentagon of the figures) has a
    // near-cusp, |κ| about 10⁶.
    let pentagon: Vec<DVec2> = [[0.0, 2.0], [-1.7, 0.3], [-0.9, -1.5], [1.1, -1.4], [0.8, -0.6]]
        .map(DVec2::from_array)
        .to_vec();
    let f = fairness(&HarmonicCurve::new(pentagon.clone()), &pentagon, 4096).unwrap();
    assert!(f.max_curvature > 1e5, "{}", f.max_curvature);
    assert!(f.bending_energy.is_finite());
    assert!(f.bending_energy_error < 1e-9 * f.bending_energy, "{f:?}");
    let circle = vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
    let smooth = fairness(&HarmonicCurve::new(circle.clone()), &circle, 4096).unwrap();
    assert!(smooth.bending_energy_error < 1e-11, "{}", smooth.bending_energy_error);
    eprintln!(
        "near-cusp: max |κ| {:e}, energy {:e} ± {:e}",
        f.max_curvature, f.bending_energy, f.bending_energy_error
    );
}
