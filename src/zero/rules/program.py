"""N rules: NC programs (``zero lint program.nc``, with ``--machine`` for N003/N004)."""

from __future__ import annotations

from zero.diagnostics import Severity
from zero.rules.base import Rule, rule

E, W = Severity.ERROR, Severity.WARNING

RULES: dict[str, Rule] = {
    r.code: r
    for r in (
        rule("N001", "machine-data-syntax", E, "A #MACHINE DATA block the controller rejects",
             """
What it checks: `#MACHINE DATA [SYN] [AX=<name> | AXNR=<n>  <P-AXIS-id>[.<idx>]=<value> |
AXPARAM="<key> <value>" [WAIT]]`: one axis (AX= or a positive AXNR=), a parameter ID that
#MACHINE DATA accepts as a keyword, an AXPARAM key and value valid for the axis list, WAIT only
with SYN.

Why it matters on the machine: the block is rejected at run time, in the middle of a program,
or (AXNR is not checked by the controller) writes the parameter of another axis.

Example: `#MACHINE DATA [AX=X P-AXIS-00209=80000 WAIT]` (WAIT without SYN)
Fix: write the block as in the manual's examples.
"""),
        rule("N002", "machine-data-after-soft-limits", W, "#MACHINE DATA after G98/G99 discards them",
             """
What it checks: a #MACHINE DATA block after G98 or G99 in the same program.

Why it matters on the machine: writing any machine data reloads the whole axis list into the
channel; soft limits programmed with G98/G99 before are silently gone, and the axis runs with
the configured ones again.

Fix: program G98/G99 again after #MACHINE DATA, or write the machine data first.
"""),
        rule("N003", "programmed-limit-widens", W, "G98/G99 widen the soft limits while that is not allowed",
             """
What it checks: with `range_check_prog_soft_limits` 1 (P-CHAN-00498), a soft limit programmed with
G98 below `swe_neg` or with G99 above `swe_pos` (G90 absolute, G91 relative to the configured limit).

Why it matters on the machine: the controller warns (P-ERR-21648 / P-ERR-21650) and keeps the
configured limit: the program does not run in the range its author expected.

Fix: stay inside the configured limits, or allow widening (P-CHAN-00498 0) deliberately.
"""),
        rule("N004", "programmed-limits-crossed", E, "G98/G99 put the negative limit at or above the positive",
             """
What it checks: a negative soft limit programmed with G98 at or above the configured positive one,
or a positive one programmed with G99 at or below the configured negative one.

Why it matters on the machine: error P-ERR-21649 / P-ERR-21878: the value is not taken over and
the controller resets, stopping the program.

Fix: check sign and unit of the programmed value (G98 sets the negative, G99 the positive limit).
"""),
    )
}
