#!/usr/bin/env bash
# `shaderport port` throughput over real passes, side by side in one run with what
# bounds it: glslangValidator given the same passes in one process (port validates
# every output with glslang) and `shaderport check`. Rounds alternate; medians of
# user+system CPU seconds, passes per CPU second and the ratios are printed.
# Run on demand (issue: speed), never in CI.
#
#   bench/port_throughput.sh [-n PASSES] [-r ROUNDS] BINARY
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
count=1000 rounds=5
while getopts "n:r:" option; do
  case $option in
    n) count=$OPTARG ;;
    r) rounds=$OPTARG ;;
    *) sed -n '2,8p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
binary=${1:?usage: bench/port_throughput.sh [-n PASSES] [-r ROUNDS] SHADERPORT_BINARY}
jsonl=${SHADERPORT_SHARED_DIR:-$root/../shared}/corpus-shadertoy/permissive.jsonl
work=$(mktemp -d /tmp/shaderport-port-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT
python3 "$here/prepare_inputs.py" "$root" "$jsonl" "$count" "$work/in" >/dev/null
mapfile -t raw < <(cut -f1 "$work/in/files.tsv")
mapfile -t wrapped < <(cut -f2 "$work/in/files.tsv")
n=${#raw[@]}

cpu() {  # NAME CMD...: appends user+system seconds to $work/NAME
  local name=$1
  shift
  /usr/bin/time -f "%U %S" -o "$work/time" "$@" >/dev/null 2>&1 || true
  tail -n 1 "$work/time" | awk '{ printf "%.3f\n", $1 + $2 }' >>"$work/$name"
}
for ((r = 0; r < rounds; r++)); do
  rm -rf "$work/out"
  cpu port "$binary" port -j 1 --out-dir "$work/out" "${raw[@]}"
  cpu glslang glslangValidator "${wrapped[@]}"
  cpu check "$binary" check -j 1 --no-cache "${raw[@]}"
done
median() { sort -n "$work/$1" | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
p=$(median port) g=$(median glslang) c=$(median check)
echo "$n passes, $rounds alternating rounds, medians of CPU seconds (user + system)"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
awk -v p="$p" -v g="$g" -v c="$c" -v n="$n" 'BEGIN {
  printf "%-44s %8.3f s %8.0f passes/s\n", "shaderport port -j 1 --out-dir", p, n / p
  printf "%-44s %8.3f s %8.0f passes/s\n", "glslangValidator, all in one process", g, n / g
  printf "%-44s %8.3f s %8.0f passes/s\n", "shaderport check -j 1", c, n / c
  printf "port / glslangValidator batched: %.2fx CPU; port / check: %.2fx\n", p / g, p / c
}'
