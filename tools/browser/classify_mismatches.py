#!/usr/bin/env python3
"""Sort render mismatches into float-precision ones and the rest, by experiment.

A picture that differs between `shaderport render` (llvmpipe) and Chromium (SwiftShader)
is either wrong (a semantic difference: shaderport must fix it) or chaotic: the shader
amplifies last-bit differences of float arithmetic (hash noise built on sin, fract of
large numbers, iterated maps), which no two GPUs agree on. This script tests each
mismatch for the second kind with two perturbations that change nothing a person could
see in a well-conditioned shader, rendering both with shaderport:

  sin/cos  every sin and cos gets its argument reduced to [0, 2*pi) first (a different
           but equally valid implementation of the same functions);
  time     iTime = 1 + 2^-20 instead of 1 (one part in a million);
  fract    every fract(x) becomes fract(x * 1.0000001) (a last-bit change: hashes built
           on fract, "hash without sine", and fused multiply-adds depend on it);
  bits     every floatBitsToInt/floatBitsToUint(x) gets x * 1.0000001 (hashes of the exact
           IEEE bits of a float, which any rounding difference changes).

If either perturbation alone moves shaderport's own picture beyond the comparison
tolerance (8x8 block means, 12/255), the picture depends on float precision and the
mismatch is classified `precision (sin/cos)`, `precision (iTime)`, `precision (fract)` or
`precision (float bits)`.

A third experiment looks for NaN: pow, log, log2, sqrt and inversesqrt get abs() of
their argument (so no NaN arises from a negative one). When shaderport's picture of
that variant matches Chromium's, the difference came from how NaN travels through
later arithmetic (llvmpipe folds x * 0.0 to 0 and clamps NaN differently from
SwiftShader; GLSL leaves all of it undefined): `NaN (undefined math)`. Everything else
is `unexplained` and needs a look by hand, except when shaderport's own render reported
NaN pixels (render/nan-or-inf): then `NaN (reported by render)`, since browsers draw NaN in
a GPU-dependent colour and the render already warns about it.

Every variant is drawn at the iTime, iFrame and iMouse the measurement used (from
DIR/summary.json). Causes shown by hand (an experiment in the report's notes) come in with
--by-hand and are not classified again.

Run (from the repository root), after measure_render_parity.py --keep DIR:
  python3 tools/browser/classify_mismatches.py --keep DIR --report REPORT.md -o causes.json
The output maps id -> cause (JSON), usable as measure_render_parity.py --causes.
Python 3 standard library only.
"""

import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare_pictures  # noqa: E402

# Defined before the macros, so the functions call the real built-ins.
REDUCED_TRIG = "".join(
    "%s shaderport_%s(%s x) { return %s(x - 6.28318530718 * floor(x / 6.28318530718)); }\n"
    % (t, f, t, f) for f in ("sin", "cos") for t in ("float", "vec2", "vec3", "vec4")
) + "#define sin shaderport_sin\n#define cos shaderport_cos\n"


NAN_FREE = "".join(
    "%s shaderport_%s(%s x) { return %s(abs(x)); }\n" % (t, f, t, f)
    for f in ("log", "log2", "sqrt", "inversesqrt") for t in ("float", "vec2", "vec3", "vec4")
) + "".join(
    "%s shaderport_pow(%s x, %s y) { return pow(abs(x), y); }\n" % (t, t, t)
    for t in ("float", "vec2", "vec3", "vec4")
) + "".join("#define %s shaderport_%s\n" % (f, f) for f in ("log", "log2", "sqrt", "inversesqrt", "pow"))


def with_prelude(code, prelude):
    """The Image code with `prelude` after any #version/#extension lines."""
    lines = code.split("\n")
    insert = 0
    for i, line in enumerate(lines):
        if re.match(r"\s*#\s*(version|extension)\b", line):
            insert = i + 1
    return "\n".join(lines[:insert] + [prelude] + lines[insert:])


PERTURBED_FRACT = "".join(
    "%s shaderport_fract(%s x) { return fract(x * 1.0000001); }\n" % (t, t)
    for t in ("float", "vec2", "vec3", "vec4")
) + "#define fract shaderport_fract\n"


PERTURBED_BITS = "".join(
    "%s shaderport_%s(%s x) { return %s(x * 1.0000001); }\n" % (r, f, t, f)
    for f, base in (("floatBitsToInt", "int"), ("floatBitsToUint", "uint"))
    for t, r in (("float", base), ("vec2", base[0] + "vec2" if base == "uint" else "ivec2"),
                 ("vec3", "uvec3" if base == "uint" else "ivec3"),
                 ("vec4", "uvec4" if base == "uint" else "ivec4"))
) + "#define floatBitsToInt shaderport_floatBitsToInt\n#define floatBitsToUint shaderport_floatBitsToUint\n"


def with_reduced_trig(code):
    return with_prelude(code, REDUCED_TRIG)


def render_once(binary, record, png, extra=()):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "record.json")
        with open(path, "w", encoding="utf-8") as f:
            json.dump(record, f)
        cmd = [binary, "render", "--hermetic", "--size", "64x64", *extra, path, "-o", png]
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120)
    return os.path.isfile(png)


