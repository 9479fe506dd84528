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
