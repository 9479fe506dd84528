"""U rules: update and revert files, the partial lists the kernel applies to a running controller.

The kernel's ``Update`` folder holds XML lists that change a few parameters online
(``achsmds1-Update.xml``) and put them back (``achsmds1-Revert.xml``). zero knows one by its
place or name (:func:`zero.markup.documents.is_update`); every S, R and M rule checks it as the
list it is part of, and these rules check what only an update has to get right.
"""

from __future__ import annotations

from collections.abc import Iterator

from zero.catalog.evidence import claim
from zero.diagnostics import Diagnostic, Span
from zero.rules.base import Context, E, Family, W

FAMILY: Family[Context] = Family("U", "update files", "list")
AXIS_NUMBER = "P-AXIS-00016"  # kopf.achs_nr: the logical axis number

RESTART = FAMILY.rule(
    "U001", "update-needs-restart", W, "An update changes a parameter that takes effect only at a restart",
    """
What it checks: every parameter an update file changes is one the catalogue lets change on a
running controller (`ChangeRequiresRestart` false in `CncParaDesc.xml`).

Why it matters on the machine: the catalogue says a change of such a parameter requires a
restart of the controller; applied online, the update does not make it take effect, and the
machine keeps running with the old value until the next start-up.

Example: `<P-COMP-00059 Value="2000" />` (`kw.ssfk.max_points`) in an update file
Fix: change it in the list itself and restart the controller; leave it out of the update.
""")
AXIS_CHECK = FAMILY.rule(
    "U002", "update-without-axis-number", E, "An axis update without the logical axis number",
    """
What it checks: an update or revert file of an axis list carries the logical axis number
`P-AXIS-00016` (`kopf.achs_nr`).

Why it matters on the machine: the kernel uses the axis number to double-check which axis an
online update is meant for; the vendor's own update files carry it for that reason ("always
needed"). Without it the update cannot be matched to its axis.

Example: an `<AX_MDS>` update holding only `<P-AXIS-00297 Value="X2" />`
Fix: add `<P-AXIS-00016 Value="N" />` with the axis's logical number.
""", reads=("P-AXIS-00016",))


UNKNOWN_AXIS = FAMILY.rule(
    "U003", "update-for-unknown-axis", E, "An axis update for an axis the machine does not have",
    """
What it checks (with a machine: `zero lint --machine STARTUP UPDATE`): the logical axis number
`P-AXIS-00016` of an axis update is the `kopf.achs_nr` of one of the machine's axis lists. The
update's values are then checked with that list's other values around them (a new `swe_pos`
against its `swe_neg`, a range that refers to a parameter the update leaves alone), and what
that finds is reported on the update's lines.

Why it matters on the machine: the kernel double-checks the axis of an online update by this
number; an update for an axis the machine does not have is refused, or meant for another
machine.

Example: `<P-AXIS-00016 Value="7" />` on a machine of three axes
Fix: correct the axis number, or apply the update on the machine it was written for.
""", reads=("P-AXIS-00016",))


@FAMILY.check(RESTART, AXIS_CHECK)
def check_update(ctx: Context) -> Iterator[Diagnostic]:
    origin = ctx.doc.origin
    if origin is None or not origin.update:
        return
    has_axis_number = False
    for res in ctx.resolved:
        spec, e = res.spec, res.entry
        if spec.id == AXIS_NUMBER:
            has_axis_number = True
        if spec.restart:
            yield ctx.report("U001", Span.on_line(e.line, e.key_start, e.key_end),
                             f"the catalogue says a change of `{e.key_text}` requires a restart: applied online by "
                             "this update, it does not take effect before the controller starts again",
                             param_id=spec.id)
    if ctx.kind == "AXIS" and not has_axis_number:
        first = next((e for e in ctx.doc.entries), None)
        span = Span.on_line(first.line, first.key_start, first.key_end) if first else Span(1, 1, 1, 1)
        yield ctx.report("U002", span, "this axis update does not carry the logical axis number P-AXIS-00016 "
                         "(`kopf.achs_nr`), which the kernel uses to double-check the axis it updates; not set, it "
                         f"is 0 (its default), and {claim('update-axis-zero').says}",
                         param_id=AXIS_NUMBER)
