#!/usr/bin/env bash
# The GitHub Action's install step: Debian/Ubuntu packages, a release build of
# the executable (no tests), installed under $RUNNER_TEMP and put on PATH.
set -euo pipefail
source_dir=${GITHUB_ACTION_PATH:?run by the GitHub Action}
build_dir=${SHADERPORT_ACTION_BUILD_DIR:-$RUNNER_TEMP/shaderport-build}
prefix=$RUNNER_TEMP/shaderport

bash "$source_dir/tools/install-deps.sh" --build
cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DSHADERPORT_BUILD_TESTS=OFF >/dev/null
cmake --build "$build_dir" --target shaderport
cmake --install "$build_dir" --prefix "$prefix" --component runtime >/dev/null
echo "$prefix/bin" >>"$GITHUB_PATH"
"$prefix/bin/shaderport" version
