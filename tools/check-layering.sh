#!/usr/bin/env bash
# Fails when a layer includes a header from a layer above it.
# Layers, lowest first (a layer may include itself and anything listed before it,
# except that toolchain, validate and report are siblings that do not include each other).
# The harness model (dialects, the ShaderToy site's uniforms) is in model, so toolchain,
# validate and render read it without reaching up to rule.
set -euo pipefail
root=${1:-$(dirname "$0")/..}
declare -A allowed=(
  [base]="base"
  [model]="base model"
  [source]="base model source"
  [diag]="base model source diag"
  [glsl]="base model source diag glsl"
  [toolchain]="base model source diag toolchain"
  [validate]="base model source diag glsl validate"
  [report]="base model source diag report"
  [rule]="base model source diag glsl rule"
  [render]="base model source diag render"
  [driver]="base model source diag glsl toolchain validate report rule rules render driver"
)
status=0
for layer in "${!allowed[@]}"; do
  dir="$root/src/$layer"
  [[ -d $dir ]] || continue
  while IFS= read -r line; do
    file=${line%%:*}
    inc=$(sed -E 's/.*#include "([a-z_]+)\/.*/\1/' <<<"$line")
    if [[ " ${allowed[$layer]} " != *" $inc "* ]]; then
      echo "layering: ${file#"$root"/} (layer $layer) includes $inc/" >&2
      status=1
    fi
  done < <(grep -rHE '^#include "[a-z_]+/' "$dir" || true)
done
# rules/ may use the rule framework and everything below it, nothing above.
if grep -rHE '^#include "(driver|validate|report|toolchain|render)/' "$root/rules" 2>/dev/null; then
  echo "layering: rules/ includes a layer above the rule framework" >&2
  status=1
fi
# The CLI may include only the driver's public headers (and lower ones), never rules directly.
if grep -rHE '^#include "rules/' "$root/tools/shaderport" 2>/dev/null; then
  echo "layering: tools/shaderport includes rules/ (go through the driver)" >&2
  status=1
fi
exit $status
