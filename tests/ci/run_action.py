#!/usr/bin/env python3
"""Runs the repository's GitHub Action (action.yml) as a runner would: each
`run:` step through `bash --noprofile --norc -eo pipefail` with the runner's
environment (GITHUB_ACTION_PATH, GITHUB_WORKSPACE, RUNNER_TEMP, GITHUB_OUTPUT,
GITHUB_PATH), `${{ }}` expressions of the forms the action uses evaluated, and
`uses:` steps checked for what they would receive. Then asserts the results for
a workspace with a finding and for a clean one, and that the problem matcher
reads `check`'s text output.

A last run installs the .deb a build job would share (DEB_DIR: the deb_package
test's output) instead of building, with paths given as a list, one of them
holding a space, and args quoted as in a shell.

  run_action.py SOURCE_DIR SCRATCH_DIR [DEB_DIR]
"""
import json
import os
import glob
import re
import shutil
import subprocess
import sys

import yaml

SOURCE = os.path.abspath(sys.argv[1])
SCRATCH = os.path.abspath(sys.argv[2])
DEB_DIR = os.path.abspath(sys.argv[3]) if len(sys.argv) > 3 else None
EXPRESSION = re.compile(r"\$\{\{\s*(.*?)\s*\}\}")

BAD = "#version 300 es\nprecision highp float;\nout vec4 color;\nvoid main() { color = vec3(1.0); }\n"
GOOD = "#version 300 es\nprecision highp float;\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n"


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


class Context:
    def __init__(self, action, inputs):
        self.inputs = {name: str(spec.get("default", "")) for name, spec in action["inputs"].items()}
        self.inputs.update(inputs)
        self.steps = {}
        self.status_ok = True

    def value(self, expression):
        """The expression forms action.yml uses: always(), inputs.X, steps.ID.outputs.X,
        string literals, == and != and &&."""
        expression = expression.strip()
        if "&&" in expression:
            return all(self.truthy(self.value(part)) for part in expression.split("&&"))
        for operator in ("==", "!="):
            if operator in expression:
                left, right = (self.value(part) for part in expression.split(operator, 1))
                return (left == right) == (operator == "==")
        if expression == "always()":
            return True
        if expression.startswith("'") and expression.endswith("'"):
            return expression[1:-1]
        match = re.fullmatch(r"inputs\.([\w-]+)", expression)
        if match:
            return self.inputs[match.group(1)]
        match = re.fullmatch(r"steps\.([\w-]+)\.outputs\.([\w-]+)", expression)
        if match:
            return self.steps.get(match.group(1), {}).get(match.group(2), "")
        fail("action.yml uses an expression this runner does not know: " + expression)

    @staticmethod
    def truthy(value):
        return value not in ("", False, None, "false", 0)

    def substitute(self, text):
        return EXPRESSION.sub(lambda m: str(self.value(m.group(1))), str(text))

    def condition(self, text):
        if text is None:
            return self.status_ok  # success() is the default
        inner = EXPRESSION.fullmatch(text.strip())
        return self.truthy(self.value(inner.group(1) if inner else text))


def run_action(workspace, inputs, build_dir):
    with open(os.path.join(SOURCE, "action.yml")) as f:
        action = yaml.safe_load(f)
    if action["runs"]["using"] != "composite":
        fail("the action is not a composite action")
    context = Context(action, inputs)
    runner_temp = os.path.join(SCRATCH, "runner-temp")
    os.makedirs(runner_temp, exist_ok=True)
    path_file = os.path.join(SCRATCH, "github-path")
    open(path_file, "a").close()
    log = []
    for step in action["runs"]["steps"]:
        if not context.condition(step.get("if")):
            log.append((step.get("name"), "skipped", ""))
            continue
        if "uses" in step:
            upload = {k: context.substitute(v) for k, v in step.get("with", {}).items()}
            log.append((step.get("name"), "uses", step["uses"], upload))
            continue
        output_file = os.path.join(SCRATCH, "github-output")
        open(output_file, "w").close()
        env = dict(os.environ)
        env.update({k: context.substitute(v) for k, v in step.get("env", {}).items()})
        with open(path_file) as f:
            extra_path = [line.strip() for line in f if line.strip()]
        env.update({
            "GITHUB_ACTION_PATH": SOURCE,
            "GITHUB_WORKSPACE": workspace,
            "GITHUB_OUTPUT": output_file,
            "GITHUB_PATH": path_file,
            "RUNNER_TEMP": runner_temp,
            "SHADERPORT_ACTION_BUILD_DIR": build_dir,
            "PATH": os.pathsep.join(extra_path[::-1] + [env["PATH"]]),
        })
        if step.get("shell") != "bash":
            fail("step %r does not use bash" % step.get("name"))
        script = context.substitute(step["run"])
        done = subprocess.run(["bash", "--noprofile", "--norc", "-eo", "pipefail", "-c", script],
                              cwd=workspace, env=env, capture_output=True, text=True, timeout=1800)
        outputs = {}
        with open(output_file) as f:
            for line in f:
                if "=" in line:
                    key, value = line.rstrip("\n").split("=", 1)
                    outputs[key] = value
        if "id" in step:
            context.steps[step["id"]] = outputs
        log.append((step.get("name"), done.returncode, done.stdout + done.stderr))
        if done.returncode != 0:
            context.status_ok = False
    return context, log


