#!/usr/bin/env python3
"""How fast the demo (scenes/fish.json) reaches relative MSE 0.01 against a long reference.

Renders the demo once with --reference (the error after each pass goes to the CSV beside the
image) and prints, for every pass: the whole process's wall time at that pass (its total less the
render's seconds still to come), the render's own seconds, and the relative MSE; then the first
pass at or below --goal, and the process's wall and CPU (user + sys) seconds with the load average
before and after. Arguments after `--` go to `tetglow render` as they are.

  bench/results/demo_speed.py --reference fish-ref-256.exr [--build DIR] [--goal 0.01] [-- --spp 12]

The reference: `build/tetglow render scenes/fish.json --spp 256 --seed 1000 -o fish-ref-256.exr`.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "bench"))
from benchlib import executable, fail, machine  # noqa: E402


def main():
    argv = sys.argv[1:]
    extra = argv[argv.index("--") + 1:] if "--" in argv else []
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--reference", required=True, help="the 256-pass reference EXR")
    parser.add_argument("--goal", type=float, default=0.01)
    a = parser.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    if not os.path.isfile(a.reference):
        fail(f"{a.reference}: no such reference image")
    tetglow = executable(os.path.join(a.build, "tetglow"))
    work = tempfile.mkdtemp(prefix="tetglow-demo-speed-")
    image = os.path.join(work, "fish.exr")
    command = [tetglow, "render", os.path.join(ROOT, "scenes", "fish.json"), "--reference", a.reference, "-o", image,
               *extra]
    load_before = machine()
    start = time.monotonic()
    with tempfile.TemporaryFile("w+") as log:
        proc = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.monotonic() - start
        log.seek(0)
        output = log.read()
    if os.waitstatus_to_exitcode(status) != 0:
        fail(f"{' '.join(command)}: exit {os.waitstatus_to_exitcode(status)}: {output.strip()[-400:]}")
    cpu = usage.ru_utime + usage.ru_stime
    with open(os.path.join(work, "fish.csv")) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        fail(f"{work}/fish.csv: no passes")
    last = float(rows[-1]["seconds"])
    print(f"command: {' '.join(command[1:])}")
    print("| pass | wall at the pass (s) | render (s) | relative MSE |")
    print("|---|---|---|---|")
    reached = None
    for row in rows:
        seconds, mse = float(row["seconds"]), float(row["rel_mse_vs_reference"])
        at = wall - (last - seconds)
        print(f"| {row['pass']} | {at:.1f} | {seconds:.1f} | {mse:.4f} |")
        if reached is None and mse <= a.goal:
            reached = (row["pass"], at, mse)
    print(f"whole process: {wall:.1f} s wall, {cpu:.1f} s CPU ({usage.ru_utime:.1f} user + {usage.ru_stime:.1f} sys)")
    print(f"before: {load_before}")
    print(f"after:  {machine()}")
    if reached:
        print(f"relative MSE {reached[2]:.4f} <= {a.goal} first at pass {reached[0]}, {reached[1]:.1f} s wall")
    else:
        print(f"relative MSE {float(rows[-1]['rel_mse_vs_reference']):.4f}: above {a.goal} at every pass")


if __name__ == "__main__":
    main()
