// SPDX-License-Identifier: MIT
//! Piecewise Bézier curves (Hardy 2005, §2.5 "Piecewise Continuous Bézier Curves", eq. 2.5,
//! figure 2.5): segments joined end to end, with constructors of C1 and G1 chains.

use crate::bounds::Aabb;
use crate::flatten::FlatnessTest;
use crate::{BezierCurve, ControlPoint, Error};

/// A chain of Bézier segments, traversed for u ∈ [0, 1] with segment i on
/// [i/s, (i+1)/s] (s segments), as Q(u) of §2.5.
///
/// The segments are stored as given; joins are not forced to be continuous (the constructors
/// of joined curves guarantee C0, C1 or G1 themselves, and [`PiecewiseBezier::joins`] measures
/// what a chain has). Segments may have different degrees.
///
/// # Examples
///
/// ```
/// use hi_bezier::{BezierCurve, PiecewiseBezier};
///
/// let a = BezierCurve::new(vec![0.0, 1.0]);
/// let b = BezierCurve::new(vec![1.0, 3.0]);
/// let chain = PiecewiseBezier::try_new(vec![a, b]).unwrap();
/// assert_eq!(chain.eval(0.25), 0.5);
/// assert_eq!(chain.eval(0.75), 2.0);
/// assert!(chain.is_c0(0.0) && !chain.is_c1(1e-9));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PiecewiseBezier<P> {
    // Invariant: at least one segment.
    segments: Vec<BezierCurve<P>>,
}

impl<P: ControlPoint> PiecewiseBezier<P> {
    /// The chain of these segments.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no segments.
    pub fn try_new(segments: Vec<BezierCurve<P>>) -> Result<Self, Error> {
        if segments.is_empty() { Err(Error::Empty) } else { Ok(Self { segments }) }
    }

