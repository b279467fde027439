#!/usr/bin/env bash
# The GitHub Action's install step: the given .deb (INPUT_DEB) unpacked, or
# Debian/Ubuntu packages and a release build of the executable (no tests); either
# way installed under $RUNNER_TEMP and put on PATH.
set -euo pipefail
source_dir=${GITHUB_ACTION_PATH:?run by the GitHub Action}
build_dir=${SHADERPORT_ACTION_BUILD_DIR:-$RUNNER_TEMP/shaderport-build}
prefix=$RUNNER_TEMP/shaderport

# A .deb made once (cpack) and shared between jobs: its run-time dependencies come
# from the runner's apt, and the package is unpacked under $RUNNER_TEMP (no build).
if [[ -n ${INPUT_DEB:-} ]]; then
  deb=$(realpath "$INPUT_DEB")
  mapfile -t depends < <(dpkg-deb -f "$deb" Depends | tr ',' '\n' | sed -E 's/\(.*\)//; s/\|.*//; s/[[:space:]]//g' | sed '/^$/d')
  missing=()
  for p in "${depends[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]} > 0)); then
    sudo_cmd=()
    [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
  fi
  rm -rf "$prefix"
  dpkg-deb -x "$deb" "$prefix"
  echo "$prefix/usr/bin" >>"$GITHUB_PATH"
  "$prefix/usr/bin/shaderport" version
  exit 0
fi

bash "$source_dir/tools/install-deps.sh" --build
cmake -S "$source_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DSHADERPORT_BUILD_TESTS=OFF >/dev/null
cmake --build "$build_dir" --target shaderport
cmake --install "$build_dir" --prefix "$prefix" --component runtime >/dev/null
echo "$prefix/bin" >>"$GITHUB_PATH"
"$prefix/bin/shaderport" version
