#!/usr/bin/env bash
# A new user's first session with shaderport, item by item of what they need to
# trust it (the CLI contract of docs/cli.md), run through the real binary on real
# ShaderToy code, a WebGL2 shader and a ShaderToy project. Fails on the first
# regression, naming it.
#   tests/new-user/session.sh SHADERPORT SOURCE_DIR SCRATCH_DIR
set -uo pipefail
sp=$1
source_dir=$2
scratch=$3
rm -rf "$scratch"
mkdir -p "$scratch"
cd "$scratch" || exit 1
export NO_COLOR=1
steps=0

fail() {
  echo "FAIL: $*" >&2
  exit 1
}
# expect CODE COMMAND...: runs the command, keeps its output in $out and $err.
expect() {
  local code=$1
  shift
  out=$("$@" 2>err.txt)
  status=$?
  err=$(cat err.txt)
  steps=$((steps + 1))
  [[ $status -eq $code ]] || fail "'$*' exited $status, expected $code${err:+: $err}"
}
contains() { [[ $1 == *"$2"* ]] || fail "expected '$2' in: ${1:0:1500}"; }
lacks() { [[ $1 != *"$2"* ]] || fail "did not expect '$2' in: ${1:0:1500}"; }

cat >toy.glsl <<'GLSL'
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    vec2 uv = fragCoord / iResolution.xy;
    float t = iGlobalTime * 1;
    vec3 c = 0.5;
    fragColor = vec4(c * t, 1.0);
}
GLSL
cat >bad.glsl <<'GLSL'
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    fragColor = vec4(nothing);
}
GLSL
cat >loop.glsl <<'GLSL'
void mainImage(out vec4 fragColor, in vec2 fragCoord)
{
    float t = 0.0;
    while (t < 1.0) { fragColor += 0.1; }
}
GLSL
cat >unwritten.frag <<'GLSL'
#version 300 es
precision highp float;
out vec4 color;
void main() { vec4 c = vec4(1.0); }
GLSL
mkdir -p empty shaders/a
cp toy.glsl shaders/a/b.glsl
cp toy.glsl shaders/c.glsl

# 1. One contract: help, typos answered with a suggestion, exit 2 for usage errors.
expect 0 "$sp" help
contains "$out" "check"
expect 0 "$sp" help check
contains "$out" "--fail-on"
expect 2 "$sp" chek toy.glsl
contains "$err" "shaderport: error: unknown command 'chek'; did you mean 'check'?"
expect 2 "$sp" check --fromat json toy.glsl
contains "$err" "did you mean '--format'?"
expect 2 "$sp" check --target webgl3 toy.glsl
contains "$err" "did you mean"
expect 2 "$sp" check missing.glsl
contains "$err" "shaderport: error:"

# 2. Empty input is an error unless --allow-empty.
expect 2 "$sp" check empty
expect 0 "$sp" check --allow-empty empty

# 3. fix fails only on what remains at --fail-on (default error).
expect 0 "$sp" fix toy.glsl
contains "$out" "iTime * 1.0"

# 4. check marks what fix repairs and counts it.
expect 1 "$sp" check toy.glsl
contains "$out" "error: [*] 'iGlobalTime': undeclared identifier"
contains "$out" "[*] 3 fixable with 'shaderport fix'"
expect 1 "$sp" check --format json toy.glsl
contains "$out" '"fixable": true'

# 5. --channel takes one value; the path after it is a path.
expect 1 "$sp" check --channel 0=cube toy.glsl

# 6. port writes nothing that does not compile; several inputs need --out-dir;
#    named files and directories share one layout.
expect 1 "$sp" port -o out.frag bad.glsl
[[ ! -e out.frag ]] || fail "port wrote a shader that does not compile"
contains "$err" "not written"
expect 2 "$sp" port toy.glsl bad.glsl
contains "$err" "--out-dir"
expect 0 "$sp" port --out-dir one shaders
expect 0 "$sp" port --out-dir two shaders/a/b.glsl shaders/c.glsl
[[ -f one/a/b.frag && -f two/a/b.frag && -f two/c.frag ]] || fail "--out-dir layouts differ"

# 7. Static findings that need no picture.
expect 0 "$sp" check loop.glsl
contains "$out" "[portability/infinite-loop]"
expect 0 "$sp" check unwritten.frag
contains "$out" "[portability/output-never-written]"

# 8. Completion and the manual page come from the same option tables.
expect 0 "$sp" completion bash
contains "$out" "complete -o filenames -o bashdefault -F _shaderport shaderport"
expect 0 "$sp" man
contains "$out" ".TH SHADERPORT 1"
expect 0 "$sp" rules --list
contains "$out" "portability/infinite-loop"

# 11. The install script installs what the tests use on a minimal Debian.
grep -q '^  file$' "$source_dir/tools/install-deps.sh" || fail "install-deps.sh lacks 'file'"

# 12. The report opens with a gallery of pictures.
expect 0 "$sp" report --html report.html shaders
page=$(cat report.html)
contains "$page" "gallery"

echo "new-user session: $steps commands, every item as documented"
