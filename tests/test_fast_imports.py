"""zero's own finder (``zero/__init__.py``, issue 40: start-up): zero's modules from their current cached
bytecode, exactly what Python's finders give, and Python's finders for everything else."""

from __future__ import annotations

import compileall
import json
import os
import py_compile
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import zero

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
