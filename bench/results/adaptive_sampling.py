#!/usr/bin/env python3
"""Does adaptive sampling put samples where the error is? Per scene: a long reference (--spp R,
seed 1000); a render with `--noise X` (adaptive: each 8x8 tile takes the passes its own estimate
asks for); and a render of plain passes for the same wall time (`--time T`, T the adaptive
render's rendering seconds). Each one's relative MSE against the reference, and its noisiest
8x8 tile's (`tetglow diff --tile 8`); the CPU seconds of each command beside its wall seconds,
since the machine may be shared. One run of one script, so both see the same load.

  bench/results/adaptive_sampling.py [--build DIR] [--scenes sphere:0.002,blub:0.002,cloud-blue:0.002]
                                     [--res 48x32] [--reference-spp 4096] [--seed 1] [--threads 2]
                                     [--figure SCENE] [--docs]

--figure writes docs/figures/adaptive-tiles.svg: the tiles of SCENE, each tile's error with plain
passes against its error with adaptive sampling. --docs rewrites the adaptive-sampling section of
docs/RESULTS.md.
"""
import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import FIGURES, ROOT, fail, loglog_chart, machine, replace_section, scene_file, tetglow  # noqa: E402

TILE = 8  # the tiles of render/AdaptiveSampling.h


def timed_render(binary, scene, out, *args):
    """Renders; (stdout, wall seconds of the command, its CPU seconds, rendering seconds tetglow printed)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    r = subprocess.run([binary, "render", scene, "-o", out, *map(str, args)], capture_output=True, text=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        fail(f"render {scene} {' '.join(map(str, args))}: exit {r.returncode}: {r.stderr.strip()}")
    cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    rendering = float(re.search(r"rendering ([0-9.]+) s", r.stdout).group(1))
    return r.stdout, wall, cpu, rendering


def spp_of(log):
    m = re.search(r"(\d+) spp(?: \(the most a pixel took; ([0-9.]+) on average\))?", log)
    return float(m.group(2)) if m.group(2) else float(m.group(1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--scenes", default="sphere:0.002,blub:0.002,cloud-blue:0.002")
    ap.add_argument("--res", default="48x32")
    ap.add_argument("--reference-spp", type=int, default=4096)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--cap", type=int, default=4096, help="the spp that caps the adaptive render")
    ap.add_argument("--figure", default="")
    ap.add_argument("--docs", action="store_true")
    args = ap.parse_args()
    binary = os.path.join(args.build, "tetglow")
    command = "bench/results/adaptive_sampling.py " + " ".join(sys.argv[1:])
    rows, figure = [], None
    with tempfile.TemporaryDirectory() as work:
        common = ["--resolution", args.res, "--threads", args.threads, "--seed", args.seed]
        for item in args.scenes.split(","):
            name, _, target = item.partition(":")
            target = float(target or 0.002)
            scene = scene_file(name, work)
            ref = os.path.join(work, name + "-ref.exr")
            if not os.path.exists(ref):
                tetglow(binary, "render", scene, "-o", ref, "--spp", args.reference_spp, "--seed", 1000,
                        "--resolution", args.res)
            measured = {}
            out = os.path.join(work, f"{name}-adaptive.exr")
            log, wall, cpu, rendering = timed_render(binary, scene, out, "--noise", target, "--spp", args.cap, *common)
            measured["adaptive"] = (spp_of(log), wall, cpu, out)
            out = os.path.join(work, f"{name}-plain.exr")
            log, wall, cpu, _ = timed_render(binary, scene, out, "--time", rendering, "--spp", args.cap, *common)
            measured["plain"] = (spp_of(log), wall, cpu, out)
            tiles = {}
            cells = [name, f"{target:g}"]
            for method in ("plain", "adaptive"):
                spp, wall, cpu, out = measured[method]
                d = json.loads(tetglow(binary, "diff", out, ref, "--json", "--tile", TILE))
                tiles[method] = d["tile_rel_mse"]
                cells += [f"{spp:.1f}", f"{wall:.1f}", f"{cpu:.1f}", f"{d['rel_mse']:.3g}", f"{max(d['tile_rel_mse']):.3g}"]
            rows.append("| " + " | ".join(cells) + " |")
            print(rows[-1], flush=True)
            if name == args.figure:
                figure = (name, target, tiles)
    text = (f"Command: `{command}`, on {machine()}.\n\n"
            f"Each scene at {args.res}, seed {args.seed}, {args.threads} threads: `--noise TARGET --spp {args.cap}` "
            "(adaptive), then plain passes for the adaptive render's rendering seconds (`--time`); the error is the "
            f"relative MSE against a {args.reference_spp}-spp render of seed 1000 (`tetglow diff`), of the whole image "
            f"and of its noisiest {TILE}x{TILE} tile (`--tile {TILE}`). spp: the mean over the pixels. Wall and CPU "
            "seconds are of the whole command (the tets are cached).\n\n"
            "| scene | target | plain: spp | wall s | CPU s | error | noisiest tile | adaptive: spp | wall s | CPU s | "
            "error | noisiest tile |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n" + "\n".join(rows))
    if figure:
        name, target, tiles = figure
        order = sorted(range(len(tiles["plain"])), key=lambda i: tiles["plain"][i])
        stem = os.path.join(FIGURES, "adaptive-tiles")
        loglog_chart(stem, f"{name}: each {TILE}x{TILE} tile's relative MSE at equal time",
                     "the tile's error with plain passes", "relative MSE",
                     [("plain passes", [(tiles["plain"][i], tiles["plain"][i]) for i in order], "y1"),
                      ("adaptive (--noise)", [(tiles["plain"][i], tiles["adaptive"][i]) for i in order], "y1"),
                      (f"target {target:g}", [(tiles["plain"][i], target) for i in order], "y1")],
                     key="top left")
        os.remove(stem + ".png")  # the SVG is what RESULTS.md shows
        text += f"\n\n![tile errors at equal time](figures/adaptive-tiles.svg)"
    print(text)
    if args.docs:
        replace_section("adaptive-sampling", text)


if __name__ == "__main__":
    main()
