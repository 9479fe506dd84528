"""Hostile input: a finding or exit 2, never a traceback, in bounded time and memory."""

from __future__ import annotations

import io
import json
import os
import random
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from conftest import lint_text
from zero.catalog.registry import Registry
from zero.cli.app import app
from zero.engine.lint import LintResult
from zero.output.text import render_text

MiB = 1024 * 1024


def _bounded(data: bytes, seconds: float = 60.0, memory_mib: int = 1024) -> LintResult:
    """Lint in a child process capped at ``memory_mib`` of address space and ``seconds``.

    The child runs the real CLI (JSON output), so this also proves: no traceback, exit 1
    or 0 with findings, or 2 with a one-line message. The parent re-lints in-process
    (uncapped) to hand the result to the assertions.
    """
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "hostile.lis"
        path.write_bytes(data)
        limit = memory_mib * MiB

        def cap() -> None:
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

        t0 = time.perf_counter()
        proc = subprocess.run(
            [sys.executable, "-m", "zero", "lint", "--output-format", "json", str(path)],
            capture_output=True, timeout=seconds, preexec_fn=cap, check=False,
        )
        elapsed = time.perf_counter() - t0
    assert proc.returncode in (0, 1, 2), proc.stderr[-2000:]
    assert b"Traceback" not in proc.stderr
    assert elapsed < seconds
    if proc.returncode != 2:
        json.loads(proc.stdout)
    result = lint_text(data)
    render_text([result], io.StringIO(), color=False)
    for d in result.diagnostics:  # every span lies inside the file
        assert 1 <= d.span.line <= max(1, len(result.document.lines))
    return result


@pytest.mark.slow
def test_random_binary() -> None:
    rng = random.Random(1234)
    data = bytes(rng.randrange(256) for _ in range(200_000))
    result = _bounded(data)
    assert result.diagnostics  # something is reported


@pytest.mark.slow
def test_nul_bytes_everywhere() -> None:
    result = _bounded(b"\x00" * 100_000 + b"\nk\x00 1\n")
    assert [d.code for d in result.diagnostics] == ["S013"]  # one root cause, one finding


def test_utf16_file() -> None:
    result = _bounded("np_grp[1].achse[0].versch 5\n".encode("utf-16"))
    assert [d.code for d in result.diagnostics] == ["S013"]


def test_a_nul_ends_the_line_as_the_controller_reads_it() -> None:
    """`1<NUL>` is the value 1 (one S008 for the NUL), not a faulty BOOLEAN."""
    result = lint_text(b"g53_verfuegbar 1\x00junk\nnp_grp[0].achse[0].versch 5\nEnde\n")
    assert [d.code for d in result.diagnostics] == ["S008"]


@pytest.mark.slow
def test_ten_megabyte_line() -> None:
    line = b"np_grp[1].achse[0].versch 5 ( " + b"x" * (10 * MiB) + b"\n"
    result = _bounded(line, memory_mib=768)
    assert result.diagnostics == []
    result = _bounded(b"a" * (10 * MiB) + b" 1\n", memory_mib=768)
    assert [d.code for d in result.diagnostics] == ["R001"]
    out = io.StringIO()
    render_text([result], out, color=False)
    assert max(len(x) for x in out.getvalue().splitlines()) < 400  # the source is cut


@pytest.mark.parametrize("digits", [20, 30, 5000])
def test_huge_indices(digits: int) -> None:
    result = _bounded(f"np_grp[{'9' * digits}].achse[0].versch 1\n".encode())
    assert [d.code for d in result.diagnostics] == ["R003"]


@pytest.mark.slow
def test_huge_values() -> None:
    result = _bounded(f"g53_verfuegbar {'9' * 5000}\n".encode())
    assert [d.code for d in result.diagnostics] == ["R005"]
    result = _bounded(f"np_grp[1].achse[0].versch -{'9' * 100}\n".encode())
    assert [d.code for d in result.diagnostics] == ["R004"]


def test_twenty_thousand_nested_members() -> None:
    key = ".".join(["a"] * 20_000)
    result = _bounded(f"{key} 1\n{key}[1] 2\n".encode())
    assert [d.code for d in result.diagnostics] == ["R001", "R001"]


