#!/usr/bin/env python3
"""Timing fuzzer for every regular expression in ``src/zero``: inputs built to make a pattern
backtrack, and a check that its time grows with the input no faster than linearly (with a margin).

    python fuzz/regex_timing.py [--size 2000] [--factor 4] [--pumps 60] [--seed 0] [--json FILE]

What it does, pattern by pattern:

1. Every pattern is collected from the source: the literal first argument of each ``re.compile``,
   ``re.match``, ``re.search``, ``re.fullmatch``, ``re.sub``, ``re.findall``, ``re.finditer`` and
   ``re.split`` call (with its flags), and every compiled pattern a module holds at import
   (patterns built by concatenation or f-strings).
2. From the pattern's parse tree, an alphabet: each literal character, one or two members of each
   character class and category, the literal strings the pattern holds, and a few characters a
   pattern rarely expects (``\\x00``, ``!``, space, newline).
3. Pumps: each literal string, each character, every pair of characters and a sample of triples
   (``--pumps`` caps the number). An input is ``prefix + pump * n + suffix`` for every suffix of
   the alphabet (the suffix makes the match fail late, which is where backtracking lives).
4. For each input, the pattern is applied as zero applies it (``search`` where any call site
   searches, finds, substitutes or splits: every start of the text is tried; else ``match``) and timed
   with the pump repeated a few times, then ``factor`` times as often, and so on up to ``--size``
   times ``factor`` characters; the pattern is *superlinear* when one size takes more than
   ``2 * factor`` times as long as the size before (quadratic gives ``factor**2``) and more than
   ``--floor`` seconds. The first such input is reported.

The exit status is 1 when a pattern is superlinear; each is printed with the input that shows it.
``growth()`` is what the unit tests use to compare two sizes of one input.
"""

from __future__ import annotations

import argparse
import ast
import functools
import importlib
import itertools
import json
import pkgutil
import random
import re
import re._constants as sre_constants  # type: ignore[import-not-found]
import re._parser as sre_parse  # type: ignore[import-not-found]
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

SRC = Path(__file__).resolve().parent.parent / "src" / "zero"
_FUNCS = {"compile", "match", "search", "fullmatch", "sub", "subn", "findall", "finditer", "split"}
_ENOUGH = 0.25  # seconds: an input this slow has said what it can
_ODD = "\x00! \n\t\"'<>.#=-_a0"


def best_time(fn: Callable[[], object], repeat: int = 3) -> float:
    """The shortest of ``repeat`` runs of ``fn``, in seconds of this process's CPU time (the wall
    clock counts every other process on a busy machine: ratios of it were noise)."""
    best = float("inf")
    for _ in range(repeat):
        start = time.process_time()
        fn()
        best = min(best, time.process_time() - start)
    return best


def growth(fn: Callable[[Any], object], make: Callable[[int], Any], small: int, large: int,
           floor: float = 0.002) -> float:
    """How many times longer ``fn(make(large))`` takes than ``fn(make(small))``, the smaller time
    taken as at least ``floor`` seconds (so that noise on microseconds is no growth). Linear
    growth gives about ``large / small``; a blow-up gives far more."""
    a, b = make(small), make(large)
    t_small = best_time(lambda: fn(a))
    t_large = best_time(lambda: fn(b), repeat=1 if t_small > 1 else 3)
    return t_large / max(t_small, floor)


def _flags(node: ast.expr | None) -> int:
    """``re.I | re.S``-style flags from the source (0 for anything else)."""
    if node is None:
        return 0
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "re":
        value = getattr(re, node.attr, 0)
        return int(value)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):
        return _flags(node.left) | _flags(node.right)
    return 0


_SEARCHING = {"search", "sub", "subn", "findall", "finditer", "split"}  # try every start of the text


def _mode(methods: set[str]) -> str:
    """How a pattern is applied: ``search`` where any call tries every start, else ``match``."""
    return "search" if not methods or methods & _SEARCHING else "match"


def uses() -> dict[tuple[str, str], set[str]]:
    """For every module and name, the methods called on that name there (``_KEY_RE.match(...)``);
    under the module ``""``, the calls on it in any module (a pattern another module imports)."""
    found: dict[tuple[str, str], set[str]] = {}
    for path in sorted(SRC.rglob("*.py")):
        module = ".".join(path.relative_to(SRC.parent).with_suffix("").parts).removesuffix(".__init__")
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
                owner = node.func.value
                name = owner.id if isinstance(owner, ast.Name) else \
                    owner.attr if isinstance(owner, ast.Attribute) else None
                if name is not None:
                    found.setdefault((module, name), set()).add(node.func.attr)
                    found.setdefault(("", name), set()).add(node.func.attr)
    return found


