// SPDX-License-Identifier: MIT
//! Non-uniform harmonic interpolation (Hardy 2005, §3.10; docs/math.md §5).
//!
//! Two readings of the section, each named for what it is:
//!
//! * [`NonUniformVariant::Thesis`]: the thesis's final formula as printed,
//!   X(t) = Re Σⱼ e^{2πi(n−1)t(tⱼ − m/n)}·Σₖ (A⁻¹)ⱼₖ·xₖ with Aₖⱼ = e^{2πik(tⱼ − m/n)} and
//!   m = ⌊n/2⌋. The tⱼ act as *frequencies*, not as nodes: this curve passes through xₖ at
//!   t = k/(n−1), not at tₖ, and it is open (X(0) = x₀, X(1) = xₙ₋₁). With tⱼ = j/n it is the
//!   uniform harmonic curve evaluated at (n−1)t/n.
//! * [`NonUniformVariant::Nodes`]: what the section sets out to do, a smooth periodic curve
//!   with X(tₖ) = xₖ at arbitrary distinct tₖ ∈ [0, 1). It is the trigonometric interpolant in
//!   the barycentric form of Henrici (1979) and Berrut (1984), and generalises the harmonic
//!   basis itself: ℓₖ(t) = Πⱼ≠ₖ sin(π(t − tⱼ))/sin(π(tₖ − tⱼ)), times cos(π(t − tₖ)) for even n.
//!   For tₖ = k/n this is exactly σⁿₖ (both parities).

mod linalg;
mod nodes;
mod thesis;

use realfft::num_complex::Complex64;

use crate::curve::spread;
use crate::differential::ParamCurve;
use crate::point::check_points;
use crate::{ControlPoint, Error, Fourier};

/// Which reading of §3.10 a [`NonUniformCurve`] follows (docs/math.md §5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum NonUniformVariant {
    /// The thesis's final formula as printed (real part, m = ⌊n/2⌋, the (n−1)·t scaling).
    /// Interpolates xₖ at t = k/(n−1), not at tₖ; defined on t ∈ [0, 1], not periodic.
    Thesis,
    /// True interpolation at the nodes: X(tₖ) = xₖ, 1-periodic, no linear solve (barycentric).
    Nodes,
}

/// Closed-polygon chord-length parameters (§3.10): t₀ = 0 and
/// tⱼ = (1/l)·Σₖ₍ₖ<ⱼ₎ |xₖ₊₁ − xₖ| with l the perimeter including the closing edge |x₀ − xₙ₋₁|.
///
/// # Errors
///
/// [`Error::Empty`], [`Error::NonFinitePoint`], [`Error::ZeroLengthPolygon`] when all points
/// coincide (n ≥ 2), and [`Error::CoincidentPoints`] when two consecutive points coincide.
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// let t = hi_curve::chord_length_params(&[DVec2::ZERO, DVec2::X, DVec2::new(1.0, 2.0), DVec2::new(0.0, 2.0)]).unwrap();
/// assert_eq!(t, vec![0.0, 1.0 / 6.0, 3.0 / 6.0, 4.0 / 6.0]);
/// ```
pub fn chord_length_params<P: ControlPoint>(points: &[P]) -> Result<Vec<f64>, Error> {
    check_points(points)?;
    let n = points.len();
    if n == 1 {
        return Ok(vec![0.0]);
    }
    let mut acc = Vec::with_capacity(n);
    let mut len = 0.0;
    for k in 0..n {
        acc.push(len);
        len += (points[(k + 1) % n] - points[k]).norm();
    }
    if len == 0.0 {
        return Err(Error::ZeroLengthPolygon);
    }
    for k in 0..n {
        if (points[(k + 1) % n] - points[k]).norm() == 0.0 {
            return Err(Error::CoincidentPoints { first: k, second: (k + 1) % n });
        }
    }
    Ok(acc.into_iter().map(|s| s / len).collect())
}

/// Checks node parameters: as many as points, finite, in [0, 1), distinct.
fn check_params(n_points: usize, params: &[f64]) -> Result<(), Error> {
    if params.len() != n_points {
        return Err(Error::ParameterCountMismatch { points: n_points, params: params.len() });
    }
    for (index, &value) in params.iter().enumerate() {
        if !(0.0..1.0).contains(&value) {
            return Err(Error::NodeOutOfRange { index, value });
        }
    }
    let mut order: Vec<usize> = (0..params.len()).collect();
    order.sort_by(|&a, &b| params[a].total_cmp(&params[b]));
    for w in order.windows(2) {
        if params[w[0]] == params[w[1]] {
            let (first, second) = (w[0].min(w[1]), w[0].max(w[1]));
            return Err(Error::ParametersNotDistinct { first, second });
        }
    }
    Ok(())
}

