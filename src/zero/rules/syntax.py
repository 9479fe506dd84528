"""S rules: how the controller reads a line, before any parameter meaning.

The tokenizer records what it sees (:class:`~zero.lists.model.Problem`); the check
below gives each kind of problem its rule and its message.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from zero.catalog.evidence import claim
from zero.catalog.registry import ParamSpec
from zero.catalog.values import bind
from zero.diagnostics import Diagnostic, Edit, Fix, Span
from zero.lists.model import Comment, CommentStyle, Problem, ValueKind
from zero.patterns import compiled
from zero.rules.base import INFO, Context, E, Family, W

FAMILY: Family[Context] = Family("S", "syntax", "list")

MALFORMED_LINE = FAMILY.rule(
    "S001", "malformed-line", E, "A line that is neither an entry, a comment nor blank",
    """
What it checks: the first word of a line must be a key made of members and indices
(`name[n].name`); a line like `*****` or `np_grp[1.achse` is not.

Why it matters on the machine: such a line sets no parameter. In an axis parameter list the
kernel ignores an element it cannot interpret (P-ERR-1001119): an error there; for the other
list kinds the vendor documents no reaction, and the warning says so.
In a zero-offset list the plausibility check reports an unknown or incorrectly written
parameter or an invalid value and the job is aborted (P-ERR-20407): an error there too.

Example: `*****  decorative line`
Fix: turn it into a comment (`# *****`) or correct the key.
""")
MISSING_VALUE = FAMILY.rule(
    "S002", "missing-value", E, "A key without a value",
    """
What it checks: every entry needs a value after its key.

Why it matters on the machine: the entry sets nothing zero can read; what the controller does
with it is not documented (a warning that says so), and it is rarely what the engineer who
wrote the key meant.
In a zero-offset list the plausibility check reports an unknown or incorrectly written
parameter or an invalid value and the job is aborted (P-ERR-20407): an error there too.

Example: `kenngr.swe_pos`
Fix: write the value (`kenngr.swe_pos 15000000`) or delete the line.
""")
UNTERMINATED_QUOTE = FAMILY.rule(
    "S003", "unterminated-quote", E, "A quoted string value without its closing quote",
    """
What it checks: a value that starts with `"` must end with `"` on the same line.

Why it matters on the machine: where the string ends is not said; what the controller does
with such an entry is not documented (a warning that says so).
In a zero-offset list the plausibility check reports an unknown or incorrectly written
parameter or an invalid value and the job is aborted (P-ERR-20407): an error there too.

Example: `example[0].name "STRING_WITH_COMMENT( # /*`
Fix: close the quote: `example[0].name "STRING_WITH_COMMENT( # /*)"`.
""")
KEY_WHITESPACE = FAMILY.rule(
    "S004", "key-whitespace", E, "Whitespace inside a key",
    """
