// SPDX-License-Identifier: MIT
//! End-to-end tests of the `hi` binary: every subcommand on 1-D, 2-D and 3-D input, checked
//! against algebra and bit for bit against `hi-curve`, and every kind of bad input.

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};

use glam::{DVec2, DVec3};
use hi_curve::{
    ControlPoint, HarmonicCurve, NonUniformCurve, NonUniformVariant, ParamCurve, PlaneCurve, Sigma,
    SpaceCurve, chord_length_params,
};
use serde_json::Value;

// ---------------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------------

/// A JSON input file under the system temp directory, removed on drop.
struct TempFile(PathBuf);

impl TempFile {
    fn new(contents: &str) -> Self {
        static COUNTER: AtomicUsize = AtomicUsize::new(0);
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let path =
            std::env::temp_dir().join(format!("hi-cli-test-{}-{n}.json", std::process::id()));
        std::fs::write(&path, contents).expect("temp file is writable");
        Self(path)
    }

    fn path(&self) -> &str {
        self.0.to_str().expect("temp paths are UTF-8 in these tests")
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// Runs `hi` with `args`, feeding `stdin` if given.
fn run(args: &[&str], stdin: Option<&str>) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_hi"))
        .args(args)
        .stdin(if stdin.is_some() { Stdio::piped() } else { Stdio::null() })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the hi binary starts");
    if let Some(text) = stdin {
        child
            .stdin
            .take()
            .expect("stdin is piped")
            .write_all(text.as_bytes())
            .expect("stdin is writable");
    }
    child.wait_with_output().expect("hi finishes")
}

/// Runs a command that must succeed and returns its raw stdout.
fn ok_text(args: &[&str], stdin: Option<&str>) -> String {
    let out = run(args, stdin);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "hi {args:?} failed ({:?}): {stderr}", out.status);
    assert!(stderr.is_empty(), "hi {args:?} wrote to stderr: {stderr}");
    String::from_utf8(out.stdout).expect("stdout is UTF-8")
}

/// Runs a command that must succeed and parses its JSON output.
fn ok(args: &[&str]) -> Value {
    let text = ok_text(args, None);
    assert!(text.ends_with('\n') && text.lines().count() == 1, "one line of JSON: {text}");
    serde_json::from_str(&text).expect("stdout is JSON")
}

/// Runs a command on a temporary input file holding `input`.
fn ok_on(input: &str, args: &[&str]) -> Value {
    let file = TempFile::new(input);
    let mut all = args.to_vec();
    all.extend(["--input", file.path()]);
    ok(&all)
}

/// Asserts a bad-input failure: exit status 2, nothing on stdout, exactly one line on stderr
/// that starts with `hi: ` and contains `expected`, and no trace of a panic.
fn bad(args: &[&str], stdin: Option<&str>, expected: &str) {
    let out = run(args, stdin);
    let stderr = String::from_utf8(out.stderr).expect("stderr is UTF-8");
    assert_eq!(out.status.code(), Some(2), "hi {args:?}: exit status (stderr: {stderr})");
    assert!(out.stdout.is_empty(), "hi {args:?}: nothing on stdout");
    assert!(
        stderr.ends_with('\n') && stderr.matches('\n').count() == 1,
        "hi {args:?}: one line: {stderr:?}"
    );
    assert!(stderr.starts_with("hi: "), "hi {args:?}: prefix: {stderr}");
    assert!(stderr.contains(expected), "hi {args:?}: {stderr:?} should contain {expected:?}");
    for word in ["panicked", "backtrace", "RUST_BACKTRACE", "internal error"] {
        assert!(!stderr.contains(word), "hi {args:?}: {stderr}");
    }
}

/// [`bad`] on a temporary input file holding `input`.
fn bad_on(input: &str, args: &[&str], expected: &str) {
    let file = TempFile::new(input);
    let mut all = args.to_vec();
    all.extend(["--input", file.path()]);
    bad(&all, None, expected);
}

/// A JSON number as printed by `hi`, or the spelled-out non-finite strings.
fn num(v: &Value) -> f64 {
    match v {
        Value::Number(n) => n.as_f64().expect("a double"),
        Value::String(s) if s == "Infinity" => f64::INFINITY,
        Value::String(s) if s == "-Infinity" => f64::NEG_INFINITY,
        Value::String(s) if s == "NaN" => f64::NAN,
        other => panic!("not a number: {other}"),
    }
}

fn nums(v: &Value) -> Vec<f64> {
    v.as_array().expect("an array").iter().map(num).collect()
}

/// An array of numbers or nulls.
fn optional_nums(v: &Value) -> Vec<Option<f64>> {
    v.as_array()
        .expect("an array")
        .iter()
        .map(|x| if x.is_null() { None } else { Some(num(x)) })
        .collect()
}

/// An array of points of dimension `P::DIM`.
fn points<P: ControlPoint>(v: &Value) -> Vec<P> {
    v.as_array()
        .expect("an array of points")
        .iter()
        .map(|p| {
            let coords = nums(p);
            assert_eq!(coords.len(), P::DIM, "point dimension");
            P::from_coords(|i| coords[i])
        })
        .collect()
}

/// Asserts that two doubles are the same bit pattern (NaN included).
fn assert_bits(got: f64, want: f64, what: &str) {
    assert!(
        got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
        "{what}: got {got:e}, want {want:e}"
    );
}

fn assert_points_bits<P: ControlPoint>(got: &[P], want: &[P], what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: number of points");
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        for i in 0..P::DIM {
            assert_bits(g.coord(i), w.coord(i), &format!("{what}: point {k}, coordinate {i}"));
        }
    }
}

