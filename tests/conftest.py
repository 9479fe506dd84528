"""Shared test helpers: the corpus location, the built-in registry and small lint shortcuts.

The tree under tests/ mirrors the packages of src/zero (tests/lists, tests/catalog, ...);
cross-cutting suites stay at the top. The directories have no ``__init__.py``: pytest's
default (prepend) import mode puts each test directory on ``sys.path``, so test file
basenames are unique across the tree and ``from conftest import ...`` works everywhere.
"""

from __future__ import annotations

import copy
import functools
import importlib.util
import json
import os
import pickle
import resource
import shlex
import subprocess
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

import pytest
from hypothesis import strategies as st

from zero.catalog.registry import Registry, load_registry
from zero.catalog.values import Resolved, bind, read_value
from zero.engine.lint import LintOptions, LintResult, lint_bytes
from zero.lists.model import Document

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures"


@functools.cache
def builtin_registry() -> Registry:
    """The built-in registry, loaded once per process (for helpers outside fixtures)."""
    return load_registry()


@pytest.fixture(scope="session")
def registry() -> Registry:
    """The built-in registry, shared by the whole session."""
    return builtin_registry()


def corpus_dir() -> Path:
    env = os.environ.get("ZERO_CORPUS")
    return Path(env) if env else ROOT.parent / "shared" / "corpus"


@pytest.fixture(scope="session")
def corpus() -> Path:
    """The real-world corpus; skipped where absent, a failure in CI (CI=true)."""
    path = corpus_dir()
    if not (path / "isg-sdk" / "listen").is_dir():
        reason = f"corpus not found at {path} (set ZERO_CORPUS)"
        if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
            pytest.fail(f"CI must run the corpus tests: {reason}")
        pytest.skip(reason)
    return path


def count_lints(monkeypatch: pytest.MonkeyPatch, seen: Callable[[str], None]) -> None:
    """Call ``seen`` with the path of every file :mod:`zero.engine.parallel` really lints: from its path
    (``lint_file``), or from the bytes it read to tell a run's twins apart (``lint_data``); a twin that
    shares another's result is not linted."""
    import zero.engine.parallel as parallel
    from zero.engine.lint import lint_data, lint_file

    def by_path(path: str | Path, registry: Registry, options: LintOptions | None = None) -> LintResult:
        seen(str(path))
        return lint_file(path, registry, options)

    def by_data(data: bytes, path: str, registry: Registry, options: LintOptions | None = None) -> LintResult:
        seen(path)
        return lint_data(data, path, registry, options)

    monkeypatch.setattr(parallel, "lint_file", by_path)
    monkeypatch.setattr(parallel, "lint_data", by_data)


def bound_one_by_one(doc: Document, registry: Registry, kind: str | None) -> list[Resolved]:
    """Every entry the controller reads, bound on its own: the per-entry reference the value model's
    passes per pattern and value are held to."""
    out = []
    for e in doc.entries:
        if e.key is None or e.value_kind is None:
            continue
        hit = bind(registry, e.key.pattern, kind)
        if hit is not None:
            out.append(Resolved(e, hit[0], read_value(hit[0], e), hit[1]))
    return out


def script_module(path: Path) -> ModuleType:
    """A script of the repository (a generator in ``tools/``, ``docs/gen_pages.py``) imported as a module,
    to test what it writes against what is committed."""
    spec = importlib.util.spec_from_file_location(path.stem, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def lint_text(text: str | bytes, path: str = "t.lis", **options: object) -> LintResult:
    data = text.encode("utf-8") if isinstance(text, str) else text
    return lint_bytes(data, builtin_registry(), path, options=LintOptions(**options))  # type: ignore[arg-type]


def codes(result: LintResult) -> list[str]:
    return [d.code for d in result.diagnostics]


def findings(result: LintResult) -> list[dict[str, object]]:
    """The golden form of findings: location, code and severity."""
    keep = ("line", "column", "end_line", "end_column", "code", "severity")
    return [{k: d.to_json()[k] for k in keep} for d in result.diagnostics]


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-golden", action="store_true",
                     help="rewrite the expected findings of the golden fixtures")


