#!/usr/bin/env python3
"""Fails when an include in src/ runs against the layering: a folder may include only itself
and the folders before it in the list CMakeLists.txt gives (TETGLOW_LAYERS).

  check_layering.py SRC_DIR LAYER [LAYER ...]     (bottom layer first)"""
import os
import re
import sys


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    src, layers = sys.argv[1], sys.argv[2:]
    rank = {name: i for i, name in enumerate(layers)}
    include = re.compile(r'^\s*#\s*include\s+"([A-Za-z_]+)/')
    wrong, unknown = [], []
    for folder in sorted(os.listdir(src)):
        path = os.path.join(src, folder)
        if not os.path.isdir(path):
            continue
        if folder not in rank:
            unknown.append(folder)
            continue
        for d, _, files in os.walk(path):
            for f in sorted(files):
                name = os.path.join(d, f)
                with open(name, encoding="utf-8") as lines:
                    for number, line in enumerate(lines, 1):
                        m = include.match(line)
                        if not m:
                            continue
                        target = m.group(1)
                        if target not in rank:
                            unknown.append(f"{name}:{number}: {target}/")
                        elif rank[target] > rank[folder]:
                            wrong.append(f"{name}:{number}: {folder} includes {line.strip()[9:]}, a layer above it")
    for line in unknown:
        print(f"layering: {line}: not a layer of TETGLOW_LAYERS")
    for line in wrong:
        print(f"layering: {line}")
    if wrong or unknown:
        return 1
    print(f"layering: every include in {src} runs down {' -> '.join(reversed(layers))}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
