// SPDX-License-Identifier: MIT
//! End-to-end tests of `hi curve sample|fairness|to-bezier --kind KIND`: every comparison
//! curve checked against its formula written out here (the uniform cubic B-spline, the
//! Catmull-Rom tangents, Chaikin's quadratic B-spline, the 4-point rule, a parabola), against
//! METAPOST's own numbers, and the Bézier segments against the samples.

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use std::f64::consts::{FRAC_PI_2, PI};

use common::{TempFile, bad, bad_on, dist, json_points, num, ok, ok_on, points};
use serde_json::Value;

/// The irregular pentagon of docs/peers.md §1 and §2b.
fn pentagon() -> Vec<Vec<f64>> {
    vec![vec![0.0, 0.0], vec![3.0, 1.0], vec![4.0, 4.0], vec![1.0, 5.0], vec![-1.0, 2.0]]
}

const SQUARE: &str = "[[1,0],[0,1],[-1,0],[0,-1]]";

const ALL_KINDS: [&str; 12] = [
    "harmonic",
    "trig",
    "lagrange",
    "catmull-rom",
    "bessel-overhauser",
    "tcb",
    "bspline-periodic",
    "bspline-open",
    "hobby-closed",
    "hobby-open",
    "chaikin",
    "four-point",
];

/// The kinds whose curves are open (from the first point at t = 0 to the last at t = 1).
const OPEN_KINDS: [&str; 3] = ["lagrange", "bspline-open", "hobby-open"];

fn sample(input: &str, kind: &str, count: usize) -> Vec<Vec<f64>> {
    let count = count.to_string();
    points(&ok_on(input, &["curve", "sample", "--count", &count, "--kind", kind])["X"])
}

