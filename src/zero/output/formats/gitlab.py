"""``--output-format gitlab``: GitLab's code quality report."""

from __future__ import annotations

import json
import os
from collections.abc import Sequence

from zero.diagnostics import Severity
from zero.engine.results import LintResult
from zero.output.formats.common import fingerprints, repo_path

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from typing import TextIO


def render_gitlab(results: Sequence[LintResult], stream: TextIO) -> None:
    """GitLab code quality report (a JSON array of issues), paths relative to the repository:
    to ``$CI_PROJECT_DIR`` where GitLab sets it (a job run from a subfolder keeps the prefix),
    else to the working directory; the fingerprint is :func:`fingerprints`'."""
    severity = {Severity.ERROR: "major", Severity.WARNING: "minor", Severity.INFO: "info"}
    root = os.environ.get("CI_PROJECT_DIR") or None
    out = []
    for r in results:
        for d, fp in zip(r.diagnostics, fingerprints(r, root), strict=True):
            out.append({"description": f"{d.code} {d.message}", "check_name": d.code, "fingerprint": fp,
                        "severity": severity[d.severity],
                        "location": {"path": repo_path(d.path, root),
                                     "lines": {"begin": d.span.line, "end": d.span.end_line}}})
    stream.write(json.dumps(out, indent=2) + "\n")
