// SPDX-License-Identifier: MIT
//! Curves: `HarmonicCurve` (thesis chapter 3: X(t) = Σₖ σⁿₖ(t)·xₖ, eq. 3.1; Theorems 5.1 and
//! 5.3; the Bézier forms of §5.7) and `Curve`, the comparison curves of chapter 2 by kind.

use glam::{DVec2, DVec3};
use hi_compare::{AnyCurve, CurveKind};
use hi_curve::bezier::{BezierScheme, DEFAULT_TOLERANCE, Tolerance};
use hi_curve::{ControlPoint, HarmonicCurve, ParamCurve, PlaneCurve};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::arrays::{Params, Points, from_point, from_points, params, to_python};
use crate::errors::value_error;

/// A harmonic curve of scalar values, plane points or space points.
#[derive(Clone, Debug)]
enum Harmonic {
    One(HarmonicCurve<f64>),
    Two(HarmonicCurve<DVec2>),
    Three(HarmonicCurve<DVec3>),
}

/// Runs `$body` on the curve inside `$inner`, whatever its dimension, as `$c`.
macro_rules! each {
    ($inner:expr, $c:ident => $body:expr) => {
        match $inner {
            Harmonic::One($c) => $body,
            Harmonic::Two($c) => $body,
            Harmonic::Three($c) => $body,
        }
    };
}

/// Values at one parameter (a point) or many (an array of points, one row each).
fn at<'py, P: ControlPoint>(
    py: Python<'py>,
    t: &Params,
    f: impl Fn(f64) -> P,
) -> PyResult<Bound<'py, PyAny>> {
    match t {
        Params::One(t) => from_point(py, &f(*t)),
        Params::Many(ts) => {
            let values: Vec<P> = ts.iter().map(|&t| f(t)).collect();
            Ok(from_points(py, &values).into_any())
        }
    }
}

/// Curvatures at one parameter (a float, or None where undefined) or many (an array, NaN
/// where undefined).
fn curvatures<'py>(
    py: Python<'py>,
    t: &Params,
    f: impl Fn(f64) -> Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    match t {
        Params::One(t) => Ok(f(*t).into_pyobject(py)?.into_any()),
        Params::Many(ts) => {
            let values: Vec<f64> = ts.iter().map(|&t| f(t).unwrap_or(f64::NAN)).collect();
            Ok(from_points(py, &values).into_any())
        }
    }
}

/// The harmonic curve through the points x₀, …, xₙ₋₁: X(t) = Σₖ σⁿₖ(t)·xₖ, a smooth
/// 1-periodic curve with X(k/n) = xₖ (thesis §3.2, eq. 3.1).
///
/// `points` has shape (n,) (values), (n, 2) or (n, 3); a NaN or infinite coordinate is a
/// `ValueError`.
///
/// >>> import numpy as np, harmonic
/// >>> c = harmonic.HarmonicCurve([[1, 0], [0, 1], [-1, 0], [0, -1]])
/// >>> bool(np.allclose(c.eval(0.125), [np.sqrt(0.5), np.sqrt(0.5)]))
/// True
/// >>> round(c.curvature(0.3), 12)
/// 1.0
#[pyclass(name = "HarmonicCurve", module = "harmonic", frozen)]
#[derive(Debug)]
pub(crate) struct PyHarmonicCurve {
    inner: Harmonic,
}

impl PyHarmonicCurve {
    /// The curve through `points`.
    fn build(points: Points) -> PyResult<Self> {
        let inner = match points {
            Points::One(p) => Harmonic::One(HarmonicCurve::try_new(p).map_err(value_error)?),
            Points::Two(p) => Harmonic::Two(HarmonicCurve::try_new(p).map_err(value_error)?),
            Points::Three(p) => Harmonic::Three(HarmonicCurve::try_new(p).map_err(value_error)?),
        };
        Ok(Self { inner })
    }
}

