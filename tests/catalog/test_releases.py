"""The table of key renames and removals between kernel releases: every row backed by a source,
consistent with the catalogue, and the prefix rule never proposes a key the catalogue lacks."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import FIXTURES
from zero.catalog import releases
from zero.catalog.data.table import GENERATED_FROM
from zero.catalog.registry import KINDS, Registry, build_registry, load_table
from zero.catalog.releases import (
    CATALOGUE_RELEASE,
    UNKNOWN_RELEASE,
    Prefix,
    Removal,
    Rename,
    format_release,
    parse_release,
    read_table,
    removed,
    renamed,
    table,
)
from zero.errors import ZeroError
from zero.lists.model import parse_key
from zero.lists.tokenizer import tokenize

TABLE = table()
ALL_ROWS: list[Rename | Removal | Prefix] = [*TABLE.renames, *TABLE.removals, *TABLE.prefixes]
KEY_ROWS: list[Rename | Removal] = [*TABLE.renames, *TABLE.removals]


def test_the_table_has_its_rows() -> None:
    assert len(TABLE.renames) == 12
    assert len(TABLE.removals) == 2
    assert [(p.old, p.new) for p in TABLE.prefixes] == [("antr_simu.", "antr.simu.")]


@pytest.mark.parametrize("row", TABLE.renames, ids=lambda r: r.old)
def test_a_rename_leads_to_a_key_and_id_of_the_catalogue(registry: Registry, row: Rename) -> None:
    spec = registry.by_pattern(row.new, row.kind)
    assert spec is not None, f"{row.new} is not in the catalogue"
    assert spec.id == row.id
    assert registry.get(row.id) is spec
    assert row.id[2:6] == row.kind


def test_no_old_key_is_known_to_the_catalogue(registry: Registry) -> None:
    """An old key the catalogue knows (in any kind, as an alias or as a vendor key) is no rename
    and no removal: zero would answer for it twice."""
    for row in KEY_ROWS:
        assert registry.by_pattern(row.old, row.kind) is None, row.old
        assert registry.kinds_of(row.old) == [], row.old
        assert registry.alias(row.old, row.kind) is None, row.old
        assert (row.kind, row.old) not in registry.vendor_keys, row.old


def test_no_prefix_is_the_start_of_a_known_key(registry: Registry) -> None:
    for p in TABLE.prefixes:
        assert not [key for (kind, key) in _keys(registry) if kind == p.kind and key.startswith(p.old)]


def _keys(registry: Registry) -> list[tuple[str, str]]:
    return [(spec.kind, spec.key) for spec in registry.specs.values() if spec.key]


def test_every_row_has_a_source_a_kind_and_a_release() -> None:
    for row in ALL_ROWS:
        assert row.source.strip(), row
        assert row.kind in KINDS
        assert row.release == UNKNOWN_RELEASE or parse_release(row.release) < CATALOGUE_RELEASE
        assert all(url.startswith("https://") for url in row.see), row
        assert re.fullmatch(r"[A-Za-z0-9_]+(\[\])?(\.[A-Za-z0-9_]+(\[\])?)*\.?", row.old), row.old


def test_a_row_whose_source_is_an_annotation_names_its_id() -> None:
    """The rows backed by a list line's own annotation say which ID the annotation names."""
    for row in TABLE.renames:
        if "annotation" in row.source:
            assert f"`( {row.id}`" in row.source, row.old


def test_old_and_new_keys_are_in_the_registry_s_spelling() -> None:
    for row in KEY_ROWS:
        key = parse_key(row.old.replace("[]", "[0]"))
        assert key is not None and key.pattern == row.old
    for row in TABLE.renames:
        assert row.new_key((1,) * row.new.count("[]")) == row.new.replace("[]", "[1]")


def test_renamed_answers_with_the_row() -> None:
    row = renamed("antr_simu.totzeit", "AXIS")
    assert row is not None
    assert (row.new, row.id, row.release) == ("antr.simu.totzeit", "P-AXIS-00194", "V3.01.3074")
    assert "P-AXIS-00194" in row.source
    assert renamed("antr_simu.totzeit", None) == row  # kind not detected: any kind
    assert renamed("antr_simu.totzeit", "CHAN") is None
    assert renamed("antr.simu.totzeit", "AXIS") is None  # today's key is no rename
    assert renamed("lr_hw[].cntr_adr", "AXIS") is None  # a removal is no rename
    cam = renamed("antr.sercos.reference_cam_signal", "AXIS")
    assert cam is not None and (cam.new, cam.id) == ("antr.reference_cam_signal", "P-AXIS-00321")
    interface = renamed("kenngr.in_zus_schn", "AXIS")
    assert interface is not None and (interface.new, interface.id) == ("kenngr.in_add_interface", "P-AXIS-00091")
    assert "default_ax_mds.xml" in interface.source


