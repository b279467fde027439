#!/usr/bin/env python3
"""Fresh ShaderToy passes through `check`: what it marks fixable, whether the marks
hold, and what the static loop and output findings say.

Draws --count Image passes without other tabs (their code alone is what the site
compiles behind its header) from the Shadertoys dataset with --seed, writes each as
a .glsl file, and runs `check --format json` on them. For every file with a marked
finding it applies the marked fix-its (from the end backwards), checks the result
again and counts the marked findings still there (same rule, same line), and
compares the result with what `shaderport fix` writes. Prints counts and ids only
(no code: most passes are not under a permissive licence).

  fixable_sweep.py --shaderport BIN --seed S --count N [--out DIR]
"""
import argparse
import json
import os
import random
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "browser"))
import shadertoy_sweep  # noqa: E402


def check_json(binary, paths, cwd):
    done = subprocess.run([binary, "check", "--format", "json", "--no-cache", "--no-config"] +
                          paths, cwd=cwd, capture_output=True, text=True, errors="replace")
    return json.loads(done.stdout)


def apply_fixes(text, diagnostics):
    data = text.encode()
    edits = []
    for d in diagnostics:
        if not d.get("fixable"):
            continue
        for fix in d["fixes"]:
            if fix["safety"] != "safe":
                continue
            r = fix["location"]["range"]
            edits.append((r["start"]["offset"], r["end"]["offset"], fix["replacement"].encode()))
    edits.sort(reverse=True)
    last = len(data) + 1
    for begin, end, replacement in edits:
        if end > last:
            return None  # overlapping edits: not one consistent set
        data = data[:begin] + replacement + data[end:]
        last = begin
    return data.decode(errors="replace")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--shaderport", required=True)
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--count", type=int, default=1000)
    parser.add_argument("--out", default="/tmp/fixable-sweep")
    args = parser.parse_args()
    records = shadertoy_sweep.load_dataset(shadertoy_sweep.DEFAULT_DATASET)
    single = sorted(rid for rid, r in records.items()
                    if len(r["passes"]) == 1 and r["passes"][0]["type"] == "image")
    random.Random(args.seed).shuffle(single)
    chosen = single[:args.count]
    os.makedirs(args.out, exist_ok=True)
    names = []
    for rid in chosen:
        name = rid + ".glsl"
        with open(os.path.join(args.out, name), "w") as f:
            f.write(records[rid]["passes"][0]["code"])
        names.append(name)
    report = check_json(args.shaderport, names, args.out)
    totals = {"files": len(names), "findings": 0, "marked": 0, "files_marked": 0,
              "marks_left_after_applying": 0, "overlapping_sets": 0,
              "applied_equals_fix": 0, "applied_differs_from_fix": 0}
    static = {"portability/infinite-loop": [], "portability/output-never-written": []}
    for entry in report["files"]:
        diagnostics = entry["diagnostics"]
        totals["findings"] += len(diagnostics)
        for d in diagnostics:
            if d["rule"] in static:
                static[d["rule"]].append(entry["path"][:-5])
        marked = [d for d in diagnostics if d.get("fixable")]
        if not marked:
            continue
        totals["marked"] += len(marked)
        totals["files_marked"] += 1
        path = os.path.join(args.out, entry["path"])
        text = open(path, errors="replace").read()
        applied = apply_fixes(text, diagnostics)
        if applied is None:
            totals["overlapping_sets"] += 1
            continue
        probe = os.path.join(args.out, "applied", entry["path"])
        os.makedirs(os.path.dirname(probe), exist_ok=True)
        with open(probe, "w") as f:
            f.write(applied)
        again = check_json(args.shaderport, [probe], args.out)["files"][0]["diagnostics"]
        left = {(d["rule"], d["location"]["range"]["start"]["line"]) for d in again
                if d["location"]}
        for d in marked:
            if d["location"] and (d["rule"], d["location"]["range"]["start"]["line"]) in left:
                totals["marks_left_after_applying"] += 1
        fixed = subprocess.run([args.shaderport, "fix", "--no-config", entry["path"]],
                               cwd=args.out, capture_output=True, text=True, errors="replace")
        key = "applied_equals_fix" if fixed.stdout == applied else "applied_differs_from_fix"
        totals[key] += 1
    print(json.dumps({"seed": args.seed, "totals": totals,
                      "static": {k: {"count": len(v), "ids": v} for k, v in static.items()}},
                     indent=1))


main()
