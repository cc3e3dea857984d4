// Starts `voxc lsp` for .vox files: the server checks each file with voxc's own checker and
// answers hover and completion (docs/editors.md).
const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration('voxc').get('path', 'voxc');
  client = new LanguageClient(
    'voxc',
    'voxc',
    { command, args: ['lsp'] },
    { documentSelector: [{ scheme: 'file', language: 'vox' }] });
  context.subscriptions.push({ dispose: () => client && client.stop() });
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
