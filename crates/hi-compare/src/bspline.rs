// SPDX-License-Identifier: MIT
//! B-spline curves of any degree (Hardy 2005, §2.9 uniform cubic B-splines, the Cox–de Boor
//! formula of §2.9, §2.10 non-uniform B-splines with repeated knots), open or closed, with
//! exact derivatives of every order and the exact conversion to Bézier segments.
//!
//! Notation: the thesis writes Nᵢ,ₖ with the *order* k (one more than the degree). Here the
//! degree p = k − 1 is used throughout, so the uniform cubic B-spline of §2.9 has p = 3 (the
//! thesis's Nᵢ,₄). The Cox–de Boor recursion (§2.9) reads, with 0/0 := 0 (§2.10),
//!
//! Nᵢ,₀(u) = 1 if uᵢ ≤ u < uᵢ₊₁ (else 0),
//! Nᵢ,ₚ(u) = (u − uᵢ)/(uᵢ₊ₚ − uᵢ)·Nᵢ,ₚ₋₁(u) + (uᵢ₊ₚ₊₁ − u)/(uᵢ₊ₚ₊₁ − uᵢ₊₁)·Nᵢ₊₁,ₚ₋₁(u),
//!
//! where the last non-empty knot interval is taken closed, so that the basis is a partition of
//! unity on the whole domain, its right end included.
//!
//! # Parameters
//!
//! Knots live in their own units u. A [`BSplineCurve`] is a [`ParamCurve`] over t ∈ [0, 1]:
//!
//! * open: u = a + t·(b − a) maps [0, 1] affinely onto the domain [a, b] = [uₚ, uₘ]
//!   (m control points); outside [0, 1] the end polynomial pieces are extrapolated;
//! * closed: u = L·t modulo the period L = τₙ − τ₀, so the curve is 1-periodic in t.
//!
//! With uniform knots every polynomial piece covers an equal share of [0, 1], which is also the
//! segment parametrisation of [`PiecewiseBezier`], so [`BSplineCurve::to_bezier`] then gives
//! the same map t ↦ X(t). With non-uniform knots the Bézier chain is the same point set, each
//! segment reparametrised linearly: see [`BSplineCurve::breakpoints`].

use hi_bezier::{BezierCurve, PiecewiseBezier};
use hi_curve::Error as CurveError;

use crate::check::check_points;
use crate::{ControlPoint, Error};
use hi_curve::{ParamCurve, ParamRange};

/// The largest distance of a point from the centroid of `points`: the `scale` of the
/// comparison curves (at least the smallest positive double).
pub(super) fn point_spread<P: ControlPoint>(points: &[P]) -> f64 {
    if points.is_empty() {
        return f64::MIN_POSITIVE;
    }
    let mut centroid = P::ZERO;
    for p in points {
        centroid += *p;
    }
    let centroid = centroid * (1.0 / points.len() as f64);
    points.iter().map(|p| (*p - centroid).norm()).fold(f64::MIN_POSITIVE, f64::max)
}

/// Degrees up to which evaluation works in a stack buffer.
const STACK_DEGREE: usize = 7;

/// a / b with the convention 0/0 := 0 of §2.10 (and x/0 := 0: the term it scales is zero).
fn div0(a: f64, b: f64) -> f64 {
    if b == 0.0 { 0.0 } else { a / b }
}

/// Checks a knot vector: finite, non-decreasing, no value repeated more than `max_mult` times.
fn check_knots(knots: &[f64], max_mult: usize) -> Result<(), Error> {
    if let Some(&value) = knots.iter().find(|u| !u.is_finite()) {
        return Err(Error::Curve(CurveError::NonFiniteParameter { name: "knot", value }));
    }
    if knots.windows(2).any(|w| w[1] < w[0]) {
        return Err(Error::InvalidKnots { reason: "knots must be non-decreasing" });
    }
    let mut run = 1;
    for w in knots.windows(2) {
        run = if w[1] == w[0] { run + 1 } else { 1 };
        if run > max_mult {
            return Err(Error::InvalidKnots {
                reason: "a knot is repeated more than degree + 1 times",
            });
        }
    }
    Ok(())
}

