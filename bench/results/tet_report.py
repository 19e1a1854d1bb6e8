#!/usr/bin/env python3
"""Formats tetglow_bench JSON runs as the docs/RESULTS.md tables, with ratios to the baselines
measured in the same run: Embree alone for ray walks, the parity test for inside tests. Each
figure is the best of the run's repetitions."""
import json
import sys

STEPS = (100, 500, 2500)  # the march's step: the box diagonal divided by these
RAYS = (1, 3, 5)          # parity rays per test (majority)


def rates(path):
    with open(path) as f:
        run = json.load(f)
    out, perRay = {}, {}
    for b in run["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        name = b.get("run_name", b["name"])
        for key in ("steps/s", "rays/s", "points/s"):
            if key in b:  # the best repetition: other jobs on a shared machine only slow runs down
                out[name] = max(out.get(name, 0), b[key])
        if "points/ray" in b:
            perRay[name] = b["points/ray"]
        if b.get("wrong", 0):
            sys.exit(f"{path}: {name} located {b['wrong']:.0f} samples in the wrong tet")
        if "bytes/tet" in b:
            out["bytes/tet"] = b["bytes/tet"]
    return out, perRay, run["context"]


def fitWalk(r, perRay):
    """The tets' time per ray as a fixed walk plus a cost per sample (seconds), fitted to the
    coarsest and finest steps."""
    (n0, s0), (n1, s1) = [(perRay[f"BM_LocateAlongPath/{k}"], r[f"BM_LocateAlongPath/{k}"]) for k in (STEPS[0], STEPS[-1])]
    perSample = (n1 / s1 - n0 / s0) / (n1 - n0)
    return n0 / s0 - n0 * perSample, perSample


def main():
    runs = [(arg.split("=")[0], *rates(arg.split("=")[1])) for arg in sys.argv[1:]]
    print("| mesh | tet steps/s (1 core) | full walks/s | Embree entry+exit/s | walk / Embree | hinted locate/s | bytes/tet |")
    print("|" + "---|" * 7)
    for name, r, _, _ in runs:
        m = lambda k: r[k] / 1e6
        print(f"| {name} | {m('BM_TetSteps'):.1f} M | {m('BM_RayWalkFull'):.3f} M | {m('BM_EmbreeEntryExit'):.2f} M "
              f"| {r['BM_RayWalkFull'] / r['BM_EmbreeEntryExit']:.2f} | {m('BM_LocateWithHint'):.2f} M | {r['bytes/tet']:.0f} |")
    print("\n| mesh | step | samples/ray | tets: located/s | parity 1 ray/s | parity 3/s | parity 5/s "
          "| tets / parity 1 | tets / parity 3 | tets / parity 5 |")
    print("|" + "---|" * 10)
    for name, r, perRay, _ in runs:
        for k in STEPS:
            tets = r[f"BM_LocateAlongPath/{k}"]
            parity = [r[f"BM_ParityAlongPath/{n}/{k}"] for n in RAYS]
            print(f"| {name} | diag / {k} | {perRay[f'BM_LocateAlongPath/{k}']:.0f} | {tets / 1e6:.1f} M | "
                  + " | ".join(f"{p / 1e6:.2f} M" for p in parity) + " | "
                  + " | ".join(f"{tets / p:.1f}" for p in parity) + " |")
    print()
    for name, r, perRay, _ in runs:
        walk, perSample = fitWalk(r, perRay)
        chord = perRay[f"BM_LocateAlongPath/{STEPS[0]}"] / STEPS[0]  # mean stretch in the box, in diagonals
        for n in RAYS:
            parity = max(r[f"BM_ParityAlongPath/{n}/{k}"] for k in STEPS)  # its best, as for every figure
            # Samples per ray from which the tets locate 20 times the parity test's rate.
            budget = 1 / (20 * parity) - perSample
            samples = walk / budget if budget > 0 else float("inf")
            print(f"- {name}, parity {n} ray{'s' if n > 1 else ''} ({1e9 / parity:.0f} ns per sample): tets 20x from "
                  f"{samples:.0f} samples per ray (step diagonal / {samples / chord:.0f}); walk {walk * 1e9:.0f} ns "
                  f"per ray + {perSample * 1e9:.1f} ns per sample")
    ctx = runs[0][3]
    print(f"\nMachine: {ctx['num_cpus']} x {ctx['mhz_per_cpu']} MHz, {ctx['host_name']}, {ctx['date']}.")


if __name__ == "__main__":
    main()
