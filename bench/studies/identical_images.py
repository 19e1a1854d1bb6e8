#!/usr/bin/env python3
"""Whether two builds of tetglow render the same images, bit for bit, on every scene in scenes/:
the check a refactoring must pass. Each scene is rendered small and briefly by both binaries with
the same seed, every integrator the scene can take; the EXR files are compared byte for byte.

  identical_images.py BASE_BINARY NEW_BINARY [--resolution 48x36] [--threads 2]

Exits 1 and names the renders that differ."""
import argparse
import filecmp
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Per integrator, options that keep each render to seconds.
INTEGRATORS = {
    "volpath": ["--integrator", "volpath", "--spp", "4"],
    "photon": ["--integrator", "photon", "--passes", "2", "--photons", "2000"],
    "single": ["--integrator", "single", "--spp", "2"],
}


def render(binary, scene, integrator, out, resolution, threads):
    command = [binary, "render", scene, "-o", out, "--resolution", resolution, "--threads", str(threads),
               "--seed", "7"] + INTEGRATORS[integrator]
    result = subprocess.run(command, capture_output=True, text=True)
    return result.returncode, result.stderr.strip().splitlines()[-1:] if result.stderr else []


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("--resolution", default="48x36")
    parser.add_argument("--threads", type=int, default=2)
    a = parser.parse_args()
    scenes_dir = os.path.join(ROOT, "scenes")
    scenes = sorted(f for f in os.listdir(scenes_dir) if f.endswith((".json", ".pbrt")))
    differ = []
    with tempfile.TemporaryDirectory() as tmp:
        for scene in scenes:
            for integrator in INTEGRATORS:
                outs = []
                for label, binary in (("base", a.base), ("new", a.new)):
                    out = os.path.join(tmp, f"{label}-{scene}-{integrator}.exr")
                    code, tail = render(binary, os.path.join(scenes_dir, scene), integrator, out, a.resolution, a.threads)
                    outs.append((code, out, tail))
                (c0, o0, t0), (c1, o1, t1) = outs
                if c0 != 0 and c1 != 0:
                    print(f"{scene:18} {integrator:8} both refuse ({t0[0] if t0 else c0})")
                    continue
                same = c0 == c1 == 0 and filecmp.cmp(o0, o1, shallow=False)
                print(f"{scene:18} {integrator:8} {'same' if same else 'DIFFERENT'}")
                if not same:
                    differ.append(f"{scene} {integrator}")
    if differ:
        print("differ: " + ", ".join(differ))
        return 1
    print(f"all {len(scenes)} scenes: the same images bit for bit")
    return 0


if __name__ == "__main__":
    sys.exit(main())
