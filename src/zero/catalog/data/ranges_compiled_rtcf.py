"""The formal ranges of the built-in catalogue's RTCF parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-RTCF-00002': ('0 < cycle_time < MAX(UNS32)', (0, True, ('L', 'MAX', 'UNS32'), True, None)),
    'P-RTCF-00003': ('0 < time_slice < MAX(UNS32)', (0, True, ('L', 'MAX', 'UNS32'), True, None)),
    'P-RTCF-00004': ('0 < windows_time < MAX(UNS16)', (0, True, ('L', 'MAX', 'UNS16'), True, None)),
    'P-RTCF-00017': ('0 <= thread[i].context_info', (0, False, None, False, None)),
}