/// The B-spline basis functions Nᵢ,ₚ(u) of a knot vector, by the Cox–de Boor formula (§2.9),
/// in knot units u: the functions of figures 2.9 and 2.10.
///
/// With knots u₀ ≤ … ≤ u_{m+p} there are m functions; Nᵢ,ₚ is non-negative, supported on
/// [uᵢ, uᵢ₊ₚ₊₁] (local support), and Σᵢ Nᵢ,ₚ(u) = 1 for u ∈ [uₚ, uₘ] (partition of unity,
/// §2.9). A knot repeated r times lowers the continuity there to C^{p−r}. The four segment
/// functions B₀, …, B₃ of figure 2.9 are N₀, …, N₃ of `BSplineBasis::uniform(3, 4)` on
/// [3, 4] (at u = 3 + t).
///
/// # Examples
///
/// ```
/// use hi_compare::bspline::BSplineBasis;
///
/// // The uniform cubic basis (figure 2.10): at a knot the three non-zero functions are
/// // 1/6, 2/3, 1/6 (§2.9: B₀(1) = B₃(0) = 0, B₁(1) = B₂(0) = 1/6, …).
/// let basis = BSplineBasis::uniform(3, 8);
/// assert!((basis.eval(0, 4.0) - 0.0).abs() < 1e-15);
/// assert!((basis.eval(1, 4.0) - 1.0 / 6.0).abs() < 1e-15);
/// assert!((basis.eval(2, 4.0) - 2.0 / 3.0).abs() < 1e-15);
/// assert!((basis.eval(3, 4.0) - 1.0 / 6.0).abs() < 1e-15);
/// let sum: f64 = basis.eval_all(4.3).iter().sum();
/// assert!((sum - 1.0).abs() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
#[doc(alias = "Cox-de Boor")]
pub struct BSplineBasis {
    degree: usize,
    // Invariant: finite, non-decreasing, len >= degree + 2, multiplicities <= degree + 1.
    knots: Vec<f64>,
    // The last index j with knots[j] < knots[j + 1] (its interval is taken closed).
    last_span: usize,
}

impl BSplineBasis {
    /// The basis of degree p on these knots.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::NonFiniteParameter`] for a NaN or infinite knot, [`Error::InvalidKnots`] when
    /// the knots decrease somewhere, a value is repeated more than p + 1 times, or there are
    /// fewer than p + 2 knots or all of them are equal.
    pub fn try_new(degree: usize, knots: Vec<f64>) -> Result<Self, Error> {
        check_knots(&knots, degree + 1)?;
        if knots.len() < degree + 2 {
            return Err(Error::InvalidKnots { reason: "a basis needs at least degree + 2 knots" });
        }
        let last_span = (0..knots.len() - 1)
            .rev()
            .find(|&j| knots[j] < knots[j + 1])
            .ok_or(Error::InvalidKnots { reason: "all knots are equal" })?;
        Ok(Self { degree, knots, last_span })
    }

    /// The uniform basis of degree p with `n_functions` functions on the knots uᵢ = i
    /// (i = 0, …, n + p), as in §2.9; its domain is [p, n].
    ///
    /// # Panics
    ///
    /// Panics if `n_functions` is 0.
    #[must_use]
    pub fn uniform(degree: usize, n_functions: usize) -> Self {
        assert!(n_functions > 0, "a basis needs at least one function");
        let knots = (0..n_functions + degree + 1).map(|i| i as f64).collect();
        Self::try_new(degree, knots).expect("uniform knots are valid")
    }

    /// The degree p.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knots u₀, …, u_{m+p}.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The number m of basis functions (knots − p − 1).
    #[must_use]
    pub fn n_functions(&self) -> usize {
        self.knots.len() - self.degree - 1
    }

    /// The domain [uₚ, uₘ] on which the functions sum to one.
    #[must_use]
    pub fn domain(&self) -> ParamRange {
        ParamRange::new(self.knots[self.degree], self.knots[self.n_functions()])
    }

    /// Nᵢ,ₚ(u) by the Cox–de Boor recursion, O(p²).
    ///
    /// # Panics
    ///
    /// Panics if `i` is not below [`BSplineBasis::n_functions`].
    #[must_use]
    pub fn eval(&self, i: usize, u: f64) -> f64 {
        assert!(i < self.n_functions(), "basis index {i} out of range (< {})", self.n_functions());
        self.cox_de_boor(i, self.degree, u)
    }

    /// All the values N₀,ₚ(u), …, N_{m−1},ₚ(u).
    #[must_use]
    pub fn eval_all(&self, u: f64) -> Vec<f64> {
        (0..self.n_functions()).map(|i| self.cox_de_boor(i, self.degree, u)).collect()
    }

