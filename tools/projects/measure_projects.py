#!/usr/bin/env python3
"""Every multipass ShaderToy project of a corpus through shaderport's JSON input.

For each record with more than one pass (corpus format, one JSON object a line), the
record is written as its own .json file and run through:
  check   : exit 0 (clean) or 1 (findings); 2/3 or an internal/* finding is a failure
  port    : --out-dir, exit 0/1; every written .frag must compile in glslangValidator
  page    : port --emit html writes one page
  render  : --frames 2 --size 64x64 --timeout 60 draws a picture (exit 0/1 with a PNG), or says why
Prints a markdown report (counts, then each project that did not go through, with the
first line of its findings). Nothing of the shaders is written to the report but ids.

  measure_projects.py SHADERPORT CORPUS.jsonl [--limit N] [--jobs N] > report.md
Python 3 standard library only; needs glslangValidator (Debian glslang-tools).
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile


def run(command, timeout=120):
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        return done.returncode, done.stdout + done.stderr
    except subprocess.TimeoutExpired:
        return "timeout", ""


def first_error(output):
    for line in output.splitlines():
        if ": error:" in line or "internal/" in line:
            return line.split(": error: ", 1)[-1][:140]
    return ""


args_timeout = 60  # render --timeout: slow is not hung (llvmpipe on a busy 2-core machine)


def measure(binary, record, work):
    key = record["id"]
    folder = os.path.join(work, key)
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, key + ".json")
    with open(path, "w") as out:
        json.dump(record, out)
    result = {"id": key, "passes": len(record["passes"])}
    code, output = run([binary, "check", "--no-cache", "-j", "1", path])
    result["check"] = code
    result["check_internal"] = "internal/" in output
    result["check_error"] = first_error(output)
    out_dir = os.path.join(folder, "port")
    code, output = run([binary, "port", "-j", "1", path, "--out-dir", out_dir])
    result["port"] = code
    result["port_error"] = first_error(output)
    frags = []
    for root, _, files in os.walk(out_dir):
        frags += [os.path.join(root, f) for f in files if f.endswith(".frag")]
    result["ported_passes"] = len(frags)
    result["ported_compile"] = sum(run(["glslangValidator", f])[0] == 0 for f in frags)
    page = os.path.join(folder, key + ".html")
    code, _ = run([binary, "port", "--emit", "html", path, "-o", page])
    result["page"] = code in (0, 1) and os.path.exists(page)
    png = os.path.join(folder, key + ".png")
    code, output = run([binary, "render", path, "--frames", "2", "--size", "64x64", "--timeout",
                        str(args_timeout), "-o", png], timeout=args_timeout + 60)
    result["render"] = code
    result["rendered"] = os.path.exists(png)
    result["render_error"] = first_error(output)
    return result


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("corpus")
    parser.add_argument("--limit", type=int, default=0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--title", default="")
    parser.add_argument("--render-timeout", type=int, default=60)
    args = parser.parse_args()
    global args_timeout
    args_timeout = args.render_timeout
    records = []
    with open(args.corpus) as corpus:
        for line in corpus:
            record = json.loads(line)
            if len(record.get("passes", [])) > 1:
                records.append(record)
    if args.limit:
        records = records[:args.limit]
    with tempfile.TemporaryDirectory() as work:
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            results = list(pool.map(lambda r: measure(args.binary, r, work), records))
    results.sort(key=lambda r: r["id"])
    n = len(results)
    count = lambda f: sum(1 for r in results if f(r))
    print("# %s" % (args.title or "Multipass projects through the JSON input"))
    print()
    print("| step | projects |")
    print("|---|---|")
    print("| multipass projects | %d (%d passes) |" % (n, sum(r["passes"] for r in results)))
    print("| check exit 0 / 1 (findings) | %d / %d |" % (count(lambda r: r["check"] == 0),
                                                       count(lambda r: r["check"] == 1)))
    print("| check exit 2, 3, timeout or internal/* | %d |" % count(
        lambda r: r["check"] not in (0, 1) or r["check_internal"]))
    print("| port exit 0 / 1 | %d / %d |" % (count(lambda r: r["port"] == 0),
                                            count(lambda r: r["port"] == 1)))
    print("| ported passes written / compile in glslangValidator | %d / %d |" % (
        sum(r["ported_passes"] for r in results), sum(r["ported_compile"] for r in results)))
    print("| projects whose every ported pass compiles | %d |" % count(
        lambda r: r["ported_passes"] > 0 and r["ported_compile"] == r["ported_passes"]))
    print("| page written (--emit html) | %d |" % count(lambda r: r["page"]))
    print("| render drew a picture | %d |" % count(lambda r: r["rendered"]))
    print("| render exit 2, 3 or timeout | %d |" % count(lambda r: r["render"] not in (0, 1)))
    print()
    failing = [r for r in results if not r["rendered"] or r["check"] not in (0, 1)
               or r["ported_compile"] != r["ported_passes"] or r["check_internal"]]
    if failing:
        print("## Projects that did not go all the way, and why")
        print()
        print("| id | check | port (compiled/written) | render | first error |")
        print("|---|---|---|---|---|")
        for r in failing:
            why = r["render_error"] or r["port_error"] or r["check_error"]
            print("| %s | %s | %s (%d/%d) | %s | %s |" % (
                r["id"], r["check"], r["port"], r["ported_compile"], r["ported_passes"],
                r["render"], why.replace("|", "\\|")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
