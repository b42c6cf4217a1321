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

use std::io::Write;

use glam::{DVec2, DVec3};
use hi_bezier::{Aabb, BezierPatch, ControlPoint, ParamRange, ParamWindow};
use hi_curve::bezier::{BasisPieces, BezierScheme, HermiteDegree, locate};
pub use hi_curve::bezier::{DEFAULT_TOLERANCE, Tolerance};

use hi_mesh::{TriangleMesh, srgb_to_linear};

use crate::{Error, HarmonicSurface};

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

/// A colour for patch `index`: hues spaced by the golden angle so that neighbours differ,
/// saturation and value fixed, as linear RGB.
#[must_use]
pub fn patch_color(index: usize) -> [f32; 3] {
    let hue = (index as f64 * 0.618_033_988_749_895).fract() * 6.0;
    let (s, v) = (0.55, 0.9);
    let c = v * s;
    let x = c * (1.0 - (hue % 2.0 - 1.0).abs());
    let (r, g, b) = match hue as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let m = v - c;
    [r, g, b].map(|k| srgb_to_linear((k + m) as f32))
}

impl SurfaceBezier<DVec3> {
    /// A triangle mesh of the patches: each patch sampled on (k + 1)² parameters (k ≥ 1) with
    /// its own vertices, normals from its partials, UVs the surface parameters, and one colour
    /// per patch ([`patch_color`]), as in figure 5.28(b).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] for k = 0 or a mesh over 2³² vertices.
    pub fn to_triangle_mesh(&self, k: usize) -> Result<TriangleMesh, Error> {
        self.to_triangle_mesh_of(k, &(0..self.patches.len()).collect::<Vec<_>>())
    }

    /// [`SurfaceBezier::to_triangle_mesh`] of the patches `indices` only (see
    /// [`SurfaceBezier::patches_in`]); each keeps the colour of its index.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidCount`] for k = 0, no patches, an index out of range or a mesh over 2³²
    /// vertices.
    pub fn to_triangle_mesh_of(&self, k: usize, indices: &[usize]) -> Result<TriangleMesh, Error> {
        if let Some(&bad) = indices.iter().find(|&&i| i >= self.patches.len()) {
            return Err(Error::InvalidCount {
                what: "patch index",
                value: bad,
                expected: "less than the number of patches",
            });
        }
        let side = k + 1;
        let total = indices.len().saturating_mul(side * side);
        if k == 0 || indices.is_empty() || total >= u32::MAX as usize {
            return Err(Error::InvalidCount {
                what: "samples per patch side",
                value: k,
                expected: "at least 1, at least one patch, and fewer than 2³² vertices in all",
            });
        }
        let nv = self.v_breaks.len() - 1;
        let (mut positions, mut normals, mut uvs, mut colors, mut triangles) = (
            Vec::with_capacity(total),
            Vec::with_capacity(total),
            Vec::with_capacity(total),
            Vec::with_capacity(total),
            Vec::new(),
        );
        for &idx in indices {
            let patch = &self.patches[idx];
            let (a, c) = (idx / nv, idx % nv);
            let (u0, u1) = (self.u_breaks[a], self.u_breaks[a + 1]);
            let (v0, v1) = (self.v_breaks[c], self.v_breaks[c + 1]);
            let base = positions.len() as u32;
            let color = patch_color(idx);
            for i in 0..side {
                let s = i as f64 / k as f64;
                for j in 0..side {
                    let t = j as f64 / k as f64;
                    let (p, pu, pv) = patch.eval_with_partials(s, t);
                    // At a degenerate corner (a pole) step inside for the normal.
                    let n = pu.cross(pv).try_normalize().or_else(|| {
                        let (_, qu, qv) = patch.eval_with_partials(
                            s.clamp(1e-6, 1.0 - 1e-6),
                            t.clamp(1e-6, 1.0 - 1e-6),
                        );
                        qu.cross(qv).try_normalize()
                    });
                    positions.push(p);
                    normals.push(n.unwrap_or(DVec3::Z));
                    uvs.push(DVec2::new(u0 + s * (u1 - u0), v0 + t * (v1 - v0)));
                    colors.push(color);
                }
            }
            for i in 0..k as u32 {
                for j in 0..k as u32 {
                    let at = |i: u32, j: u32| base + i * side as u32 + j;
                    triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                    triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
                }
            }
        }
        Ok(TriangleMesh::try_new(positions, normals, uvs, triangles)?.try_with_colors(colors)?)
    }

