"""One value model (issue 39, part C): a key is bound once (parameter ID and indices; an alias and
another kernel release's spelling through the release tables) and layered once (default list →
list, with origin); effective values, ``zero explain``, ``zero diff`` and the fleet are views of it.

Each disagreement the issue found is pinned through the real command line (a child process), on
a machine written here: an axis list that writes the older spelling ``antr_simu.zeitkonstante_z``
(P-AXIS-00239, renamed ``antr.simu.zeitkonstante_z``)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import zero_cli
from zero.catalog.registry import Registry
from zero.catalog.releases import table
from zero.catalog.values import ListValues, bind, slot_of
from zero.diff import spec_for
from zero.lists.model import parse_key
from zero.lists.tokenizer import tokenize_text
from zero.machine.effective import entries_of, own_entries, settings

OLD, NEW, PID = "antr_simu.zeitkonstante_z", "antr.simu.zeitkonstante_z", "P-AXIS-00239"


def _machine(root: Path, value: int = 10) -> Path:
    lists = root / "listen"
    lists.mkdir(parents=True, exist_ok=True)
    (lists / "hochlauf.lis").write_text(
        "konfiguration EIN_KANAL_KONFIGURIERUNG\nkanal_anzahl 1\nzahl_mds 1\n"
        "achs_mds[0] ./listen/achse_x.lis\nEnde\n")
    (lists / "achse_x.lis").write_text(f"kopf.achs_nr 1\nkopf.log_achs_name X\n{OLD} {value}\nEnde\n")
    return lists / "hochlauf.lis"


def test_explain_binds_an_older_spelling_as_show_does(tmp_path: Path) -> None:
    """`zero explain antr_simu.zeitkonstante_z --machine` answered "no list of the machine has or documents
    it" (exit 2) while `zero show --machine` binds the same key to P-AXIS-00239."""
    _machine(tmp_path)
    shown = zero_cli("show", "--machine", "listen/hochlauf.lis", cwd=tmp_path)
    assert shown.code == 0 and PID in shown.stdout and f"{NEW} = 10" in shown.stdout
    run = zero_cli("explain", OLD, "--machine", "listen/hochlauf.lis", cwd=tmp_path)
    assert run.code == 0, run.stderr
    assert "no list" not in run.stdout + run.stderr
    assert f"{NEW} = 10  {PID}" in run.stdout and "listen/achse_x.lis:3" in run.stdout
    assert "catalogue default" in run.stdout  # every layer, the catalogue's last
    today = zero_cli("explain", NEW, "--machine", "listen/hochlauf.lis", cwd=tmp_path)
    assert today.stdout == run.stdout  # either spelling asks about one parameter


def test_diff_binds_an_older_spelling_with_id_unit_and_delta(tmp_path: Path) -> None:
    """`zero diff A B` gave `"id": null`, no unit and no delta for the older spelling, while
    `zero show` and `zero diff --defaults` bound it (diff.spec_for had drifted from the binding)."""
    _machine(tmp_path / "a", 10)
    _machine(tmp_path / "b", 16)
    run = zero_cli("diff", "a/listen/achse_x.lis", "b/listen/achse_x.lis", "--output-format", "json", cwd=tmp_path)
    assert run.code in (0, 1), run.stderr
    (change,) = json.loads(run.stdout)
    assert (change["key"], change["id"], change["unit"], change["delta"]) == (NEW, PID, "s", 6)
    text = zero_cli("diff", "a/listen/achse_x.lis", "b/listen/achse_x.lis", cwd=tmp_path).stdout
    assert f"{NEW}  {PID}  10 → 16  +6 s" in text
    defaults = zero_cli("diff", "--defaults", "a/listen/achse_x.lis", cwd=tmp_path)
    assert PID in defaults.stdout and "+9 s" in defaults.stdout


def test_every_spelling_of_the_release_tables_binds_alike_everywhere(registry: Registry) -> None:
    """diff's binding, the effective values' and the rules' are one function: for every older
    spelling of the release tables, the key as diff binds it names the parameter the list's values
    bind (no view can drift again)."""
    checked = 0
    for row in table().renames:
        key = parse_key(row.old.replace("[]", "[0]"))
        if key is None or bind(registry, key.pattern, row.kind) is None:
            continue
        text = f"{key.text} 1\n"
        values = ListValues.of(tokenize_text(text, "t.lis"), registry, row.kind)
        (entry,) = values.doc.entries
        slot, spec = slot_of(registry, row.kind, entry)
        assert spec is not None and slot[0] == row.id
        assert spec_for(key.text, row.kind, registry) is spec
        assert spec_for(row.new.replace("[]", "[0]"), row.kind, registry) is spec
        assert values.value_of(spec.id, key.indices) is not None
        checked += 1
    assert checked >= 10


def test_the_fleet_and_effective_values_share_one_layering(registry: Registry) -> None:
    """A list's entries over its default list's: the same elements from `settings` (with origin) and
    `entries_of` (the fleet's and diff's view); the list's own entry wins, the default list fills in."""
    base = ListValues.of(tokenize_text(f"kopf.achs_nr 0\n{NEW} 3\nkenngr.swe_pos 100\n", "d.lis"), registry, "AXIS")
    top = ListValues.of(tokenize_text(f"kopf.achs_nr 1\n{OLD} 5\n", "a.lis"), registry, "AXIS")
    top.base = base
    layered = entries_of(top)
    with_origin = settings(top)
    assert {s.key: s.entry for s in with_origin.values()} == layered
    assert layered[NEW].value == "5" and layered["kenngr.swe_pos"].value == "100"
    assert set(own_entries(top)) == {"kopf.achs_nr", NEW}
    found: dict[int, dict[str, object]] = {}
    assert entries_of(top, found) == layered and id(base) in found  # a default list layered once


