# SPDX-License-Identifier: MIT
# blender --background --factory-startup --python blender_import.py -- FILE [FILE...]
# Imports each glTF/GLB/OBJ into an empty scene and prints one line per file:
# IMPORT <file>: meshes=M verts=V faces=F (V: the vertices the faces use)
import sys

import numpy as np

if not hasattr(np, "bool"):
    np.bool = bool  # Debian's Blender 3.4 glTF importer uses np.bool, gone in numpy 1.24

import bpy

for f in sys.argv[sys.argv.index("--") + 1:]:
    bpy.ops.wm.read_factory_settings(use_empty=True)
    try:
        if f.endswith((".gltf", ".glb")):
            bpy.ops.import_scene.gltf(filepath=f)
        elif f.endswith(".obj"):
            bpy.ops.wm.obj_import(filepath=f)
        meshes = [o for o in bpy.data.objects if o.type == "MESH"]
        # The vertices the faces use: a file's lines (an edge overlay) come in as loose edges
        # on vertices of their own.
        used = sum(len({v for p in o.data.polygons for v in p.vertices}) for o in meshes)
        print(f"IMPORT {f}: meshes={len(meshes)} "
              f"verts={used} "
              f"faces={sum(len(o.data.polygons) for o in meshes)}", flush=True)
    except Exception as e:  # any failure is reported for that file
        print(f"IMPORT {f}: error={type(e).__name__}: {e}", flush=True)
