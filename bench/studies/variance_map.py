"""Where two renderers' noise differs, inside Blender (its image loader reads OpenEXR; numpy from
python3-numpy): per-pixel variance of renderer A from two seeds (A1, A2) and of renderer B (B1,
B2), var = (x1 - x2)^2 / 2, overall and by the brightness of the pixels' mean, then the ratio
A / B per 10x10-pixel block beside the blocks' means (rows from the image's bottom).

  blender -b --factory-startup --python bench/studies/variance_map.py -- A1.exr A2.exr B1.exr B2.exr
"""
import sys

import bpy
import numpy as np


def load(path):
    img = bpy.data.images.load(path)
    w, h = img.size
    return np.array(img.pixels[:], dtype=np.float64).reshape(h, w, 4)[:, :, :3]


a1, a2, b1, b2 = [load(p) for p in sys.argv[sys.argv.index("--") + 1:][:4]]
va, vb = ((a1 - a2) ** 2 / 2).mean(axis=2), ((b1 - b2) ** 2 / 2).mean(axis=2)
mean = (a1 + a2 + b1 + b2).mean(axis=2) / 4
print(f"variance per pixel: A {va.mean():.3e}, B {vb.mean():.3e}, A / B {va.mean() / vb.mean():.2f}")
for name, m in (("mean > 0.3", mean > 0.3), ("mean 0.1-0.3", (mean > 0.1) & (mean <= 0.3)), ("mean <= 0.1", mean <= 0.1)):
    print(f"{name}: {m.sum()} pixels, A {va[m].mean():.3e}, B {vb[m].mean():.3e}, share of A's {va[m].sum() / va.sum():.2f}")
h, w = va.shape
for y in range(0, h, 10):
    ratios = " ".join(f"{va[y:y + 10, x:x + 10].mean() / max(vb[y:y + 10, x:x + 10].mean(), 1e-12):5.1f}" for x in range(0, w, 10))
    print(ratios, "   ", " ".join(f"{mean[y:y + 10, x:x + 10].mean():4.2f}" for x in range(0, w, 10)))
