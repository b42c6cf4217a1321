// SPDX-License-Identifier: MIT
//! `NumPy` arrays in and out: points, grids and faces read from anything array-like (checked,
//! with errors naming the argument and the shape it has), and results as `float64` arrays.

use glam::{DVec2, DVec3};
use hi_curve::ControlPoint;
use numpy::ndarray::{Array1, Array2, ArrayD};
use numpy::{AllowTypeChange, IntoPyArray, PyArrayDyn, PyArrayLike2, PyArrayLikeDyn};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

/// The array `value` as `float64` (lists, tuples and arrays of any real type are converted).
pub(crate) fn floats(value: &Bound<'_, PyAny>, what: &str) -> PyResult<ArrayD<f64>> {
    let array: PyArrayLikeDyn<'_, f64, AllowTypeChange> = value
        .extract()
        .map_err(|_| PyTypeError::new_err(format!("{what}: expected an array of numbers")))?;
    Ok(array.as_array().to_owned())
}

/// The shape of an array, as Python writes it.
fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!("({})", shape.iter().map(usize::to_string).collect::<Vec<_>>().join(", ")),
    }
}

/// The points of a curve: shape (n,) for scalar values, (n, 2) or (n, 3).
#[derive(Debug)]
pub(crate) enum Points {
    /// Values.
    One(Vec<f64>),
    /// Plane points.
    Two(Vec<DVec2>),
    /// Space points.
    Three(Vec<DVec3>),
}

/// The points in `value` (see [`Points`]).
pub(crate) fn points(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Points> {
    let a = floats(value, what)?;
    let flat: Vec<f64> = a.iter().copied().collect();
    match a.shape() {
        [_] => Ok(Points::One(flat)),
        [_, 2] => Ok(Points::Two(flat.chunks_exact(2).map(|c| DVec2::new(c[0], c[1])).collect())),
        [_, 3] => {
            Ok(Points::Three(flat.chunks_exact(3).map(|c| DVec3::new(c[0], c[1], c[2])).collect()))
        }
        shape => Err(PyValueError::new_err(format!(
            "{what}: expected shape (n,), (n, 2) or (n, 3), got {}",
            shape_text(shape)
        ))),
    }
}

/// Points in space: shape (n, 3).
pub(crate) fn points3(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<DVec3>> {
    let a = floats(value, what)?;
    match a.shape() {
        [_, 3] => {
            let flat: Vec<f64> = a.iter().copied().collect();
            Ok(flat.chunks_exact(3).map(|c| DVec3::new(c[0], c[1], c[2])).collect())
        }
        shape => Err(PyValueError::new_err(format!(
            "{what}: expected shape (n, 3), got {}",
            shape_text(shape)
        ))),
    }
}

/// A grid of points in space: shape (m, n, 3), rows first.
pub(crate) fn grid(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Vec<DVec3>>> {
    let a = floats(value, what)?;
    match *a.shape() {
        [_, n, 3] if n > 0 => {
            let flat: Vec<f64> = a.iter().copied().collect();
            let points: Vec<DVec3> =
                flat.chunks_exact(3).map(|c| DVec3::new(c[0], c[1], c[2])).collect();
            Ok(points.chunks(n).map(<[DVec3]>::to_vec).collect())
        }
        _ => Err(PyValueError::new_err(format!(
            "{what}: expected shape (m, n, 3), got {}",
            shape_text(a.shape())
        ))),
    }
}

/// Polygon faces: an (k, s) integer array, or a sequence of sequences of vertex indices (faces
/// of different sizes); every index checked to be a `u32`.
pub(crate) fn faces(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Vec<u32>>> {
    let rows: Vec<Vec<i64>> =
        if let Ok(array) = value.extract::<PyArrayLike2<'_, i64, AllowTypeChange>>() {
            array.as_array().rows().into_iter().map(|r| r.to_vec()).collect()
        } else {
            value.extract().map_err(|_| {
                PyTypeError::new_err(format!(
                    "{what}: expected an array of vertex indices, shape (k, 3), or a list of faces"
                ))
            })?
        };
    rows.iter()
        .enumerate()
        .map(|(f, row)| {
            row.iter()
                .map(|&k| {
                    u32::try_from(k).map_err(|_| {
                        PyValueError::new_err(format!(
                            "{what}: face {f} has vertex index {k}, which is not an index"
                        ))
                    })
                })
                .collect()
        })
        .collect()
}

/// Triangles: faces of three vertices each.
pub(crate) fn triangles(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<[u32; 3]>> {
    faces(value, what)?
        .into_iter()
        .enumerate()
        .map(|(f, face)| {
            <[u32; 3]>::try_from(face.as_slice()).map_err(|_| {
                PyValueError::new_err(format!(
                    "{what}: face {f} has {} vertices; expected triangles",
                    face.len()
                ))
            })
        })
        .collect()
}

/// Points as an array: shape (n,) for scalar values, (n, d) otherwise.
pub(crate) fn from_points<'py, P: ControlPoint>(
    py: Python<'py>,
    points: &[P],
) -> Bound<'py, PyArrayDyn<f64>> {
    // Filled in place at its final size: a collected `flat_map` has no size hint, and grew
    // (and copied) a large result several times.
    let mut flat: Vec<f64> = Vec::with_capacity(points.len() * P::DIM);
    for p in points {
        for i in 0..P::DIM {
            flat.push(p.coord(i));
        }
    }
    let shape: Vec<usize> =
        if P::DIM == 1 { vec![points.len()] } else { vec![points.len(), P::DIM] };
    // The shape holds exactly the values made above.
    ArrayD::from_shape_vec(shape, flat).unwrap_or_else(|_| ArrayD::zeros(vec![0])).into_pyarray(py)
}

/// One point as an array of its coordinates, or a float for a scalar.
pub(crate) fn from_point<'py, P: ControlPoint>(
    py: Python<'py>,
    p: &P,
) -> PyResult<Bound<'py, PyAny>> {
    if P::DIM == 1 {
        return Ok(p.coord(0).into_pyobject(py)?.into_any());
    }
    let coords: Vec<f64> = (0..P::DIM).map(|i| p.coord(i)).collect();
    Ok(Array1::from(coords).into_pyarray(py).into_any())
}

