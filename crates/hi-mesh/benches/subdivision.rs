// SPDX-License-Identifier: MIT
//! Subdivision throughput (Hardy 2005, §4.5, Table 4.1): one step of each scheme on a closed
//! mesh of at least 100 000 faces, in steps per second (criterion reports the time per step;
//! the throughput is in input faces per second).
//!
//! Inputs: the star after five Loop steps and two √3 steps (24·4⁵·9 = 221 184 triangles),
//! and the star after seven Catmull-Clark steps (72·4⁶ = 294 912 quads).

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use hi_mesh::subdivision::{LoopWeights, PolyMesh, Scheme};

/// The star after five Loop steps and two √3 steps: 24·4⁵·9 = 221 184 triangles.
fn triangle_input() -> PolyMesh {
    let m = Scheme::Loop(LoopWeights::Loop).steps(&PolyMesh::star(), 5).expect("Loop");
    Scheme::Sqrt3.steps(&m, 2).expect("√3")
}

/// The star after seven Catmull-Clark steps: 72 quads after the first, 72·4⁶ = 294 912.
fn quad_input() -> PolyMesh {
    Scheme::CatmullClark.steps(&PolyMesh::star(), 7).expect("CC")
}

fn subdivision_benches(c: &mut Criterion) {
    let tri = triangle_input();
    let quad = quad_input();
    assert!(tri.n_faces() >= 100_000 && quad.n_faces() >= 100_000, "inputs are large enough");
    let mut group = c.benchmark_group("subdivision step");
    group.sample_size(10);
    for scheme in Scheme::ALL {
        let inputs: &[(&str, &PolyMesh)] = match scheme {
            Scheme::CatmullClark | Scheme::DooSabin => &[("triangles", &tri), ("quads", &quad)],
            _ => &[("triangles", &tri)],
        };
        for &(kind, mesh) in inputs {
            group.throughput(Throughput::Elements(mesh.n_faces() as u64));
            let id = format!("{} on {} {kind}", scheme.name(), mesh.n_faces());
            group.bench_function(id, |b| b.iter(|| scheme.step(black_box(mesh)).expect("step")));
        }
    }
    group.bench_function(format!("build PolyMesh of {} triangles", tri.n_faces()), |b| {
        let faces: Vec<Vec<u32>> = tri.faces().map(<[u32]>::to_vec).collect();
        b.iter(|| PolyMesh::try_new(tri.positions().to_vec(), black_box(&faces)).expect("valid"));
    });
    group.finish();
}

criterion_group!(benches, subdivision_benches);
criterion_main!(benches);
