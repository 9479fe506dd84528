#!/usr/bin/env python3
"""Fleet drift (issue 30): ``zero diff --fleet`` on a fleet of the vendor's machine, one value changed on two.

Builds, in a temporary directory outside any git work tree, a golden machine (``gold/listen/``: the
vendor's lists, ``../shared/corpus/isg-sdk/listen``, as they lie) and M machines
(``fleet/mNNN/listen/``, copies of it), and raises ``getriebe[0].dynamik.vb_max`` of the vendor's
first axis list on two of them. (``workloads_real.py``'s fleet of bench_real.py copies the lists
without their ``listen/`` folder, which the vendor's start-up list names: its machines read no list.)

Then times the fleet drift
* as a library call (``zero.engine.fleet.fleet_drift``, the catalogue already loaded), and
* on the command line (``python -m zero diff --fleet GOLDEN FLEET --output-format json``, a fresh
  process, start-up included) where this zero has ``--fleet``,
with ``--jobs 1`` and ``--jobs 2`` and no cache (``--no-cache``: every machine read and compared),
then "the same fleet again, nothing changed" with the cache (``.zero_cache`` in a folder of the
run's own, filled by one run first), next to an anchor (reading and splitting every file of the
fleet), and prints a table with each ratio and its goal (issue 40: ≤ 5× cold, ≤ 1.5× again). It
asserts nothing but that the two machines, and only they, are found; a goal missed is said, not
failed (the machine's noise decides a run: the anchor is timed twice and the best taken).

usage: python benchmarks/bench_fleet.py [--machines 300] [--quick] [--keep DIR] [--repeat R]
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT.parent / "shared" / "corpus" / "isg-sdk" / "listen"
PY = sys.executable
ZERO = [PY, "-m", "zero"]
_ENV = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}
AXIS_LIST = "achsmds1.lis"
# The goals of issue 40, as ratios to reading and splitting every file of the fleet.
COLD_GOAL = 5.0  # a fleet of 300 machines compared
AGAIN_GOAL = 1.5  # the same fleet again, nothing changed (the cache)
KEY = b"getriebe[0].dynamik.vb_max"
NEW_VALUE = b"120000"


def changed_ones(machines: int) -> list[int]:
    return sorted({machines // 7, machines * 5 // 6})


def raise_vb_max(path: Path) -> None:
    """Set the first ``getriebe[0].dynamik.vb_max`` of an axis list to :data:`NEW_VALUE` (bytes kept)."""
    lines = path.read_bytes().split(b"\n")
    for i, line in enumerate(lines):
        if line.split(None, 1)[:1] == [KEY]:
            value = line.split()[1]
            at = line.index(value, len(KEY))
            lines[i] = line[:at] + NEW_VALUE.ljust(len(value)) + line[at + len(value):]
            break
    else:
        raise SystemExit(f"{path}: no {KEY.decode()}")
    path.write_bytes(b"\n".join(lines))


def build(out: Path, machines: int) -> tuple[Path, Path, list[str]]:
    """The golden machine and the fleet; (golden start-up list, fleet folder, the changed machines)."""
    golden, fleet = out / "gold" / "listen" / "hochlauf.lis", out / "fleet"
    marker = out / f".built-{machines}"
    changed = [str(fleet / f"m{i:03d}" / "listen" / "hochlauf.lis") for i in changed_ones(machines)]
    if marker.is_file():
        return golden, fleet, changed
    shutil.rmtree(out / "gold", ignore_errors=True)
    shutil.rmtree(fleet, ignore_errors=True)
    shutil.copytree(CORPUS, golden.parent)
    for i in range(machines):
        shutil.copytree(CORPUS, fleet / f"m{i:03d}" / "listen")
    for i in changed_ones(machines):
        raise_vb_max(fleet / f"m{i:03d}" / "listen" / AXIS_LIST)
    marker.write_text("")
    return golden, fleet, changed


def check(params: list[tuple[str, list[str]]], changed: list[str]) -> None:
    """The one assertion: exactly the two machines, and only ``vb_max``, drift."""
    assert [key for key, _ in params] == [KEY.decode()], params
    assert sorted(params[0][1]) == sorted(changed), (params, changed)


def library(golden: Path, fleet: Path, jobs: int, repeat: int, changed: list[str], cache: bool = False) -> float:
    sys.path.insert(0, str(ROOT / "src"))
    from zero.catalog.registry import load_registry
    from zero.engine.fleet import fleet_drift
    from zero.engine.project import Project

    registry = load_registry()
    best = float("inf")
    if cache:  # filled once: what is timed is the same fleet again, nothing changed
        fleet_drift(golden, [fleet], Project(lambda _d: registry, isolated=True), jobs=jobs, cache=True)
    for _ in range(repeat):
        project = Project(lambda _d: registry, isolated=True)  # a fresh resolver: nothing read before
        t = time.perf_counter()
        drift = fleet_drift(golden, [fleet], project, jobs=jobs, cache=cache)
        best = min(best, time.perf_counter() - t)
        check([(p.key, p.machines) for p in drift.params], changed)
        assert not drift.lists and not drift.unreadable
    return best


def has_fleet_option() -> bool:
    """Does this zero's ``zero diff`` take ``--fleet`` (the command line glue of issue 30)?"""
    out = subprocess.run([*ZERO, "diff", "--help"], capture_output=True, text=True, env=_ENV, cwd=ROOT, check=False)
    return "--fleet" in out.stdout


