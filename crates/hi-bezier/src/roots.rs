// SPDX-License-Identifier: MIT
//! Real roots in [0, 1] of a polynomial in Bernstein form, by subdivision (Theorem 2.2) and
//! the variation-diminishing property of Bézier curves (after Lane and Riesenfeld).
//!
//! The number of sign changes of the Bernstein coefficients bounds the number of roots in the
//! open interval and has the same parity (Descartes' rule of signs in Bernstein form), so an
//! interval whose coefficients change sign once holds exactly one simple root, found by a
//! safeguarded secant (Illinois) iteration, and an interval without sign change holds none.

use crate::BezierCurve;
use crate::curve::de_casteljau;
use crate::subdivide::split_points;

/// Deepest subdivision; at 2⁻⁵⁴ the interval is below the spacing of doubles near 1.
const MAX_DEPTH: u32 = 54;

impl BezierCurve<f64> {
    /// The real roots of the polynomial q(t) in [0, 1], sorted.
    ///
    /// Each simple root is found to a few ulps. A multiple root, or a cluster of roots where
    /// the polynomial vanishes to the rounding of its coefficients, is reported once, at the
    /// centre of the interval where the coefficients are lost in rounding (for a double root
    /// that interval is about √ε wide, so the root is located to about 1e-8). The zero
    /// polynomial (all coefficients 0) returns no roots, although every t is one.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_bezier::BezierCurve;
    ///
    /// // (t − ¼)(t − ¾) = t² − t + 3/16 in Bernstein form: c₀ = 3/16, c₁ = 3/16 − ½, c₂ = 3/16.
    /// let q = BezierCurve::new(vec![0.1875, -0.3125, 0.1875]);
    /// let roots = q.roots();
    /// assert_eq!(roots.len(), 2);
    /// assert!((roots[0] - 0.25).abs() < 1e-15 && (roots[1] - 0.75).abs() < 1e-15);
    /// ```
    #[must_use]
    pub fn roots(&self) -> Vec<f64> {
        let c = self.control_points();
        let mut res = Vec::new();
        let scale = c.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if scale == 0.0 {
            return res;
        }
        if c[0] == 0.0 {
            res.push(0.0);
        }
        let mut search = Search {
            noise: 4.0 * c.len() as f64 * f64::EPSILON * scale,
            roots: Vec::new(),
            clusters: Vec::new(),
        };
        search.isolate(c, 0.0, 1.0, 0);
        res.extend(search.roots);
        // Touching intervals of coefficients lost in rounding are one (multiple) root each.
        let mut merged: Vec<(f64, f64)> = Vec::new();
        for (a, b) in search.clusters {
            match merged.last_mut() {
                Some(last) if last.1 >= a => last.1 = last.1.max(b),
                _ => merged.push((a, b)),
            }
        }
        res.extend(merged.iter().map(|(a, b)| 0.5 * (a + b)));
        if c[c.len() - 1] == 0.0 {
            res.push(1.0);
        }
        res.sort_by(f64::total_cmp);
        res.dedup();
        res
    }
}

/// The state of one root search.
struct Search {
    /// Coefficients all below this are rounding noise of the input.
    noise: f64,
    /// Roots found as sign changes.
    roots: Vec<f64>,
    /// Intervals (in increasing order) where the polynomial vanishes to rounding.
    clusters: Vec<(f64, f64)>,
}

impl Search {
    /// Records the roots in the open interval (a, b) of the polynomial with Bernstein
    /// coefficients `c` on [a, b].
    fn isolate(&mut self, c: &[f64], a: f64, b: f64, depth: u32) {
        let changes = sign_changes(c);
        if changes == 0 {
            return;
        }
        let first = c[0];
        let last = c[c.len() - 1];
        if changes == 1 && first != 0.0 && last != 0.0 {
            self.roots.push(illinois(c, a, b));
            return;
        }
        let mid = 0.5 * (a + b);
        if depth >= MAX_DEPTH || mid <= a || mid >= b || c.iter().all(|x| x.abs() <= self.noise) {
            self.clusters.push((a, b));
            return;
        }
        let (left, right) = split_points(c, 0.5);
        self.isolate(&left, a, mid, depth + 1);
        if right[0] == 0.0 {
            self.roots.push(mid);
        }
        self.isolate(&right, mid, b, depth + 1);
    }
}