fn assert_optional_bits(got: &[Option<f64>], want: &[Option<f64>], what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: length");
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        match (g, w) {
            (Some(g), Some(w)) => assert_bits(*g, *w, &format!("{what}[{k}]")),
            (None, None) => {}
            _ => panic!("{what}[{k}]: got {g:?}, want {w:?}"),
        }
    }
}

/// The JSON text of points, printed with Rust's round-trip formatting.
fn json_points<P: ControlPoint>(pts: &[P]) -> String {
    let items: Vec<String> = pts
        .iter()
        .map(|p| {
            format!(
                "[{}]",
                (0..P::DIM).map(|i| format!("{:?}", p.coord(i))).collect::<Vec<_>>().join(",")
            )
        })
        .collect();
    format!("[{}]", items.join(","))
}

fn dist<P: ControlPoint>(a: P, b: P) -> f64 {
    (a - b).norm()
}

const SQUARE: &str = "[[1,0],[0,1],[-1,0],[0,-1]]";

fn square() -> Vec<DVec2> {
    vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y]
}

/// An irregular quadrilateral, whose alternating sum is not zero (Theorem 5.1 fails on it).
fn quad() -> Vec<DVec2> {
    vec![DVec2::new(0.0, 0.0), DVec2::new(3.0, 1.0), DVec2::new(4.0, 4.0), DVec2::new(-1.0, 2.0)]
}

/// The vertices of the unit cube in Gray-code order.
fn cube() -> Vec<DVec3> {
    [0u32, 1, 3, 2, 6, 7, 5, 4]
        .iter()
        .map(|&g| DVec3::new(f64::from(g & 1), f64::from((g >> 1) & 1), f64::from((g >> 2) & 1)))
        .collect()
}

fn line_1d() -> Vec<f64> {
    vec![0.5, 2.0, -1.25, 3.0, 0.1]
}

const TS: &str = "0,0.1,0.125,0.3,-0.45,1.7";
const TS_VALUES: [f64; 6] = [0.0, 0.1, 0.125, 0.3, -0.45, 1.7];

// ---------------------------------------------------------------------------------------------
// hi basis
// ---------------------------------------------------------------------------------------------

#[test]
fn basis_known_values() {
    let out = ok(&["basis", "--n", "3", "--k", "0", "--t", "0,0.5"]);
    let sigma = nums(&out["sigma"]);
    assert_eq!(sigma[0], 1.0, "σ³(0) = 1");
    assert!((sigma[1] + 1.0 / 3.0).abs() < 1e-16, "σ³(1/2) = −1/3: {}", sigma[1]);
    assert_bits(sigma[1], Sigma::new(3).eval(0, 0.5), "σ³(1/2)");
    assert_eq!(out.as_object().expect("an object").len(), 1, "no derivatives unless asked");

    // σ⁴₁(j/4) = δⱼ₁.
    let out = ok(&["basis", "--n", "4", "--k", "1", "--t", "0,0.25,0.5,0.75"]);
    for (j, v) in nums(&out["sigma"]).into_iter().enumerate() {
        let want = if j == 1 { 1.0 } else { 0.0 };
        assert!((v - want).abs() < 1e-15, "σ⁴₁({j}/4) = {v}");
    }
}

#[test]
fn basis_derivatives_match_the_library_bit_for_bit() {
    for (n, k) in [(3usize, 0usize), (4, 1), (7, 6), (10, 3)] {
        let sigma = Sigma::new(n);
        let out = ok(&[
            "basis",
            "--n",
            &n.to_string(),
            "--k",
            &k.to_string(),
            "--t",
            TS,
            "--derivatives",
            "4",
        ]);
        let values = nums(&out["sigma"]);
        for (i, &t) in TS_VALUES.iter().enumerate() {
            assert_bits(values[i], sigma.eval(k, t), &format!("σ{n}_{k}({t})"));
            for p in 1..=4 {
                let d = nums(&out[format!("d{p}")]);
                assert_bits(d[i], sigma.deriv(k, t, p), &format!("d{p} σ{n}_{k}({t})"));
            }
        }
        assert!(out.get("d5").is_none(), "only D derivatives");
    }
}

#[test]
fn basis_overflowing_derivatives_are_spelled_out() {
    // (2π)ᵖ overflows near p = 390; at n = 1000 the cosine sum adds +∞ and −∞ terms (NaN).
    for (n, t, d) in [(3usize, 0.1, 420usize), (1000, 0.1, 120)] {
        let out = ok(&[
            "basis",
            "--n",
            &n.to_string(),
            "--k",
            "1",
            "--t",
            &t.to_string(),
            "--derivatives",
            &d.to_string(),
        ]);
        let sigma = Sigma::new(n);
        let mut non_finite = 0;
        for p in 1..=d {
            let v = &out[format!("d{p}")][0];
            let want = sigma.deriv(1, t, p);
            if want.is_finite() {
                assert!(v.is_number(), "d{p}: {v}");
            } else {
                non_finite += 1;
                let spelled = if want.is_nan() {
                    "NaN"
                } else if want > 0.0 {
                    "Infinity"
                } else {
                    "-Infinity"
                };
                assert_eq!(v.as_str(), Some(spelled), "d{p}");
            }
            assert_bits(num(v), want, &format!("d{p}"));
        }
        assert!(non_finite > 0, "n = {n}: some derivative overflows");
    }
}

// ---------------------------------------------------------------------------------------------
// hi curve eval
// ---------------------------------------------------------------------------------------------

