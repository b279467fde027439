#!/usr/bin/env bash
# `shaderport check` against what a user would otherwise run, measured side by
# side in one run: glslangValidator given every pass (wrapped in the site's header,
# one process), and a glslangValidator-per-file loop. Runs alternate, medians of
# user+system CPU seconds and wall seconds are reported, with peak memory.
# Run on demand (issue: speed), never in CI.
#
#   bench/check_vs_glslang.sh [-n PASSES] [-r RUNS] [-j JOBS] [-l LOOP_FILES] [-c CPU] BINARY
#
#   -n  ShaderToy passes from ../shared (default 1000; corpus/ files are added)
#   -r  alternating rounds (default 5)
#   -j  also time `check -j JOBS` against JOBS glslangValidator processes (default 2)
#   -l  files for the per-file loop, scaled to the whole set (default 100)
#   -c  run the one-process commands (check -j 1, glslangValidator batched, the loop)
#       on this CPU only (taskset): on a shared VM the CPUs can differ in speed, and
#       the scheduler's choice then outweighs the difference between the tools
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
count=1000 rounds=5 jobs=2 loop_files=100 cpu=""
while getopts "n:r:j:l:c:" option; do
  case $option in
    n) count=$OPTARG ;;
    r) rounds=$OPTARG ;;
    j) jobs=$OPTARG ;;
    l) loop_files=$OPTARG ;;
    c) cpu=$OPTARG ;;
    *) sed -n '2,16p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
binary=${1:?usage: bench/check_vs_glslang.sh [options] SHADERPORT_BINARY}
jsonl=${SHADERPORT_SHARED_DIR:-$root/../shared}/corpus-shadertoy/permissive.jsonl
work=$(mktemp -d /tmp/shaderport-bench.XXXXXX)
trap 'rm -rf "$work"' EXIT
python3 "$here/prepare_inputs.py" "$root" "$jsonl" "$count" "$work/in" >/dev/null
mapfile -t raw < <(cut -f1 "$work/in/files.tsv")
mapfile -t wrapped < <(cut -f2 "$work/in/files.tsv")
n=${#raw[@]}

# measure NAME CMD...: appends "cpu wall maxrss_kib" to $work/NAME.
measure() {
  local name=$1
  shift
  /usr/bin/time -f "%U %S %e %M" -o "$work/time" "$@" >/dev/null 2>&1 || true
  # The last line: a failing exit adds a "Command exited" line before it.
  tail -n 1 "$work/time" | awk '{ printf "%.3f %.3f %d\n", $1 + $2, $3, $4 }' >>"$work/$name"
}
# Half the wrapped files each, for two glslangValidator processes at once.
glslang_pair() {
  local half=$(((n + 1) / 2))
  glslangValidator "${wrapped[@]:0:half}" >/dev/null 2>&1 &
  glslangValidator "${wrapped[@]:half}" >/dev/null 2>&1
  wait
}
glslang_loop() {
  for ((i = 0; i < loop_files && i < n; i++)); do glslangValidator "${wrapped[$i]}" >/dev/null 2>&1; done
}
export -f glslang_pair glslang_loop 2>/dev/null || true

pin=()
[[ -n $cpu ]] && pin=(taskset -c "$cpu")
for ((r = 0; r < rounds; r++)); do
  measure check1 "${pin[@]}" "$binary" check -j 1 --no-cache "${raw[@]}"
  measure glslang1 "${pin[@]}" glslangValidator "${wrapped[@]}"
  measure checkj "$binary" check -j "$jobs" --no-cache "${raw[@]}"
  measure glslangj bash -c "$(declare -p wrapped n); $(declare -f glslang_pair); glslang_pair"
done
measure loop "${pin[@]}" bash -c "$(declare -p wrapped n loop_files); $(declare -f glslang_loop); glslang_loop"

median() {  # FILE COLUMN
  sort -n -k"$2" "$1" | awk -v c="$2" '{ v[NR] = $c } END { print v[int((NR + 1) / 2)] }'
}
row() {  # LABEL NAME
  printf '%-40s %8s %8s %8s\n' "$1" "$(median "$work/$2" 1)" "$(median "$work/$2" 2)" \
    "$(median "$work/$2" 3)"
}
echo "$n passes ($count ShaderToy passes from the shared corpus plus corpus/), $rounds alternating rounds, medians${cpu:+, one-process runs on CPU $cpu}"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
printf '%-40s %8s %8s %8s\n' command cpu_s wall_s peak_KiB
row "shaderport check -j 1" check1
row "glslangValidator, all in one process" glslang1
row "shaderport check -j $jobs" checkj
row "glslangValidator, $jobs processes" glslangj
loop_cpu=$(awk '{ print $1 }' "$work/loop")
loop_wall=$(awk '{ print $2 }' "$work/loop")
awk -v c="$(median "$work/check1" 1)" -v g="$(median "$work/glslang1" 1)" \
  -v cw="$(median "$work/check1" 2)" -v gw="$(median "$work/glslang1" 2)" \
  -v jw="$(median "$work/checkj" 2)" -v pw="$(median "$work/glslangj" 2)" \
  -v lw="$loop_wall" -v lf="$loop_files" -v n="$n" 'BEGIN {
  printf "check -j 1 / glslangValidator batched: %.2fx CPU, %.2fx wall\n", c / g, cw / gw
  printf "check -j N / N glslangValidator processes: %.2fx wall\n", jw / pw
  loop = lw * n / (lf < n ? lf : n)
  printf "glslangValidator per file (loop of %d, scaled to %d): %.1f s wall: check -j 1 is %.1fx faster, check -j N %.1fx\n", lf, n, loop, loop / cw, loop / jw
}'
echo "(loop CPU for $loop_files files: ${loop_cpu} s)"
# The machine's speed drifts between rounds (a shared VM): the ratio within each round,
# whose two runs are seconds apart, is steadier than the ratio of the medians.
paste -d' ' "$work/check1" "$work/glslang1" | awk '{ print $1 / $4 }' | sort -n |
  awk '{ v[NR] = $1 } END { printf "check -j 1 / glslangValidator batched, median of the per-round CPU ratios: %.2fx (rounds: %d, range %.2f-%.2f)\n", v[int((NR + 1) / 2)], NR, v[1], v[NR] }'