/// Number of sign changes in `c`, zeros skipped.
fn sign_changes(c: &[f64]) -> usize {
    let mut count = 0;
    let mut last = 0.0;
    for &x in c {
        if x != 0.0 {
            if last != 0.0 && (x > 0.0) != (last > 0.0) {
                count += 1;
            }
            last = x;
        }
    }
    count
}

/// The single root in (a, b) of the polynomial with coefficients `c` on [a, b], whose end
/// values c₀ and cₙ have opposite signs: regula falsi with the Illinois modification, bracketed.
fn illinois(c: &[f64], a: f64, b: f64) -> f64 {
    let mut work = c.to_vec();
    let mut f = |s: f64| {
        work.copy_from_slice(c);
        de_casteljau(&mut work, s)
    };
    // Work in the local parameter s ∈ [0, 1].
    let (mut s0, mut s1) = (0.0f64, 1.0f64);
    let (mut f0, mut f1) = (c[0], c[c.len() - 1]);
    let mut side = 0i8;
    for _ in 0..200 {
        let s = if f0 == f1 { 0.5 * (s0 + s1) } else { (s0 * f1 - s1 * f0) / (f1 - f0) };
        let s = if s > s0 && s < s1 { s } else { 0.5 * (s0 + s1) };
        if s <= s0 || s >= s1 {
            break;
        }
        let fs = f(s);
        if fs == 0.0 {
            return a + (b - a) * s;
        }
        if (fs > 0.0) == (f1 > 0.0) {
            s1 = s;
            f1 = fs;
            if side == -1 {
                f0 *= 0.5;
            }
            side = -1;
        } else {
            s0 = s;
            f0 = fs;
            if side == 1 {
                f1 *= 0.5;
            }
            side = 1;
        }
        if s1 - s0 <= 4.0 * f64::EPSILON * s1.abs().max(1e-300) {
            break;
        }
    }
    let s = if f0.abs() < f1.abs() { s0 } else { s1 };
    a + (b - a) * s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Bernstein;

    /// Bernstein coefficients of Πⱼ(t − rⱼ), built by multiplying power-basis factors and
    /// converting with cᵢ = Σⱼ₌₀ⁱ C(i, j)/C(n, j)·aⱼ.
    fn from_roots(roots: &[f64]) -> BezierCurve<f64> {
        let mut a = vec![1.0];
        for &r in roots {
            let mut next = vec![0.0; a.len() + 1];
            for (k, &ak) in a.iter().enumerate() {
                next[k + 1] += ak;
                next[k] -= r * ak;
            }
            a = next;
        }
        let n = a.len() - 1;
        let c = (0..=n)
            .map(|i| {
                (0..=i)
                    .map(|j| {
                        crate::bernstein::binomial(i, j) / crate::bernstein::binomial(n, j) * a[j]
                    })
                    .sum()
            })
            .collect();
        BezierCurve::new(c)
    }

    #[test]
    fn finds_known_roots() {
        let roots = [0.05, 0.3, 0.31, 0.7, 0.999];
        let q = from_roots(&roots);
        let found = q.roots();
        assert_eq!(found.len(), roots.len(), "{found:?}");
        for (f, r) in found.iter().zip(roots) {
            assert!((f - r).abs() < 1e-12, "{f} vs {r}");
        }
    }

    #[test]
    fn roots_outside_are_ignored_and_ends_found() {
        let q = from_roots(&[-0.5, 0.0, 1.5, 1.0]);
        assert_eq!(q.roots(), vec![0.0, 1.0]);
        assert!(BezierCurve::new(vec![1.0, 2.0, 0.5]).roots().is_empty());
        assert!(BezierCurve::new(vec![0.0, 0.0]).roots().is_empty());
    }

    #[test]
    fn double_root() {
        let q = from_roots(&[0.4, 0.4]);
        let found = q.roots();
        assert!(!found.is_empty(), "a touching zero is reported");
        assert!(found.iter().all(|r| (r - 0.4).abs() < 1e-7), "{found:?}");
        let _ = Bernstein::new(2);
    }
}
