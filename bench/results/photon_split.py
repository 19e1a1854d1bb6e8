#!/usr/bin/env python3
"""How to split a photon pass between photon paths and eye samples: scenes/fish.json rendered by
the photon integrator for the same wall-clock budget with several photon counts per pass (as
photon paths per pixel, which carries over between resolutions), each measured against a
converged volpath reference. Writes the table into docs/RESULTS.md (section "photon-split").

    bench/results/photon_split.py --build build --reference ref.exr [--resolution 100x100 --time 10,30]

The reference must be scenes/fish.json at the same resolution (e.g. `tetglow render
scenes/fish.json --integrator volpath --spp 8192 --resolution 100x100`).
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import ROOT, diff, executable, fail, machine, publish, table_parser  # noqa: E402

PER_PIXEL = [0.08, 0.31, 1.25, 5.0]  # the committed fish: 50000 paths over 400x400 pixels is 0.31


def main():
    parser = table_parser(__doc__)
    parser.add_argument("--reference", required=True, help="converged volpath render of scenes/fish.json at --resolution")
    parser.add_argument("--time", default="10,30", help="seconds of rendering per run, comma-separated budgets")
    args = parser.parse_args()
    binary = executable(os.path.join(args.build, "tetglow"))
    width, height = (int(v) for v in args.resolution.split("x"))
    rows = []
    budgets = [float(t) for t in args.time.split(",")]
    with tempfile.TemporaryDirectory() as work:
        for budget, per_pixel in ((b, p) for b in budgets for p in PER_PIXEL):
            photons = max(1, round(per_pixel * width * height))
            out = os.path.join(work, f"split-{photons}.exr")
            r = subprocess.run([binary, "render", os.path.join(ROOT, "scenes", "fish.json"), "-o", out, "--resolution", args.resolution,
                                "--photons", str(photons), "--time", str(budget)], capture_output=True, text=True)
            if r.returncode != 0:
                fail(f"render with {photons} photons: {r.stderr.strip()}")
            passes = re.search(r", (\d+) spp", r.stdout)
            tracing = re.search(r"photon tracing ([0-9.]+) s, rendering ([0-9.]+) s", r.stdout)
            if not passes or not tracing:
                fail(f"no passes or times in tetglow's output: {r.stdout!r}")
            d = diff(binary, out, args.reference)
            trace, eye = float(tracing.group(1)), float(tracing.group(2))
            share = trace / (trace + eye)
            rows.append(f"| {budget:g} | {per_pixel:g} | {photons} | {passes.group(1)} | {share:.0%} | {d['rmse']:.4g} | {d['rel_mse']:.4g} |")
            print(rows[-1], flush=True)
    publish("photon-split", [
        f"Measured by `bench/results/photon_split.py --reference REF.exr --resolution {args.resolution} --time {args.time}` on {machine()}.",
        "",
        "| budget (s) | photon paths per pixel and pass | photons per pass | passes in the budget | photon tracing share of the time | RMSE | relative MSE |",
        "|---:|---:|---:|---:|---:|---:|---:|",
        *rows,
    ], args.no_results)


if __name__ == "__main__":
    main()
