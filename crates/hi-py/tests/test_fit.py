# SPDX-License-Identifier: MIT
"""``fit``: the same report, errors and warnings as ``hi fit`` on the committed and shared
models, meshes that trimesh reads as closed, scans given as arrays, and the GIL released."""

import json
import threading

import numpy as np
import pytest
import trimesh

import harmonic
from conftest import MODELS, ellipsoid, hi_json, shared_model


def same_fit_as_hi(scan, tmp_path):
    """Fits ``scan`` both ways and checks that the reports agree (times apart)."""
    r = harmonic.fit(scan)
    out = hi_json("fit", scan, "-o", tmp_path / "out.glb")
    for key in ["method", "method_reason", "points", "image", "surface", "topology", "parts",
                "both_ways", "errors", "dropped_parts", "mesh", "regularisation"]:
        assert r.report[key] == out[key], key
    assert [s["kind"] for s in r.report["stages"]] == [s["kind"] for s in out["stages"]]
    return r


def test_a_committed_model_fits_as_hi_fit_fits_it(tmp_path):
    r = same_fit_as_hi(MODELS / "spot.obj", tmp_path)
    mesh = trimesh.Trimesh(r.vertices, r.faces, process=False)
    assert mesh.is_watertight and mesh.is_winding_consistent and mesh.volume > 0
    assert r.geometry_image.shape == (*r.report["image"], 3) or r.geometry_image.ndim == 3
    assert r.surface.shape == tuple(r.report["surface"])
    assert r.report["both_ways"]["scan_to_surface"]["relative"][2] < 0.02
    assert isinstance(r.warnings, list)


@pytest.mark.parametrize("name", ["bunny.obj", "hoppe-mechpart.obj"])
def test_shared_models_fit_with_the_errors_of_hi_fit(name, tmp_path):
    same_fit_as_hi(shared_model(name), tmp_path)


def test_points_and_meshes_given_as_arrays_fit_as_their_files(tmp_path):
    from conftest import write_xyz

    points = ellipsoid(600, (2.0, 1.0, 1.0))
    path = write_xyz(tmp_path / "e.xyz", points)
    from_array = harmonic.fit(points)
    from_file = harmonic.fit(path)
    assert from_array.report["both_ways"] == from_file.report["both_ways"]
    np.testing.assert_array_equal(from_array.vertices, from_file.vertices)
    spot = trimesh.load(MODELS / "spot.obj", process=False)
    r = harmonic.fit((np.asarray(spot.vertices), np.asarray(spot.faces)))
    assert r.report["method"] == "mesh" and len(r.parts) == 1


def test_the_fit_releases_the_gil_while_it_works():
    # While a second thread is inside fit, this thread runs Python code: with the GIL held
    # by the fit, the worker would be finished before this thread could look.
    started = threading.Event()
    seen_alive = []

    def work():
        started.set()
        harmonic.fit(MODELS / "spot.obj")

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    for _ in range(200):
        threading.Event().wait(0.005)
        seen_alive.append(worker.is_alive())
        if len(seen_alive) > 3:
            break
    worker.join()
    assert any(seen_alive[1:]), "this thread ran while the fit was running"
