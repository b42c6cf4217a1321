// SPDX-License-Identifier: MIT
//! The `harmonic` Python package's native module, `harmonic._harmonic` (`PyO3`, one abi3
//! wheel for `CPython` ≥ 3.9): the `hi-*` libraries with `NumPy` arrays in and out.
//!
//! - curves (`curve`): `HarmonicCurve` (thesis chapters 3 and 5) and the comparison curves of
//!   chapter 2 by kind (`Curve`);
//! - surfaces (`surface`): `HarmonicSurface` (§5.1, §5.2), the examples of §5.9, meshes and
//!   Bézier patches (§5.7);
//! - meshes (`mesh`): `subdivide` (§4.5) and `render` (§5.5, §5.6);
//! - fitting (`fit`): `fit` and the batch functions behind `fit_many`, on `hi-fit`, the
//!   pipeline the `hi fit` command runs.
//!
//! Every error of the libraries becomes a Python exception carrying the library's one-line
//! message (`errors`); long work runs with the interpreter released (`Python::detach`).
//! The Python side (`python/harmonic`) adds `fit_many` over a Dask cluster, the type stubs and
//! the docstrings' examples.

mod arrays;
mod curve;
mod errors;
mod fit;
mod mesh;
mod surface;

use pyo3::prelude::*;

/// The native module: its classes and functions, documented in `harmonic`'s stubs.
#[pymodule]
fn _harmonic(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<curve::PyHarmonicCurve>()?;
    m.add_class::<curve::PyCurve>()?;
    m.add_function(wrap_pyfunction!(curve::curve_kinds, m)?)?;
    m.add_class::<surface::PyHarmonicSurface>()?;
    m.add_function(wrap_pyfunction!(surface::example, m)?)?;
    m.add_function(wrap_pyfunction!(surface::examples, m)?)?;
    m.add_function(wrap_pyfunction!(mesh::subdivide, m)?)?;
    m.add_function(wrap_pyfunction!(mesh::render, m)?)?;
    m.add_class::<fit::PyFitResult>()?;
    m.add_function(wrap_pyfunction!(fit::fit, m)?)?;
    m.add_function(wrap_pyfunction!(fit::expand, m)?)?;
    m.add_function(wrap_pyfunction!(fit::plan, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit_one, m)?)?;
    m.add_function(wrap_pyfunction!(fit::append_line, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit_many_local, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
