#!/usr/bin/env python3
"""Render ShaderToy Image passes (or WebGL2 fragment shaders) in headless Chromium.

The reference picture for `shaderport render`: each shader is composed exactly as
shadertoy.com composes an Image pass for WebGL2 (the header and main() are copied from
src/validate/shadertoy_contract.cpp; a Common pass is prepended to the Image code), drawn
with a full-screen triangle into a W x H RGBA8 framebuffer with the uniform values that
`shaderport render` uses (docs/render.md, src/render/uniform_values.cpp), read back with
readPixels and written top-down as PNG. Channels the record does not feed are left
unbound, as on the site (WebGL samples an unbound texture as (0,0,0,1);
iChannelResolution is 0).

Chromium runs headless with SwiftShader; one page renders a batch of shaders in its
synchronous load script and writes the results into the DOM, which --dump-dom prints.
A batch that times out (a shader that hangs) or loses the context is re-run one shader
at a time, so only the guilty shader is reported as `timeout` / `context-lost`.

Per shader: status ok | compile-error | link-error | draw-error | timeout | context-lost
| chromium-failed, the compile/link log, and OUT_DIR/<key>.png when drawn.

Run:
  python3 tools/browser/shadertoy_reference.py toy.glsl other.glsl -o out/
  python3 tools/browser/shadertoy_reference.py --jsonl corpus.jsonl --limit 20 -o out/
  python3 tools/browser/shadertoy_reference.py --jsonl corpus.jsonl --id 3d2GRh -o out/
  python3 tools/browser/shadertoy_reference.py --webgl2 probe.frag -o out/
Writes OUT/<key>.png and OUT/results.json; prints one line per shader.
Python 3 standard library only. Needs `chromium` (Debian package `chromium`).
"""

import argparse
import base64
import html
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pngio  # noqa: E402

# --- The site's composition, copied from src/validate/shadertoy_contract.cpp ----------

_UNIFORMS = (
    "uniform vec3 iResolution;\n"
    "uniform float iTime;\n"
    "uniform float iChannelTime[4];\n"
    "uniform vec4 iMouse;\n"
    "uniform vec4 iDate;\n"
    "uniform float iSampleRate;\n"
    "uniform vec3 iChannelResolution[4];\n"
    "uniform int iFrame;\n"
    "uniform float iTimeDelta;\n"
    "uniform float iFrameRate;\n")

_SAMPLER_BY_CTYPE = {"cubemap": "samplerCube", "volume": "sampler3D"}


def shadertoy_header(channel_samplers=("sampler2D",) * 4):
    """ShaderToyHeader(PassKind::kImage, channels): shadertoy_compose.header, which
    mirrors every pass kind (imported here, since it reads this module's uniforms)."""
    import shadertoy_compose
    return shadertoy_compose.header("image", channel_samplers)


# ShaderToyEpilogue(PassKind::kImage)
IMAGE_EPILOGUE = ("#ifndef mainImage\n"
                  "void mainImage(out vec4, in vec2);\n"
                  "#endif\n"
                  "void main() {\n"
                  "  vec4 shadertoy_color = vec4(1e20);\n"
                  "  mainImage(shadertoy_color, gl_FragCoord.xy);\n"
                  "  shadertoy_out_color = vec4(shadertoy_color.xyz, 1.0);\n"
                  "}\n")

VERTEX_SHADER = ("#version 300 es\n"
                 "void main() {\n"
                 "  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n"
                 "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
                 "}\n")


def _with_newline(text):
    # ComposeShaderToyRequest adds "\n" after a user part that does not end in a newline.
    if text and text[-1] not in "\r\n":
        return text + "\n"
    return text


def compose_image_pass(code, common=None, channel_samplers=("sampler2D",) * 4):
    """The complete fragment shader the site compiles for an Image pass."""
    text = shadertoy_header(channel_samplers)
    if common is not None:
        text += _with_newline(common)
    text += _with_newline(code)
    return text + IMAGE_EPILOGUE


def channel_samplers_of(pass_record):
    samplers = ["sampler2D"] * 4
    for inp in pass_record.get("inputs") or []:
        ch = inp.get("channel", -1)
        if isinstance(ch, int) and 0 <= ch <= 3:
            samplers[ch] = _SAMPLER_BY_CTYPE.get(inp.get("ctype", ""), "sampler2D")
    return tuple(samplers)


