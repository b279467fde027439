#!/usr/bin/env bash
# Validates SARIF files against the published SARIF 2.1.0 schema (vendored here,
# see README.md) and GitHub's extra requirements, after checking that the
# validator rejects deliberately broken SARIF; or, with --json-schema SCHEMA,
# shaderport JSON output against SCHEMA. Offline: Debian's python3-jsonschema.
#   tests/sarif/validate.sh [--json-schema SCHEMA] FILE...
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# Debian's interpreter is the one python3-jsonschema installs into.
python=/usr/bin/python3
[[ -x $python ]] || python=python3
if ! "$python" -c 'import jsonschema' 2>/dev/null; then
  echo "validate.sh: $python cannot import jsonschema (apt-get install python3-jsonschema)" >&2
  exit 2
fi
exec "$python" "$here/validate.py" "$@"
