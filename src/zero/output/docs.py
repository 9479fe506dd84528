"""What zero knows, as text: a rule's explanation, the list of rules, a parameter's facts; and the same
as the documentation site's Markdown pages (one per rule and per parameter)."""

from __future__ import annotations

import re
import textwrap
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from zero.catalog.registry import KINDS, ParamSpec, Registry
from zero.diagnostics import Diagnostic, Fix
from zero.forms import EXTENSION, format_of
from zero.records import Record, replace
from zero.rules import RULES

if TYPE_CHECKING:
    from zero.engine.results import LintResult
    from zero.lists.model import Document
    from zero.machine.model import Machine
    from zero.rules.startup import StartupError


def rule_text(code: str, registry: Registry) -> str:
    """A rule's explanation as ``zero rule CODE`` prints it, and the parameters it reads; a K rule's "why
    it matters" the specific consequence its documented correction gives (:func:`kernel_consequence`),
    as its page says it."""
    r = RULES[code]
    if code.startswith("K"):
        from zero.rules.startup import CHECKS  # start-up: only a K rule's explanation needs them

        err = next((c for c in CHECKS if c.code == code), None)
        if err is not None:
            why = kernel_consequence(err, registry)
            said = f"Why it matters on the machine: {why[:1].lower()}{why[1:]}"
            r = replace(r, explanation=_WHY.sub(lambda _m: said, r.explanation, count=1))
    return r.render() + reads_text(code, registry)


_WHY = re.compile(r"^Why it matters on the machine:.*?(?=\n\s*\n|\Z)", re.M | re.S)


def reads_text(code: str, registry: Registry) -> str:
    """The parameters a rule reads, as ``zero rule`` prints them after its explanation (its page links them)."""
    if code in GENERIC_RULES:
        return f"\nReads: no particular parameter; it reads {GENERIC_RULES[code]}.\n"
    named = [f"{pid} ({registry.specs[pid].key})" if registry.specs[pid].key else pid
             for pid in named_params(code, registry)]
    return f"\nReads: {', '.join(named)}.\n" if named else ""


def rules_overview() -> str:
    lines = []
    for code, r in RULES.items():
        lines.append(f"{code}  {r.severity.label:<7}  {r.name:<30} {r.summary}")
    return "\n".join(lines) + "\n"


def param_rows(spec: ParamSpec, registry: Registry) -> list[tuple[str, str]]:
    """A parameter's facts as (label, text) rows: what ``zero param`` prints and its page shows."""
    rng = registry.range_of(spec)
    if rng is not None:
        range_text = f"{spec.range_text}  (checked)"
    elif spec.enum:
        listed = spec.enum_listed()
        kind = "bits, any combination" if spec.enum_flags else "values"
        range_text = f"{listed}  ({kind} the catalogue lists in its text; checked)"
    elif spec.range_note:
        range_text = f"{spec.range_note}  (prose, not checked)"
    elif spec.type == "BOOLEAN":
        range_text = "0/1 (FALSE/TRUE)"
    else:
        range_text = "not stated formally (not checked)"
    dims = ""
    if spec.dims:
        names = spec.key.split("[]") if spec.key else []
        parts = []
        for i in range(len(spec.dims)):
            member = names[i].rsplit(".", 1)[-1] if i < len(names) else "?"
            parts.append(f"{member}[{spec.valid_indices(i)}]")
        dims = ", ".join(parts)
    rows = [
        ("ID", spec.id),
        ("key", spec.key or "(no list key documented)"),
        ("list", KINDS.get(spec.kind, (spec.kind, spec.kind))[1]),
        ("type", spec.type + (f", at most {spec.max_len} characters" if spec.max_len else "")),
        ("range", range_text),
        ("default", spec.default_display),
        ("unit", " or ".join(spec.units) if spec.units else "–"),
    ]
    if dims:
        rows.append(("indices", dims))
    if spec.symbols:
        rows.append(("symbols", ", ".join(n if v is None else f"{n}={v}" for n, v in spec.symbols)))
    if spec.restart:
        rows.append(("restart", "a change takes effect only after a restart"))
    rows.append(("meaning", spec.description or "(no description; load your CncParaDesc.xml with --param-desc)"))
    rows.append(("source", spec.source))
    return rows


def param_text(spec: ParamSpec, registry: Registry) -> str:
    rows = param_rows(spec, registry)
    width = max(len(k) for k, _ in rows)
    return "\n".join(f"{k:<{width}}  {v}" for k, v in rows) + "\n"


# ------------------------------------------------------------------ the documentation site's pages
# One page per rule and per parameter, as Markdown, for the site (docs/gen_pages.py writes them at
# build time): nothing on them is typed twice, every fact comes from the rule definitions, the
# registry and the fixtures the tests run.

_SECTION = re.compile(r"^(What it checks(?: \([^)]*\))?|Why it matters on the machine|Example|Fix):\s*(.*)$")
_MAX_LINES = 80  # an example list shown longer than this is cut
_MAX_WIDTH = 100  # and so is a line (the binary-file fixture is one long line of stray bytes)


def rule_page_path(code: str) -> str:
    """Where a rule's page lies in the site (relative to ``docs/``)."""
    return f"rules/{code}.md"


