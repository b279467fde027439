#!/usr/bin/env python3
"""Pages of the repository's seeds (corpus/MANIFEST) from `shaderport port --emit html`
run in headless Chromium and draw what `shaderport render` draws:
  - the AO template and its variants (corpus/ao, ShaderToy Image passes; not
    steps-1-5.glsl, which does not compile as the seed wrote it): page and render of
    the same file;
  - the raymarching blog's stages (corpus/raymarch, dialect raymarch-blog: the harness
    supplies uv, time and color): the page of `port --emit html --dialect raymarch-blog`
    against render of `port --dialect raymarch-blog`'s output;
  - the WebGL1 SSAO demo (corpus/ssao): each shader alone against render (a vertex
    shader on render's sphere with its depth shade, a fragment shader with render's
    feeder for its inputs), and the demo's vertex/fragment pairs
    (`port --emit html a.vert b.frag`), which render cannot draw together: no errors,
    and a picture that is not one colour.
Where SwiftShader and llvmpipe differ (GPU_DIFFERS: undefined math, hash noise) the
page is checked on its own, and for the raymarching AO a control with those
expressions made defined is compared with render instead.
Each page at 64x64, time 1, 2 frames; pictures within 12/255 by 8x8 block means
(docs/render.md), every page without console, GL or compile errors.
  seed_pages.py SHADERPORT_BINARY WORK_DIR
"""
import base64
import concurrent.futures
import glob
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "browser"))
sys.path.insert(0, HERE)
import compare_pictures  # noqa: E402
import pngio  # noqa: E402
from project_pages import Dom, chromium_dom  # noqa: E402

CORPUS = os.path.join(HERE, "..", "..", "corpus")
SIZE = 64
FRAMES = 2
# The demo's programs: geometry pass (positions, normals), lighting, screen passes.
PAIRS = [("geometry.vert", "position.frag"), ("geometry.vert", "normal.frag"),
         ("lighting.vert", "lighting.frag"), ("screen-quad.vert", "ssao.frag"),
         ("screen-quad.vert", "blend.frag"), ("screen-quad.vert", "brightness-contrast.frag")]


# Seeds whose picture depends on the GPU, not on the page: why.
GPU_DIFFERS = {
    "raymarch-stage2-ambient-occlusion": "pow(ray, vec3(3.0)) of negative ray components "
    "(undefined) and fract(sin(i * 618.21) * 41234.56) hash noise",
    "raymarch-stage3-brighter": "the same AO code as stage 2",
    "raymarch-stage4-shadows": "the same AO code as stage 2",
    "ssao-ssao-frag": "normalize() of a zero vector (NaN): the kernel offsets stay within one "
    "texel of render's procedural texture",
}
# The stage 2 AO with both made defined: page and render must agree on it.
DEFINED_AO = [("ray = pow(ray, vec3(3.0));", "ray = ray * ray * ray;"),
              ("i * 123.456", "i * 0.456"), ("i * 61.8", "i * 0.8"), ("i * 618.21", "i * 0.21"),
              ("* 41234.56", "* 4.56")]


def run(command):
    return subprocess.run(command, capture_output=True, text=True, timeout=120)


def page_pixels(chromium, work, page):
    """(pixels or None, problems) of a page after FRAMES frames."""
    text, console = chromium_dom(chromium, work, page, "#time=1&frames=%d&size=%dx%d" %
                                 (FRAMES, SIZE, SIZE))
    dom = Dom()
    dom.feed(text)
    problems = []
    state = dom.attrs.get("sp-state", {}).get("data-state")
    if state != "done":
        problems.append("page state %r: %s" % (state, dom.text.get("sp-errors", "").strip()))
    if dom.text.get("sp-log", "").strip():
        problems.append("the page logged: " + dom.text["sp-log"].strip())
    problems += ["console: " + line for line in console]
    pixels = None
    if dom.text.get("sp-pixels"):
        pixels = (SIZE, SIZE, base64.b64decode(dom.text["sp-pixels"].strip()))
        pngio.write_png(page + ".png", *pixels)
    elif not problems:
        problems.append("no pixels published")
    return pixels, problems


def render(binary, source, png):
    done = run([binary, "render", source, "--size", "%dx%d" % (SIZE, SIZE), "--frames",
                str(FRAMES), "--time", "1", "--hermetic", "-o", png])
    if not os.path.exists(png):
        return None, "render drew nothing (exit %d): %s" % (done.returncode, done.stderr.strip())
    return pngio.read_png(png), ""


def port_page(binary, work, name, sources, extra=()):
    page = os.path.join(work, name + ".html")
    done = run([binary, "port", "--emit", "html"] + list(extra) + list(sources) + ["-o", page])
    if done.returncode not in (0, 1) or not os.path.exists(page):
        return None, "port --emit html failed (exit %d): %s" % (done.returncode, done.stderr)
    return page, ""


def compared(chromium, binary, work, name, sources, render_source, extra=()):
    """Problems and a measurement line for a page compared with render."""
    png = os.path.join(work, name + ".render.png")
    reference, why = render(binary, render_source, png)
    page, why_page = port_page(binary, work, name, sources, extra)
    if page is None:
        return [why_page], ""
    pixels, problems = page_pixels(chromium, work, page)
    if reference is None:
        return problems + [why], ""
    if pixels is None:
        return problems, ""
    c = compare_pictures.compare(pixels, reference)
    if not c.match:
        problems.append("page and render differ: " + compare_pictures.describe(c))
    return problems, compare_pictures.describe(c)


