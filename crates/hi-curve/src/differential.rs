// SPDX-License-Identifier: MIT
//! Differential geometry of parametric curves: curvature, torsion, Frenet frame, arc length
//! (Hardy 2005, §2.15).
//!
//! κ = |X′ × X″| / |X′|³ (in any dimension, |X′ × X″|² = |X′|²|X″|² − (X′·X″)²),
//! signed in the plane as κ = (x′y″ − y′x″)/|X′|³, and τ = (X′ × X″)·X‴ / |X′ × X″|² in space.

use glam::{DVec2, DVec3};

use crate::ControlPoint;

/// Relative size below which |X′| counts as zero (a cusp or a stationary point).
const SINGULAR: f64 = 1e-12;

/// Nodes and weights of 8-point Gauss–Legendre quadrature on [−1, 1].
const GAUSS_8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// A curve t ↦ X(t), t ∈ [0, 1], with derivatives of every order: what curvature, torsion,
/// Frenet frames, arc length and fairness measures need. Implemented by every curve type of
/// this crate, so comparisons can be generic.
pub trait ParamCurve<P: ControlPoint> {
    /// X(t).
    fn eval(&self, t: f64) -> P;

    /// True if the curve is closed and 1-periodic (X(t + 1) = X(t)); false for an open curve
    /// from X(0) to X(1).
    fn is_periodic(&self) -> bool;

    /// The derivative X⁽ᵖ⁾(t) of order p (p = 0 is X(t)).
    fn eval_deriv(&self, t: f64, order: usize) -> P;

    /// A length typical of the curve (for instance the largest distance of a point from the
    /// centroid); derivatives smaller than 10⁻¹² times it count as zero.
    fn scale(&self) -> f64;

    /// Unsigned curvature κ(t) = |X′ × X″|/|X′|³, in any dimension (0 for 1-D curves).
    ///
    /// Computed as |X″ − (X″·T)T|/|X′|² with T = X′/|X′| (the part of the acceleration normal
    /// to the tangent), which equals |X′ × X″|/|X′|³ without the cancellation of
    /// |X′|²|X″|² − (X′·X″)². `None` where the curve is singular (X′ = 0, a cusp).
    fn curvature(&self, t: f64) -> Option<f64> {
        let d1 = self.eval_deriv(t, 1);
        let d2 = self.eval_deriv(t, 2);
        let speed = d1.norm();
        if is_singular(speed, self.scale()) {
            return None;
        }
        let tangent = d1 * (1.0 / speed);
        let normal_part = d2 - tangent * d2.dot(tangent);
        Some(normal_part.norm() / (speed * speed))
    }

    /// Arc length ∫ |X′(t)| dt from `t0` to `t1` (negative if t1 < t0) by adaptive 8-point
    /// Gauss–Legendre quadrature, to an absolute `accuracy`.
    fn arclen_range(&self, t0: f64, t1: f64, accuracy: f64) -> f64 {
        let speed = |t: f64| self.eval_deriv(t, 1).norm();
        adaptive_gauss(&speed, t0, t1, accuracy.max(f64::EPSILON), 40)
    }
}

fn is_singular(speed: f64, scale: f64) -> bool {
    // Written so that a NaN speed also counts as singular.
    speed.partial_cmp(&(SINGULAR * scale.max(f64::MIN_POSITIVE)))
        != Some(std::cmp::Ordering::Greater)
}

fn gauss(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    half * GAUSS_8.iter().map(|&(x, w)| w * (f(mid - half * x) + f(mid + half * x))).sum::<f64>()
}

fn adaptive_gauss(f: &impl Fn(f64) -> f64, a: f64, b: f64, accuracy: f64, depth: u32) -> f64 {
    let whole = gauss(f, a, b);
    let mid = 0.5 * (a + b);
    let halves = gauss(f, a, mid) + gauss(f, mid, b);
    if depth == 0 || (whole - halves).abs() <= accuracy {
        return halves;
    }
    adaptive_gauss(f, a, mid, 0.5 * accuracy, depth - 1)
        + adaptive_gauss(f, mid, b, 0.5 * accuracy, depth - 1)
}

/// The Frenet frame of a curve at a point: unit tangent, principal normal and (in space)
/// binormal, with curvature and torsion (Hardy 2005, §2.15).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FrenetFrame<P> {
    /// Unit tangent T = X′/|X′|.
    pub tangent: P,
    /// Unit principal normal N. In the plane, T turned a quarter counter-clockwise (so that
    /// dT/ds = κN with the signed κ); in space, the direction of dT/ds.
    pub normal: P,
    /// Unit binormal B = T × N (space curves only; `None` in the plane).
    pub binormal: Option<P>,
    /// Curvature: signed in the plane, non-negative in space.
    pub curvature: f64,
    /// Torsion τ (space curves only; 0 in the plane).
    pub torsion: f64,
}

