"""The ``__init__`` of every record zero declares, compiled with this module and keyed by its text:
written by tools/gen_record_inits.py (see :func:`zero.records._compiled_init`).

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from __future__ import annotations

from types import CodeType

INITS: dict[str, CodeType] = {}

def __init__(self, axes, offsets=None, default_group=None, absolute=None, plane=None, inch=None, centre_absolute=None, diameter=None, range_check=None) -> None:
    self.axes = axes
    self.offsets = __factory_offsets() if offsets is MISSING else offsets
    self.default_group = default_group
    self.absolute = absolute
    self.plane = plane
    self.inch = inch
    self.centre_absolute = centre_absolute
    self.diameter = diameter
    self.range_check = range_check
INITS['def __init__(self, axes, offsets=MISSING, default_group=__default_default_group, absolute=__default_absolute, plane=__default_plane, inch=__default_inch, centre_absolute=__default_centre_absolute, diameter=__default_diameter, range_check=__default_range_check) -> None:\n    self.axes = axes\n    self.offsets = __factory_offsets() if offsets is MISSING else offsets\n    self.default_group = default_group\n    self.absolute = absolute\n    self.plane = plane\n    self.inch = inch\n    self.centre_absolute = centre_absolute\n    self.diameter = diameter\n    self.range_check = range_check'] = __init__.__code__

def __init__(self, changes, header) -> None:
    self.changes = changes
    self.header = header
INITS['def __init__(self, changes, header) -> None:\n    self.changes = changes\n    self.header = header'] = __init__.__code__

def __init__(self, channel, group, axis_index, axis_name, log_nr, unit, acs_neg, acs_pos, offset, masked, pcs_neg, pcs_pos, note=None) -> None:
    self.channel = channel
    self.group = group
    self.axis_index = axis_index
    self.axis_name = axis_name
    self.log_nr = log_nr
    self.unit = unit
    self.acs_neg = acs_neg
    self.acs_pos = acs_pos
    self.offset = offset
    self.masked = masked
    self.pcs_neg = pcs_neg
    self.pcs_pos = pcs_pos
    self.note = note
INITS['def __init__(self, channel, group, axis_index, axis_name, log_nr, unit, acs_neg, acs_pos, offset, masked, pcs_neg, pcs_pos, note=__default_note) -> None:\n    self.channel = channel\n    self.group = group\n    self.axis_index = axis_index\n    self.axis_name = axis_name\n    self.log_nr = log_nr\n    self.unit = unit\n    self.acs_neg = acs_neg\n    self.acs_pos = acs_pos\n    self.offset = offset\n    self.masked = masked\n    self.pcs_neg = pcs_neg\n    self.pcs_pos = pcs_pos\n    self.note = note'] = __init__.__code__

def __init__(self, children=None) -> None:
    self.children = __factory_children() if children is MISSING else children
INITS['def __init__(self, children=MISSING) -> None:\n    self.children = __factory_children() if children is MISSING else children'] = __init__.__code__

def __init__(self, code, how) -> None:
    __set(self, 'code', code)
    __set(self, 'how', how)
INITS["def __init__(self, code, how) -> None:\n    __set(self, 'code', code)\n    __set(self, 'how', how)"] = __init__.__code__

def __init__(self, code, name, severity, summary, explanation, scope=None, opt_in=None, reads=None) -> None:
    __set(self, 'code', code)
    __set(self, 'name', name)
    __set(self, 'severity', severity)
    __set(self, 'summary', summary)
    __set(self, 'explanation', explanation)
    __set(self, 'scope', scope)
    __set(self, 'opt_in', opt_in)
    __set(self, 'reads', reads)
INITS["def __init__(self, code, name, severity, summary, explanation, scope=__default_scope, opt_in=__default_opt_in, reads=__default_reads) -> None:\n    __set(self, 'code', code)\n    __set(self, 'name', name)\n    __set(self, 'severity', severity)\n    __set(self, 'summary', summary)\n    __set(self, 'explanation', explanation)\n    __set(self, 'scope', scope)\n    __set(self, 'opt_in', opt_in)\n    __set(self, 'reads', reads)"] = __init__.__code__

def __init__(self, code, number, kind, params, condition_text, when_text, correction, title, source, written=None, reported=None) -> None:
    __set(self, 'code', code)
    __set(self, 'number', number)
    __set(self, 'kind', kind)
    __set(self, 'params', params)
    __set(self, 'condition_text', condition_text)
    __set(self, 'when_text', when_text)
    __set(self, 'correction', correction)
    __set(self, 'title', title)
    __set(self, 'source', source)
    __set(self, 'written', written)
    __set(self, 'reported', reported)
INITS["def __init__(self, code, number, kind, params, condition_text, when_text, correction, title, source, written=__default_written, reported=__default_reported) -> None:\n    __set(self, 'code', code)\n    __set(self, 'number', number)\n    __set(self, 'kind', kind)\n    __set(self, 'params', params)\n    __set(self, 'condition_text', condition_text)\n    __set(self, 'when_text', when_text)\n    __set(self, 'correction', correction)\n    __set(self, 'title', title)\n    __set(self, 'source', source)\n    __set(self, 'written', written)\n    __set(self, 'reported', reported)"] = __init__.__code__

def __init__(self, code, severity, message, span, path=None, param_id=None, fix=None, hint=None, related=None, kernel_error=None, consequence=None, source=None) -> None:
    __set(self, 'code', code)
    __set(self, 'severity', severity)
    __set(self, 'message', message)
    __set(self, 'span', span)
    __set(self, 'path', path)
    __set(self, 'param_id', param_id)
    __set(self, 'fix', fix)
    __set(self, 'hint', hint)
    __set(self, 'related', related)
    __set(self, 'kernel_error', kernel_error)
    __set(self, 'consequence', consequence)
    __set(self, 'source', source)
INITS["def __init__(self, code, severity, message, span, path=__default_path, param_id=__default_param_id, fix=__default_fix, hint=__default_hint, related=__default_related, kernel_error=__default_kernel_error, consequence=__default_consequence, source=__default_source) -> None:\n    __set(self, 'code', code)\n    __set(self, 'severity', severity)\n    __set(self, 'message', message)\n    __set(self, 'span', span)\n    __set(self, 'path', path)\n    __set(self, 'param_id', param_id)\n    __set(self, 'fix', fix)\n    __set(self, 'hint', hint)\n    __set(self, 'related', related)\n    __set(self, 'kernel_error', kernel_error)\n    __set(self, 'consequence', consequence)\n    __set(self, 'source', source)"] = __init__.__code__

def __init__(self, code, severity, name, summary, results=None) -> None:
    self.code = code
    self.severity = severity
    self.name = name
    self.summary = summary
    self.results = __factory_results() if results is MISSING else results
INITS['def __init__(self, code, severity, name, summary, results=MISSING) -> None:\n    self.code = code\n    self.severity = severity\n    self.name = name\n    self.summary = summary\n    self.results = __factory_results() if results is MISSING else results'] = __init__.__code__

def __init__(self, codes, run) -> None:
    __set(self, 'codes', codes)
    __set(self, 'run', run)
INITS["def __init__(self, codes, run) -> None:\n    __set(self, 'codes', codes)\n    __set(self, 'run', run)"] = __init__.__code__

def __init__(self, condition, when, read, shown) -> None:
    __set(self, 'condition', condition)
    __set(self, 'when', when)
    __set(self, 'read', read)
    __set(self, 'shown', shown)
INITS["def __init__(self, condition, when, read, shown) -> None:\n    __set(self, 'condition', condition)\n    __set(self, 'when', when)\n    __set(self, 'read', read)\n    __set(self, 'shown', shown)"] = __init__.__code__

def __init__(self, config=None, isolated=None, param_desc=None, kernel=None) -> None:
    __set(self, 'config', config)
    __set(self, 'isolated', isolated)
    __set(self, 'param_desc', param_desc)
    __set(self, 'kernel', kernel)
INITS["def __init__(self, config=__default_config, isolated=__default_isolated, param_desc=__default_param_desc, kernel=__default_kernel) -> None:\n    __set(self, 'config', config)\n    __set(self, 'isolated', isolated)\n    __set(self, 'param_desc', param_desc)\n    __set(self, 'kernel', kernel)"] = __init__.__code__

def __init__(self, data, added, unplaced) -> None:
    self.data = data
    self.added = added
    self.unplaced = unplaced
INITS['def __init__(self, data, added, unplaced) -> None:\n    self.data = data\n    self.added = added\n    self.unplaced = unplaced'] = __init__.__code__

def __init__(self, debounce=None, rule_docs=None, structured=None, machine=None, max_findings=None) -> None:
    self.debounce = debounce
    self.rule_docs = rule_docs
    self.structured = structured
    self.machine = machine
    self.max_findings = max_findings
INITS['def __init__(self, debounce=__default_debounce, rule_docs=__default_rule_docs, structured=__default_structured, machine=__default_machine, max_findings=__default_max_findings) -> None:\n    self.debounce = debounce\n    self.rule_docs = rule_docs\n    self.structured = structured\n    self.machine = machine\n    self.max_findings = max_findings'] = __init__.__code__

def __init__(self, dest, flags, help, kind=None, type=None, choices=None, minimum=None, negative=None, default=None, metavar=None, envvar=None) -> None:
    __set(self, 'dest', dest)
    __set(self, 'flags', flags)
    __set(self, 'help', help)
    __set(self, 'kind', kind)
    __set(self, 'type', type)
    __set(self, 'choices', choices)
    __set(self, 'minimum', minimum)
    __set(self, 'negative', negative)
    __set(self, 'default', default)
    __set(self, 'metavar', metavar)
    __set(self, 'envvar', envvar)
INITS["def __init__(self, dest, flags, help, kind=__default_kind, type=__default_type, choices=__default_choices, minimum=__default_minimum, negative=__default_negative, default=__default_default, metavar=__default_metavar, envvar=__default_envvar) -> None:\n    __set(self, 'dest', dest)\n    __set(self, 'flags', flags)\n    __set(self, 'help', help)\n    __set(self, 'kind', kind)\n    __set(self, 'type', type)\n    __set(self, 'choices', choices)\n    __set(self, 'minimum', minimum)\n    __set(self, 'negative', negative)\n    __set(self, 'default', default)\n    __set(self, 'metavar', metavar)\n    __set(self, 'envvar', envvar)"] = __init__.__code__

def __init__(self, doc, machine_data, limits) -> None:
    self.doc = doc
    self.machine_data = machine_data
    self.limits = limits
INITS['def __init__(self, doc, machine_data, limits) -> None:\n    self.doc = doc\n    self.machine_data = machine_data\n    self.limits = limits'] = __init__.__code__

def __init__(self, doc, registry, kind, base=None, shape_rows=None, shape_keys=None, pattern_shapes=None, bound=None, valueless=None, _groups=None, _entries=None, _resolved=None, _by_id=None) -> None:
    self.doc = doc
    self.registry = registry
    self.kind = kind
    self.base = base
    self.shape_rows = __factory_shape_rows() if shape_rows is MISSING else shape_rows
    self.shape_keys = __factory_shape_keys() if shape_keys is MISSING else shape_keys
    self.pattern_shapes = __factory_pattern_shapes() if pattern_shapes is MISSING else pattern_shapes
    self.bound = __factory_bound() if bound is MISSING else bound
    self.valueless = valueless
    self._groups = _groups
    self._entries = _entries
    self._resolved = _resolved
    self._by_id = _by_id
INITS['def __init__(self, doc, registry, kind, base=__default_base, shape_rows=MISSING, shape_keys=MISSING, pattern_shapes=MISSING, bound=MISSING, valueless=__default_valueless, _groups=__default__groups, _entries=__default__entries, _resolved=__default__resolved, _by_id=__default__by_id) -> None:\n    self.doc = doc\n    self.registry = registry\n    self.kind = kind\n    self.base = base\n    self.shape_rows = __factory_shape_rows() if shape_rows is MISSING else shape_rows\n    self.shape_keys = __factory_shape_keys() if shape_keys is MISSING else shape_keys\n    self.pattern_shapes = __factory_pattern_shapes() if pattern_shapes is MISSING else pattern_shapes\n    self.bound = __factory_bound() if bound is MISSING else bound\n    self.valueless = valueless\n    self._groups = _groups\n    self._entries = _entries\n    self._resolved = _resolved\n    self._by_id = _by_id'] = __init__.__code__

def __init__(self, doc, registry, kind, base=None, shape_rows=None, shape_keys=None, pattern_shapes=None, bound=None, valueless=None, _groups=None, _entries=None, _resolved=None, _by_id=None, severities=None, kernel=None, default_list=None) -> None:
    self.doc = doc
    self.registry = registry
    self.kind = kind
    self.base = base
    self.shape_rows = __factory_shape_rows() if shape_rows is MISSING else shape_rows
    self.shape_keys = __factory_shape_keys() if shape_keys is MISSING else shape_keys
    self.pattern_shapes = __factory_pattern_shapes() if pattern_shapes is MISSING else pattern_shapes
    self.bound = __factory_bound() if bound is MISSING else bound
    self.valueless = valueless
    self._groups = _groups
    self._entries = _entries
    self._resolved = _resolved
    self._by_id = _by_id
    self.severities = __factory_severities() if severities is MISSING else severities
    self.kernel = kernel
    self.default_list = default_list
INITS['def __init__(self, doc, registry, kind, base=__default_base, shape_rows=MISSING, shape_keys=MISSING, pattern_shapes=MISSING, bound=MISSING, valueless=__default_valueless, _groups=__default__groups, _entries=__default__entries, _resolved=__default__resolved, _by_id=__default__by_id, severities=MISSING, kernel=__default_kernel, default_list=__default_default_list) -> None:\n    self.doc = doc\n    self.registry = registry\n    self.kind = kind\n    self.base = base\n    self.shape_rows = __factory_shape_rows() if shape_rows is MISSING else shape_rows\n    self.shape_keys = __factory_shape_keys() if shape_keys is MISSING else shape_keys\n    self.pattern_shapes = __factory_pattern_shapes() if pattern_shapes is MISSING else pattern_shapes\n    self.bound = __factory_bound() if bound is MISSING else bound\n    self.valueless = valueless\n    self._groups = _groups\n    self._entries = _entries\n    self._resolved = _resolved\n    self._by_id = _by_id\n    self.severities = __factory_severities() if severities is MISSING else severities\n    self.kernel = kernel\n    self.default_list = default_list'] = __init__.__code__

def __init__(self, element, kind, doc, start, end, offset=None, item=None, name=None, properties=None) -> None:
    self.element = element
    self.kind = kind
    self.doc = doc
    self.start = start
    self.end = end
    self.offset = offset
    self.item = item
    self.name = name
    self.properties = __factory_properties() if properties is MISSING else properties
INITS['def __init__(self, element, kind, doc, start, end, offset=__default_offset, item=__default_item, name=__default_name, properties=MISSING) -> None:\n    self.element = element\n    self.kind = kind\n    self.doc = doc\n    self.start = start\n    self.end = end\n    self.offset = offset\n    self.item = item\n    self.name = name\n    self.properties = __factory_properties() if properties is MISSING else properties'] = __init__.__code__

def __init__(self, failing, passing, fixes=None, note=None) -> None:
    __set(self, 'failing', failing)
    __set(self, 'passing', passing)
    __set(self, 'fixes', fixes)
    __set(self, 'note', note)
INITS["def __init__(self, failing, passing, fixes=__default_fixes, note=__default_note) -> None:\n    __set(self, 'failing', failing)\n    __set(self, 'passing', passing)\n    __set(self, 'fixes', fixes)\n    __set(self, 'note', note)"] = __init__.__code__

def __init__(self, files, reason=None) -> None:
    self.files = files
    self.reason = reason
INITS['def __init__(self, files, reason=__default_reason) -> None:\n    self.files = files\n    self.reason = reason'] = __init__.__code__

def __init__(self, files=None, changed=None, failed=None, unreadable=None) -> None:
    self.files = files
    self.changed = changed
    self.failed = failed
    self.unreadable = unreadable
INITS['def __init__(self, files=__default_files, changed=__default_changed, failed=__default_failed, unreadable=__default_unreadable) -> None:\n    self.files = files\n    self.changed = changed\n    self.failed = failed\n    self.unreadable = unreadable'] = __init__.__code__

def __init__(self, files=None, clean=None, unreadable=None, by_severity=None, by_code=None, worst=None) -> None:
    self.files = files
    self.clean = clean
    self.unreadable = unreadable
    self.by_severity = __factory_by_severity() if by_severity is MISSING else by_severity
    self.by_code = __factory_by_code() if by_code is MISSING else by_code
    self.worst = worst
INITS['def __init__(self, files=__default_files, clean=__default_clean, unreadable=__default_unreadable, by_severity=MISSING, by_code=MISSING, worst=__default_worst) -> None:\n    self.files = files\n    self.clean = clean\n    self.unreadable = unreadable\n    self.by_severity = __factory_by_severity() if by_severity is MISSING else by_severity\n    self.by_code = __factory_by_code() if by_code is MISSING else by_code\n    self.worst = worst'] = __init__.__code__

def __init__(self, fixed, applied, result) -> None:
    self.fixed = fixed
    self.applied = applied
    self.result = result
INITS['def __init__(self, fixed, applied, result) -> None:\n    self.fixed = fixed\n    self.applied = applied\n    self.result = result'] = __init__.__code__

def __init__(self, form, source, shift, final_newline=None, kind=None, update=None, default_list=None) -> None:
    self.form = form
    self.source = source
    self.shift = shift
    self.final_newline = final_newline
    self.kind = kind
    self.update = update
    self.default_list = default_list
INITS['def __init__(self, form, source, shift, final_newline=__default_final_newline, kind=__default_kind, update=__default_update, default_list=__default_default_list) -> None:\n    self.form = form\n    self.source = source\n    self.shift = shift\n    self.final_newline = final_newline\n    self.kind = kind\n    self.update = update\n    self.default_list = default_list'] = __init__.__code__

def __init__(self, given, label, changes=None, deltas=None) -> None:
    self.given = given
    self.label = label
    self.changes = __factory_changes() if changes is MISSING else changes
    self.deltas = __factory_deltas() if deltas is MISSING else deltas
INITS['def __init__(self, given, label, changes=MISSING, deltas=MISSING) -> None:\n    self.given = given\n    self.label = label\n    self.changes = __factory_changes() if changes is MISSING else changes\n    self.deltas = __factory_deltas() if deltas is MISSING else deltas'] = __init__.__code__

def __init__(self, given, label, machine, changes=None) -> None:
    self.given = given
    self.label = label
    self.machine = machine
    self.changes = __factory_changes() if changes is MISSING else changes
INITS['def __init__(self, given, label, machine, changes=MISSING) -> None:\n    self.given = given\n    self.label = label\n    self.machine = machine\n    self.changes = __factory_changes() if changes is MISSING else changes'] = __init__.__code__

def __init__(self, golden, machines, params=None, lists=None, unreadable=None) -> None:
    self.golden = golden
    self.machines = machines
    self.params = __factory_params() if params is MISSING else params
    self.lists = __factory_lists() if lists is MISSING else lists
    self.unreadable = __factory_unreadable() if unreadable is MISSING else unreadable
INITS['def __init__(self, golden, machines, params=MISSING, lists=MISSING, unreadable=MISSING) -> None:\n    self.golden = golden\n    self.machines = machines\n    self.params = __factory_params() if params is MISSING else params\n    self.lists = __factory_lists() if lists is MISSING else lists\n    self.unreadable = __factory_unreadable() if unreadable is MISSING else unreadable'] = __init__.__code__

def __init__(self, golden, machines=None, jobs=None, param_desc=None, config=None, isolated=None, cache=None) -> None:
    self.golden = golden
    self.machines = machines
    self.jobs = jobs
    self.param_desc = param_desc
    self.config = config
    self.isolated = isolated
    self.cache = cache
INITS['def __init__(self, golden, machines=__default_machines, jobs=__default_jobs, param_desc=__default_param_desc, config=__default_config, isolated=__default_isolated, cache=__default_cache) -> None:\n    self.golden = golden\n    self.machines = machines\n    self.jobs = jobs\n    self.param_desc = param_desc\n    self.config = config\n    self.isolated = isolated\n    self.cache = cache'] = __init__.__code__

def __init__(self, group, offset, pcs_neg, pcs_pos, note=None) -> None:
    self.group = group
    self.offset = offset
    self.pcs_neg = pcs_neg
    self.pcs_pos = pcs_pos
    self.note = note
INITS['def __init__(self, group, offset, pcs_neg, pcs_pos, note=__default_note) -> None:\n    self.group = group\n    self.offset = offset\n    self.pcs_neg = pcs_neg\n    self.pcs_pos = pcs_pos\n    self.note = note'] = __init__.__code__

def __init__(self, head, tail, pattern, indices, indexed) -> None:
    self.head = head
    self.tail = tail
    self.pattern = pattern
    self.indices = indices
    self.indexed = indexed
INITS['def __init__(self, head, tail, pattern, indices, indexed) -> None:\n    self.head = head\n    self.tail = tail\n    self.pattern = pattern\n    self.indices = indices\n    self.indexed = indexed'] = __init__.__code__

def __init__(self, id, index=None) -> None:
    __set(self, 'id', id)
    __set(self, 'index', index)
INITS["def __init__(self, id, index=__default_index) -> None:\n    __set(self, 'id', id)\n    __set(self, 'index', index)"] = __init__.__code__

def __init__(self, id, kind, key, type, default=None, range_text=None, range_note=None, dims=None, symbols=None, units=None, quantity=None, max_len=None, restart=None, description=None, source=None, index_base=None, enum=None, enum_flags=None, bits=None, enum_labels=None) -> None:
    self.id = id
    self.kind = kind
    self.key = key
    self.type = type
    self.default = default
    self.range_text = range_text
    self.range_note = range_note
    self.dims = dims
    self.symbols = symbols
    self.units = units
    self.quantity = quantity
    self.max_len = max_len
    self.restart = restart
    self.description = description
    self.source = source
    self.index_base = index_base
    self.enum = enum
    self.enum_flags = enum_flags
    self.bits = bits
    self.enum_labels = enum_labels
INITS['def __init__(self, id, kind, key, type, default=__default_default, range_text=__default_range_text, range_note=__default_range_note, dims=__default_dims, symbols=__default_symbols, units=__default_units, quantity=__default_quantity, max_len=__default_max_len, restart=__default_restart, description=__default_description, source=__default_source, index_base=__default_index_base, enum=__default_enum, enum_flags=__default_enum_flags, bits=__default_bits, enum_labels=__default_enum_labels) -> None:\n    self.id = id\n    self.kind = kind\n    self.key = key\n    self.type = type\n    self.default = default\n    self.range_text = range_text\n    self.range_note = range_note\n    self.dims = dims\n    self.symbols = symbols\n    self.units = units\n    self.quantity = quantity\n    self.max_len = max_len\n    self.restart = restart\n    self.description = description\n    self.source = source\n    self.index_base = index_base\n    self.enum = enum\n    self.enum_flags = enum_flags\n    self.bits = bits\n    self.enum_labels = enum_labels'] = __init__.__code__

def __init__(self, index, lists, zero, axes=None, tools=None, others=None) -> None:
    self.index = index
    self.lists = lists
    self.zero = zero
    self.axes = __factory_axes() if axes is MISSING else axes
    self.tools = tools
    self.others = __factory_others() if others is MISSING else others
INITS['def __init__(self, index, lists, zero, axes=MISSING, tools=__default_tools, others=MISSING) -> None:\n    self.index = index\n    self.lists = lists\n    self.zero = zero\n    self.axes = __factory_axes() if axes is MISSING else axes\n    self.tools = tools\n    self.others = __factory_others() if others is MISSING else others'] = __init__.__code__

def __init__(self, index, log_nr, name, entry, source=None) -> None:
    self.index = index
    self.log_nr = log_nr
    self.name = name
    self.entry = entry
    self.source = source
INITS['def __init__(self, index, log_nr, name, entry, source=__default_source) -> None:\n    self.index = index\n    self.log_nr = log_nr\n    self.name = name\n    self.entry = entry\n    self.source = source'] = __init__.__code__

def __init__(self, key, param_id, kind, default=None, count=None, missing=None) -> None:
    __set(self, 'key', key)
    __set(self, 'param_id', param_id)
    __set(self, 'kind', kind)
    __set(self, 'default', default)
    __set(self, 'count', count)
    __set(self, 'missing', missing)
INITS["def __init__(self, key, param_id, kind, default=__default_default, count=__default_count, missing=__default_missing) -> None:\n    __set(self, 'key', key)\n    __set(self, 'param_id', param_id)\n    __set(self, 'kind', kind)\n    __set(self, 'default', default)\n    __set(self, 'count', count)\n    __set(self, 'missing', missing)"] = __init__.__code__

def __init__(self, key, param_id, kind, old, new, unit=None, delta=None, group=None, note=None, restart=None, coding=None, old_name=None, new_name=None, bits=None) -> None:
    self.key = key
    self.param_id = param_id
    self.kind = kind
    self.old = old
    self.new = new
    self.unit = unit
    self.delta = delta
    self.group = group
    self.note = note
    self.restart = restart
    self.coding = coding
    self.old_name = old_name
    self.new_name = new_name
    self.bits = bits
INITS['def __init__(self, key, param_id, kind, old, new, unit=__default_unit, delta=__default_delta, group=__default_group, note=__default_note, restart=__default_restart, coding=__default_coding, old_name=__default_old_name, new_name=__default_new_name, bits=__default_bits) -> None:\n    self.key = key\n    self.param_id = param_id\n    self.kind = kind\n    self.old = old\n    self.new = new\n    self.unit = unit\n    self.delta = delta\n    self.group = group\n    self.note = note\n    self.restart = restart\n    self.coding = coding\n    self.old_name = old_name\n    self.new_name = new_name\n    self.bits = bits'] = __init__.__code__

def __init__(self, key, param_id, value, origin, layers=None) -> None:
    __set(self, 'key', key)
    __set(self, 'param_id', param_id)
    __set(self, 'value', value)
    __set(self, 'origin', origin)
    __set(self, 'layers', layers)
INITS["def __init__(self, key, param_id, value, origin, layers=__default_layers) -> None:\n    __set(self, 'key', key)\n    __set(self, 'param_id', param_id)\n    __set(self, 'value', value)\n    __set(self, 'origin', origin)\n    __set(self, 'layers', layers)"] = __init__.__code__

def __init__(self, key, path, value, before=None, after=None, line=None, column=None, native=None, key_at=None) -> None:
    self.key = key
    self.path = path
    self.value = value
    self.before = __factory_before() if before is MISSING else before
    self.after = after
    self.line = line
    self.column = column
    self.native = native
    self.key_at = key_at
INITS['def __init__(self, key, path, value, before=MISSING, after=__default_after, line=__default_line, column=__default_column, native=__default_native, key_at=__default_key_at) -> None:\n    self.key = key\n    self.path = path\n    self.value = value\n    self.before = __factory_before() if before is MISSING else before\n    self.after = after\n    self.line = line\n    self.column = column\n    self.native = native\n    self.key_at = key_at'] = __init__.__code__

def __init__(self, key, path, values, line) -> None:
    self.key = key
    self.path = path
    self.values = values
    self.line = line
INITS['def __init__(self, key, path, values, line) -> None:\n    self.key = key\n    self.path = path\n    self.values = values\n    self.line = line'] = __init__.__code__

def __init__(self, key, raw, line, reason=None, consequence=None) -> None:
    self.key = key
    self.raw = raw
    self.line = line
    self.reason = reason
    self.consequence = consequence
INITS['def __init__(self, key, raw, line, reason=__default_reason, consequence=__default_consequence) -> None:\n    self.key = key\n    self.raw = raw\n    self.line = line\n    self.reason = reason\n    self.consequence = consequence'] = __init__.__code__

def __init__(self, key, reference, index, raw, line, path=None, status=None, reason=None) -> None:
    self.key = key
    self.reference = reference
    self.index = index
    self.raw = raw
    self.line = line
    self.path = path
    self.status = status
    self.reason = reason
INITS['def __init__(self, key, reference, index, raw, line, path=__default_path, status=__default_status, reason=__default_reason) -> None:\n    self.key = key\n    self.reference = reference\n    self.index = index\n    self.raw = raw\n    self.line = line\n    self.path = path\n    self.status = status\n    self.reason = reason'] = __init__.__code__

def __init__(self, key, section, type, default, description, example, schema, read, show=None, table=None, default_text=None) -> None:
    __set(self, 'key', key)
    __set(self, 'section', section)
    __set(self, 'type', type)
    __set(self, 'default', default)
    __set(self, 'description', description)
    __set(self, 'example', example)
    __set(self, 'schema', schema)
    __set(self, 'read', read)
    __set(self, 'show', show)
    __set(self, 'table', table)
    __set(self, 'default_text', default_text)
INITS["def __init__(self, key, section, type, default, description, example, schema, read, show=__default_show, table=__default_table, default_text=__default_default_text) -> None:\n    __set(self, 'key', key)\n    __set(self, 'section', section)\n    __set(self, 'type', type)\n    __set(self, 'default', default)\n    __set(self, 'description', description)\n    __set(self, 'example', example)\n    __set(self, 'schema', schema)\n    __set(self, 'read', read)\n    __set(self, 'show', show)\n    __set(self, 'table', table)\n    __set(self, 'default_text', default_text)"] = __init__.__code__

def __init__(self, key, spec, entry, origin) -> None:
    __set(self, 'key', key)
    __set(self, 'spec', spec)
    __set(self, 'entry', entry)
    __set(self, 'origin', origin)
INITS["def __init__(self, key, spec, entry, origin) -> None:\n    __set(self, 'key', key)\n    __set(self, 'spec', spec)\n    __set(self, 'entry', entry)\n    __set(self, 'origin', origin)"] = __init__.__code__

def __init__(self, kind, line, start, end, detail=None) -> None:
    __set(self, 'kind', kind)
    __set(self, 'line', line)
    __set(self, 'start', start)
    __set(self, 'end', end)
    __set(self, 'detail', detail)
INITS["def __init__(self, kind, line, start, end, detail=__default_detail) -> None:\n    __set(self, 'kind', kind)\n    __set(self, 'line', line)\n    __set(self, 'start', start)\n    __set(self, 'end', end)\n    __set(self, 'detail', detail)"] = __init__.__code__

def __init__(self, kind, name, line, start, end, value=None, text=None) -> None:
    self.kind = kind
    self.name = name
    self.line = line
    self.start = start
    self.end = end
    self.value = value
    self.text = text
INITS['def __init__(self, kind, name, line, start, end, value=__default_value, text=__default_text) -> None:\n    self.kind = kind\n    self.name = name\n    self.line = line\n    self.start = start\n    self.end = end\n    self.value = value\n    self.text = text'] = __init__.__code__

def __init__(self, leaves, meta=None, tail=None, path=None, notes=None, _nested=None) -> None:
    self.leaves = leaves
    self.meta = __factory_meta() if meta is MISSING else meta
    self.tail = __factory_tail() if tail is MISSING else tail
    self.path = path
    self.notes = __factory_notes() if notes is MISSING else notes
    self._nested = _nested
INITS['def __init__(self, leaves, meta=MISSING, tail=MISSING, path=__default_path, notes=MISSING, _nested=__default__nested) -> None:\n    self.leaves = leaves\n    self.meta = __factory_meta() if meta is MISSING else meta\n    self.tail = __factory_tail() if tail is MISSING else tail\n    self.path = path\n    self.notes = __factory_notes() if notes is MISSING else notes\n    self._nested = _nested'] = __init__.__code__

def __init__(self, line) -> None:
    self.line = line
INITS['def __init__(self, line) -> None:\n    self.line = line'] = __init__.__code__

def __init__(self, line, column, after=None, before=None, key_at=None) -> None:
    self.line = line
    self.column = column
    self.after = after
    self.before = __factory_before() if before is MISSING else before
    self.key_at = key_at
INITS['def __init__(self, line, column, after=__default_after, before=MISSING, key_at=__default_key_at) -> None:\n    self.line = line\n    self.column = column\n    self.after = after\n    self.before = __factory_before() if before is MISSING else before\n    self.key_at = key_at'] = __init__.__code__

def __init__(self, line, column, end_line, end_column) -> None:
    __set(self, 'line', line)
    __set(self, 'column', column)
    __set(self, 'end_line', end_line)
    __set(self, 'end_column', end_column)
INITS["def __init__(self, line, column, end_line, end_column) -> None:\n    __set(self, 'line', line)\n    __set(self, 'column', column)\n    __set(self, 'end_line', end_line)\n    __set(self, 'end_column', end_column)"] = __init__.__code__

def __init__(self, line, key_raw, key_text, key, key_start, key_end, value, value_kind, value_start, value_end, comment=None, comment_start=None, comment_style=None, annotation=None, annotation_start=None, after_end=None) -> None:
    self.line = line
    self.key_raw = key_raw
    self.key_text = key_text
    self.key = key
    self.key_start = key_start
    self.key_end = key_end
    self.value = value
    self.value_kind = value_kind
    self.value_start = value_start
    self.value_end = value_end
    self.comment = comment
    self.comment_start = comment_start
    self.comment_style = comment_style
    self.annotation = annotation
    self.annotation_start = annotation_start
    self.after_end = after_end
INITS['def __init__(self, line, key_raw, key_text, key, key_start, key_end, value, value_kind, value_start, value_end, comment=__default_comment, comment_start=__default_comment_start, comment_style=__default_comment_style, annotation=__default_annotation, annotation_start=__default_annotation_start, after_end=__default_after_end) -> None:\n    self.line = line\n    self.key_raw = key_raw\n    self.key_text = key_text\n    self.key = key\n    self.key_start = key_start\n    self.key_end = key_end\n    self.value = value\n    self.value_kind = value_kind\n    self.value_start = value_start\n    self.value_end = value_end\n    self.comment = comment\n    self.comment_start = comment_start\n    self.comment_style = comment_style\n    self.annotation = annotation\n    self.annotation_start = annotation_start\n    self.after_end = after_end'] = __init__.__code__

def __init__(self, line, start) -> None:
    self.line = line
    self.start = start
INITS['def __init__(self, line, start) -> None:\n    self.line = line\n    self.start = start'] = __init__.__code__

def __init__(self, line, start, end, axis, programmed, machine, limit, positive, group, offset, limit_from=None, unmonitored=None, arc=None, via=None) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.axis = axis
    self.programmed = programmed
    self.machine = machine
    self.limit = limit
    self.positive = positive
    self.group = group
    self.offset = offset
    self.limit_from = limit_from
    self.unmonitored = unmonitored
    self.arc = arc
    self.via = via
INITS['def __init__(self, line, start, end, axis, programmed, machine, limit, positive, group, offset, limit_from=__default_limit_from, unmonitored=__default_unmonitored, arc=__default_arc, via=__default_via) -> None:\n    self.line = line\n    self.start = start\n    self.end = end\n    self.axis = axis\n    self.programmed = programmed\n    self.machine = machine\n    self.limit = limit\n    self.positive = positive\n    self.group = group\n    self.offset = offset\n    self.limit_from = limit_from\n    self.unmonitored = unmonitored\n    self.arc = arc\n    self.via = via'] = __init__.__code__

def __init__(self, line, start, end, codes, scope, target=None, used=None) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.codes = codes
    self.scope = scope
    self.target = target
    self.used = __factory_used() if used is MISSING else used
INITS['def __init__(self, line, start, end, codes, scope, target=__default_target, used=MISSING) -> None:\n    self.line = line\n    self.start = start\n    self.end = end\n    self.codes = codes\n    self.scope = scope\n    self.target = target\n    self.used = __factory_used() if used is MISSING else used'] = __init__.__code__

def __init__(self, line, start, end, name, local, cycle) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.name = name
    self.local = local
    self.cycle = cycle
INITS['def __init__(self, line, start, end, name, local, cycle) -> None:\n    self.line = line\n    self.start = start\n    self.end = end\n    self.name = name\n    self.local = local\n    self.cycle = cycle'] = __init__.__code__

def __init__(self, line, start, end, positive, relative, axis, value) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.positive = positive
    self.relative = relative
    self.axis = axis
    self.value = value
INITS['def __init__(self, line, start, end, positive, relative, axis, value) -> None:\n    self.line = line\n    self.start = start\n    self.end = end\n    self.positive = positive\n    self.relative = relative\n    self.axis = axis\n    self.value = value'] = __init__.__code__

def __init__(self, line, start, end, syn, axis=None, axnr=None, writes=None, wait=None, problems=None, axparams=None) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.syn = syn
    self.axis = axis
    self.axnr = axnr
    self.writes = __factory_writes() if writes is MISSING else writes
    self.wait = wait
    self.problems = __factory_problems() if problems is MISSING else problems
    self.axparams = __factory_axparams() if axparams is MISSING else axparams
INITS['def __init__(self, line, start, end, syn, axis=__default_axis, axnr=__default_axnr, writes=MISSING, wait=__default_wait, problems=MISSING, axparams=MISSING) -> None:\n    self.line = line\n    self.start = start\n    self.end = end\n    self.syn = syn\n    self.axis = axis\n    self.axnr = axnr\n    self.writes = __factory_writes() if writes is MISSING else writes\n    self.wait = wait\n    self.problems = __factory_problems() if problems is MISSING else problems\n    self.axparams = __factory_axparams() if axparams is MISSING else axparams'] = __init__.__code__

def __init__(self, line, start, end, text, kind) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.text = text
    self.kind = kind
INITS['def __init__(self, line, start, end, text, kind) -> None:\n    self.line = line\n    self.start = start\n    self.end = end\n    self.text = text\n    self.kind = kind'] = __init__.__code__

def __init__(self, line, text) -> None:
    self.line = line
    self.text = text
INITS['def __init__(self, line, text) -> None:\n    self.line = line\n    self.text = text'] = __init__.__code__

def __init__(self, line, text, commented_out=None) -> None:
    self.line = line
    self.text = text
    self.commented_out = commented_out
INITS['def __init__(self, line, text, commented_out=__default_commented_out) -> None:\n    self.line = line\n    self.text = text\n    self.commented_out = commented_out'] = __init__.__code__

def __init__(self, lo, hi, x0=None, x1=None) -> None:
    self.lo = lo
    self.hi = hi
    self.x0 = x0
    self.x1 = x1
INITS['def __init__(self, lo, hi, x0=__default_x0, x1=__default_x1) -> None:\n    self.lo = lo\n    self.hi = hi\n    self.x0 = x0\n    self.x1 = x1'] = __init__.__code__

def __init__(self, low, low_strict, high, high_strict) -> None:
    __set(self, 'low', low)
    __set(self, 'low_strict', low_strict)
    __set(self, 'high', high)
    __set(self, 'high_strict', high_strict)
INITS["def __init__(self, low, low_strict, high, high_strict) -> None:\n    __set(self, 'low', low)\n    __set(self, 'low_strict', low_strict)\n    __set(self, 'high', high)\n    __set(self, 'high_strict', high_strict)"] = __init__.__code__

def __init__(self, low=None, low_strict=None, high=None, high_strict=None, allowed=None) -> None:
    __set(self, 'low', low)
    __set(self, 'low_strict', low_strict)
    __set(self, 'high', high)
    __set(self, 'high_strict', high_strict)
    __set(self, 'allowed', allowed)
INITS["def __init__(self, low=__default_low, low_strict=__default_low_strict, high=__default_high, high_strict=__default_high_strict, allowed=__default_allowed) -> None:\n    __set(self, 'low', low)\n    __set(self, 'low_strict', low_strict)\n    __set(self, 'high', high)\n    __set(self, 'high_strict', high_strict)\n    __set(self, 'allowed', allowed)"] = __init__.__code__

def __init__(self, machine, error) -> None:
    self.machine = machine
    self.error = error
INITS['def __init__(self, machine, error) -> None:\n    self.machine = machine\n    self.error = error'] = __init__.__code__

def __init__(self, machine, found=None, lists=None, error=None, deps=None) -> None:
    self.machine = machine
    self.found = __factory_found() if found is MISSING else found
    self.lists = __factory_lists() if lists is MISSING else lists
    self.error = error
    self.deps = deps
INITS['def __init__(self, machine, found=MISSING, lists=MISSING, error=__default_error, deps=__default_deps) -> None:\n    self.machine = machine\n    self.found = __factory_found() if found is MISSING else found\n    self.lists = __factory_lists() if lists is MISSING else lists\n    self.error = error\n    self.deps = deps'] = __init__.__code__

def __init__(self, machine, registry, severities=None, path=None) -> None:
    self.machine = machine
    self.registry = registry
    self.severities = __factory_severities() if severities is MISSING else severities
    self.path = path
INITS['def __init__(self, machine, registry, severities=MISSING, path=__default_path) -> None:\n    self.machine = machine\n    self.registry = registry\n    self.severities = __factory_severities() if severities is MISSING else severities\n    self.path = path'] = __init__.__code__

def __init__(self, machine, startup, registry, results, against=None, travels=None, drift=None) -> None:
    self.machine = machine
    self.startup = startup
    self.registry = registry
    self.results = results
    self.against = against
    self.travels = __factory_travels() if travels is MISSING else travels
    self.drift = drift
INITS['def __init__(self, machine, startup, registry, results, against=__default_against, travels=MISSING, drift=__default_drift) -> None:\n    self.machine = machine\n    self.startup = startup\n    self.registry = registry\n    self.results = results\n    self.against = against\n    self.travels = __factory_travels() if travels is MISSING else travels\n    self.drift = drift'] = __init__.__code__

def __init__(self, message, line=None, column=None, severity=None, elsewhere=None) -> None:
    self.message = message
    self.line = line
    self.column = column
    self.severity = severity
    self.elsewhere = elsewhere
INITS['def __init__(self, message, line=__default_line, column=__default_column, severity=__default_severity, elsewhere=__default_elsewhere) -> None:\n    self.message = message\n    self.line = line\n    self.column = column\n    self.severity = severity\n    self.elsewhere = elsewhere'] = __init__.__code__

def __init__(self, moves=None, evaluated=None, skipped=None, crossings=None, unknown=None, structure=None, calls=None, travel=None, machine=None, locals=None, unfollowed=None, not_followed=None, followed=None) -> None:
    self.moves = moves
    self.evaluated = evaluated
    self.skipped = __factory_skipped() if skipped is MISSING else skipped
    self.crossings = __factory_crossings() if crossings is MISSING else crossings
    self.unknown = __factory_unknown() if unknown is MISSING else unknown
    self.structure = __factory_structure() if structure is MISSING else structure
    self.calls = __factory_calls() if calls is MISSING else calls
    self.travel = __factory_travel() if travel is MISSING else travel
    self.machine = machine
    self.locals = __factory_locals() if locals is MISSING else locals
    self.unfollowed = __factory_unfollowed() if unfollowed is MISSING else unfollowed
    self.not_followed = __factory_not_followed() if not_followed is MISSING else not_followed
    self.followed = __factory_followed() if followed is MISSING else followed
INITS['def __init__(self, moves=__default_moves, evaluated=__default_evaluated, skipped=MISSING, crossings=MISSING, unknown=MISSING, structure=MISSING, calls=MISSING, travel=MISSING, machine=__default_machine, locals=MISSING, unfollowed=MISSING, not_followed=MISSING, followed=MISSING) -> None:\n    self.moves = moves\n    self.evaluated = evaluated\n    self.skipped = __factory_skipped() if skipped is MISSING else skipped\n    self.crossings = __factory_crossings() if crossings is MISSING else crossings\n    self.unknown = __factory_unknown() if unknown is MISSING else unknown\n    self.structure = __factory_structure() if structure is MISSING else structure\n    self.calls = __factory_calls() if calls is MISSING else calls\n    self.travel = __factory_travel() if travel is MISSING else travel\n    self.machine = machine\n    self.locals = __factory_locals() if locals is MISSING else locals\n    self.unfollowed = __factory_unfollowed() if unfollowed is MISSING else unfollowed\n    self.not_followed = __factory_not_followed() if not_followed is MISSING else not_followed\n    self.followed = __factory_followed() if followed is MISSING else followed'] = __init__.__code__

def __init__(self, name, attrs, start, end, depth, empty, raw=None) -> None:
    self.name = name
    self.attrs = attrs
    self.start = start
    self.end = end
    self.depth = depth
    self.empty = empty
    self.raw = __factory_raw() if raw is MISSING else raw
INITS['def __init__(self, name, attrs, start, end, depth, empty, raw=MISSING) -> None:\n    self.name = name\n    self.attrs = attrs\n    self.start = start\n    self.end = end\n    self.depth = depth\n    self.empty = empty\n    self.raw = __factory_raw() if raw is MISSING else raw'] = __init__.__code__

def __init__(self, name, consequence, severity, says, source, releases=None, kinds=None, kernel_error=None) -> None:
    __set(self, 'name', name)
    __set(self, 'consequence', consequence)
    __set(self, 'severity', severity)
    __set(self, 'says', says)
    __set(self, 'source', source)
    __set(self, 'releases', releases)
    __set(self, 'kinds', kinds)
    __set(self, 'kernel_error', kernel_error)
INITS["def __init__(self, name, consequence, severity, says, source, releases=__default_releases, kinds=__default_kinds, kernel_error=__default_kernel_error) -> None:\n    __set(self, 'name', name)\n    __set(self, 'consequence', consequence)\n    __set(self, 'severity', severity)\n    __set(self, 'says', says)\n    __set(self, 'source', source)\n    __set(self, 'releases', releases)\n    __set(self, 'kinds', kinds)\n    __set(self, 'kernel_error', kernel_error)"] = __init__.__code__

def __init__(self, name, detail, level, symbols=None, groups=None, order=None, first=None, last=None) -> None:
    self.name = name
    self.detail = detail
    self.level = level
    self.symbols = __factory_symbols() if symbols is MISSING else symbols
    self.groups = __factory_groups() if groups is MISSING else groups
    self.order = __factory_order() if order is MISSING else order
    self.first = first
    self.last = last
INITS['def __init__(self, name, detail, level, symbols=MISSING, groups=MISSING, order=MISSING, first=__default_first, last=__default_last) -> None:\n    self.name = name\n    self.detail = detail\n    self.level = level\n    self.symbols = __factory_symbols() if symbols is MISSING else symbols\n    self.groups = __factory_groups() if groups is MISSING else groups\n    self.order = __factory_order() if order is MISSING else order\n    self.first = first\n    self.last = last'] = __init__.__code__

def __init__(self, name, file, values=None) -> None:
    self.name = name
    self.file = file
    self.values = __factory_values() if values is MISSING else values
INITS['def __init__(self, name, file, values=MISSING) -> None:\n    self.name = name\n    self.file = file\n    self.values = __factory_values() if values is MISSING else values'] = __init__.__code__

def __init__(self, name, fmt, output=None, notes=None, findings=None, error=None, element=None) -> None:
    self.name = name
    self.fmt = fmt
    self.output = output
    self.notes = __factory_notes() if notes is MISSING else notes
    self.findings = findings
    self.error = error
    self.element = element
INITS['def __init__(self, name, fmt, output=__default_output, notes=MISSING, findings=__default_findings, error=__default_error, element=__default_element) -> None:\n    self.name = name\n    self.fmt = fmt\n    self.output = output\n    self.notes = __factory_notes() if notes is MISSING else notes\n    self.findings = findings\n    self.error = error\n    self.element = element'] = __init__.__code__

def __init__(self, name, item, properties=None, owning=None) -> None:
    self.name = name
    self.item = item
    self.properties = __factory_properties() if properties is MISSING else properties
    self.owning = owning
INITS['def __init__(self, name, item, properties=MISSING, owning=__default_owning) -> None:\n    self.name = name\n    self.item = item\n    self.properties = __factory_properties() if properties is MISSING else properties\n    self.owning = owning'] = __init__.__code__

def __init__(self, name, key, kind, side, own, based) -> None:
    self.name = name
    self.key = key
    self.kind = kind
    self.side = side
    self.own = own
    self.based = based
INITS['def __init__(self, name, key, kind, side, own, based) -> None:\n    self.name = name\n    self.key = key\n    self.kind = kind\n    self.side = side\n    self.own = own\n    self.based = based'] = __init__.__code__

def __init__(self, name, log_nr, unit, rotary, modulo, swe_neg, swe_pos, tolerance, ref, channel=None, index=None, zeros=None, modulo_range=None, old_neg=None, old_pos=None, monitoring=None, monitoring_why=None, travel=None) -> None:
    self.name = name
    self.log_nr = log_nr
    self.unit = unit
    self.rotary = rotary
    self.modulo = modulo
    self.swe_neg = swe_neg
    self.swe_pos = swe_pos
    self.tolerance = tolerance
    self.ref = ref
    self.channel = channel
    self.index = index
    self.zeros = __factory_zeros() if zeros is MISSING else zeros
    self.modulo_range = modulo_range
    self.old_neg = old_neg
    self.old_pos = old_pos
    self.monitoring = monitoring
    self.monitoring_why = monitoring_why
    self.travel = __factory_travel() if travel is MISSING else travel
INITS['def __init__(self, name, log_nr, unit, rotary, modulo, swe_neg, swe_pos, tolerance, ref, channel=__default_channel, index=__default_index, zeros=MISSING, modulo_range=__default_modulo_range, old_neg=__default_old_neg, old_pos=__default_old_pos, monitoring=__default_monitoring, monitoring_why=__default_monitoring_why, travel=MISSING) -> None:\n    self.name = name\n    self.log_nr = log_nr\n    self.unit = unit\n    self.rotary = rotary\n    self.modulo = modulo\n    self.swe_neg = swe_neg\n    self.swe_pos = swe_pos\n    self.tolerance = tolerance\n    self.ref = ref\n    self.channel = channel\n    self.index = index\n    self.zeros = __factory_zeros() if zeros is MISSING else zeros\n    self.modulo_range = modulo_range\n    self.old_neg = old_neg\n    self.old_pos = old_pos\n    self.monitoring = monitoring\n    self.monitoring_why = monitoring_why\n    self.travel = __factory_travel() if travel is MISSING else travel'] = __init__.__code__

def __init__(self, name, module, function, note, streamed=None, fail_on=None, json_statistics=None, aliases=None) -> None:
    __set(self, 'name', name)
    __set(self, 'module', module)
    __set(self, 'function', function)
    __set(self, 'note', note)
    __set(self, 'streamed', streamed)
    __set(self, 'fail_on', fail_on)
    __set(self, 'json_statistics', json_statistics)
    __set(self, 'aliases', aliases)
INITS["def __init__(self, name, module, function, note, streamed=__default_streamed, fail_on=__default_fail_on, json_statistics=__default_json_statistics, aliases=__default_aliases) -> None:\n    __set(self, 'name', name)\n    __set(self, 'module', module)\n    __set(self, 'function', function)\n    __set(self, 'note', note)\n    __set(self, 'streamed', streamed)\n    __set(self, 'fail_on', fail_on)\n    __set(self, 'json_statistics', json_statistics)\n    __set(self, 'aliases', aliases)"] = __init__.__code__

def __init__(self, name, neg, pos, rotary=None) -> None:
    self.name = name
    self.neg = neg
    self.pos = pos
    self.rotary = rotary
INITS['def __init__(self, name, neg, pos, rotary=__default_rotary) -> None:\n    self.name = name\n    self.neg = neg\n    self.pos = pos\n    self.rotary = rotary'] = __init__.__code__

def __init__(self, name, offset, offset_text, item, tag, start, end, address=None, kind=None, properties=None) -> None:
    self.name = name
    self.offset = offset
    self.offset_text = offset_text
    self.item = item
    self.tag = tag
    self.start = start
    self.end = end
    self.address = address
    self.kind = kind
    self.properties = __factory_properties() if properties is MISSING else properties
INITS['def __init__(self, name, offset, offset_text, item, tag, start, end, address=__default_address, kind=__default_kind, properties=MISSING) -> None:\n    self.name = name\n    self.offset = offset\n    self.offset_text = offset_text\n    self.item = item\n    self.tag = tag\n    self.start = start\n    self.end = end\n    self.address = address\n    self.kind = kind\n    self.properties = __factory_properties() if properties is MISSING else properties'] = __init__.__code__

def __init__(self, name, unit, code, behaviour, path, neg, pos, kernel_error=None) -> None:
    self.name = name
    self.unit = unit
    self.code = code
    self.behaviour = behaviour
    self.path = path
    self.neg = neg
    self.pos = pos
    self.kernel_error = kernel_error
INITS['def __init__(self, name, unit, code, behaviour, path, neg, pos, kernel_error=__default_kernel_error) -> None:\n    self.name = name\n    self.unit = unit\n    self.code = code\n    self.behaviour = behaviour\n    self.path = path\n    self.neg = neg\n    self.pos = pos\n    self.kernel_error = kernel_error'] = __init__.__code__

def __init__(self, nr, name, rotary, swe_neg, swe_pos, list) -> None:
    self.nr = nr
    self.name = name
    self.rotary = rotary
    self.swe_neg = swe_neg
    self.swe_pos = swe_pos
    self.list = list
INITS['def __init__(self, nr, name, rotary, swe_neg, swe_pos, list) -> None:\n    self.nr = nr\n    self.name = name\n    self.rotary = rotary\n    self.swe_neg = swe_neg\n    self.swe_pos = swe_pos\n    self.list = list'] = __init__.__code__

def __init__(self, number=None, text=None, ref=None, problem=None, detail=None) -> None:
    self.number = number
    self.text = text
    self.ref = ref
    self.problem = problem
    self.detail = detail
INITS['def __init__(self, number=__default_number, text=__default_text, ref=__default_ref, problem=__default_problem, detail=__default_detail) -> None:\n    self.number = number\n    self.text = text\n    self.ref = ref\n    self.problem = problem\n    self.detail = detail'] = __init__.__code__

def __init__(self, old, kind, new, id, release, source, see=None) -> None:
    __set(self, 'old', old)
    __set(self, 'kind', kind)
    __set(self, 'new', new)
    __set(self, 'id', id)
    __set(self, 'release', release)
    __set(self, 'source', source)
    __set(self, 'see', see)
INITS["def __init__(self, old, kind, new, id, release, source, see=__default_see) -> None:\n    __set(self, 'old', old)\n    __set(self, 'kind', kind)\n    __set(self, 'new', new)\n    __set(self, 'id', id)\n    __set(self, 'release', release)\n    __set(self, 'source', source)\n    __set(self, 'see', see)"] = __init__.__code__

def __init__(self, old, kind, new, release, source, see=None) -> None:
    __set(self, 'old', old)
    __set(self, 'kind', kind)
    __set(self, 'new', new)
    __set(self, 'release', release)
    __set(self, 'source', source)
    __set(self, 'see', see)
INITS["def __init__(self, old, kind, new, release, source, see=__default_see) -> None:\n    __set(self, 'old', old)\n    __set(self, 'kind', kind)\n    __set(self, 'new', new)\n    __set(self, 'release', release)\n    __set(self, 'source', source)\n    __set(self, 'see', see)"] = __init__.__code__

def __init__(self, old, kind, release, source, see=None) -> None:
    __set(self, 'old', old)
    __set(self, 'kind', kind)
    __set(self, 'release', release)
    __set(self, 'source', source)
    __set(self, 'see', see)
INITS["def __init__(self, old, kind, release, source, see=__default_see) -> None:\n    __set(self, 'old', old)\n    __set(self, 'kind', kind)\n    __set(self, 'release', release)\n    __set(self, 'source', source)\n    __set(self, 'see', see)"] = __init__.__code__

def __init__(self, op, left, right) -> None:
    __set(self, 'op', op)
    __set(self, 'left', left)
    __set(self, 'right', right)
INITS["def __init__(self, op, left, right) -> None:\n    __set(self, 'op', op)\n    __set(self, 'left', left)\n    __set(self, 'right', right)"] = __init__.__code__

def __init__(self, operand) -> None:
    __set(self, 'operand', operand)
INITS["def __init__(self, operand) -> None:\n    __set(self, 'operand', operand)"] = __init__.__code__

def __init__(self, out, err, out_bytes) -> None:
    self.out = out
    self.err = err
    self.out_bytes = out_bytes
INITS['def __init__(self, out, err, out_bytes) -> None:\n    self.out = out\n    self.err = err\n    self.out_bytes = out_bytes'] = __init__.__code__

def __init__(self, output, tree, notes=None, lint=None) -> None:
    self.output = output
    self.tree = tree
    self.notes = __factory_notes() if notes is MISSING else notes
    self.lint = lint
INITS['def __init__(self, output, tree, notes=MISSING, lint=__default_lint) -> None:\n    self.output = output\n    self.tree = tree\n    self.notes = __factory_notes() if notes is MISSING else notes\n    self.lint = lint'] = __init__.__code__

def __init__(self, parent, start, end) -> None:
    self.parent = parent
    self.start = start
    self.end = end
INITS['def __init__(self, parent, start, end) -> None:\n    self.parent = parent\n    self.start = start\n    self.end = end'] = __init__.__code__

def __init__(self, path, block, line) -> None:
    self.path = path
    self.block = block
    self.line = line
INITS['def __init__(self, path, block, line) -> None:\n    self.path = path\n    self.block = block\n    self.line = line'] = __init__.__code__

def __init__(self, path, config, options, param_desc, project) -> None:
    __set(self, 'path', path)
    __set(self, 'config', config)
    __set(self, 'options', options)
    __set(self, 'param_desc', param_desc)
    __set(self, 'project', project)
INITS["def __init__(self, path, config, options, param_desc, project) -> None:\n    __set(self, 'path', path)\n    __set(self, 'config', config)\n    __set(self, 'options', options)\n    __set(self, 'param_desc', param_desc)\n    __set(self, 'project', project)"] = __init__.__code__

def __init__(self, path, document, kind, diagnostics=None, note=None) -> None:
    self.path = path
    self.document = document
    self.kind = kind
    self.diagnostics = __factory_diagnostics() if diagnostics is MISSING else diagnostics
    self.note = note
INITS['def __init__(self, path, document, kind, diagnostics=MISSING, note=__default_note) -> None:\n    self.path = path\n    self.document = document\n    self.kind = kind\n    self.diagnostics = __factory_diagnostics() if diagnostics is MISSING else diagnostics\n    self.note = note'] = __init__.__code__

def __init__(self, path, kind, entries, comments=None, update=None) -> None:
    self.path = path
    self.kind = kind
    self.entries = entries
    self.comments = __factory_comments() if comments is MISSING else comments
    self.update = update
INITS['def __init__(self, path, kind, entries, comments=MISSING, update=__default_update) -> None:\n    self.path = path\n    self.kind = kind\n    self.entries = entries\n    self.comments = __factory_comments() if comments is MISSING else comments\n    self.update = update'] = __init__.__code__

def __init__(self, path=None, select=None, extend_select=None, ignore=None, per_file_ignores=None, severity=None, kind=None, encoding=None, include=None, exclude=None, param_desc=None, kernel=None, machine=None, machine_lists=None, machine_workdir=None, machine_roots=None, extend_exclude=None, extend_per_file_ignores=None, respect_gitignore=None, parent=None, given=None) -> None:
    self.path = path
    self.select = select
    self.extend_select = extend_select
    self.ignore = ignore
    self.per_file_ignores = per_file_ignores
    self.severity = __factory_severity() if severity is MISSING else severity
    self.kind = kind
    self.encoding = encoding
    self.include = include
    self.exclude = exclude
    self.param_desc = param_desc
    self.kernel = kernel
    self.machine = machine
    self.machine_lists = __factory_machine_lists() if machine_lists is MISSING else machine_lists
    self.machine_workdir = machine_workdir
    self.machine_roots = machine_roots
    self.extend_exclude = extend_exclude
    self.extend_per_file_ignores = extend_per_file_ignores
    self.respect_gitignore = respect_gitignore
    self.parent = parent
    self.given = given
INITS['def __init__(self, path=__default_path, select=__default_select, extend_select=__default_extend_select, ignore=__default_ignore, per_file_ignores=__default_per_file_ignores, severity=MISSING, kind=__default_kind, encoding=__default_encoding, include=__default_include, exclude=__default_exclude, param_desc=__default_param_desc, kernel=__default_kernel, machine=__default_machine, machine_lists=MISSING, machine_workdir=__default_machine_workdir, machine_roots=__default_machine_roots, extend_exclude=__default_extend_exclude, extend_per_file_ignores=__default_extend_per_file_ignores, respect_gitignore=__default_respect_gitignore, parent=__default_parent, given=__default_given) -> None:\n    self.path = path\n    self.select = select\n    self.extend_select = extend_select\n    self.ignore = ignore\n    self.per_file_ignores = per_file_ignores\n    self.severity = __factory_severity() if severity is MISSING else severity\n    self.kind = kind\n    self.encoding = encoding\n    self.include = include\n    self.exclude = exclude\n    self.param_desc = param_desc\n    self.kernel = kernel\n    self.machine = machine\n    self.machine_lists = __factory_machine_lists() if machine_lists is MISSING else machine_lists\n    self.machine_workdir = machine_workdir\n    self.machine_roots = machine_roots\n    self.extend_exclude = extend_exclude\n    self.extend_per_file_ignores = extend_per_file_ignores\n    self.respect_gitignore = respect_gitignore\n    self.parent = parent\n    self.given = given'] = __init__.__code__

def __init__(self, paths=None, select=None, ignore=None, kind=None, param_desc=None, jobs=None, config=None, isolated=None, fix=None, show_diff=None, unsafe_fixes=None, stdin_filename=None, machine=None, extend_select=None, add_noqa=None, force_exclude=None, ignore_noqa=None, stream=None, cache=None) -> None:
    self.paths = paths
    self.select = select
    self.ignore = ignore
    self.kind = kind
    self.param_desc = param_desc
    self.jobs = jobs
    self.config = config
    self.isolated = isolated
    self.fix = fix
    self.show_diff = show_diff
    self.unsafe_fixes = unsafe_fixes
    self.stdin_filename = stdin_filename
    self.machine = machine
    self.extend_select = extend_select
    self.add_noqa = add_noqa
    self.force_exclude = force_exclude
    self.ignore_noqa = ignore_noqa
    self.stream = stream
    self.cache = cache
INITS['def __init__(self, paths=__default_paths, select=__default_select, ignore=__default_ignore, kind=__default_kind, param_desc=__default_param_desc, jobs=__default_jobs, config=__default_config, isolated=__default_isolated, fix=__default_fix, show_diff=__default_show_diff, unsafe_fixes=__default_unsafe_fixes, stdin_filename=__default_stdin_filename, machine=__default_machine, extend_select=__default_extend_select, add_noqa=__default_add_noqa, force_exclude=__default_force_exclude, ignore_noqa=__default_ignore_noqa, stream=__default_stream, cache=__default_cache) -> None:\n    self.paths = paths\n    self.select = select\n    self.ignore = ignore\n    self.kind = kind\n    self.param_desc = param_desc\n    self.jobs = jobs\n    self.config = config\n    self.isolated = isolated\n    self.fix = fix\n    self.show_diff = show_diff\n    self.unsafe_fixes = unsafe_fixes\n    self.stdin_filename = stdin_filename\n    self.machine = machine\n    self.extend_select = extend_select\n    self.add_noqa = add_noqa\n    self.force_exclude = force_exclude\n    self.ignore_noqa = ignore_noqa\n    self.stream = stream\n    self.cache = cache'] = __init__.__code__

def __init__(self, picture, svg, settings=None, monitor_where=None) -> None:
    self.picture = picture
    self.svg = svg
    self.settings = __factory_settings() if settings is MISSING else settings
    self.monitor_where = monitor_where
INITS['def __init__(self, picture, svg, settings=MISSING, monitor_where=__default_monitor_where) -> None:\n    self.picture = picture\n    self.svg = svg\n    self.settings = __factory_settings() if settings is MISSING else settings\n    self.monitor_where = monitor_where'] = __init__.__code__

def __init__(self, program, registry, machine=None, severities=None, path=None) -> None:
    self.program = program
    self.registry = registry
    self.machine = machine
    self.severities = __factory_severities() if severities is MISSING else severities
    self.path = path
INITS['def __init__(self, program, registry, machine=__default_machine, severities=MISSING, path=__default_path) -> None:\n    self.program = program\n    self.registry = registry\n    self.machine = machine\n    self.severities = __factory_severities() if severities is MISSING else severities\n    self.path = path'] = __init__.__code__

def __init__(self, project, registry, options, scopes, defaults, keep=None) -> None:
    self.project = project
    self.registry = registry
    self.options = options
    self.scopes = scopes
    self.defaults = defaults
    self.keep = keep
INITS['def __init__(self, project, registry, options, scopes, defaults, keep=__default_keep) -> None:\n    self.project = project\n    self.registry = registry\n    self.options = options\n    self.scopes = scopes\n    self.defaults = defaults\n    self.keep = keep'] = __init__.__code__

def __init__(self, renames, removals, prefixes) -> None:
    __set(self, 'renames', renames)
    __set(self, 'removals', removals)
    __set(self, 'prefixes', prefixes)
INITS["def __init__(self, renames, removals, prefixes) -> None:\n    __set(self, 'renames', renames)\n    __set(self, 'removals', removals)\n    __set(self, 'prefixes', prefixes)"] = __init__.__code__

def __init__(self, results=None, report=None, findings_to_stderr=None, changed=None, fixed=None) -> None:
    self.results = __factory_results() if results is MISSING else results
    self.report = report
    self.findings_to_stderr = findings_to_stderr
    self.changed = changed
    self.fixed = __factory_fixed() if fixed is MISSING else fixed
INITS['def __init__(self, results=MISSING, report=__default_report, findings_to_stderr=__default_findings_to_stderr, changed=__default_changed, fixed=MISSING) -> None:\n    self.results = __factory_results() if results is MISSING else results\n    self.report = report\n    self.findings_to_stderr = findings_to_stderr\n    self.changed = changed\n    self.fixed = __factory_fixed() if fixed is MISSING else fixed'] = __init__.__code__

def __init__(self, rows, violations=None) -> None:
    self.rows = rows
    self.violations = __factory_violations() if violations is MISSING else violations
INITS['def __init__(self, rows, violations=MISSING) -> None:\n    self.rows = rows\n    self.violations = __factory_violations() if violations is MISSING else violations'] = __init__.__code__

def __init__(self, scan, blocks, files=None) -> None:
    self.scan = scan
    self.blocks = blocks
    self.files = __factory_files() if files is MISSING else files
INITS['def __init__(self, scan, blocks, files=MISSING) -> None:\n    self.scan = scan\n    self.blocks = blocks\n    self.files = __factory_files() if files is MISSING else files'] = __init__.__code__

def __init__(self, scope, key, param_id, group, golden, golden_note, golden_name, unit, value, note, name, delta, same) -> None:
    self.scope = scope
    self.key = key
    self.param_id = param_id
    self.group = group
    self.golden = golden
    self.golden_note = golden_note
    self.golden_name = golden_name
    self.unit = unit
    self.value = value
    self.note = note
    self.name = name
    self.delta = delta
    self.same = same
INITS['def __init__(self, scope, key, param_id, group, golden, golden_note, golden_name, unit, value, note, name, delta, same) -> None:\n    self.scope = scope\n    self.key = key\n    self.param_id = param_id\n    self.group = group\n    self.golden = golden\n    self.golden_note = golden_note\n    self.golden_name = golden_name\n    self.unit = unit\n    self.value = value\n    self.note = note\n    self.name = name\n    self.delta = delta\n    self.same = same'] = __init__.__code__

def __init__(self, scope, key, param_id, group, golden, golden_note=None, golden_name=None, unit=None, values=None) -> None:
    self.scope = scope
    self.key = key
    self.param_id = param_id
    self.group = group
    self.golden = golden
    self.golden_note = golden_note
    self.golden_name = golden_name
    self.unit = unit
    self.values = __factory_values() if values is MISSING else values
INITS['def __init__(self, scope, key, param_id, group, golden, golden_note=__default_golden_note, golden_name=__default_golden_name, unit=__default_unit, values=MISSING) -> None:\n    self.scope = scope\n    self.key = key\n    self.param_id = param_id\n    self.group = group\n    self.golden = golden\n    self.golden_note = golden_note\n    self.golden_name = golden_name\n    self.unit = unit\n    self.values = __factory_values() if values is MISSING else values'] = __init__.__code__

def __init__(self, scope, key, param_id, value, origin, where, differs, shown=None, default=None, default_shown=None, used=None, used_by=None, findings=None, also=None, repeated=None) -> None:
    self.scope = scope
    self.key = key
    self.param_id = param_id
    self.value = value
    self.origin = origin
    self.where = where
    self.differs = differs
    self.shown = shown
    self.default = default
    self.default_shown = default_shown
    self.used = used
    self.used_by = used_by
    self.findings = __factory_findings() if findings is MISSING else findings
    self.also = __factory_also() if also is MISSING else also
    self.repeated = repeated
INITS['def __init__(self, scope, key, param_id, value, origin, where, differs, shown=__default_shown, default=__default_default, default_shown=__default_default_shown, used=__default_used, used_by=__default_used_by, findings=MISSING, also=MISSING, repeated=__default_repeated) -> None:\n    self.scope = scope\n    self.key = key\n    self.param_id = param_id\n    self.value = value\n    self.origin = origin\n    self.where = where\n    self.differs = differs\n    self.shown = shown\n    self.default = default\n    self.default_shown = default_shown\n    self.used = used\n    self.used_by = used_by\n    self.findings = __factory_findings() if findings is MISSING else findings\n    self.also = __factory_also() if also is MISSING else also\n    self.repeated = repeated'] = __init__.__code__

def __init__(self, scope, status, reason, machines=None) -> None:
    self.scope = scope
    self.status = status
    self.reason = reason
    self.machines = __factory_machines() if machines is MISSING else machines
INITS['def __init__(self, scope, status, reason, machines=MISSING) -> None:\n    self.scope = scope\n    self.status = status\n    self.reason = reason\n    self.machines = __factory_machines() if machines is MISSING else machines'] = __init__.__code__

def __init__(self, select=None, ignore=None, kind=None, severity=None, extend_select=None, encoding=None, kernel=None, ignore_noqa=None) -> None:
    self.select = select
    self.ignore = ignore
    self.kind = kind
    self.severity = __factory_severity() if severity is MISSING else severity
    self.extend_select = extend_select
    self.encoding = encoding
    self.kernel = kernel
    self.ignore_noqa = ignore_noqa
INITS['def __init__(self, select=__default_select, ignore=__default_ignore, kind=__default_kind, severity=MISSING, extend_select=__default_extend_select, encoding=__default_encoding, kernel=__default_kernel, ignore_noqa=__default_ignore_noqa) -> None:\n    self.select = select\n    self.ignore = ignore\n    self.kind = kind\n    self.severity = __factory_severity() if severity is MISSING else severity\n    self.extend_select = extend_select\n    self.encoding = encoding\n    self.kernel = kernel\n    self.ignore_noqa = ignore_noqa'] = __init__.__code__

def __init__(self, source, path=None, line=None) -> None:
    __set(self, 'source', source)
    __set(self, 'path', path)
    __set(self, 'line', line)
INITS["def __init__(self, source, path=__default_path, line=__default_line) -> None:\n    __set(self, 'source', source)\n    __set(self, 'path', path)\n    __set(self, 'line', line)"] = __init__.__code__

def __init__(self, span, message, path=None) -> None:
    __set(self, 'span', span)
    __set(self, 'message', message)
    __set(self, 'path', path)
INITS["def __init__(self, span, message, path=__default_path) -> None:\n    __set(self, 'span', span)\n    __set(self, 'message', message)\n    __set(self, 'path', path)"] = __init__.__code__

def __init__(self, span, replacement) -> None:
    __set(self, 'span', span)
    __set(self, 'replacement', replacement)
INITS["def __init__(self, span, replacement) -> None:\n    __set(self, 'span', span)\n    __set(self, 'replacement', replacement)"] = __init__.__code__

def __init__(self, spec, key=None, indices=None, entry=None, alias=None, start=None, end=None, values=None) -> None:
    self.spec = spec
    self.key = key
    self.indices = indices
    self.entry = entry
    self.alias = alias
    self.start = start
    self.end = end
    self.values = values
INITS['def __init__(self, spec, key=__default_key, indices=__default_indices, entry=__default_entry, alias=__default_alias, start=__default_start, end=__default_end, values=__default_values) -> None:\n    self.spec = spec\n    self.key = key\n    self.indices = indices\n    self.entry = entry\n    self.alias = alias\n    self.start = start\n    self.end = end\n    self.values = values'] = __init__.__code__

def __init__(self, spec=None, indices=None, matches=None, searched=None) -> None:
    self.spec = spec
    self.indices = indices
    self.matches = __factory_matches() if matches is MISSING else matches
    self.searched = searched
INITS['def __init__(self, spec=__default_spec, indices=__default_indices, matches=MISSING, searched=__default_searched) -> None:\n    self.spec = spec\n    self.indices = indices\n    self.matches = __factory_matches() if matches is MISSING else matches\n    self.searched = searched'] = __init__.__code__

def __init__(self, specs, source=None, _by_key=None, _kinds_of=None, _ranges=None, aliases=None, vendor_keys=None, _suggestions=None, _machine_data=None, _pattern_specs=None, memo=None) -> None:
    self.specs = specs
    self.source = source
    self._by_key = __factory__by_key() if _by_key is MISSING else _by_key
    self._kinds_of = __factory__kinds_of() if _kinds_of is MISSING else _kinds_of
    self._ranges = __factory__ranges() if _ranges is MISSING else _ranges
    self.aliases = __factory_aliases() if aliases is MISSING else aliases
    self.vendor_keys = __factory_vendor_keys() if vendor_keys is MISSING else vendor_keys
    self._suggestions = __factory__suggestions() if _suggestions is MISSING else _suggestions
    self._machine_data = _machine_data
    self._pattern_specs = __factory__pattern_specs() if _pattern_specs is MISSING else _pattern_specs
    self.memo = __factory_memo() if memo is MISSING else memo
    self.__post_init__()
INITS['def __init__(self, specs, source=__default_source, _by_key=MISSING, _kinds_of=MISSING, _ranges=MISSING, aliases=MISSING, vendor_keys=MISSING, _suggestions=MISSING, _machine_data=__default__machine_data, _pattern_specs=MISSING, memo=MISSING) -> None:\n    self.specs = specs\n    self.source = source\n    self._by_key = __factory__by_key() if _by_key is MISSING else _by_key\n    self._kinds_of = __factory__kinds_of() if _kinds_of is MISSING else _kinds_of\n    self._ranges = __factory__ranges() if _ranges is MISSING else _ranges\n    self.aliases = __factory_aliases() if aliases is MISSING else aliases\n    self.vendor_keys = __factory_vendor_keys() if vendor_keys is MISSING else vendor_keys\n    self._suggestions = __factory__suggestions() if _suggestions is MISSING else _suggestions\n    self._machine_data = _machine_data\n    self._pattern_specs = __factory__pattern_specs() if _pattern_specs is MISSING else _pattern_specs\n    self.memo = __factory_memo() if memo is MISSING else memo\n    self.__post_init__()'] = __init__.__code__

def __init__(self, startup, workdir=None, named=None, axis_lists=None, channels=None, defaults=None, singles=None, compensation=None) -> None:
    self.startup = startup
    self.workdir = workdir
    self.named = __factory_named() if named is MISSING else named
    self.axis_lists = __factory_axis_lists() if axis_lists is MISSING else axis_lists
    self.channels = __factory_channels() if channels is MISSING else channels
    self.defaults = __factory_defaults() if defaults is MISSING else defaults
    self.singles = __factory_singles() if singles is MISSING else singles
    self.compensation = __factory_compensation() if compensation is MISSING else compensation
INITS['def __init__(self, startup, workdir=__default_workdir, named=MISSING, axis_lists=MISSING, channels=MISSING, defaults=MISSING, singles=MISSING, compensation=MISSING) -> None:\n    self.startup = startup\n    self.workdir = workdir\n    self.named = __factory_named() if named is MISSING else named\n    self.axis_lists = __factory_axis_lists() if axis_lists is MISSING else axis_lists\n    self.channels = __factory_channels() if channels is MISSING else channels\n    self.defaults = __factory_defaults() if defaults is MISSING else defaults\n    self.singles = __factory_singles() if singles is MISSING else singles\n    self.compensation = __factory_compensation() if compensation is MISSING else compensation'] = __init__.__code__

def __init__(self, strict=None, comments=None) -> None:
    self.strict = strict
    self.comments = comments
INITS['def __init__(self, strict=__default_strict, comments=__default_comments) -> None:\n    self.strict = strict\n    self.comments = comments'] = __init__.__code__

def __init__(self, summary, scopes) -> None:
    self.summary = summary
    self.scopes = scopes
INITS['def __init__(self, summary, scopes) -> None:\n    self.summary = summary\n    self.scopes = scopes'] = __init__.__code__

def __init__(self, text, encoding, bom, root, tags, cdata, line_starts) -> None:
    self.text = text
    self.encoding = encoding
    self.bom = bom
    self.root = root
    self.tags = tags
    self.cdata = cdata
    self.line_starts = line_starts
INITS['def __init__(self, text, encoding, bom, root, tags, cdata, line_starts) -> None:\n    self.text = text\n    self.encoding = encoding\n    self.bom = bom\n    self.root = root\n    self.tags = tags\n    self.cdata = cdata\n    self.line_starts = line_starts'] = __init__.__code__

def __init__(self, text, href) -> None:
    self.text = text
    self.href = href
INITS['def __init__(self, text, href) -> None:\n    self.text = text\n    self.href = href'] = __init__.__code__

def __init__(self, text, lines_of) -> None:
    self.text = text
    self.lines_of = lines_of
INITS['def __init__(self, text, lines_of) -> None:\n    self.text = text\n    self.lines_of = lines_of'] = __init__.__code__

def __init__(self, text, pattern, indices) -> None:
    self.text = text
    self.pattern = pattern
    self.indices = indices
INITS['def __init__(self, text, pattern, indices) -> None:\n    self.text = text\n    self.pattern = pattern\n    self.indices = indices'] = __init__.__code__

def __init__(self, title, edits=None, safe=None) -> None:
    __set(self, 'title', title)
    __set(self, 'edits', edits)
    __set(self, 'safe', safe)
INITS["def __init__(self, title, edits=__default_edits, safe=__default_safe) -> None:\n    __set(self, 'title', title)\n    __set(self, 'edits', edits)\n    __set(self, 'safe', safe)"] = __init__.__code__

def __init__(self, title, name, text, lines=None, report=None) -> None:
    __set(self, 'title', title)
    __set(self, 'name', name)
    __set(self, 'text', text)
    __set(self, 'lines', lines)
    __set(self, 'report', report)
INITS["def __init__(self, title, name, text, lines=__default_lines, report=__default_report) -> None:\n    __set(self, 'title', title)\n    __set(self, 'name', name)\n    __set(self, 'text', text)\n    __set(self, 'lines', lines)\n    __set(self, 'report', report)"] = __init__.__code__

def __init__(self, title, startup, workdir, generated, named, channels, axis_lists, axes, scopes, values, findings, rules, rule_url, against=None, counts=None, fleet=None, values_printed=None) -> None:
    self.title = title
    self.startup = startup
    self.workdir = workdir
    self.generated = generated
    self.named = named
    self.channels = channels
    self.axis_lists = axis_lists
    self.axes = axes
    self.scopes = scopes
    self.values = values
    self.findings = findings
    self.rules = rules
    self.rule_url = rule_url
    self.against = against
    self.counts = __factory_counts() if counts is MISSING else counts
    self.fleet = fleet
    self.values_printed = values_printed
INITS['def __init__(self, title, startup, workdir, generated, named, channels, axis_lists, axes, scopes, values, findings, rules, rule_url, against=__default_against, counts=MISSING, fleet=__default_fleet, values_printed=__default_values_printed) -> None:\n    self.title = title\n    self.startup = startup\n    self.workdir = workdir\n    self.generated = generated\n    self.named = named\n    self.channels = channels\n    self.axis_lists = axis_lists\n    self.axes = axes\n    self.scopes = scopes\n    self.values = values\n    self.findings = findings\n    self.rules = rules\n    self.rule_url = rule_url\n    self.against = against\n    self.counts = __factory_counts() if counts is MISSING else counts\n    self.fleet = fleet\n    self.values_printed = values_printed'] = __init__.__code__

def __init__(self, uri, version, path, name, form, text, data, saved, registry, config, options, result=None, notes=None, machine=None, references=None, cache=None, _values=None, _lists=None, _rows=None) -> None:
    self.uri = uri
    self.version = version
    self.path = path
    self.name = name
    self.form = form
    self.text = text
    self.data = data
    self.saved = saved
    self.registry = registry
    self.config = config
    self.options = options
    self.result = result
    self.notes = __factory_notes() if notes is MISSING else notes
    self.machine = machine
    self.references = __factory_references() if references is MISSING else references
    self.cache = __factory_cache() if cache is MISSING else cache
    self._values = _values
    self._lists = _lists
    self._rows = _rows
INITS['def __init__(self, uri, version, path, name, form, text, data, saved, registry, config, options, result=__default_result, notes=MISSING, machine=__default_machine, references=MISSING, cache=MISSING, _values=__default__values, _lists=__default__lists, _rows=__default__rows) -> None:\n    self.uri = uri\n    self.version = version\n    self.path = path\n    self.name = name\n    self.form = form\n    self.text = text\n    self.data = data\n    self.saved = saved\n    self.registry = registry\n    self.config = config\n    self.options = options\n    self.result = result\n    self.notes = __factory_notes() if notes is MISSING else notes\n    self.machine = machine\n    self.references = __factory_references() if references is MISSING else references\n    self.cache = __factory_cache() if cache is MISSING else cache\n    self._values = _values\n    self._lists = _lists\n    self._rows = _rows'] = __init__.__code__

def __init__(self, value) -> None:
    __set(self, 'value', value)
INITS["def __init__(self, value) -> None:\n    __set(self, 'value', value)"] = __init__.__code__

def __init__(self, value, note=None, name=None, delta=None, machines=None) -> None:
    self.value = value
    self.note = note
    self.name = name
    self.delta = delta
    self.machines = __factory_machines() if machines is MISSING else machines
INITS['def __init__(self, value, note=__default_note, name=__default_name, delta=__default_delta, machines=MISSING) -> None:\n    self.value = value\n    self.note = note\n    self.name = name\n    self.delta = delta\n    self.machines = __factory_machines() if machines is MISSING else machines'] = __init__.__code__

def __init__(self, values, line, column, shift=None, element=None) -> None:
    self.values = values
    self.line = line
    self.column = column
    self.shift = shift
    self.element = element
INITS['def __init__(self, values, line, column, shift=__default_shift, element=__default_element) -> None:\n    self.values = values\n    self.line = line\n    self.column = column\n    self.shift = shift\n    self.element = element'] = __init__.__code__

def __init__(self, what, value, where) -> None:
    self.what = what
    self.value = value
    self.where = where
INITS['def __init__(self, what, value, where) -> None:\n    self.what = what\n    self.value = value\n    self.where = where'] = __init__.__code__

def __init__(self, which, type) -> None:
    __set(self, 'which', which)
    __set(self, 'type', type)
INITS["def __init__(self, which, type) -> None:\n    __set(self, 'which', which)\n    __set(self, 'type', type)"] = __init__.__code__

del __init__
