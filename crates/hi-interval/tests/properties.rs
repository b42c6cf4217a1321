// SPDX-License-Identifier: MIT
//! Property tests of the inclusion property (Hardy 2005, §5.6): for random intervals and random
//! points in them, the `f64` evaluation of an operation or a formula (written once through
//! [`Scalar`]) lies in its interval evaluation.
//!
//! This is sound because each `f64` operation returns a double next to the exact result, and the
//! interval bounds are the outward-rounded exact range (see `tests/peer_mpmath.rs` for the
//! comparison with an independent reference).

use hi_interval::{Interval, Scalar};
use hi_testkit::proptest_config;
use proptest::prelude::*;

/// An interval [c − r, c + r]-ish and a point in it, from fractions in [0, 1].
fn interval_and_point(c: f64, w: f64, s: f64) -> (Interval, f64) {
    let lo = c;
    let hi = c + w;
    let x = Interval::new(lo, hi);
    let p = (lo + s * (hi - lo)).clamp(lo, hi);
    (x, p)
}

fn magnitude() -> impl Strategy<Value = f64> {
    prop_oneof![
        -10.0..10.0f64,
        -1e6..1e6f64,
        -1e-6..1e-6f64,
        (-300i32..300).prop_map(|e| 1.5f64 * 2f64.powi(e))
    ]
}

fn width() -> impl Strategy<Value = f64> {
    prop_oneof![Just(0.0), 0.0..1e-8f64, 0.0..1.0f64, 0.0..10.0f64]
}

/// A formula with every operation, written once.
fn formula<S: Scalar>(x: S, y: S) -> S {
    let a = (x * y - S::from_f64(0.75)).sin() * x.cos() + (y.sqr() + S::one()).sqrt();
    let b = (x / (y.sqr() + S::from_f64(2.0))).exp().ln() + x.atan() - y.abs().powi(3);
    a * b - S::ratio(1.0, 3.0)
}

proptest! {
    #![proptest_config(proptest_config(4096))]

    #[test]
    fn binary_operations_include_point_results(
        c1 in magnitude(), w1 in width(), s1 in 0.0..=1.0f64,
        c2 in magnitude(), w2 in width(), s2 in 0.0..=1.0f64,
    ) {
        let (x, p) = interval_and_point(c1, w1, s1);
        let (y, q) = interval_and_point(c2, w2, s2);
        prop_assert!((x + y).contains(p + q), "{x} + {y} ∌ {}", p + q);
        prop_assert!((x - y).contains(p - q), "{x} - {y} ∌ {}", p - q);
        prop_assert!((x * y).contains(p * q), "{x} · {y} ∌ {}", p * q);
        if q != 0.0 {
            let d = x / y;
            prop_assert!(d.contains(p / q) || (p / q).is_infinite(), "{x} / {y} ∌ {}", p / q);
        }
        prop_assert!(x.min(y).contains(p.min(q)) && x.max(y).contains(p.max(q)), "min/max");
        prop_assert!(x.hull(y).contains(p) && x.hull(y).contains(q), "hull");
    }

    #[test]
    fn unary_functions_include_point_results(c in magnitude(), w in width(), s in 0.0..=1.0f64, n in -6i32..8) {
        let (x, p) = interval_and_point(c, w, s);
        prop_assert!(x.sin().contains(p.sin()), "sin {x} ∌ sin {p}");
        prop_assert!(x.cos().contains(p.cos()), "cos {x} ∌ cos {p}");
        prop_assert!(x.atan().contains(p.atan()), "atan");
        prop_assert!(x.sqr().contains(p * p), "sqr");
        prop_assert!(x.abs().contains(p.abs()), "abs");
        let e = p.exp();
        prop_assert!(e.is_infinite() || x.exp().contains(e), "exp {x} ∌ {e}");
        if p > 0.0 {
            prop_assert!(x.ln().contains(p.ln()), "ln");
        }
        if p >= 0.0 {
            prop_assert!(x.sqrt().contains(p.sqrt()), "sqrt");
        }
        // powi by repeated exact-range products: compare with a product of enclosures, which
        // contains the real power too; both must share it.
        let pw = Interval::point(p).powi(n);
        prop_assert!(pw.is_empty() || x.powi(n).overlaps(pw), "powi {n}");
    }

    #[test]
    fn formulas_written_once_include_point_values(
        c1 in -3.0..3.0f64, w1 in width(), s1 in 0.0..=1.0f64,
        c2 in -3.0..3.0f64, w2 in width(), s2 in 0.0..=1.0f64,
    ) {
        let (x, p) = interval_and_point(c1, w1, s1);
        let (y, q) = interval_and_point(c2, w2, s2);
        let v = formula(p, q);
        let enc = formula(x, y);
        // The real value lies in `enc`; the double `v` differs from it by rounding, so compare
        // with a relative slack of a few ulps of the terms.
        let slack = 1e-12 * (1.0 + v.abs());
        prop_assert!(enc.inflate(slack).contains(v), "{enc} ∌ {v}");
        // Interval evaluation over a sub-interval is inside that over the whole (monotonicity).
        let sub = formula(Interval::point(p), Interval::point(q));
        prop_assert!(sub.is_subset(enc), "{sub} ⊄ {enc}");
    }
}