#[pymethods]
impl PyHarmonicCurve {
    #[new]
    fn new(points: &Bound<'_, PyAny>) -> PyResult<Self> {
        Self::build(crate::arrays::points(points, "points")?)
    }

    /// The interpolated points xₖ, shape (n,) or (n, d).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        each!(&self.inner, c => from_points(py, c.points()).into_any())
    }

    /// The dimension of the points: 1, 2 or 3.
    #[getter]
    fn dim(&self) -> usize {
        each!(&self.inner, c => dim_of(c.points()))
    }

    fn __len__(&self) -> usize {
        each!(&self.inner, c => c.points().len())
    }

    fn __repr__(&self) -> String {
        format!("HarmonicCurve(n={}, dim={})", self.__len__(), self.dim())
    }

    /// X(t) at a parameter (a point) or at each of an array of parameters (shape (m, d)).
    ///
    /// >>> harmonic.HarmonicCurve([0.0, 1.0, 0.0]).eval(1 / 3)
    /// 1.0
    fn eval<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let t = params(t, "t")?;
        each!(&self.inner, c => at(py, &t, |t| c.eval(t)))
    }

    /// The derivative of order `order` (≥ 0) of X at `t` (one parameter or an array).
    #[pyo3(signature = (t, order = 1))]
    fn derivative<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        order: usize,
    ) -> PyResult<Bound<'py, PyAny>> {
        let t = params(t, "t")?;
        each!(&self.inner, c => at(py, &t, |t| c.eval_deriv(t, order)))
    }

    /// The curvature at `t`: signed for a plane curve (positive turning left), unsigned in
    /// space; None (NaN in an array) where X′ = 0. A curve of values has none (`ValueError`).
    fn curvature<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let t = params(t, "t")?;
        match &self.inner {
            Harmonic::One(_) => Err(value_error("a curve of scalar values has no curvature")),
            Harmonic::Two(c) => curvatures(py, &t, |t| c.signed_curvature(t)),
            Harmonic::Three(c) => curvatures(py, &t, |t| c.curvature(t)),
        }
    }

    /// X at `count` equally spaced parameters t = j / count, by the FFT (O(N log N)); shape
    /// (count,) or (count, d).
    fn sample_uniform<'py>(&self, py: Python<'py>, count: usize) -> PyResult<Bound<'py, PyAny>> {
        let inner = self.inner.clone();
        each!(inner, c => {
            let samples = py.detach(|| c.sample_uniform(count)).map_err(value_error)?;
            Ok(from_points(py, &samples).into_any())
        })
    }

    /// The curve started `offset` of a period later: X(t + offset) as a harmonic curve of the
    /// same n (exact for every n), or Theorem 5.1's construction with `exact=False`.
    #[pyo3(signature = (offset, exact = true))]
    fn rotate(&self, offset: f64, exact: bool) -> PyResult<Self> {
        let inner = each!(&self.inner, c => {
            let r = if exact { c.rotate(offset) } else { c.rotate_theorem_5_1(offset) };
            wrap(r.map_err(value_error)?)
        });
        Ok(Self { inner })
    }

    /// The curve through `count` points of this one (Theorem 5.3: insertion for more points,
    /// reduction with a measured error for fewer). With `with_error=True`, also the measured
    /// deviation and its bound as a dict.
    #[pyo3(signature = (count, with_error = false))]
    fn resample<'py>(
        &self,
        py: Python<'py>,
        count: usize,
        with_error: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (inner, max, bound) = each!(&self.inner, c => {
            let (r, e) = c.resample(count).map_err(value_error)?;
            (wrap(r), e.max_deviation, e.upper_bound)
        });
        let curve = Bound::new(py, Self { inner })?.into_any();
        if !with_error {
            return Ok(curve);
        }
        let error = PyDict::new(py);
        error.set_item("max_error", max)?;
        error.set_item("error_bound", bound)?;
        Ok((curve, error).into_pyobject(py)?.into_any())
    }

    /// Bézier pieces of the curve by a §5.7 scheme (`hermite`, the default, C1 cubic pieces
    /// split until a guaranteed bound is below `tolerance`; `hermite-quintic`, `thesis-cubic`,
    /// `thesis-quintic`): a dict of `segments` (a list of control-point arrays, shape
    /// (degree + 1, d)), `breaks` (the pieces' parameters) and `report`.
    #[pyo3(signature = (scheme = "hermite", tolerance = None))]
    fn to_bezier<'py>(
        &self,
        py: Python<'py>,
        scheme: &str,
        tolerance: Option<f64>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (scheme, tolerance) = bezier_options(scheme, tolerance)?;
        let out = PyDict::new(py);
        let inner = self.inner.clone();
        each!(inner, c => {
            let b = py.detach(|| c.to_bezier(scheme, tolerance)).map_err(value_error)?;
            let segments: Vec<Bound<'py, PyAny>> = b
                .spline
                .segments()
                .iter()
                .map(|s| from_points(py, s.control_points()).into_any())
                .collect();
            out.set_item("segments", segments)?;
            out.set_item("breaks", from_points(py, b.spline.breaks()))?;
            out.set_item("scheme", scheme.name())?;
            out.set_item("report", to_python(py, &b.report)?)?;
        });
        Ok(out)
    }
}

