"""Chromium's compile verdict for shader stages: one headless Chromium (ANGLE on
SwiftShader) kept open over the DevTools pipe, compiling batches of stages in a WebGL1
or WebGL2 context, exactly as a page's gl.compileShader does, or (link) vertex + fragment
programs compiled and linked as gl.linkProgram does. The page enables the
WebGL extensions that the shader's `#extension` lines name (getExtension), as a page
written for that shader does and as `check` assumes; others stay off. Python standard
library only.
"""
import json
import os
import re
import shutil
import tempfile

import cdp_pipe

# The WebGL extension a page enables for each GLSL #extension name.
WEBGL_EXTENSIONS = {
    "GL_OES_standard_derivatives": "OES_standard_derivatives",
    "GL_EXT_shader_texture_lod": "EXT_shader_texture_lod",
    "GL_EXT_frag_depth": "EXT_frag_depth",
    "GL_EXT_draw_buffers": "WEBGL_draw_buffers",
    "GL_ANGLE_multi_draw": "WEBGL_multi_draw",
    "GL_OVR_multiview": "OVR_multiview2",
    "GL_OVR_multiview2": "OVR_multiview2",
    "GL_EXT_clip_cull_distance": "WEBGL_clip_cull_distance",
    "GL_ANGLE_clip_cull_distance": "WEBGL_clip_cull_distance",
    "GL_NV_shader_noperspective_interpolation": "NV_shader_noperspective_interpolation",
    "GL_OES_sample_variables": "OES_sample_variables",
    "GL_OES_shader_multisample_interpolation": "OES_shader_multisample_interpolation",
    "GL_EXT_conservative_depth": "EXT_conservative_depth",
    "GL_EXT_blend_func_extended": "WEBGL_blend_func_extended",
}
_EXTENSION_LINE = re.compile(r"^[ \t]*#[ \t]*extension[ \t]+(\w+)", re.M)


def extensions_of(source):
    """The WebGL extensions a page would enable for `source`, sorted."""
    return sorted({WEBGL_EXTENSIONS[n] for n in _EXTENSION_LINE.findall(source)
                   if n in WEBGL_EXTENSIONS})


# A context of the job's version with its extensions enabled (contexts are cached by
# both, a few at a time; a lost context is made again). Shared by the two scripts below.
_CONTEXT_FUNCTION = r"""
  const contexts = window.__spContexts || (window.__spContexts = new Map());
  function context(version, extensions) {
    const key = version + ":" + extensions.join(",");
    let gl = contexts.get(key);
    if (!gl || gl.isContextLost()) {
      if (contexts.size >= 8) {  // browsers keep few live contexts: drop the others
        for (const old of contexts.values()) {
          const lose = old.getExtension("WEBGL_lose_context");
          if (lose) lose.loseContext();
        }
        contexts.clear();
      }
      const canvas = document.createElement("canvas");
      canvas.width = canvas.height = 1;
      gl = canvas.getContext(version === 2 ? "webgl2" : "webgl", {preserveDrawingBuffer: false});
      if (gl) for (const name of extensions) gl.getExtension(name);
      contexts.set(key, gl);
    }
    return gl;
  }
"""

# Compiles every job of the batch and returns [ok, log] per job.
_COMPILE_SCRIPT = r"""
(function(jobs) {
""" + _CONTEXT_FUNCTION + r"""
  const out = [];
  for (const job of jobs) {
    const gl = context(job.context, job.extensions);
    if (!gl) { out.push([null, "no context"]); continue; }
    const shader = gl.createShader(job.stage === "vertex" ? gl.VERTEX_SHADER : gl.FRAGMENT_SHADER);
    if (!shader) { out.push([null, "createShader failed: context lost"]); continue; }
    gl.shaderSource(shader, job.source);
    gl.compileShader(shader);
    const ok = gl.getShaderParameter(shader, gl.COMPILE_STATUS);
    out.push([ok === true, gl.getShaderInfoLog(shader) || ""]);
    gl.deleteShader(shader);
  }
  return out;
})
"""

# Compiles both stages of every program in one context and links them, as a page does
# (linked even when a stage failed: LINK_STATUS is then Chromium's own answer); returns
# [vertex ok, fragment ok, linked, log] per program, the log being the stages' logs
# (named) and then the program's.
_LINK_SCRIPT = r"""
(function(jobs) {
""" + _CONTEXT_FUNCTION + r"""
  const out = [];
  for (const job of jobs) {
    const gl = context(job.context, job.extensions);
    const program = gl && gl.createProgram();
    if (!program) { out.push([null, null, null, "no context"]); continue; }
    const logs = [];
    const compile = (type, name, source) => {
      const shader = gl.createShader(type);
      gl.shaderSource(shader, source);
      gl.compileShader(shader);
      const log = (gl.getShaderInfoLog(shader) || "").trim();
      if (log) logs.push(name + ": " + log);
      gl.attachShader(program, shader);
      return [shader, gl.getShaderParameter(shader, gl.COMPILE_STATUS) === true];
    };
    const [vs, vOk] = compile(gl.VERTEX_SHADER, "vertex", job.vertex);
    const [fs, fOk] = compile(gl.FRAGMENT_SHADER, "fragment", job.fragment);
    gl.linkProgram(program);
    const linked = gl.getProgramParameter(program, gl.LINK_STATUS) === true;
    const log = (gl.getProgramInfoLog(program) || "").trim();
    if (log) logs.push(log);
    gl.deleteProgram(program);
    gl.deleteShader(vs);
    gl.deleteShader(fs);
    if (gl.isContextLost()) { out.push([null, null, null, "context lost"]); continue; }
    out.push([vOk, fOk, linked, logs.join("\n")]);
  }
  return out;
})
"""


