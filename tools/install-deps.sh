#!/usr/bin/env bash
# Installs every build and test dependency of shaderport from Debian 12 packages.
# Idempotent: packages already present are skipped, and apt is not touched at all
# when nothing is missing.
#   tools/install-deps.sh           everything the build and the test suite need
#   tools/install-deps.sh --build   only what building and installing the
#                                   executable needs (the GitHub Action uses this)
#   tools/install-deps.sh --bench   what building needs, and the profiler the
#                                   on-demand benchmarks use (bench/, not CI)
set -euo pipefail

build_packages=(
  build-essential cmake ninja-build pkg-config ccache git
  glslang-dev glslang-tools spirv-tools
  libspirv-cross-c-shared-dev spirv-cross
  libosmesa6-dev libpng-dev
  libegl1 libegl-mesa0 libgl1-mesa-dri
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libfmt-dev libmimalloc-dev
  # cpack's DEB generator runs `file` on what it packs (the .deb of docs/ci.md);
  # a minimal Debian 12 (debootstrap --variant=minbase, the debian:12 image) lacks it.
  file
)
test_packages=(
  # Test drivers and scripts (GitHub Action, schemas, browser pages, soak) are
  # Python 3, which a minimal Debian lacks.
  python3
  clang-14 libclang-rt-14-dev clang-format clang-tidy
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  # The GitHub Action and pre-commit hook tests read YAML and run pre-commit.
  python3-yaml pre-commit
  # The SARIF and JSON schema tests validate offline (tests/sarif/validate.py).
  python3-jsonschema
  # Browser tests open generated pages in headless Chromium (SwiftShader WebGL).
  chromium
  # The completion tests run the generated scripts in each shell; the man page
  # test renders shaderport(1) with groff and fails on a warning.
  zsh fish groff-base
  # The language server's end-to-end test drives Neovim's built-in LSP client.
  neovim
)

# bench/parallel_scaling_sim.py counts instructions per file with callgrind.
bench_packages=(valgrind)

packages=("${build_packages[@]}")
case "${1:-}" in
  --build) ;;
  --bench) packages+=("${bench_packages[@]}") ;;
  *) packages+=("${test_packages[@]}") ;;
esac

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
# The editor-client tests run Node and npm (editors/vscode's pinned packages need
# Node 16 or later). A machine that has them (Debian's nodejs and npm, or another
# Node with its own npm) is left alone: Debian's npm package conflicts with Node
# builds that bundle npm.
if [[ ${1:-} != --build && ${1:-} != --bench ]] && ! { command -v node && command -v npm; } >/dev/null; then
  missing+=(nodejs npm)
fi

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