def param_page_path(param_id: str) -> str:
    """Where a parameter's page lies in the site (relative to ``docs/``)."""
    return f"parameters/{param_id}.md"


def kind_page_path(kind: str) -> str:
    """Where the index of one list kind's parameters lies in the site."""
    return f"parameters/{kind}.md"


def md_text(text: str) -> str:
    """Plain text made safe as Markdown: no HTML, emphasis, links or table cells where there are none."""
    out = text.replace("\\", "\\\\").replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    for ch in "`*_[]|":
        out = out.replace(ch, "\\" + ch)
    return " ".join(out.split())


def md_inline(text: str) -> str:
    """Text whose `code` spans stay code (a rule's summary): the rest made safe as :func:`md_text`."""
    parts = text.split("`")
    if len(parts) % 2 == 0:  # an unpaired backtick: all plain text
        return md_text(text)
    def plain(p: str) -> str:  # the spaces around a code span kept
        return (" " if p[:1].isspace() else "") + md_text(p) + (" " if p[-1:].isspace() else "") if p.strip() \
            else (" " if p else "")

    return "".join(md_code(p) if i % 2 else plain(p) for i, p in enumerate(parts)).strip()


_URL = re.compile(r"(?<![<(\[`])\bhttps?://[^\s<>()`\]]+[^\s<>()`\].,;:]")


def autolink(markdown: str) -> str:
    """Each address outside a code span as a link (``<https://…>``)."""
    parts = markdown.split("`")
    return "`".join(_URL.sub(lambda m: f"<{m.group()}>", p) if i % 2 == 0 else p for i, p in enumerate(parts))


def md_code(text: str) -> str:
    """Text as an inline code span (a table cell's ``|`` escaped)."""
    fence = "``" if "`" in text else "`"
    pad = " " if text.startswith("`") or text.endswith("`") else ""
    return f"{fence}{pad}{text}{pad}{fence}".replace("|", "\\|")


def explanation_markdown(explanation: str, why: str | None = None) -> str:
    """A rule's explanation with its fixed headings (what it checks, why, example, fix) as headings,
    addresses as links; ``why``: the text under "Why it matters on the machine" instead of its own."""
    out: list[str] = []
    skipping = False
    for line in textwrap.dedent(explanation).strip().split("\n"):
        m = _SECTION.match(line)
        if m:
            out += ["", f"## {m.group(1)}", ""]
            skipping = why is not None and m.group(1) == "Why it matters on the machine"
            if skipping:
                out.append(why or "")
            elif m.group(2):
                out.append(autolink(m.group(2)[:1].upper() + m.group(2)[1:]))
        elif not skipping:
            out.append(autolink(line))
    return "\n".join(out).strip() + "\n"


class Example(Record, frozen=True):
    """A list a rule's page shows: its name, its text, the lines zero reports and what it reports."""

    title: str
    name: str  # where it lies (relative to the repository)
    text: str
    lines: tuple[int, ...] = ()
    report: str = ""


class RuleExamples(Record, frozen=True):
    """A rule's failing and passing example and the fixes zero offered on the failing one."""

    failing: Example | None
    passing: Example | None
    fixes: tuple[Fix, ...] = ()
    note: str = ""  # where the examples come from, or why there are none


def shown_list(data: bytes) -> tuple[str, int]:
    """A list's bytes as a page shows them: control characters and stray bytes as escapes
    (``\\r``, ``\\x00``, ``\\xe4``), long lines and long files cut; and its number of lines."""
    from zero.output.text import printable  # start-up: only the documentation site renders lists

    text = data.decode("utf-8", "surrogateescape")
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    shown = []
    for line in lines[:_MAX_LINES]:
        p = printable(line, escape=True)
        shown.append(p if len(p) <= _MAX_WIDTH else p[:_MAX_WIDTH] + "…")
    if len(lines) > _MAX_LINES:
        shown.append(f"… ({len(lines) - _MAX_LINES} more lines)")
    return "\n".join(shown), len(lines)


def findings_text(diagnostics: Sequence[Diagnostic], document: Document, name: str) -> str:
    """Findings as ``zero lint`` prints them (without colour), each placed in the file ``name``."""
    from zero.output.text import diagnostic_lines  # start-up: only the documentation site renders findings

    lines: list[str] = []
    for d in diagnostics:
        source = document.line_text(d.span.line) if document.has_line(d.span.line) else None
        for segments in diagnostic_lines(replace(d, path=name), source):
            lines.append("".join(text for text, _ in segments).rstrip())
    return "\n".join(lines).strip("\n")


def _fixture(folder: Path, stem: str) -> Path | None:
    """``fail.lis`` / ``pass.lis``, or the XML, update-file or YAML form a rule's fixtures take."""
    for suffix in (EXTENSION["xml"], "-Update" + EXTENSION["xml"], EXTENSION["yaml"], EXTENSION["lis"]):
        if (folder / f"{stem}{suffix}").is_file():
            return folder / f"{stem}{suffix}"
    return None


