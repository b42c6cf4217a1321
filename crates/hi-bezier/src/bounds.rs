// SPDX-License-Identifier: MIT
//! Axis-aligned bounding boxes ([`Aabb`]) of points and of Bézier curves: the control-polygon
//! box (convex hull property, Hardy 2005 §2.5) and the tight box from the extrema of each
//! coordinate (roots of the hodograph, eq. 2.3).

use crate::{BezierCurve, ControlPoint};

/// An axis-aligned box {x : minᵢ ≤ xᵢ ≤ maxᵢ for every coordinate i}.
///
/// The fields are public because any pair is a box; boxes built by this crate always have
/// `min` ≤ `max` in every coordinate.
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_bezier::Aabb;
///
/// let b = Aabb::from_points(&[DVec2::new(1.0, 5.0), DVec2::new(-2.0, 3.0)]).unwrap();
/// assert_eq!(b.min, DVec2::new(-2.0, 3.0));
/// assert_eq!(b.max, DVec2::new(1.0, 5.0));
/// assert!(b.contains(DVec2::new(0.0, 4.0)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Aabb<P> {
    /// The corner with the smallest coordinates.
    pub min: P,
    /// The corner with the largest coordinates.
    pub max: P,
}

impl<P: ControlPoint> Aabb<P> {
    /// The box holding exactly one point.
    #[must_use]
    pub fn from_point(p: P) -> Self {
        Self { min: p, max: p }
    }

    /// The smallest box holding all `points`; `None` for no points.
    #[must_use]
    pub fn from_points(points: &[P]) -> Option<Self> {
        let (first, rest) = points.split_first()?;
        let mut res = Self::from_point(*first);
        for p in rest {
            res = res.including(*p);
        }
        Some(res)
    }

    /// The smallest box holding the points of a non-empty slice.
    pub(crate) fn of_nonempty(points: &[P]) -> Self {
        points[1..].iter().fold(Self::from_point(points[0]), |b, p| b.including(*p))
    }

    /// The smallest box holding `self` and `p`.
    #[must_use]
    pub fn including(self, p: P) -> Self {
        Self {
            min: P::from_coords(|i| self.min.coord(i).min(p.coord(i))),
            max: P::from_coords(|i| self.max.coord(i).max(p.coord(i))),
        }
    }

    /// The smallest box holding both boxes.
    #[must_use]
    pub fn union(self, other: Self) -> Self {
        self.including(other.min).including(other.max)
    }

    /// True if `p` lies in the box (boundary included).
    #[must_use]
    pub fn contains(&self, p: P) -> bool {
        (0..P::DIM).all(|i| self.min.coord(i) <= p.coord(i) && p.coord(i) <= self.max.coord(i))
    }

    /// True if every point of `other` lies in `self` enlarged by `margin` on every side.
    #[must_use]
    pub fn contains_box(&self, other: &Self, margin: f64) -> bool {
        (0..P::DIM).all(|i| {
            self.min.coord(i) - margin <= other.min.coord(i)
                && other.max.coord(i) <= self.max.coord(i) + margin
        })
    }

    /// The edge lengths, max − min.
    #[must_use]
    pub fn size(&self) -> P {
        self.max - self.min
    }

    /// The centre, (min + max)/2.
    #[must_use]
    pub fn center(&self) -> P {
        (self.min + self.max) * 0.5
    }
}

impl<P: ControlPoint> BezierCurve<P> {
    /// The box of the control points: it holds the whole curve over [0, 1] by the convex hull
    /// property, but is usually larger than the curve's own box.
    #[must_use]
    pub fn control_bounding_box(&self) -> Aabb<P> {
        Aabb::of_nonempty(self.control_points())
    }

    /// The tight box of the curve over t ∈ [0, 1], for every degree.
    ///
    /// Method: each coordinate is extreme at t = 0, t = 1 or a root of that coordinate of the
    /// hodograph q′ (eq. 2.3), a polynomial of degree n − 1 in Bernstein form; the roots are
    /// isolated by subdivision and refined by a bracketed secant iteration
    /// ([`BezierCurve::roots`]). The box is the box of the curve points at those parameters, so
    /// it is exact up to the rounding of the roots and of de Casteljau's evaluation (a few ulps
    /// of the coordinates); there is no tolerance to choose.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec2;
    /// use hi_bezier::BezierCurve;
    ///
    /// // y(t) = 2t(1 − t) peaks at t = ½ with y = ½; the control box reaches y = 1.
    /// let c = BezierCurve::new(vec![DVec2::ZERO, DVec2::new(1.0, 1.0), DVec2::new(2.0, 0.0)]);
    /// let tight = c.bounding_box();
    /// assert!((tight.max.y - 0.5).abs() < 1e-15);
    /// assert_eq!(c.control_bounding_box().max.y, 1.0);
    /// ```
    #[must_use]
    pub fn bounding_box(&self) -> Aabb<P> {
        let control = self.control_points();
        let n = control.len() - 1;
        let mut res = Aabb::from_point(control[0]).including(control[n]);
        if n < 2 {
            return res;
        }
        let hodograph = self.deriv();
        for coord in 0..P::DIM {
            let component: Vec<f64> =
                hodograph.control_points().iter().map(|p| p.coord(coord)).collect();
            for t in BezierCurve::from_vec_unchecked(component).roots() {
                res = res.including(self.eval(t));
            }
        }
        res
    }
}

