// Folding for parameter lists, without VS Code (tested by tests/editors/test_vscode_extension.py):
// a section folds from the block of `#` comment lines that heads it to its last entry before the
// next comment block; a comment block with no entries below it folds on its own; so does
// everything after `Ende`. One range per start line (VS Code keeps only one). Used only where
// the server offers no folding ranges of its own.
"use strict";

const COMMENT = /^[ \t]*#/;
const BLANK = /^[ \t]*$/;
const END = /^[ \t]*Ende(?=[ \t]|$)/;

// Folding ranges (0-based, inclusive lines) of a list's lines: {start, end, kind} with kind
// "region" (a section with its heading, the lines after `Ende`) or "comment" (a comment block alone).
function foldingRanges(lines) {
  const ranges = [];
  const n = lines.length;
  let i = 0;
  while (i < n) {
    if (END.test(lines[i])) {
      if (n - 1 > i) {
        ranges.push({ start: i, end: n - 1, kind: "region" }); // what the controller does not read
      }
      break;
    }
    if (!COMMENT.test(lines[i])) {
      i += 1;
      continue;
    }
    const head = i;
    while (i < n && COMMENT.test(lines[i])) {
      i += 1;
    }
    // the section: up to the line before the next comment block or `Ende`, blank lines left out
    let j = i;
    while (j < n && !COMMENT.test(lines[j]) && !END.test(lines[j])) {
      j += 1;
    }
    let last = j - 1;
    while (last >= i && BLANK.test(lines[last])) {
      last -= 1;
    }
    if (last >= i) {
      ranges.push({ start: head, end: last, kind: "region" });
    } else if (i - 1 > head) {
      ranges.push({ start: head, end: i - 1, kind: "comment" }); // a comment block alone
    }
    i = j;
  }
  return ranges;
}

module.exports = { foldingRanges };