def page_only(chromium, binary, work, name, sources, extra=()):
    page, why = port_page(binary, work, name, sources, extra)
    if page is None:
        return [why], ""
    pixels, problems = page_pixels(chromium, work, page)
    if pixels is None:
        return problems, ""
    colours = {pixels[2][i:i + 3] for i in range(0, len(pixels[2]), 4)}
    if len(colours) < 2:
        problems.append("the picture is one colour %s" % list(colours))
    return problems, "%d colours" % len(colours)


def broken_program(chromium, binary, work, name, source):
    """A compile error in a program page is shown on the user's file and line."""
    text = open(source).read()
    line = text.count("\n") + 1 + (0 if text.endswith("\n") else 1)
    path = os.path.join(work, name + ".glsl")
    with open(path, "w") as f:
        f.write(text + ("" if text.endswith("\n") else "\n") +
                "float broken() { return undefined_name; }\n")
    # A page of code that does not compile is written only when asked for.
    page, why = port_page(binary, work, name, [path], ["--dialect", "raymarch-blog", "--write-invalid"])
    if page is None:
        return [why], ""
    dom_text, _ = chromium_dom(chromium, work, page, "#time=1&frames=1&size=64x64")
    dom = Dom()
    dom.feed(dom_text)
    panel = dom.text.get("sp-errors", "")
    state = dom.attrs.get("sp-state", {}).get("data-state")
    where = "%s.glsl:%d:" % (name, line)
    if state != "error" or where not in panel or "undefined_name" not in panel:
        return ["state %r, the panel does not put the error on %s: %r" % (state, where, panel)], ""
    return [], "error on " + where


def cli_problems(binary, work):
    """-o takes one page: two fragment shaders and a vertex shader give two."""
    ssao = os.path.join(CORPUS, "ssao")
    done = run([binary, "port", "--emit", "html", os.path.join(ssao, "geometry.vert"),
                os.path.join(ssao, "position.frag"), os.path.join(ssao, "normal.frag"), "-o",
                os.path.join(work, "two.html")])
    if done.returncode != 2 or os.path.exists(os.path.join(work, "two.html")):
        return ["port --emit html of 3 shaders with -o: exit %d, expected 2 and nothing "
                "written" % done.returncode]
    return []


def jobs(binary, work):
    """name -> (function, arguments) for every check."""
    out = {}
    for path in sorted(glob.glob(os.path.join(CORPUS, "ao", "*.glsl"))):
        if os.path.basename(path) == "steps-1-5.glsl":
            continue
        name = "ao-" + os.path.basename(path)[:-5]
        out[name] = (compared, (name, [path], path))
    raymarch = sorted(glob.glob(os.path.join(CORPUS, "raymarch", "*.glsl")))
    control = os.path.join(work, "raymarch-stage2-defined.glsl")
    text = open(os.path.join(CORPUS, "raymarch", "stage2-ambient-occlusion.glsl")).read()
    for old, new in DEFINED_AO:
        if old not in text:
            raise RuntimeError("stage2-ambient-occlusion.glsl has no %r any more" % old)
        text = text.replace(old, new)
    with open(control, "w") as f:
        f.write(text)
    for path in raymarch + [control]:
        name = "raymarch-" + os.path.basename(path)[:-5]
        if name in GPU_DIFFERS:
            out[name] = (page_only, (name, [path], ["--dialect", "raymarch-blog"]))
            continue
        frag = os.path.join(work, name + ".frag")
        done = run([binary, "port", "--dialect", "raymarch-blog", path, "-o", frag])
        if done.returncode not in (0, 1):
            raise RuntimeError("port --dialect raymarch-blog %s: %s" % (path, done.stderr))
        out[name] = (compared, (name, [path], frag, ["--dialect", "raymarch-blog"]))
    out["raymarch-broken"] = (broken_program, ("raymarch-broken", raymarch[0]))
    for path in sorted(glob.glob(os.path.join(CORPUS, "ssao", "*.*"))):
        name = "ssao-" + os.path.basename(path).replace(".", "-")
        out[name] = (page_only, (name, [path])) if name in GPU_DIFFERS else (
            compared, (name, [path], path))
    for vert, frag in PAIRS:
        name = "ssao-pair-%s-%s" % (vert.split(".")[0], frag.split(".")[0])
        out[name] = (page_only, (name, [os.path.join(CORPUS, "ssao", vert),
                                        os.path.join(CORPUS, "ssao", frag)]))
    return out


def main():
    binary, work = sys.argv[1], sys.argv[2]
    chromium = shutil.which(os.environ.get("CHROMIUM", "chromium"))
    if chromium is None:
        print("seed_pages: chromium is not installed", file=sys.stderr)
        return 1
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failed = cli_problems(binary, work)
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = {name: pool.submit(f, chromium, binary, work, *args)
                   for name, (f, args) in jobs(binary, work).items()}
        for name, future in futures.items():
            problems, measured = future.result()
            print("seed_pages: %s: %s" % (name, measured or "-"))
            failed += ["%s: %s" % (name, p) for p in problems]
    for line in failed:
        print("seed_pages: FAIL " + line, file=sys.stderr)
    print("seed_pages: %d pages, %d problems" % (len(futures), len(failed)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
