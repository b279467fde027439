#!/usr/bin/env python3
"""Sweep of real ShaderToy passes: Chromium's compile verdict against `shaderport check`.

Every pass (Image, Buffer A-D, Cube A, Sound) of the Shadertoys dataset
(github.com/Vipitis/shadertoys-dataset: data/annotated/*.jsonl, api/*.jsonl,
api/overlap/*.jsonl; all licences, deduplicated by id, the first record of an id kept)
is composed as shadertoy.com composes it (shadertoy_compose.py, a mirror of
src/validate/shadertoy_contract.cpp; Common is compiled only as part of each pass, as on
the site) and compiled as a WebGL2 fragment shader in headless Chromium. The same
records are checked as projects by `shaderport check --format json` (.jsonl files of
corpus records). A pass is rejected by check when an error-severity diagnostic other
than `link/*` lies in the pass's tab or in Common (the site compiles Common into
every pass). Per pass: agree, false reject (Chromium compiles, check errs) or false
accept (Chromium rejects, check silent), grouped by cause.

The report holds counts, ids and licence classes, and check's rule ids; messages and
code are quoted only for permissively licensed shaders (heldout_corpus.permissive).

Run (the full sweep, then the CI regression check against the committed baseline):
  python3 tools/browser/shadertoy_sweep.py --dataset /work/.mirror/Vipitis+shadertoys-dataset/repo \
      --out-md tests/reports/shadertoy-browser-sweep.md --out-json tests/reports/shadertoy-browser-sweep.json
  python3 tools/browser/shadertoy_sweep.py --regression tests/reports/shadertoy-browser-sweep.json
Python 3 standard library only; needs `chromium` and a built shaderport.
"""

import argparse
import collections
import datetime
import json
import os
import random
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import browser_compile  # noqa: E402
import heldout_corpus  # noqa: E402
import shadertoy_compose  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(HERE))
DEFAULT_DATASET = "/work/.mirror/Vipitis+shadertoys-dataset/repo"
DEFAULT_SHADERPORT = os.path.join(ROOT, "build", "release", "shaderport")
CHUNK_BYTES = 3 << 20  # check refuses files over 8 MiB (docs/limits.md)
AGREE_SAMPLE = 1000  # agreeing passes kept in the JSON for --regression
EXTRA = [("cube_a", "cube", "Cube A"), ("sound", "sound", "Sound")]


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# --- The dataset --------------------------------------------------------------------------

def dataset_files(dataset):
    names = (heldout_corpus.git(dataset, "ls-tree", "-r", "HEAD", "--name-only") or "").split()
    return sorted(p for p in names if p.startswith("data/annotated/") and p.endswith(".jsonl"))


def to_record(raw):
    """heldout_corpus's record plus the Cube A and Sound tabs it leaves out."""
    record = heldout_corpus.to_record(raw)
    for key, kind, name in EXTRA:
        if raw.get(key + "_code"):
            record["passes"].insert(-1, {"type": kind, "name": name, "code": raw[key + "_code"],
                                         "inputs": raw.get(key + "_inputs") or []})
    return record


UNREADABLE = []  # dataset files the mirror lacks (its largest blobs may be absent)


def load_dataset(dataset, wanted=None):
    """{id: record} over all licences; the first record of an id wins."""
    records = {}
    for path in dataset_files(dataset):
        text = heldout_corpus.git(dataset, "show", "HEAD:" + path)
        if text is None:
            log("skipped (not readable): %s" % path)
            UNREADABLE.append(path)
            continue
        for line in text.splitlines():
            try:
                raw = json.loads(line)
            except ValueError:
                continue
            rid = raw.get("id")
            if not rid or rid in records or (wanted is not None and rid not in wanted):
                continue
            if not raw.get("image_code"):
                continue  # no Image tab: not a shader the site can show
            records[rid] = to_record(raw)
    return records


def license_class(record):
    return "permissive" if heldout_corpus.permissive(record.get("license")) else "restricted"


# --- Chromium -------------------------------------------------------------------------------