    /// Writes the patches as an OBJ free-form surface file: the control points as `v` lines,
    /// then per patch `cstype bezier`, `deg du dv`, `surf 0 1 0 1` with the control-point
    /// indices (u varying fastest, as the OBJ specification orders surface control points),
    /// `parm u 0 1`, `parm v 0 1` and `end`.
    ///
    /// # Errors
    ///
    /// Those of `w`.
    pub fn write_obj<W: Write>(&self, w: W) -> std::io::Result<()> {
        self.write_obj_of(w, &(0..self.patches.len()).collect::<Vec<_>>())
    }

    /// [`SurfaceBezier::write_obj`] of the patches `indices` only.
    ///
    /// # Errors
    ///
    /// Those of `w`.
    ///
    /// # Panics
    ///
    /// If an index is not less than the number of patches.
    pub fn write_obj_of<W: Write>(&self, mut w: W, indices: &[usize]) -> std::io::Result<()> {
        let patches: Vec<&BezierPatch<DVec3>> = indices.iter().map(|&i| &self.patches[i]).collect();
        writeln!(w, "# harmonic surface as {} Bézier patches (Hardy 2005, §5.7)", patches.len())?;
        for patch in &patches {
            let rows = patch.rows();
            for j in 0..rows[0].len() {
                for row in &rows {
                    let p = row[j];
                    writeln!(w, "v {} {} {}", p.x, p.y, p.z)?;
                }
            }
        }
        let mut next = 1_usize;
        for patch in &patches {
            let (du, dv) = (patch.degree_u(), patch.degree_v());
            let count = (du + 1) * (dv + 1);
            writeln!(w, "cstype bezier\ndeg {du} {dv}")?;
            write!(w, "surf 0 1 0 1")?;
            for i in next..next + count {
                write!(w, " {i}")?;
            }
            writeln!(w, "\nparm u 0 1\nparm v 0 1\nend")?;
            next += count;
        }
        w.flush()
    }
}

/// The tensor-product bound of a scheme on a surface (see the module documentation): the
/// scheme's remainder (c, r) and the spectral bounds Mᵤ, Mᵥ, Mᵤᵥ of ‖∂ᵤʳp‖, ‖∂ᵥʳp‖, ‖∂ᵤʳ∂ᵥʳp‖,
/// computed once.
struct TensorBound {
    c: f64,
    r: i32,
    mu: f64,
    mv: f64,
    muv: f64,
}

impl TensorBound {
    fn new<P: ControlPoint>(surface: &HarmonicSurface<P>, scheme: BezierScheme) -> Self {
        let (c, r) = scheme.remainder();
        let (mu, mv, muv) =
            (surface.deriv_bound(r, 0), surface.deriv_bound(0, r), surface.deriv_bound(r, r));
        Self { c, r: r as i32, mu, mv, muv }
    }

