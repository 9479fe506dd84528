#!/usr/bin/env python3
"""Start-up as instructions (issue 40): what a lint of one list costs, counted by valgrind's callgrind.

Wall time on a shared machine swings by a third within minutes; the count of instructions a run executes
does not (±0.1 %), and wall time follows it about in proportion. This prints, for the vendor's axis list
(``../shared/bench/workloads_real.py``'s), the instructions of:

- the anchors: ``python -c pass`` and ``python -m`` of an empty module (what ``-m`` itself costs);
- ``python -m zero lint axis.lis`` without the cache (what ``bench_real.py``'s start-up row times), and the
  same answered by the cache (an unchanged list: zero's default);
- with ``--phases``, where a cold lint's instructions go: importing what a lint imports before it reads the
  list, loading the catalogue, reading the list, binding it to the catalogue, the value model, the checks.

It passes or fails nothing. Needs ``valgrind`` (Debian: ``apt install valgrind``); says so without it.

usage: python benchmarks/bench_startup.py [--phases] [--keep DIR]
"""

from __future__ import annotations

import argparse
import os
import py_compile
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from workloads import ready_bytecode

ROOT = Path(__file__).resolve().parent.parent
SHARED = ROOT.parent / "shared" / "bench" / "workloads_real.py"
PY = sys.executable
_ENV = {k: v for k, v in os.environ.items() if k not in ("PYTHONUNBUFFERED", "ZERO_NO_CACHE")}

# Each phase a child runs up to (argv[1]), in one interpreter: the differences are what each phase adds.
_PHASES = """
import gc, os, sys
from zero.cli import GC_THRESHOLDS
gc.set_threshold(*GC_THRESHOLDS)  # as the console entry sets them before zero is imported
import zero
zero.preload("lint"), zero.preload("check")  # as a lint does (zero.bundles), where the bundles are current
import zero.cli.exits, zero.cli.options, zero.cli.run, zero.engine.lint, zero.engine.parallel
stage = int(sys.argv[1])
if stage >= 1:
    from zero.catalog.registry import load_registry
    registry = load_registry(None)
if stage >= 2:
    from zero.lists.tokenizer import tokenize
    with open(sys.argv[2], "rb") as f:
        doc = tokenize(f.read(), sys.argv[2])
if stage >= 3:
    from zero.rules.base import Context
    ctx = Context.of(doc, registry, None)
if stage >= 4:
    ctx.by_id
if stage >= 5:
    from zero.engine.selection import layered_selection, selected_rules
    from zero.rules.base import run_checks
    from zero.rules.lists import CHECKS
    ctx.severities = selected_rules(layered_selection([((), (), ())]))
    run_checks(CHECKS, ctx)
os._exit(0)
"""
PHASES = ("import what a lint imports first", "load the catalogue", "read the list", "bind it to the catalogue",
          "the value model", "the checks")


def instructions(cmd: list[str], cwd: Path, env: dict[str, str]) -> int:
    """The instructions ``cmd`` executes (its whole process), as callgrind counts them."""
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "callgrind.out"
        done = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", *cmd], cwd=cwd,
                              env=env, capture_output=True, text=True, check=False)
        for line in done.stderr.splitlines():
            if "Collected :" in line:
                return int(line.rsplit(":", 1)[1])
    raise SystemExit(f"callgrind gave no count for {cmd}: {done.stderr[-500:]}")


def main() -> None:
    a = argparse.ArgumentParser()
    a.add_argument("--phases", action="store_true", help="where a cold lint's instructions go")
    a.add_argument("--keep", type=Path, help="build (or reuse) the workloads here")
    args = a.parse_args()
    if shutil.which("valgrind") is None:
        print("valgrind is not installed (Debian: apt install valgrind): no instruction counts")
        return
    out = args.keep or Path(tempfile.mkdtemp(prefix="zero-startup-"))
    if not (out / "axis.lis").is_file():
        zero = shutil.which("zero") or str(Path(PY).parent / "zero")
        subprocess.run([PY, str(SHARED), "--zero", zero, "--out", str(out), "--tools", "30", "--machines", "1"],
                       check=True, stdout=subprocess.DEVNULL)
    ready_bytecode(PY, ROOT / "src" / "zero")
    empty = out / "zero_bench_empty.py"
    empty.write_text("", encoding="ascii")
    # its bytecode written: an interpreter's first compile() readies the compiler, some 12 M instructions
    py_compile.compile(str(empty), doraise=True)
    cold = {**_ENV, "ZERO_NO_CACHE": "1", "PYTHONPATH": str(out)}
    cached = {**_ENV, "ZERO_CACHE_DIR": str(out / "startup-cache"), "PYTHONPATH": str(out)}
    settled = 10**9 * 1_600_000_000  # the cache keeps the result of a file not still being written
    os.utime(out / "axis.lis", ns=(settled, settled))
    lint = [PY, "-m", "zero", "lint", "axis.lis"]
    subprocess.run(lint, cwd=out, env=cached, capture_output=True, check=False)  # fills the cache
    rows = [("python -c pass", instructions([PY, "-c", "pass"], out, cold)),
            ("python -m (an empty module)", instructions([PY, "-m", "zero_bench_empty"], out, cold)),
            ("python -m zero lint axis.lis (no cache)", instructions(lint, out, cold)),
            ("the same, answered by the cache", instructions(lint, out, cached))]
    anchor = rows[0][1]
    print(f"{'run':<52}{'instructions':>16}{'× pass':>10}")
    for name, n in rows:
        print(f"{name:<52}{n / 1e6:>14.1f} M{n / anchor:>9.2f}×")
    if args.phases:
        print(f"\n{'a cold lint, phase by phase (one interpreter, no -m)':<52}{'instructions':>16}")
        before = instructions([PY, "-c", "pass"], out, cold)
        for stage, name in enumerate(PHASES):
            n = instructions([PY, "-c", _PHASES, str(stage), "axis.lis"], out, cold)
            print(f"{'  ' + name:<52}{(n - before) / 1e6:>14.1f} M")
            before = n


if __name__ == "__main__":
    main()
