"""The formal ranges of the built-in catalogue's STUP parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-STUP-00001': ('1 - 12', (1, False, 12, False, None)),
    'P-STUP-00014': ('1 ... 32', (1, False, 32, False, None)),
    'P-STUP-00016': ('1 ... 32', (1, False, 32, False, None)),
    'P-STUP-00019': ('1 ... MAX(UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-STUP-00021': ('0 ... MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-STUP-00031': ('1 ... 6', (1, False, 6, False, None)),
    'P-STUP-00033': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00036': ('1 ... MAX(UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-STUP-00037': ('0 ... MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-STUP-00042': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00043': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00051': ('0 <= P-STUP-00051 <= MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00052': ('0<= P-STUP-00052 <= MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00053': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00054': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00055': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00061': ('0 … 1000', (0, False, 1000, False, None)),
    'P-STUP-00062': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00063': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00064': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00071': ('0 ... 10000', (0, False, 10000, False, None)),
    'P-STUP-00072': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00073': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00074': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00081': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00082': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00091': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00092': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00100': ('0 … MAX(SGN32)', (0, False, ('L', 'MAX', 'SGN32'), False, None)),
    'P-STUP-00110': ('0/1', (None, False, None, False, (0, 1))),
    'P-STUP-00120': ('0 … MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00131': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00132': ('0/1', (None, False, None, False, (0, 1))),
    'P-STUP-00133': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00172': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00183': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00184': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
    'P-STUP-00185': ('0 ... MAX(UNS32)', (0, False, ('L', 'MAX', 'UNS32'), False, None)),
}
