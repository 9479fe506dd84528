"""The formal ranges of the built-in catalogue's VOLC parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-VOLC-00001': ('0 … MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-VOLC-00002': ('0 … MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-VOLC-00003': ('0 … MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-VOLC-00004': ('0 … MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-VOLC-00005': ('0 … MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-VOLC-00006': ('0 … MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-VOLC-00011': ('0/1', (None, False, None, False, (0, 1))),
    'P-VOLC-00015': ('0/1', (None, False, None, False, (0, 1))),
    'P-VOLC-00018': ('0 … MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-VOLC-00019': ('0/1', (None, False, None, False, (0, 1))),
    'P-VOLC-00020': ('0/1', (None, False, None, False, (0, 1))),
}
