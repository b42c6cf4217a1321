// SPDX-License-Identifier: MIT
//! The thesis's two schemes as piecewise-polynomial approximations of the basis σ₀ … σₙ₋₁
//! ([`BasisPieces`]), and the Hermite pieces they and the Hermite scheme are made of.

use hi_bezier::{BezierCurve, ControlPoint, ParamRange};
use hi_interval::{Interval, RootOptions};

use super::{BezierSpline, locate};
use crate::{Error, Sigma};

/// A piecewise-polynomial approximation of the whole basis σ₀ … σₙ₋₁ of size n on [0, 1]:
/// pieces [`breaks[a]`, `breaks[a+1]`] and, for each piece a and function k, the Bézier control
/// values `P[a][k][j]`, j = 0 … degree (local parameter s = (t − `breaks[a]`)/(`breaks[a+1]` − `breaks[a]`)).
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BasisPieces {
    n: usize,
    degree: usize,
    // Invariant: `breaks[0]` = 0, `breaks[last]` = 1, increasing; ctrl.len() = pieces·n·(degree+1).
    breaks: Vec<f64>,
    ctrl: Vec<f64>,
    // The breaks of σ₀'s own pieces, from 0 to 1 (σₖ's are these shifted by k/n).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub(super) own: Vec<f64>,
}

/// The inverse of the Bernstein matrix Bᵢⱼ = B³ⱼ(i/3): control values from 4 equally spaced
/// samples (P₁ = (−5f₀ + 18f₁ − 9f₂ + 2f₃)/6, P₂ symmetric).
fn cubic_from_samples(f: [f64; 4]) -> [f64; 4] {
    [
        f[0],
        (-5.0 * f[0] + 18.0 * f[1] - 9.0 * f[2] + 2.0 * f[3]) / 6.0,
        (2.0 * f[0] - 9.0 * f[1] + 18.0 * f[2] - 5.0 * f[3]) / 6.0,
        f[3],
    ]
}

/// The quintic Bézier control points of the Hermite data (f, f′, f″) at both ends of a piece of
/// width h (derivatives with respect to t).
pub(super) fn quintic_hermite<P: ControlPoint>(f0: [P; 3], f1: [P; 3], h: f64) -> [P; 6] {
    let [a, da, dda] = f0;
    let [b, db, ddb] = f1;
    [
        a,
        a + da * (h / 5.0),
        a + da * (2.0 * h / 5.0) + dda * (h * h / 20.0),
        b - db * (2.0 * h / 5.0) + ddb * (h * h / 20.0),
        b - db * (h / 5.0),
        b,
    ]
}

/// The cubic Bézier control points of the Hermite data (f, f′) at both ends of a piece of
/// width h.
pub(super) fn cubic_hermite<P: ControlPoint>(f0: [P; 2], f1: [P; 2], h: f64) -> [P; 4] {
    [f0[0], f0[0] + f0[1] * (h / 3.0), f1[0] - f1[1] * (h / 3.0), f1[0]]
}

impl BasisPieces {
    /// The thesis's cubic scheme for basis size n (docs/math.md §4): n pieces [a/n, (a+1)/n]; on
    /// each, `P[a][k]` = B⁻¹·[σₖ(a/n + i/(3n))]ᵢ. `P[a][k][0]` = δₐₖ and `P[a][k][3]` = δₐ₊₁,ₖ.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroBasisSize`] for n = 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_curve::bezier::BasisPieces;
    ///
    /// let p = BasisPieces::thesis_cubic(5)?;
    /// assert_eq!((p.n_pieces(), p.degree()), (5, 3));
    /// // The ends are Kronecker deltas: the data points are interpolated.
    /// assert_eq!(p.control(2, 2)[0], 1.0);
    /// assert_eq!(p.control(2, 3)[3], 1.0);
    /// # Ok::<(), hi_curve::Error>(())
    /// ```
    pub fn thesis_cubic(n: usize) -> Result<Self, Error> {
        let sigma = Sigma::try_new(n)?;
        let nf = n as f64;
        let mut ctrl = Vec::with_capacity(n * n * 4);
        for a in 0..n {
            for k in 0..n {
                let f = [0, 1, 2, 3].map(|i| {
                    if i == 0 {
                        f64::from(u8::from(k == a))
                    } else if i == 3 {
                        f64::from(u8::from(k == (a + 1) % n))
                    } else {
                        sigma.eval(k, (a as f64 + f64::from(i) / 3.0) / nf)
                    }
                });
                ctrl.extend(cubic_from_samples(f));
            }
        }
        let breaks: Vec<f64> = (0..=n).map(|a| a as f64 / nf).collect();
        Ok(Self { n, degree: 3, own: breaks.clone(), breaks, ctrl })
    }