def _list_examples(code: str, folder: Path, root: Path, registry: Registry, select: tuple[str, ...],
                   extend: bool) -> RuleExamples:
    from zero.engine.lint import LintOptions, lint_data  # start-up: only the documentation site lints its examples

    options = LintOptions(extend_select=select) if extend else LintOptions(select=select)
    examples: list[Example | None] = []
    fixes: list[Fix] = []
    for stem, title in (("fail", "A failing list"), ("pass", "A passing list")):
        path = _fixture(folder, stem)
        if path is None:
            examples.append(None)
            continue
        data = path.read_bytes()
        result = lint_data(data, path.name, registry, options)
        mine = [d for d in result.diagnostics if d.code == code]
        fixes += [d.fix for d in mine if d.fix is not None]
        text, _ = shown_list(data)
        examples.append(Example(title, path.relative_to(root).as_posix(), text,
                                tuple(sorted({d.span.line for d in mine})),
                                findings_text(result.diagnostics, result.document, path.name)))
    return RuleExamples(examples[0], examples[1], tuple(fixes))


_MACHINES: dict[tuple[Path, int], tuple[list[LintResult], list[LintResult]]] = {}


def _machine(startup: Path, registry: Registry) -> Machine | None:
    """A fixture machine as `zero lint --machine` builds it: through the one resolver, with no
    configuration but the catalogue given."""
    from zero.engine.project import Common, open_project  # start-up: only the documentation site lints its examples

    return open_project(lambda _path: registry, Common(isolated=True)).machine(startup=startup, required=True)


def _machine_results(root: Path, registry: Registry) -> tuple[list[LintResult], list[LintResult]]:
    """The fixture machines' results, read once: ``fixtures/machine`` (every X rule fails there but
    X007/X011) and ``fixtures/machine-clean`` (the same machine without the faults)."""
    from zero.engine.lint import lint_machine  # start-up: only the documentation site lints its examples

    hit = _MACHINES.get((root, id(registry)))
    if hit is not None:
        return hit
    out = []
    for name in ("machine", "machine-clean"):
        startup = root / "fixtures" / name / "listen" / "hochlauf.lis"
        machine = _machine(startup, registry) if startup.is_file() else None
        out.append(lint_machine(machine, registry) if machine is not None else [])
    hit = _MACHINES[(root, id(registry))] = (out[0], out[1])
    return hit


def _machine_examples(code: str, root: Path, registry: Registry) -> RuleExamples:
    failing, clean = _machine_results(root, registry)
    for result in failing:
        mine = [d for d in result.diagnostics if d.code == code]
        if not mine:
            continue
        path = Path(result.path).resolve()  # a machine's lists may be named relative to the working directory
        text, _ = shown_list(path.read_bytes())
        name = path.relative_to(root).as_posix()
        fail = Example("A failing machine: one of its lists", name, text, tuple(sorted({d.span.line for d in mine})),
                       findings_text(mine, result.document, path.name))
        twin = root / "fixtures" / "machine-clean" / "listen" / path.name
        passing = None
        if twin.is_file() and clean and not any(d.code == code for r in clean for d in r.diagnostics):
            passing = Example("The same list in a machine without the fault", twin.relative_to(root).as_posix(),
                              shown_list(twin.read_bytes())[0])
        return RuleExamples(fail, passing, tuple(d.fix for d in mine if d.fix is not None),
                            "The examples are lists of the fixture machines `fixtures/machine` and "
                            "`fixtures/machine-clean`, read through their start-up list as `zero lint --machine` "
                            "reads them.")
    return RuleExamples(None, None, (), "The fixture machine (`fixtures/machine`) has no finding of this rule, so "
                        "this page shows no example.")


def _program_examples(code: str, root: Path, registry: Registry) -> RuleExamples:
    from zero.engine.lint import lint_program  # start-up: only the documentation site lints its examples

    folder = root / "fixtures" / "programs"
    startup = root / "fixtures" / "machine" / "listen" / "hochlauf.lis"
    if not (folder / "bad.nc").is_file() or not startup.is_file():
        return RuleExamples(None, None, (), "There is no example program for this rule.")
    machine = _machine(startup, registry)
    out: list[Example | None] = []
    fixes: list[Fix] = []
    for name, title in (("bad.nc", "A failing NC program"), ("good.nc", "A passing NC program")):
        path = folder / name
        if not path.is_file():
            out.append(None)
            continue
        data = path.read_bytes()
        result = lint_program(data, registry, path.name, machine=machine)
        mine = [d for d in result.diagnostics if d.code == code]
        if title.startswith("A failing") and not mine:
            out.append(None)
            continue
        fixes += [d.fix for d in mine if d.fix is not None]
        out.append(Example(title, path.relative_to(root).as_posix(), shown_list(data)[0],
                           tuple(sorted({d.span.line for d in mine})), findings_text(mine, result.document, name)))
    return RuleExamples(out[0], out[1], tuple(fixes), "The programs run on the fixture machine `fixtures/machine`.")


