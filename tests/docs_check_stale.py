#!/usr/bin/env python3
"""The code-names check catches a stale name: in a copy of the tree, a name that the code does not
have is planted in turn in a header's comment, a doc's backticks, a test's comment and a doc's
prose, and `docs_check.py code` must fail with one line naming that file, that line and that name
(and nothing else new). Usage: tests/docs_check_stale.py [--root DIR]"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

COPIED = ("README.md", "CMakeLists.txt", "src", "tests", "bench", "fuzz", "blender", "web", "cmake", "docs")
# (file, text appended as its last line, the name the check must report)
PLANTS = [
    ("src/scene/Scene.h", "// Shadow rays: Scene::transmittanceAlong.", "Scene::transmittanceAlong"),
    ("src/integrators/PathStep.h", "// Roulette's rules: photon/Roulette.h.", "photon/Roulette.h"),
    ("docs/USAGE.md", "The medium is a `RegionMediaGone`.", "RegionMediaGone"),
    ("tests/test_render.cpp", "// A stale path: src/integrators/NoSuchIntegrator.h.", "src/integrators/NoSuchIntegrator.h"),
    ("docs/DESIGN.md", "Walked by TetWalk::nextFaceGone.", "TetWalk::nextFaceGone"),
    ("docs/FORMAT.md", "A medium is read into a `Regionless`.", "Regionless"),
]


def run_check(root):
    r = subprocess.run([sys.executable, os.path.join(root, "tests", "docs_check.py"), "code", "--root", root],
                       capture_output=True, text=True)
    return r.returncode, set(r.stdout.splitlines())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    root = parser.parse_args().root
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        copy = os.path.join(tmp, "tree")
        ignore = shutil.ignore_patterns("build*", ".git", "__pycache__", "*.png", "*.exr", "*.jpg")
        for top in COPIED:
            source = os.path.join(root, top)
            if os.path.isdir(source):
                shutil.copytree(source, os.path.join(copy, top), ignore=ignore)
            else:
                os.makedirs(copy, exist_ok=True)
                shutil.copy(source, os.path.join(copy, top))
        _, before = run_check(copy)
        for path, text, name in PLANTS:
            file = os.path.join(copy, path)
            with open(file, encoding="utf-8") as f:
                original = f.read()
            with open(file, "w", encoding="utf-8") as f:
                f.write(original.rstrip("\n") + "\n" + text + "\n")
            line = original.rstrip("\n").count("\n") + 2
            rc, after = run_check(copy)
            expected = {f"{path}:{line}: names {name}, which the code does not have"}
            if rc != 1 or after - before != expected:
                failures.append(f"{path}: planted {name!r}: exit {rc}, new lines {sorted(after - before)}, "
                                f"wanted {sorted(expected)}")
            with open(file, "w", encoding="utf-8") as f:
                f.write(original)
    for f in failures:
        print(f)
    if failures:
        sys.exit(1)
    print(f"docs_check_stale: each of {len(PLANTS)} planted stale names fails the check, named with its file and line")


if __name__ == "__main__":
    main()
