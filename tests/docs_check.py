#!/usr/bin/env python3
"""Checks that the docs stay a reference, run by the test suite:

  tests/docs_check.py names [--root DIR]   docs/RESULTS.md's headings name no issue, session,
      date or clock time; no doc, code or script names an issue number or a session
  tests/docs_check.py links [--root DIR]   every relative link in README.md, bench/README.md and
      docs/**/*.md points to a file that exists (and, with #anchor, to a heading in it)
  tests/docs_check.py code [--root DIR]    every code name that README.md, docs/*.md or a comment in
      src/ and tests/ writes exists in the code (comments left out): a CamelCase name (in docs,
      in backticks, as is a capitalized word alone in backticks), a `Class::member`, a `file.h`
      or `file.cpp` path and a `src/...` path
  tests/docs_check.py readme [--root DIR]  README.md is a door, not a manual: at most 150 lines,
      and its first command for one's own mesh (`tetglow init`) within its first 60

Prints one line per problem (file:line: what) and exits 1 when there is any.
"""
import argparse
import fnmatch
import os
import re
import subprocess
import sys

# Spelled in pieces so that this file does not match itself.
ISSUE = re.compile(r"\b" + "iss" + r"ues? #?\d+|\(" + "iss" + r"ue\b|\b" + "sess" + r"ion \d+", re.IGNORECASE)
HEADING_WORDS = re.compile(r"\b(" + "iss" + "ue|" + "sess" + r"ion)s?\b|\b\d{1,2}:\d{2}\b|\b\d{4}-\d{2}-\d{2}\b", re.IGNORECASE)
TEXT = (".md", ".cpp", ".h", ".py", ".sh", ".txt", ".cmake", ".js", ".html", ".css", ".json", ".pbrt")
SCANNED = ("README.md", "CMakeLists.txt", "setup.sh", "src", "tests", "bench", "fuzz", "web", "docs", "scenes", "cmake", ".ci")


def tracked(root, tops=SCANNED):
    """The files of the source tree under `tops`: what git tracks or would track (untracked but
    not ignored), or, outside a git checkout, every file but build outputs."""
    try:
        r = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others", "--exclude-standard", "--", *tops],
                           capture_output=True, text=True)
        if r.returncode == 0:
            return [f for f in r.stdout.splitlines() if os.path.isfile(os.path.join(root, f))]
    except FileNotFoundError:  # no git on this machine
        pass
    files = []
    for top in tops:
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


def unfenced_lines(root, docs):
    """(doc, line number, line) of each line outside ``` fences of the docs that exist."""
    for doc in sorted(set(docs)):
        if not os.path.isfile(os.path.join(root, doc)):
            continue
        with open(os.path.join(root, doc), encoding="utf-8") as f:
            lines = f.read().splitlines()
        fenced = False
        for n, line in enumerate(lines, 1):
            if line.startswith("```"):
                fenced = not fenced
            if not fenced:
                yield doc, n, line


def check_links(root):
    problems = []
    docs = ["README.md", "bench/README.md"] + [f for f in tracked(root) if f.startswith("docs/") and f.endswith(".md")]
    for doc, n, line in unfenced_lines(root, docs):
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


# Code names in docs and comments: the code they must exist in, the files whose comments are
# checked, and the names of other projects (tests/docs_check_foreign.txt) that are not ours.
CODE = ("src", "tests", "bench", "fuzz", "blender", "web", "cmake", "CMakeLists.txt")
C_LIKE, SCRIPTS = (".h", ".cpp", ".hpp", ".c", ".js"), (".py", ".sh")
IDENT = re.compile(r"[A-Za-z_]\w*")
# Two humps or more (TetWalk, OpenEXR): one-hump words (Scene, Film) are English too.
CAMEL = re.compile(r"(?<![\w.:/-])([A-Z]\w*?[a-z]\w*?[A-Z]\w*)(\*?)")
MEMBER = re.compile(r"(?<![\w.:])([A-Z]\w*)::(~?[A-Za-z_]\w*)")
PATH = re.compile(r"(?<![\w/.-])((?:\.{1,2}/)*(?:src/[\w.*/-]*|[\w*-][\w.*-]*(?:/[\w.*-]+)*\.(?:h|cpp)\b))")