@pytest.mark.slow
def test_unterminated_quote_and_empty_file() -> None:
    assert [d.code for d in _bounded(b'kopf.log_achs_name "abc\n').diagnostics] == ["S003"]
    assert _bounded(b"").diagnostics == []
    assert _bounded(b"\n\n\n").diagnostics == []


@pytest.mark.slow
def test_many_lines() -> None:
    data = b"".join(b"np_grp[%d].achse[%d].versch %d\n" % (i % 97, i % 32, i) for i in range(100_000))
    result = _bounded(data)
    # duplicates (the later value wins) and group-0 offsets without g53_verfuegbar
    assert {d.code for d in result.diagnostics} == {"R007", "M002"}


def test_cli_on_binary_file(tmp_path: Path) -> None:
    f = tmp_path / "junk.lis"
    f.write_bytes(bytes(range(256)) * 50)
    result = CliRunner().invoke(app, ["lint", "--output-format", "json", str(f)])
    assert result.exit_code in (1, 2)
    assert "Traceback" not in result.output
    json.loads(result.output)


# ------------------------------------------------------- structured inputs (convert, lint, diff)


def _run_capped(args: list[str], data: bytes, name: str, seconds: float = 60.0,
                memory_mib: int = 1024) -> subprocess.CompletedProcess[bytes]:
    """Run the real CLI on ``data`` saved as ``name`` with capped memory and time."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / name
        path.write_bytes(data)
        limit = memory_mib * MiB

        def cap() -> None:
            resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

        t0 = time.perf_counter()
        proc = subprocess.run([sys.executable, "-m", "zero", *args, str(path)], capture_output=True,
                              timeout=seconds, preexec_fn=cap, check=False)
        assert time.perf_counter() - t0 < seconds
    assert b"Traceback" not in proc.stderr, proc.stderr[-2000:]
    return proc


def _billion_laughs() -> bytes:
    text = 'a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]\n'
    for i in range(1, 10):
        prev, cur = chr(ord("a") + i - 1), chr(ord("a") + i)
        text += f"{cur}: &{cur} [" + ",".join([f"*{prev}"] * 9) + "]\n"
    return text.encode()


HOSTILE_STRUCTURED = {
    "billion-laughs.yaml": (_billion_laughs(), "anchor", 1),
    "python-tag.yaml": (b"a: !!python/object/apply:os.system ['echo pwned']\n", "tag", 1),
    "deep.yaml": (b"a: " + b"{b: " * 10_000 + b"1" + b"}" * 10_000 + b"\n", "nested deeper", 1),
    "deep-sequences.yaml": (b"a: " + b"[" * 10_000 + b"]" * 10_000 + b"\n", "sequence", 1),
    "deep.toml": (b"a = " + b"[" * 10_000 + b"]" * 10_000 + b"\n", "nested too deeply", None),
    "deep.json": (b'{"a": ' + b"[" * 10_000 + b"]" * 10_000 + b"}", "nested too deeply", None),
    "deep-objects.json": (b'{"a": ' + b'{"b": ' * 10_000 + b"1" + b"}" * 10_001, "nested", None),
    "binary.yaml": (bytes(random.Random(7).randrange(256) for _ in range(100_000)), "", None),
    "not-utf8.toml": (b"a = 1\nb = \"\xb5m\"\n", "not UTF-8", 2),
    "duplicate.yaml": (b"np_grp:\n  1: {achse: {0: {versch: 1}}}\n  1: {achse: {0: {versch: 2}}}\n",
                       "duplicate key", 3),
}


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(HOSTILE_STRUCTURED))
@pytest.mark.parametrize("command", [["convert", "--to", "lis"], ["lint"], ["diff", "--defaults"]])
def test_hostile_structured_input_is_refused_with_its_location(name: str, command: list[str]) -> None:
    data, words, line = HOSTILE_STRUCTURED[name]
    proc = _run_capped(command, data, name, memory_mib=512)
    assert proc.returncode in (1, 2)
    if command == ["lint"]:  # one S017 finding where the reader stopped, and the run goes on (issue 27)
        out = proc.stdout.decode("utf-8", "replace")
        assert proc.returncode == 1 and " S017 " in out and words in out, out
        assert f"{name}:{line if line is not None else ''}" in out
        assert b"Traceback" not in proc.stderr
        return
    err = proc.stderr.decode("utf-8", "replace")
    assert err.count("\n") <= 3 and err.startswith("zero: ")
    assert name in err
    assert words in err
    if line is not None:
        assert f"{name}:{line}:" in err
    assert proc.stdout == b""


@pytest.mark.slow
def test_two_gigabyte_sparse_index_in_yaml_is_cheap() -> None:
    text = b"np_grp:\n  2000000000:\n    achse:\n      0:\n        versch: 1\n"
    proc = _run_capped(["convert", "--to", "lis"], text, "sparse.yaml", seconds=30, memory_mib=256)
    assert proc.returncode == 0
    assert proc.stdout.startswith(b"np_grp[2000000000].achse[0].versch")
    lint = _run_capped(["lint"], text, "sparse.yaml", seconds=30, memory_mib=256)
    assert lint.returncode == 1 and b"R003" in lint.stdout


@pytest.mark.slow
def test_invalid_utf8_inside_keys_is_located() -> None:
    result = _bounded(b"np_grp[1].ach\xffse[0].versch 5\nkenngr.\xc3\x28x 1\n")
    assert [(d.code, d.span.line) for d in result.diagnostics] == [("S001", 1), ("S001", 2)]
    proc = _run_capped(["convert", "--to", "yaml"], b"np_grp[1].ach\xffse[0].versch 5\n", "k.lis")
    assert proc.returncode == 1 and b"k.lis:1:1: not an entry" in proc.stderr


# --------------------------------------------------------------------------- issue 43: bounded time, no internal error

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "fuzz"))
from regex_timing import growth  # noqa: E402  (the timing fuzzer's own comparison of two sizes)


def test_root_of_grows_linearly_with_comments() -> None:
    """`forms.root_of` over a run of comments: a lazy comment inside a repetition backtracked
    exponentially (28 comments: 86 s). Sizes compared, not a time: 12 → 20 comments took 250 times
    as long before; 1,000 → 4,000 comments now take about 4 times as long."""
    from zero.forms import root_of, xml_form

    assert growth(root_of, lambda n: b"<!--a-->" * n, 12, 20) < 8
    assert growth(root_of, lambda n: b"<!--a-->" * n + b"<-", 1000, 4000) < 10
    assert root_of(b"<?xml version='1.0'?>\n<!-- a --><!-- b -->\n<AX_MDS>") == "AX_MDS"
    assert root_of(b"<!-- a --> <!-- b --x> -->") is None
    assert xml_form(b"<!-- a -- > --><?pi x?><AX_MDS/>") == "xml"


def test_guard_toml_grows_linearly_with_a_run_of_letters() -> None:
    """`guard_toml` (every TOML form and configuration, the language server too): a run of
    letters was quadratic (80 KB: 31-52 s; 2,000 → 8,000 letters 16 times as long)."""
    from zero.errors import ZeroError
    from zero.structured.toml import guard_toml

    assert growth(guard_toml, lambda n: "a" * n, 2000, 8000) < 10  # quadratic: 16
    assert growth(guard_toml, lambda n: ("a." * 63 + "!") * n, 200, 800) < 10
    assert growth(guard_toml, lambda n: '"' + "a" * n, 100_000, 400_000) < 10
    guard_toml("x = " + ".".join(["k"] * 64))  # 64 parts: read
    with pytest.raises(ZeroError, match="more than 64 dotted parts") as got:
        guard_toml("x = 1\ny = 2\nz." + '"a.b"' + ". c ." + ".".join(["k"] * 62) + " = 1")
    assert (got.value.line, got.value.column) == (3, 1)


@pytest.mark.parametrize("command", [["lint"], ["show"], ["format", "--diff"], ["convert", "--to", "yaml"]])
def test_commands_on_an_xml_file_of_many_comments_answer_at_once(tmp_path: Path, command: list[str]) -> None:
    """Every command sniffs an XML file's root element: 40 comments (hours before) answer in seconds."""
    path = tmp_path / "c.xml"
    path.write_bytes(b"<!--a-->" * 40 + b"\n")
    proc = subprocess.run([sys.executable, "-m", "zero", *command, str(path)], capture_output=True,
                          timeout=60, check=False)
    assert b"Traceback" not in proc.stderr and b"internal error" not in proc.stderr


