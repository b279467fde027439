#!/usr/bin/env python3
"""Extracts the shader cases of WebGL conformance pages (KhronosGroup/WebGL, sdk/tests)
as headless Chromium runs them, in the format of ../shared/conformance/webgl-cts.jsonl.

The sdk/tests tree of one commit is exported (git archive) to a temporary directory and
served by a local http.server on 127.0.0.1. Every page under conformance/glsl/ (WebGL 1)
and conformance2/glsl3/ (WebGL 2), or those matching --pages, is loaded in one headless
Chromium (ANGLE on SwiftShader, over the DevTools pipe of cdp_pipe.py), one page at a time.

How a case is observed: the suite's harness, js/glsl-conformance-test.js, compiles every
case in its closure function runOneTest(gl, info). In the served copy (never in the
repository) three observer calls are added to that file and nothing else changes:
runOneTest is renamed runOneTest__sp and a new runOneTest calls window.__spHarness.begin,
then runOneTest__sp, then (finally) window.__spHarness.end; and right after the lines that
compute `vSource` and `fSource` (default shaders chosen, the GLSL ES 3.00 default picked,
vShaderPrep/fShaderPrep applied) those two strings are handed to the observer. So the
sources recorded are the very strings the harness passes to wtu.loadShader. The observer
itself is injected before any page script with Page.addScriptToEvaluateOnNewDocument; it
also wraps shaderSource on WebGLRenderingContext and WebGL2RenderingContext, to note
whether the harness really passed each recorded source to the GL during that case (it
does not when the harness reuses an identical shader it compiled for an earlier case),
and getExtension on both, to keep per context the WebGL extensions the page enabled.

Once the harness has chosen its vertex source, and before it compiles anything, the
observer compiles both sources itself in the same context (the page's own extensions
enabled, nothing else; the fragment source by the harness's own expression, checked
against the harness's `fSource` later), binds vPosition/texCoord0 as the harness does and
links, to record Chromium's verdict and logs, and the GLSL #extension names that the
WebGL extensions enabled on that context by then turn on (`extensions`, from
browser_compile.WEBGL_EXTENSIONS). (Compiled after the harness, an identical
text can come back from Chromium's cache with an empty info log.) It also counts the
testPassed/testFailed calls the harness made for the case.

Python 3 standard library only.

  conformance_pages.py --exclude-shared /work/shared/conformance/webgl-cts.jsonl \
      -o /tmp/heldout-conf/cases.jsonl
  conformance_pages.py --pages 'conformance2/glsl3/array-*.html' -o /tmp/some.jsonl
"""
import argparse
import fnmatch
import functools
import http.server
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cdp_pipe  # noqa: E402
from browser_compile import WEBGL_EXTENSIONS, find_chromium  # noqa: E402

DEFAULT_REPO = "/work/.mirror/KhronosGroup+WebGL/repo"
DEFAULT_COMMIT = "f15a73f727d8ee66a3ec6d0bed9f02f08cacc2c1"
FOLDERS = ("conformance/glsl/", "conformance2/glsl3/")
HARNESS = "js/glsl-conformance-test.js"

# (text in the harness, text it becomes): observer calls only.
_PATCHES = [
    ("function runOneTest(gl, info) {",
     "function runOneTest(gl, info) {\n"
     "  window.__spHarness.begin(gl, info);\n"
     "  try { return runOneTest__sp(gl, info); } finally { window.__spHarness.end(gl, info); }\n"
     "}\n"
     "function runOneTest__sp(gl, info) {"),
    ("  var vSource = info.vShaderPrep ? info.vShaderPrep(info.vShaderSource) :\n"
     "    info.vShaderSource;\n",
     "  var vSource = info.vShaderPrep ? info.vShaderPrep(info.vShaderSource) :\n"
     "    info.vShaderSource;\n"
     "  window.__spHarness.vertex(vSource, vIsDefault, fIsDefault, info);\n"),
    ("  var fSource = info.fShaderPrep ? info.fShaderPrep(info.fShaderSource) :\n"
     "    info.fShaderSource;\n",
     "  var fSource = info.fShaderPrep ? info.fShaderPrep(info.fShaderSource) :\n"
     "    info.fShaderSource;\n"
     "  window.__spHarness.fragment(fSource);\n"),
]


