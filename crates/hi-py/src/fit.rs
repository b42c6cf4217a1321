// SPDX-License-Identifier: MIT
//! Fitting (thesis §5.3, §5.4, §5.8, and past the thesis where `hi-geomimage` goes): `fit`, a
//! harmonic surface for each part of a scan, and the batch functions behind `fit_many` — all on
//! `hi-fit`, the pipeline `hi fit` runs, so that the surfaces, report and errors are the same.

use std::path::PathBuf;

use glam::DVec3;
use hi_fit::batch::{self, BatchOptions, Job};
use hi_fit::{OutputFormat, fit_scan, part_meshes, read_scan, summary, warnings};
use hi_geomimage::fit::Boundary;
use hi_geomimage::{ErrorMeasure, FitOptions, Layout, Method};
use hi_scan::scan::Scan;
use pyo3::prelude::*;
use pyo3::types::PyList;

use crate::arrays::{from_points, from_triangles, points3, to_python, triangles};
use crate::errors::{fit_error, value_error};
use crate::surface::{PyHarmonicSurface, grid_array};

/// The options of a fit from `fit`'s keywords, as `hi fit` reads its flags.
fn options(
    method: &str,
    param: &str,
    resolution: Option<(usize, usize)>,
    boundary: &str,
    error: &str,
) -> PyResult<FitOptions> {
    let method = match method {
        "auto" => Method::Auto,
        "mesh" => Method::Mesh,
        "shrink-wrap" => Method::ShrinkWrap,
        "radial" => Method::Radial,
        "contours" => Method::Contours,
        other => {
            return Err(value_error(format!(
                "method: unknown method '{other}' (expected auto, mesh, shrink-wrap, radial or contours)"
            )));
        }
    };
    let layout = match param {
        "sphere" => Layout::Sphere,
        "octahedron" => Layout::Octahedron,
        "flat-octahedron" => Layout::FlatOctahedron,
        other => {
            return Err(value_error(format!(
                "param: unknown layout '{other}' (expected sphere, octahedron or flat-octahedron)"
            )));
        }
    };
    let boundary = match boundary {
        "auto" => Boundary::Auto,
        "closed" => Boundary::Closed,
        "open" => Boundary::Open,
        other => {
            return Err(value_error(format!(
                "boundary: unknown boundary '{other}' (expected auto, closed or open)"
            )));
        }
    };
    let error = match error {
        "fast" => ErrorMeasure::Fast,
        "exact" => ErrorMeasure::Exact,
        "off" => ErrorMeasure::Off,
        other => {
            return Err(value_error(format!(
                "error: unknown measure '{other}' (expected fast, exact or off)"
            )));
        }
    };
    Ok(FitOptions { method, layout, resolution, boundary, error, ..FitOptions::default() })
}

/// The scan of `fit`'s first argument, and its name in the report and errors.
fn scan_of(value: &Bound<'_, PyAny>) -> PyResult<(Scan, String)> {
    if let Ok(path) = value.extract::<PathBuf>() {
        let name = path.display().to_string();
        let scan = value.py().detach(|| read_scan(&path)).map_err(fit_error)?;
        return Ok((scan, name));
    }
    if let Ok((vertices, faces)) = value.extract::<(Bound<'_, PyAny>, Bound<'_, PyAny>)>() {
        let points = points3(&vertices, "scan vertices")?;
        let tris = triangles(&faces, "scan faces")?;
        return Ok((Scan::from_arrays(points, &tris).map_err(value_error)?, "mesh".to_owned()));
    }
    let points = points3(value, "scan")?;
    Ok((Scan::from_arrays(points, &[]).map_err(value_error)?, "points".to_owned()))
}

