#!/usr/bin/env python3
"""Measures `shaderport check` on WebGL conformance cases (a JSONL in the format of
../shared/conformance/webgl-cts.jsonl, e.g. written by conformance_pages.py) and writes a
Markdown report with every disagreement.

The rules are those of tests/unit/driver/webgl_conformance_test.cpp, the same measurement
for the public part:
* Stages: each stage alone, `check --target webgl1|webgl2` (from contextVersion),
  `--format json --no-config --no-cache`. A stage compiles unless check reports an error
  whose rule is not a link rule (`link/*`). The verdict is
  compared with Chromium's compile verdict (chromium.vCompiled / fCompiled); a case whose
  Chromium verdict is missing is left out.
* Whole cases: both stages as one program: NAME.vert and NAME.frag in one directory,
  which check links as it links `--link VS FS` (one run per context), or with
  --link-each one `check --link VS FS` per case (`--link` takes one pair per run in
  shaderport 0.1.0, although docs/cli.md calls it repeatable). A stage counts as
  compiled as above; the program links when both compile and neither file has a link-rule
  error. The verdict agrees with the suite's expectation under the harness's rule: a stage
  expected to succeed must compile; a stage expected to fail may compile if the program
  then does not link (GLSL ES 1.00.17 section 10.27); linkSuccess is compared when both
  stages compile; a null expectation is not checked. Cases with ignoreResults ("should not
  crash") are left out, as the suite enforces nothing for them.
* --page-extensions: a case with an `extensions` field (conformance_pages.py records the
  GLSL #extension names the page's own getExtension calls turned on) is checked, stages
  and program, with `--enabled-extensions` set to that list (`none` when empty), as the
  page's context compiled it; cases without the field, and every case without the flag,
  get check's default (every extension the context offers). The flag needs a shaderport
  that has the option.

Python 3 standard library only.

  measure_conformance.py /tmp/heldout-conf/cases.jsonl --shaderport /tmp/sp-bin/shaderport \
      --out-md tests/reports/webgl-conformance-heldout.md
  measure_conformance.py /tmp/heldout-conf/cases.jsonl --page-extensions --out-md /tmp/h.md
"""
import argparse
import collections
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

CONTEXTS = {1: "webgl1", 2: "webgl2"}
# `none` is worth showing on a case only where a source asks for an extension.
_EXTENSION_LINE = re.compile(r"^[ \t]*#[ \t]*extension\b", re.M)


def is_link_rule(rule):
    return rule.startswith("link/")


def find_shaderport(explicit):
    here = os.path.dirname(os.path.abspath(__file__))
    for candidate in [explicit, os.path.join(here, "..", "..", "build", "release", "shaderport")]:
        if candidate and os.path.exists(candidate):
            return os.path.abspath(candidate)
    raise SystemExit("shaderport not found: pass --shaderport")


def run_check(shaderport, target, arguments, cwd, jobs):
    """{relative path: [diagnostic]} from one `check --format json` run."""
    command = [shaderport, "check", "--target", target, "--format", "json", "--no-config",
               "--no-cache", "-j", str(jobs)] + arguments
    proc = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if proc.returncode not in (0, 1):
        raise SystemExit("%s exited %d: %s" % (" ".join(command[:8]), proc.returncode,
                                               proc.stderr[-2000:]))
    report = json.loads(proc.stdout)
    return {f["path"]: f.get("diagnostics", []) for f in report["files"]}


def verdict(diagnostics):
    """(compiled, linked, errors) as webgl_conformance_test.cpp reads check's findings."""
    compiled = linked = True
    for d in diagnostics:
        if d["severity"] != "error":
            continue
        if is_link_rule(d["rule"]):
            linked = False
        else:
            compiled = False
    return compiled, linked


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8", errors="surrogateescape", newline="") as f:
        f.write(text)


