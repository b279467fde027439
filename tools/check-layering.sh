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
# The CLI parses options, calls the driver and prints (docs/architecture.md): it
# includes the driver's public headers and the layers below, never the front end,
# the validator or the rules, which it reaches through the driver's pipelines.
if grep -rHE '^#include "(rules|rule|glsl|validate)/' "$root/tools/shaderport" 2>/dev/null; then
  echo "layering: tools/shaderport includes rules/, rule/, glsl/ or validate/ (go through the driver)" >&2
  status=1
fi
# The driver's public headers: the pipelines' entry points (check, fix, port, render,
# report, summary, dump, the language server) and the types they take and give.
# The steps inside a pipeline (parallel runs, config lookup, per-file porting and
# linking, project documents) are the driver's own.
driver_public=(
  check_file.h check_options.h check_pipeline.h dialect.h dump.h harness_dialects.h
  html_report/build_report.h input_files.h input_selection.h lsp/lsp_server.h
  port/fix_run.h port/output_files.h port/port_file.h port/port_report.h port/port_run.h
  port/rule_reference.h read_input.h render_check/render_file.h
  render_check/render_multipass.h result_cache.h summary.h
)
while IFS= read -r line; do
  header=$(sed -E 's/.*#include "driver\/([^"]+)".*/\1/' <<<"$line")
  if [[ " ${driver_public[*]} " != *" $header "* ]]; then
    file=${line%%:*}
    echo "layering: ${file#"$root"/} includes driver/$header, which is not one of the driver's public headers" >&2
    status=1
  fi
done < <(grep -rHE '^#include "driver/' "$root/tools/shaderport" 2>/dev/null || true)
exit $status
