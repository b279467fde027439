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
# Every shared library the executable links directly (its NEEDED entries)
# comes from a package it depends on.
checked=0
needed=$(readelf -d "$build/shaderport" | sed -nE 's/.*\(NEEDED\).*\[(.*)\]/\1/p')
for soname in $needed; do
  library=$(ldd "$build/shaderport" | awk -v name="$soname" '$1 == name {print $3}')
  # dpkg knows a file by the path its package ships, /lib or /usr/lib.
  real=$(readlink -f "$library")
  package=""
  for candidate in "$library" "$real" "${real#/usr}"; do
    package=$(dpkg -S "$candidate" 2>/dev/null | head -1 | cut -d: -f1) && break
  done
  [[ -n "$package" ]] || { echo "FAIL: no package ships $library" >&2; exit 1; }
  checked=$((checked + 1))
  depended=$(tr ',' '\n' <<<"$depends" | awk '{print $1}')
  grep -qxF "$package" <<<"$depended" || {
    echo "FAIL: $library ($package) is not in Depends" >&2
    exit 1
  }
done
[[ $checked -gt 0 ]] || { echo "FAIL: the executable needs no shared library?" >&2; exit 1; }
echo "deb: $(basename "$deb") holds the executable, headers, libraries and CMake package; $checked linked libraries are in Depends"