def chromium_verdicts(passes, batch):
    """{(id, tab): (ok, log)}; ok None when Chromium could not answer."""
    compiler = browser_compile.BrowserCompiler(batch=batch)
    out = {}
    try:
        step = 2000
        for start in range(0, len(passes), step):
            part = passes[start:start + step]
            jobs = [{"source": p["text"], "stage": "fragment", "context": 2} for p in part]
            for p, verdict in zip(part, compiler.compile(jobs)):
                out[(p["id"], p["tab"])] = verdict
            log("  chromium: %d/%d passes" % (min(start + step, len(passes)), len(passes)))
        version = subprocess.run([compiler.chromium, "--version"], capture_output=True,
                                 text=True).stdout.strip() or compiler.version
    finally:
        compiler.close()
    return out, version


# --- shaderport check -----------------------------------------------------------------------

def run_check(shaderport, path, jobs, timeout=900):
    cmd = [shaderport, "check", "--format", "json", "--no-config", "--no-cache", "-q",
           "-j", str(jobs), path]
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timeout after %d s" % timeout
    try:
        return json.loads(proc.stdout), None
    except ValueError:
        return None, "exit %d: %s" % (proc.returncode, proc.stderr.strip()[:300])


_TAB_PATH = re.compile(r"#([^/#]*)(?:/([^/#]*))?$")


def tab_of(path, single_id=None):
    """(id, tab) from a project tab's path `FILE.jsonl#ID/TAB`; tab None for a finding
    about the whole project; None for a path naming no project. A file holding one
    project names its tabs `FILE.jsonl#TAB`: single_id is that project's id."""
    if single_id is not None:
        m = re.search(r"#([^#]*)$", path or "")
        return (single_id, m.group(1) if m else None) if path else None
    m = _TAB_PATH.search(path or "")
    return (m.group(1), m.group(2)) if m else None


def check_records(shaderport, records, jobs, work):
    """{(id, tab): the tab's first error}, tab None for the project as a whole, and
    {id: reason} for records check could not answer for. Records go into .jsonl files of
    at most CHUNK_BYTES."""
    chunks, current, size = [], [], 0
    for rec in records:
        line = json.dumps(rec) + "\n"
        if current and size + len(line.encode()) > CHUNK_BYTES:
            chunks.append(current)
            current, size = [], 0
        current.append(line)
        size += len(line.encode())
    if current:
        chunks.append(current)
    errors, failed = {}, {}

    def check_lines(lines, name):
        path = os.path.join(work, name + ".jsonl")
        with open(path, "w", encoding="utf-8") as f:
            f.writelines(lines)
        result, problem = run_check(shaderport, path, jobs)
        os.unlink(path)
        if result is None:
            if len(lines) > 1:  # find the record check fails on; keep the others' answers
                half = len(lines) // 2
                check_lines(lines[:half], name + "a")
                check_lines(lines[half:], name + "b")
            else:
                failed[json.loads(lines[0])["id"]] = problem
            return
        single = json.loads(lines[0])["id"] if len(lines) == 1 else None
        for entry in result.get("files", []):
            for diag in entry.get("diagnostics", []):
                if diag.get("severity") != "error" or diag.get("rule", "").startswith("link/"):
                    continue
                loc = diag.get("location") or {}
                where = tab_of(loc.get("path"), single) or tab_of(entry.get("path"), single)
                if where is None:
                    log("  check: an error outside any project: %s" % diag.get("message"))
                elif where not in errors:
                    errors[where] = {"rule": diag.get("rule"), "message": diag.get("message", ""),
                                     "line": ((loc.get("range") or {}).get("start") or {}).get("line")}

    for i, lines in enumerate(chunks):
        check_lines(lines, "chunk%03d" % i)
        log("  check: %d/%d files" % (i + 1, len(chunks)))
    return errors, failed


# --- Comparison -------------------------------------------------------------------------------

_QUOTED = re.compile(r"'[^']*'")


def chromium_first_error(text):
    for line in (text or "").splitlines():
        if line.startswith("ERROR:"):
            return line.strip()
    return (text or "").strip().splitlines()[0] if (text or "").strip() else "(no log)"


def chromium_cause(line):
    """Chromium's message without its location and quoted token."""
    msg = re.sub(r"^ERROR:\s*\d+:\d+:\s*", "", line)
    msg = re.sub(r"^'[^']*'\s*:\s*", "", msg)  # the leading "'token' : "
    return re.sub(r"\s+", " ", _QUOTED.sub("''", msg)).strip()


