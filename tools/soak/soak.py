#!/usr/bin/env python3
"""Soak: `shaderport check`, `fix` and `port` over every pass of a ShaderToy corpus
(JSONL in the shared corpus's format) and every stage of the WebGL conformance
cases, counting crashes, hangs and internal/* findings.

Each shader record becomes a directory (common.glsl beside its passes, as
`check` finds Common code); each conformance case a .vert/.frag pair. Every
command runs once over the whole tree; only when a run crashes or times out are
the files re-run one by one to name the culprits.

  soak.py --shaderport BIN [--shadertoy FILE.jsonl]... [--conformance FILE.jsonl]...
          [--work DIR] [--report OUT.md] [--timeout S]
Exit status: 0 when nothing crashed, hung or reported internal/*, else 1.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys

PASS_FILES = {"image": "image.glsl", "common": "common.glsl", "sound": "sound.glsl",
              "cubemap": "cube-a.glsl"}
INTERNAL = re.compile(r"^(.*?):(?:\d+:\d+:)? ?(?:error|warning|note): .*\[(internal/[a-z0-9-]+)\]$")


def safe_name(text):
    return re.sub(r"[^A-Za-z0-9._-]+", "-", text).strip("-") or "x"


def write_tree(args, root):
    """Writes the shaders; returns the list of files, relative to root."""
    files = []
    for corpus in args.shadertoy:
        for line in open(corpus, encoding="utf-8"):
            record = json.loads(line)
            directory = os.path.join("shadertoy", safe_name(record["id"]))
            os.makedirs(os.path.join(root, directory), exist_ok=True)
            for shader_pass in record["passes"]:
                kind = shader_pass["type"]
                name = PASS_FILES.get(kind) or safe_name(shader_pass["name"]).lower() + ".glsl"
                path = os.path.join(directory, name)
                with open(os.path.join(root, path), "w", encoding="utf-8",
                          errors="surrogatepass", newline="") as f:
                    f.write(shader_pass["code"])
                if kind != "common":
                    files.append(path)
    for corpus in args.conformance:
        for line in open(corpus, encoding="utf-8"):
            case = json.loads(line)
            directory = os.path.join("conformance", safe_name(case["id"]))
            os.makedirs(os.path.join(root, directory), exist_ok=True)
            for stage, extension in (("vertex", ".vert"), ("fragment", ".frag")):
                code = case.get(stage)
                if code is None:
                    continue
                path = os.path.join(directory, "shader" + extension)
                with open(os.path.join(root, path), "w", encoding="utf-8",
                          errors="surrogatepass", newline="") as f:
                    f.write(code)
                files.append(path)
    return files


def run(command, cwd, timeout):
    """(exit status or 'signal N' or 'timeout', output)."""
    try:
        done = subprocess.run(command, cwd=cwd, capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", ""
    output = (done.stdout + done.stderr).decode("utf-8", "replace")
    if done.returncode < 0:
        return "signal %d" % -done.returncode, output
    return done.returncode, output


COMMANDS = {
    "check": lambda out, paths: ["check", "--no-config", "--no-cache", "--format", "json", *paths],
    "fix": lambda out, paths: ["fix", "--no-config", "--diff", *paths],
    "port": lambda out, paths: ["port", "--no-config", "--out-dir", out, *paths],
}


def internal_findings(name, output):
    """{(path, rule)} of the internal/* findings in a command's output. check's JSON
    names the checked file even when the finding points into generated text."""
    found = set()
    if name == "check":
        start = output.find("{")
        try:
            report = json.JSONDecoder().raw_decode(output[start:])[0] if start >= 0 else {}
        except ValueError:
            report = {}
        for checked in report.get("files", []):
            for diagnostic in checked.get("diagnostics", []):
                if diagnostic.get("rule", "").startswith("internal/"):
                    found.add((checked["path"], diagnostic["rule"]))
    for line in output.splitlines():
        match = INTERNAL.match(line)
        if match:
            found.add((match.group(1), match.group(2)))
    return found


def soak(args, root, files):
    results = {}
    for name, build in COMMANDS.items():
        out = os.path.join(args.work, "out-" + name)
        shutil.rmtree(out, ignore_errors=True)
        status, output = run([args.shaderport, *build(out, ["."])], root, args.timeout)
        print("soak: %s over the tree: %s" % (name, status), file=sys.stderr, flush=True)
        crashes, hangs = [], []
        internal = internal_findings(name, output)
        if isinstance(status, str) or status == 3 and not internal:
            # Name the culprits one file at a time.
            for path in files:
                one, text = run([args.shaderport, *build(out, [path])], root, args.file_timeout)
                if one == "timeout":
                    hangs.append(path)
                elif isinstance(one, str):
                    crashes.append("%s (%s)" % (path, one))
                internal |= internal_findings(name, text)
        internal = sorted(internal)
        results[name] = {"status": status, "crashes": crashes, "hangs": hangs,
                         "internal": internal}
    return results


def report(args, files, results):
    shadertoy = sum(1 for f in files if f.startswith("shadertoy"))
    lines = [
        "# Soak: check, fix and port over the shared corpora",
        "",
        "Generated by `tools/soak/soak.py` (the `soak_shared_corpora` test); do not edit. "
        "Every pass of every record of the ShaderToy corpus (Common code beside its passes) and "
        "every vertex and fragment stage of the WebGL conformance cases, each command run once "
        "over the whole tree.",
        "",
        "| input | files |",
        "|---|---:|",
        "| ShaderToy passes (Image, Buffer, Cube, Sound) | %d |" % shadertoy,
        "| conformance stages | %d |" % (len(files) - shadertoy),
        "",
        "| command | exit | crashes | hangs | internal findings |",
        "|---|---:|---:|---:|---:|",
    ]
    for name, result in results.items():
        lines.append("| `%s` | %s | %d | %d | %d |" % (name, result["status"], len(result["crashes"]),
                                                      len(result["hangs"]), len(result["internal"])))
    problems = []
    for name, result in results.items():
        problems += ["- `%s` crashed on %s" % (name, c) for c in result["crashes"]]
        problems += ["- `%s` hung on %s" % (name, h) for h in result["hangs"]]
        problems += ["- `%s`: %s at %s" % (name, rule, path) for path, rule in result["internal"]]
    lines += ["", "## Problems", ""] + (problems or ["None."])
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--shaderport", required=True)
    parser.add_argument("--shadertoy", action="append", default=[])
    parser.add_argument("--conformance", action="append", default=[])
    parser.add_argument("--work", default="soak-work")
    parser.add_argument("--report")
    parser.add_argument("--timeout", type=float, default=900)
    parser.add_argument("--file-timeout", type=float, default=60)
    args = parser.parse_args()
    args.shaderport = os.path.abspath(args.shaderport)
    args.work = os.path.abspath(args.work)
    root = os.path.join(args.work, "tree")
    shutil.rmtree(root, ignore_errors=True)
    os.makedirs(root)
    files = write_tree(args, root)
    results = soak(args, root, files)
    text = report(args, files, results)
    if args.report:
        with open(args.report, "w") as f:
            f.write(text)
    sys.stdout.write(text)
    bad = any(r["crashes"] or r["hangs"] or r["internal"] for r in results.values())
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
