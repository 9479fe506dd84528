"""The formal ranges of the built-in catalogue's CLMP parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-CLMP-00001': ('MIN(SGN32) ≤ versatz ≤ MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), False, None)),
}