_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_VOCABULARY = None


def vocabulary():
    """Words of check's rule catalogue and GLSL (docs/rules.md, docs/browser-divergence.md)."""
    global _VOCABULARY
    if _VOCABULARY is None:
        _VOCABULARY = set()
        for doc in ("rules.md", "browser-divergence.md"):
            try:
                with open(os.path.join(ROOT, "docs", doc), encoding="utf-8") as f:
                    _VOCABULARY.update(_WORD.findall(f.read()))
            except OSError:
                pass
    return _VOCABULARY


# Messages that name the shader's macros or functions without quotes.
_UNQUOTED_NAMES = [(re.compile(r"\b([Mm]acro) [A-Za-z_]\w*"), r"\1 …"),
                   (re.compile(r"(unexpected '[^']*') [A-Za-z_]\w*"), r"\1 …"),
                   (re.compile(r"(recursive call: )[\w >-]+"), r"\1…"),
                   (re.compile(r"(: )[A-Za-z_]\w*$"), r"\1…")]  # "...: NAME" at the end


def _mask_names(text, record, filler):
    """The shader's own names out of a message: in the known unquoted places, and any
    other name of the shader unless it is a lowercase word or a word of the catalogue."""
    for pattern, repl in _UNQUOTED_NAMES:
        text = pattern.sub(repl.replace("…", filler), text)
    names = set()
    for p in record["passes"]:
        names.update(_WORD.findall(p.get("code", "")))
    words = vocabulary()

    def keep(w):
        return (w not in names or w.islower() or w in words
                or (w.istitle() and w.lower() in words))
    return _WORD.sub(lambda m: m.group(0) if keep(m.group(0)) else filler, text)


def mask(text, record):
    """A message quotes the shader's tokens and names: kept only for permissive shaders;
    for the others quoted tokens and the shader's own names become '…'."""
    if license_class(record) == "permissive":
        return text
    return _mask_names(_QUOTED.sub("'…'", text), record, "…")


def shape(text, record):
    """A message without its quoted tokens and the shader's names, to group by."""
    text = re.sub(r"^'[^']*'\s*:\s*", "", text)  # glslang's leading "'token': "
    return re.sub(r"\s+", " ", _mask_names(_QUOTED.sub("''", text), record, "…")).strip()


def compare(records, passes, chromium, check_errors, check_failed):
    rows = []
    by_id = {r["id"]: r for r in records}
    for p in passes:
        rid, tab = p["id"], p["tab"]
        rec = by_id[rid]
        ok, clog = chromium.get((rid, tab), (None, "not compiled"))
        common_ok, common_log = chromium.get((rid, "Common"), (True, ""))
        text = p["text"]
        if ok and common_ok is False:  # the Common tab alone does not compile
            ok, clog = False, common_log
            text = shadertoy_compose.compose_common_tab(rec)
        row = {"id": rid, "pass": tab, "kind": p["kind"], "license": license_class(rec)}
        if ok is None:
            row["verdict"] = "chromium-failed"
        elif rid in check_failed:
            row["verdict"] = "check-failed"
        else:
            # Common is compiled into every pass, as is a finding about the whole project.
            err = (check_errors.get((rid, tab)) or check_errors.get((rid, "Common"))
                   or check_errors.get((rid, None)))
            if ok and err:
                row.update(verdict="false-reject", rule=err["rule"],
                           message=mask(err["message"], rec), line=err["line"],
                           shape="%s: %s" % (err["rule"], shape(err["message"], rec)),
                           in_common=(rid, tab) not in check_errors)
            elif not ok and not err:
                first = chromium_first_error(clog)
                row.update(verdict="false-accept", cause=shape(chromium_cause(first), rec),
                           chromium=mask(first, rec))
                m = re.match(r"ERROR:\s*\d+:(\d+):", first)
                lines = text.splitlines()
                if row["license"] == "permissive" and m and 0 < int(m.group(1)) <= len(lines):
                    row["src_line"] = lines[int(m.group(1)) - 1].strip()[:120]
            else:
                row["verdict"] = "agree-accept" if ok else "agree-reject"
        rows.append(row)
    return rows


