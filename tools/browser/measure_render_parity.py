#!/usr/bin/env python3
"""Measure how closely `shaderport render` matches Chromium on ShaderToy passes without inputs.

From a JSONL corpus (format of /work/shared/corpus-shadertoy/permissive.jsonl) take every
record whose only pass is an Image pass with an empty `inputs` list (or the first N with
--limit), and for each:
  1. write the record to a temporary REC.json and run
     `shaderport render --hermetic --size WxH REC.json -o shaderport.png` (2 at a time);
  2. render the same pass in headless Chromium (SwiftShader) as shadertoy.com composes it
     (tools/browser/shadertoy_reference.py);
  3. compare the two pictures by 8x8 block means (tools/browser/compare_pictures.py:
     MATCH when no block's R, G or B mean differs by more than 12/255).
Prints and (--out-md) writes a Markdown report: the counts, every mismatch with id, name,
author, license, URL, the worst block difference and shaderport's findings, and the
shaders one side could not render. Rows are sorted by id; the output is deterministic
apart from the timings.

Run (from the repository root):
  python3 tools/browser/measure_render_parity.py /work/shared/corpus-shadertoy/permissive.jsonl \
      --out-md tests/reports/render-parity-baseline.md --keep /tmp/parity
  python3 tools/browser/measure_render_parity.py CORPUS.jsonl --limit 40
--keep DIR keeps DIR/<id>/{record.json,shaderport.png,chromium.png,shaderport.txt} for every
shader, side.png (shaderport | Chromium | difference x4, scaled x4) for each mismatch, and
DIR/summary.json (one entry per shader).
--causes FILE (JSON {id: cause}) adds a "cause" column with a classification (classify_mismatches.py or by hand);
--notes FILE appends a Markdown section (how the causes were found).
Python 3 standard library only; needs chromium and a built shaderport.
"""

import argparse
import concurrent.futures
import datetime
import glob
import hashlib
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare_pictures  # noqa: E402
import pngio  # noqa: E402
import shadertoy_reference  # noqa: E402

REPO = os.path.dirname(os.path.dirname(HERE))
_FINDING = re.compile(r": (error|warning|note): (.*) \[([A-Za-z0-9_./-]+)\]\s*$")


def find_shaderport(explicit):
    if explicit:
        return explicit
    for pattern in ["build/release/shaderport", "build/release/tools/shaderport/shaderport",
                    "build/*/shaderport", "build/*/tools/shaderport/shaderport"]:
        for path in sorted(glob.glob(os.path.join(REPO, pattern))):
            if os.path.isfile(path) and os.access(path, os.X_OK):
                return path
    raise SystemExit("no shaderport binary found under build/: pass --shaderport")


def select_records(corpus, limit):
    """Records whose only pass is an Image pass with no inputs ("passes without inputs")."""
    selected = []
    total = 0
    with open(corpus, encoding="utf-8") as f:
        for line in f:
            if not line.strip():
                continue
            total += 1
            rec = json.loads(line)
            passes = rec.get("passes") or []
            if len(passes) == 1 and passes[0].get("type") == "image" and not passes[0].get("inputs"):
                if not limit or len(selected) < limit:
                    selected.append(rec)
    selected.sort(key=lambda r: r["id"])
    return selected, total


def run_shaderport(args):
    """Worker (runs in the process pool): one `shaderport render`."""
    binary, rec_path, png_path, size, timeout, render_timeout, inputs = args
    cmd = [binary, "render", "--hermetic", "--size", size, rec_path, "-o", png_path]
    if render_timeout:
        cmd += ["--timeout", "%g" % render_timeout]
    if inputs:
        # One argument with '=': a negative click position must not read as an option.
        cmd += ["--time=%r" % inputs["time"], "--frame=%d" % inputs["frame"],
                "--mouse=" + ",".join(repr(v) for v in inputs["mouse"])]
    t0 = time.time()
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
        out = proc.stdout.decode("utf-8", "replace") + proc.stderr.decode("utf-8", "replace")
        code = proc.returncode
    except subprocess.TimeoutExpired:
        out, code = "shaderport did not finish in %.0f s" % timeout, None
    return {"exit": code, "output": out, "seconds": time.time() - t0,
            "rendered": os.path.isfile(png_path) and os.path.getsize(png_path) > 0}


