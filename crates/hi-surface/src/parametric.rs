// SPDX-License-Identifier: MIT
//! The test surfaces of §5.9 (figures 5.31–5.43) as parametric definitions, sampled into
//! harmonic surfaces, and the comparison of their curvature.
//!
//! The thesis samples each surface at 24×4 points (48×4 for the finer Solomon's seal), builds
//! the harmonic surface through the samples, and compares Gaussian and mean curvature of the
//! two. Here the parametric surface's curvature is computed numerically (fourth-order central
//! differences, relative accuracy about 1e-7), the harmonic surface's analytically (its exact
//! derivatives), on a common grid of parameters.
//!
//! **Reconstruction.** The formulas come from the extracted thesis text, where minus signs and
//! fractions are lost. Where a formula is ambiguous the choice made is stated on its function:
//! these are stand-ins faithful to the thesis's shapes, not guaranteed to be its exact data.

use std::f64::consts::{PI, TAU};

use glam::DVec3;

use crate::geometry::{Curvature, SurfaceDerivs};
use crate::{HarmonicSurface, ParamRange, ParamWindow};

/// A parametric surface of §5.9 with the sampling the thesis used.
#[derive(Clone, Copy, Debug)]
pub struct ParametricSurface {
    /// A short name (`torus`, `mobius`, …), used by the command line and file names.
    pub name: &'static str,
    /// The thesis figure that compares it (e.g. "5.33").
    pub figure: &'static str,
    /// A caption.
    pub title: &'static str,
    /// Samples (in u, in v) the thesis took: grid point (j, k) is f(j/m, k/n).
    pub samples: (usize, usize),
    /// The parameter window of the thesis's picture; a sub-window of [0, 1]².
    pub window: ParamWindow,
    /// True if f is 1-periodic in u and in v, so harmonic interpolation can reproduce it well.
    pub periodic: bool,
    f: fn(f64, f64) -> DVec3,
}

impl ParametricSurface {
    /// f(u, v).
    #[must_use]
    pub fn eval(&self, u: f64, v: f64) -> DVec3 {
        (self.f)(u, v)
    }

    /// f and its first and second partial derivatives by fourth-order central differences.
    #[must_use]
    pub fn derivs(&self, u: f64, v: f64) -> SurfaceDerivs {
        let f = |du: f64, dv: f64| (self.f)(u + du, v + dv);
        let h1 = 1e-3;
        let d1 = |e: (f64, f64)| {
            (f(-2.0 * h1 * e.0, -2.0 * h1 * e.1) - 8.0 * f(-h1 * e.0, -h1 * e.1)
                + 8.0 * f(h1 * e.0, h1 * e.1)
                - f(2.0 * h1 * e.0, 2.0 * h1 * e.1))
                / (12.0 * h1)
        };
        let h2 = 2e-3;
        let d2 = |e: (f64, f64)| {
            (-f(-2.0 * h2 * e.0, -2.0 * h2 * e.1) + 16.0 * f(-h2 * e.0, -h2 * e.1)
                - 30.0 * f(0.0, 0.0)
                + 16.0 * f(h2 * e.0, h2 * e.1)
                - f(2.0 * h2 * e.0, 2.0 * h2 * e.1))
                / (12.0 * h2 * h2)
        };
        // p_uv from the second differences along the diagonals: (d²(1,1) − d²(1,−1))/4.
        let puv = (d2((1.0, 1.0)) - d2((1.0, -1.0))) / 4.0;
        SurfaceDerivs {
            p: f(0.0, 0.0),
            pu: d1((1.0, 0.0)),
            pv: d1((0.0, 1.0)),
            puu: d2((1.0, 0.0)),
            puv,
            pvv: d2((0.0, 1.0)),
        }
    }

    /// Curvature of the parametric surface (numerical); `None` where the normal is undefined.
    #[must_use]
    pub fn curvature(&self, u: f64, v: f64, scale: f64) -> Option<Curvature> {
        self.derivs(u, v).curvature(scale)
    }

    /// The m×n grid f(j/m, k/n).
    #[must_use]
    pub fn sample_grid(&self, m: usize, n: usize) -> Vec<Vec<DVec3>> {
        (0..m)
            .map(|j| (0..n).map(|k| self.eval(j as f64 / m as f64, k as f64 / n as f64)).collect())
            .collect()
    }

