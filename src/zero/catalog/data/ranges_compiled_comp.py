"""The formal ranges of the built-in catalogue's COMP parameters, parsed (see ranges_compiled.py),
written by tools/gen_ranges.py: ID -> (range text, the range encoded by
zero.catalog.ranges.encode_range).

Generated: do not edit."""

# ruff: noqa

RANGES = {
    'P-COMP-00001': ('0 < achs_nr < MAX(UNS16)', (0, True, ('L', 'MAX', 'UNS16'), True, None)),
    'P-COMP-00004': ('0 ≤ last_index < P-COMP-00060', (0, False, ('R', 'P-COMP-00060', None), True, None)),
    'P-COMP-00005': ('1 ≤ master_ax_nr ≤ MAX (UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-COMP-00006': ('MIN(SGN32) ≤ setpoint < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00007': ('MIN(SGN32) ≤ correction < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00009': ('0 < interval < MAX(UNS32)', (0, True, ('L', 'MAX', 'UNS32'), True, None)),
    'P-COMP-00010': ('0 ≤ P-COMP-00010 <= 100', (0, False, 100, False, None)),
    'P-COMP-00011': ('0 ≤ P-COMP-00011 <= 100', (0, False, 100, False, None)),
    'P-COMP-00012': ('MIN(SGN32) ≤ start_position_master1 < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00013': ('MIN(SGN32) ≤ start_position_master2 < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00014': ('1 ≤ master1_ax_nr ≤ MAX (UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-COMP-00015': ('1 ≤ master2_ax_nr ≤ MAX (UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-COMP-00016': ('MIN(SGN32) ≤ correction < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00018': ('0 ≤ interval < MAX(SGN32)', (0, False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00019': ('MIN(SGN32) ≤ kw_startpos < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00020': ('0 ≤ kw_nr_max < P-COMP-00059', (0, False, ('R', 'P-COMP-00059', None), True, None)),
    'P-COMP-00023': ('MIN(SGN32) ≤ pos < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00024': ('MIN(SGN32) ≤ neg < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00025': ('MIN(SGN64) ≤ setpoint < MAX(SGN64)', (('L', 'MIN', 'SGN64'), False, ('L', 'MAX', 'SGN64'), True, None)),
    'P-COMP-00026': ('0 ≤ n_cycles ≤ 20 (maximum number of cycles for which cross compensation is activated/deactivated, application-specific)', (0, False, 20, False, None)),
    'P-COMP-00027': ('0 ≤ n_cycles ≤ 20 (maximum number of cycles for which cross compensation is activated/deactivated, application-specific)', (0, False, 20, False, None)),
    'P-COMP-00032': ('0 < interval1 < MAX(UNS32)', (0, True, ('L', 'MAX', 'UNS32'), True, None)),
    'P-COMP-00033': ('0 < interval2 < MAX(UNS32)', (0, True, ('L', 'MAX', 'UNS32'), True, None)),
    'P-COMP-00042': ('0 ≤ table_entries ≤ P-COMP-00062', (0, False, ('R', 'P-COMP-00062', None), False, None)),
    'P-COMP-00043': ('0 ≤ position_delay ≤ 10', (0, False, 10, False, None)),
    'P-COMP-00044': ('0 ≤ reversal_lookahead ≤ 4', (0, False, 4, False, None)),
    'P-COMP-00045': ('MIN(SGN16) < scaling_factor < MAX(SGN16)', (('L', 'MIN', 'SGN16'), True, ('L', 'MAX', 'SGN16'), True, None)),
    'P-COMP-00046': ('0 < table[i].in < MAX(SGN32)', (0, True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00047': ('MIN(SGN32) < table[i].out < MAX(SGN32)', (('L', 'MIN', 'SGN32'), True, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00058': ('0 ≤ delay_cycles < 249', (0, False, 249, True, None)),
    'P-COMP-00059': ('0\xa0<=\xa0P-COMP-00059', (0, False, None, False, None)),
    'P-COMP-00060': ('0\xa0<= P-COMP-00060', (0, False, None, False, None)),
    'P-COMP-00061': ('0\xa0<=\xa0P-COMP-00061', (0, False, None, False, None)),
    'P-COMP-00062': ('0\xa0<= P-COMP-00062', (0, False, None, False, None)),
    'P-COMP-00063': ('1 ≤ P-COMP-00063 ≤ MAX (UNS16)', (1, False, ('L', 'MAX', 'UNS16'), False, None)),
    'P-COMP-00064': ('0 ≤ P-COMP-00064 ≤ 20 (maximum number of cycles above which coupling or decoupling is to occur,', (0, False, 20, False, None)),
    'P-COMP-00065': ('0 ≤ P-COMP-00065 < 5', (0, False, 5, True, None)),
    'P-COMP-00066': ('MIN(SGN32) ≤ P-COMP-00066 < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
    'P-COMP-00067': ('MIN(SGN32) ≤ P-COMP-00067 < MAX(SGN32)', (('L', 'MIN', 'SGN32'), False, ('L', 'MAX', 'SGN32'), True, None)),
}
