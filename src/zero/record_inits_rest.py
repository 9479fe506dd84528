"""The ``__init__`` of every record of the other modules, compiled with this module and keyed by its text:
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

def __init__(self, code, severity, name, summary, results=None) -> None:
    self.code = code
    self.severity = severity
    self.name = name
    self.summary = summary
    self.results = __factory_results() if results is MISSING else results
INITS['def __init__(self, code, severity, name, summary, results=MISSING) -> None:\n    self.code = code\n    self.severity = severity\n    self.name = name\n    self.summary = summary\n    self.results = __factory_results() if results is MISSING else results'] = __init__.__code__

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

def __init__(self, doc, machine_data, limits) -> None:
    self.doc = doc
    self.machine_data = machine_data
    self.limits = limits
INITS['def __init__(self, doc, machine_data, limits) -> None:\n    self.doc = doc\n    self.machine_data = machine_data\n    self.limits = limits'] = __init__.__code__

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

def __init__(self, fixed, applied, result) -> None:
    self.fixed = fixed
    self.applied = applied
    self.result = result
INITS['def __init__(self, fixed, applied, result) -> None:\n    self.fixed = fixed\n    self.applied = applied\n    self.result = result'] = __init__.__code__

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

def __init__(self, line, column, after=None, before=None, key_at=None) -> None:
    self.line = line
    self.column = column
    self.after = after
    self.before = __factory_before() if before is MISSING else before
    self.key_at = key_at
INITS['def __init__(self, line, column, after=__default_after, before=MISSING, key_at=__default_key_at) -> None:\n    self.line = line\n    self.column = column\n    self.after = after\n    self.before = __factory_before() if before is MISSING else before\n    self.key_at = key_at'] = __init__.__code__

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

def __init__(self, lo, hi, x0=None, x1=None) -> None:
    self.lo = lo
    self.hi = hi
    self.x0 = x0
    self.x1 = x1
INITS['def __init__(self, lo, hi, x0=__default_x0, x1=__default_x1) -> None:\n    self.lo = lo\n    self.hi = hi\n    self.x0 = x0\n    self.x1 = x1'] = __init__.__code__

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

def __init__(self, path, kind, entries, comments=None, update=None) -> None:
    self.path = path
    self.kind = kind
    self.entries = entries
    self.comments = __factory_comments() if comments is MISSING else comments
    self.update = update
INITS['def __init__(self, path, kind, entries, comments=MISSING, update=__default_update) -> None:\n    self.path = path\n    self.kind = kind\n    self.entries = entries\n    self.comments = __factory_comments() if comments is MISSING else comments\n    self.update = update'] = __init__.__code__

def __init__(self, picture, svg, settings=None, monitor_where=None) -> None:
    self.picture = picture
    self.svg = svg
    self.settings = __factory_settings() if settings is MISSING else settings
    self.monitor_where = monitor_where
INITS['def __init__(self, picture, svg, settings=MISSING, monitor_where=__default_monitor_where) -> None:\n    self.picture = picture\n    self.svg = svg\n    self.settings = __factory_settings() if settings is MISSING else settings\n    self.monitor_where = monitor_where'] = __init__.__code__

def __init__(self, project, registry, options, scopes, defaults, keep=None) -> None:
    self.project = project
    self.registry = registry
    self.options = options
    self.scopes = scopes
    self.defaults = defaults
    self.keep = keep
INITS['def __init__(self, project, registry, options, scopes, defaults, keep=__default_keep) -> None:\n    self.project = project\n    self.registry = registry\n    self.options = options\n    self.scopes = scopes\n    self.defaults = defaults\n    self.keep = keep'] = __init__.__code__

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

def __init__(self, source, path=None, line=None) -> None:
    __set(self, 'source', source)
    __set(self, 'path', path)
    __set(self, 'line', line)
INITS["def __init__(self, source, path=__default_path, line=__default_line) -> None:\n    __set(self, 'source', source)\n    __set(self, 'path', path)\n    __set(self, 'line', line)"] = __init__.__code__

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

del __init__