    /// The derivative N⁽ʳ⁾ᵢ,ₚ(u) of order r (0 above the degree inside a knot interval), by
    /// N′ᵢ,ₚ = p·(Nᵢ,ₚ₋₁/(uᵢ₊ₚ − uᵢ) − Nᵢ₊₁,ₚ₋₁/(uᵢ₊ₚ₊₁ − uᵢ₊₁)).
    ///
    /// # Panics
    ///
    /// Panics if `i` is not below [`BSplineBasis::n_functions`].
    #[must_use]
    pub fn eval_deriv(&self, i: usize, u: f64, order: usize) -> f64 {
        assert!(i < self.n_functions(), "basis index {i} out of range (< {})", self.n_functions());
        self.deriv_rec(i, self.degree, u, order)
    }

    fn deriv_rec(&self, i: usize, p: usize, u: f64, order: usize) -> f64 {
        if order == 0 {
            return self.cox_de_boor(i, p, u);
        }
        if order > p {
            return 0.0;
        }
        let k = &self.knots;
        let left = div0(self.deriv_rec(i, p - 1, u, order - 1), k[i + p] - k[i]);
        let right = div0(self.deriv_rec(i + 1, p - 1, u, order - 1), k[i + p + 1] - k[i + 1]);
        p as f64 * (left - right)
    }

    /// Nᵢ,ₚ(u) for any p ≤ the degree (the triangle of the recursion, bottom up).
    fn cox_de_boor(&self, i: usize, p: usize, u: f64) -> f64 {
        let k = &self.knots;
        let mut n: Vec<f64> = (0..=p)
            .map(|j| {
                let s = i + j;
                let inside = k[s] <= u && u < k[s + 1];
                let right_end = s == self.last_span && u == k[s + 1];
                if inside || right_end { 1.0 } else { 0.0 }
            })
            .collect();
        for q in 1..=p {
            for j in 0..=p - q {
                let s = i + j;
                let a = div0(u - k[s], k[s + q] - k[s]) * n[j];
                let b = div0(k[s + q + 1] - u, k[s + q + 1] - k[s + 1]) * n[j + 1];
                n[j] = a + b;
            }
        }
        n[0]
    }
}

/// A B-spline curve X(u) = Σᵢ Nᵢ,ₚ(u)·xᵢ of any degree p (§2.9–2.10), open or closed.
///
/// * Open: m control points and m + p + 1 non-decreasing knots, defined over [uₚ, uₘ].
///   Clamped knots (the first and last repeated p + 1 times, §2.10) make the curve start at x₀
///   and end at x_{m−1}; a clamped curve with p + 1 control points is the Bézier curve of
///   degree p on them.
/// * Closed (periodic): n control points and n + 1 breakpoints τ₀ ≤ … ≤ τₙ, extended
///   periodically with period L = τₙ − τ₀. The basis function of xᵢ is supported on
///   [τ_{i−s}, τ_{i−s+p+1}] with s = ⌊(p + 1)/2⌋, so for odd degree it peaks at τᵢ: the uniform
///   closed cubic passes through (x_{i−1} + 4xᵢ + x_{i+1})/6 at τᵢ (§2.9).
///
/// Evaluation is de Boor's algorithm (repeated linear interpolation, §2.9); derivatives of any
/// order differentiate the control points of the active knot interval first (exact, zero above
/// the degree). See the [module documentation](self) for the map between knots and t ∈ [0, 1].
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::ParamCurve;
/// use hi_compare::bspline::BSplineCurve;
///
/// // The closed uniform cubic B-spline of a square (figure 3.8(a)).
/// let square = vec![DVec2::X, DVec2::Y, -DVec2::X, -DVec2::Y];
/// let curve = BSplineCurve::try_uniform_closed(3, square).unwrap();
/// // At t = 0 the curve is (x₃ + 4x₀ + x₁)/6 = (2/3, 0).
/// assert!((curve.eval(0.0) - DVec2::new(2.0 / 3.0, 0.0)).length() < 1e-15);
/// assert!((curve.eval(1.25) - curve.eval(0.25)).length() < 1e-15); // 1-periodic
/// // The Bézier chain is the same curve (uniform knots: same parameter too).
/// let chain = curve.to_bezier();
/// assert_eq!(chain.segments().len(), 4);
/// assert!((chain.eval(0.3) - curve.eval(0.3)).length() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineCurve<P> {
    degree: usize,
    // Invariant, open: knots.len() == control.len() + degree + 1, finite, non-decreasing,
    // multiplicities <= degree + 1, knots[degree] < knots[control.len()].
    // Invariant, closed: knots.len() == control.len() + 1, finite, non-decreasing,
    // knots[0] < knots[n], multiplicities (counted periodically) <= degree + 1.
    knots: Vec<f64>,
    // Invariant: non-empty, finite.
    control: Vec<P>,
    periodic: bool,
    // The open B-spline that evaluates the curve: for a closed curve, the knots unrolled over
    // one period plus `degree` knots on each side and the control points repeated cyclically
    // (ext_control[k] = control[(k − p + s) mod n]). For an open curve, copies of the input.
    ext_knots: Vec<f64>,
    ext_control: Vec<P>,
    // The first and last non-empty knot intervals [uⱼ, uⱼ₊₁] inside the domain.
    first_span: usize,
    last_span: usize,
}

