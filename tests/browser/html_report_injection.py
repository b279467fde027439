#!/usr/bin/env python3
"""The HTML report is injection-proof: shader text and file names carrying
`</script>`, `<img onerror=...>` and quote characters are written as text.

Writes shaders whose names and code hold such payloads, runs
`shaderport report --html`, opens the page in headless Chromium (Debian's
`chromium`, SwiftShader) and reads the DOM after scripts would have run:
  - no <script> element and no on* event attribute exists (the payloads stayed text);
  - no payload ran (each would set a data-injected attribute on <body>);
  - every payload is visible as text.
  html_report_injection.py SHADERPORT_BINARY WORK_DIR
"""
import html.parser
import os
import shutil
import subprocess
import sys
import tempfile

MARK = "data-injected"
PAYLOADS = [
    '</script><script>document.body.setAttribute("%s","script")</script>' % MARK,
    '<img src=x onerror="document.body.setAttribute(\'%s\',\'img\')">' % MARK,
    '"\'><svg onload=document.body.setAttribute("%s","svg")>' % MARK,
]
# File names cannot hold '/', but can hold the rest.
NAMES = [
    '<img src=x onerror=document.body.setAttribute(`%s`,`name`)>.glsl' % MARK,
    '"quoted\' <b>bold &amp; more.frag',
]


class Elements(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.scripts = 0
        self.handlers = []
        self.body_attributes = {}

    def handle_starttag(self, tag, attrs):
        if tag == "script":
            self.scripts += 1
        for name, value in attrs:
            if name.lower().startswith("on"):
                self.handlers.append((tag, name, value))
        if tag == "body":
            self.body_attributes = dict(attrs)


def main():
    binary, work = sys.argv[1], sys.argv[2]
    chromium = shutil.which(os.environ.get("CHROMIUM", "chromium"))
    if chromium is None:
        print("html_report_injection: chromium is not installed (tools/install-deps.sh installs it)",
              file=sys.stderr)
        return 1
    shutil.rmtree(work, ignore_errors=True)
    shaders = os.path.join(work, "shaders")
    os.makedirs(shaders)
    # A ShaderToy pass with a type error on the payload lines, so that the findings
    # quote them; one clean WebGL2 file whose name is the payload.
    code = "void mainImage(out vec4 o, in vec2 u) {\n"
    for payload in PAYLOADS:
        code += "  vec3 c = 1.0; // %s\n" % payload
    code += "  o = vec4(1);\n}\n"
    with open(os.path.join(shaders, NAMES[0]), "w") as f:
        f.write(code)
    with open(os.path.join(shaders, NAMES[1]), "w") as f:
        f.write("#version 300 es\nprecision mediump float;\nout vec4 color; // %s\n"
                "void main() { color = vec4(1.0); }\n" % PAYLOADS[1])
    page = os.path.join(work, "report.html")
    done = subprocess.run([binary, "report", "--html", page, "--size", "16", shaders],
                          capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        print(done.stdout, done.stderr, file=sys.stderr)
        print("html_report_injection: report exited %d" % done.returncode, file=sys.stderr)
        return 1
    # A control page with the payloads written raw: the checks must catch it, or
    # they prove nothing (scripts off, Chromium not loading file:// pages, ...).
    control = os.path.join(work, "control.html")
    with open(control, "w") as f:
        f.write("<!DOCTYPE html><html><body><pre>%s</pre></body></html>" % "\n".join(PAYLOADS))
    if not problems_of(chromium, work, control, []):
        print("html_report_injection: the control page with raw payloads passed", file=sys.stderr)
        return 1
    problems = problems_of(chromium, work, page, PAYLOADS + NAMES)
    for problem in problems:
        print("html_report_injection: " + problem, file=sys.stderr)
    return 1 if problems else 0


def problems_of(chromium, work, page, shown):
    profile = tempfile.mkdtemp(prefix="chromium-", dir=work)
    dom = subprocess.run(
        [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--disable-background-networking", "--disable-extensions",
         "--no-first-run", "--user-data-dir=" + profile, "--virtual-time-budget=2000",
         "--dump-dom", "file://" + page],
        capture_output=True, text=True, timeout=120).stdout
    if "<body" not in dom:
        return ["Chromium returned no DOM for " + page]
    elements = Elements()
    elements.feed(dom)
    problems = []
    if elements.scripts:
        problems.append("%d <script> elements in the page" % elements.scripts)
    problems += ["an event handler %s on <%s>: %s" % (n, t, v) for t, n, v in elements.handlers]
    if MARK in elements.body_attributes:
        problems.append("a payload ran: body %s=%s" % (MARK, elements.body_attributes[MARK]))
    text = html.unescape(dom)
    for payload in shown:
        if payload not in text:
            problems.append("payload not shown as text: %s" % payload)
    return problems


if __name__ == "__main__":
    sys.exit(main())
