#!/usr/bin/env python3
"""Records headless Chromium's compile verdict for every shader of a verdict folder
(tests/browser-verdicts): DIR/webgl1/* compiled in a WebGL1 context, DIR/webgl2/* in a
WebGL2 one, the stage from the extension (.vert vertex, anything else fragment). Writes
DIR/verdicts.json ({"webgl2/name.frag": {"compiled": bool, "log": "..."}}), the golden
file browser_verdicts_test compares `check` with. A `.glsl` file with a mainImage and no
main is a ShaderToy Image pass: it is compiled as the site composes it
(shadertoy_reference.compose_image_pass). DIR/projects/NAME.json is a ShaderToy project
(a record with "passes", as in the Shadertoys dataset): each pass but Common is compiled
as the site composes it with Common (shadertoy_compose.compose_record), in a WebGL2
context, recorded as "projects/NAME.json#TAB", and the Common tab alone as the site
compiles it ("projects/NAME.json#Common"). Python standard library only.

  record_verdicts.py tests/browser-verdicts
  record_verdicts.py --add NAME --context 2 --stage fragment FILE tests/browser-verdicts
"""
import argparse
import json
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shadertoy_compose  # noqa: E402
import shadertoy_reference  # noqa: E402
from browser_compile import BrowserCompiler  # noqa: E402

_EXT = {"vertex": ".vert", "fragment": ".frag"}


def shaders(folder):
    for context in (1, 2):
        sub = os.path.join(folder, "webgl%d" % context)
        if not os.path.isdir(sub):
            continue
        for name in sorted(os.listdir(sub)):
            stage = "vertex" if name.endswith(".vert") else "fragment"
            yield "webgl%d/%s" % (context, name), context, stage


def project_passes(folder):
    """("projects/NAME.json#TAB", composed text) for every pass of every project."""
    sub = os.path.join(folder, "projects")
    if not os.path.isdir(sub):
        return
    for name in sorted(os.listdir(sub)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(sub, name), encoding="utf-8") as f:
            record = json.load(f)
        for tab, _, text in shadertoy_compose.compose_record(record):
            yield "projects/%s#%s" % (name, tab), text
        common = shadertoy_compose.compose_common_tab(record)
        if common is not None:
            yield "projects/%s#Common" % name, common


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder")
    parser.add_argument("--add", metavar="NAME", help="copy FILE in as NAME first")
    parser.add_argument("--context", type=int, choices=(1, 2), default=2)
    parser.add_argument("--stage", choices=sorted(_EXT), default="fragment")
    parser.add_argument("file", nargs="?")
    parser.add_argument("--chromium")
    args = parser.parse_args(argv)
    if args.add:
        target = os.path.join(args.folder, "webgl%d" % args.context, args.add + _EXT[args.stage])
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(args.file, target)
    entries = list(shaders(args.folder))
    jobs = []
    for path, context, stage in entries:
        with open(os.path.join(args.folder, path), encoding="utf-8", errors="surrogateescape") as f:
            source = f.read()
        if path.endswith(".glsl") and "mainImage" in source and \
                not re.search(r"\bvoid\s+main\s*\(", source):
            source = shadertoy_reference.compose_image_pass(source)
        jobs.append({"source": source, "stage": stage, "context": context})
    for path, source in project_passes(args.folder):
        entries.append((path, 2, "fragment"))
        jobs.append({"source": source, "stage": "fragment", "context": 2})
    compiler = BrowserCompiler(args.chromium)
    try:
        results = compiler.compile(jobs)
        version = compiler.version
    finally:
        compiler.close()
    verdicts = {}
    for (path, _, _), (ok, log) in zip(entries, results):
        if ok is None:
            raise SystemExit("record_verdicts: Chromium gave no verdict for %s: %s" % (path, log))
        verdicts[path] = {"compiled": ok, "log": log.strip()}
    with open(os.path.join(args.folder, "verdicts.json"), "w", encoding="utf-8") as f:
        json.dump(verdicts, f, indent=1, sort_keys=True, ensure_ascii=False)
        f.write("\n")
    print("record_verdicts: %d shaders, %d compiled, %s" %
          (len(verdicts), sum(v["compiled"] for v in verdicts.values()), version))
    return 0


if __name__ == "__main__":
    sys.exit(main())
