#!/usr/bin/env python3
"""Time and peak memory of `tetglow tetrahedralize` on a broken mesh of about 100k triangles
(holes and crossing parts: the repair path) against a clean mesh of the same size (the exact
path), each run fresh (--no-cache), best of --repeats. Prints a docs/RESULTS.md table.

    bench/repair_bench.py [--build DIR] [--repeats N] [--subdivisions S]

Both meshes are an icosphere of 20 * 4^S triangles (S = 6: 81920) plus one of 20 * 4^(S-1)
(20480): beside it (clean), or crossing it with 12 holes punched in the big one (broken)."""
import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import fail, machine, tetglow  # noqa: E402


def read_obj(path):
    vs, fs = [], []
    with open(path) as f:
        for line in f:
            p = line.split()
            if p and p[0] == "v":
                vs.append(tuple(map(float, p[1:4])))
            elif p and p[0] == "f":
                fs.append(tuple(int(x.split("/")[0]) - 1 for x in p[1:4]))
    return vs, fs


def write_obj(path, parts):
    with open(path, "w") as f:
        base = 0
        for vs, fs in parts:
            for v in vs:
                f.write("v %.9g %.9g %.9g\n" % v)
            for t in fs:
                f.write("f %d %d %d\n" % tuple(base + i + 1 for i in t))
            base += len(vs)


def punch(vs, fs, centres, radius):
    """The faces whose centroid is farther than radius from every centre."""
    def far(t):
        c = [sum(vs[i][k] for i in t) / 3 for k in range(3)]
        return all(math.dist(c, q) > radius for q in centres)
    return [t for t in fs if far(t)]


class Failed(Exception):
    """tetrahedralize refused the mesh: its message, and the time it took to."""

    def __init__(self, message, seconds, cpu):
        super().__init__(message)
        self.message, self.seconds, self.cpu = message, seconds, cpu


def run(binary, mesh):
    """Wall seconds, CPU seconds (user + system, TetGen's child included: on a loaded machine the
    fairer figure) and peak resident MiB (GNU time: tetglow or its TetGen child, the larger)."""
    start = time.monotonic()
    r = subprocess.run(["/usr/bin/time", "-f", "%U %S %M", binary, "tetrahedralize", mesh, "--no-cache"],
                       capture_output=True, text=True)
    seconds = time.monotonic() - start
    user, system, peak_kib = r.stderr.strip().splitlines()[-1].split()
    if r.returncode != 0:
        errors = [line for line in r.stderr.splitlines() if line.startswith("tetglow: error: ")]
        raise Failed(errors[-1][len("tetglow: error: "):] if errors else r.stderr.strip()[-300:], seconds,
                     float(user) + float(system))
    summary = [line for line in r.stdout.splitlines() if line.startswith(("repaired", "tetrahedra"))]
    return seconds, float(user) + float(system), int(peak_kib) / 1024, summary


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--subdivisions", type=int, default=6)
    a = ap.parse_args()
    binary = os.path.join(a.build, "tetglow")
    s = a.subdivisions
    with tempfile.TemporaryDirectory() as work:
        big, small = os.path.join(work, "big.obj"), os.path.join(work, "small.obj")
        tetglow(binary, "generate", "sphere", "--subdivisions", s, "-o", big)
        tetglow(binary, "generate", "sphere", "--subdivisions", s - 1, "--radius", 0.5, "-o", small)
        bv, bf = read_obj(big)
        sv, sf = read_obj(small)
        clean, broken = os.path.join(work, "clean.obj"), os.path.join(work, "broken.obj")
        write_obj(clean, [(bv, bf), ([(x + 2.5, y, z) for x, y, z in sv], sf)])
        holes = [bv[i * len(bv) // 12] for i in range(12)]
        write_obj(broken, [(bv, punch(bv, bf, holes, 0.05)), ([(x + 0.9, y + 0.1, z) for x, y, z in sv], sf)])
        rows = []
        for name, mesh in (("clean (exact path)", clean), ("holes + crossing (repair)", broken)):
            try:
                best = min((run(binary, mesh) for _ in range(a.repeats)), key=lambda r: r[1])
            except Failed as e:
                fail(f"tetrahedralize {mesh}: {e.message}")
            rows.append((name, sum(1 for line in open(mesh) if line.startswith("f ")), *best))
    print(f"machine: {machine()}\n")
    print("| mesh | triangles | wall seconds | CPU seconds | peak MiB |")
    print("|------|-----------|--------------|-------------|----------|")
    for name, tris, sec, cpu, mib, _ in rows:
        print(f"| {name} | {tris} | {sec:.2f} | {cpu:.2f} | {mib:.0f} |")
    print(f"\nratio: {rows[1][3] / rows[0][3]:.2f}x CPU time, {rows[1][2] / rows[0][2]:.2f}x wall time, "
          f"{rows[1][4] / rows[0][4]:.2f}x memory")
    for line in rows[1][5]:
        print("    " + line)


if __name__ == "__main__":
    main()