def enabled_extensions(case, page_extensions):
    """The --enabled-extensions value for a case, None for check's default."""
    if not page_extensions or case.get("extensions") is None:
        return None
    return ",".join(case["extensions"]) or "none"


def measure(cases, shaderport, jobs, link_each, page_extensions=False):
    work = tempfile.mkdtemp(prefix="sp-measure-conformance-")
    try:
        # One directory per --enabled-extensions value, as check takes one per run; the
        # default's keeps the old paths.
        values = [enabled_extensions(c, page_extensions) for c in cases]
        prefixes = {None: ""}
        for value in sorted(set(v for v in values if v is not None)):
            prefixes[value] = "x%d/" % len(prefixes)
        stage_files, pair_files = {}, {}
        for i, case in enumerate(cases):
            target = CONTEXTS[case.get("contextVersion", 1)]
            name = "c%05d" % i
            prefix = prefixes[values[i]]
            stage_files[i] = ("%sstage/%s/%s-v.vert" % (prefix, target, name),
                              "%sstage/%s/%s-f.frag" % (prefix, target, name))
            pair_files[i] = ("%sprogram/%s/%s.vert" % (prefix, target, name),
                             "%sprogram/%s/%s.frag" % (prefix, target, name))
            for (vs, fs) in (stage_files[i], pair_files[i]):
                write(os.path.join(work, vs), case["vertex"])
                write(os.path.join(work, fs), case["fragment"])
        stage_findings, pair_findings = {}, {}
        for value, prefix in prefixes.items():
            option = [] if value is None else ["--enabled-extensions", value]
            for target in CONTEXTS.values():
                if os.path.isdir(os.path.join(work, prefix + "stage", target)):
                    stage_findings.update(run_check(
                        shaderport, target, option + [prefix + "stage/" + target], work, jobs))
                pairs = [pair_files[i] for i, c in enumerate(cases) if values[i] == value and
                         CONTEXTS[c.get("contextVersion", 1)] == target]
                if not pairs:
                    continue
                if link_each:  # one `check --link VS FS` per case
                    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
                        for found in pool.map(lambda pair: run_check(
                                shaderport, target, option + ["--link", pair[0], pair[1]], work,
                                1), pairs):
                            pair_findings.update(found)
                else:  # NAME.vert and NAME.frag in one directory: linked as by --link
                    pair_findings.update(run_check(
                        shaderport, target, option + [prefix + "program/" + target], work, jobs))
        results = []
        for i, case in enumerate(cases):
            missing = [p for p in stage_files[i] + pair_files[i]
                       if p not in stage_findings and p not in pair_findings]
            if missing:
                raise SystemExit("check did not report %s" % ", ".join(missing))
            results.append({
                "stage": [stage_findings[p] for p in stage_files[i]],
                "pair": [pair_findings[p] for p in pair_files[i]],
            })
        return results
    finally:
        shutil.rmtree(work, ignore_errors=True)


def whole_case_agrees(expected, v_compiled, f_compiled, linked):
    """webgl_conformance_test.cpp's rule (the harness's)."""
    agrees = True
    for key, ours in (("vShaderSuccess", v_compiled), ("fShaderSuccess", f_compiled)):
        want = expected.get(key)
        if want is None:
            continue
        if want and not ours:
            agrees = False
        if not want and ours and linked:
            agrees = False
    if expected.get("linkSuccess") is not None and v_compiled and f_compiled and \
            expected["linkSuccess"] != linked:
        agrees = False
    return agrees


