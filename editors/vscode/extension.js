// zero for VS Code: starts `zero server` (the language server of the zero Python package) for
// parameter lists (*.lis, *.lst), NC programs (*.nc, *.mpf, *.spf) and the YAML/TOML/JSON forms
// of lists. Everything else (findings, hover, completion, fixes, formatting, outline) is the server's.
"use strict";

const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

const SELECTOR = [
  { scheme: "file", pattern: "**/*.{lis,lst,LIS,LST}" },
  { scheme: "file", pattern: "**/*.{nc,mpf,spf,NC,MPF,SPF}" },
  { scheme: "file", language: "yaml" },
  { scheme: "file", language: "toml" },
  { scheme: "file", language: "json" },
];

function settings() {
  const config = vscode.workspace.getConfiguration("zero");
  return {
    debounce: config.get("debounce"),
    ruleDocs: config.get("ruleDocs") || null,
    structured: config.get("structured"),
    machine: config.get("machine"),
  };
}

function expand(text) {
  const folder = vscode.workspace.workspaceFolders && vscode.workspace.workspaceFolders[0];
  return folder ? text.replace(/\$\{workspaceFolder\}/g, folder.uri.fsPath) : text;
}

async function start() {
  const config = vscode.workspace.getConfiguration("zero");
  const command = (config.get("path") || ["zero"]).map(expand);
  const args = [...command.slice(1), "server", ...(config.get("args") || []).map(expand)];
  const folder = vscode.workspace.workspaceFolders && vscode.workspace.workspaceFolders[0];
  const serverOptions = {
    command: command[0],
    args,
    options: folder ? { cwd: folder.uri.fsPath } : {},
  };
  const clientOptions = {
    documentSelector: SELECTOR,
    initializationOptions: settings(),
    synchronize: { configurationSection: "zero" },
  };
  client = new LanguageClient("zero", "zero", serverOptions, clientOptions);
  await client.start();
}

async function restart() {
  if (client) {
    await client.stop();
    client = undefined;
  }
  await start();
}

function activate(context) {
  context.subscriptions.push(vscode.commands.registerCommand("zero.restart", restart));
  context.subscriptions.push(vscode.workspace.onDidChangeConfiguration((event) => {
    if (event.affectsConfiguration("zero.path") || event.affectsConfiguration("zero.args")) {
      restart();
    }
  }));
  return start().catch((error) => {
    vscode.window.showErrorMessage(
      `zero: cannot start \`${(vscode.workspace.getConfiguration("zero").get("path") || ["zero"]).join(" ")} server\`` +
      ` (${error.message}). Install zero (pip install zero-lint) or set zero.path.`);
  });
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
