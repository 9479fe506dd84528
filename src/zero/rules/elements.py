"""S rules on the parameter elements of an XML list that did not become entries.

An XML list is read as list text in which every XML line that is not a parameter entry is a
comment line holding that line (:mod:`zero.markup.lists`). A parameter element stays such a
line when zero cannot make an entry of it: the catalogue does not know its ID, its indices do
not fit the parameter, or it is not written one element to a line. These checks find those
lines, in the XML file and in its list, YAML, TOML or JSON conversion alike, so that no
element goes unchecked in silence. An element with an empty ``Value`` is left alone: neither
the catalogue nor the vendor's documentation says what the kernel makes of it, and the vendor's
own templates hold such elements.
"""

from __future__ import annotations

from collections.abc import Iterator

from zero.catalog.registry import KINDS
from zero.diagnostics import Diagnostic, Span
from zero.lists.model import Comment
from zero.patterns import compiled
from zero.rules.base import INFO, Context, E, W
from zero.rules.syntax import FAMILY

__all__ = ["FAMILY", "FORM_REFUSED", "NOT_CHECKED", "UNKNOWN_ID", "XML_REFUSED", "check_elements"]

# compiled at the first XML comment line checked (through re's cache): most lists have none
_ELEMENT_RE = r"<(P-[A-Z]{4}-[0-9]{5})((?:\.[0-9]+)*)(?=[\s/>]|$)"
_VALUE_RE = r"""\sValue\s*=\s*(?:"([^"]*)"|'([^']*)')"""

XML_REFUSED = FAMILY.rule(
    "S014", "xml-not-read", E, "An XML file zero will not read",
    """
What it checks: a file that starts like XML is read with a hardened parser (defusedxml). It must
be well-formed, and it may not declare a document type (DTD) or entities or refer to anything
outside itself. Anything else is this one finding, where the parser stopped; nothing in the file
is checked. The engine reports it.

Why it matters on the machine: a list that is not well-formed XML cannot be read by the kernel's
XML reader either. A DTD or entity is never part of a parameter list and is how hostile files
expand to gigabytes (billion laughs) or make a tool read other files (external entities).

Example: `<P-AXIS-00016 Value="1">` never closed; `<!DOCTYPE x [<!ENTITY a "...">]>`.
Fix: repair the XML; remove the DTD.
""")
FORM_REFUSED = FAMILY.rule(
    "S017", "form-not-read", E, "A YAML, TOML or JSON list form zero cannot read",
    """
What it checks: a `.yaml`, `.yml`, `.toml` or `.json` file zero is given must read as the list
it converts to: valid YAML/TOML/JSON within zero's limits (no anchors, tags, duplicate keys,
deep nesting), every key a parameter key or part of one, every value a scalar. Anything else
is this one finding, where the reader stopped; nothing in the file is checked, and the run goes
on with the other files. A file that reads as keys and values but whose top-level keys are
mostly not parameters' (a `package.json`) and that has no `_zero` table is no list form: it is
skipped with a note and no finding. The engine reports it.

Why it matters on the machine: a form that does not convert cannot become the list the
controller reads; `zero convert` refuses it too.

Example: `kopf: {achs_nr: 1` (a mapping never closed)
Fix: repair the file; `zero convert` writes forms that read back.
""")
UNKNOWN_ID = FAMILY.rule(
    "S015", "unknown-parameter-id", W, "An XML element names a parameter the catalogue does not know",
    """
What it checks: every parameter element of an XML list (`<P-AXIS-00016 Value="1" />`) names an
ID the catalogue documents, with as many dot-separated indices as the parameter has array
dimensions (`<P-ZERO-00003.1.0 …/>` for `np_grp[1].achse[0].versch`).

Why it matters on the machine: zero cannot tell which parameter such an element sets, so it
cannot check it. The catalogue is silent on what the kernel does with it; the vendor's own
templates use a few IDs the catalogue lacks (`P-RTCF-00015`), so it may well be read. Point
zero at the controller's own `CncParaDesc.xml` (`--param-desc`) to check it.

Example: `<P-ZERO-00003.1 Value="0" />` (the parameter has two indices)
Fix: correct the ID or the indices; or give zero the catalogue that documents it.
""")
NOT_CHECKED = FAMILY.rule(
    "S016", "element-not-checked", INFO, "An XML parameter element zero does not read",
    """
What it checks: an XML list holds each parameter element alone on its line (`<ID Value="…" />`),
as the vendor's lists do. An element that shares its line with another, spans lines, has
content, or holds a value zero cannot carry in list form is not checked, and this says so.

Why it matters on the machine: nothing by itself — the kernel reads XML, not lines — but a
parameter zero does not read is a parameter nobody checked.

Example: `<P-AXIS-00016 Value="1" /><P-AXIS-00297 Value="X" />`
Fix: write one element to a line.
""")


@FAMILY.check(UNKNOWN_ID, NOT_CHECKED)
def check_elements(ctx: Context) -> Iterator[Diagnostic]:
    """S015/S016: parameter elements left as comment lines of an XML list's text."""
    doc = ctx.doc
    if doc.origin is None and not doc.holds_xml_lines():
        return
    for item in doc.items:
        if type(item) is not Comment:
            continue
        text = doc.lines[item.line - 1]
        if not text.startswith("# ") or "<P-" not in text:
            continue
        for m in compiled(_ELEMENT_RE).finditer(text):
            value = compiled(_VALUE_RE).match(text, m.end())
            if value is not None and not (value.group(1) or value.group(2)):
                continue  # an empty Value: nothing to check, nothing known to say
            span = Span.on_line(item.line, m.start(1), m.end(2))
            pid, dots = m.group(1), m.group(2)
            spec = ctx.registry.get(pid)
            if spec is None or not spec.key:
                yield ctx.report("S015", span, f"{pid} is not in the catalogue ({ctx.registry.source}): zero cannot "
                                 "say which parameter this element sets or check its value; the catalogue is "
                                 "silent on whether the kernel reads it", param_id=pid)
                continue
            if ctx.kind is not None and spec.kind != ctx.kind:
                yield ctx.report("S015", span, f"{pid} (`{spec.key}`) belongs to the {KINDS[spec.kind][1]}, not to "
                                 f"this {KINDS[ctx.kind][1]}: zero does not check it here, and the catalogue does "
                                 "not say what the kernel does with it", param_id=pid)
                continue
            want = spec.key.count("[]")
            given = dots.count(".")
            if want != given:
                yield ctx.report("S015", span, f"{pid} (`{spec.key}`) has {want} ind{'ex' if want == 1 else 'ices'}, "
                                 f"the element gives {given}: zero cannot say which element of it is meant",
                                 param_id=pid)
                continue
            yield ctx.report("S016", span, f"{pid}{dots} is not written alone on its line as "
                             "`<ID Value=\"…\" />`: zero does not check it", param_id=pid)
