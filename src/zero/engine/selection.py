"""Which rules run on a file: the selection of the command line and the configuration's layers, as ruff
resolves it, over every rule's code, declared severity and opt-in flag (:func:`rule_table`).

The table is read from :mod:`zero.catalog.data.rule_codes` (written by ``tools/gen_rule_codes.py``) while it
was written from the rule modules as they are, else from the registry (``zero.rules.RULES``): a run whose
every result comes from the cache (:mod:`zero.engine.cache`, which keys a file's results by its options)
thus imports no rule module.
"""

from __future__ import annotations

import os
from collections.abc import Sequence

from zero.diagnostics import Severity
from zero.engine.results import LintOptions

_TABLE: dict[str, tuple[Severity, bool]] = {}  # code → (declared severity, opt-in), in the registry's order


def rule_sources() -> tuple[tuple[str, int], ...]:
    """The name and size of every module of zero/rules/ (what the written table was read from)."""
    folder = os.path.join(os.path.dirname(os.path.dirname(__file__)), "rules")
    with os.scandir(folder) as it:
        return tuple(sorted((e.name, e.stat().st_size) for e in it if e.name.endswith(".py")))


def _written() -> dict[str, tuple[Severity, bool]] | None:
    """The table as tools/gen_rule_codes.py wrote it; ``None`` where a rule module is not the one it was
    written from (or cannot be looked at)."""
    from zero.catalog.data.rule_codes import CODES, SOURCES  # start-up: the table only when a selection is made

    try:
        if rule_sources() != SOURCES:
            return None
    except OSError:
        return None
    by_name = {s.name: s for s in Severity}  # a dictionary's look-up, not the enum's per code
    return {code: (by_name[severity], opt_in) for code, severity, opt_in in CODES}


def _imported() -> dict[str, tuple[Severity, bool]]:
    from zero.rules import RULES  # start-up: only where the written table is stale

    return {code: (r.severity, r.opt_in) for code, r in RULES.items()}


def rule_table() -> dict[str, tuple[Severity, bool]]:
    """Every rule's code → (its declared severity, is it opt-in), in the registry's order; read once."""
    if not _TABLE:
        _TABLE.update(_written() or _imported())
    return _TABLE


def known_code(prefix: str) -> bool:
    """Does a code or prefix match a rule (``ALL``: every rule, as in ruff)?"""
    return prefix == ALL or any(code.startswith(prefix) for code in rule_table())


_selected: dict[tuple[object, ...], dict[str, Severity]] = {}


def selected_rules(options: LintOptions) -> dict[str, Severity]:
    """Code → severity of every rule the options enable (longest prefix wins); memoised."""
    key = (options.select, options.ignore, options.extend_select, tuple(sorted(options.severity.items())))
    hit = _selected.get(key)
    if hit is None:
        hit = _selected[key] = _selected_rules(options)
    return hit


ALL = "ALL"  # as in ruff: every rule, opt-in ones included, the least specific selector

_PREFIX_FREE: list[tuple[dict[str, tuple[Severity, bool]], bool]] = []  # (the rule table, is it prefix-free)


def _prefix_free(table: dict[str, tuple[Severity, bool]]) -> bool:
    """Whether no code of ``table`` (:func:`rule_table`'s) begins another: a selector naming a code then
    matches that code alone. Worked out once per table."""
    if not _PREFIX_FREE or _PREFIX_FREE[0][0] is not table:
        codes = sorted(table)  # a code that begins another sorts right before it, or before one it begins
        _PREFIX_FREE[:] = [(table, not any(map(str.startswith, codes[1:], codes)))]  # b.startswith(a), in C
    return _PREFIX_FREE[0][1]


class _Default:
    """What no selector changes, worked out once per rule table: ``codes``, every rule that is not opt-in,
    sorted (the selection :func:`layered_selection` gives where no layer selects or ignores), and
    ``severities``, their code → declared severity in the table's order (what :func:`selected_rules` gives
    for those codes, or for no selector at all, before per-code severities)."""

    __slots__ = ("codes", "severities", "table")

    def __init__(self, table: dict[str, tuple[Severity, bool]]) -> None:
        self.table = table
        self.severities = {code: severity for code, (severity, opt_in) in table.items() if not opt_in}
        self.codes = tuple(sorted(self.severities))


_DEFAULT: list[_Default] = []  # the rule table's (one: a test may put in another table)


def _default(table: dict[str, tuple[Severity, bool]]) -> _Default:
    if not _DEFAULT or _DEFAULT[0].table is not table:
        _DEFAULT[:] = [_Default(table)]
    return _DEFAULT[0]


def _match(prefixes: Sequence[str], code: str, names: frozenset[str] = frozenset()) -> int:
    """How specific the longest of ``prefixes`` that matches ``code`` is (``ALL``: 0); -1: none.
    ``names``: ``prefixes`` as a set, for a selection of full codes (one look-up, not one per prefix)."""
    if code in names:  # as long as a prefix of it can be
        return len(code)
    if not prefixes:  # what max() below gives for none, without a generator per code (a run asks ~600 times)
        return -1
    return max((0 if p == ALL else len(p) for p in prefixes if p == ALL or code.startswith(p)), default=-1)


