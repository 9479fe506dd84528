"""The README fits on a screen or two and every link in it resolves (issue 28)."""

from __future__ import annotations

import re

from conftest import ROOT

README = (ROOT / "README.md").read_text(encoding="utf-8")


def test_the_readme_is_short() -> None:
    assert len(README.splitlines()) < 200


def test_every_link_in_the_readme_resolves() -> None:
    links = re.findall(r"\]\(([^)\s]+)\)", README)
    assert len(links) >= 10
    for link in links:
        target = link.split("#", 1)[0]
        if re.match(r"[a-z]+://", link):
            assert link.startswith("https://"), link
            continue
        assert target and (ROOT / target).is_file(), link


def test_the_quick_start_is_two_commands() -> None:
    section = README.split("## Quick start", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```sh\n(.*?)```", section, re.S)
    assert [b.strip().count("\n") for b in blocks] == [0, 0]
    assert "zero lint fixtures/seed/nullp_3achsen.lis" in blocks[0] and "pytest" in blocks[1]


def readme_test_command() -> str:
    """The README's test command: its first ``sh`` block that runs pytest (as the before-stop check reads it)."""
    blocks = re.findall(r"```(?:sh|bash|console)?\n(.*?)```", README, re.S)
    return next(b.strip() for b in blocks if "pytest" in b)


def test_ci_runs_the_readmes_test_command_verbatim() -> None:
    """CI runs exactly what a new user runs (issue 35): extra tools are installed in steps before it."""
    command = readme_test_command()
    assert command == "python3 -m venv .venv && .venv/bin/pip install -e '.[test]' && .venv/bin/python -m pytest"
    lines = [line.strip() for line in (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()]
    assert command in lines, "the README's test command is not a line of .ci/run"
    assert lines[-1] == command, "the README's test command is not the last step of .ci/run"


def test_the_sample_report_is_what_zero_prints() -> None:
    """The README's report of the quick-start list is zero's output today (severities follow the evidence)."""
    import os
    import subprocess
    import sys

    block = README.split("## What a report looks like", 1)[1].split("```text\n", 1)[1].split("```", 1)[0]
    run = subprocess.run([sys.executable, "-m", "zero", "lint", "fixtures/seed/nullp_3achsen.lis"], cwd=ROOT,
                         capture_output=True, text=True, timeout=120, env={**os.environ, "NO_COLOR": "1"},
                         check=False)
    assert block in run.stdout
    quick = README.split("## Quick start", 1)[1].split("```sh", 1)[0]
    assert ("exits 1" in quick) == (run.returncode == 1), quick  # the quick start says how it ends
