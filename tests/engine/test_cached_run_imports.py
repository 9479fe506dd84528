"""A run whose every result comes from the cache imports no rule, no tokenizer and no value model (issue 40:
the same fleet again): its results, options and report need none of them."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from conftest import zero_modules

LINT_PATH = ("zero.rules", "zero.lists.tokenizer", "zero.catalog.values", "zero.engine.lint", "zero.engine.parallel")

def _run(folder: Path) -> tuple[str, set[str]]:
    env = {**os.environ, "ZERO_CACHE_DIR": str(folder / "cache")}
    env.pop("ZERO_NO_CACHE", None)
    report, modules, _ = zero_modules("lint", "--exit-zero", "--output-format", "json", "lists", cwd=folder, env=env)
    return report, modules


@pytest.mark.parametrize("config", [None, 'extend-select = ["M"]\nignore = ["R003"]\n'])
def test_a_cached_run_imports_no_rule_and_no_tokenizer(tmp_path: Path, config: str | None) -> None:
    lists = tmp_path / "lists"
    lists.mkdir()
    if config is not None:  # its selection is made over the written rule table
        (tmp_path / "zero.toml").write_text(config, encoding="utf-8")
    for n in range(3):
        (lists / f"achse{n}.lis").write_text(f"kopf.achs_nr {n + 1}\nkenngr.swe_pos 5000000000\nEnde\n",
                                             encoding="utf-8")
    old = time.time() - 60  # results are kept only for files last changed well before the run
    for f in lists.iterdir():
        os.utime(f, (old, old))
    first, loaded = _run(tmp_path)
    assert '"code"' in first  # findings: the files were linted, with the rules
    assert {"zero.rules", "zero.lists.tokenizer", "zero.engine.lint"} <= loaded
    again, loaded = _run(tmp_path)
    assert again == first
    assert not [m for m in loaded if m.startswith(LINT_PATH)], sorted(m for m in loaded if m.startswith(LINT_PATH))
    assert "zero.engine.results" in loaded and "zero.engine.cache" in loaded