def _glsl_names():
    """{WebGL extension name in lower case: [GLSL #extension names it enables]}."""
    names = {}
    for glsl, webgl in WEBGL_EXTENSIONS.items():
        names.setdefault(webgl.lower(), []).append(glsl)
    return {webgl: sorted(glsl) for webgl, glsl in names.items()}


# Runs in every document before its own scripts.
_OBSERVER = r"""
(function() {
  if (window.__spHarness) return;
  const state = {cases: [], current: null, harnessLoaded: false, errors: []};
  const glslNames = __SP_GLSL_NAMES__;
  const enabled = new WeakMap();  // context -> Set of the WebGL extensions it returned
  window.addEventListener("error", e => {
    if (state.errors.length < 5) state.errors.push(String(e.message));
  });
  for (const proto of [window.WebGLRenderingContext, window.WebGL2RenderingContext]) {
    if (!proto) continue;
    const original = proto.prototype.shaderSource;
    proto.prototype.shaderSource = function(shader, source) {
      if (state.current && !state.verdict) state.current.passed.push(String(source));
      return original.call(this, shader, source);
    };
    const getExtension = proto.prototype.getExtension;
    proto.prototype.getExtension = function(name) {
      const result = getExtension.apply(this, arguments);
      if (result !== null && result !== undefined) {
        // Names match case-insensitively: keep the one the context lists.
        const wanted = String(name).toLowerCase();
        const listed = (this.getSupportedExtensions() || []).find(n => n.toLowerCase() === wanted);
        if (!enabled.has(this)) enabled.set(this, new Set());
        enabled.get(this).add(listed || String(name));
      }
      return result;
    };
  }
  // The GLSL #extension names the page has turned on in `gl` so far, sorted.
  function glslExtensions(gl) {
    const out = new Set();
    for (const name of (gl && enabled.get(gl)) || []) {
      for (const glsl of glslNames[name.toLowerCase()] || []) out.add(glsl);
    }
    return Array.from(out).sort();
  }
  function expectation(value) {
    return value === undefined || value === null ? null : !!value;
  }
  function wrapResults() {
    if (window.__spWrappedResults || typeof window.reportTestResultsToHarness !== "function") return;
    const original = window.reportTestResultsToHarness;
    window.reportTestResultsToHarness = function(success, msg) {
      const c = state.current;
      if (c) {
        if (success) c.harness.pass++; else {
          c.harness.fail++;
          if (c.harness.failMsgs.length < 3) c.harness.failMsgs.push(String(msg));
        }
      }
      return original.apply(this, arguments);
    };
    window.__spWrappedResults = true;
  }
  function verdict(gl, vSource, fSource) {
    const out = {vCompiled: null, fCompiled: null, linked: null, vLog: "", fLog: "", linkLog: ""};
    if (!gl || gl.isContextLost()) { out.error = "context lost"; return out; }
    const compile = (type, source) => {
      const shader = gl.createShader(type);
      gl.shaderSource(shader, source);
      gl.compileShader(shader);
      return [shader, gl.getShaderParameter(shader, gl.COMPILE_STATUS) === true,
              gl.getShaderInfoLog(shader) || ""];
    };
    const [vs, vOk, vLog] = compile(gl.VERTEX_SHADER, vSource);
    const [fs, fOk, fLog] = compile(gl.FRAGMENT_SHADER, fSource);
    Object.assign(out, {vCompiled: vOk, fCompiled: fOk, vLog: vLog, fLog: fLog});
    if (vOk && fOk) {
      const program = gl.createProgram();
      gl.attachShader(program, vs);
      gl.attachShader(program, fs);
      if (vSource.indexOf("vPosition") >= 0) gl.bindAttribLocation(program, 0, "vPosition");
      if (vSource.indexOf("texCoord0") >= 0) gl.bindAttribLocation(program, 1, "texCoord0");
      gl.linkProgram(program);
      out.linked = gl.getProgramParameter(program, gl.LINK_STATUS) === true;
      out.linkLog = gl.getProgramInfoLog(program) || "";
      gl.deleteProgram(program);
    }
    gl.deleteShader(vs);
    gl.deleteShader(fs);
    if (gl.isContextLost()) out.error = "context lost";
    return out;
  }
  function safeVerdict(gl, vSource, fSource) {
    state.verdict = true;
    try {
      return verdict(gl, vSource, fSource);
    } catch (e) {
      return {vCompiled: null, fCompiled: null, linked: null, vLog: "", fLog: "", linkLog: "",
              error: String(e)};
    } finally {
      state.verdict = false;
    }
  }
  window.__spHarness = {
    state: state,
    begin(gl, info) {
      state.harnessLoaded = true;
      wrapResults();
      state.current = {gl: gl, passed: [], harness: {pass: 0, fail: 0, failMsgs: []},
                       fragmentByHarness: false,
                       passMsg: info.passMsg === undefined ? null : String(info.passMsg),
                       vertex: null, fragment: null};
    },
    vertex(vSource, vIsDefault, fIsDefault, info) {
      const c = state.current;
      if (!c) return;
      c.vertex = vSource;
      c.vIsDefault = vIsDefault;
      c.fIsDefault = fIsDefault;
      c.expected = {vShaderSuccess: expectation(info.vShaderSuccess),
                    fShaderSuccess: expectation(info.fShaderSuccess),
                    linkSuccess: expectation(info.linkSuccess)};
      c.render = !!info.render;
      c.ignoreResults = !!info.ignoreResults;
      c.hasVShaderTest = !!info.vShaderTest;
      c.hasFShaderTest = !!info.fShaderTest;
      c.usesPrep = !!(info.vShaderPrep || info.fShaderPrep);
      // The fragment source the harness is about to compute (its own expression), so that
      // Chromium's verdict is taken before the harness compiles anything: a second compile
      // of the same text can come from a cache and lose the info log's warnings.
      c.fragment = info.fShaderPrep ? info.fShaderPrep(info.fShaderSource) : info.fShaderSource;
      c.pageContextVersion = (window.WebGL2RenderingContext &&
                              c.gl instanceof WebGL2RenderingContext) ? 2 : 1;
      c.chromium = safeVerdict(c.gl, c.vertex, c.fragment);
      c.extensions = glslExtensions(c.gl);  // those Chromium compiled with
    },
    fragment(fSource) {
      const c = state.current;
      if (!c || c.vertex === null) return;
      c.fragmentByHarness = true;
      if (fSource !== c.fragment) {  // a prep that is not a pure function: take the real one
        c.fragmentPrepDiffered = true;
        c.fragment = fSource;
        c.chromium = safeVerdict(c.gl, c.vertex, c.fragment);
        c.extensions = glslExtensions(c.gl);
      }
    },
    end(gl, info) {
      const c = state.current;
      state.current = null;
      if (!c || c.vertex === null) return;  // the harness gave up before choosing its shaders
      c.vPassedToGL = c.passed.indexOf(c.vertex) >= 0;
      c.fPassedToGL = c.passed.indexOf(c.fragment) >= 0;
      delete c.passed;
      delete c.gl;
      state.cases.push(c);
    },
  };
})();
""".replace("__SP_GLSL_NAMES__", json.dumps(_glsl_names(), sort_keys=True))

