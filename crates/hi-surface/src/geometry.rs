// SPDX-License-Identifier: MIT
//! Differential geometry of a harmonic surface in space (Hardy 2005, §4.6; docs/math.md §3):
//! normal, fundamental forms, Gaussian and mean curvature, principal curvatures and directions.
//!
//! With E, F, G = pᵤ·pᵤ, pᵤ·pᵥ, pᵥ·pᵥ and L, M, N = pᵤᵤ·n, pᵤᵥ·n, pᵥᵥ·n for the unit
//! normal n = pᵤ × pᵥ/|pᵤ × pᵥ|:
//! K = (LN − M²)/(EG − F²), H = (EN − 2FM + GL)/(2(EG − F²)), κ₁,₂ = H ± √(H² − K).
//!
//! **Convention.** The thesis labels (EN − 2FM + GL)/(EG − F²) = κ₁ + κ₂ the "mean curvature"
//! (its sphere example gives ±2/r). Here H is the average, and κ₁ + κ₂ = 2H is reported under
//! its own name, [`Curvature::k1_plus_k2`]. Signs follow the normal pᵤ × pᵥ: for the sphere
//! and torus grids of docs/math.md §3 it points outward, so L, N < 0 and H < 0 there (a convex
//! surface with an outward normal has negative mean curvature in this convention).

use glam::DVec3;

use crate::HarmonicSurface;

/// Below this, relative to the size of the surface, |pᵤ × pᵥ| counts as zero: a pole or a
/// crease where the normal is undefined.
const DEGENERATE: f64 = 1e-10;

/// The surface point and its first and second partial derivatives.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SurfaceDerivs {
    /// p(u, v).
    pub p: DVec3,
    /// ∂p/∂u.
    pub pu: DVec3,
    /// ∂p/∂v.
    pub pv: DVec3,
    /// ∂²p/∂u².
    pub puu: DVec3,
    /// ∂²p/∂u∂v.
    pub puv: DVec3,
    /// ∂²p/∂v².
    pub pvv: DVec3,
}

/// The first (E, F, G) and second (L, M, N) fundamental forms at a point (§4.6).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FundamentalForms {
    /// E = pᵤ·pᵤ.
    pub e: f64,
    /// F = pᵤ·pᵥ.
    pub f: f64,
    /// G = pᵥ·pᵥ.
    pub g: f64,
    /// L = pᵤᵤ·n.
    pub l: f64,
    /// M = pᵤᵥ·n.
    pub m: f64,
    /// N = pᵥᵥ·n.
    pub n: f64,
}

/// Curvature at a regular point of a surface (§4.6).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Curvature {
    /// The unit normal pᵤ × pᵥ/|pᵤ × pᵥ| the signs refer to.
    pub normal: DVec3,
    /// Gaussian curvature K = κ₁κ₂.
    pub gaussian: f64,
    /// Mean curvature H = (κ₁ + κ₂)/2.
    pub mean: f64,
    /// κ₁ + κ₂ = 2H, which the thesis calls the mean curvature.
    pub k1_plus_k2: f64,
    /// The larger principal curvature κ₁ = H + √(H² − K).
    pub k1: f64,
    /// The smaller principal curvature κ₂ = H − √(H² − K).
    pub k2: f64,
    /// Unit principal direction of κ₁ (in space, tangent to the surface).
    pub dir1: DVec3,
    /// Unit principal direction of κ₂ (orthogonal to `dir1`; at an umbilic any orthonormal
    /// tangent pair is principal, and the pair along pᵤ is returned).
    pub dir2: DVec3,
}

impl SurfaceDerivs {
    /// The unit normal, or `None` where pᵤ × pᵥ vanishes relative to `scale`² (a pole).
    #[must_use]
    pub fn normal(&self, scale: f64) -> Option<DVec3> {
        let c = self.pu.cross(self.pv);
        let len = c.length();
        (len > DEGENERATE * scale * scale && len.is_finite()).then(|| c / len)
    }

    /// The fundamental forms, or `None` at a degenerate point.
    #[must_use]
    pub fn fundamental_forms(&self, scale: f64) -> Option<FundamentalForms> {
        let n = self.normal(scale)?;
        Some(FundamentalForms {
            e: self.pu.dot(self.pu),
            f: self.pu.dot(self.pv),
            g: self.pv.dot(self.pv),
            l: self.puu.dot(n),
            m: self.puv.dot(n),
            n: self.pvv.dot(n),
        })
    }