@pytest.mark.parametrize("asked", [OLD, NEW, PID])
def test_effective_values_answer_any_spelling(tmp_path: Path, registry: Registry, asked: str) -> None:
    from zero.machine.effective import effective
    from zero.machine.model import load_machine

    m = load_machine(_machine(tmp_path), registry)
    (scope,) = effective(m, [asked], explain=True)
    (value,) = scope.values
    assert (value.key, value.param_id, value.value) == (NEW, PID, "10")
    assert [o.source for _, o in value.layers] == ["list", "catalogue default"]


def test_the_language_server_hovers_an_older_spelling(registry: Registry) -> None:
    """The editor's hover bound a key by its documented spelling and alias only: over
    `antr_simu.zeitkonstante_z` it showed nothing, while lint (R013) and `zero show` bind it."""
    from zero.server import hover
    from zero.server.documents import Projects

    a = Projects(lambda _desc: registry).analyse("untitled:achsmds1.lis", 1, f"kopf.achs_nr 1\n{OLD} 10\n")
    h = hover.hover(a, 1, 3)
    assert h is not None and isinstance(h.contents, str) is False
    text = getattr(h.contents, "value", "")
    assert text.startswith(f"**{OLD}** — {PID}") and f"key      {NEW}" in text


def test_zero_param_binds_an_older_spelling(tmp_path: Path) -> None:
    """`zero param antr_simu.zeitkonstante_z` answered "unknown parameter" (did you mean the new one?)."""
    run = zero_cli("param", OLD, cwd=tmp_path)
    assert run.code == 0, run.stderr
    assert f"ID       {PID}" in run.stdout and f"key      {NEW}" in run.stdout


def test_the_language_server_completes_the_values_of_an_older_spelling(registry: Registry) -> None:
    """Value completion bound the key by its documented spelling and alias only: no values after
    `antr.sercos.reference_cam_signal` (today `antr.reference_cam_signal`), as zero show binds it."""
    from zero.server import completion
    from zero.server.documents import Projects

    key = "antr.sercos.reference_cam_signal"
    text = f"kopf.achs_nr 1\n{key} \n"
    a = Projects(lambda _desc: registry).analyse("untitled:achsmds1.lis", 1, text)
    labels = {i.label for i in completion.completion(a, 1, len(key) + 1, False).items}
    assert {"PLC", "RT_STATUS_BIT_1"} <= labels


def test_the_rules_values_and_the_effective_values_are_one_layering(registry: Registry) -> None:
    """On a machine with default lists under its axis and channel lists, every element the effective
    values show comes from the entry the rules read (`ListValues.value_of`: this list, else the default
    list under it), and its origin names that entry's list and line."""
    from conftest import FIXTURES
    from zero.machine.effective import LIST
    from zero.machine.model import load_machine

    m = load_machine(FIXTURES / "machine-layered" / "listen" / "hochlauf.lis", registry)
    compared = 0
    for _, lf in m.scopes():
        values = lf.values
        for (pid, indices), s in settings(values).items():
            if s.spec is None:
                continue
            res = values.value_of(pid, indices)
            assert res is not None and res.entry is s.entry, (lf.path, s.key)
            layer = values.layer_of(pid, indices)
            assert layer is not None and (s.origin.source == LIST) == (layer is values)
            assert s.origin.path == layer.doc.path and s.origin.line == layer.doc.file_line(s.entry.line)
            compared += 1
    assert compared > 20 and any(lf.values.base is not None for _, lf in m.scopes())


# Where a key is looked up in the catalogue by hand, and why that is no second binding.
_OWN_LOOKUPS = {
    "catalog/values.py": "the binding itself",
    "catalog/registry.py": "the look-ups the binding is made of",
    "catalog/releases.py": "the release tables the binding reads (a rename's target must be documented)",
    "rules/registry.py": "R001/R003/R013 tell a documented key, an alias and another release's spelling apart",
    "rules/syntax.py": "whether a key is known in any list kind (S rules)",
    "machine/model.py": "whether a file is a parameter list at all (any kind)",
    "markup/lists.py": "an XML element's ID for a key (the documented spelling only, by design)",
    "structured/tree.py": "a value's native type in YAML/TOML/JSON (the documented spelling)",
    "structured/formats.py": "a float for an integer parameter (the documented spelling)",
    "structured/schema.py": "the schema of the documented keys",
    "output/docs.py": "parameter pages of the documented keys",
}


def test_no_module_binds_a_key_by_hand_where_a_value_is_read() -> None:
    """A reader of values (diff, effective values, explain, param, hover, completion, the fleet) binds
    through `bind`; a hand-made `by_pattern(...) or alias(...)` drifted from it before (diff.spec_for)."""
    from conftest import ROOT

    src = ROOT / "src" / "zero"
    for path in src.rglob("*.py"):
        rel = path.relative_to(src).as_posix()
        text = path.read_text(encoding="utf-8")
        if ".by_pattern(" in text or ".alias(" in text:
            assert rel in _OWN_LOOKUPS, f"{rel}: bind a key with zero.catalog.values.bind"
