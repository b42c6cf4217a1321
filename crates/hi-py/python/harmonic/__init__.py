# SPDX-License-Identifier: MIT
"""Harmonic interpolation for smooth curves and surfaces (A. Hardy, 2005), from Python.

Curves, surfaces, subdivision, scan fitting and ray tracing from the ``hi-*`` Rust crates,
with NumPy arrays in and out:

- ``HarmonicCurve(points)``: the harmonic curve X(t) = sum_k sigma_k(t) x_k through the points
  (chapter 3); ``Curve(points, kind)``: the comparison curves of chapter 2 by kind;
- ``HarmonicSurface(grid)``: the tensor-product surface through an (m, n, 3) grid (section
  5.1), ``example(name)`` for the surfaces of section 5.9;
- ``subdivide(vertices, faces, scheme, levels)``: the schemes of section 4.5;
- ``fit(scan)``: a harmonic surface for each part of a scan, as ``hi fit`` fits it;
- ``fit_many(paths, out_dir, client=None)``: many scans into one folder, on this machine or on
  a Dask cluster, as ``hi fit SCAN... --out-dir DIR`` does;
- ``render(obj)``: a ray-traced image as an (h, w, 3) ``uint8`` array.

Errors are Python exceptions (``ValueError``, ``TypeError``, ``FileNotFoundError``, ...) with
the library's one-line message; long computations release the GIL.

>>> import numpy as np, harmonic
>>> c = harmonic.HarmonicCurve([[1, 0], [0, 1], [-1, 0], [0, -1]])
>>> c.sample_uniform(8).shape
(8, 2)
"""

from ._harmonic import (
    Curve,
    FitResult,
    HarmonicCurve,
    HarmonicSurface,
    __version__,
    curve_kinds,
    example,
    examples,
    fit,
    render,
    subdivide,
)
from .batch import fit_many

__all__ = [
    "Curve",
    "FitResult",
    "HarmonicCurve",
    "HarmonicSurface",
    "__version__",
    "curve_kinds",
    "example",
    "examples",
    "fit",
    "fit_many",
    "render",
    "subdivide",
]
