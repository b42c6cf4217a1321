// SPDX-License-Identifier: MIT
//! Harmonic surfaces as Bézier patches (Hardy 2005, §5.7; docs/math.md §4), "so that most computer
//! graphics software will be able to import the surface".
//!
//! The schemes are those of curves ([`hi_curve::bezier`]), applied along u and v:
//!
//! - [`BezierScheme::ThesisCubic`]: m×n bicubic patches, `Q[a][b][j][i]` = Σₖ Σₗ `Pᵐ[a][k][j]`·
//!   `Pⁿ[b][l][i]`·xₖₗ (the thesis's formula); C0, through the data points.
//! - [`BezierScheme::ThesisQuintic`]: the same with the degree-5 basis pieces; C2 but not
//!   exactly through the points.
//! - [`BezierScheme::Hermite`]: tensor-product Hermite patches from the surface's own value,
//!   pᵤ, pᵥ and twist pᵤᵥ (bicubic; with the second derivatives too for biquintic) at the
//!   corners; adjacent patches share their edge data, so the result is C1 (C2). The patch grid
//!   starts at the m×n data grid and each direction is halved until the guaranteed bound is
//!   below the tolerance (uniform per direction, so the patches meet edge to edge).
//!
//! # Deviation
//!
//! Measured on every patch at 9×9 parameters (5×5 beyond 2¹⁴ patches) against the surface,
//! and bounded: each scheme but
//! the thesis quintic is a tensor product P = Pᵤ·Pᵥ of one-dimensional interpolation operators,
//! so I − Pᵤ·Pᵥ = (I − Pᵤ) + (I − Pᵥ) − (I − Pᵤ)·(I − Pᵥ) gives
//! ‖p − Pp‖ ≤ c·hᵤʳ·Mᵤ + c·hᵥʳ·Mᵥ + c²·hᵤʳhᵥʳ·Mᵤᵥ, with (c, r) the curve scheme's remainder
//! constant and Mᵤ, Mᵥ, Mᵤᵥ bounds of ‖∂ᵤʳp‖, ‖∂ᵥʳp‖, ‖∂ᵤʳ∂ᵥʳp‖ from the spectrum in interval
//! arithmetic ([`HarmonicSurface::deriv_bound`]). The thesis quintic approximates each σₖ on its
//! own pieces: its bound is (eᵤ(1 + eᵥ) + eᵥ)·Σ‖xₖₗ‖ with eᵤ, eᵥ the basis bounds.
//!
//! The conversion is in `convert`, the measured deviation, the bounds and the normal jumps in
//! `bounds`, the triangle meshes of the patches in `meshing`, the OBJ writer in `obj` and the
//! patch colours in `palette`.
//!
//! [`BezierScheme::ThesisCubic`]: hi_curve::bezier::BezierScheme::ThesisCubic
//! [`BezierScheme::ThesisQuintic`]: hi_curve::bezier::BezierScheme::ThesisQuintic
//! [`BezierScheme::Hermite`]: hi_curve::bezier::BezierScheme::Hermite
//! [`HarmonicSurface::deriv_bound`]: crate::HarmonicSurface::deriv_bound

mod bounds;
mod convert;
mod meshing;
mod obj;
mod palette;

use hi_bezier::{BezierPatch, ControlPoint, ParamRange, ParamWindow};
use hi_curve::bezier::locate;
pub use hi_curve::bezier::{DEFAULT_TOLERANCE, Tolerance};
pub use palette::patch_color;

/// The most patches a conversion makes.
pub const MAX_PATCHES: usize = 1 << 22;

/// Parameters per patch side for the measured deviation (the ends included: this + 1; half as
/// many beyond 2¹⁴ patches).
pub const SAMPLES_PER_SIDE: usize = 8;

/// What a surface conversion achieved (§5.7): patch count, deviation (measured, bounded) and
/// the largest normal-angle jump across patch edges.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PatchReport {
    /// Number of patches.
    pub patches: usize,
    /// Degrees (in u, in v).
    pub degree: (usize, usize),
    /// Largest distance between surface and patches on the sample.
    pub max_deviation: f64,
    /// RMS distance on the sample.
    pub rms_deviation: f64,
    /// A guaranteed upper bound of the distance everywhere (see the module documentation).
    pub bound: f64,
    /// The largest angle between the normals of two patches along their shared edge, radians
    /// (sampled at [`SAMPLES_PER_SIDE`] + 1 points per edge).
    pub max_normal_jump: f64,
}

