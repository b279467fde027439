#!/usr/bin/env bash
# A fuzzing campaign over every libFuzzer target (tests/fuzz/), for people and
# scheduled jobs; CI runs only the short smoke tests. Each target runs for the same
# time with libFuzzer's fork mode (-fork=JOBS: JOBS worker processes share one
# corpus and keep going after a crash, which is saved as an artifact).
#
#   tools/fuzz/campaign.sh [-t SECONDS] [-j JOBS] [-b BUILD_DIR] [-w WORK_DIR]
#                          [-T "target ..."] SUMMARY.md
#
#   -t  wall seconds per target. Default: enough for all targets together to use
#       at least one CPU-hour: ceil(3600 / (targets * JOBS)), at least 60.
#   -j  worker processes per target (default: nproc).
#   -b  a build with -DSHADERPORT_FUZZ=ON (default: build/fuzz, the `fuzz` preset);
#       the targets are built there first.
#   -w  corpora and crash artifacts, kept between campaigns (default:
#       ${TMPDIR:-/tmp}/shaderport-fuzz); must be outside the repository.
#   -T  only these targets.
# Writes a markdown table (target, CPU seconds, executions, corpus size, crashes)
# to SUMMARY.md. Prefix with `nice -n 10` on a shared machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)

all_targets="fuzz_frontend fuzz_webgl_semantics fuzz_fix fuzz_port fuzz_check fuzz_config
  fuzz_shadertoy_json fuzz_suppressions fuzz_formatters"
seconds=""
jobs=$(nproc)
build="$root/build/fuzz"
work="${TMPDIR:-/tmp}/shaderport-fuzz"
targets=""
while getopts "t:j:b:w:T:" option; do
  case $option in
    t) seconds=$OPTARG ;;
    j) jobs=$OPTARG ;;
    b) build=$OPTARG ;;
    w) work=$OPTARG ;;
    T) targets=$OPTARG ;;
    *) sed -n '2,20p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
if [[ $# -ne 1 ]]; then
  echo "usage: $0 [-t SECONDS] [-j JOBS] [-b BUILD_DIR] [-w WORK_DIR] [-T targets] SUMMARY.md" >&2
  exit 2
fi
summary=$(realpath -m "$1")
targets=${targets:-$all_targets}
read -r -a target_list <<<"$(echo $targets)"
if [[ -z $seconds ]]; then
  seconds=$(( (3600 + ${#target_list[@]} * jobs - 1) / (${#target_list[@]} * jobs) ))
  (( seconds < 60 )) && seconds=60
fi
mkdir -p "$work"
work=$(realpath "$work")
if [[ $work == "$root" || $work == "$root"/* ]]; then
  echo "campaign.sh: the work directory must be outside the repository" >&2
  exit 2
fi

if [[ ! -f $build/CMakeCache.txt ]]; then
  (cd "$root" && cmake --preset fuzz >/dev/null)
fi
# The commit the targets are built from (HEAD may move while the campaign runs).
commit=$(git -C "$root" rev-parse --short HEAD)
cmake --build "$build" -j "$jobs" --target "${target_list[@]}"

dict="$root/tests/fuzz/glsl.dict"
text_seeds=("$root/corpus" "$root/tests/data")
# ShaderToy records: the shared corpus, one JSON object a line, split into files.
json_seeds="$work/seeds/shadertoy_json"
shared="$root/../shared/corpus-shadertoy/permissive.jsonl"
if [[ -f $shared && ! -d $json_seeds ]]; then
  mkdir -p "$json_seeds"
  head -n 200 "$shared" | split -l 1 - "$json_seeds/record-"
fi

# Flags and seed directories of one target.
target_args() {
  case $1 in
    fuzz_frontend) echo "-max_len=65536 -dict=$dict ${text_seeds[*]}" ;;
    fuzz_webgl_semantics)
      echo "-max_len=16384 -dict=$dict ${text_seeds[*]} $root/tests/render-parity/shaders" ;;
    fuzz_fix | fuzz_port | fuzz_check) echo "-max_len=8192 -dict=$dict ${text_seeds[*]}" ;;
    fuzz_config) echo "-max_len=4096 $root/tests/data/check-project $root/rules/dialects" ;;
    fuzz_shadertoy_json)
      echo "-max_len=65536 $root/tests/fuzz/seeds/shadertoy_json $([[ -d $json_seeds ]] && echo "$json_seeds")" ;;
    fuzz_suppressions) echo "-max_len=4096 -dict=$dict $root/tests/data" ;;
    fuzz_formatters) echo "-max_len=4096 $root/tests/data" ;;
    *) echo "campaign.sh: unknown target $1" >&2; return 1 ;;
  esac
}

{
  echo "| target | wall s | CPU s | executions | corpus files | crashes | slow inputs |"
  echo "|---|---:|---:|---:|---:|---:|---:|"
} >"$summary.rows"
total_cpu=0
total_crashes=0
for target in "${target_list[@]}"; do
  corpus="$work/$target/corpus"
  artifacts="$work/$target/artifacts"
  mkdir -p "$corpus" "$artifacts"
  log="$work/$target/log.txt"
  read -r -a args <<<"$(target_args "$target")"
  # Failures are crash-, leak-, timeout- and oom- files; slow-unit- files are inputs
  # that took over 10 s (-report_slow_units), worth a look but not failures.
  failures() { find "$artifacts" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l; }
  slow_units() { find "$artifacts" -type f -name 'slow-unit-*' | wc -l; }
  crashes_before=$(failures)
  slow_before=$(slow_units)
  echo "== $target: ${seconds}s x $jobs workers"
  start=$(date +%s)
  TIMEFORMAT='%U %S'
  # bash's `time` counts the CPU of every waited-for descendant: all the workers.
  cpu=$( { time "$build/tests/fuzz/$target" -fork="$jobs" -ignore_crashes=1 -ignore_timeouts=1 \
             -ignore_ooms=1 -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2048 \
             -artifact_prefix="$artifacts/" -print_final_stats=1 "$corpus" "${args[@]}" \
             >"$log" 2>&1; } 2>&1 ) || true
  wall=$(( $(date +%s) - start ))
  cpu_seconds=$(awk '{ printf "%d", $1 + $2 }' <<<"$cpu")
  # Fork mode's status lines start with "#<executions>:".
  executions=$(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#')
  corpus_files=$(find "$corpus" -type f | wc -l)
  crashes=$(( $(failures) - crashes_before ))
  slow=$(( $(slow_units) - slow_before ))
  total_cpu=$((total_cpu + cpu_seconds))
  total_crashes=$((total_crashes + crashes))
  echo "| $target | $wall | $cpu_seconds | ${executions:-?} | $corpus_files | $crashes | $slow |" >>"$summary.rows"
done

{
  echo "# Fuzzing campaign $(date -u +%Y-%m-%dT%H:%MZ)"
  echo
  echo "Commit $commit, ${seconds} s per target with" \
       "$jobs workers (libFuzzer -fork), work directory \`$work\`."
  echo "Total: $total_cpu CPU seconds, $total_crashes new crash/leak/timeout/OOM artifacts" \
       "(in \`<work>/<target>/artifacts/\`; replay one with \`<target> FILE\`)."
  echo
  cat "$summary.rows"
} >"$summary"
rm -f "$summary.rows"
echo "summary written to $summary"
