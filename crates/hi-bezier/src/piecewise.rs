// SPDX-License-Identifier: MIT
//! Piecewise Bézier curves (Hardy 2005, §2.5): segments joined end to end.

use crate::{BezierCurve, ControlPoint, Error};

/// A chain of Bézier segments, traversed for u ∈ [0, 1] with segment i on
/// [i/s, (i+1)/s] (s segments).
///
/// The segments are stored as given; joins are not forced to be continuous (the constructors
/// of joined curves guarantee C0, C1 or G1 themselves).
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

    /// The segment index and local parameter of the global parameter u.
    #[must_use]
    pub fn locate(&self, u: f64) -> (usize, f64) {
        let s = self.segments.len();
        let x = (u * s as f64).clamp(0.0, s as f64);
        let i = (x.floor() as usize).min(s - 1);
        (i, x - i as f64)
    }
}
