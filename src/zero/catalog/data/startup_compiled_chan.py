"""The CHAN K rules' conditions of startup_errors.toml as Python (see startup_compiled.py),
written by tools/gen_conditions.py.

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from zero.catalog.condition_helpers import _abs, _binary, _both, _fact, _isname, _len, _member, _neg, _not, _startswith, _supports


def _K002(lookup):
    return _fact(lookup('unique:P-CHAN-00007', None))


def _K003(lookup):
    return _fact(lookup('unique:P-CHAN-00036', None))


def _K004(lookup):
    return _fact(lookup('unique:P-CHAN-00035', None))


def _K005(lookup):
    return _fact(lookup('unique:P-CHAN-00006', None))


def _K006(lookup):
    return (True if (_v1 := (True if (_v2 := (True if (_v3 := (True if (_v4 := (True if (_v5 := (True if (_v6 := (True if (_v7 := (True if (_v8 := (True if (_v9 := _startswith(lookup('P-CHAN-00006', None), 'X')) is not None and _v9 else _both(_v9, _startswith(lookup('P-CHAN-00006', None), 'Y')))) is not None and _v8 else _both(_v8, _startswith(lookup('P-CHAN-00006', None), 'Z')))) is not None and _v7 else _both(_v7, _startswith(lookup('P-CHAN-00006', None), 'A')))) is not None and _v6 else _both(_v6, _startswith(lookup('P-CHAN-00006', None), 'B')))) is not None and _v5 else _both(_v5, _startswith(lookup('P-CHAN-00006', None), 'C')))) is not None and _v4 else _both(_v4, _startswith(lookup('P-CHAN-00006', None), 'U')))) is not None and _v3 else _both(_v3, _startswith(lookup('P-CHAN-00006', None), 'V')))) is not None and _v2 else _both(_v2, _startswith(lookup('P-CHAN-00006', None), 'W')))) is not None and _v1 else _both(_v1, _startswith(lookup('P-CHAN-00006', None), 'Q')))


def _K007(lookup):
    return _fact(lookup('unique:P-CHAN-00036,P-CHAN-00035', None))


def _K008(lookup):
    return _binary('!=', lookup('P-CHAN-00059', None), 0)


def _K009(lookup):
    return _binary('!=', lookup('P-CHAN-00060', None), 0)


def _K010(lookup):
    return (False if (_v1 := _binary('!=', lookup('P-CHAN-00037', None), 0)) is not None and not _v1 else _both(_v1, _binary('!=', lookup('P-CHAN-00038', None), 0)))


def _K010_when(lookup):
    return (True if (_v1 := _binary('!=', lookup('P-CHAN-00037', None), 0)) is not None and _v1 else _both(_v1, _binary('!=', lookup('P-CHAN-00038', None), 0)))


def _K011(lookup):
    return _binary('!=', lookup('P-CHAN-00037', None), lookup('P-CHAN-00038', None))


def _K011_when(lookup):
    return _binary('!=', lookup('P-CHAN-00037', None), 0)


def _K012(lookup):
    return _not(_fact(lookup('elsewhere:P-CHAN-00037,P-CHAN-00038', None)))


def _K014(lookup):
    return (True if (_v1 := _binary('==', lookup('P-CHAN-00085', None), '')) is not None and _v1 else _both(_v1, _binary('!=', lookup('P-CHAN-00062', None), '')))


def _K015(lookup):
    return _binary('==', lookup('P-CHAN-00040', None), 0)


def _K015_when(lookup):
    return _binary('!=', _binary('&', lookup('P-CHAN-00041', None), 1), 0)


def _K018(lookup):
    return _startswith(lookup('P-CHAN-00007', None), 'S')


def _K019(lookup):
    return (True if (_v1 := _binary('==', lookup('P-CHAN-00007', None), '')) is not None and _v1 else _both(_v1, _binary('!=', lookup('P-CHAN-00007', None), lookup('P-CHAN-00053', None))))


def _K021(lookup):
    return _binary('==', lookup('P-CHAN-00116', None), 1)


def _K021_when(lookup):
    return _binary('==', lookup('P-CHAN-00148', None), 1)


def _K022(lookup):
    return (False if (_v1 := (False if (_v2 := _binary('>=', lookup('P-CHAN-00192', None), 10)) is not None and not _v2 else _both(_v2, _binary('>=', lookup('P-CHAN-00193', None), 10)))) is not None and not _v1 else _both(_v1, _binary('>=', lookup('P-CHAN-00194', None), 10)))


def _K022_when(lookup):
    return (False if (_v1 := _binary('!=', lookup('P-CHAN-00190', None), 0)) is not None and not _v1 else _both(_v1, _binary('>', lookup('P-CHAN-00191', None), 0)))


def _K120(lookup):
    return _binary('<=', lookup('P-CHAN-00056', None), 2000)


def _K160(lookup):
    return _member(lookup('P-CHAN-00394', None), ('XYZ', 'XYX', 'XZY', 'XZX', 'YXZ', 'YXY', 'YZX', 'YZY', 'ZXY', 'ZXZ', 'ZYX', 'ZYZ'), False)


def _K161(lookup):
    return _binary('<=', lookup('P-CHAN-00023', None), 1)


def _K176(lookup):
    return _not(_fact(lookup('elsewhere:P-CHAN-00038,P-CHAN-00038', None)))


COMPILED = {
    'K002': ('unique(P-CHAN-00007)', '', _K002, None,
             ('P-CHAN-00007',), (('P-CHAN-00007', None),)),
    'K003': ('unique(P-CHAN-00036)', '', _K003, None,
             ('P-CHAN-00036',), (('P-CHAN-00036', None),)),
    'K004': ('unique(P-CHAN-00035)', '', _K004, None,
             ('P-CHAN-00035',), (('P-CHAN-00035', None),)),
    'K005': ('unique(P-CHAN-00006)', '', _K005, None,
             ('P-CHAN-00006',), (('P-CHAN-00006', None),)),
    'K006': ('startswith(P-CHAN-00006, "X") or startswith(P-CHAN-00006, "Y") or startswith(P-CHAN-00006, "Z") or startswith(P-CHAN-00006, "A") or startswith(P-CHAN-00006, "B") or startswith(P-CHAN-00006, "C") or startswith(P-CHAN-00006, "U") or startswith(P-CHAN-00006, "V") or startswith(P-CHAN-00006, "W") or startswith(P-CHAN-00006, "Q")', '', _K006, None,
             ('P-CHAN-00006',), (('P-CHAN-00006', None),)),
    'K007': ('unique(P-CHAN-00036, P-CHAN-00035)', '', _K007, None,
             ('P-CHAN-00036', 'P-CHAN-00035'), (('P-CHAN-00036', None), ('P-CHAN-00035', None))),
    'K008': ('P-CHAN-00059 != 0', '', _K008, None,
             ('P-CHAN-00059',), (('P-CHAN-00059', None),)),
    'K009': ('P-CHAN-00060 != 0', '', _K009, None,
             ('P-CHAN-00060',), (('P-CHAN-00060', None),)),
    'K010': ('P-CHAN-00037 != 0 and P-CHAN-00038 != 0', 'P-CHAN-00037 != 0 or P-CHAN-00038 != 0', _K010, _K010_when,
             ('P-CHAN-00037', 'P-CHAN-00038'), (('P-CHAN-00037', None), ('P-CHAN-00038', None))),
    'K011': ('P-CHAN-00037 != P-CHAN-00038', 'P-CHAN-00037 != 0', _K011, _K011_when,
             ('P-CHAN-00037', 'P-CHAN-00038'), (('P-CHAN-00037', None), ('P-CHAN-00038', None))),
    'K012': ('not elsewhere(P-CHAN-00037, P-CHAN-00038)', '', _K012, None,
             ('P-CHAN-00037', 'P-CHAN-00038'), (('P-CHAN-00037', None), ('P-CHAN-00038', None))),
    'K014': ('P-CHAN-00085 == "" or P-CHAN-00062 != ""', '', _K014, None,
             ('P-CHAN-00085', 'P-CHAN-00062'), (('P-CHAN-00085', None), ('P-CHAN-00062', None))),
    'K015': ('P-CHAN-00040 == 0', '(P-CHAN-00041 & 0x1) != 0', _K015, _K015_when,
             ('P-CHAN-00040',), (('P-CHAN-00040', None),)),
    'K018': ('startswith(P-CHAN-00007, "S")', '', _K018, None,
             ('P-CHAN-00007',), (('P-CHAN-00007', None),)),
    'K019': ('P-CHAN-00007 == "" or P-CHAN-00007 != P-CHAN-00053', '', _K019, None,
             ('P-CHAN-00007', 'P-CHAN-00053'), (('P-CHAN-00007', None), ('P-CHAN-00053', None))),
    'K021': ('P-CHAN-00116 == 1', 'P-CHAN-00148 == 1', _K021, _K021_when,
             ('P-CHAN-00116',), (('P-CHAN-00116', None),)),
    'K022': ('P-CHAN-00192 >= 10 and P-CHAN-00193 >= 10 and P-CHAN-00194 >= 10', 'P-CHAN-00190 != 0 and P-CHAN-00191 > 0', _K022, _K022_when,
             ('P-CHAN-00192', 'P-CHAN-00193', 'P-CHAN-00194'), (('P-CHAN-00192', None), ('P-CHAN-00193', None), ('P-CHAN-00194', None))),
    'K120': ('P-CHAN-00056 <= 2000', '', _K120, None,
             ('P-CHAN-00056',), (('P-CHAN-00056', None),)),
    'K160': ('P-CHAN-00394 in ("XYZ", "XYX", "XZY", "XZX", "YXZ", "YXY", "YZX", "YZY", "ZXY", "ZXZ", "ZYX", "ZYZ")', '', _K160, None,
             ('P-CHAN-00394',), (('P-CHAN-00394', None),)),
    'K161': ('P-CHAN-00023 <= 1', '', _K161, None,
             ('P-CHAN-00023',), (('P-CHAN-00023', None),)),
    'K176': ('not elsewhere(P-CHAN-00038, P-CHAN-00038)', '', _K176, None,
             ('P-CHAN-00038',), (('P-CHAN-00038', None),)),
}
