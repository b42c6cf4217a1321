// SPDX-License-Identifier: MIT
//! A tensor-product Bézier patch of at most [`SmallPatch::MAX_POINTS`] control points held on
//! the stack (a bicubic patch's 4 × 4), with the two operations a subdivision search repeats
//! without allocating: the control box (convex hull property, Hardy 2005 §2.5) and the four
//! quarters by de Casteljau at ½ in u and v (§4.3). `hi-raytrace` halves its patches this way
//! for every ray that meets them.

use crate::{Aabb, BezierPatch, ControlPoint};

/// See [`SmallPatch::MAX_POINTS`].
const MAX_POINTS: usize = 16;

/// A Bézier patch of (m + 1) × (n + 1) ≤ [`SmallPatch::MAX_POINTS`] control points, row j (of
/// u) after row j − 1, in a fixed array: copied, split and bounded without allocating.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_bezier::{BezierPatch, ParamRange, ParamWindow, SmallPatch};
///
/// let patch =
///     BezierPatch::try_from_fn(3, 3, |j, k| DVec3::new(j as f64, k as f64, (j * k) as f64)).unwrap();
/// let small = SmallPatch::try_from_patch(&patch).expect("16 points fit");
/// // The first quarter is the patch over [0, ½] × [0, ½].
/// let quarter = small.quarters()[0];
/// let sub = patch.subpatch(ParamWindow::new(ParamRange::new(0.0, 0.5), ParamRange::new(0.0, 0.5)));
/// for (a, b) in quarter.control_points().iter().zip(sub.control_points()) {
///     assert!((*a - *b).length() < 1e-15);
/// }
/// assert_eq!(small.control_bounding_box(), patch.control_bounding_box());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmallPatch<P: ControlPoint> {
    points: [P; MAX_POINTS],
    m: usize,
    n: usize,
}

impl<P: ControlPoint> SmallPatch<P> {
    /// Most control points a small patch holds: a bicubic patch's 4 × 4.
    pub const MAX_POINTS: usize = MAX_POINTS;

    /// The patch `patch` on the stack, if it has at most [`SmallPatch::MAX_POINTS`] control
    /// points (`None` for a larger one).
    #[must_use]
    pub fn try_from_patch(patch: &BezierPatch<P>) -> Option<Self> {
        let p = patch.control_points();
        (p.len() <= Self::MAX_POINTS).then(|| {
            let mut points = [P::ZERO; MAX_POINTS];
            points[..p.len()].copy_from_slice(p);
            Self { points, m: patch.degree_u(), n: patch.degree_v() }
        })
    }

    /// The degree m in u.
    #[must_use]
    pub fn degree_u(&self) -> usize {
        self.m
    }

    /// The degree n in v.
    #[must_use]
    pub fn degree_v(&self) -> usize {
        self.n
    }

    /// The (m + 1)(n + 1) control points, row by row (as [`BezierPatch::control_points`]).
    #[must_use]
    pub fn control_points(&self) -> &[P] {
        &self.points[..(self.m + 1) * (self.n + 1)]
    }

    /// The box of the control points, which holds the patch (convex hull property).
    #[must_use]
    pub fn control_bounding_box(&self) -> Aabb<P> {
        Aabb::of_nonempty(self.control_points())
    }

    /// The four quarters of the patch, split at the middle of u and v by de Casteljau: u low
    /// and v low, u high and v low, u low and v high, u high and v high.
    #[must_use]
    pub fn quarters(&self) -> [Self; 4] {
        let (rows, cols) = (self.m + 1, self.n + 1);
        let empty = Self { points: [P::ZERO; MAX_POINTS], m: self.m, n: self.n };
        // Each row halved in v, then each column of each half halved in u.
        let (mut v_low, mut v_high) = (empty, empty);
        let mut work = [P::ZERO; MAX_POINTS];
        for j in 0..rows {
            let row = &self.points[j * cols..(j + 1) * cols];
            halve(row, &mut work, |i, a, b| {
                v_low.points[j * cols + i] = a;
                v_high.points[j * cols + cols - 1 - i] = b;
            });
        }
        let mut quarter = |half: &Self| {
            let (mut low, mut high) = (empty, empty);
            let mut column = [P::ZERO; MAX_POINTS];
            for k in 0..cols {
                for (j, c) in column[..rows].iter_mut().enumerate() {
                    *c = half.points[j * cols + k];
                }
                halve(&column[..rows], &mut work, |i, a, b| {
                    low.points[i * cols + k] = a;
                    high.points[(rows - 1 - i) * cols + k] = b;
                });
            }
            (low, high)
        };
        let (a, b) = quarter(&v_low);
        let (c, d) = quarter(&v_high);
        [a, b, c, d]
    }
}

/// De Casteljau at ½ on the polygon `c`: calls `out(i, first, last)` with the first and last
/// point after i steps, which are point i of the first half and point i from the end of the
/// second. `work` holds at least `c.len()` points.
fn halve<P: ControlPoint>(c: &[P], work: &mut [P], mut out: impl FnMut(usize, P, P)) {
    let len = c.len();
    work[..len].copy_from_slice(c);
    for i in 0..len {
        out(i, work[0], work[len - 1 - i]);
        for j in 0..len - 1 - i {
            work[j] = (work[j] + work[j + 1]) * 0.5;
        }
    }
}
