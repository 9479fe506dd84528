"""What an editor may set for the language server (``initializationOptions`` or
``workspace/didChangeConfiguration``, section ``zero``), and what it sends that is its own."""

from __future__ import annotations

from zero.records import Record

CLIENT_KEYS = ("path", "args", "trace")  # the editor extension's own settings, sent along


class Settings(Record):
    """What the editor may set (``initializationOptions`` or ``workspace/didChangeConfiguration``,
    section ``zero``)."""

    debounce: float = 0.25  # seconds of quiet after a change before the document is linted again
    rule_docs: str | None = None  # URL of a rule's text, `{code}` replaced; None: rendered files
    structured: str = "zero"  # "zero": YAML/TOML/JSON with a `_zero` record or matched by `include`; "all"
    machine: bool = True  # X findings and NC program checks against [tool.zero.machine]
    max_findings: int = 2000  # findings published per document, then one summary finding; 0: all

    def update(self, given: object) -> list[str]:
        """Take the known keys of a settings object; the names of values that were refused."""
        if not isinstance(given, dict):
            return []
        given = given.get("zero", given) if isinstance(given.get("zero"), dict) else given
        refused = []
        for key, value in given.items():
            if key in CLIENT_KEYS:
                continue
            if key == "debounce" and isinstance(value, (int, float)) and not isinstance(value, bool) \
                    and 0 <= value <= 10_000:
                self.debounce = value / 1000
            elif key == "ruleDocs" and (value is None or (isinstance(value, str) and "{code}" in value)):
                self.rule_docs = value or None
            elif key == "structured" and value in ("zero", "all"):
                self.structured = value
            elif key == "machine" and isinstance(value, bool):
                self.machine = value
            elif key == "maxFindings" and isinstance(value, int) and not isinstance(value, bool) \
                    and 0 <= value <= 10_000_000:
                self.max_findings = value
            else:
                refused.append(key)
        return refused
