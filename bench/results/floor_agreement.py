#!/usr/bin/env python3
"""Whether the photon integrator agrees with volpath on the directly lit floor: block
z-tests on BxB-pixel blocks of converged images of fish.json and blub.json.

Per scene: K renders of each method with seeds 1..K (volpath --spp N, photon --passes P, with
and without final gathering, and with --cycles-spp C Blender's Cycles through
../shared/peers/cycles_render.py as a third opinion; it renders no nested media). For
each block of the directly lit floor, z = (photon mean - volpath mean) / sqrt(s_p^2 / K + s_v^2 / K)
with s^2 the variance of the block's mean over the K seeds: photon noise is correlated from pixel
to pixel (one photon lights many), so only independent renders say how much a block mean
varies. Where both are unbiased, z is about N(0, 1) (Student's t with few seeds: heavier tails).
Where an estimate is heavy-tailed (volpath's and Cycles' light from a small lamp through the
fish's glass skin: docs/RESULTS.md), K runs' means usually fall short together and z overstates
the difference; the range of the runs' block means, printed per block, shows it.

The directly lit floor: pixels whose direct light (--max-depth 2, sky off) is the same with the
media made opaque black as with no media at all (to 1e-3), and above 0: nothing of the medium in
the pixel or in the way of its light. A block counts when all its pixels do.

  bench/results/floor_agreement.py [--build DIR] [--scenes fish,blub] [--res 200x200] [--runs 4]
                           [--spp 1024] [--passes 256] [--block 20] [--final-gather off,on]
                           [--cycles-spp C]
                           [--out DIR [--reuse]] [--docs]

The per-pixel work runs in Blender's Python (bench/results/exr_blocks.py: its image loader reads
OpenEXR, numpy from python3-numpy); without Blender the script says so and exits 0. --docs
rewrites the floor-agreement section of docs/RESULTS.md.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import PEER, ROOT, blender_env, cycles_render, fail, machine, replace_section, scene_file, scene_variant, tetglow  # noqa: E402


def direct_only(s, opaque):
    s["lights"] = [l for l in s["lights"] if l["type"] != "environment"]
    if opaque:
        for m in s["media"]:
            m.update({"sigma_a": 1e4, "sigma_s": 0, "emission": 0, "boundary": {"type": "interface"}})
            m.pop("density", None)
    else:
        s["media"] = []
        s.pop("cavities", None)


def blocks(blender, block, mask, free, images):
    r = subprocess.run([blender, "-b", "--factory-startup", "--python", os.path.join(ROOT, "bench", "exr_blocks.py"), "--",
                        "--block", str(block), "--mask", mask, "--unmasked", free, *images], capture_output=True, text=True,
                       env=blender_env())
    line = next((l for l in r.stdout.splitlines() if l.startswith("EXR_BLOCKS ")), None)
    if r.returncode != 0 or not line:
        fail(f"exr_blocks.py: exit {r.returncode}: {(r.stderr + r.stdout).strip()[-400:]}")
    return json.loads(line[len("EXR_BLOCKS "):])


def spread(values):
    mean = sum(values) / len(values)
    return mean, sum((v - mean) ** 2 for v in values) / (len(values) - 1)


def measure(a, blender, name, work):
    scene = scene_file(name, work)
    binary = os.path.join(a.build, "tetglow")
    common = ["--resolution", a.res, "--threads", str(a.threads)]
    mask, free = os.path.join(work, f"{name}-mask.exr"), os.path.join(work, f"{name}-free.exr")
    for out, opaque in ((mask, True), (free, False)):
        s = scene_variant(scene, work, f"{name}-{'opaque' if opaque else 'free'}", lambda s: direct_only(s, opaque))
        tetglow(binary, "render", s, "-o", out, "--integrator", "volpath", "--max-depth", 2, "--spp", 64, *common)
    methods = {"volpath": ["--integrator", "volpath", "--spp", a.spp]}
    for g in a.final_gather:
        methods[f"photon, final gather {g}"] = ["--integrator", "photon", "--passes", a.passes, "--final-gather", g]
    if a.cycles_spp:
        methods["Cycles"] = None  # not tetglow: benchlib.cycles_render
    runs = {m: [] for m in methods}
    for k in range(1, a.runs + 1):
        for method, extra in methods.items():
            out = os.path.join(work, f"{name}-{method.replace(', ', '-').replace(' ', '-')}-{k}.exr")
            if not (a.reuse and os.path.exists(out)):
                if extra is None:
                    cycles_render(blender, scene, out, a.cycles_spp, k, a.res, a.threads)
                else:
                    tetglow(binary, "render", scene, "-o", out, "--seed", k, *extra, *common)
            runs[method].append(out)
    b = blocks(blender, a.block, mask, free, [p for r in runs.values() for p in r])
    results = []
    for method in list(methods)[1:]:
        zs, ratios, ranges = [], [], []
        for i in range(len(b["blocks"])):
            v, m = [b["means"][p][i] for p in runs["volpath"]], [b["means"][p][i] for p in runs[method]]
            (mv, sv), (mp, sp) = spread(v), spread(m)
            zs.append((mp - mv) / math.sqrt((sv + sp) / a.runs) if sv + sp > 0 else 0.0)
            ratios.append(mp / mv if mv > 0 else float("nan"))
            # How far apart the runs' block means lie, relative: a heavy tail shows as a wide range.
            ranges.append(tuple((max(x) - min(x)) / (sum(x) / len(x)) if sum(x) > 0 else 0.0 for x in (v, m)))
        results.append({"scene": name, "method": method, "blocks": len(zs), "masked_pixels": b["masked_pixels"], "z": zs,
                        "ratios": ratios, "ranges": ranges, "mean_z": sum(zs) / len(zs) if zs else float("nan"),
                        "above_3": sum(abs(z) > 3 for z in zs), "mean_ratio": sum(ratios) / len(ratios) if ratios else float("nan")})
    return results


def table(a, results):
    rows = [f"| scene | method | floor blocks ({a.block}x{a.block} px) | method / volpath, mean over blocks | mean z | std z | abs(z) > 3 |",
            "|---|---|---|---|---|---|---|"]
    for r in results:
        n = r["blocks"]
        std = math.sqrt(sum((z - r["mean_z"]) ** 2 for z in r["z"]) / (n - 1)) if n > 1 else float("nan")
        rows.append(f"| {r['scene']} | {r['method']} | {n} ({r['masked_pixels']} px in the mask) | {r['mean_ratio']:.5f} | "
                    f"{r['mean_z']:.2f} | {std:.2f} | {r['above_3']} of {n} |")
    return "\n".join(rows)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    p.add_argument("--scenes", default="fish,blub", help="scenes/NAME.json, or a variant of fish.json (benchlib.scene_file())")
    p.add_argument("--res", default="200x200")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--runs", type=int, default=4)
    p.add_argument("--spp", type=int, default=1024)
    p.add_argument("--passes", type=int, default=256)
    p.add_argument("--block", type=int, default=20)
    p.add_argument("--final-gather", default="off,on", help="photon renders with --final-gather off, on or both")
    p.add_argument("--cycles-spp", type=int, default=0, help="> 0: Cycles renders too, at this many spp")
    p.add_argument("--out", default=None)
    p.add_argument("--reuse", action="store_true", help="keep the renders already in --out (same arguments)")
    p.add_argument("--docs", action="store_true")
    a = p.parse_args()
    a.final_gather = a.final_gather.split(",")
    if a.runs < 2:
        fail("--runs must be at least 2: a block's variance comes from the runs")
    blender = shutil.which("blender")
    if not blender:
        print("floor_agreement: skipped: needs blender on PATH (its Python reads OpenEXR) and python3-numpy")
        return
    if a.cycles_spp and not os.path.exists(PEER):
        fail(f"--cycles-spp needs {PEER}")
    work = a.out or tempfile.mkdtemp(prefix="tetglow-floor-")
    os.makedirs(work, exist_ok=True)
    print(f"floor_agreement: {machine()}; work in {work}", flush=True)
    results = [r for name in a.scenes.split(",") for r in measure(a, blender, name, work)]
    text = table(a, results)
    print(text)
    for r in results:  # block by block, in exr_blocks.py's order: where a disagreement sits
        print(f"{r['scene']}, {r['method']}: z " + " ".join(f"{z:.2f}" for z in r["z"]) + "; against volpath " +
              " ".join(f"{x:.4f}" for x in r["ratios"]) + "; range of the runs' block means, volpath / method (%) " +
              " ".join(f"{100 * v:.2f}/{100 * m:.2f}" for v, m in r["ranges"]))
    if a.docs:
        replace_section("floor-agreement", f"Measured on {machine()}: `bench/results/floor_agreement.py --res {a.res} --runs {a.runs} "
                                           f"--spp {a.spp} --passes {a.passes} --block {a.block}`.\n\n" + text)


if __name__ == "__main__":
    main()