def test_removed_answers_with_the_row() -> None:
    row = removed("lr_hw[].cntr_adr", "AXIS")
    assert row is not None and row.release == "V3.01.3074" and "issue 25" in row.source
    assert removed("lr_hw[].cntr_adr", None) == row
    assert removed("lr_hw[].cntr_adr", "CHAN") is None
    assert removed("lr_param.pos_einschw_zt", "AXIS") is not None
    assert removed("antr_simu.totzeit", "AXIS") is None  # a rename is no removal
    assert removed("kenngr.frei_1", "AXIS") is None  # reserve fields: no source, no row


def test_the_prefix_leads_only_to_keys_the_catalogue_has(registry: Registry) -> None:
    row = renamed("antr_simu.use_initial_position", "AXIS", registry)  # no row of its own
    assert row is not None
    assert (row.new, row.id) == ("antr.simu.use_initial_position", "P-AXIS-00791")
    assert row.source == TABLE.prefixes[0].source
    assert renamed("antr_simu.use_initial_position", "AXIS") is None  # without a catalogue: never
    assert renamed("antr_simu.anfangsposition", "AXIS", registry) is None  # no such key today
    assert renamed("antr_simu.", "AXIS", registry) is None
    assert renamed("antr_simu.use_initial_position", "CHAN", registry) is None
    assert renamed("antr_simux.totzeit", "AXIS", registry) is None


def test_the_prefix_agrees_with_every_row_it_covers(registry: Registry) -> None:
    for p in TABLE.prefixes:
        covered = [r for r in TABLE.renames if r.kind == p.kind and r.old.startswith(p.old)]
        assert len(covered) == 9
        for r in covered:
            assert r.new == p.new + r.old[len(p.old):]


def test_a_catalogue_without_the_new_key_gets_no_rename() -> None:
    """With a catalogue of another release that lacks today's key, no row answers: zero never
    proposes a key it cannot check."""
    rows = [r for r in load_table() if r["id"] != "P-AXIS-00194"]
    other = build_registry(rows, "a catalogue without P-AXIS-00194")
    assert renamed("antr_simu.totzeit", "AXIS", other) is None
    assert renamed("antr_simu.daempfung_n", "AXIS", other) is not None


def test_the_annotated_lines_of_the_fixture_agree_with_the_table() -> None:
    """fixtures/releases/old_axis.lis: every line its README calls a rename (row) is one, with the
    ID its annotation names (but line 16, whose annotation names the wrong parameter)."""
    path = FIXTURES / "releases" / "old_axis.lis"
    doc = tokenize(path.read_bytes(), str(path))
    readme = (FIXTURES / "releases" / "README.md").read_text(encoding="utf-8")
    said = dict(re.findall(r"^\| (\d+) \| `[^`]+` \| ([a-z ()]+) \|", readme, flags=re.M))
    reg = build_registry(load_table(), "built-in")
    seen = set()
    for e in doc.entries:
        assert e.key is not None
        answer = said[str(e.line)]
        seen.add(e.line)
        row = renamed(e.key.pattern, "AXIS", reg)
        if answer == "known":
            assert reg.by_pattern(e.key.pattern, "AXIS") is not None, e.line
        elif answer.startswith("rename"):
            assert row is not None, e.line
            assert (answer == "rename (row)") == (renamed(e.key.pattern, "AXIS") is not None), e.line
            if e.annotation is not None and e.line != 16:
                assert e.annotation == row.id, e.line
        elif answer == "removal":
            assert row is None and removed(e.key.pattern, "AXIS") is not None, e.line
        else:
            assert answer == "unknown"
            assert row is None and removed(e.key.pattern, "AXIS") is None, e.line
            assert reg.by_pattern(e.key.pattern, "AXIS") is None, e.line
    assert seen == {int(n) for n in said}
    assert 20 <= len(path.read_bytes().splitlines()) <= 40


