"""The fuzz targets, importable without atheris (tests replay crashes through them).

The first byte of an input picks the target (``% 9`` for 0-8; 0xF9 to 0xFD for 9-13, so
that every input saved before the last targets existed replays as it did); the rest is the data:
0 tokenizer + lint of list bytes, 1 list → YAML/TOML/JSON → list (must be the
identity), 2 YAML reader, 3 TOML reader, 4 JSON reader, 5 diff of two halves,
6 NC program against the fixture machine, 7 zero format (idempotent, meaning kept),
8 fixes (a fixed list has no fixable finding left, or the fix loop stopped), 9 a
configuration file (``zero.toml``: its patterns matched too), 10 a machine layout (a
start-up list and the lists it names, split from the data, read from memory: references,
counts, paths, default lists, the X rules), 11 the language server's transport (the bytes a
client sends, framed as pygls will read them), 12 XML: an XML list (lint with every finding inside
the file, XML → list → XML the identity where it converts), and the same bytes as a TwinCAT export
(its lists in place, a fixed export unchanged outside its CDATA sections), 13 a git repository
(``.gitignore``, ``.git/info/exclude``, ``zero.toml`` and file names: what a directory walk finds).
A target turns zero's own refusals (ZeroError: located, said) into a return; anything else that
escapes is a crash (``fuzz_zero.py`` and the replayed regressions treat every exception so).
"""

from __future__ import annotations

import os
from pathlib import Path

from zero.catalog.registry import load_registry
from zero.diff import DiffOptions, diff_sides, read_side
from zero.engine.convert import convert
from zero.engine.fixes import fix_bytes
from zero.engine.formatting import format_bytes
from zero.engine.lint import lint_bytes, lint_program
from zero.errors import ZeroError
from zero.forms import xml_form
from zero.lists.encoding import document_bytes
from zero.lists.tokenizer import tokenize
from zero.machine.model import Machine, load_machine
from zero.structured.formats import read_tree

REGISTRY = load_registry()
MACHINE_STARTUP = Path(__file__).resolve().parent.parent / "fixtures" / "machine" / "listen" / "hochlauf.lis"


def check_lint(data: bytes) -> None:
    result = lint_bytes(data, REGISTRY, "f.lis")
    n = len(result.document.lines)
    for d in result.diagnostics:
        assert 1 <= d.span.line <= max(n, 1) + 1, d


def check_round_trip(data: bytes) -> None:
    for fmt in ("yaml", "toml", "json"):
        try:
            first = convert(data, "lis", fmt, REGISTRY, "f.lis")
        except ZeroError:
            return
        back = convert(first.output, fmt, "lis", REGISTRY, "f." + fmt, check=False).output
        if any("mixed line endings" in n for n in first.notes):  # said plainly: one style
            assert back.replace(b"\r\n", b"\n") == data.replace(b"\r\n", b"\n"), (fmt, data, back)
        else:
            assert back == data, (fmt, data, back)


def check_reader(fmt: str, data: bytes) -> None:
    try:
        read_tree(data, fmt, REGISTRY, "f." + fmt)
        convert(data, fmt, "lis", REGISTRY, "f." + fmt)
        for other in ("yaml", "toml", "json"):
            convert(data, fmt, other, REGISTRY, "f." + fmt, check=False)
    except ZeroError:
        pass


def check_diff(data: bytes) -> None:
    half = len(data) // 2
    try:
        a, b = read_side(data[:half], "lis", "a", REGISTRY), read_side(data[half:], "lis", "b", REGISTRY)
    except ZeroError:  # a binary half: refused plainly
        return
    diff_sides(a, b, REGISTRY)
    diff_sides(b, a, REGISTRY)


_machine: list[Machine] = []


def check_program(data: bytes) -> None:
    if not _machine:
        _machine.append(load_machine(MACHINE_STARTUP, REGISTRY))
    result = lint_program(data, REGISTRY, "f.nc", machine=_machine[0])
    for d in result.diagnostics:
        assert 1 <= d.span.line <= max(len(result.document.lines), 1), d


