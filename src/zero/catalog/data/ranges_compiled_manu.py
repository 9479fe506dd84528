"""The formal ranges of the built-in catalogue's MANU parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-MANU-00001': ('0 ... 6 (maximum number of handwheels, application-specific)', (0, False, 6, False, None)),
    'P-MANU-00002': ('1 ... MAX(UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-MANU-00005': ('1 ... MAX(UNS32)', (1, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-MANU-00006': ('1 ... MAX(UNS32)', (1, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-MANU-00007': ('< MAX(UNS32)', (None, False, ('L', 'MAX', 'UNS32'), True, None)),
    'P-MANU-00008': ('0 ... 9 (maximum number of inching key pairs, application-specific)', (0, False, 9, False, None)),
    'P-MANU-00009': ('1 ... MAX(UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-MANU-00010': ('0/1', (None, False, None, False, (0, 1))),
    'P-MANU-00011': ('0/1', (None, False, None, False, (0, 1))),
    'P-MANU-00014': ('0/1', (None, False, None, False, (0, 1))),
}