    /// The zeros of σ′ in [0, 1), from interval Newton, reduced modulo 1 and sorted; 0 is one.
    fn sigma_prime_zeros(n: usize) -> Result<Vec<f64>, Error> {
        let sigma = Sigma::try_new(n)?;
        let roots = sigma.deriv_roots(1, Interval::new(-0.01, 1.01), &RootOptions::default());
        if !roots.complete {
            return Err(Error::Singular { what: "the zeros of σ′ (the root search hit a cap)" });
        }
        // The enclosures are narrow but not tight: polish each midpoint by Newton's method on
        // σ′ (staying inside the enclosure) so that shifted copies of one zero coincide.
        let mut zeros: Vec<f64> = roots
            .roots
            .iter()
            .map(|r| {
                let (lo, hi) = (r.enclosure.lo(), r.enclosure.hi());
                let mut t = r.enclosure.mid();
                for _ in 0..4 {
                    let d2 = sigma.deriv(0, t, 2);
                    if d2 == 0.0 {
                        break;
                    }
                    t = (t - sigma.deriv(0, t, 1) / d2).clamp(lo, hi);
                }
                t.rem_euclid(1.0)
            })
            .collect();
        zeros.push(0.0);
        Ok(dedup_sorted(zeros))
    }

    /// The thesis's degree-5 scheme for basis size n: σ is approximated between consecutive
    /// zeros of σ′ by two quintic Hermite pieces (value, σ′, σ″ of σ at the zeros and the
    /// midpoint); σₖ(t) = σ(t − k/n) by the same pieces shifted. The result's breaks are the
    /// union of all shifted breaks, and on each of its pieces every σₖ is the restriction of
    /// one of its own quintics.
    ///
    /// # Errors
    ///
    /// [`Error::ZeroBasisSize`] for n = 0; [`Error::InvalidCount`] for n ≤ 2, where σ′ has
    /// too few zeros for the scheme (n = 1: σ′ ≡ 0); [`Error::Singular`] if the root search
    /// does not complete.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_curve::bezier::BasisPieces;
    ///
    /// let p = BasisPieces::thesis_quintic(5)?;
    /// assert_eq!(p.degree(), 5);
    /// // Exact at the zeros of σ′, which include the nodes: σ₀(0) = 1.
    /// assert!((p.eval(0, 0.0) - 1.0).abs() < 1e-14);
    /// # Ok::<(), hi_curve::Error>(())
    /// ```
    pub fn thesis_quintic(n: usize) -> Result<Self, Error> {
        if n == 0 {
            return Err(Error::ZeroBasisSize);
        }
        if n <= 2 {
            return Err(Error::InvalidCount {
                what: "basis size n for the thesis quintic scheme",
                value: n,
                expected: "n ≥ 3 (σ′ needs zeros that split the period)",
            });
        }
        let sigma = Sigma::new(n);
        let zeros = Self::sigma_prime_zeros(n)?;
        // σ's own breaks: the zeros and the midpoints between them (cyclically).
        let mut own = Vec::with_capacity(2 * zeros.len() + 1);
        for (i, &z) in zeros.iter().enumerate() {
            let next = zeros.get(i + 1).copied().unwrap_or(1.0 + zeros[0]);
            own.push(z);
            own.push(0.5 * (z + next));
        }
        own.push(1.0 + zeros[0]);
        let nf = n as f64;
        let mut all: Vec<f64> = (0..n)
            .flat_map(|k| own.iter().map(move |&b| (b + k as f64 / nf).rem_euclid(1.0)))
            .collect();
        all.push(0.0);
        let mut breaks = dedup_sorted(all);
        breaks.push(1.0);
        let data = |t: f64| [0, 1, 2].map(|o| sigma.deriv(0, t, o));
        // σ's quintic on each of its own pieces, made once: every σₖ on every piece of the
        // basis is a part of one of them.
        let ends: Vec<[f64; 3]> = own.iter().map(|&b| data(b)).collect();
        let quintics: Vec<BezierCurve<f64>> = own
            .windows(2)
            .zip(ends.windows(2))
            .map(|(b, e)| BezierCurve::new(quintic_hermite(e[0], e[1], b[1] - b[0]).to_vec()))
            .collect();
        let mut ctrl = Vec::with_capacity((breaks.len() - 1) * n * 6);
        for w in breaks.windows(2) {
            let (u0, u1) = (w[0], w[1]);
            for k in 0..n {
                // σₖ on [u0, u1] is σ on [u0 − k/n, u1 − k/n]: find σ's piece holding it, the
                // first [b₀, b₁] with b₀ ≤ mid ≤ b₁ (mid ≥ own[0] by construction).
                let shift = k as f64 / nf;
                let mid = (0.5 * (u0 + u1) - shift - own[0]).rem_euclid(1.0) + own[0];
                let after = own.partition_point(|&b| b < mid);
                let i = if after < own.len() { after.saturating_sub(1) } else { 0 };
                let (b0, b1) = (own[i], own[i + 1]);
                let curve = &quintics[i];
                // Local parameters of [u0, u1] − shift inside [b0, b1], unwrapped near mid.
                let offset = mid - (0.5 * (u0 + u1) - shift);
                let (s0, s1) = (
                    (u0 - shift + offset - b0) / (b1 - b0),
                    (u1 - shift + offset - b0) / (b1 - b0),
                );
                let sub = curve.subsegment(ParamRange::new(s0.clamp(0.0, 1.0), s1.clamp(0.0, 1.0)));
                ctrl.extend_from_slice(sub.control_points());
            }
        }
        Ok(Self { n, degree: 5, breaks, ctrl, own })
    }

