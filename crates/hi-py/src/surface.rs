// SPDX-License-Identifier: MIT
//! Surfaces: `HarmonicSurface`, the tensor product of harmonic curves through a grid (thesis
//! §5.1, §5.2), its partials and curvatures (§4.6), meshes, Bézier patches (§5.7), and the
//! examples of §5.9.

use glam::DVec3;
use hi_surface::{HarmonicSurface, MeshOptions, ParamRange, ParamWindow, SurfaceDerivs};
use numpy::IntoPyArray;
use numpy::ndarray::Array3;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays::{Params, from_points, from_triangles, params, to_python};
use crate::curve::bezier_options;
use crate::errors::value_error;

/// The sphere's radius in `example("sphere")`, and the torus's radii.
const SPHERE_RADIUS: f64 = 1.0;
/// The torus's radii (centre circle, tube) in `example("torus")`.
const TORUS_RADII: (f64, f64) = (2.0, 1.0);

/// The pairs (u, v) of two parameters or arrays of them, and whether they were one pair.
fn pairs(u: &Bound<'_, PyAny>, v: &Bound<'_, PyAny>) -> PyResult<(Vec<(f64, f64)>, bool)> {
    match (params(u, "u")?, params(v, "v")?) {
        (Params::One(u), Params::One(v)) => Ok((vec![(u, v)], true)),
        (Params::Many(us), Params::Many(vs)) if us.len() == vs.len() => {
            Ok((us.into_iter().zip(vs).collect(), false))
        }
        (Params::Many(us), Params::Many(vs)) => Err(value_error(format!(
            "u has {} values and v has {}: give one v for each u",
            us.len(),
            vs.len()
        ))),
        _ => Err(value_error("u and v: give two numbers, or two arrays of the same length")),
    }
}

/// Points at the pairs: one point (shape (3,)) for one pair, else shape (k, 3).
fn points_out<'py>(py: Python<'py>, values: &[DVec3], one: bool) -> Bound<'py, PyAny> {
    let array = from_points(py, values).into_any();
    if one { array.get_item(0).unwrap_or(array) } else { array }
}

/// A harmonic surface through a grid of points xᵢⱼ, shape (m, n, 3): p(u, v) = Σᵢⱼ σᵐᵢ(u)
/// σⁿⱼ(v) xᵢⱼ, doubly periodic, with p(i/m, j/n) = xᵢⱼ (thesis §5.1).
///
/// >>> import numpy as np
/// >>> s = harmonic.example("sphere")
/// >>> round(float(np.linalg.norm(s.eval(0.3, 0.7))), 12)
/// 1.0
#[pyclass(name = "HarmonicSurface", module = "harmonic", frozen)]
#[derive(Debug)]
pub(crate) struct PyHarmonicSurface {
    pub(crate) inner: HarmonicSurface<DVec3>,
}

#[pymethods]
impl PyHarmonicSurface {
    #[new]
    fn new(grid: &Bound<'_, PyAny>) -> PyResult<Self> {
        let rows = crate::arrays::grid(grid, "grid")?;
        Ok(Self { inner: HarmonicSurface::try_new(rows).map_err(value_error)? })
    }

