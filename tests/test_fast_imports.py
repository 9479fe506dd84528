"""zero's own finder (``zero/__init__.py``, issue 40: start-up): zero's modules from their current cached
bytecode, exactly what Python's finders give, and Python's finders for everything else; and the bundles
(``zero.bundles``, ``zero.preload``): a command's modules run from one file, as Python's import runs them."""

from __future__ import annotations

import ast
import compileall
import json
import marshal
import os
import py_compile
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import zero
from zero.bundled_modules import COMMANDS

SRC = Path(zero.__file__).parent

# A child's view of modules: for each, what Python's import system gave it, and whether zero's finder did.
_PROBE = r"""
import importlib, json, sys
first = sys.argv[1]
if first == "--python-finders":
    import zero
    sys.meta_path[:] = [f for f in sys.meta_path if getattr(f, "__module__", None) != "zero"]
    names = sys.argv[2:]
else:
    names = sys.argv[1:]
out = {}
for name in names:
    m = importlib.import_module(name)
    spec = m.__spec__
    out[name] = {
        "file": m.__file__, "cached": getattr(m, "__cached__", None), "path": list(getattr(m, "__path__", []) or []),
        "package": m.__package__, "origin": spec.origin, "spec_cached": spec.cached, "parent": spec.parent,
        "has_location": spec.has_location, "search": list(spec.submodule_search_locations or []),
        "co_filename": next((v.__code__.co_filename for v in vars(m).values()
                             if getattr(v, "__module__", None) == name and hasattr(v, "__code__")), None),
        "source_is_file": m.__loader__.get_source(name) == open(m.__file__, encoding="utf-8").read(),
        "ours": type(m.__loader__).__module__ == "zero", "marker": getattr(m, "MARKER", None),
    }
print(json.dumps(out))
"""


def _copy(tmp: Path) -> Path:
    """zero's source in ``tmp/zero`` (no cached bytecode); the folder to put on the child's path."""
    shutil.copytree(SRC, tmp / "zero", ignore=shutil.ignore_patterns("__pycache__"))
    return tmp


def _compile(root: Path, mode: py_compile.PycInvalidationMode = py_compile.PycInvalidationMode.TIMESTAMP) -> None:
    assert compileall.compile_dir(root / "zero", quiet=2, invalidation_mode=mode, workers=1)


def _child(root: Path, *args: str, **env: str) -> subprocess.CompletedProcess[str]:
    """``python ARGS`` in a fresh interpreter on the copy in ``root`` (writing no bytecode of its own)."""
    return subprocess.run([sys.executable, *args], env={**os.environ, "PYTHONPATH": str(root),
                                                        "PYTHONDONTWRITEBYTECODE": "1", **env},
                          capture_output=True, text=True, check=False, timeout=120, cwd=root)


def _probe(root: Path, *names: str, python_finders: bool = False,
           flags: tuple[str, ...] = ()) -> dict[str, dict[str, object]]:
    args = ["--python-finders", *names] if python_finders else list(names)
    out = _child(root, *flags, "-c", _PROBE, *args)
    assert out.returncode == 0, out.stderr
    result: dict[str, dict[str, object]] = json.loads(out.stdout)
    return result


MODULES = ("zero.engine.lint", "zero.rules", "zero.catalog.data", "zero.catalog.data.table", "zero.output.formats",
           "zero.lists.tokenizer", "zero.cli.lean")


def test_the_packages_are_zeros_folders() -> None:
    folders = {str(p.parent.relative_to(SRC)).replace(os.sep, ".") for p in SRC.rglob("__init__.py")} - {"."}
    assert folders == zero.PACKAGES