What it checks: a key is one word; `np_grp[0].achse[1]. inaktiv 0` (from the ZERO
manual's own example) has a blank after the dot.

Why it matters on the machine: the controller reads the key up to the first blank,
so it sees the unknown key `np_grp[0].achse[1].` with the value `inaktiv`. In an axis
parameter list the kernel ignores an element it cannot interpret (P-ERR-1001119): an
error; for the other list kinds (this example's zero-offset list) no reaction is
documented, and the warning says so — for `inaktiv 1` the offset may stay active although
the list says it is masked. zero reads the joined key for its other checks, so that one
slip gives one finding.

Example: `np_grp[0].achse[1]. inaktiv 0`
Fix: remove the blank (safe fix): `np_grp[0].achse[1].inaktiv 0`.
""")
HASH_NO_SPACE = FAMILY.rule(
    "S005", "hash-no-space", W, "`#` glued to comment text",
    """
What it checks: a full-line comment is `#` followed by a space (a lone `#` or `#` and a
tab are accepted too). Not reported: banners of punctuation (`#=====`, `#*****`), tags a
tool writes (`#TC_AXIS_DESC: …`), and parameters commented out as `#key value`, the
vendor's own habit (S012, opt-in, reports those).

Why it matters on the machine: the manual requires the space after `#`; a comment glued
to its `#` is text the controller may try to read as an entry.

Example: `#Achse X neu vermessen`
Fix: insert a space after `#` (safe fix): `# Achse X neu vermessen`.
""")
UNDECODABLE = FAMILY.rule(
    "S007", "undecodable", W, "Bytes that are not valid in the file's encoding",
    """
What it checks: a list is UTF-8 (with or without BOM) or Windows-1252/Latin-1 as a
whole, or in the code page the configuration declares for it (`encoding`). A byte that is
invalid UTF-8 in a file that also holds UTF-8 text means the file mixes encodings
(typically an editor saved a Latin-1 `µ` into a UTF-8 file); a byte the declared code page
does not define means the declaration or the file is wrong.

Why it matters on the machine: names and comments come out garbled; in a value the
controller reads something other than what the engineer sees in the editor.

Example: a UTF-8 file with `ä` in one comment and byte 0xB5 in another.
Fix: re-save the file in one encoding.
""")
NUL_BYTE = FAMILY.rule(
    "S008", "nul-byte", W, "A NUL byte in the file",
    """
What it checks: byte 0x00 anywhere in a list.

Why it matters on the machine: files with NUL bytes are usually corrupt copies or UTF-16
files; what the controller does with a NUL in a line is not documented (a warning that says
so).

Fix: remove the NUL bytes, or convert a UTF-16 file to UTF-8.
""")
AFTER_END = FAMILY.rule(
    "S009", "after-end", W, "Entries after the `Ende` line",
    """
What it checks: nothing but comments and blank lines may follow the `Ende` line.

Why it matters on the machine: the controller stops reading at `Ende`; every entry
after it is silently ignored, however important.

Example: `Ende` followed by `kenngr.swe_pos 15000000`
Fix: move the entries above `Ende`.
""")
CONTROL_CHARACTER = FAMILY.rule(
    "S010", "control-character", W, "A control character in a line",
    """
What it checks: characters below 0x20 other than tab, and DEL, anywhere in a line; a
carriage return that is not part of a CRLF line ending; and the C1 controls (U+0080 to U+009F)
in the part of a line the controller reads (key and value). A C1 control is what a byte above
0x7F of another code page becomes when the list is read as Latin-1 (CP850's 0x81 `ü`, 0x84 `ä`):
in a comment (`#`, `( ...`, `/* */` after a value, a full-line `#` comment, a commented-out
entry, the `Ende` line and what follows it) it is a letter of a comment and not reported.
Declare such a list's code page (`encoding = {"old/**/*.lis" = "cp850"}` in the configuration)
to read, convert and format it as the text it is.

Why it matters on the machine: invisible in most editors, but part of the key or
value the controller reads, which then matches nothing.

Fix: delete the character.
""")
BINARY_FILE = FAMILY.rule(
    "S013", "binary-file", E, "A file that is not text",
    """
What it checks: whether a list is text at all. A file where more than one character in twenty
is a control character or a byte the encoding cannot read (a binary file, a UTF-16 file, a
compressed or corrupt copy) is reported once, as a whole; no other rule reports on it.

Why it matters on the machine: the controller cannot read such a file as a parameter list;
none of its entries is taken over.

Fix: put the real list in its place (a UTF-16 file: save it as UTF-8 or Windows-1252).
""")
MIXED_LINE_ENDINGS = FAMILY.rule(
    "S011", "mixed-line-endings", INFO, "LF and CRLF line endings in one file",
    """
What it checks: whether a file uses one kind of line ending throughout.

Why it matters on the machine: the controller reads both, but mixed endings are a
sign of a list assembled from several sources, and they make diffs noisy.

Fix: convert the file to one line ending (zero keeps what it finds when it rewrites).
""")

COMMENTED_OUT = FAMILY.rule(
    "S012", "commented-out-parameter", INFO, "A parameter commented out as `#key value`",
    """
What it checks (opt-in: `--select S012` or `extend-select = ["S012"]`): a parameter commented
out without a space after `#`, as the vendor's own lists do (`#kenngr.swe_pos 15000000`).

Why it matters on the machine: the manual asks for a space after `#`. The vendor's lists
comment parameters out this way by the hundred, so the check is off by default; turn it on
to keep your own lists to the manual's form.

Example: `#m_default_outp_ax_name[0]   X`
Fix: insert a space after `#` (safe fix): `# m_default_outp_ax_name[0]   X`.
""", opt_in=True)


_MESSAGES: dict[str, tuple[str, Callable[[Problem], str]]] = {
    "malformed-line": (
        "S001",
        lambda p: f"`{_short(p.detail)}` is not a key: nothing is set by this line",
    ),
    "missing-value": (
        "S002",
        lambda p: f"`{_short(p.detail)}` has no value: zero reads nothing for it",
    ),
    "unterminated-quote": (
        "S003",
        lambda p: f"the string value of `{_short(p.detail)}` has no closing quote: where it ends is not "
        "said",
    ),
    "key-whitespace": (
        "S004",
        lambda p: f"whitespace inside the key `{_short(p.detail)}`: read up to the blank, it is another, "
        "unknown key",
    ),
    "undecodable": (
        "S007",
        lambda p: f"byte {p.detail} is not valid UTF-8 in a file that also contains UTF-8 text "
        "(mixed encodings)" if " " not in p.detail else
        "byte {} is not defined in {}, the encoding the configuration declares".format(*p.detail.split(" ", 1)),
    ),
    "nul-byte": ("S008", lambda p: "NUL byte in the line: zero reads the line without it"),
    "after-end": (
        "S009",
        lambda p: f"content after `Ende` (line {p.detail}): the controller stops reading at "
        "`Ende` and ignores it",
    ),
    "control-char": (
        "S010",
        lambda p: f"control character {p.detail}: invisible, but part of what the controller reads",
    ),
    "binary": (
        "S013",
        lambda p: f"not a text file ({p.detail} control characters or stray bytes): the controller cannot read "
        "it as a parameter list",
    ),
    "mixed-endings": (
        "S011",
        lambda p: "line ending differs from the first line's: the file mixes LF and CRLF",
    ),
}


def _short(text: str, limit: int = 60) -> str:
    return text if len(text) <= limit else text[: limit - 1] + "…"


@FAMILY.check(MALFORMED_LINE, MISSING_VALUE, UNTERMINATED_QUOTE, KEY_WHITESPACE, HASH_NO_SPACE,
              UNDECODABLE, NUL_BYTE, AFTER_END, CONTROL_CHARACTER, MIXED_LINE_ENDINGS, COMMENTED_OUT,
              BINARY_FILE)
def check_problems(ctx: Context) -> Iterator[Diagnostic]:
    """Findings for the faults the tokenizer recorded."""
    for p in ctx.doc.problems:
        if p.kind == "hash-no-space":
            found = _hash_no_space(ctx, p)
            if found is not None:
                yield found
            continue
        code, make = _MESSAGES[p.kind]
        span = Span.on_line(p.line, p.start, p.end)
        fix = None
        if p.kind == "key-whitespace":
            fix = Fix("Remove the whitespace inside the key", (Edit(span, ""),))
        elif p.kind == "unterminated-quote":
            end = Span.on_line(p.line, p.end, p.end)
            fix = Fix("Close the quote at the end of the line", (Edit(end, '"'),), safe=False)
        message = make(p)
        if code in _SAID:  # what the controller does, as the evidence table says for this list kind
            message = f"{message}; {claim(_SAID[code], ctx.kind).says}"
        yield ctx.report(code, span, message, fix=fix, hint=fix.title if fix else None)


# the claim each of these findings ends with (zero.catalog.evidence)
_SAID = {"S001": "malformed-line", "S002": "unreadable-entry", "S003": "unreadable-entry",
         "S004": "malformed-line", "S007": "text", "S008": "text"}


def _commented_parameter(ctx: Context, line: int) -> str | None:
    """The key of a parameter commented out on ``line``: a documented key, or one shaped like a
    key of members and indices (``a.b``, ``a[0]``); ``#Achse X neu`` is prose, not a parameter."""
    item = ctx.doc.item_at(line)
    entry = item.commented_out if type(item) is Comment else None
    if entry is None or entry.key is None:
        return None
    pattern = entry.key.pattern
    registry = ctx.registry
    known = registry.kinds_of(pattern) or registry.alias(pattern, None) is not None
    return entry.key_text if known or "." in pattern or "[" in pattern else None


# Compiled at their first use (re keeps them), by a list with a comment glued to its `#`:
_BANNER = r"#[^A-Za-z0-9\s]*\s*$"  # `#=====`, `#*****`: decoration
_TAG = r"#[A-Z][A-Z0-9_]*:"  # `#TC_AXIS_DESC:`: a tag a tool writes


def _hash_no_space(ctx: Context, p: Problem) -> Diagnostic | None:
    span = Span.on_line(p.line, p.start, p.end)
    fix = Fix("Insert a space after `#`", (Edit(Span.on_line(p.line, p.end, p.end), " "),))
    key = _commented_parameter(ctx, p.line) if p.detail == "entry" else None
    if key is not None:
        return ctx.report("S012", span, f"`{key}` is commented out without a space after `#`: the manual "
                          "asks for one; the vendor's own lists write it this way", fix=fix, hint=fix.title)
    rest = ctx.doc.line_text(p.line)[p.start:]
    if compiled(_BANNER).match(rest) or compiled(_TAG).match(rest):
        return None
    return ctx.report("S005", span, "comment text glued to `#`: the manual requires a space after `#`, "
                      "and without it the controller may try to read the line as an entry", fix=fix,
                      hint=fix.title)


STRING_COMMENT = FAMILY.rule(
    "S006", "string-comment", W, "A comment after a string value that does not start with `(`",
    """
What it checks: after a value of a STRING parameter only `(` starts a comment; a
blank, `#` or `/*` does not (the manual's rule). Numeric values may be followed by
any comment.

Why it matters on the machine: the controller may take the words after the string as
part of the value, or reject the entry and use the default.

Example: `kopf.log_achs_name  X_Achse  # main axis`
Fix: start the comment with `(`: `kopf.log_achs_name  X_Achse  ( main axis`.
""")


@FAMILY.check(STRING_COMMENT)
def check_string_comments(ctx: Context) -> Iterator[Diagnostic]:
    """S006: after a STRING value only `(` opens a comment. A pass over the columns: the comments that
    start otherwise, then the rows that hold one, then their parameters (bound once per pattern)."""
    cols = ctx.doc.columns
    wanted = {cid for cid, style in enumerate(cols.styles) if style is not CommentStyle.PAREN}
    if not wanted:
        return
    kinds, values, patterns = cols.kinds, cols.value, cols.pattern
    strings: dict[int, ParamSpec | None] = {}  # pattern id -> its parameter when a STRING one
    for row, cid in enumerate(cols.comment):
        if cid not in wanted:
            continue
        kind = kinds[values[row]]
        if kind is None or kind is ValueKind.FLAGS:
            continue
        pid = patterns[row]
        if pid not in strings:
            hit = bind(ctx.registry, cols.patterns[pid], ctx.kind)
            strings[pid] = hit[0] if hit is not None and hit[0].type == "STRING" else None
        spec = strings[pid]
        if spec is None:
            continue
        e = ctx.doc.entry_at(row)
        span = Span.on_line(e.line, e.comment_start, len(ctx.doc.line_text(e.line)))
        fix = Fix(
            "Start the comment with `(`",
            (Edit(Span.on_line(e.line, e.comment_start, e.comment_start), "( "),),
            safe=False,
        )
        yield ctx.report(
            "S006",
            span,
            f"comment after the string value of `{e.key_text}` does not start with `(`: the "
            "controller may read it as part of the value",
            param_id=spec.id,
            fix=fix,
            hint=fix.title,
        )
