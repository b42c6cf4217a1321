// SPDX-License-Identifier: MIT
//! The 2-D spectrum of a harmonic surface: the tensor product of the curve spectra.
//!
//! p(u, v) = Σₐ Σᵦ [Aₐᵦ·cos 2πau·cos 2πβv + Bₐᵦ·cos 2πau·sin 2πβv
//!                  + Cₐᵦ·sin 2πau·cos 2πβv + Dₐᵦ·sin 2πau·sin 2πβv],
//! a ≤ ⌊m/2⌋, β ≤ ⌊n/2⌋, computed by 1-D FFTs along v (each row) and then along u (each
//! coefficient sequence), with the even-size Nyquist terms halved as for curves (docs/math.md §7).
//! Any partial derivative is the same sum with each factor differentiated.

use std::f64::consts::TAU;

use hi_curve::{ControlPoint, Fourier};
use hi_interval::Interval;

/// Degrees below this keep one direction's harmonics in a stack array; above it they are
/// recomputed per row (the same values, no allocation either way).
const STACK: usize = 64;

/// The real 2-D spectrum of a harmonic surface (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Spectrum2<P> {
    /// Degree ⌊m/2⌋ in u.
    deg_u: usize,
    /// Degree ⌊n/2⌋ in v.
    deg_v: usize,
    /// Coefficients (A, B, C, D) at index `a·(deg_v + 1) + b`.
    coeffs: Vec<[P; 4]>,
}

impl<P: ControlPoint> Spectrum2<P> {
    /// The spectrum of the m×n grid `grid` (row-major, row j ↔ u, column k ↔ v).
    pub(crate) fn from_grid(grid: &[P], m: usize, n: usize) -> Self {
        // Along v: each row's cosine and sine coefficients.
        let rows: Vec<Fourier<P>> = grid.chunks(n).map(Fourier::from_points).collect();
        let (deg_u, deg_v) = (m / 2, n / 2);
        let mut coeffs = vec![[P::ZERO; 4]; (deg_u + 1) * (deg_v + 1)];
        for b in 0..=deg_v {
            let cos_v: Vec<P> = rows.iter().map(|r| r.cos_coeffs()[b]).collect();
            let sin_v: Vec<P> = rows.iter().map(|r| r.sin_coeffs()[b]).collect();
            // Along u: the spectrum of each coefficient sequence.
            let fc = Fourier::from_points(&cos_v);
            let fs = Fourier::from_points(&sin_v);
            for a in 0..=deg_u {
                coeffs[a * (deg_v + 1) + b] = [
                    fc.cos_coeffs()[a],
                    fs.cos_coeffs()[a],
                    fc.sin_coeffs()[a],
                    fs.sin_coeffs()[a],
                ];
            }
        }
        Self { deg_u, deg_v, coeffs }
    }

    /// ∂^{p+q}/∂uᵖ∂v^q of the surface at (u, v), O(mn/4), without allocating.
    pub(crate) fn eval_deriv(&self, u: f64, v: f64, p: usize, q: usize) -> P {
        let dv = self.deg_v;
        let mut row_v = [(0.0, 0.0); STACK];
        if dv < STACK {
            Fourier::<P>::for_each_trig(dv, v, q, |b, c, s| row_v[b] = (c, s));
        }
        let mut res = P::ZERO;
        Fourier::<P>::for_each_trig(self.deg_u, u, p, |a, cu, su| {
            if cu == 0.0 && su == 0.0 {
                return;
            }
            let coeffs = &self.coeffs[a * (dv + 1)..(a + 1) * (dv + 1)];
            let mut with_cos = P::ZERO;
            let mut with_sin = P::ZERO;
            let mut term = |b: usize, cv: f64, sv: f64| {
                let c = &coeffs[b];
                with_cos += c[0] * cv + c[1] * sv;
                with_sin += c[2] * cv + c[3] * sv;
            };
            if dv < STACK {
                for (b, &(cv, sv)) in row_v[..=dv].iter().enumerate() {
                    term(b, cv, sv);
                }
            } else {
                Fourier::<P>::for_each_trig(dv, v, q, term);
            }
            res += with_cos * cu + with_sin * su;
        });
        res
    }

