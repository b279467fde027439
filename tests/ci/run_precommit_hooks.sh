#!/usr/bin/env bash
# Runs the repository's pre-commit hooks (.pre-commit-hooks.yaml) with Debian's
# pre-commit, as a user's `pre-commit run` would: `pre-commit try-repo` clones
# this repository (uncommitted changes included) and runs a hook on files of a
# scratch repository. Skipped (exit 77) when the source is not a git work tree.
#   run_precommit_hooks.sh SOURCE_DIR SHADERPORT_BINARY SCRATCH_DIR
set -euo pipefail
source_dir=$(cd "$1" && pwd)
binary_dir=$(cd "$(dirname "$2")" && pwd)
scratch=$3

if ! git -C "$source_dir" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "not a git work tree: $source_dir" >&2
  exit 77
fi

rm -rf "$scratch"
mkdir -p "$scratch/repo"
scratch=$(cd "$scratch" && pwd)
export PRE_COMMIT_HOME=$scratch/pre-commit-home
export PATH=$binary_dir:$PATH
export GIT_AUTHOR_NAME=shaderport-test GIT_AUTHOR_EMAIL=test@invalid
export GIT_COMMITTER_NAME=shaderport-test GIT_COMMITTER_EMAIL=test@invalid
export GIT_CONFIG_GLOBAL=/dev/null GIT_CONFIG_NOSYSTEM=1

cd "$scratch/repo"
git init -q .
mkdir shaders
printf '#version 300 es\nprecision highp float;\nout vec4 color;\nvoid main() { color = vec3(1.0); }\n' >shaders/bad.frag
printf '#version 300 es\nprecision highp float;\nout vec4 color;\nvoid main() { color = vec4(1.0); }\n' >shaders/good.frag
printf '#version 300 es\nprecision highp float;\nout vec4 color;\nvoid main() { vec3 v = 1.0; color = vec4(v, 1.0); }\n' >shaders/fixable.frag
printf 'not a shader\n' >notes.txt
git add .

run_hook() {  # hook-id files...
  local hook=$1
  shift
  pre-commit try-repo "$source_dir" "$hook" --files "$@" 2>&1
}

# shaderport-check: fails on the error, at its line; passes a clean file; skips
# files that are not shaders.
if output=$(run_hook shaderport-check shaders/bad.frag notes.txt); then
  echo "FAIL: shaderport-check passed a shader with an error:" >&2
  echo "$output" >&2
  exit 1
fi
grep -q "shaders/bad.frag:4:" <<<"$output" || {
  echo "FAIL: no finding at shaders/bad.frag:4 in:" >&2
  echo "$output" >&2
  exit 1
}
output=$(run_hook shaderport-check shaders/good.frag notes.txt) || {
  echo "FAIL: shaderport-check failed a clean shader:" >&2
  echo "$output" >&2
  exit 1
}

# shaderport-fix: rewrites the file, and pre-commit fails because it changed.
if output=$(run_hook shaderport-fix shaders/fixable.frag); then
  echo "FAIL: shaderport-fix did not report the file it changed:" >&2
  echo "$output" >&2
  exit 1
fi
grep -q "vec3 v = vec3(1.0);" shaders/fixable.frag || {
  echo "FAIL: shaderport-fix left:" >&2
  cat shaders/fixable.frag >&2
  exit 1
}
run_hook shaderport-fix shaders/fixable.frag >/dev/null || {
  echo "FAIL: a second shaderport-fix changed the file again" >&2
  exit 1
}
# shaderport-fix passes a file it cannot change whose findings are only warnings
# (as ruff's and eslint's fixers do): an array read before it is written has no
# zero to write in GLSL ES 1.00.
printf 'precision mediump float;\nvoid main() {\n  int i = 0;\n  float a[4];\n  gl_FragColor = vec4(a[i]);\n}\n' >shaders/warning.frag
git add shaders/warning.frag
before=$(cat shaders/warning.frag)
output=$(run_hook shaderport-fix shaders/warning.frag) || {
  echo "FAIL: shaderport-fix failed on a file with only unfixable warnings:" >&2
  echo "$output" >&2
  exit 1
}
[[ $(cat shaders/warning.frag) == "$before" ]] || {
  echo "FAIL: shaderport-fix changed shaders/warning.frag" >&2
  exit 1
}
echo "pre-commit hooks: check fails on an error and passes clean code; fix rewrites once and passes unfixable warnings"