def rule_examples(code: str, root: Path, registry: Registry) -> RuleExamples:
    """A rule's examples from the fixtures the tests run (``root`` is the repository): a rule's own
    folder under ``fixtures/rules``, a K rule's by its error number under ``fixtures/startup``, the
    fixture machines for the X rules, the fixture programs for the N rules; none is made up."""
    from zero.rules.startup import CHECKS  # start-up: only the documentation site

    folder = root / "fixtures" / "rules" / code
    if folder.is_dir():
        return _list_examples(code, folder, root, registry, (code,), extend=True)
    kernel = {c.code: c for c in CHECKS}.get(code)
    if kernel is not None:
        folder = root / "fixtures" / "startup" / str(kernel.number)
        if folder.is_dir():
            return _list_examples(code, folder, root, registry, ("K",), extend=False)
    if code.startswith("X"):
        return _machine_examples(code, root, registry)
    if code.startswith("N"):
        return _program_examples(code, root, registry)
    return RuleExamples(None, None, (), "zero has no example list for this rule in its fixtures; its tests make "
                        "the case they check (see the tests named in the explanation, or search the tests for the "
                        "code).")


def _fence(text: str) -> str:
    longest = max((len(m) for m in re.findall(r"`+", text)), default=0)
    return "`" * max(3, longest + 1)


def _language(name: str) -> str:
    form = format_of(name)
    return form if form is not None and form != "lis" else "text"


def example_markdown(example: Example, code: str) -> str:
    """An example list as a titled code block (the reported lines marked), and what zero says about it."""
    fence = _fence(example.text)
    marks = f' hl_lines="{" ".join(map(str, example.lines))}"' if example.lines else ""
    out = [f"### {example.title}", "", f"`{example.name}`:", "",
           f'{fence}{_language(example.name)} title="{Path(example.name).name}"{marks}', example.text, fence, ""]
    if example.report:
        fence = _fence(example.report)
        out += ["What `zero lint` reports:", "", f"{fence}{{ .text .zero-output }}", example.report, fence, ""]
    else:
        out += [f"`zero lint` reports no {code} here.", ""]
    return "\n".join(out)


def fix_markdown(fixes: tuple[Fix, ...], have_example: bool) -> str:
    """Whether zero fixes the rule's findings, and how safe that is, from the fixes its failing example got."""
    if not fixes:
        if have_example:
            return ("zero offers no automatic fix for this finding (none on the failing example): correct the list "
                    "as the explanation says.\n")
        return "This page has no example to show a fix on; the explanation says how to correct the list.\n"
    lines = []
    for title, safe in dict.fromkeys((f.title, f.safe) for f in fixes):
        if safe:
            lines.append(f"- {md_text(title)}: **safe** (it keeps what the controller reads): `zero lint --fix` "
                         "applies it, `zero lint --diff` shows it first.")
        else:
            lines.append(f"- {md_text(title)}: **unsafe** (it changes what the controller reads): applied only "
                         "with `zero lint --fix --unsafe-fixes`; `zero lint --diff --unsafe-fixes` shows it "
                         "first. Check the result.")
    return "On the failing example, zero offers:\n\n" + "\n".join(lines) + "\n"


def rule_page(code: str, root: Path, registry: Registry) -> str:
    """A rule's page: code, name, severity, summary, explanation, the kernel's error number, the
    parameters a K rule reads, the examples and the fix with its safety."""
    from zero.rules import FAMILIES  # start-up: only the documentation site
    from zero.rules.startup import CHECKS, compiled  # start-up: as above

    r = RULES[code]
    rows = [("Code", f"`{r.code}`"), ("Name", f"`{r.name}`"), ("Default severity", r.severity.label),
            ("Family", f"{code[0]}: {FAMILIES.get(code[0], code[0])}"), ("Scope", r.scope)]
    if r.opt_in:
        rows.append(("Opt-in", f"runs only when selected by its full code: `--extend-select {code}`"))
    kernel = {c.code: c for c in CHECKS}.get(code)
    params: list[str] = []
    why: str | None = None
    if kernel is not None:
        rows.append(("Kernel error", f"`{kernel.kernel_error}` (list: {md_text(kernel.kind)})"))
        params = list(dict.fromkeys([*kernel.params, *compiled(kernel).read]))
        why = kernel_consequence(kernel, registry)
    params = list(dict.fromkeys([*params, *named_params(code, registry)]))
    if params:
        links = [f"[{p}](../{param_page_path(p)})" + (f" {md_code(registry.specs[p].key or '')}"
                                                        if registry.specs[p].key else "")
                 if p in registry.specs else f"`{p}`" for p in params]
        rows.append(("Parameters", ", ".join(links)))
    elif code in GENERIC_RULES:
        rows.append(("Parameters", f"none in particular: it reads {md_text(GENERIC_RULES[code])}"))
    out = [f"# {code} {r.name}", "", md_inline(r.summary), ""]
    out += [f"| {k} | {v} |" for k, v in rows[:1]] + ["| --- | --- |"] + [f"| {k} | {v} |" for k, v in rows[1:]]
    out += ["", _linked_outside_code(explanation_markdown(r.explanation, why), registry)]
    evidence = evidence_markdown(code)
    if evidence:
        out += ["## Evidence", "", evidence]
    ex = rule_examples(code, root, registry)
    out += ["## Examples", ""]
    if ex.note:
        out += [ex.note, ""]
    for example in (ex.failing, ex.passing):
        if example is not None:
            out.append(example_markdown(example, code))
    if ex.failing is None and ex.passing is None and not ex.note:
        out += ["zero has no example list for this rule in its fixtures.", ""]
    out += ["## Automatic fix", "", fix_markdown(ex.fixes, ex.failing is not None)]
    out += ["## Turning it off", "",
            f"`zero lint --ignore {code}`, `ignore = [\"{code}\"]` in `[tool.zero]`, or `# zero: ignore[{code}]` "
            "on the line. `zero rule " + code + "` prints this explanation in the terminal.", ""]
    return "\n".join(out)