impl<P: ControlPoint> BSplineCurve<P> {
    /// The open B-spline of degree p with these knots and control points (§2.10).
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`] / [`hi_curve::Error::NonFinitePoint`] for bad control points,
    /// [`Error::TooFewPoints`] for fewer than p + 1 of them, [`hi_curve::Error::NonFiniteParameter`] for a
    /// non-finite knot, [`Error::InvalidKnots`] unless there are exactly (control points) + p + 1
    /// non-decreasing knots, none repeated more than p + 1 times, with uₚ < uₘ.
    pub fn try_new(degree: usize, knots: Vec<f64>, control: Vec<P>) -> Result<Self, Error> {
        check_points(&control)?;
        let m = control.len();
        if m < degree + 1 {
            return Err(Error::TooFewPoints {
                what: "an open B-spline (degree + 1 control points)",
                needed: degree + 1,
                got: m,
            });
        }
        if knots.len() != m + degree + 1 {
            return Err(Error::InvalidKnots {
                reason: "an open B-spline needs (number of control points) + degree + 1 knots",
            });
        }
        check_knots(&knots, degree + 1)?;
        if knots[degree] >= knots[m] {
            return Err(Error::InvalidKnots { reason: "the domain [uₚ, uₘ] is empty" });
        }
        Ok(Self::assemble(degree, knots.clone(), control.clone(), false, knots, control))
    }

    /// The open B-spline of degree p with these knots and control points.
    ///
    /// # Panics
    ///
    /// Panics on invalid input; see [`BSplineCurve::try_new`].
    #[must_use]
    pub fn new(degree: usize, knots: Vec<f64>, control: Vec<P>) -> Self {
        Self::try_new(degree, knots, control).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The open uniform B-spline of §2.9: knots uᵢ = i, i = 0, …, m + p, so the curve runs over
    /// [p, m] and does not reach x₀ or x_{m−1} (for p = 3, the thesis's uniform cubic
    /// B-spline with its m − 3 segments).
    ///
    /// # Errors
    ///
    /// As [`BSplineCurve::try_new`]: bad or fewer than p + 1 control points.
    pub fn try_uniform_open(degree: usize, control: Vec<P>) -> Result<Self, Error> {
        let knots = (0..control.len() + degree + 1).map(|i| i as f64).collect();
        Self::try_new(degree, knots, control)
    }

    /// The clamped B-spline of §2.10 with uniform interior knots: the first and last knot
    /// repeated p + 1 times, so the curve starts at x₀ and ends at x_{m−1}, and with
    /// m = p + 1 control points it is their Bézier curve.
    ///
    /// # Errors
    ///
    /// As [`BSplineCurve::try_new`]: bad or fewer than p + 1 control points.
    pub fn try_clamped(degree: usize, control: Vec<P>) -> Result<Self, Error> {
        let m = control.len();
        let n_spans = m.saturating_sub(degree).max(1);
        let mut knots = vec![0.0; degree + 1];
        knots.extend((1..n_spans).map(|i| i as f64));
        knots.extend(std::iter::repeat_n(n_spans as f64, degree + 1));
        Self::try_new(degree, knots, control)
    }

    /// The closed (periodic) B-spline of degree p with breakpoints τ₀ ≤ … ≤ τₙ (n + 1 values
    /// for n control points), period L = τₙ − τ₀.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`] / [`hi_curve::Error::NonFinitePoint`] for bad control points,
    /// [`hi_curve::Error::NonFiniteParameter`] for a non-finite breakpoint, [`Error::InvalidKnots`]
    /// unless there are n + 1 non-decreasing breakpoints with τ₀ < τₙ, none repeated
    /// (periodically) more than p + 1 times.
    pub fn try_new_periodic(
        degree: usize,
        breakpoints: Vec<f64>,
        control: Vec<P>,
    ) -> Result<Self, Error> {
        check_points(&control)?;
        let n = control.len();
        if breakpoints.len() != n + 1 {
            return Err(Error::InvalidKnots {
                reason: "a closed B-spline needs (number of control points) + 1 breakpoints",
            });
        }
        check_knots(&breakpoints, degree + 1)?;
        let period = breakpoints[n] - breakpoints[0];
        if period <= 0.0 {
            return Err(Error::InvalidKnots {
                reason: "the period τₙ − τ₀ is not positive"
            });
        }
        let p = degree;
        let s = p.div_ceil(2);
        // Knot u_k = τ_{k−p}, extended with τ_{j+n} = τ_j + L, k = 0..n + 2p.
        let tau = |j: isize| -> f64 {
            let (q, r) = (j.div_euclid(n as isize), j.rem_euclid(n as isize));
            breakpoints[r as usize] + q as f64 * period
        };
        let ext_knots: Vec<f64> =
            (0..n + 2 * p + 1).map(|k| tau(k as isize - p as isize)).collect();
        check_knots(&ext_knots, degree + 1)?;
        let ext_control: Vec<P> = (0..n + p)
            .map(|k| {
                control[(k as isize - p as isize + s as isize).rem_euclid(n as isize) as usize]
            })
            .collect();
        Ok(Self::assemble(degree, breakpoints, control, true, ext_knots, ext_control))
    }

    /// The closed uniform B-spline of degree p: breakpoints τᵢ = i/n, so xᵢ's basis function
    /// is centred at t = i/n for odd p.
    ///
    /// # Errors
    ///
    /// [`hi_curve::Error::Empty`] / [`hi_curve::Error::NonFinitePoint`] for bad control points.
    pub fn try_uniform_closed(degree: usize, control: Vec<P>) -> Result<Self, Error> {
        let n = control.len();
        let breakpoints = (0..=n).map(|i| i as f64 / n.max(1) as f64).collect();
        Self::try_new_periodic(degree, breakpoints, control)
    }

    fn assemble(
        degree: usize,
        knots: Vec<f64>,
        control: Vec<P>,
        periodic: bool,
        ext_knots: Vec<f64>,
        ext_control: Vec<P>,
    ) -> Self {
        let m = ext_control.len();
        let nonempty = |j: &usize| ext_knots[*j] < ext_knots[*j + 1];
        let first_span = (degree..m).find(nonempty).expect("the domain is not empty");
        let last_span = (degree..m).rev().find(nonempty).expect("the domain is not empty");
        Self { degree, knots, control, periodic, ext_knots, ext_control, first_span, last_span }
    }

    /// The degree p.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knots as given: the whole knot vector of an open curve, the n + 1 breakpoints
    /// τ₀, …, τₙ of a closed one.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The control points x₀, …, x_{m−1}.
    #[must_use]
    pub fn control_points(&self) -> &[P] {
        &self.control
    }

    /// True for a closed (periodic) curve.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.periodic
    }

    /// The domain [a, b] in knot units: [uₚ, uₘ] for an open curve, [τ₀, τₙ] for a closed one.
    #[must_use]
    pub fn domain(&self) -> ParamRange {
        ParamRange::new(self.ext_knots[self.degree], self.ext_knots[self.ext_control.len()])
    }

    /// The knot parameter u of the curve parameter t (see the [module documentation](self)).
    #[must_use]
    pub fn knot_param(&self, t: f64) -> f64 {
        let ParamRange { start: a, end: b } = self.domain();
        let len = b - a;
        if self.periodic {
            let u = a + (len * t - a).rem_euclid(len);
            // rem_euclid may round up to exactly len.
            if u >= b { a } else { u }
        } else {
            a + t * len
        }
    }

    /// The curve parameters t of the ends of the polynomial pieces, increasing, one more than
    /// the number of pieces (the segments of [`BSplineCurve::to_bezier`]): piece i covers
    /// [tᵢ, tᵢ₊₁]. Open curves give t₀ = 0 and the last = 1; a closed curve gives τⱼ/L, one
    /// period starting at τ₀/L.
    ///
    /// Segment i of [`BSplineCurve::to_bezier`] at its own parameter v ∈ [0, 1] is this curve at
    /// t = tᵢ + v·(tᵢ₊₁ − tᵢ).
    #[must_use]
    pub fn breakpoints(&self) -> Vec<f64> {
        let ParamRange { start: a, end: b } = self.domain();
        let len = b - a;
        let to_t = |u: f64| if self.periodic { u / len } else { (u - a) / len };
        let mut res = vec![to_t(self.ext_knots[self.first_span])];
        for j in self.spans() {
            res.push(to_t(self.ext_knots[j + 1]));
        }
        res
    }

    /// The non-empty knot intervals [uⱼ, uⱼ₊₁] of the domain, by index j.
    fn spans(&self) -> impl Iterator<Item = usize> + '_ {
        (self.first_span..=self.last_span).filter(|&j| self.ext_knots[j] < self.ext_knots[j + 1])
    }

    /// The index j of the knot interval [uⱼ, uⱼ₊₁) holding u (the end pieces outside).
    fn span(&self, u: f64) -> usize {
        let j = self.ext_knots.partition_point(|&k| k <= u);
        j.saturating_sub(1).clamp(self.first_span, self.last_span)
    }

    /// X(t), by de Boor's algorithm.
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        self.eval_deriv(t, 0)
    }

    /// The derivative X⁽ʳ⁾(t) with respect to t of any order (0 above the degree), exact. At a
    /// knot where the curve is less smooth, the derivative of the piece on the right (on the
    /// left at the end of an open curve).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        let u = self.knot_param(t);
        let ParamRange { start: a, end: b } = self.domain();
        self.eval_knot_deriv(u, order) * (b - a).powi(order as i32)
    }

    /// X⁽ʳ⁾ with respect to the knot parameter u, at u.
    fn eval_knot_deriv(&self, u: f64, order: usize) -> P {
        let p = self.degree;
        if order > p {
            return P::ZERO;
        }
        let (k, c) = (&self.ext_knots, &self.ext_control);
        let j = self.span(u);
        // The p + 1 active control points, on the stack for the usual degrees.
        let mut stack = [P::ZERO; STACK_DEGREE + 1];
        let mut heap = Vec::new();
        let d: &mut [P] = if p <= STACK_DEGREE {
            &mut stack[..=p]
        } else {
            heap.resize(p + 1, P::ZERO);
            &mut heap
        };
        d.copy_from_slice(&c[j - p..=j]);
        de_boor(k, j, d, u, order)
    }

    /// The blossom (polar form) of the polynomial piece on interval j at `args` (p values).
    fn blossom(&self, j: usize, args: &[f64]) -> P {
        let p = self.degree;
        let mut d: Vec<P> = self.ext_control[j - p..=j].to_vec();
        blossom(&self.ext_knots, j, &mut d, args)
    }

    /// The weight of every control point at t: X(t) = Σᵢ wᵢ(t)·xᵢ. The weights are the basis
    /// functions Nᵢ,ₚ at the knot parameter of t (summed over the periodic copies of a closed
    /// curve): non-negative, at most p + 1 of them non-zero (local support), summing to one.
    #[must_use]
    pub fn basis_values(&self, t: f64) -> Vec<f64> {
        let u = self.knot_param(t);
        let p = self.degree;
        let k = &self.ext_knots;
        let j = self.span(u);
        // Piegl & Tiller, The NURBS Book, algorithm A2.2.
        let mut values = vec![0.0; p + 1];
        values[0] = 1.0;
        let mut left = vec![0.0; p + 1];
        let mut right = vec![0.0; p + 1];
        for r in 1..=p {
            left[r] = u - k[j + 1 - r];
            right[r] = k[j + r] - u;
            let mut saved = 0.0;
            for s in 0..r {
                let temp = values[s] / (right[s + 1] + left[r - s]);
                values[s] = saved + right[s + 1] * temp;
                saved = left[r - s] * temp;
            }
            values[r] = saved;
        }
        let n = self.control.len();
        let mut res = vec![0.0; n];
        let shift = if self.periodic { p as isize - p.div_ceil(2) as isize } else { 0 };
        for (i, v) in values.into_iter().enumerate() {
            let ext = (j - p + i) as isize;
            res[(ext - shift).rem_euclid(n as isize) as usize] += v;
        }
        res
    }

    /// The same curve as a chain of Bézier curves of degree p, one per non-empty knot
    /// interval, found by blossoming (the result of inserting every knot until its
    /// multiplicity is p).
    ///
    /// With uniform knots `to_bezier().eval(t)` equals `eval(t)` for t ∈ [0, 1]; otherwise see
    /// [`BSplineCurve::breakpoints`] for the parameter of each segment.
    ///
    /// # Panics
    ///
    /// Does not panic: every Bézier control point is a convex combination of the (finite)
    /// control points, and the domain has at least one non-empty knot interval.
    #[must_use]
    pub fn to_bezier(&self) -> PiecewiseBezier<P> {
        let p = self.degree;
        let segments = self
            .spans()
            .map(|j| {
                let (lo, hi) = (self.ext_knots[j], self.ext_knots[j + 1]);
                let control = (0..=p)
                    .map(|i| {
                        let args: Vec<f64> =
                            (0..p).map(|r| if r < p - i { lo } else { hi }).collect();
                        self.blossom(j, &args)
                    })
                    .collect();
                BezierCurve::try_new(control).expect("convex combinations of finite points")
            })
            .collect();
        PiecewiseBezier::try_new(segments).expect("the domain has a non-empty knot interval")
    }
}

