// The VS Code client of `shaderport lsp`: GLSL files (and ShaderToy JSON projects)
// are checked by the same engine as `shaderport check`; fix-its are quick fixes. The
// status bar shows what the active file's verdict is against (shaderport/status).
const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

// Status bar text and tooltip for one shaderport/status notification.
function describe(status) {
  const verdict = status.fails ? '$(error)' : '$(check)';
  const tooltip = [
    `Checked as a ${status.dialect} ${status.stage} shader for ${status.target}`,
    status.harness ? `harness: ${status.harness}` : '',
    status.channels.length ? `channels: ${status.channels.map((c, i) => `iChannel${i} ${c}`).join(', ')}` : '',
    `fails at: ${status.failOn}${status.rendered ? ' (rendered on save)' : ''}`,
  ].filter(Boolean).join('\n');
  return { text: `${verdict} shaderport: ${status.summary}`, tooltip };
}

function activate(context) {
  const command = vscode.workspace.getConfiguration('shaderport').get('path', 'shaderport');
  const server = { command, args: ['lsp'] };
  client = new LanguageClient('shaderport', 'shaderport', { run: server, debug: server }, {
    documentSelector: [
      { scheme: 'file', language: 'glsl' },
      { scheme: 'untitled', language: 'glsl' },
      { scheme: 'file', pattern: '**/*.shadertoy.json' },
    ],
    // The server reads `shaderport.*` from workspace/didChangeConfiguration.
    synchronize: { configurationSection: 'shaderport' },
  });
  const bar = vscode.window.createStatusBarItem(vscode.StatusBarAlignment.Left);
  const statuses = new Map();
  const show = () => {
    const editor = vscode.window.activeTextEditor;
    const status = editor && statuses.get(editor.document.uri.toString());
    if (!status) return bar.hide();
    Object.assign(bar, describe(status));
    bar.show();
  };
  context.subscriptions.push(bar, vscode.window.onDidChangeActiveTextEditor(show));
  context.subscriptions.push({ dispose: () => client && client.stop() });
  return client.start().then(() => {
    client.onNotification('shaderport/status', (status) => {
      statuses.set(vscode.Uri.parse(status.uri).toString(), status);
      show();
    });
  });
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate, describe };
