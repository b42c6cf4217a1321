// SPDX-License-Identifier: MIT
//! Non-uniform interpolation: set-up and evaluation of both readings of §3.10.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use glam::DVec2;
use hi_curve::{NonUniformCurve, NonUniformVariant};

fn points(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            DVec2::new(a.cos() * (1.0 + 0.3 * (3.0 * a).sin()), a.sin())
        })
        .collect()
}

fn nonuniform(c: &mut Criterion) {
    let mut group = c.benchmark_group("nonuniform_setup");
    for n in [8usize, 32, 128] {
        for variant in [NonUniformVariant::Nodes, NonUniformVariant::Thesis] {
            group.bench_with_input(BenchmarkId::new(format!("{variant:?}"), n), &n, |b, &n| {
                b.iter(|| NonUniformCurve::try_new(black_box(points(n)), variant).unwrap())
            });
        }
    }
    group.finish();

    let mut group = c.benchmark_group("nonuniform_eval");
    for n in [8usize, 32, 128] {
        for variant in [NonUniformVariant::Nodes, NonUniformVariant::Thesis] {
            let curve = NonUniformCurve::try_new(points(n), variant).unwrap();
            group.bench_with_input(BenchmarkId::new(format!("{variant:?}"), n), &n, |b, _| {
                b.iter(|| curve.eval(black_box(0.123_456)))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, nonuniform);
criterion_main!(benches);
