#!/usr/bin/env python3
"""Mutation sweep: real ShaderToy passes, each mutated once (a character deleted, a '}'
deleted, a line duplicated or two words swapped), through `check`, `fix --diff` and
`port -o` and, for the first --heavy of them, `port --emit spirv --opt O` and `render`,
under the 2 GiB address-space cap the tests use. Counts exit codes; lists every exit 3,
signal and hang with its internal/* messages.

  tools/soak/mutation_sweep.py --shaderport BIN --shadertoy passes.jsonl [-n 300] [--heavy N]
                               [--seed 7] [-j 2]
"""
import argparse
import collections
import concurrent.futures
import json
import os
import random
import subprocess
import tempfile


def mutate(code, rng):
    op = rng.choice(["del_char", "del_brace", "dup_line", "swap_words"])
    if op == "del_char" and code:
        k = rng.randrange(len(code))
        return code[:k] + code[k + 1:]
    if op == "del_brace":
        braces = [k for k, ch in enumerate(code) if ch == "}"]
        if braces:
            k = rng.choice(braces)
            return code[:k] + code[k + 1:]
    if op == "dup_line":
        lines = code.split("\n")
        k = rng.randrange(len(lines))
        lines.insert(k, lines[k])
        return "\n".join(lines)
    words = code.split(" ")
    if len(words) > 2:
        k = rng.randrange(len(words) - 1)
        words[k], words[k + 1] = words[k + 1], words[k]
    return " ".join(words)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shaderport", required=True)
    parser.add_argument("--shadertoy", required=True)
    parser.add_argument("-n", type=int, default=300)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--heavy", type=int, default=None,
                        help="passes also given to port --emit spirv --opt O and render "
                             "(default: all)")
    parser.add_argument("-j", "--jobs", type=int, default=1)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    passes = []
    with open(args.shadertoy) as records:
        for line in records:
            for p in json.loads(line).get("passes", []):
                if p.get("type") in ("image", "buffer") and p.get("code"):
                    passes.append(p["code"])
    rng.shuffle(passes)
    heavy = args.n if args.heavy is None else args.heavy
    counts = collections.Counter()
    problems = []
    with tempfile.TemporaryDirectory() as work:
        jobs = []
        for i, code in enumerate(passes[: args.n]):
            path = os.path.join(work, f"m{i}.glsl")
            with open(path, "w") as f:
                f.write(mutate(code, rng))
            commands = [("check", ["check", "--no-cache", path]),
                        ("fix --diff", ["fix", "--diff", path]),
                        ("port -o", ["port", "-o", path + ".out", path])]
            if i < heavy:
                commands += [("port --emit spirv --opt O",
                              ["port", "--emit", "spirv", "--opt", "O", "-o", path + ".spv", path]),
                             ("render", ["render", "--size", "32x32", "-o", path + ".png", path])]
            jobs += [(label, command, i) for label, command in commands]

        def run(job):
            label, command, i = job
            try:
                done = subprocess.run(["prlimit", "--as=2147483648", args.shaderport] + command,
                                      capture_output=True, text=True, timeout=120)
                return label, done.returncode, i, [l for l in done.stderr.splitlines()
                                                   if "internal/" in l]
            except subprocess.TimeoutExpired:
                return label, "hang", i, []

        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            for label, code_, i, internal in pool.map(run, jobs):
                counts[(label, code_)] += 1
                if code_ == 3 or code_ == "hang" or (isinstance(code_, int) and code_ < 0):
                    problems.append((label, code_, i, internal[:3]))
    print(f"{min(args.n, len(passes))} passes, seed {args.seed}")
    for (command, code_), n in sorted(counts.items(), key=str):
        print(f"{command}: exit {code_}: {n}")
    print(f"{len(problems)} problems (exit 3, signal or hang)")
    for problem in problems:
        print("  ", problem)


if __name__ == "__main__":
    main()
