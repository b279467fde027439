#!/usr/bin/env bash
# Times glslangValidator, one process per file, against `shaderport check` on all files in one
# process, over corpus/ plus the first N ShaderToy image/buffer passes. Run on demand, not in CI.
#
# Usage: bench/compare_glslang.sh [SHADERPORT_BINARY] [options]
#   --count N    ShaderToy passes to add (default 200)
#   --runs R     timed runs per measurement (default 3; the mean is reported)
#   --out DIR    where inputs are written (default: a fresh temporary directory)
# Without a working SHADERPORT_BINARY only the glslangValidator side is measured.
# Uses hyperfine when it is installed, else a `date +%s%N` loop.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source_dir="$(dirname "$here")"
shared_dir="${SHADERPORT_SHARED_DIR:-$source_dir/../shared}"
jsonl="$shared_dir/corpus-shadertoy/permissive.jsonl"

binary=""
count=200
runs=3
out=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --count) count="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) binary="$1"; shift ;;
  esac
done

command -v glslangValidator >/dev/null || { echo "glslangValidator not found" >&2; exit 2; }
[[ -f "$jsonl" ]] || { echo "ShaderToy corpus not found: $jsonl" >&2; exit 2; }
[[ -n "$out" ]] || out="$(mktemp -d /tmp/shaderport-bench.XXXXXX)"
mkdir -p "$out"

python3 "$here/prepare_inputs.py" "$source_dir" "$jsonl" "$count" "$out"
mapfile -t raw_files < <(cut -f1 "$out/files.tsv")
mapfile -t wrapped_files < <(cut -f2 "$out/files.tsv")
n=${#raw_files[@]}
echo "inputs: $n files in $out (ShaderToy credits: $out/ATTRIBUTION.tsv)"

have_hyperfine=0
command -v hyperfine >/dev/null && have_hyperfine=1

# mean_ms CMD... : mean wall time of CMD over $runs runs, in milliseconds (exit code ignored;
# files with errors are part of the workload).
mean_ms() {
  if [[ $have_hyperfine -eq 1 ]]; then
    local json
    json="$(mktemp)"
    hyperfine -N -i --runs "$runs" --style none --export-json "$json" -- "$(printf '%q ' "$@")" \
      >/dev/null 2>&1
    python3 -c 'import json,sys; print("%.3f" % (json.load(open(sys.argv[1]))["results"][0]["mean"]*1000))' "$json"
    rm -f "$json"
  else
    local total=0 start end
    for ((r = 0; r < runs; r++)); do
      start=$(date +%s%N)
      "$@" >/dev/null 2>&1 || true
      end=$(date +%s%N)
      total=$((total + end - start))
    done
    awk -v t="$total" -v r="$runs" 'BEGIN { printf "%.3f\n", t / r / 1e6 }'
  fi
}

echo
echo "== glslangValidator, one process per file (mean of $runs runs, ms)"
glslang_sum=0
for ((i = 0; i < n; i++)); do
  ms="$(mean_ms glslangValidator "${wrapped_files[$i]}")"
  printf '%10s  %s\n' "$ms" "${raw_files[$i]#"$out"/raw/}"
  glslang_sum="$(awk -v a="$glslang_sum" -v b="$ms" 'BEGIN { printf "%.3f", a + b }')"
done

echo
echo "== glslangValidator, all files in one process (for reference)"
glslang_batch="$(mean_ms glslangValidator "${wrapped_files[@]}")"

shaderport_ms=""
if [[ -z "$binary" ]]; then
  echo "== shaderport: no binary given, skipped"
elif [[ ! -x "$binary" ]]; then
  echo "== shaderport: '$binary' is not an executable, skipped"
elif ! "$binary" check --help >/dev/null 2>&1; then
  echo "== shaderport: '$binary check' is not available yet, skipped"
else
  # Exit status 0 (clean) and 1 (diagnostics found) both mean the check ran.
  set +e
  "$binary" check "${raw_files[@]}" >"$out/shaderport-check.out" 2>&1
  status=$?
  set -e
  if [[ $status -gt 1 ]]; then
    echo "== shaderport check failed (exit $status, see $out/shaderport-check.out), skipped"
  else
    echo "== shaderport check, all files in one process"
    shaderport_ms="$(mean_ms "$binary" check "${raw_files[@]}")"
  fi
fi

echo
echo "== summary ($n files)"
awk -v s="$glslang_sum" -v n="$n" \
  'BEGIN { printf "glslangValidator per file : %10.1f ms total, %7.3f ms/file\n", s, s / n }'
awk -v s="$glslang_batch" -v n="$n" \
  'BEGIN { printf "glslangValidator batch    : %10.1f ms total, %7.3f ms/file\n", s, s / n }'
if [[ -n "$shaderport_ms" ]]; then
  awk -v s="$shaderport_ms" -v n="$n" -v g="$glslang_sum" -v b="$glslang_batch" 'BEGIN {
    printf "shaderport check          : %10.1f ms total, %7.3f ms/file\n", s, s / n
    printf "ratio glslang per-file / shaderport: %.2fx\n", g / s
    printf "ratio glslang batch / shaderport   : %.2fx\n", b / s
  }'
fi