def source_patterns() -> Iterator[tuple[str, re.Pattern[Any], str]]:
    """Every literal pattern in a ``re.*`` call in ``src/zero``, with where it is and how it is applied."""
    for path in sorted(SRC.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                    and isinstance(node.func.value, ast.Name) and node.func.value.id == "re"
                    and node.func.attr in _FUNCS and node.args):
                continue
            first = node.args[0]
            if not (isinstance(first, ast.Constant) and isinstance(first.value, (str, bytes))):
                continue
            flag_node = next((k.value for k in node.keywords if k.arg == "flags"), None)
            if flag_node is None:
                at = {"compile": 1, "match": 2, "search": 2, "fullmatch": 2, "findall": 2, "finditer": 2,
                      "split": 3, "sub": 4, "subn": 4}[node.func.attr]
                flag_node = node.args[at] if len(node.args) > at else None
            where = f"{path.relative_to(SRC.parent)}:{node.lineno}"
            mode = "" if node.func.attr == "compile" else _mode({node.func.attr})  # "": as its name is used
            yield where, re.compile(first.value, _flags(flag_node)), mode


def module_patterns() -> Iterator[tuple[str, re.Pattern[Any], str]]:
    """Every compiled pattern a module of zero holds at import (built ones included), and how it is
    applied (from the calls on its name)."""
    called = uses()
    sys.path.insert(0, str(SRC.parent))
    import zero

    for info in pkgutil.walk_packages(zero.__path__, "zero."):
        if info.name.startswith(("zero.cli", "zero.__main__")):
            continue
        try:
            module = importlib.import_module(info.name)
        except Exception:  # an optional extra that is not installed
            continue
        for name, value in vars(module).items():
            if isinstance(value, re.Pattern):
                methods = called.get((info.name, name)) or called.get(("", name), set())
                yield f"{info.name}.{name}", value, _mode(methods & (_SEARCHING | {"match", "fullmatch"}))


def all_patterns() -> dict[tuple[str | bytes, int], tuple[str, re.Pattern[Any], str]]:
    """Each distinct (pattern, flags) once, with the first place it was seen and how it is applied
    (``search`` if any place searches)."""
    found: dict[tuple[str | bytes, int], tuple[str, re.Pattern[Any], str]] = {}
    for where, pattern, mode in itertools.chain(module_patterns(), source_patterns()):
        key = (pattern.pattern, pattern.flags)
        if key in found and mode and found[key][2] != mode:
            found[key] = (found[key][0], pattern, "search")
        elif key not in found:
            found[key] = (where, pattern, mode or "search")  # compiled where no name shows its use
    return found


def _alphabet(parsed: Any, chars: set[str], strings: set[str]) -> None:
    """Characters and literal strings of a parsed pattern (sre_parse's tree)."""
    run: list[str] = []
    for op, av in parsed:
        if op is sre_constants.LITERAL:
            chars.add(chr(av))
            run.append(chr(av))
            continue
        if len(run) > 1:
            strings.add("".join(run))
        run = []
        if op is sre_constants.NOT_LITERAL:
            chars.add(chr(av))
            chars.add("a" if av != ord("a") else "b")
        elif op is sre_constants.IN:
            for iop, iav in av:
                if iop is sre_constants.LITERAL:
                    chars.add(chr(iav))
                elif iop is sre_constants.RANGE:
                    chars.update((chr(iav[0]), chr(iav[1])))
                elif iop is sre_constants.CATEGORY:
                    chars.update({"CATEGORY_DIGIT": "7", "CATEGORY_SPACE": " \n", "CATEGORY_WORD": "a_",
                                  "CATEGORY_NOT_SPACE": "a", "CATEGORY_NOT_DIGIT": "a", "CATEGORY_NOT_WORD": "-"}
                                 .get(str(iav), ""))
        elif op is sre_constants.ANY:
            chars.update("a\n")
        elif op in (sre_constants.MAX_REPEAT, sre_constants.MIN_REPEAT, sre_constants.POSSESSIVE_REPEAT):
            _alphabet(av[2], chars, strings)
        elif op is sre_constants.SUBPATTERN:
            _alphabet(av[-1], chars, strings)
        elif op is sre_constants.ATOMIC_GROUP:
            _alphabet(av, chars, strings)
        elif op in (sre_constants.ASSERT, sre_constants.ASSERT_NOT):
            _alphabet(av[1], chars, strings)
        elif op is sre_constants.BRANCH:
            for branch in av[1]:
                _alphabet(branch, chars, strings)
        elif op is sre_constants.GROUPREF_EXISTS:
            _alphabet(av[1], chars, strings)
            if av[2] is not None:
                _alphabet(av[2], chars, strings)
    if len(run) > 1:
        strings.add("".join(run))


