"""What the bench scripts share: running tetglow and timing it, the machine's description,
log-log charts drawn by gnuplot (PNG and SVG, in docs/figures/), and rewriting their sections of
docs/RESULTS.md (from Python, or from a shell script through `benchlib.py section`)."""
import argparse
import json
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def fail(message):
    sys.exit(f"{os.path.basename(sys.argv[0])}: error: {message}")


def executable(path):
    """path, when it is an executable tetglow, else the script fails naming it."""
    if not os.access(path, os.X_OK):
        fail(f"{path}: not an executable tetglow")
    return path


def tetglow(binary, *args):
    """Runs tetglow; its stdout, or a one-line failure with its stderr."""
    r = subprocess.run([binary, *map(str, args)], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"tetglow {' '.join(map(str, args))}: exit {r.returncode}: {r.stderr.strip()}")
    return r.stdout


def render(binary, scene, output, *args):
    """Renders; returns (rendering seconds as tetglow reports them, peak resident MiB of the whole
    command). The seconds leave out tetrahedralization (cached, the same for every method)."""
    command = [binary, "render", scene, "-o", output, *map(str, args)]
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        proc = subprocess.Popen(command, stdout=out, stderr=err)
        _, status, usage = os.wait4(proc.pid, 0)  # this child's own peak memory
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0), err.seek(0)
        stdout, stderr = out.read(), err.read()
    if proc.returncode != 0:
        fail(f"{' '.join(command)}: exit {proc.returncode}: {stderr.strip()}")
    # tetglow prints the seconds to 0.01; samples over samples per second keeps the digits.
    size = re.search(r": (\d+)x(\d+), (\d+) spp", stdout)
    rate = re.search(r"rendering [0-9.]+ s \((\d+) samples/s\)", stdout)
    if not size or not rate or int(rate.group(1)) == 0:
        fail(f"no rendering time in tetglow's output: {stdout!r}")
    average = re.search(r"spp \(the most a pixel took; ([0-9.]+) on average\)", stdout)  # --noise: adaptive
    samples = int(size.group(1)) * int(size.group(2)) * (float(average.group(1)) if average else int(size.group(3)))
    return samples / int(rate.group(1)), usage.ru_maxrss / 1024


def scene_variant(scene, work, name, edit):
    """Writes work/name.json: the scene file after edit(parsed JSON) (a function that changes it
    in place), its mesh paths made absolute so that it loads from there."""
    with open(scene) as f:
        s = json.load(f)
    for m in s["media"] + s.get("cavities", []):
        if m["shape"].get("file"):
            m["shape"]["file"] = os.path.join(os.path.dirname(os.path.abspath(scene)), m["shape"]["file"])
    edit(s)
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(s, f)
    return path


def fish_variant(work, name, edit):
    """scene_variant() of scenes/fish.json, its media unnamed (Cycles' peer script takes no names)."""
    def unnamed(s):
        edit(s)
        for m in s["media"]:
            m.pop("name", None)
    return scene_variant(os.path.join(ROOT, "scenes", "fish.json"), work, name, unnamed)


def glass_quad(s):
    """fish.json's body alone, a blue scattering medium of moderate density (optical thickness
    1 to 1.5 across the body) in a glass skin of index 1.5, lit by a 0.2 x 0.2 quad light above
    it, whose caustic falls on the floor and whose reflection and refraction a few pixels see."""
    s["media"] = [dict(s["media"][0], sigma_a=[1.2, 0.45, 0.06], sigma_s=[0.8, 1.1, 1.4], g=0.3,
                       boundary={"type": "dielectric", "ior": 1.5})]
    s["media"][0].pop("emission")
    s["integrator"].pop("spp")  # --time alone ends a render
    s["lights"] = [{"type": "quad", "corner": [0.1, 2.5, 0.3], "edge0": [0.2, 0, 0], "edge1": [0, 0, 0.2],
                    "radiance": [500, 480, 450]}, s["lights"][1]]


def scene_file(name, work):
    """scenes/NAME.json, or a variant of fish.json written into work: fish-body (the body alone:
    Cycles' peer script renders no nested media; the body keeps its glass skin), fish-clear (the
    body alone, its medium cleared: the glass skin's caustics and reflections alone),
    fish-matched (the skin index-matched: no caustics) or fish-wide-light (the spot's disk 4
    times as wide, so that paths through the skin reach it 16 times as often) or glass-quad
    (glass_quad())."""
    if name == "fish-body":
        return fish_variant(work, name, lambda s: s.update(media=s["media"][:1]))
    if name == "fish-clear":
        return fish_variant(work, name, lambda s: s.update(media=[dict(s["media"][0], sigma_a=0, sigma_s=0, emission=0)]))
    if name == "fish-matched":
        return fish_variant(work, name, lambda s: s["media"][0].update(boundary={"type": "interface"}))
    if name == "fish-wide-light":
        return fish_variant(work, name, lambda s: [l.update(radius=4 * l["radius"]) for l in s["lights"] if l["type"] == "spot"])
    if name == "glass-quad":
        return fish_variant(work, name, glass_quad)
    return os.path.join(ROOT, "scenes", name + ".json")


