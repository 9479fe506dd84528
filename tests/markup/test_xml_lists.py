"""The kernel's XML lists: read into the one document model, findings in the XML file, back byte for byte."""

from __future__ import annotations

from pathlib import Path

import pytest

from conftest import FIXTURES
from zero.catalog.registry import Registry
from zero.engine.lint import LintOptions, lint_bytes, lint_file
from zero.errors import ZeroError
from zero.forms import xml_form
from zero.lists.tokenizer import tokenize_text
from zero.markup import read_document
from zero.markup.lists import to_list, to_xml

pytestmark = pytest.mark.slow


def _xml_files(corpus: Path) -> list[Path]:
    files = sorted((corpus / "isg-sdk" / "xml").rglob("*.xml"))
    assert len(files) == 18
    return files


def _list_text(path: Path, registry: Registry) -> tuple[bytes, str | None]:
    data = path.read_bytes()
    text, _, kind = to_list(data, registry, str(path))
    return (b"\xef\xbb\xbf" if data.startswith(b"\xef\xbb\xbf") else b"") + text.encode("utf-8"), kind


def test_every_corpus_xml_list_is_read_as_a_list(corpus: Path, registry: Registry) -> None:
    for path in _xml_files(corpus):
        data = path.read_bytes()
        assert xml_form(data) == "xml", path
        doc = read_document(data, str(path), registry)
        assert doc.origin is not None and doc.origin.kind is not None, path
        assert len(doc.entries) > 0, path
        # one list line for one XML line, and `Ende` after them
        assert len(doc.lines) == len(data.decode("utf-8-sig").splitlines()) + 1, path


def test_every_corpus_xml_list_comes_back_byte_for_byte(corpus: Path, registry: Registry) -> None:
    for path in _xml_files(corpus):
        data = path.read_bytes()
        text, kind = _list_text(path, registry)
        doc = read_document(text, str(path), registry)
        assert to_xml(doc, registry, kind) == data, path  # its BOM and encoding too


def test_findings_equal_those_of_the_list_conversion(corpus: Path, registry: Registry) -> None:
    """Code, parameter and line (one list line for one XML line) of every finding."""
    total = 0
    for path in _xml_files(corpus):
        xml = lint_file(path, registry)
        text, kind = _list_text(path, registry)
        listed = lint_bytes(text, registry, str(path.with_suffix(".lis")), LintOptions(kind=kind))
        assert [(d.code, d.param_id, d.span.line) for d in xml.diagnostics] == \
            [(d.code, d.param_id, d.span.line) for d in listed.diagnostics], path
        total += len(xml.diagnostics)
    # the vendor's templates: the few findings left are each true of the catalogue (counted here so
    # that new noise shows up as a changed number)
    assert total == 11  # with K074 (P-ERR-110421) on the spindle template ax_mds_6_spdl.xml


def test_a_finding_points_at_the_value_attribute(registry: Registry, tmp_path: Path) -> None:
    path = tmp_path / "ax.xml"
    path.write_text('<?xml version="1.0" encoding="utf-8"?>\n<AX_MDS>\n  <Head>\n'
                    '    <P-AXIS-00016 Value="1" />\n    <P-AXIS-00018 Value="abc" />\n  </Head>\n</AX_MDS>\n')
    result = lint_file(path, registry)
    [d] = result.diagnostics
    assert (d.code, d.param_id) == ("R005", "P-AXIS-00018")
    line = result.document.line_text(d.span.line)
    assert line[d.span.column - 1: d.span.end_column - 1] == "abc"


def test_a_key_finding_points_at_the_element_name(registry: Registry, tmp_path: Path) -> None:
    path = tmp_path / "zero.xml"
    path.write_text('<?xml version="1.0" encoding="utf-8"?>\n<ZeroOffset>\n'
                    '  <P-ZERO-00003.99.0 Value="0" />\n</ZeroOffset>\n')
    [d] = lint_file(path, registry).diagnostics
    assert d.code == "R003" and (d.span.line, d.span.column, d.span.end_column) == (3, 4, 21)


def test_a_list_converted_to_xml_and_back_reads_the_same(corpus: Path, registry: Registry) -> None:
    """Every corpus ASCII list whose keys all have IDs: the same entries, values and annotations."""
    converted = 0
    for path in sorted((corpus / "isg-sdk" / "listen").rglob("*.lis")):
        doc = read_document(path.read_bytes(), str(path), registry)
        from zero.rules.base import Context

        kind = Context.of(doc, registry, None).kind
        try:
            xml = to_xml(doc, registry, kind)
        except ZeroError as exc:  # a key without an ID: refused, located
            assert "has no parameter ID" in str(exc) or "no root element" in str(exc) or "not known" in str(exc)
            continue
        back = read_document(xml, str(path.with_suffix(".xml")), registry)
        assert [(e.key_text, e.value) for e in back.entries] == [(e.key_text, e.value) for e in doc.entries], path
        converted += 1
    assert converted >= 10


@pytest.mark.parametrize(("name", "where", "words"), [
    ("billion_laughs.xml", None, "document type"),
    ("external_entity.xml", None, "document type"),
    ("dtd_only.xml", None, "document type"),
    ("malformed.xml", None, "not well-formed"),
    ("unclosed_cdata.xml", None, "not well-formed"),
])
def test_hostile_xml_is_one_located_finding(name: str, where: object, words: str, registry: Registry) -> None:
    path = FIXTURES / "xml" / "hostile" / name
    result = lint_file(path, registry)
    assert [d.code for d in result.diagnostics] == ["S014"], result.diagnostics
    assert words in result.diagnostics[0].message
    assert result.diagnostics[0].span.line >= 1


def test_a_huge_attribute_is_refused_located(tmp_path: Path, registry: Registry) -> None:
    path = tmp_path / "huge.xml"
    with open(path, "wb") as f:
        f.write(b'<?xml version="1.0" encoding="utf-8"?>\n<ZeroOffset>\n  <P-ZERO-00001 Value="')
        chunk = b"9" * (1 << 20)
        for _ in range(100):
            f.write(chunk)
        f.write(b'" />\n</ZeroOffset>\n')
    result = lint_file(path, registry)
    [d] = result.diagnostics
    assert d.code == "F001" and "line 3 is longer than" in d.message


def test_list_text_form_is_readable(registry: Registry) -> None:
    data = (b'<?xml version="1.0" encoding="utf-8"?>\n<AX_MDS>\n  <!-- Logical axis number -->\n'
            b'  <P-AXIS-00016 Value="1" />\n  <P-AXIS-00297 Value="X"/>\n</AX_MDS>\n')
    text, _, kind = to_list(data, registry)
    assert kind == "AXIS"
    assert text.splitlines() == [
        '# <?xml version="1.0" encoding="utf-8"?>',
        "# <AX_MDS>",
        "#   <!-- Logical axis number -->",
        "kopf.achs_nr" + " " * 42 + "1",
        "kopf.log_achs_name" + " " * 36 + 'X  ( xml:   <P-AXIS-00297 Value="{}"/>',
        "# </AX_MDS>",
        "Ende",
    ]
    assert to_xml(tokenize_text(text), registry, kind) == data