#[test]
fn eval_square_is_the_unit_circle() {
    let out = ok_on(SQUARE, &["curve", "eval", "--t", "0.125,0.25,0.3,0.9", "--derivatives", "2"]);
    let x: Vec<DVec2> = points(&out["X"]);
    let h = 0.5f64.sqrt();
    assert!(dist(x[0], DVec2::new(h, h)) < 1e-15, "X(1/8) = (√½, √½): {}", x[0]);
    assert!(dist(x[1], DVec2::Y) < 1e-15, "X(1/4) = x₁: {}", x[1]);
    for p in &x {
        assert!((p.length() - 1.0).abs() < 1e-14, "on the unit circle: {p}");
    }
    for k in nums(&out["curvature"]) {
        assert!((k - 1.0).abs() < 1e-12, "counter-clockwise unit circle: κ = 1, got {k}");
    }
    // |X′| = 2π on the unit circle traversed once.
    for d in points::<DVec2>(&out["d1"]) {
        assert!((d.length() - 2.0 * std::f64::consts::PI).abs() < 1e-12, "speed 2π: {d}");
    }
    assert!(out.get("torsion").is_none(), "no torsion in the plane");

    // Clockwise: the signed curvature is −1.
    let out = ok_on("[[1,0],[0,-1],[-1,0],[0,1]]", &["curve", "eval", "--t", "0.1,0.6"]);
    for k in nums(&out["curvature"]) {
        assert!((k + 1.0).abs() < 1e-12, "clockwise: κ = −1, got {k}");
    }
}

#[test]
fn eval_2d_matches_the_library_bit_for_bit() {
    let pts = quad();
    let curve = HarmonicCurve::new(pts.clone());
    let out = ok_on(&json_points(&pts), &["curve", "eval", "--t", TS, "--derivatives", "3"]);
    assert_points_bits(&points::<DVec2>(&out["X"]), &curve.eval_many(&TS_VALUES), "X");
    for p in 1..=3 {
        let want: Vec<DVec2> = TS_VALUES.iter().map(|&t| curve.eval_deriv(t, p)).collect();
        assert_points_bits(&points::<DVec2>(&out[format!("d{p}")]), &want, &format!("d{p}"));
    }
    let want: Vec<Option<f64>> = TS_VALUES.iter().map(|&t| curve.signed_curvature(t)).collect();
    assert_optional_bits(&optional_nums(&out["curvature"]), &want, "curvature");
}

#[test]
fn eval_keys_come_in_order() {
    let text = ok_text(
        &["curve", "eval", "--input", "-", "--t", "0.2", "--derivatives", "2"],
        Some(SQUARE),
    );
    let at =
        |key: &str| text.find(&format!("\"{key}\"")).unwrap_or_else(|| panic!("{key} in {text}"));
    assert!(at("X") < at("d1") && at("d1") < at("d2") && at("d2") < at("curvature"), "{text}");
}

#[test]
fn eval_1d_has_no_curvature() {
    let pts = line_1d();
    let curve = HarmonicCurve::new(pts.clone());
    let out = ok_on(&json_points(&pts), &["curve", "eval", "--t", TS, "--derivatives", "2"]);
    assert_points_bits(&points::<f64>(&out["X"]), &curve.eval_many(&TS_VALUES), "X");
    let want: Vec<f64> = TS_VALUES.iter().map(|&t| curve.eval_deriv(t, 2)).collect();
    assert_points_bits(&points::<f64>(&out["d2"]), &want, "d2");
    assert!(out.get("curvature").is_none() && out.get("torsion").is_none(), "1-D: {out}");
    // The curve passes through the points.
    let out = ok_on("[0.5, 2, -1.25, 3, 0.1]", &["curve", "eval", "--t", "0,0.2,0.4,0.6,0.8"]);
    for (got, want) in points::<f64>(&out["X"]).into_iter().zip(pts) {
        // t = k/5 is rounded to a double, so X(t) is xₖ only to about |X′|·ε.
        assert!((got - want).abs() < 1e-14, "X(k/n) = xₖ: {got} vs {want}");
    }
}

#[test]
fn eval_3d_curvature_and_torsion_match_the_library() {
    let pts = cube();
    let curve = HarmonicCurve::new(pts.clone());
    let nodes = "0,0.125,0.25,0.375,0.5,0.625,0.75,0.875";
    let out = ok_on(&json_points(&pts), &["curve", "eval", "--t", nodes]);
    for (got, want) in points::<DVec3>(&out["X"]).into_iter().zip(&pts) {
        assert!(dist(got, *want) < 1e-15, "X(k/8) = xₖ: {got} vs {want}");
    }
    let out = ok_on(&json_points(&pts), &["curve", "eval", "--t", TS, "--derivatives", "1"]);
    assert_points_bits(&points::<DVec3>(&out["X"]), &curve.eval_many(&TS_VALUES), "X");
    let curvature: Vec<Option<f64>> = TS_VALUES.iter().map(|&t| curve.curvature(t)).collect();
    let torsion: Vec<Option<f64>> = TS_VALUES.iter().map(|&t| curve.torsion(t)).collect();
    assert_optional_bits(&optional_nums(&out["curvature"]), &curvature, "curvature");
    assert_optional_bits(&optional_nums(&out["torsion"]), &torsion, "torsion");
    assert!(torsion.iter().any(Option::is_some), "the cube tour is not planar");

    // In space the curvature is unsigned.
    for k in nums(&out["curvature"]) {
        assert!(k > 0.0, "unsigned curvature: {k}");
    }
}

