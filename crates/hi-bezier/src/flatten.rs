// SPDX-License-Identifier: MIT
//! Flattening Bézier curves into polylines by recursive subdivision (Hardy 2005, §2.5
//! "Recursive Subdivision"): split in halves (Theorem 2.2) until each piece passes a flatness
//! test, the midpoint test of eq. 2.7 or the convex hull test.

use crate::subdivide::split_points;
use crate::{BezierCurve, ControlPoint, Error};

/// Deepest subdivision of [`BezierCurve::flatten`]: 2³² pieces is far beyond any accepted
/// tolerance (the tolerance floor keeps the depth near 20 for smooth curves).
const MAX_DEPTH: u32 = 32;

/// Relative floor of a tolerance: below 1e-10 of the coordinate magnitude, rounding in the
/// subdivision would decide the result.
const RELATIVE_FLOOR: f64 = 1e-10;

/// How [`BezierCurve::flatten_with`] decides that a piece is flat enough to be drawn as the
/// chord from its first to its last control point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum FlatnessTest {
    /// The convex hull test: every control point lies within the tolerance of the chord
    /// segment from P₀ to Pₙ. Then so does every point of the piece (it is a convex combination of
    /// the control points, and distance to a segment is a convex function), and every point of
    /// the chord lies within the tolerance of the piece. This is the guaranteed test.
    ConvexHull,
    /// Eq. 2.7: |q(½) − (P₀ + Pₙ)/2| < δ. Cheap and usually right, but a heuristic: an S-shaped
    /// piece symmetric about its chord's midpoint passes it while bulging far from the chord.
    Midpoint,
}

impl<P: ControlPoint> BezierCurve<P> {
    /// The distance of q(½) from the chord's midpoint (P₀ + Pₙ)/2: the left side of eq. 2.7.
    #[must_use]
    #[doc(alias = "eq. 2.7")]
    pub fn midpoint_flatness(&self) -> f64 {
        let c = self.control_points();
        let n = c.len() - 1;
        (self.eval(0.5) - (c[0] + c[n]) * 0.5).norm()
    }

    /// The largest distance of a control point from the chord segment from P₀ to Pₙ: an upper bound of
    /// the distance of every curve point over [0, 1] from that segment (convex hull property).
    #[must_use]
    pub fn hull_flatness(&self) -> f64 {
        hull_distance(self.control_points())
    }

    /// A polyline through points of the curve (q(0) first, q(1) last) whose distance from the
    /// curve is at most `tolerance`, both ways: every curve point is within `tolerance` of the
    /// polyline and every polyline point within `tolerance` of the curve.
    ///
    /// Splits in halves (Theorem 2.2) until every piece passes the convex hull test
    /// ([`FlatnessTest::ConvexHull`]).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidTolerance`] unless `tolerance` is finite and at least 1e-10 times the
    /// largest coordinate magnitude of the control points (below that, rounding decides).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_bezier::BezierCurve;
    ///
    /// let c = BezierCurve::new(vec![DVec2::ZERO, DVec2::new(0.0, 1.0), DVec2::new(1.0, 1.0)]);
    /// let coarse = c.flatten(0.1).unwrap();
    /// let fine = c.flatten(1e-4).unwrap();
    /// assert!(coarse.len() < fine.len());
    /// assert_eq!((fine[0], *fine.last().unwrap()), (DVec2::ZERO, DVec2::ONE));
    /// ```
    pub fn flatten(&self, tolerance: f64) -> Result<Vec<P>, Error> {
        self.flatten_with(tolerance, FlatnessTest::ConvexHull)
    }

    /// [`BezierCurve::flatten`] with a chosen flatness test; only
    /// [`FlatnessTest::ConvexHull`] guarantees the tolerance.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidTolerance`] as for [`BezierCurve::flatten`].
    pub fn flatten_with(&self, tolerance: f64, test: FlatnessTest) -> Result<Vec<P>, Error> {
        let mut out = vec![self.control_points()[0]];
        self.flatten_into(tolerance, test, &mut out)?;
        Ok(out)
    }

