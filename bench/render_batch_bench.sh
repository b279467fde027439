#!/usr/bin/env bash
# Per-render time inside one batch, and `report` over 500 ShaderToy passes, with the
# persistent render worker (default) and with a fresh process per render
# (SHADERPORT_RENDER_WORKER_RENDERS=1, the model before the worker). Not a test:
# prints a table. Usage: bench/render_batch_bench.sh [BUILD_DIR]
#   cold: `check --render -j1` over N variants of corpus/ao/template.glsl that differ
#         in one constant (distinct text and code, so every compile misses Mesa's
#         shader cache) with an empty cache; the worker starts with the batch, so the
#         first render pays its start-up (it is one of N samples, not the p50).
#   warm: the same batch again on the cache the cold run filled.
#   p50 is the median of the parent's per-render time (request sent to reply
#   decoded, SHADERPORT_RENDER_DEBUG lines); first is the batch's first render (with
#   the worker's start-up); wall is the whole `check` process.
# Env: N (variants, default 40), PASSES (report size, default 500, 0 skips),
#      SHARED (default ../shared next to the repo), MODES (default
#      "worker fresh-process"; a binary from before the worker has only the latter).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
binary=$build/shaderport
[[ -x $binary ]] || { echo "render_batch_bench: build $binary first" >&2; exit 2; }
count=${N:-40}
passes=${PASSES:-500}
shared=${SHARED:-$root/../shared}
read -r -a modes <<<"${MODES:-worker fresh-process}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

mkdir -p "$work/variants"
for ((k = 0; k < count; k++)); do
  sed "s/^#define AO_STRENGTH 3.0$/#define AO_STRENGTH 3.$(printf %04d "$k")1/" \
    "$root/corpus/ao/template.glsl" >"$work/variants/v$k.glsl"
done

now_ms() { echo $(($(date +%s%N) / 1000000)); }

p50() {  # median of the per-render times in a debug log
  grep -o 'shaderport render worker: status 0 in [0-9.]*' "$1" | awk '{print $NF}' |
    sort -n | awk '{v[NR] = $1} END {if (NR == 0) print "n/a"; else printf "%.1f", v[int((NR + 1) / 2)]}'
}

first() {  # the first render of a debug log: it includes the worker's start-up
  grep -o 'shaderport render worker: status [0-9]* in [0-9.]*' "$1" | head -1 |
    awk '{print $NF} END {if (NR == 0) print "n/a"}'
}

batch() {  # MODE_ENV CACHE: prints "first_ms p50_ms wall_ms"
  local start end
  start=$(now_ms)
  env $1 XDG_CACHE_HOME="$2" SHADERPORT_RENDER_DEBUG=1 "$binary" check --no-cache --render \
    --render-size 64 -j1 "$work/variants" >/dev/null 2>"$work/log" || true
  end=$(now_ms)
  echo "$(first "$work/log") $(p50 "$work/log") $((end - start))"
}

echo "check --render -j1 over $count variants of corpus/ao/template.glsl at 64x64 (ms)"
printf '%-16s %10s %10s %10s %10s %10s\n' mode cold_first cold_p50 cold_wall warm_p50 warm_wall
for mode in "${modes[@]}"; do
  setting=SHADERPORT_RENDER_WORKER_RENDERS=200
  [[ $mode == fresh-process ]] && setting=SHADERPORT_RENDER_WORKER_RENDERS=1
  cache=$work/cache-$mode
  read -r cold_first cold_p50 cold_wall < <(batch "$setting" "$cache")
  read -r _ warm_p50 warm_wall < <(batch "$setting" "$cache")
  printf '%-16s %10s %10s %10s %10s %10s\n' "$mode" "$cold_first" "$cold_p50" "$cold_wall" \
    "$warm_p50" "$warm_wall"
done

((passes > 0)) || exit 0
jsonl=$shared/corpus-shadertoy/permissive.jsonl
[[ -f $jsonl ]] || { echo "render_batch_bench: no $jsonl, report skipped" >&2; exit 0; }
# The first PASSES Image passes, each with its shader's Common prepended (as the site does).
python3 - "$jsonl" "$passes" "$work/passes" <<'PY'
import json, os, sys
source, wanted, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
os.makedirs(out)
written = 0
with open(source) as f:
  for line in f:
    shader = json.loads(line)
    common = "".join(p["code"] + "\n" for p in shader["passes"] if p.get("type") == "common")
    for p in shader["passes"]:
      if p.get("type") == "image" and written < wanted:
        with open(os.path.join(out, "%04d-%s.glsl" % (written, shader["id"])), "w") as g:
          g.write(common + p["code"])
        written += 1
print("report over %d Image passes" % written)
PY
echo "(ms, default -j = $(nproc) cores; cold: empty Mesa cache, warm: the same run again)"
printf '%-16s %10s %10s\n' mode cold_wall warm_wall
for mode in "${modes[@]}"; do
  setting=SHADERPORT_RENDER_WORKER_RENDERS=200
  [[ $mode == fresh-process ]] && setting=SHADERPORT_RENDER_WORKER_RENDERS=1
  cache=$work/report-cache-$mode
  walls=()
  for run in cold warm; do
    start=$(now_ms)
    env $setting XDG_CACHE_HOME="$cache" "$binary" report --html "$work/report.html" \
      "$work/passes" >/dev/null 2>&1 || true
    walls+=($(($(now_ms) - start)))
  done
  printf '%-16s %10s %10s\n' "$mode" "${walls[0]}" "${walls[1]}"
done
