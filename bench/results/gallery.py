#!/usr/bin/env python3
"""The README gallery: the demo fish and the figures of the report tetglow grew from remade by tetglow (the white
and the blue cloud, each with single scattering beside multiple scattering, and the inside/outside
debug picture of the tets against the parity test). Every image is rendered here by the command
printed under it; the PNG previews tetglow writes beside its EXRs are copied to docs/images/ and
the gallery section of README.md is rewritten with each command and its whole-process time.

  bench/results/gallery.py [--build DIR]
"""
import argparse
import os
import re
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
    ("fish", "The demo: a fish in a glass skin with glowing photophores, lure core and dark eyes nested in its scattering body; photon mapping with caustics on the floor",
     ["render", "scenes/fish.json", "-o", "out/fish.exr"]),
    ("inside-outside", "Inside/outside along the camera rays: green inside by tets and parity, dim red in the box "
     "only, magenta where the parity baseline's test disagrees with the tets",
     ["compare-boundary", "scenes/fish.json", "--points", "1000", "--rays", "100", "--picture", "out/inside-outside.exr"]),
    ("cloud-white-single", "White cloud, single scattering",
     ["render", "scenes/cloud-white.json", "--integrator", "single", "--spp", "8", "-o", "out/cloud-white-single.exr"]),
    ("cloud-white-multiple", "White cloud, multiple scattering (photon mapping)",
     ["render", "scenes/cloud-white.json", "--integrator", "photon", "--passes", "48", "-o", "out/cloud-white-multiple.exr"]),
    ("cloud-blue-single", "Blue cloud, single scattering",
     ["render", "scenes/cloud-blue.json", "--integrator", "single", "--spp", "8", "-o", "out/cloud-blue-single.exr"]),
    ("cloud-blue-multiple", "Blue cloud, multiple scattering (photon mapping)",
     ["render", "scenes/cloud-blue.json", "--integrator", "photon", "--passes", "48", "-o", "out/cloud-blue-multiple.exr"]),
]


def run(binary, args):
    """Runs one gallery command from the repository root; returns its whole-process seconds and
    the tetrahedralization seconds tetglow reports (None where it reports none)."""
    start = time.monotonic()
    r = subprocess.run([binary, *args], cwd=ROOT, capture_output=True, text=True)
    seconds = time.monotonic() - start
    if r.returncode != 0:
        fail(f"tetglow {' '.join(args)}: exit {r.returncode}: {r.stderr.strip()}")
    tets = re.search(r"tetrahedralization ([0-9.]+) s", r.stdout)
    return seconds, float(tets.group(1)) if tets else None


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
        seconds, tets = run(binary, command)
        exr = command[command.index("-o" if "-o" in command else "--picture") + 1]
        shutil.copyfile(os.path.join(ROOT, os.path.splitext(exr)[0] + ".png"), os.path.join(IMAGES, name + ".png"))
        timing = f"{seconds:.1f} s" + (f" (tetrahedralization {tets:.2f} s of it)" if tets is not None else "")
        print(f"gallery: {name}: {timing}")
        cells.append(f"![{caption}](docs/images/{name}.png)<br>{caption}.<br>`build/tetglow {' '.join(command)}`<br>{timing}")
    total = sum(os.path.getsize(os.path.join(IMAGES, name + ".png")) for name, _, _ in GALLERY)
    if total > LIMIT:
        fail(f"the gallery's images take {total} bytes, over the {LIMIT} allowed")
    rows = ["| | |", "|---|---|"]
    for i in range(0, len(cells), 2):
        rows.append("| " + " | ".join(cells[i:i + 2] + [""] * (2 - len(cells[i:i + 2]))) + " |")
    note = (f"Rendered by `bench/results/gallery.py` on {machine_line}; times are whole-process wall times "
            f"(the first render of a mesh includes its tetrahedralization, cached after). Images: {total // 1024} KiB in all.")
    replace_section("gallery", "\n".join(rows) + "\n\n" + note, os.path.join(ROOT, "README.md"))


if __name__ == "__main__":
    main()
