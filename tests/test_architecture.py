"""The layers of zero, held by a test: imports flow one way, and there is no import circle.

Every ``import``/``from … import`` of a zero module counts, also inside functions and
under ``TYPE_CHECKING``. Each package (or foundation module) may import only the
components listed for it; an import inside a function must say why (``# start-up``).
"""

from __future__ import annotations

import ast
from pathlib import Path

from conftest import ROOT

SRC = ROOT / "src"

# component → the components it may import (besides itself)
# foundation: zero (version), zero.errors, zero.records, zero.record_inits(_rest), zero.hints, zero.diagnostics,
# zero.files, zero.forms, zero.patterns (with zero.pattern_codes), zero.bundles (with zero.bundled_modules),
# zero.nearest
FOUNDATION = "foundation"
ALLOWED: dict[str, set[str]] = {
    FOUNDATION: set(),
    "lists": {FOUNDATION},
    "catalog": {FOUNDATION, "lists"},
    "structured": {FOUNDATION, "lists", "catalog"},
    "markup": {FOUNDATION, "lists", "catalog"},
    "machine": {FOUNDATION, "lists", "catalog", "markup"},
    "nc": {FOUNDATION, "lists", "catalog"},
    "diff": {FOUNDATION, "lists", "catalog", "structured", "markup"},
    "rules": {FOUNDATION, "lists", "catalog", "machine", "nc"},
    "engine": {FOUNDATION, "lists", "catalog", "structured", "markup", "machine", "nc", "diff", "rules"},
    "output": {FOUNDATION, "lists", "catalog", "machine", "diff", "rules", "engine"},
    "server": {FOUNDATION, "lists", "catalog", "structured", "markup", "machine", "nc", "diff", "rules", "engine",
               "output"},
    "cli": {FOUNDATION, "lists", "catalog", "structured", "markup", "machine", "nc", "diff", "rules", "engine",
            "output", "server"},
}


def module_name(path: Path) -> str:
    parts = list(path.relative_to(SRC).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


MODULES = {module_name(p): p for p in (SRC / "zero").rglob("*.py")}


def component(module: str) -> str:
    parts = module.split(".")
    if len(parts) == 1 or parts[1] in ("errors", "records", "record_inits", "record_inits_rest", "hints",
                                       "diagnostics", "files", "forms", "patterns", "pattern_codes", "bundles",
                                       "bundled_modules", "nearest", "__main__"):
        return FOUNDATION if parts[-1] != "__main__" else "cli"
    return parts[1]


def imports(module: str) -> list[tuple[str, int, bool, str]]:
    """(imported zero module, line, inside a function, source line) for one module."""
    path = MODULES[module]
    text = path.read_text(encoding="utf-8")
    lines = text.split("\n")
    tree = ast.parse(text)
    inside: set[int] = set()
    for fn in ast.walk(tree):
        if isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)):
            inside.update(id(n) for n in ast.walk(fn) if isinstance(n, (ast.Import, ast.ImportFrom)))
    out = []
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    for node in ast.walk(tree):
        targets: list[str] = []
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:  # a relative import: resolved against the module's package
                parts = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*parts, base] if base else parts)
            for alias in node.names:
                sub = f"{base}.{alias.name}"
                targets.append(sub if sub in MODULES else base)
        for t in targets:
            if t == "zero" or t.startswith("zero."):
                out.append((t, node.lineno, id(node) in inside, lines[node.lineno - 1]))
    return out


GRAPH = {m: sorted({t for t, *_ in imports(m) if t != m}) for m in MODULES}


def test_the_modules_are_found() -> None:
    assert len(MODULES) > 40
    assert {component(m) for m in MODULES} == set(ALLOWED)


def test_no_module_imports_a_layer_above_it() -> None:
    wrong = [f"{m} imports {t} ({component(m)} may import {sorted(ALLOWED[component(m)])})"
             for m, targets in GRAPH.items() for t in targets
             if component(t) != component(m) and component(t) not in ALLOWED[component(m)]]
    assert wrong == []