def compose_record(record):
    """Fragment text for a corpus record's Image pass (Common prepended)."""
    passes = record.get("passes") or []
    image = next((p for p in passes if p.get("type") == "image"), None)
    if image is None:
        raise ValueError("record %s has no Image pass" % record.get("id"))
    common = next((p.get("code", "") for p in passes if p.get("type") == "common"), None)
    return compose_image_pass(image.get("code", ""), common, channel_samplers_of(image))


# --- The page ---------------------------------------------------------------------------

_PAGE_SCRIPT = r"""
"use strict";
const out = document.getElementById("results");
function emit(obj) { out.appendChild(document.createTextNode("@@R " + JSON.stringify(obj) + "\n")); }
const W = CONFIG.width, H = CONFIG.height, T = CONFIG.time;
const canvas = document.createElement("canvas");
canvas.width = W; canvas.height = H;
const gl = canvas.getContext("webgl2", {antialias: false, depth: false, stencil: false,
                                        alpha: true, premultipliedAlpha: false,
                                        preserveDrawingBuffer: true});
const G = gl || {};
function b64(bytes) {
  let s = "";
  for (let i = 0; i < bytes.length; i += 0x8000)
    s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s);
}
function lower(s) { return s.toLowerCase(); }
function has(s, n) { return s.indexOf(n) >= 0; }
function perspective(aspect) {
  const fov = 60.0 * 3.14159265 / 180.0, f = 1.0 / Math.tan(fov / 2.0), n = 0.1, fa = 100.0;
  const m = new Float32Array(16);
  m[0] = f / aspect; m[5] = f; m[10] = (fa + n) / (n - fa); m[11] = -1.0; m[14] = 2.0 * fa * n / (n - fa);
  return m;
}
function identity(n) { const m = new Float32Array(n * n); for (let i = 0; i < n; ++i) m[i * n + i] = 1; return m; }
function repeat(arr, count) { const o = []; for (let i = 0; i < count; ++i) o.push(...arr); return o; }
function isSampler(t) {
  return [G.SAMPLER_2D, G.SAMPLER_3D, G.SAMPLER_CUBE, G.SAMPLER_2D_SHADOW, G.SAMPLER_CUBE_SHADOW,
          G.SAMPLER_2D_ARRAY, G.SAMPLER_2D_ARRAY_SHADOW, G.INT_SAMPLER_2D, G.INT_SAMPLER_3D,
          G.INT_SAMPLER_CUBE, G.INT_SAMPLER_2D_ARRAY, G.UNSIGNED_INT_SAMPLER_2D,
          G.UNSIGNED_INT_SAMPLER_3D, G.UNSIGNED_INT_SAMPLER_CUBE,
          G.UNSIGNED_INT_SAMPLER_2D_ARRAY].indexOf(t) >= 0;
}
// The values of src/render/uniform_values.cpp (SetShaderToyUniform, then by type and name).
function setUniforms(prog, job) {
  // A job may bring its own iTime, iFrame and iMouse (random-time parity runs).
  const T = job.time !== undefined ? job.time : CONFIG.time;
  const FRAME = job.frame || 0;
  const MOUSE = job.mouse || [0, 0, 0, 0];
  const count = gl.getProgramParameter(prog, gl.ACTIVE_UNIFORMS);
  const delta = 1.0 / 60.0;
  let unit = 0;
  for (let i = 0; i < count; ++i) {
    const info = gl.getActiveUniform(prog, i);
    const loc = gl.getUniformLocation(prog, info.name);
    if (loc === null) continue;  // uniform block member
    let name = info.name;
    if (name.length > 3 && name.endsWith("[0]")) name = name.slice(0, -3);
    const size = info.size, t = info.type;
    if (isSampler(t)) { gl.uniform1i(loc, unit++); continue; }  // nothing bound, as on the site
    if (name === "iResolution") gl.uniform3f(loc, W, H, 1.0);
    else if (name === "iTime" || name === "iGlobalTime" || name === "iTimeOffset") gl.uniform1f(loc, T);
    else if (name === "iTimeDelta") gl.uniform1f(loc, delta);
    else if (name === "iFrameRate") gl.uniform1f(loc, 60.0);
    else if (name === "iFrame") gl.uniform1i(loc, FRAME);
    else if (name === "iMouse") gl.uniform4f(loc, MOUSE[0], MOUSE[1], MOUSE[2], MOUSE[3]);
    else if (name === "iDate") gl.uniform4f(loc, 2025, 0, 1, 43200);
    else if (name === "iSampleRate") gl.uniform1f(loc, 44100.0);
    else if (name === "iSampleOffset") gl.uniform1i(loc, 0);
    else if (name === "iChannelTime") gl.uniform1fv(loc, repeat([T], Math.min(size, 4)));
    else if (name === "iChannelResolution") gl.uniform3fv(loc, repeat([0, 0, 0], Math.min(size, 4)));
    else if (name === "unViewport") gl.uniform4f(loc, 0, 0, W, H);
    else if (name === "unCorners")
      gl.uniform3fv(loc, [-1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1, 0, 0, 0].slice(0, 3 * Math.min(size, 5)));
    else {
      const n = lower(name);
      let v = [0.5, 0.5, 0.5, 1.0];
      if (has(n, "texel")) v = [1.0 / W, 1.0 / H, 0, 0];
      else if (has(n, "resolution") || has(n, "viewport") || has(n, "size")) v = [W, H, 1, 1];
      else if (has(n, "time")) v = [T, T, T, T];
      const f = (c) => repeat(v.slice(0, c), size);
      if (t === gl.FLOAT) gl.uniform1fv(loc, f(1));
      else if (t === gl.FLOAT_VEC2) gl.uniform2fv(loc, f(2));
      else if (t === gl.FLOAT_VEC3) gl.uniform3fv(loc, f(3));
      else if (t === gl.FLOAT_VEC4) gl.uniform4fv(loc, f(4));
      else if (t === gl.INT || t === gl.BOOL) gl.uniform1iv(loc, repeat([1], size));
      else if (t === gl.INT_VEC2 || t === gl.BOOL_VEC2) gl.uniform2iv(loc, repeat([1], 2 * size));
      else if (t === gl.INT_VEC3 || t === gl.BOOL_VEC3) gl.uniform3iv(loc, repeat([1], 3 * size));
      else if (t === gl.INT_VEC4 || t === gl.BOOL_VEC4) gl.uniform4iv(loc, repeat([1], 4 * size));
      else if (t === gl.UNSIGNED_INT) gl.uniform1uiv(loc, repeat([1], size));
      else if (t === gl.UNSIGNED_INT_VEC2) gl.uniform2uiv(loc, repeat([1], 2 * size));
      else if (t === gl.UNSIGNED_INT_VEC3) gl.uniform3uiv(loc, repeat([1], 3 * size));
      else if (t === gl.UNSIGNED_INT_VEC4) gl.uniform4uiv(loc, repeat([1], 4 * size));
      else if (t === gl.FLOAT_MAT2) gl.uniformMatrix2fv(loc, false, repeat(identity(2), size));
      else if (t === gl.FLOAT_MAT3) gl.uniformMatrix3fv(loc, false, repeat(identity(3), size));
      else if (t === gl.FLOAT_MAT4) {
        let m = identity(4);
        if (has(n, "proj")) m = perspective(W / H);
        else if (has(n, "view")) m[14] = -3.0;
        gl.uniformMatrix4fv(loc, false, repeat(m, size));
      }
    }
  }
}
function run() {
  if (!gl) {
    for (const job of JOBS) emit({key: job.key, status: "context-lost", log: "no WebGL2 context"});
    return;
  }
  const fbo = gl.createFramebuffer();
  const tex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, W, H);
  gl.bindTexture(gl.TEXTURE_2D, null);
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
  const vao = gl.createVertexArray();
  const vs = gl.createShader(gl.VERTEX_SHADER);
  gl.shaderSource(vs, VERTEX_SHADER);
  gl.compileShader(vs);
  const pixels = new Uint8Array(W * H * 4);
  const flipped = new Uint8Array(W * H * 4);
  for (const job of JOBS) {
    const t0 = performance.now();
    const r = {key: job.key, status: "ok", log: ""};
    if (gl.isContextLost()) { r.status = "context-lost"; emit(r); continue; }
    const fs = gl.createShader(gl.FRAGMENT_SHADER);
    gl.shaderSource(fs, job.fragment);
    gl.compileShader(fs);
    if (!gl.getShaderParameter(fs, gl.COMPILE_STATUS)) {
      r.status = gl.isContextLost() ? "context-lost" : "compile-error";
      r.log = gl.getShaderInfoLog(fs) || "";
      gl.deleteShader(fs);
      r.ms = performance.now() - t0; emit(r); continue;
    }
    const prog = gl.createProgram();
    gl.attachShader(prog, vs);
    gl.attachShader(prog, fs);
    gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) {
      r.status = gl.isContextLost() ? "context-lost" : "link-error";
      r.log = gl.getProgramInfoLog(prog) || "";
      gl.deleteProgram(prog); gl.deleteShader(fs);
      r.ms = performance.now() - t0; emit(r); continue;
    }
    r.log = gl.getShaderInfoLog(fs) || "";
    gl.useProgram(prog);
    gl.bindVertexArray(vao);
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.viewport(0, 0, W, H);
    gl.disable(gl.BLEND); gl.disable(gl.DEPTH_TEST); gl.disable(gl.DITHER);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT);
    setUniforms(prog, job);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
    const err = gl.getError();
    if (gl.isContextLost()) { r.status = "context-lost"; }
    else if (err !== gl.NO_ERROR) { r.status = "draw-error"; r.log += "glGetError 0x" + err.toString(16); }
    else {
      const stride = W * 4;
      for (let y = 0; y < H; ++y)  // readPixels is bottom-up; the PNG is top-down
        flipped.set(pixels.subarray((H - 1 - y) * stride, (H - y) * stride), y * stride);
      r.pixels = b64(flipped);
    }
    gl.useProgram(null);
    gl.deleteProgram(prog); gl.deleteShader(fs);
    r.ms = performance.now() - t0;
    emit(r);
  }
}
try { run(); } catch (e) { emit({key: "", status: "script-error", log: String(e && e.stack || e)}); }
emit({key: "", status: "done"});
"""


