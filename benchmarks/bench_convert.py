#!/usr/bin/env python3
"""Print conversion throughput: list → YAML/TOML/JSON and back, per workload.

Usage: python benchmarks/bench_convert.py [--quick]

Each figure is measured in a fresh child process (so peak memory is that of one
conversion); the standard loaders on the same structured text are printed next
to zero's reader as anchors. Figures, not pass/fail.
"""

from __future__ import annotations

import multiprocessing as mp
import resource
import sys
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

from workloads import full_zero_list, million_entries

FORMATS = ("yaml", "toml", "json")


def _measure(job: tuple[str, str, str, int], queue: Any) -> None:
    workload, fmt, direction, repeat = job
    from zero.catalog.registry import load_registry
    from zero.engine.convert import convert

    registry = load_registry()
    data = full_zero_list() if workload == "zero" else million_entries()
    if direction != "to":
        data = convert(data, "lis", fmt, registry, "w.lis").output
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        if direction == "to":
            convert(data, "lis", fmt, registry, "w.lis")
        elif direction == "from":
            convert(data, fmt, "lis", registry, "w." + fmt, check=False)
        else:  # the standard loader parsing the same text: an anchor, not zero
            text = data.decode("utf-8")
            if fmt == "yaml":
                import yaml

                yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
            elif fmt == "toml":
                import tomllib

                tomllib.loads(text)
            else:
                import json

                json.loads(text)
        best = min(best, time.perf_counter() - t0)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    queue.put((best, len(data), peak))


def measure(job: tuple[str, str, str, int]) -> tuple[float, int, float]:
    ctx = mp.get_context("spawn")
    queue = ctx.Queue()
    proc = ctx.Process(target=_measure, args=(job, queue))
    proc.start()
    result: tuple[float, int, float] = queue.get()
    proc.join()
    return result


def main() -> None:
    quick = "--quick" in sys.argv
    workloads = [("zero", "97 x 32 zero list", 6_210, 5)]
    if not quick:
        workloads.append(("million", "1,000,000 entries", 1_000_000, 1))
    print(f"{'workload':<20}{'format':<7}{'step':<22}{'seconds':>9}{'entries/s':>12}{'MB/s':>8}"
          f"{'peak MiB':>10}")
    for key, name, entries, repeat in workloads:
        for fmt in FORMATS:
            for direction, label in (("to", f"list -> {fmt}"), ("from", f"{fmt} -> list"),
                                     ("anchor", f"anchor: load {fmt}")):
                seconds, size, peak = measure((key, fmt, direction, repeat))
                print(f"{name:<20}{fmt:<7}{label:<22}{seconds:>9.3f}{entries / seconds:>12,.0f}"
                      f"{size / 1e6 / seconds:>8.1f}{peak:>10.0f}")


if __name__ == "__main__":
    main()
