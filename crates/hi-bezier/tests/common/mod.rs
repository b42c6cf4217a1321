// SPDX-License-Identifier: MIT
//! Reference implementations for the tests, independent of the code under test: exact integer
//! binomials, Bernstein polynomials from powers, conversion to the power basis, Horner, and
//! nearest-point searches by dense sampling.
#![allow(dead_code, reason = "each test binary uses a different subset of the helpers")]

use glam::DVec2;
use hi_bezier::ControlPoint;

/// C(n, k) in exact integer arithmetic.
pub(crate) fn binomial(n: u64, k: u64) -> f64 {
    if k > n {
        return 0.0;
    }
    let k = k.min(n - k);
    let mut res: u128 = 1;
    for j in 0..k {
        res = res * u128::from(n - j) / u128::from(j + 1);
    }
    res as f64
}

/// Bⁿᵢ(t) straight from eq. 2.2: C(n, i)·tⁱ·(1 − t)ⁿ⁻ⁱ.
pub(crate) fn bernstein(n: usize, i: usize, t: f64) -> f64 {
    binomial(n as u64, i as u64) * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32)
}

/// Σᵢ Bⁿᵢ(t)·Pᵢ by the explicit sum (no de Casteljau).
pub(crate) fn bezier_sum<P: ControlPoint>(points: &[P], t: f64) -> P {
    let n = points.len() - 1;
    let mut res = P::ZERO;
    for (i, &p) in points.iter().enumerate() {
        res += p * bernstein(n, i, t);
    }
    res
}

/// Power-basis coefficients a₀, …, aₙ of Σᵢ Bⁿᵢ(t)·Pᵢ, expanding
/// (1 − t)ⁿ⁻ⁱ = Σₗ C(n − i, l)(−t)ˡ.
pub(crate) fn power_coefficients<P: ControlPoint>(points: &[P]) -> Vec<P> {
    let n = points.len() - 1;
    let mut a = vec![P::ZERO; n + 1];
    for (i, &p) in points.iter().enumerate() {
        let c = binomial(n as u64, i as u64);
        for l in 0..=n - i {
            let sign = if l % 2 == 0 { 1.0 } else { -1.0 };
            a[i + l] += p * (c * binomial((n - i) as u64, l as u64) * sign);
        }
    }
    a
}

/// The k-th derivative of the power-basis polynomial Σ aⱼtʲ at t, by differentiating the
/// coefficients and Horner's rule.
pub(crate) fn power_deriv<P: ControlPoint>(a: &[P], k: usize, t: f64) -> P {
    if k >= a.len() {
        return P::ZERO;
    }
    let d: Vec<P> =
        (k..a.len()).map(|j| a[j] * ((j - k + 1..=j).map(|x| x as f64).product::<f64>())).collect();
    let mut res = P::ZERO;
    for &c in d.iter().rev() {
        res = res * t + c;
    }
    res
}

/// Distance from `p` to the segment ab.
pub(crate) fn dist_to_segment<P: ControlPoint>(p: P, a: P, b: P) -> f64 {
    let ab = b - a;
    let len2 = ab.dot(ab);
    let s = if len2 > 0.0 { ((p - a).dot(ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
    (p - (a + ab * s)).norm()
}

/// Distance from `p` to the polyline.
pub(crate) fn dist_to_polyline<P: ControlPoint>(p: P, poly: &[P]) -> f64 {
    if poly.len() == 1 {
        return (p - poly[0]).norm();
    }
    poly.windows(2).map(|w| dist_to_segment(p, w[0], w[1])).fold(f64::INFINITY, f64::min)
}

/// Distance from `p` to the curve f over [0, 1]: the nearest of `n` samples, refined by a
/// golden-section search on the two neighbouring sample intervals.
pub(crate) fn dist_to_curve<P: ControlPoint>(p: P, f: &impl Fn(f64) -> P, n: usize) -> f64 {
    let d = |t: f64| (f(t) - p).norm();
    let (best_i, _) = (0..=n)
        .map(|i| (i, d(i as f64 / n as f64)))
        .fold((0, f64::INFINITY), |acc, x| if x.1 < acc.1 { x } else { acc });
    let h = 1.0 / n as f64;
    let (mut a, mut b) = ((best_i as f64 * h - h).max(0.0), (best_i as f64 * h + h).min(1.0));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let c = b - g * (b - a);
        let e = a + g * (b - a);
        if d(c) < d(e) {
            b = e;
        } else {
            a = c;
        }
    }
    d(0.5 * (a + b)).min(d(best_i as f64 * h))
}

/// Central difference of order 1 of f at t with step h.
pub(crate) fn central<P: ControlPoint>(f: impl Fn(f64) -> P, t: f64, h: f64) -> P {
    (f(t + h) - f(t - h)) * (0.5 / h)
}

/// A fixed "random" plane polygon of m points (a linear congruential sequence), so tests need
/// no RNG.
pub(crate) fn wiggly_points(m: usize, seed: u64) -> Vec<DVec2> {
    let mut state = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
    let mut next = || {
        state =
            state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        ((state >> 11) as f64 / (1u64 << 53) as f64) * 4.0 - 2.0
    };
    (0..m).map(|i| DVec2::new(i as f64 + 0.5 * next(), next())).collect()
}