    /// The grid of points it passes through, shape (m, n, 3).
    #[getter]
    fn grid<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        grid_array(py, &self.inner.rows())
    }

    /// The grid's size (m, n).
    #[getter]
    fn shape(&self) -> (usize, usize) {
        (self.inner.m(), self.inner.n())
    }

    fn __repr__(&self) -> String {
        format!("HarmonicSurface(m={}, n={})", self.inner.m(), self.inner.n())
    }

    /// p(u, v) at a pair of parameters (shape (3,)) or at pairs from two arrays (shape (k, 3)).
    fn eval<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (uv, one) = pairs(u, v)?;
        let values: Vec<DVec3> = uv.iter().map(|&(u, v)| self.inner.eval(u, v)).collect();
        Ok(points_out(py, &values, one))
    }

    /// The partial derivative ∂^(du+dv) p / ∂u^du ∂v^dv at (u, v) (numbers or arrays).
    #[pyo3(signature = (u, v, du = 1, dv = 0))]
    fn derivative<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        du: usize,
        dv: usize,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (uv, one) = pairs(u, v)?;
        let values: Vec<DVec3> =
            uv.iter().map(|&(u, v)| self.inner.eval_deriv(u, v, du, dv)).collect();
        Ok(points_out(py, &values, one))
    }

    /// p and its first and second partials at (u, v): a dict of `p`, `pu`, `pv`, `puu`,
    /// `puv`, `pvv` (each shape (3,), or (k, 3) for arrays).
    fn partials<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (uv, one) = pairs(u, v)?;
        let derivs: Vec<SurfaceDerivs> = uv.iter().map(|&(u, v)| self.inner.derivs(u, v)).collect();
        let out = PyDict::new(py);
        let field =
            |f: fn(&SurfaceDerivs) -> DVec3| -> Vec<DVec3> { derivs.iter().map(f).collect() };
        out.set_item("p", points_out(py, &field(|d| d.p), one))?;
        out.set_item("pu", points_out(py, &field(|d| d.pu), one))?;
        out.set_item("pv", points_out(py, &field(|d| d.pv), one))?;
        out.set_item("puu", points_out(py, &field(|d| d.puu), one))?;
        out.set_item("puv", points_out(py, &field(|d| d.puv), one))?;
        out.set_item("pvv", points_out(py, &field(|d| d.pvv), one))?;
        Ok(out)
    }

    /// The curvatures at (u, v) (§4.6): a dict of `gaussian` K, `mean` H, the principal
    /// curvatures `k1` ≥ `k2` and the unit `normal`; NaN where pᵤ × pᵥ = 0 (poles, creases).
    fn curvature<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (uv, one) = pairs(u, v)?;
        let radius = self.inner.radius();
        let c: Vec<_> =
            uv.iter().map(|&(u, v)| self.inner.derivs(u, v).curvature(radius)).collect();
        let scalar = |f: fn(&hi_surface::Curvature) -> f64| -> Vec<f64> {
            c.iter().map(|c| c.as_ref().map_or(f64::NAN, f)).collect()
        };
        let out = PyDict::new(py);
        for (name, values) in [
            ("gaussian", scalar(|c| c.gaussian)),
            ("mean", scalar(|c| c.mean)),
            ("k1", scalar(|c| c.k1)),
            ("k2", scalar(|c| c.k2)),
        ] {
            if one {
                out.set_item(name, values[0])?;
            } else {
                out.set_item(name, from_points(py, &values))?;
            }
        }
        let normals: Vec<DVec3> =
            c.iter().map(|c| c.as_ref().map_or(DVec3::NAN, |c| c.normal)).collect();
        out.set_item("normal", points_out(py, &normals, one))?;
        Ok(out)
    }

    /// A triangle mesh of the surface over `window` = (u0, u1, v0, v1) (the whole period by
    /// default; the doubled sphere of §5.2 covers itself once over u in [0, 0.5]),
    /// `resolution` = (samples along u, along v), seams welded and poles closed: `(vertices,
    /// faces)`, shapes (V, 3) float and (F, 3) int, as `trimesh.Trimesh(vertices, faces)`
    /// takes them.
    #[pyo3(signature = (resolution = (64, 64), window = (0.0, 1.0, 0.0, 1.0)))]
    fn mesh<'py>(
        &self,
        py: Python<'py>,
        resolution: (usize, usize),
        window: (f64, f64, f64, f64),
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
        let (u0, u1, v0, v1) = window;
        let options = MeshOptions {
            n_u: resolution.0,
            n_v: resolution.1,
            window: ParamWindow::new(ParamRange::new(u0, u1), ParamRange::new(v0, v1)),
            ..MeshOptions::default()
        };
        let surface = &self.inner;
        let mesh = py.detach(|| surface.to_mesh(&options)).map_err(value_error)?;
        Ok((from_points(py, mesh.positions()).into_any(), from_triangles(py, mesh.triangles())?))
    }

    /// Bézier patches of the surface by a §5.7 scheme along u and v (`hermite`, the default,
    /// C1 bicubic patches within `tolerance`; `hermite-quintic`, `thesis-cubic`,
    /// `thesis-quintic`): a dict of `patches` (a list of control nets, shape
    /// (degree in u + 1, degree in v + 1, 3)), `u_breaks`, `v_breaks` and `report`.
    #[pyo3(signature = (scheme = "hermite", tolerance = None))]
    fn to_bezier<'py>(
        &self,
        py: Python<'py>,
        scheme: &str,
        tolerance: Option<f64>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (scheme, tolerance) = bezier_options(scheme, tolerance)?;
        let surface = &self.inner;
        let b = py.detach(|| surface.to_bezier(scheme, tolerance)).map_err(value_error)?;
        let mut patches = Vec::with_capacity(b.patches.len());
        for patch in &b.patches {
            let dv = patch.degree_v();
            let rows: Vec<Vec<DVec3>> =
                patch.control_points().chunks(dv + 1).map(<[DVec3]>::to_vec).collect();
            patches.push(grid_array(py, &rows)?);
        }
        let out = PyDict::new(py);
        out.set_item("patches", patches)?;
        out.set_item("u_breaks", from_points(py, &b.u_breaks))?;
        out.set_item("v_breaks", from_points(py, &b.v_breaks))?;
        out.set_item("scheme", scheme.name())?;
        out.set_item("report", to_python(py, &b.report)?)?;
        Ok(out)
    }
}

