"""The RTCF K rules' conditions of startup_errors.toml as Python (see startup_compiled.py),
written by tools/gen_conditions.py.

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from zero.catalog.condition_helpers import _abs, _binary, _both, _fact, _isname, _len, _member, _neg, _not, _startswith, _supports


def _K187(lookup):
    return _binary('==', _binary('%', lookup('P-RTCF-00002', None), lookup('P-RTCF-00003', None)), 0)


COMPILED = {
    'K187': ('P-RTCF-00002 % P-RTCF-00003 == 0', '', _K187, None,
             ('P-RTCF-00002', 'P-RTCF-00003'), (('P-RTCF-00002', None), ('P-RTCF-00003', None))),
}