def evaluate(cases, results):
    stats = {c: collections.Counter() for c in CONTEXTS}
    stage_rows, case_rows = [], []
    for case, result in zip(cases, results):
        context = case.get("contextVersion", 1)
        s = stats[context]
        chromium = case.get("chromium") or {}
        for index, (stage, key) in enumerate((("vertex", "vCompiled"), ("fragment", "fCompiled"))):
            browser = chromium.get(key)
            ours, _ = verdict(result["stage"][index])
            if browser is None:
                s["stages without a Chromium verdict"] += 1
                continue
            s["stages"] += 1
            s[stage + " stages"] += 1
            if ours == browser:
                s["stages agree"] += 1
                s[stage + " stages agree"] += 1
                continue
            s["false accepts" if ours else "false rejects"] += 1
            stage_rows.append({"case": case, "stage": stage, "ours": ours,
                               "findings": result["stage"][index],
                               "log": chromium.get("vLog" if stage == "vertex" else "fLog", "")})
        v_compiled, v_linked = verdict(result["pair"][0])
        f_compiled, f_linked = verdict(result["pair"][1])
        linked = v_compiled and f_compiled and v_linked and f_linked
        if case.get("ignoreResults"):
            s["ignoreResults cases"] += 1
            continue
        s["cases"] += 1
        expected = case.get("expected") or {}
        if whole_case_agrees(expected, v_compiled, f_compiled, linked):
            s["cases agree"] += 1
        else:
            s["cases disagree"] += 1
            case_rows.append({"case": case, "verdict": (v_compiled, f_compiled, linked),
                              "findings": result["pair"]})
        # Not part of the measure: Chromium's own whole-program verdict against check's.
        if chromium.get("vCompiled") is not None and chromium.get("fCompiled") is not None:
            browser_ok = bool(chromium["vCompiled"] and chromium["fCompiled"] and
                              chromium.get("linked"))
            s["programs with a Chromium verdict"] += 1
            s["programs: check = Chromium"] += (browser_ok == linked)
    return stats, stage_rows, case_rows


def rate(agree, total):
    return "%.2f %%" % (100.0 * agree / total) if total else "n/a"


def fence(text, info=""):
    text = text if text.endswith("\n") else text + "\n"
    ticks = "```"
    while ticks in text:
        ticks += "`"
    return "%s%s\n%s%s\n" % (ticks, info, text, ticks)


def findings_text(diagnostics):
    lines = []
    for d in diagnostics:
        where = d.get("location", {}).get("range", {}).get("start", {})
        lines.append("%s %s:%s [%s] %s" % (d["severity"], where.get("line", "?"),
                                           where.get("column", "?"), d["rule"],
                                           d["message"].replace("\n", " ")))
    return "\n".join(lines) if lines else "(no findings)"


def expectation_text(expected):
    def one(value):
        return {True: "succeed", False: "fail", None: "unchecked"}[value]
    return "vertex %s, fragment %s, link %s" % (one(expected.get("vShaderSuccess")),
                                                one(expected.get("fShaderSuccess")),
                                                one(expected.get("linkSuccess")))


def chromium_text(chromium):
    def one(value):
        return {True: "ok", False: "error", None: "-"}[value]
    return "vertex %s, fragment %s, link %s" % (one(chromium.get("vCompiled")),
                                                one(chromium.get("fCompiled")),
                                                one(chromium.get("linked")))


def case_header(case, page_extensions=False):
    text = ("* page: `%s` (WebGL %d)\n* test: %s\n* expected: %s; Chromium: %s\n" % (
        case["file"], case.get("contextVersion", 1), case.get("passMsg") or "(none)",
        expectation_text(case.get("expected") or {}), chromium_text(case.get("chromium") or {})))
    value = enabled_extensions(case, page_extensions)
    if value is not None and (value != "none" or any(
            _EXTENSION_LINE.search(case[k]) for k in ("vertex", "fragment"))):
        text += "* checked with `--enabled-extensions %s` (what the page enabled)\n" % value
    return text


MAX_SOURCE_CHARS = 20000


def shown(text):
    if len(text) <= MAX_SOURCE_CHARS:
        return text
    return "%s\n/* ... %d more characters: the full text is in the JSONL */\n" % (
        text[:MAX_SOURCE_CHARS], len(text) - MAX_SOURCE_CHARS)


