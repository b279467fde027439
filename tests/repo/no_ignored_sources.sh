#!/usr/bin/env bash
# Files under the source directories that .gitignore hides are missing from a
# clean clone (CI's checkout), so a test that reads one passes here and fails
# there. Lists them and fails; skipped (77) outside a git work tree.
set -euo pipefail
cd "$1"
git rev-parse --is-inside-work-tree >/dev/null 2>&1 || exit 77
# Python's bytecode caches (written when one test script imports another) are
# regenerated on any machine: not sources.
ignored=$(git ls-files --others --ignored --exclude-standard -- \
  src rules tests corpus docs tools bench cmake | grep -v '/__pycache__/' || true)
if [[ -n "$ignored" ]]; then
  echo "ignored by .gitignore, so absent from a clean clone:" >&2
  echo "$ignored" >&2
  exit 1
fi
