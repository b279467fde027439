#!/usr/bin/env bash
# The GitHub Action's check step: SARIF for code scanning, workflow-command
# annotations for the pull request, and the exit code as a step output (the
# verdict comes after the upload, so findings are uploaded even when they fail
# the job).
set -uo pipefail
read -r -a paths <<<"${INPUT_PATHS:-.}"
read -r -a extra <<<"${INPUT_ARGS:-}"
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
