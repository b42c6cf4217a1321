// SPDX-License-Identifier: MIT
//! One parameter direction of a cubic B-spline (Hardy 2005, §2.9–2.10, §4.4): its knots, open
//! or closed, unrolled into an ordinary knot vector, with de Boor evaluation, blossoms and exact
//! knot refinement of the control points along it.
//!
//! The closed convention is that of `hi_curve`'s `BSplineCurve` for degree 3: with n control
//! points and breakpoints τ₀ < … < τₙ (period L = τₙ − τ₀), control point i has the B-spline
//! supported on [τᵢ₋₂, τᵢ₊₂], centred at τᵢ. Unrolled, the knots are uₖ = τₖ₋₃ (k = 0, …, n + 6,
//! with τⱼ₊ₙ = τⱼ + L) and the n + 3 control points are cᵢ₋₁ mod n.

use crate::bspline::{blossom, de_boor};
use glam::DVec3;
use hi_curve::Error as CurveError;

use crate::{Error, ParamRange};

/// The degree: the surfaces of §4.4 are bicubic.
pub(crate) const DEGREE: usize = 3;

/// One direction of a bicubic B-spline surface.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Axis {
    /// Closed (periodic) direction.
    pub(crate) closed: bool,
    /// The knots as given: n + 4 (open) or the n + 1 breakpoints τ₀, …, τₙ (closed).
    pub(crate) knots: Vec<f64>,
    /// The number n of control points along the direction.
    pub(crate) n_control: usize,
    /// The unrolled knot vector (the knots themselves when open).
    pub(crate) ext: Vec<f64>,
    /// The first and last non-empty knot intervals [uⱼ, uⱼ₊₁] of the domain, by index j.
    first_span: usize,
    last_span: usize,
}

impl Axis {
    /// An open direction with these knots for `n_control` control points, or a closed one with
    /// these breakpoints.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::NonFiniteParameter`] for a non-finite knot, [`hi_curve::Error::InvalidCount`] for a
    /// knot count that does not fit, fewer than 4 control points (open) or 3 (closed),
    /// decreasing knots, a knot of multiplicity above 3 inside the domain (4 at the ends of an
    /// open direction), or an empty domain.
    pub(crate) fn try_new(
        knots: Vec<f64>,
        n_control: usize,
        closed: bool,
        name: &'static str,
    ) -> Result<Self, Error> {
        if let Some(&value) = knots.iter().find(|k| !k.is_finite()) {
            return Err(Error::Curve(CurveError::NonFiniteParameter { name, value }));
        }
        let (needed, expected_knots) =
            if closed { (3, n_control + 1) } else { (DEGREE + 1, n_control + DEGREE + 1) };
        if n_control < needed {
            return Err(Error::Curve(CurveError::InvalidCount {
                what: "number of control points along a direction",
                value: n_control,
                expected: if closed { "at least 3 (closed)" } else { "at least 4 (open)" },
            }));
        }
        if knots.len() != expected_knots {
            return Err(Error::Curve(CurveError::InvalidCount {
                what: name,
                value: knots.len(),
                expected: if closed {
                    "one more breakpoint than control points (closed)"
                } else {
                    "4 more knots than control points (open)"
                },
            }));
        }
        if let Some(i) = knots.windows(2).position(|w| w[1] < w[0]) {
            return Err(Error::Curve(CurveError::InvalidCount {
                what: "index of a decreasing knot",
                value: i + 1,
                expected: "knots in non-decreasing order",
            }));
        }
        let ext = if closed {
            let n = n_control;
            let period = knots[n] - knots[0];
            let tau = |j: isize| {
                let (q, r) = (j.div_euclid(n as isize), j.rem_euclid(n as isize));
                knots[r as usize] + q as f64 * period
            };
            (0..n + 2 * DEGREE + 1).map(|k| tau(k as isize - DEGREE as isize)).collect()
        } else {
            knots.clone()
        };
        let n_ext = ext.len() - DEGREE - 1;
        let nonempty = |j: &usize| ext[*j] < ext[*j + 1];
        let Some(first_span) = (DEGREE..n_ext).find(nonempty) else {
            return Err(Error::Curve(CurveError::InvalidCount {
                what: "number of non-empty knot intervals",
                value: 0,
                expected: "at least 1",
            }));
        };
        let last_span = (DEGREE..n_ext).rev().find(nonempty).unwrap_or(first_span);
        // Multiplicity: at most 3 inside the domain (the curve stays continuous), 4 at the
        // clamped ends of an open direction.
        let mut run = 1;
        for (k, w) in ext.windows(2).enumerate() {
            run = if w[1] == w[0] { run + 1 } else { 1 };
            let at_end = !closed && (k < DEGREE || k + 1 >= n_ext);
            if run > DEGREE + usize::from(at_end) {
                return Err(Error::Curve(CurveError::InvalidCount {
                    what: "multiplicity of a knot",
                    value: run,
                    expected: "at most 3 (4 at the ends of an open direction)",
                }));
            }
        }
        Ok(Self { closed, knots, n_control, ext, first_span, last_span })
    }