/// Signed curvature and Frenet frame of plane curves.
pub trait PlaneCurve: ParamCurve<DVec2> {
    /// Signed curvature κ = (x′y″ − y′x″)/|X′|³: positive where the curve turns left
    /// (counter-clockwise). `None` where X′ = 0.
    fn signed_curvature(&self, t: f64) -> Option<f64> {
        let d1 = self.eval_deriv(t, 1);
        let d2 = self.eval_deriv(t, 2);
        let speed = d1.length();
        if is_singular(speed, self.scale()) {
            return None;
        }
        Some(d1.perp_dot(d2) / (speed * speed * speed))
    }

    /// The frame (T, N) with N = T turned by +90°, and the signed curvature. `None` where
    /// X′ = 0.
    fn frenet_frame(&self, t: f64) -> Option<FrenetFrame<DVec2>> {
        let tangent = self.eval_deriv(t, 1).normalize_or_zero();
        let curvature = self.signed_curvature(t)?;
        Some(FrenetFrame {
            tangent,
            normal: tangent.perp(),
            binormal: None,
            curvature,
            torsion: 0.0,
        })
    }
}

impl<C: ParamCurve<DVec2> + ?Sized> PlaneCurve for C {}

/// Torsion and Frenet frame of space curves.
pub trait SpaceCurve: ParamCurve<DVec3> {
    /// Torsion τ = (X′ × X″)·X‴ / |X′ × X″|². `None` where X′ × X″ = 0 (a singular point or an
    /// inflection, where the osculating plane is undefined).
    fn torsion(&self, t: f64) -> Option<f64> {
        let d1 = self.eval_deriv(t, 1);
        let d2 = self.eval_deriv(t, 2);
        let d3 = self.eval_deriv(t, 3);
        let cross = d1.cross(d2);
        let scale = self.scale();
        if is_singular(d1.length(), scale) || is_singular(cross.length(), scale * d1.length()) {
            return None;
        }
        Some(cross.dot(d3) / cross.length_squared())
    }

    /// The frame (T, N, B) with curvature and torsion. `None` where X′ × X″ = 0.
    fn frenet_frame(&self, t: f64) -> Option<FrenetFrame<DVec3>> {
        let d1 = self.eval_deriv(t, 1);
        let d2 = self.eval_deriv(t, 2);
        let tangent = d1.normalize_or_zero();
        let binormal = d1.cross(d2).normalize_or_zero();
        let torsion = self.torsion(t)?;
        let curvature = self.curvature(t)?;
        Some(FrenetFrame {
            tangent,
            normal: binormal.cross(tangent),
            binormal: Some(binormal),
            curvature,
            torsion,
        })
    }
}

impl<C: ParamCurve<DVec3> + ?Sized> SpaceCurve for C {}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// A helix (r cos 2πt, r sin 2πt, h t): κ = r/(r² + c²), τ = c/(r² + c²) with c = h/2π.
    struct Helix {
        r: f64,
        h: f64,
    }

    impl ParamCurve<DVec3> for Helix {
        fn eval(&self, t: f64) -> DVec3 {
            self.eval_deriv(t, 0)
        }
        fn eval_deriv(&self, t: f64, order: usize) -> DVec3 {
            let w = 2.0 * PI;
            let a = w * t + order as f64 * PI / 2.0;
            let lin = match order {
                0 => self.h * t,
                1 => self.h,
                _ => 0.0,
            };
            DVec3::new(
                self.r * w.powi(order as i32) * a.cos(),
                self.r * w.powi(order as i32) * a.sin(),
                lin,
            )
        }
        fn scale(&self) -> f64 {
            self.r
        }
        fn is_periodic(&self) -> bool {
            false
        }
    }

    #[test]
    fn helix_curvature_and_torsion() {
        let helix = Helix { r: 2.0, h: 3.0 };
        let c = 3.0 / (2.0 * PI);
        let frame = helix.frenet_frame(0.3).unwrap();
        assert!((frame.curvature - 2.0 / (4.0 + c * c)).abs() < 1e-14);
        assert!((frame.torsion - c / (4.0 + c * c)).abs() < 1e-14);
        let b = frame.binormal.unwrap();
        assert!(frame.tangent.dot(frame.normal).abs() < 1e-15 && b.dot(frame.normal).abs() < 1e-15);
        // The principal normal of a helix points at its axis.
        let p = helix.eval(0.3);
        assert!(frame.normal.dot(-DVec3::new(p.x, p.y, 0.0).normalize()) > 1.0 - 1e-14);
        // Arc length of one turn: √((2πr)² + h²).
        let len = helix.arclen_range(0.0, 1.0, 1e-12);
        assert!((len - ((4.0 * PI).powi(2) + 9.0f64).sqrt()).abs() < 1e-11, "{len}");
    }
}