# The limits that pages sizing their shaders from the context read.
_LIMITS = r"""
(function() {
  const out = {};
  for (const version of [1, 2]) {
    const gl = document.createElement("canvas").getContext(version === 2 ? "webgl2" : "webgl");
    if (!gl) continue;
    const limits = {};
    for (const name of ["MAX_VERTEX_UNIFORM_VECTORS", "MAX_FRAGMENT_UNIFORM_VECTORS",
                        "MAX_VARYING_VECTORS", "MAX_VERTEX_ATTRIBS", "MAX_TEXTURE_IMAGE_UNITS",
                        "MAX_VERTEX_TEXTURE_IMAGE_UNITS"]) {
      limits[name] = gl.getParameter(gl[name]);
    }
    out["webgl" + version] = limits;
    const lose = gl.getExtension("WEBGL_lose_context");
    if (lose) lose.loseContext();
  }
  return out;
})()
"""

_POLL = r"""
JSON.stringify({
  ready: document.readyState,
  finished: !!window._didNotifyFinishedToHarness,
  harness: typeof GLSLConformanceTester !== "undefined",
  count: window.__spHarness ? window.__spHarness.state.cases.length : -1,
  running: !!(window.__spHarness && window.__spHarness.state.current),
})
"""


def export_tree(repo, commit, into):
    """git archive of sdk/tests at `commit` into `into`; returns the tests root."""
    # A partial mirror makes git print "invalid object" for blobs outside sdk/tests
    # while still archiving sdk/tests completely: its messages are shown only on failure.
    with tempfile.TemporaryFile() as errors:
        archive = subprocess.Popen(["git", "-C", repo, "archive", commit, "sdk/tests"],
                                   stdout=subprocess.PIPE, stderr=errors)
        subprocess.run(["tar", "-x", "-C", into], stdin=archive.stdout, check=True)
        archive.stdout.close()
        if archive.wait() != 0:
            errors.seek(0)
            raise SystemExit("git archive failed: " + errors.read().decode(errors="replace"))
    root = os.path.join(into, "sdk", "tests")
    harness = os.path.join(root, HARNESS)
    with open(harness, encoding="utf-8") as f:
        text = f.read()
    for old, new in _PATCHES:
        if text.count(old) != 1:
            raise SystemExit("%s at %s does not have the expected text: %r" % (HARNESS, commit, old))
        text = text.replace(old, new)
    with open(harness, "w", encoding="utf-8") as f:
        f.write(text)
    return root


