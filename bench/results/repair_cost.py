#!/usr/bin/env python3
"""Cost of validation and repair against the number of shells and of crossings: `tetglow
tetrahedralize --no-cache` on N disjoint tetrahedra (the exact path: every shell's nesting is
decided), on K thin boxes turned about a common axis in general position (the repair: every
box crosses every other), on fans of B thin tetrahedra, through one axis (CGAL cannot split
them: the winding number's grid) and in general position, and on the 67-part engine of
engine_mesh.py (open, crossing and CAD-tessellated parts; --engine). Prints a docs/RESULTS.md table.

    bench/results/repair_cost.py [--build DIR] [--shells N ...] [--boxes K ...] [--fans B ...] [--engine]"""
import argparse
import math
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # bench/results, for repair_bench
import engine_mesh  # noqa: E402
import repair_bench  # noqa: E402
from benchlib import machine  # noqa: E402

FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
BOX_FACES = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
             (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]


def write_obj(path, parts, faces):
    with open(path, "w") as f:
        base = 1
        for corners in parts:
            for p in corners:
                f.write("v %.9g %.9g %.9g\n" % p)
            for t in faces:
                f.write("f %d %d %d\n" % tuple(base + i for i in t))
            base += len(corners)


def tetrahedra(n):
    side = math.ceil(n ** (1 / 3))
    parts = []
    for i in range(n):
        x, y, z = 2.0 * (i % side), 2.0 * (i // side % side), 2.0 * (i // side // side)
        parts.append([(x, y, z), (x + 1, y, z), (x, y + 1, z), (x, y, z + 1)])
    return parts


def boxes(k):
    """Thin boxes through the z axis, each turned by a different angle and tilted a little, so that
    every pair crosses in general position (no three faces through one point)."""
    parts = []
    for i in range(k):
        a, tilt = math.pi * (i + 0.37) / k, 0.05 * math.sin(7.3 * i)
        c, s = math.cos(a), math.sin(a)
        corners = []
        for bits in range(8):
            u = 1.0 if bits & 1 else -1.0       # along the box's length
            v = 0.04 if bits & 2 else -0.04     # across
            w = 0.5 if bits & 4 else -0.5       # height
            x, y = u * c - v * s, u * s + v * c
            corners.append((x + tilt * w, y + 0.013 * i, w + 0.011 * i))
        parts.append(corners)
    return parts


def fan(blades, general):
    """tests/test_repair_robustness.cpp's crossingFan: thin tetrahedra about the z axis."""
    parts = []
    for i in range(blades):
        a = math.pi * (i + (0.37 if general else 0)) / blades
        c, s = math.cos(a), math.sin(a)
        dx, dy, dz = (0.05 * math.sin(7.3 * i), 0.013 * i, 0.011 * i) if general else (0, 0, 0)
        parts.append([(x + dx, y + dy, z + dz) for x, y, z in
                      [(c, s, -1), (-c, -s, -1), (-0.2 * s, 0.2 * c, -0.8), (0.1 * c, 0.1 * s, 1)]])
    return parts


def run(binary, mesh):
    """Wall and CPU seconds of tetrahedralize (repair_bench's run), the crossing pairs resolved,
    whether the boundary came out approximate (the winding number's grid), and the outcome (""
    when it tetrahedralized, else its error)."""
    try:
        seconds, cpu, _, summary = repair_bench.run(binary, mesh)
    except repair_bench.Failed as e:
        return e.seconds, e.cpu, 0, False, e.message
    text = " ".join(summary)
    # The winding number's grid reports the input's crossings instead of those it resolved.
    crossings = re.search(r"(\d+) crossing pairs? (?:resolved|\(first at)", text)
    approximate = "the boundary is approximate" in text
    return seconds, cpu, int(crossings.group(1)) if crossings else 0, approximate, ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--shells", type=int, nargs="*", default=[1000, 5000, 20000])
    ap.add_argument("--boxes", type=int, nargs="*", default=[5, 10, 20, 40])
    ap.add_argument("--fans", type=int, nargs="*", default=[53])
    ap.add_argument("--engine", action="store_true", help="also the 67-part engine (engine_mesh.py)")
    a = ap.parse_args()
    binary = os.path.join(a.build, "tetglow")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for n in a.shells:
            mesh = os.path.join(work, f"tets{n}.obj")
            write_obj(mesh, tetrahedra(n), FACES)
            rows.append((f"{n} disjoint tetrahedra", 4 * n, n, *run(binary, mesh)))
        for k in a.boxes:
            mesh = os.path.join(work, f"boxes{k}.obj")
            write_obj(mesh, boxes(k), BOX_FACES)
            rows.append((f"{k} crossing boxes", 12 * k, k, *run(binary, mesh)))
        for b in a.fans:
            for general in (False, True):
                mesh = os.path.join(work, f"fan{b}{general}.obj")
                write_obj(mesh, fan(b, general), FACES)
                where = "in general position" if general else "through one axis"
                rows.append((f"fan of {b} blades {where}", 4 * b, b, *run(binary, mesh)))
        if a.engine:
            mesh = os.path.join(work, "engine.obj")
            parts = engine_mesh.engine()
            engine_mesh.write_obj(mesh, parts)
            rows.append(("67-part engine", sum(len(fs) for _, _, fs in parts), len(parts), *run(binary, mesh)))
    print(f"machine: {machine()}\n")
    print("| mesh | triangles | shells | crossing pairs | wall seconds | CPU seconds |")
    print("|------|-----------|--------|----------------|--------------|-------------|")
    for name, tris, shells, sec, cpu, crossings, approximate, error in rows:
        name += " (grid)" if approximate else ""
        pairs = f"error: {error}" if error else crossings
        print(f"| {name} | {tris} | {shells} | {pairs} | {sec:.2f} | {cpu:.2f} |")


if __name__ == "__main__":
    main()
