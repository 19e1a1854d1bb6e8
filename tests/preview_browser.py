#!/usr/bin/env python3
"""`tetglow preview` in headless Chromium, end to end.

Starts the server on a free port with a small copy of the demo fish (without its water), then: other paths get 404;
malformed and out-of-range requests get the loader's one-line errors and change nothing; on a
sphere under one light, a colour swatch shows its linear colour sRGB-encoded, every control has a
title saying what it is, and a colour picked that the server refuses (the light made black) shows its
error in the page, naming the control, until a good colour is picked; the page shows the image; dragging the g slider restarts the render (the pass counter starts again) and
changes the image; a bad value typed into the page shows the error there, in the field's words;
an emission that overflows the film and a negative photon count, typed in turn, show two errors
(the first naming the medium and field) while the render goes on, each cleared when its field
takes a good value; dragging the image orbits the camera, a shift-drag pans it, the wheel zooms
and the field of view is typed (a bad one refused in the page), each moving the camera as it
should, and the image follows; a light turned off and on, and its strength typed, and the image
follows; a second tab sees the same settings and render; the saved scene holds the new values,
differs from the file loaded only where they changed, never overwrites, and renders the same
through `tetglow render`, bit for bit. A screenshot of the page goes to OUT/preview.png.
The test relies on the demo fish having a camera, a light and glowing media, not on their values.

  tests/preview_browser.py --tetglow build/tetglow --out build/preview-browser

Exits 77 (CTest: skipped), saying so, when chromium is not installed.
"""
import argparse
import functools
import json
import os
import select
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PASSES = 40  # the test scene's spp: the preview stops there, as `tetglow render` does


def check(condition, message):
    if not condition:
        raise AssertionError(message)


# The waits are bounds for a stuck server, not measurements. The sanitizer build runs tetglow
# several times slower (.ci/sanitize.sh sets TETGLOW_TEST_TIME_SCALE), and a machine busy with
# other work by its load over its cores.
TIME_SCALE = float(os.environ.get("TETGLOW_TEST_TIME_SCALE", "1"))


def time_scale():
    return TIME_SCALE * max(1.0, os.getloadavg()[0] / (os.cpu_count() or 1))


def wait_for(what, condition, timeout=20, progress=None):
    """Polls `condition` until it gives a true value, which it returns. The wait fails when
    `timeout` seconds (scaled) pass without it, counted from the last change of `progress()`
    when given: a render that is slow but moving is waited for."""
    last, deadline = None, 0
    while True:
        mark = progress() if progress else None
        if last is None or mark != last:
            last, deadline = mark, time.time() + timeout * time_scale()
        value = condition()
        if value:
            return value
        if time.time() >= deadline:
            raise AssertionError(f"timed out waiting for {what} ({timeout * time_scale():.0f} s without progress)")
        time.sleep(0.05)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_scene(folder):
    with open(os.path.join(ROOT, "scenes", "fish.json")) as f:
        scene = json.load(f)
    scene["camera"]["resolution"] = [128, 128]
    scene["integrator"].update(photons=20000, spp=PASSES)
    # Without the water around the fish, which makes a pass several times dearer.
    scene["media"] = [medium for medium in scene["media"] if medium["shape"]["type"] == "mesh"]
    for medium in scene["media"]:  # the meshes' paths, from the folder the copy is written to
        medium["shape"]["file"] = os.path.join(ROOT, "scenes", medium["shape"]["file"])
    del scene["output"]
    path = os.path.join(folder, "fish.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


def distance(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5


def close(a, b, tolerance=1e-9):
    return distance(a, b) <= tolerance * max(1, max(abs(x) for x in a + b))


def differences(a, b, path=""):
    """The JSON pointers at which a and b differ (a value, or a key one of them lacks)."""
    if isinstance(a, dict) and isinstance(b, dict):
        return [d for k in a.keys() | b.keys() for d in differences(a.get(k), b.get(k), path + "/" + k)]
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b) and any(isinstance(x, (dict, list)) for x in a):
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in differences(x, y, f"{path}/{i}")]
    return [] if a == b else [path]


