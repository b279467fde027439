#!/usr/bin/env python3
"""Writes the benchmark inputs for compare_glslang.sh into OUT_DIR.

  raw/      files as a user would pass them to `shaderport check`: the corpus files as they are,
            then the first N ShaderToy image/buffer passes (Common prepended, as the site does)
  wrapped/  the same shaders made whole for glslangValidator (site header, harness header)
  files.tsv raw path, wrapped path (one line per input)
  ATTRIBUTION.tsv  id, author, license, url of every ShaderToy shader used (their licenses
            require attribution; keep it with the files)

Usage: prepare_inputs.py SOURCE_DIR SHADERTOY_JSONL COUNT OUT_DIR
"""
import csv
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shadertoy_wrap  # noqa: E402

_HARNESS_HEADER = ("#version 300 es\nprecision highp float;\nin vec2 uv;\nuniform float time;\n"
                   "out vec4 color;\n#line 1 0\n")


def write(path, text):
  os.makedirs(os.path.dirname(path), exist_ok=True)
  with open(path, "w") as f:
    f.write(text)


def corpus_inputs(source_dir, out_dir):
  corpus = os.path.join(source_dir, "corpus")
  rows = []
  with open(os.path.join(corpus, "MANIFEST")) as f:
    for row in csv.DictReader(f, delimiter="\t"):
      with open(os.path.join(corpus, row["path"])) as src:
        text = src.read()
      raw = os.path.join(out_dir, "raw", "corpus", row["path"])
      write(raw, text)
      base = os.path.join(out_dir, "wrapped", "corpus", row["path"])
      if row["dialect"] == "shadertoy":
        wrapped, text = base + ".frag", shadertoy_wrap.wrap(text)
      elif row["dialect"] == "raymarch-harness":
        wrapped, text = base + ".frag", _HARNESS_HEADER + text
      else:
        wrapped = base  # already .vert / .frag
      write(wrapped, text)
      rows.append((raw, wrapped))
  return rows


def shadertoy_inputs(jsonl, count, out_dir):
  rows, credits = [], []
  with open(jsonl) as f:
    for line in f:
      if len(rows) >= count:
        break
      shader = json.loads(line)
      common = "".join(p["code"] for p in shader["passes"] if p["type"] == "common")
      used = False
      for p in shader["passes"]:
        if p["type"] not in ("image", "buffer") or len(rows) >= count:
          continue
        ctypes = [""] * 4
        for channel in p.get("inputs", []):
          if 0 <= int(channel.get("channel", -1)) < 4:
            ctypes[int(channel["channel"])] = channel.get("ctype", "")
        name = "st-%s-%s" % (shader["id"], re.sub(r"[^a-z0-9]+", "-", p["name"].lower()))
        raw = os.path.join(out_dir, "raw", "shadertoy", name + ".glsl")
        write(raw, (common + "\n" if common else "") + p["code"])
        wrapped = os.path.join(out_dir, "wrapped", "shadertoy", name + ".frag")
        write(wrapped, shadertoy_wrap.wrap(p["code"], common, ctypes))
        rows.append((raw, wrapped))
        used = True
      if used:
        credits.append((shader["id"], shader["author"], shader["license"], shader["url"]))
  return rows, credits


def main():
  if len(sys.argv) != 5:
    sys.exit(__doc__)
  source_dir, jsonl, count, out_dir = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
  rows = corpus_inputs(source_dir, out_dir)
  st_rows, credits = shadertoy_inputs(jsonl, count, out_dir)
  with open(os.path.join(out_dir, "files.tsv"), "w") as f:
    for raw, wrapped in rows + st_rows:
      f.write("%s\t%s\n" % (raw, wrapped))
  with open(os.path.join(out_dir, "ATTRIBUTION.tsv"), "w") as f:
    f.write("id\tauthor\tlicense\turl\n")
    for credit in credits:
      f.write("\t".join(credit) + "\n")
  print("%d corpus files, %d ShaderToy passes from %d shaders" %
        (len(rows), len(st_rows), len(credits)))


if __name__ == "__main__":
  main()
