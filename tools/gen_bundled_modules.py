#!/usr/bin/env python3
"""Write which of zero's modules each bundle holds to ``src/zero/bundled_modules.py`` (see ``zero.bundles``),
from real runs: ``zero lint`` of each list of ``fixtures/machine-clean/`` (an axis, channel, start-up and
zero-offset list) in a folder of its own: without the cache (``ZERO_NO_CACHE``), with nothing cached, and
answered by the cache, each in a fresh interpreter that loads every module through Python's import (no bundle) and
records the order in which their bodies finish.

- ``lint``: the modules every run loads after the console script knows the command is ``lint`` and before
  it checks a file (a run the cache answers loads these and little else);
- ``check``: the other modules every run that checks a list loads (the catalogue, the reader, the rules),
  whatever the list's kind: a kind's own tables stay out;
- ``table-<kind>`` for each kind of the built-in table: its table (IDs, keys, rows), asked for where the
  kind's table is first read (a list's unknown key is looked for in every kind's);
- ``kind-<kind>``: the kind's other data modules (its specs, ranges and K conditions as written at build
  time), asked for at the kind's first parameter.

Each in the order the first run (without the cache) finished them, so that a module runs after what it
imports. Run it after changing what a lint imports (a stale list is not wrong: a module it misses is
imported as usual, one it holds that a run no longer needs is run anyway; a test fails on it).

Usage: python tools/gen_bundled_modules.py [--check]   (--check: exit 1 if the file is stale, write nothing)
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _gen

ROOT = _gen.ROOT
SRC = ROOT / "src"
LISTS = ROOT / "fixtures" / "machine-clean" / "listen"
DATA = SRC / "zero" / "catalog" / "data"
# in the order a lint imports them; not the kind's table, which telling a list's kind reads before
KIND_DATA = ("specs", "ranges_compiled", "startup_compiled")

# A run of ``zero lint LIST`` that records each zero module as its body finishes, and each bundle asked for
# (as "@name"), then writes them as JSON to the file named by ZERO_RECORD.
_RECORD = r"""
import json, os, sys
import _frozen_importlib as bootstrap
import zero

order = []

def preload(command):
    order.append("@" + command)
    return False

zero.preload = preload
load = bootstrap._load_unlocked

def recorded(spec):
    module = load(spec)
    order.append(spec.name)
    return module

bootstrap._load_unlocked = recorded
import zero.cli.lean as lean

def end(code):
    with open(os.environ["ZERO_RECORD"], "w", encoding="utf-8") as f:
        json.dump(order, f)
    os._exit(0 if code in (0, 1) else code)

lean.end = end
sys.argv = ["zero", "lint", sys.argv[1]]
lean.main()
"""


def _run(folder: Path, name: str, cache: bool) -> list[str]:
    """What one lint of ``name`` in ``folder`` loaded, in order, with the bundles it asked for."""
    record = folder / "record.json"
    env = {k: v for k, v in os.environ.items() if not k.startswith("ZERO_")}
    env.update(PYTHONPATH=str(SRC), ZERO_RECORD=str(record), ZERO_CACHE_DIR=str(folder / "cache"))
    if not cache:
        env["ZERO_NO_CACHE"] = "1"
    done = subprocess.run([sys.executable, "-c", _RECORD, name], cwd=folder, env=env, capture_output=True,
                          text=True, check=False, timeout=300)
    if done.returncode not in (0, 1) or not record.is_file():
        raise SystemExit(f"gen_bundled_modules: `zero lint {name}` failed:\n{done.stderr}")
    order: list[str] = json.loads(record.read_text(encoding="utf-8"))
    return order


def _after(order: list[str], start: str, stop: str | None) -> list[str]:
    """zero's modules loaded after the bundle ``start`` was asked for and before ``stop`` (or the end)."""
    if start not in order:
        return []
    rest = order[order.index(start) + 1:]
    if stop is not None and stop in rest:
        rest = rest[:rest.index(stop)]
    return [name for name in rest if name.startswith("zero.")]


def bundles() -> dict[str, list[str]]:
    """Each bundle's modules, from runs of every list (see the module)."""
    lint: list[list[str]] = []
    check: list[list[str]] = []
    with tempfile.TemporaryDirectory() as tmp:
        for path in sorted(LISTS.glob("*.lis")):
            folder = Path(tmp) / path.stem
            folder.mkdir()
            shutil.copy(path, folder / path.name)
            for cache in (False, True, True):  # no cache; nothing cached; answered by the cache
                order = _run(folder, path.name, cache)
                lint.append(_after(order, "@lint", "@check"))
                if "@check" in order:
                    check.append(_after(order, "@lint", None))
    if not lint or not check:
        raise SystemExit("gen_bundled_modules: no run of a list asked for both bundles")
    first = [n for n in lint[0] if all(n in run for run in lint)]
    made = {"lint": first, "check": [n for n in check[0] if n not in first and all(n in run for run in check)]}
    kinds = [table.stem.removeprefix("table_") for table in sorted(DATA.glob("table_*.py"))]
    for kind in kinds:
        made[f"table-{kind}"] = [f"zero.catalog.data.table_{kind}"]
        made[f"kind-{kind}"] = [f"zero.catalog.data.{part}_{kind}" for part in KIND_DATA
                                if (DATA / f"{part}_{kind}.py").is_file()]
    bundled = {n for names in made.values() for n in names}
    for order in check:  # every data module of a kind that a run loaded is in its kind's bundle
        for name in order:
            if name.rpartition("_")[2] in kinds and name.startswith("zero.catalog.data.") and name not in bundled:
                raise SystemExit(f"gen_bundled_modules: {name}, a kind's data module, is in no bundle")
    return made


def render() -> str:
    """The module's text."""
    parts = []
    for command, names in bundles().items():
        listed = "".join(f"\n        {name!r}," for name in names)
        parts.append(f"\n    {command!r}: ({listed}\n    ),")
    return ('"""The modules each bundle of ``zero.bundles`` holds, in the order a run finished them: written by\n'
            "tools/gen_bundled_modules.py.\n\n"
            'Generated: do not edit."""\n\n'
            "# ruff: noqa\n"
            "from __future__ import annotations\n\n"
            f"COMMANDS: dict[str, tuple[str, ...]] = {{{''.join(parts)}\n}}\n")


def files() -> dict[Path, str | None]:
    return {SRC / "zero" / "bundled_modules.py": render()}


def main(argv: list[str] | None = None) -> None:
    _gen.run("gen_bundled_modules.py", files, argv)


if __name__ == "__main__":
    main()