def split_c_like(text, quotes):
    """(code with comments blanked, [(line, comment text)]) of C++ or JavaScript source. String
    and raw-string literals stay code: a name an error message spells exists."""
    code, comments, i, n, line = [], [], 0, len(text), 1
    while i < n:
        c = text[i]
        if text.startswith("//", i) or text.startswith("/*", i):
            end = text.find("\n", i) if c == "/" and text[i + 1] == "/" else text.find("*/", i + 2)
            end = n if end < 0 else end + (0 if text[i + 1] == "/" else 2)
            for k, part in enumerate(text[i:end].split("\n")):
                comments.append((line + k, part))
            code.append("".join(ch if ch == "\n" else " " for ch in text[i:end]))
            line += text.count("\n", i, end)
            i = end
        elif c == "R" and text.startswith('"', i + 1) and "(" in text[i + 2:i + 20]:
            delim = text[i + 2:text.index("(", i + 2)]
            end = text.find(")" + delim + '"', i)
            end = n if end < 0 else end + len(delim) + 2
            code.append(text[i:end])
            line += text.count("\n", i, end)
            i = end
        elif c in quotes and (c != "'" or not (i and text[i - 1].isalnum())):  # 1'000 is a digit separator
            j = i + 1
            while j < n and text[j] != c and (text[j] != "\n" or c == "`"):
                j += 2 if text[j] == "\\" else 1
            code.append(text[i:j + 1])
            line += text.count("\n", i, j + 1)
            i = j + 1
        else:
            code.append(c)
            line += c == "\n"
            i += 1
    return "".join(code), comments


def split_script(text):
    """(code, [(line, comment text)]) of Python or shell: a # that starts a line's comment, outside quotes."""
    code, comments = [], []
    for n, row in enumerate(text.split("\n"), 1):
        quote, cut = None, None
        for k, ch in enumerate(row):
            if quote:
                quote = None if ch == quote and row[k - 1] != "\\" else quote
            elif ch in "'\"":
                quote = ch
            elif ch == "#" and (k == 0 or row[k - 1] in " \t") and not row.startswith("#!"):
                cut = k
                break
        code.append(row if cut is None else row[:cut])
        if cut is not None:
            comments.append((n, row[cut:]))
    return "\n".join(code), comments


def split_source(path, text):
    if path.endswith(C_LIKE):
        return split_c_like(text, "\"'`" if path.endswith(".js") else "\"'")
    if path.endswith(SCRIPTS):
        return split_script(text)
    return text, []


