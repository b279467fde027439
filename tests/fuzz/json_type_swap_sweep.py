#!/usr/bin/env python3
"""Type-swap sweep of a ShaderToy JSON document through the real binary.

Every value of the document is replaced, one at a time, by values of other types
(the mutations of tests/fuzz/json_mutations.h: a type swap, a removed member, a
wrong shape), and each mutant is given to the commands. Counts exit codes and
signals per command; an exit 3 (internal error), a signal or a timeout is a bug.

  tests/fuzz/json_type_swap_sweep.py BINARY DOCUMENT [--commands check,render] [--limit N]
"""
import argparse
import collections
import json
import os
import subprocess
import sys
import tempfile

SWAPS = ["0", 0, -1, 4, 1.5, True, None, [], {}]


def pointers(value, at=()):
    if isinstance(value, dict):
        for key, member in value.items():
            yield at + (key,)
            yield from pointers(member, at + (key,))
    elif isinstance(value, list):
        for i, member in enumerate(value):
            yield at + (i,)
            yield from pointers(member, at + (i,))


def mutants(document):
    for at in pointers(document):
        parent_at, last = at[:-1], at[-1]
        def with_value(change):
            copy = json.loads(json.dumps(document))
            parent = copy
            for step in parent_at:
                parent = parent[step]
            change(parent, last)
            return copy
        original = json.dumps(document)
        for swap in SWAPS:
            def put(parent, key, swap=swap):
                parent[key] = swap
            mutated = with_value(put)
            if json.dumps(mutated) != original:
                yield "swap", at, mutated
        yield "shape", at, with_value(lambda p, k: p.__setitem__(k, [p[k]]))
        if isinstance(last, str):
            yield "remove", at, with_value(lambda p, k: p.pop(k))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("document")
    parser.add_argument("--commands", default="check,render")
    parser.add_argument("--limit", type=int, default=0)
    args = parser.parse_args()
    document = json.load(open(args.document))
    commands = {
        "check": ["check", "--no-cache", "DOC"],
        "render": ["render", "--hermetic", "DOC"],
        "fix": ["fix", "--diff", "DOC"],
        "port": ["port", "--out-dir", "OUT", "DOC"],
        "report": ["report", "--hermetic", "--html", "OUT/r.html", "DOC"],
    }
    outcomes = collections.defaultdict(collections.Counter)
    bad = []
    runs = 0
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "mutant.json")
        out = os.path.join(work, "out")
        for index, (kind, at, mutated) in enumerate(mutants(document)):
            if args.limit and index >= args.limit:
                break
            with open(path, "w") as f:
                json.dump(mutated, f)
            for name in args.commands.split(","):
                os.makedirs(out, exist_ok=True)
                argv = [args.binary] + [path if w == "DOC" else w.replace("OUT", out)
                                        for w in commands[name]]
                runs += 1
                try:
                    done = subprocess.run(argv, capture_output=True, timeout=60)
                    code = done.returncode
                except subprocess.TimeoutExpired:
                    code = "timeout"
                outcomes[name][code] += 1
                if code == 3 or code == "timeout" or (isinstance(code, int) and code < 0):
                    bad.append((name, kind, "/" + "/".join(map(str, at)), code))
    print(f"{runs} runs of {args.document}")
    for name, counts in sorted(outcomes.items()):
        print(f"  {name}: " + ", ".join(f"exit {k}: {v}" for k, v in sorted(counts.items(), key=str)))
    print(f"  internal errors, signals or timeouts: {len(bad)}")
    for entry in bad[:10]:
        print("   ", *entry)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