def check_format(data: bytes) -> None:
    try:
        once = format_bytes(data, "f.lis", REGISTRY)
    except ZeroError:
        return
    assert format_bytes(once, "f.lis", REGISTRY) == once, (data, once)
    try:
        before = read_side(data, "lis", "a", REGISTRY)
    except ZeroError:  # not text: format refused nothing, but there is nothing to compare
        return
    assert diff_sides(before, read_side(once, "lis", "b", REGISTRY), REGISTRY,
                      DiffOptions(strict=True, comments=True)) == [], (data, once)


def check_fix(data: bytes) -> None:
    fix_bytes(data, "f.lis", REGISTRY, unsafe=True)


def check_config(data: bytes) -> None:
    from zero.engine.config import parse_config

    try:
        cfg = parse_config(Path("/project/zero.toml"), data.decode("utf-8", "replace"))
    except ZeroError:
        return
    if cfg is not None:
        for name in ("a.lis", "old/b.lis", "machines/m1/listen/nullp_1.lis", "x" * 200 + ".lis"):
            cfg.excluded(Path("/project") / name)
            cfg.included(Path("/project") / name)
            codec = cfg.encoding_for(Path("/project") / name)
            if codec is not None:  # a declared code page reads and writes back any bytes
                assert document_bytes(tokenize(data, name, codec)) == data


def check_machine(data: bytes) -> None:
    """Up to eight files split at NUL bytes: the first is the start-up list, the others are the
    lists `./l1.lis` … `./l7.lis`; anything else a reference names does not exist."""
    from zero.engine.lint import lint_machine

    parts = data.split(b"\0")[:8]
    root = Path("/nonexistent-zero-fuzz/m")
    files = {root / "hochlauf.lis": parts[0], **{root / f"l{i}.lis": p for i, p in enumerate(parts[1:], 1)}}

    def reader(path: Path) -> bytes:
        got = files.get(Path(os.path.normpath(path)))
        if got is None:
            raise ZeroError("no such file", str(path))
        return got

    try:
        machine = load_machine(root / "hochlauf.lis", REGISTRY, reader=reader, workdir=root)
    except ZeroError:  # a start-up list zero refuses (XML not well-formed, too many entries): said, located
        return
    for r in lint_machine(machine, REGISTRY):
        for d in r.diagnostics:
            assert d.span.line >= 1, d


def check_transport(data: bytes) -> None:
    import io
    import json
    import logging

    from zero.server.lsp import FramedInput

    logging.getLogger("zero.server").setLevel(logging.ERROR)  # each refusal is said on stderr: not here
    replies: list[bytes] = []
    framed = FramedInput(io.BufferedReader(io.BytesIO(data)), replies.append)  # type: ignore[arg-type]
    while True:
        header = framed.readline()
        if not header:
            break
        assert header.startswith(b"Content-Length: "), header
        length = int(header[len(b"Content-Length: "):].strip())
        assert framed.readline() == b"\r\n"
        body = framed.read(length)
        assert len(body) == length
        json.loads(body.decode("utf-8", "surrogatepass"))
    for reply in replies:
        assert reply.startswith(b"Content-Length: ")


_REPOSITORY: list[Path] = []
_SAFE_NAME = bytes(range(ord("a"), ord("z") + 1)) + b"0123456789_-.[]*!?# "


