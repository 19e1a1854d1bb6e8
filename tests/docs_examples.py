#!/usr/bin/env python3
"""Runs the examples of README.md and docs/FORMAT.md as a reader would, on a fresh copy of the
source tree (the files git tracks, and the build's tetglow at build/tetglow):

  tests/docs_examples.py --root SRC --tetglow BINARY [--section HEADING] [--expect FILE ...]

A code block is a command when its first word is a program or a path to one: each of its lines
runs in the copy's root (a trailing "# ..." is a comment) and must exit 0. A JSON block holding a
scene (an object with "camera" or "media") is saved, under the name of a preceding
`<!-- file: NAME -->` or one of its own, and rendered small, without a warning. A JSON block after
`<!-- fragment: NAME -->` is part of a scene (an object, or its keys without the braces): its
keys replace those of the scene an earlier block saved as NAME, and that is rendered small. Any
other JSON block that is not an object is an error, so that fragments stay marked. A block right after
`<!-- synopsis -->` is a synopsis (placeholders, a cluster, an installer) and is not run; any
other command that is not `build/tetglow` is an error, so that such blocks stay marked and rare.
Blocks run in the order of the files, each file in its own copy. With --section, only the blocks
under that heading run, and each --expect file must exist afterwards.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

COMMAND = re.compile(r"^(\./|build/|bench/|fuzz/|tests/|tetglow\s|cmake\b|ctest\b|python3?\b|sudo\b|apt(-get)?\b|git\b|cd\b)")
MARK = re.compile(r"<!--\s*(synopsis|(?:file|fragment):\s*(\S+))\s*-->")


def blocks(text):
    """(heading, mark, kind, body) for each code block: kind "fenced-LANG" or "indented"."""
    lines, heading, mark, i = text.split("\n"), "", None, 0
    while i < len(lines):
        line = lines[i]
        if line.startswith("#"):
            heading = line.lstrip("#").strip()
        m = MARK.search(line)
        if m:
            mark = m.group(1)
        if line.startswith("```"):
            j = i + 1
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            yield heading, mark, "fenced-" + line[3:].strip(), "\n".join(lines[i + 1:j])
            mark, i = None, j + 1
            continue
        if line.startswith("    ") and i > 0 and lines[i - 1].strip() == "":
            j = i
            while j < len(lines) and (lines[j].startswith("    ") or (lines[j].strip() == "" and j + 1 < len(lines) and lines[j + 1].startswith("    "))):
                j += 1
            yield heading, mark, "indented", "\n".join(l[4:] for l in lines[i:j])
            mark, i = None, j
            continue
        if line.strip() and not m:
            mark = None
        i += 1


def fresh_copy(root, tetglow, into):
    # Only what git tracks: a reader's own files (mine/, out/, a mesh beside the checkout) stay
    # out of the copy, so that the examples neither see nor depend on them.
    r = subprocess.run(["git", "-C", root, "ls-files", "--cached"], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{root}: not a git checkout: {r.stderr.strip()}")
    for f in r.stdout.splitlines():
        src = os.path.join(root, f)
        if os.path.isfile(src):
            os.makedirs(os.path.dirname(os.path.join(into, f)), exist_ok=True)
            shutil.copy2(src, os.path.join(into, f))
    os.makedirs(os.path.join(into, "build"), exist_ok=True)
    shutil.copy2(tetglow, os.path.join(into, "build", "tetglow"))


def run(cmd, cwd):
    print("$", cmd, flush=True)
    r = subprocess.run(cmd, shell=True, cwd=cwd, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        print(r.stdout + r.stderr)
    return r.returncode == 0


def render_scene(name, n, cwd):
    """"" when the scene renders without a warning, else what went wrong."""
    cmd = f"build/tetglow render {name} --resolution 24x18 --spp 1 -o out/docs-block-{n}.exr"
    print("$", cmd, flush=True)
    r = subprocess.run(cmd, shell=True, cwd=cwd, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        return "does not render: " + (r.stdout + r.stderr).strip()
    warnings = [line for line in r.stderr.splitlines() if "warning:" in line]
    return "renders with a warning: " + warnings[0] if warnings else ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--root", required=True)
    ap.add_argument("--tetglow", required=True)
    ap.add_argument("--section")
    ap.add_argument("--expect", nargs="*", default=[])
    args = ap.parse_args()
    failures, ran = [], 0
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["TETGLOW_CACHE_DIR"] = os.path.join(tmp, "cache")
        for doc in ["README.md"] if args.section else ["README.md", "docs/FORMAT.md"]:
            copy = os.path.join(tmp, doc.replace("/", "_"))
            fresh_copy(args.root, args.tetglow, copy)
            with open(os.path.join(args.root, doc)) as f:
                text = f.read()
            for n, (heading, mark, kind, body) in enumerate(blocks(text)):
                if args.section and heading != args.section:
                    continue
                where = f"{doc}, block {n} under '{heading}'"
                if mark == "synopsis":
                    continue
                first = body.strip().split("\n")[0] if body.strip() else ""
                if kind == "fenced-json" and mark and mark.startswith("fragment:"):
                    whole = mark[len("fragment:"):].strip()
                    try:
                        part = json.loads(body if body.lstrip().startswith("{") else "{" + body + "}")
                        with open(os.path.join(copy, whole)) as f:
                            scene = json.load(f)
                    except (ValueError, OSError) as e:
                        failures.append(f"{where}: a fragment of {whole}: {e}")
                        continue
                    scene.update(part)
                    name = f"docs-block-{n}.json"
                    with open(os.path.join(copy, name), "w") as f:
                        json.dump(scene, f)
                    ran += 1
                    if problem := render_scene(name, n, copy):
                        failures.append(f"{where}: {whole} with this fragment {problem}")
                elif kind == "fenced-json":
                    try:
                        scene = json.loads(body)
                    except ValueError as e:
                        failures.append(f"{where}: not a JSON object ({e}): mark a fragment <!-- fragment: FILE -->")
                        continue
                    if not isinstance(scene, dict) or not ("camera" in scene or "media" in scene):
                        continue
                    name = mark[len("file:"):].strip() if mark and mark.startswith("file:") else f"docs-block-{n}.json"
                    with open(os.path.join(copy, name), "w") as f:
                        f.write(body)
                    ran += 1
                    if problem := render_scene(name, n, copy):
                        failures.append(f"{where}: the scene {problem}")
                elif COMMAND.match(first):
                    for line in body.split("\n"):
                        cmd = re.sub(r"\s+#.*$", "", line).strip()
                        if not cmd:
                            continue
                        if not cmd.startswith("build/tetglow "):
                            failures.append(f"{where}: '{cmd}' cannot run here: mark the block <!-- synopsis -->")
                            break
                        ran += 1
                        if not run(cmd, copy):
                            failures.append(f"{where}: '{cmd}' failed")
                            break
            for e in args.expect:
                if not os.path.exists(os.path.join(copy, e)):
                    failures.append(f"{doc}: {e} was not written")
    for f in failures:
        print("FAIL:", f)
    print(f"{ran} examples run, {len(failures)} failures")
    sys.exit(1 if failures or ran == 0 else 0)


if __name__ == "__main__":
    main()