def sources(case):
    out = []
    for stage, key, default in (("vertex", "vertex", "vIsDefault"),
                                ("fragment", "fragment", "fIsDefault")):
        label = "%s shader%s" % (stage.capitalize(), " (the harness's default)"
                                 if case.get(default) else "")
        out.append("%s:\n\n%s" % (label, fence(shown(case[key]), "glsl")))
    return "\n".join(out)


def source_text(jsonl, cases):
    """Where the cases come from, from the extraction's JSONL.pages.json when present."""
    path = jsonl + ".pages.json"
    by_context = collections.Counter(c.get("contextVersion", 1) for c in cases)
    text = "%d cases (%d WebGL 1, %d WebGL 2) from `%s`." % (
        len(cases), by_context[1], by_context[2], os.path.basename(jsonl))
    if not os.path.exists(path):
        return text
    with open(path, encoding="utf-8") as f:
        summary = json.load(f)
    pages = summary.get("pages", {})
    def count(predicate, context):
        return sum(1 for p, d in pages.items()
                   if predicate(d) and p.startswith("conformance2/" if context == 2 else "conformance/"))
    rows = [
        ("pages loaded", lambda d: True),
        ("pages that gave cases", lambda d: d["cases"] > 0),
        ("no cases: the page does not load glsl-conformance-test.js (own checks)",
         lambda d: d["cases"] == 0 and d["status"] == "ok" and not d.get("harness")
         and not d.get("idle")),
        ("no cases: no harness, and a script error stopped the page before it finished",
         lambda d: d["cases"] == 0 and d["status"] == "ok" and not d.get("harness")
         and d.get("idle")),
        ("no cases: the harness script is loaded but its runOneTest never runs",
         lambda d: d["cases"] == 0 and d["status"] == "ok" and d.get("harness")),
        ("no cases: timed out", lambda d: d["status"] == "timeout"),
        ("no cases: browser error", lambda d: d["status"] == "error"),
    ]
    table = ["| pages | WebGL 1 | WebGL 2 |", "|---|---|---|"]
    for label, predicate in rows:
        table.append("| %s | %d | %d |" % (label, count(predicate, 1), count(predicate, 2)))
    limits = summary.get("limits") or {}
    return ("Cases extracted by tools/browser/conformance_pages.py from KhronosGroup/WebGL "
            "commit `%s` (sdk/tests; pages under conformance/glsl/ and conformance2/glsl3/ "
            "whose `file` is not in ../shared/conformance/webgl-cts.jsonl), in %s (ANGLE on "
            "SwiftShader). %s\n\n%s\n\nLimits of that Chromium (pages that size their shaders "
            "from the context follow them): %s." % (
                summary.get("commit"), summary.get("chromium"), text, "\n".join(table),
                "; ".join("%s %s" % (ctx, ", ".join("%s %s" % kv for kv in sorted(v.items())))
                          for ctx, v in sorted(limits.items()))))


