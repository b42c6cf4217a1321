// SPDX-License-Identifier: MIT
//! Evaluation throughput of the comparison curves of chapter 2 (Lagrange, Catmull-Rom,
//! Bessel-Overhauser, TCB, B-splines, NURBS, interpolating cubic B-splines), and the set-up cost
//! of cubic B-spline interpolation (one O(n) tridiagonal solve).

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec2;
use hi_compare::bspline::BSplineCurve;
use hi_compare::bspline_interp::{InterpolatingSpline, Parameters};
use hi_compare::cardinal::{Closure, HermiteSpline, Tcb};
use hi_compare::lagrange::LagrangeCurve;
use hi_compare::nurbs::NurbsCurve;
use hi_curve::ParamCurve;

/// Number of parameters evaluated per iteration.
const N_SAMPLES: usize = 1000;

fn points(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            DVec2::new(a.cos() * (1.0 + 0.3 * (3.0 * a).sin()), a.sin())
        })
        .collect()
}

/// Evaluates X and X′ at `N_SAMPLES` parameters in [0, 1].
fn sweep(curve: &dyn ParamCurve<DVec2>) -> DVec2 {
    let mut acc = DVec2::ZERO;
    for i in 0..N_SAMPLES {
        let t = black_box(i as f64 / N_SAMPLES as f64);
        acc += curve.eval(t) + curve.eval_deriv(t, 1);
    }
    acc
}

fn families(n: usize) -> Vec<(&'static str, Box<dyn ParamCurve<DVec2>>)> {
    let pts = points(n);
    let mut res: Vec<(&'static str, Box<dyn ParamCurve<DVec2>>)> = vec![
        (
            "catmull_rom",
            Box::new(HermiteSpline::catmull_rom(pts.clone(), Closure::Closed).unwrap()),
        ),
        (
            "bessel_overhauser",
            Box::new(HermiteSpline::bessel_overhauser(pts.clone(), Closure::Closed).unwrap()),
        ),
        (
            "tcb",
            Box::new(
                HermiteSpline::kochanek_bartels(
                    pts.clone(),
                    Closure::Closed,
                    Tcb::new(0.2, 0.1, -0.1),
                )
                .unwrap(),
            ),
        ),
        (
            "bspline_cubic_closed",
            Box::new(BSplineCurve::try_uniform_closed(3, pts.clone()).unwrap()),
        ),
        ("bspline_degree5_clamped", Box::new(BSplineCurve::try_clamped(5, pts.clone()).unwrap())),
        (
            "interpolating_periodic",
            Box::new(
                InterpolatingSpline::try_periodic(pts.clone(), Parameters::ChordLength).unwrap(),
            ),
        ),
        ("nurbs_circle", Box::new(NurbsCurve::circle(DVec2::ZERO, 1.0))),
    ];
    if n <= 16 {
        res.push(("lagrange", Box::new(LagrangeCurve::try_new(pts).unwrap())));
    }
    res
}

fn eval(c: &mut Criterion) {
    let mut group = c.benchmark_group("compare_eval");
    group.throughput(Throughput::Elements(N_SAMPLES as u64));
    for n in [16usize, 128] {
        for (name, curve) in families(n) {
            group.bench_with_input(BenchmarkId::new(name, n), &n, |b, _| {
                b.iter(|| sweep(curve.as_ref()))
            });
        }
    }
    group.finish();

    let mut group = c.benchmark_group("compare_interpolation_setup");
    for n in [16usize, 128, 1024] {
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::new("periodic_chord", n), &n, |b, &n| {
            let pts = points(n);
            b.iter(|| {
                InterpolatingSpline::try_periodic(black_box(pts.clone()), Parameters::ChordLength)
                    .unwrap()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, eval);
criterion_main!(benches);
