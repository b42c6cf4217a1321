# SPDX-License-Identifier: MIT
"""Loads meshes with trimesh, one JSON line per file, for `cargo xtask crosscheck`.

Usage: python3 trimesh_load.py FILE [FILE...]
Each line: {"file", "vertices", "faces", "sum": [Σx, Σy, Σz], "watertight", "volume"}.
Meshes are loaded as they are (process=False: no merging or reordering).
"""
import json
import sys

import trimesh

for path in sys.argv[1:]:
    try:
        mesh = trimesh.load(path, force="mesh", process=False)
        print(json.dumps({
            "file": path,
            "vertices": int(len(mesh.vertices)),
            "faces": int(len(mesh.faces)),
            "sum": [float(c) for c in mesh.vertices.sum(axis=0)],
            "watertight": bool(mesh.is_watertight),
            "volume": float(mesh.volume),
        }))
    except Exception as e:  # noqa: BLE001 - any failure is reported for that file
        print(json.dumps({"file": path, "error": f"{type(e).__name__}: {e}"}))
