#!/usr/bin/env python3
"""Which exported files render, and which are refused? Builds about 30 files of the kinds modelling
tools export (multi-part models, open parts, duplicated and flipped faces, labels and quads on
solids, camera- and light-only scenes, point clouds, lines, sheets, the 67-part engine of
engine_mesh.py) in OBJ, PLY, STL, OFF, GLB (plain and Draco-compressed) and Collada, runs `tetglow tetrahedralize --no-cache`
on each with a time limit, and tabulates each against its truth: a closed-form volume (the
polyhedra's own, so exact; for the engine, the winding-number estimate of engine_mesh.py --truth),
or a refusal where the file has no inside. A file is right when its volume is within 3% of the
truth or when it should be refused and is, in one line naming it; refused when it has an inside
but tetglow refuses it; wrong when tetglow accepts what has no inside or gives another volume.
Prints a docs/RESULTS.md table.

    bench/results/export_corpus.py [--build DIR] [--limit SECONDS] [--only NAME ...]

The limit is wall time (default 60 s); a file past it is wrong ("no answer within the limit")."""
import argparse
import json
import math
import os
import random
import re
import resource
import struct
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/results, for engine_mesh
import engine_mesh  # noqa: E402
from benchlib import machine  # noqa: E402

REFUSE = "refused"


# Shapes: (vertices, faces), faces as index tuples of 3 or more corners, wound outward.
def box(lo=(0, 0, 0), hi=(1, 1, 1)):
    vs = [(hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]) for i in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return vs, quads


def triangulated(shape):
    vs, fs = shape
    return vs, [(f[0], f[i], f[i + 1]) for f in fs for i in range(1, len(f) - 1)]


def sphere(subdivisions=3, radius=1.0, centre=(0, 0, 0)):
    """An icosphere, vertices on the sphere."""
    t = (1 + 5 ** 0.5) / 2
    vs = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
          (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    vs = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in vs]
    fs = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
          (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
          (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        mid, out = {}, []

        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in mid:
                m = [(x + y) / 2 for x, y in zip(vs[a], vs[b])]
                n = math.sqrt(sum(x * x for x in m))
                vs.append(tuple(x / n for x in m))
                mid[key] = len(vs) - 1
            return mid[key]

        for a, b, c in fs:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            out += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        fs = out
    return [tuple(centre[k] + radius * v[k] for k in range(3)) for v in vs], fs


def volume(shape):
    vs, fs = triangulated(shape)
    total = 0.0
    for a, b, c in fs:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = vs[a], vs[b], vs[c]
        total += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)
    return total / 6


def inward(shape):
    vs, fs = shape
    return vs, [tuple(reversed(f)) for f in fs]


def drop(shape, keep):
    vs, fs = shape
    return vs, [f for i, f in enumerate(fs) if keep(i, f)]


def near(shape, centre, radius):
    """The faces whose centroid lies within radius of centre."""
    vs, _ = shape

    def test(_, f):
        c = [sum(vs[i][k] for i in f) / len(f) for k in range(3)]
        return math.dist(c, centre) < radius
    return test


def merge(*shapes):
    vs, fs = [], []
    for v, f in shapes:
        fs += [tuple(i + len(vs) for i in t) for t in f]
        vs += list(v)
    return vs, fs


def prism(outline, height):
    """A closed prism over a simple polygon in z = 0 (counterclockwise), caps as one n-gon each."""
    n = len(outline)
    vs = [(x, y, 0.0) for x, y in outline] + [(x, y, height) for x, y in outline]
    fs = [tuple(reversed(range(n))), tuple(range(n, 2 * n))]
    fs += [(k, (k + 1) % n, n + (k + 1) % n, n + k) for k in range(n)]
    return vs, fs


def polygon_area(outline):
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(outline, outline[1:] + outline[:1]))


# Writers.
def write_obj(path, parts, lines=None, points_only=False):
    with open(path, "w") as f:
        base = 1
        for name, (vs, fs) in parts:
            f.write(f"o {name}\n")
            for v in vs:
                f.write("v %.9g %.9g %.9g\n" % tuple(v))
            if not points_only:
                for t in fs:
                    f.write("f " + " ".join(str(base + i) for i in t) + "\n")
            for a, b in lines or []:
                f.write(f"l {base + a} {base + b}\n")
            base += len(vs)


