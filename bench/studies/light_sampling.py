#!/usr/bin/env python3
"""Where volpath's noise comes from, and its variance at equal time against Cycles.

For scenes/blub.json, sphere.json and fish.json and for variants of each (every light alone,
direct light only with --max-depth 2, emission alone where the medium glows), two renders with
seeds 1 and 2 give each pixel's variance, var = rmse(a, b)^2 / 2 (mean over pixels and RGB, of
one render). The figure of merit is var x seconds (the whole process's CPU time, user + system,
which a shared machine disturbs less than its wall time; both are printed): the variance at
equal time, lower is better. Several tetglow binaries can be compared (--tetglow LABEL=BINARY, repeated).

With --cycles, Cycles renders each scene's full variant the same way through
../shared/peers/cycles_render.py (Blender 3.4 with numpy in its Python; skipped with a message
when either is absent: nothing else needs Blender), and the table gets Cycles' var x seconds (whole process, and its own
render time wall_s) beside tetglow's.

  bench/studies/light_sampling.py [--tetglow new=build/tetglow] [--spp 256] [--res 100] [--threads 1]
                          [--scenes blub,sphere,fish,blub-spot] [--cycles] [--cycles-spp 256]
"""
import argparse
import copy
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import PEER, ROOT, diff, fail, machine  # noqa: E402



# blub.json lit by a spot light without a radius instead of its quad light and environment
# (the "point spot light" case, where equiangular sampling matters).
BLUB_SPOT = {"type": "spot", "position": [0, 1.5, 0], "look_at": [-0.08, 0.02, 0], "cone_angle": 30, "cone_delta": 5,
             "intensity": [8, 8, 7.5]}


def load_scene(name):
    """The scene's JSON with its mesh paths made absolute, so variants load from anywhere;
    blub-spot: blub.json with BLUB_SPOT as its only light."""
    if name == "blub-spot":
        scene = load_scene("blub")
        scene["lights"] = [BLUB_SPOT]
        return scene
    path = os.path.join(ROOT, "scenes", name + ".json")
    with open(path) as f:
        scene = json.load(f)
    for m in scene.get("media", []) + scene.get("surfaces", []):
        if m["shape"].get("file"):
            m["shape"]["file"] = os.path.normpath(os.path.join(os.path.dirname(path), m["shape"]["file"]))
    return scene


def variants(scene):
    """(label, scene JSON, extra tetglow arguments): the whole scene, each light alone, the
    direct light only, and emission alone where a medium glows."""
    out = [("full", scene, [])]
    lights = scene["lights"]
    if len(lights) > 1:
        for i, light in enumerate(lights):
            alone = copy.deepcopy(scene)
            alone["lights"] = [light]
            out.append((f"{light['type']} light only", alone, []))
    out.append(("direct only (max-depth 2)", scene, ["--max-depth", 2]))
    if any(m.get("emission") for m in scene["media"]):
        dark = copy.deepcopy(scene)
        dark["lights"] = []
        out.append(("emission only", dark, []))
    return out


def timed(command):
    """(whole-process wall seconds, CPU seconds (user + system), stdout). On a shared machine the
    CPU seconds of a one-thread render are the steadier cost; both are reported."""
    start = time.monotonic()
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        proc = subprocess.Popen(command, stdout=out, stderr=err)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.monotonic() - start
        out.seek(0), err.seek(0)
        stdout, stderr = out.read(), err.read()
    if os.waitstatus_to_exitcode(status) != 0:
        fail(f"{' '.join(command)}: exit {os.waitstatus_to_exitcode(status)}: {stderr.strip()}")
    return wall, usage.ru_utime + usage.ru_stime, stdout


def variance(binary, a, b):
    return diff(binary, a, b)["rmse"] ** 2 / 2


def tetglow_point(binary, scene_path, work, tag, args):
    """(variance, mean whole-process wall seconds, mean CPU seconds) from seeds 1 and 2."""
    images, walls, cpus = [], [], []
    for seed in (1, 2):
        out = os.path.join(work, f"{tag}-s{seed}.exr")
        wall, cpu, _ = timed([binary, "render", scene_path, "-o", out, "--integrator", "volpath", "--seed", str(seed), *map(str, args)])
        images.append(out), walls.append(wall), cpus.append(cpu)
    return variance(binary, *images), sum(walls) / 2, sum(cpus) / 2