@pytest.mark.parametrize("name", ["f.toml", "zero.toml"])
def test_toml_form_and_configuration_with_a_run_of_letters_answer_at_once(tmp_path: Path, name: str) -> None:
    path = tmp_path / name
    path.write_text("a" * 80_000 + "\n", encoding="utf-8")
    target = tmp_path / ("f.toml" if name == "f.toml" else "x.lis")
    if name == "zero.toml":
        target.write_bytes(b"kanal_anzahl 1\n")
    proc = subprocess.run([sys.executable, "-m", "zero", "lint", str(target)], capture_output=True,
                          timeout=30, cwd=tmp_path, check=False)
    assert proc.returncode in (1, 2), proc.stderr
    assert b"Traceback" not in proc.stderr and b"internal error" not in proc.stderr


_DIGITS = "1" * 4400  # beyond Python's int conversion limit (4,300 digits)
_HUGE_INDEX_FORMS = {
    "idx.lis": f"getriebe[{_DIGITS}].dynamik.a_max 1\nkopf.achs_mode P-AXIS-00001.{_DIGITS}\n",
    "idx.xml": f'<?xml version="1.0"?>\n<AX_MDS>\n<P-AXIS-00008.{_DIGITS} Value="1" />\n'
               f'<P-AXIS-00001 Value="P-AXIS-00008.{_DIGITS}" />\n</AX_MDS>\n',
    "idx.yaml": f"getriebe:\n  {_DIGITS}:\n    dynamik:\n      a_max: 1\n",
    "idx.json": f'{{"getriebe": {{"{_DIGITS}": {{"dynamik": {{"a_max": 1}}}}}}}}',
    "idx.toml": f'[getriebe.{_DIGITS}.dynamik]\na_max = 1\n',
}


