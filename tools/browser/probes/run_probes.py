#!/usr/bin/env python3
"""Render the semantic probes in Chromium (and shaderport) and print their pixel values.

Each probe (tools/browser/probes/*.glsl: ShaderToy Image passes, composed as the site does;
*.frag: WebGL2 fragment shaders drawn as they are) lays its observations out in columns
8 pixels wide; the header comment of each probe says what each column shows. This script
prints the RGB bytes at the centre of every column's top half (PNG row 16) and bottom half
(row 48), for Chromium (SwiftShader) and, unless --no-shaderport, for `shaderport render`.

Run (from the repository root, after the release build):
  python3 tools/browser/probes/run_probes.py [--out-dir /tmp/probes] [--shaderport BIN]
Writes OUT/chromium/<probe>.png, OUT/shaderport/<probe>.png and prints a Markdown table.
"""

import argparse
import glob
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
import pngio  # noqa: E402
import shadertoy_reference  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
COLUMNS = 8
SIZE = 64


def sample(width, height, rgba, x, y):
    i = (y * width + x) * 4
    return tuple(rgba[i:i + 4])


def samples(width, height, rgba):
    out = []
    for half, y in (("top", 16), ("bottom", 48)):
        for col in range(COLUMNS):
            out.append((half, col, sample(width, height, rgba, col * 8 + 4, y)))
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description="Render the probes in Chromium and shaderport and "
                                             "print the pixel values per column.")
    ap.add_argument("--out-dir", default="/tmp/shaderport-probes")
    ap.add_argument("--shaderport", help="shaderport binary (default build/release/shaderport)")
    ap.add_argument("--no-shaderport", action="store_true")
    ap.add_argument("probes", nargs="*", help="probe files (default: all in this directory)")
    args = ap.parse_args(argv)
    files = args.probes or sorted(glob.glob(os.path.join(HERE, "*.glsl")) +
                                  glob.glob(os.path.join(HERE, "*.frag")))
    jobs = []
    for path in files:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        key = os.path.splitext(os.path.basename(path))[0]
        frag = text if path.endswith(".frag") else shadertoy_reference.compose_image_pass(text)
        jobs.append({"key": key, "fragment": frag, "path": path})
    os.makedirs(os.path.join(args.out_dir, "chromium"), exist_ok=True)
    os.makedirs(os.path.join(args.out_dir, "shaderport"), exist_ok=True)
    results = shadertoy_reference.render_jobs(jobs, SIZE, SIZE, 1.0, batch_size=len(jobs),
                                              log=lambda s: print(s, file=sys.stderr))
    binary = args.shaderport or os.path.join(REPO, "build", "release", "shaderport")
    print("| probe | half | column | Chromium RGBA | shaderport RGBA |")
    print("|---|---|---|---|---|")
    for job in jobs:
        key = job["key"]
        r = results[key]
        ch = None
        if r["status"] == "ok":
            pngio.write_png(os.path.join(args.out_dir, "chromium", key + ".png"), SIZE, SIZE, r["rgba"])
            ch = samples(SIZE, SIZE, r["rgba"])
        else:
            print("| %s | | | %s: %s | |" % (key, r["status"], " ".join(r.get("log", "").split())[:200]))
        sp = None
        if not args.no_shaderport:
            png = os.path.join(args.out_dir, "shaderport", key + ".png")
            if os.path.exists(png):
                os.remove(png)
            proc = subprocess.run([binary, "render", "--hermetic", "--size", "%dx%d" % (SIZE, SIZE),
                                   job["path"], "-o", png], stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT)
            with open(os.path.join(args.out_dir, "shaderport", key + ".txt"), "wb") as f:
                f.write(proc.stdout)
            if os.path.exists(png):
                sp = samples(*pngio.read_png(png))
        if ch is None:
            continue
        for idx, (half, col, px) in enumerate(ch):
            sp_px = sp[idx][2] if sp else None
            print("| %s | %s | %d | %s | %s |" % (key, half, col, px, sp_px if sp_px else "-"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