#[test]
fn eval_singular_points_are_null() {
    // Two points: X(t) = m + c·cos 2πt runs back and forth on a segment, X′(0) = 0.
    let out = ok_on("[[1,2],[3,4]]", &["curve", "eval", "--t", "0,0.3"]);
    let curvature = optional_nums(&out["curvature"]);
    assert_eq!(curvature[0], None, "κ undefined where X′ = 0");
    assert_eq!(curvature[1], Some(0.0), "a straight segment");
    // One 3-D point: a constant curve, singular everywhere.
    let out = ok_on("[[1,2,3]]", &["curve", "eval", "--t", "0.2"]);
    assert!(out["curvature"][0].is_null() && out["torsion"][0].is_null(), "{out}");
    assert_eq!(points::<DVec3>(&out["X"]), vec![DVec3::new(1.0, 2.0, 3.0)], "constant");
}

// ---------------------------------------------------------------------------------------------
// hi curve sample
// ---------------------------------------------------------------------------------------------

#[test]
fn sample_square_on_the_circle() {
    let out = ok_on(SQUARE, &["curve", "sample", "--count", "8"]);
    let x: Vec<DVec2> = points(&out["X"]);
    assert_eq!(x.len(), 8, "N samples");
    let h = 0.5f64.sqrt();
    assert!(dist(x[1], DVec2::new(h, h)) < 1e-15, "X(1/8): {}", x[1]);
    assert!(dist(x[2], DVec2::Y) < 1e-15, "X(2/8) = x₁: {}", x[2]);
    let want = HarmonicCurve::new(square()).sample_uniform(8).expect("valid count");
    assert_points_bits(&x, &want, "FFT samples");
}

#[test]
fn sample_1d_and_3d_match_the_library() {
    let out = ok_on(&json_points(&line_1d()), &["curve", "sample", "--count", "13"]);
    let want = HarmonicCurve::new(line_1d()).sample_uniform(13).expect("valid count");
    assert_points_bits(&points::<f64>(&out["X"]), &want, "1-D");
    let out = ok_on(&json_points(&cube()), &["curve", "sample", "--count", "3"]);
    let want = HarmonicCurve::new(cube()).sample_uniform(3).expect("valid count");
    assert_points_bits(&points::<DVec3>(&out["X"]), &want, "3-D, N < n");
    for (l, p) in want.iter().enumerate() {
        let direct = HarmonicCurve::new(cube()).eval(l as f64 / 3.0);
        assert!(dist(*p, direct) < 1e-14, "sample {l} is X(l/N)");
    }
}

// ---------------------------------------------------------------------------------------------
// hi curve rotate
// ---------------------------------------------------------------------------------------------

#[test]
fn rotate_exact_on_four_points_gives_five_and_the_shifted_curve() {
    let pts = quad();
    let original = HarmonicCurve::new(pts.clone());
    let offset = 0.1;
    let out = ok_on(&json_points(&pts), &["curve", "rotate", "--offset", "0.1", "--exact"]);
    let rotated: Vec<DVec2> = points(&out["points"]);
    assert_eq!(rotated.len(), 5, "n + 1 points for even n");
    let curve = HarmonicCurve::new(rotated.clone());
    for i in 0..50 {
        let t = i as f64 / 50.0;
        let d = dist(curve.eval(t), original.eval(t + offset));
        assert!(d < 1e-13, "Y(t) = X(t + o) at t = {t}: {d}");
    }
    assert_points_bits(
        &rotated,
        original.rotate(offset).expect("finite offset").points(),
        "library",
    );
}

#[test]
fn rotate_theorem_5_1_matches_the_library() {
    // Even n: n points, bit for bit as the library (which is not the shifted curve there).
    let pts = quad();
    let out = ok_on(&json_points(&pts), &["curve", "rotate", "--offset", "-0.3"]);
    let want = HarmonicCurve::new(pts).rotate_theorem_5_1(-0.3).expect("finite offset");
    assert_points_bits(&points::<DVec2>(&out["points"]), want.points(), "2-D");

    // Odd n (3-D, 5 points): the theorem holds, Y(t) = X(t + o).
    let pts = vec![
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 2.0, 0.5),
        DVec3::new(-1.0, 0.0, 1.0),
        DVec3::new(0.0, -1.0, 0.0),
        DVec3::new(0.5, 0.5, -1.0),
    ];
    let original = HarmonicCurve::new(pts.clone());
    for exact in [false, true] {
        let mut args = vec!["curve", "rotate", "--offset", "0.37"];
        if exact {
            args.push("--exact");
        }
        let rotated: Vec<DVec3> = points(&ok_on(&json_points(&pts), &args)["points"]);
        assert_eq!(rotated.len(), 5, "odd n keeps n points");
        let curve = HarmonicCurve::new(rotated);
        for i in 0..20 {
            let t = i as f64 / 20.0;
            assert!(
                dist(curve.eval(t), original.eval(t + 0.37)) < 1e-13,
                "exact = {exact}, t = {t}"
            );
        }
    }

    // 1-D, a whole number of steps: a relabelling of the points.
    let out = ok_on("[1, 2, 3, 4]", &["curve", "rotate", "--offset", "0.25"]);
    assert_eq!(points::<f64>(&out["points"]), vec![2.0, 3.0, 4.0, 1.0], "relabelled");
}

// ---------------------------------------------------------------------------------------------
// hi curve resample
// ---------------------------------------------------------------------------------------------

