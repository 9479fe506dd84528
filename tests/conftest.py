"""Shared test helpers: the corpus location and small lint shortcuts."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from zero.lint import LintOptions, LintResult, lint_bytes

ROOT = Path(__file__).resolve().parent.parent
FIXTURES = ROOT / "fixtures"


def corpus_dir() -> Path:
    env = os.environ.get("ZERO_CORPUS")
    return Path(env) if env else ROOT.parent / "shared" / "corpus"


@pytest.fixture(scope="session")
def corpus() -> Path:
    """The real-world corpus; skipped where absent, a failure in CI (CI=true)."""
    path = corpus_dir()
    if not (path / "isg-sdk" / "listen").is_dir():
        reason = f"corpus not found at {path} (set ZERO_CORPUS)"
        if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
            pytest.fail(f"CI must run the corpus tests: {reason}")
        pytest.skip(reason)
    return path


def lint_text(text: str | bytes, path: str = "t.lis", **options: object) -> LintResult:
    data = text.encode("utf-8") if isinstance(text, str) else text
    return lint_bytes(data, path, options=LintOptions(**options))  # type: ignore[arg-type]


def codes(result: LintResult) -> list[str]:
    return [d.code for d in result.diagnostics]


def findings(result: LintResult) -> list[dict[str, object]]:
    """The golden form of findings: location, code and severity."""
    keep = ("line", "column", "end_line", "end_column", "code", "severity")
    return [{k: d.to_json()[k] for k in keep} for d in result.diagnostics]


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-golden", action="store_true",
                     help="rewrite the expected findings of the golden fixtures")


def golden(path: Path, actual: object, update: bool) -> object:
    if update:
        path.write_text(json.dumps(actual, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    return json.loads(path.read_text(encoding="utf-8"))
