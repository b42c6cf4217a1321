// SPDX-License-Identifier: MIT
//! The §5.9 comparison of a parametric surface and its harmonic surface: the pictures of
//! figures 5.31–5.43 and the two tables.

use anyhow::{Context, Result, ensure};
use glam::{DVec2, DVec3};
use hi_mesh::{ColorMap, ColorScale, Palette, TriangleMesh};
use hi_surface::{
    CurvatureQuantity, HarmonicSurface, MeshOptions, ParametricSurface, compare_curvature,
    test_surface, test_surfaces,
};

use super::super::glb::glb;
use super::colours::colored;
use super::meshes::{parametric_mesh, with_markers};
use super::{COVERAGE, FLOOR, MARKER_SIZE, OVER, SPECS, Side, Spec, TABLE_RES};

/// A §5.9 comparison: the surface, its harmonic surface and both meshes.
pub(super) struct Comparison {
    surface: ParametricSurface,
    harmonic: HarmonicSurface<DVec3>,
    /// The curvature scale (the harmonic surface's radius).
    scale: f64,
    /// The mesh of the parametric surface and the parameters of its vertices.
    parametric_mesh: (TriangleMesh, Vec<DVec2>),
    /// The mesh of the harmonic surface and the parameters of its vertices.
    harmonic_mesh: (TriangleMesh, Vec<DVec2>),
}

impl Comparison {
    pub(super) fn new(spec: &Spec) -> Result<Self> {
        let surface =
            test_surface(spec.name).with_context(|| format!("no §5.9 surface {}", spec.name))?;
        ensure!(
            surface.figure == spec.figure,
            "surface {} is figure {}, not {}",
            spec.name,
            surface.figure,
            spec.figure
        );
        let harmonic = surface.harmonic();
        let scale = harmonic.radius();
        let window = surface.window;
        let parametric_mesh =
            parametric_mesh(&|u, v| surface.derivs(u, v), scale, window, (spec.n_u, spec.n_v))?;
        let options = MeshOptions { n_u: spec.n_u, n_v: spec.n_v, window, ..Default::default() };
        let mesh = harmonic.to_mesh(&options)?;
        let params = mesh.uvs().iter().map(|t| DVec2::from(window.lerp(t.x, t.y))).collect();
        Ok(Comparison { surface, harmonic, scale, parametric_mesh, harmonic_mesh: (mesh, params) })
    }

    /// The mesh of one side and the parameters of its vertices.
    pub(super) fn mesh(&self, side: Side) -> &(TriangleMesh, Vec<DVec2>) {
        match side {
            Side::Parametric => &self.parametric_mesh,
            Side::Harmonic => &self.harmonic_mesh,
        }
    }

    /// `quantity` at the vertices of one side's mesh; NaN where undefined.
    pub(super) fn values(&self, side: Side, quantity: CurvatureQuantity) -> Vec<f64> {
        let curvature = |t: &DVec2| match side {
            Side::Parametric => self.surface.curvature(t.x, t.y, self.scale),
            Side::Harmonic => self.harmonic.curvature(t.x, t.y),
        };
        self.mesh(side)
            .1
            .iter()
            .map(|t| curvature(t).map_or(f64::NAN, |c| quantity.of(&c)))
            .collect()
    }

    /// The colour-scale extent of `quantity` (see the module notes).
    pub(super) fn extent(&self, quantity: CurvatureQuantity) -> Result<f64> {
        let map =
            ColorMap { scale: ColorScale::Magnitude, coverage: COVERAGE, palette: Palette::Thesis };
        let a = map.try_apply(&self.values(Side::Parametric, quantity))?.legend.max;
        let floor = match quantity {
            CurvatureQuantity::Gaussian => FLOOR / (self.scale * self.scale),
            _ => FLOOR / self.scale,
        };
        Ok(if a.is_finite() { a.max(floor) } else { floor })
    }
}

/// One panel of figures 5.31–5.43: a side, plain (the harmonic one with its samples marked) or
/// coloured by the magnitude of a curvature.
pub(super) fn comparison(
    spec: &Spec,
    side: Side,
    show: Option<CurvatureQuantity>,
) -> Result<Vec<u8>> {
    let c = Comparison::new(spec)?;
    let mesh = &c.mesh(side).0;
    let mesh = match show {
        Some(quantity) => colored(mesh.clone(), &c.values(side, quantity), c.extent(quantity)?)?,
        None if side == Side::Harmonic => {
            with_markers(mesh, c.harmonic.points(), MARKER_SIZE * c.scale)?
        }
        None => mesh.clone(),
    };
    glb(&mesh)
}

/// The curvature comparison of §5.9, one row per surface.
pub(super) fn curvature_table() -> Result<String> {
    let mut s = String::from(
        "| fig | surface | samples | points | max ΔK | RMS ΔK | max \\|K\\| | max ΔH | RMS ΔH | max \\|H\\| |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    for surface in test_surfaces() {
        let c = compare_curvature(&surface, TABLE_RES);
        s += &format!(
            "| {} | {} | {}×{} | {} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} | {:.3e} |\n",
            surface.figure,
            surface.title,
            surface.samples.0,
            surface.samples.1,
            c.n_points,
            c.gaussian_max,
            c.gaussian_rms,
            c.gaussian_scale,
            c.mean_max,
            c.mean_rms,
            c.mean_scale
        );
    }
    Ok(s)
}

/// The meshes and colour scales of figures 5.31–5.43.
pub(super) fn mesh_table() -> Result<String> {
    let mut s = String::from(
        "| fig | surface | window (u0, u1, v0, v1) | quads | vertices (parametric, harmonic) | a for \\|K\\| | over a | a for \\|H\\| | over a |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for spec in &SPECS {
        let c = Comparison::new(spec)?;
        let over = |quantity| -> Result<(f64, usize)> {
            let a = c.extent(quantity)?;
            let n =
                c.values(Side::Harmonic, quantity).iter().filter(|x| x.abs() > OVER * a).count();
            Ok((a, n))
        };
        let ((ak, nk), (ah, nh)) =
            (over(CurvatureQuantity::Gaussian)?, over(CurvatureQuantity::Mean)?);
        let w = c.surface.window;
        let (u0, u1, v0, v1) = (w.u.start, w.u.end, w.v.start, w.v.end);
        s += &format!(
            "| {} | {} | ({u0}, {u1}, {v0}, {v1}) | {}×{} | {}, {} | {ak:.3e} | {nk} | {ah:.3e} | {nh} |\n",
            spec.figure,
            c.surface.title,
            spec.n_u,
            spec.n_v,
            c.parametric_mesh.0.n_vertices(),
            c.harmonic_mesh.0.n_vertices(),
        );
    }
    Ok(s)
}