def kernel_consequence(err: StartupError, registry: Registry) -> str:
    """Why a K rule matters on the machine, from its documented correction (``startup_errors.toml``):
    what the kernel does to which parameter at start-up, and what the machine then runs with."""
    def name(pid: str) -> str:
        spec = registry.specs.get(pid)
        return f"`{spec.key}` ({pid})" if spec is not None and spec.key else pid

    reported = name(err.params[0]) if err.params else "the list"
    head = f"When the controller starts with such a list it reports error {err.kernel_error} ({err.title})"
    c = err.correction.strip()
    if c == "abort":
        return f"{head} and aborts the start-up: the controller does not come up until the list is corrected."
    if c == "none":
        return (f"{head} as a warning and changes no value: the machine runs with {reported} as written, "
                "and the message comes back at every start.")
    if c == "default":
        spec = registry.specs.get(err.params[0]) if err.params else None
        dflt = f" (`{spec.default_display}`)" if spec is not None else ""
        return (f"{head} and replaces {reported} with its default{dflt}: the machine runs with the default, "
                "not with the value the list writes, and nothing in the list shows it.")
    target, eq, value = c.partition("=")
    if eq and target.strip().startswith("P-"):
        value = value.strip()
        said = f"the value of {name(value)}" if value.startswith("P-") else f"`{value}`"
        return (f"{head} and sets {name(target.strip())} to {said}: the machine runs with that value, not "
                "with the one the list writes, and nothing in the list shows it.")
    return (f"{head}. The documentation does not say what the kernel then uses for {reported}: "
            "what the machine runs with is not known from the list.")


# The rules that read no particular parameter, each with why: they check the list's text, every parameter
# against its own catalogue entry (each parameter's page lists them from the catalogue's facts), zero's own
# comments, or the program alone. Every other rule declares what it reads (``Rule.reads``), and
# tests/docs fails on one that does not.
_GENERIC: tuple[tuple[str, str], ...] = (
    ("S001 S002 S003 S004 S005 S006 S007 S008 S009 S010 S011 S012 S013",
     "the list's text (its lines, bytes and comments), whatever parameter a line sets"),
    ("S014 S015 S016 S017", "the XML list's elements, whatever parameter each one names"),
    ("R001 R002 R003 R004 R005 R006 R007 R008 R009 R010 R011 R012 R013",
     "every parameter the list sets, against that parameter's own catalogue entry: each parameter's page "
     "says which of these rules check it and how"),
    ("U001", "every parameter an update changes, against its restart flag: each parameter that has the flag "
     "lists this rule on its page"),
    ("Z001 Z002", "zero's own suppression comments"),
    ("F001", "the file itself, before any of its lines"),
    ("N001", "whatever axis parameter a #MACHINE DATA block writes, checked as an entry of an axis list by the "
     "S and R rules"),
    ("N002 N007 N008 N010", "the NC program alone, no parameter of the machine's lists"),
)
GENERIC_RULES: dict[str, str] = {code: why for codes, why in _GENERIC for code in codes.split()}


def _declared_id(name: str, registry: Registry) -> str | None:
    """A declared parameter's ID: an ID the catalogue has, or the ID of a key it knows."""
    from zero.lists.model import parse_key  # start-up: only the documentation site

    if name in registry.specs:
        return name
    if name.startswith("P-"):
        return None
    key = parse_key(name)
    spec = registry.by_pattern(key.pattern, None) if key is not None else None
    return spec.id if spec is not None else None


def unknown_reads(registry: Registry) -> list[tuple[str, str]]:
    """(rule, name) for each parameter a rule declares that the catalogue does not know."""
    return [(code, name) for code, r in RULES.items() for name in r.reads if _declared_id(name, registry) is None]


def named_params(code: str, registry: Registry) -> list[str]:
    """The parameters a rule reads, by ID: those it declares (``Rule.reads``; a key the catalogue knows
    taken as its ID). A rule of :data:`GENERIC_RULES` reads no particular parameter and names none."""
    found = [_declared_id(name, registry) for name in RULES[code].reads]
    return list(dict.fromkeys(pid for pid in found if pid is not None))


def evidence_markdown(code: str) -> str:
    """What the controller does on a rule's finding and the document that says so (``evidence.toml``),
    each address a link."""
    from zero.catalog.evidence import claims, rule_claims  # start-up: only the documentation site

    name = rule_claims().get(code)
    rows = [c for c in claims() if c.name == name] if name else []
    lines = []
    for c in rows:
        kinds = f" ({', '.join(c.kinds)} lists)" if c.kinds else ""
        source = autolink(md_text(c.source)).replace("\\_", "_") if "http" in c.source else md_text(c.source)
        lines.append(f"- **{md_text(c.consequence)}**{kinds}: {md_text(c.says)}. Source: {source}")
    return "\n".join(lines) + "\n" if lines else ""


