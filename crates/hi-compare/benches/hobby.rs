// SPDX-License-Identifier: MIT
//! Hobby's algorithm (Hardy 2005, §2.14): set-up (the O(n) mock-curvature solve) and
//! evaluation throughput of METAPOST curves.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec2;
use hi_compare::hobby::{HobbyCurve, HobbyOptions, Tension};
use hi_curve::ParamCurve;

fn points(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            DVec2::new(a.cos() * (1.0 + 0.3 * (3.0 * a).sin()), a.sin())
        })
        .collect()
}

fn hobby(c: &mut Criterion) {
    let configs = [
        ("closed", HobbyOptions::closed()),
        ("open", HobbyOptions::open()),
        ("closed_atleast", HobbyOptions::closed().with_tension(Tension::at_least(1.2))),
    ];
    let mut group = c.benchmark_group("hobby_setup");
    for n in [8usize, 64, 512, 4096] {
        group.throughput(Throughput::Elements(n as u64));
        for (name, config) in &configs {
            let pts = points(n);
            group.bench_with_input(BenchmarkId::new(*name, n), &n, |b, _| {
                b.iter(|| HobbyCurve::try_new(black_box(pts.clone()), config).unwrap())
            });
        }
    }
    group.finish();

    let mut group = c.benchmark_group("hobby_eval");
    let n_evals = 1024;
    group.throughput(Throughput::Elements(n_evals as u64));
    for n in [8usize, 512] {
        let curve = HobbyCurve::new(points(n), &HobbyOptions::closed());
        let ts: Vec<f64> = (0..n_evals).map(|i| i as f64 / n_evals as f64).collect();
        group.bench_with_input(BenchmarkId::new("eval", n), &n, |b, _| {
            b.iter(|| ts.iter().map(|&t| curve.eval(black_box(t))).fold(DVec2::ZERO, |a, p| a + p))
        });
        group.bench_with_input(BenchmarkId::new("curvature", n), &n, |b, _| {
            b.iter(|| ts.iter().filter_map(|&t| curve.curvature(black_box(t))).sum::<f64>())
        });
        let bezier = curve.to_bezier();
        group.bench_with_input(BenchmarkId::new("piecewise_bezier_eval", n), &n, |b, _| {
            b.iter(|| ts.iter().map(|&t| bezier.eval(black_box(t))).fold(DVec2::ZERO, |a, p| a + p))
        });
    }
    group.finish();
}

criterion_group!(benches, hobby);
criterion_main!(benches);