def pages_of(repo, commit, pattern):
    names = subprocess.run(["git", "-C", repo, "ls-tree", "-r", "--name-only", commit,
                            "sdk/tests/" + FOLDERS[0], "sdk/tests/" + FOLDERS[1]],
                           capture_output=True, text=True, check=True).stdout.split("\n")
    pages = sorted(n[len("sdk/tests/"):] for n in names if n.endswith(".html"))
    if pattern:
        pages = [p for p in pages if fnmatch.fnmatch(p, pattern)]
    return pages


def test_lists(root):
    """{page: {listed, minVersion, maxVersion}} from the 00_test_list.txt files reachable
    from conformance/00_test_list.txt and conformance2/00_test_list.txt: the versions on
    the page's line, else those of the nearest list line above it that has them (the
    top-level `--min-version 2.0.0 conformance2/00_test_list.txt` is not counted, as in
    webgl-cts.jsonl)."""
    found = {}

    def walk(relative, inherited=None):
        inherited = inherited or {}
        path = os.path.join(root, relative)
        if not os.path.exists(path):
            return
        base = os.path.dirname(relative)
        with open(path, encoding="utf-8") as f:
            for line in f:
                line = line.strip()
                if not line or line.startswith("#") or line.startswith("//"):
                    continue
                words = line.split()
                options = {}
                while len(words) >= 2 and words[0].startswith("--"):
                    options[words[0]] = words[1]
                    words = words[2:]
                if not words:
                    continue
                name = os.path.normpath(os.path.join(base, words[0]))
                merged = dict(inherited, **options)
                if name.endswith(".txt"):
                    walk(name, merged)
                else:
                    found[name] = {"listed": True, "minVersion": merged.get("--min-version"),
                                   "maxVersion": merged.get("--max-version")}

    walk("conformance/00_test_list.txt")
    walk("conformance2/00_test_list.txt")
    return found


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(root):
    handler = functools.partial(_QuietHandler, directory=root)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