/// The dimension of points of type `P`.
/// The §5.7 scheme named `scheme` and the absolute `tolerance` (the library's default when
/// `None`) of a `to_bezier` call, shared by curves and surfaces.
pub(crate) fn bezier_options(
    scheme: &str,
    tolerance: Option<f64>,
) -> PyResult<(BezierScheme, Tolerance)> {
    let scheme = BezierScheme::from_name(scheme).ok_or_else(|| {
        value_error(format!(
            "unknown scheme '{scheme}' (expected hermite, hermite-quintic, thesis-cubic or thesis-quintic)"
        ))
    })?;
    Ok((scheme, tolerance.map_or(DEFAULT_TOLERANCE, Tolerance::Absolute)))
}

fn dim_of<P: ControlPoint>(_: &[P]) -> usize {
    P::DIM
}

/// The point types a curve may have, each with its place in the enums of this module.
trait Dim: ControlPoint {
    /// The harmonic curve in [`Harmonic`].
    fn harmonic(c: HarmonicCurve<Self>) -> Harmonic;
}

impl Dim for f64 {
    fn harmonic(c: HarmonicCurve<Self>) -> Harmonic {
        Harmonic::One(c)
    }
}

impl Dim for DVec2 {
    fn harmonic(c: HarmonicCurve<Self>) -> Harmonic {
        Harmonic::Two(c)
    }
}

impl Dim for DVec3 {
    fn harmonic(c: HarmonicCurve<Self>) -> Harmonic {
        Harmonic::Three(c)
    }
}

/// A harmonic curve of any dimension in the enum.
fn wrap<P: Dim>(curve: HarmonicCurve<P>) -> Harmonic {
    P::harmonic(curve)
}

/// A comparison curve of scalar values, plane points or space points.
#[derive(Clone, Debug)]
enum Comparison {
    One(AnyCurve<f64>),
    Two(AnyCurve<DVec2>),
    Three(AnyCurve<DVec3>),
}

/// Runs `$body` on the comparison curve inside `$inner` as `$c`.
macro_rules! each_kind {
    ($inner:expr, $c:ident => $body:expr) => {
        match $inner {
            Comparison::One($c) => $body,
            Comparison::Two($c) => $body,
            Comparison::Three($c) => $body,
        }
    };
}

/// The names of the curve kinds `Curve` takes, in the thesis's order (chapter 2, §4.5).
///
/// >>> harmonic.curve_kinds()[:3]
/// ['harmonic', 'trig', 'lagrange']
#[pyfunction]
pub(crate) fn curve_kinds() -> Vec<&'static str> {
    CurveKind::ALL.iter().map(|k| k.name()).collect()
}