def write_ply(path, shape, binary=False, faces=True):
    vs, fs = shape
    fs = fs if faces else []
    header = ["ply", "format " + ("binary_little_endian" if binary else "ascii") + " 1.0",
              f"element vertex {len(vs)}", "property float x", "property float y", "property float z"]
    if faces:
        header += [f"element face {len(fs)}", "property list uchar int vertex_indices"]
    header.append("end_header")
    with open(path, "wb") as f:
        f.write(("\n".join(header) + "\n").encode())
        for v in vs:
            f.write(struct.pack("<3f", *v) if binary else ("%.9g %.9g %.9g\n" % tuple(v)).encode())
        for t in fs:
            f.write(struct.pack(f"<B{len(t)}i", len(t), *t) if binary else
                    (f"{len(t)} " + " ".join(map(str, t)) + "\n").encode())


def normal(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    return (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])


def write_stl(path, shape, binary=True):
    vs, fs = triangulated(shape)
    with open(path, "wb") as f:
        if binary:
            f.write(b"exported".ljust(80, b" ") + struct.pack("<I", len(fs)))
            for a, b, c in fs:
                f.write(struct.pack("<12fH", *normal(vs[a], vs[b], vs[c]), *vs[a], *vs[b], *vs[c], 0))
        else:
            f.write(b"solid exported\n")
            for a, b, c in fs:
                f.write(("facet normal %g %g %g\n outer loop\n" % normal(vs[a], vs[b], vs[c])).encode())
                for v in (vs[a], vs[b], vs[c]):
                    f.write(("  vertex %.9g %.9g %.9g\n" % v).encode())
                f.write(b" endloop\nendfacet\n")
            f.write(b"endsolid exported\n")


def write_off(path, shape):
    vs, fs = shape
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vs)} {len(fs)} 0\n")
        for v in vs:
            f.write("%.9g %.9g %.9g\n" % tuple(v))
        for t in fs:
            f.write(f"{len(t)} " + " ".join(map(str, t)) + "\n")