def golden(path: Path, actual: object, update: bool) -> object:
    if update:
        path.write_text(json.dumps(actual, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    return json.loads(path.read_text(encoding="utf-8"))


# --------------------------------------------------------------- generated list files
# (hypothesis strategy shared by tests/test_properties.py and tests/engine/test_fix.py)

_KEYS = st.one_of(
    st.builds("np_grp[{}].achse[{}].versch".format, st.integers(0, 96), st.integers(0, 31)),
    st.builds("np_grp[{}].achse[{}].inaktiv".format, st.integers(0, 96), st.integers(0, 31)),
    st.sampled_from(["kenngr.swe_pos", "kenngr.achs_mode", "g53_verfuegbar", "default_index",
                     "lr_param.kv", "a", "a.b"]),
    st.builds("wz[{}].name".format, st.integers(1, 10**30)),
    st.builds("getriebe[{}].dynamik.vb_max".format, st.integers(0, 4_000_000_000)),
)
_VALUES = st.one_of(
    st.integers(-(2**31), 2**32 - 1).map(str),
    st.sampled_from(["-2147483648", "4294967295", "0", "-0", "010", "+7", "0x400001", "0X1f", "1.5",
                     "1e3", "1.50", "TRUE", "FALSE", "ERROR", "on", "no", "yes", "null", "~",
                     "PLC_INFO | MOS", "REPORT | REPORT_EXTENDED |PRINT", "P-AXIS-00212.0",
                     "P-AXIS-00376", '"text with ( # spaces"', '"a:b"', "X_Achse",
                     "./listen/achsmds1.lis", "20804,20805", "cnc_ve_%s_[%d]_r", "µm", "'q'"]),
)
_COMMENTS = st.one_of(
    st.none(),
    st.sampled_from(["# hash note", "#", "( P-ZERO-00003 : offset", "( unclosed ( nested)",
                     "/* 20 */ ( second", "plain words", "( with # and \"quotes\" : colon",
                     "( Maße in µm", "#x 5"]),
)
_GAP = st.sampled_from([" ", "  ", "\t", " \t ", "      "])
_FULL_LINES = st.sampled_from(["# comment", "#", "#\ttab", "#key 5", "#np_grp[0].achse[0].versch 1",
                               "", "\t", "   ", "  # indented", "# ä µ €"])


@st.composite
def generated_lists(draw: st.DrawFn) -> bytes:
    """Whole list files: entries, comments, blanks, Ende, both line endings, two encodings."""
    canonical = draw(st.booleans())
    lines: list[str] = []
    for _ in range(draw(st.integers(0, 25))):
        for _ in range(draw(st.integers(0, 2))):
            lines.append(draw(_FULL_LINES))
        key, value, comment = draw(_KEYS), draw(_VALUES), draw(_COMMENTS)
        if canonical:
            from zero.structured.tree import canonical_line

            lines.append(canonical_line(key, value, comment, 54, 70))
        else:
            line = key + draw(_GAP) + value
            if comment is not None:
                line += draw(_GAP) + comment
            lines.append(line + draw(st.sampled_from(["", " ", "\t"])))
    lines.extend(draw(st.lists(_FULL_LINES, max_size=2)))
    end = draw(st.sampled_from(["Ende", "Ende  ", None]))
    if end is not None:
        lines.append(end)
        lines.extend(draw(st.lists(st.sampled_from(["", " "]), max_size=2)))
    newline = draw(st.sampled_from(["\n", "\r\n"]))
    text = newline.join(lines) + (newline if bool(lines) and draw(st.booleans()) else "")
    encoding = draw(st.sampled_from(["utf-8", "cp1252"]))
    return text.encode(encoding)


MiB = 1024 * 1024


@dataclass(frozen=True)
class Run:
    code: int
    out: bytes
    err: bytes
    seconds: float

    @property
    def stdout(self) -> str:
        return self.out.decode("utf-8", "replace")

    @property
    def stderr(self) -> str:
        return self.err.decode("utf-8", "replace")


def zero_cli(*args: str, cwd: Path | None = None, stdin: bytes | None = None, timeout: float = 60.0,
             memory_mib: int = 1024, env: dict[str, str] | None = None, prefix: tuple[str, ...] = ()) -> Run:
    """The real ``zero`` command line in a child process, capped in address space and time.

    Asserts what every run must give: an exit code zero documents and no traceback.
    ``prefix`` runs it under another program (``capsh --drop=…``)."""
    limit = memory_mib * MiB

    def cap() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    command = [sys.executable, "-m", "zero", *args]
    if prefix:
        command = [*prefix, " ".join(shlex.quote(c) for c in command)]
    t0 = time.perf_counter()
    proc = subprocess.run(command, cwd=cwd, input=stdin if stdin is not None else b"", capture_output=True,
                          timeout=timeout, preexec_fn=cap, env={**os.environ, **(env or {})}, check=False)
    run = Run(proc.returncode, proc.stdout, proc.stderr, time.perf_counter() - t0)
    assert run.code in (0, 1, 2, 130, 141, 143), run
    assert b"Traceback" not in proc.stderr, run.stderr
    return run


_MODULES_SCRIPT = """
import sys
import zero.cli.lean as lean

def end(code):
    probe = {probe}
    sys.stdout.write("\\nMODULES " + " ".join(sorted(sys.modules)) + "\\nPROBE " + repr(probe) + "\\n")
    sys.stdout.flush()
    raise SystemExit(code)

lean.end = end
sys.argv = ["zero", *sys.argv[1:]]
lean.main()
"""


def zero_modules(*args: str, cwd: Path, env: dict[str, str], probe: str = "None") -> tuple[str, set[str], str]:
    """The console script's ``zero ARGS`` in a fresh interpreter, as a pre-commit hook starts it: its report,
    the modules loaded when it ends, and ``repr`` of the expression ``probe`` evaluated then (issue 40:
    what a command leaves unloaded). ``env`` is the child's whole environment."""
    out = subprocess.run([sys.executable, "-c", _MODULES_SCRIPT.format(probe=probe), *args], cwd=cwd, env=env,
                         capture_output=True, text=True, timeout=120, check=False)
    assert "\nMODULES " in out.stdout and out.returncode in (0, 1), out.stderr
    report, _, tail = out.stdout.rpartition("\nMODULES ")
    modules, _, probed = tail.partition("\nPROBE ")
    return report, set(modules.split()), probed.strip()


def assert_stays_itself(member: object) -> None:
    """A member of one of zero's enumerations (Severity, ValueKind, ...) is itself after pickling with every
    protocol, a copy and a deep copy: compared by identity, as an enum's member is."""
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        assert pickle.loads(pickle.dumps(member, protocol)) is member
    assert copy.copy(member) is member
    assert copy.deepcopy({"m": [member]})["m"][0] is member
