"""The EXTV K rules' conditions of startup_errors.toml as Python (see startup_compiled.py),
written by tools/gen_conditions.py.

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from zero.catalog.condition_helpers import _abs, _binary, _both, _fact, _isname, _len, _member, _neg, _not, _startswith, _supports


def _K166(lookup):
    return _member(lookup('P-EXTV-00004', None), ('GLOBAL', 'CHANNEL'), False)


def _K167(lookup):
    return _member(lookup('P-EXTV-00015', None), ('BOOLEAN', 'SGN08', 'SGN16', 'SGN32', 'UNS08', 'UNS16', 'UNS32', 'REAL64', 'STRING'), True)


def _K168(lookup):
    return _isname(lookup('P-EXTV-00003', None))


def _K169(lookup):
    return (True if (_v1 := (True if (_v2 := _member(lookup('P-EXTV-00003', None), ('BOOLEAN', 'SGN08', 'UNS08', 'SGN16', 'UNS16', 'SGN32', 'UNS32', 'REAL64', 'STRING', 'VSTRING'), False)) is not None and _v2 else _both(_v2, _not(_isname(lookup('P-EXTV-00003', None)))))) is not None and _v1 else _both(_v1, _fact(lookup('elsewhere:P-EXTV-00003,P-EXTV-00015', None))))


def _K185(lookup):
    return (True if (_v1 := (True if (_v2 := _member(lookup('P-EXTV-00017', None), ('BOOLEAN', 'SGN08', 'UNS08', 'SGN16', 'UNS16', 'SGN32', 'UNS32', 'REAL64', 'STRING', 'VSTRING'), False)) is not None and _v2 else _both(_v2, _not(_isname(lookup('P-EXTV-00017', None)))))) is not None and _v1 else _both(_v1, _fact(lookup('elsewhere:P-EXTV-00017,P-EXTV-00015', None))))


COMPILED = {
    'K166': ('P-EXTV-00004 in ("GLOBAL", "CHANNEL")', '', _K166, None,
             ('P-EXTV-00004',), (('P-EXTV-00004', None),)),
    'K167': ('P-EXTV-00015 not in ("BOOLEAN", "SGN08", "SGN16", "SGN32", "UNS08", "UNS16", "UNS32", "REAL64", "STRING")', '', _K167, None,
             ('P-EXTV-00015',), (('P-EXTV-00015', None),)),
    'K168': ('isname(P-EXTV-00003)', '', _K168, None,
             ('P-EXTV-00003',), (('P-EXTV-00003', None),)),
    'K169': ('P-EXTV-00003 in ("BOOLEAN", "SGN08", "UNS08", "SGN16", "UNS16", "SGN32", "UNS32", "REAL64", "STRING", "VSTRING") or not isname(P-EXTV-00003) or elsewhere(P-EXTV-00003, P-EXTV-00015)', '', _K169, None,
             ('P-EXTV-00003', 'P-EXTV-00015'), (('P-EXTV-00003', None), ('P-EXTV-00015', None))),
    'K185': ('P-EXTV-00017 in ("BOOLEAN", "SGN08", "UNS08", "SGN16", "UNS16", "SGN32", "UNS32", "REAL64", "STRING", "VSTRING") or not isname(P-EXTV-00017) or elsewhere(P-EXTV-00017, P-EXTV-00015)', '', _K185, None,
             ('P-EXTV-00017', 'P-EXTV-00015'), (('P-EXTV-00017', None), ('P-EXTV-00015', None))),
}