    /// The domain [a, b]: [u₃, uₙ] open, [τ₀, τₙ] closed.
    pub(crate) fn domain(&self) -> ParamRange {
        ParamRange::new(self.ext[DEGREE], self.ext[self.ext.len() - DEGREE - 1])
    }

    /// The distinct knots of the domain, increasing, from a to b: the ends of the polynomial
    /// pieces.
    pub(crate) fn breakpoints(&self) -> Vec<f64> {
        let mut res = vec![self.ext[self.first_span]];
        for j in self.spans() {
            res.push(self.ext[j + 1]);
        }
        res
    }

    /// The indices j of the non-empty intervals [uⱼ, uⱼ₊₁] of the domain.
    pub(crate) fn spans(&self) -> impl Iterator<Item = usize> + '_ {
        (self.first_span..=self.last_span).filter(|&j| self.ext[j] < self.ext[j + 1])
    }

    /// The parameter reduced to one period [a, b) when closed, and the shift (a whole number
    /// of periods) taken off; open directions return u and 0.
    pub(crate) fn wrap(&self, u: f64) -> (f64, f64) {
        if !self.closed {
            return (u, 0.0);
        }
        let ParamRange { start: a, end: b } = self.domain();
        let period = b - a;
        let mut turns = ((u - a) / period).floor();
        let mut w = u - turns * period;
        // Rounding may land on b or just below a.
        if w >= b {
            w -= period;
            turns += 1.0;
        } else if w < a {
            w += period;
            turns -= 1.0;
        }
        (w.clamp(a, b), turns * period)
    }

    /// The interval index j with uⱼ ≤ u < uⱼ₊₁ (the end pieces outside the domain).
    pub(crate) fn span(&self, u: f64) -> usize {
        let j = self.ext.partition_point(|&k| k <= u);
        j.saturating_sub(1).clamp(self.first_span, self.last_span)
    }

    /// The control point index of unrolled index k.
    pub(crate) fn control_index(&self, k: usize) -> usize {
        if self.closed { (k + self.n_control - 1) % self.n_control } else { k }
    }

    /// The four control point indices active on interval j (unrolled indices j − 3, …, j).
    pub(crate) fn active(&self, j: usize) -> [usize; 4] {
        std::array::from_fn(|i| self.control_index(j - DEGREE + i))
    }

    /// The derivative of order `order` (0 for the value) at u of the cubic with control points
    /// `d` active on interval j, with respect to u: the control points are differenced first,
    /// then de Boor's algorithm runs on the lower degree (as `BSplineCurve` does).
    pub(crate) fn eval_span(&self, j: usize, mut d: [DVec3; 4], u: f64, order: usize) -> DVec3 {
        de_boor(&self.ext, j, &mut d, u, order)
    }

    /// The blossom (polar form) f(x₁, x₂, x₃) of the cubic piece on interval j with active
    /// control points `d`.
    pub(crate) fn blossom(&self, j: usize, mut d: [DVec3; 4], args: [f64; 3]) -> DVec3 {
        blossom(&self.ext, j, &mut d, &args)
    }

    /// The four Bézier control points of the piece on interval j (the blossoms at (a, a, a),
    /// (a, a, b), (a, b, b), (b, b, b)): inserting both its knots until they have multiplicity 3.
    pub(crate) fn bezier_span(&self, j: usize, d: [DVec3; 4]) -> [DVec3; 4] {
        let (a, b) = (self.ext[j], self.ext[j + 1]);
        [
            self.blossom(j, d, [a, a, a]),
            self.blossom(j, d, [a, a, b]),
            self.blossom(j, d, [a, b, b]),
            self.blossom(j, d, [b, b, b]),
        ]
    }

    /// The control points along `finer` of the curve with control points `control` along this
    /// direction, when every knot of this direction is a knot of `finer` (with at least its
    /// multiplicity) and the domains agree: knot insertion (Boehm 1980) of all the new knots at
    /// once. Control point c of the finer curve is the blossom at its three inner knots of the
    /// piece under any non-empty interval of its support; the curve is unchanged.
    pub(crate) fn refine(&self, control: &[DVec3], finer: &Self) -> Vec<DVec3> {
        let e = &finer.ext;
        (0..finer.n_control)
            .map(|c| {
                // Unrolled index of control point c along the finer direction.
                let k = if finer.closed { c + 1 } else { c };
                let args = [e[k + 1], e[k + 2], e[k + 3]];
                // The widest non-empty interval of the support [e_k, e_{k+4}] (inside the
                // domain when open: outside it the knots carry no piece of the curve).
                let (lo, hi) = if finer.closed {
                    (k, k + DEGREE)
                } else {
                    (k.max(finer.first_span), (k + DEGREE).min(finer.last_span))
                };
                let width = |l: usize| e[l + 1] - e[l];
                let l = (lo..=hi.max(lo))
                    .fold(lo, |best, l| if width(l) > width(best) { l } else { best });
                let mid = 0.5 * (e[l] + e[l + 1]);
                // A closed direction: move to the period the coarse knots cover, and the
                // arguments with it (the blossom of a periodic spline is shift-covariant).
                let (mid, shift) = self.wrap(mid);
                let j = self.span(mid);
                let d = self.active(j).map(|i| control[i]);
                self.blossom(j, d, args.map(|x| x - shift))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_unrolling_matches_the_convention() {
        let axis = Axis::try_new(vec![0.0, 0.25, 0.5, 1.0], 3, true, "knot").unwrap();
        assert_eq!(axis.ext.len(), 3 + 7);
        assert_eq!(axis.domain(), ParamRange::UNIT);
        assert_eq!(axis.breakpoints(), vec![0.0, 0.25, 0.5, 1.0]);
        assert_eq!(axis.control_index(0), 2);
        assert_eq!(axis.control_index(1), 0);
        assert_eq!(axis.wrap(1.25), (0.25, 1.0));
        assert_eq!(axis.wrap(-0.75), (0.25, -1.0));
    }

    #[test]
    fn bad_knots_are_rejected() {
        assert!(Axis::try_new(vec![0.0; 8], 4, false, "knot").is_err());
        assert!(Axis::try_new(vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 4, false, "knot").is_err());
        let nan = vec![0.0, 0.0, 0.0, 0.0, f64::NAN, 1.0, 1.0, 1.0, 1.0];
        assert!(Axis::try_new(nan, 5, false, "knot").is_err());
        let four = vec![0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0];
        assert!(Axis::try_new(four, 8, false, "knot").is_err());
        assert!(Axis::try_new(vec![0.0, 0.0, 0.0], 2, true, "knot").is_err());
    }
}