class PageRunner:
    def __init__(self, chromium, work):
        self.chromium = chromium
        self.work = work
        self.browser = None
        self.version = None
        self.limits = None

    def start(self):
        self.browser = cdp_pipe.Browser(self.chromium, self.work)
        self.browser.open("about:blank")
        self.version = self.browser.send("Browser.getVersion").get("product")
        self.limits = self.browser.evaluate(_LIMITS)
        self.browser.session = None

    def restart(self):
        self.stop()
        self.start()

    def stop(self):
        if self.browser:
            try:
                self.browser.close()
            except OSError:
                pass
            self.browser = None

    def run(self, url, timeout, idle):
        """(status, cases, details): status ok | timeout | error."""
        if self.browser is None:
            self.start()
        b = self.browser
        b.session = None
        target = b.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        b.session = b.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        deadline = time.time() + timeout
        try:
            b.send("Page.enable")
            b.send("Page.addScriptToEvaluateOnNewDocument", {"source": _OBSERVER})
            b.send("Page.navigate", {"url": url})
            last_count, last_change, info = -2, time.time(), {}
            while True:
                left = deadline - time.time()
                if left <= 0:
                    raise TimeoutError("page")
                result = b.send("Runtime.evaluate", {"expression": _POLL, "returnByValue": True},
                                timeout=max(1.0, left))
                value = result.get("result", {}).get("value")
                if value:
                    info = json.loads(value)
                    if info["count"] != last_count:
                        last_count, last_change = info["count"], time.time()
                    if info["ready"] == "complete" and not info["running"]:
                        if info["finished"]:
                            break
                        if time.time() - last_change > idle:  # never finishes: idle is done
                            info["idle"] = True
                            break
                time.sleep(0.2)
            left = max(1.0, deadline - time.time())
            dump = b.send("Runtime.evaluate", {
                "expression": "JSON.stringify({cases: window.__spHarness.state.cases, "
                              "errors: window.__spHarness.state.errors})",
                "returnByValue": True}, timeout=left)
            data = json.loads(dump["result"]["value"])
            b.session = None
            b.send("Target.closeTarget", {"targetId": target}, timeout=20)
            return "ok", data["cases"], {"harness": info.get("harness"),
                                         "finished": info.get("finished"),
                                         "idle": info.get("idle", False),
                                         "errors": data["errors"]}
        except (TimeoutError, EOFError, RuntimeError, KeyError, TypeError, ValueError) as error:
            self.restart()
            status = "timeout" if isinstance(error, TimeoutError) else "error"
            return status, [], {"error": "%s: %s" % (type(error).__name__, error)}


def agreement(expected, chromium):
    """strict: Chromium's compile and link results equal the expectations exactly;
    harness: Chromium passes the case under the harness's own checks."""
    v, f, linked = chromium.get("vCompiled"), chromium.get("fCompiled"), chromium.get("linked")
    if v is None or f is None:
        return {"strict": None, "harness": None}
    link_outcome = bool(v and f and linked)
    strict = True
    for key, actual in (("vShaderSuccess", v), ("fShaderSuccess", f), ("linkSuccess", link_outcome)):
        if expected.get(key) is not None and expected[key] != actual:
            strict = False
    harness = True
    if expected.get("vShaderSuccess") and not v:
        harness = False
    if expected.get("fShaderSuccess") and not f:
        harness = False
    if v and f:
        if linked != expected.get("linkSuccess"):  # `linked != info.linkSuccess`
            harness = False
    elif expected.get("linkSuccess"):
        harness = False
    return {"strict": strict, "harness": harness}


