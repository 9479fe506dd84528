"""The AXIS K rules' conditions of startup_errors.toml as Python (see startup_compiled.py),
written by tools/gen_conditions.py.

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from zero.catalog.condition_helpers import _abs, _binary, _both, _fact, _isname, _len, _member, _neg, _not, _startswith, _supports


def _K023(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00621', None), 1)) is not None and _v1 else _both(_v1, _binary('==', lookup('P-AXIS-00621', None), 2)))


def _K031(lookup):
    return _binary('!=', _binary('&', lookup('P-AXIS-00015', None), 1), 0)


def _K031_when(lookup):
    return _binary('==', lookup('P-AXIS-00018', None), 1)


def _K032(lookup):
    return _binary('>', _binary('-', lookup('P-AXIS-00126', None), lookup('P-AXIS-00127', None)), 0)


def _K032_when(lookup):
    return _binary('!=', lookup('P-AXIS-00018', None), 1)


def _K033(lookup):
    return _binary('!=', _binary('&', lookup('P-AXIS-00015', None), 7), 0)


def _K033_when(lookup):
    return _binary('==', lookup('P-AXIS-00018', None), 2)


def _K034(lookup):
    return _binary('<=', lookup('P-AXIS-00216', None), lookup('P-AXIS-00212', None))


def _K035(lookup):
    return (True if (_v1 := (True if (_v2 := _binary('==', lookup('P-AXIS-00018', None), 1)) is not None and _v2 else _both(_v2, _binary('==', lookup('P-AXIS-00018', None), 2)))) is not None and _v1 else _both(_v1, _binary('==', lookup('P-AXIS-00018', None), 4)))


def _K036(lookup):
    return _binary('!=', lookup('P-AXIS-00016', None), 0)


def _K037(lookup):
    return _binary('!=', lookup('P-AXIS-00212', None), 0)


def _K039(lookup):
    return _binary('!=', lookup('P-AXIS-00233', None), 0)


def _K040(lookup):
    return _binary('!=', lookup('P-AXIS-00001', None), 0)


def _K041(lookup):
    return _binary('!=', lookup('P-AXIS-00002', None), 0)


def _K042(lookup):
    return _binary('!=', lookup('P-AXIS-00178', None), lookup('P-AXIS-00177', None))


def _K043(lookup):
    return _binary('>=', lookup('P-AXIS-00109', None), 1)


def _K044(lookup):
    return _binary('!=', lookup('P-AXIS-00079', None), 0)


def _K046(lookup):
    return _binary('>', lookup('P-AXIS-00023', None), 0)


def _K047(lookup):
    return _binary('!=', lookup('P-AXIS-00228', None), 0)


def _K048(lookup):
    return _binary('!=', lookup('P-AXIS-00229', None), 0)


def _K049(lookup):
    return _binary('!=', lookup('P-AXIS-00099', None), 0)


def _K050(lookup):
    return _binary('!=', lookup('P-AXIS-00128', None), 0)


def _K051(lookup):
    return _binary('!=', lookup('P-AXIS-00217', None), 0)


def _K053(lookup):
    return (True if (_v1 := (True if (_v2 := _binary('==', lookup('P-AXIS-00207', None), 0)) is not None and _v2 else _both(_v2, _binary('==', lookup('P-AXIS-00207', None), 1)))) is not None and _v1 else _both(_v1, _binary('==', lookup('P-AXIS-00207', None), 2)))


def _K054(lookup):
    return _binary('!=', lookup('P-AXIS-00205', None), 0)


def _K055(lookup):
    return _binary('>=', lookup('P-AXIS-00199', None), lookup('P-AXIS-00201', None))


def _K056(lookup):
    return _binary('==', lookup('P-AXIS-00016', None), 0)


def _K056_when(lookup):
    return _binary('==', lookup('DEFAULT_LIST', None), 1)


def _K058(lookup):
    return _binary('==', lookup('P-AXIS-00070', None), 0)


def _K058_when(lookup):
    return _binary('!=', _binary('&', lookup('P-AXIS-00015', None), 65536), 0)


def _K060(lookup):
    return _binary('!=', _binary('&', lookup('P-AXIS-00015', None), 4), 0)


def _K060_when(lookup):
    return _binary('==', lookup('P-AXIS-00018', None), 4)


def _K062(lookup):
    return _member(lookup('P-AXIS-00264', None), (0, 1, 2, 3), False)


def _K062_when(lookup):
    return _binary('==', lookup('P-AXIS-00020', None), 2)


def _K063(lookup):
    return _binary('>=', lookup('P-AXIS-00345', None), 0)


def _K065(lookup):
    return _binary('!=', lookup('P-AXIS-00225', None), 0)


def _K066(lookup):
    return _binary('!=', lookup('P-AXIS-00226', None), 0)


def _K067(lookup):
    return _binary('!=', lookup('P-AXIS-00129', None), 0)


def _K068(lookup):
    return _binary('!=', lookup('P-AXIS-00234', None), 0)


def _K069(lookup):
    return _binary('>=', lookup('P-AXIS-00293', None), lookup('P-AXIS-00201', None))


def _K069_when(lookup):
    return _binary('>', lookup('P-AXIS-00293', None), 0)


def _K070(lookup):
    return (False if (_v1 := _binary('>', lookup('P-AXIS-00305', None), 0)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00305', None), _binary('/', lookup('P-AXIS-00212', 0), 2))))


def _K071(lookup):
    return (False if (_v1 := _binary('>', lookup('P-AXIS-00306', None), 0)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00306', None), _binary('/', lookup('P-AXIS-00008', 0), 2))))


def _K072(lookup):
    return _binary('<=', lookup('P-AXIS-00333', None), lookup('P-AXIS-00268', None))


def _K073(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00294', None), 0)) is not None and _v1 else _both(_v1, _supports('P-AXIS-00294', lookup)))


def _K074(lookup):
    return _binary('<=', lookup('P-AXIS-00219', None), lookup('P-AXIS-00268', None))


def _K074_when(lookup):
    return (False if (_v1 := _binary('>', lookup('P-AXIS-00268', None), 0)) is not None and not _v1 else _both(_v1, (True if (_v2 := _binary('==', lookup('P-AXIS-00018', None), 4)) is not None and _v2 else _both(_v2, _binary('!=', lookup('P-AXIS-00250', None), 0)))))


def _K075(lookup):
    return _binary('<=', lookup('P-AXIS-00218', None), lookup('P-AXIS-00268', None))


def _K075_when(lookup):
    return (False if (_v1 := _binary('>', lookup('P-AXIS-00268', None), 0)) is not None and not _v1 else _both(_v1, (True if (_v2 := _binary('==', lookup('P-AXIS-00018', None), 4)) is not None and _v2 else _both(_v2, _binary('!=', lookup('P-AXIS-00250', None), 0)))))


def _K076(lookup):
    return _binary('!=', lookup('P-AXIS-00311', None), 0)


def _K076_when(lookup):
    return _binary('==', lookup('P-AXIS-00312', None), 1)


def _K077(lookup):
    return (False if (_v1 := _binary('>', lookup('P-AXIS-00376', None), 0)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00376', None), _binary('/', _binary('*', _binary('/', lookup('P-AXIS-00008', 0), 2), 1000000), lookup('P-AXIS-00201', 0)))))


def _K078(lookup):
    return (False if (_v1 := _binary('>', lookup('P-AXIS-00377', None), 0)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00377', None), _binary('/', _binary('*', _binary('/', lookup('P-AXIS-00008', 0), 2), 1000000), lookup('P-AXIS-00201', 0)))))


def _K079(lookup):
    return (True if (_v1 := _binary('!=', lookup('P-AXIS-00320', None), 'DRIVE_POSITION_CONTROL')) is not None and _v1 else _both(_v1, _member(lookup('P-AXIS-00020', None), (2, 3, 8), False)))


def _K080(lookup):
    return _binary('!=', lookup('P-AXIS-00363', None), 0)


def _K081(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00364', None), 1)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00364', None), 2)))


def _K081_when(lookup):
    return _binary('==', lookup('P-AXIS-00020', None), 8)


def _K082(lookup):
    return _member(lookup('P-AXIS-00381', None), (0, 1, 2, 3), False)


def _K082_when(lookup):
    return _binary('!=', lookup('P-AXIS-00380', None), 0)


def _K083(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00369', None), 0)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00369', None), 4)))


def _K084(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00387', None), 1)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00387', None), 16)))


def _K084_when(lookup):
    return _binary('!=', lookup('P-AXIS-00387', None), 0)


def _K085(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00388', None), 0)) is not None and _v1 else _both(_v1, _supports('P-AXIS-00388', lookup)))


def _K086(lookup):
    return _binary('==', lookup('P-AXIS-00386', None), 0)


def _K086_when(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00018', None), 4)) is not None and _v1 else _both(_v1, _binary('==', lookup('P-AXIS-00250', None), 1)))


def _K087(lookup):
    return _binary('<=', lookup('P-AXIS-00395', None), lookup('P-AXIS-00236', None))


def _K089(lookup):
    return _binary('==', lookup('P-AXIS-00412', None), 0)


def _K089_when(lookup):
    return _binary('==', lookup('P-AXIS-00018', None), 1)


def _K090(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00426', None), '')) is not None and _v1 else _both(_v1, _supports('P-AXIS-00426', lookup)))


def _K091(lookup):
    return _binary('<=', lookup('P-AXIS-00472', None), 0)


def _K091_when(lookup):
    return _binary('==', lookup('P-AXIS-00018', None), 4)


def _K092(lookup):
    return _binary('<=', lookup('P-AXIS-00395', None), lookup('P-AXIS-00472', None))


def _K092_when(lookup):
    return _binary('>', lookup('P-AXIS-00472', None), 0)


def _K093(lookup):
    return _binary('!=', lookup('P-AXIS-00512', None), 0)


def _K094(lookup):
    return (True if (_v1 := _binary('!=', lookup('P-AXIS-00299', None), 'IGNORE_ABS_POS')) is not None and _v1 else _both(_v1, _binary('==', lookup('P-AXIS-00014', None), 1)))


def _K095(lookup):
    return _binary('==', lookup('P-AXIS-00519', None), 0)


def _K095_when(lookup):
    return _binary('!=', lookup('P-AXIS-00018', None), 4)


def _K096(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00531', None), 0)) is not None and not _v1 else _both(_v1, (True if (_v2 := _binary('==', _binary('&', lookup('P-AXIS-00015', None), 4), 0)) is not None and _v2 else _both(_v2, _binary('<=', lookup('P-AXIS-00531', None), _binary('-', lookup('P-AXIS-00126', 0), lookup('P-AXIS-00127', 0)))))))


def _K097(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00261', None), 0)) is not None and _v1 else _both(_v1, _member(lookup('P-AXIS-00704', None), ('DEFAULT', 'EDGE_TRIGGERED'), False)))


def _K098(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00539', None), 0)) is not None and _v1 else _both(_v1, _supports('P-AXIS-00539', lookup)))


def _K099(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00761', None), 'OFF')) is not None and _v1 else _both(_v1, _binary('==', lookup('P-AXIS-00014', None), 0)))


def _K100(lookup):
    return (True if (_v1 := (True if (_v2 := _binary('==', lookup('P-AXIS-00815', None), _neg(1))) is not None and _v2 else _both(_v2, _binary('!=', lookup('P-AXIS-00020', None), 8)))) is not None and _v1 else _both(_v1, _member(lookup('P-AXIS-00815', None), (6, 7), False)))


def _K103(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00584', None), 0)) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00584', None), 1)))


def _K105(lookup):
    return _binary('<=', _binary('-', lookup('P-AXIS-00126', None), lookup('P-AXIS-00127', None)), 2147483647)


def _K105_when(lookup):
    return _binary('!=', lookup('P-AXIS-00018', None), 1)


def _K106(lookup):
    return _binary('<=', lookup('P-AXIS-00408', None), lookup('P-AXIS-00409', None))


def _K106_when(lookup):
    return (False if (_v1 := _binary('!=', lookup('P-AXIS-00408', None), 1e+199)) is not None and not _v1 else _both(_v1, _binary('!=', lookup('P-AXIS-00409', None), 1e+199)))


def _K107(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00353', None), 1)) is not None and _v1 else _both(_v1, (False if (_v2 := _binary('==', lookup('P-AXIS-00020', None), 3)) is not None and not _v2 else _both(_v2, _binary('==', lookup('P-AXIS-00353', None), 2)))))


def _K108(lookup):
    return _binary('==', _binary('&', lookup('P-AXIS-00622', None), 1), 0)


def _K109(lookup):
    return _binary('==', _binary('&', lookup('P-AXIS-00623', None), 1), 0)


def _K110(lookup):
    return _binary('!=', lookup('P-AXIS-00236', None), 0)


def _K111(lookup):
    return _binary('>=', lookup('P-AXIS-00484', None), 100000)


def _K111_when(lookup):
    return _binary('!=', lookup('P-AXIS-00484', None), 0)


def _K112(lookup):
    return _binary('<=', lookup('P-AXIS-00497', None), 500000)


def _K113(lookup):
    return _binary('<=', lookup('P-AXIS-00495', None), 60000000)


def _K114(lookup):
    return _binary('>=', lookup('P-AXIS-00495', None), 1000)


def _K114_when(lookup):
    return _binary('!=', lookup('P-AXIS-00495', None), 0)


def _K115(lookup):
    return _binary('<=', lookup('P-AXIS-00496', None), 1000)


def _K116(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00709', None), _neg(1))) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00709', None), 31)))


def _K117(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00709', None), _neg(1))) is not None and _v1 else _both(_v1, _supports('P-AXIS-00709', lookup)))


def _K118(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00425', None), _neg(1))) is not None and _v1 else _both(_v1, _supports('P-AXIS-00425', lookup)))


def _K119(lookup):
    return (False if (_v1 := _binary('>=', lookup('P-AXIS-00425', None), _neg(1))) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00425', None), 31)))


def _K121(lookup):
    return (True if (_v1 := (True if (_v2 := (True if (_v3 := (True if (_v4 := (True if (_v5 := (True if (_v6 := _member(lookup('P-AXIS-00399', None), ('SGN08', 'SGN16', 'SGN32', 'UNS08', 'UNS16', 'UNS32'), True)) is not None and _v6 else _both(_v6, (False if (_v7 := _binary('==', lookup('P-AXIS-00399', None), 'SGN08')) is not None and not _v7 else _both(_v7, _binary('<=', lookup('P-AXIS-00409', None), 127)))))) is not None and _v5 else _both(_v5, (False if (_v8 := _binary('==', lookup('P-AXIS-00399', None), 'SGN16')) is not None and not _v8 else _both(_v8, _binary('<=', lookup('P-AXIS-00409', None), 32767)))))) is not None and _v4 else _both(_v4, (False if (_v9 := _binary('==', lookup('P-AXIS-00399', None), 'SGN32')) is not None and not _v9 else _both(_v9, _binary('<=', lookup('P-AXIS-00409', None), 2147483647)))))) is not None and _v3 else _both(_v3, (False if (_v10 := _binary('==', lookup('P-AXIS-00399', None), 'UNS08')) is not None and not _v10 else _both(_v10, _binary('<=', lookup('P-AXIS-00409', None), 255)))))) is not None and _v2 else _both(_v2, (False if (_v11 := _binary('==', lookup('P-AXIS-00399', None), 'UNS16')) is not None and not _v11 else _both(_v11, _binary('<=', lookup('P-AXIS-00409', None), 65535)))))) is not None and _v1 else _both(_v1, (False if (_v12 := _binary('==', lookup('P-AXIS-00399', None), 'UNS32')) is not None and not _v12 else _both(_v12, _binary('<=', lookup('P-AXIS-00409', None), 4294967295)))))


def _K121_when(lookup):
    return _binary('!=', lookup('P-AXIS-00409', None), 1e+199)


def _K122(lookup):
    return (True if (_v1 := (True if (_v2 := (True if (_v3 := (True if (_v4 := (True if (_v5 := (True if (_v6 := _member(lookup('P-AXIS-00399', None), ('SGN08', 'SGN16', 'SGN32', 'UNS08', 'UNS16', 'UNS32'), True)) is not None and _v6 else _both(_v6, (False if (_v7 := _binary('==', lookup('P-AXIS-00399', None), 'SGN08')) is not None and not _v7 else _both(_v7, _binary('>=', lookup('P-AXIS-00408', None), _neg(128))))))) is not None and _v5 else _both(_v5, (False if (_v8 := _binary('==', lookup('P-AXIS-00399', None), 'SGN16')) is not None and not _v8 else _both(_v8, _binary('>=', lookup('P-AXIS-00408', None), _neg(32768))))))) is not None and _v4 else _both(_v4, (False if (_v9 := _binary('==', lookup('P-AXIS-00399', None), 'SGN32')) is not None and not _v9 else _both(_v9, _binary('>=', lookup('P-AXIS-00408', None), _neg(2147483648))))))) is not None and _v3 else _both(_v3, (False if (_v10 := _binary('==', lookup('P-AXIS-00399', None), 'UNS08')) is not None and not _v10 else _both(_v10, _binary('>=', lookup('P-AXIS-00408', None), 0)))))) is not None and _v2 else _both(_v2, (False if (_v11 := _binary('==', lookup('P-AXIS-00399', None), 'UNS16')) is not None and not _v11 else _both(_v11, _binary('>=', lookup('P-AXIS-00408', None), 0)))))) is not None and _v1 else _both(_v1, (False if (_v12 := _binary('==', lookup('P-AXIS-00399', None), 'UNS32')) is not None and not _v12 else _both(_v12, _binary('>=', lookup('P-AXIS-00408', None), 0)))))


def _K122_when(lookup):
    return _binary('!=', lookup('P-AXIS-00408', None), 1e+199)


def _K123(lookup):
    return _binary('<=', lookup('P-AXIS-00760', None), lookup('P-AXIS-00008', None))


def _K124(lookup):
    return _binary('<=', lookup('P-AXIS-00777', None), 1000)


def _K125(lookup):
    return _binary('<=', lookup('P-AXIS-00772', None), 1000)


def _K126(lookup):
    return _member(lookup('P-AXIS-00204', None), (1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13), False)


def _K127(lookup):
    return (False if (_v1 := _binary('<=', lookup('P-AXIS-00221', None), lookup('P-AXIS-00212', None))) is not None and not _v1 else _both(_v1, _binary('<=', lookup('P-AXIS-00211', None), lookup('P-AXIS-00212', None))))


def _K149(lookup):
    return (True if (_v1 := _binary('!=', lookup('P-AXIS-00399', None), 'BITARRAY_16')) is not None and _v1 else _both(_v1, _member(lookup('P-AXIS-00429', None), ('BIT_16', 'BIT_17', 'BIT_18', 'BIT_19', 'BIT_20', 'BIT_21', 'BIT_22', 'BIT_23', 'BIT_24', 'BIT_25', 'BIT_26', 'BIT_27', 'BIT_28', 'BIT_29', 'BIT_30', 'BIT_31'), True)))


def _K183(lookup):
    return _binary('!=', lookup('P-AXIS-00338', None), 0)


def _K184(lookup):
    return _binary('<=', lookup('P-AXIS-00290', None), lookup('P-AXIS-00291', None))


def _K188(lookup):
    return _binary('>', lookup('P-AXIS-00415', None), 0)


def _K189(lookup):
    return _binary('>', lookup('P-AXIS-00416', None), 0)


def _K202(lookup):
    return _binary('<=', lookup('P-AXIS-00818', None), 1000)


def _K203(lookup):
    return _binary('<=', lookup('P-AXIS-00343', None), 1000)


def _K204(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00405', None), 0)) is not None and _v1 else _both(_v1, _supports('P-AXIS-00405', lookup)))


def _K205(lookup):
    return (True if (_v1 := _binary('==', lookup('P-AXIS-00328', None), 0)) is not None and _v1 else _both(_v1, _supports('P-AXIS-00328', lookup)))


COMPILED = {
    'K023': ('P-AXIS-00621 == 1 or P-AXIS-00621 == 2', '', _K023, None,
             ('P-AXIS-00621',), (('P-AXIS-00621', None),)),
    'K031': ('P-AXIS-00015 & 0x1 != 0', 'P-AXIS-00018 == 1', _K031, _K031_when,
             ('P-AXIS-00015',), (('P-AXIS-00015', None),)),
    'K032': ('P-AXIS-00126 - P-AXIS-00127 > 0', 'P-AXIS-00018 != 1', _K032, _K032_when,
             ('P-AXIS-00126', 'P-AXIS-00127'), (('P-AXIS-00126', None), ('P-AXIS-00127', None))),
    'K033': ('P-AXIS-00015 & 0x7 != 0', 'P-AXIS-00018 == 2', _K033, _K033_when,
             ('P-AXIS-00015',), (('P-AXIS-00015', None),)),
    'K034': ('P-AXIS-00216 <= P-AXIS-00212', '', _K034, None,
             ('P-AXIS-00216', 'P-AXIS-00212'), (('P-AXIS-00216', None), ('P-AXIS-00212', None))),
    'K035': ('P-AXIS-00018 == 1 or P-AXIS-00018 == 2 or P-AXIS-00018 == 4', '', _K035, None,
             ('P-AXIS-00018',), (('P-AXIS-00018', None),)),
    'K036': ('P-AXIS-00016 != 0', '', _K036, None,
             ('P-AXIS-00016',), (('P-AXIS-00016', None),)),
    'K037': ('P-AXIS-00212 != 0', '', _K037, None,
             ('P-AXIS-00212',), (('P-AXIS-00212', None),)),
    'K039': ('P-AXIS-00233 != 0', '', _K039, None,
             ('P-AXIS-00233',), (('P-AXIS-00233', None),)),
    'K040': ('P-AXIS-00001 != 0', '', _K040, None,
             ('P-AXIS-00001',), (('P-AXIS-00001', None),)),
    'K041': ('P-AXIS-00002 != 0', '', _K041, None,
             ('P-AXIS-00002',), (('P-AXIS-00002', None),)),
    'K042': ('P-AXIS-00178 != P-AXIS-00177', '', _K042, None,
             ('P-AXIS-00178', 'P-AXIS-00177'), (('P-AXIS-00178', None), ('P-AXIS-00177', None))),
    'K043': ('P-AXIS-00109 >= 1', '', _K043, None,
             ('P-AXIS-00109',), (('P-AXIS-00109', None),)),
    'K044': ('P-AXIS-00079 != 0', '', _K044, None,
             ('P-AXIS-00079',), (('P-AXIS-00079', None),)),
    'K046': ('P-AXIS-00023 > 0', '', _K046, None,
             ('P-AXIS-00023',), (('P-AXIS-00023', None),)),
    'K047': ('P-AXIS-00228 != 0', '', _K047, None,
             ('P-AXIS-00228',), (('P-AXIS-00228', None),)),
    'K048': ('P-AXIS-00229 != 0', '', _K048, None,
             ('P-AXIS-00229',), (('P-AXIS-00229', None),)),
    'K049': ('P-AXIS-00099 != 0', '', _K049, None,
             ('P-AXIS-00099',), (('P-AXIS-00099', None),)),
    'K050': ('P-AXIS-00128 != 0', '', _K050, None,
             ('P-AXIS-00128',), (('P-AXIS-00128', None),)),
    'K051': ('P-AXIS-00217 != 0', '', _K051, None,
             ('P-AXIS-00217',), (('P-AXIS-00217', None),)),
    'K053': ('P-AXIS-00207 == 0 or P-AXIS-00207 == 1 or P-AXIS-00207 == 2', '', _K053, None,
             ('P-AXIS-00207',), (('P-AXIS-00207', None),)),
    'K054': ('P-AXIS-00205 != 0', '', _K054, None,
             ('P-AXIS-00205',), (('P-AXIS-00205', None),)),
    'K055': ('P-AXIS-00199 >= P-AXIS-00201', '', _K055, None,
             ('P-AXIS-00199', 'P-AXIS-00201'), (('P-AXIS-00199', None), ('P-AXIS-00201', None))),
    'K056': ('P-AXIS-00016 == 0', 'DEFAULT_LIST == 1', _K056, _K056_when,
             ('P-AXIS-00016',), (('P-AXIS-00016', None),)),
    'K058': ('P-AXIS-00070 == 0', 'P-AXIS-00015 & 0x10000 != 0', _K058, _K058_when,
             ('P-AXIS-00070',), (('P-AXIS-00070', None),)),
    'K060': ('P-AXIS-00015 & 0x4 != 0', 'P-AXIS-00018 == 4', _K060, _K060_when,
             ('P-AXIS-00015',), (('P-AXIS-00015', None),)),
    'K062': ('P-AXIS-00264 in (0, 1, 2, 3)', 'P-AXIS-00020 == 2', _K062, _K062_when,
             ('P-AXIS-00264',), (('P-AXIS-00264', None),)),
    'K063': ('P-AXIS-00345 >= 0', '', _K063, None,
             ('P-AXIS-00345',), (('P-AXIS-00345', None),)),
    'K065': ('P-AXIS-00225 != 0', '', _K065, None,
             ('P-AXIS-00225',), (('P-AXIS-00225', None),)),
    'K066': ('P-AXIS-00226 != 0', '', _K066, None,
             ('P-AXIS-00226',), (('P-AXIS-00226', None),)),
    'K067': ('P-AXIS-00129 != 0', '', _K067, None,
             ('P-AXIS-00129',), (('P-AXIS-00129', None),)),
    'K068': ('P-AXIS-00234 != 0', '', _K068, None,
             ('P-AXIS-00234',), (('P-AXIS-00234', None),)),
    'K069': ('P-AXIS-00293 >= P-AXIS-00201', 'P-AXIS-00293 > 0', _K069, _K069_when,
             ('P-AXIS-00293', 'P-AXIS-00201'), (('P-AXIS-00293', None), ('P-AXIS-00201', None))),
    'K070': ('P-AXIS-00305 > 0 and P-AXIS-00305 <= P-AXIS-00212.0 / 2', '', _K070, None,
             ('P-AXIS-00305', 'P-AXIS-00212'), (('P-AXIS-00305', None), ('P-AXIS-00212', 0))),
    'K071': ('P-AXIS-00306 > 0 and P-AXIS-00306 <= P-AXIS-00008.0 / 2', '', _K071, None,
             ('P-AXIS-00306', 'P-AXIS-00008'), (('P-AXIS-00306', None), ('P-AXIS-00008', 0))),
    'K072': ('P-AXIS-00333 <= P-AXIS-00268', '', _K072, None,
             ('P-AXIS-00333', 'P-AXIS-00268'), (('P-AXIS-00333', None), ('P-AXIS-00268', None))),
    'K073': ('P-AXIS-00294 == 0 or supports(P-AXIS-00294)', '', _K073, None,
             ('P-AXIS-00294', 'P-AXIS-00020'), (('P-AXIS-00294', None), ('P-AXIS-00020', None))),
    'K074': ('P-AXIS-00219 <= P-AXIS-00268', 'P-AXIS-00268 > 0 and (P-AXIS-00018 == 4 or P-AXIS-00250 != 0)', _K074, _K074_when,
             ('P-AXIS-00219', 'P-AXIS-00268'), (('P-AXIS-00219', None), ('P-AXIS-00268', None))),
    'K075': ('P-AXIS-00218 <= P-AXIS-00268', 'P-AXIS-00268 > 0 and (P-AXIS-00018 == 4 or P-AXIS-00250 != 0)', _K075, _K075_when,
             ('P-AXIS-00218', 'P-AXIS-00268'), (('P-AXIS-00218', None), ('P-AXIS-00268', None))),
    'K076': ('P-AXIS-00311 != 0', 'P-AXIS-00312 == 1', _K076, _K076_when,
             ('P-AXIS-00311',), (('P-AXIS-00311', None),)),
    'K077': ('P-AXIS-00376 > 0 and P-AXIS-00376 <= P-AXIS-00008.0 / 2 * 1000000 / P-AXIS-00201.0', '', _K077, None,
             ('P-AXIS-00376', 'P-AXIS-00008', 'P-AXIS-00201'), (('P-AXIS-00376', None), ('P-AXIS-00008', 0), ('P-AXIS-00201', 0))),
    'K078': ('P-AXIS-00377 > 0 and P-AXIS-00377 <= P-AXIS-00008.0 / 2 * 1000000 / P-AXIS-00201.0', '', _K078, None,
             ('P-AXIS-00377', 'P-AXIS-00008', 'P-AXIS-00201'), (('P-AXIS-00377', None), ('P-AXIS-00008', 0), ('P-AXIS-00201', 0))),
    'K079': ('P-AXIS-00320 != "DRIVE_POSITION_CONTROL" or P-AXIS-00020 in (2, 3, 8)', '', _K079, None,
             ('P-AXIS-00320', 'P-AXIS-00020'), (('P-AXIS-00320', None), ('P-AXIS-00020', None))),
    'K080': ('P-AXIS-00363 != 0', '', _K080, None,
             ('P-AXIS-00363',), (('P-AXIS-00363', None),)),
    'K081': ('P-AXIS-00364 >= 1 and P-AXIS-00364 <= 2', 'P-AXIS-00020 == 8', _K081, _K081_when,
             ('P-AXIS-00364',), (('P-AXIS-00364', None),)),
    'K082': ('P-AXIS-00381 in (0, 1, 2, 3)', 'P-AXIS-00380 != 0', _K082, _K082_when,
             ('P-AXIS-00381',), (('P-AXIS-00381', None),)),
    'K083': ('P-AXIS-00369 >= 0 and P-AXIS-00369 <= 4', '', _K083, None,
             ('P-AXIS-00369',), (('P-AXIS-00369', None),)),
    'K084': ('P-AXIS-00387 >= 1 and P-AXIS-00387 <= 16', 'P-AXIS-00387 != 0', _K084, _K084_when,
             ('P-AXIS-00387',), (('P-AXIS-00387', None),)),
    'K085': ('P-AXIS-00388 == 0 or supports(P-AXIS-00388)', '', _K085, None,
             ('P-AXIS-00388', 'P-AXIS-00020'), (('P-AXIS-00388', None), ('P-AXIS-00020', None))),
    'K086': ('P-AXIS-00386 == 0', 'P-AXIS-00018 == 4 or P-AXIS-00250 == 1', _K086, _K086_when,
             ('P-AXIS-00386',), (('P-AXIS-00386', None),)),
    'K087': ('P-AXIS-00395 <= P-AXIS-00236', '', _K087, None,
             ('P-AXIS-00395', 'P-AXIS-00236'), (('P-AXIS-00395', None), ('P-AXIS-00236', None))),
    'K089': ('P-AXIS-00412 == 0', 'P-AXIS-00018 == 1', _K089, _K089_when,
             ('P-AXIS-00412',), (('P-AXIS-00412', None),)),
    'K090': ('P-AXIS-00426 == "" or supports(P-AXIS-00426)', '', _K090, None,
             ('P-AXIS-00426', 'P-AXIS-00020'), (('P-AXIS-00426', None), ('P-AXIS-00020', None))),
    'K091': ('P-AXIS-00472 <= 0', 'P-AXIS-00018 == 4', _K091, _K091_when,
             ('P-AXIS-00472',), (('P-AXIS-00472', None),)),
    'K092': ('P-AXIS-00395 <= P-AXIS-00472', 'P-AXIS-00472 > 0', _K092, _K092_when,
             ('P-AXIS-00395', 'P-AXIS-00472'), (('P-AXIS-00395', None), ('P-AXIS-00472', None))),
    'K093': ('P-AXIS-00512 != 0', '', _K093, None,
             ('P-AXIS-00512',), (('P-AXIS-00512', None),)),
    'K094': ('P-AXIS-00299 != "IGNORE_ABS_POS" or P-AXIS-00014 == 1', '', _K094, None,
             ('P-AXIS-00299', 'P-AXIS-00014'), (('P-AXIS-00299', None), ('P-AXIS-00014', None))),
    'K095': ('P-AXIS-00519 == 0', 'P-AXIS-00018 != 4', _K095, _K095_when,
             ('P-AXIS-00519',), (('P-AXIS-00519', None),)),
    'K096': ('P-AXIS-00531 >= 0 and ((P-AXIS-00015 & 0x4) == 0 or P-AXIS-00531 <= P-AXIS-00126.0 - P-AXIS-00127.0)', '', _K096, None,
             ('P-AXIS-00531', 'P-AXIS-00015', 'P-AXIS-00126', 'P-AXIS-00127'), (('P-AXIS-00531', None), ('P-AXIS-00015', None), ('P-AXIS-00126', 0), ('P-AXIS-00127', 0))),
    'K097': ('P-AXIS-00261 == 0 or P-AXIS-00704 in ("DEFAULT", "EDGE_TRIGGERED")', '', _K097, None,
             ('P-AXIS-00261', 'P-AXIS-00704'), (('P-AXIS-00261', None), ('P-AXIS-00704', None))),
    'K098': ('P-AXIS-00539 == 0 or supports(P-AXIS-00539)', '', _K098, None,
             ('P-AXIS-00539', 'P-AXIS-00020'), (('P-AXIS-00539', None), ('P-AXIS-00020', None))),
    'K099': ('P-AXIS-00761 == "OFF" or P-AXIS-00014 == 0', '', _K099, None,
             ('P-AXIS-00761', 'P-AXIS-00014'), (('P-AXIS-00761', None), ('P-AXIS-00014', None))),
    'K100': ('P-AXIS-00815 == -1 or P-AXIS-00020 != 8 or P-AXIS-00815 in (6, 7)', '', _K100, None,
             ('P-AXIS-00815', 'P-AXIS-00020'), (('P-AXIS-00815', None), ('P-AXIS-00020', None))),
    'K103': ('P-AXIS-00584 >= 0 and P-AXIS-00584 <= 1', '', _K103, None,
             ('P-AXIS-00584',), (('P-AXIS-00584', None),)),
    'K105': ('P-AXIS-00126 - P-AXIS-00127 <= 2147483647', 'P-AXIS-00018 != 1', _K105, _K105_when,
             ('P-AXIS-00126', 'P-AXIS-00127'), (('P-AXIS-00126', None), ('P-AXIS-00127', None))),
    'K106': ('P-AXIS-00408 <= P-AXIS-00409', 'P-AXIS-00408 != 1e199 and P-AXIS-00409 != 1e199', _K106, _K106_when,
             ('P-AXIS-00408', 'P-AXIS-00409'), (('P-AXIS-00408', None), ('P-AXIS-00409', None))),
    'K107': ('P-AXIS-00353 == 1 or (P-AXIS-00020 == 3 and P-AXIS-00353 == 2)', '', _K107, None,
             ('P-AXIS-00353', 'P-AXIS-00020'), (('P-AXIS-00353', None), ('P-AXIS-00020', None))),
    'K108': ('(P-AXIS-00622 & 0x1) == 0', '', _K108, None,
             ('P-AXIS-00622',), (('P-AXIS-00622', None),)),
    'K109': ('(P-AXIS-00623 & 0x1) == 0', '', _K109, None,
             ('P-AXIS-00623',), (('P-AXIS-00623', None),)),
    'K110': ('P-AXIS-00236 != 0', '', _K110, None,
             ('P-AXIS-00236',), (('P-AXIS-00236', None),)),
    'K111': ('P-AXIS-00484 >= 100000', 'P-AXIS-00484 != 0', _K111, _K111_when,
             ('P-AXIS-00484',), (('P-AXIS-00484', None),)),
    'K112': ('P-AXIS-00497 <= 500000', '', _K112, None,
             ('P-AXIS-00497',), (('P-AXIS-00497', None),)),
    'K113': ('P-AXIS-00495 <= 60000000', '', _K113, None,
             ('P-AXIS-00495',), (('P-AXIS-00495', None),)),
    'K114': ('P-AXIS-00495 >= 1000', 'P-AXIS-00495 != 0', _K114, _K114_when,
             ('P-AXIS-00495',), (('P-AXIS-00495', None),)),
    'K115': ('P-AXIS-00496 <= 1000', '', _K115, None,
             ('P-AXIS-00496',), (('P-AXIS-00496', None),)),
    'K116': ('P-AXIS-00709 >= -1 and P-AXIS-00709 <= 31', '', _K116, None,
             ('P-AXIS-00709',), (('P-AXIS-00709', None),)),
    'K117': ('P-AXIS-00709 == -1 or supports(P-AXIS-00709)', '', _K117, None,
             ('P-AXIS-00709', 'P-AXIS-00020'), (('P-AXIS-00709', None), ('P-AXIS-00020', None))),
    'K118': ('P-AXIS-00425 == -1 or supports(P-AXIS-00425)', '', _K118, None,
             ('P-AXIS-00425', 'P-AXIS-00020'), (('P-AXIS-00425', None), ('P-AXIS-00020', None))),
    'K119': ('P-AXIS-00425 >= -1 and P-AXIS-00425 <= 31', '', _K119, None,
             ('P-AXIS-00425',), (('P-AXIS-00425', None),)),
    'K121': ('P-AXIS-00399 not in ("SGN08", "SGN16", "SGN32", "UNS08", "UNS16", "UNS32") or (P-AXIS-00399 == "SGN08" and P-AXIS-00409 <= 127) or (P-AXIS-00399 == "SGN16" and P-AXIS-00409 <= 32767) or (P-AXIS-00399 == "SGN32" and P-AXIS-00409 <= 2147483647) or (P-AXIS-00399 == "UNS08" and P-AXIS-00409 <= 255) or (P-AXIS-00399 == "UNS16" and P-AXIS-00409 <= 65535) or (P-AXIS-00399 == "UNS32" and P-AXIS-00409 <= 4294967295)', 'P-AXIS-00409 != 1e199', _K121, _K121_when,
             ('P-AXIS-00399', 'P-AXIS-00409'), (('P-AXIS-00399', None), ('P-AXIS-00409', None))),
    'K122': ('P-AXIS-00399 not in ("SGN08", "SGN16", "SGN32", "UNS08", "UNS16", "UNS32") or (P-AXIS-00399 == "SGN08" and P-AXIS-00408 >= -128) or (P-AXIS-00399 == "SGN16" and P-AXIS-00408 >= -32768) or (P-AXIS-00399 == "SGN32" and P-AXIS-00408 >= -2147483648) or (P-AXIS-00399 == "UNS08" and P-AXIS-00408 >= 0) or (P-AXIS-00399 == "UNS16" and P-AXIS-00408 >= 0) or (P-AXIS-00399 == "UNS32" and P-AXIS-00408 >= 0)', 'P-AXIS-00408 != 1e199', _K122, _K122_when,
             ('P-AXIS-00399', 'P-AXIS-00408'), (('P-AXIS-00399', None), ('P-AXIS-00408', None))),
    'K123': ('P-AXIS-00760 <= P-AXIS-00008', '', _K123, None,
             ('P-AXIS-00760', 'P-AXIS-00008'), (('P-AXIS-00760', None), ('P-AXIS-00008', None))),
    'K124': ('P-AXIS-00777 <= 1000', '', _K124, None,
             ('P-AXIS-00777',), (('P-AXIS-00777', None),)),
    'K125': ('P-AXIS-00772 <= 1000', '', _K125, None,
             ('P-AXIS-00772',), (('P-AXIS-00772', None),)),
    'K126': ('P-AXIS-00204 in (1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13)', '', _K126, None,
             ('P-AXIS-00204',), (('P-AXIS-00204', None),)),
    'K127': ('P-AXIS-00221 <= P-AXIS-00212 and P-AXIS-00211 <= P-AXIS-00212', '', _K127, None,
             ('P-AXIS-00221', 'P-AXIS-00212', 'P-AXIS-00211'), (('P-AXIS-00221', None), ('P-AXIS-00212', None), ('P-AXIS-00211', None))),
    'K149': ('P-AXIS-00399 != "BITARRAY_16" or P-AXIS-00429 not in ("BIT_16", "BIT_17", "BIT_18", "BIT_19", "BIT_20", "BIT_21", "BIT_22", "BIT_23", "BIT_24", "BIT_25", "BIT_26", "BIT_27", "BIT_28", "BIT_29", "BIT_30", "BIT_31")', '', _K149, None,
             ('P-AXIS-00399', 'P-AXIS-00429'), (('P-AXIS-00399', None), ('P-AXIS-00429', None))),
    'K183': ('P-AXIS-00338 != 0', '', _K183, None,
             ('P-AXIS-00338',), (('P-AXIS-00338', None),)),
    'K184': ('P-AXIS-00290 <= P-AXIS-00291', '', _K184, None,
             ('P-AXIS-00290', 'P-AXIS-00291'), (('P-AXIS-00290', None), ('P-AXIS-00291', None))),
    'K188': ('P-AXIS-00415 > 0', '', _K188, None,
             ('P-AXIS-00415',), (('P-AXIS-00415', None),)),
    'K189': ('P-AXIS-00416 > 0', '', _K189, None,
             ('P-AXIS-00416',), (('P-AXIS-00416', None),)),
    'K202': ('P-AXIS-00818 <= 1000', '', _K202, None,
             ('P-AXIS-00818',), (('P-AXIS-00818', None),)),
    'K203': ('P-AXIS-00343 <= 1000', '', _K203, None,
             ('P-AXIS-00343',), (('P-AXIS-00343', None),)),
    'K204': ('P-AXIS-00405 == 0 or supports(P-AXIS-00405)', '', _K204, None,
             ('P-AXIS-00405', 'P-AXIS-00020'), (('P-AXIS-00405', None), ('P-AXIS-00020', None))),
    'K205': ('P-AXIS-00328 == 0 or supports(P-AXIS-00328)', '', _K205, None,
             ('P-AXIS-00328', 'P-AXIS-00020'), (('P-AXIS-00328', None), ('P-AXIS-00020', None))),
}
