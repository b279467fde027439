#!/usr/bin/env bash
# Installs a built shaderport into a scratch prefix, moves the prefix (an
# installed tree must not need the build or source tree), builds a consumer
# project against it with find_package(shaderport), and runs both the consumer
# and the installed executable on a good and a bad shader.
#   tests/install/install_and_consume.sh BUILD_DIR SCRATCH_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd)
scratch=$2
rm -rf "$scratch"
mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)

cmake --install "$build" --prefix "$scratch/staging" >/dev/null
mv "$scratch/staging" "$scratch/prefix"
prefix=$scratch/prefix

test -x "$prefix/bin/shaderport"
test -f "$prefix/lib/cmake/shaderport/shaderportConfig.cmake"
test -f "$prefix/include/shaderport/driver/check_pipeline.h"

cat >"$scratch/good.frag" <<'GLSL'
precision mediump float;
void main() { gl_FragColor = vec4(1.0); }
GLSL
cat >"$scratch/bad.frag" <<'GLSL'
precision mediump float;
void main() { gl_FragColor = vec3(1.0); }
GLSL

generator=()
if command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S "$here/consumer" -B "$scratch/consumer-build" "${generator[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$scratch/consumer-build" >/dev/null

consumer=$scratch/consumer-build/consumer
"$consumer" "$scratch/good.frag"
if "$consumer" "$scratch/bad.frag" >"$scratch/bad.txt"; then
  echo "consumer: the bad shader passed" >&2
  exit 1
fi
grep -q "bad.frag:2:" "$scratch/bad.txt"

# The installed executable, away from the source tree: the shipped dialects are
# compiled in.
(cd "$scratch" && "$prefix/bin/shaderport" check --no-config good.frag >/dev/null)
cat >"$scratch/blog.frag" <<'GLSL'
void main() { color = vec4(uv, 0.5 + 0.5 * sin(time), 1.0); }
GLSL
(cd "$scratch" && "$prefix/bin/shaderport" port --dialect raymarch-blog blog.frag >blog-port.frag)
grep -q "uniform highp float time;" "$scratch/blog-port.frag"
"$prefix/bin/shaderport" rules >"$scratch/rules.txt"
grep -q "shadertoy/" "$scratch/rules.txt"
echo "installed tree at $prefix: consumer and executable work"
