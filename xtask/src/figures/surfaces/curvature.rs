// SPDX-License-Identifier: MIT
//! The §5.9 comparison of a parametric surface and its harmonic surface: the pictures of
//! figures 5.31–5.43 and the two tables.

use anyhow::{Context, Result, ensure};
use glam::{DVec2, DVec3};
use hi_mesh::TriangleMesh;
use hi_surface::{
    CurvatureQuantity, HarmonicSurface, MeshOptions, ParametricSurface, compare_curvature,
    test_surface, test_surfaces,
};

use super::super::glb::glb;
use super::colours::colored;
use super::meshes::{parametric_mesh, with_markers};
use super::{COVERAGE, FLOOR, MARKER_SIZE, MIN_COLOUR_USE, OVER, SPECS, Side, Spec, TABLE_RES};

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

    /// The least colour-scale extent of `quantity`: [`FLOOR`] of the curvature of the surface's
    /// size (1/r² for K, 1/r for H), below which a value counts as flat.
    fn floor(&self, quantity: CurvatureQuantity) -> f64 {
        match quantity {
            CurvatureQuantity::Gaussian => FLOOR / (self.scale * self.scale),
            _ => FLOOR / self.scale,
        }
    }

    /// The colour-scale extent of `quantity` (see the module notes): the [`COVERAGE`] quantile
    /// of |values| over the parametric surface's *area* (each vertex weighted by a third of
    /// its triangles' area), so that what most of the picture shows sets the scale, not the
    /// many small triangles a parameterisation crowds near an apex or a pole.
    pub(super) fn extent(&self, quantity: CurvatureQuantity) -> Result<f64> {
        let (mesh, _) = self.mesh(Side::Parametric);
        let a =
            area_quantile(&self.values(Side::Parametric, quantity), &vertex_areas(mesh), COVERAGE);
        let floor = self.floor(quantity);
        Ok(if a.is_finite() { a.max(floor) } else { floor })
    }

    /// How much of the colour bar [−a, a] the picture of `quantity` on `side` uses, as a
    /// fraction of the bar: from the least to the greatest of 0 and the 2 % and 98 % area
    /// quantiles of the values (the neutral grey of 0 counts as shown: a sphere's constant K
    /// uses half the bar); `None` for a quantity that vanishes everywhere (a plane's K), which no
    /// scale can show.
    pub(super) fn colour_use(
        &self,
        side: Side,
        quantity: CurvatureQuantity,
    ) -> Result<Option<f64>> {
        let a = self.extent(quantity)?;
        let values = self.values(side, quantity);
        let areas = vertex_areas(&self.mesh(side).0);
        let floor = self.floor(quantity);
        if values.iter().all(|x| !x.is_finite() || x.abs() <= floor) {
            return Ok(None);
        }
        let (v, w): (Vec<f64>, Vec<f64>) = values
            .iter()
            .zip(&areas)
            .filter(|(x, _)| x.is_finite())
            .map(|(x, w)| (x.clamp(-a, a), *w))
            .unzip();
        let (lo, hi) = (
            weighted_quantile(v.clone(), &w, 0.02).min(0.0),
            weighted_quantile(v, &w, 0.98).max(0.0),
        );
        Ok(Some((hi - lo) / (2.0 * a)))
    }
}

/// The area around each vertex of `mesh`: a third of the area of each triangle at it.
fn vertex_areas(mesh: &TriangleMesh) -> Vec<f64> {
    let p = mesh.positions();
    let mut areas = vec![0.0; p.len()];
    for t in mesh.triangles() {
        let [a, b, c] = t.map(|k| p[k as usize]);
        let third = (b - a).cross(c - a).length() / 6.0;
        for k in t {
            areas[*k as usize] += third;
        }
    }
    areas
}

/// The `q` quantile of |`values`| weighted by `weights` (non-finite values left out).
fn area_quantile(values: &[f64], weights: &[f64], q: f64) -> f64 {
    let (v, w): (Vec<f64>, Vec<f64>) = values
        .iter()
        .zip(weights)
        .filter(|(x, _)| x.is_finite())
        .map(|(x, w)| (x.abs(), *w))
        .unzip();
    weighted_quantile(v, &w, q)
}

/// The smallest of `values` below which at least the fraction `q` of the total weight lies
/// (NaN for no values).
fn weighted_quantile(values: Vec<f64>, weights: &[f64], q: f64) -> f64 {
    let mut order: Vec<usize> = (0..values.len()).collect();
    order.sort_by(|&i, &j| values[i].total_cmp(&values[j]));
    let total: f64 = weights.iter().sum();
    let mut below = 0.0;
    for &i in &order {
        below += weights[i];
        if below >= q * total {
            return values[i];
        }
    }
    order.last().map_or(f64::NAN, |&i| values[i])
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
        Some(quantity) => {
            if let Some(used) = c.colour_use(side, quantity)? {
                ensure!(
                    used >= MIN_COLOUR_USE,
                    "figure {} ({side:?}, {}): the picture uses {:.0} % of its colour bar, less \
                     than {:.0} %: its scale says nothing",
                    spec.figure,
                    quantity.symbol(),
                    100.0 * used,
                    100.0 * MIN_COLOUR_USE
                );
            }
            colored(mesh.clone(), &c.values(side, quantity), c.extent(quantity)?)?
        }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every curvature picture of figures 5.31–5.43 uses at least a quarter of its colour bar
    /// (the figures refuse to draw otherwise; here each is named with its share).
    #[test]
    fn curvature_pictures_use_their_colour_bars() {
        let mut report = Vec::new();
        for spec in &SPECS {
            let c = Comparison::new(spec).expect("a §5.9 surface");
            for side in [Side::Parametric, Side::Harmonic] {
                for q in [CurvatureQuantity::Gaussian, CurvatureQuantity::Mean] {
                    let used = c.colour_use(side, q).expect("values");
                    report.push(format!("{} {side:?} {}: {used:.2?}", spec.figure, q.symbol()));
                    assert!(used.is_none_or(|u| u >= MIN_COLOUR_USE), "{}", report.join("\n"));
                }
            }
        }
        eprintln!("{}", report.join("\n"));
    }
}