    /// (p, pᵤ, pᵥ) at (u, v) in one pass over the spectrum, O(mn/4), without allocating.
    pub(crate) fn eval_with_partials(&self, u: f64, v: f64) -> (P, P, P) {
        let dv = self.deg_v;
        let mut row_v = [(0.0, 0.0); STACK];
        if dv < STACK {
            Fourier::<P>::for_each_trig(dv, v, 0, |b, c, s| row_v[b] = (c, s));
        }
        let (mut p, mut pu, mut pv) = (P::ZERO, P::ZERO, P::ZERO);
        Fourier::<P>::for_each_trig(self.deg_u, u, 0, |a, cu, su| {
            let coeffs = &self.coeffs[a * (dv + 1)..(a + 1) * (dv + 1)];
            let (mut wc, mut ws, mut wcv, mut wsv) = (P::ZERO, P::ZERO, P::ZERO, P::ZERO);
            let mut term = |b: usize, cv: f64, sv: f64| {
                let c = &coeffs[b];
                let w = TAU * b as f64;
                wc += c[0] * cv + c[1] * sv;
                ws += c[2] * cv + c[3] * sv;
                wcv += (c[1] * cv - c[0] * sv) * w;
                wsv += (c[3] * cv - c[2] * sv) * w;
            };
            if dv < STACK {
                for (b, &(cv, sv)) in row_v[..=dv].iter().enumerate() {
                    term(b, cv, sv);
                }
            } else {
                Fourier::<P>::for_each_trig(dv, v, 0, term);
            }
            let w = TAU * a as f64;
            p += wc * cu + ws * su;
            pu += (ws * cu - wc * su) * w;
            pv += wcv * cu + wsv * su;
        });
        (p, pu, pv)
    }

    /// The coefficients (A, B, C, D) at index `a·(deg_v + 1) + b`.
    pub(crate) fn coefficients(&self) -> &[[P; 4]] {
        &self.coeffs
    }

    /// The degrees (⌊m/2⌋, ⌊n/2⌋).
    pub(crate) fn degrees(&self) -> (usize, usize) {
        (self.deg_u, self.deg_v)
    }

    /// An enclosure of ∂^{p+q}p/∂uᵖ∂v^q over the box `u` × `v`, per coordinate, written to
    /// `out` (`P::DIM` intervals): the sum of the module documentation with each factor's
    /// derivative, (cos 2πau)⁽ᵖ⁾ = (2πa)ᵖ·cos(2πau + pπ/2) and likewise for sin, evaluated in
    /// interval arithmetic (§5.6), so every value of the stored spectrum's derivative over the box
    /// lies in it.
    pub(crate) fn enclose_deriv(
        &self,
        u: Interval,
        v: Interval,
        p: usize,
        q: usize,
        out: &mut [Interval],
    ) {
        let two_pi = Interval::PI * 2.0;
        let trig = |x: Interval, deg: usize, order: usize| -> Vec<(Interval, Interval)> {
            (0..=deg)
                .map(|a| {
                    let w = two_pi * a as f64;
                    let (s, c) = (w * x).sin_cos();
                    deriv_pair_interval(c, s, w, order)
                })
                .collect()
        };
        let tu = trig(u, self.deg_u, p);
        let tv = trig(v, self.deg_v, q);
        out.fill(Interval::ZERO);
        for (a, &(cu, su)) in tu.iter().enumerate() {
            for (b, &(cv, sv)) in tv.iter().enumerate() {
                let c = &self.coeffs[a * (self.deg_v + 1) + b];
                for (k, o) in out.iter_mut().enumerate() {
                    let [ca, cb, cc, cd] = c.map(|x| x.coord(k));
                    *o += cu * (cv * ca + sv * cb) + su * (cv * cc + sv * cd);
                }
            }
        }
    }

