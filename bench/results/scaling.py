#!/usr/bin/env python3
"""How cost grows with the mesh: render time and peak memory of scenes/fish.json against the
fish generator's triangle count, and against the tet count when TetGen refines the same fish
with -q / -a (Steiner points a homogeneous medium does not need).

  bench/results/scaling.py [--build DIR]   writes docs/figures/scaling-triangles.{png,svg}, scaling-tets.{png,svg},
                                   docs/figures/scaling-fish.json and the scaling section of docs/RESULTS.md

Every render first runs once to fill the tet cache; the fastest of the next three is measured,
so it times rendering alone and its peak memory is tetglow's own (TetGen runs in a child).
"""
import argparse
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import FIGURES, ROOT, executable, fish_variant, loglog_chart, machine, render, replace_section, tetglow  # noqa: E402

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
    ("photon, beam", ["--integrator", "photon", "--estimate", "beam", "--photons", 50000, "--passes", 8]),
]
# The parity march never looks at the tets: refining them only changes the others.
TET_INTEGRATORS = [i for i in INTEGRATORS if i[0] != "single, parity"]


def measure(binary, work, name, mesh, quality=0, max_volume=0, integrators=INTEGRATORS):
    tet_args = (["--quality", quality] if quality else []) + (["--max-volume", max_volume] if max_volume else [])
    tets = json.loads(tetglow(binary, "tetrahedralize", mesh, "--json", "--no-cache", *tet_args))
    def edit(scene):
        del scene["media"][1:]  # the organs fit the default body only
        medium = scene["media"][0]
        medium["shape"]["file"] = os.path.abspath(mesh)
        medium["tetgen"] = {"quality": quality, "max_volume": max_volume}
    scene = fish_variant(work, name, edit)
    row = {"name": name, "triangles": tets["boundary_faces"], "tets": tets["tets"], "steiner_points": tets["steiner_points"],
           "tetgen_seconds": tets["seconds"],
           "tet_mib": (tets["tets"] * tets["bytes_per_tet"] + tets["vertices"] * 24) / 2**20, "renders": {}}
    output = os.path.join(work, "render.exr")
    render(binary, scene, output, "--resolution", RESOLUTION, *integrators[0][1])  # fills the tet cache
    for label, args in integrators:
        seconds, mib = min(render(binary, scene, output, "--resolution", RESOLUTION, *args) for _ in range(REPEATS))
        row["renders"][label] = {"seconds": seconds, "peak_mib": mib}
    print(f"{name}: {row['triangles']} triangles, {row['tets']} tets, " +
          ", ".join(f"{k} {v['seconds']:.2f} s {v['peak_mib']:.0f} MiB" for k, v in row["renders"].items()), file=sys.stderr)
    return row


def charts(by_triangles, by_tets):
    def series(rows, key, integrators):
        rows = sorted(rows, key=lambda r: r[key])  # the refinements are listed by switch, not size
        s = [(f"{label}: seconds", [(r[key], r["renders"][label]["seconds"]) for r in rows], "y1") for label, _ in integrators]
        s.append(("volpath: peak MiB (right axis)", [(r[key], r["renders"]["volpath"]["peak_mib"]) for r in rows], "y2"))
        s.append(("tet mesh MiB (right axis)", [(r[key], r["tet_mib"]) for r in rows], "y2"))
        return s
    loglog_chart(os.path.join(FIGURES, "scaling-triangles"), f"fish at {RESOLUTION}: cost against triangles (no Steiner points)",
                 "boundary triangles", "rendering time (s)", series(by_triangles, "triangles", INTEGRATORS), "MiB", "bottom right")
    loglog_chart(os.path.join(FIGURES, "scaling-tets"), f"demo fish at {RESOLUTION}: cost against tets (TetGen -q / -a)",
                 "tetrahedra", "rendering time (s)", series(by_tets, "tets", TET_INTEGRATORS), "MiB", "bottom right")