@pytest.mark.parametrize("name", sorted(_HUGE_INDEX_FORMS))
def test_an_index_of_4400_digits_is_a_finding_in_every_form(registry: Registry, name: str) -> None:
    """An index (of a key, an XML element or a reference) beyond Python's int limit: a finding, never
    `internal error: ValueError`, in lint and --fix, in every form."""
    from zero.engine.fixes import fix_bytes
    from zero.engine.lint import lint_data

    data = _HUGE_INDEX_FORMS[name].encode()
    result = lint_data(data, name, registry)
    assert result.diagnostics
    assert all(1 <= d.span.line <= data.count(b"\n") + 1 for d in result.diagnostics)
    fix_bytes(data, name, registry, unsafe=True)


@pytest.mark.parametrize("value", ["0x" + "F" * 260, "9" * 401, "-" + "9" * 401, "1e400", "9" * 401 + ".5"])
@pytest.mark.parametrize("name", ["achsmds1.lis", "sda_mds1.lis", "wzd1.lis"])
def test_a_number_beyond_a_double_is_a_finding_for_every_parameter(registry: Registry, name: str,
                                                                   value: str) -> None:
    """Every parameter of a list kind set to a number no double holds (`a_max 0x` + 260 `F`, a
    401-digit `vb_max`): lint and --fix find it (R004 for a REAL64), never `OverflowError` from the
    ranges, conditions and start-up checks that compute with it."""
    from zero.engine.fixes import fix_bytes
    from zero.engine.lint import lint_data

    kind = {"achsmds1.lis": "AXIS", "sda_mds1.lis": "CHAN", "wzd1.lis": "TOOL"}[name]
    specs = [s for s in registry.specs.values() if s.key and s.kind == kind]
    data = "".join(f"{s.key.replace('[]', '[0]')} {value}\n" for s in specs).encode()
    result = lint_data(data, name, registry)
    reals = {i + 1 for i, s in enumerate(specs) if s.type == "REAL64"}
    flagged = {d.span.line for d in result.diagnostics if d.code == "R004"}
    assert reals <= flagged
    fix_bytes(data, name, registry, unsafe=True)


