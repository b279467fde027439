#!/usr/bin/env python3
"""Project pages (`shaderport port --emit html`) run in headless Chromium as the site
runs the project, and draw what `shaderport render` draws.

For each project in tests/browser/project_pages/ (ShaderToy API exports):
  - build its page; open it in Debian's `chromium` (SwiftShader) in the page's
    deterministic mode (#time=1&frames=N&size=64x64) and read the DOM after the last
    frame: its state, its log (console errors, exceptions, GL errors, compile errors)
    and the last frame's pixels;
  - projects render can draw: `shaderport render` the same project at 64x64, N frames,
    time 1, and compare the pictures by 8x8 block means within 12/255
    (docs/render.md, tools/browser/compare_pictures.py); the texture probe must match
    texel for texel (the procedural textures are the same bytes);
  - page-only projects (Cube A, keyboard, a compile error, injection payloads) check
    what the page itself shows.
Every project is checked twice: with the passes composed as the site composes them
(the fixture tool: header, Common, pass, main(), the text render draws), which tests
the page's runtime alone, and ported (`shaderport port --emit html` when the binary
offers it, else the fixture tool's --port: PortProject and PageFromPorted).
  project_pages.py SHADERPORT_BINARY FIXTURE_BINARY WORK_DIR
Measuring on a corpus: every project with a Buffer pass in a ShaderToy .jsonl, both
ways, against render:
  project_pages.py --corpus CORPUS.jsonl [--limit N] [--frames N] [--modes site,ported]
                   SHADERPORT FIXTURE WORK
With --ids A,B,.. --require-match (ctest project_pages_corpus) it fails unless each
listed project is in the corpus and its pages (--modes) load without errors and match
render.
"""
import base64
import concurrent.futures
import html
import html.parser
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "browser"))
import cdp_pipe  # noqa: E402
import compare_pictures  # noqa: E402
import pngio  # noqa: E402


DATA = os.path.join(HERE, "project_pages")
SIZE = 64
MARK = "data-injected"
# name -> frames; compared with render.
COMPARED = {"feedback": 3, "buffer_order": 4, "textures": 1, "uniforms": 2}
MOUSE = {"uniforms": "20,30,10,-12"}  # iMouse as render's --mouse sets it
EXACT = {"textures": 2}  # largest per-channel difference allowed anywhere
PAGE_ONLY = {"cube_pass": 2, "keyboard": 1, "broken": 1, "injection": 1, "sound": 1}
EXTRA = {"sound": "&sound=44100"}  # the first second of the Sound pass, for the test


class Dom(html.parser.HTMLParser):
    """The test hooks of the page: ids sp-state, sp-log, sp-pixels, sp-errors."""

    def __init__(self):
        super().__init__()
        self.attrs = {}
        self.text = {}
        self.scripts = 0
        self.handlers = []
        self.body = {}
        self.title = ""
        self._open = []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "script":
            self.scripts += 1
        if tag == "body":
            self.body = attrs
        self.handlers += [(tag, n) for n in attrs if n.lower().startswith("on")]
        ident = attrs.get("id")
        if ident:
            self.attrs[ident] = attrs
            self.text.setdefault(ident, "")
        self._open.append((tag, ident))

    def handle_endtag(self, tag):
        while self._open:
            t, _ = self._open.pop()
            if t == tag:
                break

    def handle_data(self, data):
        for _, ident in self._open:
            if ident:
                self.text[ident] += data
        if self._open and self._open[-1][0] == "title":
            self.title += data


def chromium_dom(chromium, work, page, fragment, timeout=120, flags=()):
    profile = tempfile.mkdtemp(prefix="chromium-", dir=work)
    done = subprocess.run(
        [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--disable-background-networking", "--disable-extensions",
         "--no-first-run", "--user-data-dir=" + profile, "--virtual-time-budget=10000",
         "--enable-logging=stderr", "--v=0"] + list(flags) +
        ["--dump-dom", "file://" + page + fragment],
        capture_output=True, text=True, timeout=timeout)
    shutil.rmtree(profile, ignore_errors=True)
    # Performance notes of the GL driver (a ReadPixels stall) are not problems.
    console = [line for line in done.stderr.splitlines()
               if "CONSOLE" in line and "GL Driver Message (OpenGL, Performance" not in line]
    return done.stdout, console


