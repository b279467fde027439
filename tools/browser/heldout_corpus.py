#!/usr/bin/env python3
"""Build a JSONL corpus of permissively licensed ShaderToy shaders that are NOT in ../shared.

Measurements must also hold on shaders the project was not given. The shared corpus
(../shared/corpus-shadertoy/permissive.jsonl) comes from the Shadertoys dataset
(github.com/Vipitis/shadertoys-dataset, commit 7a5d340, data/annotated/*.jsonl) with a
fixed 30 % held back. This script reads a checkout of that dataset, keeps the records
whose license field allows reuse (the shared corpus's policy: MIT, CC0, public domain,
Unlicense, Apache-2.0, CC-BY(-SA) 3.0/4.0, BSD; `A OR B` when one side is allowed, `A AND B`
when both are) and whose id is not in the shared corpus, and writes them in the shared
corpus's format (id, url, name, author, license, passes[] with type/name/code/inputs).
Each record keeps its license and author; the output is for measuring, not for shipping.

Run:
  python3 tools/browser/heldout_corpus.py --dataset GIT_DIR --shared ../shared/corpus-shadertoy/permissive.jsonl -o heldout.jsonl
GIT_DIR is a clone (or bare mirror) of the dataset; files are read with `git show HEAD:...`.
Python 3 standard library only.
"""

import argparse
import json
import subprocess

ALLOWED = {"mit", "cc0-1.0", "public-domain", "unlicense", "apache-2.0", "cc-by-3.0", "cc-by-4.0",
           "cc-by-sa-3.0", "cc-by-sa-4.0", "bsd-new", "bsd-simplified", "bsd-2-clause",
           "bsd-3-clause"}
BUFFERS = [("buffer_a", "Buffer A"), ("buffer_b", "Buffer B"), ("buffer_c", "Buffer C"),
           ("buffer_d", "Buffer D")]


def permissive(license_text):
    if not license_text:
        return False
    if " OR " in license_text:
        return any(permissive(part.strip()) for part in license_text.split(" OR "))
    if " AND " in license_text:
        return all(permissive(part.strip()) for part in license_text.split(" AND "))
    return license_text.strip().lower() in ALLOWED


def git(dataset, *args):
    """Standard output, or None when git fails (a mirror may lack its largest blobs)."""
    proc = subprocess.run(["git", "-C", dataset, *args], capture_output=True, text=True)
    return proc.stdout if proc.returncode == 0 else None


def to_record(raw):
    record = {"id": raw["id"], "url": "https://www.shadertoy.com/view/" + raw["id"],
              "name": raw.get("name"), "author": raw.get("author"), "license": raw.get("license"),
              "passes": []}
    if raw.get("common_code"):
        record["passes"].append({"type": "common", "name": "Common", "code": raw["common_code"],
                                 "inputs": []})
    for key, name in BUFFERS:
        if raw.get(key + "_code"):
            record["passes"].append({"type": "buffer", "name": name, "code": raw[key + "_code"],
                                     "inputs": raw.get(key + "_inputs") or []})
    record["passes"].append({"type": "image", "name": "Image", "code": raw["image_code"],
                             "inputs": raw.get("image_inputs") or []})
    return record


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dataset", required=True, help="git directory of the Shadertoys dataset")
    ap.add_argument("--shared", required=True, help="the shared permissive.jsonl (ids to leave out)")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()
    with open(args.shared, encoding="utf-8") as f:
        shared = {json.loads(line)["id"] for line in f if line.strip()}
    files = sorted(p for p in (git(args.dataset, "ls-tree", "-r", "HEAD", "--name-only") or "").split()
                   if p.startswith("data/annotated/") and p.endswith(".jsonl"))
    seen, records = set(), []
    for path in files:
        text = git(args.dataset, "show", "HEAD:" + path)
        if text is None:
            print("skipped (not readable): %s" % path)
            continue
        for line in text.splitlines():
            try:
                raw = json.loads(line)
            except ValueError:
                continue
            if raw["id"] in shared or raw["id"] in seen or not permissive(raw.get("license")):
                continue
            seen.add(raw["id"])
            records.append(to_record(raw))
    records.sort(key=lambda r: r["id"])
    with open(args.output, "w", encoding="utf-8") as out:
        for record in records:
            out.write(json.dumps(record) + "\n")
    print("%d permissive records not in the shared corpus" % len(records))


if __name__ == "__main__":
    main()
