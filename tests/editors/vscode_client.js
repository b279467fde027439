// The protocol library VS Code's client is built on (vscode-languageserver-protocol,
// from editors/vscode's pinned dependencies) against `shaderport lsp`: initialize,
// open a ShaderToy pass, wait for the diagnostics, ask for the code actions, apply
// the quick fix of the first finding, read the status notification, shut down.
//   node vscode_client.js SHADERPORT EXTENSION_DIR SCRATCH_DIR
const path = require('path');
const fs = require('fs');
const cp = require('child_process');
const [binary, extensionDir, scratch] = process.argv.slice(2);
const protocol = require(path.join(extensionDir, 'node_modules', 'vscode-languageserver-protocol', 'node'));

function fail(message) {
  console.error('FAIL: ' + message);
  process.exit(1);
}

async function main() {
  fs.mkdirSync(scratch, { recursive: true });
  const file = path.join(scratch, 'toy.glsl');
  const text = 'void mainImage(out vec4 fragColor, in vec2 fragCoord)\n{\n    float t = iGlobalTime;\n    fragColor = vec4(t);\n}\n';
  fs.writeFileSync(file, text);
  const server = cp.spawn(binary, ['lsp'], { cwd: scratch, stdio: ['pipe', 'pipe', 'inherit'] });
  const connection = protocol.createProtocolConnection(
    new protocol.StreamMessageReader(server.stdout), new protocol.StreamMessageWriter(server.stdin));
  const published = new Promise((resolve) =>
    connection.onNotification(protocol.PublishDiagnosticsNotification.type, resolve));
  const statused = new Promise((resolve) =>
    connection.onNotification(new protocol.NotificationType('shaderport/status'), resolve));
  connection.listen();
  const init = await connection.sendRequest(protocol.InitializeRequest.type,
    { processId: process.pid, rootUri: null, capabilities: {} });
  if (init.capabilities.textDocumentSync.change !== protocol.TextDocumentSyncKind.Incremental) {
    fail('sync kind ' + JSON.stringify(init.capabilities.textDocumentSync));
  }
  await connection.sendNotification(protocol.InitializedNotification.type, {});
  const uri = 'file://' + file;
  await connection.sendNotification(protocol.DidOpenTextDocumentNotification.type,
    { textDocument: { uri, languageId: 'glsl', version: 1, text } });
  const diagnostics = (await published).diagnostics;
  if (diagnostics.length !== 1 || diagnostics[0].code !== 'glslang/undeclared-identifier') {
    fail('diagnostics ' + JSON.stringify(diagnostics));
  }
  const status = await statused;
  if (status.target !== 'webgl2' || status.harness !== 'shadertoy' || !status.fails ||
      status.summary !== 'webgl2, shadertoy') {
    fail('status ' + JSON.stringify(status));
  }
  const actions = await connection.sendRequest(protocol.CodeActionRequest.type, {
    textDocument: { uri }, range: diagnostics[0].range, context: { diagnostics },
  });
  const quick = actions.find((a) => a.kind === 'quickfix');
  if (!quick) fail('no quick fix: ' + JSON.stringify(actions));
  const edit = quick.edit.changes[uri][0];
  const lines = text.split('\n');
  const line = lines[edit.range.start.line];
  lines[edit.range.start.line] = line.slice(0, edit.range.start.character) + edit.newText +
    line.slice(edit.range.end.character);
  if (lines[2] !== '    float t = iTime;') fail('the quick fix gave ' + lines[2]);
  await connection.sendRequest(protocol.ShutdownRequest.type);
  await connection.sendNotification(protocol.ExitNotification.type);
  const code = await new Promise((resolve) => server.on('exit', resolve));
  if (code !== 0) fail('exit code ' + code);
  console.log('vscode-languageserver-protocol: diagnostics, status, quick fix, shutdown');
  process.exit(0);
}

main().catch((error) => fail(String(error && error.stack || error)));
