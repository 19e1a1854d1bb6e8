#!/usr/bin/env python3
"""Speed against accuracy on the fish: every point is an actual render of scenes/fish.json,
its error measured by `tetglow diff` against a volpath reference, its time the rendering time
tetglow reports. One chart, error (log) against seconds (log), one curve per method. The error
is the mean absolute error: the caustic under the fish gives volpath rare, very bright samples
that dominate RMSE (reported too) for thousands of samples per pixel, the reference's included.

  bench/sweep.py --quick [--build DIR] [--out DIR]   small and cheap, for the test suite: the
      chart and data go to DIR (default BUILD/sweep-quick); checks that every render is finite
      and that volpath converges
  bench/sweep.py --full [--build DIR] [--reference EXR]   the docs' figures: renders the
      reference (or takes EXR, which must be the same size), writes docs/sweep-fish.{png,svg,json}
      and prints the docs/RESULTS.md table
"""
import argparse
import json
import math
import os
import sys
import tempfile

from benchlib import diff, fail, loglog_chart, machine, render

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "scenes", "fish.json")

# The settings of each mode: image size, reference samples per pixel, samples per pixel of the
# single-scattering renders.
MODES = {
    "quick": {"resolution": "48x48", "reference_spp": 2048, "single_spp": 4},
    "full": {"resolution": "160x160", "reference_spp": 16384, "single_spp": 16},
}

# One entry per curve: the label, the fixed arguments, the swept option and its values in each
# mode. A new method (the photon integrator's settings) is one more entry.
METHODS = [
    {"label": "volpath", "args": ["--integrator", "volpath"], "sweep": "--spp",
     "quick": [1, 4, 16, 64], "full": [1, 2, 4, 8, 16, 32, 64, 128, 256, 512]},
    {"label": "single, parity (the seed)", "args": ["--integrator", "single", "--boundary", "parity"], "sweep": "--step",
     "quick": [0.1, 0.04, 0.01], "full": [0.2, 0.1, 0.05, 0.02, 0.01, 0.005]},
    {"label": "single, tets", "args": ["--integrator", "single", "--boundary", "tet"], "sweep": "--step",
     "quick": [0.1, 0.04, 0.01], "full": [0.2, 0.1, 0.05, 0.02, 0.01, 0.005]},
]

REFERENCE_SEED = 1000  # the reference's noise is independent of every measured render's (seed 1)


def reference_args(mode):
    m = MODES[mode]
    return ["--integrator", "volpath", "--spp", m["reference_spp"], "--resolution", m["resolution"], "--seed", REFERENCE_SEED]


def sweep(binary, mode, reference, work):
    m = MODES[mode]
    points = []
    for method in METHODS:
        for value in method[mode]:
            args = list(method["args"]) + [method["sweep"], value, "--resolution", m["resolution"], "--seed", 1]
            if method["sweep"] != "--spp":
                args += ["--spp", m["single_spp"]]
            output = os.path.join(work, f"{len(points)}.exr")
            seconds, _ = render(binary, SCENE, output, *args)
            d = diff(binary, output, reference)
            points.append({"method": method["label"], "option": method["sweep"], "value": value, "seconds": seconds,
                           "mae": d["mae"], "rmse": d["rmse"], "rel_mse": d["rel_mse"], "non_finite": d["non_finite"],
                           "args": " ".join(map(str, args))})
            print(f"{method['label']:28} {method['sweep']} {value:<6} {seconds:8.3f} s  mae {d['mae']:.5f}", file=sys.stderr)
    return points


def chart(points, stem, title):
    series = [(method["label"], [(p["seconds"], p["mae"]) for p in points if p["method"] == method["label"]], "y1")
              for method in METHODS]
    loglog_chart(stem, title, "rendering time (s)", "mean absolute error against the volpath reference", series)


def check_quick(points):
    """The quick mode's assertions: every image finite, volpath's error falling with its samples."""
    problems = [f"{p['method']} {p['option']} {p['value']}: {p['non_finite']} non-finite pixels" for p in points if p["non_finite"]]
    problems += [f"{p['method']} {p['option']} {p['value']}: rmse {p['rmse']}" for p in points if not math.isfinite(p["rmse"])]
    volpath = [p["mae"] for p in points if p["method"] == "volpath"]
    if not volpath[-1] < 0.5 * volpath[0]:
        problems.append(f"volpath does not converge: mean absolute error {volpath}")
    if problems:
        fail("; ".join(problems))


def table(points, mode, reference, reference_seconds, command_line, machine_line):
    m = MODES[mode]
    lines = [f"Command: `{command_line}`. Scene `scenes/fish.json` at {m['resolution']}; reference: volpath,"
             f" {m['reference_spp']} spp, seed {REFERENCE_SEED}" +
             (f" ({reference_seconds:.1f} s)" if reference_seconds else f" (given: {reference})") +
             f"; single scattering at {m['single_spp']} spp. Machine: {machine_line}.", "",
             "| method | setting | rendering (s) | mean abs. error | RMSE | relative MSE |", "|---|---|---|---|---|---|"]
    for p in points:
        lines.append(f"| {p['method']} | {p['option']} {p['value']} | {p['seconds']:.3f} | {p['mae']:.5f} | {p['rmse']:.5f} "
                     f"| {p['rel_mse']:.5f} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--quick", action="store_true")
    group.add_argument("--full", action="store_true")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="build folder holding tetglow")
    parser.add_argument("--out", help="quick mode: where the chart and data go (default BUILD/sweep-quick)")
    parser.add_argument("--reference", help="full mode: a volpath reference EXR of the full mode's size")
    a = parser.parse_args()
    mode = "quick" if a.quick else "full"
    binary = os.path.join(a.build, "tetglow")
    if not os.access(binary, os.X_OK):
        fail(f"{binary}: not found; build first or give --build")
    out = os.path.join(ROOT, "docs") if a.full else (a.out or os.path.join(a.build, "sweep-quick"))
    os.makedirs(out, exist_ok=True)
    machine_start = machine()
    with tempfile.TemporaryDirectory() as work:
        reference, reference_seconds = a.reference, None
        if not reference:
            reference = os.path.join(work, "reference.exr")
            print("reference: tetglow render scenes/fish.json " + " ".join(map(str, reference_args(mode))), file=sys.stderr)
            reference_seconds, _ = render(binary, SCENE, reference, *reference_args(mode))
        points = sweep(binary, mode, reference, work)
    stem = os.path.join(out, "sweep-fish")
    chart(points, stem, f"fish, {MODES[mode]['resolution']}: error against rendering time")
    with open(stem + ".json", "w") as f:
        json.dump({"mode": mode, "machine": machine_start, "points": points}, f, indent=1)
    if a.quick:
        check_quick(points)
    command_line = "bench/sweep.py " + " ".join(sys.argv[1:])
    print(table(points, mode, a.reference, reference_seconds, command_line, machine_start))
    print(f"\nwrote {stem}.png, {stem}.svg, {stem}.json", file=sys.stderr)


if __name__ == "__main__":
    main()
