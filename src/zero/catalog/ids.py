"""Well-known parameter IDs, units and G codes: the one place where code names them.

Rules and the machine model read most parameters generically through the registry;
the few they reason about by meaning (soft limits, axis numbers, zero offsets) are
named here once. Lengths and angles in the lists are integers in 0.1 µm and
0.0001°: :data:`LENGTH_UNIT` of them make one millimetre or one degree.
"""

from __future__ import annotations

from collections.abc import Sequence

Number = int | float

# Lengths and angles: this many list units per mm or degree.
LENGTH_UNIT = 10_000
FULL_TURN = 360 * LENGTH_UNIT  # one revolution of a rotary axis, in 0.0001°

# Axis list (P-AXIS-…)
AXIS_NR = "P-AXIS-00016"  # kopf.achs_nr: the logical axis number
AXIS_TYPE = "P-AXIS-00018"  # kenngr.achs_typ: 1 linear, 2 rotary, 4 spindle
AXIS_NAME = "P-AXIS-00297"  # kopf.log_achs_name
OFFSET_NEG, OFFSET_POS = "P-AXIS-00137", "P-AXIS-00138"  # manual-mode offset limits
SWE_NEG, SWE_POS, SWE_TOL = "P-AXIS-00177", "P-AXIS-00178", "P-AXIS-00179"  # soft limits, tolerance
SWE_BEHAVIOUR = "P-AXIS-00554"  # kenngr.swe_behaviour
SWE_CHECK = "P-AXIS-00705"  # kenngr.swe_check
SOFT_LIMITS = (SWE_NEG, SWE_POS)
# the position resolution, per gear stage (wegaufz / wegaufn) or by the feed constant
RES_NUM, RES_DEN = "P-AXIS-00234", "P-AXIS-00233"  # getriebe[g].wegaufz, getriebe[g].wegaufn
FEED_NUM, FEED_DEN = "P-AXIS-00362", "P-AXIS-00363"  # antr.feed_const_num, antr.feed_const_denom
ROTARY_TYPES = (2, 4)  # kenngr.achs_typ of a rotary axis and of a spindle


def is_rotary(axis_type: float | None) -> bool:
    """The one decision "rotary or linear" from the value of ``kenngr.achs_typ``: rotary axes and
    spindles measure their lengths in 0.0001°, everything else (and an unknown type) in 0.1 µm."""
    return axis_type is not None and axis_type in ROTARY_TYPES


def axis_unit(axis_type: float | None) -> str:
    return "°" if is_rotary(axis_type) else "mm"

# Channel list (P-CHAN-…)
CH_COUNT = "P-CHAN-00003"  # gruppe[0].achs_anzahl
CH_NAME = "P-CHAN-00006"  # gruppe[0].achse[j].bezeichnung
CH_LOG_NR = "P-CHAN-00035"  # gruppe[0].achse[j].log_achs_nr
SPINDLE_AXIS = "P-CHAN-00036"  # spindel[s].log_achs_nr
RANGE_CHECK_PROG_LIMITS = "P-CHAN-00498"  # range_check_prog_soft_limits

# Start-up list (P-STUP-…)
CHANNELS = "P-STUP-00001"  # kanal_anzahl
AXIS_LISTS = "P-STUP-00014"  # zahl_mds
COMP_LISTS = "P-STUP-00016"  # zahl_kw
COMP_AXIS = "P-STUP-00036"  # achs_kw_log_ax_nr[i]: the axis of compensation list i
COMP_LIST_AXIS = "P-COMP-00001"  # kopf.achs_nr of a compensation list
# a compensation the axis list switches on → the table entries of the compensation list that feed it
COMPENSATIONS = {
    "P-AXIS-00175": ("leadscrew error compensation", "kw.ssfk.table[]",
                     ("P-COMP-00023", "P-COMP-00024", "P-COMP-00025")),
    "P-AXIS-00047": ("cross compensation", "kw.crosscomp.table[]", ("P-COMP-00006", "P-COMP-00007")),
    "P-AXIS-00174": ("plane compensation", "kw.crosscomp2.table[][]", ("P-COMP-00016",)),
}

# Zero-offset list (P-ZERO-…)
G53_AVAILABLE = "P-ZERO-00001"  # g53_verfuegbar
DEFAULT_INDEX = "P-ZERO-00002"  # default_index
OFFSET = "P-ZERO-00003"  # np_grp[i].achse[j].versch
INACTIVE = "P-ZERO-00004"  # np_grp[i].achse[j].inaktiv

# Tool list (P-TOOL-…)
TOOL_LENGTH = "P-TOOL-00003"  # wz[t].laenge
TOOL_AXIS_OFFSET = "P-TOOL-00006"  # wz[t].ax_versatz[j]
TOOL_LENGTH_AXIS = 2  # the tool length acts along the third channel axis (Z in G17)

