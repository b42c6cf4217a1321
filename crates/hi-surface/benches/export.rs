// SPDX-License-Identifier: MIT
//! Mesh export throughput (§5.5): meshing a 512×512 torus (FFT grid path) and writing it as
//! `.glb` and OBJ to memory, in vertices per second.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use hi_mesh::{ColorMap, export};
use hi_surface::{CurvatureColoring, CurvatureQuantity, MeshOptions, torus};

fn export_benches(c: &mut Criterion) {
    let surface = torus(2.0, 0.5);
    let opts = MeshOptions { n_u: 512, n_v: 512, ..Default::default() };
    let mesh = surface.to_mesh(&opts).expect("torus mesh");
    let colored_opts = MeshOptions {
        color: Some(CurvatureColoring {
            quantity: CurvatureQuantity::Gaussian,
            map: ColorMap::default(),
        }),
        ..opts
    };
    let mut group = c.benchmark_group("torus 512x512");
    group.sample_size(10);
    group.throughput(Throughput::Elements(mesh.n_vertices() as u64));
    group.bench_function("mesh", |b| b.iter(|| black_box(&surface).to_mesh(&opts)));
    group.bench_function("mesh with curvature colours", |b| {
        b.iter(|| black_box(&surface).to_mesh(&colored_opts))
    });
    let mut out = Vec::new();
    group.bench_function("write glb", |b| {
        b.iter(|| {
            out.clear();
            export::write_glb(black_box(&mesh), &mut out).expect("glb");
        });
    });
    group.bench_function("write obj", |b| {
        b.iter(|| {
            out.clear();
            export::write_obj(black_box(&mesh), &mut out).expect("obj");
        });
    });
    group.bench_function("mesh and write glb", |b| {
        b.iter(|| {
            out.clear();
            let m = black_box(&surface).to_mesh(&opts).expect("mesh");
            export::write_glb(&m, &mut out).expect("glb");
        });
    });
    group.finish();
}

criterion_group!(benches, export_benches);
criterion_main!(benches);
