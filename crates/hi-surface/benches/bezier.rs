// SPDX-License-Identifier: MIT
//! Bézier conversion (§5.7): the time to turn a harmonic surface into patches, per scheme, with
//! the throughput in patches per second (criterion's elements), the deviation measurement and
//! the bound included.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::DVec3;
use hi_curve::bezier::{BezierScheme, HermiteDegree};
use hi_surface::HarmonicSurface;
use hi_surface::bezier::Tolerance;

/// A bumpy closed m×m surface (a torus with a ripple), like a fitted geometry image.
fn bumpy(m: usize) -> HarmonicSurface<DVec3> {
    let rows = (0..m)
        .map(|j| {
            (0..m)
                .map(|k| {
                    let (u, v) = (j as f64 / m as f64, k as f64 / m as f64);
                    let (tu, tv) = (std::f64::consts::TAU * u, std::f64::consts::TAU * v);
                    let r = 1.0 + 0.2 * (5.0 * tu).sin() * (3.0 * tv).cos();
                    DVec3::new(
                        (3.0 + r * tv.cos()) * tu.cos(),
                        (3.0 + r * tv.cos()) * tu.sin(),
                        r * tv.sin(),
                    )
                })
                .collect()
        })
        .collect();
    HarmonicSurface::new(rows)
}

fn bezier_benches(c: &mut Criterion) {
    let mut group = c.benchmark_group("bezier conversion");
    group.sample_size(10);
    for m in [16usize, 64] {
        let surface = bumpy(m);
        for (scheme, tolerance) in [
            (BezierScheme::ThesisCubic, hi_surface::bezier::DEFAULT_TOLERANCE),
            (BezierScheme::Hermite(HermiteDegree::Cubic), Tolerance::Absolute(1e-3)),
            (BezierScheme::Hermite(HermiteDegree::Quintic), Tolerance::Absolute(1e-3)),
        ] {
            let patches = surface.to_bezier(scheme, tolerance).expect("converts").report.patches;
            group.throughput(Throughput::Elements(patches as u64));
            let id = format!("{} {m}x{m} ({patches} patches)", scheme.name());
            group.bench_function(id, |b| {
                b.iter(|| surface.to_bezier(black_box(scheme), tolerance).expect("converts"));
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bezier_benches);
criterion_main!(benches);
