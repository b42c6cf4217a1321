// SPDX-License-Identifier: MIT
//! Uniform sampling of a harmonic curve at N = 16n points: the thesis's direct sum, O(nN),
//! against the FFT path, O(N log N) (docs/math.md §7), for n = 64 … 4096; and, in the same run, the
//! independent peer `scipy.signal.resample` (which computes the same samples) when Python with
//! scipy is installed, reported as a ratio.

use std::hint::black_box;
use std::io::Write;
use std::process::{Command, Stdio};
use std::time::Instant;

use criterion::{BenchmarkId, Criterion, criterion_group};
use glam::DVec2;
use hi_curve::HarmonicCurve;

const SIZES: [usize; 4] = [64, 256, 1024, 4096];

fn points(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|k| {
            DVec2::new((k as f64 * 0.37).sin() * 3.0, (k as f64 * 1.3).cos() + 0.01 * k as f64)
        })
        .collect()
}

fn sampling(c: &mut Criterion) {
    let mut group = c.benchmark_group("sample_16n");
    group.sample_size(10);
    for n in SIZES {
        let curve = HarmonicCurve::new(points(n));
        group.bench_with_input(BenchmarkId::new("fft", n), &n, |b, &n| {
            b.iter(|| curve.sample_uniform(black_box(16 * n)).unwrap())
        });
        // The direct sum is O(16n²): about 10 s per run at n = 4096.
        group.bench_with_input(BenchmarkId::new("direct", n), &n, |b, &n| {
            b.iter(|| hi_curve::testing::sample_uniform_direct(&curve, black_box(16 * n)).unwrap())
        });
    }
    group.finish();
}

/// Median wall time of `f` over `reps` runs, in seconds.
fn median_time(reps: usize, mut f: impl FnMut()) -> f64 {
    let mut times: Vec<f64> = (0..reps)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[reps / 2]
}

/// Times scipy.signal.resample on the same data (2-D, n points to 16n) in one Python process.
fn scipy_times() -> Option<Vec<f64>> {
    let script = r#"
import json, sys, timeit
import numpy as np, scipy.signal
out = []
for n in json.load(sys.stdin):
    k = np.arange(n)
    x = np.stack([np.sin(k * 0.37) * 3.0, np.cos(k * 1.3) + 0.01 * k], axis=1)
    t = timeit.repeat(lambda: scipy.signal.resample(x, 16 * n, axis=0), number=1, repeat=21)
    out.append(sorted(t)[10])
print(json.dumps(out))
"#;
    let mut child = Command::new("python3")
        .args(["-c", script])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    child.stdin.take()?.write_all(format!("{SIZES:?}").as_bytes()).ok()?;
    let output = child.wait_with_output().ok()?;
    if !output.status.success() {
        return None;
    }
    let text = String::from_utf8(output.stdout).ok()?;
    text.trim().trim_matches(['[', ']']).split(',').map(|v| v.trim().parse().ok()).collect()
}

fn peer_table() {
    let Some(scipy) = scipy_times() else {
        println!("\nscipy.signal.resample: not measured (python3 with scipy is not installed)");
        return;
    };
    println!("\nSampling n 2-D points at 16n points, median of 21 runs (same machine, same run):");
    println!("{:>6} {:>14} {:>14} {:>14}", "n", "hi-curve FFT", "scipy", "scipy / ours");
    for (n, scipy) in SIZES.iter().zip(scipy) {
        let curve = HarmonicCurve::new(points(*n));
        let ours = median_time(21, || {
            black_box(curve.sample_uniform(16 * n).unwrap());
        });
        println!("{n:>6} {:>12.1}µs {:>12.1}µs {:>14.2}", ours * 1e6, scipy * 1e6, scipy / ours);
    }
}

criterion_group!(benches, sampling);

fn main() {
    benches();
    peer_table();
    Criterion::default().configure_from_args().final_summary();
}