def to_record(page, index, case, lists):
    context = 2 if page.startswith("conformance2/") else 1
    expected = case.get("expected") or {"vShaderSuccess": None, "fShaderSuccess": None,
                                        "linkSuccess": None}
    chromium = case["chromium"]
    record = {
        "id": "%s#%d" % (page, index), "file": page, "index": index,
        "folder": os.path.dirname(page), "passMsg": case.get("passMsg"),
        "contextVersion": context, "pageContextVersion": case.get("pageContextVersion"),
        "vertex": case["vertex"], "fragment": case["fragment"],
        "vIsDefault": case.get("vIsDefault"), "fIsDefault": case.get("fIsDefault"),
        "expected": expected, "render": case.get("render"),
        "ignoreResults": case.get("ignoreResults"), "hasVShaderTest": case.get("hasVShaderTest"),
        "hasFShaderTest": case.get("hasFShaderTest"), "usesPrep": case.get("usesPrep"),
        "chromium": chromium, "harness": case.get("harness"),
        "testList": lists.get(page, {"listed": False, "minVersion": None, "maxVersion": None}),
        "agree": agreement(expected, chromium),
        # not in webgl-cts.jsonl: whether the harness itself passed each source to
        # gl.shaderSource in this case (false: it reused an identical compiled shader) and
        # whether it got as far as the fragment stage.
        "capture": {"vPassedToGL": case.get("vPassedToGL"), "fPassedToGL": case.get("fPassedToGL"),
                    "fragmentByHarness": case.get("fragmentByHarness"),
                    "fragmentPrepDiffered": case.get("fragmentPrepDiffered", False)},
        # not in webgl-cts.jsonl: the GLSL #extension names turned on by the WebGL extensions
        # the page had enabled on its context when Chromium compiled the case (getExtension
        # returned an object), sorted; for `check --enabled-extensions`.
        "extensions": case.get("extensions", []),
    }
    return record


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--webgl-repo", default=DEFAULT_REPO, help="a KhronosGroup/WebGL clone "
                        "or bare mirror (default %(default)s)")
    parser.add_argument("--commit", default=DEFAULT_COMMIT,
                        help="commit to export (default %(default)s; HEAD when absent)")
    parser.add_argument("--exclude-shared", metavar="PATH",
                        help="skip the pages whose `file` appears in this JSONL")
    parser.add_argument("--pages", metavar="GLOB", help="only pages matching this glob "
                        "(relative to sdk/tests, e.g. 'conformance2/glsl3/*')")
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds per page")
    parser.add_argument("--idle", type=float, default=8.0,
                        help="a loaded page that never calls finishTest is done after this "
                             "many seconds without a new case")
    parser.add_argument("--chromium")
    parser.add_argument("-o", "--out", required=True, help="output JSONL")
    args = parser.parse_args(argv)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # run `finally`: kill Chromium

    commit = args.commit
    known = subprocess.run(["git", "-C", args.webgl_repo, "cat-file", "-t", commit],
                           capture_output=True, text=True).stdout.strip() == "commit"
    if not known:
        commit = subprocess.run(["git", "-C", args.webgl_repo, "rev-parse", "HEAD"],
                                capture_output=True, text=True, check=True).stdout.strip()
        print("commit %s not in %s: using HEAD %s" % (args.commit, args.webgl_repo, commit))
    pages = pages_of(args.webgl_repo, commit, args.pages)
    if args.exclude_shared:
        with open(args.exclude_shared, encoding="utf-8") as f:
            shared = {json.loads(line)["file"] for line in f if line.strip()}
        pages = [p for p in pages if p not in shared]
    print("commit %s: %d pages" % (commit, len(pages)), flush=True)

    work = tempfile.mkdtemp(prefix="sp-conformance-pages-")
    server = None
    runner = PageRunner(find_chromium(args.chromium), work)
    summary = {"commit": commit, "pages": {}}
    try:
        root = export_tree(args.webgl_repo, commit, work)
        lists = test_lists(root)
        server = serve(root)
        base = "http://127.0.0.1:%d/" % server.server_address[1]
        runner.start()
        summary["chromium"] = runner.version
        summary["limits"] = runner.limits
        print("%s; limits %s" % (runner.version, json.dumps(runner.limits)), flush=True)
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        total = 0
        with open(args.out, "w", encoding="utf-8") as out:
            for number, page in enumerate(pages, 1):
                started = time.time()
                status, cases, details = runner.run(base + page, args.timeout, args.idle)
                for index, case in enumerate(cases):
                    out.write(json.dumps(to_record(page, index, case, lists)) + "\n")
                out.flush()
                total += len(cases)
                details.update({"status": status, "cases": len(cases),
                                "seconds": round(time.time() - started, 1)})
                summary["pages"][page] = details
                print("[%d/%d] %s: %s, %d cases (%.1f s)" % (number, len(pages), page, status,
                                                             len(cases), time.time() - started),
                      flush=True)
        summary["cases"] = total
        with open(args.out + ".pages.json", "w", encoding="utf-8") as f:
            json.dump(summary, f, indent=1, sort_keys=True)
        print("%d cases from %d pages; page statuses in %s.pages.json" % (
            total, sum(1 for d in summary["pages"].values() if d["cases"]), args.out))
    finally:
        runner.stop()
        if server:
            server.shutdown()
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