def test_an_xml_list_with_cr_only_line_breaks_places_s014_on_its_one_line(registry: Registry) -> None:
    """Expat counts a lone CR as a line break, zero (and the controller's list reader) does not:
    S014 was placed on line 5 of a one-line file."""
    from zero.engine.lint import lint_data

    for data, where in [
        (b'<?xml version="1.0"?>\r<AX_MDS>\r<P-AXIS-00001 Value="1" />\r<bad\r</AX_MDS>\r', (1, 64)),
        ('<?xml version="1.0"?>\r<AX_MDS>\u00c4\u00d6\u00dc\r&</AX_MDS>\n'.encode(), (1, 36)),
        (b"<a>\r\n\r<b", (2, 2)),
        (b'<?xml version="1.0"?>\n<AX_MDS>\n<bad\n</AX_MDS>\n', (4, 1)),
    ]:
        result = lint_data(data, "cr.xml", registry)
        assert [(d.code, d.span.line, d.span.column) for d in result.diagnostics] == [("S014", *where)], data


def _machine_of_one_list(folder: Path, entries: int, references: int = 64) -> Path:
    """A start-up list naming one axis list (of ``entries`` entries) as all ``references`` axes."""
    body = "".join(f"getriebe[0].dynamik.a_max {i % 900 + 1}\n" if i % 2 else f"# {i}\n" for i in range(2 * entries))
    (folder / "big.lis").write_text("kopf.achs_nr 1\n" + body + "Ende\n", encoding="utf-8")
    startup = folder / "hochlauf.lis"
    startup.write_text(f"zahl_mds {references}\n" + "".join(f"achs_mds[{i}] ./big.lis\n" for i in range(references))
                       + "Ende\n", encoding="utf-8")
    return startup


def test_a_list_named_64_times_is_read_and_interpreted_once(registry: Registry, tmp_path: Path,
                                                            monkeypatch: pytest.MonkeyPatch) -> None:
    """`zahl_mds 64` with every reference to one list: its bytes read once and its values built
    once per machine (built per reference: 0.7 s and a copy of every entry each; a million lines
    needed 7 GB). Steps counted, not time."""
    from zero.catalog.values import ListValues
    from zero.machine.model import load_machine

    startup = _machine_of_one_list(tmp_path, 200)
    built, reads = [], []
    original = ListValues.of.__func__  # type: ignore[attr-defined]

    def counting(cls: type[ListValues], *args: object, **kwargs: object) -> ListValues:
        built.append(args[0])
        return original(cls, *args, **kwargs)  # type: ignore[no-any-return]

    def reader(path: Path) -> bytes:
        reads.append(path)
        return path.read_bytes()

    monkeypatch.setattr(ListValues, "of", classmethod(counting))
    machine = load_machine(startup, registry, reader=reader)
    assert len(machine.axis_lists) == 64
    assert len(reads) == 2 and len(built) == 2  # the start-up list and the axis list, once each


@pytest.mark.parametrize("command", [["lint", "--machine", "hochlauf.lis", "big.lis"],
                                     ["show", "--machine", "hochlauf.lis"],
                                     ["explain", "--machine", "hochlauf.lis", "P-AXIS-00008"],
                                     ["diff", "--machine", "hochlauf.lis", "hochlauf.lis"],
                                     ["limits", "--machine", "hochlauf.lis"],
                                     ["report", "--machine", "hochlauf.lis", "-o", "r.html"]])
def test_a_machine_beyond_the_entry_bound_is_refused_where_the_start_up_list_crosses_it(
        tmp_path: Path, command: list[str]) -> None:
    """64 references to a list of 8,000 entries (512,000 for the machine, over its bound of 500,000):
    every machine command refuses at the reference that crosses the bound, before any rule or table
    (200,000 lines took `explain`, `diff` and `report` past 120 s; a million lines: MemoryError)."""
    from zero.machine.model import MAX_MACHINE_ENTRIES

    _machine_of_one_list(tmp_path, 8000)
    crossing = MAX_MACHINE_ENTRIES // 8000 + 1  # the reference whose entries pass the bound (+ the start-up list's)
    proc = subprocess.run([sys.executable, "-m", "zero", *command], capture_output=True, text=True, timeout=120,
                          cwd=tmp_path, check=False)
    assert proc.returncode == 2, (proc.stdout[-500:], proc.stderr[-2000:])
    assert "Traceback" not in proc.stderr and "internal error" not in proc.stderr
    assert f"hochlauf.lis:{crossing + 1}:1: `achs_mds[{crossing - 1}]` brings the machine's lists to more than " \
        f"{MAX_MACHINE_ENTRIES:,} entries" in proc.stderr, proc.stderr


