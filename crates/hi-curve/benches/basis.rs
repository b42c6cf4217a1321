// SPDX-License-Identifier: MIT
//! Benchmarks of the four evaluation forms of σⁿₖ and of all n values at once.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use hi_curve::{Form, Sigma};

fn forms(c: &mut Criterion) {
    let mut group = c.benchmark_group("sigma_one_value");
    for n in [7usize, 64, 1024] {
        let sigma = Sigma::new(n);
        for form in Form::ALL {
            group.bench_with_input(BenchmarkId::new(format!("{form:?}"), n), &n, |b, _| {
                b.iter(|| sigma.eval_form(form, black_box(3), black_box(0.123_456)))
            });
        }
        group.bench_with_input(BenchmarkId::new("Derivative2", n), &n, |b, _| {
            b.iter(|| sigma.deriv(black_box(3), black_box(0.123_456), 2))
        });
    }
    group.finish();

    let mut group = c.benchmark_group("sigma_all_values");
    for n in [7usize, 64, 1024, 4096] {
        let sigma = Sigma::new(n);
        let mut out = Vec::new();
        group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| sigma.values_into(black_box(0.123_456), &mut out))
        });
    }
    group.finish();
}

criterion_group!(benches, forms);
criterion_main!(benches);