def composed_passes(records):
    out = []
    for rec in records:
        for tab, kind, text in shadertoy_compose.compose_record(rec):
            out.append({"id": rec["id"], "tab": tab, "kind": kind, "text": text})
    return out


def common_tabs(records):
    """The Common tab of each record that has one, compiled alone as the site does: a
    pass runs only when its Common tab compiles too."""
    out = []
    for rec in records:
        text = shadertoy_compose.compose_common_tab(rec)
        if text is not None:
            out.append({"id": rec["id"], "tab": "Common", "kind": "common", "text": text})
    return out


def sweep(records, args, only=None):
    """Rows for the passes of `records` (restricted to the (id, tab) set `only`)."""
    times = {}
    passes = composed_passes(records)
    if only is not None:
        passes = [p for p in passes if (p["id"], p["tab"]) in only]
    t0 = time.time()
    log("chromium: %d passes" % len(passes))
    tabs = [t for t in common_tabs(records) if any(p["id"] == t["id"] for p in passes)]
    chromium, version = chromium_verdicts(passes + tabs, args.batch)
    times["chromium_s"] = round(time.time() - t0, 1)
    t0 = time.time()
    log("shaderport check: %d records" % len(records))
    with tempfile.TemporaryDirectory(prefix="sp-sweep-") as work:
        errors, failed = check_records(args.shaderport, records, args.jobs, work)
    times["check_s"] = round(time.time() - t0, 1)
    return compare(records, passes, chromium, errors, failed), version, times


# --- Report ----------------------------------------------------------------------------------

def tool_versions(shaderport):
    """The version line says little between commits: add the binary's date and the tree."""
    try:
        out = subprocess.run([shaderport, "version"], capture_output=True, text=True).stdout
    except OSError:
        return "?"
    built = datetime.datetime.fromtimestamp(os.path.getmtime(shaderport), datetime.timezone.utc)
    head = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True).stdout.strip()
    return "%s (binary built %s; HEAD of the tree then %s)" % (
        out.strip().splitlines()[0] if out.strip() else "?", built.strftime("%Y-%m-%d %H:%M UTC"), head)


def summarise(rows):
    count = collections.Counter(r["verdict"] for r in rows)
    judged = sum(count[k] for k in ("agree-accept", "agree-reject", "false-reject", "false-accept"))
    agree = count["agree-accept"] + count["agree-reject"]
    return {"passes": len(rows), "judged": judged, "agree": agree,
            "agreement_percent": round(100.0 * agree / judged, 3) if judged else None,
            **{k.replace("-", "_"): count[k] for k in
               ("agree-accept", "agree-reject", "false-reject", "false-accept", "chromium-failed",
                "check-failed")}}


def groups(rows, verdict, key):
    out = collections.defaultdict(list)
    for r in rows:
        if r["verdict"] == verdict:
            out[r[key]].append(r)
    return sorted(out.items(), key=lambda kv: (-len(kv[1]), kv[0]))


def flagged_line(record, row):
    """The flagged line of a permissive shader's tab, for the report (None otherwise)."""
    if "src_line" in row:
        return row["src_line"]
    if row["license"] != "permissive" or not row.get("line"):
        return None
    tab = "Common" if row.get("in_common") else row["pass"]
    code = next((p["code"] for p in record["passes"] if p["name"] == tab), "")
    lines = code.splitlines()
    if 0 < row["line"] <= len(lines):
        return lines[row["line"] - 1].strip()[:120]
    return None


