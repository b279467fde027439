#!/usr/bin/env bash
# The GitHub Action's check step: SARIF for code scanning, workflow-command
# annotations for the pull request, and the exit code as a step output (the
# verdict comes after the upload, so findings are uploaded even when they fail
# the job).
set -uo pipefail
# Paths one per line (spaces inside a path kept); args split as a shell would
# (xargs honours quotes and backslashes, and runs nothing).
paths=()
while IFS= read -r line; do
  line=${line#"${line%%[![:space:]]*}"}
  line=${line%"${line##*[![:space:]]}"}
  [[ -n $line ]] && paths+=("$line")
done <<<"${INPUT_PATHS:-.}"
((${#paths[@]} > 0)) || paths=(.)
extra=()
if [[ -n ${INPUT_ARGS:-} ]]; then
  if ! parsed=$(printf '%s' "$INPUT_ARGS" | xargs -n 1 printf '%s\n' 2>&1); then
    echo "::error title=shaderport::the args input cannot be split: $parsed"
    echo "exit-code=2" >>"$GITHUB_OUTPUT"
    exit 2
  fi
  mapfile -t extra <<<"$parsed"
fi
sarif=${INPUT_SARIF_FILE:-shaderport.sarif}
fail_on=${INPUT_FAIL_ON:-error}

shaderport check --format sarif --fail-on "$fail_on" "${extra[@]}" "${paths[@]}" >"$sarif"
status=$?
if [[ $status -ge 2 ]]; then
  echo "::error title=shaderport::shaderport check failed to run (exit $status)"
  echo "exit-code=$status" >>"$GITHUB_OUTPUT"
  exit "$status"
fi
if [[ "${INPUT_ANNOTATE:-true}" == "true" ]]; then
  shaderport check --format github --fail-on "$fail_on" "${extra[@]}" "${paths[@]}"
fi
echo "sarif-file=$sarif" >>"$GITHUB_OUTPUT"
echo "exit-code=$status" >>"$GITHUB_OUTPUT"
