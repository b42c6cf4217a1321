// SPDX-License-Identifier: MIT
//! Triangular Bézier patches (Hardy 2005, §4.3 "Triangular Bézier Surfaces", figure 4.4):
//! p(u, v) = Σᵢ₊ⱼ₊ₖ₌ₙ Bⁿᵢⱼₖ(u, v)·xᵢⱼₖ with Bⁿᵢⱼₖ = n!/(i!j!k!)·uⁱvʲwᵏ and w = 1 − u − v,
//! evaluated by the barycentric de Casteljau algorithm.

use glam::DVec3;

use crate::bounds::Aabb;
use crate::error::check_points;
use crate::patch::unit_normal;
use crate::{BezierCurve, ControlPoint, Error};

/// A triangular Bézier patch of degree n: (n + 1)(n + 2)/2 control points xᵢⱼₖ, i + j + k = n,
/// over the parameter triangle u, v ≥ 0, u + v ≤ 1 with barycentric coordinates (u, v, w),
/// w = 1 − u − v.
///
/// The corners are p(1, 0) = xₙ₀₀, p(0, 1) = x₀ₙ₀ and p(0, 0) = x₀₀ₙ. Control points are stored
/// by i, then j: x₀,₀,ₙ, x₀,₁,ₙ₋₁, …, x₀,ₙ,₀, x₁,₀,ₙ₋₁, …, xₙ,₀,₀
/// ([`TriangularPatch::index`]).
///
/// The thesis states the partial derivatives as Σ Bⁿ⁻¹ᵢⱼₖ·xᵢ₊₁,ⱼ,ₖ; with w = 1 − u − v the full
/// form is ∂p/∂u = n·Σ Bⁿ⁻¹ᵢⱼₖ·(xᵢ₊₁,ⱼ,ₖ − xᵢ,ⱼ,ₖ₊₁), which is what this type computes.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_bezier::TriangularPatch;
///
/// // Degree 1 is the flat triangle with vertices x₁₀₀, x₀₁₀, x₀₀₁.
/// let (a, b, c) = (DVec3::X, DVec3::Y, DVec3::Z);
/// let tri = TriangularPatch::try_from_fn(1, |i, j, _| if i == 1 { a } else if j == 1 { b } else { c })
///     .unwrap();
/// let p = tri.eval(0.2, 0.3);
/// assert!((p - (0.2 * a + 0.3 * b + 0.5 * c)).length() < 1e-15);
/// assert!((tri.normal(0.2, 0.3).unwrap() - DVec3::ONE.normalize()).length() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TriangularPatch<P> {
    // Invariant: points.len() == (n + 1)(n + 2)/2 for n = degree, all finite.
    degree: usize,
    points: Vec<P>,
}

/// The number of control points of degree n, (n + 1)(n + 2)/2.
const fn n_points(n: usize) -> usize {
    (n + 1) * (n + 2) / 2
}

/// Index of (i, j) in the net of degree n (k = n − i − j).
#[inline]
fn idx(n: usize, i: usize, j: usize) -> usize {
    i * (n + 1) - i * i.saturating_sub(1) / 2 + j
}

impl<P: ControlPoint> TriangularPatch<P> {
    /// The patch with these control points in the order of [`TriangularPatch::index`]; the
    /// degree follows from their number.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no points, [`Error::TriangularCount`] unless the number is
    /// (n + 1)(n + 2)/2 for some n, [`Error::NonFinitePoint`] for a non-finite coordinate.
    pub fn try_new(points: Vec<P>) -> Result<Self, Error> {
        check_points(&points)?;
        let mut degree = 0;
        while n_points(degree) < points.len() {
            degree += 1;
        }
        if n_points(degree) != points.len() {
            return Err(Error::TriangularCount { found: points.len() });
        }
        Ok(Self { degree, points })
    }

