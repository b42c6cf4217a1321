// SPDX-License-Identifier: MIT
//! `cargo xtask bench curves`: uniform sampling of a harmonic curve through n points at N = 16n
//! parameters, by the thesis's direct sum of the basis (O(nN), the baseline), by our FFT path
//! (spectral zero-padding, O(N log N), docs/math.md §7) and by `scipy.signal.resample`, which
//! computes the same samples (checked in `crates/hi-curve/tests/peer_scipy.rs`), in one run,
//! for n = 16 … 16 384; and how each grows with n, on log axes (`docs/perf-curves.svg`).
//! The peer runs through `xtask/peers/curve_peers.py`.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use glam::DVec2;
use hi_curve::HarmonicCurve;

use super::{
    Growth, Headline, Section, growth_plot, machine, median_time, ms, progress_bar, ratio, table,
};

/// Curve sizes n (samples N = 16n): powers of 4 and the odd size after each (the harmonic
/// basis of §2.3 differs for odd and even n, and so does the FFT's length).
const SIZES: [usize; 12] = [16, 17, 64, 65, 256, 257, 1024, 1025, 4096, 4097, 16_384, 16_385];
/// The largest n whose direct sum is timed (about 10 s per run at 4096; 16 times that at the
/// next size).
const DIRECT_MAX: usize = 4096;
/// From this n on, the direct sum is timed once, without a warm-up.
const DIRECT_ONCE: usize = 1024;
/// Timed runs of each measurement (after a warm-up).
const RUNS: usize = 7;
/// Samples per data point.
const FACTOR: usize = 16;

/// The data of the peer script: xₖ = (3 sin 0.37k, cos 1.3k + 0.01k) (also the curve of
/// [`super::batch`]'s Python calls).
pub(super) fn points(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|k| {
            let k = k as f64;
            DVec2::new((k * 0.37).sin() * 3.0, (k * 1.3).cos() + 0.01 * k)
        })
        .collect()
}

/// scipy's median times per size; `Ok(None)` when scipy is not installed.
fn scipy(root: &Path) -> Result<Option<Vec<Duration>>> {
    let script = root.join("xtask/peers/curve_peers.py");
    let mut cmd = Command::new("python3");
    cmd.arg(&script).arg(RUNS.to_string()).args(SIZES.iter().map(ToString::to_string));
    let Ok(out) = cmd.output() else { return Ok(None) };
    if out.status.code() == Some(3) {
        return Ok(None);
    }
    if !out.status.success() {
        bail!("{}: {}", script.display(), String::from_utf8_lossy(&out.stderr).trim());
    }
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).context("the peer's JSON")?;
    let times = v["seconds"]
        .as_array()
        .context("no \"seconds\" in the peer's JSON")?
        .iter()
        .map(|t| t.as_f64().map(Duration::from_secs_f64).context("a time that is not a number"))
        .collect::<Result<Vec<_>>>()?;
    if times.len() != SIZES.len() {
        bail!("the peer timed {} sizes, not {}", times.len(), SIZES.len());
    }
    Ok(Some(times))
}