#[test]
fn resample_insertion_is_exact_and_stays_on_the_curve() {
    let pts = quad();
    let original = HarmonicCurve::new(pts.clone());
    let out = ok_on(&json_points(&pts), &["curve", "resample", "--count", "7"]);
    assert_eq!(num(&out["max_error"]), 0.0, "N > n: no error");
    assert_eq!(num(&out["error_bound"]), 0.0, "N > n: no error bound");
    let new: Vec<DVec2> = points(&out["points"]);
    assert_eq!(new.len(), 7, "N points");
    let curve = HarmonicCurve::new(new.clone());
    for i in 0..40 {
        let t = i as f64 / 40.0 + 0.003;
        assert!(dist(curve.eval(t), original.eval(t)) < 1e-13, "same curve at t = {t}");
    }
    for (j, p) in new.iter().enumerate() {
        assert!(dist(*p, original.eval(j as f64 / 7.0)) < 1e-14, "yⱼ = X(j/N)");
    }
    assert_points_bits(&new, original.resample(7).expect("valid count").0.points(), "library");
}

#[test]
fn resample_reduction_reports_its_error() {
    let pts = cube();
    let out = ok_on(&json_points(&pts), &["curve", "resample", "--count", "5"]);
    let (curve, error) = HarmonicCurve::new(pts).resample(5).expect("valid count");
    assert_points_bits(&points::<DVec3>(&out["points"]), curve.points(), "points");
    let (e, b) = (num(&out["max_error"]), num(&out["error_bound"]));
    assert_bits(e, error.max_deviation, "max_error");
    assert_bits(b, error.upper_bound, "error_bound");
    assert!(e > 0.0 && e <= b, "0 < max_error ≤ error_bound: {e}, {b}");

    let out = ok_on(&json_points(&line_1d()), &["curve", "resample", "--count", "2"]);
    let (curve, error) = HarmonicCurve::new(line_1d()).resample(2).expect("valid count");
    assert_points_bits(&points::<f64>(&out["points"]), curve.points(), "1-D points");
    assert_bits(num(&out["max_error"]), error.max_deviation, "1-D max_error");
}

#[test]
fn printed_numbers_read_back_bit_for_bit() {
    // Resampling to N = n copies the points exactly, so the output must be the input's bits.
    let values =
        [0.1, 5e-324, -0.0, 1e300, 9007199254740993.0, 1.0 / 3.0, -2.5e-310, 123456.789e-7];
    let text =
        format!("[{}]", values.iter().map(|v| format!("{v:?}")).collect::<Vec<_>>().join(","));
    let out = ok_on(&text, &["curve", "resample", "--count", &values.len().to_string()]);
    assert_points_bits(&points::<f64>(&out["points"]), &values, "round trip");
    assert!(num(&out["points"][2][0]).is_sign_negative(), "−0.0 keeps its sign");
}

// ---------------------------------------------------------------------------------------------
// hi curve subdivide
// ---------------------------------------------------------------------------------------------

#[test]
fn subdivide_keeps_the_original_points() {
    let pts = quad();
    let original = HarmonicCurve::new(pts.clone());
    let out = ok_on(&json_points(&pts), &["curve", "subdivide", "--levels", "1"]);
    let level1: Vec<DVec2> = points(&out["points"]);
    assert_eq!(level1.len(), 8, "2n points");
    for (i, p) in pts.iter().enumerate() {
        assert_points_bits(&[level1[2 * i]], &[*p], "even indices are the original points");
        let mid = original.eval((2 * i + 1) as f64 / 8.0);
        assert!(dist(level1[2 * i + 1], mid) < 1e-14, "odd indices are X((2i+1)/(2n))");
    }
    assert_points_bits(&level1, original.subdivide(1).expect("small").points(), "library");
    for (got, want) in level1.iter().zip(hi_curve::testing::subdivide_step_direct(&original)) {
        assert!(dist(*got, want) < 1e-14, "the direct formula of §5.2: {got} vs {want}");
    }

    let out = ok_on(&json_points(&cube()), &["curve", "subdivide", "--levels", "2"]);
    let level2: Vec<DVec3> = points(&out["points"]);
    assert_eq!(level2.len(), 32, "n·4 points");
    for (i, p) in cube().iter().enumerate() {
        assert_points_bits(&[level2[4 * i]], &[*p], "every 4th point is an original");
    }
    assert_points_bits(
        &level2,
        HarmonicCurve::new(cube()).subdivide(2).expect("small").points(),
        "3-D",
    );

    let out = ok_on(&json_points(&line_1d()), &["curve", "subdivide", "--levels", "0"]);
    assert_points_bits(&points::<f64>(&out["points"]), &line_1d(), "level 0 is the input");
}

// ---------------------------------------------------------------------------------------------
// hi curve nonuniform
// ---------------------------------------------------------------------------------------------

#[test]
fn nonuniform_nodes_passes_through_the_points_at_their_params() {
    let pts = quad();
    let params = [0.0, 0.1, 0.45, 0.7];
    let out = ok_on(
        &json_points(&pts),
        &[
            "curve",
            "nonuniform",
            "--t",
            "0,0.1,0.45,0.7",
            "--variant",
            "nodes",
            "--params",
            "0,0.1,0.45,0.7",
        ],
    );
    assert_eq!(nums(&out["params"]), params.to_vec(), "params as given");
    for (got, want) in points::<DVec2>(&out["X"]).into_iter().zip(&pts) {
        assert!(dist(got, *want) < 1e-13, "X(tₖ) = xₖ: {got} vs {want}");
    }
    let curve = NonUniformCurve::try_with_params(pts, params.to_vec(), NonUniformVariant::Nodes)
        .expect("valid");
    assert_bits(num(&out["condition"]), curve.condition(), "condition");
    assert!(num(&out["condition"]) >= 1.0, "a Lebesgue constant is at least 1");
    assert!(out.get("matrix_condition").is_none(), "nodes variant solves no system");
}