def blender_env():
    """The environment without a Python version manager's paths: Blender's embedded Python would
    take its modules (numpy, which cycles_render.py needs) from there instead of Debian's."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYENV")}
    env["PATH"] = os.pathsep.join(d for d in env.get("PATH", "").split(os.pathsep) if "pyenv" not in d)
    return env


def timed(command, out, env=None):
    """Runs a whole process that writes `out`; its wall-clock seconds, or a one-line failure
    (Blender exits 0 even when the script it runs fails, so the output is checked too)."""
    if os.path.exists(out):
        os.remove(out)
    start = time.monotonic()
    r = subprocess.run(command, capture_output=True, text=True, env=env)
    seconds = time.monotonic() - start
    if r.returncode != 0 or not os.path.exists(out):
        fail(f"{' '.join(command)}: exit {r.returncode}, {out} {'written' if os.path.exists(out) else 'not written'}: "
             f"{(r.stderr + r.stdout).strip()[-400:]}")
    return seconds


# Blender's Cycles with every convention matched to tetglow's (its README.md has the table).
PEER = os.path.join(os.path.dirname(ROOT), "shared", "peers", "cycles_render.py")


def cycles_render(blender, scene, out, spp, seed, res, threads):
    """Renders a tetglow JSON scene with Cycles through PEER; its whole-process seconds."""
    return timed([blender, "-b", "--factory-startup", "--python", PEER, "--", scene, "--spp", str(spp), "--out", out,
                  "--res", res, "--threads", str(threads), "--seed", str(seed)], out, blender_env())


def diff(binary, test, reference):
    return json.loads(tetglow(binary, "diff", test, reference, "--json"))


def machine():
    """One line: CPU model, cores, memory, OS, load at the time of the call."""
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            model = next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
    except (OSError, StopIteration):
        pass
    memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    return f"{os.cpu_count()} x {model}, {memory:.0f} GiB, {platform.system()} {platform.release()}, load average {load}"


def loglog_chart(stem, title, xlabel, ylabel, series, y2label=None, key="top right"):
    """Writes stem.png and stem.svg: one line per (label, [(x, y), ...], axis) in `series`, axis
    "y1" or "y2" (the right axis, labelled y2label), both axes logarithmic; `key` places the legend
    where the data leave room."""
    gnuplot = shutil.which("gnuplot")
    if not gnuplot:
        fail("gnuplot not found: install gnuplot-nox (./setup.sh does)")
    blocks = []
    for i, (label, points, _) in enumerate(series):
        rows = "\n".join(f"{x!r} {y!r}" for x, y in points if x > 0 and y > 0)
        blocks.append(f"$s{i} << EOD\n{rows}\nEOD")
    plots = ", ".join(f"$s{i} using 1:2 axes x1{axis} with linespoints lw 2 pt {7 + i % 6} title {json.dumps(label)}"
                      for i, (label, _, axis) in enumerate(series))
    common = "\n".join(blocks) + f"""
set title {json.dumps(title)}
set xlabel {json.dumps(xlabel)}
set ylabel {json.dumps(ylabel)}
set logscale xy
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set key inside {key} box opaque
set format x '%g'
set format y '%g'
"""
    if y2label:
        common += f"set y2label {json.dumps(y2label)}\nset logscale y2\nset y2tics\nset format y2 '%g'\n"
    for terminal, ext in (("pngcairo size 1000,640 font 'sans,11'", "png"), ("svg size 1000,640 font 'sans,11'", "svg")):
        script = f"set terminal {terminal}\nset output {json.dumps(f'{stem}.{ext}')}\n{common}plot {plots}\n"
        r = subprocess.run([gnuplot], input=script, capture_output=True, text=True)
        if r.returncode != 0:
            fail(f"gnuplot failed on {stem}.{ext}: {r.stderr.strip()}")


RESULTS = os.path.join(ROOT, "docs", "RESULTS.md")
FIGURES = os.path.join(ROOT, "docs", "figures")  # charts and their data, linked from RESULTS.md


def replace_section(name, text, path=RESULTS):
    """Puts `text` between <!-- name:begin --> and <!-- name:end --> in `path` (docs/RESULTS.md),
    leaving the rest (written by hand or by other scripts) as it is. The markers must already be there."""
    begin, end = f"<!-- {name}:begin -->", f"<!-- {name}:end -->"
    with open(path) as f:
        doc = f.read()
    if doc.count(begin) != 1 or doc.count(end) != 1 or doc.index(begin) > doc.index(end):
        fail(f"{path}: needs exactly one {begin} followed by one {end}")
    head, rest = doc.split(begin)
    with open(path, "w") as f:
        f.write(f"{head}{begin}\n{text}\n{end}{rest.split(end, 1)[1]}")


def table_parser(doc):
    """Arguments of a script that writes a table into docs/RESULTS.md: --build, --resolution and
    --no-results; the script adds its own."""
    parser = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="folder with this build's tetglow")
    parser.add_argument("--resolution", default="100x100")
    parser.add_argument("--no-results", action="store_true", help="print the table only, leave docs/RESULTS.md")
    return parser


def publish(section, lines, no_results):
    """Prints `lines` and, unless no_results, writes them into `section` of docs/RESULTS.md."""
    text = "\n".join(lines)
    if not no_results:
        replace_section(section, text)
    print(text)


def section_from_stdin(argv):
    """`python3 bench/benchlib.py section NAME COMMAND < TEXT`: how the shell scripts rewrite their
    section of docs/RESULTS.md, with TEXT under a line naming COMMAND and this machine."""
    if len(argv) != 3 or argv[0] != "section":
        fail("usage: benchlib.py section NAME COMMAND < TEXT")
    name, command = argv[1], argv[2]
    replace_section(name, f"Command: `{command}`, on {machine()}.\n\n{sys.stdin.read().strip()}")


if __name__ == "__main__":
    section_from_stdin(sys.argv[1:])
