#!/usr/bin/env python3
"""Draws a random sample of ShaderToy records from the whole Shadertoys dataset (every
licence), for measurements on shaders the project was not given: records in the shared
corpus are left out, and the seed is printed. Records of shaders under a restrictive
licence keep their code only in the output file (a measurement input under /tmp, never
committed) and lose their name and author, so that a report built from them can show
their id alone.

  python3 tools/browser/sample_dataset.py --dataset GIT_DIR --seed 5517 --count 300 \
      --image-only -o /tmp/sample.jsonl

--image-only keeps records whose only pass is an Image pass without inputs (what
measure_render_parity.py draws). Python 3 standard library only.
"""
import argparse
import json
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import heldout_corpus  # noqa: E402
import shadertoy_sweep  # noqa: E402

SHARED = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "shared",
                      "corpus-shadertoy", "permissive.jsonl")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--dataset", required=True, help="git directory of the Shadertoys dataset")
    ap.add_argument("--shared", default=SHARED, help="the shared corpus (left out)")
    ap.add_argument("--seed", type=int, required=True)
    ap.add_argument("--count", type=int, required=True)
    ap.add_argument("--image-only", action="store_true")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args(argv)
    shared = set()
    with open(args.shared, encoding="utf-8") as f:
        for line in f:
            try:
                shared.add(json.loads(line)["id"])
            except (ValueError, KeyError):
                continue
    pool = []
    for rid, rec in sorted(shadertoy_sweep.load_dataset(args.dataset).items()):
        passes = rec["passes"]
        if rid in shared or (args.image_only and (
                len(passes) != 1 or passes[0]["type"] != "image" or passes[0].get("inputs"))):
            continue
        pool.append(rec)
    picked = random.Random(args.seed).sample(pool, min(args.count, len(pool)))
    restricted = 0
    with open(args.output, "w", encoding="utf-8") as f:
        for rec in picked:
            if not heldout_corpus.permissive(rec.get("license")):
                rec = dict(rec, name="", author="", restricted=True,
                           url="https://www.shadertoy.com/view/" + rec["id"])
                restricted += 1
            f.write(json.dumps(rec) + "\n")
    print("sample_dataset: %d of %d eligible records, seed %d (%d under a restrictive licence)"
          % (len(picked), len(pool), args.seed, restricted), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