    /// The patch with these control points.
    ///
    /// # Panics
    ///
    /// Panics on invalid input; see [`TriangularPatch::try_new`].
    #[must_use]
    pub fn new(points: Vec<P>) -> Self {
        Self::try_new(points).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The patch of degree n with xᵢⱼₖ = f(i, j, k).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinitePoint`] if `f` returns a non-finite point.
    pub fn try_from_fn(
        degree: usize,
        mut f: impl FnMut(usize, usize, usize) -> P,
    ) -> Result<Self, Error> {
        let mut points = Vec::with_capacity(n_points(degree));
        for i in 0..=degree {
            for j in 0..=degree - i {
                points.push(f(i, j, degree - i - j));
            }
        }
        check_points(&points)?;
        Ok(Self { degree, points })
    }

    /// The degree n.
    #[must_use]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The control points, ordered by i, then j.
    #[must_use]
    pub fn control_points(&self) -> &[P] {
        &self.points
    }

    /// The position of xᵢⱼₖ in [`TriangularPatch::control_points`]:
    /// i(n + 1) − i(i − 1)/2 + j; `None` unless i + j + k = n.
    #[must_use]
    pub fn index(&self, i: usize, j: usize, k: usize) -> Option<usize> {
        (i + j + k == self.degree).then(|| idx(self.degree, i, j))
    }

    /// The control point xᵢⱼₖ; `None` unless i + j + k = n.
    #[must_use]
    pub fn control_point(&self, i: usize, j: usize, k: usize) -> Option<P> {
        self.index(i, j, k).map(|n| self.points[n])
    }

    /// p(u, v) by the barycentric de Casteljau algorithm: n rounds of
    /// xʳᵢⱼₖ = u·xʳ⁻¹ᵢ₊₁,ⱼ,ₖ + v·xʳ⁻¹ᵢ,ⱼ₊₁,ₖ + w·xʳ⁻¹ᵢ,ⱼ,ₖ₊₁ (outside the triangle it
    /// extrapolates).
    #[must_use]
    pub fn eval(&self, u: f64, v: f64) -> P {
        let mut net = self.points.clone();
        for r in (1..=self.degree).rev() {
            step(&mut net, r, u, v, 1.0 - u - v);
        }
        net[0]
    }

    /// The derivative of order `order` along the parameter-plane direction `direction` =
    /// (du, dv), i.e. dᵒʳᵈᵉʳ/dsᵒʳᵈᵉʳ p(u + s·du, v + s·dv) at s = 0; zero beyond the degree.
    ///
    /// Each order is one de Casteljau round with the barycentric direction (du, dv, −du − dv)
    /// in place of (u, v, w), times the current degree.
    #[must_use]
    pub fn eval_directional(&self, u: f64, v: f64, direction: (f64, f64), order: usize) -> P {
        let (du, dv) = direction;
        self.eval_mixed(u, v, &vec![(du, dv); order])
    }

    /// The partial derivative ∂ᵃ⁺ᵇp/∂uᵃ∂vᵇ (v, respectively u, held fixed; w = 1 − u − v
    /// varies).
    #[must_use]
    pub fn eval_deriv(&self, u: f64, v: f64, order_u: usize, order_v: usize) -> P {
        let mut dirs = vec![(1.0, 0.0); order_u];
        dirs.extend(std::iter::repeat_n((0.0, 1.0), order_v));
        self.eval_mixed(u, v, &dirs)
    }

    /// The mixed directional derivative along each of `directions` in turn.
    fn eval_mixed(&self, u: f64, v: f64, directions: &[(f64, f64)]) -> P {
        let n = self.degree;
        if directions.len() > n {
            return P::ZERO;
        }
        let mut net = self.points.clone();
        let mut r = n;
        for &(du, dv) in directions {
            step(&mut net, r, du, dv, -du - dv);
            let scale = r as f64;
            for p in &mut net[..n_points(r - 1)] {
                *p = *p * scale;
            }
            r -= 1;
        }
        while r > 0 {
            step(&mut net, r, u, v, 1.0 - u - v);
            r -= 1;
        }
        net[0]
    }

    /// The same surface with degree n + 1:
    /// yᵢⱼₖ = (i·xᵢ₋₁,ⱼ,ₖ + j·xᵢ,ⱼ₋₁,ₖ + k·xᵢ,ⱼ,ₖ₋₁)/(n + 1).
    #[must_use]
    pub fn elevate(&self) -> Self {
        let n = self.degree;
        let m = n + 1;
        let mut points = Vec::with_capacity(n_points(m));
        for i in 0..=m {
            for j in 0..=m - i {
                points.push(self.elevated_point(i, j, m - i - j));
            }
        }
        Self { degree: m, points }
    }

    /// Control point (i, j, k) of the degree-elevated net.
    fn elevated_point(&self, i: usize, j: usize, k: usize) -> P {
        let n = self.degree;
        let mut p = P::ZERO;
        if i > 0 {
            p += self.points[idx(n, i - 1, j)] * i as f64;
        }
        if j > 0 {
            p += self.points[idx(n, i, j - 1)] * j as f64;
        }
        if k > 0 {
            p += self.points[idx(n, i, j)] * k as f64;
        }
        p * (1.0 / (n + 1) as f64)
    }

    /// The three boundary curves, each a Bézier curve of degree n:
    /// `[v = 0: t ↦ p(t, 0), u = 0: t ↦ p(0, t), w = 0: t ↦ p(1 − t, t)]`.
    #[must_use]
    pub fn boundary_curves(&self) -> [BezierCurve<P>; 3] {
        let n = self.degree;
        let v0 = (0..=n).map(|i| self.points[idx(n, i, 0)]).collect();
        let u0 = (0..=n).map(|j| self.points[idx(n, 0, j)]).collect();
        let w0 = (0..=n).map(|j| self.points[idx(n, n - j, j)]).collect();
        [
            BezierCurve::from_vec_unchecked(v0),
            BezierCurve::from_vec_unchecked(u0),
            BezierCurve::from_vec_unchecked(w0),
        ]
    }

    /// The box of the control points, which holds the patch (convex hull property).
    #[must_use]
    pub fn control_bounding_box(&self) -> Aabb<P> {
        Aabb::of_nonempty(&self.points)
    }
}

impl TriangularPatch<DVec3> {
    /// The unit normal (∂p/∂u × ∂p/∂v)/|…|; `None` where the patch is degenerate (see
    /// [`crate::BezierPatch::normal`]).
    #[must_use]
    pub fn normal(&self, u: f64, v: f64) -> Option<DVec3> {
        unit_normal(self.eval_deriv(u, v, 1, 0), self.eval_deriv(u, v, 0, 1))
    }
}

/// One barycentric de Casteljau round from degree r to r − 1, in place, with weights (a, b, c)
/// on (i + 1, j, k), (i, j + 1, k), (i, j, k + 1).
fn step<P: ControlPoint>(net: &mut [P], r: usize, a: f64, b: f64, c: f64) {
    // Writing (i, j) of degree r − 1 reads (i + 1, j), (i, j + 1), (i, j) of degree r; in the
    // order i, then j, the reads of later entries are never overwritten first, because
    // idx(r − 1, i, j) ≤ idx(r, i, j) and the entries read later have larger indices.
    for i in 0..r {
        for j in 0..r - i {
            let p = net[idx(r, i + 1, j)] * a + net[idx(r, i, j + 1)] * b + net[idx(r, i, j)] * c;
            net[idx(r - 1, i, j)] = p;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_layout() {
        let n = 3;
        let mut expected = 0;
        for i in 0..=n {
            for j in 0..=n - i {
                assert_eq!(idx(n, i, j), expected);
                expected += 1;
            }
        }
        assert_eq!(expected, n_points(n));
    }

    #[test]
    fn validation() {
        assert_eq!(TriangularPatch::<f64>::try_new(vec![]), Err(Error::Empty));
        assert_eq!(
            TriangularPatch::try_new(vec![0.0; 4]),
            Err(Error::TriangularCount { found: 4 })
        );
        assert_eq!(TriangularPatch::try_new(vec![0.0; 6]).map(|t| t.degree()), Ok(2));
        assert_eq!(TriangularPatch::try_new(vec![0.0]).map(|t| t.degree()), Ok(0));
        let t = TriangularPatch::try_from_fn(2, |i, j, k| (100 * i + 10 * j + k) as f64).unwrap();
        assert_eq!(t.control_point(1, 0, 1), Some(101.0));
        assert_eq!(t.control_point(1, 1, 1), None);
    }

    #[test]
    fn corners_and_edges() {
        let t = TriangularPatch::try_from_fn(3, |i, j, k| {
            DVec3::new(i as f64, j as f64, (k * k) as f64)
        })
        .unwrap();
        assert!((t.eval(1.0, 0.0) - DVec3::new(3.0, 0.0, 0.0)).length() < 1e-15);
        assert!((t.eval(0.0, 1.0) - DVec3::new(0.0, 3.0, 0.0)).length() < 1e-15);
        assert!((t.eval(0.0, 0.0) - DVec3::new(0.0, 0.0, 9.0)).length() < 1e-15);
        let [e0, e1, e2] = t.boundary_curves();
        for s in [0.0, 0.3, 0.8, 1.0] {
            assert!((e0.eval(s) - t.eval(s, 0.0)).length() < 1e-14);
            assert!((e1.eval(s) - t.eval(0.0, s)).length() < 1e-14);
            assert!((e2.eval(s) - t.eval(1.0 - s, s)).length() < 1e-14);
        }
    }
}