def _named(code: str, *selectors: Sequence[str]) -> bool:
    """Is an opt-in rule enabled by ``selectors``: by its full code, or by ``ALL``?"""
    return any(code in s or ALL in s for s in selectors)


def _selected_rules(options: LintOptions) -> dict[str, Severity]:
    """All rules (or those ``select`` names), plus ``extend_select``, less ``ignore``; the longest
    matching prefix decides, and at equal length ``ignore`` wins. An opt-in rule runs only when
    named by its full code (or by ``ALL``)."""
    table = rule_table()
    if not options.extend_select and not options.ignore:
        default = _default(table)
        if not options.select or options.select == default.codes:
            # what a lint asks but for a configuration that selects: every rule that is not opt-in, by its full
            # code (layered_selection of no selector) or by no selector at all, each matched by itself (an
            # opt-in rule is not named); worked out once, not tried code by code (with layered_selection's
            # default: a lint 132.34 M -> 131.71 M instructions)
            out = dict(default.severities)
            for code, severity in options.severity.items():
                if code in out:
                    out[code] = severity
            return out
    out = {}
    # sets, where a selector names full codes: a configuration's layered selection names every rule
    # (199 codes), and 199 prefixes tried on each code were the slowest part of start-up
    select, extend, ignore = (frozenset(options.select), frozenset(options.extend_select),
                              frozenset(options.ignore))
    if select and not extend and not ignore and _prefix_free(table) and select <= table.keys():
        # what every lint asks (layered_selection: each enabled rule by its full code): the codes named, each
        # matched by itself alone (no code is a prefix of another), opt-in ones included (named by full code)
        overrides = options.severity
        return {code: overrides.get(code, declared) for code, (declared, _) in table.items() if code in select}
    # (a selector that is empty matches nothing, and a code a set names is matched by it: no call for either)
    for code, (severity, opt_in) in table.items():
        sel = len(code) if code in select else _match(options.select, code) if select else -1
        ext = len(code) if code in extend else _match(options.extend_select, code) if extend else -1
        ign = len(code) if code in ignore else _match(options.ignore, code) if ignore else -1
        if opt_in and not _named(code, options.select, options.extend_select):
            continue
        if options.select and sel < 0 and ext < 0:
            continue
        if ign >= 0 and ign >= max(sel, ext):  # at equal specificity, ignore wins (as in ruff)
            continue
        out[code] = options.severity.get(code, severity)
    return out


Layer = tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]  # select, extend-select, ignore


_layered: dict[tuple[tuple[Layer, ...], tuple[str, ...]], LintOptions] = {}


def layered_selection(layers: Sequence[Layer], dropped: Sequence[str] = ()) -> LintOptions:
    """:func:`_layered_selection`, memoised: every file of a run asks with the same few layers."""
    key = (tuple(layers), tuple(dropped))
    hit = _layered.get(key)
    if hit is None:
        hit = _layered[key] = _layered_selection(key[0], key[1])
    return hit


def _layered_selection(layers: Sequence[Layer], dropped: Sequence[str] = ()) -> LintOptions:
    """Rule selection as ruff resolves it, as options for one file. Each layer (an inherited
    configuration, the configuration, the command line) changes the rules the one below enabled:
    a layer with ``select`` starts anew (what the layers below enabled or ignored no longer
    counts), one without adds its ``extend-select`` and removes its ``ignore``. Within a layer the
    longest matching prefix decides and, at equal length, ``ignore`` wins; a rule no selector of a
    layer matches keeps its state. An opt-in rule is enabled only by its full code. ``dropped``
    (the file's per-file ignores) removes every code it matches, whatever selected it."""
    table = rule_table()
    default = _default(table)
    enabled: set[str] | None = None  # None: what no layer changed, the default (a lint without a selection)
    for select, extend, ignore in layers:
        if not (select or extend or ignore):
            continue
        if enabled is None:
            enabled = set(default.codes)
        for code, (_, opt_in) in table.items():
            on = _match((*select, *extend), code)
            off = _match(ignore, code)
            if opt_in and not _named(code, select, extend):
                on = -1
            if not select and on < 0 and off < 0:
                continue
            if on > off:
                enabled.add(code)
            else:
                enabled.discard(code)
    if dropped:
        enabled = {c for c in (default.codes if enabled is None else enabled) if not any(map(c.startswith, dropped))}
    kept = default.codes if enabled is None else tuple(sorted(enabled))
    return LintOptions(select=kept) if kept else LintOptions(ignore=("",))  # "" matches every code


__all__ = ["ALL", "Layer", "known_code", "layered_selection", "rule_sources", "rule_table", "selected_rules"]