def random_inputs(seed, rid, width, height):
    """iTime, iFrame and iMouse for one shader of a --seed run: the same seed and id
    always give the same values (the seed is printed in the report)."""
    rng = random.Random("%d:%s" % (seed, rid))
    pressed = rng.random() < 0.5
    x, y = round(rng.uniform(0, width), 1), round(rng.uniform(0, height), 1)
    cx, cy = round(rng.uniform(0, width), 1), round(rng.uniform(0, height), 1)
    # ShaderToy: zw hold the click position, negative while the button is up.
    return {"time": round(rng.uniform(0.0, 120.0), 2), "frame": rng.randrange(0, 1000),
            "mouse": [x, y, cx if pressed else -cx, cy if pressed else -cy]}


def findings_of(output):
    """[(severity, rule, message)] from shaderport's text diagnostics."""
    found = []
    for line in output.splitlines():
        m = _FINDING.search(line)
        if m:
            found.append((m.group(1), m.group(3), m.group(2)))
    return found


def summarize_findings(findings):
    if not findings:
        return "none"
    counts = {}
    for sev, rule, _msg in findings:
        counts[(sev, rule)] = counts.get((sev, rule), 0) + 1
    parts = []
    for (sev, rule), n in sorted(counts.items()):
        parts.append("%s %s%s" % (sev, rule, " x%d" % n if n > 1 else ""))
    return ", ".join(parts)


def md(text, limit=None):
    text = " ".join(str(text if text is not None else "").split())
    if limit and len(text) > limit:
        text = text[:limit - 1] + "…"
    return text.replace("|", "\\|").replace("<", "&lt;").replace(">", "&gt;")