class Server:
    def __init__(self, tetglow, scene):
        self.process = subprocess.Popen([tetglow, "preview", scene, "--port", str(free_port())],
                                        stdout=subprocess.PIPE, text=True)
        ready, _, _ = select.select([self.process.stdout], [], [], 60 * time_scale())
        line = self.process.stdout.readline() if ready else ""
        check(line.startswith("preview: http://127.0.0.1:"), "no URL printed: " + repr(line))
        self.url = line.split()[1].rstrip("/")
        self.scene = scene

    def request(self, path, body=None):
        data = None if body is None else body.encode()
        headers = {} if body is None else {"Content-Type": "application/json"}  # the only body the server takes
        try:
            with urllib.request.urlopen(urllib.request.Request(self.url + path, data=data, headers=headers), timeout=10 * time_scale()) as r:
                return r.status, r.read()
        except urllib.error.HTTPError as e:
            return e.code, e.read()

    def json(self, path, body=None):
        status, data = self.request(path, body)
        return status, json.loads(data)

    def state(self):
        return self.json("/state")[1]

    def progress(self):
        """What moves while the server renders: the settings' generation and the image's passes."""
        s = self.state()
        return s["generation"], s["image"] and (s["image"]["generation"], s["image"]["passes"])

    def stop(self):
        self.process.terminate()
        return self.process.wait(10 * time_scale())


# A sphere under one point light, nothing glowing: a light made black leaves nothing emitting.
ONE_LIGHT = {
    "camera": {"position": [0.3, 0.2, 4], "look_at": [0, 0, 0], "fov": 35, "resolution": [32, 32]},
    "integrator": {"type": "volpath", "spp": 4, "seed": 1},
    "lights": [{"type": "point", "position": [2, 3, 2], "intensity": 20}],
    "media": [{"shape": {"type": "sphere", "center": [0, 0, 0], "radius": 1, "subdivisions": 2},
               "sigma_a": [0.3, 0.06, 0.03], "sigma_s": 1.5, "g": 0, "boundary": {"type": "interface"}}],
}


def srgb_hex(rgb):
    """A linear colour as the #rrggbb a screen shows it by: the sRGB transfer function (IEC 61966-2-1)."""
    encode = lambda v: 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055
    return "#" + "".join(f"{round(255 * encode(v)):02x}" for v in rgb)


def check_choices(browser, tetglow, folder):
    """A colour swatch shows its linear colour sRGB-encoded; every control says what it is when
    pointed at; a colour picked that the server refuses: its error is shown in the page, naming
    the control and the value picked, the control shows the good colour again, and the error
    clears when a good colour is picked."""
    path = os.path.join(folder, "one-light.json")
    with open(path, "w") as f:
        json.dump(ONE_LIGHT, f)
    server = Server(tetglow, path)
    wait = functools.partial(wait_for, progress=server.progress)
    try:
        browser.get(server.url + "/")
        js = browser.execute_script
        errors = lambda: js("return [...document.querySelectorAll('#error li')].map((e) => e.textContent)")
        colour = lambda: js("const c = document.querySelector('.light .light-colour'); return c && c.value")  # once built
        wait("the light's colour in the page", lambda: colour() == "#ffffff")
        # The absorption colour: sigma_a over the largest coefficient (sigma_s, 1.5).
        absorb = js("return document.querySelector('.medium .absorb-colour').value")
        expected = srgb_hex([0.3 / 1.5, 0.06 / 1.5, 0.03 / 1.5])
        check(absorb == expected, f"the absorption swatch shows {absorb}, not the sRGB encoding {expected}")
        untitled = js("""return [...document.querySelectorAll('input, select')]
            .filter((e) => !(e.title || (e.closest('label') || {}).title))
            .map((e) => e.id || e.className || e.dataset.key)""")
        check(untitled == [], f"controls without a title: {untitled}")
        pick = "const c = document.querySelector('.light .light-colour'); c.value = arguments[0]; c.dispatchEvent(new Event('change'));"
        generation = server.state()["generation"]
        js(pick, "#000000")
        wait("the refusal shown", lambda: errors() == [
            "point · colour #000000: request: nothing emits light: turn a light on, or give it or a medium an emission"])
        check(colour() == "#ffffff", f"the picker shows {colour()}, not the good colour")
        check(server.state()["generation"] == generation, "a refused colour restarted the render")
        js(pick, "#ff0000")
        wait("the error cleared by a good colour", lambda: errors() == [])
        light = server.state()["settings"]["lights"][0]["intensity"]
        check(light == [20, 0, 0], f"the red light is {light}")
    finally:
        check(server.stop() == 0, "the one-light preview did not stop cleanly")


