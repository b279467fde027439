#!/usr/bin/env bash
# Time per `shaderport render` at 64x64 and 256x256, with Mesa's shader cache cold
# (a fresh cache dir per run) and warm (second run on a filled cache). Not a test:
# prints a table. Usage: bench/render_bench.sh [BUILD_DIR] [SHADER...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift || true
binary=$build/shaderport
[[ -x $binary ]] || { echo "render_bench: build $binary first" >&2; exit 2; }
shaders=("$@")
if ((${#shaders[@]} == 0)); then
  shaders=("$root/corpus/ao/template.glsl" "$root/corpus/ao/variant-hemisphere.glsl"
           "$root/corpus/strict-typing/control-explicit-conversions.glsl")
fi
runs=${RUNS:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

ms() {  # wall time of one command in milliseconds
  local start end
  start=$(date +%s%N)
  "$@" >/dev/null 2>&1 || true
  end=$(date +%s%N)
  echo $(((end - start) / 1000000))
}

printf '%-50s %9s %10s %10s\n' shader size cold_ms warm_ms
for shader in "${shaders[@]}"; do
  for size in 64x64 256x256; do
    cold=0 warm=0
    for ((i = 0; i < runs; i++)); do
      cache=$work/cache-$size-$i
      # A fresh XDG cache dir: Mesa compiles and JITs from scratch (cold).
      cold=$((cold + $(ms env XDG_CACHE_HOME="$cache" "$binary" render "$shader" --size "$size" -o "$work/out.png")))
      # Same cache dir again: Mesa's shader cache is warm.
      warm=$((warm + $(ms env XDG_CACHE_HOME="$cache" "$binary" render "$shader" --size "$size" -o "$work/out.png")))
    done
    printf '%-50s %9s %10d %10d\n' "${shader#"$root"/}" "$size" $((cold / runs)) $((warm / runs))
  done
done
echo "(mean of $runs runs; whole process: fork, context, compile, draw, PNG)"
