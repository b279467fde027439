#!/usr/bin/env python3
"""Differential run of `shaderport check --target` against headless Chromium on mutants of
real shaders (tools/browser/README.md, "Differential run"). Prints its seed; writes every
disagreement, minimised, with the browser's log. Python standard library only.

  differential.py --count 20000 --out DIR              a campaign with a fresh seed
  differential.py --seed 7 --count 300 --max-false-accepts 0 --min-agreement 99.9
                                                      the bounded run CI makes
"""
import argparse
import collections
import json
import os
import random
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import minimise  # noqa: E402
import mutate  # noqa: E402
from stage_oracles import StageOracles, browser_message  # noqa: E402

ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))

# Where check departs from the browser on purpose (docs/browser-divergence.md, "Limits
# shaderport keeps"): such false rejects are counted apart and do not fail a run.
# Rule ids of limits shaderport keeps on purpose where Chromium goes further, counted
# apart from disagreements. None today: the parser's nesting limit is the browser's
# (docs/limits.md, "Nesting").
KNOWN_LIMITS = {}


def known_limit(verdict):
    return minimise.direction(verdict) == "false-reject" and \
        verdict["check_first"].split(":", 1)[0] in KNOWN_LIMITS


def draw(seeds, count, rng):
    mutants = []
    while len(mutants) < count:
        mutant = mutate.mutate(rng, rng.choice(seeds))
        if mutant is not None:
            mutants.append(mutant)
    return mutants


def tally(mutants, verdicts):
    stats = collections.Counter()
    by_family = collections.defaultdict(collections.Counter)
    for mutant, v in zip(mutants, verdicts):
        if v["browser"] is None or v["check"] is None:
            stats["unjudged"] += 1
            continue
        stats["judged"] += 1
        agree = v["browser"] == v["check"]
        stats["agree"] += agree
        kind = "known-limit" if known_limit(v) else minimise.direction(v)
        if kind:
            stats[kind] += 1
        family = mutant["family"] + (":" + mutant["edit"].split(":")[0].split()[1]
                                     if mutant["family"] == "insert" else "")
        by_family[family]["n"] += 1
        by_family[family]["agree"] += agree
        if "glslang" in v and v["glslang"] is not None and v["glslang"] != v["browser"]:
            stats["glslang-differs"] += 1
            stats["glslang-differs-check-follows"] += agree
        if "glslang" in v and v["glslang"] is not None:
            stats["glslang-judged"] += 1
            stats["glslang-agree"] += v["glslang"] == v["browser"]
    return stats, by_family


def percent(a, b):
    return 100.0 * a / b if b else 100.0


