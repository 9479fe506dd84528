"""The condition language of the kernel's start-up checks and the prose ranges: closed, and exact."""

from __future__ import annotations

import pytest

from zero.catalog.conditions import DEFAULT_LIST, compile_condition, parse, ref_elements, refs, supported_drive_types


def run(text: str, values: dict[str, float | int | str | None]) -> object:
    return compile_condition(parse(text))(lambda pid, index: values.get(pid if index is None else f"{pid}.{index}"))


def test_bits_bind_tighter_than_comparisons_and_arithmetic_as_usual() -> None:
    assert run("P-AXIS-00015 & 0x4 != 0", {"P-AXIS-00015": 0x400004}) is True  # (a & 4) != 0, not a & (4 != 0)
    assert run("P-AXIS-00015 & 0x4 != 0", {"P-AXIS-00015": 0x1}) is False
    assert run("P-AXIS-00126 - P-AXIS-00127 > 2 * 3", {"P-AXIS-00126": 10, "P-AXIS-00127": 3}) is True
    assert run("not P-AXIS-00001 == 1 or abs(-2) == 2", {"P-AXIS-00001": 1}) is True


def test_an_unknown_value_says_nothing_unless_the_other_side_decides() -> None:
    assert run("P-AXIS-00219 <= P-AXIS-00268", {"P-AXIS-00219": 5}) is None
    assert run("P-AXIS-00018 == 1 and P-AXIS-00412 == 0", {"P-AXIS-00018": 4}) is False
    assert run("P-AXIS-00018 == 4 or P-AXIS-00250 != 0", {"P-AXIS-00018": 4}) is True
    assert run("P-AXIS-00018 == 1 and P-AXIS-00412 == 0", {"P-AXIS-00018": 1}) is None
    assert run("P-AXIS-00212 / P-AXIS-00001 > 1", {"P-AXIS-00212": 5, "P-AXIS-00001": 0}) is None  # no division by 0


def test_elements_and_the_list_fact() -> None:
    node = parse("P-AXIS-00305 <= P-AXIS-00212.0 / 2 and DEFAULT_LIST == 0")
    assert refs(node) == ["P-AXIS-00305", "P-AXIS-00212"]
    assert ref_elements(node) == [("P-AXIS-00305", None), ("P-AXIS-00212", 0)]
    assert run("P-AXIS-00212.0 > P-AXIS-00212", {"P-AXIS-00212.0": 3, "P-AXIS-00212": 2}) is True
    assert run(f"{DEFAULT_LIST} == 1", {DEFAULT_LIST: 1}) is True


@pytest.mark.parametrize("text", ["__import__('os')", "P-AXIS-00016 ==", "P-AXIS-00016 = 1", "x < 1",
                                  "(P-AXIS-00016 < 1", "P-AXIS-00016 < 1)", "size(P-AXIS-00016)",
                                  "len(P-AXIS-00016, 2)", "startswith(P-CHAN-00007)", "supports(3)",
                                  "P-AXIS-00018 in (P-AXIS-00016)", "P-AXIS-00018 in 1", "P-CHAN-00007 == \"S"])
def test_anything_else_is_refused(text: str) -> None:
    with pytest.raises(ValueError):
        parse(text)


