#!/usr/bin/env python3
"""Checks that the docs stay a reference, run by the test suite:

  tests/docs_check.py names [--root DIR]   docs/RESULTS.md's headings name no issue, session,
      date or clock time; no doc, code or script names an issue number or a session
  tests/docs_check.py links [--root DIR]   every relative link in README.md, bench/README.md and
      docs/**/*.md points to a file that exists (and, with #anchor, to a heading in it)
  tests/docs_check.py readme [--root DIR]  README.md is a door, not a manual: at most 150 lines,
      and its first command for one's own mesh (`tetglow init`) within its first 60

Prints one line per problem (file:line: what) and exits 1 when there is any.
"""
import argparse
import os
import re
import subprocess
import sys

# Spelled in pieces so that this file does not match itself.
ISSUE = re.compile(r"\b" + "iss" + r"ues? #?\d+|\(" + "iss" + r"ue\b|\b" + "sess" + r"ion \d+", re.IGNORECASE)
HEADING_WORDS = re.compile(r"\b(" + "iss" + "ue|" + "sess" + r"ion)s?\b|\b\d{1,2}:\d{2}\b|\b\d{4}-\d{2}-\d{2}\b", re.IGNORECASE)
TEXT = (".md", ".cpp", ".h", ".py", ".sh", ".txt", ".cmake", ".js", ".html", ".css", ".json", ".pbrt")
SCANNED = ("README.md", "CMakeLists.txt", "setup.sh", "src", "tests", "bench", "fuzz", "web", "docs", "scenes", "cmake", ".ci")


def tracked(root):
    """The files of the source tree under the scanned paths: what git tracks or would track
    (untracked but not ignored), or, outside a git checkout, every file but build outputs."""
    try:
        r = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others", "--exclude-standard", "--", *SCANNED],
                           capture_output=True, text=True)
        if r.returncode == 0:
            return [f for f in r.stdout.splitlines() if os.path.isfile(os.path.join(root, f))]
    except FileNotFoundError:  # no git on this machine
        pass
    files = []
    for top in SCANNED:
        if os.path.isfile(os.path.join(root, top)):
            files.append(top)
        for folder, dirs, names in os.walk(os.path.join(root, top)):
            dirs[:] = [d for d in dirs if not d.startswith(("build", ".git", "__pycache__"))]
            files += [os.path.relpath(os.path.join(folder, n), root) for n in names]
    return files


def headings(lines):
    """(line number, heading text) of every Markdown heading outside fenced code blocks."""
    fenced = False
    for n, line in enumerate(lines, 1):
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and re.match(r"#{1,6} ", line):
            yield n, line.lstrip("#").strip()


def check_names(root):
    problems = []
    results = os.path.join(root, "docs", "RESULTS.md")
    with open(results, encoding="utf-8") as f:
        for n, title in headings(f.read().splitlines()):
            if HEADING_WORDS.search(title):
                problems.append(f"docs/RESULTS.md:{n}: heading names an issue, a session, a date or a clock time: {title}")
    for path in tracked(root):
        if not path.endswith(TEXT) or os.path.abspath(os.path.join(root, path)) == os.path.abspath(__file__):
            continue
        with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
            for n, line in enumerate(f, 1):
                m = ISSUE.search(line)
                if m:
                    problems.append(f"{path}:{n}: names an issue or a session ({m.group(0)!r}): {line.strip()[:120]}")
    return problems


def slug(title):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    title = re.sub(r"[`*_]", "", title.lower())
    return re.sub(r"[^\w\- ]", "", title).replace(" ", "-")


LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def check_links(root):
    problems = []
    docs = ["README.md", "bench/README.md"] + [f for f in tracked(root) if f.startswith("docs/") and f.endswith(".md")]
    for doc in sorted(set(docs)):
        if not os.path.isfile(os.path.join(root, doc)):
            continue
        with open(os.path.join(root, doc), encoding="utf-8") as f:
            lines = f.read().splitlines()
        fenced = False
        for n, line in enumerate(lines, 1):
            if line.startswith("```"):
                fenced = not fenced
            if fenced:
                continue
            for target in LINK.findall(line):
                if re.match(r"[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto:
                    continue
                path, _, anchor = target.partition("#")
                file = os.path.normpath(os.path.join(root, os.path.dirname(doc), path)) if path else os.path.join(root, doc)
                if not os.path.exists(file):
                    problems.append(f"{doc}:{n}: link to a missing file: {target}")
                elif anchor and file.endswith(".md"):
                    with open(file, encoding="utf-8") as g:
                        anchors = {slug(t) for _, t in headings(g.read().splitlines())}
                    if anchor not in anchors:
                        problems.append(f"{doc}:{n}: link to a missing heading: {target}")
    return problems


README_LINES, FIRST_SCENE_BY = 150, 60


def check_readme(root):
    with open(os.path.join(root, "README.md"), encoding="utf-8") as f:
        lines = f.read().splitlines()
    problems = []
    if len(lines) > README_LINES:
        problems.append(f"README.md: {len(lines)} lines, more than {README_LINES}: move the detail to docs/")
    init = next((n for n, line in enumerate(lines, 1) if re.match(r"\s*build/tetglow init ", line)), None)
    if init is None:
        problems.append("README.md: no command for one's own mesh (build/tetglow init MESH ...)")
    elif init > FIRST_SCENE_BY:
        problems.append(f"README.md:{init}: the first command for one's own mesh comes after line {FIRST_SCENE_BY}")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("check", choices=["names", "links", "readme"])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    a = parser.parse_args()
    problems = {"names": check_names, "links": check_links, "readme": check_readme}[a.check](a.root)
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)
    print(f"docs_check {a.check}: no problems")


if __name__ == "__main__":
    main()