def write_json(path, meta, rows):
    summary = summarise(rows)
    agreeing = sorted([r["id"], r["pass"]] for r in rows if r["verdict"].startswith("agree"))
    data = {
        "meta": meta, "summary": summary,
        "by_kind": {k: summarise([r for r in rows if r["kind"] == k])
                    for k in sorted({r["kind"] for r in rows})},
        "false_reject_causes": {c: len(v) for c, v in groups(rows, "false-reject", "rule")},
        "false_reject_messages": {c: len(v) for c, v in groups(rows, "false-reject", "shape")},
        "false_accept_causes": {c: len(v) for c, v in groups(rows, "false-accept", "cause")},
        "false_rejects": [{"id": r["id"], "pass": r["pass"], "license": r["license"],
                           "rule": r["rule"], "cause": r["shape"]}
                          for r in rows if r["verdict"] == "false-reject"],
        "false_accepts": [{"id": r["id"], "pass": r["pass"], "license": r["license"],
                           "cause": r["cause"]} for r in rows if r["verdict"] == "false-accept"],
        "failed": [{"id": r["id"], "pass": r["pass"], "verdict": r["verdict"]}
                   for r in rows if r["verdict"] in ("chromium-failed", "check-failed")],
        # A fixed sample of agreeing passes the regression check re-runs.
        "agree_sample": random.Random(1).sample(agreeing, min(AGREE_SAMPLE, len(agreeing))),
    }
    with open(path, "w", encoding="utf-8") as f:
        json.dump(data, f, indent=1)
        f.write("\n")


def write_md(path, meta, rows, by_id):
    s = summarise(rows)
    out = ["# Sweep of real ShaderToy passes: Chromium against `shaderport check`", "",
           "Generated by `tools/browser/shadertoy_sweep.py` (tools/browser/README.md, "
           "\"Sweep of real ShaderToy passes\"). Do not edit by hand.", "",
           "| | |", "|---|---|"]
    t = meta.get("times", {})
    for label, value in (
            ("date", meta.get("date")), ("selection", meta.get("selection")),
            ("dataset", meta.get("dataset")),
            ("dataset files not in the mirror", ", ".join(meta.get("unreadable") or []) or "none"),
            ("shaderport", meta.get("shaderport")), ("Chromium", meta.get("chromium")),
            ("wall time", "%s s (Chromium %s s, check -j %s %s s, the rest reading the dataset)" % (
                meta.get("wall_time_s"), t.get("chromium_s"), meta.get("jobs"), t.get("check_s")))):
        out.append("| %s | %s |" % (label, value))
    out += ["", "## Verdicts per pass", "",
            "Each pass is composed as the site composes it (Common compiled into every pass) and "
            "compiled as a WebGL2 fragment shader by Chromium, and so is the Common tab alone as the "
            "site compiles it; Chromium accepts a pass when both compile. check rejects a pass when "
            "it reports an error (other than `link/*`) in the pass's tab or in Common.", "",
            "| passes | shaders | agree (both accept / both reject) | agreement | false rejects | "
            "false accepts | Chromium failed | check failed |", "|---|---|---|---|---|---|---|---|",
            "| %d | %d | %d (%d / %d) | %s %% | %d | %d | %d | %d |" % (
                s["passes"], meta["shaders"], s["agree"], s["agree_accept"], s["agree_reject"],
                s["agreement_percent"], s["false_reject"], s["false_accept"], s["chromium_failed"],
                s["check_failed"]), "",
            "| kind | passes | agreement | false rejects | false accepts |", "|---|---|---|---|---|"]
    for kind in sorted({r["kind"] for r in rows}):
        k = summarise([r for r in rows if r["kind"] == kind])
        out.append("| %s | %d | %s %% | %d | %d |" % (kind, k["passes"], k["agreement_percent"],
                                                      k["false_reject"], k["false_accept"]))

    def ids(group):
        return ", ".join("%s/%s%s" % (r["id"], r["pass"], "" if r["license"] == "permissive" else "*")
                         for r in group)

    out += ["", "Ids: `ID/PASS`, a `*` marks a shader under a restrictive licence (only its id "
            "is given; view it at https://www.shadertoy.com/view/ID).", "",
            "## False rejects by check's rule (Chromium compiles, check has an error)", "",
            "| rule | passes | ids |", "|---|---|---|"]
    for rule, group in groups(rows, "false-reject", "rule"):
        out.append("| `%s` | %d | %s |" % (rule, len(group), ids(group)))
    out += ["", "The same, split by check's message (quoted tokens and the shader's own names "
            "removed):", "", "| rule: message | passes | ids |", "|---|---|---|"]
    for cause, group in groups(rows, "false-reject", "shape"):
        out.append("| %s | %d | %s |" % (cause.replace("|", "\\|"), len(group), ids(group)))
    out += ["", "## False accepts by Chromium's message (Chromium rejects, check is silent)", "",
            "| Chromium's first error (quoted token removed) | passes | ids |", "|---|---|---|"]
    for cause, group in groups(rows, "false-accept", "cause"):
        out.append("| %s | %d | %s |" % (cause.replace("|", "\\|"), len(group), ids(group)))
    out += ["", "## Every false reject", "",
            "Message quoted for permissive shaders; for the others quoted tokens and the shader's own names are "
            "replaced by `'…'`. `(Common)`: the error lies in Common.", "",
            "| id | pass | licence | rule | check's message | flagged line (permissive only) |",
            "|---|---|---|---|---|---|"]
    for r in sorted((r for r in rows if r["verdict"] == "false-reject"),
                    key=lambda r: (r["rule"], r["id"], r["pass"])):
        line = flagged_line(by_id[r["id"]], r)
        out.append("| %s | %s | %s | `%s` | %s%s | %s |" % (
            r["id"], r["pass"], r["license"], r["rule"], r["message"].replace("|", "\\|")[:200],
            " (Common)" if r.get("in_common") else "",
            ("`%s`" % line.replace("|", "\\|").replace("`", "'")) if line else ""))
    out += ["", "## Every false accept", "",
            "| id | pass | licence | Chromium's first error | flagged line (permissive only) |",
            "|---|---|---|---|---|"]
    for r in sorted((r for r in rows if r["verdict"] == "false-accept"),
                    key=lambda r: (r["cause"], r["id"], r["pass"])):
        line = flagged_line(by_id[r["id"]], r)
        out.append("| %s | %s | %s | %s | %s |" % (
            r["id"], r["pass"], r["license"], r["chromium"].replace("|", "\\|")[:200],
            ("`%s`" % line.replace("|", "\\|").replace("`", "'")) if line else ""))
    permissive = sorted({r["id"] for r in rows if r["verdict"] in ("false-reject", "false-accept")
                         and r["license"] == "permissive"})
    if permissive:
        out += ["", "## Attribution of the quoted lines", "",
                "| id | name | author | licence | url |", "|---|---|---|---|---|"]
        for rid in permissive:
            rec = by_id[rid]
            out.append("| %s | %s | %s | %s | %s |" % (
                rid, (rec.get("name") or "").replace("|", "\\|"), rec.get("author"),
                rec.get("license"), rec.get("url")))
    failed = [r for r in rows if r["verdict"] in ("chromium-failed", "check-failed")]
    if failed:
        out += ["", "## Not judged", ""] + ["- %s/%s: %s" % (r["id"], r["pass"], r["verdict"])
                                              for r in failed]
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")