def cycles_point(binary, scene_path, work, tag, spp, res, threads):
    """(variance, mean whole-process CPU seconds, mean wall_s Cycles reports) from seeds 1 and 2."""
    images, seconds, walls = [], [], []
    for seed in (1, 2):
        out = os.path.join(work, f"{tag}-cycles-s{seed}.exr")
        _, s, stdout = timed(["blender", "-b", "--factory-startup", "--python", PEER, "--", scene_path, "--spp", str(spp),
                           "--out", out, "--res", res, "--threads", str(threads), "--seed", str(seed)])
        wall = re.search(r"CYCLES_RENDER .*wall_s=([0-9.]+)", stdout)
        if not wall:
            fail(f"no CYCLES_RENDER line from cycles_render.py: {stdout[-500:]!r}")
        images.append(out), seconds.append(s), walls.append(float(wall.group(1)))
    return variance(binary, *images), sum(seconds) / 2, sum(walls) / 2


def cycles_usable():
    """Whether cycles_render.py can run: Blender installed, with numpy in its Python."""
    if not shutil.which("blender"):
        print("light_sampling.py: blender not found, Cycles skipped", file=sys.stderr)
        return False
    probe = subprocess.run(["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python-expr", "import numpy"],
                           capture_output=True, text=True)
    if probe.returncode != 0:
        print("light_sampling.py: Blender's Python has no numpy (cycles_render.py needs it), Cycles skipped", file=sys.stderr)
        return False
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tetglow", action="append", default=[], help="LABEL=BINARY (repeatable; default new=build/tetglow)")
    parser.add_argument("--spp", type=int, default=256)
    parser.add_argument("--res", type=int, default=100)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--scenes", default="blub,sphere,fish,blub-spot")
    parser.add_argument("--full-only", action="store_true", help="only the full scenes, no decomposition")
    parser.add_argument("--cycles", action="store_true", help="also Cycles (needs blender)")
    parser.add_argument("--cycles-spp", type=int, default=256)
    a = parser.parse_args()
    binaries = [t.split("=", 1) for t in a.tetglow] or [["new", os.path.join(ROOT, "build", "tetglow")]]
    for label, binary in binaries:
        if not os.access(binary, os.X_OK):
            fail(f"{label}: {binary} is not an executable")
    cycles = a.cycles and cycles_usable()
    res = f"{a.res}x{a.res}"
    common = ["--spp", a.spp, "--resolution", res, "--threads", a.threads]
    print(f"# {machine()}; {res}, {a.spp} spp, {a.threads} thread(s)")
    print("| scene | variant | " + " | ".join(f"{l}: var, wall s, CPU s, var x CPU s" for l, _ in binaries) + (" | Cycles: var, CPU s (wall_s), var x CPU s (x wall_s)" if cycles else "") + " |")
    print("|---|---|" + "---|" * (len(binaries) + bool(cycles)))
    with tempfile.TemporaryDirectory() as work:
        for name in a.scenes.split(","):
            for i, (label, scene, args) in enumerate(variants(load_scene(name))):
                if a.full_only and i > 0:
                    break
                path = os.path.join(work, f"{name}-{i}.json")
                with open(path, "w") as f:
                    json.dump(scene, f)
                cells = []
                for tag, binary in binaries:
                    v, wall, cpu = tetglow_point(binary, path, work, f"{name}-{i}-{tag}", common + args)
                    cells.append(f"{v:.3g}, {wall:.2f}, {cpu:.2f}, {v * cpu:.3g}")
                if cycles and label == "full":
                    v, s, wall = cycles_point(binaries[0][1], path, work, f"{name}-{i}", a.cycles_spp, res, a.threads)
                    cells.append(f"{v:.3g}, {s:.2f} ({wall:.2f}), {v * s:.3g} ({v * wall:.3g})")
                elif cycles:
                    cells.append("")
                print(f"| {name} | {label} | " + " | ".join(cells) + " |", flush=True)
    print(f"# done; {machine()}")


if __name__ == "__main__":
    main()