/// Faces as an (k, 3) `int64` array, or a list of lists when their sizes differ.
pub(crate) fn from_faces<'py>(py: Python<'py>, faces: &[Vec<u32>]) -> PyResult<Bound<'py, PyAny>> {
    let size = faces.first().map_or(3, Vec::len);
    if faces.iter().all(|f| f.len() == size) {
        let flat: Vec<i64> = faces.iter().flatten().map(|&k| i64::from(k)).collect();
        let array = Array2::from_shape_vec((faces.len(), size), flat)
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        return Ok(array.into_pyarray(py).into_any());
    }
    Ok(faces.to_vec().into_pyobject(py)?.into_any())
}

/// Triangles as an (k, 3) `int64` array.
pub(crate) fn from_triangles<'py>(
    py: Python<'py>,
    triangles: &[[u32; 3]],
) -> PyResult<Bound<'py, PyAny>> {
    let faces: Vec<Vec<u32>> = triangles.iter().map(|t| t.to_vec()).collect();
    from_faces(py, &faces)
}

/// Values at one parameter or many: a float gives one value, anything else an array of them.
pub(crate) enum Params {
    /// One parameter.
    One(f64),
    /// Several, with the array's shape.
    Many(Vec<f64>),
}

/// The parameter(s) in `value`.
pub(crate) fn params(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Params> {
    if let Ok(t) = value.extract::<f64>() {
        return Ok(Params::One(t));
    }
    let a = floats(value, what)?;
    if a.ndim() != 1 {
        return Err(PyValueError::new_err(format!(
            "{what}: expected a number or a 1-D array, got shape {}",
            shape_text(a.shape())
        )));
    }
    Ok(Params::Many(a.iter().copied().collect()))
}

/// A value with a `serde` form as the Python object `json.loads` makes of it (dicts, lists,
/// floats), for reports.
pub(crate) fn to_python<'py>(
    py: Python<'py>,
    value: &impl serde::Serialize,
) -> PyResult<Bound<'py, PyAny>> {
    let text = serde_json::to_string(value).map_err(|e| PyValueError::new_err(e.to_string()))?;
    py.import("json")?.call_method1("loads", (text,))
}