class BrowserCompiler:
    """Compiles stages (and links programs) in headless Chromium. A job is
    {source, stage, context}: stage "vertex" or "fragment", context 1 (WebGL1) or 2
    (WebGL2)."""

    def __init__(self, chromium=None, batch=200):
        self.chromium = chromium or find_chromium()
        self.batch = batch
        self.work = tempfile.mkdtemp(prefix="sp-browser-compile-")
        self.browser = None
        self.version = None

    def _start(self):
        self.browser = cdp_pipe.Browser(self.chromium, self.work)
        self.browser.open("about:blank")
        self.version = self.browser.evaluate("navigator.userAgent")

    def _restart(self):
        if self.browser:
            try:
                self.browser.close()
            except OSError:
                pass
        self.browser = None
        self._start()

    def _run(self, jobs, script=_COMPILE_SCRIPT):
        expression = "%s(%s)" % (script, json.dumps(jobs))
        return self.browser.evaluate(expression)

    def compile(self, jobs):
        """[(ok, log)] in job order; ok is None when Chromium could not answer."""
        if self.browser is None:
            self._start()
        results = []
        for start in range(0, len(jobs), self.batch):
            part = [{"source": j["source"], "stage": j["stage"], "context": j["context"],
                     "extensions": extensions_of(j["source"])}
                    for j in jobs[start:start + self.batch]]
            results.extend(self._compile_part(part))
        return [(r[0], r[1]) for r in results]

    def link(self, programs):
        """[(vertex_ok, fragment_ok, link_ok, log)] in program order for programs
        {vertex, fragment, context}: both stages compiled in one context of that version
        (with the extensions either names), attached and linked; None where Chromium
        could not answer."""
        if self.browser is None:
            self._start()
        results = []
        for start in range(0, len(programs), self.batch):
            part = [{"vertex": p["vertex"], "fragment": p["fragment"], "context": p["context"],
                     "extensions": sorted(set(extensions_of(p["vertex"]) +
                                              extensions_of(p["fragment"])))}
                    for p in programs[start:start + self.batch]]
            results.extend(self._compile_part(part, _LINK_SCRIPT))
        # A failure row is [None, message]: widen it to the program's four fields.
        return [tuple(r) if len(r) == 4 else (None, None, None, r[-1]) for r in results]

    def _compile_part(self, part, script=_COMPILE_SCRIPT):
        try:
            answer = self._run(part, script)
            if answer is not None and len(answer) == len(part) and \
                    all(r[0] is not None for r in answer):
                return answer
        except (TimeoutError, EOFError, RuntimeError):
            self._restart()
        if len(part) == 1:  # one job that kills the page or the context on its own
            try:
                answer = self._run(part, script)
                if answer and answer[0][0] is not None:
                    return answer
            except (TimeoutError, EOFError, RuntimeError) as error:
                self._restart()
                return [[None, "chromium failed: %s" % error]]
            return [[None, "chromium failed: context lost"]]
        half = len(part) // 2
        return self._compile_part(part[:half], script) + \
            self._compile_part(part[half:], script)

    def close(self):
        if self.browser:
            self.browser.close()
            self.browser = None
        shutil.rmtree(self.work, ignore_errors=True)


def find_chromium(explicit=None):
    for candidate in [explicit, os.environ.get("CHROMIUM"), "chromium", "chromium-browser"]:
        if candidate and shutil.which(candidate):
            return shutil.which(candidate)
    raise SystemExit("chromium not found: install the Debian package `chromium` or pass --chromium")


if __name__ == "__main__":  # compile files given on the command line: STAGE CONTEXT FILE...
    import sys
    stage, context = sys.argv[1], int(sys.argv[2])
    compiler = BrowserCompiler()
    try:
        jobs = [{"source": open(p, encoding="utf-8", errors="surrogateescape").read(),
                 "stage": stage, "context": context} for p in sys.argv[3:]]
        for path, (ok, log) in zip(sys.argv[3:], compiler.compile(jobs)):
            print("%s: %s %s" % (path, {True: "ok", False: "error", None: "failed"}[ok],
                                 log.strip()))
        print("chromium:", compiler.version)
    finally:
        compiler.close()
