#!/usr/bin/env python3
"""How fast `tetglow preview` answers a change, on the demo fish (scenes/fish.json, 400x400).

Starts the preview on a copy of the scene in a temporary folder, changes g through the page's own
request (POST /settings) a few times and measures, from sending the request: the first new image
(the quarter-size quick look) and the first full-size pass, as seen by polling /state. Then it
saves the image every --every seconds while the last change renders, saves the scene, stops the
preview and renders the tuned scene with --reference-passes passes as the reference; each saved
image's relative MSE against it (`tetglow diff`) gives the time to relative MSE 0.05. --docs also
rewrites the preview section of docs/RESULTS.md.

  bench/results/preview_latency.py [--build DIR] [--changes N] [--watch S] [--reference-passes N] [--reference EXR] [--docs]
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests"))
sys.path.insert(0, os.path.join(ROOT, "bench"))
from preview_browser import Server  # noqa: E402  (the test's way of starting the server)
from benchlib import fish_variant, machine, replace_section  # noqa: E402


def relative_mse(tetglow, image, reference):
    out = subprocess.run([tetglow, "diff", image, reference, "--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)["rel_mse"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--changes", type=int, default=5)
    parser.add_argument("--reference-passes", type=int, default=400)
    parser.add_argument("--every", type=float, default=0.25)
    parser.add_argument("--watch", type=float, default=20, help="seconds of saved images after the last change")
    parser.add_argument("--reference", help="the reference EXR: read when it exists, else rendered there (default: a temporary file)")
    parser.add_argument("--docs", action="store_true", help="rewrite the preview section of docs/RESULTS.md")
    a = parser.parse_args()
    tetglow = os.path.join(a.build, "tetglow")
    work = tempfile.mkdtemp(prefix="tetglow-preview-bench-")
    path = fish_variant(work, "fish", lambda s: s.pop("output", None))

    server = Server(tetglow, path)
    state = server.state
    while not (state()["image"] or {}).get("passes"):
        time.sleep(0.05)
    quick, full = [], []
    for i in range(a.changes):
        g = 0.5 if i % 2 == 0 else 0.3
        sent = time.perf_counter()
        generation = server.json("/settings", json.dumps({"media": [{"g": g}]}))[1]["generation"]
        seen_quick = None
        while True:
            image = state()["image"]
            now = time.perf_counter() - sent
            if image["generation"] == generation:
                if image["passes"] == 0 and seen_quick is None:
                    seen_quick = now
                if image["passes"] >= 1:
                    full.append(now)
                    quick.append(seen_quick if seen_quick is not None else now)
                    break
            time.sleep(0.002)
        if i + 1 < a.changes:
            time.sleep(1)
    # The last change renders on: its images over time against the reference.
    saves = []
    while time.perf_counter() - sent < a.watch:
        _, reply = server.json("/save/image", "")
        saves.append((time.perf_counter() - sent, reply["passes"], reply["exr"]))
        time.sleep(a.every)
    tuned = server.json("/save/scene", "")[1]["scene"]
    server.stop()
    report = []

    def out(line):
        print(line, flush=True)
        report.append(line)

    out(f"changes of g: {a.changes}; first new image (quick look, 100x100): median {statistics.median(quick):.3f} s, "
          f"range {min(quick):.3f}-{max(quick):.3f} s; first full-size pass: median {statistics.median(full):.3f} s, "
          f"range {min(full):.3f}-{max(full):.3f} s")
    reference = a.reference or os.path.join(work, "reference.exr")
    if not os.path.isfile(reference):
        t = time.perf_counter()
        subprocess.run([tetglow, "render", tuned, "--passes", str(a.reference_passes), "-o", reference], check=True, capture_output=True)
        out(f"reference: {a.reference_passes} passes of the tuned scene (g {g}) in {time.perf_counter() - t:.0f} s")
    errors = [(s, p, relative_mse(tetglow, exr, reference)) for s, p, exr in saves]
    reached = next(((s, p, e) for s, p, e in errors if e <= 0.05), None)

    out("")
    out("| seconds after the change | passes | relative MSE |")
    out("|---|---|---|")
    for s, p, e in errors:
        out(f"| {s:.2f} | {p} | {e:.4f} |")
    out("")
    out("relative MSE 0.05 reached: " + (f"{reached[0]:.2f} s after the change ({reached[1]} passes)" if reached else "not within the watch"))
    if a.docs:
        replace_section("preview", f"Command: `bench/results/preview_latency.py --changes {a.changes} --reference-passes "
                        f"{a.reference_passes} --docs`, on {machine()}.\n\n" + "\n".join(report))
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
