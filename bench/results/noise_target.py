#!/usr/bin/env python3
"""How close `render --noise X` comes to the error it promises: per scene, a long reference
(--spp R, seed 1000), then renders with --noise X and seeds 1..N; each one's relative MSE against
the reference (`tetglow diff`) is compared with X, and with the estimate the render printed; and
per pixel: the relative MSE of each 8x8 tile (`diff --tile 8`, the unit `--noise` plans its
passes by; one pixel's error alone is one draw of a squared error, which spreads over a factor 10)
against X. The
reference's own error (about X times the passes a --noise render takes, over R) is part of what
is measured, so R is at least 64 times the most passes a render took (the script says when not).

  bench/results/noise_target.py [--build DIR] [--scenes sphere:0.002,cloud-blue:0.002,blub:0.002]
                                [--res 32x24] [--seeds 10] [--reference-spp 4096]
                                [--integrator volpath] [--cap N] [--docs]

Each scene is NAME or NAME:TARGET, a name repeated for several targets (a scene of scenes/ or a variant benchlib.scene_file knows).
--noise samples adaptively, so that every tile ends within the target: the image's error, a mean
over the tiles, lies below it. Passes if, on every scene, the image's error is at most 1.5 times
the target in at least 9 of 10 renders (the same share of other counts), and the noisiest tile's
in at least 8 of 10 (per pixel). --cap N gives the renders --spp N (default: the scene's spp caps
them). --docs rewrites the noise-target section of docs/RESULTS.md.
"""
import argparse
import json
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import ROOT, machine, replace_section, scene_file, tetglow  # noqa: E402

TILE = 8  # the tiles of render/AdaptiveSampling.h


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--scenes", default="sphere:0.002,cloud-blue:0.002,blub:0.002")
    ap.add_argument("--res", default="32x24")
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--reference-spp", type=int, default=4096)
    ap.add_argument("--integrator", default="volpath")
    ap.add_argument("--cap", type=int, default=0)
    ap.add_argument("--docs", action="store_true")
    args = ap.parse_args()
    binary = os.path.join(args.build, "tetglow")
    command = "bench/results/noise_target.py " + " ".join(sys.argv[1:])
    rows, notes, ok = [], [], True
    with tempfile.TemporaryDirectory() as work:
        common = ["--resolution", args.res, "--integrator", args.integrator]
        for item in args.scenes.split(","):
            name, _, target = item.partition(":")
            target = float(target or 0.002)
            scene = scene_file(name, work)
            ref = os.path.join(work, name + "-ref.exr")
            if not os.path.exists(ref):  # one reference per scene, whatever the targets
                tetglow(binary, "render", scene, "-o", ref, "--spp", args.reference_spp, "--seed", 1000, *common)
            errors, passes, ratios, worst = [], [], [], []
            for seed in range(1, args.seeds + 1):
                out = os.path.join(work, f"{name}-{seed}.exr")
                cap = ["--spp", args.cap] if args.cap else []
                log = tetglow(binary, "render", scene, "-o", out, "--noise", target, "--seed", seed, *cap, *common)
                passes.append(int(re.search(r"(\d+) spp", log).group(1)))
                estimate = float(re.search(r"noise ([0-9.e+-]+) \(estimated", log).group(1))
                measured = json.loads(tetglow(binary, "diff", out, ref, "--json", "--tile", TILE))
                errors.append(measured["rel_mse"])
                worst.append(max(measured["tile_rel_mse"]))
                ratios.append(errors[-1] / estimate)
            within = sum(e <= target * 1.5 for e in errors)
            pixels_within = sum(w <= target * 1.5 for w in worst)
            ok &= within >= 0.9 * args.seeds and pixels_within >= 0.8 * args.seeds
            if max(passes) * 64 > args.reference_spp:
                notes.append(f"{name}: the reference has fewer than 64 times the {max(passes)} passes of the longest render")
            median = lambda v: sorted(v)[len(v) // 2]  # noqa: E731
            rows.append(f"| {name} | {target:g} | {min(passes)}..{max(passes)} | {min(errors):.4g} | {median(errors):.4g} | "
                        f"{max(errors):.4g} | {min(ratios):.2f}..{max(ratios):.2f} | {within} of {args.seeds} | "
                        f"{min(worst) / target:.2f}..{max(worst) / target:.2f} | {pixels_within} of {args.seeds} |")
            print(rows[-1], flush=True)
    text = (f"Command: `{command}`, on {machine()}.\n\n"
            f"Each scene at {args.res} with `--integrator {args.integrator} --noise TARGET` and seeds 1..{args.seeds}; "
            f"the error is the relative MSE against a {args.reference_spp}-spp render of seed 1000 (`tetglow diff`); "
            "the ratio is the error over the estimate the render printed when it stopped; per pixel: the "
            f"relative MSE of the noisiest {TILE}x{TILE} tile over the target.\n\n"
            "| scene | target | passes taken | error: least | median | most | error / estimate | at most 1.5 times the target "
            "| per pixel: noisiest tile / target | noisiest tile within 1.5 times the target |\n"
            "|---|---|---|---|---|---|---|---|---|---|\n"
            + "\n".join(rows) + "".join(f"\n\n{n}." for n in notes))
    print(text)
    if args.docs:
        replace_section("noise-target", text)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