def test_strings_prefix_length_and_sets() -> None:
    """Issue 38: what the documentation says of names (20971: a spindle name starts with S)."""
    assert run('startswith(P-CHAN-00007, "S")', {"P-CHAN-00007": "S1"}) is True
    assert run("startswith(P-CHAN-00007, 'S')", {"P-CHAN-00007": "X1"}) is False
    assert run('startswith(P-CHAN-00007, "S")', {}) is None
    assert run("len(P-CHAN-00007) <= 16", {"P-CHAN-00007": "S" * 17}) is False
    assert run('P-CHAN-00007 == "S"', {"P-CHAN-00007": "S"}) is True
    assert run('P-AXIS-00320 in ("DRIVE_DEFAULT", "CNC_POSITION_CONTROL")', {"P-AXIS-00320": "OTHER"}) is False
    assert run('P-AXIS-00320 not in ("A", "B")', {"P-AXIS-00320": "A"}) is False
    assert run("P-AXIS-00018 in (1, 2, -4)", {"P-AXIS-00018": -4}) is True
    assert run('P-AXIS-00018 in ("1")', {"P-AXIS-00018": 1}) is False  # text is never a number
    # a string against a number is unknown, never an exception
    assert run('P-CHAN-00007 < 3', {"P-CHAN-00007": "S"}) is None
    assert run("len(P-AXIS-00018) == 1", {"P-AXIS-00018": 1}) is None
    assert refs(parse('startswith(P-CHAN-00007, "S") and P-CHAN-00036 in (1, 2)')) == ["P-CHAN-00007", "P-CHAN-00036"]


def test_supports_reads_the_drive_type_table() -> None:
    """`supports(P)`: the drive type P-AXIS-00020 is one the table (the parameter page's "Drive
    types" row) lists for P; unknown where the table has no row."""
    from zero.catalog.conditions import supported_drive_types

    assert supported_drive_types("P-AXIS-00539") == frozenset({2, 3})  # SERCOS, Profidrive
    assert run("supports(P-AXIS-00539)", {"P-AXIS-00020": 2}) is True
    assert run("supports(P-AXIS-00539)", {"P-AXIS-00020": 4}) is False
    assert run("supports(P-AXIS-00539)", {}) is None
    assert run("supports(P-AXIS-00016)", {"P-AXIS-00020": 4}) is None  # no row: nothing said
    assert run("P-AXIS-00539 == 0 or supports(P-AXIS-00539)", {"P-AXIS-00539": 0}) is True
    assert refs(parse("P-AXIS-00539 == 0 or supports(P-AXIS-00539)")) == ["P-AXIS-00539", "P-AXIS-00020"]


def test_every_drive_type_row_is_sourced_and_known(registry: object) -> None:
    import tomllib

    from conftest import ROOT
    from zero.catalog.data.drive_types import DRIVE_TYPES

    toml = ROOT / "src" / "zero" / "catalog" / "data" / "drive_types.toml"
    assert tomllib.loads(toml.read_text(encoding="utf-8"))["drive"] == DRIVE_TYPES  # gen_startup.py was run
    for row in DRIVE_TYPES:
        assert str(row["source"]).startswith("https://infosys.beckhoff.com/"), row
        assert set(row["types"]) <= {1, 2, 3, 4, 5, 6, 7, 8, 16, 32}, row  # P-AXIS-00020's documented values
        assert ("param" in row) != ("key" in row), row  # one parameter, or one subtree of keys
        if "param" in row:
            assert registry.get(row["param"]) is not None, row  # type: ignore[attr-defined]
        else:
            assert str(row["key"]).endswith("."), row


def test_each_drive_type_fact_lives_in_one_table(registry: object) -> None:
    """Issue 38: the evidence table's drive-type rows (a range finding on a parameter of another drive
    type is information) are drive_types.toml's, compiled by key (tools/gen_evidence.py), not a second
    table: what supports() reads and what a range finding says come from the same row."""
    import tomllib

    from conftest import ROOT
    from zero.catalog.data.drive_types import DRIVE_TYPES
    from zero.catalog.data.evidence_table import DRIVES
    from zero.catalog.evidence import drive_types

    assert "drive" not in tomllib.loads((ROOT / "src" / "zero" / "catalog" / "data" / "evidence.toml")
                                        .read_text(encoding="utf-8"))
    assert len(DRIVES) == len(DRIVE_TYPES)
    for row, compiled in zip(DRIVE_TYPES, DRIVES, strict=True):
        key = row["key"] if "key" in row else registry.get(row["param"]).key  # type: ignore[attr-defined]
        assert compiled == {"key": key, "types": row["types"], "source": row["source"]}
    assert drive_types("lr_hw[].mask_mess_1") == ((2,), "https://infosys.beckhoff.com/content/1033/"
                                                  "tf5200_axis_parameter/117337611.html")
    assert drive_types("antr.sercos.times.t1") is not None  # a subtree
    assert drive_types("kenngr.measure.input_edge_banding") == ((2, 3), "https://infosys.beckhoff.com/content/"
                                                                "1033/tf5200_axis_parameter/117333003.html")
    assert supported_drive_types("P-AXIS-00106") == frozenset({2})  # and supports() reads the same row


