// SPDX-License-Identifier: MIT
//! Rendering the torus of Hardy 2005, figure 5.26 (§5.6) at 64 × 64, one sample per pixel, by
//! interval Newton, interval bisection, Bézier patches and a triangle mesh; criterion's elements
//! are camera rays. The scene's preparation (spectrum, cell bounds, BVHs, Bézier conversion,
//! meshing) is measured apart.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use hi_raytrace::testing::{TorusMethod, torus_scene};
use hi_raytrace::{RenderOptions, render};

fn render_benches(c: &mut Criterion) {
    let mut group = c.benchmark_group("torus 64x64");
    group.sample_size(10);
    let settings =
        RenderOptions { width: 64, height: 64, samples_per_pixel: 1, tile_size: 16, first_pass: 0 };
    group.throughput(Throughput::Elements(64 * 64));
    for method in TorusMethod::ALL {
        let (scene, camera) = torus_scene(method).expect("the fixed torus scene is valid");
        group.bench_function(method.name(), |b| {
            b.iter(|| render(black_box(&scene), &camera, &settings, None).expect("valid settings"));
        });
    }
    group.finish();
    let mut group = c.benchmark_group("torus scene preparation");
    group.sample_size(10);
    for method in TorusMethod::ALL {
        group.bench_function(method.name(), |b| {
            b.iter(|| torus_scene(black_box(method)).expect("the fixed torus scene is valid"));
        });
    }
    group.finish();
}

criterion_group!(benches, render_benches);
criterion_main!(benches);
