#!/usr/bin/env python3
"""tetglow (volpath, photon) against Blender's Cycles at equal time, in one script run.

Every point is a whole process (start-up, scene load, tets from the cache, photon tracing,
rendering, EXR written) timed by this script, on the same machine with the same thread count:
`tetglow render --time T` for tetglow, `blender -b --python cycles_render.py --spp N` for Cycles
with N chosen from a fit of its whole-process time against spp. The error is the MSE over
pixels and channels against a long Cycles reference (or tetglow volpath's, --volpath-reference), less the reference's own MSE, which is
estimated from a second reference with another seed (MSE(a, b) / 2) and must be at most a
quarter of the smallest MSE plotted; the script says so when it is not.

  bench/results/peer_sweep.py [--build DIR] [--scenes fish-body,blub,sphere,jade] [--budgets 2,5,15,60]
                      [--res 100x100] [--threads 2] [--reference-spp 16384] [--volpath-reference fish-body]
                      [--photons-per-pixel 1] [--out DIR] [--docs]

--docs writes docs/figures/peer-<scene>.{png,svg}, docs/figures/peer-sweep.json and the peer-sweep section of
docs/RESULTS.md. Needs Blender 3.4 and numpy for its Python (`apt-get install blender python3-numpy`) and
../shared/peers/cycles_render.py:
without either it says so and exits 0, writing nothing.
"""
import argparse
import json
import math
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import FIGURES, PEER, ROOT, cycles_render, diff, loglog_chart, machine, replace_section, scene_file, timed  # noqa: E402

METHODS = {"volpath": ["--integrator", "volpath"], "photon": ["--integrator", "photon"]}


def cycles(blender, scene, out, spp, seed, a):
    return cycles_render(blender, scene, out, spp, seed, a.res, a.threads)


def tetglow(a, scene, out, method, seconds, seed):
    extra = []
    if method == "photon":  # the photon paths per pass, from the image's pixels (docs/RESULTS.md, "How should a photon pass split ...")
        w, h = map(int, a.res.split("x"))
        extra = ["--photons", str(max(1, round(a.photons_per_pixel * w * h)))]
    # The most passes there are: a scene's own spp would otherwise end the render before --time.
    return timed([os.path.join(a.build, "tetglow"), "render", scene, "-o", out, *METHODS[method], *extra, "--time", f"{seconds:.3f}",
                  "--spp", "1048576", "--resolution", a.res, "--threads", str(a.threads), "--seed", str(seed)], out)


def mse(a, test, reference, own=0.0):
    """MSE against the reference, less the reference's own MSE `own`: for a test independent of
    the reference, E[(test - ref)^2] = E[(test - truth)^2] + E[(ref - truth)^2]."""
    return diff(os.path.join(a.build, "tetglow"), test, reference)["rmse"] ** 2 - own


def cycles_at(r, seconds):
    """Cycles' MSE at `seconds` of whole process: it is unbiased, so its MSE is inverse to its
    samples, which grow with the time after its start-up; scaled from the Cycles point nearest
    in time."""
    t0, m0, _ = min(r["curves"]["Cycles"], key=lambda p: abs(math.log(p[0] / seconds)))
    o = r["cycles_overhead_s"]
    return m0 * (t0 - o) / (seconds - o) if seconds > o else None


def reference(a, blender, scene, name, out, seed):
    """A long render for the reference: Cycles', or tetglow volpath's where --volpath-reference
    names the scene (where it is the more efficient unbiased renderer: the sweep's own volpath
    and Cycles curves say which)."""
    if name in a.volpath_reference:
        return timed([os.path.join(a.build, "tetglow"), "render", scene, "-o", out, "--integrator", "volpath", "--spp",
                      str(a.reference_spp), "--resolution", a.res, "--threads", str(a.threads), "--seed", str(seed)], out)
    return cycles(blender, scene, out, a.reference_spp, seed, a)


