# SPDX-License-Identifier: MIT
"""Bad inputs raise Python exceptions of the right kind, each with the message ``hi``
prints for the same input."""

import numpy as np
import pytest

import harmonic
from conftest import MODELS, ellipsoid, hi_error, write_xyz


def test_a_missing_scan_is_a_file_not_found_error_with_hi_fits_message(tmp_path):
    missing = tmp_path / "missing.obj"
    with pytest.raises(FileNotFoundError) as e:
        harmonic.fit(missing)
    assert str(e.value) == hi_error("fit", missing, "-o", tmp_path / "o.glb")


def test_a_malformed_scan_is_a_value_error_naming_the_line(tmp_path):
    bad = tmp_path / "bad.xyz"
    bad.write_text("0 0 0\n1 0 0\n0 1\n")
    with pytest.raises(ValueError, match="XYZ, line 3: expected 3 numbers") as e:
        harmonic.fit(bad)
    assert str(e.value) == hi_error("fit", bad, "-o", tmp_path / "o.glb")
    las = tmp_path / "scan.las"
    las.write_text("x")
    with pytest.raises(ValueError, match="unknown scan format"):
        harmonic.fit(las)


def test_a_scan_that_cannot_be_fitted_is_a_value_error(tmp_path):
    few = write_xyz(tmp_path / "few.xyz", ellipsoid(3))
    with pytest.raises(ValueError) as e:
        harmonic.fit(few)
    assert str(e.value) == hi_error("fit", few, "-o", tmp_path / "o.glb")
    with pytest.raises(ValueError, match="method"):
        harmonic.fit(MODELS / "spot.obj", method="magic")


def test_bad_arrays_name_the_argument_and_the_shape():
    with pytest.raises(ValueError, match=r"scan: expected shape \(n, 3\), got \(4, 2\)"):
        harmonic.fit(np.zeros((4, 2)))
    with pytest.raises(TypeError, match="points: expected an array of numbers"):
        harmonic.HarmonicCurve([["a", "b"]])
    with pytest.raises(ValueError, match="grid: expected shape"):
        harmonic.HarmonicSurface(np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"points: expected shape \(n,\), \(n, 2\) or \(n, 3\)"):
        harmonic.HarmonicCurve(np.zeros((3, 4)))
    with pytest.raises(ValueError, match="scan faces: face 0 has vertex index -1"):
        harmonic.fit((ellipsoid(10), [[0, 1, -1]]))
    with pytest.raises(ValueError, match="triangle 0 uses vertex 10"):
        harmonic.fit((ellipsoid(10), [[0, 1, 10]]))


def test_library_errors_carry_the_librarys_message():
    out = hi_error("curve", "eval", "--input", "/dev/null", "--t", "0")
    assert out  # hi names the empty input
    with pytest.raises(ValueError) as e:
        harmonic.HarmonicCurve(np.array([[0.0, np.nan]]))
    assert "finite" in str(e.value) or "NaN" in str(e.value)
    with pytest.raises(ValueError, match="unknown"):
        harmonic.Curve([[0, 0], [1, 0], [0, 1]], "spline-of-dreams")
    with pytest.raises(ValueError, match="unknown scheme 'wavy'"):
        harmonic.subdivide([[0, 0, 0]], [[0, 0, 0]], "wavy", 1)
    with pytest.raises(ValueError, match="levels"):
        harmonic.subdivide([[0, 0, 0]], [[0, 0, 0]], "loop", 99)
    with pytest.raises(ValueError, match="unknown example surface"):
        harmonic.example("teacup")
    with pytest.raises(ValueError, match="u has 2 values and v has 1"):
        harmonic.example("sphere").eval([0.1, 0.2], [0.3])
    with pytest.raises(TypeError, match="render: expected a HarmonicSurface"):
        harmonic.render(42)
    with pytest.raises(ValueError, match="unknown method"):
        harmonic.render(harmonic.example("sphere"), method="crayon", width=4, height=4)
    with pytest.raises(ValueError):
        harmonic.HarmonicCurve([[0.0, 0.0]]).sample_uniform(0)