#[test]
fn nonuniform_chord_length_and_thesis_match_the_library() {
    let pts = cube();
    let out = ok_on(&json_points(&pts), &["curve", "nonuniform", "--t", TS, "--variant", "thesis"]);
    let params = chord_length_params(&pts).expect("distinct points");
    assert_points_bits(&nums(&out["params"]), &params, "chord-length params");
    let curve = NonUniformCurve::try_new(pts.clone(), NonUniformVariant::Thesis).expect("valid");
    let want: Vec<DVec3> = TS_VALUES.iter().map(|&t| curve.eval(t)).collect();
    assert_points_bits(&points::<DVec3>(&out["X"]), &want, "thesis X");
    assert_bits(num(&out["condition"]), curve.condition(), "condition");
    assert_bits(
        num(&out["matrix_condition"]),
        curve.matrix_condition().expect("thesis"),
        "matrix_condition",
    );

    // The thesis variant passes through xₖ at k/(n−1).
    let out = ok_on(
        &json_points(&pts),
        &["curve", "nonuniform", "--t", "0,0.42857142857142855,1", "--variant", "thesis"],
    );
    let x: Vec<DVec3> = points(&out["X"]);
    assert!(
        dist(x[0], pts[0]) < 1e-12 && dist(x[1], pts[3]) < 1e-12 && dist(x[2], pts[7]) < 1e-12,
        "{x:?}"
    );

    // 1-D, nodes variant with chord-length params.
    let out =
        ok_on(&json_points(&line_1d()), &["curve", "nonuniform", "--t", TS, "--variant", "nodes"]);
    let curve = NonUniformCurve::try_new(line_1d(), NonUniformVariant::Nodes).expect("valid");
    let want: Vec<f64> = TS_VALUES.iter().map(|&t| curve.eval(t)).collect();
    assert_points_bits(&points::<f64>(&out["X"]), &want, "1-D X");
    for (p, x) in nums(&out["params"]).into_iter().zip(line_1d()) {
        let through = ok_on(
            &json_points(&line_1d()),
            &["curve", "nonuniform", "--t", &p.to_string(), "--variant", "nodes"],
        );
        assert!((num(&through["X"][0][0]) - x).abs() < 1e-13, "X(tₖ) = xₖ at {p}");
    }
}

// ---------------------------------------------------------------------------------------------
// Input forms, stdin, output options, help
// ---------------------------------------------------------------------------------------------

#[test]
fn input_forms_are_equivalent() {
    let args = ["curve", "eval", "--t", "0.1,0.7", "--derivatives", "1"];
    let bare = ok_on(SQUARE, &args);
    assert_eq!(ok_on(&format!("{{\"points\": {SQUARE}}}"), &args), bare, "object form");
    let stdin = ok_text(
        &["curve", "eval", "--input", "-", "--t", "0.1,0.7", "--derivatives", "1"],
        Some(SQUARE),
    );
    assert_eq!(serde_json::from_str::<Value>(&stdin).expect("JSON"), bare, "stdin");
    // 1-D points as bare numbers or one-element arrays.
    let args = ["curve", "sample", "--count", "5"];
    assert_eq!(ok_on("[1, 2.5, -3]", &args), ok_on("[[1], [2.5], [-3]]", &args), "1-D forms");
    assert_eq!(
        ok_on("{\"points\": [1, [2.5], -3]}", &args),
        ok_on("[[1], [2.5], [-3]]", &args),
        "mixed 1-D forms"
    );
}

#[test]
fn pretty_output_is_the_same_json() {
    let file = TempFile::new(SQUARE);
    let plain = ok_text(&["curve", "sample", "--input", file.path(), "--count", "6"], None);
    let pretty =
        ok_text(&["--pretty", "curve", "sample", "--input", file.path(), "--count", "6"], None);
    assert!(pretty.lines().count() > 1, "indented");
    let parse = |s: &str| serde_json::from_str::<Value>(s).expect("JSON");
    assert_eq!(parse(&plain), parse(&pretty), "same content");
}

#[test]
fn help_explains_the_json_shapes() {
    let main = ok_text(&["--help"], None);
    for needle in ["\"points\"", "basis", "curve", "Infinity", "null", "Exit status"] {
        assert!(main.contains(needle), "hi --help mentions {needle}");
    }
    let cases: [(&[&str], &[&str]); 7] = [
        (&["basis"], &["\"sigma\"", "\"d1\""]),
        (&["curve", "eval"], &["\"X\"", "\"curvature\"", "\"torsion\"", "\"points\""]),
        (&["curve", "sample"], &["\"X\""]),
        (&["curve", "rotate"], &["\"points\"", "--exact"]),
        (&["curve", "resample"], &["\"max_error\"", "\"error_bound\""]),
        (&["curve", "subdivide"], &["\"points\""]),
        (
            &["curve", "nonuniform"],
            &["\"params\"", "\"condition\"", "\"matrix_condition\"", "thesis", "nodes"],
        ),
    ];
    for (command, needles) in cases {
        let mut args = command.to_vec();
        args.push("--help");
        let help = ok_text(&args, None);
        for needle in needles {
            assert!(help.contains(needle), "hi {command:?} --help mentions {needle}");
        }
    }
    assert!(ok_text(&["--version"], None).starts_with("hi "), "version");
}

// ---------------------------------------------------------------------------------------------
// Bad input
// ---------------------------------------------------------------------------------------------

