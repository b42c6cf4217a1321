# SPDX-License-Identifier: MIT
"""Surfaces: interpolation of the grid, the exact sphere and torus against algebra (radius,
curvatures), meshes read by trimesh (closed, outward, the sphere's volume), Bézier patches
against the surface, the examples of §5.9, and the ``hi surface eval`` command."""

import json

import numpy as np
import pytest
import trimesh

import harmonic
from conftest import hi_json


def test_the_surface_interpolates_its_grid():
    grid = np.random.default_rng(2).normal(size=(5, 6, 3))
    s = harmonic.HarmonicSurface(grid)
    assert s.shape == (5, 6)
    i, j = np.meshgrid(np.arange(5), np.arange(6), indexing="ij")
    np.testing.assert_allclose(s.eval(i.ravel() / 5, j.ravel() / 6), grid.reshape(-1, 3),
                               atol=1e-13)
    np.testing.assert_allclose(s.grid, grid)


def test_the_sphere_has_radius_one_and_unit_curvatures():
    s = harmonic.example("sphere")
    rng = np.random.default_rng(5)
    u, v = rng.uniform(0.05, 0.45, 50), rng.uniform(0, 1, 50)
    np.testing.assert_allclose(np.linalg.norm(s.eval(u, v), axis=1), 1.0, atol=1e-12)
    c = s.curvature(u, v)
    np.testing.assert_allclose(c["gaussian"], 1.0, rtol=1e-9)
    np.testing.assert_allclose(np.abs(c["mean"]), 1.0, rtol=1e-9)
    np.testing.assert_allclose(np.abs(np.sum(c["normal"] * s.eval(u, v), axis=1)), 1.0, atol=1e-9)


def test_the_torus_lies_at_distance_r_from_its_centre_circle():
    s = harmonic.example("torus")
    rng = np.random.default_rng(6)
    p = s.eval(rng.uniform(0, 1, 40), rng.uniform(0, 1, 40))
    ring = np.hypot(p[:, 0], p[:, 1])
    np.testing.assert_allclose(np.hypot(ring - 2.0, p[:, 2]), 1.0, atol=1e-12)


def test_partials_and_curvatures_are_those_of_hi_surface_eval(tmp_path):
    grid = np.random.default_rng(7).normal(size=(4, 5, 3))
    (tmp_path / "g.json").write_text(json.dumps({"grid": grid.tolist()}))
    u, v = [0.1, 0.6], [0.3, 0.8]
    out = hi_json("surface", "eval", "--input", tmp_path / "g.json", "--u", "0.1,0.6",
                  "--v", "0.3,0.8")
    s = harmonic.HarmonicSurface(grid)
    d = s.partials(u, v)
    for name in ["p", "pu", "pv", "puu", "puv", "pvv"]:
        np.testing.assert_allclose(d[name], out[name], rtol=1e-14, atol=1e-12, err_msg=name)
    c = s.curvature(u, v)
    np.testing.assert_allclose(c["gaussian"], out["gaussian"], rtol=1e-12)
    np.testing.assert_allclose(c["mean"], out["mean"], rtol=1e-12)
    np.testing.assert_allclose(s.derivative(u, v, 1, 1), out["puv"], rtol=1e-14, atol=1e-12)


@pytest.mark.parametrize("name,euler,window", [("sphere", 2, (0, 0.5, 0, 1)),
                                               ("torus", 0, (0, 1, 0, 1))])
def test_meshes_are_closed_and_outward_as_trimesh_reads_them(name, euler, window):
    # The harmonic sphere is the thesis's doubled sphere: once over u in [0, 1/2].
    vertices, faces = harmonic.example(name).mesh((48, 64), window)
    mesh = trimesh.Trimesh(vertices, faces, process=False)
    assert mesh.is_watertight and mesh.is_winding_consistent
    assert mesh.euler_number == euler
    assert mesh.volume > 0
    if name == "sphere":
        assert mesh.volume == pytest.approx(4 / 3 * np.pi, rel=0.01)


def test_bezier_patches_meet_the_surface_at_their_corners():
    s = harmonic.example("torus")
    b = s.to_bezier(tolerance=1e-5)
    ub, vb = b["u_breaks"], b["v_breaks"]
    assert len(b["patches"]) == (len(ub) - 1) * (len(vb) - 1)
    net = b["patches"][0]
    assert net.shape == (4, 4, 3)
    np.testing.assert_allclose(net[0, 0], s.eval(ub[0], vb[0]), atol=1e-9)
    np.testing.assert_allclose(net[-1, -1], s.eval(ub[1], vb[1]), atol=1e-9)
    assert b["report"]["max_deviation"] <= 1e-5


def test_the_examples_of_section_5_9():
    names = harmonic.examples()
    assert names[:2] == ["sphere", "torus"] and len(names) >= 13
    for name in names[2:]:
        s = harmonic.example(name)
        assert np.isfinite(s.eval(0.3, 0.4)).all()
    assert np.isfinite(harmonic.example("5.33").grid).all()
    assert harmonic.example("sphere", samples=(6, 8)).shape == (6, 8)