def make_workspace(name, text):
    workspace = os.path.join(SCRATCH, name)
    shutil.rmtree(workspace, ignore_errors=True)
    os.makedirs(os.path.join(workspace, "shaders"))
    with open(os.path.join(workspace, "shaders", "color.frag"), "w") as f:
        f.write(text)
    return workspace


def step(log, name):
    for entry in log:
        if entry[0] == name:
            return entry
    fail("no step named %r ran: %r" % (name, [e[0] for e in log]))


def main():
    os.makedirs(SCRATCH, exist_ok=True)
    build_dir = os.path.join(SCRATCH, "build")

    # A workspace with an error: SARIF uploaded, the PR annotated, the job failed.
    workspace = make_workspace("with-finding", BAD)
    context, log = run_action(workspace, {"paths": "shaders"}, build_dir)
    install = step(log, "Install shaderport")
    if install[1] != 0:
        fail("install step failed:\n" + install[2])
    check = step(log, "Check shaders")
    if check[1] != 0:
        fail("check step failed to run:\n" + check[2])
    if context.steps["check"].get("exit-code") != "1":
        fail("check step output exit-code=%r, expected 1" % context.steps["check"].get("exit-code"))
    if not re.search(r"^::error file=shaders/color\.frag,line=4,", check[2], re.M):
        fail("no pull-request annotation for shaders/color.frag:4:\n" + check[2])
    upload = step(log, "Upload SARIF to code scanning")
    if upload[1] != "uses" or not upload[2].startswith("github/codeql-action/upload-sarif@"):
        fail("the SARIF upload step is not github/codeql-action/upload-sarif")
    sarif_path = os.path.join(workspace, upload[3]["sarif_file"])
    with open(sarif_path) as f:
        sarif = json.load(f)
    results = sarif["runs"][0]["results"]
    if sarif["version"] != "2.1.0" or not any(r["level"] == "error" for r in results):
        fail("the uploaded SARIF has no error result")
    verdict = step(log, "Verdict")
    if verdict[1] != 1:
        fail("the verdict step exited %r on a finding, expected 1" % verdict[1])

    # A clean workspace: the job passes, and with upload-sarif false nothing is uploaded.
    workspace = make_workspace("clean", GOOD)
    context, log = run_action(workspace, {"paths": "shaders", "upload-sarif": "false"}, build_dir)
    if step(log, "Check shaders")[1] != 0 or context.steps["check"].get("exit-code") != "0":
        fail("the clean workspace did not pass the check step")
    if step(log, "Upload SARIF to code scanning")[1] != "skipped":
        fail("upload-sarif: false still uploaded")
    if step(log, "Verdict")[1] != 0:
        fail("the verdict step failed on a clean workspace")

    # The problem matcher reads the text format.
    with open(os.path.join(SOURCE, ".github", "shaderport-problem-matcher.json")) as f:
        pattern = json.load(f)["problemMatcher"][0]["pattern"][0]
    shaderport = os.path.join(SCRATCH, "runner-temp", "shaderport", "bin", "shaderport")
    workspace = make_workspace("matcher", BAD)
    text = subprocess.run([shaderport, "check", "shaders"], cwd=workspace, capture_output=True,
                          text=True).stdout
    regexp = re.compile(pattern["regexp"])
    matches = [regexp.match(line) for line in text.splitlines()]
    matches = [m for m in matches if m]
    if not matches:
        fail("the problem matcher matches no line of:\n" + text)
    first = matches[0]
    if (first.group(pattern["file"]), first.group(pattern["line"]),
            first.group(pattern["severity"])) != ("shaders/color.frag", "4", "error"):
        fail("the problem matcher read %r" % (first.groups(),))
    installed_from = "a source build"
    if DEB_DIR:
        debs = sorted(glob.glob(os.path.join(DEB_DIR, "shaderport_*.deb")))
        if not debs:
            fail("no .deb in " + DEB_DIR)
        workspace = make_workspace("from-deb", BAD)
        spaced = os.path.join(workspace, "more shaders")
        os.makedirs(spaced)
        with open(os.path.join(spaced, "second color.frag"), "w") as f:
            f.write(BAD)
        inputs = {"paths": "shaders\n  more shaders  \n", "deb": debs[0],
                  "args": "--stage 'fragment' --no-config"}
        context, log = run_action(workspace, inputs, os.path.join(SCRATCH, "no-build"))
        install = step(log, "Install shaderport")
        if install[1] != 0:
            fail("installing the .deb failed:\n" + install[2])
        if os.path.exists(os.path.join(SCRATCH, "no-build")):
            fail("the .deb install built shaderport")
        check = step(log, "Check shaders")
        if context.steps["check"].get("exit-code") != "1":
            fail("from the .deb: exit-code=%r\n%s" % (context.steps["check"].get("exit-code"),
                                                       check[2]))
        for name in ("shaders/color.frag", "more shaders/second color.frag"):
            if not re.search(r"^::error file=%s,line=4," % re.escape(name), check[2], re.M):
                fail("no annotation for %r (paths as a list):\n%s" % (name, check[2]))
        installed_from = "a source build and from " + os.path.basename(debs[0])
    print("action: finding fails the job after upload and annotation; clean passes; "
          "problem matcher reads %d line(s); installed from %s" % (len(matches), installed_from))


main()
