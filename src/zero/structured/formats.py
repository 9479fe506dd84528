"""The structured forms by name: which format a file is, and reading or writing a tree.

``lis`` is the list itself; ``yaml``, ``toml`` and ``json`` are the structured forms
(:mod:`zero.structured.yaml`, ``toml``, ``json``: each holds its reader and writer).
:func:`read_tree` reads any of them into a :class:`~zero.structured.tree.Tree` and
refuses what the catalogue says the controller would not take over (a floating-point
number for an integer parameter); :func:`write_tree` writes a tree in any of them.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from zero.catalog.registry import INTEGER_TYPES, Registry, kind_from_name
from zero.errors import ZeroError
from zero.lists.model import parse_key
from zero.lists.tokenizer import tokenize
from zero.structured import json as json_form
from zero.structured import toml as toml_form
from zero.structured import yaml as yaml_form
from zero.structured.tree import Tree, encode_list, from_document, structured_path, to_list_text

READERS: dict[str, Callable[[str, str], Tree]] = {
    "yaml": yaml_form.read_yaml, "toml": toml_form.read_toml, "json": json_form.read_json}
WRITERS: dict[str, Callable[[Tree], str]] = {
    "yaml": yaml_form.write_yaml, "toml": toml_form.write_toml, "json": json_form.write_json}


def decode_structured(data: bytes, path: str) -> str:
    """YAML/TOML/JSON are UTF-8 (a BOM is allowed); anything else is refused with its offset."""
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        col = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
        raise ZeroError(f"not UTF-8 (byte 0x{data[exc.start]:02X}); YAML, TOML and JSON files "
                        "are read as UTF-8", path, line, col) from None


_EXPONENT_RE = re.compile(r"[+-]?(?:[0-9]++(?:\.[0-9]*+)?|\.[0-9]++)[eE][+-]?[0-9]++")  # possessive: linear


def check_types(tree: Tree, registry: Registry) -> None:
    """Refuse a number of the wrong kind that the format made (a float for an integer), also when it
    is written with an exponent (``1e3``), which YAML keeps as text."""
    floats = [leaf for leaf in tree.leaves if leaf.native == "float"
              or (leaf.native == "plain" and isinstance(leaf.value, str) and _EXPONENT_RE.fullmatch(leaf.value))]
    if not floats:
        return
    kind = tree.meta.get("kind") if isinstance(tree.meta.get("kind"), str) else None
    kind = kind_from_name(kind) if kind else None
    for leaf in floats:
        key = parse_key(leaf.key)
        spec = registry.by_pattern(key.pattern, kind) if key else None
        if spec is not None and spec.type in INTEGER_TYPES:
            raise ZeroError(
                f"{structured_path(leaf.path)}: {leaf.value} is a floating-point number but "
                f"{spec.id} is {spec.type}; the controller would not take it over — "
                "write an integer", tree.path, leaf.line, leaf.column)


def read_tree(data: bytes, fmt: str, registry: Registry, path: str = "-", kind: str | None = None) -> Tree:
    """Read list, YAML, TOML or JSON bytes as a tree."""
    if fmt == "lis":
        return from_document(tokenize(data, path), registry, kind)
    if fmt not in READERS:
        raise ZeroError(f"unknown input format {fmt!r} (use one of: lis, yaml, toml, json)", path)
    tree = READERS[fmt](decode_structured(data, path), path)
    check_types(tree, registry)
    if kind and "kind" not in tree.meta:
        tree.meta["kind"] = kind
    return tree


def write_tree(tree: Tree, fmt: str) -> bytes:
    """A tree as list, YAML, TOML or JSON bytes."""
    if fmt == "lis":
        return encode_list(tree, to_list_text(tree).text)
    if fmt not in WRITERS:
        raise ZeroError(f"unknown output format {fmt!r} (use one of: lis, yaml, toml, json)")
    return WRITERS[fmt](tree).encode("utf-8")
