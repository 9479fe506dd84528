"""The formal ranges of the built-in catalogue's EXTV parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-EXTV-00002': ('0 ... MAX(SGN32)', (0, False, ('L', 'MAX', 'SGN32'), False, None)),
    'P-EXTV-00007': ('1 ... MAX(UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-EXTV-00008': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-EXTV-00010': ('0 ... MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-EXTV-00020': ('1 ... MAX(UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
}