/// The largest value over [0, 1]² of the scalar tensor-product Bézier patch with coefficients
/// `grid` (row-major, `n_rows` × `n_cols`), to within `accuracy` from above: returns m with
/// max ≤ m ≤ max + `accuracy`, found by branch and bound on the convex hull property.
///
/// A subpatch's corner coefficients are values of the patch (lower bounds of the maximum) and
/// its largest coefficient is an upper bound; subpatches whose upper bound is within
/// `accuracy` of the best value seen are settled, the others are split in four.
pub(crate) fn grid_max(grid: &[f64], n_rows: usize, n_cols: usize, accuracy: f64) -> f64 {
    let corners = |g: &[f64]| {
        g[0].max(g[n_cols - 1]).max(g[(n_rows - 1) * n_cols]).max(g[n_rows * n_cols - 1])
    };
    let mut best = corners(grid);
    let mut settled = best;
    let mut stack = vec![(grid.to_vec(), 0u32)];
    while let Some((g, depth)) = stack.pop() {
        let upper = g.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if upper <= best + accuracy || depth >= 40 {
            settled = settled.max(upper);
            continue;
        }
        let mut pieces = Vec::with_capacity(4);
        for half in split_grid_rows(&g, n_rows, n_cols) {
            let (a, b) = split_grid_cols(&half, n_rows, n_cols);
            pieces.push(a);
            pieces.push(b);
        }
        for piece in pieces {
            best = best.max(corners(&piece));
            stack.push((piece, depth + 1));
        }
    }
    settled.max(best)
}

/// Splits a scalar grid at ½ along the row index (the first parameter).
fn split_grid_rows(g: &[f64], n_rows: usize, n_cols: usize) -> [Vec<f64>; 2] {
    let mut a = vec![0.0; g.len()];
    let mut b = vec![0.0; g.len()];
    let mut column = vec![0.0; n_rows];
    for j in 0..n_cols {
        for i in 0..n_rows {
            column[i] = g[i * n_cols + j];
        }
        let (left, right) = crate::subdivide::split_points(&column, 0.5);
        for i in 0..n_rows {
            a[i * n_cols + j] = left[i];
            b[i * n_cols + j] = right[i];
        }
    }
    [a, b]
}

/// Splits a scalar grid at ½ along the column index (the second parameter).
fn split_grid_cols(g: &[f64], n_rows: usize, n_cols: usize) -> (Vec<f64>, Vec<f64>) {
    let mut a = Vec::with_capacity(g.len());
    let mut b = Vec::with_capacity(g.len());
    for i in 0..n_rows {
        let (left, right) = crate::subdivide::split_points(&g[i * n_cols..(i + 1) * n_cols], 0.5);
        a.extend(left);
        b.extend(right);
    }
    (a, b)
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;

    #[test]
    fn box_operations() {
        let a = Aabb::from_point(DVec3::ZERO);
        let b = Aabb::from_point(DVec3::ONE);
        let u = a.union(b);
        assert_eq!(u.size(), DVec3::ONE);
        assert_eq!(u.center(), DVec3::splat(0.5));
        assert!(u.contains_box(&a, 0.0));
        assert!(!a.contains_box(&u, 0.5));
        assert!(a.contains_box(&u, 1.0));
        assert_eq!(Aabb::<f64>::from_points(&[]), None);
    }

    #[test]
    fn scalar_grid_maximum() {
        // f(u, v) = 4u(1 − u)·4v(1 − v): coefficients of 2u(1 − u) are [0, 1, 0]·... max is 1.
        let row = [0.0, 2.0, 0.0];
        let grid: Vec<f64> = row.iter().flat_map(|a| row.iter().map(move |b| a * b)).collect();
        let m = grid_max(&grid, 3, 3, 1e-9);
        assert!((1.0..=1.0 + 1e-9).contains(&m), "{m}");
    }
}
