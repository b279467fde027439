#!/usr/bin/env python3
"""Drives `shaderport lsp` over its standard input and output as an editor does.

Asserts: the handshake; diagnostics on open and after full and incremental
changes; that for every file of the corpus the published diagnostics equal
`check --format json`'s (rule id, severity, range); quick fixes whose edits
repair the finding; "fix all" equal to `shaderport fix`; errors for a malformed
message, an unknown method and a request before initialize; a clean exit after
shutdown and exit 1 when the client goes away.

  lsp_session_test.py SHADERPORT SOURCE_DIR SCRATCH_DIR [SHARED_DIR]

With SHARED_DIR, the same equality is proven for every pass of the shared ShaderToy
shaders (SHARED_DIR/corpus-shadertoy/permissive.jsonl), projects as folders.
"""
import json
import os
import shutil
import subprocess
import sys

BINARY, SOURCE, SCRATCH = (os.path.abspath(a) for a in sys.argv[1:4])
SHARED = os.path.abspath(sys.argv[4]) if len(sys.argv) > 4 else None
REPAIRABLE = ("void mainImage(out vec4 fragColor, in vec2 fragCoord)\n{\n"
              "    float t = iGlobalTime * 1;\n    vec3 c = 0.5;\n"
              "    fragColor = vec4(c * t, 1.0);\n}\n")


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


class Client:
    def __init__(self):
        self.process = subprocess.Popen([BINARY, "lsp"], stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, cwd=SCRATCH)
        self.next_id = 0
        self.logs = []
        self.statuses = []
        # Messages read while waiting for a response: checks run on the server's own
        # thread, so their diagnostics may come before or after a response.
        self.waiting = []

    def send_raw(self, body):
        self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.process.stdin.flush()

    def send(self, method, params=None, request=True):
        message = {"jsonrpc": "2.0", "method": method}
        if params is not None:
            message["params"] = params
        if request:
            self.next_id += 1
            message["id"] = self.next_id
        self.send_raw(json.dumps(message).encode())
        return message.get("id")

    def receive(self):
        if self.waiting:
            return self.waiting.pop(0)
        return self.read()

    def read(self):
        length = None
        while True:
            line = self.process.stdout.readline()
            if not line:
                fail("the server closed its output")
            line = line.strip()
            if not line:
                break
            name, _, value = line.decode().partition(":")
            if name.lower() == "content-length":
                length = int(value)
        return json.loads(self.process.stdout.read(length))

    def request(self, method, params=None):
        return self.response_to(self.send(method, params))

    def response_to(self, wanted):
        for index, message in enumerate(self.waiting):
            if message.get("id") == wanted and "method" not in message:
                return self.waiting.pop(index)
        while True:
            message = self.read()
            if message.get("id") == wanted and "method" not in message:
                return message
            self.waiting.append(message)

    def diagnostics_for(self, wanted):
        """The next diagnostics published for `wanted` (others are passed over)."""
        while True:
            params = self.diagnostics()
            if params["uri"] == wanted:
                return params

    def diagnostics(self):
        while True:
            message = self.receive()
            if message.get("method") == "window/logMessage":
                self.logs.append(message["params"]["message"])
            if message.get("method") == "shaderport/status":
                self.statuses.append(message["params"])
            if message.get("method") == "textDocument/publishDiagnostics":
                return message["params"]


def uri(path):
    return "file://" + os.path.abspath(path)


def apply(text, edits):
    lines = text.split("\n")
    starts = [0]
    for line in lines[:-1]:
        starts.append(starts[-1] + len(line) + 1)

    def offset(position):  # ASCII texts: a UTF-16 unit is a byte
        return starts[position["line"]] + position["character"]

    for edit in sorted(edits, key=lambda e: offset(e["range"]["start"]), reverse=True):
        text = text[:offset(edit["range"]["start"])] + edit["newText"] + text[offset(edit["range"]["end"]):]
    return text


