// The VS Code client of `shaderport lsp`: GLSL files (and ShaderToy JSON projects)
// are checked by the same engine as `shaderport check`; fix-its are quick fixes.
const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration('shaderport').get('path', 'shaderport');
  const server = { command, args: ['lsp'] };
  client = new LanguageClient('shaderport', 'shaderport', { run: server, debug: server }, {
    documentSelector: [
      { scheme: 'file', language: 'glsl' },
      { scheme: 'untitled', language: 'glsl' },
      { scheme: 'file', pattern: '**/*.shadertoy.json' },
    ],
    // The server reads `shaderport.target` from workspace/didChangeConfiguration.
    synchronize: { configurationSection: 'shaderport' },
  });
  context.subscriptions.push({ dispose: () => client && client.stop() });
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