def differs(a, b):
    if not (os.path.isfile(a) and os.path.isfile(b)):
        return None
    return not compare_pictures.compare_files(a, b)[0]


def input_arguments(inputs, time_scale=1.0):
    """render's options for the iTime, iFrame and iMouse the measurement drew with."""
    if not inputs:
        return ("--time=%r" % (1.0 * time_scale),) if time_scale != 1.0 else ()
    return ("--time=%r" % (inputs["time"] * time_scale), "--frame=%d" % inputs["frame"],
            "--mouse=" + ",".join(repr(v) for v in inputs["mouse"]))


def classify(job):
    binary, directory, inputs = job
    record_path = os.path.join(directory, "record.json")
    with open(record_path, encoding="utf-8") as f:
        record = json.load(f)
    base = os.path.join(directory, "classify-base.png")
    trig = os.path.join(directory, "classify-trig.png")
    time = os.path.join(directory, "classify-time.png")
    # Every variant is drawn at the inputs of the measurement (a random iTime with
    # --seed), not at render's default iTime 1, where the mismatch may not occur.
    at = input_arguments(inputs)

    def render(binary_, record_, png, extra=()):
        return render_once(binary_, record_, png, tuple(extra) or at)

    render(binary, record, base)
    perturbed = json.loads(json.dumps(record))
    for p in perturbed["passes"]:
        p["code"] = with_reduced_trig(p["code"])
    render(binary, perturbed, trig)
    render(binary, record, time, input_arguments(inputs, 1.0 + 2.0 ** -20))
    if differs(base, trig):
        return "precision (sin/cos)"
    if differs(base, time):
        return "precision (iTime)"
    fract = json.loads(json.dumps(record))
    for p in fract["passes"]:
        p["code"] = with_prelude(p["code"], PERTURBED_FRACT)
    fract_png = os.path.join(directory, "classify-fract.png")
    render(binary, fract, fract_png)
    if differs(base, fract_png):
        return "precision (fract)"
    if "floatBitsTo" in "".join(p["code"] for p in record["passes"]):
        bits = json.loads(json.dumps(record))
        for p in bits["passes"]:
            p["code"] = with_prelude(p["code"], PERTURBED_BITS)
        bits_png = os.path.join(directory, "classify-bits.png")
        render(binary, bits, bits_png)
        if differs(base, bits_png):
            return "precision (float bits)"
    nan_free = json.loads(json.dumps(record))
    for p in nan_free["passes"]:
        p["code"] = with_prelude(p["code"], NAN_FREE)
    nan_png = os.path.join(directory, "classify-nan.png")
    render(binary, nan_free, nan_png)
    if differs(nan_png, os.path.join(directory, "chromium.png")) is False:
        return "NaN (undefined math)"
    if not os.path.isfile(base):
        return "shaderport failed"
    output = os.path.join(directory, "shaderport.txt")
    if os.path.isfile(output):
        with open(output, encoding="utf-8", errors="replace") as f:
            if "[render/nan-or-inf]" in f.read():
                return "NaN (reported by render)"
    return "unexplained"


def mismatch_ids(report):
    ids = []
    in_table = False
    with open(report, encoding="utf-8") as f:
        for line in f:
            if line.startswith("## "):
                in_table = line.strip() == "## Mismatches"
            m = re.match(r"\| \[(\w+)\]", line)
            if in_table and m:
                ids.append(m.group(1))
    return ids


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--keep", required=True, help="the --keep DIR of measure_render_parity.py")
    ap.add_argument("--report", required=True, help="its Markdown report (the mismatch table)")
    ap.add_argument("--shaderport", default="build/release/shaderport", help="shaderport binary")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--by-hand", help="JSON {id: cause} of causes shown by hand (an experiment "
                    "written down in the report's notes); these ids are not classified again")
    ap.add_argument("-o", "--output", required=True, help="JSON {id: cause}")
    args = ap.parse_args()
    ids = mismatch_ids(args.report)
    by_hand = {}
    if args.by_hand:
        with open(args.by_hand, encoding="utf-8") as f:
            by_hand = json.load(f)
    inputs = {}
    summary = os.path.join(args.keep, "summary.json")
    if os.path.isfile(summary):
        with open(summary, encoding="utf-8") as f:
            inputs = {entry["id"]: entry.get("inputs") for entry in json.load(f)}
    left = [i for i in ids if i not in by_hand]
    jobs = [(os.path.abspath(args.shaderport), os.path.join(args.keep, i), inputs.get(i)) for i in left]
    with concurrent.futures.ProcessPoolExecutor(max_workers=args.jobs) as pool:
        causes = dict(zip(left, pool.map(classify, jobs)))
    causes.update({i: by_hand[i] for i in ids if i in by_hand})
    with open(args.output, "w", encoding="utf-8") as f:
        json.dump(causes, f, indent=1, sort_keys=True)
        f.write("\n")
    counts = {}
    for cause in causes.values():
        counts[cause] = counts.get(cause, 0) + 1
    for cause, n in sorted(counts.items(), key=lambda x: -x[1]):
        print("%4d  %s" % (n, cause))


if __name__ == "__main__":
    main()