    /// Appends the polyline of [`BezierCurve::flatten_with`] to `out`, without its first
    /// point q(0) (so the polylines of consecutive segments chain without repeats).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidTolerance`] as for [`BezierCurve::flatten`].
    pub fn flatten_into(
        &self,
        tolerance: f64,
        test: FlatnessTest,
        out: &mut Vec<P>,
    ) -> Result<(), Error> {
        let c = self.control_points();
        check_tolerance(tolerance, c)?;
        let n = c.len() - 1;
        let mut stack = vec![(c.to_vec(), 0u32)];
        while let Some((piece, depth)) = stack.pop() {
            let flat = match test {
                FlatnessTest::ConvexHull => hull_distance(&piece) <= tolerance,
                FlatnessTest::Midpoint => {
                    let mid = crate::curve::de_casteljau(&mut piece.clone(), 0.5);
                    (mid - (piece[0] + piece[n]) * 0.5).norm() < tolerance
                }
            };
            if flat || depth >= MAX_DEPTH {
                out.push(piece[n]);
            } else {
                let (left, right) = split_points(&piece, 0.5);
                stack.push((right, depth + 1));
                stack.push((left, depth + 1));
            }
        }
        Ok(())
    }
}

/// Checks a tolerance against the relative floor of the points' coordinates.
pub(crate) fn check_tolerance<P: ControlPoint>(tolerance: f64, points: &[P]) -> Result<(), Error> {
    let magnitude = points
        .iter()
        .flat_map(|p| (0..P::DIM).map(move |i| p.coord(i).abs()))
        .fold(0.0f64, f64::max);
    let minimum = RELATIVE_FLOOR * magnitude;
    if tolerance.is_finite() && tolerance > 0.0 && tolerance >= minimum {
        Ok(())
    } else {
        Err(Error::InvalidTolerance { value: tolerance, minimum: minimum.max(f64::MIN_POSITIVE) })
    }
}

/// The distance from `p` to the segment ab (to the point a if a = b).
#[must_use]
pub(crate) fn distance_to_segment<P: ControlPoint>(p: P, a: P, b: P) -> f64 {
    let ab = b - a;
    let ap = p - a;
    let len2 = ab.dot(ab);
    let s = if len2 > 0.0 { (ap.dot(ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
    (ap - ab * s).norm()
}

/// The largest distance of the inner control points from the chord from P₀ to Pₙ.
fn hull_distance<P: ControlPoint>(c: &[P]) -> f64 {
    if c.len() <= 2 {
        return 0.0;
    }
    let (a, b) = (c[0], c[c.len() - 1]);
    c[1..c.len() - 1].iter().map(|&p| distance_to_segment(p, a, b)).fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use glam::DVec2;

    use super::*;

    #[test]
    fn tolerance_checks() {
        let c = BezierCurve::new(vec![DVec2::ZERO, DVec2::new(1e6, 0.0)]);
        assert!(matches!(c.flatten(0.0), Err(Error::InvalidTolerance { .. })));
        assert!(matches!(c.flatten(f64::NAN), Err(Error::InvalidTolerance { .. })));
        assert!(matches!(c.flatten(1e-6), Err(Error::InvalidTolerance { .. })));
        assert_eq!(c.flatten(1e-3).unwrap().len(), 2, "a line is flat");
        let point = BezierCurve::new(vec![DVec2::ZERO, DVec2::ZERO]);
        assert_eq!(point.flatten(1e-300).unwrap().len(), 2);
        let degree_zero = BezierCurve::new(vec![DVec2::ONE]);
        assert_eq!(degree_zero.flatten(0.1).unwrap(), vec![DVec2::ONE, DVec2::ONE]);
        assert_eq!(degree_zero.hull_flatness(), 0.0);
        assert_eq!(degree_zero.midpoint_flatness(), 0.0);
    }

    #[test]
    fn segment_distance() {
        let (a, b) = (DVec2::ZERO, DVec2::X);
        assert_eq!(distance_to_segment(DVec2::new(0.5, 2.0), a, b), 2.0);
        assert_eq!(distance_to_segment(DVec2::new(-3.0, 4.0), a, b), 5.0);
        assert_eq!(distance_to_segment(DVec2::new(3.0, 4.0), a, a), 5.0);
    }

    #[test]
    fn midpoint_test_can_be_fooled() {
        // An S: q(½) is the chord's midpoint, so eq. 2.7 accepts the chord at once.
        let s = BezierCurve::new(vec![
            DVec2::ZERO,
            DVec2::new(1.0, 1.0),
            DVec2::new(2.0, -1.0),
            DVec2::new(3.0, 0.0),
        ]);
        assert!(s.midpoint_flatness() < 1e-15);
        assert_eq!(s.flatten_with(0.01, FlatnessTest::Midpoint).unwrap().len(), 2);
        assert!(s.flatten(0.01).unwrap().len() > 10);
        assert!(s.hull_flatness() > 0.9);
    }
}
