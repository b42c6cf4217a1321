#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Peer timings for `cargo xtask bench fit` (xtask/src/bench/fit.rs).

usage: fit_peers.py resample ROWS COLS RUNS
         4x upsampling of a ROWS x COLS three-channel image with scipy.signal.resample on both
         axes (the same periodic zero-padding as Theorem 5.3); prints {"seconds": median}.
       fit_peers.py poisson IN.ply OUT.ply DEPTH
         screened Poisson reconstruction (pymeshlab) of the points of IN.ply, normals estimated
         first for a point cloud (a mesh keeps the normals of its faces); prints {"seconds": ..., "normals_seconds": ...}.
Exit status 3: the peer (scipy or pymeshlab) is not installed.
"""
import json, sys, time


def resample(rows, cols, runs):
    try:
        import numpy as np
        from scipy.signal import resample as rs
    except ImportError:
        sys.exit(3)
    rng = np.random.default_rng(5)
    img = rng.standard_normal((rows, cols, 3))
    times = []
    for _ in range(runs + 1):  # the first run warms up
        t = time.perf_counter()
        out = rs(rs(img, 4 * rows, axis=0), 4 * cols, axis=1)
        times.append(time.perf_counter() - t)
    assert out.shape == (4 * rows, 4 * cols, 3)
    times = sorted(times[1:])
    print(json.dumps({"seconds": times[(len(times) - 1) // 2]}))


def poisson(src, dst, depth):
    try:
        import pymeshlab as ml
    except ImportError:
        sys.exit(3)
    ms = ml.MeshSet()
    ms.load_new_mesh(src)
    normals = 0.0
    if ms.current_mesh().face_number() == 0:  # a point cloud: estimate normals
        t = time.perf_counter()
        ms.compute_normal_for_point_clouds(k=10)
        normals = time.perf_counter() - t
    t = time.perf_counter()
    ms.generate_surface_reconstruction_screened_poisson(depth=depth, preclean=True)
    seconds = time.perf_counter() - t
    ms.save_current_mesh(dst, save_vertex_normal=False, save_vertex_color=False)
    print(json.dumps({"seconds": seconds, "normals_seconds": normals}))


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "resample":
        resample(int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]))
    elif len(sys.argv) == 5 and sys.argv[1] == "poisson":
        poisson(sys.argv[2], sys.argv[3], int(sys.argv[4]))
    else:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
