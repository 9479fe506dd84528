"""Deterministic workloads shared by the benchmark scripts (no randomness, no files needed), and the
cached bytecode every script readies before it measures."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

HEADER = [
    "# ****************************************",
    "# zero-offset list (generated for benchmarks)",
    "# ****************************************",
    "#",
]


def full_zero_list() -> bytes:
    """97 groups x 32 axes x (versch, inaktiv) = 6,208 entries (+2), vendor layout, all comment styles."""
    lines = [*HEADER, "g53_verfuegbar".ljust(54) + "1", "default_index".ljust(54) + "1"]
    for i in range(97):
        lines.append(f"# G159 = {i}")
        for j in range(32):
            lines.append(f"np_grp[{i}].achse[{j}].versch".ljust(54)
                         + f"{i * 1000 + j}".ljust(14) + "( P-ZERO-00003 : offset")
            style = ("# active", "/* 0 */ ( on", "( P-ZERO-00004")[j % 3]
            lines.append(f"np_grp[{i}].achse[{j}].inaktiv".ljust(54) + "0".ljust(14) + style)
    lines.append("Ende")
    return ("\n".join(lines) + "\n").encode()


def million_entries(n: int = 1_000_000) -> bytes:
    """n entries with distinct keys: zero offsets in many groups, axis-like and tool-like keys."""
    lines = [*HEADER]
    shapes = (
        lambda k: (f"np_grp[{k // 64}].achse[{k % 32}].{'versch' if k % 64 < 32 else 'inaktiv'}", str(k)),
        lambda k: (f"getriebe[{k}].dynamik.vb_max", "0x400001"),
        lambda k: (f"wz[{k}].kopf.name", "PLC_INFO | MOS"),
        lambda k: (f"lr_param[{k}].kv", "P-AXIS-00212.0"),
    )
    for k in range(n):
        key, value = shapes[k % 4](k)
        comment = "  ( P-ZERO-00003 : offset" if k % 10 == 0 else ""
        lines.append(key.ljust(54) + value + comment)
    lines.append("Ende")
    return ("\n".join(lines) + "\n").encode()


def axis_list(entries: int = 577) -> bytes:
    """An axis list shaped like the vendor's: header, sections, aligned `( P-AXIS-…` comments,
    blank lines; keys and values from the registry (defaults), so it lints clean."""
    from zero.catalog.registry import load_registry
    from zero.catalog.values import default_number
    from zero.engine.lint import lint_bytes

    reg = load_registry()
    lines = ["# ****************************************", "#", "# Axis Parameter (generated)", "#",
             "# ****************************************", "#"]
    count = 0
    section = ""
    for spec in sorted(reg.specs.values(), key=lambda s: (s.key or "", s.id)):
        if spec.kind != "AXIS" or not spec.key or spec.type == "STRING":
            continue
        n = default_number(spec)
        if n is None or isinstance(n, float):
            continue
        key = spec.key.replace("[]", "[0]")
        probe = f"{key} {n}\nEnde\n".encode()
        if lint_bytes(probe, reg, "achsmds.lis").diagnostics:
            continue
        first = key.split(".", 1)[0]
        if first != section:
            section = first
            lines += ["", f"# ---------------------------------------------- {section}"]
        lines.append(key.ljust(54) + str(n).ljust(15) + f"( {spec.id} : {spec.quantity or 'value'}")
        count += 1
        if count == entries:
            break
    lines.append("Ende")
    data = ("\n".join(lines) + "\n").encode()
    bad = {d.span.line for d in lint_bytes(data, reg, "achsmds.lis").diagnostics}
    kept = [x for n, x in enumerate(lines, 1) if n not in bad]  # cross-parameter findings
    return ("\n".join(kept) + "\n").encode()


def small_list(i: int) -> bytes:
    """One of many small files: a clamp-offset list of 3 groups x 3 axes."""
    lines = ["# clamp offsets", *[f"pzv_grp[{g}].achse[{a}].versatz".ljust(54) + str((i * 7 + g * 3 + a) % 5000)
                                  for g in range(3) for a in range(3)], "Ende"]
    return ("\n".join(lines) + "\n").encode()


def ready_bytecode(python: str, package: Path) -> None:
    """Compile zero's modules and write its bundles (``zero.bundles``), as an installed zero has them after
    its first run: a work tree under ``PYTHONDONTWRITEBYTECODE`` would otherwise compile every edited module
    at every start and measure that instead. Forced (``-f``): compileall takes a cached file for current
    when its source's time matches to the second, and the import system, which also checks the size, then
    compiles a source edited within that second at every start."""
    subprocess.run([python, "-m", "compileall", "-q", "-f", str(package)], check=False, stdout=subprocess.DEVNULL)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    subprocess.run([python, "-m", "zero.bundles"], check=False, env={**env, "PYTHONPATH": str(package.parent)})