#[derive(Clone, Debug, PartialEq)]
enum Inner<P> {
    Thesis(thesis::Thesis<P>),
    Nodes(nodes::Nodes<P>),
}

/// A curve through points at non-uniform parameters (§3.10), in one of two readings
/// ([`NonUniformVariant`]).
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_curve::{HarmonicCurve, NonUniformCurve, NonUniformVariant};
///
/// let pts = vec![DVec2::new(0.0, 0.0), DVec2::new(3.0, 1.0), DVec2::new(4.0, 4.0), DVec2::new(-1.0, 2.0)];
/// let params = vec![0.0, 0.1, 0.45, 0.7];
/// let curve = NonUniformCurve::try_with_params(pts.clone(), params.clone(), NonUniformVariant::Nodes).unwrap();
/// for (p, t) in pts.iter().zip(&params) {
///     assert!((curve.eval(*t) - *p).length() < 1e-13); // passes through xₖ at tₖ
/// }
/// // With uniform nodes it is the harmonic curve, for even n too.
/// let uniform = NonUniformCurve::try_with_params(pts.clone(), vec![0.0, 0.25, 0.5, 0.75], NonUniformVariant::Nodes).unwrap();
/// let harmonic = HarmonicCurve::new(pts);
/// assert!((uniform.eval(0.3) - harmonic.eval(0.3)).length() < 1e-13);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct NonUniformCurve<P> {
    // Invariant: points non-empty and finite; params valid for points (check_params).
    points: Vec<P>,
    params: Vec<f64>,
    variant: NonUniformVariant,
    inner: Inner<P>,
}

impl<P: ControlPoint> NonUniformCurve<P> {
    /// The curve through `points` with closed chord-length parameters
    /// ([`chord_length_params`]).
    ///
    /// # Errors
    ///
    /// As [`chord_length_params`], and [`Error::Singular`] if the thesis's Vandermonde matrix is
    /// singular to working precision.
    pub fn try_new(points: Vec<P>, variant: NonUniformVariant) -> Result<Self, Error> {
        let params = chord_length_params(&points)?;
        Self::try_with_params(points, params, variant)
    }

    /// The curve through `points` with parameters `params` given by the caller: distinct,
    /// in [0, 1), one per point, in any order.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`], [`Error::NonFinitePoint`], [`Error::ParameterCountMismatch`],
    /// [`Error::NodeOutOfRange`] (also for NaN), [`Error::ParametersNotDistinct`], and
    /// [`Error::Singular`] for the thesis variant if its matrix is singular in floating point.
    pub fn try_with_params(
        points: Vec<P>,
        params: Vec<f64>,
        variant: NonUniformVariant,
    ) -> Result<Self, Error> {
        check_points(&points)?;
        check_params(points.len(), &params)?;
        let inner = match variant {
            NonUniformVariant::Thesis => Inner::Thesis(thesis::Thesis::new(&points, &params)?),
            NonUniformVariant::Nodes => Inner::Nodes(nodes::Nodes::new(&points, &params)),
        };
        Ok(Self { points, params, variant, inner })
    }

    /// The interpolated points.
    #[must_use]
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The parameters tₖ.
    #[must_use]
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// Which reading of §3.10 this curve follows.
    #[must_use]
    pub fn variant(&self) -> NonUniformVariant {
        self.variant
    }

    /// Where the curve passes through xₖ: tₖ for [`NonUniformVariant::Nodes`], k/(n−1) for
    /// [`NonUniformVariant::Thesis`] (0 for a single point).
    #[must_use]
    pub fn interpolation_params(&self) -> Vec<f64> {
        let n = self.points.len();
        match self.variant {
            NonUniformVariant::Nodes => self.params.clone(),
            NonUniformVariant::Thesis if n == 1 => vec![0.0],
            NonUniformVariant::Thesis => (0..n).map(|k| k as f64 / (n - 1) as f64).collect(),
        }
    }

    /// The condition number of the interpolation problem: the Lebesgue constant
    /// Λ = maxₜ Σₖ |ℓₖ(t)| of the curve's cardinal functions, so that moving the points by δ
    /// moves the curve by at most Λ·δ. Measured by sampling every gap between interpolation
    /// parameters and refining the largest sample of each gap (golden section); O(n²), and
    /// O(n³) for the thesis variant. For uniform nodes Λ grows like (2/π)·ln n.
    #[must_use]
    pub fn condition(&self) -> f64 {
        match &self.inner {
            Inner::Thesis(c) => c.lebesgue(),
            Inner::Nodes(c) => c.lebesgue(),
        }
    }