    /// The harmonic surface through the thesis's samples.
    #[must_use]
    #[allow(
        clippy::missing_panics_doc,
        reason = "the definitions are finite on [0, 1]², checked by a test"
    )]
    pub fn harmonic(&self) -> HarmonicSurface<DVec3> {
        HarmonicSurface::new(self.sample_grid(self.samples.0, self.samples.1))
    }
}

/// Gaussian and mean curvature of a parametric surface against its harmonic surface.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CurvatureComparison {
    /// Points compared (regular on both surfaces).
    pub n_points: usize,
    /// Points skipped because a normal was undefined on either surface.
    pub n_skipped: usize,
    /// max |K(parametric) − K(harmonic)|.
    pub gaussian_max: f64,
    /// RMS of K(parametric) − K(harmonic).
    pub gaussian_rms: f64,
    /// max |H(parametric) − H(harmonic)|.
    pub mean_max: f64,
    /// RMS of H(parametric) − H(harmonic).
    pub mean_rms: f64,
    /// max |K(parametric)|, for scale.
    pub gaussian_scale: f64,
    /// max |H(parametric)|, for scale.
    pub mean_scale: f64,
}

/// Compares the curvature of `surface` and its harmonic surface on a `res`×`res` grid of cell
/// centres of the surface's window.
#[must_use]
pub fn compare_curvature(surface: &ParametricSurface, res: usize) -> CurvatureComparison {
    let harmonic = surface.harmonic();
    let scale = harmonic.radius().max(1e-300);
    let ParamWindow { u: ParamRange { start: u0, end: u1 }, v: ParamRange { start: v0, end: v1 } } =
        surface.window;
    let mut c = CurvatureComparison {
        n_points: 0,
        n_skipped: 0,
        gaussian_max: 0.0,
        gaussian_rms: 0.0,
        mean_max: 0.0,
        mean_rms: 0.0,
        gaussian_scale: 0.0,
        mean_scale: 0.0,
    };
    for i in 0..res {
        for l in 0..res {
            let u = u0 + (u1 - u0) * (i as f64 + 0.5) / res as f64;
            let v = v0 + (v1 - v0) * (l as f64 + 0.5) / res as f64;
            let (Some(a), Some(b)) = (surface.curvature(u, v, scale), harmonic.curvature(u, v))
            else {
                c.n_skipped += 1;
                continue;
            };
            let (dk, dh) = ((a.gaussian - b.gaussian).abs(), (a.mean - b.mean).abs());
            c.n_points += 1;
            c.gaussian_max = c.gaussian_max.max(dk);
            c.mean_max = c.mean_max.max(dh);
            c.gaussian_rms += dk * dk;
            c.mean_rms += dh * dh;
            c.gaussian_scale = c.gaussian_scale.max(a.gaussian.abs());
            c.mean_scale = c.mean_scale.max(a.mean.abs());
        }
    }
    let count = c.n_points.max(1) as f64;
    c.gaussian_rms = (c.gaussian_rms / count).sqrt();
    c.mean_rms = (c.mean_rms / count).sqrt();
    c
}

/// A point on the sphere-like surface (r cos ρ cos θ, r cos ρ sin θ, r sin ρ).
fn spherical(r: f64, rho: f64, theta: f64) -> DVec3 {
    DVec3::new(r * rho.cos() * theta.cos(), r * rho.cos() * theta.sin(), r * rho.sin())
}

/// A plane (the thesis's "quadrilateral"): (3u − 1.5, 3v − 1.5, 0). Reconstructed.
fn plane(u: f64, v: f64) -> DVec3 {
    DVec3::new(3.0 * u - 1.5, 3.0 * v - 1.5, 0.0)
}

/// Partial sphere: ρ = 0.9(πv − π/2), θ = 2πu, r = 1.
fn partial_sphere(u: f64, v: f64) -> DVec3 {
    spherical(1.0, 0.9 * (PI * v - PI / 2.0), TAU * u)
}

/// Sphere: ρ = 2πv − π/2 (the meridian circle, so v runs around the sphere twice and the data
/// is periodic), θ = 2πu, r = 1.
fn sphere_surface(u: f64, v: f64) -> DVec3 {
    spherical(1.0, TAU * v - PI / 2.0, TAU * u)
}

