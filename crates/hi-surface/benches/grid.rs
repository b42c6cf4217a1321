// SPDX-License-Identifier: MIT
//! Grid evaluation of a harmonic surface with 64×64 control points: the direct sum of the
//! thesis, separable basis matrices, and the 2-D FFT, for 128² … 1024² samples.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use glam::DVec3;
use hi_surface::HarmonicSurface;

fn surface() -> HarmonicSurface<DVec3> {
    let grid = (0..64)
        .map(|j| {
            (0..64)
                .map(|k| {
                    let (a, b) = (j as f64 * 0.098, k as f64 * 0.098);
                    DVec3::new(
                        (a.cos() + 2.0) * b.cos(),
                        (a.cos() + 2.0) * b.sin(),
                        a.sin() + 0.05 * ((j * k) % 7) as f64,
                    )
                })
                .collect()
        })
        .collect();
    HarmonicSurface::new(grid)
}

fn grids(c: &mut Criterion) {
    let s = surface();
    let mut group = c.benchmark_group("surface_grid_64x64");
    group.sample_size(10);
    for res in [128usize, 256, 512, 1024] {
        let params: Vec<f64> = (0..res).map(|i| i as f64 / res as f64).collect();
        group.bench_with_input(BenchmarkId::new("fft", res), &res, |b, &res| {
            b.iter(|| s.sample_uniform(black_box(res), res, 0, 0).unwrap())
        });
        group.bench_with_input(BenchmarkId::new("separable", res), &res, |b, _| {
            b.iter(|| s.sample_params(black_box(&params), &params, 0, 0).unwrap())
        });
        // The direct sum is O(res²·64²): about 4·10⁹ multiply–adds at 1024².
        if res <= 512 {
            group.bench_with_input(BenchmarkId::new("direct", res), &res, |b, _| {
                b.iter(|| {
                    hi_surface::testing::sample_params_direct(&s, black_box(&params), &params)
                        .unwrap()
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, grids);
criterion_main!(benches);
