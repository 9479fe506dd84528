"""The formal ranges of the built-in catalogue's TOOL parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-TOOL-00002': ('0 < srk_lage ≤ 9', (0, True, 9, False, None)),
    'P-TOOL-00003': ('MIN(SGN32) < length < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00004': ('MIN(SGN32) ≤ radius < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00005': ('0/1', (None, False, None, False, (0, 1))),
    'P-TOOL-00006': ('MIN(SGN32) < ax_versatz[j] < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00007': ('MIN(REAL64) ≤ param[j] ≤ MAX(REAL64)', (('L', 'MIN', 'REAL64'), False, ('L', 'MAX', 'REAL64'), False, None)),
    'P-TOOL-00009': ('MIN(SGN32) < param[j] < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00010': ('0/1', (None, False, None, False, (0, 1))),
    'P-TOOL-00011': ('0 ≤ kin_id ≤ MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-TOOL-00012': ('0 ≤ log_ax_nr_spdl ≤ MAX(UNS16)', (0, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-TOOL-00013': ('0 ≤ vb_min ≤ P-TOOL-00014', (0, False, ('R', 'P-TOOL-00014', None), False, None)),
    'P-TOOL-00014': ('1 ≤ vb_max ≤ 2000000000', (1, False, 2000000000, False, None)),
    'P-TOOL-00015': ('1 ≤ a_max ≤ 100000000', (1, False, 100000000, False, None)),
    'P-TOOL-00016': ('0 ≤ gear_ratio_num ≤ MAX(SGN32)', (0, False, ('L', 'MAX', 'SGN32'), False, None)),
    'P-TOOL-00017': ('0 ≤ gear_ratio_denom ≤ MAX(SGN32)', (0, False, ('L', 'MAX', 'SGN32'), False, None)),
    'P-TOOL-00018': ('0/1', (None, False, None, False, (0, 1))),
    'P-TOOL-00019': ('0/1', (None, False, None, False, (0, 1))),
    'P-TOOL-00030': ('0 ≤ grinding_wear_const', (0, False, None, False, None)),
    'P-TOOL-00031': ('MIN(SGN32) ≤ grinding_max_infeed ≤ MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), False, None)),
    'P-TOOL-00102': ('MIN(SGN32) < translation[k] < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00103': ('-360° < rotation[k] < 360°', (-360, True, 360, True, None)),
    'P-TOOL-00104': ('0 < ax_nr ≤ MAX(UNS16)', (0, True, ('L', 'MAX', 'UNS16'), False, None)),
    'P-TOOL-00105': ('MIN(SGN32) < trans_rot < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00109': ('MIN(SGN32) < arm_len < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00123': ('MIN(SGN32) < translation[k] < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00124': ('-360° < rotation[k] < 360°', (-360, True, 360, True, None)),
    'P-TOOL-00138': ('-45°≤ grinding_tilt_angle ≤ 45°', (-45, False, 45, False, None)),
    'P-TOOL-00141': ('MIN(SGN32) < P-TOOL-00141< MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00142': ('MIN(SGN32) < P-TOOL-00142 < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00143': ('MIN(SGN32) < P-TOOL-00143 < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-TOOL-00144': ('0 / 1', (None, False, None, False, (0, 1))),
    'P-TOOL-00145': ('0 / 1', (None, False, None, False, (0, 1))),
}
