// The tokens of lines under one of the extension's grammars, as VS Code's own TextMate engine
// (vscode-textmate with vscode-oniguruma, installed with vscode-tmgrammar-test) gives them.
// stdin: {"grammar": "<path of a .tmLanguage.json>", "documents": [["line", ...], ...]}
// stdout: per document, per line, a list of [startIndex, endIndex, [scopes...]] (UTF-16 offsets).
// tests/editors/test_vscode_extension.py compares them with zero's tokenizer.
"use strict";

const fs = require("fs");
const path = require("path");
const vsctm = require("vscode-textmate");
const oniguruma = require("vscode-oniguruma");

async function main() {
  const input = JSON.parse(fs.readFileSync(0, "utf8"));
  const wasm = fs.readFileSync(path.join(path.dirname(require.resolve("vscode-oniguruma")), "onig.wasm"));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new vsctm.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (text) => new oniguruma.OnigString(text),
    }),
    loadGrammar: async () => vsctm.parseRawGrammar(fs.readFileSync(input.grammar, "utf8"), input.grammar),
  });
  const grammar = await registry.loadGrammar(JSON.parse(fs.readFileSync(input.grammar, "utf8")).scopeName);
  const out = input.documents.map((lines) => {
    let stack = vsctm.INITIAL;
    return lines.map((line) => {
      const result = grammar.tokenizeLine(line, stack);
      stack = result.ruleStack;
      return result.tokens.map((t) => [t.startIndex, Math.min(t.endIndex, line.length), t.scopes]);
    });
  });
  process.stdout.write(JSON.stringify(out));
}

main().catch((error) => {
  process.stderr.write(`${error.stack || error}\n`);
  process.exit(1);
});