/// Rows of points as an array of shape (rows, columns, 3).
pub(crate) fn grid_array<'py>(py: Python<'py>, rows: &[Vec<DVec3>]) -> PyResult<Bound<'py, PyAny>> {
    let (m, n) = (rows.len(), rows.first().map_or(0, Vec::len));
    let flat: Vec<f64> = rows.iter().flatten().flat_map(|p| p.to_array()).collect();
    let array = Array3::from_shape_vec((m, n, 3), flat).map_err(value_error)?;
    Ok(array.into_pyarray(py).into_any())
}

/// The names `example` takes: `sphere` and `torus` (exact harmonic surfaces) and the test
/// surfaces of §5.9.
///
/// >>> harmonic.examples()[:2]
/// ['sphere', 'torus']
#[pyfunction]
pub(crate) fn examples() -> Vec<&'static str> {
    let mut names = vec!["sphere", "torus"];
    names.extend(
        hi_surface::test_surfaces()
            .iter()
            .map(|s| s.name)
            .filter(|n| *n != "sphere" && *n != "torus"),
    );
    names
}

/// An example surface: `sphere` (radius 1) and `torus` (radii 2 and 1), exact harmonic
/// surfaces; or a test surface of §5.9 by name or figure number (`"5.33"`) sampled on its
/// grid, or on `samples` = (m, n).
///
/// >>> harmonic.example("torus").shape
/// (4, 4)
#[pyfunction]
#[pyo3(signature = (name, samples = None))]
pub(crate) fn example(name: &str, samples: Option<(usize, usize)>) -> PyResult<PyHarmonicSurface> {
    let exact = match name {
        "sphere" => Some(hi_surface::sphere(SPHERE_RADIUS)),
        "torus" => Some(hi_surface::torus(TORUS_RADII.0, TORUS_RADII.1)),
        _ => None,
    };
    if let Some(surface) = exact {
        let Some((m, n)) = samples else { return Ok(PyHarmonicSurface { inner: surface }) };
        let s = surface.sample_uniform(m, n, 0, 0).map_err(value_error)?;
        let rows: Vec<Vec<DVec3>> = s.values.chunks(n.max(1)).map(<[DVec3]>::to_vec).collect();
        return Ok(PyHarmonicSurface {
            inner: HarmonicSurface::try_new(rows).map_err(value_error)?,
        });
    }
    let surface = hi_surface::test_surfaces()
        .into_iter()
        .find(|s| s.name == name || s.figure == name)
        .ok_or_else(|| {
            value_error(format!(
                "unknown example surface '{name}': expected one of {} or a figure number 5.31 to 5.43",
                examples().join(", ")
            ))
        })?;
    let (m, n) = samples.unwrap_or(surface.samples);
    if m == 0 || n == 0 || m.saturating_mul(n) > 1 << 24 {
        return Err(value_error(format!("samples: {m}x{n}: expected 1 to 2^24 points")));
    }
    let rows = surface.sample_grid(m, n);
    Ok(PyHarmonicSurface { inner: HarmonicSurface::try_new(rows).map_err(value_error)? })
}