def inputs(pattern: re.Pattern[Any], pumps: int, rng: random.Random) -> list[tuple[str, str, str]]:
    """(prefix, pump, suffix) triples built to make ``pattern`` backtrack."""
    source = pattern.pattern.decode("latin-1") if isinstance(pattern.pattern, bytes) else pattern.pattern
    chars: set[str] = set()
    strings: set[str] = set()
    _alphabet(sre_parse.parse(source, pattern.flags & ~re.LOCALE), chars, strings)
    chars = {c for c in chars if ord(c) < 0x110000}
    alphabet = sorted(chars | set(_ODD))
    pumped: list[str] = sorted(strings) + sorted(chars)
    pairs = [a + b for a in sorted(chars) for b in alphabet]
    rng.shuffle(pairs)
    pumped += pairs[: pumps]
    pumped += ["".join(rng.choice(alphabet) for _ in range(3)) for _ in range(pumps // 4)]
    pumped += [s + c for s in sorted(strings) for c in sorted(chars)][: pumps // 2]
    suffixes = ["", "\x00", "!", "\n"]
    prefixes = ["", *sorted(strings)[:3]]
    out = []
    for pump in dict.fromkeys(pumped):
        for prefix in prefixes:
            for suffix in suffixes:
                out.append((prefix, pump, suffix))
    return out


def _encode(pattern: re.Pattern[Any], text: str) -> str | bytes:
    return text.encode("latin-1", "replace") if isinstance(pattern.pattern, bytes) else text


def check(pattern: re.Pattern[Any], size: int, factor: int, pumps: int, floor: float,
          rng: random.Random, mode: str = "search") -> tuple[float, str] | None:
    """The first superlinear growth found for ``pattern`` (ratio and the input), or ``None``.

    Each input grows by ``factor`` from a few characters up to ``size * factor`` (or until one
    search takes longer than ``_ENOUGH``: an exponential pattern shows itself at a few dozen
    characters, long before it would hang); growth past ``2 * factor`` from one size to the next,
    beyond the floor, is superlinear."""
    apply = pattern.search if mode == "search" else pattern.match
    for prefix, pump, suffix in inputs(pattern, pumps, rng):
        k, previous = max(1, 8 // len(pump)), None
        while True:
            text = _encode(pattern, prefix + pump * k + suffix)
            spent = best_time(functools.partial(apply, text), repeat=1 if previous and previous > 0.05 else 3)
            if previous is not None and spent > floor and spent / max(previous, floor) > 2 * factor:
                smaller = _encode(pattern, prefix + pump * (k // factor) + suffix)  # again: not a pause
                again = best_time(functools.partial(apply, text), 2) / \
                    max(best_time(functools.partial(apply, smaller), 3), floor)
                if again > 2 * factor:
                    return min(again, spent / max(previous, floor)), f"{prefix!r} + {pump!r} * {k} + {suffix!r}"
            if spent > _ENOUGH or len(pump) * k >= size * factor:
                break
            previous, k = spent, k * factor
    return None


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=2000, help="characters of the smaller input")
    parser.add_argument("--factor", type=int, default=4, help="the larger input is this many times the smaller")
    parser.add_argument("--pumps", type=int, default=60, help="pairs of characters tried per pattern")
    parser.add_argument("--floor", type=float, default=0.002, help="seconds below which time is noise")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--only", help="only patterns whose place contains this")
    parser.add_argument("--json", help="write the figures here")
    args = parser.parse_args(argv)
    rng = random.Random(args.seed)
    started = time.perf_counter()
    patterns = all_patterns()
    flagged = []
    tried = 0
    for where, pattern, mode in sorted(patterns.values(), key=lambda v: v[0]):
        if args.only and args.only not in where:
            continue
        tried += 1
        worst = check(pattern, args.size, args.factor, args.pumps, args.floor, rng, mode)
        if worst is not None:
            flagged.append({"where": where, "mode": mode, "pattern": str(pattern.pattern),
                            "growth": round(worst[0], 1), "input": worst[1]})
            print(f"SUPERLINEAR {where} ({mode}): x{worst[0]:.1f} at x{args.factor} the size: {pattern.pattern!r}\n"
                  f"    input: {worst[1]}", flush=True)
    figures = {"patterns": tried, "superlinear": len(flagged), "seconds": round(time.perf_counter() - started, 1),
               "size": args.size, "factor": args.factor, "flagged": flagged}
    print(json.dumps({k: v for k, v in figures.items() if k != "flagged"}))
    if args.json:
        Path(args.json).write_text(json.dumps(figures, indent=2) + "\n", encoding="utf-8")
    return 1 if flagged else 0


if __name__ == "__main__":
    sys.exit(main())
