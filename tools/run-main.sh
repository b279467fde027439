#!/usr/bin/env bash
# Installs what is missing, builds shaderport, and runs the main job on the
# bundled corpus: every shader is checked (findings printed), ported to WebGL2,
# validated and rendered, and one self-contained HTML report is written.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

bash tools/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" --target shaderport

bin=build/release/shaderport
"$bin" summary corpus
set +e
"$bin" check corpus
status=$?
set -e
# The corpus holds deliberately broken shaders, so findings (exit 1) are expected;
# a usage (2) or internal (3) error is not.
if [[ $status -ge 2 ]]; then
  echo "run-main: shaderport check failed with exit $status" >&2
  exit "$status"
fi
"$bin" report --html build/corpus-report.html corpus
echo "run-main: done (check exit $status: findings are expected in the corpus)"
echo "run-main: report with a picture of every shader: build/corpus-report.html"