/// What `fit` returns: the fitted surface of each part, their meshes as one (`vertices`,
/// `faces`, as `trimesh.Trimesh(r.vertices, r.faces)` takes them), the largest part's geometry
/// image, the warnings `hi fit` prints and its report as a dict.
#[pyclass(name = "FitResult", module = "harmonic", frozen, get_all)]
#[derive(Debug)]
pub(crate) struct PyFitResult {
    /// The vertices of every part's mesh, shape (V, 3).
    vertices: Py<PyAny>,
    /// The triangles, shape (F, 3), indices into `vertices`.
    faces: Py<PyAny>,
    /// Each part's mesh as its own `(vertices, faces)`, largest part first.
    parts: Py<PyAny>,
    /// The largest part's geometry image, shape (rows, cols, 3).
    geometry_image: Py<PyAny>,
    /// The largest part's harmonic surface.
    surface: Py<PyHarmonicSurface>,
    /// Every part's harmonic surface, largest first.
    surfaces: Py<PyAny>,
    /// The report of the fit, as `hi fit` prints it (method, errors both ways, parts, …).
    report: Py<PyAny>,
    /// The warnings and notes, as `hi fit` prints them on stderr.
    warnings: Vec<String>,
}

#[pymethods]
impl PyFitResult {
    fn __repr__(&self, py: Python<'_>) -> String {
        let report = self.report.bind(py);
        let method = report.get_item("method").map(|m| m.to_string()).unwrap_or_default();
        let parts = self.parts.bind(py).len().unwrap_or(0);
        format!("FitResult(method={method}, parts={parts})")
    }
}

/// Fits a harmonic surface to each part of a scan through its geometry image, as `hi fit`
/// does (the same pipeline, report, warnings and errors). `scan` is a file path (OBJ, PLY,
/// OFF, STL, XYZ, PTS, glTF, GLB), an (n, 3) array of points, or a `(vertices, faces)` pair.
/// The keywords are `hi fit`'s: `method` (`auto`, `mesh`, `shrink-wrap`, `radial`,
/// `contours`), `param` (`flat-octahedron`, `octahedron`, `sphere`), `resolution` (rows, cols),
/// `boundary` (`auto`, `closed`, `open`) and `error` (`fast`, `exact`, `off`).
///
/// A missing file raises `FileNotFoundError`, a malformed scan or a fit that cannot be made
/// `ValueError`, each with `hi fit`'s message.
#[pyfunction]
#[pyo3(signature = (scan, *, method = "auto", param = "flat-octahedron", resolution = None,
                    boundary = "auto", error = "fast"))]
pub(crate) fn fit(
    py: Python<'_>,
    scan: &Bound<'_, PyAny>,
    method: &str,
    param: &str,
    resolution: Option<(usize, usize)>,
    boundary: &str,
    error: &str,
) -> PyResult<PyFitResult> {
    let options = options(method, param, resolution, boundary, error)?;
    let (scan, name) = scan_of(scan)?;
    let (fitted, meshes, lines) = py
        .detach(|| {
            let mut fitted = fit_scan(&scan, &name, &options, &mut |_| {})?;
            let meshes = part_meshes(&mut fitted, &name)?;
            let lines = warnings(&fitted, &name);
            Ok::<_, hi_fit::Error>((fitted, meshes, lines))
        })
        .map_err(fit_error)?;
    let report = to_python(py, &summary(&name, &fitted, &[], None))?;
    let mut vertices: Vec<DVec3> = Vec::new();
    let mut faces: Vec<[u32; 3]> = Vec::new();
    let parts = PyList::empty(py);
    for mesh in &meshes {
        let base = u32::try_from(vertices.len()).map_err(value_error)?;
        vertices.extend_from_slice(mesh.positions());
        faces.extend(mesh.triangles().iter().map(|t| t.map(|k| k + base)));
        parts.append((from_points(py, mesh.positions()), from_triangles(py, mesh.triangles())?))?;
    }
    let largest = fitted.largest();
    let image: Vec<Vec<DVec3>> =
        largest.image.texels().chunks(largest.image.cols()).map(<[DVec3]>::to_vec).collect();
    let surfaces = PyList::empty(py);
    for part in &fitted.parts {
        surfaces.append(PyHarmonicSurface { inner: part.surface.clone() })?;
    }
    Ok(PyFitResult {
        vertices: from_points(py, &vertices).into_any().unbind(),
        faces: from_triangles(py, &faces)?.unbind(),
        parts: parts.into_any().unbind(),
        geometry_image: grid_array(py, &image)?.unbind(),
        surface: Py::new(py, PyHarmonicSurface { inner: largest.surface.clone() })?,
        surfaces: surfaces.into_any().unbind(),
        report: report.unbind(),
        warnings: lines,
    })
}