def test_a_patch_grows_linearly_with_the_lines_of_a_list() -> None:
    """`zero format --diff`, `zero lint --diff`: the patch of a list whose lines repeat (blank lines,
    the same comment, the same value) was difflib's, quadratic or worse: 100 → 400 lines took 76
    times as long, a 40,000-line list 100 s. Now the common start and end, lines in place and
    anchors of unique lines; difflib only between two anchors close together."""
    from zero.engine.fixes import unified_diff

    def make(n: int) -> tuple[bytes, bytes]:
        before = b"".join(b"kopf.achs_nr    %d   \n\n" % (i % 7) for i in range(n))
        return before, b"".join(b"kopf.achs_nr %d\n\n" % (i % 7) for i in range(n)) + b"x 1\n"

    assert growth(lambda pair: unified_diff("f.lis", *pair), make, 100, 400) < 10
    assert growth(lambda pair: unified_diff("f.lis", *pair), make, 10_000, 40_000) < 10


def test_the_patterns_the_timing_fuzzer_flagged_grow_linearly() -> None:
    """Patterns fuzz/regex_timing.py found superlinear on inputs zero reads (a document of blank
    lines in the editor, a long NC line, a long number in a form), each on the input it reported."""
    from zero.nc import motion
    from zero.server import completion, documents, hover
    from zero.structured import formats

    cases = [
        (documents._ZERO_RECORD.search, lambda n: "\n" * n + "x"),
        (formats._EXPONENT_RE.fullmatch, lambda n: "0" * n + "x"),
        (motion._VALUE_START.match, lambda n: " " * n + "x"),
        (motion._SIMPLE.match, lambda n: "\n" * n + "!"),
        (motion.assigned, lambda n: "V." * n + "=1"),
        (motion._GOTO.findall, lambda n: "$GOTO[" * n),
        (completion._AXPARAM_OPEN.search, lambda n: "AXPARAM" + " " * n + "x"),
        (hover._AXPARAM.search, lambda n: "AXPARAM" + " " * n + "x"),
    ]
    for apply, make in cases:
        assert growth(apply, make, 20_000, 80_000) < 10, apply


def test_the_timing_fuzzer_finds_a_backtracking_pattern() -> None:
    """The fuzzer is no no-op: the TOML guard's pattern before issue 43 is found superlinear."""
    import random
    import re

    from regex_timing import check

    old = re.compile(r"""(?:(?:[A-Za-z0-9_-]+|"[^"\n]*"|'[^'\n]*')[ \t]*\.[ \t]*){64}""")
    assert check(old, 500, 4, 10, 0.002, random.Random(0)) is not None
    assert check(re.compile(r"[A-Za-z_][A-Za-z0-9_]*"), 500, 4, 10, 0.002, random.Random(0), "match") is None


def test_a_tree_nested_deeper_than_the_recursion_limit_is_walked(tmp_path: Path) -> None:
    """A list 1,200 folders down (deeper than Python's recursion limit, which os.walk of 3.11 recursed
    into) is found and linted: no internal error."""
    folder = tmp_path / "tree"
    folder.mkdir()
    here = str(folder)
    for _ in range(1200):
        here += "/d"
        Path(here).mkdir()
    Path(here, "a.lis").write_text("kopf.achs_nr 1\nunknown_key_here 1\nEnde\n")
    try:
        out = subprocess.run([sys.executable, "-m", "zero", "lint", "--output-format", "json", "--no-cache", "tree"],
                             cwd=tmp_path, capture_output=True, text=True, timeout=120, check=False)
    finally:  # from the bottom up: shutil.rmtree (pytest's clean-up) recurses per level too
        Path(here, "a.lis").unlink()
        while here != str(folder):
            os.rmdir(here)
            here = os.path.dirname(here)
    assert "internal error" not in out.stderr and out.returncode in (0, 1), out.stderr
    found = json.loads(out.stdout)
    assert found and all(f["path"].endswith("/d/a.lis") and f["path"].count("/d") == 1200 for f in found)
