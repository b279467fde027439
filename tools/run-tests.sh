#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test: a release build, an
# ASan+UBSan build, and a short libFuzzer run. `.ci/run` calls this script.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

bash tools/install-deps.sh
# The editor-client tests use the VS Code extension's npm packages, pinned by its
# lockfile; installed here, so that no test fetches anything while it runs.
(cd editors/vscode && npm ci --no-audit --no-fund --loglevel=error)

jobs=$(nproc)
export CTEST_OUTPUT_ON_FAILURE=1
passed=0
failed=0

run_ctest() {  # build-dir label
  local log
  log=$(mktemp)
  set +e
  ctest --test-dir "$1" -j "$jobs" --timeout 600 2>&1 | tee "$log"
  local status=${PIPESTATUS[0]}
  set -e
  local total fails
  total=$(sed -nE 's/.*tests passed, ([0-9]+) tests failed out of ([0-9]+).*/\2/p' "$log" | tail -1)
  fails=$(sed -nE 's/.*tests passed, ([0-9]+) tests failed out of ([0-9]+).*/\1/p' "$log" | tail -1)
  total=${total:-0}
  fails=${fails:-0}
  if [[ $status -ne 0 && $fails -eq 0 ]]; then fails=1; fi
  passed=$((passed + total - fails))
  failed=$((failed + fails))
  echo "== $2: $((total - fails)) passed, $fails failed"
  rm -f "$log"
}

echo "== release build"
cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs"
run_ctest build/release release

echo "== ASan+UBSan build"
cmake --preset asan-ubsan >/dev/null
cmake --build --preset asan-ubsan -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
LSAN_OPTIONS=suppressions=$root/tools/lsan.supp \
  run_ctest build/asan-ubsan asan-ubsan

if [[ -f tests/fuzz/CMakeLists.txt ]]; then
  echo "== fuzz build (clang, libFuzzer)"
  cmake --preset fuzz >/dev/null
  cmake --build --preset fuzz -j "$jobs" --target fuzz_frontend fuzz_webgl_semantics fuzz_fix \
    fuzz_port fuzz_check fuzz_config fuzz_shadertoy_json fuzz_project_json fuzz_suppressions \
    fuzz_formatters fuzz_lsp
  run_ctest build/fuzz fuzz
fi

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