/// A harmonic surface as Bézier patches: patch (a, b) covers u ∈ [`u_breaks[a]`,
/// `u_breaks[a+1]`], v ∈ [`v_breaks[b]`, `v_breaks[b+1]`], with local parameters in [0, 1].
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(
    feature = "serde",
    serde(bound(
        serialize = "P: ControlPoint + serde::Serialize",
        deserialize = "P: ControlPoint + serde::de::DeserializeOwned"
    ))
)]
pub struct SurfaceBezier<P> {
    /// The patch boundaries in u, from 0 to 1.
    pub u_breaks: Vec<f64>,
    /// The patch boundaries in v, from 0 to 1.
    pub v_breaks: Vec<f64>,
    /// The patches, row-major: index a·(number of v pieces) + b.
    pub patches: Vec<BezierPatch<P>>,
    /// What they achieve.
    pub report: PatchReport,
}

impl<P: ControlPoint> SurfaceBezier<P> {
    /// The patch holding (u, v) (taken modulo 1) and the local parameters.
    #[must_use]
    pub fn locate(&self, u: f64, v: f64) -> (usize, f64, f64) {
        let (a, s) = locate(&self.u_breaks, u);
        let (b, t) = locate(&self.v_breaks, v);
        (a * (self.v_breaks.len() - 1) + b, s, t)
    }

    /// The point of the patches at (u, v).
    #[must_use]
    pub fn eval(&self, u: f64, v: f64) -> P {
        let (i, s, t) = self.locate(u, v);
        self.patches[i].eval(s, t)
    }

    /// The parameter window [u0, u1] × [v0, v1] of patch `index` (row-major).
    ///
    /// # Panics
    ///
    /// If `index` is not less than the number of patches.
    #[must_use]
    pub fn window(&self, index: usize) -> ParamWindow {
        assert!(index < self.patches.len(), "patch {index} of {}", self.patches.len());
        let nv = self.v_breaks.len() - 1;
        let (a, c) = (index / nv, index % nv);
        ParamWindow::new(
            ParamRange::new(self.u_breaks[a], self.u_breaks[a + 1]),
            ParamRange::new(self.v_breaks[c], self.v_breaks[c + 1]),
        )
    }

