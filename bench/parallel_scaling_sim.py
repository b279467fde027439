#!/usr/bin/env python3
"""How `check -j N` would scale on a machine with more cores than this one, by simulating
its work split on measured per-file costs. Run on demand (issue: speed), never in CI.

  bench/parallel_scaling_sim.py [-n PASSES] [--max-jobs 32] BINARY

One `check -j 1 --no-cache` run over the passes (as bench/check_vs_glslang.sh prepares
them) under callgrind, dumping a profile at the start of every file, gives the
instructions of each file, of the start-up and of the end (output and exit; an empty
file is checked last so that the end holds no real file). ParallelFor hands the files
out one at a time in input order to whichever job asks first, so the simulation gives
each file, in order, to the job that becomes free first. glslang builds its built-in
tables for a language version and stage once per process, under a lock: the first file
of each pair carries that work, so its excess over the median file counts as serial.

Printed for N jobs: the simulated speed-up over one job and its efficiency (speed-up / N).
Instruction counts stand in for time: the simulation knows nothing of memory bandwidth
or caches shared between cores, so real machines do worse than it says as N grows.
"""
import argparse
import glob
import heapq
import os
import shutil
import statistics
import subprocess
import sys
import tempfile


def dump_totals(prefix):
    """(part number, total instructions) of every callgrind dump written under `prefix`."""
    parts = []
    for path in glob.glob(prefix + "*"):
        part = 0
        total = None
        with open(path, encoding="utf-8", errors="replace") as dump:
            for line in dump:
                if line.startswith("part:"):
                    part = int(line.split()[1])
                elif line.startswith("totals:"):
                    total = int(line.split()[1])
                    break
        if total is not None:
            parts.append((part, total))
    return [total for _, total in sorted(parts)]


def simulate(costs, jobs):
    """Makespan of giving `costs`, in order, each to the job that is free first."""
    free_at = [0] * jobs
    heapq.heapify(free_at)
    for cost in costs:
        heapq.heappush(free_at, heapq.heappop(free_at) + cost)
    return max(free_at)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("binary")
    parser.add_argument("-n", "--passes", type=int, default=1000)
    parser.add_argument("--max-jobs", type=int, default=32)
    args = parser.parse_args()
    if shutil.which("valgrind") is None:
        sys.exit("parallel_scaling_sim: needs valgrind (tools/install-deps.sh --bench)")
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    shared = os.environ.get("SHADERPORT_SHARED_DIR", os.path.join(root, "..", "shared"))
    jsonl = os.path.join(shared, "corpus-shadertoy", "permissive.jsonl")
    work = tempfile.mkdtemp(prefix="shaderport-scaling.")
    try:
        subprocess.run([sys.executable, os.path.join(here, "prepare_inputs.py"), root, jsonl,
                        str(args.passes), os.path.join(work, "in")], check=True,
                       stdout=subprocess.DEVNULL)
        with open(os.path.join(work, "in", "files.tsv"), encoding="utf-8") as table:
            files = [line.split("\t")[0] for line in table if line.strip()]
        empty = os.path.join(work, "last-empty.glsl")
        open(empty, "w", encoding="utf-8").close()
        prefix = os.path.join(work, "callgrind.out")
        subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + prefix,
                        "--dump-before=shaderport::driver::CheckFile*", args.binary, "check",
                        "-j", "1", "--no-cache", *files, empty],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
        totals = dump_totals(prefix)
        sizes = [os.path.getsize(path) for path in files]
    finally:
        shutil.rmtree(work, ignore_errors=True)
    # Dump 1 ends where the first file starts; dump k + 1 holds file k; the last dump,
    # written at exit, holds the empty file, the output and the exit.
    if len(totals) != len(files) + 2:
        sys.exit(f"parallel_scaling_sim: {len(totals)} profiles for {len(files)} files")
    start, costs, end = totals[0], totals[1:-1], totals[-1]
    median = statistics.median(costs)
    # The built-in tables: the first file's excess over the median (the other version and
    # stage pairs are rare in the corpus and stay in their files' costs).
    tables = max(0, costs[0] - median)
    costs = [costs[0] - tables] + costs[1:]
    serial = start + tables + end
    one = serial + sum(costs)
    print(f"{len(files)} files; instructions: start-up {start / 1e6:.1f} M, built-in tables "
          f"{tables / 1e6:.1f} M, files {sum(costs) / 1e6:.1f} M (median {median / 1e6:.2f} M, "
          f"largest {max(costs) / 1e6:.1f} M), end {end / 1e6:.1f} M")
    # The same files handed out largest first (by bytes, which the driver knows before
    # it starts): the alternative to input order that a long last file cannot spoil.
    by_size = [cost for _, cost in sorted(zip(sizes, costs), key=lambda pair: -pair[0])]
    print(f"{'jobs':>5} {'speed-up':>9} {'efficiency':>11} {'largest first':>14}")
    jobs = 1
    while jobs <= args.max_jobs:
        speedup = one / (serial + simulate(costs, jobs))
        largest_first = one / (serial + simulate(by_size, jobs))
        print(f"{jobs:>5} {speedup:>9.2f} {speedup / jobs:>10.0%} {largest_first:>9.2f} "
              f"({largest_first / jobs:.0%})")
        jobs *= 2


if __name__ == "__main__":
    main()
