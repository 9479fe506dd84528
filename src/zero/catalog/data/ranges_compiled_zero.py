"""The formal ranges of the built-in catalogue's ZERO parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-ZERO-00001': ('0/1', (None, False, None, False, (0, 1))),
    'P-ZERO-00002': ('0 ... 96', (0, False, 96, False, None)),
    'P-ZERO-00003': ('MIN(SGN32) < versch < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-ZERO-00004': ('0/1', (None, False, None, False, (0, 1))),
}