    /// The chain of these segments.
    ///
    /// # Panics
    ///
    /// Panics for no segments; see [`PiecewiseBezier::try_new`].
    #[must_use]
    pub fn new(segments: Vec<BezierCurve<P>>) -> Self {
        Self::try_new(segments).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The C1 chain of cubic Hermite segments: segment i runs from `points[i]` to
    /// `points[i + 1]` with derivatives `tangents[i]` and `tangents[i + 1]` (with respect to its
    /// own parameter t), so its control points are Pᵢ, Pᵢ + Tᵢ/3, Pᵢ₊₁ − Tᵢ₊₁/3, Pᵢ₊₁ and the
    /// joins satisfy eq. 2.5.
    ///
    /// # Errors
    ///
    /// [`Error::TooFewPoints`] for fewer than two points, [`Error::LengthMismatch`] unless
    /// there is one tangent per point, [`Error::NonFinitePoint`] for a non-finite point
    /// (index i) or tangent (index `points.len()` + i).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_bezier::PiecewiseBezier;
    ///
    /// let pts = [DVec2::ZERO, DVec2::new(1.0, 1.0), DVec2::new(2.0, 0.0)];
    /// let tangents = [DVec2::new(1.0, 2.0), DVec2::new(1.5, 0.0), DVec2::new(1.0, -2.0)];
    /// let chain = PiecewiseBezier::c1_hermite(&pts, &tangents).unwrap();
    /// assert!(chain.is_c1(1e-15));
    /// assert_eq!(chain.eval(0.5), DVec2::new(1.0, 1.0));
    /// ```
    pub fn c1_hermite(points: &[P], tangents: &[P]) -> Result<Self, Error> {
        if points.len() < 2 {
            return Err(Error::TooFewPoints { needed: 2, found: points.len() });
        }
        if tangents.len() != points.len() {
            return Err(Error::LengthMismatch {
                what: "tangents",
                expected: points.len(),
                found: tangents.len(),
            });
        }
        check_all(points.iter().chain(tangents), 0)?;
        let third = 1.0 / 3.0;
        let segments = (0..points.len() - 1)
            .map(|i| {
                BezierCurve::from_vec_unchecked(vec![
                    points[i],
                    points[i] + tangents[i] * third,
                    points[i + 1] - tangents[i + 1] * third,
                    points[i + 1],
                ])
            })
            .collect();
        Ok(Self { segments })
    }

    /// The C1 chain that starts with `first` and continues with one segment per entry of
    /// `tails`: a tail R₂, …, Rₘ gives the segment R₀, R₁, R₂, …, Rₘ of degree m, with R₀ the
    /// end Qₙ of the previous segment and R₁ fixed by C1 continuity,
    /// m(R₁ − R₀) = n(Qₙ − Qₙ₋₁) (eq. 2.5, adapted to different degrees as §2.5 suggests).
    ///
    /// For cubics each tail is the pair (R₂, R₃): the third control point and the end.
    ///
    /// # Errors
    ///
    /// [`Error::TooFewPoints`] if `first` has degree 0 (no tangent), [`Error::NonFinitePoint`]
    /// for a non-finite tail point (index counted through all tails in order).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_bezier::{BezierCurve, PiecewiseBezier};
    ///
    /// let first = BezierCurve::new(vec![DVec2::ZERO, DVec2::Y, DVec2::ONE, DVec2::X]);
    /// let chain = PiecewiseBezier::c1_chain(first, &[vec![DVec2::new(3.0, 1.0), DVec2::new(3.0, 0.0)]])
    ///     .unwrap();
    /// // R₁ = R₀ + (R₀ − Q₂) = (1, 0) + (0, −1).
    /// assert_eq!(chain.segments()[1].control_points()[1], DVec2::new(1.0, -1.0));
    /// assert!(chain.is_c1(1e-15));
    /// ```
    pub fn c1_chain(first: BezierCurve<P>, tails: &[Vec<P>]) -> Result<Self, Error> {
        Self::chain(first, tails, 1.0)
    }

    /// The G1 chain of §2.5: as [`PiecewiseBezier::c1_chain`], but with
    /// n(Qₙ − Qₙ₋₁) = s·m(R₁ − R₀), so the tangent directions agree and the speeds differ by the
    /// shape factor s (figure 2.5(b) uses s = 0.6; s = 1 is C1).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidArgument`] unless s is positive and finite, and the errors of
    /// [`PiecewiseBezier::c1_chain`].
    pub fn g1_chain(first: BezierCurve<P>, tails: &[Vec<P>], s: f64) -> Result<Self, Error> {
        if !(s.is_finite() && s > 0.0) {
            return Err(Error::InvalidArgument {
                name: "s",
                value: s,
                expected: "a positive finite shape factor",
            });
        }
        Self::chain(first, tails, s)
    }

    /// The chain with n(Qₙ − Qₙ₋₁) = s·m(R₁ − R₀) at every join.
    fn chain(first: BezierCurve<P>, tails: &[Vec<P>], s: f64) -> Result<Self, Error> {
        if first.degree() == 0 {
            return Err(Error::TooFewPoints { needed: 2, found: 1 });
        }
        check_all(tails.iter().flatten(), 0)?;
        let mut segments = vec![first];
        for tail in tails {
            let prev = segments[segments.len() - 1].control_points();
            let n = prev.len() - 1;
            let m = tail.len() + 1;
            let r0 = prev[n];
            let end_tangent = (prev[n] - prev[n - 1]) * n as f64;
            let r1 = r0 + end_tangent * (1.0 / (s * m as f64));
            let mut control = Vec::with_capacity(m + 1);
            control.push(r0);
            control.push(r1);
            control.extend_from_slice(tail);
            segments.push(BezierCurve::from_vec_unchecked(control));
        }
        Ok(Self { segments })
    }

    /// The segments.
    #[must_use]
    pub fn segments(&self) -> &[BezierCurve<P>] {
        &self.segments
    }

    /// The point at u ∈ [0, 1] (segment ⌊u·s⌋ at local parameter u·s − ⌊u·s⌋; u = 1 is the
    /// end of the last segment).
    #[must_use]
    pub fn eval(&self, u: f64) -> P {
        let (i, t) = self.locate(u);
        self.segments[i].eval(t)
    }

    /// The derivative of order `order` with respect to the global parameter u, sᵒʳᵈᵉʳ times the
    /// segment's own derivative (one-sided at joins: the segment that starts there).
    #[must_use]
    pub fn eval_deriv(&self, u: f64, order: usize) -> P {
        let (i, t) = self.locate(u);
        let s = self.segments.len() as f64;
        self.segments[i].eval_deriv(t, order) * s.powi(order as i32)
    }

    /// The segment index and local parameter of the global parameter u.
    #[must_use]
    pub fn locate(&self, u: f64) -> (usize, f64) {
        let s = self.segments.len();
        let x = (u * s as f64).clamp(0.0, s as f64);
        let i = (x.floor() as usize).min(s - 1);
        (i, x - i as f64)
    }

    /// A polyline within `tolerance` of the chain, both ways (each segment flattened by
    /// [`BezierCurve::flatten`]; a gap at a join appears as a polyline edge across it).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidTolerance`] as for [`BezierCurve::flatten`].
    pub fn flatten(&self, tolerance: f64) -> Result<Vec<P>, Error> {
        let mut out = vec![self.segments[0].control_points()[0]];
        for seg in &self.segments {
            let start = seg.control_points()[0];
            if out.last() != Some(&start) {
                out.push(start);
            }
            seg.flatten_into(tolerance, FlatnessTest::ConvexHull, &mut out)?;
        }
        Ok(out)
    }

    /// The tight bounding box of the chain (union of the segments' tight boxes).
    #[must_use]
    pub fn bounding_box(&self) -> Aabb<P> {
        let first = self.segments[0].bounding_box();
        self.segments[1..].iter().fold(first, |acc, seg| acc.union(seg.bounding_box()))
    }
}

/// Checks a sequence of points for finiteness, reporting indices from `offset`.
fn check_all<'a, P: ControlPoint>(
    points: impl Iterator<Item = &'a P>,
    offset: usize,
) -> Result<(), Error> {
    for (i, p) in points.enumerate() {
        if !p.is_finite() {
            return Err(Error::NonFinitePoint { index: offset + i });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;

    #[test]
    fn constructor_errors() {
        let p = [DVec2::ZERO];
        assert_eq!(
            PiecewiseBezier::c1_hermite(&p, &p),
            Err(Error::TooFewPoints { needed: 2, found: 1 })
        );
        let p2 = [DVec2::ZERO, DVec2::X];
        assert_eq!(
            PiecewiseBezier::c1_hermite(&p2, &p),
            Err(Error::LengthMismatch { what: "tangents", expected: 2, found: 1 })
        );
        assert_eq!(
            PiecewiseBezier::c1_hermite(&p2, &[DVec2::X, DVec2::NAN]),
            Err(Error::NonFinitePoint { index: 3 })
        );
        let point = BezierCurve::new(vec![DVec2::ZERO]);
        assert!(PiecewiseBezier::c1_chain(point, &[]).is_err());
        let line = BezierCurve::new(vec![DVec2::ZERO, DVec2::X]);
        assert!(PiecewiseBezier::g1_chain(line.clone(), &[], 0.0).is_err());
        assert_eq!(
            PiecewiseBezier::c1_chain(line, &[vec![DVec2::ONE], vec![DVec2::INFINITY]]),
            Err(Error::NonFinitePoint { index: 1 })
        );
        assert_eq!(PiecewiseBezier::<f64>::try_new(vec![]), Err(Error::Empty));
    }

    #[test]
    fn global_derivative_scales_with_the_segment_count() {
        let a = BezierCurve::new(vec![0.0, 1.0]);
        let chain = PiecewiseBezier::new(vec![a.clone(), a.clone(), a]);
        assert_eq!(chain.eval_deriv(0.5, 1), 3.0);
        assert_eq!(chain.locate(1.0), (2, 1.0));
        assert_eq!(chain.locate(-1.0), (0, 0.0));
    }

    #[test]
    fn mixed_degree_chain_is_c1() {
        let first = BezierCurve::new(vec![DVec2::ZERO, DVec2::new(1.0, 2.0)]);
        let chain = PiecewiseBezier::c1_chain(
            first,
            &[vec![DVec2::new(4.0, 0.0), DVec2::new(5.0, 1.0)], vec![]],
        )
        .unwrap();
        assert_eq!(chain.segments()[1].degree(), 3);
        assert_eq!(chain.segments()[2].degree(), 1);
        assert!(chain.is_c1(1e-14), "{:?}", chain.joins());
    }
}
