"""Block means of several renders, inside Blender (its image loader reads OpenEXR; numpy from
python3-numpy): for each BxB block of pixels, the grey mean of every image given, and the mask's
verdict (every pixel of the block in the mask). Used by bench/results/floor_agreement.py.

  blender -b --factory-startup --python bench/results/exr_blocks.py -- --block 20 --mask MASK.exr --unmasked FREE.exr A.exr ...

A pixel is in the mask when MASK is above 0 and equals FREE to 1e-3 (nothing of the medium in its
footprint or in the way of its light). The last line, EXR_BLOCKS {...}, holds the numbers as JSON.
"""
import json
import sys

import bpy
import numpy as np


def grey(path):
    img = bpy.data.images.load(path)
    w, h = img.size
    # Blender's rows run bottom to top; the block grid only needs to be the same for every image.
    return np.array(img.pixels[:], dtype=np.float64).reshape(h, w, 4)[:, :, :3].mean(axis=2)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    block = int(argv[argv.index("--block") + 1])
    mask, free = grey(argv[argv.index("--mask") + 1]), grey(argv[argv.index("--unmasked") + 1])
    skip = {argv.index(k) + 1 for k in ("--block", "--mask", "--unmasked")}
    paths = [p for i, p in enumerate(argv) if p.lower().endswith(".exr") and i not in skip]
    inside = (mask > 0) & (np.abs(mask - free) <= 1e-3 * np.maximum(free, 1e-12))
    h, w = mask.shape
    blocks = [(y, x) for y in range(0, h - block + 1, block) for x in range(0, w - block + 1, block)
              if inside[y:y + block, x:x + block].all()]
    images = {p: grey(p) for p in paths}
    means = {p: [float(g[y:y + block, x:x + block].mean()) for y, x in blocks] for p, g in images.items()}
    print("EXR_BLOCKS " + json.dumps({"blocks": blocks, "masked_pixels": int(inside.sum()), "means": means}))


main()
