#!/usr/bin/env python3
"""Where each method breaks, regenerated for docs/RESULTS.md: the figures the stability tests
print (each test asserts its own bounds; here they are only collected) and the per-query cost
of the boundary methods from `tetglow compare-boundary --json` on the fish and blub.

  bench/results/stability.py [--build DIR]   rewrites the stability section of docs/RESULTS.md
"""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import ROOT, fail, machine, replace_section, tetglow  # noqa: E402

# (test, what it breaks): the order of the section.
TESTS = [
    ("StabilityRender.RaysThroughVerticesEdgesAndGrazingEveryIntegrator",
     "Camera rays exactly through vertices and edges and grazing faces of an absorbing polyhedron, every renderer"),
    ("StabilityRender.RaysThroughVerticesEdgesAndGrazingAnInterface",
     "The same lines through the vertices and edges of a polyhedron nested in another and grazing its faces (an interface), every renderer"),
    ("Stability.DegenerateLinesThroughAConvexPolyhedron", "The same lines, boundary methods alone"),
    ("Stability.SliverTets", "Sliver tets of a boundary-only tetrahedralization"),
    ("Stability.SelfIntersectionHidesTheOverlapFromParity", "A self-intersecting mesh"),
    ("Stability.FishWithAHole", "The fish with a hole"),
    ("CompareBoundary.ParityIsWrongOnAMeshWithAHole", "A sphere without its cap"),
    ("StabilityRender.BrokenMediaAreRefused", "Broken media in a scene: what the renderer says"),
    ("Stability.ThinPlates", "Very thin features"),
    ("StabilityRender.PhotonCountsAndRadiiAtTheirExtremes", "Photon counts and radii at their extremes"),
    ("StabilityRender.ExtremeCoefficientsStayFiniteAndBounded",
     "Extreme coefficients in a white furnace (radiance 1 everywhere: no mean may exceed 1)"),
]
MESHES = ["scenes/meshes/fish.obj", "../shared/meshes/blub.obj"]  # from the repository root


def printed(tests_binary, test):
    """What the test printed, gtest's own lines left out; fails if the test does."""
    r = subprocess.run([tests_binary, f"--gtest_filter={test}"], capture_output=True, text=True)
    if r.returncode != 0 or "[  PASSED  ] 1 test" not in r.stdout:
        fail(f"{test} did not pass:\n{r.stdout[-2000:]}{r.stderr[-2000:]}")
    return "\n".join(l for l in r.stdout.splitlines() if l.strip() and not l.startswith(("[", "Running main", "Note:")))


def boundary_costs(binary):
    """Markdown tables from `tetglow compare-boundary MESH --json` on each mesh: time per point
    classified (mean over the bounding box and the shells) and per line's optical depth."""
    points = ["**Cost per query of the boundary methods** (`tetglow compare-boundary MESH --json`, one thread).",
              "Inside/outside of a point, ns (mean over the bounding box and six shells 1e-2 to 1e-7 diagonals"
              " from the surface; error rates against the tets in brackets):", "",
              "| mesh | tets | parity 1 ray | parity 3 rays | parity 5 rays | bounding box |", "|---|---|---|---|---|---|"]
    lines = ["", "Optical depth along random lines across the bounding box (sigma_t 1), the parity baseline's march with one"
             " parity ray per step:", "", "| mesh | method | step | us per line | x tets | relative error |", "|---|---|---|---|---|---|"]
    for mesh in MESHES:
        if not os.path.isfile(mesh):
            fail(f"{mesh}: missing")
        medium = json.loads(tetglow(binary, "compare-boundary", mesh, "--json"))["media"][0]
        regions = medium["classification"]
        cells = []
        for i, method in enumerate(regions[0]["methods"]):
            ns = sum(r["methods"][i]["ns_per_query"] for r in regions) / len(regions)
            rate = sum(r["methods"][i]["errors"] for r in regions) / sum(r["points"] for r in regions)
            cells.append(f"{ns:.0f} ({100 * rate:.2g}%)")
        points.append(f"| {medium['name']} | " + " | ".join(cells) + " |")
        tets = medium["optical_depth"]["methods"][0]["us_per_ray"]
        for m in medium["optical_depth"]["methods"]:
            step = f"{m['step']:.3g}" if m["step"] else "-"
            lines.append(f"| {medium['name']} | {m['method']} | {step} | {m['us_per_ray']:.3g} | {m['us_per_ray'] / tets:.3g} "
                         f"| {m['relative_error']:.2g} |")
    return points + lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="build folder holding tetglow and tetglow_tests")
    a = parser.parse_args()
    binary, tests_binary = os.path.abspath(os.path.join(a.build, "tetglow")), os.path.abspath(os.path.join(a.build, "tetglow_tests"))
    os.chdir(ROOT)
    for b in (binary, tests_binary):
        if not os.access(b, os.X_OK):
            fail(f"{b}: not found; build first (with tests) or give --build")
    lines = [f"Command: `bench/results/stability.py` (runs each test below as `tetglow_tests --gtest_filter=TEST` and collects"
             f" what it prints; the bounds are asserted by the tests). Machine: {machine()}.", ""]
    for test, title in TESTS:
        lines += [f"**{title}** (`{test}`):", "", "```", printed(tests_binary, test), "```", ""]
    lines += boundary_costs(binary)
    replace_section("stability", "\n".join(lines).rstrip())
    print("rewrote the stability section of docs/RESULTS.md")


if __name__ == "__main__":
    main()