    /// A bound of the rounding error of ∂^{p+q}p/∂uᵖ∂v^q evaluated in `f64` by
    /// [`Spectrum2::eval_deriv`] or [`Spectrum2::eval_with_partials`], per coordinate: each
    /// term's trigonometric values carry O((a + β + 2)·ε) (angle addition) and the sum
    /// O(number of terms·ε), so 16·γₖ·Σₐᵦ (2πa)ᵖ(2πβ)^q·(a + β + 2)·max(|A|, …) with
    /// k = a + β + 2 + 4·(terms) covers both (γₖ = k·u/(1 − k·u), Higham).
    pub(crate) fn eval_error_bound(&self, p: i32, q: i32) -> f64 {
        let (deg_u, deg_v) = (self.deg_u, self.deg_v);
        let n_terms = (deg_u + deg_v + 2 + 4 * (deg_u + 1) * (deg_v + 1)) as u32;
        let mut w = 0.0;
        for a in 0..=deg_u {
            for b in 0..=deg_v {
                let c = &self.coeffs[a * (deg_v + 1) + b];
                let size: f64 = c
                    .iter()
                    .map(|x| {
                        (0..P::DIM).map(|d| x.coord(d).abs()).fold(f64::NEG_INFINITY, f64::max)
                    })
                    .sum();
                w +=
                    size * (TAU * a as f64).powi(p) * (TAU * b as f64).powi(q) * (a + b + 2) as f64;
            }
        }
        16.0 * gamma(n_terms) * w
    }

    /// An upper bound of sup over (u, v) of ‖∂^{p+q}p/∂uᵖ∂v^q‖: Σₐᵦ (2πa)ᵖ(2πβ)^q·(‖Aₐᵦ‖ +
    /// ‖Bₐᵦ‖ + ‖Cₐᵦ‖ + ‖Dₐᵦ‖) (each term's factors have magnitude at most one), summed in
    /// interval arithmetic and rounded up, so it bounds the spectrum as stored.
    pub(crate) fn deriv_bound(&self, p: usize, q: usize) -> f64 {
        let two_pi = Interval::PI * Interval::point(2.0);
        let norm = |x: P| {
            (0..P::DIM)
                .map(|d| Interval::point(x.coord(d)).powi(2))
                .fold(Interval::point(0.0), |a, b| a + b)
                .sqrt()
        };
        let mut sum = Interval::point(0.0);
        for a in 0..=self.deg_u {
            if p > 0 && a == 0 {
                continue;
            }
            let wu = (two_pi * Interval::point(a as f64)).powi(p as i32);
            for b in 0..=self.deg_v {
                if q > 0 && b == 0 {
                    continue;
                }
                let wv = (two_pi * Interval::point(b as f64)).powi(q as i32);
                let c = &self.coeffs[a * (self.deg_v + 1) + b];
                let size = c.iter().fold(Interval::point(0.0), |acc, &x| acc + norm(x));
                sum += wu * wv * size;
            }
        }
        sum.hi()
    }
}

/// The derivative of order `order` of the enclosures (cos 2πaX, sin 2πaX), given ω = 2πa:
/// ωᵒʳᵈᵉʳ·(cos, sin) turned by `order` quarter turns.
fn deriv_pair_interval(
    c: Interval,
    s: Interval,
    w: Interval,
    order: usize,
) -> (Interval, Interval) {
    let wp = w.powi(order as i32);
    let (dc, ds) = match order % 4 {
        0 => (c, s),
        1 => (-s, c),
        2 => (-c, -s),
        _ => (s, -c),
    };
    (wp * dc, wp * ds)
}

/// γₙ = n·u/(1 − n·u) with u = 2⁻⁵³: the bound of the relative error of n rounded operations
/// (Higham, *Accuracy and Stability of Numerical Algorithms*, §3.1).
fn gamma(n: u32) -> f64 {
    let nu = f64::from(n) * f64::EPSILON * 0.5;
    nu / (1.0 - nu)
}