def write_glb(path, meshes, nodes, extra=None):
    """glTF 2.0 binary: `meshes` are triangle shapes, `nodes` dicts (mesh index, translation, camera)."""
    blob, views, accessors, gmeshes = bytearray(), [], [], []
    for shape in meshes:
        vs, fs = triangulated(shape)
        for data, target, ctype, count, kind in (
                (struct.pack(f"<{3 * len(vs)}f", *[c for v in vs for c in v]), 34962, 5126, len(vs), "VEC3"),
                (struct.pack(f"<{3 * len(fs)}I", *[i for t in fs for i in t]), 34963, 5125, 3 * len(fs), "SCALAR")):
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data), "target": target})
            accessor = {"bufferView": len(views) - 1, "componentType": ctype, "count": count, "type": kind}
            if kind == "VEC3":
                accessor["min"] = [min(v[k] for v in vs) for k in range(3)]
                accessor["max"] = [max(v[k] for v in vs) for k in range(3)]
            accessors.append(accessor)
            blob += data
            blob += b"\0" * (-len(blob) % 4)
        gmeshes.append({"primitives": [{"attributes": {"POSITION": len(accessors) - 2}, "indices": len(accessors) - 1}]})
    doc = {"asset": {"version": "2.0", "generator": "export_corpus.py"}, "scene": 0,
           "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes}
    if gmeshes:
        doc.update(meshes=gmeshes, accessors=accessors, bufferViews=views, buffers=[{"byteLength": len(blob)}])
    doc.update(extra or {})
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text
    if blob:
        chunks += struct.pack("<I4s", len(blob), b"BIN\0") + bytes(blob)
    with open(path, "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)


def write_dae(path, shape=None, camera=False, light=False):
    """Collada 1.4: a triangle mesh, and/or a camera or a light, each in its own node."""
    parts = ['<?xml version="1.0" encoding="utf-8"?>',
             '<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">',
             '<asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>']
    nodes = []
    if camera:
        parts.append('<library_cameras><camera id="cam"><optics><technique_common><perspective>'
                     '<yfov>40</yfov><aspect_ratio>1.5</aspect_ratio><znear>0.1</znear><zfar>100</zfar>'
                     '</perspective></technique_common></optics></camera></library_cameras>')
        nodes.append('<node id="Camera" name="Camera"><translate>0 -5 1</translate>'
                     '<instance_camera url="#cam"/></node>')
    if light:
        parts.append('<library_lights><light id="lamp"><technique_common><point><color>1 1 1</color>'
                     '</point></technique_common></light></library_lights>')
        nodes.append('<node id="Lamp" name="Lamp"><translate>2 2 3</translate><instance_light url="#lamp"/></node>')
    if shape:
        vs, fs = triangulated(shape)
        floats = " ".join("%.9g" % c for v in vs for c in v)
        parts.append('<library_geometries><geometry id="mesh"><mesh>'
                     f'<source id="pos"><float_array id="pos-a" count="{3 * len(vs)}">{floats}</float_array>'
                     f'<technique_common><accessor source="#pos-a" count="{len(vs)}" stride="3">'
                     '<param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>'
                     '</accessor></technique_common></source>'
                     '<vertices id="verts"><input semantic="POSITION" source="#pos"/></vertices>'
                     f'<triangles count="{len(fs)}"><input semantic="VERTEX" source="#verts" offset="0"/>'
                     f'<p>{" ".join(str(i) for t in fs for i in t)}</p></triangles>'
                     '</mesh></geometry></library_geometries>')
        nodes.append('<node id="Body" name="Body"><instance_geometry url="#mesh"/></node>')
    parts.append('<library_visual_scenes><visual_scene id="Scene">' + "".join(nodes) +
                 '</visual_scene></library_visual_scenes><scene><instance_visual_scene url="#Scene"/></scene>')
    parts.append("</COLLADA>")
    with open(path, "w") as f:
        f.write("\n".join(parts) + "\n")


def cases():
    """(file name, what it is, writer(path), truth: a volume or REFUSE)."""
    rng = random.Random(7)
    s3 = sphere(3)
    v3 = volume(s3)
    c = []

    def add(name, what, write, truth):
        c.append((name, what, write, truth))

    three = [("a", box()), ("b", box((2, 0, 0), (3, 2, 1))), ("c", triangulated(sphere(2, 0.5, (5, 0.5, 0.5))))]
    v_three = 1 + 2 + volume(three[2][1])
    add("multipart.obj", "three parts, one `o` each", lambda p: write_obj(p, three), v_three)
    add("multipart.glb", "three meshes, three nodes", lambda p: write_glb(
        p, [s for _, s in three], [{"mesh": i} for i in range(3)]), v_three)
    add("instanced.glb", "one box placed by four nodes", lambda p: write_glb(
        p, [box()], [{"mesh": 0, "translation": [2.0 * i, 0, 0]} for i in range(4)]), 4.0)
    add("quads.obj", "a box of quads", lambda p: write_obj(p, [("box", box())]), 1.0)
    add("box.off", "a box of quads (OFF)", lambda p: write_off(p, box()), 1.0)
    add("box-ascii.stl", "an ASCII STL box, corners repeated per face", lambda p: write_stl(p, box(), False), 1.0)
    add("sphere.stl", "a binary STL sphere", lambda p: write_stl(p, s3), v3)
    add("sphere-quads.ply", "a binary PLY sphere", lambda p: write_ply(p, s3, True), v3)
    add("box.dae", "a Collada box with a camera and a light", lambda p: write_dae(p, box(), True, True), 1.0)
    ell = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    add("concave-prism.obj", "an L-shaped prism, n-gon caps", lambda p: write_obj(p, [("L", prism(ell, 0.5))]),
        polygon_area(ell) * 0.5)
    # Open parts and holes.
    holed = drop(s3, lambda i, f: not near(s3, s3[0][0], 0.15)(i, f))
    add("holed-sphere.obj", "a sphere missing the faces around a vertex", lambda p: write_obj(p, [("s", holed)]),
        v3)
    perforated = drop(s3, lambda i, f: rng.random() > 0.15)
    add("perforated-sphere.stl", "15% of a sphere's faces missing (STL)", lambda p: write_stl(p, perforated), v3)
    add("part-with-hole.obj", "a closed box beside a sphere with a hole", lambda p: write_obj(
        p, [("box", box((3, 0, 0), (4, 1, 1))), ("s", holed)]), 1 + v3)
    cavity = triangulated(inward(sphere(2, 0.5)))
    add("hollow-hole.obj", "a hollow sphere, a hole in its outer shell", lambda p: write_obj(
        p, [("outer", holed), ("cavity", cavity)]), v3 - volume(sphere(2, 0.5)))
    add("hollow.ply", "a hollow sphere (cavity wound inward)", lambda p: write_ply(
        p, merge(s3, cavity)), v3 - volume(sphere(2, 0.5)))
    add("nested-outward.obj", "a box in a ball, both wound outward", lambda p: write_obj(
        p, [("ball", s3), ("box", box((-0.3, -0.3, -0.3), (0.3, 0.3, 0.3)))]), v3)
    # Duplicated and flipped faces, crossings.
    vs, fs = triangulated(box())
    add("duplicated.obj", "a box with every face twice", lambda p: write_obj(p, [("box", (vs, fs + fs))]), 1.0)
    add("some-duplicated.ply", "a sphere with ten faces repeated", lambda p: write_ply(
        p, (s3[0], s3[1] + s3[1][:10])), v3)
    add("flipped-part.obj", "two spheres, one wound inward", lambda p: write_obj(
        p, [("a", s3), ("b", inward(sphere(3, 1.0, (3, 0, 0))))]), 2 * v3)
    add("holed-beside-flipped.obj", "a sphere with a hole beside a closed one wound inward", lambda p: write_obj(
        p, [("holed", holed), ("flipped", inward(sphere(3, 1.0, (3, 0, 0))))]), 2 * v3)
    add("all-inward.stl", "a sphere wound inward throughout", lambda p: write_stl(p, inward(s3)), v3)
    add("crossing-boxes.obj", "two boxes crossing, one mesh", lambda p: write_obj(
        p, [("a", box()), ("b", box((0.5, 0.5, 0.5), (1.5, 1.5, 1.5)))]), 2 - 0.125)
    add("bolt-through-plate.glb", "a cylinder through a plate", lambda p: write_glb(
        p, [box((-1, -1, 0), (1, 1, 0.2)), cylinder(0.1, -0.5, 0.7, 32)], [{"mesh": 0}, {"mesh": 1}]),
        0.8 + cylinder_volume(0.1, 1.2, 32) - cylinder_volume(0.1, 0.2, 32))
    # Labels, quads and sheets on or beside solids.
    label = ([(0.2, 0.2, 1.001), (0.8, 0.2, 1.001), (0.8, 0.8, 1.001), (0.2, 0.8, 1.001)], [(0, 1, 2, 3)])
    add("label-on-box.obj", "a box with a label quad just above its top", lambda p: write_obj(
        p, [("box", box()), ("label", label)]), 1.0)
    ground = ([(-1, -1, 0), (4, -1, 0), (4, 2, 0), (-1, 2, 0)], [(0, 1, 2, 3)])
    letters = [("I", box((0, 0, 0), (0.2, 0.2, 1))), ("L1", box((0.5, 0, 0), (0.7, 0.2, 1))),
               ("L2", box((0.7, 0, 0), (1.1, 0.2, 0.2)))]
    add("letters-on-ground.glb", "closed letters standing on a ground quad", lambda p: write_glb(
        p, [s for _, s in letters] + [ground], [{"mesh": i} for i in range(4)]), 0.04 + 0.04 + 0.016)
    below = ([(x, y, -0.01) for x, y, _ in ground[0]], ground[1])
    add("letters-over-ground.glb", "the letters 0.01 above the ground quad", lambda p: write_glb(
        p, [s for _, s in letters] + [below], [{"mesh": i} for i in range(4)]), 0.04 + 0.04 + 0.016)
    labelled, v_labelled = spheres_with_labels()
    add("labelled-spheres.glb", "18 spheres, some overlapping or touching, 9 label quads on them, 37k triangles",
        lambda p: write_glb(p, labelled, [{"mesh": i} for i in range(len(labelled))]), v_labelled)
    add("sheet.obj", "one quad", lambda p: write_obj(p, [("q", ground)]), REFUSE)
    add("flat-concave.obj", "a flat concave polygon", lambda p: write_obj(p, [("L", ([(x, y, 0) for x, y in ell],
                                                                                     [tuple(range(6))]))]), REFUSE)
    # Nothing to fill.
    add("camera-only.dae", "Collada with a camera and a light only", lambda p: write_dae(p, None, True, True),
        REFUSE)
    add("camera-only.glb", "glTF with a camera node only", lambda p: write_glb(p, [], [{"camera": 0}], {
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}]}), REFUSE)
    add("points.ply", "a point cloud (PLY vertices only)", lambda p: write_ply(p, s3, faces=False), REFUSE)
    add("points.obj", "a point cloud (OBJ v lines only)", lambda p: write_obj(p, [("p", s3)], points_only=True),
        REFUSE)
    add("lines.obj", "a wireframe (OBJ l lines only)", lambda p: write_obj(
        p, [("w", (box()[0], []))], lines=[(0, 1), (1, 3), (3, 2), (2, 0)]), REFUSE)
    add("empty.obj", "an empty OBJ", lambda p: open(p, "w").close(), REFUSE)
    # The engine's truth: engine_mesh.py --truth, a jittered-grid estimate of its union's volume
    # (standard error about 0.25%), kept in engine_mesh.TRUTH.
    add("engine.obj", "the 67-part engine (engine_mesh.py), 111k triangles",
        lambda p: engine_mesh.write_obj(p, engine_mesh.engine()), engine_mesh.TRUTH)
    if DRACO_TOOL and os.path.exists(DRACO_TOOL):  # built with the tests
        add("box-draco.glb", "a box, Draco-compressed (KHR_draco_mesh_compression)",
            lambda p: write_draco_glb(p, lambda q: write_obj(q, [("box", box())])), 1.0)
        add("engine-draco.glb", "the engine as a Draco GLB, a mesh a part, positions exact",
            lambda p: write_draco_glb(p, lambda q: engine_mesh.write_obj(q, engine_mesh.engine())),
            engine_mesh.TRUTH)
    return c