def hover_on(client, path, name):
    """Hover on the first use of `name` in a document opened just for it."""
    text = "void mainImage(out vec4 o, in vec2 p) { o = vec4(p / %s.xy, 0.0, 1.0); }\n" % name
    other = os.path.join(SCRATCH, "hover.glsl")
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": uri(other), "languageId": "glsl", "version": 1, "text": text}}, request=False)
    client.diagnostics()
    result = client.request("textDocument/hover", {"textDocument": {"uri": uri(other)},
                                                   "position": {"line": 0, "character": text.index(name) + 1}})
    client.send("textDocument/didClose", {"textDocument": {"uri": uri(other)}}, request=False)
    client.diagnostics()
    return (result["result"] or {}).get("contents", {}).get("value", "")


def check_json(path):
    done = subprocess.run([BINARY, "check", "--format", "json", "--no-cache", path],
                          capture_output=True, text=True, cwd=SCRATCH)
    return json.loads(done.stdout)


def expected_of(path):
    """check's findings in LSP terms (0-based; the corpus is ASCII)."""
    out = []
    for entry in check_json(path)["files"]:
        for d in entry["diagnostics"]:
            location = d["location"]
            if location and os.path.abspath(os.path.join(SCRATCH, location["path"])) != os.path.abspath(path):
                continue
            if location:
                r = location["range"]
                rng = ((r["start"]["line"] - 1, r["start"]["column"] - 1),
                       (r["end"]["line"] - 1, r["end"]["column"] - 1))
            else:
                rng = ((0, 0), (0, 0))
            out.append((d["rule"], {"error": 1, "warning": 2, "note": 3}[d["severity"]], rng))
    return sorted(out)


def expected_of_target(path, target):
    done = subprocess.run([BINARY, "check", "--format", "json", "--no-cache", "--target", target,
                           path], capture_output=True, text=True, cwd=SCRATCH)
    out = []
    for entry in json.loads(done.stdout)["files"]:
        for d in entry["diagnostics"]:
            r = d["location"]["range"]
            out.append((d["rule"], {"error": 1, "warning": 2, "note": 3}[d["severity"]],
                        ((r["start"]["line"] - 1, r["start"]["column"] - 1),
                         (r["end"]["line"] - 1, r["end"]["column"] - 1))))
    return sorted(out)


def published_of(params):
    return sorted((d["code"], d["severity"],
                   ((d["range"]["start"]["line"], d["range"]["start"]["character"]),
                    (d["range"]["end"]["line"], d["range"]["end"]["character"])))
                  for d in params["diagnostics"])


def large_pass(lines):
    """A valid ShaderToy pass of about `lines` lines (its check takes a while)."""
    body = "".join("float f%d(vec3 p) { vec3 q = abs(p) - vec3(0.5); return length(max(q, 0.0)) + %d.0; }\n"
                   % (i, i) for i in range(lines))
    return body + "void mainImage(out vec4 o, in vec2 c) { o = vec4(f0(vec3(c, 1.0))); }\n"


def status_for(client, wanted):
    """The newest shaderport/status of `wanted` (read up to its diagnostics)."""
    client.diagnostics_for(wanted)
    return [s for s in client.statuses if s["uri"] == wanted][-1]