def side_by_side(a, b, scale=4, gap=8):
    """(w, h, rgba): a | b | |a-b| x4, each scaled by `scale`."""
    w, h, pa = a
    _, _, pb = b
    diff = bytearray(len(pa))
    for i in range(0, len(pa), 4):
        for c in range(3):
            diff[i + c] = min(255, 4 * abs(pa[i + c] - pb[i + c]))
        diff[i + 3] = 255
    panels = [pa, pb, bytes(diff)]
    ow = (w * scale) * 3 + gap * 2
    oh = h * scale
    out = bytearray([40, 40, 40, 255] * (ow * oh))
    for p, pix in enumerate(panels):
        x0 = p * (w * scale + gap)
        for y in range(oh):
            sy = y // scale
            for x in range(w * scale):
                sx = x // scale
                si = (sy * w + sx) * 4
                di = (y * ow + x0 + x) * 4
                out[di:di + 3] = pix[si:si + 3]
                out[di + 3] = 255
    return ow, oh, bytes(out)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Render every Image-only, input-free ShaderToy record with shaderport and with "
                    "Chromium, compare by 8x8 block means and report the mismatches.")
    ap.add_argument("corpus", help="JSONL corpus (e.g. /work/shared/corpus-shadertoy/permissive.jsonl)")
    ap.add_argument("--limit", type=int, default=0, help="only the first N selected records")
    ap.add_argument("--shaderport", help="shaderport binary (default: found under build/)")
    ap.add_argument("--size", default="64x64", help="picture size (default 64x64)")
    ap.add_argument("--jobs", type=int, default=2, help="parallel shaderport renders (default 2)")
    ap.add_argument("--batch", type=int, default=20, help="shaders per Chromium page (default 20)")
    ap.add_argument("--shaderport-timeout", type=float, default=60.0,
                    help="seconds for one shaderport process (its own render timeout is 10 s)")
    ap.add_argument("--render-timeout", type=float, default=0,
                    help="pass --timeout SECONDS to shaderport render (default: not passed, "
                    "its 10 s); a busy machine makes slow shaders time out at 10 s")
    ap.add_argument("--chromium", help="Chromium binary (default: chromium on PATH)")
    ap.add_argument("--threshold", type=float, default=compare_pictures.DEFAULT_THRESHOLD,
                    help="block mean threshold in byte units (default 12)")
    ap.add_argument("--causes", help="JSON file {id: cause} with a classification of the mismatches (classify_mismatches.py or by hand)")
    ap.add_argument("--notes", help="Markdown file appended to the report (e.g. how the causes "
                    "were found)")
    ap.add_argument("--seed", type=int, help="draw each shader at its own random iTime "
                    "(0-120 s), iFrame (0-999) and iMouse, from this seed (default: iTime 1, "
                    "iFrame 0, iMouse 0)")
    ap.add_argument("--out-md", help="write the Markdown report here")
    ap.add_argument("--keep", help="keep both PNGs and shaderport's output per shader, and a "
                    "side-by-side picture per mismatch, in this directory")
    args = ap.parse_args(argv)
    m = re.fullmatch(r"(\d+)x(\d+)", args.size)
    if not m:
        ap.error("--size must be WIDTHxHEIGHT")
    width, height = int(m.group(1)), int(m.group(2))
    binary = os.path.abspath(find_shaderport(args.shaderport))
    chromium = shadertoy_reference.find_chromium(args.chromium)
    causes = {}
    if args.causes:
        with open(args.causes, encoding="utf-8") as f:
            causes = json.load(f)

    t_start = time.time()
    records, total = select_records(args.corpus, args.limit)
    print("%d of %d records are Image-only passes without inputs%s" %
          (len(records), total, " (limited)" if args.limit else ""), file=sys.stderr)
    work = tempfile.mkdtemp(prefix="render-parity-")
    try:
        # 1. shaderport, 2 processes at a time.
        tasks = []
        rec_inputs = {}
        for rec in records:
            d = os.path.join(work, rec["id"])
            os.makedirs(d)
            rec_path = os.path.join(d, "record.json")
            with open(rec_path, "w", encoding="utf-8") as f:
                json.dump(rec, f)
            inputs = (random_inputs(args.seed, rec["id"], width, height)
                      if args.seed is not None else None)
            rec_inputs[rec["id"]] = inputs
            tasks.append((binary, rec_path, os.path.join(d, "shaderport.png"), args.size,
                          max(args.shaderport_timeout, (args.render_timeout or 10.0) + 30.0),
                          args.render_timeout, inputs))
        t0 = time.time()
        with concurrent.futures.ProcessPoolExecutor(max_workers=args.jobs) as pool:
            sp_results = list(pool.map(run_shaderport, tasks))
        t_shaderport = time.time() - t0
        print("shaderport: %d renders in %.1f s" % (len(tasks), t_shaderport), file=sys.stderr)

        # 2. Chromium.
        t0 = time.time()
        jobs = [dict({"key": rec["id"], "fragment": shadertoy_reference.compose_record(rec)},
                     **(rec_inputs[rec["id"]] or {}))
                for rec in records]
        ch_results = shadertoy_reference.render_jobs(
            jobs, width, height, 1.0, args.batch, chromium=chromium,
            log=lambda s: print(s, file=sys.stderr))
        t_chromium = time.time() - t0
        print("chromium: %d renders in %.1f s" % (len(jobs), t_chromium), file=sys.stderr)

        # 3. Compare.
        rows = []
        for rec, sp in zip(records, sp_results):
            rid = rec["id"]
            d = os.path.join(work, rid)
            ch = ch_results[rid]
            row = {"rec": rec, "sp": sp, "ch": ch, "findings": findings_of(sp["output"]),
                   "comparison": None}
            if ch["status"] == "ok":
                pngio.write_png(os.path.join(d, "chromium.png"), width, height, ch["rgba"])
            if sp["rendered"] and ch["status"] == "ok":
                try:
                    a = pngio.read_png(os.path.join(d, "shaderport.png"))
                    b = (width, height, ch["rgba"])
                    row["comparison"] = compare_pictures.compare(a, b, threshold=args.threshold)
                    if args.keep and not row["comparison"].match:
                        pngio.write_png(os.path.join(d, "side.png"), *side_by_side(a, b))
                except (pngio.PngError, ValueError) as e:
                    row["compare_error"] = str(e)
            if args.keep:
                with open(os.path.join(d, "shaderport.txt"), "w", encoding="utf-8") as f:
                    f.write(sp["output"])
                if ch.get("log"):
                    with open(os.path.join(d, "chromium.txt"), "w", encoding="utf-8") as f:
                        f.write(ch["log"])
            rows.append(row)
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
            for rec in records:
                dst = os.path.join(args.keep, rec["id"])
                shutil.rmtree(dst, ignore_errors=True)
                shutil.copytree(os.path.join(work, rec["id"]), dst)
            summary = []
            for r in rows:
                c = r["comparison"]
                summary.append({
                    "id": r["rec"]["id"], "name": r["rec"].get("name"),
                    "author": r["rec"].get("author"), "license": r["rec"].get("license"),
                    "url": r["rec"].get("url"), "shaderport_rendered": r["sp"]["rendered"],
                    "shaderport_exit": r["sp"]["exit"], "chromium": r["ch"]["status"],
                    "chromium_ms": r["ch"].get("ms"),
                    "inputs": rec_inputs.get(r["rec"]["id"]),
                    "match": c.match if c else None, "worst": round(c.worst, 2) if c else None,
                    "mean_abs": round(c.mean_abs, 2) if c else None,
                    "blocks_over": c.blocks_over if c else None,
                    "findings": summarize_findings(r["findings"])})
            with open(os.path.join(args.keep, "summary.json"), "w", encoding="utf-8") as f:
                json.dump(summary, f, indent=1, ensure_ascii=False)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    elapsed = time.time() - t_start

    report = build_report(args, rows, total, binary, elapsed, t_shaderport, t_chromium, causes)
    if args.out_md:
        os.makedirs(os.path.dirname(os.path.abspath(args.out_md)), exist_ok=True)
        with open(args.out_md, "w", encoding="utf-8") as f:
            f.write(report)
        print("wrote %s" % args.out_md, file=sys.stderr)
    else:
        sys.stdout.write(report)
    return 0