def tables(by_triangles, by_tets, machine_line):
    def header(first, labels):
        return [f"| {first} | triangles | tets | Steiner points | TetGen (s) | tet mesh (MiB) | " +
                " | ".join(f"{l} (s)" for l in labels) + " | volpath peak (MiB) |", "|" + "---|" * (7 + len(labels))]

    def line(first, r, labels):
        return (f"| {first} | {r['triangles']} | {r['tets']} | {r['steiner_points']} | {r['tetgen_seconds']:.2f} | {r['tet_mib']:.2f} | " +
                " | ".join(f"{r['renders'][l]['seconds']:.2f}" for l in labels) + f" | {r['renders']['volpath']['peak_mib']:.0f} |")

    labels = [l for l, _ in INTEGRATORS]
    out = [f"Command: `bench/results/scaling.py`. Renders of scenes/fish.json at {RESOLUTION}: volpath {SPP} spp, single scattering"
           f" 4 spp with step 0.02, photon beam 8 passes of 50,000 paths; times are tetglow's rendering time (photon tracing"
           f" included, the tet cache warm), the fastest of three runs. Machine: {machine_line}.", "",
           "![cost against triangles](figures/scaling-triangles.svg)", "", "![cost against tets](figures/scaling-tets.svg)", ""]
    out += header("fish (rings x segments)", labels)
    out += [line(r["name"], r, labels) for r in by_triangles]
    out += ["", "Demo fish (112 x 96) refined by TetGen:", ""]
    tet_labels = [l for l, _ in TET_INTEGRATORS]
    out += header("TetGen switches", tet_labels)
    out += [line(r["name"], r, tet_labels) for r in by_tets]
    # What boundary-only tetrahedralization saves against TetGen's usual quality mesh (-q1.4).
    plain, quality = by_tets[0], next(r for r in by_tets if r["name"] == "-q1.4")
    out += ["", f"Boundary-only against `-q1.4`: {plain['tets']} tets instead of {quality['tets']} "
            f"({quality['tets'] / plain['tets']:.2f}x), {plain['tet_mib']:.2f} MiB instead of {quality['tet_mib']:.2f}, TetGen "
            f"{plain['tetgen_seconds']:.2f} s instead of {quality['tetgen_seconds']:.2f} s; rendering " +
            ", ".join(f"{l} {plain['renders'][l]['seconds']:.2f} s instead of {quality['renders'][l]['seconds']:.2f} s"
                      for l in tet_labels) + "."]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="build folder holding tetglow")
    a = parser.parse_args()
    binary = executable(os.path.join(a.build, "tetglow"))
    machine_line = machine()
    with tempfile.TemporaryDirectory() as work:
        by_triangles = []
        for rings, segments in FISH_SIZES:
            mesh = os.path.join(work, f"fish-{rings}x{segments}.obj")
            tetglow(binary, "generate", "fish", "--rings", rings, "--segments", segments, "-o", mesh)
            by_triangles.append(measure(binary, work, f"{rings} x {segments}", mesh))
        demo = os.path.join(ROOT, "scenes", "meshes", "fish.obj")
        by_tets = [measure(binary, work, " ".join(f for f in (f"-q{q}" if q else "", f"-a{v:g}" if v else "") if f) or "none (-pY)", demo, q, v,
                           TET_INTEGRATORS) for q, v in REFINEMENTS]
    charts(by_triangles, by_tets)
    with open(os.path.join(FIGURES, "scaling-fish.json"), "w") as f:
        json.dump({"machine": machine_line, "by_triangles": by_triangles, "by_tets": by_tets}, f, indent=1)
    replace_section("scaling", tables(by_triangles, by_tets, machine_line))
    print("wrote docs/figures/scaling-*.{png,svg}, docs/figures/scaling-fish.json and the scaling section of docs/RESULTS.md", file=sys.stderr)


if __name__ == "__main__":
    main()