def build_page(jobs, width, height, time_value):
    def js(value):
        # JSON is valid JavaScript; "</" must not close the <script> element.
        return json.dumps(value, ensure_ascii=True).replace("</", "<\\/")

    return ("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>shaderport reference</title>"
            "</head><body><pre id=\"results\"></pre>\n<script>\n"
            "const CONFIG = " + js({"width": width, "height": height, "time": time_value}) + ";\n"
            "const VERTEX_SHADER = " + js(VERTEX_SHADER) + ";\n"
            "const JOBS = " + js([{k: j[k] for k in ("key", "fragment", "time", "frame", "mouse")
                                  if k in j} for j in jobs]) +
            ";\n" + _PAGE_SCRIPT + "</script></body></html>\n")


# --- Chromium -----------------------------------------------------------------------------

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
                  "--enable-unsafe-swiftshader", "--disable-background-networking",
                  "--disable-extensions", "--no-first-run"]


def find_chromium(explicit=None):
    for candidate in [explicit, os.environ.get("CHROMIUM"), "chromium", "chromium-browser",
                      "google-chrome"]:
        if candidate and shutil.which(candidate):
            return shutil.which(candidate)
    raise SystemExit("chromium not found: install the Debian package `chromium` or pass --chromium")


def _run_page(chromium, jobs, width, height, time_value, timeout, virtual_time_ms):
    """Renders `jobs` in one Chromium process. Returns (results by key, error text);
    results is None when Chromium timed out."""
    workdir = tempfile.mkdtemp(prefix="shaderport-chromium-")
    try:
        page = os.path.join(workdir, "page.html")
        with open(page, "w", encoding="utf-8") as f:
            f.write(build_page(jobs, width, height, time_value))
        profile = os.path.join(workdir, "profile")
        cmd = [chromium] + CHROMIUM_FLAGS + [
            "--user-data-dir=" + profile, "--virtual-time-budget=%d" % virtual_time_ms,
            "--dump-dom", "file://" + page]
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                start_new_session=True)
        try:
            stdout, stderr = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            _kill_group(proc)
            return None, "timeout after %.0f s" % timeout
        finally:
            _kill_group(proc)  # helper processes of this Chromium only (its own session)
        text = stdout.decode("utf-8", "replace")
        results = {}
        done = False
        start = text.find('<pre id="results">')
        end = text.find("</pre>", start)
        body = text[start + len('<pre id="results">'):end] if start >= 0 and end >= 0 else ""
        for line in body.splitlines():
            if not line.startswith("@@R "):
                continue
            obj = json.loads(html.unescape(line[4:]))
            if obj.get("status") == "done":
                done = True
            elif obj.get("key"):
                results[obj["key"]] = obj
            elif obj.get("status") == "script-error":
                return results, "page script error: " + obj.get("log", "")
        if not done:
            tail = stderr.decode("utf-8", "replace")[-2000:]
            return results, "page did not finish (exit %s): %s" % (proc.returncode, tail)
        return results, ""
    finally:
        shutil.rmtree(workdir, ignore_errors=True)


