"""zero convert: round trips, value fidelity, comments, sparse keys, edits, refusals."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path
from typing import Any

import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from conftest import FIXTURES, builtin_registry
from zero.catalog.registry import Registry
from zero.engine.convert import convert
from zero.engine.lint import lint_file
from zero.errors import ZeroError
from zero.structured.formats import read_tree, write_tree
from zero.structured.json import scan_json
from zero.structured.tree import Tree, nest

FORMATS = ("yaml", "toml", "json")
SEED = FIXTURES / "seed" / "nullp_3achsen.lis"


def corpus_lists(corpus: Path) -> list[Path]:
    return sorted((corpus / "isg-sdk" / "listen").rglob("*.lis"))


def round_trip(data: bytes, fmt: str, path: str = "t.lis") -> tuple[bytes, bytes]:
    structured = convert(data, "lis", fmt, builtin_registry(), path).output
    back = convert(structured, fmt, "lis", builtin_registry(), path + "." + fmt, check=False).output
    return structured, back


def tree_data(tree: Tree) -> dict[str, Any]:
    """What a standard loader should read from our output: nested values, str keys."""
    root, flat = nest(tree.leaves)

    def plain(node: dict[str, Any]) -> dict[str, Any]:
        return {k: plain(v) if isinstance(v, dict) else v.value for k, v in node.items()}

    out = plain(root)
    out.update({leaf.key: leaf.value for leaf in flat})
    return out


def str_keys(data: Any) -> Any:
    if isinstance(data, dict):
        return {str(k): str_keys(v) for k, v in data.items()}
    return data


def loaded(fmt: str, text: bytes) -> dict[str, Any]:
    if fmt == "yaml":
        data = yaml.safe_load(text)
    elif fmt == "toml":
        data = tomllib.loads(text.decode("utf-8"))
    else:
        data = json.loads(text)
    data.pop("_zero")
    result: dict[str, Any] = str_keys(data)
    return result


# ------------------------------------------------------------------ round trips


@pytest.mark.parametrize("fmt", FORMATS)
def test_seed_example_round_trips_byte_for_byte(registry: Registry, fmt: str) -> None:
    data = SEED.read_bytes()
    structured, back = round_trip(data, fmt, str(SEED))
    assert back == data
    tree = read_tree(data, "lis", registry, str(SEED))
    assert loaded(fmt, structured) == str_keys(tree_data(tree))


@pytest.mark.slow
@pytest.mark.parametrize("fmt", FORMATS)
def test_corpus_round_trips_byte_for_byte(registry: Registry, corpus: Path, fmt: str) -> None:
    files = corpus_lists(corpus)
    assert len(files) == 21
    for path in files:
        data = path.read_bytes()
        structured, back = round_trip(data, fmt, str(path))
        assert back == data, path
        tree = read_tree(data, "lis", registry, str(path))
        assert loaded(fmt, structured) == str_keys(tree_data(tree)), path


def _edit_first_int(fmt: str, text: str, tree: Tree) -> tuple[str, str]:
    """Change the first integer value as a person would in an editor; return key and new value."""
    leaf = next(x for x in tree.leaves if x.native == "int" and x.line)
    assert leaf.line is not None
    lines = text.split("\n")
    old = lines[leaf.line - 1]
    new_value = str(int(leaf.value) + 12345)
    pattern = r"(: |= )" + re.escape(str(leaf.value)) + r"\b"
    lines[leaf.line - 1] = re.sub(pattern, r"\g<1>" + new_value, old, count=1)
    assert lines[leaf.line - 1] != old
    return "\n".join(lines), new_value


@pytest.mark.parametrize("fmt", ["yaml", "toml"])
def test_editing_one_value_changes_exactly_one_line(registry: Registry, corpus: Path, fmt: str) -> None:
    for path in [SEED, *corpus_lists(corpus)]:
        data = path.read_bytes()
        structured = convert(data, "lis", fmt, registry, str(path)).output.decode("utf-8")
        tree = read_tree(structured.encode("utf-8"), fmt, registry, "x." + fmt)
        edited, new_value = _edit_first_int(fmt, structured, tree)
        back = convert(edited.encode("utf-8"), fmt, "lis", registry, "x." + fmt, check=False).output
        before, after = data.split(b"\n"), back.split(b"\n")
        assert len(before) == len(after), path
        changed = [i for i, (a, b) in enumerate(zip(before, after, strict=True)) if a != b]
        assert len(changed) == 1, path
        assert new_value.encode() in after[changed[0]]


# ------------------------------------------------------------------ values


TRICKY = ["ERROR", "on", "no", "0x1F", "010", "1e3", "-0", "TRUE", "+7", "0x400001", "PLC_INFO | MOS",
          "REPORT | REPORT_EXTENDED |PRINT", "P-AXIS-00212.0", '"text with ( # spaces"', "1.50",
          "X_Achse", "./listen/achsmds1.lis", "20804,20805", "cnc_ve_%s_[%d]_r", "null", "~", "yes",
          "inf", "1_000", "-", "a:b", "'q'", "4294967295", "-2147483648", "18446744073709551616"]


@pytest.mark.parametrize("fmt", FORMATS)
def test_values_come_back_as_written(fmt: str) -> None:
    lines = [f"wert[{i}].x   {v}" for i, v in enumerate(TRICKY)]
    data = ("\n".join([*lines, "Ende"]) + "\n").encode()
    structured, back = round_trip(data, fmt)
    assert back == data
    got = loaded(fmt, structured)["wert"]
    for i, v in enumerate(TRICKY):
        value = got[str(i)]["x"]
        # integers stay integers only where they are exact decimal integers
        if re.fullmatch(r"-?[1-9][0-9]*|0", v):
            assert value == int(v)
        else:
            assert value == v, (v, value)


def test_yaml_plain_scalars_written_by_hand_keep_their_text(registry: Registry) -> None:
    # (plain scalars YAML reads as another value than the list would, `010` or `on`, are refused:
    # tests/structured/test_convert_precision.py)
    text = "wert:\n  a: 0x1F\n  e: 1e3\n  f: -0\n"
    out = convert(text.encode(), "yaml", "lis", registry, "t.yaml", check=False).output.decode()
    values = [line.split()[1] for line in out.splitlines() if line.startswith("wert")]
    assert values == ["0x1F", "1e3", "-0"]


def test_real_parameter_values_are_numbers_and_string_parameters_stay_text(registry: Registry) -> None:
    reg = registry
    real = next(s for s in reg.specs.values() if s.type == "REAL64" and s.key and "[]" not in s.key)
    text = next(s for s in reg.specs.values() if s.type == "STRING" and s.key and "[]" not in s.key
                and s.kind == real.kind)
    data = f"{real.key} 1.5\n{text.key} 123\nEnde\n".encode()
    tree = read_tree(data, "lis", registry, "t.lis", real.kind)
    assert [leaf.value for leaf in tree.leaves] == [1.5, "123"]
    assert round_trip(data, "toml")[1] == data


# ------------------------------------------------------------------ structure


def test_sparse_stays_sparse() -> None:
    data = b"np_grp[96].achse[31].versch 5\nnp_grp[4000000000].achse[0].versch 1\n" \
           b"np_grp[123456789012345678901234567890].achse[0].inaktiv 1\nEnde\n"
    for fmt in FORMATS:
        structured, back = round_trip(data, fmt)
        assert back == data
        assert len(structured) < 2000
        groups = loaded(fmt, structured)["np_grp"]
        assert sorted(groups) == sorted(["96", "4000000000", "123456789012345678901234567890"])


def test_key_that_is_both_value_and_group_is_kept_flat() -> None:
    data = b"a 1\na.b 2\nx[0] 3\nx[0].y 4\nEnde\n"
    for fmt in FORMATS:
        assert round_trip(data, fmt)[1] == data


def test_duplicate_keys_keep_the_earlier_line_and_the_effective_value(registry: Registry) -> None:
    data = b"# first\nkenngr.antr_typ 1\nkenngr.x 5\nkenngr.antr_typ 2  ( later wins\nEnde\n"
    c = convert(data, "lis", "yaml", registry, "t.lis")
    assert any("set again later" in n for n in c.notes)
    assert yaml.safe_load(c.output)["kenngr"]["antr_typ"] == 2
    assert convert(c.output, "yaml", "lis", registry, "t.yaml", check=False).output == data
    # deleting the key in YAML removes both of its lines
    edited = c.output.decode().replace("  antr_typ: 2  # ( later wins\n", "")
    back = convert(edited.encode(), "yaml", "lis", registry, "t.yaml", check=False).output
    assert b"antr_typ" not in back


def test_a_list_with_thousands_of_keys_set_twice_converts_and_comes_back(registry: Registry) -> None:
    """Each key set twice: the effective line of each was searched for through every item (the
    same list repeated to 10 MB took 37 s to format); now it is found by its line."""
    block = "".join(f"np_grp[{g}].achse[{a}].versch {g * 100 + a}\n" for g in range(20) for a in range(32))
    data = (block + block.replace(".versch 0\n", ".versch 1\n") + "Ende\n").encode()
    c = convert(data, "lis", "yaml", registry, "n.lis")
    assert sum("set again later" in n for n in c.notes) == 640
    assert convert(c.output, "yaml", "lis", registry, "n.yaml", check=False).output == data


def test_adding_and_removing_keys_in_yaml(registry: Registry) -> None:
    data = SEED.read_bytes()
    text = convert(data, "lis", "yaml", registry, str(SEED)).output.decode()
    text = text.replace("        versch: 81000  # # NP-Verschiebung 8,1 mm\n",
                        "        versch: 81000  # # NP-Verschiebung 8,1 mm\n        neu: 7\n")
    text = text.replace("default_index: 2  # ( G55 ist nach Hochlauf automatisch aktiv)\n", "")
    back = convert(text.encode(), "yaml", "lis", registry, "t.yaml", check=False).output.decode()
    lines = back.split("\n")
    i = next(n for n, x in enumerate(lines) if x.startswith("np_grp[0].achse[1].versch"))
    assert lines[i + 1].startswith("np_grp[0].achse[1].neu")
    assert "default_index" not in back
    assert len(lines) == len(data.decode("latin-1").split("\n"))  # one added, one removed


def test_comments_are_visible_next_to_their_entry() -> None:
    data = (b"# header\n\n#  indented note\nk.a 1  ( paren note\nk.b 2  /* block */ ( second\n"
            b"k.c 3  # hash note\nk.d 4  plain words\n#k.e 5   commented out\n   \t\nk.f 6\n"
            b"# closing\nEnde   \n\n")
    for fmt in ("yaml", "toml"):
        structured, back = round_trip(data, fmt)
        assert back == data
        text = structured.decode()
        assert re.search(r"a\s*[:=] 1  # \( paren note", text)
        assert re.search(r"b\s*[:=] 2  # /\* block \*/ \( second", text)
        assert re.search(r"c\s*[:=] 3  # # hash note", text)
        assert "#k.e 5   commented out" in text
        assert text.index("# header") < text.index("a")
        assert text.index("# closing") > re.search(r"\n\s*f\s*[:=] 6", text).start()  # type: ignore[union-attr]
    assert round_trip(data, "json")[1] == data


@pytest.mark.parametrize("fmt", FORMATS)
def test_encoding_endings_and_bom_survive(fmt: str) -> None:
    cases = [
        "k.a 1  ( Ma\xdfe in \xb5m\r\nk.b 2\r\nEnde\r\n".encode("cp1252"),
        b"\xef\xbb\xbfk.a 1\nEnde",
        "k.a 1  # \u20ac\nEnde\n".encode(),
        b"k.a 1\nk.b 2\n",
    ]
    for data in cases:
        assert round_trip(data, fmt)[1] == data


def test_canonical_layout_when_written_from_scratch(registry: Registry) -> None:
    text = "np_grp:\n  1:\n    achse:\n      0:\n        versch: 100000  # ( P-ZERO-00003\n"
    out = convert(text.encode(), "yaml", "lis", registry, "t.yaml", check=False).output.decode()
    assert out == "np_grp[1].achse[0].versch" + " " * 29 + "100000  ( P-ZERO-00003\nEnde\n"


# ------------------------------------------------------------------ refusals


REFUSED_YAML = {
    "sequence leaf": ("np_grp:\n  1:\n    achse: [1, 2]\n", "sequence", 3),
    "top-level list": ("- a\n- b\n", "top level", 1),
    "top-level scalar": ("hello\n", "top level", 1),
    "python tag": ("a: !!python/object/apply:os.system ['true']\n", "tag", 1),
    "custom tag": ("a: !foo 1\n", "tag", 1),
    "anchor": ("a: &x 1\nb: *x\n", "anchor", 1),
    "duplicate key": ("np_grp:\n  1:\n    achse: {}\n  1:\n    achse: {}\n", "duplicate key", 4),
    "null": ("a:\n  b:\n", "no value", 2),
    "two documents": ("a: 1\n---\nb: 2\n", "more than one", 2),
    "not yaml": ("a: 'x\n", "not valid YAML", None),
    "float for integer": ("np_grp:\n  1:\n    achse:\n      0:\n        versch: 1.5\n", "floating", 5),
    "multi-line value": ('a: "x\\ny"\n', "line break", 1),
    "index first": ("0: 1\n", "starts with a name", 1),
    "bad key": ("a b: 1\n", "not a key", 1),
}


@pytest.mark.parametrize("name", sorted(REFUSED_YAML))
def test_yaml_refusals_are_located(registry: Registry, name: str) -> None:
    text, words, line = REFUSED_YAML[name]
    with pytest.raises(ZeroError) as info:
        convert(text.encode(), "yaml", "lis", registry, "t.yaml")
    assert words in info.value.message
    if line is not None:
        assert info.value.line == line
    assert str(info.value).startswith("t.yaml")


def test_billion_laughs_is_refused_before_expansion(registry: Registry) -> None:
    bomb = "a: &a [\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\",\"lol\"]\n"
    for i in range(1, 10):
        prev = chr(ord("a") + i - 1)
        cur = chr(ord("a") + i)
        bomb += f"{cur}: &{cur} [" + ",".join([f"*{prev}"] * 9) + "]\n"
    with pytest.raises(ZeroError, match="anchor"):
        read_tree(bomb.encode(), "yaml", registry, "bomb.yaml")


@pytest.mark.parametrize(("fmt", "text", "words"), [
    ("toml", "[np_grp.1.achse.0]\nversch = 1.5\n", "floating"),
    ("toml", "a = true\n", "boolean"),
    ("toml", "a = [1, 2]\n", "list/array"),
    ("toml", "a = 1979-05-27\n", "not a parameter value"),
    ("toml", "a = 1\na = 2\n", "not valid TOML"),
    ("toml", "a = ", "not valid TOML"),
    ("json", '{"a": 1, "a": 2}', "duplicate key"),
    ("json", '{"a": null}', "null"),
    ("json", '{"a": true}', "boolean"),
    ("json", "[1]", "top level"),
    ("json", '{"a": {"b": [1]}}', "list/array"),
    ("json", '{"a": 1', "not valid JSON"),
    ("json", '{"a": "\\ud800"}', "control character"),
    ("json", '{"_zero": {"zero": 99}, "a": 1}', "newer zero"),
    ("json", '{"_zero": [], "a": 1}', "must be a mapping"),
    ("json", '{"_zero": {"layout": null}, "a": 1}', "does not have the form"),
    ("json", '{"_zero": {"end": "Ende\\nb 2"}, "a": 1}', "does not have the form"),
    ("json", '{"_zero": {"colour": 1}, "a": 1}', "not part of zero"),
    ("yaml", '_zero:\n  value_column: -3\na: 1\n', "does not have the form"),
])
def test_toml_and_json_refusals(registry: Registry, fmt: str, text: str, words: str) -> None:
    with pytest.raises(ZeroError) as info:
        convert(text.encode(), fmt, "lis", registry, "t." + fmt)
    assert words in info.value.message


@pytest.mark.parametrize("fmt", FORMATS)
def test_nesting_ten_thousand_deep_is_refused(registry: Registry, fmt: str) -> None:
    depth = 10_000
    if fmt == "yaml":
        text = "a: " + "{b: " * depth + "1" + "}" * depth + "\n"
    elif fmt == "toml":
        text = "a = " + "{b = " * depth + "1" + "}" * depth + "\n"
    else:
        text = '{"a": ' + '{"b": ' * depth + "1" + "}" * depth + "}"
    with pytest.raises(ZeroError, match=r"nested|deep"):
        read_tree(text.encode(), fmt, registry, "deep." + fmt)


def test_structured_input_must_be_utf8(registry: Registry) -> None:
    with pytest.raises(ZeroError, match="not UTF-8") as info:
        read_tree(b"a: 1\nb: \xb5m\n", "yaml", registry, "t.yaml")
    assert (info.value.line, info.value.column) == (2, 4)


def test_list_lines_that_cannot_be_carried_are_refused(registry: Registry) -> None:
    with pytest.raises(ZeroError, match="not an entry") as info:
        convert(b"k.a 1\n*****\nEnde\n", "lis", "yaml", registry, "t.lis")
    assert info.value.line == 2
    with pytest.raises(ZeroError, match="control character") as info:
        convert(b"k.a 1\nk.b 2 \x01\n", "lis", "yaml", registry, "t.lis")
    assert info.value.line == 2


def test_values_a_list_line_cannot_hold_are_refused(registry: Registry) -> None:
    with pytest.raises(ZeroError, match="whitespace"):
        convert(b'a: "two words"\n', "yaml", "lis", registry, "t.yaml")
    with pytest.raises(ZeroError, match="cannot be written"):
        convert(b'a: "x # y"\n', "yaml", "lis", registry, "t.yaml")


def test_a_huge_sparse_index_in_yaml_is_cheap(registry: Registry) -> None:
    text = "np_grp:\n  2000000000:\n    achse:\n      0:\n        versch: 1\n"
    out = convert(text.encode(), "yaml", "lis", registry, "t.yaml").output
    assert out.startswith(b"np_grp[2000000000].achse[0].versch")


# ------------------------------------------------------------------ lint of structured input


def test_findings_point_into_the_yaml(registry: Registry) -> None:
    text = "np_grp:\n  1:\n    achse:\n      0:\n        versch: 99999999999\n"
    c = convert(text.encode(), "yaml", "lis", registry, "t.yaml")
    assert c.lint is not None
    d = next(x for x in c.lint.diagnostics if x.code == "R004")
    assert (d.span.line, d.span.column) == (5, 17)
    assert d.message.startswith("np_grp.1.achse.0.versch: ")


def test_write_tree_refuses_unknown_format(registry: Registry) -> None:
    tree = read_tree(b"a 1\n", "lis", registry)
    with pytest.raises(ZeroError):
        write_tree(tree, "xml")


def test_mixed_line_endings_are_said_plainly(registry: Registry) -> None:
    data = b"k.a 1\r\nk.b 2\nk.c 3\nEnde\n"
    c = convert(data, "lis", "yaml", registry, "t.lis")
    assert any("mixed line endings" in n for n in c.notes)
    back = convert(c.output, "yaml", "lis", registry, "t.yaml", check=False).output
    assert back == b"k.a 1\nk.b 2\nk.c 3\nEnde\n"


_JSON_KEYS = st.text(st.characters(codec="utf-8", exclude_categories=("Cs",)), min_size=1, max_size=6)
_JSON_LEAVES = st.one_of(st.integers(-10**12, 10**12), st.text(st.characters(codec="utf-8", exclude_categories=("Cs",)),
                                                                max_size=8))
_JSON_TREES = st.recursive(st.dictionaries(_JSON_KEYS, _JSON_LEAVES, min_size=1, max_size=4),
                           lambda inner: st.dictionaries(_JSON_KEYS, inner | _JSON_LEAVES, min_size=1, max_size=4),
                           max_leaves=20)


@given(_JSON_TREES, st.sampled_from([None, 2, 0]), st.booleans())
@settings(max_examples=300, deadline=None)
def test_every_json_value_is_located_where_it_is_written(data: dict[str, Any], indent: int | None,
                                                          ascii_only: bool) -> None:
    """scan_json gives each value's line and column: the text there is the value (after a string's
    quote), however the JSON is laid out, escaped or nested. A dotted key is split into the
    segments the reader splits it into (`"a.b"` is `a` → `b`)."""
    from hypothesis import assume

    from zero.structured.tree import is_index, split_key

    text = json.dumps(data, indent=indent, ensure_ascii=ascii_only)
    lines = text.split("\n")
    found = scan_json(text)
    leaves: list[tuple[tuple[str, ...], Any]] = []
    stack: list[tuple[tuple[str, ...], Any]] = [((), data)]
    while stack:
        here, node = stack.pop()
        for k, v in node.items():
            seg = (k,) if is_index(k) else split_key(k) or (k,)
            (stack.append(((*here, *seg), v)) if isinstance(v, dict) else leaves.append(((*here, *seg), v)))
    paths = [p for p, _ in leaves]
    assume(len(set(paths)) == len(paths) and not any(a != b and b[:len(a)] == a for a in paths for b in paths))
    assert set(found) == set(paths)
    for where, value in leaves:
        at = found[where]
        line = lines[at.line - 1]
        if isinstance(value, str):  # the column is the first character after the opening quote
            token = re.match(r'"(?:[^"\\]|\\.)*"', line[at.column - 2:])
            assert token is not None and json.loads(token.group()) == value
        else:
            assert line[at.column - 1:].startswith(str(value))


def test_findings_in_a_json_file_are_located_at_their_value(registry: Registry, tmp_path: Path) -> None:
    path = tmp_path / "n.json"
    path.write_text('{\n  "np_grp": {"1": {"achse": {"0": {"versch": 99999999999, "inaktiv": 7}}}},\n'
                    '  "_zero": {"zero": 1, "kind": "ZERO"}\n}\n')
    found = [(d.span.line, d.span.column, d.span.end_column, d.code) for d in lint_file(path, registry).diagnostics]
    assert found == [(2, 46, 57, "R004"), (2, 70, 71, "R005")]
