#!/usr/bin/env python3
"""Where Blender's glTF importer places the meshes of a node hierarchy: the expected corners in
tests/test_mesh_formats.cpp (MeshFormats.GltfNodesArePlacedWhereBlenderPlacesThem) come from this.

    blender --background --python bench/studies/gltf_blender_placement.py

Writes the test's hierarchy (Group: translation (1, 2, 3), 90 degrees about y, scale 2; its
children Body, the unit cube, translation (0, 1, 0), 90 degrees about z, scale (1, 0.5, 1), and
Fin, the cube [0, 0.5]^3 mirrored by a matrix x -> 5 - x) to a GLB, imports it with Blender's
own importer and prints each mesh object's world-space corners and bounds in glTF's Y-up frame
(Blender's Z-up (x, y, z) is glTF's (x, z, -y)). Blender is a study tool here, never needed by
the build or the tests."""
import json
import os
import struct
import tempfile

import bpy
import numpy

if not hasattr(numpy, "bool"):  # Debian's Blender 3.4 importer still says np.bool, gone in numpy 1.24
    numpy.bool = bool

S = 0.70710678118654757  # sin and cos of 45 degrees: a quaternion of 90


def cube(size):
    corners = [(size * (i & 1), size * (i >> 1 & 1), size * (i >> 2 & 1)) for i in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return corners, [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]


def glb():
    blob, meshes, accessors, views = b"", [], [], []
    for corners, triangles in (cube(1.0), cube(0.5)):
        positions = b"".join(struct.pack("<3f", *p) for p in corners)
        indices = b"".join(struct.pack("<3I", *t) for t in triangles)
        for data, kind, count, target in ((positions, "VEC3", 8, 34962), (indices, "SCALAR", 36, 34963)):
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
            accessor = {"bufferView": len(views) - 1, "componentType": 5126 if kind == "VEC3" else 5125, "count": count, "type": kind}
            if kind == "VEC3":
                accessor.update({"min": [min(p[k] for p in corners) for k in range(3)], "max": [max(p[k] for p in corners) for k in range(3)]})
            accessors.append(accessor)
            blob += data
        meshes.append({"primitives": [{"attributes": {"POSITION": len(accessors) - 2}, "indices": len(accessors) - 1}]})
    doc = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [
            {"name": "Group", "children": [1, 2], "translation": [1, 2, 3], "rotation": [0, S, 0, S], "scale": [2, 2, 2]},
            {"name": "Body", "mesh": 0, "translation": [0, 1, 0], "rotation": [0, 0, S, S], "scale": [1, 0.5, 1]},
            {"name": "Fin", "mesh": 1, "matrix": [-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1]},
        ],
        "meshes": meshes, "accessors": accessors, "bufferViews": views, "buffers": [{"byteLength": len(blob)}],
    }
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    blob += b"\0" * (-len(blob) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(blob), 0x004E4942) + blob
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def main():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "hierarchy.glb")
        with open(path, "wb") as f:
            f.write(glb())
        bpy.ops.import_scene.gltf(filepath=path)
    print(f"Blender {bpy.app.version_string}")
    for obj in sorted((o for o in bpy.context.scene.objects if o.type == "MESH"), key=lambda o: o.name):
        world = [obj.matrix_world @ v.co for v in obj.data.vertices]
        corners = sorted({(round(p.x, 6), round(p.z, 6), round(-p.y, 6)) for p in world})
        lo = [min(c[k] for c in corners) for k in range(3)]
        hi = [max(c[k] for c in corners) for k in range(3)]
        print(f"{obj.name}: bounds {lo} .. {hi}")
        print(f"{obj.name}: corners {corners}")


main()
