// SPDX-License-Identifier: MIT
//! The cost of rigour: interval operations per second against the same operations on `f64`.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use hi_interval::Interval;

const N: usize = 1024;

fn inputs() -> (Vec<f64>, Vec<Interval>) {
    let xs: Vec<f64> = (0..N).map(|i| 0.1 + 3.7 * (i as f64 * 0.618_034).fract()).collect();
    let ivs = xs.iter().map(|&x| Interval::new(x, x + 1e-3)).collect();
    (xs, ivs)
}

fn ops(c: &mut Criterion) {
    let (xs, ivs) = inputs();
    let mut group = c.benchmark_group("ops");
    group.throughput(Throughput::Elements(N as u64));
    macro_rules! pair {
        ($name:literal, $f:expr, $g:expr) => {
            group.bench_function(concat!($name, "/f64"), |b| {
                b.iter(|| xs.windows(2).map(|w| $f(black_box(w[0]), black_box(w[1]))).sum::<f64>())
            });
            group.bench_function(concat!($name, "/interval"), |b| {
                b.iter(|| {
                    ivs.windows(2)
                        .map(|w| $g(black_box(w[0]), black_box(w[1])))
                        .fold(0.0, |s, v: Interval| s + v.hi())
                })
            });
        };
    }
    pair!("add", |a: f64, b: f64| a + b, |a: Interval, b: Interval| a + b);
    pair!("mul", |a: f64, b: f64| a * b, |a: Interval, b: Interval| a * b);
    pair!("div", |a: f64, b: f64| a / b, |a: Interval, b: Interval| a / b);
    pair!("sqrt", |a: f64, _b: f64| a.sqrt(), |a: Interval, _b: Interval| a.sqrt());
    pair!("sin", |a: f64, _b: f64| a.sin(), |a: Interval, _b: Interval| a.sin());
    pair!("cos", |a: f64, _b: f64| a.cos(), |a: Interval, _b: Interval| a.cos());
    pair!("exp", |a: f64, _b: f64| a.exp(), |a: Interval, _b: Interval| a.exp());
    pair!("powi5", |a: f64, _b: f64| a.powi(5), |a: Interval, _b: Interval| a.powi(5));
    group.finish();
}

criterion_group!(benches, ops);
criterion_main!(benches);