def test_facts_of_the_whole_list_are_asked_of_the_lookup() -> None:
    """unique() and elsewhere() compare one element with the list's others: the evaluator asks the
    lookup for the fact by name (``unique:P,Q``, ``elsewhere:P,Q``), unknown where it has none."""
    seen: list[str] = []

    def lookup(pid: str, index: int | None) -> int | None:
        seen.append(pid)
        return {"unique:P-CHAN-00036,P-CHAN-00035": 0, "elsewhere:P-CHAN-00037,P-CHAN-00038": 1}.get(pid)

    assert compile_condition(parse("unique(P-CHAN-00036, P-CHAN-00035)"))(lookup) is False
    assert compile_condition(parse("not elsewhere(P-CHAN-00037, P-CHAN-00038)"))(lookup) is False
    assert compile_condition(parse("unique(P-CHAN-00007)"))(lookup) is None
    assert seen == ["unique:P-CHAN-00036,P-CHAN-00035", "elsewhere:P-CHAN-00037,P-CHAN-00038", "unique:P-CHAN-00007"]
    assert refs(parse("not elsewhere(P-CHAN-00037, P-CHAN-00038)")) == ["P-CHAN-00037", "P-CHAN-00038"]
    for bad in ("elsewhere(P-CHAN-00037)", "unique(3)", "unique(P-CHAN-00036.1)", "supports(DEFAULT_LIST)"):
        with pytest.raises(ValueError):
            parse(bad)


def test_isname_accepts_letters_digits_and_the_underscore_only() -> None:
    """Issue 38 (21438): a variable type of the external variables may hold letters, the digits 0-9
    and the underscore only."""
    assert run("isname(P-EXTV-00003)", {"P-EXTV-00003": "My_Type2"}) is True
    assert run("isname(P-EXTV-00003)", {"P-EXTV-00003": "REAL-64"}) is False
    assert run("isname(P-EXTV-00003)", {"P-EXTV-00003": "Typ ä"}) is False
    assert run("isname(P-EXTV-00003)", {"P-EXTV-00003": ""}) is None  # empty: nothing to check
    assert run("isname(P-EXTV-00003)", {"P-EXTV-00003": 5}) is None
    assert run("isname(P-EXTV-00003)", {}) is None
    with pytest.raises(ValueError):
        parse("isname(P-EXTV-00003, 2)")


def test_the_remainder_says_whether_one_time_is_a_whole_multiple_of_another() -> None:
    """Issue 38 (1000153): the real-time configuration's cycle time must be a whole multiple of its
    time slice; `%` binds like `*` and `/`, and a remainder by 0 is unknown, never an exception."""
    assert run("P-RTCF-00002 % P-RTCF-00003 == 0", {"P-RTCF-00002": 2000, "P-RTCF-00003": 500}) is True
    assert run("P-RTCF-00002 % P-RTCF-00003 == 0", {"P-RTCF-00002": 2000, "P-RTCF-00003": 300}) is False
    assert run("P-RTCF-00002 % P-RTCF-00003 == 0", {"P-RTCF-00002": 2000, "P-RTCF-00003": 0}) is None
    assert run("P-RTCF-00002 % P-RTCF-00003 == 0", {"P-RTCF-00002": 2000}) is None
    assert run("1 + 7 % 4 * 2 == 7", {}) is True  # 1 + ((7 % 4) * 2)
    assert refs(parse("P-RTCF-00002 % P-RTCF-00003 == 0")) == ["P-RTCF-00002", "P-RTCF-00003"]
