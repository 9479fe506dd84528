"""The COMP K rules' conditions of startup_errors.toml as Python (see startup_compiled.py),
written by tools/gen_conditions.py.

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from zero.catalog.condition_helpers import _abs, _binary, _both, _fact, _isname, _len, _member, _neg, _not, _startswith, _supports


def _K104(lookup):
    return _binary('<=', _binary('*', _binary('+', lookup('P-COMP-00010', None), 1), _binary('+', lookup('P-COMP-00011', None), 1)), lookup('P-COMP-00061', None))


def _K104_when(lookup):
    return _binary('!=', lookup('P-COMP-00061', None), 0)


def _K186(lookup):
    return _binary('>=', lookup('P-COMP-00046', None), 0)


COMPILED = {
    'K104': ('(P-COMP-00010 + 1) * (P-COMP-00011 + 1) <= P-COMP-00061', 'P-COMP-00061 != 0', _K104, _K104_when,
             ('P-COMP-00010', 'P-COMP-00011', 'P-COMP-00061'), (('P-COMP-00010', None), ('P-COMP-00011', None), ('P-COMP-00061', None))),
    'K186': ('P-COMP-00046 >= 0', '', _K186, None,
             ('P-COMP-00046',), (('P-COMP-00046', None),)),
}
