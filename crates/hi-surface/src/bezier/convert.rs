// SPDX-License-Identifier: MIT
//! The conversion of a harmonic surface to Bézier patches by each scheme (§5.7).

use hi_bezier::{BezierPatch, ControlPoint};
use hi_curve::bezier::{BasisPieces, BezierScheme, HermiteDegree};

use super::bounds::{TensorBound, bounding_diagonal, max_normal_jump};
use super::{DEFAULT_TOLERANCE, MAX_PATCHES, PatchReport, SurfaceBezier, Tolerance};
use crate::{Error, HarmonicSurface};

/// Weights of the one-dimensional Hermite control points on a piece of width h: control point
/// i is Σ over d of `w[i][d]`·f⁽ᵈ⁾(end), the end being the left one for i < (degree + 1)/2.
fn hermite_weights(degree: HermiteDegree, h: f64) -> Vec<Vec<f64>> {
    match degree {
        HermiteDegree::Cubic => {
            vec![vec![1.0, 0.0], vec![1.0, h / 3.0], vec![1.0, -h / 3.0], vec![1.0, 0.0]]
        }
        HermiteDegree::Quintic => vec![
            vec![1.0, 0.0, 0.0],
            vec![1.0, h / 5.0, 0.0],
            vec![1.0, 2.0 * h / 5.0, h * h / 20.0],
            vec![1.0, -2.0 * h / 5.0, h * h / 20.0],
            vec![1.0, -h / 5.0, 0.0],
            vec![1.0, 0.0, 0.0],
        ],
    }
}

impl<P: ControlPoint> HarmonicSurface<P> {
    /// The surface as Bézier patches by `scheme` (§5.7), with the deviation measured and
    /// bounded. `tolerance` is the deviation the Hermite scheme may leave, absolute or relative
    /// to the diagonal of the grid's bounding box ([`DEFAULT_TOLERANCE`]: 10⁻⁴ of it); the
    /// thesis schemes only report theirs.
    ///
    /// # Errors
    ///
    /// [`Error::NonFiniteParameter`] or [`Error::InvalidValue`] for a tolerance that is not
    /// finite and positive; [`Error::Curve`] for the thesis quintic with m or n ≤ 2;
    /// [`Error::InvalidCount`] if more than [`MAX_PATCHES`] patches would be needed.
    ///
    /// # Examples
    ///
    /// ```
    /// use hi_curve::bezier::{BezierScheme, DEFAULT_TOLERANCE, HermiteDegree, Tolerance};
    ///
    /// let torus = hi_surface::torus(2.0, 1.0);
    /// // The thesis: 16 bicubic patches for the 4×4 torus, through the 16 points.
    /// let thesis = torus.to_bezier(BezierScheme::ThesisCubic, DEFAULT_TOLERANCE)?;
    /// assert_eq!(thesis.report.patches, 16);
    /// assert!((thesis.eval(0.25, 0.5) - torus.point(1, 2)).length() < 1e-14);
    /// // C1 Hermite patches within 1e-3.
    /// let cubic = BezierScheme::Hermite(HermiteDegree::Cubic);
    /// let c1 = torus.to_bezier(cubic, Tolerance::Absolute(1e-3))?;
    /// assert!(c1.report.bound <= 1e-3 && c1.report.max_normal_jump < 1e-6);
    /// # Ok::<(), hi_surface::Error>(())
    /// ```
    pub fn to_bezier(
        &self,
        scheme: BezierScheme,
        tolerance: Tolerance,
    ) -> Result<SurfaceBezier<P>, Error> {
        let value = tolerance.value();
        if !value.is_finite() {
            return Err(Error::NonFiniteParameter { name: "tolerance", value });
        }
        let Some(tolerance) = tolerance.distance(bounding_diagonal(self.points())) else {
            return Err(Error::InvalidValue {
                what: "tolerance",
                index: None,
                value,
                expected: "a positive number",
            });
        };
        let (u_breaks, v_breaks, patches, bound) = match scheme {
            BezierScheme::Hermite(degree) => self.hermite(degree, tolerance)?,
            _ => self.thesis(scheme)?,
        };
        let mut out = SurfaceBezier {
            u_breaks,
            v_breaks,
            patches,
            report: PatchReport {
                patches: 0,
                degree: (0, 0),
                max_deviation: 0.0,
                rms_deviation: 0.0,
                bound,
                max_normal_jump: 0.0,
            },
        };
        let (max, rms) = self.measure(&out)?;
        out.report = PatchReport {
            patches: out.patches.len(),
            degree: (out.patches[0].degree_u(), out.patches[0].degree_v()),
            max_deviation: max,
            rms_deviation: rms,
            bound,
            max_normal_jump: max_normal_jump(&out),
        };
        Ok(out)
    }