def write_report(out, args, seed, stats, by_family, found, elapsed, chromium):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "disagreements.jsonl"), "w", encoding="utf-8") as f:
        for entry in found:
            f.write(json.dumps(entry, ensure_ascii=False) + "\n")
    summary = {"seed": seed, "count": args.count, "chromium": chromium,
               "elapsed_s": round(elapsed, 1), "stats": dict(stats),
               "agreement_percent": round(percent(stats["agree"], stats["judged"]), 3),
               "families": {k: dict(v) for k, v in sorted(by_family.items())}}
    with open(os.path.join(out, "summary.json"), "w", encoding="utf-8") as f:
        json.dump(summary, f, indent=1, sort_keys=True)
    lines = ["# Differential run: `check --target` against Chromium", "",
             "Seed %d, %d mutants, %s, %.0f s." % (seed, args.count, chromium, elapsed), "",
             "| measure | value |", "|---|---|",
             "| judged by both | %d |" % stats["judged"],
             "| check = browser | %d (%.2f %%) |" % (stats["agree"], summary["agreement_percent"]),
             "| false accepts (browser rejects, check accepts) | %d |" % stats["false-accept"],
             "| false rejects (browser accepts, check rejects) | %d |" % stats["false-reject"],
             "| known limits (check rejects on purpose; disagreements that do not fail a run) | %d |" %
             stats["known-limit"]]
    if stats["glslang-judged"]:
        lines += ["| glslangValidator = browser | %.2f %% |" %
                  percent(stats["glslang-agree"], stats["glslang-judged"]),
                  "| where glslang and browser differ, check follows the browser | %d of %d (%.1f %%) |" %
                  (stats["glslang-differs-check-follows"], stats["glslang-differs"],
                   percent(stats["glslang-differs-check-follows"], stats["glslang-differs"]))]
    lines += ["", "| family | mutants | agree |", "|---|---|---|"]
    for family, c in sorted(by_family.items()):
        lines.append("| %s | %d | %.2f %% |" % (family, c["n"], percent(c["agree"], c["n"])))
    lines += ["", "## Disagreements (minimised)", ""]
    for entry in found:
        lines += ["### %s: %s" % (entry["direction"], entry["seed"]), "",
                  "%s; browser: %s; check: %s" % (entry["edit"][:200], entry["browser_first"] or "ok",
                                                   entry["check_first"] or "no error"), "",
                  "```glsl", entry["minimised"], "```", ""]
    with open(os.path.join(out, "summary.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return summary


def findings(bad, smallest):
    found = []
    for (mutant, verdict), (small, small_verdict) in zip(bad, smallest):
        found.append({"direction": minimise.direction(verdict), "seed": mutant["seed"],
                      "family": mutant["family"], "edit": mutant["edit"],
                      "stage": mutant["stage"], "context": mutant["context"],
                      "browser_first": browser_message(verdict["browser_log"]),
                      "check_first": verdict["check_first"], "minimised": small,
                      "minimised_browser_log": small_verdict["browser_log"],
                      "minimised_check_first": small_verdict["check_first"],
                      "mutant": mutant["source"]})
    return found


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, help="random seed (default: a fresh one, printed)")
    parser.add_argument("--count", type=int, default=1000, help="mutants to draw")
    parser.add_argument("--out", default="/tmp/shaderport-differential", help="report directory")
    parser.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"))
    parser.add_argument("--shaderport", default=os.path.join(ROOT, "build", "release", "shaderport"))
    parser.add_argument("--chromium")
    parser.add_argument("--no-glslang", action="store_true", help="skip glslangValidator's verdicts")
    parser.add_argument("--no-minimise", action="store_true")
    parser.add_argument("--minimise-budget", type=float, default=600,
                        help="seconds spent minimising (default 600)")
    parser.add_argument("--chunk", type=int, default=1000, help="mutants judged per batch")
    parser.add_argument("--max-false-accepts", type=int, help="fail (exit 1) above this many")
    parser.add_argument("--max-false-rejects", type=int, help="fail (exit 1) above this many")
    parser.add_argument("--min-agreement", type=float, help="fail (exit 1) below this percentage")
    args = parser.parse_args(argv)

    seed = args.seed if args.seed is not None else random.SystemRandom().randrange(1 << 31)
    print("differential: seed %d, %d mutants" % (seed, args.count), flush=True)
    rng = random.Random(seed)
    seeds = mutate.load_seeds(args.shared, os.path.join(ROOT, "corpus"))
    mutants = draw(seeds, args.count, rng)
    oracles = StageOracles(args.shaderport, args.chromium, with_glslang=not args.no_glslang)
    start = time.time()
    try:
        verdicts = []
        for at in range(0, len(mutants), args.chunk):
            verdicts.extend(oracles.judge(mutants[at:at + args.chunk], glslang=not args.no_glslang))
            print("differential: %d of %d judged (%.0f s)" % (len(verdicts), len(mutants),
                                                            time.time() - start), flush=True)
        stats, by_family = tally(mutants, verdicts)
        bad = [(m, v) for m, v in zip(mutants, verdicts)
               if minimise.direction(v) and not known_limit(v)]
        # The unminimised report first: a run cut short still leaves its findings.
        found = findings(bad, [(m["source"], v) for m, v in bad])
        summary = write_report(args.out, args, seed, stats, by_family, found, time.time() - start,
                               oracles.browser.version)
        if not args.no_minimise and bad:
            # One case a class (the shortest): the others of the class say nothing new.
            firsts = {}
            for i, (mutant, verdict) in enumerate(bad):
                key = minimise.class_key(verdict)
                if key not in firsts or len(mutant["source"]) < len(bad[firsts[key]][0]["source"]):
                    firsts[key] = i
            chosen = sorted(firsts.values())
            smallest = minimise.minimise(oracles, [bad[i] for i in chosen],
                                         budget_s=args.minimise_budget,
                                         log=lambda s: print("differential: " + s, flush=True))
            results = [(m["source"], v) for m, v in bad]
            for i, result in zip(chosen, smallest):
                results[i] = result
            found = findings(bad, results)
            summary = write_report(args.out, args, seed, stats, by_family, found,
                                   time.time() - start, oracles.browser.version)
    finally:
        oracles.close()

    print("differential: seed %d: %d judged, check = browser on %.3f %%, %d false accepts, "
          "%d false rejects; report in %s" % (seed, stats["judged"], summary["agreement_percent"],
                                              stats["false-accept"], stats["false-reject"], args.out))
    failed = (args.max_false_accepts is not None and stats["false-accept"] > args.max_false_accepts) or \
        (args.max_false_rejects is not None and stats["false-reject"] > args.max_false_rejects) or \
        (args.min_agreement is not None and summary["agreement_percent"] < args.min_agreement) or \
        stats["unjudged"] > max(2, args.count // 100)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
