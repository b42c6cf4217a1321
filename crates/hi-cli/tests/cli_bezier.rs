// SPDX-License-Identifier: MIT
//! End-to-end tests of the Bézier forms of §5.7: `hi bezier basis` and
//! `hi curve to-bezier --kind harmonic --scheme …`.

#[allow(dead_code, reason = "each test file uses a part of the shared helpers")]
mod common;

use common::{bad, bad_on, dist, num, nums, ok, ok_on, points};
use serde_json::Value;

/// The closed form for n = 3: σ₀(t) = (1 + 2 cos 2πt)/3 (docs/math.md §1), shifted by k/3.
fn sigma3(k: usize, t: f64) -> f64 {
    (1.0 + 2.0 * (std::f64::consts::TAU * (t - k as f64 / 3.0)).cos()) / 3.0
}

/// The cubic Bézier with control values `c` at s.
fn cubic(c: &[f64], s: f64) -> f64 {
    let r = 1.0 - s;
    c[0] * r * r * r + 3.0 * c[1] * s * r * r + 3.0 * c[2] * s * s * r + c[3] * s * s * s
}

#[test]
fn the_thesis_cubic_basis_interpolates_sigma_at_four_points_per_interval() {
    let json = ok(&["bezier", "basis", "--n", "3", "--scheme", "thesis-cubic"]);
    assert_eq!(json["degree"], 3, "cubic");
    assert_eq!(nums(&json["breaks"]), vec![0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0], "breaks a/n");
    let p = json["P"].as_array().expect("P");
    assert_eq!(p.len(), 3, "n pieces");
    for (a, piece) in p.iter().enumerate() {
        let piece = piece.as_array().expect("piece");
        assert_eq!(piece.len(), 3, "n functions");
        for (k, c) in piece.iter().enumerate() {
            let c = nums(c);
            assert_eq!(c.len(), 4, "4 control values");
            for i in 0..4 {
                let s = f64::from(i) / 3.0;
                let t = (a as f64 + s) / 3.0;
                let (got, want) = (cubic(&c, s), sigma3(k, t));
                assert!((got - want).abs() < 1e-14, "a {a} k {k} s {s}: {got} vs {want}");
            }
        }
    }
}

#[test]
fn the_thesis_quintic_basis_has_quintic_pieces() {
    let json = ok(&["bezier", "basis", "--n", "5", "--scheme", "thesis-quintic"]);
    assert_eq!(json["degree"], 5, "quintic");
    let breaks = nums(&json["breaks"]);
    assert_eq!((breaks[0], *breaks.last().expect("breaks")), (0.0, 1.0), "from 0 to 1");
    assert!(breaks.windows(2).all(|w| w[0] < w[1]), "increasing");
    let p = json["P"].as_array().expect("P");
    assert_eq!(p.len(), breaks.len() - 1, "one piece per break interval");
    assert!(p.iter().all(|piece| piece.as_array().expect("piece").len() == 5), "n functions");
}

#[test]
fn bezier_basis_rejects_bad_n() {
    bad(&["bezier", "basis", "--n", "0"], "n must be at least 1");
    bad(&["bezier", "basis", "--n", "2", "--scheme", "thesis-quintic"], "n ≥ 3");
    bad(&["bezier", "basis", "--n", "5000"], "too large");
    bad(&["bezier", "basis", "--n", "4", "--scheme", "bogus"], "bogus");
}

const SQUARE: &str = "[[1,0],[0,1],[-1,0],[0,-1]]";

#[test]
fn a_harmonic_curve_converts_within_the_tolerance() {
    let json = ok_on(
        SQUARE,
        &["curve", "to-bezier", "--kind", "harmonic", "--scheme", "hermite", "--tolerance", "1e-6"],
    );
    let report = &json["report"];
    assert!(num(&report["bound"]) <= 1e-6, "{report}");
    assert!(num(&report["max_deviation"]) <= num(&report["bound"]), "{report}");
    assert!(num(&report["max_tangent_jump"]) < 1e-9, "C1: {report}");
    let segments = json["segments"].as_array().expect("segments");
    assert_eq!(segments.len() as u64, report["pieces"].as_u64().expect("pieces"), "pieces");
    let breaks = nums(&json["breaks"]);
    assert_eq!(breaks.len(), segments.len() + 1, "a break per segment end");
    // The square's harmonic curve is the unit circle (n = 4: x(t) = (cos 2πt, sin 2πt) plus
    // the Nyquist term, zero here): every control end point lies on it at its break.
    for (seg, t) in segments.iter().zip(&breaks) {
        let first = &points(seg)[0];
        let want = [(std::f64::consts::TAU * t).cos(), (std::f64::consts::TAU * t).sin()];
        assert!(dist(first, &want) < 1e-12, "at t = {t}: {first:?}");
    }
}

#[test]
fn the_thesis_schemes_are_reported_as_they_are() {
    let cubic: Value =
        ok_on(SQUARE, &["curve", "to-bezier", "--kind", "harmonic", "--scheme", "thesis-cubic"]);
    assert_eq!(cubic["report"]["pieces"], 4, "n pieces");
    assert!(num(&cubic["report"]["max_tangent_jump"]) > 1e-3, "C0");
    let quintic: Value =
        ok_on(SQUARE, &["curve", "to-bezier", "--kind", "harmonic", "--scheme", "thesis-quintic"]);
    assert_eq!(quintic["report"]["degree"], 5, "quintic");
    assert!(
        num(&quintic["report"]["max_deviation"]) < num(&cubic["report"]["max_deviation"]),
        "the quintic is closer"
    );
}

#[test]
fn schemes_apply_to_harmonic_curves_only() {
    bad_on(
        SQUARE,
        &["curve", "to-bezier", "--kind", "catmull-rom", "--scheme", "hermite"],
        "--kind harmonic only",
    );
    bad_on(
        SQUARE,
        &["curve", "to-bezier", "--kind", "harmonic", "--scheme", "cubic"],
        "unknown scheme",
    );
    bad_on(SQUARE, &["curve", "to-bezier", "--kind", "harmonic", "--tolerance", "-1"], "tolerance");
}