/// Measures every size and returns the report's section.
pub(super) fn run(root: &Path) -> Result<Section> {
    let bar = progress_bar(SIZES.len() as u64 + 1)?;
    bar.set_message("scipy.signal.resample");
    let theirs = scipy(root)?;
    bar.inc(1);
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    let (mut fft_growth, mut direct_growth, mut scipy_growth) =
        (Vec::new(), Vec::new(), Vec::new());
    let mut rows = Vec::new();
    let mut headlines = Vec::new();
    for (i, &n) in SIZES.iter().enumerate() {
        bar.set_message(format!("n = {n}"));
        let curve = HarmonicCurve::try_new(points(n))?;
        let samples = FACTOR * n;
        let fft = one.install(|| {
            median_time(RUNS, || {
                std::hint::black_box(curve.sample_uniform(samples)?);
                Ok(())
            })
        })?;
        // The growth plot follows the even sizes (the odd ones sit beside them).
        let even = n % 2 == 0;
        if even {
            fft_growth.push((n as f64, fft));
        }
        let direct = if n <= DIRECT_MAX {
            let t = time_direct(&one, &curve, n, samples)?;
            if even {
                direct_growth.push((n as f64, t));
            }
            Some(t)
        } else {
            None
        };
        // The two paths compute the same samples: the largest difference, relative to the
        // largest coordinate.
        // (At 1024 and 1025: the direct sum takes about a second.)
        let agreement =
            if n <= DIRECT_ONCE + 1 { agreement(&curve, samples)? } else { "–".to_owned() };
        let peer = theirs.as_ref().map(|t| t[i]);
        if let (Some(t), true) = (peer, even) {
            scipy_growth.push((n as f64, t));
        }
        rows.push(vec![
            n.to_string(),
            samples.to_string(),
            direct.map_or_else(|| "not run".to_owned(), ms),
            ms(fft),
            direct.map_or_else(|| "–".to_owned(), |d| ratio(d, fft)),
            peer.map_or_else(|| "scipy not installed".to_owned(), ms),
            peer.map_or_else(|| "–".to_owned(), |t| ratio(t, fft)),
            agreement,
        ]);
        if n == 1024 || n == 1025 {
            headlines.push(Headline {
                what: format!("harmonic curve, {n} points sampled at {samples}"),
                ours: fft,
                peer: "the thesis's direct sum".to_owned(),
                theirs: direct,
            });
            headlines.push(Headline {
                what: format!("harmonic curve, {n} points sampled at {samples}"),
                ours: fft,
                peer: "`scipy.signal.resample`".to_owned(),
                theirs: peer,
            });
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let series = [
        Growth { name: "FFT (ours)".to_owned(), points: fft_growth },
        Growth { name: "direct sum (thesis)".to_owned(), points: direct_growth },
        Growth { name: "scipy.signal.resample".to_owned(), points: scipy_growth },
    ];
    let plot = growth_plot(
        root,
        "perf-curves.svg",
        "Sampling a harmonic curve through n points at 16n parameters",
        "n",
        &series,
    )?;
    let body = body(&rows, &plot);
    Ok(Section { body, headlines, sub_headlines: Vec::new() })
}

/// The direct sum's time at `n` points and `samples` samples on the pool `one`: timed once
/// from [`DIRECT_ONCE`], else the median of [`RUNS`] after a warm-up.
fn time_direct(
    one: &rayon::ThreadPool,
    curve: &HarmonicCurve<DVec2>,
    n: usize,
    samples: usize,
) -> Result<Duration> {
    Ok(if n >= DIRECT_ONCE {
        let start = Instant::now();
        std::hint::black_box(
            one.install(|| hi_curve::testing::sample_uniform_direct(curve, samples))?,
        );
        start.elapsed()
    } else {
        one.install(|| {
            median_time(RUNS, || {
                std::hint::black_box(hi_curve::testing::sample_uniform_direct(curve, samples)?);
                Ok(())
            })
        })?
    })
}

/// The largest difference between the FFT's and the direct sum's samples, relative to the
/// largest coordinate, as a cell ("3.1e-15").
fn agreement(curve: &HarmonicCurve<DVec2>, samples: usize) -> Result<String> {
    let (a, b) =
        (curve.sample_uniform(samples)?, hi_curve::testing::sample_uniform_direct(curve, samples)?);
    let scale = a.iter().map(|p| p.abs().max_element()).fold(0.0, f64::max);
    let diff = a.iter().zip(&b).map(|(p, q)| (*p - *q).abs().max_element());
    Ok(format!("{:.1e}", diff.fold(0.0, f64::max) / scale))
}

/// The section's text around its table of `rows` and its growth `plot`.
fn body(rows: &[Vec<String>], plot: &str) -> String {
    format!(
        "## Harmonic curves (§2.3, docs/math.md §7)\n\n\
         Machine: {}.\n\n\
         A planar harmonic curve through n points xₖ = (3 sin 0.37k, cos 1.3k + 0.01k), sampled \
         at N = {FACTOR}n uniform parameters on one thread: by the thesis's direct sum of the \
         Dirichlet-kernel basis (`hi_curve::testing::sample_uniform_direct`, O(nN); timed once, \
         without a warm-up, from n = {DIRECT_ONCE}, and not run past n = {DIRECT_MAX}), by our \
         FFT path (`HarmonicCurve::sample_uniform`, O(N log N)), and by `scipy.signal.resample` \
         on the same points, which computes the same samples. Medians of {RUNS} runs after a \
         warm-up, in ms. The last column is the largest difference between the direct and FFT \
         samples over the largest coordinate. The growth plot follows the even n. The thesis gives \
         no timings for curves.\n\n{}\n{}",
        machine(),
        table(
            &[
                "n",
                "samples N",
                "direct sum (ms)",
                "FFT (ms)",
                "direct / FFT",
                "scipy (ms)",
                "scipy / FFT",
                "largest direct − FFT difference",
            ],
            rows,
        ),
        plot
    )
}
