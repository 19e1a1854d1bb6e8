#!/usr/bin/env python3
"""How close `render --noise X` comes to the error it promises: per scene, a long reference
(--spp R, seed 1000), then renders with --noise X and seeds 1..N; each one's relative MSE against
the reference (`tetglow diff`) is compared with X. The reference's own error (about X times the
passes a --noise render takes, over R) is part of what is measured: R must be large.

  bench/results/noise_target.py [--build DIR] [--scenes sphere,fish,cloud-blue] [--res 32x24]
                                [--noise 0.01] [--seeds 10] [--reference-spp 1024] [--integrator volpath] [--docs]

Passes if, on every scene, at least 9 of 10 renders (the same share of other counts) land within
a factor 1.5 of X. --docs rewrites the noise-target section of docs/RESULTS.md.
"""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import ROOT, diff, machine, replace_section, tetglow  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--scenes", default="sphere,fish,cloud-blue")
    ap.add_argument("--res", default="32x24")
    ap.add_argument("--noise", type=float, default=0.01)
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--reference-spp", type=int, default=1024)
    ap.add_argument("--integrator", default="volpath")
    ap.add_argument("--docs", action="store_true")
    args = ap.parse_args()
    binary = os.path.join(args.build, "tetglow")
    command = "bench/results/noise_target.py " + " ".join(sys.argv[1:])
    rows, ok = [], True
    with tempfile.TemporaryDirectory() as work:
        for name in args.scenes.split(","):
            scene = os.path.join(ROOT, "scenes", name + ".json")
            common = ["--resolution", args.res, "--integrator", args.integrator]
            ref = os.path.join(work, name + "-ref.exr")
            tetglow(binary, "render", scene, "-o", ref, "--spp", args.reference_spp, "--seed", 1000, *common)
            errors, passes = [], []
            for seed in range(1, args.seeds + 1):
                out = os.path.join(work, f"{name}-{seed}.exr")
                log = tetglow(binary, "render", scene, "-o", out, "--noise", args.noise, "--seed", seed, *common)
                passes.append(int(log.split(" spp")[0].rsplit(" ", 1)[1]))
                errors.append(diff(binary, out, ref)["rel_mse"])
            within = sum(args.noise / 1.5 <= e <= args.noise * 1.5 for e in errors)
            ok &= within >= 0.9 * args.seeds
            rows.append(f"| {name} | {min(passes)}..{max(passes)} | {min(errors):.4g} | {sorted(errors)[len(errors) // 2]:.4g} | "
                        f"{max(errors):.4g} | {within} of {args.seeds} |")
            print(rows[-1], flush=True)
    text = (f"Command: `{command}`, on {machine()}.\n\n"
            f"Each scene at {args.res} with `--integrator {args.integrator} --noise {args.noise}` and seeds 1..{args.seeds}; "
            f"the error is the relative MSE against a {args.reference_spp}-spp render of seed 1000 (`tetglow diff`).\n\n"
            "| scene | passes taken | error: least | median | most | within a factor 1.5 of the target |\n|---|---|---|---|---|---|\n"
            + "\n".join(rows))
    print(text)
    if args.docs:
        replace_section("noise-target", text)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