def _git_rev():
    try:
        rev = subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL).stdout.decode().strip()
        dirty = subprocess.run(["git", "-C", REPO, "status", "--porcelain", "--untracked-files=no",
                                "src", "rules"], stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL).stdout.decode().strip()
        return rev + (" (with uncommitted changes under src/ or rules/)" if dirty else "")
    except OSError:
        return "unknown"


def _chromium_version(chromium):
    try:
        out = subprocess.run([chromium, "--version"], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, timeout=30).stdout.decode().strip()
        return out.splitlines()[0] if out else "unknown"
    except (OSError, subprocess.TimeoutExpired):
        return "unknown"


def redacted(rec, text, limit=None):
    """Findings and logs quote the shader's own names: only for permissive records
    (sample_dataset.py marks the others `restricted`)."""
    return "(restricted licence: id only)" if rec.get("restricted") else md(text, limit)


def build_report(args, rows, total, binary, elapsed, t_sp, t_ch, causes):
    both = [r for r in rows if r["comparison"] is not None]
    match = [r for r in both if r["comparison"].match]
    mismatch = [r for r in both if not r["comparison"].match]
    sp_failed = [r for r in rows if not r["sp"]["rendered"]]
    ch_failed = [r for r in rows if r["ch"]["status"] != "ok"]
    ch_status = {}
    for r in ch_failed:
        ch_status[r["ch"]["status"]] = ch_status.get(r["ch"]["status"], 0) + 1
    n = len(rows)

    def pct(k, of):
        return "%.1f %%" % (100.0 * k / of) if of else "-"

    corpus_name = os.path.relpath(args.corpus, REPO) if args.corpus.startswith(REPO) else args.corpus
    lines = []
    lines.append("# Render parity: `shaderport render` against Chromium (ShaderToy passes without inputs)")
    lines.append("")
    lines.append("Generated by `tools/browser/measure_render_parity.py` (see tools/browser/README.md); "
                 "do not edit by hand, regenerate:")
    lines.append("")
    lines.append("```sh")
    cmd = "python3 tools/browser/measure_render_parity.py %s" % corpus_name
    if args.limit:
        cmd += " --limit %d" % args.limit
    if args.shaderport:
        cmd += " --shaderport %s" % args.shaderport
    if args.render_timeout:
        cmd += " --render-timeout %g" % args.render_timeout
    if args.seed is not None:
        cmd += " --seed %d" % args.seed
    if args.causes:
        cmd += " --causes %s" % os.path.relpath(os.path.abspath(args.causes), REPO)
    if args.notes:
        cmd += " --notes %s" % os.path.relpath(os.path.abspath(args.notes), REPO)
    if args.out_md:
        cmd += " --out-md %s" % os.path.relpath(os.path.abspath(args.out_md), REPO)
    lines.append(cmd)
    lines.append("```")
    lines.append("")
    lines.append("* Selection: records of `%s` whose only pass is an Image pass with empty `inputs`: "
                 "%d of %d records%s." % (corpus_name, n, total,
                                          " (first %d only)" % args.limit if args.limit else ""))
    built = datetime.datetime.fromtimestamp(os.path.getmtime(binary), datetime.timezone.utc)
    with open(binary, "rb") as f:
        digest = hashlib.sha256(f.read()).hexdigest()[:12]
    shown = os.path.relpath(binary, REPO) if binary.startswith(REPO + os.sep) else binary
    extra = " --timeout %g" % args.render_timeout if args.render_timeout else ""
    lines.append("* shaderport: `%s render --hermetic --size %s%s REC.json -o out.png`; binary built "
                 "%s UTC (sha256 %s…), repository HEAD %s at run time." %
                 (shown, args.size, extra, built.strftime("%Y-%m-%d %H:%M"), digest, _git_rev()))
    uniform_note = ("iTime, iFrame and iMouse drawn per shader from seed %d: iTime uniform in "
                    "0-120 s, iFrame in 0-999, iMouse anywhere in the picture, button up or down "
                    "(values per shader in the `--keep` summary); both sides get the same values"
                    % args.seed if args.seed is not None else "iTime 1, iFrame 0, iMouse 0")
    lines.append("* Chromium: %s, headless, `--use-angle=swiftshader`; the site's composition "
                 "(src/validate/shadertoy_contract.cpp) drawn into an RGBA8 framebuffer with "
                 "shaderport's uniform values (%s, iDate 2025-01-01 12:00); "
                 "unfed channels are unbound, as on the site." % (uniform_note, _chromium_version(
                     shadertoy_reference.find_chromium(args.chromium))))
    lines.append("* Comparison: 8x8 blocks, R/G/B mean per block; MATCH when no block mean differs "
                 "by more than %g/255." % args.threshold)
    lines.append("* Run time: %.0f s in all (shaderport %.0f s with %d processes, Chromium %.0f s)." %
                 (elapsed, t_sp, args.jobs, t_ch))
    lines.append("")
    lines.append("| measure | shaders | share of selected |")
    lines.append("|---|---|---|")
    lines.append("| selected | %d | 100 %% |" % n)
    lines.append("| both rendered | %d | %s |" % (len(both), pct(len(both), n)))
    lines.append("| match | %d | %s (%s of both rendered) |" % (len(match), pct(len(match), n),
                                                              pct(len(match), len(both))))
    lines.append("| mismatch | %d | %s |" % (len(mismatch), pct(len(mismatch), n)))
    lines.append("| shaderport wrote no picture | %d | %s |" % (len(sp_failed), pct(len(sp_failed), n)))
    lines.append("| Chromium did not draw | %d | %s |" % (len(ch_failed), pct(len(ch_failed), n)) +
                 "")
    for status in sorted(ch_status):
        lines.append("| Chromium: %s | %d | %s |" % (status, ch_status[status], pct(ch_status[status], n)))
    lines.append("")
    if causes:
        tally = {}
        for r in mismatch:
            c = causes.get(r["rec"]["id"])
            if c:
                key = c.split(":")[0].strip()
                tally.setdefault(key, []).append(r["rec"]["id"])
        if tally:
            lines.append("## Classified mismatches (%d of %d; how: see the notes)" %
                         (sum(len(v) for v in tally.values()), len(mismatch)))
            lines.append("")
            lines.append("| cause | shaders | ids |")
            lines.append("|---|---|---|")
            for key, ids in sorted(tally.items(), key=lambda kv: (-len(kv[1]), kv[0])):
                lines.append("| %s | %d | %s |" % (md(key), len(ids), ", ".join(ids)))
            lines.append("")
    lines.append("## Mismatches")
    lines.append("")
    lines.append("Worst = the largest difference of one 8x8 block's R, G or B mean, in 1/255; "
                 "findings = what `shaderport render` reported.")
    lines.append("")
    head = "| id | name | author | license | worst | findings |"
    sep = "|---|---|---|---|---|---|"
    if causes:
        head += " cause |"
        sep += "---|"
    lines.append(head)
    lines.append(sep)
    for r in mismatch:
        rec = r["rec"]
        c = r["comparison"]
        url = rec.get("url") or "https://www.shadertoy.com/view/%s" % rec["id"]
        line = "| [%s](%s) | %s | %s | %s | %.1f | %s |" % (
            rec["id"], url, md(rec.get("name"), 60), md(rec.get("author"), 30),
            md(rec.get("license")), c.worst, redacted(rec, summarize_findings(r["findings"])))
        if causes:
            line += " %s |" % md(causes.get(rec["id"], ""))
        lines.append(line)
    if not mismatch:
        lines.append("| none | | | | | |" + (" |" if causes else ""))
    lines.append("")
    lines.append("## shaderport wrote no picture")
    lines.append("")
    lines.append("| id | name | author | license | Chromium | shaderport findings |")
    lines.append("|---|---|---|---|---|---|")
    for r in sp_failed:
        rec = r["rec"]
        url = rec.get("url") or "https://www.shadertoy.com/view/%s" % rec["id"]
        lines.append("| [%s](%s) | %s | %s | %s | %s | %s |" % (
            rec["id"], url, md(rec.get("name"), 60), md(rec.get("author"), 30), md(rec.get("license")),
            r["ch"]["status"], redacted(rec, summarize_findings(r["findings"]) if r["findings"]
                                     else r["sp"]["output"], 200)))
    if not sp_failed:
        lines.append("| none | | | | | |")
    lines.append("")
    lines.append("## Chromium did not draw")
    lines.append("")
    lines.append("| id | name | author | license | status | Chromium log | shaderport findings |")
    lines.append("|---|---|---|---|---|---|---|")
    for r in ch_failed:
        rec = r["rec"]
        url = rec.get("url") or "https://www.shadertoy.com/view/%s" % rec["id"]
        lines.append("| [%s](%s) | %s | %s | %s | %s | %s | %s |" % (
            rec["id"], url, md(rec.get("name"), 60), md(rec.get("author"), 30), md(rec.get("license")),
            r["ch"]["status"], redacted(rec, r["ch"].get("log", ""), 200),
            redacted(rec, summarize_findings(r["findings"]))))
    if not ch_failed:
        lines.append("| none | | | | | | |")
    lines.append("")
    if args.notes:
        with open(args.notes, encoding="utf-8") as f:
            lines.append(f.read().rstrip("\n"))
            lines.append("")
    lines.append("Shader code stays under each author's license (column license); see the URL for "
                 "the original.")
    lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":
    sys.exit(main())
