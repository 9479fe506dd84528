"""The prose ranges' conditions of prose_ranges.toml as Python, written by tools/gen_conditions.py:
ID -> (condition, guard, the condition's function, the guard's or None, the elements it reads, the
catalogue's prose); ROWS_SIZE: the size of the prose_ranges.py they were written from (while it has it,
a lint reads the prose ranges from here alone).

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from zero.catalog.condition_helpers import _abs, _binary, _both, _fact, _isname, _len, _member, _neg, _not, _startswith, _supports

ROWS_SIZE = 8140


def _r0(lookup):
    return _binary('<=', lookup('P-AXIS-00030', None), lookup('P-AXIS-00212', None))


def _r1(lookup):
    return _binary('<', lookup('P-AXIS-00072', None), lookup('P-AXIS-00071', None))


def _r1_when(lookup):
    return _binary('!=', lookup('P-AXIS-00071', None), 0)


def _r2(lookup):
    return _binary('<', lookup('P-AXIS-00127', None), lookup('P-AXIS-00126', None))


def _r3(lookup):
    return _binary('<', lookup('P-AXIS-00127', None), lookup('P-AXIS-00126', None))


def _r4(lookup):
    return (False if (_v1 := _binary('<=', lookup('P-AXIS-00177', None), lookup('P-AXIS-00152', None))) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00152', None), lookup('P-AXIS-00178', None))))


def _r5(lookup):
    return _binary('<', lookup('P-AXIS-00246', None), lookup('P-AXIS-00248', None))


def _r6(lookup):
    return (False if (_v1 := _binary('<=', lookup('P-AXIS-00292', None), lookup('P-AXIS-00008', None))) is not None and not _v1 else _both(_v1, (True if (_v2 := (False if (_v3 := _binary('<=', lookup('P-AXIS-00001', None), lookup('P-AXIS-00292', None))) is not None and not _v3 else _both(_v3, _binary('<=', lookup('P-AXIS-00002', None), lookup('P-AXIS-00292', None))))) is not None and _v2 else _both(_v2, (False if (_v4 := _binary('<=', lookup('P-AXIS-00011', None), lookup('P-AXIS-00292', None))) is not None and not _v4 else _both(_v4, _binary('<=', lookup('P-AXIS-00012', None), lookup('P-AXIS-00292', None))))))))


def _r7(lookup):
    return (False if (_v1 := (False if (_v2 := (False if (_v3 := (False if (_v4 := _binary('<=', lookup('P-AXIS-00201', None), lookup('P-AXIS-00293', None))) is not None and not _v4 else _both(_v4, _binary('<=', lookup('P-AXIS-00293', None), lookup('P-AXIS-00195', None))))) is not None and not _v3 else _both(_v3, _binary('<=', lookup('P-AXIS-00293', None), lookup('P-AXIS-00196', None))))) is not None and not _v2 else _both(_v2, _binary('<=', lookup('P-AXIS-00293', None), lookup('P-AXIS-00197', None))))) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00293', None), lookup('P-AXIS-00198', None))))


def _r7_when(lookup):
    return _binary('!=', lookup('P-AXIS-00293', None), 0)


def _r8(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00305', None), 1)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00305', None), _binary('/', lookup('P-AXIS-00212', 0), 2))))


def _r9(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00306', None), 1)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00306', None), _binary('/', lookup('P-AXIS-00008', 0), 2))))


def _r10(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00307', None), 1)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00307', None), _binary('/', lookup('P-AXIS-00008', 0), 2))))


def _r11(lookup):
    return _binary('<', lookup('P-AXIS-00335', None), _binary('/', _binary('*', lookup('P-AXIS-00008', None), 1000000), lookup('P-AXIS-00196', None)))


def _r12(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00376', None), 1)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00376', None), _binary('/', _binary('*', _binary('/', lookup('P-AXIS-00008', 0), 2), 1000000), lookup('P-AXIS-00201', 0)))))


def _r13(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00377', None), 1)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00377', None), _binary('/', _binary('*', _binary('/', lookup('P-AXIS-00008', 0), 2), 1000000), lookup('P-AXIS-00201', 0)))))


def _r14(lookup):
    return _binary('!=', lookup('P-AXIS-00388', None), 0)


def _r14_when(lookup):
    return _binary('==', lookup('P-AXIS-00386', None), 1)


def _r15(lookup):
    return (False if (_v1 := _binary('<=', lookup('P-AXIS-00395', None), lookup('P-AXIS-00236', None))) is not None and not _v1 else _both(_v1, (True if (_v2 := _binary('<=', lookup('P-AXIS-00472', None), 0)) is not None and _v2 else _both(_v2, _binary('<=', lookup('P-AXIS-00395', None), lookup('P-AXIS-00472', None))))))


def _r16(lookup):
    return (False if (_v1 := _binary('>', lookup('P-AXIS-00531', None), 0)) is not None and not _v1 else _both(_v1, (True if (_v2 := _binary('==', lookup('P-AXIS-00018', None), 1)) is not None and _v2 else _both(_v2, _binary('<', lookup('P-AXIS-00531', None), _binary('-', lookup('P-AXIS-00126', 0), lookup('P-AXIS-00127', 0)))))))


def _r16_when(lookup):
    return _binary('!=', lookup('P-AXIS-00531', None), 0)


def _r17(lookup):
    return _binary('<=', lookup('P-AXIS-00760', None), lookup('P-AXIS-00008', None))


def _r18(lookup):
    return (True if (_v1 := (False if (_v2 := (False if (_v3 := _binary('==', lookup('P-MANU-00003', None), 0)) is not None and not _v3 else _both(_v3, _binary('>=', lookup('P-MANU-00004', None), 0)))) is not None and not _v2 else _both(_v2, _binary('<=', lookup('P-MANU-00004', None), 5)))) is not None and _v1 else _both(_v1, (False if (_v4 := _binary('==', lookup('P-MANU-00003', None), 1)) is not None and not _v4 else _both(_v4, _binary('>', lookup('P-MANU-00004', None), 0)))))


def _r19(lookup):
    return _binary('>', lookup('P-RTCF-00013', None), 0)


COMPILED = {
    'P-AXIS-00030': ('P-AXIS-00030 <= P-AXIS-00212', '', _r0, None, (('P-AXIS-00030', None), ('P-AXIS-00212', None)),
                     '0 ≤ vb_max_red_zone ≤ P-AXIS-00212 (vb_max)'),
    'P-AXIS-00071': ('P-AXIS-00072 < P-AXIS-00071', 'P-AXIS-00071 != 0', _r1, _r1_when, (('P-AXIS-00072', None), ('P-AXIS-00071', None)),
                     '0 < gantry_max_diff_resetable < gantry_max_diff_reset_locked < MAX(UNS32)'),
    'P-AXIS-00126': ('P-AXIS-00127 < P-AXIS-00126', '', _r2, None, (('P-AXIS-00127', None), ('P-AXIS-00126', None)),
                     'modulou < moduloo ≤ MAX(SGN32)'),
    'P-AXIS-00127': ('P-AXIS-00127 < P-AXIS-00126', '', _r3, None, (('P-AXIS-00127', None), ('P-AXIS-00126', None)),
                     'MIN(SGN32) ≤ modulou < moduloo'),
    'P-AXIS-00152': ('P-AXIS-00177 <= P-AXIS-00152 and P-AXIS-00152 <= P-AXIS-00178', '', _r4, None, (('P-AXIS-00177', None), ('P-AXIS-00152', None), ('P-AXIS-00178', None)),
                     'swe_neg < pos_refpkt < swe_pos'),
    'P-AXIS-00248': ('P-AXIS-00246 < P-AXIS-00248', '', _r5, None, (('P-AXIS-00246', None), ('P-AXIS-00248', None)),
                     'v1 < v2 ≤ MAX(UNS32)'),
    'P-AXIS-00292': ('P-AXIS-00292 <= P-AXIS-00008 and ((P-AXIS-00001 <= P-AXIS-00292 and P-AXIS-00002 <= P-AXIS-00292) or (P-AXIS-00011 <= P-AXIS-00292 and P-AXIS-00012 <= P-AXIS-00292))', '', _r6, None, (('P-AXIS-00292', None), ('P-AXIS-00008', None), ('P-AXIS-00001', None), ('P-AXIS-00002', None), ('P-AXIS-00011', None), ('P-AXIS-00012', None)),
                     'A_F ≤ a_w_max ≤ P-AXIS-00008; A_F = MAX[P-AXIS-00001, P-AXIS-00002] (non-linear slope), MAX[P-AXIS-00011, P-AXIS-00012] (linear slope)'),
    'P-AXIS-00293': ('P-AXIS-00201 <= P-AXIS-00293 and P-AXIS-00293 <= P-AXIS-00195 and P-AXIS-00293 <= P-AXIS-00196 and P-AXIS-00293 <= P-AXIS-00197 and P-AXIS-00293 <= P-AXIS-00198', 'P-AXIS-00293 != 0', _r7, _r7_when, (('P-AXIS-00201', None), ('P-AXIS-00293', None), ('P-AXIS-00195', None), ('P-AXIS-00196', None), ('P-AXIS-00197', None), ('P-AXIS-00198', None)),
                     'P-AXIS-00201 ≤ tr_w_min ≤ TR_F; TR_F = MIN[P-AXIS-00195, P-AXIS-00196, P-AXIS-00197, P-AXIS-00198]'),
    'P-AXIS-00305': ('P-AXIS-00305 >= 1 and P-AXIS-00305 <= P-AXIS-00212.0 / 2', '', _r8, None, (('P-AXIS-00305', None), ('P-AXIS-00212', 0)),
                     '1 ... P-AXIS-00212 / 2'),
    'P-AXIS-00306': ('P-AXIS-00306 >= 1 and P-AXIS-00306 <= P-AXIS-00008.0 / 2', '', _r9, None, (('P-AXIS-00306', None), ('P-AXIS-00008', 0)),
                     '1 ... P-AXIS-00008 / 2'),
    'P-AXIS-00307': ('P-AXIS-00307 >= 1 and P-AXIS-00307 <= P-AXIS-00008.0 / 2', '', _r10, None, (('P-AXIS-00307', None), ('P-AXIS-00008', 0)),
                     '1 ... P-AXIS-00008 / 2'),
    'P-AXIS-00335': ('P-AXIS-00335 < P-AXIS-00008 * 1000000 / P-AXIS-00196', '', _r11, None, (('P-AXIS-00335', None), ('P-AXIS-00008', None), ('P-AXIS-00196', None)),
                     '1 ≤ torq_move_jerk < (P-AXIS-00008 / P-AXIS-00196)'),
    'P-AXIS-00376': ('P-AXIS-00376 >= 1 and P-AXIS-00376 <= P-AXIS-00008.0 / 2 * 1000000 / P-AXIS-00201.0', '', _r12, None, (('P-AXIS-00376', None), ('P-AXIS-00008', 0), ('P-AXIS-00201', 0)),
                     '1 ... (P-AXIS-00008 / 2) / P-AXIS-00201'),
    'P-AXIS-00377': ('P-AXIS-00377 >= 1 and P-AXIS-00377 <= P-AXIS-00008.0 / 2 * 1000000 / P-AXIS-00201.0', '', _r13, None, (('P-AXIS-00377', None), ('P-AXIS-00008', 0), ('P-AXIS-00201', 0)),
                     '1 ... (P-AXIS-00008 / 2) / P-AXIS-00201'),
    'P-AXIS-00388': ('P-AXIS-00388 != 0', 'P-AXIS-00386 == 1', _r14, _r14_when, (('P-AXIS-00388', None),),
                     '0: value is not configured. If P-AXIS-00386 is set to 1, set this parameter to a valid value'),
    'P-AXIS-00395': ('P-AXIS-00395 <= P-AXIS-00236 and (P-AXIS-00472 <= 0 or P-AXIS-00395 <= P-AXIS-00472)', '', _r15, None, (('P-AXIS-00395', None), ('P-AXIS-00236', None), ('P-AXIS-00472', None)),
                     '0 ... MIN(P-AXIS-00236, P-AXIS-00472)'),
    'P-AXIS-00531': ('P-AXIS-00531 > 0 and (P-AXIS-00018 == 1 or P-AXIS-00531 < P-AXIS-00126.0 - P-AXIS-00127.0)', 'P-AXIS-00531 != 0', _r16, _r16_when, (('P-AXIS-00531', None), ('P-AXIS-00018', None), ('P-AXIS-00126', 0), ('P-AXIS-00127', 0)),
                     '0 < P-AXIS-00531 < MAX(SGN32) for translatory axes; 0 < P-AXIS-00531 < (P-AXIS-00126 - P-AXIS-00127) for rotary axes and spindles'),
    'P-AXIS-00760': ('P-AXIS-00760 <= P-AXIS-00008', '', _r17, None, (('P-AXIS-00760', None), ('P-AXIS-00008', None)),
                     '[0 … P-AXIS-00008]'),
    'P-MANU-00004': ('(P-MANU-00003 == 0 and P-MANU-00004 >= 0 and P-MANU-00004 <= 5) or (P-MANU-00003 == 1 and P-MANU-00004 > 0)', '', _r18, None, (('P-MANU-00003', None), ('P-MANU-00004', None)),
                     '0 ... 5: array index in the HLI where P-MANU-00003 = 0; > 0: physical address of a counter module where P-MANU-00003 = 1'),
    'P-RTCF-00013': ('P-RTCF-00013 > 0', '', _r19, None, (('P-RTCF-00013', None),),
                     '0 < P-RTFC-00013 < MAX(UNS32)'),
}
