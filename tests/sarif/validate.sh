#!/usr/bin/env bash
# Validates SARIF files with a real validator (ajv and the published SARIF 2.1.0
# schema), after checking that it rejects deliberately broken SARIF.
#   tests/sarif/validate.sh [--json-schema SCHEMA] FILE...
# The npm packages are installed with `npm ci` into $SHADERPORT_SARIF_WORK_DIR
# (default: ./sarif-validator under the current directory, i.e. the build tree
# when ctest runs it) and reused while package-lock.json is unchanged.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
work="${SHADERPORT_SARIF_WORK_DIR:-$PWD/sarif-validator}"

if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  echo "validate.sh: node and npm are required" >&2
  exit 2
fi

mkdir -p "$work"
if [[ ! -d "$work/node_modules" ]] || ! cmp -s "$here/package-lock.json" "$work/package-lock.json"; then
  cp "$here/package.json" "$here/package-lock.json" "$work/"
  (cd "$work" && npm ci --no-audit --no-fund --loglevel=error) >&2
fi
cp "$here/validate.js" "$work/validate.js"

# Make relative file arguments absolute: node runs with the work dir's modules.
args=()
for arg in "$@"; do
  if [[ "$arg" != -* && "$arg" != /* ]]; then arg="$PWD/$arg"; fi
  args+=("$arg")
done
exec node "$work/validate.js" "${args[@]}"
