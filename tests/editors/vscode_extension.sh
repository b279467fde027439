#!/usr/bin/env bash
# The VS Code extension (editors/vscode): its pinned npm dependencies (installed by
# tools/run-tests.sh with `npm ci` before the tests; this test fetches nothing) drive
# `shaderport lsp` through VS Code's protocol library, and `vsce package` makes a .vsix
# whose manifest is checked as VS Code's extension format.
#   tests/editors/vscode_extension.sh SHADERPORT SOURCE_DIR SCRATCH_DIR
set -euo pipefail
binary=$(realpath "$1")
source_dir=$(cd "$2" && pwd)
scratch=$3
extension=$source_dir/editors/vscode
rm -rf "$scratch"
mkdir -p "$scratch"
scratch=$(cd "$scratch" && pwd)
if [[ ! -d $extension/node_modules/vscode-languageclient ]]; then
  echo "FAIL: editors/vscode/node_modules is missing: run 'npm ci' there (tools/run-tests.sh does)" >&2
  exit 1
fi
node "$source_dir/tests/editors/vscode_client.js" "$binary" "$extension" "$scratch/client"
(cd "$extension" && npx --no-install vsce package --skip-license --allow-missing-repository \
  -o "$scratch/shaderport.vsix" >"$scratch/vsce.log" 2>&1) || {
  cat "$scratch/vsce.log" >&2
  exit 1
}
python3 - "$scratch/shaderport.vsix" <<'PY'
import json, sys, zipfile
import xml.etree.ElementTree as ET
vsix = zipfile.ZipFile(sys.argv[1])
names = set(vsix.namelist())
for needed in ("extension.vsixmanifest", "[Content_Types].xml", "extension/package.json",
               "extension/extension.js", "extension/language-configuration.json",
               "extension/node_modules/vscode-languageclient/node.js"):
    if needed not in names:
        sys.exit("FAIL: %s is not in the .vsix" % needed)
manifest = json.loads(vsix.read("extension/package.json"))
for key in ("name", "publisher", "version", "engines", "main", "contributes"):
    if key not in manifest:
        sys.exit("FAIL: package.json has no %s" % key)
identity = ET.fromstring(vsix.read("extension.vsixmanifest")).find(
    ".//{http://schemas.microsoft.com/developer/vsx-schema/2011}Identity")
if identity is None or identity.get("Id") != manifest["name"] or identity.get("Version") != manifest["version"]:
    sys.exit("FAIL: the vsixmanifest's identity does not match package.json")
languages = manifest["contributes"]["languages"][0]
if not {".glsl", ".frag", ".vert"} <= set(languages["extensions"]):
    sys.exit("FAIL: the glsl language does not take .glsl/.frag/.vert")
print("vsix: %d files, %s %s for VS Code %s" % (len(names), identity.get("Id"),
                                                identity.get("Version"), manifest["engines"]["vscode"]))
PY