    /// The indices of the patches whose u-window lies inside `u` (to 1e-12): for a surface that
    /// covers its object twice, such as a fitted spherical geometry image, the patches of one
    /// cover.
    #[must_use]
    pub fn patches_in(&self, u: ParamRange) -> Vec<usize> {
        (0..self.patches.len())
            .filter(|&i| {
                let w = self.window(i).u;
                w.start >= u.start - 1e-12 && w.end <= u.end + 1e-12
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;
    use hi_curve::bezier::{BasisPieces, BezierScheme, HermiteDegree};

    use super::bounds::{angle, uniform_pieces};
    use super::convert::thesis_patches_direct;
    use super::*;
    use crate::HarmonicSurface;

    /// A 3-D grid with no symmetry: m × n points on a bumpy torus.
    fn bumpy(m: usize, n: usize) -> HarmonicSurface<DVec3> {
        let rows = (0..m)
            .map(|j| {
                (0..n)
                    .map(|k| {
                        let (u, v) = (
                            std::f64::consts::TAU * j as f64 / m as f64,
                            std::f64::consts::TAU * k as f64 / n as f64,
                        );
                        let r = 1.0 + 0.3 * (3.0 * u + 1.0).sin() * (2.0 * v).cos();
                        DVec3::new(
                            (3.0 + r * v.cos()) * u.cos(),
                            (3.0 + r * v.cos()) * u.sin(),
                            r * v.sin(),
                        )
                    })
                    .collect()
            })
            .collect();
        HarmonicSurface::new(rows)
    }

    /// The normal jump by evaluating both patches at every edge sample with their partials.
    fn jump_by_evaluation(b: &SurfaceBezier<DVec3>) -> f64 {
        let (nu, nv) = (b.u_breaks.len() - 1, b.v_breaks.len() - 1);
        let patch = |a: usize, c: usize| &b.patches[(a % nu) * nv + (c % nv)];
        let normal = |p: &BezierPatch<DVec3>, s: f64, t: f64| {
            let (_, pu, pv) = p.eval_with_partials(s, t);
            pu.cross(pv).try_normalize()
        };
        let mut worst: f64 = 0.0;
        for a in 0..nu {
            for c in 0..nv {
                for i in 0..=SAMPLES_PER_SIDE {
                    let x = i as f64 / SAMPLES_PER_SIDE as f64;
                    let pairs = [
                        (normal(patch(a, c), 1.0, x), normal(patch(a + 1, c), 0.0, x)),
                        (normal(patch(a, c), x, 1.0), normal(patch(a, c + 1), x, 0.0)),
                    ];
                    for (l, r) in pairs {
                        if let (Some(l), Some(r)) = (l, r) {
                            worst = worst.max(angle(l, r));
                        }
                    }
                }
            }
        }
        worst
    }

    #[test]
    fn edge_normals_from_boundary_rows_match_evaluation() {
        for (m, n) in [(4, 4), (5, 6), (7, 3)] {
            let surface = bumpy(m, n);
            for scheme in [
                BezierScheme::ThesisCubic,
                BezierScheme::ThesisQuintic,
                BezierScheme::Hermite(HermiteDegree::Cubic),
            ] {
                let b = surface.to_bezier(scheme, Tolerance::Absolute(1e-2)).expect("converts");
                let (fast, slow) = (b.report.max_normal_jump, jump_by_evaluation(&b));
                assert!(slow > 0.0 || scheme != BezierScheme::ThesisCubic, "C0 patches jump");
                assert!(
                    (fast - slow).abs() <= 1e-12 * slow.max(1.0),
                    "{m}×{n} {scheme:?}: {fast} against {slow}"
                );
            }
        }
    }

    #[test]
    fn cubic_patches_by_fft_are_the_basis_sums() {
        // Odd and even sizes both ways: the FFT samples against §5.7's sums of basis pieces.
        for (m, n) in [(4, 4), (5, 6), (7, 3), (8, 9)] {
            let surface = bumpy(m, n);
            let fast = surface.thesis_cubic_patches().expect("samples");
            let (bu, bv) = (
                BasisPieces::thesis_cubic(m).expect("m ≥ 2"),
                BasisPieces::thesis_cubic(n).expect("n ≥ 2"),
            );
            let slow = thesis_patches_direct(&surface, &bu, &bv);
            assert_eq!(fast.len(), slow.len(), "{m}×{n}: one patch per cell");
            for (p, q) in fast.iter().zip(&slow) {
                for (x, y) in p.control_points().iter().zip(q.control_points()) {
                    assert!((*x - *y).length() < 1e-12, "{m}×{n}: {x} against {y}");
                }
            }
        }
    }

    #[test]
    fn the_measured_deviation_is_that_of_direct_evaluation() {
        // The report's deviation (FFT samples for uniform breaks) against p(u, v) and the
        // patches evaluated one point at a time.
        let surface = bumpy(5, 6);
        let b = surface.to_bezier(BezierScheme::ThesisCubic, DEFAULT_TOLERANCE).expect("converts");
        let k = SAMPLES_PER_SIDE;
        let nv = b.v_breaks.len() - 1;
        let mut max: f64 = 0.0;
        for (idx, patch) in b.patches.iter().enumerate() {
            let (a, c) = (idx / nv, idx % nv);
            for i in 0..=k {
                for j in 0..=k {
                    let (s, t) = (i as f64 / k as f64, j as f64 / k as f64);
                    let u = b.u_breaks[a] + (b.u_breaks[a + 1] - b.u_breaks[a]) * s;
                    let v = b.v_breaks[c] + (b.v_breaks[c + 1] - b.v_breaks[c]) * t;
                    max = max.max((patch.eval(s, t) - surface.eval(u, v)).length());
                }
            }
        }
        assert!(max > 1e-6, "the cubic scheme deviates");
        assert!(
            (b.report.max_deviation - max).abs() < 1e-12,
            "{} against {max}",
            b.report.max_deviation
        );
    }

    #[test]
    fn uniform_breaks_are_recognised() {
        assert_eq!(uniform_pieces(&[0.0, 0.25, 0.5, 0.75, 1.0]), Some(4), "uniform");
        let third = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];
        assert_eq!(uniform_pieces(&third), Some(3), "thirds, rounded");
        assert_eq!(uniform_pieces(&[0.0, 0.3, 1.0]), None, "uneven");
        assert_eq!(uniform_pieces(&[0.0]), None, "no piece");
    }
}