def lens_volume(r1, r2, d):
    """The volume two balls of radii r1, r2 whose centres are d apart share (closed form)."""
    if d >= r1 + r2:
        return 0.0
    return math.pi * (r1 + r2 - d) ** 2 * (d * d + 2 * d * (r1 + r2) - 3 * (r1 - r2) ** 2) / (12 * d)


def spheres_with_labels():
    """18 icospheres in three rows, some pairs overlapping and some touching, and 9 label quads
    facing up on the tops of nine: 1/1000 above, through the top vertex, or 3/1000 into the cap.
    (meshes, truth): the union of the polyhedra, each overlap the lens of the two balls scaled
    by the polyhedra's share of their balls' volume (the caps labels cut off are under 1e-4)."""
    gaps = [[1.6, 3, 2.0, 3, 1.7], [3, 3, 1.7, 3, 3], [2.0, 3, 3, 1.8, 3]]
    centres = []
    for row, g in enumerate(gaps):
        x = 0.0
        for k in range(6):
            centres.append((x, 4.0 * row, 0.0))
            x += g[k] if k < 5 else 0
    spheres = [sphere(4 if i % 5 == 0 else 3, 1.0, c) for i, c in enumerate(centres)]
    share = [volume(s) / (4 * math.pi / 3) for s in spheres]
    truth = sum(volume(s) for s in spheres)
    for i in range(len(centres) - 1):
        if centres[i][1] == centres[i + 1][1]:
            truth -= lens_volume(1, 1, math.dist(centres[i], centres[i + 1])) * (share[i] + share[i + 1]) / 2
    labels = []
    for n, i in enumerate(range(0, 18, 2)):
        x, y, _ = centres[i]
        z = 1.0 + (0.001, 0.0, -0.003)[n % 3]
        labels.append(([(x - 0.3, y - 0.15, z), (x + 0.3, y - 0.15, z), (x + 0.3, y + 0.15, z),
                        (x - 0.3, y + 0.15, z)], [(0, 1, 2, 3)]))
    return spheres + labels, truth


