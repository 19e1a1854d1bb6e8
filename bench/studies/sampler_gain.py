#!/usr/bin/env python3
"""The pixel sampler's gain: the variance of a render at n samples per pixel (passes) with the
Owen-scrambled Sobol sampler of this build, against a baseline tetglow built before it
(independent PCG numbers), on scenes/fish.json and scenes/blub.json.

A study: it needs a second build from before the Sobol sampler, e.g. commit 6d405fe (`git
worktree add ../old 6d405fe` and a Release build there; the scenes must load in both builds).

The variance needs no reference: two renders with different seeds are independent, so the
per-pixel variance of one is half the mean squared difference between them (their bias
cancels). Writes the table into docs/RESULTS.md (section "sampler").

    bench/studies/sampler_gain.py --build build --baseline /path/to/old/tetglow
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import ROOT, diff, executable, machine, publish, render, table_parser  # noqa: E402

SCENES = ["fish", "blub"]
INTEGRATORS = ["volpath", "photon"]


def spread(binary, tag, scene, integrator, spp, resolution, work):
    """The variance per pixel and channel of one render, and the mean absolute difference of two
    (robust where a few rare bright paths dominate the variance)."""
    images = []
    for seed in (1, 2):
        out = os.path.join(work, f"{tag}-{scene}-{integrator}-{spp}-{seed}.exr")
        render(binary, os.path.join(ROOT, "scenes", scene + ".json"), out, "--integrator", integrator, "--spp", spp, "--seed", seed,
               "--resolution", resolution)
        images.append(out)
    d = diff(binary, images[0], images[1])
    return d["rmse"] ** 2 / 2, d["mae"]


def main():
    parser = table_parser(__doc__)
    parser.add_argument("--baseline", required=True, help="a tetglow built before the Sobol sampler")
    parser.add_argument("--spp", default="4,16,64", help="samples per pixel (photon: passes), comma-separated")
    args = parser.parse_args()
    binary, baseline = executable(os.path.join(args.build, "tetglow")), executable(args.baseline)
    spps = [int(s) for s in args.spp.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for scene in SCENES:
            for integrator in INTEGRATORS:
                for spp in spps:
                    old, oldMae = spread(baseline, "old", scene, integrator, spp, args.resolution, work)
                    new, newMae = spread(binary, "new", scene, integrator, spp, args.resolution, work)
                    rows.append(f"| {scene} | {integrator} | {spp} | {old:.3g} | {new:.3g} | {old / new:.2f} | {oldMae / newMae:.2f} |")
                    print(rows[-1], flush=True)
    publish("sampler", [
        f"Measured by `bench/studies/sampler_gain.py --baseline OLD/tetglow` at {args.resolution} on {machine()}.",
        "Variance per pixel and channel of one render (half the mean squared difference of two seeds), and the ratio",
        "of the mean absolute differences (independent over Sobol).",
        "",
        "| scene | integrator | spp | variance, independent (PCG) | variance, Sobol | ratio | MAE ratio |",
        "|---|---|---:|---:|---:|---:|---:|",
        *rows,
    ], args.no_results)


if __name__ == "__main__":
    main()