impl<P: ControlPoint> ParamCurve<P> for BSplineCurve<P> {
    fn eval(&self, t: f64) -> P {
        BSplineCurve::eval(self, t)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> P {
        BSplineCurve::eval_deriv(self, t, order)
    }

    fn scale(&self) -> f64 {
        point_spread(&self.control)
    }

    fn is_periodic(&self) -> bool {
        self.periodic
    }
}

/// The derivative of order `order` (0: the value) at u, with respect to u, of the polynomial
/// piece on interval j (`knots[j] ≤ u < knots[j + 1]`) of a B-spline of degree p = `d.len() − 1`
/// with the (extended) knot vector `knots`, given the piece's p + 1 active control points `d`
/// (overwritten): the control points are differenced `order` times, then de Boor's algorithm
/// runs on degree p − `order`. Zero above the degree.
///
/// After difference level l, `d[i]` is the coefficient of N with index g = j − p + l + i,
/// `Q⁽ˡ⁾[g] = (p − l + 1)(Q⁽ˡ⁻¹⁾[g] − Q⁽ˡ⁻¹⁾[g−1])/(u[g+p−l+1] − u[g])`.
///
/// # Panics
///
/// If `d` is empty or the knots do not reach p + 1 past j on either side.
///
/// # Examples
///
/// ```
/// use hi_compare::bspline::de_boor;
/// // The uniform cubic on knots 0..8, interval 3: the control points 0, 1, 2, 3 give the line u − 2.
/// let knots: Vec<f64> = (0..8).map(f64::from).collect();
/// let mut d = [0.0, 1.0, 2.0, 3.0];
/// assert!((de_boor(&knots, 3, &mut d, 3.5, 0) - 1.5).abs() < 1e-15);
/// let mut d = [0.0, 1.0, 2.0, 3.0];
/// assert!((de_boor(&knots, 3, &mut d, 3.5, 1) - 1.0).abs() < 1e-15);
/// ```
pub fn de_boor<P: ControlPoint>(knots: &[f64], j: usize, d: &mut [P], u: f64, order: usize) -> P {
    let p = d.len() - 1;
    if order > p {
        return P::ZERO;
    }
    let k = knots;
    for l in 1..=order {
        for i in 0..=p - l {
            let g = j - p + l + i;
            let scale = (p - l + 1) as f64 / (k[g + p - l + 1] - k[g]);
            d[i] = (d[i + 1] - d[i]) * scale;
        }
    }
    // de Boor on degree q = p − order; d[i] belongs to N_{j−q+i, q}.
    let q = p - order;
    for r in 1..=q {
        for i in (r..=q).rev() {
            let g = j - q + i;
            let alpha = (u - k[g]) / (k[g + q + 1 - r] - k[g]);
            d[i] = d[i - 1] * (1.0 - alpha) + d[i] * alpha;
        }
    }
    d[q]
}

/// The blossom (polar form) f(x₁, …, xₚ) at `args` of the polynomial piece on interval j of a
/// B-spline of degree p = `d.len() − 1` with the (extended) knot vector `knots`, given the
/// piece's active control points `d` (overwritten). With every xᵢ = u it is the point at u;
/// at the knots it gives the control points of knot insertion and of the Bézier pieces.
///
/// # Panics
///
/// If `d` is empty, `args` has fewer than p values, or the knots do not reach around j.
///
/// # Examples
///
/// ```
/// use hi_compare::bspline::blossom;
/// let knots: Vec<f64> = (0..8).map(f64::from).collect();
/// let mut d = [0.0, 1.0, 2.0, 3.0]; // the line u − 2 on interval 3
/// assert!((blossom(&knots, 3, &mut d, &[3.5, 3.5, 3.5]) - 1.5).abs() < 1e-15);
/// ```
pub fn blossom<P: ControlPoint>(knots: &[f64], j: usize, d: &mut [P], args: &[f64]) -> P {
    let p = d.len() - 1;
    let k = knots;
    for r in 1..=p {
        let x = args[r - 1];
        for i in (r..=p).rev() {
            let g = j - p + i;
            let alpha = (x - k[g]) / (k[g + p + 1 - r] - k[g]);
            d[i] = d[i - 1] * (1.0 - alpha) + d[i] * alpha;
        }
    }
    d[p]
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn uniform_cubic_segment_basis_matches_section_2_9() {
        // On [3, 4], N₀, …, N₃ are B₀(t), …, B₃(t) of §2.9 at t = u − 3.
        let basis = BSplineBasis::uniform(3, 7);
        for step in 0..=10 {
            let t = step as f64 / 10.0;
            let b0 = (1.0 - t).powi(3) / 6.0;
            let b1 = (3.0 * t.powi(3) - 6.0 * t * t + 4.0) / 6.0;
            let b2 = (-3.0 * t.powi(3) + 3.0 * t * t + 3.0 * t + 1.0) / 6.0;
            let b3 = t.powi(3) / 6.0;
            let u = 3.0 + t;
            let got = [basis.eval(0, u), basis.eval(1, u), basis.eval(2, u), basis.eval(3, u)];
            for (g, e) in got.iter().zip([b0, b1, b2, b3]) {
                assert!((g - e).abs() < 1e-15, "t = {t}: {g} vs {e}");
            }
        }
    }

    #[test]
    fn basis_derivative_matches_difference_quotient() {
        let basis =
            BSplineBasis::try_new(3, vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0])
                .unwrap();
        let h = 1e-6;
        for i in 0..basis.n_functions() {
            for u in [0.1, 0.4, 0.7, 0.95] {
                let fd = (basis.eval(i, u + h) - basis.eval(i, u - h)) / (2.0 * h);
                assert!((basis.eval_deriv(i, u, 1) - fd).abs() < 1e-6, "i = {i}, u = {u}");
            }
        }
    }