/// A scan and its output.
type Pair = (PathBuf, PathBuf);

/// The batch's output format of a name.
fn format(name: &str) -> PyResult<OutputFormat> {
    OutputFormat::from_name(name).map_err(fit_error)
}

/// The scans named by paths, folders and glob patterns (`hi_fit::batch::expand`).
#[pyfunction]
pub(crate) fn expand(py: Python<'_>, inputs: Vec<PathBuf>) -> PyResult<Vec<PathBuf>> {
    py.detach(|| batch::expand(&inputs)).map_err(fit_error)
}

/// The (input, output) pairs to fit into `out_dir` and those skipped as done, by the resume
/// rule of `hi fit --out-dir` (`hi_fit::batch::plan`).
#[pyfunction]
#[pyo3(signature = (scans, out_dir, format = "glb", force = false))]
pub(crate) fn plan(
    scans: Vec<PathBuf>,
    out_dir: PathBuf,
    format: &str,
    force: bool,
) -> PyResult<(Vec<Pair>, Vec<Pair>)> {
    let plan = batch::plan(&scans, &out_dir, self::format(format)?, force).map_err(fit_error)?;
    let pairs = |jobs: Vec<Job>| jobs.into_iter().map(|j| (j.input, j.output)).collect();
    Ok((pairs(plan.jobs), pairs(plan.skipped)))
}

/// Fits one scan of a batch into `output` with the default options and returns its summary
/// line (JSON), never raising for the scan's own errors (`hi_fit::batch::fit_one`): the unit of
/// work of a cluster's worker.
#[pyfunction]
#[pyo3(signature = (input, output, format = "glb"))]
pub(crate) fn fit_one(
    py: Python<'_>,
    input: PathBuf,
    output: PathBuf,
    format: &str,
) -> PyResult<String> {
    let format = self::format(format)?;
    let job = Job { input, output };
    Ok(py.detach(|| batch::fit_one(&job, &FitOptions::default(), format).to_line()))
}

/// Appends a summary line to `out_dir/summary.jsonl`.
#[pyfunction]
pub(crate) fn append_line(out_dir: PathBuf, line: &str) -> PyResult<()> {
    batch::append_line(&out_dir, line).map_err(fit_error)
}

/// Fits every scan into `out_dir` on this machine, `jobs` at a time, as `hi fit SCAN...
/// --out-dir DIR` does (`hi_fit::batch::run`); returns the records as JSON lines (in the order
/// of the inputs) and the number skipped.
#[pyfunction]
#[pyo3(signature = (scans, out_dir, format = "glb", force = false, jobs = None))]
pub(crate) fn fit_many_local(
    py: Python<'_>,
    scans: Vec<PathBuf>,
    out_dir: PathBuf,
    format: &str,
    force: bool,
    jobs: Option<usize>,
) -> PyResult<(Vec<String>, usize)> {
    let cores = std::thread::available_parallelism().map_or(1, std::num::NonZero::get);
    let options = BatchOptions {
        format: self::format(format)?,
        force,
        jobs: jobs.unwrap_or(cores).max(1),
        fit: FitOptions::default(),
    };
    let outcome =
        py.detach(|| batch::run(&scans, &out_dir, &options, &|_, _, _| {})).map_err(fit_error)?;
    Ok((outcome.records.iter().map(batch::Record::to_line).collect(), outcome.skipped.len()))
}