def responsiveness(client, toy):
    """Checks run off the reading thread: stale versions are not published, a queued
    code action can be cancelled, a render on save does not hold up requests."""
    big = os.path.join(SCRATCH, "big.glsl")
    text = large_pass(1500)
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": uri(big), "languageId": "glsl", "version": 1, "text": text}}, request=False)
    client.diagnostics_for(uri(big))
    # A burst of edits: versions are published in order, the last one is published,
    # and edits made while a check ran are checked together (fewer publications).
    for version in range(2, 22):
        client.send("textDocument/didChange", {
            "textDocument": {"uri": uri(big), "version": version},
            "contentChanges": [{"range": {"start": {"line": 0, "character": 0},
                                          "end": {"line": 0, "character": 0}}, "text": " "}]},
            request=False)
    # Requests that need no check are answered while the checks run.
    symbols_id = client.send("textDocument/documentSymbol", {"textDocument": {"uri": uri(toy)}})
    # A code action waits for the checks before it; cancelled, it is answered so.
    action_id = client.send("textDocument/codeAction", {
        "textDocument": {"uri": uri(big)},
        "range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}},
        "context": {"diagnostics": []}})
    client.send("$/cancelRequest", {"id": action_id}, request=False)
    order = []
    versions = []
    while True:
        message = client.receive()
        if message.get("id") in (symbols_id, action_id) and "method" not in message:
            order.append(message)
        elif message.get("method") == "textDocument/publishDiagnostics" and \
                message["params"]["uri"] == uri(big):
            versions.append(message["params"]["version"])
            order.append(message)
        if versions and versions[-1] == 21 and len([m for m in order if "id" in m]) == 2:
            break
    if versions != sorted(versions) or len(versions) >= 20:
        fail("published versions after a burst of 20 edits: %r" % versions)
    symbols_at = next(i for i, m in enumerate(order) if m.get("id") == symbols_id)
    last_publish = max(i for i, m in enumerate(order) if m.get("method"))
    if symbols_at > last_publish:
        fail("documentSymbol waited for every check: %r" % [m.get("method", m.get("id")) for m in order])
    cancelled = next(m for m in order if m.get("id") == action_id)
    if cancelled.get("error", {}).get("code") != -32800:
        fail("a cancelled code action queued behind a check: %r" % cancelled)
    client.send("textDocument/didClose", {"textDocument": {"uri": uri(big)}}, request=False)
    client.diagnostics_for(uri(big))
    print("lsp: 20 edits of a %d-line pass published as versions %r" % (text.count("\n"), versions))

    # Render on save: the picture is checked in the background; requests go on.
    client.send("workspace/didChangeConfiguration",
                {"settings": {"shaderport": {"renderOnSave": True, "failOn": "warning"}}},
                request=False)
    status = status_for(client, uri(toy))
    if status["failOn"] != "warning" or status["rendered"]:
        fail("status after failOn: %r" % status)
    client.send("textDocument/didSave", {"textDocument": {"uri": uri(toy)}}, request=False)
    hover_id = client.send("textDocument/hover", {
        "textDocument": {"uri": uri(toy)}, "position": {"line": 4, "character": 25}})
    first = client.receive()
    while first.get("method") == "window/logMessage":
        first = client.receive()
    if first.get("id") != hover_id:
        fail("a hover waited for the render: %r came first" % first.get("method"))
    rendered = status_for(client, uri(toy))
    if not rendered["rendered"]:
        fail("no rendered status after save: %r" % rendered)
    client.send("workspace/didChangeConfiguration", {"settings": {"shaderport": {}}}, request=False)
    status_for(client, uri(toy))


def position_of(text, needle, skip=0):
    """The LSP position of `needle` (plus `skip` characters) in an ASCII text."""
    at = text.index(needle) + skip
    return {"line": text.count("\n", 0, at), "character": at - (text.rfind("\n", 0, at) + 1)}