    #[test]
    fn curve_derivative_matches_difference_quotient() {
        let control: Vec<DVec2> =
            (0..7).map(|i| DVec2::new(i as f64, ((i * i) % 5) as f64)).collect();
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.2, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0];
        let curve = BSplineCurve::try_new(3, knots, control).unwrap();
        let h = 1e-5;
        for t in [0.1, 0.3, 0.45, 0.8] {
            for order in 1..=3 {
                let fd = (curve.eval_deriv(t + h, order - 1) - curve.eval_deriv(t - h, order - 1))
                    / (2.0 * h);
                let d = curve.eval_deriv(t, order);
                assert!((d - fd).length() < 1e-4 * (1.0 + d.length()), "t={t} order={order}");
            }
            assert_eq!(curve.eval_deriv(t, 4), DVec2::ZERO);
        }
    }

    #[test]
    fn invalid_input_is_rejected() {
        let pts = vec![0.0, 1.0, 2.0, 3.0];
        assert!(BSplineCurve::try_new(3, vec![0.0; 8], pts.clone()).is_err()); // empty domain
        assert!(BSplineCurve::try_new(3, vec![0.0; 7], pts.clone()).is_err()); // wrong count
        assert!(BSplineCurve::try_new(4, (0..9).map(f64::from).collect(), pts.clone()).is_err());
        let decreasing = vec![0.0, 1.0, 2.0, 3.0, 2.5, 5.0, 6.0, 7.0];
        assert!(matches!(
            BSplineCurve::try_new(3, decreasing, pts.clone()),
            Err(Error::InvalidKnots { .. })
        ));
        let nan = vec![0.0, 1.0, 2.0, f64::NAN, 4.0, 5.0, 6.0, 7.0];
        assert!(BSplineCurve::try_new(3, nan, pts.clone()).is_err());
        assert!(BSplineCurve::<f64>::try_uniform_closed(3, vec![]).is_err());
        assert!(BSplineCurve::try_new_periodic(3, vec![0.0, 0.0, 0.0], vec![1.0, 2.0]).is_err());
        assert!(BSplineCurve::try_new_periodic(2, vec![0.0, 0.5], vec![1.0, 2.0]).is_err());
        assert!(BSplineBasis::try_new(2, vec![1.0, 1.0, 1.0, 1.0]).is_err());
    }
}
