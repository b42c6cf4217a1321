# SPDX-License-Identifier: MIT
"""Subdivision against trimesh's Loop scheme and against the counts of the schemes' algebra;
rendering into an array of pixels."""

import json

import numpy as np
import pytest
import trimesh

import harmonic
from conftest import hi_json

TETRA_V = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float)
TETRA_F = np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])

CUBE_V = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
CUBE_F = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]


def test_loop_is_trimeshs_loop():
    v, f = harmonic.subdivide(TETRA_V, TETRA_F, "loop", 1)
    tv, tf = trimesh.remesh.subdivide_loop(TETRA_V, TETRA_F, iterations=1)
    # The same points, in any order.
    np.testing.assert_allclose(np.array(sorted(map(tuple, v))), np.array(sorted(map(tuple, tv))),
                               atol=1e-12)
    assert len(f) == len(tf)


@pytest.mark.parametrize("scheme,faces_per_face", [("loop", 4), ("butterfly", 4), ("sqrt3", 3)])
def test_triangle_schemes_multiply_the_faces(scheme, faces_per_face):
    v, f = harmonic.subdivide(TETRA_V, TETRA_F, scheme, 2)
    assert f.shape == (4 * faces_per_face ** 2, 3)
    mesh = trimesh.Trimesh(v, f, process=False)
    assert mesh.is_watertight and mesh.euler_number == 2 and mesh.volume > 0


def test_catmull_clark_turns_a_cube_into_quads():
    v, f = harmonic.subdivide(CUBE_V, CUBE_F, "catmull-clark", 2)
    assert f.shape == (96, 4)
    # The limit shrinks towards the centre but stays inside the cube.
    assert (v > 0).all() and (v < 1).all()


def test_render_gives_an_image_of_the_object_on_the_background():
    image = harmonic.render(harmonic.example("sphere"), width=48, height=32, spp=1)
    assert image.shape == (32, 48, 3) and image.dtype == np.uint8
    corner, centre = image[0, 0], image[16, 24]
    assert (image[0, :] == corner).all(), "the top row is background"
    assert not (centre == corner).all(), "the sphere is drawn in the middle"
    v, f = harmonic.example("torus").mesh((32, 32))
    mesh_image = harmonic.render((v, f), width=40, height=40, spp=1)
    assert mesh_image.shape == (40, 40, 3) and (mesh_image != mesh_image[0, 0]).any()


@pytest.mark.parametrize("method", ["bezier", "mesh"])
def test_render_draws_what_hi_render_quick_draws(tmp_path, method):
    # The same surface, framing, lights and background as the command: the same pixels.
    PIL = pytest.importorskip("PIL.Image")
    surface = harmonic.example("torus")
    grid = tmp_path / "torus.json"
    grid.write_text(json.dumps({"grid": surface.grid.tolist()}))
    png = tmp_path / "torus.png"
    hi_json("render", "--quick", grid, "--method", method, "--width", "40", "--height", "30",
            "--spp", "2", "-o", png)
    expected = np.asarray(PIL.open(png).convert("RGB"))
    image = harmonic.render(surface, width=40, height=30, spp=2, method=method)
    np.testing.assert_array_equal(image, expected)