def make_page(binary, fixture, mode, project, out):
    """site: the fixture's composition; ported: `port --emit html`, else fixture --port."""
    if mode == "site":
        subprocess.run([fixture, project, out], check=True, timeout=60)
        return "fixture (site composition)"
    done = subprocess.run([binary, "port", project, "--emit", "html", "-o", out],
                          capture_output=True, text=True, timeout=120)
    if done.returncode in (0, 1) and os.path.exists(out):
        return "shaderport port --emit html"
    subprocess.run([fixture, "--port", project, out], check=True, timeout=120)
    return "fixture --port (PortProject)"


def record_of(export):
    """The corpus record render reads ({"passes": [...]}) for an API export."""
    shader = export["Shader"]
    passes = []
    for p in shader["renderpass"]:
        passes.append({"type": p["type"], "name": p["name"], "code": p["code"],
                       "inputs": [{"channel": i["channel"], "ctype": i["ctype"], "src": i["src"]}
                                  for i in p.get("inputs", [])]})
    return {"id": shader["info"]["id"], "name": shader["info"]["name"], "passes": passes}


def render(binary, work, name, frames):
    record = os.path.join(work, name + ".record.json")
    with open(record, "w") as f:
        json.dump(record_of(json.load(open(os.path.join(DATA, name + ".json")))), f)
    png = os.path.join(work, name + ".render.png")
    mouse = ["--mouse=" + MOUSE[name]] if name in MOUSE else []
    done = subprocess.run([binary, "render", record, "--size", "%dx%d" % (SIZE, SIZE), "--frames",
                           str(frames), "--time", "1", "--hermetic", "-o", png] + mouse,
                          capture_output=True, text=True, timeout=120)
    if not os.path.exists(png):
        return None, "render drew nothing (exit %d): %s" % (done.returncode, done.stderr.strip())
    return pngio.read_png(png), ""


def page_result(chromium, binary, fixture, work, mode, name, frames):
    page = os.path.join(work, mode, name + ".html")
    source = make_page(binary, fixture, mode, os.path.join(DATA, name + ".json"), page)
    fragment = "#time=1&frames=%d&size=%dx%d" % (frames, SIZE, SIZE)
    if name in MOUSE:
        fragment += "&mouse=" + MOUSE[name]
    fragment += EXTRA.get(name, "")
    dom_text, console = chromium_dom(chromium, work, page, fragment)
    with open(os.path.join(work, mode, name + ".dom.html"), "w") as f:
        f.write(dom_text)
    dom = Dom()
    dom.feed(dom_text)
    pixels = None
    if dom.text.get("sp-pixels"):
        pixels = (SIZE, SIZE, base64.b64decode(dom.text["sp-pixels"].strip()))
        pngio.write_png(os.path.join(work, mode, name + ".page.png"), *pixels)
    return {"dom": dom, "raw": dom_text, "console": console, "pixels": pixels, "source": source}


def clean_run(label, r, problems):
    dom = r["dom"]
    state = dom.attrs.get("sp-state", {}).get("data-state")
    if state != "done":
        problems.append("%s: page state %r, not done" % (label, state))
    log = dom.text.get("sp-log", "").strip()
    if log:
        problems.append("%s: the page logged: %s" % (label, log))
    if dom.text.get("sp-errors", "").strip() and "hidden" not in dom.attrs.get("sp-errors", {}):
        problems.append("%s: error panel shown: %s" % (label, dom.text["sp-errors"].strip()))
    for line in r["console"]:
        problems.append("%s: console: %s" % (label, line))
    if r["pixels"] is None:
        problems.append("%s: no pixels published" % label)


def max_difference(a, b):
    return max(abs(x - y) for i, (x, y) in enumerate(zip(a[2], b[2])) if i % 4 != 3)


def check_compared(name, label, r, reference, problems, measured):
    clean_run(label, r, problems)
    if r["pixels"] is None or reference is None:
        return
    c = compare_pictures.compare(r["pixels"], reference)
    worst = max_difference(r["pixels"], reference)
    measured.append("%s: %s; largest pixel difference %d" %
                    (label, compare_pictures.describe(c), worst))
    if not c.match:
        problems.append("%s: page and render differ: %s" % (label, compare_pictures.describe(c)))
    if name in EXACT and worst > EXACT[name]:
        problems.append("%s: a texel differs by %d (> %d) from render" %
                        (label, worst, EXACT[name]))