@pytest.mark.parametrize(("text", "release"), [
    ("V3.1.3074", (3, 1, 3074)),
    ("V3.01.3074", (3, 1, 3074)),
    ("v3.01.3074", (3, 1, 3074)),
    (" V3.1.3080.12 ", (3, 1, 3080, 12)),
    ("4.13", (4, 13)),
    ("V4.13.0.0", (4, 13)),
    ("V2.11.2809.06", (2, 11, 2809, 6)),
    ("4", (4,)),
])
def test_a_release_is_parsed_into_a_comparable_tuple(text: str, release: tuple[int, ...]) -> None:
    assert parse_release(text) == release


def test_releases_compare_in_release_order() -> None:
    order = ["V2.11.2809.06", "V3.01.3074", "V3.1.3079.06", "V3.1.3080.12", "V4.13.0.0", "V4.14"]
    assert sorted(order, key=parse_release) == order
    assert parse_release("V3.01.3074") < CATALOGUE_RELEASE
    assert parse_release("4.13") == CATALOGUE_RELEASE


@pytest.mark.parametrize("text", ["", "V", "3.", "V3..1", "TwinCAT 2021", "V3.1a", "unknown", "-4.13"])
def test_text_that_is_no_release_is_refused(text: str) -> None:
    with pytest.raises(ZeroError, match="not a kernel release"):
        parse_release(text)


def test_format_release_round_trips() -> None:
    for text in ["V3.1.3074", "V4.13", "V2.11.2809.6"]:
        assert format_release(parse_release(text)) == text
    assert format_release((4,)) == "V4.0"


def test_the_catalogue_release_is_the_shipped_table_s() -> None:
    m = re.search(r"kernel (V[\d.]+)", GENERATED_FROM)
    assert m is not None
    assert parse_release(m.group(1)) == CATALOGUE_RELEASE == (4, 13)


def test_a_row_without_a_source_is_refused(tmp_path: Path) -> None:
    bad = tmp_path / "releases.toml"
    bad.write_text('[[rename]]\nold = "a.b"\nkind = "AXIS"\nnew = "a.c"\nid = "P-AXIS-00001"\n'
                   'release = "V3.01"\nsource = " "\n', encoding="utf-8")
    with pytest.raises(ZeroError, match=r"\[\[rename\]\] row 1 lacks source"):
        read_table(bad)
    bad.write_text('[[removal]]\nold = "a.b"\nkind = "AXIS"\nrelease = "V3.01"\nsource = "x"\nnew = "c"\n',
                   encoding="utf-8")
    with pytest.raises(ZeroError, match="wrong fields new"):
        read_table(bad)
    bad.write_text('[[removal]]\nold = "a.b"\nkind = "AXIS"\nrelease = 3\nsource = "x"\n', encoding="utf-8")
    with pytest.raises(ZeroError, match="lacks release"):
        read_table(bad)
    bad.write_text('[[removal]]\nold = "a.b"\nkind = "AXIS"\nrelease = "soon"\nsource = "x"\n', encoding="utf-8")
    with pytest.raises(ZeroError, match="not a kernel release"):
        read_table(bad)
    bad.write_text("[[removal]\n", encoding="utf-8")
    with pytest.raises(ZeroError, match="cannot read the release table"):
        read_table(bad)


def test_the_table_is_read_once() -> None:
    assert table() is table()


def test_importing_the_module_reads_no_toml() -> None:
    """Start-up: the table is read at the first question, not at import."""
    code = "import sys, zero.catalog.releases as r; print('tomllib' in sys.modules, r._table is None)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["False", "True"]
    assert releases.DATA.is_file()


def test_the_compiled_table_is_the_toml() -> None:
    """tools/gen_startup.py was run after the last edit of releases.toml (zero builds the table from the
    compiled module: no TOML parser for a list's first unknown key)."""
    assert read_table(releases.DATA) == TABLE


def test_no_rename_keeps_its_key() -> None:
    """A rename (or prefix) leads to another key than the one it renames: check_keys reads a pattern bound to
    a parameter whose key it is as the catalogue's own key (never a rename's), so this must hold."""
    table = releases.table()
    assert all(r.old != r.new for r in table.renames)
    assert all(p.old != p.new for p in table.prefixes)