    /// For the thesis variant, the 1-norm condition number ‖A‖₁·‖A⁻¹‖₁ of its Vandermonde
    /// matrix, which bounds the rounding error of the construction; `None` for the nodes
    /// variant, which solves no system.
    #[must_use]
    pub fn matrix_condition(&self) -> Option<f64> {
        match &self.inner {
            Inner::Thesis(c) => Some(c.matrix_condition()),
            Inner::Nodes(_) => None,
        }
    }

    /// For the nodes variant, its spectrum (it is a trigonometric polynomial of degree ⌊n/2⌋);
    /// `None` for the thesis variant, whose frequencies are not integers.
    #[must_use]
    pub fn fourier(&self) -> Option<&Fourier<P>> {
        match &self.inner {
            Inner::Thesis(_) => None,
            Inner::Nodes(c) => Some(c.fourier()),
        }
    }

    /// X(t).
    #[must_use]
    pub fn eval(&self, t: f64) -> P {
        match &self.inner {
            Inner::Thesis(c) => c.eval_deriv(t, 0),
            Inner::Nodes(c) => c.eval(t),
        }
    }

    /// X⁽ᵖ⁾(t).
    #[must_use]
    pub fn eval_deriv(&self, t: f64, order: usize) -> P {
        match &self.inner {
            Inner::Thesis(c) => c.eval_deriv(t, order),
            Inner::Nodes(c) if order == 0 => c.eval(t),
            Inner::Nodes(c) => c.fourier().eval_deriv(t, order),
        }
    }
}

impl<P: ControlPoint> ParamCurve<P> for NonUniformCurve<P> {
    fn eval(&self, t: f64) -> P {
        NonUniformCurve::eval(self, t)
    }

    fn eval_deriv(&self, t: f64, order: usize) -> P {
        NonUniformCurve::eval_deriv(self, t, order)
    }

    fn scale(&self) -> f64 {
        let n = self.points.len() as f64;
        let centroid = self.points.iter().fold(P::ZERO, |acc, p| acc + *p) * (1.0 / n);
        spread(&self.points, centroid)
    }

    fn is_periodic(&self) -> bool {
        self.variant == NonUniformVariant::Nodes
    }
}

/// The maximum of `f` over the gaps between sorted parameters (cyclic if `periodic`, else
/// over [min, max]): 8 samples inside each gap, then a golden-section refinement around the best
/// sample of each gap. This is where a Lebesgue function, smooth between nodes, peaks.
fn max_over_gaps(params: &[f64], periodic: bool, f: impl Fn(f64) -> f64) -> f64 {
    const PER_GAP: usize = 8;
    let mut sorted = params.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n_gaps = if periodic { sorted.len() } else { sorted.len().saturating_sub(1) };
    let mut best = f(sorted[0]);
    for g in 0..n_gaps {
        let a = sorted[g];
        let b = if g + 1 < sorted.len() { sorted[g + 1] } else { sorted[0] + 1.0 };
        let h = (b - a) / (PER_GAP + 1) as f64;
        let (mut arg, mut top) = (a, f64::NEG_INFINITY);
        for i in 1..=PER_GAP {
            let t = a + h * i as f64;
            let v = f(t);
            if v > top {
                (arg, top) = (t, v);
            }
        }
        best = best.max(top).max(golden_max(&f, arg - h, arg + h));
    }
    best
}

/// Golden-section search for the maximum of a unimodal `f` on [lo, hi].
fn golden_max(f: &impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    const INV_PHI: f64 = 0.618_033_988_749_894_8;
    let mut x1 = hi - INV_PHI * (hi - lo);
    let mut x2 = lo + INV_PHI * (hi - lo);
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..40 {
        if f1 < f2 {
            lo = x1;
            (x1, f1) = (x2, f2);
            x2 = lo + INV_PHI * (hi - lo);
            f2 = f(x2);
        } else {
            hi = x2;
            (x2, f2) = (x1, f1);
            x1 = hi - INV_PHI * (hi - lo);
            f1 = f(x1);
        }
    }
    f1.max(f2)
}

/// A complex vector per coordinate: point-valued complex numbers (re, im).
type ComplexPoint<P> = (P, P);

fn complex_of<P: ControlPoint>(coords: &[Vec<Complex64>], j: usize) -> ComplexPoint<P> {
    (P::from_coords(|i| coords[i][j].re), P::from_coords(|i| coords[i][j].im))
}