def _linked_outside_code(markdown: str, registry: Registry) -> str:
    """Each parameter ID outside code spans and fences linked to its page."""
    out = []
    fenced = False
    for line in markdown.split("\n"):
        if line.startswith("```"):
            fenced = not fenced
        if fenced or line.startswith("```"):
            out.append(line)
            continue
        parts = line.split("`")
        out.append("`".join(_linked(p, registry) if i % 2 == 0 else p for i, p in enumerate(parts)))
    return "\n".join(out)


def rules_index_page() -> str:
    """The table of every rule, by family."""
    from zero.rules import FAMILIES  # start-up: only the documentation site

    out = ["# Rules", "", f"zero has {len(RULES)} rules. Each has a page: what it checks, why it matters on the "
           "machine, a failing and a passing example, and the fix.", ""]
    for letter, title in FAMILIES.items():
        codes = [c for c in RULES if c.startswith(letter)]
        if not codes:
            continue
        out += [f"## {letter}: {title}", "", "| Code | Name | Severity | Summary |",
                "| --- | --- | --- | --- |"]
        for c in codes:
            r = RULES[c]
            out.append(f"| [{c}]({c}.md) | `{r.name}` | {r.severity.label} | {md_inline(r.summary)} |")
        out.append("")
    return "\n".join(out)


class Checked(Record, frozen=True):
    """A rule that checks a parameter, and how."""

    code: str
    how: str


def param_checks(registry: Registry) -> dict[str, list[Checked]]:
    """Which rules check each parameter, where zero knows it from its tables: the type (R004), the
    indices (R003), the formal range or listed values (R005, R006 where the range names other
    parameters, and R006 on each parameter named), the prose ranges zero evaluates (R006), the
    kernel's start-up checks (K rules) and the restart flag (U001)."""
    from zero.catalog.conditions import parse  # start-up: only the documentation site
    from zero.catalog.conditions import refs as condition_refs  # start-up: as above
    from zero.catalog.data.prose_ranges import RANGES  # start-up: as above
    from zero.rules.startup import CHECKS, compiled  # start-up: as above

    out: dict[str, list[Checked]] = {pid: [] for pid in registry.specs}

    def add(pid: str, code: str, how: str) -> None:
        if pid in out and code in RULES:
            out[pid].append(Checked(code, how))

    prose = {row["id"]: row for row in RANGES}
    named_by: dict[str, list[str]] = {}
    for pid, spec in registry.specs.items():
        if spec.dims:
            add(pid, "R003", "its indices must lie within the array")
        add(pid, "R004", f"its value must be of type {spec.type}")
        rng = registry.range_of(spec)
        if rng is not None:
            refs = list(dict.fromkeys(r.id for r in rng.refs))
            if refs:
                add(pid, "R006", f"its range `{spec.range_text}` names other parameters")
                for ref in refs:
                    named_by.setdefault(ref, []).append(pid)
            else:
                add(pid, "R005", f"its value must lie in `{spec.range_text}`")
        elif spec.enum:
            add(pid, "R005", f"its value must be {'a combination' if spec.enum_flags else 'one'} of "
                f"{spec.enum_listed()}")
        row = prose.get(pid)
        if row is not None:
            add(pid, "R006", f"the catalogue's prose range `{row['prose']}`, evaluated as `{row['condition']}`")
            for ref in condition_refs(parse(row["condition"])):
                if ref != pid:
                    named_by.setdefault(ref, []).append(pid)
        if spec.restart:
            add(pid, "U001", "an update file that changes it takes effect only after a restart")
    for ref, pids in named_by.items():
        links = ", ".join(f"[{pid}](../{param_page_path(pid)})" for pid in sorted(set(pids)))
        add(ref, "R006", f"it is named in the range of {links}")
    for err in CHECKS:
        for pid in dict.fromkeys([*err.params, *compiled(err).read]):
            add(pid, err.code, f"the kernel's start-up check {err.kernel_error}: {err.title}")
    for code in RULES:  # every rule's declared parameters (a K rule's are said above, with its number)
        for pid in named_params(code, registry):
            if not any(c.code == code for c in out.get(pid, [])):
                add(pid, code, md_inline(RULES[code].summary))
    order = {code: n for n, code in enumerate(RULES)}
    for checks in out.values():
        checks.sort(key=lambda c: (order[c.code], c.how))
    return out


_ID = re.compile(r"\bP-[A-Z]{4}-\d{5}\b")


def _linked(text: str, registry: Registry) -> str:
    """Markdown with each parameter ID that has a page linked to it (from another parameter's page)."""
    return _ID.sub(lambda m: f"[{m.group()}](../{param_page_path(m.group())})" if m.group() in registry.specs
                   else m.group(), text)