def _cycles(graph: dict[str, list[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan), or a self-import."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    out: list[list[str]] = []
    counter = [0]

    def visit(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in graph.get(v, []):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            scc = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                scc.append(w)
                if w == v:
                    break
            if len(scc) > 1:
                out.append(sorted(scc))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return out


def test_no_import_circle_counting_imports_inside_functions() -> None:
    assert _cycles(GRAPH) == []


def test_the_circle_detector_finds_a_circle() -> None:
    assert _cycles({"a": ["b"], "b": ["c"], "c": ["a"], "d": ["a"]}) == [["a", "b", "c"]]


def test_layers_do_not_import_each_other_in_a_circle() -> None:
    layers: dict[str, set[str]] = {}
    for m, targets in GRAPH.items():
        layers.setdefault(component(m), set()).update(component(t) for t in targets if component(t) != component(m))
    assert _cycles({k: sorted(v) for k, v in layers.items()}) == []


def test_imports_inside_functions_say_why() -> None:
    """An import inside a function is there for start-up time, and its line says so."""
    silent = []
    for path in MODULES.values():
        text = path.read_text(encoding="utf-8")
        lines = text.split("\n")
        for fn in ast.walk(ast.parse(text)):
            if isinstance(fn, (ast.FunctionDef, ast.AsyncFunctionDef)):
                for node in ast.walk(fn):
                    if isinstance(node, (ast.Import, ast.ImportFrom)) and "start-up" not in lines[node.lineno - 1]:
                        silent.append(f"{path.relative_to(SRC)}:{node.lineno}: {lines[node.lineno - 1].strip()}")
    assert silent == []


def test_the_registry_is_passed_in_never_fetched_from_a_global() -> None:
    """Below the command line nothing loads a registry of its own."""
    loaders = [f"{m}:{line}" for m in MODULES if component(m) != "cli"
               for t, line, _, src in imports(m) if "load_registry" in src and m != "zero.catalog.registry"]
    assert loaders == []
    assert "default_registry" not in (SRC / "zero" / "catalog" / "registry.py").read_text(encoding="utf-8")


def test_one_error_type() -> None:
    """Every layer raises zero.errors.ZeroError; no other exception class is defined."""
    classes = [f"{module_name(p)}.{node.name}" for p in MODULES.values()
               for node in ast.walk(ast.parse(p.read_text(encoding="utf-8")))
               if isinstance(node, ast.ClassDef)
               and any(getattr(b, "id", getattr(b, "attr", "")).endswith(("Error", "Exception")) for b in node.bases)]
    assert classes == ["zero.errors.ZeroError"]


def readme_tree() -> set[str]:
    """The files of the layout tree in the architecture page (``src/zero/`` block), as paths below
    ``src/zero``."""
    page = (ROOT / "docs" / "contributing" / "architecture.md").read_text(encoding="utf-8")
    block = page.split("src/zero/\n", 1)[1].split("```", 1)[0]
    out: set[str] = set()
    folders: dict[int, str] = {0: ""}  # depth → the folder a line at the next depth is in
    for line in block.splitlines():
        name = line.strip().split(" ", 1)[0]
        depth = (len(line) - len(line.lstrip(" "))) // 2
        if depth < 1 or depth - 1 not in folders:
            continue  # a line that goes on the one above it
        folders = {d: f for d, f in folders.items() if d < depth}
        out.add(folders[depth - 1] + name.rstrip("/"))
        if name.endswith("/"):
            folders[depth] = folders[depth - 1] + name
    return out


def test_the_readme_layout_matches_the_tree() -> None:
    shown = readme_tree()
    data = SRC / "zero" / "catalog" / "data"  # generated tables: the README's `data/` line names them
    actual = {str(p.relative_to(SRC / "zero")) for p in MODULES.values()
              if (p.name != "__init__.py" or p.parent == SRC / "zero") and p.parent != data}
    actual |= {str(p.relative_to(SRC / "zero")) for p in (SRC / "zero").iterdir() if (p / "__init__.py").is_file()}
    actual |= {str(p.parent.relative_to(SRC / "zero")) for p in MODULES.values()  # packages in packages
               if p.name == "__init__.py" and p.parent.parent != SRC / "zero" and p.parent != SRC / "zero"}
    actual.add("catalog/data")
    assert shown == actual


RESOLVER = "zero.engine.project"
# name → the module that defines it: only the resolver may use it (issue 22: the machine was loaded,
# and the configuration read, in six places that disagreed)
RESOLVED_ONLY = {"load_machine": "zero.machine.model", "ConfigFinder": "zero.engine.config",
                 "parse_config": "zero.engine.config"}


def _names_used(path: Path) -> set[str]:
    """Every name a module imports or refers to (``x`` and ``m.x``)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            out.update(a.name for a in node.names)
        elif isinstance(node, ast.Name):
            out.add(node.id)
        elif isinstance(node, ast.Attribute):
            out.add(node.attr)
    return out


def test_only_the_resolver_loads_a_machine_or_reads_configuration() -> None:
    """No command, no server module, no other engine module answers "which configuration, which
    machine" on its own: they ask zero.engine.project."""
    wrong = sorted(f"{m} uses {name}" for m, path in MODULES.items() if m != RESOLVER
                   for name in _names_used(path) & set(RESOLVED_ONLY) if RESOLVED_ONLY[name] != m)
    assert wrong == []
    assert set(RESOLVED_ONLY) <= _names_used(MODULES[RESOLVER]) | {"parse_config"}


def test_the_architecture_check_sees_a_machine_loaded_elsewhere(tmp_path: Path) -> None:
    bad = tmp_path / "bad.py"
    bad.write_text("from zero.machine.model import load_machine\nm = load_machine(p, r)\n")
    assert "load_machine" in _names_used(bad)


GIT_MODULE = "zero.engine.git"
# What starts another program: only the one module that runs git may (issue 43: git was run in two
# places with two sets of protections, and one of them let a repository run a command).
SPAWNERS = {"subprocess", "pty", "system", "popen", "spawnl", "spawnle", "spawnlp", "spawnlpe", "spawnv", "spawnve",
            "spawnvp", "spawnvpe", "execl", "execle", "execlp", "execlpe", "execv", "execve", "execvp", "execvpe",
            "posix_spawn", "posix_spawnp", "startfile"}


def _spawns(path: Path) -> set[str]:
    """The ways of starting a program a module imports or calls (``import subprocess``,
    ``os.system``, ``os.posix_spawn``, ...)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out.update(a.name.split(".")[0] for a in node.names if a.name.split(".")[0] in SPAWNERS)
        elif isinstance(node, ast.ImportFrom) and node.module is not None:
            if node.module.split(".")[0] in SPAWNERS:
                out.add(node.module)
            out.update(a.name for a in node.names if node.module == "os" and a.name in SPAWNERS)
        elif isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "os" \
                and node.attr in SPAWNERS:
            out.add(f"os.{node.attr}")
    return out


def test_only_the_git_module_starts_a_program() -> None:
    """Every git call goes through zero.engine.git, with its one set of protections: no other module
    imports subprocess or calls os.system, os.popen, os.exec*, os.spawn* or os.posix_spawn*."""
    wrong = sorted(f"{m}: {', '.join(sorted(found))}" for m, path in MODULES.items() if m != GIT_MODULE
                   if (found := _spawns(path)))
    assert wrong == []
    assert "subprocess" in _spawns(MODULES[GIT_MODULE])


def test_the_architecture_check_sees_a_program_started_elsewhere(tmp_path: Path) -> None:
    for text in ("import subprocess\n", "from subprocess import run\n", "import os\nos.system('git status')\n",
                 "from os import posix_spawn\n", "def f():\n    import subprocess  # start-up\n"):
        bad = tmp_path / "bad.py"
        bad.write_text(text)
        assert _spawns(bad), text


# --------------------------------------------------------------------- issue 39: one answer, one path


def _calls(path: Path, name: str) -> list[int]:
    """The lines where a module calls ``name(...)`` or ``x.name(...)``."""
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Call):
            f = node.func
            if (isinstance(f, ast.Name) and f.id == name) or (isinstance(f, ast.Attribute) and f.attr == name):
                out.append(node.lineno)
    return out


def test_a_project_is_made_only_by_open_project() -> None:
    """The resolver of a run is made in one place (zero.engine.project.open_project, ruff's
    ``resolve``); every command and the server get theirs from it (issue 39: it was made in eight)."""
    made = sorted(f"{m}:{line}" for m, path in MODULES.items() for line in _calls(path, "Project") if m != RESOLVER)
    assert made == []
    assert len(_calls(MODULES[RESOLVER], "Project")) == 1


def test_the_architecture_check_sees_a_project_made_elsewhere(tmp_path: Path) -> None:
    bad = tmp_path / "bad.py"
    bad.write_text("from zero.engine import project\np = project.Project(r)\nq = Project(r, isolated=True)\n")
    assert _calls(bad, "Project") == [2, 3]


# What only the engine does: linting, running git, comparing machines and fleets, making the resolver.
ORCHESTRATION = {"lint_machine", "lint_file", "lint_data", "lint_bytes", "lint_document", "lint_program", "lint_many",
                 "iter_lint_many", "run_lint", "run_format", "run_fleet", "fleet_drift", "revision_reader",
                 "machine_changes", "program_travel_of", "run_diff", "run_effective", "run_limits", "report_facts",
                 "open_project", "Project", "load_machine"}
# output/docs.py lints each rule's examples for the documentation site (the docs' own build step);
# the one module of output/ allowed to, until that build step moves into the engine.
RENDERS_AND_LINTS = {"zero.output.docs"}


def test_output_only_renders() -> None:
    """output/ lays out what the engine found; it lints nothing, runs no git, compares no machine and
    makes no resolver (issue 39: output/report.py linted the machine and ran git, output/fleet.py ran
    the fleet comparison)."""
    wrong = sorted(f"{m} uses {name}" for m, path in MODULES.items()
                   if component(m) == "output" and m not in RENDERS_AND_LINTS
                   for name in _names_used(path) & ORCHESTRATION)
    assert wrong == []


def test_the_command_line_builds_no_json() -> None:
    """The JSON of every command is written by output/ (issue 39: cli/app.py built it inline)."""
    wrong = sorted(f"{m}:{line}" for m, path in MODULES.items() if component(m) == "cli"
                   for line in _calls(path, "dumps"))
    allowed = {f"zero.cli.run:{line}" for line in _calls(MODULES["zero.cli.run"], "dumps")
               if "command_line_config" in _function_at(MODULES["zero.cli.run"], line)}
    assert sorted(set(wrong) - allowed) == []


def _function_at(path: Path, line: int) -> str:
    """The name of the top-level function that holds ``line``."""
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.FunctionDef) and node.lineno <= line <= (node.end_lineno or node.lineno):
            return node.name
    return ""


def test_every_command_that_reads_lists_takes_the_common_options() -> None:
    """--config, --isolated, --param-desc and --kernel, declared once, on every command that reads
    lists (issue 39: only lint, format and config had --config)."""
    import typer.main

    from zero.cli.app import app

    group = typer.main.get_command(app)
    for name in ("lint", "format", "show", "explain", "diff", "limits", "convert", "report", "config"):
        command = group.commands[name]  # type: ignore[attr-defined]
        names = {o for p in command.params for o in getattr(p, "opts", ())}
        assert {"--config", "--isolated", "--param-desc", "--kernel"} <= names, name


def test_the_command_line_is_thin() -> None:
    """The typer commands say which parameters they take and hand over; the help is cli/help.py's."""
    assert "def help_text" not in MODULES["zero.cli.app"].read_text(encoding="utf-8")
    assert len(MODULES["zero.cli.app"].read_text(encoding="utf-8").splitlines()) < 800
