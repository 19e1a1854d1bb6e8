#!/usr/bin/env python3
"""Speed against accuracy on the fish: every point is an actual render of scenes/fish.json
without the water around the fish (the box of water would dominate every method's cost), its error measured by `tetglow diff` against a volpath reference, its time the rendering time
tetglow reports. One chart, error (log) against seconds (log), one curve per method. The error
is the mean absolute error: the caustic under the fish gives volpath rare, very bright samples
that dominate RMSE (reported too) for thousands of samples per pixel, the reference's included.

  bench/results/sweep.py --quick [--build DIR] [--out DIR]   a 48x48 fish for the test suite: chart and
      data go to DIR (default BUILD/sweep-quick); fails unless every image is finite and the
      error falls with cost along every curve but single scattering's
  bench/results/sweep.py --full [--build DIR] [--reference EXR]   the docs' figures at 400x400 against
      EXR (rendered there first when missing: volpath, 4096 spp, seed 777), written to
      docs/figures/sweep-fish.{png,svg,json} and the sweep section of docs/RESULTS.md
"""
import argparse
import json
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import FIGURES, ROOT, diff, executable, fail, fish_variant, loglog_chart, machine, render, replace_section  # noqa: E402


RESOLUTION = {"quick": "48x48", "full": "400x400"}  # the full mode's is the scene's own

PHOTON = ["--integrator", "photon"]
# One entry per curve: the label, the fixed arguments, the swept option and its values in each
# mode; "fixed_radius" renders a copy of the scene whose photon radii do not shrink between
# passes (alpha 1, as in plain photon mapping: more passes only average more images).
METHODS = [
    {"label": "volpath", "args": ["--integrator", "volpath"], "sweep": "--spp",
     "quick": [1, 4, 16, 64], "full": [1, 4, 16, 64, 256, 512]},
    {"label": "single, parity (the parity baseline)", "args": ["--integrator", "single", "--boundary", "parity", "--spp", 4],
     "sweep": "--step", "quick": [0.1, 0.04, 0.01], "full": [0.2, 0.1, 0.05, 0.02]},
    {"label": "single, tets", "args": ["--integrator", "single", "--boundary", "tet", "--spp", 4],
     "sweep": "--step", "quick": [0.1, 0.04, 0.01], "full": [0.2, 0.1, 0.05, 0.02]},
    {"label": "photon, k-NN march (the parity baseline's), k 16, 50k photons", "fixed_radius": True,
     "args": PHOTON + ["--estimate", "knn-march", "--k", 16, "--photons", 50000], "sweep": "--passes",
     "quick": [1, 4], "full": [1, 2, 4]},
    {"label": "photon, k-NN march, k 64, 50k photons", "fixed_radius": True,
     "args": PHOTON + ["--estimate", "knn-march", "--k", 64, "--photons", 50000], "sweep": "--passes",
     "quick": [1, 4], "full": [1, 2, 4]},
    {"label": "photon, k-NN march, k 16, 200k photons", "fixed_radius": True,
     "args": PHOTON + ["--estimate", "knn-march", "--k", 16, "--photons", 200000], "sweep": "--passes",
     "quick": [1, 4], "full": [1, 2, 4]},
    {"label": "photon, beam, 50k photons", "fixed_radius": True,
     "args": PHOTON + ["--estimate", "beam", "--photons", 50000], "sweep": "--passes",
     "quick": [1, 4, 16], "full": [4, 16, 64, 128]},
    {"label": "photon, beam, progressive, 50k photons", "args": PHOTON + ["--estimate", "beam", "--photons", 50000],
     "sweep": "--passes", "quick": [1, 4, 16], "full": [4, 16, 64, 128, 256]},
]

# The reference: volpath with a seed independent of every measured render's (seed 1). The full
# mode's is main's photon-bench reference (scenes/fish.json at its own 400x400).
REFERENCE = {"quick": ["--spp", 2048, "--seed", 1000], "full": ["--spp", 4096, "--seed", 777]}


def without_water(scene):
    """The demo fish's scene less the box of water it swims in (the media of the fish are meshes)."""
    scene["media"] = [m for m in scene["media"] if m["shape"]["type"] == "mesh"]


def sweep(binary, mode, reference, work, fish):
    fixed_radius = fish_variant(work, "fixed-radius", lambda s: (without_water(s), s["integrator"].update(alpha=1)))
    points = []
    for method in METHODS:
        scene = fixed_radius if method.get("fixed_radius") else fish
        for value in method[mode]:
            args = list(method["args"]) + [method["sweep"], value, "--resolution", RESOLUTION[mode], "--seed", 1]
            output = os.path.join(work, f"{len(points)}.exr")
            seconds, mib = render(binary, scene, output, *args)
            d = diff(binary, output, reference)
            points.append({"method": method["label"], "option": method["sweep"], "value": value, "seconds": seconds,
                           "peak_mib": mib, "mae": d["mae"], "rmse": d["rmse"], "rel_mse": d["rel_mse"],
                           "non_finite": d["non_finite"], "fixed_radius": scene != fish, "args": " ".join(map(str, args))})
            print(f"{method['label']:52} {method['sweep']} {value:<7} {seconds:8.2f} s  mae {d['mae']:.5f}", file=sys.stderr)
    return points