def test_modules_are_what_pythons_finders_give(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    _compile(root)
    ours = _probe(root, *MODULES)
    python = _probe(root, *MODULES, python_finders=True)
    assert all(m.pop("ours") for m in ours.values())
    assert not any(m.pop("ours") for m in python.values())
    assert ours == python
    assert ours["zero.rules"]["path"] == [str(root / "zero" / "rules")]
    assert ours["zero.engine.lint"]["cached"] == str(
        root / "zero" / "engine" / "__pycache__" / f"lint.{sys.implementation.cache_tag}.pyc")


def test_a_lint_loads_every_module_through_it(tmp_path: Path) -> None:
    """With the cached bytecode current, no zero module is left to Python's finders (the package list is right)."""
    root = _copy(tmp_path)
    _compile(root)
    code = ("import sys, zero.cli.lean as lean\n"
            "def end(code):\n"
            "    print(sorted(n for n, m in sys.modules.items() if n.startswith('zero.')"
            " and type(m.__loader__).__module__ != 'zero'))\n"
            "    raise SystemExit(0)\n"
            "lean.end = end\nsys.argv = ['zero', 'lint', 'axis.lis']\nlean.main()\n")
    (root / "axis.lis").write_text("# axis\nkenngr.achs_name   X\nEnde\n", encoding="latin-1")
    out = _child(root, "-c", code, ZERO_NO_CACHE="1")
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "[]"


@pytest.mark.parametrize("change", ["content", "same size, other time"])
def test_an_edited_source_is_compiled_again(tmp_path: Path, change: str) -> None:
    root = _copy(tmp_path)
    module = root / "zero" / "engine" / "discovery.py"
    text = module.read_text(encoding="utf-8")
    module.write_text(text + "# " + "x" * 30 + "\n", encoding="utf-8")
    _compile(root)
    st = module.stat()
    if change == "content":
        module.write_text(text + "MARKER = 'edited'\n", encoding="utf-8")
    else:  # the same number of bytes, a later time: Python's loader reads it again, and so does zero's finder
        module.write_text(text + "MARKER = 'edited'  # " + "x" * 11 + "\n", encoding="utf-8")
        assert module.stat().st_size == st.st_size
        os.utime(module, (st.st_atime, st.st_mtime + 10))
    got = _probe(root, "zero.engine.discovery", "zero.engine.config")
    assert got["zero.engine.discovery"]["marker"] == "edited"
    assert got["zero.engine.discovery"]["ours"] is False
    assert got["zero.engine.config"]["ours"] is True


def test_without_cached_bytecode_pythons_finders_load(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    got = _probe(root, *MODULES)
    assert not any(m["ours"] for m in got.values())


def test_hash_based_bytecode_is_left_to_python(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    _compile(root, py_compile.PycInvalidationMode.CHECKED_HASH)
    got = _probe(root, "zero.engine.lint")
    assert got["zero.engine.lint"]["ours"] is False


def test_bytecode_of_another_python_is_left_to_python(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    _compile(root)
    cached = root / "zero" / "engine" / "__pycache__" / f"lint.{sys.implementation.cache_tag}.pyc"
    data = cached.read_bytes()
    cached.write_bytes(bytes([data[0] ^ 1]) + data[1:])  # another magic number
    got = _probe(root, "zero.engine.lint", "zero.engine.config")
    assert got["zero.engine.lint"]["ours"] is False
    assert got["zero.engine.config"]["ours"] is True


def test_optimized_runs_use_pythons_finders(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    _compile(root)
    got = _probe(root, "zero.engine.lint", flags=("-O",))
    assert got["zero.engine.lint"]["ours"] is False


def test_a_missing_module_is_still_not_found(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    _compile(root)
    for name in ("zero.nope", "zero.engine.nope", "zero.catalog.data.nope.deeper"):
        out = _child(root, "-c", f"import {name}")
        assert out.returncode == 1 and "ModuleNotFoundError" in out.stderr, out.stderr


def test_importing_zero_again_keeps_one_finder(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    _compile(root)
    code = ("import importlib, sys, zero\n"
            "importlib.reload(zero); importlib.reload(zero)\n"
            "import zero.engine.lint as m\n"
            "ours = sum(getattr(f, '__module__', None) == 'zero' for f in sys.meta_path)\n"
            "print(ours, type(m.__loader__).__module__)")
    out = _child(root, "-c", code)
    assert out.stdout.split() == ["1", "zero"], out.stderr


# --- bundles (zero.bundles, zero.preload): a command's modules from one file -----------------------------

# A child's view of every bundled module, after the bundles were run ("preload") or after Python imported
# each ("import"): what the import system leaves on a module, and the names its body made (with their types).
_BUNDLE_PROBE = r"""
import importlib, json, sys, types
import zero
from zero.bundled_modules import COMMANDS
how = sys.argv[1]
for command, names in COMMANDS.items():
    if how == "preload":
        assert zero.preload(command), command
    else:
        for name in names:
            importlib.import_module(name)
out = {"modules": sorted(n for n in sys.modules if n.startswith("zero"))}
for names in COMMANDS.values():
    for name in names:
        m = sys.modules[name]
        spec = m.__spec__
        out[name] = {
            "file": m.__file__, "cached": m.__cached__, "path": getattr(m, "__path__", None), "package": m.__package__,
            "spec": [spec.name, spec.origin, spec.cached, spec.parent, spec.has_location,
                     spec.submodule_search_locations, getattr(spec, "_initializing", "unset")],
            "loader": [type(m.__loader__).__module__, m.__loader__.name, m.__loader__.path,
                       m.__loader__ is spec.loader],
            "on_parent": getattr(sys.modules[name.rpartition(".")[0]], name.rpartition(".")[2], None) is m,
            "names": sorted((k, v.__name__ if isinstance(v, types.ModuleType) else type(v).__name__)
                            for k, v in vars(m).items() if k not in ("__spec__", "__loader__", "__builtins__")),
        }
print(json.dumps(out))
"""


def _bundle(root: Path, command: str) -> Path:
    return root / "zero" / "__pycache__" / f"bundle-{command}.{sys.implementation.cache_tag}.bin"


def _write_bundles(root: Path) -> None:
    out = _child(root, "-m", "zero.bundles", PYTHONDONTWRITEBYTECODE="")
    assert out.returncode == 0, out.stderr
    assert all(_bundle(root, command).is_file() for command in COMMANDS)


def _bundled_copy(tmp: Path) -> Path:
    """zero's source in ``tmp/zero``, compiled, with every bundle written (``python -m zero.bundles``)."""
    root = _copy(tmp)
    _compile(root)
    _write_bundles(root)
    return root


# A lint of axis.lis in the child that says, as its last line, which bundles it asked for and used.
_LINT = ("import sys, zero, zero.cli.lean as lean\n"
         "end = lean.end\n"
         "def told(code):\n"
         "    print(sorted(zero.BUNDLES_ASKED.items()))\n"
         "    end(code)\n"
         "lean.end = told\nsys.argv = ['zero', 'lint', 'axis.lis']\nlean.main()\n")


def _lint(root: Path, **env: str) -> tuple[str, dict[str, bool]]:
    if not (root / "axis.lis").exists():
        (root / "axis.lis").write_text("# axis\nkenngr.achs_name   X\nkenngr.achs_typ   9\nEnde\n", encoding="latin-1")
    out = _child(root, "-c", _LINT, ZERO_NO_CACHE="1", **env)
    assert out.returncode in (0, 1), out.stderr
    *said, used = out.stdout.strip().splitlines()
    return "\n".join(said) + out.stderr, dict(ast.literal_eval(used))


def test_bundled_modules_are_what_pythons_import_gives(tmp_path: Path) -> None:
    root = _bundled_copy(tmp_path)
    preloaded = json.loads(_child(root, "-c", _BUNDLE_PROBE, "preload").stdout)
    imported = json.loads(_child(root, "-c", _BUNDLE_PROBE, "import").stdout)
    assert preloaded == imported
    assert preloaded["zero.rules"]["path"] == [str(root / "zero" / "rules")]
    assert preloaded["zero.engine.lint"]["loader"][0] == "zero"  # zero's own loader, as its finder gives


def _asked(used: bool) -> dict[str, bool]:
    """The bundles the lint of ``_lint``'s axis list asks for, each used or not: the lint's and an axis list's
    data (its unknown key's did-you-mean looks among the axis keys only, no other kind's table)."""
    return {command: used for command in COMMANDS if command in ("lint", "check", "kind-axis", "table-axis")}


def test_a_lint_writes_its_bundles_and_the_next_runs_them(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    _compile(root)
    first, used = _lint(root, PYTHONDONTWRITEBYTECODE="")
    assert used == _asked(False)  # an axis list's data: no other kind's
    assert all(_bundle(root, command).is_file() for command in used)
    again, used = _lint(root)
    assert used == _asked(True)
    assert again == first and "1 file checked" in first


def test_no_bundle_is_written_where_python_writes_no_cached_bytecode(tmp_path: Path) -> None:
    root = _copy(tmp_path)
    _compile(root)
    for env in ({}, {"PYTHONDONTWRITEBYTECODE": "", "PYTHONOPTIMIZE": "1"}):  # _child: -B; then -O (no finder)
        _, used = _lint(root, **env)
        assert not any(used.values())
        assert not any(_bundle(root, command).exists() for command in COMMANDS)


@pytest.mark.parametrize("change", ["content", "same size, other time", "module list"])
def test_a_stale_bundle_is_not_run_and_is_written_again(tmp_path: Path, change: str) -> None:
    root = _bundled_copy(tmp_path)
    module = root / "zero" / ("bundled_modules.py" if change == "module list" else "rules/syntax.py")
    st = module.stat()
    if change == "same size, other time":
        os.utime(module, ns=(st.st_atime_ns, st.st_mtime_ns + 1))  # a nanosecond later: no longer the same file
    else:
        module.write_text(module.read_text(encoding="utf-8") + "\nMARKER = 'edited'\n", encoding="utf-8")
    before = _bundle(root, "check").read_bytes()
    _, used = _lint(root, PYTHONDONTWRITEBYTECODE="")
    others = change != "module list"  # the list of modules is in every bundle's sources
    assert used == {**_asked(others), "check": False}
    assert _bundle(root, "check").read_bytes() != before  # written again, of the module as it is now
    _, used = _lint(root)
    assert used == _asked(True)
    if change == "content":
        code = ("import zero; zero.preload('lint'); zero.preload('check')\n"
                "import zero.rules.syntax as m; print(m.MARKER)")
        assert _child(root, "-c", code).stdout.strip() == "edited"


@pytest.mark.parametrize("damage", ["empty", "cut short", "another format", "not marshal", "not modules", "moved"])
def test_a_damaged_or_foreign_bundle_is_not_run(tmp_path: Path, damage: str) -> None:
    root = _bundled_copy(tmp_path)
    bundle = _bundle(root, "check")
    data = bundle.read_bytes()
    if damage == "moved":  # the same files elsewhere: each module's file names would be wrong
        moved = tmp_path / "elsewhere"
        shutil.copytree(root / "zero", moved / "zero")
        root = moved
    else:
        size = int.from_bytes(data[:4], "little")
        header = marshal.dumps((99, *marshal.loads(data[4:4 + size])[1:]))  # another format number
        bundle.write_bytes({"empty": b"", "cut short": data[: len(data) // 2],
                            "another format": len(header).to_bytes(4, "little") + header + data[4 + size:],
                            "not modules": data[:4 + size] + marshal.dumps((("zero.x", False, "x.py", 1),)),
                            "not marshal": b"\xff" * 64}[damage])
    said, used = _lint(root)
    assert used == {**_asked(damage != "moved"), "check": False}
    assert "Traceback" not in said


def test_a_module_already_imported_is_not_run_again(tmp_path: Path) -> None:
    root = _bundled_copy(tmp_path)
    code = ("import sys, zero, zero.rules.syntax as before\n"
            "assert zero.preload('lint') and zero.preload('check')\n"
            "import zero.rules.syntax as after, zero.rules as rules\n"
            "print(before is after is rules.syntax, zero.preload('check'))")
    out = _child(root, "-c", code)
    assert out.stdout.split() == ["True", "False"], out.stderr  # and a bundle is run once in a process


def test_a_module_whose_body_fails_is_not_left_behind() -> None:
    """As Python's import: the failing module, and those made for it and not run, leave sys.modules."""
    fails = compile("raise RuntimeError('in the body')", "fails.py", "exec")
    items = ((f"zero.{PACKAGE}.child", False, f"{PACKAGE}/child.py", compile("", "child.py", "exec")),
             (f"zero.{PACKAGE}.fails", False, f"{PACKAGE}/fails.py", fails),
             (f"zero.{PACKAGE}.after", False, f"{PACKAGE}/after.py", compile("", "after.py", "exec")),
             (f"zero.{PACKAGE}", True, f"{PACKAGE}/__init__.py", compile("", "__init__.py", "exec")))
    with pytest.raises(RuntimeError, match="in the body"):
        zero._run(items, str(SRC))
    left = sorted(n for n in sys.modules if n.startswith(f"zero.{PACKAGE}"))
    for name in left:
        del sys.modules[name]
    assert left == [f"zero.{PACKAGE}.child"]  # run to its end, as Python keeps an imported module


PACKAGE = "bundle_test_package"


def test_a_bundle_is_read_where_it_cannot_be_mapped(tmp_path: Path) -> None:
    """Without ``mmap`` (another system, a trimmed Python) the bundle is read instead, to the same modules."""
    root = _bundled_copy(tmp_path)
    code = ("import sys\nsys.modules['mmap'] = None  # import mmap fails\n"
            "import zero\nprint(zero.preload('lint'), zero.preload('check'))\n"
            "import zero.rules.syntax as m; print(m.__file__)")
    out = _child(root, "-c", code)
    assert out.stdout.split() == ["True", "True", str(root / "zero" / "rules" / "syntax.py")], out.stderr
    empty = tmp_path / "empty"
    empty.write_bytes(b"")
    with open(empty, "rb", buffering=0) as f:
        assert zero._mapped(f) == b""  # no mapping of nothing: read
    with open(_bundle(root, "lint"), "rb", buffering=0) as f:
        mapped = zero._mapped(f)
        assert not isinstance(mapped, bytes) and mapped[:] == _bundle(root, "lint").read_bytes()
        mapped.close()


# How a child's zero modules answer a missing name, each module loaded by a bundle or by zero's finder.
_MISSING_PROBE = r"""
import json, sys, types, zero
if sys.argv[1] == "preload":
    assert zero.preload("lint") and zero.preload("check")
import zero.diagnostics as plain, zero.catalog.data.table as answers, zero.rules as package

def error(run):
    try:
        run()
    except (AttributeError, ImportError) as e:
        return f"{type(e).__name__}: {e}"
    return None

print(json.dumps({
    "classes": [type(m).__name__ for m in (zero, plain, package)],
    "modules": all(isinstance(m, types.ModuleType) for m in (zero, plain, answers, package)),
    "its_own_answer": type(answers) is types.ModuleType and error(lambda: answers.nothing),
    "rows": len(answers.ROWS) > 0,
    "paths": [hasattr(plain, "__path__"), hasattr(package, "__path__")],
    "missing": error(lambda: plain.nothing),
    "not_importable": error(lambda: exec("from zero.diagnostics import nothing")),
    "default": getattr(plain, "nothing", "default"),
    "set": (setattr(plain, "added", 1), plain.added, delattr(plain, "added"), hasattr(plain, "added")),
}))
"""


@pytest.mark.parametrize("how", ["preload", "import"])
def test_a_missing_name_of_zeros_modules_is_still_missing(tmp_path: Path, how: str) -> None:
    """zero's modules are of a module subclass that looks a missing name up without an error made and thrown
    away (``zero._Module``); to any caller they are modules, and one that answers missing names itself (a module
    ``__getattr__``) keeps Python's class."""
    root = _bundled_copy(tmp_path)
    out = _child(root, "-c", _MISSING_PROBE, how)
    assert out.returncode == 0, out.stderr
    assert json.loads(out.stdout) == {
        "classes": ["module", "module", "module"], "modules": True,
        "its_own_answer": "AttributeError: module 'zero.catalog.data.table' has no attribute 'nothing'",
        "rows": True, "paths": [False, True],
        "missing": "AttributeError: 'module' object has no attribute 'nothing'",
        "not_importable": f"ImportError: cannot import name 'nothing' from 'zero.diagnostics' "
                          f"({root / 'zero' / 'diagnostics.py'})",
        "default": "default", "set": [None, 1, None, False]}
    classes = _child(root, "-c", "import sys, zero, zero.diagnostics, zero.catalog.data.table as t\n"
                     "print(type(zero) is type(zero.diagnostics) is zero._Module, type(t) is type(sys))")
    assert classes.stdout.split() == ["True", "True"], classes.stderr