    /// On patches of 1/nᵤ × 1/nᵥ: the u term c·hᵤʳ·Mᵤ, the v term, and the whole bound (with a
    /// relative margin of 1e-9 for rounding).
    fn on(&self, nu: usize, nv: usize) -> (f64, f64, f64) {
        let (hu, hv) = ((nu as f64).recip().powi(self.r), (nv as f64).recip().powi(self.r));
        let (eu, ev) = (self.c * hu, self.c * hv);
        let (tu, tv) = (eu * self.mu, ev * self.mv);
        (tu, tv, (tu + tv + eu * ev * self.muv) * (1.0 + 1e-9))
    }
}

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
    fn thesis_cubic_patches(&self) -> Result<Vec<BezierPatch<P>>, Error> {
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

    /// Largest and RMS distance between the surface and the patches on every patch's
    /// (k + 1)² parameters, k = [`SAMPLES_PER_SIDE`] (half that beyond 2¹⁴ patches), the
    /// surface sampled by separable basis matrices.
    fn measure(&self, b: &SurfaceBezier<P>) -> Result<(f64, f64), Error> {
        let k = if b.patches.len() > 1 << 14 { SAMPLES_PER_SIDE / 2 } else { SAMPLES_PER_SIDE };
        let params = |breaks: &[f64]| -> Vec<f64> {
            breaks
                .windows(2)
                .flat_map(|w| (0..=k).map(move |i| w[0] + (w[1] - w[0]) * i as f64 / k as f64))
                .collect()
        };
        let nv = b.v_breaks.len() - 1;
        // Patch (a, c) at (i/k, j/k), from the uniform grid by FFT when the breaks are
        // uniform, else from the separable sums at the parameters themselves.
        let on: Box<dyn Fn(usize, usize, usize, usize) -> P> =
            match (uniform_pieces(&b.u_breaks), uniform_pieces(&b.v_breaks)) {
                (Some(pu), Some(pv)) => {
                    let (ru, rv) = (pu * k, pv * k);
                    let grid = self.sample_uniform(ru, rv, 0, 0)?;
                    Box::new(move |a, c, i, j| {
                        grid.values[((a * k + i) % ru) * rv + (c * k + j) % rv]
                    })
                }
                _ => {
                    let (us, vs) = (params(&b.u_breaks), params(&b.v_breaks));
                    let samples = self.sample_params(&us, &vs, 0, 0)?;
                    Box::new(move |a, c, i, j| samples.get(a * (k + 1) + i, c * (k + 1) + j))
                }
            };
        let (mut max, mut sum, mut count) = (0.0_f64, 0.0, 0_usize);
        let local: Vec<f64> = (0..=k).map(|i| i as f64 / k as f64).collect();
        for (idx, patch) in b.patches.iter().enumerate() {
            let (a, c) = (idx / nv, idx % nv);
            let values = patch.eval_grid(&local, &local);
            for i in 0..=k {
                for j in 0..=k {
                    let d = (values[i * (k + 1) + j] - on(a, c, i, j)).norm();
                    max = max.max(d);
                    sum += d * d;
                    count += 1;
                }
            }
        }
        Ok((max, (sum / count.max(1) as f64).sqrt()))
    }
}