# The vendor's overview of each list kind's parameters (TF5200, Beckhoff Information System), where
# zero knows its address; every parameter has a page there titled with its ID.
VENDOR_OVERVIEW = {
    "AXIS": "https://infosys.beckhoff.com/content/1033/tf5200_axis_parameter/117162635.html",
    "CHAN": "https://infosys.beckhoff.com/content/1033/tf5200_channel_parameter/147959819.html",
}

# German words for the German abbreviations in the vendor's keys (``swe`` is the Software-Endschalter,
# ``nullp`` the Nullpunkt), so that a search in German finds the parameter: zero's own glossary of
# the keys, no text of the catalogue.
GERMAN: tuple[tuple[str, str], ...] = (
    (r"(^|[._])swe(_|$)|sw_limit|soft_limit", "Softwareendschalter Endschalter SWE"),
    (r"nullp|np_grp|versch\b", "Nullpunktverschiebung Nullpunkt Verschiebung"),
    (r"refpkt|homing|referenz", "Referenzpunkt Referenzpunktfahrt Referenzieren"),
    (r"getriebe", "Getriebe Getriebestufe"),
    (r"handbetrieb", "Handbetrieb"),
    (r"(^|[._])(werkz|wz)([._\[]|$)", "Werkzeug Werkzeugdaten"),
    (r"(^|[._])achs|achse", "Achse"),
    (r"kenngr", "Kenngrößen Achskenngrößen"),
    (r"(^|[._])antr([._]|$)", "Antrieb"),
    (r"geschw|(^|[._])vb_|v_max|_vel", "Geschwindigkeit Vorschub"),
    (r"beschl|(^|[._])a_(max|grenz|stufe|emergency)", "Beschleunigung"),
    (r"brems", "Bremsen Verzögerung"),
    (r"toleranz", "Toleranz"),
    (r"tipp", "Tippbetrieb"),
    (r"spindel", "Spindel"),
    (r"kanal|sda_mds", "Kanal Kanalparameter"),
    (r"vorsteuer", "Vorsteuerung"),
    (r"schlepp", "Schleppfehler"),
    (r"mod_rechng|modulo", "Modulo Rundachse"),
    (r"(^|[._])lr_", "Lageregler"),
    (r"hochlauf", "Hochlauf"),
    (r"bezeichnung", "Bezeichnung Name"),
    (r"offsetgrenze", "Offsetgrenze Handbetrieb"),
    (r"(^|[._])kw([._\[]|$)|kompens", "Kompensation Achskompensation"),
    (r"zyklus|cycle", "Zyklus Zykluszeit"),
)
_GERMAN = tuple((re.compile(pattern), words) for pattern, words in GERMAN)


_GLOSSARY_WORDS = tuple(dict.fromkeys(w for _, said in GERMAN for w in said.split() if len(w) >= 6))


def german_terms(spec: ParamSpec, name: str | None = None) -> list[str]:
    """German search terms for a parameter: the glossary's words for the German abbreviations in its key,
    and, given its German name from the user's catalogue (``name``), the glossary's words that name holds
    inside its compounds (``Softwareendschalterüberwachung``: Endschalter), which a search for the
    word alone would not find in it."""
    key = (spec.key or "").lower()
    words: list[str] = []
    for pattern, said in _GERMAN:
        if pattern.search(key):
            words += said.split()
    if name:
        folded = name.casefold()
        words += [w for w in _GLOSSARY_WORDS if w.casefold() in folded]
    return list(dict.fromkeys(words))


def german_names(path: str | Path) -> dict[str, str]:
    """The German names (short descriptions) of the parameters in the user's ``CncParaDesc.xml``, read
    when the site is built (``ZERO_PARAM_DESC``): they go into the pages built, never into this project."""
    from zero.catalog.vendor_names import short_names  # start-up: only the documentation site

    return short_names(path, "de")


def english_names(path: str | Path) -> dict[str, str]:
    """The English short descriptions in the user's ``CncParaDesc.xml``, read when the site is built: the
    meaning of a parameter zero has no description of, on the pages built, never in this project."""
    from zero.catalog.vendor_names import short_names  # start-up: only the documentation site

    return short_names(path, "en")


def _vendor_docs(spec: ParamSpec) -> list[str]:
    """Where the vendor documents a parameter: its page in the TF5200 documentation (titled with its
    ID), the kind's overview where zero knows its address, and every vendor page zero's tables cite
    for it."""
    from zero.catalog.data.drive_types import DRIVE_TYPES  # start-up: only the documentation site
    from zero.catalog.data.startup_errors import ERRORS  # start-up: as above

    name = KINDS.get(spec.kind, (spec.kind, spec.kind))[1]
    overview = VENDOR_OVERVIEW.get(spec.kind)
    first = (f"The vendor documents the parameters of the {md_text(name)} in its TF5200 documentation (Beckhoff "
             f"Information System), a page per parameter whose title ends with its ID (`{spec.id}`)")
    out = [first + (f"; the overview of all of them: <{overview}>." if overview else "."), ""]
    cited = [(str(row["source"]), f"start-up error P-ERR-{row['number']}") for row in ERRORS
             if spec.id in (row.get("params") or ()) and str(row.get("source", "")).startswith("http")]
    cited += [(str(row["source"]), "the drive types it applies to") for row in DRIVE_TYPES
              if row.get("param") == spec.id and str(row.get("source", "")).startswith("http")]
    for url, what in dict.fromkeys(cited):
        out.append(f"- {md_text(what)}: <{url}>")
    if spec.source and spec.source != "CncParaDesc.xml":
        out.append(f"- zero's description: {md_text(spec.source)}")
    return out


