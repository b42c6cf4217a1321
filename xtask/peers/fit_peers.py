#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Peer timings for `cargo xtask bench fit` (xtask/src/bench/fit.rs).

usage: fit_peers.py resample ROWS COLS RUNS
         4x upsampling of a ROWS x COLS three-channel image with scipy.signal.resample on both
         axes (the same periodic zero-padding as Theorem 5.3); prints {"seconds": median}.
       fit_peers.py poisson IN.ply OUT.ply DEPTH
         screened Poisson reconstruction (pymeshlab) of the points of IN.ply, normals estimated
         first for a point cloud (a mesh keeps the normals of its faces); prints {"seconds": ..., "normals_seconds": ...}.
       fit_peers.py distances POINTS.xyz SCAN OUT N SEED
         trimesh's measurement of a reconstruction OUT (any mesh trimesh reads) against a scan:
         N of the scan's points (POINTS.xyz, x y z per line), drawn at random with SEED, to
         their closest points on OUT; N points sampled uniformly on OUT to the scan SCAN (its
         triangles if it has faces, else its nearest point); the mesh checks (watertight,
         consistent winding, volume; after welding coincident vertices, the connected parts,
         "bodies", and the Euler characteristic V - E + F, "euler_number"). Prints JSON;
         distances relative to the diagonal of the points' bounding box.
Exit status 3: the peer (scipy, pymeshlab or trimesh) is not installed.
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


def distances(points_path, scan_path, out_path, n, seed):
    try:
        import numpy as np
        import rtree  # noqa: F401  (trimesh's closest-point queries need it)
        import trimesh
        from scipy.spatial import cKDTree
    except ImportError:
        sys.exit(3)
    pts = np.loadtxt(points_path, ndmin=2)
    diag = float(np.linalg.norm(pts.max(0) - pts.min(0)))
    out = trimesh.load(out_path, force="mesh", process=False)
    # trimesh's point-triangle test (trimesh.triangles.closest_point) compares barycentric
    # terms against absolute tolerances, and misjudges triangles with edges near 1e-3 (a
    # dense scan in metres): a point 2e-5 from a triangle's interior is put on its edge, 9e-5
    # away. Distances relative to the diagonal do not depend on the scale, so everything is
    # measured with the diagonal scaled to 100.
    origin = pts.min(0)
    scale = 100.0 / diag if diag > 0 else 1.0
    pts = (pts - origin) * scale
    out.vertices = (out.vertices - origin) * scale
    diag = 100.0
    # Watertight as stored (every edge shared by exactly two faces, by vertex index), and after
    # welding coincident vertices (which a mesh with split seams needs).
    welded = out.copy()
    welded.merge_vertices(merge_tex=True, merge_norm=True)
    rng = np.random.default_rng(seed)
    pick = pts[rng.choice(len(pts), size=min(n, len(pts)), replace=False)]
    _, d_scan, _ = trimesh.proximity.closest_point(out, pick)
    samples, _ = trimesh.sample.sample_surface(out, n, seed=seed)
    scan = trimesh.load(scan_path, force="mesh", process=False) if scan_path != "-" else None
    if scan is not None and len(getattr(scan, "faces", [])) > 0:
        scan.vertices = (scan.vertices - origin) * scale
        _, d_surf, _ = trimesh.proximity.closest_point(scan, samples)
    else:
        d_surf, _ = cKDTree(pts).query(samples)
    def summary(d):
        d = np.asarray(d) / diag
        return {"mean": float(d.mean()), "rms": float(np.sqrt((d * d).mean())),
                "p99": float(np.percentile(d, 99)), "max": float(d.max())}
    print(json.dumps({
        "scan_to_surface": summary(d_scan),
        "surface_to_scan": summary(d_surf),
        "watertight": bool(out.is_watertight),
        "watertight_welded": bool(welded.is_watertight),
        "winding_consistent": bool(welded.is_winding_consistent),
        "volume": float(welded.volume) if welded.is_watertight else None,
        "faces": int(len(out.faces)),
        "bodies": int(welded.body_count),
        "euler_number": int(welded.euler_number),
    }))


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "resample":
        resample(int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]))
    elif len(sys.argv) == 5 and sys.argv[1] == "poisson":
        poisson(sys.argv[2], sys.argv[3], int(sys.argv[4]))
    elif len(sys.argv) == 7 and sys.argv[1] == "distances":
        distances(sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5]), int(sys.argv[6]))
    else:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