DRACO_TOOL = None  # tetglow_draco_glb of the build (tests/tools/draco_glb.cpp)


def write_draco_glb(path, write_parts):
    """What `write_parts` writes as OBJ, as a Draco-compressed GLB with a mesh and a node a part."""
    write_parts(path + ".obj")
    subprocess.run([DRACO_TOOL, path + ".obj", path], check=True, capture_output=True)


def cylinder(radius, z0, z1, sides):
    """A closed cylinder about the z axis, n-gon caps."""
    vs = [(radius * math.cos(2 * math.pi * k / sides), radius * math.sin(2 * math.pi * k / sides), z)
          for z in (z0, z1) for k in range(sides)]
    fs = [tuple(reversed(range(sides))), tuple(range(sides, 2 * sides))]
    fs += [(k, (k + 1) % sides, sides + (k + 1) % sides, sides + k) for k in range(sides)]
    return vs, fs


def cylinder_volume(radius, height, sides):
    return 0.5 * sides * radius * radius * math.sin(2 * math.pi / sides) * height


def run(binary, path, limit):
    """Exit code (None past the limit), stderr, wall and CPU seconds (user + system, TetGen's
    child included: on a loaded machine the fairer figure), volume."""
    start, used = time.monotonic(), resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        r = subprocess.run([binary, "tetrahedralize", path, "--no-cache"], capture_output=True, text=True,
                           timeout=limit)
    except subprocess.TimeoutExpired:
        return None, "", time.monotonic() - start, None, None
    seconds = time.monotonic() - start
    now = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = now.ru_utime + now.ru_stime - used.ru_utime - used.ru_stime
    m = re.search(r"^volume\s+mesh \S+ tets ([-0-9.e+]+)", r.stdout.replace(",", ""), re.M)
    return r.returncode, r.stderr.strip(), seconds, cpu, float(m.group(1)) if m else None


