// zero for VS Code: the languages `isg-list` (parameter lists, *.lis, *.lst) and `isg-nc` (NC
// programs, *.nc, *.mpf, *.spf) with their grammars and language configurations, and `zero server`
// (the language server of the zero Python package) for them, for XML lists and for the
// YAML/TOML/JSON forms of lists the settings name by pattern. Everything else (findings, hover,
// completion, fixes, formatting, outline, links) is the server's.
"use strict";

const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");
const { foldingRanges } = require("./folding");

const LANGUAGES = ["isg-list", "isg-nc"];
// The commands the extension contributes. `zero.fixAll` and `zero.showEffectiveValue` are the
// server's (`workspace/executeCommand`); the arguments come from the active editor.
const COMMANDS = {
  restart: "zero.restart",
  fixAll: "zero.fixAll",
  showEffectiveValue: "zero.showEffectiveValue",
};
const SERVER_COMMANDS = [COMMANDS.fixAll, COMMANDS.showEffectiveValue];
// Settings read when the client starts: a change restarts the server.
const RESTART_ON = ["zero.path", "zero.args", "zero.structuredGlobs", "zero.xmlGlobs"];

let client;
let fallbacks = []; // commands and providers of the extension's own, where the server has none

// Which documents the server gets: lists and NC programs (by language, and by name where
// `files.associations` gives them another language), XML lists and YAML/TOML/JSON forms only
// where the settings' patterns name them — never every YAML/TOML/JSON/XML file of the workspace.
function documentSelector(config) {
  const selector = [
    ...LANGUAGES.map((language) => ({ scheme: "file", language })),
    { scheme: "file", pattern: "**/*.{lis,lst,LIS,LST,Lis,Lst}" },
    { scheme: "file", pattern: "**/*.{nc,mpf,spf,NC,MPF,SPF}" },
  ];
  for (const pattern of [...(config.get("xmlGlobs") || []), ...(config.get("structuredGlobs") || [])]) {
    if (typeof pattern === "string" && pattern) {
      selector.push({ scheme: "file", pattern });
    }
  }
  return selector;
}

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

// The arguments of a server command run from the palette or a menu: [uri] for fix all,
// [uri, position] for the effective value, taken from the active editor.
function commandArguments(command, args) {
  if (args.length > 0 && !(args[0] instanceof vscode.Uri)) {
    return args; // given by the caller (a code lens, a keybinding with args)
  }
  const editor = vscode.window.activeTextEditor;
  const uri = args[0] instanceof vscode.Uri ? args[0] : editor && editor.document.uri;
  if (!uri) {
    return undefined;
  }
  const out = [client.code2ProtocolConverter.asUri(uri)];
  if (command === COMMANDS.showEffectiveValue) {
    if (!editor || editor.document.uri.toString() !== uri.toString()) {
      return undefined;
    }
    out.push(client.code2ProtocolConverter.asPosition(editor.selection.active));
  }
  return out;
}

// What the server answers: it applies fix all itself (`workspace/applyEdit`) and shows the effective
// value (`window/showMessage`); a refused edit is said, a returned workspace edit applied.
async function showResult(command, result) {
  if (result && (result.changes || result.documentChanges)) {
    await vscode.workspace.applyEdit(await client.protocol2CodeConverter.asWorkspaceEdit(result));
  } else if (command === COMMANDS.fixAll && result && result.applied === false) {
    vscode.window.showWarningMessage(`zero: the fixes were not applied${result.reason ? ` (${result.reason})` : ""}.`);
  }
  return result;
}

async function executeCommand(command, args, next) {
  if (!SERVER_COMMANDS.includes(command)) {
    return next(command, args);
  }
  const filled = commandArguments(command, args);
  if (!filled) {
    vscode.window.showWarningMessage(`zero: ${command} needs an open list or NC program.`);
    return undefined;
  }
  return showResult(command, await next(command, filled));
}

// Where the server does not offer a command (an older zero), the extension registers it: fix
// all as the `source.fixAll.zero` code action, the effective value through the hover.
function registerFallbacks() {
  const capabilities = (client && client.initializeResult && client.initializeResult.capabilities) || {};
  const offered = (capabilities.executeCommandProvider && capabilities.executeCommandProvider.commands) || [];
  if (!offered.includes(COMMANDS.fixAll)) {
    fallbacks.push(vscode.commands.registerCommand(COMMANDS.fixAll, () =>
      vscode.commands.executeCommand("editor.action.codeAction", { kind: "source.fixAll.zero", apply: "first" })));
  }
  if (!offered.includes(COMMANDS.showEffectiveValue)) {
    fallbacks.push(vscode.commands.registerCommand(COMMANDS.showEffectiveValue, () =>
      vscode.commands.executeCommand("editor.action.showHover")));
  }
  if (!capabilities.foldingRangeProvider) {
    fallbacks.push(vscode.languages.registerFoldingRangeProvider({ language: "isg-list" }, {
      provideFoldingRanges(document) {
        const lines = [];
        for (let i = 0; i < document.lineCount; i += 1) {
          lines.push(document.lineAt(i).text);
        }
        return foldingRanges(lines).map((r) => new vscode.FoldingRange(r.start, r.end,
          r.kind === "comment" ? vscode.FoldingRangeKind.Comment : vscode.FoldingRangeKind.Region));
      },
    }));
  }
}

function disposeFallbacks() {
  for (const disposable of fallbacks) {
    disposable.dispose();
  }
  fallbacks = [];
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
    documentSelector: documentSelector(config),
    initializationOptions: settings(),
    synchronize: { configurationSection: "zero" },
    middleware: { executeCommand },
  };
  disposeFallbacks(); // the client registers the server's commands under the same names
  client = new LanguageClient("zero", "zero", serverOptions, clientOptions);
  try {
    await client.start();
  } finally {
    registerFallbacks();
  }
}

async function restart() {
  if (client) {
    const old = client;
    client = undefined;
    await old.stop().catch(() => undefined); // a dead server cannot say goodbye
  }
  await start();
}

function startFailed(error) {
  const path = (vscode.workspace.getConfiguration("zero").get("path") || ["zero"]).join(" ");
  vscode.window.showErrorMessage(
    `zero: cannot start \`${path} server\` (${error.message}). Install zero (pip install zero-lint) or set zero.path.`);
}

function activate(context) {
  context.subscriptions.push(vscode.commands.registerCommand(COMMANDS.restart, () => restart().catch(startFailed)));
  context.subscriptions.push(vscode.workspace.onDidChangeConfiguration((event) => {
    if (RESTART_ON.some((section) => event.affectsConfiguration(section))) {
      restart().catch(startFailed);
    }
  }));
  context.subscriptions.push({ dispose: disposeFallbacks });
  return start().catch(startFailed);
}

function deactivate() {
  disposeFallbacks();
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate, documentSelector, COMMANDS };