/// Solves the dense system a·x = b by Gaussian elimination with partial pivoting.
fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
    let n = b.len();
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
            .expect("a non-empty column");
        a.swap(col, pivot);
        b.swap(col, pivot);
        let pivot_row = a[col].clone();
        for row in col + 1..n {
            let f = a[row][col] / pivot_row[col];
            for (x, p) in a[row].iter_mut().zip(&pivot_row).skip(col) {
                *x -= f * p;
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = vec![0.0; n];
    for row in (0..n).rev() {
        let s: f64 = (row + 1..n).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x
}

/// Evaluates a Bézier curve of any degree by de Casteljau's algorithm.
fn de_casteljau(control: &[Vec<f64>], s: f64) -> Vec<f64> {
    let mut level = control.to_vec();
    while level.len() > 1 {
        level = level
            .windows(2)
            .map(|w| w[0].iter().zip(&w[1]).map(|(a, b)| (1.0 - s) * a + s * b).collect())
            .collect();
    }
    level.remove(0)
}

/// Evaluates a chain of Bézier segments at t ∈ [0, 1], segment i on [i/s, (i+1)/s].
fn eval_chain(segments: &[Vec<Vec<f64>>], t: f64) -> Vec<f64> {
    let s = segments.len();
    let u = t * s as f64;
    let i = (u.floor().max(0.0) as usize).min(s - 1);
    de_casteljau(&segments[i], u - i as f64)
}

fn segments(input: &str, kind: &str) -> Vec<Vec<Vec<f64>>> {
    let json = ok_on(input, &["curve", "to-bezier", "--kind", kind]);
    json["segments"].as_array().expect("an array of segments").iter().map(points).collect()
}

#[test]
fn harmonic_is_the_default_and_unchanged() {
    let file = TempFile::new(SQUARE);
    let plain = ok(&["curve", "sample", "--input", file.path(), "--count", "8"]);
    let named =
        ok(&["curve", "sample", "--input", file.path(), "--count", "8", "--kind", "harmonic"]);
    assert_eq!(plain, named, "--kind harmonic is the default");
    // The harmonic curve through the square is its circumcircle, X(t) = (cos 2πt, sin 2πt).
    for (l, p) in points(&plain["X"]).iter().enumerate() {
        let t = l as f64 / 8.0;
        assert!(dist(p, &[(2.0 * PI * t).cos(), (2.0 * PI * t).sin()]) < 1e-14, "sample {l}");
    }
}

#[test]
fn periodic_bspline_is_the_uniform_cubic_bspline_through_the_points() {
    // The control points c solve (cᵢ₋₁ + 4cᵢ + cᵢ₊₁)/6 = xᵢ (indices mod n); the curve on
    // [i/n, (i+1)/n] at local s is Σₖ cᵢ₋₁₊ₖ·Bₖ(s) with the uniform cubic B-spline blending
    // functions (§2.9).
    let pts = pentagon();
    let n = pts.len();
    let matrix: Vec<Vec<f64>> = (0..n)
        .map(|i| {
            let mut row = vec![0.0; n];
            row[(i + n - 1) % n] += 1.0 / 6.0;
            row[i] += 4.0 / 6.0;
            row[(i + 1) % n] += 1.0 / 6.0;
            row
        })
        .collect();
    let control: Vec<Vec<f64>> = {
        let xs = solve(matrix.clone(), pts.iter().map(|p| p[0]).collect());
        let ys = solve(matrix, pts.iter().map(|p| p[1]).collect());
        xs.into_iter().zip(ys).map(|(x, y)| vec![x, y]).collect()
    };
    let blend = |s: f64| {
        [
            (1.0 - s).powi(3) / 6.0,
            (3.0 * s * s * s - 6.0 * s * s + 4.0) / 6.0,
            (-3.0 * s * s * s + 3.0 * s * s + 3.0 * s + 1.0) / 6.0,
            s * s * s / 6.0,
        ]
    };
    let count = 40;
    let got = sample(&json_points(&pts), "bspline-periodic", count);
    assert_eq!(got.len(), count, "N samples");
    for (l, p) in got.iter().enumerate() {
        let u = l as f64 / count as f64 * n as f64;
        let i = u.floor() as usize;
        let b = blend(u - i as f64);
        let want: Vec<f64> =
            (0..2).map(|c| (0..4).map(|k| b[k] * control[(i + n - 1 + k) % n][c]).sum()).collect();
        assert!(dist(p, &want) < 1e-12, "sample {l}: {p:?} vs {want:?}");
    }
    // It interpolates: point k at t = k/n (count is a multiple of n).
    for (k, x) in pts.iter().enumerate() {
        assert!(dist(&got[k * count / n], x) < 1e-13, "point {k}");
    }
}

#[test]
fn catmull_rom_and_tcb_segments_have_the_central_difference_tangents() {
    // Closed Catmull-Rom (eq. 2.8): segment i is xᵢ, xᵢ + (xᵢ₊₁ − xᵢ₋₁)/6,
    // xᵢ₊₁ − (xᵢ₊₂ − xᵢ)/6, xᵢ₊₁; TCB with T = C = B = 0 is the same curve.
    let pts = pentagon();
    let n = pts.len();
    let at = |i: usize| &pts[i % n];
    let lin = |a: &[f64], b: &[f64], c: &[f64], w: f64| -> Vec<f64> {
        (0..2).map(|k| a[k] + w * (b[k] - c[k])).collect()
    };
    for kind in ["catmull-rom", "tcb"] {
        let segs = segments(&json_points(&pts), kind);
        assert_eq!(segs.len(), n, "{kind}: n segments when closed");
        for (i, seg) in segs.iter().enumerate() {
            let want = [
                at(i).clone(),
                lin(at(i), at(i + 1), at(i + n - 1), 1.0 / 6.0),
                lin(at(i + 1), at(i + 2), at(i), -1.0 / 6.0),
                at(i + 1).clone(),
            ];
            for (j, (g, w)) in seg.iter().zip(&want).enumerate() {
                assert!(dist(g, w) < 1e-14, "{kind}: segment {i}, control point {j}");
            }
        }
    }
}

#[test]
fn hobby_control_points_are_metapost_s() {
    // `mpost -numbersystem=double` on the closed pentagon (docs/peers.md §1): postcontrol of z₀.
    let segs = segments(&json_points(&pentagon()), "hobby-closed");
    assert_eq!(segs.len(), 5, "five segments");
    assert!(dist(&segs[0][0], &[0.0, 0.0]) == 0.0, "a segment starts at its knot");
    assert!(
        dist(&segs[0][1], &[1.019_296_273_979_157_6, -0.522_550_304_019_629_2]) < 1e-12,
        "postcontrol 0: {:?}",
        segs[0][1]
    );
    for (i, seg) in segs.iter().enumerate() {
        assert_eq!(seg.len(), 4, "cubic");
        assert_eq!(seg[3], segs[(i + 1) % 5][0], "segment {i} ends at the next knot");
    }
    let open = segments(&json_points(&pentagon()), "hobby-open");
    assert_eq!(open.len(), 4, "n - 1 segments when open");
}

#[test]
fn bezier_segments_reproduce_the_samples() {
    let input = json_points(&pentagon());
    let count = 50;
    for kind in ["lagrange", "catmull-rom", "tcb", "bspline-periodic", "bspline-open"]
        .into_iter()
        .chain(["hobby-closed", "hobby-open", "chaikin"])
    {
        let segs = segments(&input, kind);
        let got = sample(&input, kind, count);
        let open = OPEN_KINDS.contains(&kind);
        for (l, p) in got.iter().enumerate() {
            let t = if open { l as f64 / (count - 1) as f64 } else { l as f64 / count as f64 };
            let want = eval_chain(&segs, t);
            assert!(dist(p, &want) < 1e-12, "{kind}: sample {l}: {p:?} vs {want:?}");
        }
    }
}

#[test]
fn open_kinds_run_from_the_first_point_to_the_last() {
    let pts = pentagon();
    for kind in OPEN_KINDS {
        let got = sample(&json_points(&pts), kind, 9);
        assert!(dist(&got[0], &pts[0]) < 1e-14, "{kind}: starts at x₀");
        assert!(dist(&got[8], &pts[4]) < 1e-14, "{kind}: ends at x₄");
    }
    // The Lagrange polynomial of points on the parabola y = x² at x = 0, 1, 2 is that parabola.
    let got = sample("[[0,0],[1,1],[2,4]]", "lagrange", 5);
    for (l, p) in got.iter().enumerate() {
        let x = l as f64 / 2.0;
        assert!(dist(p, &[x, x * x]) < 1e-14, "sample {l}");
    }
}

#[test]
fn chaikin_is_the_quadratic_bspline_of_the_polygon() {
    // Segment j of the limit runs from the midpoint of edge j to the midpoint of edge j + 1:
    // ½(1 − s)²·xⱼ + (½ + s − s²)·xⱼ₊₁ + ½s²·xⱼ₊₂.
    let pts = pentagon();
    let n = pts.len();
    let count = 20;
    let got = sample(&json_points(&pts), "chaikin", count);
    for (l, p) in got.iter().enumerate() {
        let u = l as f64 / count as f64 * n as f64;
        let j = u.floor() as usize;
        let s = u - j as f64;
        let w = [0.5 * (1.0 - s) * (1.0 - s), 0.5 + s - s * s, 0.5 * s * s];
        let want: Vec<f64> =
            (0..2).map(|c| (0..3).map(|k| w[k] * pts[(j + k) % n][c]).sum()).collect();
        assert!(dist(p, &want) < 1e-13, "sample {l}");
    }
    let segs = segments(&json_points(&pts), "chaikin");
    assert!(segs.iter().all(|s| s.len() == 3), "quadratic segments");
}

#[test]
fn four_point_passes_through_the_points_and_the_inserted_ones() {
    let pts = pentagon();
    let n = pts.len();
    let got = sample(&json_points(&pts), "four-point", 2 * n);
    for k in 0..n {
        assert!(dist(&got[2 * k], &pts[k]) < 1e-12, "point {k}");
        // The first step's new point: (9/16)(xₖ + xₖ₊₁) − (1/16)(xₖ₋₁ + xₖ₊₂).
        let want: Vec<f64> = (0..2)
            .map(|c| {
                9.0 / 16.0 * (pts[k][c] + pts[(k + 1) % n][c])
                    - (pts[(k + n - 1) % n][c] + pts[(k + 2) % n][c]) / 16.0
            })
            .collect();
        assert!(dist(&got[2 * k + 1], &want) < 1e-12, "new point in edge {k}");
    }
}

#[test]
fn every_kind_samples_1d_2d_and_closed_kinds_interpolate() {
    let pts = pentagon();
    for kind in ALL_KINDS {
        let got = sample(&json_points(&pts), kind, 10);
        assert_eq!(got.len(), 10, "{kind}");
        if !OPEN_KINDS.contains(&kind) && !["chaikin", "bessel-overhauser"].contains(&kind) {
            for k in 0..5 {
                assert!(dist(&got[2 * k], &pts[k]) < 1e-12, "{kind}: point {k} at t = k/n");
            }
        }
        if !kind.starts_with("hobby") {
            let one_d = sample("[0, 1, 3, 2, 5]", kind, 4);
            assert!(one_d.iter().all(|p| p.len() == 1), "{kind}: 1-D");
        }
    }
}

#[test]
fn fairness_of_the_circle() {
    // The harmonic curve through the square is the unit circle: κ = 1, ∫κ² ds = 2π, length 2π,
    // and its area over the square's is π/2.
    let f = ok_on(SQUARE, &["curve", "fairness"]);
    let text = f.to_string();
    for key in ["max_curvature", "max_curvature_at", "monotone_pieces"].into_iter().chain([
        "bending_energy",
        "bending_energy_error",
        "length",
        "confinement",
    ]) {
        assert!(text.contains(&format!("\"{key}\":")), "{key} in {text}");
    }
    assert_eq!(f.as_object().expect("an object").len(), 7, "six measures and an error");
    assert!(num(&f["bending_energy_error"]) < 1e-10, "a smooth curve's energy converges");
    assert!((num(&f["max_curvature"]) - 1.0).abs() < 1e-12, "max |κ|");
    assert_eq!(f["monotone_pieces"], Value::from(1), "a whole number");
    assert!((num(&f["bending_energy"]) - 2.0 * PI).abs() < 1e-10, "energy");
    assert!((num(&f["length"]) - 2.0 * PI).abs() < 1e-10, "length");
    assert!((num(&f["confinement"]) - FRAC_PI_2).abs() < 1e-6, "confinement");
}

#[test]
fn fairness_of_every_kind_is_finite_and_collinear_points_have_no_confinement() {
    let input = json_points(&pentagon());
    for kind in ALL_KINDS {
        let f = ok_on(&input, &["curve", "fairness", "--kind", kind, "--samples", "512"]);
        for key in ["max_curvature", "bending_energy", "length", "confinement"] {
            assert!(num(&f[key]).is_finite() && num(&f[key]) > 0.0, "{kind}: {key}");
        }
        assert!(f["monotone_pieces"].as_u64().is_some_and(|p| p >= 1), "{kind}");
    }
    let line = ok_on("[[0,0],[1,0],[2,0]]", &["curve", "fairness", "--kind", "hobby-open"]);
    assert!(line["confinement"].is_null(), "collinear points: {line}");
    assert!(num(&line["bending_energy"]).abs() < 1e-20, "a straight segment");
    assert!((num(&line["length"]) - 2.0).abs() < 1e-12, "length 2");
}

#[test]
fn bad_kinds_and_inputs() {
    let sample = ["curve", "sample", "--count", "4"];
    bad_on(
        SQUARE,
        &["curve", "sample", "--count", "4", "--kind", "spline"],
        "unknown curve kind 'spline'",
    );
    bad_on(SQUARE, &["curve", "sample", "--count", "4", "--kind", "spline"], "bspline-periodic");
    bad_on(
        "[[0,0],[1,1]]",
        &[&sample[..], &["--kind", "catmull-rom"]].concat(),
        "at least 3 points",
    );
    bad_on("[[0,0]]", &[&sample[..], &["--kind", "lagrange"]].concat(), "at least 2 points");
    bad_on("[[0,0,0],[1,1,1]]", &[&sample[..], &["--kind", "hobby-open"]].concat(), "planar");
    bad_on(
        "[[0,0],[0,0],[1,1]]",
        &[&sample[..], &["--kind", "bessel-overhauser"]].concat(),
        "coincide",
    );
    bad_on("[[0,0,0],[1,1,1],[2,0,1]]", &["curve", "fairness"], "2-D points");
    bad_on("[0, 1, 2]", &["curve", "fairness"], "2-D points");
    bad_on(SQUARE, &["curve", "fairness", "--samples", "2"], "--samples");
    bad_on(SQUARE, &["curve", "to-bezier", "--kind", "trig"], "not piecewise polynomial");
    bad_on(SQUARE, &["curve", "to-bezier", "--kind", "four-point"], "catmull-rom");
    bad_on(SQUARE, &["curve", "to-bezier"], "--kind");
    bad_on("[[0,0],[1,null]]", &["curve", "to-bezier", "--kind", "tcb"], "coordinate 1");
    bad(&["curve", "fairness", "--input", "/nonexistent/hi.json"], "cannot read");
}
