#!/usr/bin/env python3
"""The gallery (docs/GALLERY.md): the demo fish with a close-up of its head and lure at a higher resolution,
and the figures of the report tetglow grew from remade by tetglow (the white and the blue cloud,
each with single scattering beside multiple scattering, and the inside/outside debug picture of
the tets against the parity test). Every image is rendered here by the command printed under it;
the PNG previews tetglow writes beside its EXRs are copied to docs/images/ as 256-colour PNGs
(pngquant), and the gallery section of docs/GALLERY.md is rewritten with each command, its
whole-process time and the machine's load average while it ran.

  bench/results/gallery.py [--build DIR]
"""
import argparse
import os
import re
import resource
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # bench/, for benchlib
from benchlib import ROOT, fail, machine, replace_section  # noqa: E402

IMAGES = os.path.join(ROOT, "docs", "images")
LIMIT = 1 << 20  # all gallery images together, bytes

# (file name, caption, arguments after `tetglow`), shown two to a row; outputs go to out/, which git ignores.
GALLERY = [
    ("fish", "The demo: a deep-sea anglerfish in thin scattering water, lit by its own photophores and the lure on its "
     "stalk, which make a halo in the water; a dim blue-green key light casts its shadow and the caustic of its glass "
     "skin on the floor (photon mapping)",
     ["render", "scenes/fish.json", "-o", "out/fish.exr"]),
    ("fish-closeup", "The same scene closer, at 640 x 640: the lure's core and the two rows of photophores seen through "
     "the body, the eye, the stalk rising from the head",
     ["render", "scenes/fish-closeup.json", "-o", "out/fish-closeup.exr"]),
    ("cloud-white-single", "White cloud lit from the upper left, single scattering: only light scattered once reaches the eye, "
     "so the bright, nearly lossless cloud looks grey and its shadowed side black",
     ["render", "scenes/cloud-white.json", "--integrator", "single", "--spp", "24", "-o", "out/cloud-white-single.exr"]),
    ("cloud-white-multiple", "White cloud, multiple scattering (photon mapping): the light scattered many times fills it, "
     "white, and brightens its shadowed side",
     ["render", "scenes/cloud-white.json", "--integrator", "photon", "--passes", "96", "-o", "out/cloud-white-multiple.exr"]),
    ("cloud-blue-single", "Blue cloud lit from above and behind, single scattering: grey-green, bright only where the light enters, dark below",
     ["render", "scenes/cloud-blue.json", "--integrator", "single", "--spp", "24", "-o", "out/cloud-blue-single.exr"]),
    ("cloud-blue-multiple", "Blue cloud, multiple scattering (photon mapping): the long paths absorb the red and the green, "
     "so the whole cloud glows blue, its underside too",
     ["render", "scenes/cloud-blue.json", "--integrator", "photon", "--passes", "96", "-o", "out/cloud-blue-multiple.exr"]),
    ("inside-outside", "Inside/outside along the camera rays through the fish's mesh: green inside by tets and parity, "
     "dim red in the box only, magenta where the parity baseline's test disagrees with the tets",
     ["compare-boundary", "scenes/meshes/fish.obj", "--points", "1000", "--rays", "100", "--picture", "out/inside-outside.exr",
      "--picture-width", "400"]),
]


def run(binary, args):
    """Runs one gallery command from the repository root; returns its whole-process wall and CPU
    seconds (user and system, all threads: on a shared machine the wall time says more about the
    load than about tetglow) and the tetrahedralization seconds tetglow reports (None where it
    reports none)."""
    start, before = time.monotonic(), resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run([binary, *args], cwd=ROOT, capture_output=True, text=True)
    seconds, after = time.monotonic() - start, resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    if r.returncode != 0:
        fail(f"tetglow {' '.join(args)}: exit {r.returncode}: {r.stderr.strip()}")
    tets = re.search(r"tetrahedralization ([0-9.]+) s", r.stdout)
    return seconds, cpu, float(tets.group(1)) if tets else None


def quantize(source, target):
    """A 256-colour copy of a rendered PNG: a third to a fifth of the size, no difference the eye sees."""
    pngquant = shutil.which("pngquant")
    if not pngquant:
        fail("pngquant not found: install pngquant (./setup.sh does)")
    r = subprocess.run([pngquant, "--quality", "60-90", "--speed", "1", "--force", "--output", target, source],
                       capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"pngquant {source}: exit {r.returncode}: {r.stderr.strip()}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="folder holding the tetglow binary")
    args = parser.parse_args()
    binary = os.path.abspath(os.path.join(args.build, "tetglow"))
    if not os.access(binary, os.X_OK):
        fail(f"{binary} not found: build first (./setup.sh build)")
    os.makedirs(IMAGES, exist_ok=True)
    machine_line = machine()
    cells = []
    for name, caption, command in GALLERY:
        seconds, cpu, tets = run(binary, command)
        exr = command[command.index("-o" if "-o" in command else "--picture") + 1]
        quantize(os.path.join(ROOT, os.path.splitext(exr)[0] + ".png"), os.path.join(IMAGES, name + ".png"))
        timing = f"{seconds:.1f} s, CPU {cpu:.1f} s" + (f" (tetrahedralization {tets:.2f} s of it)" if tets is not None else "")
        print(f"gallery: {name}: {timing}")
        cells.append(f"![{caption}](images/{name}.png)<br>{caption}.<br>`build/tetglow {' '.join(command)}`<br>{timing}")
    total = sum(os.path.getsize(os.path.join(IMAGES, name + ".png")) for name, _, _ in GALLERY)
    if total > LIMIT:
        fail(f"the gallery's images take {total} bytes, over the {LIMIT} allowed")
    rows = ["| | |", "|---|---|"]
    for i in range(0, len(cells), 2):
        rows.append("| " + " | ".join(cells[i:i + 2] + [""] * (2 - len(cells[i:i + 2]))) + " |")
    note = (f"Rendered by `bench/results/gallery.py` on {machine_line}; times are whole-process wall times and "
            f"CPU times of all threads (the first render of a mesh includes its tetrahedralization, cached after), "
            f"measured at that load: where it exceeds the cores, the wall times grow with it. "
            f"Images: {total // 1024} KiB in all.")
    replace_section("gallery", "\n".join(rows) + "\n\n" + note, os.path.join(ROOT, "docs", "GALLERY.md"))


if __name__ == "__main__":
    main()