/// Torus (cos θ(r cos ρ + R), r sin ρ, sin θ(r cos ρ + R)), θ = 2πu, ρ = 2πv; R = 2, r = 1
/// (the radii are not given in the text).
fn torus_surface(u: f64, v: f64) -> DVec3 {
    let (theta, rho) = (TAU * u, TAU * v);
    let w = rho.cos() + 2.0;
    DVec3::new(theta.cos() * w, rho.sin(), theta.sin() * w)
}

/// Doubled Möbius strip: (sin s·(2 − t sin(s/2)), cos s·(2 − t sin(s/2)), t cos(s/2)) with
/// s = 4πu and t = v − ½: u ∈ [0, 1] goes round twice, so the data is periodic in u. The
/// point (u + ½, v) is (u, 1 − v): the window v ∈ [0, ½] covers the strip once, one half of
/// its width on each round, the halves meeting along the centre line t = 0 (the sample row
/// v = ½, which the harmonic surface passes through).
fn mobius(u: f64, v: f64) -> DVec3 {
    let (s, t) = (2.0 * TAU * u, v - 0.5);
    let w = 2.0 - t * (s / 2.0).sin();
    DVec3::new(s.sin() * w, s.cos() * w, t * (s / 2.0).cos())
}

/// Surface of revolution: (θ, cos ρ(sin θ + 2), sin ρ(sin θ + 2)), θ = 2πu − π, ρ = 2πv: not
/// periodic in u.
fn revolution(u: f64, v: f64) -> DVec3 {
    let (theta, rho) = (TAU * u - PI, TAU * v);
    let w = theta.sin() + 2.0;
    DVec3::new(theta, rho.cos() * w, rho.sin() * w)
}

/// The periodic version: θ = 4πu − π and the axis coordinate g(θ) = θ for θ < π, 2π − θ
/// otherwise, so u ∈ [½, 1] retraces u ∈ [0, ½]; the thesis shows 0 < u < ½.
fn revolution_periodic(u: f64, v: f64) -> DVec3 {
    let (theta, rho) = (2.0 * TAU * u - PI, TAU * v);
    let g = if theta < PI { theta } else { TAU - theta };
    let w = theta.sin() + 2.0;
    DVec3::new(g, rho.cos() * w, rho.sin() * w)
}

/// A shell: ((r−1)cos θ(1 + cos ρ), (r−1) sin θ(1 + cos ρ), (r² − 1) + (r−1) sin ρ) with
/// θ = 6πu, ρ = 2πv, r = eᵘ. The third component is reconstructed from "(r 2 1)".
fn shell(u: f64, v: f64) -> DVec3 {
    let (theta, rho, r) = (3.0 * TAU * u, TAU * v, u.exp());
    let a = (r - 1.0) * (1.0 + rho.cos());
    DVec3::new(a * theta.cos(), a * theta.sin(), (r * r - 1.0) + (r - 1.0) * rho.sin())
}

/// Another shell: ((r−1) sin ρ, (r−1)(1 + cos ρ) sin φ, (r−1)(1 + cos ρ) cos φ) with
/// φ = θ − sin(2ρ + π/2), θ = 6πu, ρ = 2πv, r = eᵘ: a whorl coiled three times about the
/// x axis, its cross-section twisted back and forth by a radian. Reconstructed: the extracted
/// text reads "sin(θ sin(2ρ+π/2)", and it drops every minus sign ("r 1" for r − 1); read as a
/// product, θ·sin(2ρ + π/2), the angle would swing through ±6π across every cross-section, a
/// stack of discs that no 24×4 samples describe and not the shell the text discusses.
fn shell2(u: f64, v: f64) -> DVec3 {
    let (theta, rho, r) = (3.0 * TAU * u, TAU * v, u.exp());
    let a = (r - 1.0) * (1.0 + rho.cos());
    let phi = theta - (2.0 * rho + PI / 2.0).sin();
    DVec3::new((r - 1.0) * rho.sin(), a * phi.sin(), a * phi.cos())
}

/// Part of the Klein bottle: (x + r cos(ρ + π), 16 sin θ, r sin ρ) with θ = πu + π, ρ = 2πv,
/// r = 4(1 − cos θ/2), x = 6 cos θ(1 + sin θ) (the classic "bottle" parametrisation).
fn klein(u: f64, v: f64) -> DVec3 {
    let (theta, rho) = (PI * u + PI, TAU * v);
    let r = 4.0 * (1.0 - theta.cos() / 2.0);
    let x = 6.0 * theta.cos() * (1.0 + theta.sin());
    DVec3::new(x + r * (rho + PI).cos(), 16.0 * theta.sin(), r * rho.sin())
}

