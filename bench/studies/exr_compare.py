"""Whether two renders of one scene have the same expectation: per-channel image means, the
ratio A/B with its 1-sigma error from the per-pixel difference (the renders' noise is
independent), and a z-test of the grey difference on blocks of pixels (z ~ N(0, 1) per block
when both are unbiased). Runs inside Blender (its image loader reads OpenEXR; no numpy needed):

  blender -b --factory-startup --python bench/studies/exr_compare.py -- A.exr B.exr [--block 10]

The last line, EXR_COMPARE {...}, holds the numbers as JSON.
"""
import json
import math
import sys

import bpy


def load(path):
    img = bpy.data.images.load(path)
    w, h = img.size
    px = img.pixels[:]
    return w, h, [px[i:i + 3] for i in range(0, len(px), 4)]


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    block = int(argv[argv.index("--block") + 1]) if "--block" in argv else 10
    paths = [p for p in argv if p.lower().endswith(".exr")]
    (w, h, a), (w2, h2, b) = load(paths[0]), load(paths[1])
    if (w, h) != (w2, h2):
        sys.exit(f"different sizes: {w}x{h} and {w2}x{h2}")
    n = w * h
    mean_a = [sum(p[c] for p in a) / n for c in range(3)]
    mean_b = [sum(p[c] for p in b) / n for c in range(3)]
    ratio, sigma = [], []
    for c in range(3):
        d = [p[c] - q[c] for p, q in zip(a, b)]
        md = sum(d) / n
        sd = math.sqrt(sum((x - md) ** 2 for x in d) / (n - 1))
        ratio.append(mean_a[c] / mean_b[c])
        sigma.append(sd / math.sqrt(n) / mean_b[c])
    zs = []
    for by in range(0, h - block + 1, block):
        for bx in range(0, w - block + 1, block):
            d = [sum(a[y * w + x]) / 3 - sum(b[y * w + x]) / 3 for y in range(by, by + block) for x in range(bx, bx + block)]
            level = sum(sum(a[y * w + x]) for y in range(by, by + block) for x in range(bx, bx + block)) / (3 * len(d))
            m = sum(d) / len(d)
            s = math.sqrt(sum((x - m) ** 2 for x in d) / (len(d) - 1))
            # A block without noise (the sky seen directly) differs by a constant, to float
            # rounding: there is nothing to test its difference against.
            if s > 1e-6 * abs(level):
                zs.append(m / (s / math.sqrt(len(d))))
    mz = sum(zs) / len(zs)
    sz = math.sqrt(sum((z - mz) ** 2 for z in zs) / (len(zs) - 1))
    result = {"mean_a": mean_a, "mean_b": mean_b, "ratio": ratio, "sigma": sigma, "blocks": len(zs),
              "mean_z": mz, "std_z": sz, "above_3": sum(abs(z) > 3 for z in zs), "above_4": sum(abs(z) > 4 for z in zs)}
    print("EXR_COMPARE " + json.dumps(result))


main()