#[test]
fn bad_input_files() {
    let eval = ["curve", "eval", "--t", "0.1"];
    bad(
        &["curve", "eval", "--t", "0", "--input", "/nonexistent/hi-cli-test.json"],
        None,
        "cannot read",
    );
    let dir = std::env::temp_dir();
    bad(
        &["curve", "eval", "--t", "0", "--input", dir.to_str().expect("UTF-8")],
        None,
        "cannot read",
    );
    bad_on("[[1,2],[3,4]", &eval, "invalid JSON");
    bad_on("", &eval, "invalid JSON");
    bad_on("[[1,2],[3,4]] x", &eval, "invalid JSON");
    bad_on("[[1,2],[NaN,4]]", &eval, "invalid JSON");
    bad_on("[[1,2],[1e999,4]]", &eval, "number out of range");
    bad_on("[[1,2],[-1e400,4]]", &eval, "number out of range");
    bad_on("[]", &eval, "no points given");
    bad_on("{\"points\": []}", &eval, "no points given");
    bad_on("[[1,2,3,4]]", &eval, "point 0 has 4 coordinates");
    bad_on("[[0,0],[]]", &eval, "point 1 has 0 coordinates");
    bad_on(
        "[[1,2],[\"3\",4]]",
        &eval,
        "point 1, coordinate 0: invalid type: string \"3\", expected a number",
    );
    bad_on("[[1,2],null]", &eval, "point 1: invalid type: null, expected a number or an array");
    bad_on("[[1,2],[[3],4]]", &eval, "point 1, coordinate 0: invalid type: sequence");
    bad_on("{\"point\": [[1,2]]}", &eval, "unknown key \"point\"");
    bad_on("{}", &eval, "no key \"points\"");
    bad_on("{\"points\": 3}", &eval, "\"points\": invalid type: integer `3`, expected a sequence");
    bad_on("3", &eval, "expected an array of points");
    bad_on("[1, [2, 3]]", &eval, "point 1 has 2 coordinates, point 0 has 1");

    // The message names the file and the point, as in the issue.
    let file = TempFile::new("[[1,2,3],[4,5,6],[7,8,9],[1,2]]");
    let out = run(&["curve", "sample", "--count", "3", "--input", file.path()], None);
    assert_eq!(out.status.code(), Some(2), "mixed dimensions");
    assert_eq!(
        String::from_utf8(out.stderr).expect("UTF-8"),
        format!("hi: {}: point 3 has 2 coordinates, point 0 has 3\n", file.path()),
        "exact message"
    );

    // stdin.
    bad(
        &["curve", "sample", "--count", "3", "--input", "-"],
        Some("[[1,2],"),
        "<stdin>: invalid JSON",
    );
    bad(&["curve", "sample", "--count", "3", "--input", "-"], Some(""), "<stdin>: invalid JSON");
}

#[test]
fn bad_numbers_on_the_command_line() {
    for t in
        ["nan", "NaN", "inf", "-inf", "infinity", "1e999", "0.1,nan", "", "1,,2", "abc", "0.5x"]
    {
        bad(&["basis", "--n", "3", "--k", "0", "--t", t], None, "--t");
        bad_on(SQUARE, &["curve", "eval", "--t", t], "--t");
        bad_on(SQUARE, &["curve", "nonuniform", "--variant", "nodes", "--t", t], "--t");
        bad_on(
            SQUARE,
            &["curve", "nonuniform", "--variant", "nodes", "--t", "0", "--params", t],
            "--params",
        );
    }
    for offset in ["nan", "inf", "-1e999", "x"] {
        bad_on(SQUARE, &["curve", "rotate", "--offset", offset], "--offset");
    }
    bad_on(SQUARE, &["curve", "eval", "--t", "0", "--derivatives", "2000"], "at most 1024");
    bad_on(SQUARE, &["curve", "eval", "--t", "0", "--derivatives", "-1"], "--derivatives");
    bad(
        &["basis", "--n", "3", "--k", "0", "--t", "0", "--derivatives", "1025"],
        None,
        "at most 1024",
    );
}

#[test]
fn bad_counts_and_sizes() {
    bad(&["basis", "--n", "0", "--k", "0", "--t", "0"], None, "--n");
    bad(
        &["basis", "--n", "4", "--k", "4", "--t", "0"],
        None,
        "basis index k = 4 is out of range for n = 4",
    );
    bad(&["basis", "--n", "4", "--k", "9", "--t", "0"], None, "--k");
    bad(&["basis", "--n", "-3", "--k", "0", "--t", "0"], None, "--n");
    bad(&["basis", "--n", "3.5", "--k", "0", "--t", "0"], None, "--n");
    bad_on(SQUARE, &["curve", "sample", "--count", "0"], "--count");
    bad_on(SQUARE, &["curve", "resample", "--count", "0"], "--count");
    bad_on(SQUARE, &["curve", "sample", "--count", "-2"], "--count");
    bad_on(SQUARE, &["curve", "sample", "--count", "300000000"], "--count");
    bad_on(SQUARE, &["curve", "resample", "--count", "300000000"], "--count");
    bad_on(SQUARE, &["curve", "subdivide", "--levels", "40"], "--levels");
    bad_on(SQUARE, &["curve", "subdivide", "--levels", "27"], "--levels");
    bad_on(SQUARE, &["curve", "subdivide", "--levels", "-1"], "--levels");
}