def judge(truth, code, err, vol, path):
    """(verdict, what tetglow said)."""
    if code is None:
        return "wrong", "no answer within the limit"
    one_line = len(err.splitlines()) == 1 and os.path.basename(path) in err
    if code != 0:
        said = err.splitlines()[-1] if err else f"exit {code}"
        if truth == REFUSE:
            return ("right" if one_line else "wrong"), said
        return "refused", said
    said = f"volume {vol:.6g}"
    if truth == REFUSE:
        return "wrong", said
    if truth is None:
        return "no truth", said
    return ("right" if abs(vol - truth) <= 0.03 * abs(truth) else "wrong"), said


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--limit", type=float, default=60)
    ap.add_argument("--only", nargs="*")
    a = ap.parse_args()
    binary = os.path.join(a.build, "tetglow")
    global DRACO_TOOL
    DRACO_TOOL = os.path.join(a.build, "tetglow_draco_glb")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name, what, write, truth in cases():
            if a.only and name not in a.only:
                continue
            path = os.path.join(work, name)
            write(path)
            code, err, seconds, cpu, vol = run(binary, path, a.limit)
            verdict, said = judge(truth, code, err, vol, path)
            said = said.replace(work + "/", "").replace("|", "/")
            rows.append((name, what, truth, verdict, said, seconds, cpu))
            print(f"{name}: {verdict} ({seconds:.1f} s) {said[:150]}", file=sys.stderr)
    print(f"machine: {machine()}\n")
    print("| file | what it is | truth | verdict | tetglow said | wall seconds | CPU seconds |")
    print("|------|------------|-------|---------|--------------|--------------|-------------|")
    for name, what, truth, verdict, said, seconds, cpu in rows:
        t = "no inside" if truth == REFUSE else "—" if truth is None else f"{truth:.6g}"
        if len(said) > 160:
            said = said[:157] + "..."
        used = "—" if cpu is None else f"{cpu:.2f}"
        print(f"| {name} | {what} | {t} | {verdict} | {said} | {seconds:.2f} | {used} |")
    counts = {v: sum(r[3] == v for r in rows) for v in ("right", "refused", "wrong", "no truth")}
    print("\n" + ", ".join(f"{n} {v}" for v, n in counts.items() if n) + f" of {len(rows)}")


if __name__ == "__main__":
    main()
