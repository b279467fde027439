#!/usr/bin/env bash
# Neovim (Debian's, headless, its built-in LSP client) against `shaderport lsp`:
# the diagnostics arrive and the first one's quick fix repairs the buffer.
#   tests/editors/neovim_lsp.sh SHADERPORT SOURCE_DIR SCRATCH_DIR
set -euo pipefail
binary=$(realpath "$1")
source_dir=$(cd "$2" && pwd)
scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch"
cd "$scratch"
cat >toy.glsl <<'GLSL'
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float t = iGlobalTime;
    fragColor = vec4(t);
}
GLSL
SHADERPORT=$binary timeout 120 nvim --headless -u NONE -i NONE \
  -c "luafile $source_dir/tests/editors/neovim_lsp.lua" toy.glsl
grep -qx '    float t = iTime;' toy.glsl.result || {
  echo "FAIL: the quick fix did not reach the buffer:" >&2
  cat toy.glsl.result >&2
  exit 1
}
grep -q '^DIAGNOSTICS 1 FIRST glslang/undeclared-identifier$' toy.glsl.result || {
  echo "FAIL: diagnostics as Neovim got them:" >&2
  tail -1 toy.glsl.result >&2
  exit 1
}
echo "neovim: $(nvim --version | head -1): diagnostics published, quick fix applied"
