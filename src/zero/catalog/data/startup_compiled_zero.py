"""The ZERO K rules' conditions of startup_errors.toml as Python (see startup_compiled.py),
written by tools/gen_conditions.py.

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from zero.catalog.condition_helpers import _abs, _binary, _both, _fact, _isname, _len, _member, _neg, _not, _startswith, _supports


def _K013(lookup):
    return _binary('<=', lookup('P-ZERO-00002', None), 96)


COMPILED = {
    'K013': ('P-ZERO-00002 <= 96', '', _K013, None,
             ('P-ZERO-00002',), (('P-ZERO-00002', None),)),
}