    /// The thesis's patches: both directions' basis pieces applied to the grid.
    #[allow(clippy::type_complexity, reason = "a private tuple of the conversion's parts")]
    fn thesis(
        &self,
        scheme: BezierScheme,
    ) -> Result<(Vec<f64>, Vec<f64>, Vec<BezierPatch<P>>, f64), Error> {
        let pieces = |k: usize| match scheme {
            BezierScheme::ThesisQuintic => BasisPieces::thesis_quintic(k),
            _ => BasisPieces::thesis_cubic(k),
        };
        let (bu, bv) = (pieces(self.m())?, pieces(self.n())?);
        let patches = if scheme == BezierScheme::ThesisCubic {
            self.thesis_cubic_patches()?
        } else {
            thesis_patches_direct(self, &bu, &bv)
        };
        let bound = if scheme == BezierScheme::ThesisCubic {
            TensorBound::new(self, scheme).on(self.m(), self.n()).2
        } else {
            // Basis bounds of σ on its own pieces, from the curve conversion of one σ.
            let basis = |k: usize| -> Result<f64, Error> {
                let delta: Vec<f64> = (0..k).map(|i| f64::from(u8::from(i == 0))).collect();
                let c = hi_curve::HarmonicCurve::try_new(delta)?;
                Ok(c.to_bezier(BezierScheme::ThesisQuintic, DEFAULT_TOLERANCE)?.report.bound)
            };
            let (eu, ev) = (basis(self.m())?, basis(self.n())?);
            let size: f64 = self.points().iter().map(|x| x.norm()).sum();
            (eu * (1.0 + ev) + ev) * size * (1.0 + 1e-9)
        };
        Ok((bu.breaks().to_vec(), bv.breaks().to_vec(), patches, bound))
    }

    /// The thesis's cubic patches from the surface itself (docs/math.md §4): patch (a, b)
    /// interpolates p at the 4×4 points (a/m + r/(3m), b/n + s/(3n)), r, s = 0 … 3, so its
    /// control points are B⁻¹·S·B⁻ᵀ with S those samples and B the cubic Bernstein matrix at
    /// 0, ⅓, ⅔, 1. The samples are the uniform 3m × 3n grid, taken by FFT: O(mn log mn)
    /// instead of the O(mn(m + n)) sums of the basis pieces, with the same patches up to
    /// rounding.
    pub(super) fn thesis_cubic_patches(&self) -> Result<Vec<BezierPatch<P>>, Error> {
        let (m, n) = (self.m(), self.n());
        let grid = self.sample_uniform(3 * m, 3 * n, 0, 0)?;
        // At the grid's own nodes the surface is the data: taken exactly, so the patches pass
        // through the points bit for bit as the basis sums do.
        let at = |r: usize, s: usize| {
            let (r, s) = (r % (3 * m), s % (3 * n));
            if r % 3 == 0 && s % 3 == 0 {
                self.point(r / 3, s / 3)
            } else {
                grid.values[r * (3 * n) + s]
            }
        };
        let inverse = cubic_interpolation_inverse();
        let mut patches = Vec::with_capacity(m * n);
        for a in 0..m {
            for b in 0..n {
                // T = B⁻¹·S (along u), then T·B⁻ᵀ (along v).
                let mut t = [[P::ZERO; 4]; 4];
                for (j, row) in t.iter_mut().enumerate() {
                    for (s, slot) in row.iter_mut().enumerate() {
                        *slot = (0..4)
                            .fold(P::ZERO, |acc, r| acc + at(3 * a + r, 3 * b + s) * inverse[j][r]);
                    }
                }
                let control: Vec<Vec<P>> = t
                    .iter()
                    .map(|row| {
                        (0..4)
                            .map(|i| (0..4).fold(P::ZERO, |acc, s| acc + row[s] * inverse[i][s]))
                            .collect()
                    })
                    .collect();
                patches.push(BezierPatch::new(control));
            }
        }
        Ok(patches)
    }