def project_navigation(client):
    """Definitions, references, hover and completion across a ShaderToy project's tabs
    (folder form and JSON form); scope-aware completion; expression types on hover."""
    folder = os.path.join(SCRATCH, "project")
    os.makedirs(folder, exist_ok=True)
    common = "float hash(float n) { return fract(sin(n) * 43758.5453); }\nconst float SCALE = 2.0;\n"
    image = ("float helper(float x) { float inner = x; return inner; }\n"
             "void mainImage(out vec4 o, in vec2 p) {\n    float h = hash(p.x * SCALE);\n"
             "    o = vec4(h);\n}\n")
    buffer = "void mainImage(out vec4 o, in vec2 p) { o = vec4(hash(p.y)); }\n"
    for name, text in (("common.glsl", common), ("image.glsl", image), ("buffer-a.glsl", buffer)):
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
    image_uri, common_uri = uri(os.path.join(folder, "image.glsl")), uri(os.path.join(folder, "common.glsl"))
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": image_uri, "languageId": "glsl", "version": 1, "text": image}}, request=False)
    client.diagnostics_for(image_uri)

    def ask(method, at_uri, position, **extra):
        params = {"textDocument": {"uri": at_uri}, "position": position}
        params.update(extra)
        return client.request(method, params)["result"]

    definition = ask("textDocument/definition", image_uri, position_of(image, "hash("))
    if definition != {"uri": common_uri, "range": {"start": {"line": 0, "character": 6},
                                                   "end": {"line": 0, "character": 10}}}:
        fail("definition of hash from image.glsl: %r" % definition)
    hover = ask("textDocument/hover", image_uri, position_of(image, "SCALE"))["contents"]["value"]
    if "const float SCALE" not in hover or "Common" not in hover:
        fail("hover on SCALE: %r" % hover)
    expression = ask("textDocument/hover", image_uri, position_of(image, "p.x", 2))
    if expression is None or "float" not in expression["contents"]["value"] or \
            "p.x" not in expression["contents"]["value"]:
        fail("hover on the x of p.x: %r" % expression)
    items = ask("textDocument/completion", image_uri, position_of(image, "    o = vec4(h)"))["items"]
    labels = {item["label"] for item in items}
    for wanted in ("hash", "SCALE", "helper", "h", "o", "p", "iTime", "texture"):
        if wanted not in labels:
            fail("completion in mainImage lacks %r" % wanted)
    for unwanted in ("inner", "x"):
        if unwanted in labels:
            fail("completion in mainImage offers %r, a name of helper()" % unwanted)
    # From Common: every tab's use is a reference (buffer-a.glsl is not open: read from disk).
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": common_uri, "languageId": "glsl", "version": 1, "text": common}}, request=False)
    client.diagnostics_for(common_uri)
    references = ask("textDocument/references", common_uri, position_of(common, "hash"),
                     context={"includeDeclaration": True})
    got = sorted((os.path.basename(r["uri"]), r["range"]["start"]["line"], r["range"]["start"]["character"])
                 for r in references)
    if got != [("buffer-a.glsl", 0, 49), ("common.glsl", 0, 6), ("image.glsl", 2, 14)]:
        fail("references of hash across the folder: %r" % got)
    for closing in (image_uri, common_uri):
        client.send("textDocument/didClose", {"textDocument": {"uri": closing}}, request=False)
        client.diagnostics_for(closing)

    # The JSON form: positions are in the JSON document; the passes are its strings.
    record = {"id": "navtst", "name": "navigation", "author": "shaderport", "license": "MIT",
              "passes": [{"name": "Common", "type": "common", "code": common},
                         {"name": "Image", "type": "image", "code": image}]}
    document = json.dumps(record, indent=1)
    project = os.path.join(SCRATCH, "navigation.json")
    with open(project, "w") as f:
        f.write(document)
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": uri(project), "languageId": "json", "version": 1, "text": document}}, request=False)
    client.diagnostics_for(uri(project))
    use = document.index("hash(p.x")
    definition = ask("textDocument/definition", uri(project), position_of(document, "hash(p.x"))
    want = position_of(document, "hash(float")
    if definition is None or definition["uri"] != uri(project) or definition["range"]["start"] != want:
        fail("definition of hash in the JSON project: %r (want %r, use at %d)" % (definition, want, use))
    symbols = client.request("textDocument/documentSymbol", {"textDocument": {"uri": uri(project)}})["result"]
    outline = [(s["name"], [c["name"] for c in s.get("children", [])]) for s in symbols]
    if outline != [("Common", ["hash", "SCALE"]), ("Image", ["helper", "mainImage"])]:
        fail("outline of the JSON project: %r" % outline)
    client.send("textDocument/didClose", {"textDocument": {"uri": uri(project)}}, request=False)
    client.diagnostics_for(uri(project))
    print("lsp: definition, references, hover and completion across a project's tabs")