# --- Modes -------------------------------------------------------------------------------------

def dataset_commit(dataset):
    return (heldout_corpus.git(dataset, "rev-parse", "HEAD") or "?").strip()


def full_sweep(args):
    start = time.time()
    log("reading %s" % args.dataset)
    records = load_dataset(args.dataset)
    ids = sorted(records)
    selection = "all %d shaders" % len(ids)
    if args.sample:
        ids = sorted(random.Random(args.seed).sample(ids, min(args.sample, len(ids))))
        selection = "random sample of %d of %d shaders, seed %d" % (len(ids), len(records), args.seed)
    elif args.limit:
        ids = ids[:args.limit]
        selection = "first %d of %d shaders by id" % (len(ids), len(records))
    log(selection)
    chosen = [records[i] for i in ids]
    rows, version, times = sweep(chosen, args)
    meta = {"date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "selection": selection, "seed": args.seed if args.sample else None,
            "dataset": "Vipitis/shadertoys-dataset @ %s" % dataset_commit(args.dataset)[:12],
            "dataset_commit": dataset_commit(args.dataset),
            "shaderport": tool_versions(args.shaderport), "chromium": version,
            "unreadable": UNREADABLE, "jobs": args.jobs,
            "shaders": len(chosen), "wall_time_s": round(time.time() - start, 1), "times": times}
    s = summarise(rows)
    print("%d shaders, %d passes: agreement %s %% (%d agree, %d false rejects, %d false accepts, "
          "%d Chromium failed, %d check failed) in %.0f s" % (
              len(chosen), s["passes"], s["agreement_percent"], s["agree"], s["false_reject"],
              s["false_accept"], s["chromium_failed"], s["check_failed"], meta["wall_time_s"]))
    if args.out_json:
        write_json(args.out_json, meta, rows)
    if args.out_md:
        write_md(args.out_md, meta, rows, records)
    return 0


