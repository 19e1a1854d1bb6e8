#!/usr/bin/env python3
"""Volpath's time per sample in two builds of tetglow, in one run: blub, the sphere and jade,
rendered by the two binaries in turn (old, new, old, new, ...) with the same seed, and for each the
rendering time the renderer reports and the process's CPU seconds (user + sys, which load inflates
less than wall time). Prints per scene the medians and new / old; the load average before and after.

  volpath_sample_time.py OLD_BINARY NEW_BINARY [--repeats 4] [--threads 1] [--scenes blub,sphere,jade]

The tet cache is warmed first, so neither build pays the tetrahedralization."""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Per scene: resolution and samples per pixel for a few seconds of rendering on one core.
SCENES = {"blub": ("100x100", 32), "sphere": ("100x100", 32), "jade": ("64x48", 32)}


def run(binary, scene, threads, out):
    res, spp = SCENES[scene]
    command = [binary, "render", os.path.join(ROOT, "scenes", scene + ".json"), "--integrator", "volpath",
               "--resolution", res, "--spp", str(spp), "--threads", str(threads), "--seed", "1", "-o", out]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)}: exit {result.returncode}: {result.stderr.strip().splitlines()[-1:]}")
    match = re.search(r"rendering ([0-9.]+) s \(([0-9]+) samples/s\)", result.stdout + result.stderr)
    if not match:
        sys.exit(f"{' '.join(command)}: no rendering time in its output")
    return float(match.group(1)), int(match.group(2))


def cpu_seconds(function, *args):
    before = os.times()
    result = function(*args)
    after = os.times()
    return result, (after.children_user - before.children_user) + (after.children_system - before.children_system)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--repeats", type=int, default=4)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--scenes", default="blub,sphere,jade")
    a = parser.parse_args()
    print(f"load average before: {' '.join(f'{x:.1f}' for x in os.getloadavg())}")
    with tempfile.TemporaryDirectory() as tmp:
        for scene in a.scenes.split(","):
            run(a.old, scene, a.threads, os.path.join(tmp, "warm.exr"))  # the tet cache
            times = {"old": [], "new": []}
            cpu = {"old": [], "new": []}
            for _ in range(a.repeats):
                for label in ("old", "new"):
                    (seconds, _), used = cpu_seconds(run, getattr(a, label), scene, a.threads,
                                                     os.path.join(tmp, label + ".exr"))
                    times[label].append(seconds)
                    cpu[label].append(used)
            old_t, new_t = statistics.median(times["old"]), statistics.median(times["new"])
            old_c, new_c = statistics.median(cpu["old"]), statistics.median(cpu["new"])
            res, spp = SCENES[scene]
            print(f"{scene} {res} {spp} spp, {a.threads} thread(s), median of {a.repeats}: rendering "
                  f"{old_t:.2f} s -> {new_t:.2f} s (new/old {new_t / old_t:.3f}); process CPU "
                  f"{old_c:.2f} s -> {new_c:.2f} s ({new_c / old_c:.3f})")
            print(f"  rendering s, old: {' '.join(f'{x:.2f}' for x in times['old'])}; "
                  f"new: {' '.join(f'{x:.2f}' for x in times['new'])}")
    print(f"load average after: {' '.join(f'{x:.1f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