#[test]
fn bad_nonuniform_requests() {
    let nodes = ["curve", "nonuniform", "--t", "0.5", "--variant", "nodes"];
    bad_on(
        SQUARE,
        &["curve", "nonuniform", "--t", "0.5", "--variant", "spline"],
        "invalid value 'spline'",
    );
    bad_on(SQUARE, &["curve", "nonuniform", "--t", "0.5"], "--variant");
    bad_on(
        SQUARE,
        &[&nodes[..], &["--params", "0,0.5"]].concat(),
        "2 parameters given for 4 points",
    );
    bad_on(SQUARE, &[&nodes[..], &["--params", "0,0.25,0.5,1"]].concat(), "outside [0, 1)");
    bad_on(SQUARE, &[&nodes[..], &["--params", "0,-0.25,0.5,0.7"]].concat(), "outside [0, 1)");
    bad_on(SQUARE, &[&nodes[..], &["--params", "0,0.5,0.5,0.7"]].concat(), "coincide");
    bad_on("[[0,0],[1,0],[1,0],[0,1]]", &nodes, "points 1 and 2 coincide");
    bad_on("[[2,2],[2,2],[2,2]]", &nodes, "all points coincide");
    bad_on(
        "[[2,2],[2,2],[2,2]]",
        &["curve", "nonuniform", "--t", "0.5", "--variant", "thesis"],
        "all points coincide",
    );
}

#[test]
fn clap_usage_errors_are_one_line() {
    bad(&[], None, "requires a subcommand");
    bad(&["curve"], None, "'hi curve' requires a subcommand");
    bad(&["frob"], None, "unrecognized subcommand 'frob'");
    bad(&["curve", "frob"], None, "unrecognized subcommand 'frob'");
    bad(&["basis", "--n", "3", "--k", "0"], None, "--t");
    bad(
        &["basis", "--n", "3", "--k", "0", "--t", "0", "--bogus"],
        None,
        "unexpected argument '--bogus'",
    );
    bad(&["curve", "eval", "--t", "0"], None, "--input");
    bad(&["curve", "sample", "--input", "x.json"], None, "see 'hi curve sample --help'");
    bad(&["basis", "--n", "3", "--k", "0", "--t", "0", "--t", "1"], None, "--t");
}

#[test]
fn unwritable_output_exits_1_with_one_line() {
    let full = std::path::Path::new("/dev/full");
    if !full.exists() {
        return; // Only where the OS has a device that refuses writes.
    }
    let file = TempFile::new(SQUARE);
    let out = Command::new(env!("CARGO_BIN_EXE_hi"))
        .args(["curve", "sample", "--count", "4", "--input", file.path()])
        .stdout(std::fs::File::create(full).expect("/dev/full opens"))
        .stderr(Stdio::piped())
        .output()
        .expect("hi runs");
    let stderr = String::from_utf8(out.stderr).expect("UTF-8");
    assert_eq!(out.status.code(), Some(1), "output failure: {stderr}");
    assert!(
        stderr.starts_with("hi: cannot write the output") && stderr.matches('\n').count() == 1,
        "{stderr:?}"
    );
}

/// The enclosures and verdicts of `hi basis roots`.
fn roots(n: &str, derivative: &str) -> (Vec<(f64, f64)>, Vec<String>) {
    let out = ok(&["basis", "roots", "--n", n, "--derivative", derivative]);
    assert_eq!(out["complete"], Value::Bool(true), "the search finished");
    let roots = out["roots"]
        .as_array()
        .expect("an array")
        .iter()
        .map(|r| (num(&r[0]), num(&r[1])))
        .collect::<Vec<_>>();
    let verdicts: Vec<String> = out["verdicts"]
        .as_array()
        .expect("an array")
        .iter()
        .map(|v| v.as_str().expect("a string").to_owned())
        .collect();
    let unique: Vec<bool> = out["unique"]
        .as_array()
        .expect("an array")
        .iter()
        .map(|u| u == &Value::Bool(true))
        .collect();
    assert_eq!(
        unique,
        verdicts.iter().map(|v| v == "unique").collect::<Vec<_>>(),
        "unique matches the verdicts"
    );
    (roots, verdicts)
}

#[test]
fn basis_roots_enclose_the_known_zeros() {
    // σ³′(t) = −(4π/3)·sin 2πt: zeros at 0, 1/2 and 1, all simple.
    let (r, v) = roots("3", "1");
    assert_eq!(r.len(), 3, "{r:?}");
    for ((lo, hi), zero) in r.iter().zip([0.0, 0.5, 1.0]) {
        assert!(*lo <= zero && zero <= *hi && hi - lo < 1e-8, "[{lo}, {hi}] and {zero}");
    }
    assert_eq!(v[1], "unique");
    // σ⁴(t) = cos(πt)·sin(4πt)/(4 sin πt): simple zeros at 1/4 and 3/4, and a double zero at
    // 1/2 (both factors vanish), where uniqueness cannot be shown.
    let (r, v) = roots("4", "0");
    assert_eq!(r.len(), 3, "{r:?}");
    for ((lo, hi), zero) in r.iter().zip([0.25, 0.5, 0.75]) {
        assert!(*lo <= zero && zero <= *hi && hi - lo < 1e-7, "[{lo}, {hi}] and {zero}");
    }
    assert_eq!(v, ["unique", "unknown", "unique"]);
    bad(
        &["basis", "roots", "--n", "0"],
        None,
        "hi: --n: the basis size n must be at least 1, got 0",
    );
    bad(
        &["basis", "roots", "--n", "5000"],
        None,
        "hi: --n: 5000 is too large for the root search (at most 4096)",
    );
    bad(
        &["basis", "roots", "--n", "5", "--derivative", "17"],
        None,
        "hi: --derivative: 17 is too large (at most 16)",
    );
}
