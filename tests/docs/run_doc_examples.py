#!/usr/bin/env python3
"""Runs every command example of README.md and docs/cli.md through the binary, so
that the docs fail a test when one no longer works.

Examples are the lines of fenced code blocks that start with `shaderport ` (or
`$ shaderport `). A line written as a synopsis (placeholders such as PATH..., FILE,
[options], a|b) only has its command checked (`shaderport help COMMAND`); every
other line runs in bash, in a fresh copy of a small workspace (ShaderToy passes,
WebGL shaders, the repository's corpus), with HOME inside it. An example works when
it exits 0 or 1 (1: it found something, which examples may show) and prints no
`shaderport: error:`.

  run_doc_examples.py SOURCE_DIR SHADERPORT SCRATCH_DIR
"""
import os
import re
import shutil
import subprocess
import sys

SOURCE, BINARY, SCRATCH = (os.path.abspath(a) for a in sys.argv[1:4])
DOCS = ["README.md", os.path.join("docs", "cli.md")]
PLACEHOLDER = re.compile(r"\b(PATH|FILE|OUT|DIR|ID|KIND|COMMAND|N|OUT\.png)\b|\[|\||\.\.\.")

TOY = ("void mainImage(out vec4 fragColor, in vec2 fragCoord)\n{\n"
       "    vec2 uv = fragCoord / iResolution.xy;\n"
       "    fragColor = vec4(uv, 0.5 + 0.5 * sin(iGlobalTime), 1);\n}\n")
WEBGL1 = ("precision mediump float;\nuniform float t;\n"
          "void main() { gl_FragColor = vec4(t, 0.0, 0.0, 1.0); }\n")
WEBGL2_ERROR = ("#version 300 es\nprecision highp float;\nout vec4 color;\n"
                "void main() { color = vec3(1.0); }\n")


def examples(path):
    """(path, line, text, block) for each example; `block` numbers the code blocks, whose
    examples run in order in one workspace (a baseline written, then read)."""
    found = []
    in_block = False
    block = 0
    with open(os.path.join(SOURCE, path)) as f:
        for number, line in enumerate(f, 1):
            if line.startswith("```"):
                in_block = not in_block
                block += 1
                continue
            text = line.strip()
            if text.startswith("$ "):
                text = text[2:]
            if in_block and text.startswith("shaderport "):
                found.append((path, number, text, block))
    return found


def workspace(name):
    root = os.path.join(SCRATCH, name)
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(os.path.join(root, "shaders"))
    os.makedirs(os.path.join(root, "home"))
    files = {"toy.glsl": TOY, "shader.frag": WEBGL1, "shaders/a.frag": WEBGL1,
             "shaders/b.frag": WEBGL2_ERROR, "shaders/toy.glsl": TOY}
    for relative, text in files.items():
        with open(os.path.join(root, relative), "w") as f:
            f.write(text)
    os.symlink(os.path.join(SOURCE, "corpus"), os.path.join(root, "corpus"))
    return root


def main():
    os.makedirs(SCRATCH, exist_ok=True)
    failures = []
    ran = checked = 0
    root = None
    current_block = None
    for doc in DOCS:
        for path, number, text, block in examples(doc):
            command = re.sub(r"\s+#.*$", "", text)  # the comment after the example
            words = command.split()
            if PLACEHOLDER.search(command):
                # A synopsis: the command it names must exist.
                result = subprocess.run([BINARY, "help", words[1]], capture_output=True, text=True,
                                        stdin=subprocess.DEVNULL)
                checked += 1
                if result.returncode != 0:
                    failures.append("%s:%d: 'shaderport help %s' exits %d: %s" %
                                    (path, number, words[1], result.returncode, result.stderr))
                continue
            command = re.sub(r"\s{3,}\S.*$", "", command)  # a synopsis line's description
            if (doc, block) != current_block:
                current_block = (doc, block)
                root = workspace("example-%d" % (ran + 1))
            env = dict(os.environ, HOME=os.path.join(root, "home"), NO_COLOR="1")
            env["PATH"] = os.path.dirname(BINARY) + os.pathsep + env["PATH"]
            script = command.replace("~/", "$HOME/")
            # Where an example writes into a directory a user already has, make it.
            for target in re.findall(r">\s*(\S+)", script):
                parent = os.path.dirname(target.replace("$HOME", env["HOME"]).strip('"'))
                if parent and "$" not in parent and "{" not in parent:
                    os.makedirs(os.path.join(root, parent), exist_ok=True)
            if "${" in script:  # shell-specific expansions (zsh's fpath)
                script = re.sub(r'"\$\{[^}]*\}/', '"$HOME/', script)
            result = subprocess.run(["bash", "-c", script], cwd=root, env=env,
                                    stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                    stderr=subprocess.PIPE,
                                    text=True, errors="replace", timeout=300)
            ran += 1
            if result.returncode not in (0, 1) or "shaderport: error:" in result.stderr:
                failures.append("%s:%d: '%s' exits %d:\n%s" %
                                (path, number, command, result.returncode, result.stderr[-2000:]))
    for failure in failures:
        print("FAIL: " + failure)
    print("doc examples: %d run, %d synopsis lines checked, %d failed" %
          (ran, checked, len(failures)))
    if ran < 10:
        print("FAIL: fewer than 10 examples found: did the docs move?")
        return 1
    return 1 if failures else 0


sys.exit(main())