def _kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        pass


def render_jobs(jobs, width=64, height=64, time_value=1.0, batch_size=20, batch_timeout=None,
                single_timeout=30.0, chromium=None, log=None):
    """jobs: [{"key", "fragment"}] (complete fragment shaders). Returns {key: result} with
    status, log, and for status ok `rgba` (bytes, top-down) and `width`, `height`."""
    chromium = find_chromium(chromium)
    results = {}

    def note(msg):
        if log:
            log(msg)

    def finish(key, obj):
        r = {"status": obj.get("status", "chromium-failed"), "log": obj.get("log", ""),
             "ms": obj.get("ms")}
        if r["status"] == "ok":
            r["rgba"] = base64.b64decode(obj["pixels"])
            r["width"], r["height"] = width, height
        results[key] = r

    for start in range(0, len(jobs), batch_size):
        batch = jobs[start:start + batch_size]
        timeout = batch_timeout if batch_timeout else 20.0 + 4.0 * len(batch)
        t0 = time.time()
        got, err = _run_page(chromium, batch, width, height, time_value, timeout,
                             virtual_time_ms=int(timeout * 1000))
        note("chromium batch %d-%d: %.1f s%s" % (start, start + len(batch) - 1, time.time() - t0,
                                                  (" (" + err.splitlines()[0] + ")") if err else ""))
        clean = got is not None and not err and all(
            k["key"] in got and got[k["key"]].get("status") != "context-lost" for k in batch)
        if clean or len(batch) == 1:
            for job in batch:
                if got is not None and job["key"] in got:
                    finish(job["key"], got[job["key"]])
                elif got is None:
                    results[job["key"]] = {"status": "timeout", "log": err}
                else:
                    results[job["key"]] = {"status": "chromium-failed", "log": err}
            continue
        # Something went wrong: keep what finished before the first context loss, then
        # run the rest one by one.
        for job in batch:
            key = job["key"]
            prior = got.get(key) if got else None
            if prior is not None and prior.get("status") != "context-lost":
                finish(key, prior)
                continue
            t1 = time.time()
            one, err1 = _run_page(chromium, [job], width, height, time_value, single_timeout,
                                  virtual_time_ms=int(single_timeout * 1000))
            note("  alone %s: %.1f s%s" % (key, time.time() - t1, (" (" + err1 + ")") if err1 else ""))
            if one is None:
                results[key] = {"status": "timeout", "log": err1}
            elif key in one:
                finish(key, one[key])
            else:
                results[key] = {"status": "chromium-failed", "log": err1}
    return results