def check_page_only(name, label, r, problems):
    dom = r["dom"]
    if name == "broken":
        state = dom.attrs.get("sp-state", {}).get("data-state")
        panel = dom.text.get("sp-errors", "")
        if state != "error":
            problems.append(label + ": state %r, not error" % state)
        if "hidden" in dom.attrs.get("sp-errors", {}):
            problems.append(label + ": the error panel is hidden")
        if "Buffer A:3:" not in panel or "undefined_name" not in panel:
            problems.append(label + ": the panel does not put the error on Buffer A:3: %r" % panel)
        for line in r["console"]:
            if "undefined_name" not in line:
                problems.append(label + ": console: %s" % line)
        return
    clean_run(label, r, problems)
    px = r["pixels"]
    if px is None:
        return
    w, h, rgba = px
    if name == "keyboard":
        bad = sum(1 for i in range(0, len(rgba), 4) if tuple(rgba[i:i + 3]) != (0, 255, 0))
        if bad:
            problems.append(label + ": %d pixels say the keyboard texture is wrong" % bad)
    if name == "cube_pass":
        left = [rgba[(y * w + x) * 4 + c] for y in range(h) for x in range(w // 2 - 1)
                for c in range(3)]
        right = [rgba[(y * w + x) * 4 + c] for y in range(h) for x in range(w // 2 + 1, w)
                 for c in range(3)]
        if max(right) > 24:
            problems.append(label + ": Cube A differs from its ray directions by %d/255" %
                            max(right))
        if sum(left) / len(left) < 40:
            problems.append(label + ": the cube map looks empty")
    if name == "injection":
        check_injection(label, r, problems)
    if name == "sound":
        check_sound(label, r, problems)


def check_sound(label, r, problems):
    """The Sound pass's samples, read back as the site reads them: 440 Hz left, 220 Hz
    at half volume right (16-bit packing, float sin on the GPU: within 2e-3)."""
    text = r["dom"].text.get("sp-sound", "")
    if not text:
        problems.append(label + ": no samples published")
        return
    samples = json.loads(text)
    if len(samples) != 441:
        problems.append(label + ": %d samples published, expected 441" % len(samples))
    worst = 0.0
    for k, (left, right) in enumerate(samples):
        t = k * 100 / 44100.0
        worst = max(worst, abs(left - math.sin(2 * math.pi * 440 * t)),
                    abs(right - 0.5 * math.sin(2 * math.pi * 220 * t)))
    if worst > 2e-3:
        problems.append(label + ": samples differ from the tone by %.4f" % worst)


def check_injection(label, r, problems):
    dom = r["dom"]
    if MARK in dom.body:
        problems.append(label + ": a payload ran: body %s=%s" % (MARK, dom.body[MARK]))
    if dom.scripts != 2:
        problems.append(label + ": %d <script> elements, expected the page's 2" % dom.scripts)
    if dom.handlers:
        problems.append(label + ": event handler attributes: %s" % dom.handlers)
    shown = html.unescape(dom.text.get("sp-title", ""))
    if "</script><script>" not in shown or "onerror=" not in shown:
        problems.append(label + ": the title does not show the payload as text: %r" % shown)
    if "</script><script>" not in html.unescape(dom.title):
        problems.append(label + ": <title> lost the payload text: %r" % dom.title)


_LIVE_STATE = """(() => {
  const s = document.getElementById('sp-state');
  return [s.getAttribute('data-state'), Number(s.getAttribute('data-frames') || 0),
          document.getElementById('sp-log').textContent.trim()];
})()"""


def check_live(chromium, work, problems, timeout=120):
    """Without the test parameters the page animates (requestAnimationFrame)."""
    page = os.path.join(work, "ported", "feedback.html")
    # The console comes from a DOM dump, which runs on virtual time: a loaded machine's
    # slow shader compiles can outlast its budget before the first animation frame, so
    # the drawing itself is watched in real time over the DevTools protocol.
    _, console = chromium_dom(chromium, work, page, "")
    problems += ["live: console: " + line for line in console]
    browser = cdp_pipe.Browser(chromium, work)
    try:
        browser.open("file://" + page)
        deadline = time.time() + timeout
        state, frames, log = browser.evaluate(_LIVE_STATE)
        while (state != "running" or frames < 2) and time.time() < deadline:
            time.sleep(0.05)
            state, frames, log = browser.evaluate(_LIVE_STATE)
        if state != "running" or frames < 2:
            problems.append("live: the page does not animate: state %s after %d frames in %d s"
                            % (state, frames, timeout))
        if log:
            problems.append("live: the page logged: %s" % log)
    finally:
        browser.close()


# Reads the canvas at the middle of each 16-pixel column (the interaction project's).
_READ_COLUMNS = """(() => {
  const c = document.getElementById('sp-canvas');
  const t = document.createElement('canvas');
  t.width = c.width; t.height = c.height;
  const g = t.getContext('2d');
  g.drawImage(c, 0, 0);
  return [8, 24, 40, 56].map((x) => Array.from(g.getImageData(x, 8, 1, 1).data).slice(0, 3));
})()"""


class Interaction:
    """The interaction page in a browser driven over the DevTools protocol."""

    def __init__(self, browser):
        self.b = browser

    def frame(self):
        clock = self.b.evaluate("document.getElementById('sp-clock').textContent") or ""
        m = re.search(r"iFrame (\d+)", clock)
        return int(m.group(1)) if m else -1

    def wait_frames(self, n, timeout=120):  # a loaded CI machine draws slowly
        start = self.frame()
        deadline = time.time() + timeout
        while self.frame() < start + n:
            if time.time() > deadline:
                raise TimeoutError("the page stopped drawing at iFrame %d" % self.frame())
            time.sleep(0.05)

    def columns(self):
        return self.b.evaluate(_READ_COLUMNS)

    def canvas_point(self, x, y):
        r = self.b.evaluate("(() => { const r = document.getElementById('sp-canvas')"
                            ".getBoundingClientRect(); return [r.left, r.top]; })()")
        return r[0] + x + 0.5, r[1] + y + 0.5

    def click(self, button_id):
        self.b.evaluate("document.getElementById('%s').click()" % button_id)

    def state(self):
        return self.b.evaluate("document.getElementById('sp-state').getAttribute('data-state')")


def expect(problems, what, got, want):
    if got != want:
        problems.append("interaction: %s: got %s, expected %s" % (what, got, want))


def check_interaction(chromium, binary, fixture, work, problems):
    """Mouse, keyboard, pause, space, restart and resize as on the site."""
    page = os.path.join(work, "ported", "interaction.html")
    make_page(binary, fixture, "ported", os.path.join(DATA, "interaction.json"), page)
    browser = cdp_pipe.Browser(chromium, work)
    try:
        browser.open("file://" + page + "#size=64x64")
        p = Interaction(browser)
        p.wait_frames(3)
        expect(problems, "iMouse before any click", p.columns()[:2], [[0, 0, 0], [0, 0, 0]])
        # Press at canvas pixel (10, 20) from the top: iMouse.xy = (10, 43), z and w > 0.
        x, y = p.canvas_point(10, 20)
        browser.mouse("mousePressed", x, y, 1)
        p.wait_frames(3)
        c = p.columns()
        expect(problems, "iMouse while down", c[0], [10, 43, 255])
        expect(problems, "iMouse.zw after the click's frame", c[1], [10, 43, 0])
        expect(problems, "iMouse.w > 0 on the click's frame (latched)", c[2][0], 255)
        x, y = p.canvas_point(30, 40)
        browser.mouse("mouseMoved", x, y, 1)
        p.wait_frames(3)
        expect(problems, "iMouse after dragging", p.columns()[0], [30, 23, 255])
        browser.mouse("mouseReleased", x, y, 0)
        p.wait_frames(3)
        c = p.columns()
        expect(problems, "iMouse after release (z < 0)", c[0], [30, 23, 0])
        expect(problems, "|iMouse.zw| after release", c[1], [10, 43, 0])
        # The click focused the canvas: keys go to the shader.
        expect(problems, "canvas focused by the click",
               browser.evaluate("document.activeElement.id"), "sp-canvas")
        browser.key("keyDown", "a", "KeyA", 65)
        p.wait_frames(3)
        c = p.columns()
        expect(problems, "key A down (row 0)", c[3][0], 255)
        expect(problems, "key A pressed (row 1, latched) and toggled (row 2)", c[2][1:], [255, 255])
        browser.key("keyUp", "a", "KeyA", 65)
        p.wait_frames(3)
        c = p.columns()
        expect(problems, "key A up (row 0)", c[3][0], 0)
        expect(problems, "key A still toggled (row 2)", c[2][2], 255)
        # Pause and resume with the button, then with space (canvas not focused).
        for how in ("button", "space"):
            if how == "button":
                p.click("sp-pause")
            else:
                browser.evaluate("document.getElementById('sp-canvas').blur()")
                browser.key("keyDown", " ", "Space", 32)
                browser.key("keyUp", " ", "Space", 32)
            time.sleep(0.3)
            before = p.frame()
            time.sleep(0.5)
            expect(problems, "iFrame while paused by " + how, p.frame(), before)
            expect(problems, "state paused by " + how, p.state(), "paused")
            if how == "button":
                p.click("sp-pause")
            else:
                browser.key("keyDown", " ", "Space", 32)
                browser.key("keyUp", " ", "Space", 32)
            p.wait_frames(3)
        # Restart: iFrame from 0 and the buffers cleared (Buffer A counts its frames).
        p.wait_frames(20)
        before = p.frame()
        p.click("sp-restart")
        time.sleep(0.1)
        after, count = p.frame(), p.columns()[3][1]
        if not (after < before and count <= after + 1):
            problems.append("interaction: restart: iFrame %d -> %d, Buffer A counted %d frames" %
                            (before, after, count))
        # Resize: the canvas follows its element; buffers are reallocated and cleared.
        browser.open("file://" + page)
        p.wait_frames(20)
        browser.send("Emulation.setDeviceMetricsOverride",
                     {"width": 320, "height": 400, "deviceScaleFactor": 1, "mobile": False})
        p.wait_frames(2)
        size = browser.evaluate("[document.getElementById('sp-canvas').width,"
                                " document.getElementById('sp-canvas').clientWidth]")
        expect(problems, "canvas width after resize (= its element's)", size[0], size[1])
        expect(problems, "canvas width after resize", size[0], 320)
        if p.columns()[3][1] > p.frame() + 1 or p.columns()[3][1] > 60:
            problems.append("interaction: buffers not cleared on resize: Buffer A counted %d" %
                            p.columns()[3][1])
        log = browser.evaluate("document.getElementById('sp-log').textContent").strip()
        if log:
            problems.append("interaction: the page logged: " + log)
        check_texture_file(browser, binary, fixture, work, problems)
        check_sound_button(browser, binary, fixture, work, problems)
    except (TimeoutError, RuntimeError, EOFError) as e:
        problems.append("interaction: %s" % e)
    finally:
        browser.close()


def check_texture_file(browser, binary, fixture, work, problems):
    """A 2D channel's texture replaced by an image file (256x128 red): the textures
    page's texel rows show it and iChannelResolution[0] is its size."""
    page = os.path.join(work, "ported", "textures.html")
    make_page(binary, fixture, "ported", os.path.join(DATA, "textures.json"), page)
    image = os.path.join(work, "red.png")
    pngio.write_png(image, 256, 128, bytes([255, 0, 0, 255] * (256 * 128)))
    browser.open("file://" + page + "#size=64x64&time=1")
    p = Interaction(browser)
    p.wait_frames(2)
    browser.set_file("#sp-channels input[type=file]", image)
    deadline = time.time() + 30
    read = ("(() => { const c = document.getElementById('sp-canvas');"
            " const t = document.createElement('canvas'); t.width = 64; t.height = 64;"
            " const g = t.getContext('2d'); g.drawImage(c, 0, 0);"
            " const at = (x, y) => Array.from(g.getImageData(x, y, 1, 1).data).slice(0, 3);"
            " return [at(20, 58), at(63, 0)]; })()")
    while time.time() < deadline:
        texel, resolution = browser.evaluate(read)
        if texel == [255, 0, 0]:
            break
        time.sleep(0.1)
    expect(problems, "a texel of the user's image", texel, [255, 0, 0])
    expect(problems, "iChannelResolution[0] of the user's image / 256", resolution, [255, 128, 1])


def check_without_webgl2(chromium, work, problems):
    """Without WebGL the page says so instead of failing silently."""
    page = os.path.join(work, "ported", "feedback.html")
    dom_text, _ = chromium_dom(chromium, work, page, "", flags=["--disable-3d-apis"])
    dom = Dom()
    dom.feed(dom_text)
    state = dom.attrs.get("sp-state", {}).get("data-state")
    fallback = dom.attrs.get("sp-fallback", {"hidden": ""})
    if state != "no-webgl2" or "hidden" in fallback:
        problems.append("no WebGL2: state %r, fallback text %s" %
                        (state, "hidden" if "hidden" in fallback else "shown"))


def check_sound_button(browser, binary, fixture, work, problems):
    """A real click on the Sound button starts Web Audio; pausing stops it; no errors."""
    page = os.path.join(work, "ported", "sound.html")
    make_page(binary, fixture, "ported", os.path.join(DATA, "sound.json"), page)
    browser.open("file://" + page + "#size=64x64")
    p = Interaction(browser)
    p.wait_frames(2)
    box = browser.evaluate("(() => { const r = document.getElementById('sp-sound-toggle')"
                           ".getBoundingClientRect(); return [r.left + r.width / 2,"
                           " r.top + r.height / 2]; })()")
    browser.mouse("mousePressed", box[0], box[1], 1)
    browser.mouse("mouseReleased", box[0], box[1], 0)
    p.wait_frames(2)
    expect(problems, "Sound button after a click",
           browser.evaluate("document.getElementById('sp-sound-toggle').textContent"), "Sound off")
    p.click("sp-pause")
    p.click("sp-pause")
    p.wait_frames(2)
    log = browser.evaluate("document.getElementById('sp-log').textContent").strip()
    if log:
        problems.append("interaction: the sound page logged: " + log)


def control_catches(chromium, work):
    """A page with a raw payload must trip the checks, or they prove nothing."""
    page = os.path.join(work, "control.html")
    with open(page, "w") as f:
        f.write("<!DOCTYPE html><html><body><img src=x onerror=\"document.body.setAttribute("
                "'%s','img')\"></body></html>" % MARK)
    dom_text, _ = chromium_dom(chromium, work, page, "")
    dom = Dom()
    dom.feed(dom_text)
    return MARK in dom.body


def render_differs(record):
    """Why render cannot draw what the site (and the page) draws, or ''. Since render
    binds each pass's own channels with their sampler settings and a zero keyboard
    (commit caddb96), only a Cube A pass is left: render does not draw it."""
    reasons = set()
    for p in record.get("passes", []):
        if p.get("type") == "cubemap":
            reasons.add("cube-pass")
    return ",".join(sorted(reasons))


def measure_corpus(argv):
    """Pages of a corpus's multipass projects against render; prints one line each."""
    import argparse
    ap = argparse.ArgumentParser()
    ap.add_argument("--corpus", required=True)
    ap.add_argument("--limit", type=int, default=0)
    ap.add_argument("--frames", type=int, default=3)
    ap.add_argument("--ids", default="", help="only these record ids (comma-separated)")
    ap.add_argument("--modes", default="site,ported", help="site, ported or both")
    ap.add_argument("--require-match", action="store_true",
                    help="exit 1 unless every project's pages are clean and match render")
    ap.add_argument("binary")
    ap.add_argument("fixture")
    ap.add_argument("work")
    args = ap.parse_args(argv)
    chromium = shutil.which(os.environ.get("CHROMIUM", "chromium"))
    shutil.rmtree(args.work, ignore_errors=True)
    modes = [m for m in args.modes.split(",") if m in ("site", "ported")]
    for mode in modes:
        os.makedirs(os.path.join(args.work, mode))
    records = []
    with open(args.corpus) as f:
        for line in f:
            record = json.loads(line)
            if any(p.get("type") == "buffer" for p in record.get("passes", [])):
                records.append(record)
    missing = []
    if args.ids:
        wanted = [i for i in args.ids.split(",") if i]
        records = [r for r in records if r.get("id") in wanted]
        missing = sorted(set(wanted) - {r.get("id") for r in records})
    if args.limit:
        records = records[:args.limit]

    def one(record):
        started = time.time()
        key = record["id"]
        path = os.path.join(args.work, key + ".json")
        with open(path, "w") as f:
            json.dump(record, f)
        png = os.path.join(args.work, key + ".render.png")
        try:
            subprocess.run([args.binary, "render", path, "--size", "%dx%d" % (SIZE, SIZE),
                            "--frames", str(args.frames), "--time", "1", "--hermetic",
                            "--timeout", "100", "-o", png],
                           capture_output=True, timeout=120)
        except subprocess.TimeoutExpired:
            pass
        reference = pngio.read_png(png) if os.path.exists(png) else None
        out = {"id": key, "differs": render_differs(record)}
        for mode in modes:
            page = os.path.join(args.work, mode, key + ".html")
            try:
                # ported: what users get (`port --emit html`), as in the main test.
                make_page(args.binary, args.fixture, mode, path, page)
                text, console = chromium_dom(chromium, args.work, page,
                                             "#time=1&frames=%d&size=%dx%d" %
                                             (args.frames, SIZE, SIZE), timeout=60)
            except (subprocess.CalledProcessError, subprocess.TimeoutExpired) as e:
                out[mode] = "page-failed " + type(e).__name__
                continue
            dom = Dom()
            dom.feed(text)
            state = dom.attrs.get("sp-state", {}).get("data-state")
            log = dom.text.get("sp-log", "").strip()
            if state != "done" or not dom.text.get("sp-pixels") or log or console:
                out[mode] = "state-%s %s" % (state, (log or " ".join(console))[:160])
                continue
            pixels = (SIZE, SIZE, base64.b64decode(dom.text["sp-pixels"].strip()))
            if reference is None:
                out[mode] = "no-render"
                continue
            c = compare_pictures.compare(pixels, reference)
            out[mode] = "%s %.1f" % ("match" if c.match else "MISMATCH", c.worst)
        out["seconds"] = time.time() - started
        return out

    counts = {}
    failed = ["%s: not a project with a Buffer pass in %s" % (i, args.corpus) for i in missing]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for out in pool.map(one, records):
            print("%s %s render-differs=%s %.0fs" %
                  (out["id"], " ".join("%s=%s" % (m, out.get(m)) for m in modes),
                   out["differs"] or "-", out["seconds"]), flush=True)
            for mode in modes:
                word = out.get(mode, "?").split(" ")[0]
                group = "render-differs" if out["differs"] else "comparable"
                counts[(group, mode, word)] = counts.get((group, mode, word), 0) + 1
                if word != "match":
                    failed.append("%s (%s): %s" % (out["id"], mode, out.get(mode)))
    print("%d projects with buffers: %s" % (len(records), sorted(counts.items())))
    if args.require_match:
        for line in failed:
            print("project_pages: FAIL " + line, file=sys.stderr)
        return 1 if failed or not records else 0
    return 0


def main():
    if "--corpus" in sys.argv:
        return measure_corpus(sys.argv[1:])
    binary, fixture, work = sys.argv[1], sys.argv[2], sys.argv[3]
    chromium = shutil.which(os.environ.get("CHROMIUM", "chromium"))
    if chromium is None:
        print("project_pages: chromium is not installed (tools/install-deps.sh installs it)",
              file=sys.stderr)
        return 1
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    problems = []
    measured = []
    if not control_catches(chromium, work):
        print("project_pages: the control page's payload did not run", file=sys.stderr)
        return 1
    jobs = dict(COMPARED, **PAGE_ONLY)
    modes = ("site", "ported")
    for mode in modes:
        os.makedirs(os.path.join(work, mode))
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        renders = {n: pool.submit(render, binary, work, n, f) for n, f in COMPARED.items()}
        pages = {(m, n): pool.submit(page_result, chromium, binary, fixture, work, m, n, f)
                 for m in modes for n, f in jobs.items()}
        for mode in modes:
            for name in jobs:
                r = pages[(mode, name)].result()
                label = "%s (%s)" % (name, mode)
                if name in COMPARED:
                    reference, why = renders[name].result()
                    if reference is None:
                        problems.append("%s: %s" % (label, why))
                    check_compared(name, label, r, reference, problems, measured)
                else:
                    check_page_only(name, label, r, problems)
            measured.append("%s pages from %s" % (mode, r["source"]))
    check_live(chromium, work, problems)
    check_without_webgl2(chromium, work, problems)
    check_interaction(chromium, binary, fixture, work, problems)
    for line in measured:
        print("project_pages: " + line)
    for problem in problems:
        print("project_pages: FAIL " + problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