def command_line(golden: Path, fleet: Path, jobs: int, repeat: int, changed: list[str], cache: bool = False) -> float:
    best = float("inf")
    command = [*ZERO, "diff", "--fleet", str(golden), str(fleet), "--jobs", str(jobs), "--output-format", "json"]
    if not cache:
        command.append("--no-cache")
    else:  # filled once: what is timed is the same fleet again, nothing changed
        subprocess.run(command, capture_output=True, env=_ENV, check=False)
    for _ in range(repeat):
        t = time.perf_counter()
        out = subprocess.run(command, capture_output=True, text=True, env=_ENV, check=False)
        best = min(best, time.perf_counter() - t)
        assert out.returncode == 1, (out.returncode, out.stderr)
        data = json.loads(out.stdout)
        check([(p["key"], [m for v in p["values"] for m in v["machines"]]) for p in data["parameters"]], changed)
    return best


def read_all(fleet: Path) -> float:
    t = time.perf_counter()
    for d, _, fs in os.walk(fleet):
        for f in fs:
            with open(os.path.join(d, f), "rb") as fh:
                fh.read().splitlines()
    return time.perf_counter() - t


def main() -> None:
    a = argparse.ArgumentParser()
    a.add_argument("--machines", type=int, help="machines in the fleet (default 300; 30 with --quick)")
    a.add_argument("--quick", action="store_true")
    a.add_argument("--keep", type=Path, help="build (or reuse) the fleet here")
    a.add_argument("--repeat", type=int, default=1, help="best of this many runs")
    args = a.parse_args()
    machines = args.machines or (30 if args.quick else 300)
    out = args.keep or Path(tempfile.mkdtemp(prefix="zero-fleet-"))
    golden, fleet, changed = build(out, machines)
    subprocess.run([PY, "-m", "compileall", "-q", "-f", str(ROOT / "src" / "zero")], check=False,  # -f: bench_real.py
                   stdout=subprocess.DEVNULL)
    files = sum(len(fs) for _, _, fs in os.walk(fleet))
    print(f"fleet in {out}: {machines} machines, {files:,} files; {KEY.decode()} raised on "
          f"{', '.join(Path(c).parent.parent.name for c in changed)}\n")
    os.environ["ZERO_CACHE_DIR"] = _ENV["ZERO_CACHE_DIR"] = str(out / "cache")  # the run's own, whatever its folder
    shutil.rmtree(out / "cache", ignore_errors=True)
    anchor = min(read_all(fleet) for _ in range(3))
    print(f"{'workload':<52}{'time':>11}{'per machine':>14}   {'anchor: read + split':>22}{'ratio':>9}   goal")

    def row(name: str, seconds: float, goal: float) -> None:
        ratio = seconds / anchor
        print(f"{name:<52}{seconds * 1000:>8.0f} ms{seconds * 1000 / machines:>11.2f} ms   "
              f"{anchor * 1000:>19.0f} ms{ratio:>8.1f}×   ≤ {goal}×{'' if ratio <= goal else '  (missed)'}")

    for jobs in (1, 2):
        row(f"fleet_drift (library), jobs {jobs}", library(golden, fleet, jobs, args.repeat, changed), COLD_GOAL)
    row("fleet_drift again, nothing changed (cache), jobs 2",
        library(golden, fleet, 2, max(args.repeat, 3), changed, cache=True), AGAIN_GOAL)
    if has_fleet_option():
        for jobs in (1, 2):
            row(f"zero diff --fleet --jobs {jobs} --no-cache (json)",
                command_line(golden, fleet, jobs, args.repeat, changed), COLD_GOAL)
        row("zero diff --fleet again, nothing changed (json)",
            command_line(golden, fleet, 2, max(args.repeat, 3), changed, cache=True), AGAIN_GOAL)
    else:
        print("zero diff --fleet: not on this zero's command line yet (the library call is timed above)")
    print(f"\nfound: {KEY.decode()} differs on exactly the {len(changed)} changed machines")
    if args.keep is None:
        shutil.rmtree(out, ignore_errors=True)


if __name__ == "__main__":
    main()
