"""The three verdicts a differential run compares for a batch of stages: Chromium's
(browser_compile.py), `shaderport check --target`'s and glslangValidator's. A job is
{source, stage, context}; each verdict is (ok, first message). Python standard library only.
"""
import json
import os
import re
import shutil
import subprocess
import tempfile

from browser_compile import BrowserCompiler

_EXT = {"vertex": ".vert", "fragment": ".frag"}


def _is_link_rule(rule):
    return rule.startswith("link/")


def browser_message(log):
    """The first error of an ANGLE info log, without its 'ERROR: 0:LINE:' prefix."""
    log = log.replace("'\n'", "'\\n'")  # a directive's end of line, quoted as the token
    for line in log.splitlines():
        match = re.match(r"ERROR:\s*\d+:\d+:\s*(.*)", line)
        if match:
            return match.group(1).strip()
    return log.strip().splitlines()[0] if log.strip() else ""


def browser_class(log):
    """What a browser error is about, without the token it quotes."""
    message = browser_message(log)
    return message.split(" : ", 1)[1] if " : " in message else message


class CheckOracle:
    def __init__(self, shaderport, jobs=2):
        self.shaderport = shaderport
        self.jobs = jobs

    def verdicts(self, jobs):
        """[(ok, 'rule: message')] for each job; ok is None when check failed to run."""
        work = tempfile.mkdtemp(prefix="sp-diff-check-")
        try:
            names = {}
            for i, job in enumerate(jobs):
                folder = os.path.join(work, "webgl%d" % job["context"])
                os.makedirs(folder, exist_ok=True)
                path = os.path.join(folder, "m%06d%s" % (i, _EXT[job["stage"]]))
                with open(path, "w", encoding="utf-8", errors="surrogateescape", newline="") as f:
                    f.write(job["source"])
                names[os.path.realpath(path)] = i
            results = [(None, "not checked")] * len(jobs)
            for context in (1, 2):
                folder = os.path.join(work, "webgl%d" % context)
                if os.path.isdir(folder):
                    self._run(folder, context, names, results)
            return results
        finally:
            shutil.rmtree(work, ignore_errors=True)

    def _run(self, folder, context, names, results):
        command = [self.shaderport, "check", "--target", "webgl%d" % context, "--format", "json",
                   "--no-config", "--no-cache", "-j", str(self.jobs), "--quiet", folder]
        proc = subprocess.run(command, capture_output=True, text=True, errors="replace")
        try:
            report = json.loads(proc.stdout)
        except json.JSONDecodeError:
            for path, i in names.items():
                if path.startswith(os.path.realpath(folder) + os.sep):
                    results[i] = (None, "check exit %d: %s" % (proc.returncode, proc.stderr[-300:]))
            return
        for entry in report.get("files", []):
            path = os.path.realpath(entry["path"] if os.path.isabs(entry["path"])
                                    else os.path.join(os.getcwd(), entry["path"]))
            i = names.get(path)
            if i is None:
                continue
            first = ""
            ok = True
            for d in entry.get("diagnostics", []):
                if d.get("severity") == "error" and not _is_link_rule(d.get("rule", "")):
                    ok = False
                    first = first or "%s: %s" % (d.get("rule"), d.get("message", "")[:160])
            results[i] = (ok, first)


class GlslangOracle:
    """glslangValidator alone, as a user would run it on each stage (ES 1.00 when the
    text has no #version). Many files a process: it compiles each on its own and prints
    every file's name before that file's messages."""

    def __init__(self, binary="glslangValidator", per_process=200):
        self.binary = shutil.which(binary)
        self.per_process = per_process

    def verdicts(self, jobs):
        if not self.binary:
            return [(None, "glslangValidator not found")] * len(jobs)
        work = tempfile.mkdtemp(prefix="sp-diff-glslang-")
        try:
            paths = []
            for i, job in enumerate(jobs):
                path = os.path.join(work, "m%06d%s" % (i, _EXT[job["stage"]]))
                with open(path, "w", encoding="utf-8", errors="surrogateescape", newline="") as f:
                    f.write(job["source"])
                paths.append(path)
            results = {}
            for at in range(0, len(paths), self.per_process):
                results.update(self._run(paths[at:at + self.per_process]))
            return [results.get(p, (None, "no answer")) for p in paths]
        finally:
            shutil.rmtree(work, ignore_errors=True)

    def _run(self, paths):
        try:
            proc = subprocess.run([self.binary] + paths, capture_output=True, text=True,
                                  errors="replace", timeout=300)
        except subprocess.TimeoutExpired:
            return {p: (None, "timeout") for p in paths}
        if proc.returncode < 0:  # it crashed on one of them: find which, one at a time
            if len(paths) == 1:
                return {paths[0]: (None, "glslangValidator crashed")}
            results = {}
            for path in paths:
                results.update(self._run([path]))
            return results
        names = set(paths)
        results = {p: (True, "") for p in paths}
        current = None
        for line in (proc.stdout + proc.stderr).splitlines():
            if line in names:
                current = line
            elif current and line.startswith("ERROR"):
                if results[current][0]:
                    results[current] = (False, line)
        return results


class StageOracles:
    def __init__(self, shaderport, chromium=None, with_glslang=True):
        self.browser = BrowserCompiler(chromium)
        self.check = CheckOracle(shaderport)
        self.glslang = GlslangOracle() if with_glslang else None

    def judge(self, jobs, glslang=False):
        """Per job: {browser, browser_log, check, check_first[, glslang]}."""
        browser = self.browser.compile(jobs)
        check = self.check.verdicts(jobs)
        out = []
        for (b_ok, b_log), (c_ok, c_first) in zip(browser, check):
            out.append({"browser": b_ok, "browser_log": b_log, "check": c_ok, "check_first": c_first})
        if glslang and self.glslang:
            for entry, (g_ok, g_first) in zip(out, self.glslang.verdicts(jobs)):
                entry["glslang"], entry["glslang_first"] = g_ok, g_first
        return out

    def close(self):
        self.browser.close()
