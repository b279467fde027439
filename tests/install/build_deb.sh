#!/usr/bin/env bash
# Builds the .deb with cpack and checks it: the executable, the CMake package
# and the headers are in it, and its Depends name the Debian packages of the
# shared libraries the executable links (found by dpkg-shlibdeps).
#   tests/install/build_deb.sh BUILD_DIR SCRATCH_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
scratch=$2
rm -rf "$scratch"
mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)

(cd "$scratch" && cpack -G DEB --config "$build/CPackConfig.cmake" -B "$scratch" >cpack.log 2>&1) || {
  cat "$scratch/cpack.log" >&2
  exit 1
}
deb=$(ls "$scratch"/shaderport_*.deb)
contents=$(dpkg-deb -c "$deb")
for path in ./usr/bin/shaderport ./usr/lib/cmake/shaderport/shaderportConfig.cmake \
            ./usr/include/shaderport/driver/check_pipeline.h ./usr/lib/libshaderport_driver.a; do
  grep -qF " $path" <<<"$contents" || { echo "FAIL: $path is not in $deb" >&2; exit 1; }
done
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
# Every shared library the executable needs comes from a package it depends on.
checked=0
for library in $(ldd "$build/shaderport" | awk '/=> \//{print $3}'); do
  # dpkg knows a file by the path its package ships, /lib or /usr/lib.
  real=$(readlink -f "$library")
  package=""
  for candidate in "$library" "$real" "${real#/usr}"; do
    package=$(dpkg -S "$candidate" 2>/dev/null | head -1 | cut -d: -f1) && break
  done
  [[ -n "$package" ]] || { echo "FAIL: no package ships $library" >&2; exit 1; }
  checked=$((checked + 1))
  grep -qE "(^|, )$package( |,|$)" <<<"$depends" || {
    echo "FAIL: $library ($package) is not in Depends" >&2
    exit 1
  }
done
[[ $checked -gt 0 ]] || { echo "FAIL: ldd listed no libraries" >&2; exit 1; }
echo "deb: $(basename "$deb") holds the executable, headers, libraries and CMake package; $checked linked libraries are in Depends"
