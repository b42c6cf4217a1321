// SPDX-License-Identifier: MIT
//! Benchmarks of Bézier curves: evaluation throughput by degree, split (Theorem 2.2),
//! flattening to a tolerance (eq. 2.7 / convex hull test) and the tight bounding box.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec2;
use hi_bezier::{Bernstein, BezierCurve, RationalBezierCurve};

/// A wiggly plane curve of degree n with control points on a zig-zag.
fn curve(n: usize) -> BezierCurve<DVec2> {
    BezierCurve::new(
        (0..=n).map(|i| DVec2::new(i as f64, if i % 2 == 0 { 0.0 } else { 1.0 })).collect(),
    )
}

fn evaluation(c: &mut Criterion) {
    let mut group = c.benchmark_group("curve_eval");
    const N_PARAMS: usize = 256;
    group.throughput(Throughput::Elements(N_PARAMS as u64));
    for n in [1usize, 3, 5, 10, 20, 50] {
        let bez = curve(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                let mut acc = DVec2::ZERO;
                for i in 0..N_PARAMS {
                    acc += bez.eval(black_box(i as f64 / N_PARAMS as f64));
                }
                acc
            })
        });
    }
    group.finish();

    let mut group = c.benchmark_group("curve_eval_deriv1");
    for n in [3usize, 10, 50] {
        let bez = curve(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| bez.eval_deriv(black_box(0.37), 1))
        });
    }
    group.finish();

    let mut group = c.benchmark_group("bernstein_values");
    for n in [3usize, 20, 200] {
        let basis = Bernstein::new(n);
        let mut out = Vec::new();
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| basis.values_into(black_box(0.37), &mut out))
        });
    }
    group.finish();

    let arc = RationalBezierCurve::circle_arc(DVec2::ZERO, 1.0, 0.0, 2.0).expect("valid arc");
    c.bench_function("rational_arc_eval", |b| b.iter(|| arc.eval(black_box(0.37))));
}

fn split(c: &mut Criterion) {
    let mut group = c.benchmark_group("curve_split");
    for n in [3usize, 10, 50] {
        let bez = curve(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| bez.split(black_box(0.37)))
        });
    }
    group.finish();
}

fn flatten(c: &mut Criterion) {
    let mut group = c.benchmark_group("curve_flatten");
    for tolerance in [1e-2, 1e-4, 1e-6] {
        let bez = curve(3);
        group.bench_with_input(BenchmarkId::new("cubic", tolerance), &tolerance, |b, &tol| {
            b.iter(|| bez.flatten(black_box(tol)).expect("valid tolerance").len())
        });
    }
    let bez = curve(10);
    group.bench_function("degree10/1e-4", |b| {
        b.iter(|| bez.flatten(black_box(1e-4)).expect("valid tolerance").len())
    });
    group.finish();

    let mut group = c.benchmark_group("curve_bounding_box");
    for n in [3usize, 10] {
        let bez = curve(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| black_box(&bez).bounding_box())
        });
    }
    group.finish();
}

criterion_group!(benches, evaluation, split, flatten);
criterion_main!(benches);