    /// Hermite patches on the data grid refined per direction until the bound is met.
    #[allow(clippy::type_complexity, reason = "a private tuple of the conversion's parts")]
    fn hermite(
        &self,
        degree: HermiteDegree,
        tolerance: f64,
    ) -> Result<(Vec<f64>, Vec<f64>, Vec<BezierPatch<P>>, f64), Error> {
        let tensor = TensorBound::new(self, BezierScheme::Hermite(degree));
        let (mut nu, mut nv) = (self.m(), self.n());
        let (mut eu, mut ev, mut bound) = tensor.on(nu, nv);
        while bound > tolerance {
            if nu.saturating_mul(nv).saturating_mul(2) > MAX_PATCHES {
                return Err(Error::InvalidCount {
                    what: "Bézier patches needed for the tolerance",
                    value: MAX_PATCHES,
                    expected: "a larger tolerance (the limit of patches was reached)",
                });
            }
            // Halve the direction whose term is larger.
            if eu >= ev {
                nu *= 2;
            } else {
                nv *= 2;
            }
            (eu, ev, bound) = tensor.on(nu, nv);
        }
        let u_breaks: Vec<f64> = (0..=nu).map(|a| a as f64 / nu as f64).collect();
        let v_breaks: Vec<f64> = (0..=nv).map(|b| b as f64 / nv as f64).collect();
        let orders = match degree {
            HermiteDegree::Cubic => 2,
            HermiteDegree::Quintic => 3,
        };
        // Corner data: ∂ᵤᵈ∂ᵥᵉp at every grid vertex, d, e < orders, by separable sampling.
        let mut grids = Vec::with_capacity(orders * orders);
        for d in 0..orders {
            for e in 0..orders {
                grids.push(self.sample_params(&u_breaks, &v_breaks, d, e)?);
            }
        }
        let data = |a: usize, b: usize, d: usize, e: usize| grids[d * orders + e].get(a, b);
        let (wu, wv) =
            (hermite_weights(degree, 1.0 / nu as f64), hermite_weights(degree, 1.0 / nv as f64));
        let half = wu.len() / 2;
        let mut patches = Vec::with_capacity(nu * nv);
        for a in 0..nu {
            for b in 0..nv {
                let control: Vec<Vec<P>> = (0..wu.len())
                    .map(|i| {
                        (0..wv.len())
                            .map(|j| {
                                let ca = if i < half { a } else { a + 1 };
                                let cb = if j < half { b } else { b + 1 };
                                let mut sum = P::ZERO;
                                for (du, &x) in wu[i].iter().enumerate() {
                                    for (dv, &y) in wv[j].iter().enumerate() {
                                        if x != 0.0 && y != 0.0 {
                                            sum += data(ca, cb, du, dv) * (x * y);
                                        }
                                    }
                                }
                                sum
                            })
                            .collect()
                    })
                    .collect();
                patches.push(BezierPatch::new(control));
            }
        }
        Ok((u_breaks, v_breaks, patches, bound))
    }
}

/// The inverse of the cubic Bernstein matrix at 0, ⅓, ⅔, 1, `Bᵢⱼ = B³ⱼ(i/3)`: the control
/// values of the cubic through four equally spaced values.
fn cubic_interpolation_inverse() -> [[f64; 4]; 4] {
    // From the Bernstein forms: c₀ = f₀, c₃ = f₃, and the middle two solve the 2×2 system of
    // the inner samples.
    [
        [1.0, 0.0, 0.0, 0.0],
        [-5.0 / 6.0, 3.0, -1.5, 1.0 / 3.0],
        [1.0 / 3.0, -1.5, 3.0, -5.0 / 6.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

/// Patches from the basis pieces of both directions applied to the grid (§5.7):
/// `Q[a][b][j][i] = Σₖ Σₗ Pᵤ[a][k][j]·Pᵥ[b][l][i]·xₖₗ`, along v first.
pub(super) fn thesis_patches_direct<P: ControlPoint>(
    surface: &HarmonicSurface<P>,
    bu: &BasisPieces,
    bv: &BasisPieces,
) -> Vec<BezierPatch<P>> {
    let (m, n) = (surface.m(), surface.n());
    let (du, dv) = (bu.degree(), bv.degree());
    let (pu, pv) = (bu.n_pieces(), bv.n_pieces());
    // rows[k][b][i] = Σₗ P[b][l][i]·xₖₗ.
    let mut rows = vec![P::ZERO; m * pv * (dv + 1)];
    for b in 0..pv {
        let weights: Vec<&[f64]> = (0..n).map(|l| bv.control(b, l)).collect();
        for k in 0..m {
            for i in 0..=dv {
                let sum = (0..n).fold(P::ZERO, |acc, l| acc + surface.point(k, l) * weights[l][i]);
                rows[(k * pv + b) * (dv + 1) + i] = sum;
            }
        }
    }
    let mut patches = Vec::with_capacity(pu * pv);
    for a in 0..pu {
        let weights: Vec<&[f64]> = (0..m).map(|k| bu.control(a, k)).collect();
        for b in 0..pv {
            let control: Vec<Vec<P>> = (0..=du)
                .map(|j| {
                    (0..=dv)
                        .map(|i| {
                            (0..m).fold(P::ZERO, |acc, k| {
                                acc + rows[(k * pv + b) * (dv + 1) + i] * weights[k][j]
                            })
                        })
                        .collect()
                })
                .collect();
            patches.push(BezierPatch::new(control));
        }
    }
    patches
}