/// The number of pieces if `breaks` are the uniform 0, 1/p, …, 1 (to rounding), else `None`.
fn uniform_pieces(breaks: &[f64]) -> Option<usize> {
    let p = breaks.len().checked_sub(1).filter(|&p| p > 0)?;
    breaks
        .iter()
        .enumerate()
        .all(|(i, &x)| (x - i as f64 / p as f64).abs() <= 4.0 * f64::EPSILON)
        .then_some(p)
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
fn thesis_patches_direct<P: ControlPoint>(
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

/// The angle between unit vectors, accurate near 0.
fn angle(a: DVec3, b: DVec3) -> f64 {
    2.0 * (a - b).length().atan2((a + b).length())
}

/// The largest normal jump across the edges between neighbouring patches (both directions,
/// wrapping around), sampled at `SAMPLES_PER_SIDE + 1` points per edge; 0 for points that are
/// not 3-D.
///
/// On an edge u = 0 or 1 a patch's partials are curves of its boundary rows: ∂p/∂v is the
/// derivative of the boundary row and ∂p/∂u is m times the difference of the last two rows
/// (§4.3), so the normals along every edge come from Bernstein tables at the sample points
/// shared by all patches of one degree.
fn max_normal_jump<P: ControlPoint>(b: &SurfaceBezier<P>) -> f64 {
    if P::DIM != 3 {
        return 0.0;
    }
    let (nu, nv) = (b.u_breaks.len() - 1, b.v_breaks.len() - 1);
    let patch = |a: usize, c: usize| &b.patches[(a % nu) * nv + (c % nv)];
    let mut worst: f64 = 0.0;
    let mut tables = EdgeTables::default();
    for a in 0..nu {
        for c in 0..nv {
            let here = patch(a, c);
            // The edge u = end of patch a, between (a, c) and (a + 1, c).
            let (l, r) =
                (tables.normals(here, Edge::UEnd), tables.normals(patch(a + 1, c), Edge::UStart));
            // The edge v = end of patch c, between (a, c) and (a, c + 1).
            let (lv, rv) =
                (tables.normals(here, Edge::VEnd), tables.normals(patch(a, c + 1), Edge::VStart));
            for (x, y) in l.iter().zip(&r).chain(lv.iter().zip(&rv)) {
                if let (Some(x), Some(y)) = (x, y) {
                    worst = worst.max(angle(*x, *y));
                }
            }
        }
    }
    worst
}

/// A side of a patch's parameter square.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Edge {
    /// u = 0.
    UStart,
    /// u = 1.
    UEnd,
    /// v = 0.
    VStart,
    /// v = 1.
    VEnd,
}

/// Bernstein values and first derivatives at the edge samples i/`SAMPLES_PER_SIDE`, by degree.
#[derive(Default)]
struct EdgeTables {
    by_degree: Vec<DegreeTable>,
}

/// The tables of one degree.
struct DegreeTable {
    degree: usize,
    /// `values[sample][i]`: Bᵢ at the sample.
    values: Vec<Vec<f64>>,
    /// `derivs[sample][i]`: Bᵢ′ at the sample.
    derivs: Vec<Vec<f64>>,
}

impl EdgeTables {
    /// The tables of `degree`, made on first use.
    fn get(&mut self, degree: usize) -> (&[Vec<f64>], &[Vec<f64>]) {
        let at = match self.by_degree.iter().position(|t| t.degree == degree) {
            Some(at) => at,
            None => {
                let basis = hi_bezier::Bernstein::new(degree);
                let xs = (0..=SAMPLES_PER_SIDE).map(|i| i as f64 / SAMPLES_PER_SIDE as f64);
                let values = xs.clone().map(|x| basis.values(x)).collect();
                let derivs = xs.map(|x| basis.derivs(x, 1)).collect();
                self.by_degree.push(DegreeTable { degree, values, derivs });
                self.by_degree.len() - 1
            }
        };
        let table = &self.by_degree[at];
        (&table.values, &table.derivs)
    }

    /// The unit normals pᵤ × pᵥ along `edge` of `patch` at the samples (`None` where the
    /// partials are parallel).
    fn normals<P: ControlPoint>(
        &mut self,
        patch: &BezierPatch<P>,
        edge: Edge,
    ) -> Vec<Option<DVec3>> {
        let (du, dv) = (patch.degree_u(), patch.degree_v());
        let x = |j: usize, k: usize| {
            let p = patch.control_point(j, k).unwrap_or(P::ZERO);
            DVec3::new(p.coord(0), p.coord(1), p.coord(2))
        };
        // The boundary line and its neighbour inside, with the degree across the edge and the
        // sign that makes the difference a derivative in increasing parameter.
        let (along, line, inner, across, sign): (usize, Vec<DVec3>, Vec<DVec3>, usize, f64) =
            match edge {
                Edge::UStart => (
                    dv,
                    (0..=dv).map(|k| x(0, k)).collect(),
                    (0..=dv).map(|k| x(1.min(du), k)).collect(),
                    du,
                    -1.0,
                ),
                Edge::UEnd => (
                    dv,
                    (0..=dv).map(|k| x(du, k)).collect(),
                    (0..=dv).map(|k| x(du.saturating_sub(1), k)).collect(),
                    du,
                    1.0,
                ),
                Edge::VStart => (
                    du,
                    (0..=du).map(|j| x(j, 0)).collect(),
                    (0..=du).map(|j| x(j, 1.min(dv))).collect(),
                    dv,
                    -1.0,
                ),
                Edge::VEnd => (
                    du,
                    (0..=du).map(|j| x(j, dv)).collect(),
                    (0..=du).map(|j| x(j, dv.saturating_sub(1))).collect(),
                    dv,
                    1.0,
                ),
            };
        let (values, derivs) = self.get(along);
        values
            .iter()
            .zip(derivs)
            .map(|(w, dw)| {
                // The derivative along the edge, and the one across it.
                let d_along = line.iter().zip(dw).fold(DVec3::ZERO, |acc, (p, w)| acc + *p * *w);
                let d_across = line
                    .iter()
                    .zip(&inner)
                    .zip(w)
                    .fold(DVec3::ZERO, |acc, ((p, q), w)| acc + (*p - *q) * *w)
                    * (sign * across as f64);
                let (pu, pv) = match edge {
                    Edge::UStart | Edge::UEnd => (d_across, d_along),
                    Edge::VStart | Edge::VEnd => (d_along, d_across),
                };
                pu.cross(pv).try_normalize()
            })
            .collect()
    }
}

/// The diagonal of the bounding box of `points` (0 for none).
fn bounding_diagonal<P: ControlPoint>(points: &[P]) -> f64 {
    Aabb::from_points(points).map_or(0.0, |b| b.size().norm())
}

#[cfg(test)]
mod tests {
    use super::*;

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
