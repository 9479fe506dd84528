#!/usr/bin/env python3
"""zero's benchmark table: speed and memory next to the anchors, on generated data.

Usage:
    pip install -e '.[bench]'          # yamllint, an anchor
    python benchmarks/bench.py         # full run (several minutes; the 1,000,000-entry rows dominate)
    python benchmarks/bench.py --quick # without the 1,000,000-entry workload

Every in-process figure is measured in a fresh child process (best of N runs), so
"peak MiB" is that process's maximum resident memory. Whole-process figures
(start-up, many files) are wall times of real `zero` / `yamllint` processes.
Workloads are generated deterministically (benchmarks/workloads.py). Figures,
not pass/fail: compare the ratios, since absolute times drift on shared machines.
"""

from __future__ import annotations

import multiprocessing as mp
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import workloads  # noqa: E402

WORKLOADS = {
    "zero": ("97 x 32 zero list", workloads.full_zero_list),
    "axis": ("axis list", workloads.axis_list),
    "million": ("1,000,000 entries", workloads.million_entries),
}


def _data(name: str) -> bytes:
    return WORKLOADS[name][1]()


def _changed(data: bytes) -> bytes:
    """The same list with one value changed (for diff)."""
    lines = data.split(b"\n")
    for i in range(len(lines) // 2, len(lines)):
        parts = lines[i].split()
        if len(parts) >= 2 and parts[1].lstrip(b"-").isdigit():
            lines[i] = lines[i].replace(parts[1], str(int(parts[1]) + 10000).encode(), 1)
            break
    return b"\n".join(lines)


def _step(name: str, step: str) -> Callable[[], Any]:
    """The function one benchmark row times (prepared outside the timing)."""
    data = _data(name)
    if step == "tokenize":
        from zero.lists.tokenizer import tokenize

        return lambda: tokenize(data)
    if step == "lint":
        from zero.catalog.registry import load_registry
        from zero.engine.lint import lint_bytes

        registry = load_registry()
        return lambda: lint_bytes(data, registry, "bench.lis")
    if step.startswith("convert"):
        from zero.catalog.registry import load_registry
        from zero.engine.convert import convert

        registry = load_registry()
        fmt = step.split()[-1]
        return lambda: convert(data, "lis", fmt, registry, "bench.lis")
    if step == "diff":
        from zero.catalog.registry import load_registry
        from zero.diff import diff_sides, read_side

        registry = load_registry()
        other = _changed(data)
        return lambda: diff_sides(read_side(data, "lis", "a.lis", registry), read_side(other, "lis", "b.lis", registry),
                                  registry)
    from zero.catalog.registry import load_registry
    from zero.engine.convert import convert

    fmt = step.split()[-1]
    text = convert(data, "lis", fmt, load_registry(), "bench.lis").output.decode("utf-8")
    if fmt == "toml":
        import tomllib

        return lambda: tomllib.loads(text)
    if fmt == "yaml":
        import yaml

        return lambda: yaml.load(text, Loader=yaml.CSafeLoader)
    import json

    return lambda: json.loads(text)


def _child(job: tuple[str, str, int], queue: Any) -> None:
    name, step, repeat = job
    fn = _step(name, step)
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    queue.put((best, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024))


def measure(name: str, step: str, repeat: int) -> tuple[float, float]:
    ctx = mp.get_context("spawn")
    queue = ctx.Queue()
    proc = ctx.Process(target=_child, args=((name, step, repeat), queue))
    proc.start()
    result: tuple[float, float] = queue.get()
    proc.join()
    return result


def wall(args: list[str], repeat: int = 5, cwd: str | None = None) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(args, capture_output=True, check=False, cwd=cwd)
        best = min(best, time.perf_counter() - t0)
    return best


def zero_cmd() -> list[str]:
    exe = shutil.which("zero", path=str(Path(sys.executable).parent)) or shutil.which("zero")
    return [exe] if exe else [sys.executable, "-m", "zero"]


def yamllint_cmd() -> list[str] | None:
    exe = shutil.which("yamllint", path=str(Path(sys.executable).parent)) or shutil.which("yamllint")
    return [exe, "-d", "relaxed"] if exe else None


def row(workload: str, step: str, seconds: float, entries: int, size: int, peak: float | None,
        note: str = "") -> None:
    peak_text = f"{peak:>9.0f}" if peak is not None else f"{'':>9}"
    print(f"{workload:<19}{step:<24}{seconds * 1000:>11.1f}{entries / seconds:>13,.0f}"
          f"{size / 1e6 / seconds:>8.1f}{peak_text}  {note}")


def main() -> None:
    quick = "--quick" in sys.argv
    names = ["zero", "axis"] + ([] if quick else ["million"])
    print(f"{'workload':<19}{'step':<24}{'ms':>11}{'entries/s':>13}{'MB/s':>8}{'peak MiB':>9}  vs anchor")
    from zero.catalog.registry import load_registry
    from zero.engine.convert import convert
    from zero.lists.tokenizer import tokenize

    registry = load_registry()
    for name in names:
        data = _data(name)
        entries = len(tokenize(data).entries)
        label = WORKLOADS[name][0]
        repeat = 1 if name == "million" else 5
        anchors: dict[str, float] = {}
        for fmt in ("toml", "yaml", "json"):
            sec, peak = measure(name, f"anchor load {fmt}", repeat)
            anchors[fmt] = sec
            size = len(convert(data, "lis", fmt, registry, "b.lis").output)
            row(label, f"anchor: load {fmt}", sec, entries, size, peak)
        for step in ("tokenize", "lint", "convert yaml", "convert toml", "convert json", "diff"):
            sec, peak = measure(name, step, repeat)
            note = f"{anchors['toml'] / sec:.2f}x tomllib.loads" if step in ("tokenize", "lint") else ""
            row(label, f"zero {step}", sec, entries, len(data), peak, note)
        lint_cmd = yamllint_cmd()
        if lint_cmd and name != "million":
            with tempfile.TemporaryDirectory() as tmp:
                y = Path(tmp) / "data.yaml"
                y.write_bytes(convert(data, "lis", "yaml", load_registry(), "b.lis").output)
                sec = wall([*lint_cmd, str(y)], 3)
                row(label, "anchor: yamllint", sec, entries, y.stat().st_size, None, "whole process")
                lis = Path(tmp) / "data.lis"
                lis.write_bytes(data)
                zsec = wall([*zero_cmd(), "lint", str(lis)], 3)
                row(label, "zero lint (process)", zsec, entries, len(data), None,
                    f"{sec / zsec:.1f}x faster than yamllint (whole processes)")
                lint_sec, _ = measure(name, "lint", repeat)
                print(f"{'':<19}{'zero lint vs yamllint':<24}{sec / lint_sec:>11.1f}x faster (in-process lint)")
        print()

    # start-up: whole processes on the axis list
    with tempfile.TemporaryDirectory() as tmp:
        axis = Path(tmp) / "achsmds.lis"
        axis.write_bytes(workloads.axis_list())
        t_pass = wall([sys.executable, "-c", "pass"], 10)
        t_zero = wall([*zero_cmd(), "lint", str(axis)], 10)
        print(f"start-up (axis list, {len(tokenize(axis.read_bytes()).entries)} entries, clean):")
        print(f"  python3 -c pass          {t_pass * 1000:7.1f} ms")
        print(f"  zero lint                {t_zero * 1000:7.1f} ms  ({t_zero / t_pass:.1f}x python -c pass)")
        lint_cmd = yamllint_cmd()
        if lint_cmd:
            y = Path(tmp) / "achsmds.yaml"
            y.write_bytes(convert(axis.read_bytes(), "lis", "yaml", load_registry(), "a.lis").output)
            t_yl = wall([*lint_cmd, str(y)], 5)
            print(f"  yamllint (same as YAML)  {t_yl * 1000:7.1f} ms  (zero lint = {t_zero / t_yl:.2f}x of it)")

    # many files
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(10_000):
            (Path(tmp) / f"pzv{i:05d}.lis").write_bytes(workloads.small_list(i))
        one = wall([*zero_cmd(), "lint", "-j", "1", tmp], 3)
        cores = os.cpu_count() or 1
        many = wall([*zero_cmd(), "lint", "-j", str(cores), tmp], 3)
        print(f"\n10,000 files: 1 process {one:.2f} s, {cores} processes {many:.2f} s "
              f"({one / many:.2f}x)")


if __name__ == "__main__":
    main()
