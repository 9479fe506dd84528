"""The formal ranges of the built-in catalogue's SECO parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-SECO-00003': ('0 / 1', (None, False, None, False, (0, 1))),
    'P-SECO-00025': ('MIN(REAL64) ≤ P-SECO-00025 ≤ MAX(REAL64)', (('L', 'MIN', 'REAL64'), False, ('L', 'MAX', 'REAL64'), False, None)),
    'P-SECO-00026': ('-1 <= P-SECO-00026 <= 1', (-1, False, 1, False, None)),
}