def check_repository(data: bytes) -> None:
    """A git repository from the data, split at NUL bytes: ``.gitignore``, ``.git/info/exclude``,
    ``zero.toml``, then one file name a line (letters, digits and a few pattern characters, in
    folders; each file a small list). The walk ``zero lint DIR`` does (its ignore rules and the
    configuration's exclude) finds only regular files inside the repository, each a file it
    created, in bounded time; a refusal is a ZeroError."""
    import shutil
    import subprocess
    import tempfile

    from zero.engine.config import parse_config
    from zero.engine.discovery import collect_files

    if not _REPOSITORY:
        root = Path(tempfile.mkdtemp(prefix="zero-fuzz-repo-"))
        subprocess.run(["git", "init", "-q", str(root)], check=True, capture_output=True, timeout=30)
        _REPOSITORY.append(root)
    root = _REPOSITORY[0]
    for child in root.iterdir():
        if child.name != ".git":
            shutil.rmtree(child) if child.is_dir() and not child.is_symlink() else child.unlink()
    parts = data.split(b"\0")[:4] + [b""] * 4
    (root / ".gitignore").write_bytes(parts[0])
    (root / ".git" / "info").mkdir(parents=True, exist_ok=True)
    (root / ".git" / "info" / "exclude").write_bytes(parts[1])
    (root / "zero.toml").write_bytes(parts[2])
    made: set[str] = set()  # collect_files names files by their text, as a Path prints it
    for raw in parts[3].split(b"\n")[:40]:
        name = bytes(c for c in raw if c in _SAFE_NAME or c == ord("/")).decode("ascii").strip("/ ")
        if not name or any(seg in ("", ".", "..", ".git") for seg in name.split("/")):
            continue
        path = root / f"{name}.lis"
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(b"kanal_anzahl 1\n")
        except OSError:  # a name that is a folder already, or too long
            continue
        made.add(str(path))
    exclude = None
    try:
        cfg = parse_config(root / "zero.toml", parts[2].decode("utf-8", "replace"))
        exclude = cfg.excluded if cfg is not None else None
    except ZeroError:
        pass
    found = collect_files([root], exclude=exclude, note=lambda _text: None)
    for name in found:
        f = Path(name)
        assert name in made or f.suffix != ".lis", (name, made)
        assert f.is_file() and not f.is_symlink() and f.resolve().is_relative_to(root.resolve()), name


_XML_HEAD = b'<?xml version="1.0" encoding="utf-8"?>\n'


def check_xml(data: bytes) -> None:
    """An XML list from the data (wrapped in a root element when it has none): its findings lie
    inside the file, and where it converts, XML → list → XML gives its bytes back; then the data
    as a TwinCAT export's axis list: findings inside the file, a fix that changes only the CDATA."""
    from zero.engine.lint import lint_data

    xml = data if data.lstrip().startswith(b"<") else _XML_HEAD + b"<AX_MDS>\n" + data + b"\n</AX_MDS>\n"
    lines = xml.count(b"\n") + 1
    result = lint_data(xml, "fuzz.xml", REGISTRY)
    assert all(1 <= d.span.line <= lines for d in result.diagnostics), result.diagnostics
    mixed = b"\r\n" in xml and b"\n" in xml.replace(b"\r\n", b"")  # written back with one ending (a note says so)
    if xml_form(xml) == "xml" and not mixed:  # an XML list (a TwinCAT export converts to the list it holds)
        try:
            as_list = convert(xml, "xml", "lis", REGISTRY, "fuzz.xml", check=False).output
            back = convert(as_list, "lis", "xml", REGISTRY, "fuzz.lis", check=False).output
        except ZeroError:
            pass
        else:
            assert back == xml, (xml, as_list, back)
    if b"]]>" in data:
        return
    export = _XML_HEAD + b"<TreeItem>\n<ItemName>X</ItemName>\n<IsgAxisDef>\n<AchsMds><![CDATA[" + data + \
        b"]]></AchsMds>\n</IsgAxisDef>\n</TreeItem>\n"
    result = lint_data(export, "fuzz_export.xml", REGISTRY)
    total = export.count(b"\n") + 1
    assert all(1 <= d.span.line <= total for d in result.diagnostics), result.diagnostics
    fixed = fix_bytes(export, "fuzz_export.xml", REGISTRY).fixed
    head, tail = export.split(b"<![CDATA[", 1)[0], export.rsplit(b"]]>", 1)[1]
    assert fixed.startswith(head) and fixed.endswith(tail), (export, fixed)


def one_input(raw: bytes) -> None:
    if not raw:
        return
    target, data = (raw[0] - 0xF0 if raw[0] in (0xF9, 0xFA, 0xFB, 0xFC, 0xFD) else raw[0] % 9), raw[1:]
    try:
        TARGETS[target](data)
    except ZeroError as exc:  # a refusal: located, never a crash (the command line says it, exit 2)
        assert exc.message, exc


TARGETS = {
    0: check_lint, 1: check_round_trip, 2: lambda d: check_reader("yaml", d), 3: lambda d: check_reader("toml", d),
    4: lambda d: check_reader("json", d), 5: check_diff, 6: check_program, 7: check_format, 8: check_fix,
    9: check_config, 10: check_machine, 11: check_transport, 12: check_xml, 13: check_repository,
}