def sweep_scene(a, blender, name, work):
    scene = scene_file(name, work)
    refs = [os.path.join(work, f"{name}-ref{s}.exr") for s in (1, 2)]
    ref_seconds = [reference(a, blender, scene, name, r, 1000 + s) for s, r in enumerate(refs)]
    ref_error = mse(a, refs[0], refs[1]) / 2  # each reference's own MSE: the two are independent
    # Cycles' whole-process time against spp, t = overhead + spp * cost: from 16 spp and from
    # the first doubling that takes at least 2 s more (Blender's start-up alone is about a second).
    calibration = os.path.join(work, "cal.exr")
    t16, spp = cycles(blender, scene, calibration, 16, 7, a), 32
    while (t := cycles(blender, scene, calibration, spp, 7, a)) < t16 + 2 and spp < 1 << 20:
        spp *= 2
    cost = (t - t16) / (spp - 16)
    overhead = max(t16 - 16 * cost, 0)
    curves = {"Cycles": [], "volpath": [], "photon": []}
    for budget in a.budgets:
        spp = max(1, round((budget - overhead) / cost))
        out = os.path.join(work, f"{name}-cycles-{budget}.exr")
        curves["Cycles"].append((cycles(blender, scene, out, spp, 1, a), mse(a, out, refs[0], ref_error), spp))
        for method in METHODS:
            out = os.path.join(work, f"{name}-{method}-{budget}.exr")
            # --time bounds the rendering; the start-up (tets cached after the first run) comes on top.
            seconds = tetglow(a, scene, out, method, max(0.05, budget - a.tetglow_overhead), 1)
            curves[method].append((seconds, mse(a, out, refs[0], ref_error), None))
        print(f"{name} {budget} s: " + ", ".join(f"{k} {v[-1][0]:.1f} s MSE {v[-1][1]:.3g}" for k, v in curves.items()), flush=True)
    return {"scene": name, "reference": "tetglow volpath" if name in a.volpath_reference else "Cycles",
            "reference_spp": a.reference_spp, "reference_seconds": ref_seconds, "reference_mse": ref_error,
            "cycles_overhead_s": overhead, "cycles_s_per_spp": cost, "curves": curves}


def table(results):
    rows = ["| scene | method | seconds | MSE | Cycles' MSE at that time | tetglow / Cycles |", "|---|---|---|---|---|---|"]
    for r in results:
        for t, m, spp in r["curves"]["Cycles"]:
            rows.append(f"| {r['scene']} | Cycles, {spp} spp | {t:.1f} | {m:.3g} | | |")
        for method in METHODS:
            for t, m, _ in r["curves"][method]:
                c = cycles_at(r, t)
                rows.append(f"| {r['scene']} | tetglow {method} | {t:.1f} | {m:.3g} | {c:.3g} | {m / c:.2f} |" if c else
                            f"| {r['scene']} | tetglow {method} | {t:.1f} | {m:.3g} | - | - |")
    return "\n".join(rows)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default=os.path.join(ROOT, "build"))
    # jade: the dense showcase (albedo >= 0.99, mean free path about 1% of the figure, a small spot).
    p.add_argument("--scenes", default="fish-body,blub,sphere,jade")
    p.add_argument("--budgets", default="2,5,15,60")
    p.add_argument("--res", default="100x100")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--reference-spp", type=int, default=16384)
    p.add_argument("--volpath-reference", default="fish-body", help="scenes (comma-separated) whose reference tetglow volpath renders")
    p.add_argument("--photons-per-pixel", type=float, default=1.0, help="photon: photon paths per pass and pixel")
    p.add_argument("--tetglow-overhead", type=float, default=0.3, help="seconds of start-up taken off --time")
    p.add_argument("--out", default=None)
    p.add_argument("--docs", action="store_true")
    a = p.parse_args()
    a.budgets = [float(b) for b in a.budgets.split(",")]
    a.volpath_reference = [s for s in a.volpath_reference.split(",") if s]
    blender = shutil.which("blender")
    if not blender or not os.path.exists(PEER):
        print(f"peer_sweep: skipped: needs blender on PATH ({blender or 'not found'}) and {PEER} "
              f"({'found' if os.path.exists(PEER) else 'not found'})")
        return
    work = a.out or tempfile.mkdtemp(prefix="tetglow-peer-")
    os.makedirs(work, exist_ok=True)
    print(f"peer_sweep: {machine()}; work in {work}", flush=True)
    results = [sweep_scene(a, blender, name, work) for name in a.scenes.split(",")]
    for r in results:
        smallest = min(m for v in r["curves"].values() for _, m, _ in v)
        if r["reference_mse"] > smallest / 4:
            print(f"peer_sweep: warning: {r['scene']}: the reference's own MSE {r['reference_mse']:.3g} is above a quarter "
                  f"of the smallest MSE plotted ({smallest:.3g}): raise --reference-spp")
    print(table(results))
    if a.docs:
        for r in results:
            series = [(k, [(t, m) for t, m, _ in v], "y1") for k, v in r["curves"].items()]
            loglog_chart(os.path.join(FIGURES, f"peer-{r['scene']}"), f"{r['scene']}.json at {a.res}, {a.threads} threads",
                         "whole-process seconds", "MSE against the reference", series)
        with open(os.path.join(FIGURES, "peer-sweep.json"), "w") as f:
            json.dump({"machine": machine(), "args": vars(a), "results": results}, f, indent=1)
        replace_section("peer-sweep", f"Measured on {machine()}.\n\n" + table(results))


if __name__ == "__main__":
    main()
