#!/usr/bin/env bash
# The soak_shared_corpora test: check, fix and port over every pass of the shared
# ShaderToy corpus and every stage of the shared conformance cases; fails on any
# crash, hang or internal/* finding, and when the counts differ from the committed
# report tests/reports/soak.md (SHADERPORT_UPDATE_GOLDENS=1 rewrites it: review
# the diff).
#   tools/soak/soak_test.sh SHADERPORT_BINARY SHARED_DIR WORK_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
binary=$1 shared=$2 work=$3
report=$work/soak.md
mkdir -p "$work"
python3 "$root/tools/soak/soak.py" --shaderport "$binary" \
  --shadertoy "$shared/corpus-shadertoy/permissive.jsonl" \
  --conformance "$shared/conformance/webgl-cts.jsonl" \
  --work "$work" --report "$report" >/dev/null
committed=$root/tests/reports/soak.md
if [[ ${SHADERPORT_UPDATE_GOLDENS:-} == 1 ]]; then
  cp "$report" "$committed"
  echo "soak_test: wrote $committed; review the diff"
elif ! diff -u "$committed" "$report"; then
  echo "soak_test: the counts differ from $committed (SHADERPORT_UPDATE_GOLDENS=1 to rewrite)" >&2
  exit 1
fi