def param_page(spec: ParamSpec, registry: Registry, checks: Sequence[Checked], german: str | None = None,
               english: str | None = None) -> str:
    """A parameter's page: its facts (as ``zero param`` shows them), the rules that check it, where
    the vendor documents it, and German search terms (``german``: its German name in the catalogue the
    site is built with, where one is given; ``english``: its English short description there, the
    meaning where zero has none)."""
    title = f"{spec.id} {spec.key}" if spec.key else spec.id
    out = [f"# {md_text(title)}", ""]
    if spec.description:
        out += [md_text(spec.description), ""]
    for n, (label, value) in enumerate(param_rows(spec, registry)):
        if label == "meaning" and spec.description:
            continue  # said above the table
        if label == "meaning" and english:
            value = f"{english} (the short description in the CncParaDesc.xml this site was built with)"
        if label == "key" and spec.key:
            value = md_code(spec.key)
        elif label == "list":
            value = f"[{md_text(value)}](../{kind_page_path(spec.kind)})"
        elif label in ("ID", "range", "default") and value and value != "–":
            value = md_code(value) if label != "range" else _linked(md_text(value), registry)
        else:
            value = md_text(value)
        out += [f"| {label} | {value} |"] + (["| --- | --- |"] if n == 0 else [])
    out += ["", "## Checked by", ""]
    if checks:
        out += [f"- [{c.code}](../{rule_page_path(c.code)}) `{RULES[c.code].name}`: {c.how}" for c in checks]
    else:
        out.append("No rule zero knows of checks this parameter by its ID.")
    out += ["", "## Vendor documentation", "", *_vendor_docs(spec)]
    out += ["", f"`zero param {spec.key or spec.id}` prints these facts in the terminal.", ""]
    terms = german_terms(spec, german)
    if german or terms:
        out += ["## German", ""]
    if german:
        out += [f"German name (from the CncParaDesc.xml this site was built with): {md_text(german)}", ""]
    if terms:
        out += [f"Search terms (German): {md_text(', '.join(terms))}", ""]
    return "\n".join(out)


def kind_page(kind: str, registry: Registry) -> str:
    """The index of one list kind's parameters: ID, key, type, default, unit."""
    specs = sorted((s for s in registry.specs.values() if s.kind == kind), key=lambda s: s.id)
    name = KINDS.get(kind, (kind, kind))[1]
    out = [f"# {md_text(name[:1].upper() + name[1:])} ({kind})", "",
           f"{len(specs)} parameters of the {md_text(name)}, by ID.", "",
           "| ID | Key | Type | Default | Unit |", "| --- | --- | --- | --- | --- |"]
    for s in specs:
        out.append(f"| [{s.id}]({s.id}.md) | {md_code(s.key) if s.key else '–'} | {s.type} | "
                   f"{md_code(s.default_display) if s.default_display else '–'} | "
                   f"{md_text(' or '.join(s.units)) if s.units else '–'} |")
    out.append("")
    return "\n".join(out)


def params_index_page(registry: Registry, german_source: str | None = None) -> str:
    """The parameters' index: one row per list kind, and where the German search terms come from
    (``german_source``: the catalogue the site was built with, where one was given)."""
    counts: dict[str, int] = {}
    for s in registry.specs.values():
        counts[s.kind] = counts.get(s.kind, 0) + 1
    out = ["# Parameters", "", f"zero's catalogue ({md_text(registry.source)}) has {len(registry.specs)} "
           "parameters. Each has a page: ID, key, list, type, unit, default, range, symbols, the restart flag "
           "and the rules that check it. Use the search to find a key (`swe_pos`) or an ID.", "",
           "| List | Kind | Parameters |", "| --- | --- | --- |"]
    for kind in sorted(counts, key=lambda k: (list(KINDS).index(k) if k in KINDS else len(KINDS), k)):
        name = KINDS.get(kind, (kind, kind))[1]
        out.append(f"| [{md_text(name)}]({kind}.md) | `{kind}` | {counts[kind]} |")
    out += ["", "## German search terms", ""]
    if german_source:
        out.append("Each parameter page carries the German name the catalogue this site was built with gives the "
                   f"parameter ({md_code(Path(german_source).name)}, read at build time through "
                   "`ZERO_PARAM_DESC` and not part of zero), and German words for the abbreviations in its key "
                   "from zero's own glossary; a parameter zero describes nowhere has that catalogue's English "
                   "short description as its meaning.")
    else:
        out.append("Each parameter page carries German words for the German abbreviations in its key (`swe`: "
                   "Softwareendschalter, Endschalter) from zero's own glossary. The catalogue's German names are "
                   "the vendor's text, which zero does not ship: build the site with `ZERO_PARAM_DESC` naming your "
                   "`CncParaDesc.xml` and each page carries its German name too (and its English short description "
                   "where zero has no description of its own).")
    out.append("")
    return "\n".join(out)