/// A tube of radius `radius` around the curve `c`, built from its Frenet frame: the circle
/// c(t) + radius·(cos 2πv·N + sin 2πv·B). Derivatives of c by central differences.
fn tube(c: fn(f64) -> DVec3, radius: f64, u: f64, v: f64) -> DVec3 {
    let h = 1e-4;
    let d1 = (c(u + h) - c(u - h)) / (2.0 * h);
    let d2 = (c(u + h) - 2.0 * c(u) + c(u - h)) / (h * h);
    let t = d1.normalize();
    let b = d1.cross(d2).normalize();
    let n = b.cross(t);
    let phi = TAU * v;
    c(u) + radius * (phi.cos() * n + phi.sin() * b)
}

/// The overhand (trefoil) knot (cos θ(2 − sin(3θ/2)), sin θ(2 − sin(3θ/2)), cos(3θ/2)),
/// θ = 4πt; reconstructed from the garbled text.
fn overhand_curve(t: f64) -> DVec3 {
    let th = 2.0 * TAU * t;
    let w = 2.0 - (1.5 * th).sin();
    DVec3::new(th.cos() * w, th.sin() * w, (1.5 * th).cos())
}

/// Solomon's seal, the (2, 5) torus knot (cos 2θ(1 + ⅖ cos 5θ), sin 2θ(1 + ⅖ cos 5θ), ½ sin 5θ),
/// θ = 2πt; reconstructed from the garbled text.
fn solomon_curve(t: f64) -> DVec3 {
    let th = TAU * t;
    let w = 1.0 + 0.4 * (5.0 * th).cos();
    DVec3::new((2.0 * th).cos() * w, (2.0 * th).sin() * w, 0.5 * (5.0 * th).sin())
}

fn overhand(u: f64, v: f64) -> DVec3 {
    tube(overhand_curve, 0.3, u, v)
}

fn solomon(u: f64, v: f64) -> DVec3 {
    tube(solomon_curve, 0.12, u, v)
}

/// The thirteen comparisons of §5.9, in the thesis's figure order (5.31–5.43).
#[must_use]
pub fn test_surfaces() -> Vec<ParametricSurface> {
    let full = [0.0, 1.0, 0.0, 1.0];
    let s = |name, figure, title, samples, window, periodic, f| ParametricSurface {
        name,
        figure,
        title,
        samples,
        window: {
            let [u0, u1, v0, v1]: [f64; 4] = window;
            ParamWindow::new(ParamRange::new(u0, u1), ParamRange::new(v0, v1))
        },
        periodic,
        f,
    };
    vec![
        s("plane", "5.31", "Plane", (24, 4), full, false, plane as fn(f64, f64) -> DVec3),
        s("partial-sphere", "5.32", "Partial sphere", (24, 4), full, false, partial_sphere),
        s("torus", "5.33", "Torus", (24, 4), full, true, torus_surface),
        s("sphere", "5.34", "Sphere", (24, 4), [0.0, 1.0, 0.0, 0.5], true, sphere_surface),
        s("mobius", "5.35", "Doubled Möbius strip", (24, 4), [0.0, 1.0, 0.0, 0.5], false, mobius),
        s("revolution", "5.36", "Surface of revolution", (24, 4), full, false, revolution),
        s("shell", "5.37", "Shell", (24, 4), full, false, shell),
        s("shell2", "5.38", "Another shell", (24, 4), full, false, shell2),
        s("klein", "5.39", "Partial Klein bottle", (24, 4), full, false, klein),
        s("overhand", "5.40", "Overhand knot tube", (24, 4), full, false, overhand),
        s("solomon", "5.41", "Solomon's seal tube", (24, 4), full, false, solomon),
        s(
            "solomon-fine",
            "5.42",
            "Solomon's seal tube, 48×4 samples",
            (48, 4),
            full,
            false,
            solomon,
        ),
        s(
            "revolution-periodic",
            "5.43",
            "Periodic surface of revolution",
            (24, 4),
            [0.0, 0.5, 0.0, 1.0],
            true,
            revolution_periodic,
        ),
    ]
}

/// The §5.9 surface called `name`, if any.
#[must_use]
pub fn test_surface(name: &str) -> Option<ParametricSurface> {
    test_surfaces().into_iter().find(|s| s.name == name)
}