    /// Gaussian, mean and principal curvatures with directions, or `None` at a degenerate
    /// point.
    #[must_use]
    pub fn curvature(&self, scale: f64) -> Option<Curvature> {
        let normal = self.normal(scale)?;
        let ff = self.fundamental_forms(scale)?;
        let det = ff.e * ff.g - ff.f * ff.f;
        let gaussian = (ff.l * ff.n - ff.m * ff.m) / det;
        let k1_plus_k2 = (ff.e * ff.n - 2.0 * ff.f * ff.m + ff.g * ff.l) / det;
        let mean = 0.5 * k1_plus_k2;
        let disc = (mean * mean - gaussian).max(0.0).sqrt();
        let (k1, k2) = (mean + disc, mean - disc);
        let dir1 = self.principal_direction(&ff, k1).unwrap_or_else(|| self.pu.normalize());
        let dir2 = normal.cross(dir1).normalize();
        Some(Curvature { normal, gaussian, mean, k1_plus_k2, k1, k2, dir1, dir2 })
    }

    /// The tangent direction du·pᵤ + dv·pᵥ for which (II − κ·I)(du, dv) = 0, from the better
    /// conditioned of the two rows; `None` at an umbilic.
    fn principal_direction(&self, ff: &FundamentalForms, k: f64) -> Option<DVec3> {
        // Rows of II − κI: [L − κE, M − κF] and [M − κF, N − κG].
        let (a, b) = (ff.l - k * ff.e, ff.m - k * ff.f);
        let (c, d) = (ff.m - k * ff.f, ff.n - k * ff.g);
        let scale = ff.l.abs() + ff.m.abs() + ff.n.abs() + k.abs() * (ff.e + ff.f.abs() + ff.g);
        let (du, dv) = if a.hypot(b) >= c.hypot(d) { (b, -a) } else { (d, -c) };
        if du.hypot(dv) <= 1e-9 * scale {
            return None;
        }
        Some((self.pu * du + self.pv * dv).normalize())
    }
}

impl HarmonicSurface<DVec3> {
    /// p and its first and second partial derivatives at (u, v).
    #[must_use]
    pub fn derivs(&self, u: f64, v: f64) -> SurfaceDerivs {
        SurfaceDerivs {
            p: self.eval(u, v),
            pu: self.eval_deriv(u, v, 1, 0),
            pv: self.eval_deriv(u, v, 0, 1),
            puu: self.eval_deriv(u, v, 2, 0),
            puv: self.eval_deriv(u, v, 1, 1),
            pvv: self.eval_deriv(u, v, 0, 2),
        }
    }

    /// The unit normal pᵤ × pᵥ/|pᵤ × pᵥ|; `None` where it is undefined (pᵤ × pᵥ = 0, as
    /// at the poles of the sphere grid).
    #[must_use]
    pub fn normal(&self, u: f64, v: f64) -> Option<DVec3> {
        self.derivs(u, v).normal(self.radius())
    }

    /// The first and second fundamental forms; `None` where the normal is undefined.
    #[must_use]
    pub fn fundamental_forms(&self, u: f64, v: f64) -> Option<FundamentalForms> {
        self.derivs(u, v).fundamental_forms(self.radius())
    }

    /// Gaussian curvature K, mean curvature H, κ₁ + κ₂ = 2H, principal curvatures and
    /// directions; `None` where the normal is undefined.
    #[must_use]
    pub fn curvature(&self, u: f64, v: f64) -> Option<Curvature> {
        self.derivs(u, v).curvature(self.radius())
    }
}

/// Which curvature a colour shows (§4.6); signs refer to the normal the mesh was built with.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum CurvatureQuantity {
    /// Gaussian curvature K = κ₁κ₂ (the default).
    #[default]
    Gaussian,
    /// Mean curvature H = (κ₁ + κ₂)/2.
    Mean,
    /// κ₁ + κ₂ = 2H, which the thesis calls the mean curvature.
    K1PlusK2,
}

impl CurvatureQuantity {
    /// The quantity at a point, from its [`Curvature`].
    #[must_use]
    pub fn of(self, c: &Curvature) -> f64 {
        match self {
            CurvatureQuantity::Gaussian => c.gaussian,
            CurvatureQuantity::Mean => c.mean,
            CurvatureQuantity::K1PlusK2 => c.k1_plus_k2,
        }
    }

    /// Whether the value changes sign with the normal (H and κ₁ + κ₂ do, K does not).
    #[must_use]
    pub fn is_odd_in_normal(self) -> bool {
        !matches!(self, CurvatureQuantity::Gaussian)
    }

    /// A short name for legends: "K", "H" or "κ₁ + κ₂".
    #[must_use]
    pub fn symbol(self) -> &'static str {
        match self {
            CurvatureQuantity::Gaussian => "K",
            CurvatureQuantity::Mean => "H",
            CurvatureQuantity::K1PlusK2 => "κ₁ + κ₂",
        }
    }
}