/// A curve of the thesis's comparisons through the points, by kind (chapter 2 and §4.5):
/// `harmonic`, `trig`, `lagrange`, `catmull-rom`, `bessel-overhauser`, `tcb`,
/// `bspline-periodic`, `bspline-open`, `hobby-closed`, `hobby-open`, `chaikin`, `four-point`
/// (see `curve_kinds()`), over t in [0, 1] (1-periodic when closed).
///
/// >>> c = harmonic.Curve([[1, 0], [0, 1], [-1, 0], [0, -1]], "catmull-rom")
/// >>> c.eval(0.25).tolist()
/// [0.0, 1.0]
#[pyclass(name = "Curve", module = "harmonic", frozen)]
#[derive(Debug)]
pub(crate) struct PyCurve {
    inner: Comparison,
}

#[pymethods]
impl PyCurve {
    #[new]
    #[pyo3(signature = (points, kind = "harmonic"))]
    fn new(points: &Bound<'_, PyAny>, kind: &str) -> PyResult<Self> {
        let kind: CurveKind = kind.parse().map_err(value_error)?;
        let inner = match crate::arrays::points(points, "points")? {
            Points::One(p) => Comparison::One(kind.build(p).map_err(value_error)?),
            Points::Two(p) => Comparison::Two(kind.build(p).map_err(value_error)?),
            Points::Three(p) => Comparison::Three(kind.build(p).map_err(value_error)?),
        };
        Ok(Self { inner })
    }

    /// The kind's name.
    #[getter]
    fn kind(&self) -> &'static str {
        each_kind!(&self.inner, c => c.kind().name())
    }

    /// The points it interpolates (or, for the B-spline and subdivision kinds, is built on).
    #[getter]
    fn points<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        each_kind!(&self.inner, c => from_points(py, c.points()).into_any())
    }

    fn __repr__(&self) -> String {
        let n = each_kind!(&self.inner, c => c.points().len());
        format!("Curve(kind={:?}, n={n})", self.kind())
    }

    /// The curve at a parameter or an array of them.
    fn eval<'py>(&self, py: Python<'py>, t: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let t = params(t, "t")?;
        each_kind!(&self.inner, c => at(py, &t, |t| c.eval(t)))
    }

    /// The derivative of order `order` at a parameter or an array of them.
    #[pyo3(signature = (t, order = 1))]
    fn derivative<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        order: usize,
    ) -> PyResult<Bound<'py, PyAny>> {
        let t = params(t, "t")?;
        each_kind!(&self.inner, c => at(py, &t, |t| c.eval_deriv(t, order)))
    }

    /// The curvature (signed in the plane, unsigned in space; None or NaN where undefined).
    fn curvature<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let t = params(t, "t")?;
        match &self.inner {
            Comparison::One(_) => Err(value_error("a curve of scalar values has no curvature")),
            Comparison::Two(c) => curvatures(py, &t, |t| c.signed_curvature(t)),
            Comparison::Three(c) => curvatures(py, &t, |t| c.curvature(t)),
        }
    }

    /// The curve at `count` equally spaced parameters (over the period when closed, from end
    /// to end when open).
    fn sample<'py>(&self, py: Python<'py>, count: usize) -> PyResult<Bound<'py, PyAny>> {
        each_kind!(&self.inner, c => {
            let samples = c.sample(count).map_err(value_error)?;
            Ok(from_points(py, &samples).into_any())
        })
    }

    /// The curve's exact piecewise Bézier form (the polynomial kinds): a list of control-point
    /// arrays, one per segment.
    fn to_bezier<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyAny>>> {
        each_kind!(&self.inner, c => {
            let b = c.to_bezier().map_err(value_error)?;
            Ok(b.segments().iter().map(|s| from_points(py, s.control_points()).into_any()).collect())
        })
    }
}
