"""`zero lint --add-noqa`: today's findings recorded in the lists' own comment syntax."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from conftest import zero_cli


@pytest.mark.slow
def test_a_baseline_of_the_vendor_lists_hides_todays_findings_and_keeps_their_meaning(
        tmp_path: Path, corpus: Path) -> None:
    lists = tmp_path / "listen"
    shutil.copytree(corpus / "isg-sdk" / "listen", lists)
    before = json.loads(zero_cli("lint", "--output-format", "json", str(lists)).stdout)
    assert len(before) > 30
    run = zero_cli("lint", "--add-noqa", str(lists))
    assert run.code == 0, run
    assert "noqa directives added" in run.stderr
    assert json.loads(zero_cli("lint", "--output-format", "json", str(lists)).stdout) == []
    for original in sorted((corpus / "isg-sdk" / "listen").rglob("*.lis")):
        copy = lists / original.relative_to(corpus / "isg-sdk" / "listen")
        same = zero_cli("diff", "--strict", str(original), str(copy))  # values as the controller reads them
        assert same.code == 0, (copy, same.stdout)
    again = zero_cli("lint", "--add-noqa", str(lists))
    assert again.code == 0 and "added" not in again.stderr  # nothing left to record


def test_noqa_goes_into_the_comment_or_opens_one(tmp_path: Path) -> None:
    f = tmp_path / "a.lis"
    f.write_bytes(b"kopf.log_achs_name X_Achse\nkenngr.swe_pso 1 # typo\n#Achse neu\nEnde\n")
    run = zero_cli("lint", "--add-noqa", "--kind", "axis", str(f))
    assert f.read_bytes() == (b"kopf.log_achs_name X_Achse\nkenngr.swe_pso 1 # typo  noqa: R001 -- baseline\n"
                              b"#Achse neu\nEnde\n")
    assert "1 finding on lines without an entry cannot be recorded" in run.stderr  # the S005 on line 3