# --- Command line -------------------------------------------------------------------------

def _safe_key(text):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", text).strip("_") or "shader"


def load_jobs(args):
    jobs = []
    common = None
    if args.common:
        with open(args.common, encoding="utf-8", errors="replace") as f:
            common = f.read()
    if args.jsonl:
        wanted = set(args.id or [])
        with open(args.jsonl, encoding="utf-8") as f:
            for line in f:
                if not line.strip():
                    continue
                rec = json.loads(line)
                if wanted and rec.get("id") not in wanted:
                    continue
                try:
                    frag = compose_record(rec)
                except ValueError as e:
                    print("skip: %s" % e, file=sys.stderr)
                    continue
                jobs.append({"key": _safe_key(rec.get("id", "record")), "fragment": frag,
                             "meta": {k: rec.get(k) for k in ("id", "name", "author", "license", "url")}})
                if args.limit and len(jobs) >= args.limit:
                    break
    for path in args.files:
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        key = _safe_key(os.path.splitext(os.path.basename(path))[0])
        if path.endswith(".json"):
            frag = compose_record(json.loads(text))
        elif args.webgl2 or text.lstrip().startswith("#version 300 es"):
            frag = text  # a WebGL2 fragment shader, drawn as it is
        else:
            frag = compose_image_pass(text, common)
        jobs.append({"key": key, "fragment": frag, "meta": {"file": path}})
    return jobs


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Render ShaderToy Image passes / WebGL2 fragment shaders in headless Chromium "
                    "(SwiftShader) as shadertoy.com composes them, and write PNGs.")
    ap.add_argument("files", nargs="*", help=".glsl ShaderToy Image pass, .json ShaderToy record, "
                    "or a '#version 300 es' fragment shader (drawn as it is)")
    ap.add_argument("--jsonl", help="corpus JSONL (records with passes[]); renders each Image pass")
    ap.add_argument("--id", action="append", help="with --jsonl: only this record id (repeatable)")
    ap.add_argument("--limit", type=int, default=0, help="with --jsonl: first N records")
    ap.add_argument("--common", help="Common pass prepended to each .glsl file")
    ap.add_argument("--webgl2", action="store_true",
                    help="treat every file as a complete WebGL2 fragment shader (one out vec4)")
    ap.add_argument("-o", "--out-dir", required=True, help="directory for <key>.png and results.json")
    ap.add_argument("--size", default="64x64", help="WIDTHxHEIGHT (default 64x64)")
    ap.add_argument("--time", type=float, default=1.0, help="iTime (default 1.0)")
    ap.add_argument("--batch", type=int, default=20, help="shaders per Chromium page (default 20)")
    ap.add_argument("--batch-timeout", type=float, default=0,
                    help="seconds per batch (default 20 + 4 per shader)")
    ap.add_argument("--timeout", type=float, default=30.0, help="seconds for one shader alone")
    ap.add_argument("--chromium", help="Chromium binary (default: chromium on PATH)")
    ap.add_argument("--dump-fragment", action="store_true",
                    help="also write OUT/<key>.frag, the composed fragment shader")
    args = ap.parse_args(argv)
    m = re.fullmatch(r"(\d+)x(\d+)", args.size)
    if not m:
        ap.error("--size must be WIDTHxHEIGHT")
    width, height = int(m.group(1)), int(m.group(2))
    jobs = load_jobs(args)
    if not jobs:
        ap.error("nothing to render")
    keys = [j["key"] for j in jobs]
    if len(set(keys)) != len(keys):
        ap.error("two inputs have the same name")
    os.makedirs(args.out_dir, exist_ok=True)
    results = render_jobs(jobs, width, height, args.time, args.batch, args.batch_timeout,
                          args.timeout, args.chromium, log=lambda s: print(s, file=sys.stderr))
    summary = []
    for job in jobs:
        r = results[job["key"]]
        entry = {"key": job["key"], "status": r["status"], "log": r.get("log", ""), **job["meta"]}
        if args.dump_fragment:
            with open(os.path.join(args.out_dir, job["key"] + ".frag"), "w") as f:
                f.write(job["fragment"])
        if r["status"] == "ok":
            png = os.path.join(args.out_dir, job["key"] + ".png")
            pngio.write_png(png, width, height, r["rgba"])
            entry["png"] = png
        summary.append(entry)
        log = (" " + r.get("log", "").strip().replace("\n", " | ")[:300]) if r["status"] != "ok" else ""
        print("%s: %s%s" % (job["key"], r["status"], log))
    with open(os.path.join(args.out_dir, "results.json"), "w") as f:
        json.dump(summary, f, indent=1)
    return 0 if all(s["status"] == "ok" for s in summary) else 1


if __name__ == "__main__":
    sys.exit(main())
