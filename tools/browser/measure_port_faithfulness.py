#!/usr/bin/env python3
"""Check that `shaderport port` keeps the picture: the port drawn in Chromium = the site.

For every record kept by measure_render_parity.py (--keep DIR: DIR/<id>/record.json and
DIR/<id>/chromium.png, the site's composition drawn in Chromium), the Image pass is
ported to a WebGL2 fragment shader with `shaderport port`, drawn as it is in headless
Chromium with the same uniforms (tools/browser/shadertoy_reference.py), and compared
with the site's picture by 8x8 block means (12/255, tools/browser/compare_pictures.py).
Prints the counts and every id whose port differs or does not compile in Chromium.

Run (from the repository root):
  python3 tools/browser/measure_port_faithfulness.py --keep DIR --shaderport build/release/shaderport
Python 3 standard library only; needs chromium.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare_pictures  # noqa: E402
import pngio  # noqa: E402
import shadertoy_reference  # noqa: E402


def port(binary, code):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "image.glsl")
        with open(path, "w", encoding="utf-8") as f:
            f.write(code)
        proc = subprocess.run([binary, "port", path], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, timeout=120)
    return proc.stdout.decode("utf-8", "replace") if proc.returncode == 0 else None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--keep", required=True, help="the --keep DIR of measure_render_parity.py")
    ap.add_argument("--shaderport", default="build/release/shaderport")
    args = ap.parse_args()
    ids = sorted(i for i in os.listdir(args.keep)
                 if os.path.isfile(os.path.join(args.keep, i, "chromium.png")))
    jobs, not_ported = [], []
    for i in ids:
        with open(os.path.join(args.keep, i, "record.json"), encoding="utf-8") as f:
            record = json.load(f)
        image = [p for p in record["passes"] if p.get("type") == "image"][0]
        ported = port(os.path.abspath(args.shaderport), image["code"])
        if ported is None:
            not_ported.append(i)
            continue
        jobs.append({"key": i, "fragment": ported, "meta": {"id": i}})
    out_dir = tempfile.mkdtemp(prefix="port-faithfulness-")
    results = shadertoy_reference.render_jobs(jobs)
    same, differ, failed = 0, [], []
    for job in jobs:
        result = results.get(job["key"], {})
        if result.get("status") != "ok":
            failed.append((job["key"], result.get("status")))
            continue
        png = os.path.join(out_dir, job["key"] + ".png")
        pngio.write_png(png, result["width"], result["height"], result["rgba"])
        comparison = compare_pictures.compare_files(png, os.path.join(args.keep, job["key"], "chromium.png"))
        if comparison[0]:
            same += 1
        else:
            differ.append((job["key"], round(comparison[1], 1)))
    print("records with the site's picture: %d" % len(ids))
    print("ported: %d (port failed: %d %s)" % (len(jobs), len(not_ported), not_ported))
    print("port drawn in Chromium = site's picture: %d of %d" % (same, len(jobs)))
    print("port differs: %d %s" % (len(differ), differ))
    print("port did not draw in Chromium: %d %s" % (len(failed), failed))


if __name__ == "__main__":
    main()
