// SPDX-License-Identifier: MIT
//! More points for sparse meshes: the thesis samples "additional points on the polygons" of
//! models with few vertices before building their geometry images (§5.3). Points are spread
//! over the triangles in proportion to their area, deterministically.

use glam::DVec3;

use crate::scan::Scan;

/// The scan's points plus about `target − points` more on its triangles, spread by area
/// (a triangle of area A gets A/total of them, rounding carried over from one triangle to
/// the next) at the points of Roberts' low-discrepancy R₂ sequence folded into the triangle.
/// A scan with no triangles or at least `target` points is returned as its points.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use hi_scan::sampling::densify;
/// use hi_scan::scan::Scan;
///
/// let scan = Scan {
///     points: vec![DVec3::ZERO, DVec3::X, DVec3::Y],
///     triangles: vec![[0, 1, 2]],
///     ..Scan::default()
/// };
/// let points = densify(&scan, 100);
/// assert_eq!(points.len(), 100);
/// assert!(points.iter().all(|p| p.z == 0.0 && p.x >= 0.0 && p.y >= 0.0 && p.x + p.y <= 1.0));
/// ```
#[must_use]
pub fn densify(scan: &Scan, target: usize) -> Vec<DVec3> {
    let mut points = scan.points.clone();
    if scan.triangles.is_empty() || points.len() >= target {
        return points;
    }
    let extra = target - points.len();
    let corners = |t: &[u32; 3]| t.map(|k| scan.points[k as usize]);
    let areas: Vec<f64> = scan
        .triangles
        .iter()
        .map(|t| {
            let [a, b, c] = corners(t);
            0.5 * (b - a).cross(c - a).length()
        })
        .collect();
    let total: f64 = areas.iter().sum();
    if total.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) || !total.is_finite() {
        return points;
    }
    // R₂: the plastic number's powers give well-spread points in the unit square.
    let g = 1.324_717_957_244_746_f64;
    let (a1, a2) = (1.0 / g, 1.0 / (g * g));
    let mut carry = 0.0;
    let mut k = 0u64;
    for (t, area) in scan.triangles.iter().zip(&areas) {
        let want = extra as f64 * area / total + carry;
        let n = want.floor();
        carry = want - n;
        let [a, b, c] = corners(t);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "0 ≤ n ≤ extra"
        )]
        for _ in 0..n as usize {
            k += 1;
            let (mut s, mut r) = ((0.5 + a1 * k as f64).fract(), (0.5 + a2 * k as f64).fract());
            if s + r > 1.0 {
                (s, r) = (1.0 - s, 1.0 - r);
            }
            points.push(a + (b - a) * s + (c - a) * r);
        }
    }
    // Rounding may leave the count one short of the target: add the last triangle's centroid.
    while points.len() < target {
        let Some(t) = scan.triangles.last() else { break };
        points.push(corners(t).iter().sum::<DVec3>() / 3.0);
    }
    points
}