class CodeNames:
    """What the code has: its identifiers (comments left out), where each type or namespace is
    defined, and its files."""

    def __init__(self, root):
        self.files = tracked(root, CODE) + tracked(root)
        self.code, self.comments = {}, {}
        for path in set(self.files):
            # This check's own files spell stale names on purpose; they are no part of the code.
            if path.endswith(C_LIKE + SCRIPTS + (".txt", ".cmake")) and not os.path.basename(path).startswith("docs_check"):
                with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
                    self.code[path], self.comments[path] = split_source(path, f.read())
        self.idents = set()
        for text in self.code.values():
            self.idents.update(IDENT.findall(text))
        self.root = root
        self._defined = {}

    def defined_in(self, name):
        """The files whose code defines `name` as a class, struct, enum or namespace."""
        if name not in self._defined:
            pattern = re.compile(r"\b(?:class|struct|union|namespace|enum(?:\s+class)?)\s+" + name + r"\b(?!\s*;)")
            self._defined[name] = [p for p, t in self.code.items() if p.endswith(C_LIKE) and pattern.search(t)]
        return self._defined[name]

    def has_member(self, owner, member):
        if any(f"{owner}::{member}" in t for t in self.code.values()):
            return True
        files = self.defined_in(owner)
        if not files:
            return None  # not ours to judge: a type of another project
        stems = {os.path.splitext(p)[0] for p in files}
        return any(os.path.splitext(p)[0] in stems and re.search(r"\b" + re.escape(member.lstrip("~")) + r"\b", t)
                   for p, t in self.code.items())

    def has_path(self, path):
        path = re.sub(r"^(\.{1,2}/)+", "", path).rstrip("/")
        if "*" in path:
            return any(fnmatch.fnmatch(f, path) or fnmatch.fnmatch(f, "*/" + path) for f in self.files)
        if any(os.path.exists(os.path.join(self.root, top, path)) for top in ("", "src", "tests")):
            return True
        return any(f.endswith("/" + path) for f in self.files)

    def has_camel(self, name, prefix):
        if prefix:  # a test filter's Suite.Name*
            return any(i.startswith(name) for i in self.idents)
        return name in self.idents or (name.endswith("s") and name[:-1] in self.idents)  # InputErrors


def foreign_names(root):
    """Names of other projects (pbrt, Cycles, Embree, CGAL, TetGen, Blender, ...) that docs and
    comments may write: tests/docs_check_foreign.txt, one a line, # comments."""
    with open(os.path.join(root, "tests", "docs_check_foreign.txt"), encoding="utf-8") as f:
        return {w for line in f for w in [line.split("#", 1)[0].strip()] if w}


def stale_names(names, foreign, text, camel):
    """The code names in `text` that the code does not have: `Class::member`, paths, and
    CamelCase names when `camel`."""
    stale = []
    for owner, member in MEMBER.findall(text):
        if owner in foreign or f"{owner}::{member}" in foreign:
            continue
        if names.has_member(owner, member) is False or (owner not in names.idents and not names.defined_in(owner)):
            stale.append(f"{owner}::{member}")
    for path in PATH.findall(text):
        path = path.rstrip(".")  # a sentence's full stop
        if path not in foreign and not names.has_path(path):
            stale.append(path)
    if camel:
        for name, star in CAMEL.findall(text):
            if name not in foreign and not names.has_camel(name, star):
                stale.append(name + star)
    return stale


CODE_DOCS = ("README.md", "bench/README.md")
BACKTICKS = re.compile(r"`([^`]+)`")


def check_code(root):
    names, foreign = CodeNames(root), foreign_names(root)
    problems = []

    def report(path, n, stale):
        for name in dict.fromkeys(stale):
            problems.append(f"{path}:{n}: names {name}, which the code does not have")

    docs = [f for f in tracked(root) if re.fullmatch(r"docs/[^/]+\.md", f)] + list(CODE_DOCS)
    for doc, n, line in unfenced_lines(root, docs):
        if not line.startswith("<!--"):
            # CamelCase only in backticks: prose names TetGen, OpenEXR and GitHub too. A span that is
            # one capitalized word (`Scene`) is a type name as well.
            spans = BACKTICKS.findall(line)
            report(doc, n, stale_names(names, foreign, line, False) +
                   [s for span in spans for s in stale_names(names, foreign, span, True)] +
                   [w for w in spans if re.fullmatch(r"[A-Z]\w*", w) and w not in foreign and w not in names.idents])
    for path in sorted(names.comments):
        if path.startswith(("src/", "tests/")):
            for n, comment in names.comments[path]:
                report(path, n, stale_names(names, foreign, comment, True))
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
    parser.add_argument("check", choices=["names", "links", "code", "readme"])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    a = parser.parse_args()
    problems = {"names": check_names, "links": check_links, "code": check_code, "readme": check_readme}[a.check](a.root)
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)
    print(f"docs_check {a.check}: no problems")


if __name__ == "__main__":
    main()