def check_requests(server):
    """Only the page, the image and the API answer; bad requests get one-line errors and change nothing."""
    for path in ["/nope", "/etc/passwd", "/..%2f..%2fetc%2fpasswd", "/web/preview.js", "/index.html", "/image.exr", "/previewXjs"]:
        status, body = server.json(path)
        check(status == 404 and body == {"error": "not found"}, f"GET {path}: {status} {body}")
    before = server.state()
    bad = {
        '{"media": [{"g": 1.5}]}': "request: /media/0/g: expected a number in (-1, 1), got 1.5",
        '{"media": [{"g": NaN}]}': "request:1:18: /media/0/g: syntax error while parsing value - invalid literal; last read: '\"g\": N'",
        '{"media": [{"g": null}]}': "request: /media/0/g: expected a number in (-1, 1), got null",
        '{"integrator": {"photons": -5}}': "request: /integrator/photons: expected an integer in 1..1099511627776, got -5",
        '{"media": [{"shape": {"type": "mesh", "file": "/etc/passwd"}}]}':
            "request: /media/0/shape: unknown key; allowed here: scale, sigma_a, sigma_s, g, emission, density",
        '{"media": [{}, {}, {}, {}, {}]}':  # the fish has four media: body, photophores, lure core, eyes
            "request: /media: expected an array of at most 4 media, one per medium of the scene, got [{...",
        '{"resolution_scale": 3}': "request: /resolution_scale: expected a number in (0, 1], got 3",
        '{"path": "/tmp/x"}': "request: /path: unknown key; allowed here: integrator, media, camera, lights, resolution_scale",
        '{"camera": {"fov": 200}}': "request: /camera/fov: expected a number in (0, 180), got 200",
        '{"camera": {"look_at": null}}': "request: /camera/look_at: expected an array of 3 numbers",
        '{"lights": [{"on": "off"}]}': 'request: /lights/0/on: expected true or false, got "off"',
        '{"lights": [{"position": [0, 0, 0]}]}': "request: /lights/0/position: unknown key; allowed here: scale, {...",
        '[1]': "request: expected an object, got [1]",
        '{"media": [{"g": 0.5}': "request:1:22: /media/1: syntax error while parsing array - unexpected end of input; expected ']'",
    }
    for body, message in bad.items():
        status, reply = server.json("/settings", body)
        check(status == 400, f"POST /settings {body}: status {status}")
        check(reply["error"].startswith(message.split("{...")[0]), f"POST /settings {body}: {reply['error']!r}, expected {message!r}")
        check("\n" not in reply["error"], "a multi-line error")
    status, reply = server.json("/settings", '{"media": [{"g": 0.1}], "pad": "' + "x" * 70000 + '"}')
    check(status == 413 and reply["error"] == "request too large: at most 65536 bytes", f"a 70 kB request: {status} {reply}")
    status, reply = server.json("/image.png?exposure=abc")
    check(status == 400 and reply["error"].startswith("request:1:14: /exposure: syntax error"), f"exposure=abc: {reply}")
    after = server.state()
    check(after["settings"] == before["settings"] and after["generation"] == before["generation"], "a bad request changed the settings")
    check(server.request("/")[0] == 200, "the server stopped serving after bad requests")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tetglow", required=True)
    parser.add_argument("--out", required=True)
    a = parser.parse_args()
    chromium = shutil.which("chromium")
    if not chromium:
        print("SKIP: chromium is not installed (./setup.sh test installs chromium, chromium-driver, python3-selenium)")
        return 77
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys

    start = time.time()
    os.makedirs(a.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="tetglow-preview-")
    server = Server(a.tetglow, test_scene(work))
    wait = functools.partial(wait_for, progress=server.progress)  # a slow render is waited for while it moves
    options = webdriver.ChromeOptions()
    options.binary_location = chromium
    for arg in ["--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1000,820", f"--user-data-dir={work}/chromium"]:
        options.add_argument(arg)
    browser = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
    try:
        check_requests(server)
        check_choices(browser, a.tetglow, work)

        browser.get(server.url + "/")
        js = browser.execute_script
        progress = lambda: (js("return document.getElementById('progress').dataset.passes"), js("return document.getElementById('progress').dataset.generation"))
        finished = lambda: server.state()["image"]["passes"] == PASSES
        wait("the first image in the page", lambda: js("return document.getElementById('image').naturalWidth") == 128)
        wait("the first render to finish", finished)
        _, first = server.request("/image.png")
        check(server.request("/image.png?exposure=2")[1] != first, "exposure does not change the PNG")
        exposure = browser.find_element(By.ID, "exposure")
        exposure.send_keys(Keys.ARROW_RIGHT)  # one step: 0.1 stops
        wait("the page's image at the new exposure", lambda: "exposure=0.1&" in browser.find_element(By.ID, "image").get_attribute("src"))
        exposure.send_keys(Keys.ARROW_LEFT)
        first_generation = server.state()["generation"]

        # Drag the g slider: the render starts again from its first pass, and the image changes.
        slider = browser.find_element(By.CSS_SELECTOR, ".medium .g-slider")
        ActionChains(browser).drag_and_drop_by_offset(slider, 30, 0).perform()
        generation = wait("the slider's change", lambda: server.state()["generation"] > first_generation and server.state()["generation"])
        g = server.state()["settings"]["media"][0]["g"]
        check(abs(g - 0.3) > 0.01, f"the slider left g at {g}")
        seen = wait("the page to show the new render", lambda: progress()[1] == str(server.state()["generation"]) and progress())
        check(int(seen[0]) < PASSES, f"the pass counter did not start again: {seen}")
        wait("the new render to finish", lambda: finished() and server.state()["image"]["generation"] == server.state()["generation"])
        _, second = server.request("/image.png")
        check(second != first, "the image did not change with g")

        # A bad value typed into the page: its error is shown there, and the last good values stay.
        generation = server.state()["generation"]
        box = browser.find_element(By.CSS_SELECTOR, ".medium .g")
        box.send_keys(Keys.CONTROL, "a")  # not clear(): it sends a change of its own
        box.send_keys("1.5", Keys.TAB)
        shown = wait("the error in the page", lambda: browser.find_element(By.ID, "error").text)
        # The media are named as the scene names them, else by their mesh files.
        with open(server.scene) as f:
            body = json.load(f)["media"][0]
        name = body.get("name", os.path.basename(body["shape"]["file"]))
        check(server.state()["media_names"][0] == name, f"the body is named {server.state()['media_names'][0]!r}, not {name!r}")
        check(js("return document.querySelector('.medium legend').textContent") == name, "the page does not show the medium's name")
        check(shown == name + " · g: 1.5 is outside the range allowed, a number (-1, 1)", "page error: " + shown)
        wait("the good g back in the page", lambda: float(box.get_attribute("value")) == g)
        check(server.state()["generation"] == generation, "a bad value restarted the render")
        g = round(g - 0.05, 2)  # another value: typing the one shown again changes nothing
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys(str(g), Keys.TAB)
        wait("the error cleared by a good g", lambda: browser.find_element(By.ID, "error").text == "")
        wait("the good g sent", lambda: server.state()["settings"]["media"][0]["g"] == g)

        # Two bad values in turn: an emission that overflows the film (the server's render fails,
        # names the medium and field, and goes back to the last good values) and a negative
        # photon count (refused in the page). Both errors stay in view, the render goes on, and
        # each clears when its field is fixed.
        errors = lambda: js("return [...document.querySelectorAll('#error li')].map((e) => e.textContent)")
        def type_into(selector, text):
            field = browser.find_element(By.CSS_SELECTOR, selector)
            field.send_keys(Keys.CONTROL, "a")
            field.send_keys(text, Keys.TAB)
        strength = browser.find_element(By.CSS_SELECTOR, ".medium .emission-strength").get_attribute("value")
        photons_before = server.state()["settings"]["integrator"]["photons"]
        type_into(".medium .emission-strength", "1e30")
        wait("the overflow named", lambda: any(e.startswith(name + " · emission ") and "beyond the film's range" in e for e in errors()))
        type_into("[data-key=photons]", "-5")
        wait("both errors", lambda: len(errors()) == 2)
        check(any(e == "photons per pass: -5 is outside the range allowed, an integer [1, 1099511627776]" for e in errors()), f"errors: {errors()}")
        state = wait("the render going on with the good values",
                         lambda: server.state()["image"]["generation"] == server.state()["generation"] and server.state())
        check(state["settings"]["integrator"]["photons"] == photons_before, "the bad photon count was sent")
        check(max(state["settings"]["media"][0]["emission"]) < 1e29 if isinstance(state["settings"]["media"][0]["emission"], list)
              else state["settings"]["media"][0]["emission"] < 1e29, "the overflowing emission stayed")
        type_into(".medium .emission-strength", "0.5" if strength != "0.5" else "0.25")  # not the value shown: no change
        wait("the overflow's error cleared", lambda: len(errors()) == 1)
        type_into("[data-key=photons]", str(photons_before // 2))
        wait("every error cleared", lambda: errors() == [])

        # The camera. Each gesture is checked on the server for what it must do to the view, once
        # the page has sent all it had (no pass is assumed rendered in between).
        settled = lambda: finished() and server.state()["image"]["generation"] == server.state()["generation"]
        wait("the render to finish", settled)
        _, before_camera = server.request("/image.png")
        idle = lambda: js("return !sending && queued === null")
        camera = lambda: server.state()["settings"]["camera"]
        def gesture(what, actions, moved):
            start = camera()
            actions.perform()
            return wait(what, lambda: idle() and moved(start, camera()) and camera())
        image = browser.find_element(By.ID, "image")
        offset = lambda c: [p - l for p, l in zip(c["position"], c["look_at"])]
        # Orbit: about the look-at point, at the same distance.
        gesture("the orbit", ActionChains(browser).drag_and_drop_by_offset(image, 40, 0),
                lambda a, b: b["position"] != a["position"] and b["look_at"] == a["look_at"]
                and abs(distance(b["position"], b["look_at"]) - distance(a["position"], a["look_at"])) < 1e-9 * distance(a["position"], a["look_at"]))
        # Pan: the view moves as a whole.
        gesture("the pan", ActionChains(browser).key_down(Keys.SHIFT).click_and_hold(image).move_by_offset(25, 15).release().key_up(Keys.SHIFT),
                lambda a, b: b["look_at"] != a["look_at"] and close(offset(a), offset(b)))
        # Zoom: along the view, towards or away from the look-at point.
        from selenium.webdriver.common.actions.wheel_input import ScrollOrigin
        zoomed = gesture("the zoom", ActionChains(browser).scroll_from_origin(ScrollOrigin.from_element(image), 0, 200),
                         lambda a, b: b["look_at"] == a["look_at"] and distance(b["position"], b["look_at"]) > distance(a["position"], a["look_at"])
                         and close([x / distance(a["position"], a["look_at"]) for x in offset(a)], [x / distance(b["position"], b["look_at"]) for x in offset(b)]))
        # The field of view, typed: out of range refused in the page in its words, then a good one.
        type_into("#camera .fov", "200")
        wait("the fov refused", lambda: errors() == ["camera · field of view: 200 is outside the range allowed, a number (0, 180)"])
        fov = zoomed["fov"] + 5 if zoomed["fov"] < 170 else zoomed["fov"] - 5
        type_into("#camera .fov", f"{fov:g}")
        wait("the fov sent", lambda: camera()["fov"] == fov and errors() == [])
        wait("the position's field to follow",  # shown to 6 digits
                 lambda: abs(float(js("return document.querySelector('#camera .position').value")) - camera()["position"][0]) <= 1e-5 * distance(camera()["position"], [0, 0, 0]))
        wait("the render of the new view", settled)
        wait("the page to show it", lambda: progress() == (str(PASSES), str(server.state()["generation"])))
        _, moved = server.request("/image.png")
        check(moved != before_camera, "the image did not follow the camera")

        # A light: off, then on again with another strength; the image follows.
        light = server.state()["settings"]["lights"][0]
        key = next(k for k in ("intensity", "irradiance", "radiance") if k in light)
        check(js("return document.querySelector('.light legend').textContent") == "Light · " + server.state()["light_names"][0], "the light is not named")
        browser.find_element(By.CSS_SELECTOR, ".light .on").click()
        wait("the light off", lambda: server.state()["settings"]["lights"][0]["on"] is False)
        wait("the render without it", settled)
        _, dark = server.request("/image.png")
        check(dark != moved, "the image did not follow the light turned off")
        browser.find_element(By.CSS_SELECTOR, ".light .on").click()
        strength = max(light[key]) * 2 if max(light[key]) > 0 else 1
        type_into(".light .strength", f"{strength:g}")
        wait("the light on, at the new strength", lambda: server.state()["settings"]["lights"][0]["on"] is True
                 and max(server.state()["settings"]["lights"][0][key]) == float(f"{strength:g}"))
        wait("the render with it", settled)
        _, lit = server.request("/image.png")
        check(lit not in (moved, dark), "the image did not follow the light's strength")

        # A second tab sees the same render; a change made there shows in the first.
        browser.switch_to.new_window("tab")
        browser.get(server.url + "/")
        wait("the second tab's image", lambda: js("return document.getElementById('image').naturalWidth") == 128)
        wait("the second tab's g", lambda: float(browser.find_element(By.CSS_SELECTOR, ".medium .g").get_attribute("value")) == g)
        photons = browser.find_element(By.CSS_SELECTOR, "[data-key=photons]")
        photons.send_keys(Keys.CONTROL, "a")
        photons.send_keys("12000", Keys.TAB)
        wait("the second tab's change", lambda: server.state()["settings"]["integrator"]["photons"] == 12000)
        browser.close()
        browser.switch_to.window(browser.window_handles[0])
        wait("the change in the first tab",
                 lambda: browser.find_element(By.CSS_SELECTOR, "[data-key=photons]").get_attribute("value") == "12000")
        wait("the render to finish", lambda: finished() and server.state()["image"]["generation"] == server.state()["generation"])
        wait("the page to show it", lambda: progress() == (str(PASSES), str(server.state()["generation"])))
        time.sleep(0.3)  # the last image loads
        browser.save_screenshot(os.path.join(a.out, "preview.png"))

        # Save the scene twice (a new name each time) and the image; the saved scene renders the same.
        saved = lambda: browser.find_element(By.ID, "saved").text
        browser.find_element(By.ID, "save-scene").click()
        text = wait("the scene saved", lambda: saved().startswith("saved ") and saved())
        scene = text.split(" ", 1)[1]
        check(scene == os.path.join(work, "fish-tuned-1.json"), "saved as " + scene)
        browser.find_element(By.ID, "save-scene").click()
        wait("the second save", lambda: saved() == "saved " + os.path.join(work, "fish-tuned-2.json"))
        with open(scene) as f:
            tuned = json.load(f)
        check(tuned["media"][0]["g"] == g and tuned["integrator"]["photons"] == 12000, f"the saved scene holds {tuned['media'][0]}")
        # Against the file loaded, only the values changed in the page (no mesh copied, the
        # spot's scale kept).
        with open(os.path.join(work, "fish.json")) as f:
            original = json.load(f)
        changed = sorted(differences(original, tuned))
        expected = sorted(["/camera/fov", "/camera/look_at", "/camera/position", "/integrator/photons", "/lights/0/" + key,
                           "/media/0/emission", "/media/0/g"])
        check(changed == expected, f"the saved scene differs at {changed}, not {expected}")
        check(not [n for n in os.listdir(work) if n.endswith(".obj")], "a mesh was copied beside the saved scene")
        browser.find_element(By.ID, "save-image").click()
        wait("the image saved", lambda: f"({PASSES} passes)" in saved())
        exr = os.path.join(work, "fish-image-1.exr")
        check(os.path.isfile(exr) and os.path.isfile(exr[:-4] + ".png"), "no EXR + PNG saved")
        rendered = os.path.join(work, "rendered.exr")
        subprocess.run([a.tetglow, "render", scene, "-o", rendered], check=True, capture_output=True)
        d = json.loads(subprocess.run([a.tetglow, "diff", exr, rendered, "--json"], check=True, capture_output=True, text=True).stdout)
        check(d["rmse"] == 0, f"the saved scene renders otherwise through tetglow render: {d}")
        check(server.request("/")[0] == 200, "the server stopped serving")
    finally:
        browser.quit()
        code = server.stop()
    check(code == 0, f"tetglow preview exited with {code} on SIGTERM")
    shutil.rmtree(work)
    print(f"preview browser test passed in {time.time() - start:.1f} s; screenshot {os.path.join(a.out, 'preview.png')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