# Siemens S5 IP247: positions within ±99.999999 m, in 0.1 µm.
IP247_LIMIT = 999_999_990


_INF = float("inf")  # math.inf, without importing math (an extension module: start-up)


def in_units(value: Number) -> float:
    """A length or angle in list units as mm or degrees (±inf beyond a float: a number no
    parameter holds, which the rules report; the caller shows it with :func:`fixed`)."""
    try:
        return value / LENGTH_UNIT
    except OverflowError:
        return _INF if value > 0 else -_INF


def _four_decimals(value: Number) -> str:
    """``value`` list units in mm or degrees with four decimals, exact for integers of any size
    (a float would turn 10^40 into 10^36 and overflow beyond 10^308)."""
    if isinstance(value, int):
        if value.bit_length() > 4000:  # more digits than Python prints
            return f"{'-' if value < 0 else ''}(a number of about {int(value.bit_length() * 0.30103)} digits)"
        whole, part = divmod(abs(value), LENGTH_UNIT)
        return f"{'-' if value < 0 else ''}{whole}.{part:04d}"
    return f"{value / LENGTH_UNIT:.4f}"


def fixed(value: Number, unit: str = "") -> str:
    """A length or angle with four decimals: ``-1000.0000 mm``."""
    text = _four_decimals(value)
    return f"{text} {unit}" if unit else text


def length_text(value: Number, rotary: bool | None = None) -> str:
    """A length or angle, trailing zeros dropped (both units when the axis type is unknown)."""
    shown = _four_decimals(value)
    shown = shown.rstrip("0").rstrip(".") if "." in shown else shown
    if rotary is None:
        return f"{shown} mm (or °)"
    return f"{shown} °" if rotary else f"{shown} mm"


def g_code(group: int) -> str:
    """The G code that selects zero-offset group ``group``: G53, G54..G59, else G159=n."""
    if group == 0:
        return "G53"
    if 1 <= group <= 6:
        return f"G{53 + group}"
    return f"G159={group}"


def g_code_with_index(group: int) -> str:
    """The G code with its G159 form where they differ: ``G54 (G159=1)``, ``G159=7``."""
    code = g_code(group)
    return code if code.startswith("G159") else f"{code} (G159={group})"


# ------------------------------------------------------------------------- engineering units

# The catalogue's units (linear, rotary) and what an engineer reads: factor and unit for each.
_UNIT_PAIRS: dict[tuple[str, ...], tuple[tuple[float, str], tuple[float, str]]] = {
    ("0.1um", "0.1mdeg"): ((1e-4, "mm"), (1e-4, "°")),
    ("um/s", "mdeg/s"): ((6e-5, "m/min"), (0.06, "°/min")),
    ("mm/s^2", "deg/s^2"): ((1, "mm/s²"), (1, "°/s²")),
    ("mm/s^3", "deg/s^3"): ((1, "mm/s³"), (1, "°/s³")),
    ("m/s^3", "kdeg/min^3"): ((1, "m/s³"), (1, "k°/min³")),
    ("um", "mdeg"): ((1, "µm"), (1e-3, "°")),
    ("mm", "deg"): ((1, "mm"), (1, "°")),
    ("0.1um/rev", "0.1mdeg/rev"): ((1e-4, "mm/rev"), (1e-4, "°/rev")),
}
_UNIT_ONE: dict[str, tuple[float, str]] = {
    "us": (1, "µs"), "ms": (1, "ms"), "s": (1, "s"), "Hz": (1, "Hz"), "0.1%": (0.1, "%"), "%": (1, "%"),
    "0.01/s": (0.01, "1/s"), "deg": (1, "°"), "rev/min": (1, "rpm"), "mm/min": (1, "mm/min"),
    "um/m": (1, "µm/m"), "0.1um/m": (0.1, "µm/m"), "rev": (1, "rev"),
}


def engineering_number(value: float) -> str:
    """1040 → "1,040"; up to four decimals."""
    text = f"{value:,.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def in_engineering(units: Sequence[str], number: float | int, rotary: bool | None) -> str | None:
    """A number in the catalogue's ``units`` as an engineer reads it: 10400000 0.1 µm → "1,040 mm",
    2000000 µm/s → "120 m/min"; ``rotary`` None (not known): both readings. None: no known unit."""
    pair = _UNIT_PAIRS.get(tuple(units))
    try:
        if pair is not None:
            if rotary is None:
                return " or ".join(f"{engineering_number(number * f)} {u}" for f, u in pair)
            factor, unit = pair[1 if rotary else 0]
        elif len(units) == 1 and units[0] in _UNIT_ONE:
            factor, unit = _UNIT_ONE[units[0]]
        else:
            return None
        return f"{engineering_number(number * factor)} {unit}"
    except (OverflowError, ValueError):
        return None
