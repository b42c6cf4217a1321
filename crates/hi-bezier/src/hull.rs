// SPDX-License-Identifier: MIT
//! Convex hulls and areas of plane polygons: the convex hull property of Bézier curves
//! (Hardy 2005, §2.5 and figure 2.4) made concrete.

use glam::DVec2;

use crate::BezierCurve;

/// The convex hull of plane points, counter-clockwise, starting at the point with the least x
/// (then least y), without repeated or collinear vertices (Andrew's monotone chain,
/// O(m log m)).
///
/// Fewer than three distinct points give those points (one or two); collinear input gives its
/// two extreme points. Non-finite coordinates do not panic but give an unspecified hull.
///
/// # Examples
///
/// ```
/// use glam::DVec2;
/// use hi_bezier::{convex_hull_2d, polygon_area};
///
/// let pts = [
///     DVec2::new(0.0, 0.0),
///     DVec2::new(2.0, 0.0),
///     DVec2::new(1.0, 1.0), // inside
///     DVec2::new(2.0, 2.0),
///     DVec2::new(0.0, 2.0),
///     DVec2::new(1.0, 0.0), // on an edge
/// ];
/// let hull = convex_hull_2d(&pts);
/// assert_eq!(hull, vec![DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::splat(2.0), DVec2::new(0.0, 2.0)]);
/// assert_eq!(polygon_area(&hull), 4.0);
/// ```
#[must_use]
pub fn convex_hull_2d(points: &[DVec2]) -> Vec<DVec2> {
    let mut pts = points.to_vec();
    pts.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let cross = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut hull: Vec<DVec2> = Vec::with_capacity(2 * pts.len());
    // Lower chain, then upper chain; a non-left turn pops the middle point.
    for &p in &pts {
        while hull.len() >= 2 && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0 {
            hull.pop();
        }
        hull.push(p);
    }
    let lower_len = hull.len() + 1;
    for &p in pts.iter().rev().skip(1) {
        while hull.len() >= lower_len && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
        {
            hull.pop();
        }
        hull.push(p);
    }
    hull.pop(); // The first point again.
    hull
}

/// The signed area of a plane polygon by the shoelace formula ½·Σ (xᵢyᵢ₊₁ − xᵢ₊₁yᵢ): positive
/// for counter-clockwise vertices, negative for clockwise, 0 for fewer than three.
#[must_use]
pub fn polygon_area(polygon: &[DVec2]) -> f64 {
    let m = polygon.len();
    if m < 3 {
        return 0.0;
    }
    0.5 * (0..m).map(|i| polygon[i].perp_dot(polygon[(i + 1) % m])).sum::<f64>()
}

impl BezierCurve<DVec2> {
    /// The convex hull of the control polygon (figure 2.4), which holds the curve over
    /// [0, 1]; see [`convex_hull_2d`].
    #[must_use]
    pub fn control_hull(&self) -> Vec<DVec2> {
        convex_hull_2d(self.control_points())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degenerate_inputs() {
        assert!(convex_hull_2d(&[]).is_empty());
        assert_eq!(convex_hull_2d(&[DVec2::ONE, DVec2::ONE]), vec![DVec2::ONE]);
        let line = [DVec2::ZERO, DVec2::splat(2.0), DVec2::ONE, DVec2::splat(3.0)];
        assert_eq!(convex_hull_2d(&line), vec![DVec2::ZERO, DVec2::splat(3.0)]);
        assert_eq!(polygon_area(&[DVec2::ZERO, DVec2::X]), 0.0);
        let nan = [DVec2::NAN, DVec2::ZERO, DVec2::X, DVec2::Y];
        let _ = convex_hull_2d(&nan);
    }

    #[test]
    fn clockwise_area_is_negative() {
        let cw = [DVec2::ZERO, DVec2::Y, DVec2::ONE, DVec2::X];
        assert_eq!(polygon_area(&cw), -1.0);
        let hull = convex_hull_2d(&cw);
        assert_eq!(polygon_area(&hull), 1.0);
    }
}