def report(args, cases, stats, stage_rows, case_rows, meta):
    out = ["# WebGL conformance pages held out of the shared part: `check` against Chromium\n"]
    out.append((meta or source_text(args.jsonl, cases)) + "\n")
    out.append("Rules as in tests/unit/driver/webgl_conformance_test.cpp (the same measurement "
               "on the public part): each stage checked alone with `--target` from "
               "contextVersion and compared with Chromium's compile verdict; whole cases "
               "(both stages linked as `check --link VS FS` links them) compared with the suite's expectation under the "
               "harness's rule (a stage expected to fail may fail at link instead), "
               "ignoreResults cases left out. A stage fails when check reports an error "
               "whose rule is not `link/*`.\n")
    told = [enabled_extensions(c, args.page_extensions) for c in cases]
    if any(v is not None for v in told):
        out.append("With `--page-extensions`: %d cases were checked with `--enabled-extensions` "
                   "set to the GLSL extensions their page's getExtension calls turned on "
                   "(%d of them `none`), the others with every extension the context offers.\n"
                   % (sum(1 for v in told if v is not None), told.count("none")))
    out.append("The shader sources below are from the Khronos WebGL conformance suite "
               "(github.com/KhronosGroup/WebGL, sdk/tests), under the MIT license (see "
               "LICENSE.txt in that repository); this notice stays with them.\n")
    out.append("## Counts\n")
    out.append("| context | stages | agree | rate | false accepts | false rejects | whole cases "
               "| agree | rate | ignoreResults (left out) |\n|---|---|---|---|---|---|---|---|---|---|")
    total = collections.Counter()
    for context, name in ((1, "WebGL 1"), (2, "WebGL 2")):
        s = stats[context]
        total.update(s)
        out.append("| %s | %d | %d | %s | %d | %d | %d | %d | %s | %d |" % (
            name, s["stages"], s["stages agree"], rate(s["stages agree"], s["stages"]),
            s["false accepts"], s["false rejects"], s["cases"], s["cases agree"],
            rate(s["cases agree"], s["cases"]), s["ignoreResults cases"]))
    out.append("| all | %d | %d | %s | %d | %d | %d | %d | %s | %d |\n" % (
        total["stages"], total["stages agree"], rate(total["stages agree"], total["stages"]),
        total["false accepts"], total["false rejects"], total["cases"], total["cases agree"],
        rate(total["cases agree"], total["cases"]), total["ignoreResults cases"]))
    out.append("By stage: " + "; ".join(
        "%s %s %d of %d" % (name, stage, stats[c][stage + " stages agree"],
                            stats[c][stage + " stages"])
        for c, name in ((1, "WebGL 1"), (2, "WebGL 2")) for stage in ("vertex", "fragment"))
        + ". Stages without a Chromium verdict: %d.\n" % total["stages without a Chromium verdict"])
    chromium_fails = sum(1 for row in case_rows
                         if (row["case"].get("agree") or {}).get("harness") is False)
    out.append("Whole-case mismatches that Chromium itself does not pass under the harness's "
               "rule either (check agrees with Chromium there): %d of %d.\n" % (
                   chromium_fails, len(case_rows)))
    out.append("Not part of the measure: the whole program (`--link`) against Chromium's own "
               "compile and link verdict, ignoreResults cases left out: %d of %d agree.\n" % (
                   total["programs: check = Chromium"], total["programs with a Chromium verdict"]))
    if args.notes:
        with open(args.notes, encoding="utf-8") as f:
            out.append(f.read().rstrip("\n") + "\n")
    out.append("## Stage mismatches\n")
    if not stage_rows:
        out.append("None.\n")
    else:
        out.append("| case | stage | check | Chromium | check's first error / Chromium's log "
                   "|\n|---|---|---|---|---|")
        for row in stage_rows:
            errors = [d for d in row["findings"] if d["severity"] == "error"]
            first = ("%s: %s" % (errors[0]["rule"], errors[0]["message"]) if errors
                     else (row["log"] or "").strip())
            out.append("| %s | %s | %s | %s | %s |" % (
                row["case"]["id"], row["stage"], "accepts" if row["ours"] else "rejects",
                "rejects" if row["ours"] else "accepts",
                first.replace("|", "\\|").replace("\n", " ")[:200]))
        out.append("")
        for row in stage_rows:
            case = row["case"]
            out.append("### %s, %s stage: check %s, Chromium %s\n" % (
                case["id"], row["stage"], "accepts" if row["ours"] else "rejects",
                "rejects" if row["ours"] else "accepts"))
            out.append(case_header(case, args.page_extensions))
            out.append("Chromium's %s log:\n\n%s" % (row["stage"], fence(row["log"] or "(empty)")))
            out.append("check's findings on the %s stage alone:\n\n%s" % (
                row["stage"], fence(findings_text(row["findings"]))))
            out.append(sources(case))
    out.append("## Whole-case mismatches\n")
    if not case_rows:
        out.append("None.\n")
    else:
        for row in case_rows:
            case = row["case"]
            v, f, linked = row["verdict"]
            chromium = case.get("chromium") or {}
            chromium_passes = (case.get("agree") or {}).get("harness")
            out.append("### %s%s\n" % (case["id"], "" if chromium_passes is not False else
                                        " (Chromium fails this case too)"))
            out.append(case_header(case, args.page_extensions))
            out.append("* check (`--link`): vertex %s, fragment %s, link %s\n" % (
                "ok" if v else "error", "ok" if f else "error", "ok" if linked else "error"))
            out.append("Chromium's logs:\n\n%s" % fence(
                "vertex: %s\nfragment: %s\nlink: %s" % (
                    (chromium.get("vLog") or "").strip(), (chromium.get("fLog") or "").strip(),
                    (chromium.get("linkLog") or "").strip())))
            out.append("check's findings:\n\n%s" % fence(
                "vertex:\n%s\nfragment:\n%s" % (findings_text(row["findings"][0]),
                                                findings_text(row["findings"][1]))))
            out.append(sources(case))
    return "\n".join(out)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("jsonl")
    parser.add_argument("--shaderport", help="the binary (default build/release/shaderport)")
    parser.add_argument("--jobs", type=int, default=2, help="check -j (default %(default)s)")
    parser.add_argument("--link-each", action="store_true",
                        help="link each case with its own `check --link VS FS` process "
                             "(default: one run over a directory of NAME.vert/NAME.frag "
                             "pairs per context, which check links the same way)")
    parser.add_argument("--page-extensions", action="store_true",
                        help="check each case that has an `extensions` field with "
                             "`--enabled-extensions` set to it (`none` when empty): only the "
                             "extensions its page enabled (default: check's own default, "
                             "every extension the context offers)")
    parser.add_argument("--meta", default="", help="a paragraph for the top of the report "
                        "(default: where the cases come from, read from JSONL.pages.json, "
                        "which conformance_pages.py writes)")
    parser.add_argument("--notes", help="a Markdown file appended after the counts")
    parser.add_argument("--out-md", required=True)
    parser.add_argument("--out-json", help="also write the counts and mismatch ids as JSON")
    args = parser.parse_args(argv)
    with open(args.jsonl, encoding="utf-8") as f:
        cases = [json.loads(line) for line in f if line.strip()]
    shaderport = find_shaderport(args.shaderport)
    results = measure(cases, shaderport, args.jobs, args.link_each, args.page_extensions)
    stats, stage_rows, case_rows = evaluate(cases, results)
    text = report(args, cases, stats, stage_rows, case_rows, args.meta)
    os.makedirs(os.path.dirname(os.path.abspath(args.out_md)), exist_ok=True)
    with open(args.out_md, "w", encoding="utf-8") as f:
        f.write(text)
    summary = {"contexts": {CONTEXTS[c]: dict(s) for c, s in stats.items()},
               "stageMismatches": [[r["case"]["id"], r["stage"], r["ours"]] for r in stage_rows],
               "caseMismatches": [r["case"]["id"] for r in case_rows]}
    if args.out_json:
        with open(args.out_json, "w", encoding="utf-8") as f:
            json.dump(summary, f, indent=1)
    for context, s in stats.items():
        print("%s: stages %d of %d (%s), %d false accepts, %d false rejects; whole cases %d of "
              "%d (%s), %d ignoreResults left out" % (
                  CONTEXTS[context], s["stages agree"], s["stages"],
                  rate(s["stages agree"], s["stages"]), s["false accepts"], s["false rejects"],
                  s["cases agree"], s["cases"], rate(s["cases agree"], s["cases"]),
                  s["ignoreResults cases"]))
    print("report:", args.out_md)


if __name__ == "__main__":
    sys.exit(main())
