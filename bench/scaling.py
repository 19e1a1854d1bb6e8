#!/usr/bin/env python3
"""How cost grows with the mesh: render time and peak memory of scenes/fish.json against the
fish generator's triangle count, and against the tet count when TetGen refines the same fish
with -q / -a (Steiner points a homogeneous medium does not need).

  bench/scaling.py [--build DIR]   writes docs/scaling-triangles.{png,svg}, docs/scaling-tets.{png,svg},
                                   docs/scaling-fish.json and prints the docs/RESULTS.md tables

Every render first runs once to fill the tet cache; the fastest of the next three is measured,
so it times rendering alone and its peak memory is tetglow's own (TetGen runs in a child).
"""
import argparse
import json
import os
import sys
import tempfile

from benchlib import fail, loglog_chart, machine, render, tetglow

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESOLUTION, SPP = "160x160", 16
REPEATS = 3  # the fastest of three: other work on the machine only ever adds time

# (rings, segments) of the generator: about 1.1 * rings * segments triangles; 112 x 96 is the demo.
FISH_SIZES = [(14, 12), (28, 24), (56, 48), (112, 96), (224, 192), (448, 384)]
# TetGen refinement of the demo fish: (radius-edge ratio -q, largest tet volume -a), 0 = off.
REFINEMENTS = [(0, 0), (2.0, 0), (1.4, 0), (0, 1e-4), (0, 1e-5), (1.4, 1e-5), (0, 2e-6), (0, 5e-7)]
INTEGRATORS = [
    ("volpath", ["--integrator", "volpath", "--spp", SPP]),
    ("single, tets", ["--integrator", "single", "--boundary", "tet", "--step", 0.02, "--spp", 4]),
    ("single, parity", ["--integrator", "single", "--boundary", "parity", "--step", 0.02, "--spp", 4]),
]


def scene_with(work, name, mesh, quality, max_volume):
    """scenes/fish.json with its medium's mesh and TetGen switches replaced."""
    with open(os.path.join(ROOT, "scenes", "fish.json")) as f:
        scene = json.load(f)
    medium = scene["media"][0]
    medium["shape"]["file"] = os.path.abspath(mesh)
    medium["tetgen"] = {"quality": quality, "max_volume": max_volume}
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


def measure(binary, work, name, mesh, quality=0, max_volume=0, integrators=INTEGRATORS):
    tet_args = (["--quality", quality] if quality else []) + (["--max-volume", max_volume] if max_volume else [])
    tets = json.loads(tetglow(binary, "tetrahedralize", mesh, "--json", "--no-cache", *tet_args))
    scene = scene_with(work, name, mesh, quality, max_volume)
    row = {"name": name, "triangles": tets["boundary_faces"], "tets": tets["tets"], "steiner_points": tets["steiner_points"],
           "tetgen_seconds": tets["seconds"],
           "tet_mib": (tets["tets"] * tets["bytes_per_tet"] + tets["vertices"] * 24) / 2**20, "renders": {}}
    for label, args in integrators:
        output = os.path.join(work, "render.exr")
        render(binary, scene, output, "--resolution", RESOLUTION, *args)  # fills the tet cache
        seconds, mib = min(render(binary, scene, output, "--resolution", RESOLUTION, *args) for _ in range(REPEATS))
        row["renders"][label] = {"seconds": seconds, "peak_mib": mib}
    print(f"{name}: {row['triangles']} triangles, {row['tets']} tets, " +
          ", ".join(f"{k} {v['seconds']:.2f} s {v['peak_mib']:.0f} MiB" for k, v in row["renders"].items()), file=sys.stderr)
    return row


def charts(by_triangles, by_tets, docs):
    def series(rows, key, integrators):
        s = [(f"{label}: seconds", [(r[key], r["renders"][label]["seconds"]) for r in rows], "y1") for label, _ in integrators]
        s.append(("volpath: peak MiB (right axis)", [(r[key], r["renders"]["volpath"]["peak_mib"]) for r in rows], "y2"))
        s.append(("tet mesh MiB (right axis)", [(r[key], r["tet_mib"]) for r in rows], "y2"))
        return s
    loglog_chart(os.path.join(docs, "scaling-triangles"), f"fish at {RESOLUTION}: cost against triangles (no Steiner points)",
                 "boundary triangles", "rendering time (s)", series(by_triangles, "triangles", INTEGRATORS), "MiB")
    loglog_chart(os.path.join(docs, "scaling-tets"), f"demo fish at {RESOLUTION}: cost against tets (TetGen -q / -a)",
                 "tetrahedra", "rendering time (s)", series(by_tets, "tets", INTEGRATORS[:2]), "MiB")


def tables(by_triangles, by_tets, machine_line):
    def header(first, labels):
        return [f"| {first} | triangles | tets | Steiner points | TetGen (s) | tet mesh (MiB) | " +
                " | ".join(f"{l} (s)" for l in labels) + " | volpath peak (MiB) |", "|" + "---|" * (7 + len(labels))]

    def line(first, r, labels):
        return (f"| {first} | {r['triangles']} | {r['tets']} | {r['steiner_points']} | {r['tetgen_seconds']:.2f} | {r['tet_mib']:.2f} | " +
                " | ".join(f"{r['renders'][l]['seconds']:.2f}" for l in labels) + f" | {r['renders']['volpath']['peak_mib']:.0f} |")

    labels = [l for l, _ in INTEGRATORS]
    out = [f"Command: `bench/scaling.py`. Renders of scenes/fish.json at {RESOLUTION}: volpath {SPP} spp, single scattering"
           f" 4 spp with step 0.02; times are tetglow's rendering time (the tet cache warm), the fastest of three runs. Machine: {machine_line}.", ""]
    out += header("fish (rings x segments)", labels)
    out += [line(r["name"], r, labels) for r in by_triangles]
    out += ["", "Demo fish (112 x 96) refined by TetGen:", ""]
    out += header("TetGen switches", labels[:2])
    out += [line(r["name"], r, labels[:2]) for r in by_tets]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="build folder holding tetglow")
    a = parser.parse_args()
    binary = os.path.join(a.build, "tetglow")
    if not os.access(binary, os.X_OK):
        fail(f"{binary}: not found; build first or give --build")
    machine_line = machine()
    docs = os.path.join(ROOT, "docs")
    with tempfile.TemporaryDirectory() as work:
        by_triangles = []
        for rings, segments in FISH_SIZES:
            mesh = os.path.join(work, f"fish-{rings}x{segments}.obj")
            tetglow(binary, "generate", "fish", "--rings", rings, "--segments", segments, "-o", mesh)
            by_triangles.append(measure(binary, work, f"{rings} x {segments}", mesh))
        demo = os.path.join(ROOT, "scenes", "meshes", "fish.obj")
        by_tets = [measure(binary, work, (f"-q{q} " if q else "") + (f"-a{v:g}" if v else "") or "none (-pY)", demo, q, v,
                           INTEGRATORS[:2]) for q, v in REFINEMENTS]
    charts(by_triangles, by_tets, docs)
    with open(os.path.join(docs, "scaling-fish.json"), "w") as f:
        json.dump({"machine": machine_line, "by_triangles": by_triangles, "by_tets": by_tets}, f, indent=1)
    print(tables(by_triangles, by_tets, machine_line))


if __name__ == "__main__":
    main()