    /// The basis size n.
    #[must_use]
    pub fn n(&self) -> usize {
        self.n
    }

    /// The degree of every piece (3 or 5).
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The number of pieces.
    #[must_use]
    pub fn n_pieces(&self) -> usize {
        self.breaks.len() - 1
    }

    /// The piece boundaries, 0 = `breaks[0]` < … < `breaks[pieces]` = 1.
    #[must_use]
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }

    /// The breaks of σ₀'s own pieces, from 0 to 1: those of σₖ are these shifted by k/n. For
    /// the cubic scheme they are the breaks a/n; for the quintic scheme the zeros of σ′ and the
    /// midpoints between them, a subset of [`BasisPieces::breaks`].
    #[must_use]
    pub fn sigma_breaks(&self) -> &[f64] {
        &self.own
    }

    /// The control values `P[a][k][0 ..= degree]` of σₖ on piece a.
    ///
    /// # Panics
    ///
    /// If a ≥ [`BasisPieces::n_pieces`] or k ≥ n.
    #[must_use]
    pub fn control(&self, a: usize, k: usize) -> &[f64] {
        assert!(a < self.n_pieces() && k < self.n, "piece {a} or function {k} out of range");
        let m = self.degree + 1;
        let start = (a * self.n + k) * m;
        &self.ctrl[start..start + m]
    }

    /// The piece holding t (taken modulo 1) and the local parameter in it.
    fn locate(&self, t: f64) -> (usize, f64) {
        locate(&self.breaks, t)
    }

    /// The approximation of σₖ(t) (t taken modulo 1; k modulo n).
    #[must_use]
    pub fn eval(&self, k: usize, t: f64) -> f64 {
        let (a, s) = self.locate(t);
        BezierCurve::new(self.control(a, k % self.n).to_vec()).eval(s)
    }

    /// The Bézier form of the curve Σₖ σₖ(t)·xₖ with this approximation of the basis: piece a
    /// has control points Σₖ `P[a][k][j]`·xₖ (the thesis's patch formula, in one direction).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] if `points.len()` is not n; [`Error::NonFinitePoint`].
    pub fn apply<P: ControlPoint>(&self, points: &[P]) -> Result<BezierSpline<P>, Error> {
        if points.len() != self.n {
            return Err(Error::InvalidCount {
                what: "number of points for this basis",
                value: points.len(),
                expected: "exactly the basis size n",
            });
        }
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        let segments = (0..self.n_pieces())
            .map(|a| {
                let control = (0..=self.degree)
                    .map(|j| {
                        let mut sum = P::ZERO;
                        for (k, &x) in points.iter().enumerate() {
                            sum += x * self.control(a, k)[j];
                        }
                        sum
                    })
                    .collect();
                BezierCurve::new(control)
            })
            .collect();
        Ok(BezierSpline { breaks: self.breaks.clone(), segments })
    }
}

/// Sorts and removes values closer than 1e-9 to their predecessor (the same break reached by
/// two shifts, up to rounding); values ≥ 1 − 1e-9 wrap to 0.
fn dedup_sorted(mut v: Vec<f64>) -> Vec<f64> {
    for x in &mut v {
        if *x >= 1.0 - 1e-9 {
            *x = 0.0;
        }
    }
    v.sort_by(f64::total_cmp);
    v.dedup_by(|b, a| (*b - *a).abs() < 1e-9);
    v
}