def curves(points):
    return {method["label"]: [p for p in points if p["method"] == method["label"]] for method in METHODS}


def chart(points, stem, title):
    series = [(label, [(p["seconds"], p["mae"]) for p in curve], "y1") for label, curve in curves(points).items()]
    loglog_chart(stem, title, "rendering time (s), photon tracing included", "mean absolute error against the volpath reference", series)


def check_quick(points, stem):
    """The quick mode's assertions: every image finite, the files written, and along every curve
    but single scattering's (biased: it has no multiple scattering) the error falling with cost."""
    problems = [f"{p['method']} {p['option']} {p['value']}: {p['non_finite']} non-finite pixels" for p in points if p["non_finite"]]
    problems += [f"{p['method']} {p['option']} {p['value']}: rmse {p['rmse']}" for p in points if not math.isfinite(p["rmse"])]
    for label, curve in curves(points).items():
        if not label.startswith("single") and not curve[-1]["mae"] < 0.8 * curve[0]["mae"]:
            problems.append(f"{label}: error does not fall with cost: {[round(p['mae'], 5) for p in curve]}")
    problems += [f"{stem}{ext} not written" for ext in (".png", ".svg", ".json")
                 if not os.path.isfile(stem + ext) or os.path.getsize(stem + ext) == 0]
    if problems:
        fail("; ".join(problems))


def pareto(points, budgets=(0.5, 1, 2, 5, 10, 20, 50, 100)):
    """For each time budget the render with the lowest error among those that fit in it."""
    rows = []
    for budget in budgets:
        fitting = [p for p in points if p["seconds"] <= budget]
        if fitting:
            rows.append((budget, min(fitting, key=lambda p: p["mae"])))
    return rows


def section(points, reference_line, command_line, machine_line):
    lines = [f"Command: `{command_line}`. Every point is `tetglow render scenes/fish.json ARGS` (the scene less its water) at {RESOLUTION['full']},"
             f" then `tetglow diff` against {reference_line}. Time: tetglow's rendering time (photon tracing included,"
             f" tetrahedralization left out: it is cached and the same for every method). Error: the mean absolute"
             f" pixel error (the caustic's rare bright volpath samples dominate RMSE, given too). Machine: {machine_line}.",
             "", "![error against time](figures/sweep-fish.svg)", "",
             "**Pareto front** (the most accurate render that fits each time budget):", "",
             "| budget (s) | best method | setting | time (s) | mean abs. error |", "|---|---|---|---|---|"]
    lines += [f"| {b:g} | {p['method']} | `{p['option']} {p['value']}` | {p['seconds']:.2f} | {p['mae']:.5f} |" for b, p in pareto(points)]
    lines += ["", "Every point:", "", "| method | setting | time (s) | peak MiB | mean abs. error | RMSE | relative MSE |",
              "|---|---|---|---|---|---|---|"]
    lines += [f"| {p['method']} | `{p['option']} {p['value']}` | {p['seconds']:.2f} | {p['peak_mib']:.0f} | {p['mae']:.5f} "
              f"| {p['rmse']:.5f} | {p['rel_mse']:.5f} |" for p in points]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--quick", action="store_true")
    group.add_argument("--full", action="store_true")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="build folder holding tetglow")
    parser.add_argument("--out", help="quick mode: where the chart and data go (default BUILD/sweep-quick)")
    parser.add_argument("--reference", default=os.path.join(ROOT, "ref", "fish-volpath-4096.exr"),
                        help="full mode: the volpath reference, rendered there when missing (default %(default)s)")
    a = parser.parse_args()
    mode = "quick" if a.quick else "full"
    binary = executable(os.path.join(a.build, "tetglow"))
    out = FIGURES if a.full else (a.out or os.path.join(a.build, "sweep-quick"))
    os.makedirs(out, exist_ok=True)
    machine_line = machine()
    reference_args = ["--integrator", "volpath", *REFERENCE[mode], "--resolution", RESOLUTION[mode]]
    reference_line = "volpath " + " ".join(map(str, REFERENCE[mode]))
    with tempfile.TemporaryDirectory() as work:
        fish = fish_variant(work, "fish", without_water)
        reference = os.path.join(work, "reference.exr") if a.quick else a.reference
        if a.quick or not os.path.isfile(reference):
            os.makedirs(os.path.dirname(os.path.abspath(reference)), exist_ok=True)
            print("reference: tetglow render scenes/fish.json (less its water) " + " ".join(map(str, reference_args)), file=sys.stderr)
            seconds, _ = render(binary, fish, reference, *reference_args)
            reference_line += f" (rendered in {seconds:.0f} s)"
        points = sweep(binary, mode, reference, work, fish)
    stem = os.path.join(out, "sweep-fish")
    chart(points, stem, f"fish, {RESOLUTION[mode]}: error against rendering time")
    with open(stem + ".json", "w") as f:
        json.dump({"mode": mode, "machine": machine_line, "reference": reference_line, "points": points}, f, indent=1)
    if a.quick:
        check_quick(points, stem)
    else:
        replace_section("sweep", section(points, reference_line, "bench/results/sweep.py --full", machine_line))
    print(f"wrote {stem}.png, {stem}.svg, {stem}.json" + ("" if a.quick else " and docs/RESULTS.md"), file=sys.stderr)


if __name__ == "__main__":
    main()