def regression(args):
    """Re-run the baseline's disagreements and its sample of agreeing passes; exit 1 when a
    pass that agreed now disagrees. Without the dataset there is nothing to compile: skip."""
    with open(args.regression, encoding="utf-8") as f:
        base = json.load(f)
    start = time.time()
    if dataset_commit(args.dataset) != base["meta"].get("dataset_commit"):
        log("warning: dataset at %s, the baseline was taken at %s" % (
            dataset_commit(args.dataset), base["meta"].get("dataset_commit")))
    agreeing = {tuple(p) for p in base["agree_sample"][:args.regression_sample]}
    before = {(r["id"], r["pass"]): "false-reject" for r in base["false_rejects"]}
    before.update({(r["id"], r["pass"]): "false-accept" for r in base["false_accepts"]})
    wanted = agreeing | set(before)
    records = load_dataset(args.dataset, {rid for rid, _ in wanted})
    rows, version, _ = sweep([records[i] for i in sorted(records)], args, only=wanted)
    if version != base["meta"].get("chromium"):
        log("warning: Chromium %s, the baseline used %s" % (version, base["meta"].get("chromium")))
    now = {(r["id"], r["pass"]): r for r in rows}
    regressed = [r for key, r in sorted(now.items()) if key in agreeing
                 and r["verdict"] in ("false-reject", "false-accept")]
    fixed = [key for key, was in sorted(before.items())
             if key in now and now[key]["verdict"].startswith("agree")]
    missing = sorted(wanted - set(now))
    for r in regressed:
        print("REGRESSION %s/%s: %s %s" % (r["id"], r["pass"], r["verdict"],
                                          r.get("rule") or r.get("cause")))
    for rid, tab in fixed:
        print("fixed %s/%s (was %s)" % (rid, tab, before[(rid, tab)]))
    print("shadertoy sweep regression: %d agreeing passes re-run, %d now disagree; %d of %d known "
          "disagreements now agree; %d not found; %.0f s" % (
              len(agreeing), len(regressed), len(fixed), len(before), len(missing),
              time.time() - start))
    return 1 if regressed else 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dataset", default=DEFAULT_DATASET, help="git directory of the Shadertoys dataset")
    ap.add_argument("--shaderport", default=DEFAULT_SHADERPORT)
    ap.add_argument("--limit", type=int, default=0, help="the first N shaders by id")
    ap.add_argument("--sample", type=int, default=0, help="a random sample of N shaders")
    ap.add_argument("--seed", type=int, default=1, help="seed of --sample")
    ap.add_argument("--out-md", help="Markdown report")
    ap.add_argument("--out-json", help="counts and ids (the --regression baseline)")
    ap.add_argument("--jobs", type=int, default=2, help="check -j")
    ap.add_argument("--batch", type=int, default=100, help="passes per Chromium evaluation")
    ap.add_argument("--regression", metavar="BASELINE_JSON",
                    help="re-run the baseline's disagreements and agreeing sample; exit 1 on a "
                         "newly disagreeing pass (exit 0 without the dataset)")
    ap.add_argument("--regression-sample", type=int, default=500,
                    help="agreeing passes of the baseline to re-run (default 500)")
    args = ap.parse_args(argv)
    if args.regression and (not os.path.isdir(args.dataset) or dataset_commit(args.dataset) == "?"):
        # CI has no copy of the dataset: nothing to compile, which is not a failure.
        print("shadertoy sweep regression: SKIPPED, no Shadertoys dataset at %s "
              "(pass --dataset GIT_DIR)" % args.dataset)
        return 0
    if not os.path.exists(args.shaderport):
        ap.error("no shaderport at %s (build it or pass --shaderport)" % args.shaderport)
    return regression(args) if args.regression else full_sweep(args)


if __name__ == "__main__":
    sys.exit(main())
