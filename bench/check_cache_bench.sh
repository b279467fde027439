#!/usr/bin/env bash
# Cold and warm `shaderport check` over 10,000 shader files: copies of corpus/,
# each file made unique by a trailing comment, so every file is its own cache
# entry (vertex/fragment pairs included). Prints the wall times of an uncached
# run (--no-cache), a cold run (empty cache) and a warm run (nothing changed),
# and checks that all three print the same bytes. Not a test.
# Usage: bench/check_cache_bench.sh [BUILD_DIR] [FILES]
#   or:  cmake --build --preset bench --target check_cache_bench
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build/bench}" && pwd)
count=${2:-10000}
binary=$build/shaderport
[[ -x $binary ]] || { echo "check_cache_bench: build $binary first" >&2; exit 2; }
work=$(mktemp -d)
trap 'cat "$work"/*.err >&2 2>/dev/null; rm -rf "$work"' EXIT

# One python process writes the copies: a shell loop forks per file (minutes for 10,000).
made=$(python3 - "$root" "$work/shaders" "$count" <<'PY'
import os, sys
root, out, count = sys.argv[1], sys.argv[2], int(sys.argv[3])
originals = sorted(os.path.relpath(os.path.join(d, f), os.path.join(root, "corpus"))
                   for d, _, fs in os.walk(os.path.join(root, "corpus"))
                   for f in fs if f.endswith((".glsl", ".frag", ".vert")))
made, copy = 0, 0
while made < count:
    for name in originals:
        if made == count:
            break
        target = os.path.join(out, f"copy{copy}", name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(os.path.join(root, "corpus", name), "rb") as src, open(target, "wb") as dst:
            dst.write(src.read() + f"\n// copy {copy}\n".encode())
        made += 1
    copy += 1
print(made)
PY
)

ms() {  # wall time of one command in milliseconds; its output goes to $work/$1.out
  local name=$1 start end
  shift
  start=$(date +%s%N)
  (cd "$work" && "$@" >"$work/$name.out" 2>"$work/$name.err") || true
  end=$(date +%s%N)
  echo $(((end - start) / 1000000))
}

median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# Alternating uncached and cold runs (a fresh cache directory each time), then
# warm runs over the last cache: medians, so that a noisy run does not decide.
runs=${RUNS:-3}
uncached=() cold=() warm=()
for ((run = 0; run < runs; run++)); do
  uncached+=("$(ms uncached "$binary" check --no-cache shaders)")
  cold+=("$(ms cold "$binary" check --cache-dir "$work/cache$run" shaders)")
done
cache=$work/cache$((runs - 1))
for ((run = 0; run < runs; run++)); do
  warm+=("$(ms warm "$binary" check --cache-dir "$cache" shaders)")
done
cmp -s "$work/uncached.out" "$work/cold.out" || { echo "check_cache_bench: cold output differs" >&2; exit 1; }
cmp -s "$work/cold.out" "$work/warm.out" || { echo "check_cache_bench: warm output differs" >&2; exit 1; }
uncached_ms=$(median "${uncached[@]}") cold_ms=$(median "${cold[@]}") warm_ms=$(median "${warm[@]}")

printf '%d files (%s), %d runs each, medians (all runs in ms)\n' "$made" "$(du -sh "$work/shaders" | cut -f1)" "$runs"
printf '%-26s %8d ms  (%s)\n' "no cache (--no-cache)" "$uncached_ms" "${uncached[*]}" \
  "cold (empty cache)" "$cold_ms" "${cold[*]}" "warm (nothing changed)" "$warm_ms" "${warm[*]}"
printf 'cold/uncached: %s; uncached/warm: %s; cache size: %s in %d entries\n' \
  "$(awk -v c="$cold_ms" -v u="$uncached_ms" 'BEGIN { printf "%.2f", c / u }')" \
  "$(awk -v u="$uncached_ms" -v w="$warm_ms" 'BEGIN { printf "%.1f", u / (w > 0 ? w : 1) }')" \
  "$(du -sh "$cache" | cut -f1)" "$(find "$cache" -type f -name '????????????????????????????????' | wc -l)"