def shared_passes(client):
    """Every shared ShaderToy pass: the server's diagnostics equal check's (one `check
    --format json` over all of them). A single-pass shader is a file; a project is a
    folder with a file per tab (common.glsl beside the passes), as an editor opens it."""
    corpus = os.path.join(SHARED or "", "corpus-shadertoy", "permissive.jsonl")
    if not SHARED or not os.path.exists(corpus):
        return 0
    folder = os.path.join(SCRATCH, "shared")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    texts = {}
    with open(corpus) as f:
        records = [json.loads(line) for line in f if line.strip()]
    for record in records:
        passes = record["passes"]
        for one in passes:
            if len(passes) == 1:
                path = os.path.join(folder, record["id"] + ".glsl")
            else:
                os.makedirs(os.path.join(folder, record["id"]), exist_ok=True)
                name = (one.get("name") or one["type"]).lower().replace(" ", "-")
                path = os.path.join(folder, record["id"], name + ".glsl")
            with open(path, "w", newline="") as out:
                out.write(one["code"])
            texts[path] = one["code"]
    done = subprocess.run([BINARY, "check", "--format", "json", "--no-cache", "-j", "2", folder],
                          capture_output=True, text=True, cwd=SCRATCH)
    expected = {}
    for entry in json.loads(done.stdout)["files"]:
        path = os.path.abspath(os.path.join(SCRATCH, entry["path"]))
        for d in entry["diagnostics"]:
            location = d["location"]
            if location and os.path.abspath(os.path.join(SCRATCH, location["path"])) != path:
                continue
            r = location["range"] if location else None
            rng = ((r["start"]["line"] - 1, r["start"]["column"] - 1),
                   (r["end"]["line"] - 1, r["end"]["column"] - 1)) if r else ((0, 0), (0, 0))
            expected.setdefault(path, []).append(
                (d["rule"], {"error": 1, "warning": 2, "note": 3}[d["severity"]], rng))
    for path, text in sorted(texts.items()):
        client.send("textDocument/didOpen", {"textDocument": {
            "uri": uri(path), "languageId": "glsl", "version": 1, "text": text}}, request=False)
        got = published_of(client.diagnostics_for(uri(path)))
        # Columns count UTF-16 units in the server and bytes in check: compare lines
        # only on lines with other than ASCII text.
        def comparable(items):
            lines = text.split("\n")
            out = []
            for rule, severity, ((l0, c0), (l1, c1)) in items:
                ascii_only = all(ord(ch) < 128 for ch in "".join(lines[l0:l1 + 1]))
                out.append((rule, severity, ((l0, c0), (l1, c1)) if ascii_only else ((l0, -1), (l1, -1))))
            return sorted(out)
        if comparable(got) != comparable(expected.get(path, [])):
            fail("%s:\nserver %r\ncheck  %r" % (path, got, sorted(expected.get(path, []))))
        client.send("textDocument/didClose", {"textDocument": {"uri": uri(path)}}, request=False)
        client.diagnostics_for(uri(path))
    return len(texts)


