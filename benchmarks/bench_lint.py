#!/usr/bin/env python3
"""Print throughput figures of the tokenizer and of lint on generated lists.

Usage: python benchmarks/bench_lint.py   (figures, not pass/fail; see issue 7 for targets)
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from workloads import full_zero_list

from zero.catalog.registry import load_registry
from zero.engine.lint import lint_bytes
from zero.lists.tokenizer import tokenize


def best(fn, repeat: int = 5) -> float:  # type: ignore[no-untyped-def]
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main() -> None:
    registry = load_registry()
    zero = full_zero_list()
    body = zero.replace(b"Ende\n", b"")
    big = body * 161 + b"Ende\n"  # ~1M entries (keys repeat: the later value wins)
    rows = []
    for name, data in (("zero list 6,208 entries", zero), ("1M entries", big)):
        n = len(tokenize(data).entries)
        t_tok = best(lambda d=data: tokenize(d), 3 if len(data) > 1e6 else 5)
        t_lint = best(lambda d=data: lint_bytes(d, registry), 1 if len(data) > 1e6 else 5)
        mb = len(data) / 1e6
        rows.append((name, n, t_tok, n / t_tok, mb / t_tok, t_lint, n / t_lint))
    print(f"{'workload':<26}{'entries':>10}{'tokenize s':>12}{'entries/s':>12}{'MB/s':>8}"
          f"{'lint s':>9}{'entries/s':>12}")
    for r in rows:
        print(f"{r[0]:<26}{r[1]:>10}{r[2]:>12.3f}{r[3]:>12.0f}{r[4]:>8.1f}{r[5]:>9.3f}{r[6]:>12.0f}")

    axis = Path(__file__).resolve().parent.parent.parent / "shared/corpus/isg-sdk/listen/achsmds1.lis"
    target = str(axis) if axis.exists() else None
    if target:
        def run(args: list[str]) -> float:
            return best(lambda: subprocess.run(args, capture_output=True, check=False), 5)

        t_pass = run([sys.executable, "-c", "pass"])
        t_zero = run([sys.executable, "-m", "zero", "lint", target])
        print(f"\nstart-up: python -c pass {t_pass * 1000:.0f} ms; zero lint achsmds1.lis "
              f"{t_zero * 1000:.0f} ms ({t_zero / t_pass:.1f}x)")


if __name__ == "__main__":
    main()
