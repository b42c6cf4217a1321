// SPDX-License-Identifier: MIT
//! Benchmarks of Bézier patches: tensor-product evaluation by degree, partial derivatives,
//! rational (sphere octant) and triangular evaluation.

use std::f64::consts::FRAC_PI_2;
use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::{DVec2, DVec3};
use hi_bezier::{BezierPatch, RationalBezierCurve, RationalBezierPatch, TriangularPatch};

/// A bumpy patch of degree (n, n).
fn patch(n: usize) -> BezierPatch<DVec3> {
    BezierPatch::try_from_fn(n, n, |j, k| {
        DVec3::new(j as f64, k as f64, ((j * 7 + k * 3) % 5) as f64 * 0.2)
    })
    .expect("finite points")
}

fn evaluation(c: &mut Criterion) {
    const GRID: usize = 16;
    let mut group = c.benchmark_group("patch_eval");
    group.throughput(Throughput::Elements((GRID * GRID) as u64));
    for n in [1usize, 3, 5, 10] {
        let p = patch(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                let mut acc = DVec3::ZERO;
                for i in 0..GRID {
                    for j in 0..GRID {
                        acc += p.eval(black_box(i as f64 / 15.0), black_box(j as f64 / 15.0));
                    }
                }
                acc
            })
        });
    }
    group.finish();

    let mut group = c.benchmark_group("patch_normal");
    for n in [3usize, 5] {
        let p = patch(n);
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| p.normal(black_box(0.3), black_box(0.6)))
        });
    }
    group.finish();

    let arc = RationalBezierCurve::circle_arc(DVec2::ZERO, 1.0, 0.0, FRAC_PI_2).expect("valid arc");
    let octant = RationalBezierPatch::revolve(&arc, &arc);
    c.bench_function("rational_patch_eval_sphere_octant", |b| {
        b.iter(|| octant.eval(black_box(0.3), black_box(0.6)))
    });

    let mut group = c.benchmark_group("triangle_eval");
    for n in [1usize, 3, 6] {
        let t = TriangularPatch::try_from_fn(n, |i, j, k| {
            DVec3::new(i as f64, j as f64, (k % 3) as f64)
        })
        .expect("finite points");
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| t.eval(black_box(0.2), black_box(0.3)))
        });
    }
    group.finish();

    let p = patch(3);
    c.bench_function("patch_split_u/3", |b| b.iter(|| p.split_u(black_box(0.4))));
}

criterion_group!(benches, evaluation);
criterion_main!(benches);