def main():
    shutil.rmtree(SCRATCH, ignore_errors=True)
    os.makedirs(SCRATCH)
    toy = os.path.join(SCRATCH, "toy.glsl")
    with open(toy, "w") as f:
        f.write(REPAIRABLE)

    client = Client()
    early = client.request("textDocument/codeAction", {})
    if early.get("error", {}).get("code") != -32002:
        fail("a request before initialize: %r" % early)
    init = client.request("initialize", {"processId": None, "rootUri": uri(SCRATCH), "capabilities": {}})
    capabilities = init["result"]["capabilities"]
    if capabilities["textDocumentSync"]["change"] != 2 or "codeActionProvider" not in capabilities:
        fail("capabilities: %r" % capabilities)
    client.send("initialized", {}, request=False)

    # Open: the same findings as check.
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": uri(toy), "languageId": "glsl", "version": 1, "text": REPAIRABLE}}, request=False)
    published = client.diagnostics()
    if published_of(published) != expected_of(toy):
        fail("on open:\n%r\n!=\n%r" % (published_of(published), expected_of(toy)))
    if "toy.glsl is checked as a shadertoy fragment shader, harness shadertoy, target webgl2" \
            not in client.logs:
        fail("the decision was not told: %r" % client.logs)
    status = client.statuses[-1]
    if (status["target"], status["harness"], status["channels"], status["failOn"], status["fails"]) != \
            ("webgl2", "shadertoy", ["2d", "2d", "2d", "2d"], "error", True):
        fail("status on open: %r" % status)
    # iGlobalTime, a name the site renamed: deprecated code (tag 2).
    deprecated = [d for d in published["diagnostics"] if d.get("tags") == [2]]
    if not deprecated or deprecated[0]["range"]["start"] != {"line": 2, "character": 14}:
        fail("iGlobalTime is not tagged deprecated: %r" % published["diagnostics"])
    first = published["diagnostics"][0]
    if not first["codeDescription"]["href"].startswith("https://") or first["source"] != "shaderport":
        fail("diagnostic fields: %r" % first)

    # A quick fix repairs its finding.
    actions = client.request("textDocument/codeAction", {
        "textDocument": {"uri": uri(toy)}, "range": first["range"],
        "context": {"diagnostics": [first]}})["result"]
    quick = [a for a in actions if a["kind"] == "quickfix"]
    if not quick:
        fail("no quick fix for %r: %r" % (first, actions))
    repaired = apply(REPAIRABLE, quick[0]["edit"]["changes"][uri(toy)])
    if "iGlobalTime" in repaired:
        fail("the quick fix left iGlobalTime:\n" + repaired)
    # Fix all is what `shaderport fix` writes.
    fix_all = [a for a in actions if a["kind"] == "source.fixAll.shaderport"]
    fixed = subprocess.run([BINARY, "fix", toy], capture_output=True, text=True).stdout
    if not fix_all or apply(REPAIRABLE, fix_all[0]["edit"]["changes"][uri(toy)]) != fixed:
        fail("fix all differs from shaderport fix: %r" % fix_all)

    # Port to WebGL2 is what `shaderport port` writes.
    port_action = [a for a in actions if a["kind"] == "source.convert.webgl2.shaderport"]
    ported = subprocess.run([BINARY, "port", toy], capture_output=True, text=True).stdout
    if not port_action or apply(REPAIRABLE, port_action[0]["edit"]["changes"][uri(toy)]) != ported:
        fail("port action differs from shaderport port: %r" % port_action)
    if not ported.startswith("#version 300 es"):
        fail("shaderport port wrote %r" % ported[:80])

    # The outline and a definition: 't' in line 5 is declared in line 3.
    symbols = client.request("textDocument/documentSymbol", {"textDocument": {"uri": uri(toy)}})["result"]
    if [(s["name"], s["kind"]) for s in symbols] != [("mainImage", 12)]:
        fail("document symbols: %r" % symbols)
    definition = client.request("textDocument/definition", {
        "textDocument": {"uri": uri(toy)}, "position": {"line": 4, "character": 25}})["result"]
    if definition is None or definition["range"]["start"] != {"line": 2, "character": 10}:
        fail("definition of t: %r" % definition)
    builtin = client.request("textDocument/definition", {
        "textDocument": {"uri": uri(toy)}, "position": {"line": 2, "character": 16}})["result"]
    if builtin is not None:
        fail("iGlobalTime has no declaration in the document: %r" % builtin)

    # Hover: a local's type, a built-in's overloads, what the site provides.
    def hover(line, character):
        result = client.request("textDocument/hover", {
            "textDocument": {"uri": uri(toy)}, "position": {"line": line, "character": character}})
        return (result["result"] or {}).get("contents", {}).get("value", "")
    if "float t" not in hover(4, 25) or "(local)" not in hover(4, 25):
        fail("hover on t: %r" % hover(4, 25))
    if "vec4 vec4" in hover(4, 18) or "fragColor" not in hover(4, 6):
        fail("hover on fragColor: %r" % hover(4, 6))
    if "uniform vec3 iResolution" not in hover_on(client, toy, "iResolution") or \
            "viewport size in pixels" not in hover_on(client, toy, "iResolution"):
        fail("hover on iResolution: %r" % hover_on(client, toy, "iResolution"))
    # A channel is shown with the sampler type the check gave it (a cube map here).
    cube = os.path.join(SCRATCH, "cube.glsl")
    cube_text = ("void mainImage(out vec4 o, in vec2 p) {\n"
                 "    o = texture(iChannel1, normalize(vec3(p, 1.0)));\n}\n")
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": uri(cube), "languageId": "glsl", "version": 1, "text": cube_text}}, request=False)
    client.diagnostics_for(uri(cube))
    channel = client.request("textDocument/hover", {"textDocument": {"uri": uri(cube)},
                                                    "position": position_of(cube_text, "iChannel1", 2)})
    if "uniform samplerCube iChannel1" not in (channel["result"] or {}).get("contents", {}).get("value", ""):
        fail("hover on a cube-map channel: %r" % channel)
    client.send("textDocument/didClose", {"textDocument": {"uri": uri(cube)}}, request=False)
    client.diagnostics_for(uri(cube))

    # References of t: its declaration (asked for) and its one use.
    references = client.request("textDocument/references", {
        "textDocument": {"uri": uri(toy)}, "position": {"line": 4, "character": 25},
        "context": {"includeDeclaration": True}})["result"]
    if sorted((r["range"]["start"]["line"], r["range"]["start"]["character"]) for r in references) \
            != [(2, 10), (4, 25)]:
        fail("references of t: %r" % references)
    # A suppression that silences nothing is unnecessary code (tag 1).
    quiet = os.path.join(SCRATCH, "quiet.frag")
    quiet_text = ("precision mediump float;\n// shaderport-ignore-next-line(glslang/type-mismatch)\n"
                  "void main() { gl_FragColor = vec4(1.0); }\n")
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": uri(quiet), "languageId": "glsl", "version": 1, "text": quiet_text}}, request=False)
    tagged = client.diagnostics()["diagnostics"]
    if [(d["code"], d.get("tags")) for d in tagged] != [("suppression/unused", [1])]:
        fail("unused suppression: %r" % tagged)
    client.send("textDocument/didClose", {"textDocument": {"uri": uri(quiet)}}, request=False)
    client.diagnostics()

    # Completion: the document's names, built-ins of its version, the site's uniforms.
    completion = client.request("textDocument/completion", {
        "textDocument": {"uri": uri(toy)}, "position": {"line": 4, "character": 4}})["result"]
    labels = {item["label"] for item in completion["items"]}
    for wanted in ("mainImage", "fragColor", "t", "c", "texture", "smoothstep", "iTime",
                   "iResolution", "gl_FragCoord"):
        if wanted not in labels:
            fail("completion lacks %r" % wanted)
    if "texture2D" in labels:
        fail("completion offers texture2D in GLSL ES 3.00 code")

    # An incremental change: replace line 3 with the repaired line.
    client.send("textDocument/didChange", {
        "textDocument": {"uri": uri(toy), "version": 2},
        "contentChanges": [{"range": {"start": {"line": 2, "character": 0},
                                      "end": {"line": 3, "character": 17}},
                            "text": "    float t = iTime * 1.0;\n    vec3 c = vec3(0.5);"}]},
        request=False)
    after = client.diagnostics()
    if after["version"] != 2 or after["diagnostics"]:
        fail("after the incremental change: %r" % after)
    # A full change back.
    client.send("textDocument/didChange", {"textDocument": {"uri": uri(toy), "version": 3},
                                           "contentChanges": [{"text": REPAIRABLE}]}, request=False)
    if published_of(client.diagnostics()) != expected_of(toy):
        fail("after the full change")

    responsiveness(client, toy)
    project_navigation(client)

    # Every corpus file: the server and check agree.
    compared = 0
    for folder, _, names in sorted(os.walk(os.path.join(SOURCE, "corpus"))):
        for name in sorted(names):
            if not name.endswith((".glsl", ".frag", ".vert")):
                continue
            path = os.path.join(folder, name)
            text = open(path).read()
            client.send("textDocument/didOpen", {"textDocument": {
                "uri": uri(path), "languageId": "glsl", "version": 1, "text": text}}, request=False)
            got = published_of(client.diagnostics())
            want = expected_of(path)
            if got != want:
                fail("%s:\nserver %r\ncheck  %r" % (path, got, want))
            client.send("textDocument/didClose", {"textDocument": {"uri": uri(path)}}, request=False)
            if client.diagnostics()["diagnostics"]:
                fail("closing did not clear the diagnostics")
            compared += 1
    if compared < 20:
        fail("only %d corpus files" % compared)
    shared = shared_passes(client)
    if SHARED and shared < 900:
        fail("only %d shared ShaderToy passes" % shared)

    # Settings: shaderport.target makes every document checked for that context.
    webgl1 = os.path.join(SCRATCH, "derivative.frag")
    webgl1_text = ("#version 300 es\nprecision highp float;\nout vec4 c;\n"
                   "void main() { c = vec4(1.0); }\n")
    with open(webgl1, "w") as f:
        f.write(webgl1_text)
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": uri(webgl1), "languageId": "glsl", "version": 1, "text": webgl1_text}}, request=False)
    if client.diagnostics()["diagnostics"]:
        fail("a WebGL2 shader has findings for WebGL2")
    client.send("workspace/didChangeConfiguration",
                {"settings": {"shaderport": {"target": "webgl1"}}}, request=False)
    # Every open document is checked again; this one's diagnostics are what counts.
    against_webgl1 = client.diagnostics_for(uri(webgl1))
    want = expected_of_target(webgl1, "webgl1")
    if not against_webgl1["diagnostics"] or published_of(against_webgl1) != want:
        fail("with target webgl1: %r != %r" % (published_of(against_webgl1), want))
    client.send("workspace/didChangeConfiguration", {"settings": {"shaderport": {}}}, request=False)
    back = client.diagnostics_for(uri(webgl1))
    if back["diagnostics"]:
        fail("back to per-file targets: %r" % published_of(back))
    client.send("textDocument/didClose", {"textDocument": {"uri": uri(webgl1)}}, request=False)
    client.diagnostics_for(uri(webgl1))

    # A 20 MB document: check's input limit applies; navigation does not read it.
    huge = os.path.join(SCRATCH, "huge.glsl")
    client.send("textDocument/didOpen", {"textDocument": {
        "uri": uri(huge), "languageId": "glsl", "version": 1, "text": "// x\n" * (4 << 20)}},
        request=False)
    if client.request("textDocument/hover", {"textDocument": {"uri": uri(huge)},
                                             "position": {"line": 3, "character": 1}})["result"] is not None:
        fail("hover in a 20 MB document")
    if [d["code"] for d in client.diagnostics_for(uri(huge))["diagnostics"]] != ["input/too-large"]:
        fail("a 20 MB document is not input/too-large")
    client.send("textDocument/didClose", {"textDocument": {"uri": uri(huge)}}, request=False)
    client.diagnostics_for(uri(huge))

    # Robustness: not JSON, an unknown method, a notification it does not know.
    client.send_raw(b"{not json")
    if client.response_to(None).get("error", {}).get("code") != -32700:
        fail("a malformed message is not a parse error")
    if client.request("shaderport/nothing", {}).get("error", {}).get("code") != -32601:
        fail("an unknown method is not MethodNotFound")
    client.send("$/cancelRequest", {"id": 99}, request=False)
    if client.request("shutdown").get("result", "missing") is not None:
        fail("shutdown")
    client.send("exit", request=False)
    if client.process.wait(timeout=30) != 0:
        fail("exit after shutdown is not 0")

    gone = Client()
    gone.request("initialize", {"capabilities": {}})
    gone.process.stdin.close()
    if gone.process.wait(timeout=30) != 1:
        fail("a client that goes away: exit is not 1")
    print("lsp: handshake, diagnostics equal check's on %d corpus files and %d shared ShaderToy "
          "passes, quick fix, fix all, incremental and full changes, errors, shutdown"
          % (compared, shared))


main()
