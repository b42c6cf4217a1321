// SPDX-License-Identifier: MIT
use super::*;

#[test]
fn empty_and_entire_propagate() {
    let e = Interval::EMPTY;
    let x = Interval::new(1.0, 2.0);
    assert!((e + x).is_empty() && (x * e).is_empty() && (e / x).is_empty(), "empty absorbs");
    assert!(e.sqrt().is_empty() && e.sqr().is_empty() && e.powi(3).is_empty(), "unary");
    assert!((Interval::ENTIRE + x).is_entire(), "entire + bounded");
    assert_eq!(Interval::ENTIRE * Interval::ZERO, Interval::ZERO, "0 · ℝ = 0");
    assert!(Interval::new(f64::INFINITY, f64::INFINITY).is_empty(), "[∞, ∞] is no interval");
    assert!(Interval::new(f64::NEG_INFINITY, f64::INFINITY).is_entire(), "ℝ");
}

#[test]
fn signed_zeros_are_one_value() {
    let a = Interval::new(0.0, 0.0);
    let b = Interval::new(-0.0, -0.0);
    assert_eq!(a, b);
    assert!(a.lo().is_sign_negative() && a.hi().is_sign_positive(), "normalised zeros");
    // 1/[0, 1] and 1/[-0, 1] are the same half-line.
    let one = Interval::ONE;
    assert_eq!(one / Interval::new(0.0, 1.0), Interval::new(1.0, f64::INFINITY));
    assert_eq!(one / Interval::new(-0.0, 1.0), Interval::new(1.0, f64::INFINITY));
    assert_eq!(one / Interval::new(-1.0, -0.0), Interval::new(f64::NEG_INFINITY, -1.0));
    assert_eq!(-Interval::new(0.0, 1.0), Interval::new(-1.0, 0.0));
}

#[test]
fn division_by_intervals_holding_zero() {
    let x = Interval::new(1.0, 2.0);
    assert!((x / Interval::new(-1.0, 1.0)).is_entire(), "0 inside Y");
    assert!((x / Interval::ZERO).is_empty(), "Y = [0, 0]");
    assert!((Interval::new(-1.0, 1.0) / Interval::new(0.0, 1.0)).is_entire(), "0 in both");
    let (a, b) = Interval::new(-2.0, -1.0).div_extended(Interval::new(-4.0, 2.0));
    assert_eq!(a, Interval::new(f64::NEG_INFINITY, -0.5));
    assert_eq!(b, Interval::new(0.25, f64::INFINITY));
    let (a, b) = Interval::new(-2.0, -1.0).div_extended(Interval::new(-4.0, 0.0));
    assert_eq!(a, Interval::new(0.25, f64::INFINITY));
    assert!(b.is_empty(), "one part only");
}

#[test]
fn exact_results_are_tight() {
    let x = Interval::new(0.5, 3.0);
    let y = Interval::new(-2.0, 0.25);
    assert_eq!(x + y, Interval::new(-1.5, 3.25));
    assert_eq!(x - y, Interval::new(0.25, 5.0));
    assert_eq!(x * y, Interval::new(-6.0, 0.75));
    assert_eq!(x / Interval::new(2.0, 4.0), Interval::new(0.125, 1.5));
    assert_eq!(Interval::new(4.0, 9.0).sqrt(), Interval::new(2.0, 3.0));
    assert_eq!(Interval::new(-3.0, 2.0).abs(), Interval::new(0.0, 3.0));
    assert_eq!(Interval::new(-3.0, 2.0).powi(4), Interval::new(0.0, 81.0));
    assert_eq!(Interval::new(2.0, 4.0).powi(-2), Interval::new(1.0 / 16.0, 0.25));
}

#[test]
fn inexact_results_enclose() {
    // 0.1 + 0.2: the exact sum of the two doubles lies strictly between two doubles.
    let s = Interval::point(0.1) + Interval::point(0.2);
    assert_eq!(s.lo().next_up(), s.hi(), "one ulp wide");
    assert!(s.contains(0.1 + 0.2), "contains the nearest double");
    let third = Interval::ratio(1.0, 3.0);
    assert!((third * 3.0).contains(1.0), "(1/3)·3 ∋ 1");
    let root2 = Interval::point(2.0).sqrt();
    assert!(root2.sqr().contains(2.0), "(√2)² ∋ 2");
    assert!(Interval::PI.lo() < Interval::PI.hi(), "π is not a double");
    assert_eq!(Interval::PI.lo().next_up(), Interval::PI.hi(), "tightest π");
}

#[test]
fn overflow_goes_to_infinity_outward() {
    let big = Interval::new(f64::MAX, f64::MAX);
    let s = big + big;
    assert_eq!((s.lo(), s.hi()), (f64::MAX, f64::INFINITY));
    let p = big * Interval::new(-2.0, -2.0);
    assert_eq!((p.lo(), p.hi()), (f64::NEG_INFINITY, -f64::MAX));
}

#[test]
fn mid_width_mag_mig() {
    let x = Interval::new(-1.0, 3.0);
    assert_eq!((x.mid(), x.width(), x.mag(), x.mig(), x.rad()), (1.0, 4.0, 3.0, 0.0, 2.0));
    assert_eq!(Interval::ENTIRE.mid(), 0.0);
    assert!(Interval::EMPTY.mid().is_nan(), "documented NaN");
    let h = Interval::new(-f64::MAX, f64::MAX);
    assert_eq!(h.mid(), 0.0);
    assert_eq!(h.width(), f64::INFINITY);
}
