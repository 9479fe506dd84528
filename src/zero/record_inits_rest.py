"""The records of the other modules, worked out ahead of time: written by tools/gen_record_inits.py
(see :func:`zero.records._body`).

``RECORDS``: by module and qualified name, what declaring the record takes (its own annotations and
flags, the fields with values, which of them are field()s and of which kind, the fields without: all
checked; all names, those shown and compared; its ``__init__`` code). ``INITS``: by its text, the
``__init__`` code of a record that is not in ``RECORDS``.

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from __future__ import annotations

from types import CodeType

INITS: dict[str, CodeType] = {}

def __init__(self, path, kind, entries, comments=None, update=None) -> None:
    self.path = path
    self.kind = kind
    self.entries = entries
    self.comments = __factory_comments() if comments is MISSING else comments
    self.update = update
_0 = __init__.__code__

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
_1 = __init__.__code__

def __init__(self, strict=None, comments=None) -> None:
    self.strict = strict
    self.comments = comments
_2 = __init__.__code__

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
_3 = __init__.__code__

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
_4 = __init__.__code__

def __init__(self, leaves, meta=None, tail=None, path=None, notes=None, _nested=None) -> None:
    self.leaves = leaves
    self.meta = __factory_meta() if meta is MISSING else meta
    self.tail = __factory_tail() if tail is MISSING else tail
    self.path = path
    self.notes = __factory_notes() if notes is MISSING else notes
    self._nested = _nested
_5 = __init__.__code__

def __init__(self, children=None) -> None:
    self.children = __factory_children() if children is MISSING else children
_6 = __init__.__code__

def __init__(self, text, lines_of) -> None:
    self.text = text
    self.lines_of = lines_of
_7 = __init__.__code__

def __init__(self, files=None, changed=None, failed=None, unreadable=None) -> None:
    self.files = files
    self.changed = changed
    self.failed = failed
    self.unreadable = unreadable
_8 = __init__.__code__

def __init__(self, line, column, after=None, before=None, key_at=None) -> None:
    self.line = line
    self.column = column
    self.after = after
    self.before = __factory_before() if before is MISSING else before
    self.key_at = key_at
_9 = __init__.__code__

def __init__(self, output, tree, notes=None, lint=None) -> None:
    self.output = output
    self.tree = tree
    self.notes = __factory_notes() if notes is MISSING else notes
    self.lint = lint
_10 = __init__.__code__

def __init__(self, name, fmt, output=None, notes=None, findings=None, error=None, element=None) -> None:
    self.name = name
    self.fmt = fmt
    self.output = output
    self.notes = __factory_notes() if notes is MISSING else notes
    self.findings = findings
    self.error = error
    self.element = element
_11 = __init__.__code__

def __init__(self, key, param_id, kind, default=None, count=None, missing=None) -> None:
    __set(self, 'key', key)
    __set(self, 'param_id', param_id)
    __set(self, 'kind', kind)
    __set(self, 'default', default)
    __set(self, 'count', count)
    __set(self, 'missing', missing)
_12 = __init__.__code__

def __init__(self, key, path, values, line) -> None:
    self.key = key
    self.path = path
    self.values = values
    self.line = line
_13 = __init__.__code__

def __init__(self, key, reference, index, raw, line, path=None, status=None, reason=None) -> None:
    self.key = key
    self.reference = reference
    self.index = index
    self.raw = raw
    self.line = line
    self.path = path
    self.status = status
    self.reason = reason
_14 = __init__.__code__

def __init__(self, nr, name, rotary, swe_neg, swe_pos, list) -> None:
    self.nr = nr
    self.name = name
    self.rotary = rotary
    self.swe_neg = swe_neg
    self.swe_pos = swe_pos
    self.list = list
_15 = __init__.__code__

def __init__(self, index, log_nr, name, entry, source=None) -> None:
    self.index = index
    self.log_nr = log_nr
    self.name = name
    self.entry = entry
    self.source = source
_16 = __init__.__code__

def __init__(self, index, lists, zero, axes=None, tools=None, others=None) -> None:
    self.index = index
    self.lists = lists
    self.zero = zero
    self.axes = __factory_axes() if axes is MISSING else axes
    self.tools = tools
    self.others = __factory_others() if others is MISSING else others
_17 = __init__.__code__

def __init__(self, key, raw, line, reason=None, consequence=None) -> None:
    self.key = key
    self.raw = raw
    self.line = line
    self.reason = reason
    self.consequence = consequence
_18 = __init__.__code__

def __init__(self, startup, workdir=None, named=None, axis_lists=None, channels=None, defaults=None, singles=None, compensation=None) -> None:
    self.startup = startup
    self.workdir = workdir
    self.named = __factory_named() if named is MISSING else named
    self.axis_lists = __factory_axis_lists() if axis_lists is MISSING else axis_lists
    self.channels = __factory_channels() if channels is MISSING else channels
    self.defaults = __factory_defaults() if defaults is MISSING else defaults
    self.singles = __factory_singles() if singles is MISSING else singles
    self.compensation = __factory_compensation() if compensation is MISSING else compensation
_19 = __init__.__code__

def __init__(self, source, path=None, line=None) -> None:
    __set(self, 'source', source)
    __set(self, 'path', path)
    __set(self, 'line', line)
_20 = __init__.__code__

def __init__(self, key, param_id, value, origin, layers=None) -> None:
    __set(self, 'key', key)
    __set(self, 'param_id', param_id)
    __set(self, 'value', value)
    __set(self, 'origin', origin)
    __set(self, 'layers', layers)
_21 = __init__.__code__

def __init__(self, name, file, values=None) -> None:
    self.name = name
    self.file = file
    self.values = __factory_values() if values is MISSING else values
_22 = __init__.__code__

def __init__(self, key, spec, entry, origin) -> None:
    __set(self, 'key', key)
    __set(self, 'spec', spec)
    __set(self, 'entry', entry)
    __set(self, 'origin', origin)
_23 = __init__.__code__

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
_24 = __init__.__code__

def __init__(self, what, value, where) -> None:
    self.what = what
    self.value = value
    self.where = where
_25 = __init__.__code__

def __init__(self, changes, header) -> None:
    self.changes = changes
    self.header = header
_26 = __init__.__code__

def __init__(self, spec=None, indices=None, matches=None, searched=None) -> None:
    self.spec = spec
    self.indices = indices
    self.matches = __factory_matches() if matches is MISSING else matches
    self.searched = searched
_27 = __init__.__code__

def __init__(self, rows, violations=None) -> None:
    self.rows = rows
    self.violations = __factory_violations() if violations is MISSING else violations
_28 = __init__.__code__

def __init__(self, summary, scopes) -> None:
    self.summary = summary
    self.scopes = scopes
_29 = __init__.__code__

def __init__(self, title, name, text, lines=None, report=None) -> None:
    __set(self, 'title', title)
    __set(self, 'name', name)
    __set(self, 'text', text)
    __set(self, 'lines', lines)
    __set(self, 'report', report)
_30 = __init__.__code__

def __init__(self, failing, passing, fixes=None, note=None) -> None:
    __set(self, 'failing', failing)
    __set(self, 'passing', passing)
    __set(self, 'fixes', fixes)
    __set(self, 'note', note)
_31 = __init__.__code__

def __init__(self, code, how) -> None:
    __set(self, 'code', code)
    __set(self, 'how', how)
_32 = __init__.__code__

def __init__(self, data, added, unplaced) -> None:
    self.data = data
    self.added = added
    self.unplaced = unplaced
_33 = __init__.__code__

def __init__(self, fixed, applied, result) -> None:
    self.fixed = fixed
    self.applied = applied
    self.result = result
_34 = __init__.__code__

def __init__(self, value, note=None, name=None, delta=None, machines=None) -> None:
    self.value = value
    self.note = note
    self.name = name
    self.delta = delta
    self.machines = __factory_machines() if machines is MISSING else machines
_35 = __init__.__code__

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
_36 = __init__.__code__

def __init__(self, scope, status, reason, machines=None) -> None:
    self.scope = scope
    self.status = status
    self.reason = reason
    self.machines = __factory_machines() if machines is MISSING else machines
_37 = __init__.__code__

def __init__(self, machine, error) -> None:
    self.machine = machine
    self.error = error
_38 = __init__.__code__

def __init__(self, golden, machines, params=None, lists=None, unreadable=None) -> None:
    self.golden = golden
    self.machines = machines
    self.params = __factory_params() if params is MISSING else params
    self.lists = __factory_lists() if lists is MISSING else lists
    self.unreadable = __factory_unreadable() if unreadable is MISSING else unreadable
_39 = __init__.__code__

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
_40 = __init__.__code__

def __init__(self, machine, found=None, lists=None, error=None, deps=None) -> None:
    self.machine = machine
    self.found = __factory_found() if found is MISSING else found
    self.lists = __factory_lists() if lists is MISSING else lists
    self.error = error
    self.deps = deps
_41 = __init__.__code__

def __init__(self, name, key, kind, side, own, based) -> None:
    self.name = name
    self.key = key
    self.kind = kind
    self.side = side
    self.own = own
    self.based = based
_42 = __init__.__code__

def __init__(self, project, registry, options, scopes, defaults, keep=None) -> None:
    self.project = project
    self.registry = registry
    self.options = options
    self.scopes = scopes
    self.defaults = defaults
    self.keep = keep
_43 = __init__.__code__

def __init__(self, golden, machines=None, jobs=None, param_desc=None, config=None, isolated=None, cache=None) -> None:
    self.golden = golden
    self.machines = machines
    self.jobs = jobs
    self.param_desc = param_desc
    self.config = config
    self.isolated = isolated
    self.cache = cache
_44 = __init__.__code__

def __init__(self, files, reason=None) -> None:
    self.files = files
    self.reason = reason
_45 = __init__.__code__

def __init__(self, given, label, machine, changes=None) -> None:
    self.given = given
    self.label = label
    self.machine = machine
    self.changes = __factory_changes() if changes is MISSING else changes
_46 = __init__.__code__

def __init__(self, machine, startup, registry, results, against=None, travels=None, drift=None) -> None:
    self.machine = machine
    self.startup = startup
    self.registry = registry
    self.results = results
    self.against = against
    self.travels = __factory_travels() if travels is MISSING else travels
    self.drift = drift
_47 = __init__.__code__

def __init__(self, name, attrs, start, end, depth, empty, raw=None) -> None:
    self.name = name
    self.attrs = attrs
    self.start = start
    self.end = end
    self.depth = depth
    self.empty = empty
    self.raw = __factory_raw() if raw is MISSING else raw
_48 = __init__.__code__

def __init__(self, parent, start, end) -> None:
    self.parent = parent
    self.start = start
    self.end = end
_49 = __init__.__code__

def __init__(self, text, encoding, bom, root, tags, cdata, line_starts) -> None:
    self.text = text
    self.encoding = encoding
    self.bom = bom
    self.root = root
    self.tags = tags
    self.cdata = cdata
    self.line_starts = line_starts
_50 = __init__.__code__

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
_51 = __init__.__code__

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
_52 = __init__.__code__

def __init__(self, scan, blocks, files=None) -> None:
    self.scan = scan
    self.blocks = blocks
    self.files = __factory_files() if files is MISSING else files
_53 = __init__.__code__

def __init__(self, name, item, properties=None, owning=None) -> None:
    self.name = name
    self.item = item
    self.properties = __factory_properties() if properties is MISSING else properties
    self.owning = owning
_54 = __init__.__code__

def __init__(self, path, block, line) -> None:
    self.path = path
    self.block = block
    self.line = line
_55 = __init__.__code__

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
_56 = __init__.__code__

def __init__(self, line, start, end, positive, relative, axis, value) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.positive = positive
    self.relative = relative
    self.axis = axis
    self.value = value
_57 = __init__.__code__

def __init__(self, doc, machine_data, limits) -> None:
    self.doc = doc
    self.machine_data = machine_data
    self.limits = limits
_58 = __init__.__code__

def __init__(self, name, neg, pos, rotary=None) -> None:
    self.name = name
    self.neg = neg
    self.pos = pos
    self.rotary = rotary
_59 = __init__.__code__

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
_60 = __init__.__code__

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
_61 = __init__.__code__

def __init__(self, line, start, end, text, kind) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.text = text
    self.kind = kind
_62 = __init__.__code__

def __init__(self, line, start, end, name, local, cycle) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.name = name
    self.local = local
    self.cycle = cycle
_63 = __init__.__code__

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
_64 = __init__.__code__

def __init__(self, kind, name, line, start, end, value=None, text=None) -> None:
    self.kind = kind
    self.name = name
    self.line = line
    self.start = start
    self.end = end
    self.value = value
    self.text = text
_65 = __init__.__code__

def __init__(self, group, offset, pcs_neg, pcs_pos, note=None) -> None:
    self.group = group
    self.offset = offset
    self.pcs_neg = pcs_neg
    self.pcs_pos = pcs_pos
    self.note = note
_66 = __init__.__code__

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
_67 = __init__.__code__

def __init__(self, lo, hi, x0=None, x1=None) -> None:
    self.lo = lo
    self.hi = hi
    self.x0 = x0
    self.x1 = x1
_68 = __init__.__code__

def __init__(self, text, href) -> None:
    self.text = text
    self.href = href
_69 = __init__.__code__

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
_70 = __init__.__code__

def __init__(self, picture, svg, settings=None, monitor_where=None) -> None:
    self.picture = picture
    self.svg = svg
    self.settings = __factory_settings() if settings is MISSING else settings
    self.monitor_where = monitor_where
_71 = __init__.__code__

def __init__(self, code, severity, name, summary, results=None) -> None:
    self.code = code
    self.severity = severity
    self.name = name
    self.summary = summary
    self.results = __factory_results() if results is MISSING else results
_72 = __init__.__code__

def __init__(self, given, label, changes=None, deltas=None) -> None:
    self.given = given
    self.label = label
    self.changes = __factory_changes() if changes is MISSING else changes
    self.deltas = __factory_deltas() if deltas is MISSING else deltas
_73 = __init__.__code__

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
_74 = __init__.__code__

def __init__(self, name, unit, code, behaviour, path, neg, pos, kernel_error=None) -> None:
    self.name = name
    self.unit = unit
    self.code = code
    self.behaviour = behaviour
    self.path = path
    self.neg = neg
    self.pos = pos
    self.kernel_error = kernel_error
_75 = __init__.__code__

def __init__(self, debounce=None, rule_docs=None, structured=None, machine=None, max_findings=None) -> None:
    self.debounce = debounce
    self.rule_docs = rule_docs
    self.structured = structured
    self.machine = machine
    self.max_findings = max_findings
_76 = __init__.__code__

def __init__(self, message, line=None, column=None, severity=None, elsewhere=None) -> None:
    self.message = message
    self.line = line
    self.column = column
    self.severity = severity
    self.elsewhere = elsewhere
_77 = __init__.__code__

def __init__(self, values, line, column, shift=None, element=None) -> None:
    self.values = values
    self.line = line
    self.column = column
    self.shift = shift
    self.element = element
_78 = __init__.__code__

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
_79 = __init__.__code__

def __init__(self, spec, key=None, indices=None, entry=None, alias=None, start=None, end=None, values=None) -> None:
    self.spec = spec
    self.key = key
    self.indices = indices
    self.entry = entry
    self.alias = alias
    self.start = start
    self.end = end
    self.values = values
_80 = __init__.__code__

def __init__(self, name, detail, level, symbols=None, groups=None, order=None, first=None, last=None) -> None:
    self.name = name
    self.detail = detail
    self.level = level
    self.symbols = __factory_symbols() if symbols is MISSING else symbols
    self.groups = __factory_groups() if groups is MISSING else groups
    self.order = __factory_order() if order is MISSING else order
    self.first = first
    self.last = last
_81 = __init__.__code__

RECORDS: dict[str, dict[str, tuple]] = {
    'zero.diff': {
        'Change': ({'key': 'str', 'param_id': 'str | None', 'kind': 'str', 'old': 'str | None', 'new': 'str | None', 'unit': 'str | None', 'delta': 'float | int | None', 'group': 'str', 'note': 'str', 'restart': 'bool', 'coding': 'str | None', 'old_name': 'str | None', 'new_name': 'str | None', 'bits': 'tuple[tuple[str, ...], tuple[str, ...]] | None'}, (False, True, False, False), ('unit', 'delta', 'group', 'note', 'restart', 'coding', 'old_name', 'new_name', 'bits'), (), ('key', 'param_id', 'kind', 'old', 'new'), ('key', 'param_id', 'kind', 'old', 'new', 'unit', 'delta', 'group', 'note', 'restart', 'coding', 'old_name', 'new_name', 'bits'), ('key', 'param_id', 'kind', 'old', 'new', 'unit', 'delta', 'group', 'note', 'restart', 'coding', 'old_name', 'new_name', 'bits'), ('key', 'param_id', 'kind', 'old', 'new', 'unit', 'delta', 'group', 'note', 'restart', 'coding', 'old_name', 'new_name', 'bits'), _1),
        'DiffOptions': ({'strict': 'bool', 'comments': 'bool'}, (False, True, False, False), ('strict', 'comments'), (), (), ('strict', 'comments'), ('strict', 'comments'), ('strict', 'comments'), _2),
        'Side': ({'path': 'str', 'kind': 'str | None', 'entries': 'Mapping[str, Entry]', 'comments': 'Mapping[str, tuple[str, ...]]', 'update': 'bool'}, (False, True, False, False), ('comments', 'update'), ((0, (False, True, True, True)),), ('path', 'kind', 'entries'), ('path', 'kind', 'entries', 'comments', 'update'), ('path', 'kind', 'entries', 'comments', 'update'), ('path', 'kind', 'entries', 'comments', 'update'), _0),
    },
    'zero.engine.baseline': {
        'Baseline': ({'data': 'bytes', 'added': 'int', 'unplaced': 'int'}, (False, True, False, False), (), (), ('data', 'added', 'unplaced'), ('data', 'added', 'unplaced'), ('data', 'added', 'unplaced'), ('data', 'added', 'unplaced'), _33),
    },
    'zero.engine.config_file': {
        'ConfigOption': ({'key': 'str', 'section': 'str', 'type': 'str', 'default': 'Any', 'description': 'str', 'example': 'str', 'schema': 'dict[str, Any]', 'read': 'Callable[[_Reading, Any], None]', 'show': 'Callable[[Config, str], list[str]] | None', 'table': 'bool', 'default_text': 'str'}, (True, True, False, False), ('show', 'table', 'default_text'), (), ('key', 'section', 'type', 'default', 'description', 'example', 'schema', 'read'), ('key', 'section', 'type', 'default', 'description', 'example', 'schema', 'read', 'show', 'table', 'default_text'), ('key', 'section', 'type', 'default', 'description', 'example', 'schema', 'read', 'show', 'table', 'default_text'), ('key', 'section', 'type', 'default', 'description', 'example', 'schema', 'read', 'show', 'table', 'default_text'), _3),
    },
    'zero.engine.convert': {
        'Conversion': ({'output': 'bytes', 'tree': 'Tree', 'notes': 'list[str]', 'lint': 'LintResult | None'}, (False, True, False, False), ('notes', 'lint'), ((0, (False, True, True, True)),), ('output', 'tree'), ('output', 'tree', 'notes', 'lint'), ('output', 'tree', 'notes', 'lint'), ('output', 'tree', 'notes', 'lint'), _10),
        'ConvertItem': ({'name': 'str', 'fmt': 'str', 'output': 'bytes | None', 'notes': 'list[str]', 'findings': 'LintResult | None', 'error': 'str | None', 'element': 'str | None'}, (False, True, False, False), ('output', 'notes', 'findings', 'error', 'element'), ((1, (False, True, True, True)),), ('name', 'fmt'), ('name', 'fmt', 'output', 'notes', 'findings', 'error', 'element'), ('name', 'fmt', 'output', 'notes', 'findings', 'error', 'element'), ('name', 'fmt', 'output', 'notes', 'findings', 'error', 'element'), _11),
    },
    'zero.engine.fixes': {
        'FixResult': ({'fixed': 'bytes', 'applied': 'int', 'result': 'LintResult'}, (False, True, False, False), (), (), ('fixed', 'applied', 'result'), ('fixed', 'applied', 'result'), ('fixed', 'applied', 'result'), ('fixed', 'applied', 'result'), _34),
    },
    'zero.engine.fleet': {
        'FleetDrift': ({'golden': 'str', 'machines': 'list[str]', 'params': 'list[ParamDrift]', 'lists': 'list[ListDrift]', 'unreadable': 'list[Unreadable]'}, (False, True, False, False), ('params', 'lists', 'unreadable'), ((0, (False, True, True, True)), (1, (False, True, True, True)), (2, (False, True, True, True))), ('golden', 'machines'), ('golden', 'machines', 'params', 'lists', 'unreadable'), ('golden', 'machines', 'params', 'lists', 'unreadable'), ('golden', 'machines', 'params', 'lists', 'unreadable'), _39),
        'FleetRequest': ({'golden': 'str', 'machines': 'Sequence[str]', 'jobs': 'int | None', 'param_desc': 'str | Path | None', 'config': 'str | Path | Sequence[str] | None', 'isolated': 'bool', 'cache': 'bool'}, (False, True, False, False), ('machines', 'jobs', 'param_desc', 'config', 'isolated', 'cache'), (), ('golden',), ('golden', 'machines', 'jobs', 'param_desc', 'config', 'isolated', 'cache'), ('golden', 'machines', 'jobs', 'param_desc', 'config', 'isolated', 'cache'), ('golden', 'machines', 'jobs', 'param_desc', 'config', 'isolated', 'cache'), _44),
        'FleetValue': ({'value': 'str | None', 'note': 'str', 'name': 'str | None', 'delta': 'float | int | None', 'machines': 'list[str]'}, (False, True, False, False), ('note', 'name', 'delta', 'machines'), ((3, (False, True, True, True)),), ('value',), ('value', 'note', 'name', 'delta', 'machines'), ('value', 'note', 'name', 'delta', 'machines'), ('value', 'note', 'name', 'delta', 'machines'), _35),
        'ListDrift': ({'scope': 'str', 'status': 'str', 'reason': 'str', 'machines': 'list[str]'}, (False, True, False, False), ('machines',), ((0, (False, True, True, True)),), ('scope', 'status', 'reason'), ('scope', 'status', 'reason', 'machines'), ('scope', 'status', 'reason', 'machines'), ('scope', 'status', 'reason', 'machines'), _37),
        'ParamDrift': ({'scope': 'str', 'key': 'str', 'param_id': 'str | None', 'group': 'str', 'golden': 'str | None', 'golden_note': 'str', 'golden_name': 'str | None', 'unit': 'str | None', 'values': 'list[FleetValue]'}, (False, True, False, False), ('golden_note', 'golden_name', 'unit', 'values'), ((3, (False, True, True, True)),), ('scope', 'key', 'param_id', 'group', 'golden'), ('scope', 'key', 'param_id', 'group', 'golden', 'golden_note', 'golden_name', 'unit', 'values'), ('scope', 'key', 'param_id', 'group', 'golden', 'golden_note', 'golden_name', 'unit', 'values'), ('scope', 'key', 'param_id', 'group', 'golden', 'golden_note', 'golden_name', 'unit', 'values'), _36),
        'Unreadable': ({'machine': 'str', 'error': 'str'}, (False, True, False, False), (), (), ('machine', 'error'), ('machine', 'error'), ('machine', 'error'), ('machine', 'error'), _38),
        '_Found': ({'scope': 'str', 'key': 'str', 'param_id': 'str | None', 'group': 'str', 'golden': 'str | None', 'golden_note': 'str', 'golden_name': 'str | None', 'unit': 'str | None', 'value': 'str | None', 'note': 'str', 'name': 'str | None', 'delta': 'float | int | None', 'same': 'Hashable'}, (False, True, False, False), (), (), ('scope', 'key', 'param_id', 'group', 'golden', 'golden_note', 'golden_name', 'unit', 'value', 'note', 'name', 'delta', 'same'), ('scope', 'key', 'param_id', 'group', 'golden', 'golden_note', 'golden_name', 'unit', 'value', 'note', 'name', 'delta', 'same'), ('scope', 'key', 'param_id', 'group', 'golden', 'golden_note', 'golden_name', 'unit', 'value', 'note', 'name', 'delta', 'same'), ('scope', 'key', 'param_id', 'group', 'golden', 'golden_note', 'golden_name', 'unit', 'value', 'note', 'name', 'delta', 'same'), _40),
        '_Golden': ({'project': 'Project', 'registry': 'Registry', 'options': 'DiffOptions', 'scopes': 'dict[str, _Scope]', 'defaults': 'dict[str, tuple[str, Rows]]', 'keep': 'FleetCache | None'}, (False, True, False, False), ('keep',), (), ('project', 'registry', 'options', 'scopes', 'defaults'), ('project', 'registry', 'options', 'scopes', 'defaults', 'keep'), ('project', 'registry', 'options', 'scopes', 'defaults', 'keep'), ('project', 'registry', 'options', 'scopes', 'defaults', 'keep'), _43),
        '_MachineDrift': ({'machine': 'str', 'found': 'list[_Found]', 'lists': 'list[tuple[str, str, str]]', 'error': 'str | None', 'deps': 'tuple[Any, ...] | None'}, (False, True, False, False), ('found', 'lists', 'error', 'deps'), ((0, (False, True, True, True)), (1, (False, True, True, True))), ('machine',), ('machine', 'found', 'lists', 'error', 'deps'), ('machine', 'found', 'lists', 'error', 'deps'), ('machine', 'found', 'lists', 'error', 'deps'), _41),
        '_Scope': ({'name': 'str', 'key': 'str', 'kind': 'str | None', 'side': 'Side', 'own': 'Rows', 'based': 'bool'}, (False, True, False, False), (), (), ('name', 'key', 'kind', 'side', 'own', 'based'), ('name', 'key', 'kind', 'side', 'own', 'based'), ('name', 'key', 'kind', 'side', 'own', 'based'), ('name', 'key', 'kind', 'side', 'own', 'based'), _42),
    },
    'zero.engine.formatting': {
        'FormatRun': ({'files': 'int', 'changed': 'int', 'failed': 'int', 'unreadable': 'int'}, (False, True, False, False), ('files', 'changed', 'failed', 'unreadable'), (), (), ('files', 'changed', 'failed', 'unreadable'), ('files', 'changed', 'failed', 'unreadable'), ('files', 'changed', 'failed', 'unreadable'), _8),
    },
    'zero.engine.git': {
        'Visible': ({'files': 'set[str] | None', 'reason': 'str'}, (False, True, False, False), ('reason',), (), ('files',), ('files', 'reason'), ('files', 'reason'), ('files', 'reason'), _45),
    },
    'zero.engine.queries': {
        'DiffRun': ({'changes': 'list[Change]', 'header': 'str'}, (False, True, False, False), (), (), ('changes', 'header'), ('changes', 'header'), ('changes', 'header'), ('changes', 'header'), _26),
        'EffectiveRun': ({'summary': 'dict[str, object]', 'scopes': 'list[Scope]'}, (False, True, False, False), (), (), ('summary', 'scopes'), ('summary', 'scopes'), ('summary', 'scopes'), ('summary', 'scopes'), _29),
        'LimitsRun': ({'rows': 'list[LimitRow]', 'violations': 'list[Ip247Violation]'}, (False, True, False, False), ('violations',), ((0, (False, True, True, True)),), ('rows',), ('rows', 'violations'), ('rows', 'violations'), ('rows', 'violations'), _28),
        'ParamLookup': ({'spec': 'ParamSpec | None', 'indices': 'tuple[int, ...]', 'matches': 'list[ParamSpec]', 'searched': 'bool'}, (False, True, False, False), ('spec', 'indices', 'matches', 'searched'), ((2, (False, True, True, True)),), (), ('spec', 'indices', 'matches', 'searched'), ('spec', 'indices', 'matches', 'searched'), ('spec', 'indices', 'matches', 'searched'), _27),
    },
    'zero.engine.report': {
        'Compared': ({'given': 'str', 'label': 'str', 'machine': 'Machine', 'changes': 'list[Change]'}, (False, True, False, False), ('changes',), ((0, (False, True, True, True)),), ('given', 'label', 'machine'), ('given', 'label', 'machine', 'changes'), ('given', 'label', 'machine', 'changes'), ('given', 'label', 'machine', 'changes'), _46),
        'ReportFacts': ({'machine': 'Machine', 'startup': 'Path', 'registry': 'Registry', 'results': 'list[LintResult]', 'against': 'Compared | None', 'travels': 'list[Travel]', 'drift': 'FleetDrift | None'}, (False, True, False, False), ('against', 'travels', 'drift'), ((1, (False, True, True, True)),), ('machine', 'startup', 'registry', 'results'), ('machine', 'startup', 'registry', 'results', 'against', 'travels', 'drift'), ('machine', 'startup', 'registry', 'results', 'against', 'travels', 'drift'), ('machine', 'startup', 'registry', 'results', 'against', 'travels', 'drift'), _47),
    },
    'zero.machine.effective': {
        'Origin': ({'source': 'str', 'path': 'str | None', 'line': 'int | None'}, (True, True, False, False), ('path', 'line'), (), ('source',), ('source', 'path', 'line'), ('source', 'path', 'line'), ('source', 'path', 'line'), _20),
        'Scope': ({'name': 'str', 'file': 'ListFile', 'values': 'list[Value]'}, (False, True, False, False), ('values',), ((0, (False, True, True, True)),), ('name', 'file'), ('name', 'file', 'values'), ('name', 'file', 'values'), ('name', 'file', 'values'), _22),
        'Setting': ({'key': 'str', 'spec': 'ParamSpec | None', 'entry': 'Entry', 'origin': 'Origin'}, (True, True, False, False), (), (), ('key', 'spec', 'entry', 'origin'), ('key', 'spec', 'entry', 'origin'), ('key', 'spec', 'entry', 'origin'), ('key', 'spec', 'entry', 'origin'), _23),
        'Value': ({'key': 'str', 'param_id': 'str | None', 'value': 'str | None', 'origin': 'Origin', 'layers': 'tuple[tuple[str | None, Origin], ...]'}, (True, True, False, False), ('layers',), (), ('key', 'param_id', 'value', 'origin'), ('key', 'param_id', 'value', 'origin', 'layers'), ('key', 'param_id', 'value', 'origin', 'layers'), ('key', 'param_id', 'value', 'origin', 'layers'), _21),
    },
    'zero.machine.limits': {
        'Ip247Violation': ({'what': 'str', 'value': 'Number', 'where': 'str'}, (False, True, False, False), (), (), ('what', 'value', 'where'), ('what', 'value', 'where'), ('what', 'value', 'where'), ('what', 'value', 'where'), _25),
        'LimitRow': ({'channel': 'int', 'group': 'int', 'axis_index': 'int', 'axis_name': 'str', 'log_nr': 'int', 'unit': 'str', 'acs_neg': 'Number', 'acs_pos': 'Number', 'offset': 'Number', 'masked': 'bool', 'pcs_neg': 'Number', 'pcs_pos': 'Number', 'note': 'str'}, (False, True, False, False), ('note',), (), ('channel', 'group', 'axis_index', 'axis_name', 'log_nr', 'unit', 'acs_neg', 'acs_pos', 'offset', 'masked', 'pcs_neg', 'pcs_pos'), ('channel', 'group', 'axis_index', 'axis_name', 'log_nr', 'unit', 'acs_neg', 'acs_pos', 'offset', 'masked', 'pcs_neg', 'pcs_pos', 'note'), ('channel', 'group', 'axis_index', 'axis_name', 'log_nr', 'unit', 'acs_neg', 'acs_pos', 'offset', 'masked', 'pcs_neg', 'pcs_pos', 'note'), ('channel', 'group', 'axis_index', 'axis_name', 'log_nr', 'unit', 'acs_neg', 'acs_pos', 'offset', 'masked', 'pcs_neg', 'pcs_pos', 'note'), _24),
    },
    'zero.machine.model': {
        'Axis': ({'nr': 'int', 'name': 'str', 'rotary': 'bool', 'swe_neg': 'Number', 'swe_pos': 'Number', 'list': 'ListFile'}, (False, True, False, False), (), (), ('nr', 'name', 'rotary', 'swe_neg', 'swe_pos', 'list'), ('nr', 'name', 'rotary', 'swe_neg', 'swe_pos', 'list'), ('nr', 'name', 'rotary', 'swe_neg', 'swe_pos', 'list'), ('nr', 'name', 'rotary', 'swe_neg', 'swe_pos', 'list'), _15),
        'Channel': ({'index': 'int', 'lists': 'ListFile | None', 'zero': 'ListFile | None', 'axes': 'list[ChannelAxis]', 'tools': 'ListFile | None', 'others': 'dict[str, ListFile]'}, (False, True, False, False), ('axes', 'tools', 'others'), ((0, (False, True, True, True)), (2, (False, True, True, True))), ('index', 'lists', 'zero'), ('index', 'lists', 'zero', 'axes', 'tools', 'others'), ('index', 'lists', 'zero', 'axes', 'tools', 'others'), ('index', 'lists', 'zero', 'axes', 'tools', 'others'), _17),
        'ChannelAxis': ({'index': 'int', 'log_nr': 'int', 'name': 'str', 'entry': 'Entry | None', 'source': 'Path | None'}, (False, True, False, False), ('source',), (), ('index', 'log_nr', 'name', 'entry'), ('index', 'log_nr', 'name', 'entry', 'source'), ('index', 'log_nr', 'name', 'entry', 'source'), ('index', 'log_nr', 'name', 'entry', 'source'), _16),
        'ListFile': ({'key': 'str', 'path': 'Path', 'values': 'ListValues', 'line': 'int'}, (False, True, False, False), (), (), ('key', 'path', 'values', 'line'), ('key', 'path', 'values', 'line'), ('key', 'path', 'values', 'line'), ('key', 'path', 'values', 'line'), _13),
        'Machine': ({'startup': 'ListFile', 'workdir': 'Path', 'named': 'list[Named]', 'axis_lists': 'list[ListFile]', 'channels': 'list[Channel]', 'defaults': 'dict[str, ListFile]', 'singles': 'dict[str, ListFile]', 'compensation': 'list[tuple[int, ListFile]]'}, (False, True, False, False), ('workdir', 'named', 'axis_lists', 'channels', 'defaults', 'singles', 'compensation'), ((1, (False, True, True, True)), (2, (False, True, True, True)), (3, (False, True, True, True)), (4, (False, True, True, True)), (5, (False, True, True, True)), (6, (False, True, True, True))), ('startup',), ('startup', 'workdir', 'named', 'axis_lists', 'channels', 'defaults', 'singles', 'compensation'), ('startup', 'workdir', 'named', 'axis_lists', 'channels', 'defaults', 'singles', 'compensation'), ('startup', 'workdir', 'named', 'axis_lists', 'channels', 'defaults', 'singles', 'compensation'), _19),
        'Missing': ({'key': 'str', 'raw': 'str', 'line': 'int', 'reason': 'str', 'consequence': 'str'}, (False, True, False, False), ('reason', 'consequence'), (), ('key', 'raw', 'line'), ('key', 'raw', 'line', 'reason', 'consequence'), ('key', 'raw', 'line', 'reason', 'consequence'), ('key', 'raw', 'line', 'reason', 'consequence'), _18),
        'Named': ({'key': 'str', 'reference': 'Reference', 'index': 'int | None', 'raw': 'str', 'line': 'int', 'path': 'Path | None', 'status': 'str', 'reason': 'str'}, (False, True, False, False), ('path', 'status', 'reason'), (), ('key', 'reference', 'index', 'raw', 'line'), ('key', 'reference', 'index', 'raw', 'line', 'path', 'status', 'reason'), ('key', 'reference', 'index', 'raw', 'line', 'path', 'status', 'reason'), ('key', 'reference', 'index', 'raw', 'line', 'path', 'status', 'reason'), _14),
        'Reference': ({'key': 'str', 'param_id': 'str', 'kind': 'str', 'default': 'bool', 'count': 'str | None', 'missing': 'str'}, (True, True, False, False), ('default', 'count', 'missing'), (), ('key', 'param_id', 'kind'), ('key', 'param_id', 'kind', 'default', 'count', 'missing'), ('key', 'param_id', 'kind', 'default', 'count', 'missing'), ('key', 'param_id', 'kind', 'default', 'count', 'missing'), _12),
    },
    'zero.machine.tsproj': {
        'Found': ({'path': 'Path', 'block': 'Block', 'line': 'int'}, (False, False, False, False), (), (), ('path', 'block', 'line'), ('path', 'block', 'line'), ('path', 'block', 'line'), ('path', 'block', 'line'), _55),
    },
    'zero.markup.documents': {
        'Embedded': ({'element': 'str', 'kind': 'str | None', 'doc': 'Document', 'start': 'int', 'end': 'int', 'offset': 'int | None', 'item': 'str', 'name': 'str', 'properties': 'dict[str, str]'}, (False, False, False, False), ('offset', 'item', 'name', 'properties'), ((3, (False, True, True, True)),), ('element', 'kind', 'doc', 'start', 'end'), ('element', 'kind', 'doc', 'start', 'end', 'offset', 'item', 'name', 'properties'), ('element', 'kind', 'doc', 'start', 'end', 'offset', 'item', 'name', 'properties'), ('element', 'kind', 'doc', 'start', 'end', 'offset', 'item', 'name', 'properties'), _51),
    },
    'zero.markup.safe': {
        'Cdata': ({'parent': 'str', 'start': 'int', 'end': 'int'}, (False, False, False, False), (), (), ('parent', 'start', 'end'), ('parent', 'start', 'end'), ('parent', 'start', 'end'), ('parent', 'start', 'end'), _49),
        'Scan': ({'text': 'str', 'encoding': 'str', 'bom': 'bool', 'root': 'str', 'tags': 'list[Tag]', 'cdata': 'list[Cdata]', 'line_starts': 'list[int]'}, (False, False, False, False), (), (), ('text', 'encoding', 'bom', 'root', 'tags', 'cdata', 'line_starts'), ('text', 'encoding', 'bom', 'root', 'tags', 'cdata', 'line_starts'), ('text', 'encoding', 'bom', 'root', 'tags', 'cdata', 'line_starts'), ('text', 'encoding', 'bom', 'root', 'tags', 'cdata', 'line_starts'), _50),
        'Tag': ({'name': 'str', 'attrs': 'dict[str, str]', 'start': 'int', 'end': 'int', 'depth': 'int', 'empty': 'bool', 'raw': 'dict[str, tuple[int, int]]'}, (False, False, False, False), ('raw',), ((0, (False, True, True, True)),), ('name', 'attrs', 'start', 'end', 'depth', 'empty'), ('name', 'attrs', 'start', 'end', 'depth', 'empty', 'raw'), ('name', 'attrs', 'start', 'end', 'depth', 'empty', 'raw'), ('name', 'attrs', 'start', 'end', 'depth', 'empty', 'raw'), _48),
    },
    'zero.markup.tsproj': {
        'Block': ({'name': 'str', 'offset': 'int | None', 'offset_text': 'str | None', 'item': 'str', 'tag': 'int', 'start': 'int', 'end': 'int', 'address': 'str', 'kind': 'str | None', 'properties': 'dict[str, str]'}, (False, False, False, False), ('address', 'kind', 'properties'), ((2, (False, True, True, True)),), ('name', 'offset', 'offset_text', 'item', 'tag', 'start', 'end'), ('name', 'offset', 'offset_text', 'item', 'tag', 'start', 'end', 'address', 'kind', 'properties'), ('name', 'offset', 'offset_text', 'item', 'tag', 'start', 'end', 'address', 'kind', 'properties'), ('name', 'offset', 'offset_text', 'item', 'tag', 'start', 'end', 'address', 'kind', 'properties'), _52),
        'ProjectFile': ({'scan': 'Scan', 'blocks': 'list[Block]', 'files': 'list[tuple[int, str]]'}, (False, False, False, False), ('files',), ((0, (False, True, True, True)),), ('scan', 'blocks'), ('scan', 'blocks', 'files'), ('scan', 'blocks', 'files'), ('scan', 'blocks', 'files'), _53),
        '_Entry': ({'name': 'str', 'item': 'str', 'properties': 'dict[str, str]', 'owning': 'int'}, (False, False, False, False), ('properties', 'owning'), ((0, (False, True, True, True)),), ('name', 'item'), ('name', 'item', 'properties', 'owning'), ('name', 'item', 'properties', 'owning'), ('name', 'item', 'properties', 'owning'), _54),
    },
    'zero.nc.motion': {
        'Analysis': ({'moves': 'int', 'evaluated': 'int', 'skipped': 'dict[str, list[int]]', 'crossings': 'list[Crossing]', 'unknown': 'list[Word]', 'structure': 'list[tuple[int, int, int, str]]', 'calls': 'list[Call]', 'travel': 'dict[int, list[float]]', 'machine': 'bool', 'locals': 'set[str]', 'unfollowed': 'list[tuple[str, int]]', 'not_followed': 'list[Call]', 'followed': 'list[Call]'}, (False, True, False, False), ('moves', 'evaluated', 'skipped', 'crossings', 'unknown', 'structure', 'calls', 'travel', 'machine', 'locals', 'unfollowed', 'not_followed', 'followed'), ((2, (False, True, True, True)), (3, (False, True, True, True)), (4, (False, True, True, True)), (5, (False, True, True, True)), (6, (False, True, True, True)), (7, (False, True, True, True)), (9, (False, True, True, True)), (10, (False, True, True, True)), (11, (False, True, True, True)), (12, (False, True, True, True))), (), ('moves', 'evaluated', 'skipped', 'crossings', 'unknown', 'structure', 'calls', 'travel', 'machine', 'locals', 'unfollowed', 'not_followed', 'followed'), ('moves', 'evaluated', 'skipped', 'crossings', 'unknown', 'structure', 'calls', 'travel', 'machine', 'locals', 'unfollowed', 'not_followed', 'followed'), ('moves', 'evaluated', 'skipped', 'crossings', 'unknown', 'structure', 'calls', 'travel', 'machine', 'locals', 'unfollowed', 'not_followed', 'followed'), _64),
        'AxisSetup': ({'name': 'str', 'neg': 'float', 'pos': 'float', 'rotary': 'bool'}, (False, True, False, False), ('rotary',), (), ('name', 'neg', 'pos'), ('name', 'neg', 'pos', 'rotary'), ('name', 'neg', 'pos', 'rotary'), ('name', 'neg', 'pos', 'rotary'), _59),
        'Call': ({'line': 'int', 'start': 'int', 'end': 'int', 'name': 'str', 'local': 'bool', 'cycle': 'bool'}, (False, True, False, False), (), (), ('line', 'start', 'end', 'name', 'local', 'cycle'), ('line', 'start', 'end', 'name', 'local', 'cycle'), ('line', 'start', 'end', 'name', 'local', 'cycle'), ('line', 'start', 'end', 'name', 'local', 'cycle'), _63),
        'Crossing': ({'line': 'int', 'start': 'int', 'end': 'int', 'axis': 'int', 'programmed': 'float', 'machine': 'float', 'limit': 'float', 'positive': 'bool', 'group': 'int', 'offset': 'float', 'limit_from': 'str', 'unmonitored': 'str', 'arc': 'bool', 'via': 'str'}, (False, True, False, False), ('limit_from', 'unmonitored', 'arc', 'via'), (), ('line', 'start', 'end', 'axis', 'programmed', 'machine', 'limit', 'positive', 'group', 'offset'), ('line', 'start', 'end', 'axis', 'programmed', 'machine', 'limit', 'positive', 'group', 'offset', 'limit_from', 'unmonitored', 'arc', 'via'), ('line', 'start', 'end', 'axis', 'programmed', 'machine', 'limit', 'positive', 'group', 'offset', 'limit_from', 'unmonitored', 'arc', 'via'), ('line', 'start', 'end', 'axis', 'programmed', 'machine', 'limit', 'positive', 'group', 'offset', 'limit_from', 'unmonitored', 'arc', 'via'), _61),
        'Setup': ({'axes': 'list[AxisSetup]', 'offsets': 'dict[int, tuple[float, ...]]', 'default_group': 'int', 'absolute': 'bool', 'plane': 'int', 'inch': 'bool', 'centre_absolute': 'bool', 'diameter': 'bool', 'range_check': 'bool'}, (False, True, False, False), ('offsets', 'default_group', 'absolute', 'plane', 'inch', 'centre_absolute', 'diameter', 'range_check'), ((0, (False, True, True, True)),), ('axes',), ('axes', 'offsets', 'default_group', 'absolute', 'plane', 'inch', 'centre_absolute', 'diameter', 'range_check'), ('axes', 'offsets', 'default_group', 'absolute', 'plane', 'inch', 'centre_absolute', 'diameter', 'range_check'), ('axes', 'offsets', 'default_group', 'absolute', 'plane', 'inch', 'centre_absolute', 'diameter', 'range_check'), _60),
        'Word': ({'line': 'int', 'start': 'int', 'end': 'int', 'text': 'str', 'kind': 'str'}, (False, True, False, False), (), (), ('line', 'start', 'end', 'text', 'kind'), ('line', 'start', 'end', 'text', 'kind'), ('line', 'start', 'end', 'text', 'kind'), ('line', 'start', 'end', 'text', 'kind'), _62),
        '_Tok': ({'kind': 'str', 'name': 'str', 'line': 'int', 'start': 'int', 'end': 'int', 'value': 'float | None', 'text': 'str'}, (False, True, False, False), ('value', 'text'), (), ('kind', 'name', 'line', 'start', 'end'), ('kind', 'name', 'line', 'start', 'end', 'value', 'text'), ('kind', 'name', 'line', 'start', 'end', 'value', 'text'), ('kind', 'name', 'line', 'start', 'end', 'value', 'text'), _65),
    },
    'zero.nc.program': {
        'MachineData': ({'line': 'int', 'start': 'int', 'end': 'int', 'syn': 'bool', 'axis': 'str | None', 'axnr': 'str | None', 'writes': 'list[tuple[str, str, int, int]]', 'wait': 'bool', 'problems': 'list[tuple[str, int, int]]', 'axparams': 'list[tuple[str, int, int]]'}, (False, True, False, False), ('axis', 'axnr', 'writes', 'wait', 'problems', 'axparams'), ((2, (False, True, True, True)), (4, (False, True, True, True)), (5, (False, True, True, True))), ('line', 'start', 'end', 'syn'), ('line', 'start', 'end', 'syn', 'axis', 'axnr', 'writes', 'wait', 'problems', 'axparams'), ('line', 'start', 'end', 'syn', 'axis', 'axnr', 'writes', 'wait', 'problems', 'axparams'), ('line', 'start', 'end', 'syn', 'axis', 'axnr', 'writes', 'wait', 'problems', 'axparams'), _56),
        'Program': ({'doc': 'Document', 'machine_data': 'list[MachineData]', 'limits': 'list[SoftLimit]'}, (False, True, False, False), (), (), ('doc', 'machine_data', 'limits'), ('doc', 'machine_data', 'limits'), ('doc', 'machine_data', 'limits'), ('doc', 'machine_data', 'limits'), _58),
        'SoftLimit': ({'line': 'int', 'start': 'int', 'end': 'int', 'positive': 'bool', 'relative': 'bool', 'axis': 'str', 'value': 'float'}, (False, True, False, False), (), (), ('line', 'start', 'end', 'positive', 'relative', 'axis', 'value'), ('line', 'start', 'end', 'positive', 'relative', 'axis', 'value'), ('line', 'start', 'end', 'positive', 'relative', 'axis', 'value'), ('line', 'start', 'end', 'positive', 'relative', 'axis', 'value'), _57),
    },
    'zero.output.docs': {
        'Checked': ({'code': 'str', 'how': 'str'}, (True, True, False, False), (), (), ('code', 'how'), ('code', 'how'), ('code', 'how'), ('code', 'how'), _32),
        'Example': ({'title': 'str', 'name': 'str', 'text': 'str', 'lines': 'tuple[int, ...]', 'report': 'str'}, (True, True, False, False), ('lines', 'report'), (), ('title', 'name', 'text'), ('title', 'name', 'text', 'lines', 'report'), ('title', 'name', 'text', 'lines', 'report'), ('title', 'name', 'text', 'lines', 'report'), _30),
        'RuleExamples': ({'failing': 'Example | None', 'passing': 'Example | None', 'fixes': 'tuple[Fix, ...]', 'note': 'str'}, (True, True, False, False), ('fixes', 'note'), (), ('failing', 'passing'), ('failing', 'passing', 'fixes', 'note'), ('failing', 'passing', 'fixes', 'note'), ('failing', 'passing', 'fixes', 'note'), _31),
    },
    'zero.output.report': {
        'Against': ({'given': 'str', 'label': 'str', 'changes': 'list[Change]', 'deltas': 'list[str]'}, (False, True, False, False), ('changes', 'deltas'), ((0, (False, True, True, True)), (1, (False, True, True, True))), ('given', 'label'), ('given', 'label', 'changes', 'deltas'), ('given', 'label', 'changes', 'deltas'), ('given', 'label', 'changes', 'deltas'), _73),
        'AxisView': ({'picture': 'AxisPicture', 'svg': 'str', 'settings': 'list[tuple[str, str | None, str, Link | None]]', 'monitor_where': 'Link | None'}, (False, True, False, False), ('settings', 'monitor_where'), ((0, (False, True, True, True)),), ('picture', 'svg'), ('picture', 'svg', 'settings', 'monitor_where'), ('picture', 'svg', 'settings', 'monitor_where'), ('picture', 'svg', 'settings', 'monitor_where'), _71),
        'FindingGroup': ({'code': 'str', 'severity': 'str', 'name': 'str', 'summary': 'str', 'results': 'list[dict[str, Any]]'}, (False, True, False, False), ('results',), ((0, (False, True, True, True)),), ('code', 'severity', 'name', 'summary'), ('code', 'severity', 'name', 'summary', 'results'), ('code', 'severity', 'name', 'summary', 'results'), ('code', 'severity', 'name', 'summary', 'results'), _72),
        'Link': ({'text': 'str', 'href': 'str | None'}, (False, True, False, False), (), (), ('text', 'href'), ('text', 'href'), ('text', 'href'), ('text', 'href'), _69),
        'MachineReport': ({'title': 'str', 'startup': 'Link', 'workdir': 'str', 'generated': 'str', 'named': 'list[dict[str, Any]]', 'channels': 'list[dict[str, Any]]', 'axis_lists': 'list[dict[str, Any]]', 'axes': 'list[AxisView]', 'scopes': 'list[str]', 'values': 'list[ValueRow]', 'findings': 'list[FindingGroup]', 'rules': 'list[dict[str, str]]', 'rule_url': 'str | None', 'against': 'Against | None', 'counts': 'dict[str, int]', 'fleet': 'dict[str, Any] | None', 'values_printed': 'str'}, (False, True, False, False), ('against', 'counts', 'fleet', 'values_printed'), ((1, (False, True, True, True)),), ('title', 'startup', 'workdir', 'generated', 'named', 'channels', 'axis_lists', 'axes', 'scopes', 'values', 'findings', 'rules', 'rule_url'), ('title', 'startup', 'workdir', 'generated', 'named', 'channels', 'axis_lists', 'axes', 'scopes', 'values', 'findings', 'rules', 'rule_url', 'against', 'counts', 'fleet', 'values_printed'), ('title', 'startup', 'workdir', 'generated', 'named', 'channels', 'axis_lists', 'axes', 'scopes', 'values', 'findings', 'rules', 'rule_url', 'against', 'counts', 'fleet', 'values_printed'), ('title', 'startup', 'workdir', 'generated', 'named', 'channels', 'axis_lists', 'axes', 'scopes', 'values', 'findings', 'rules', 'rule_url', 'against', 'counts', 'fleet', 'values_printed'), _74),
        'ValueRow': ({'scope': 'str', 'key': 'str', 'param_id': 'str | None', 'value': 'str | None', 'origin': 'str', 'where': 'Link | None', 'differs': 'bool', 'shown': 'str | None', 'default': 'str | None', 'default_shown': 'str | None', 'used': 'str | None', 'used_by': 'str | None', 'findings': 'list[tuple[str, str, str]]', 'also': 'list[str]', 'repeated': 'bool'}, (False, True, False, False), ('shown', 'default', 'default_shown', 'used', 'used_by', 'findings', 'also', 'repeated'), ((5, (False, True, True, True)), (6, (False, True, True, True))), ('scope', 'key', 'param_id', 'value', 'origin', 'where', 'differs'), ('scope', 'key', 'param_id', 'value', 'origin', 'where', 'differs', 'shown', 'default', 'default_shown', 'used', 'used_by', 'findings', 'also', 'repeated'), ('scope', 'key', 'param_id', 'value', 'origin', 'where', 'differs', 'shown', 'default', 'default_shown', 'used', 'used_by', 'findings', 'also', 'repeated'), ('scope', 'key', 'param_id', 'value', 'origin', 'where', 'differs', 'shown', 'default', 'default_shown', 'used', 'used_by', 'findings', 'also', 'repeated'), _70),
    },
    'zero.output.svg': {
        'AxisPicture': ({'name': 'str', 'log_nr': 'int', 'unit': 'str', 'rotary': 'bool', 'modulo': 'bool', 'swe_neg': 'float', 'swe_pos': 'float', 'tolerance': 'float', 'ref': 'float | None', 'channel': 'int | None', 'index': 'int | None', 'zeros': 'list[ZeroPoint]', 'modulo_range': 'tuple[float, float] | None', 'old_neg': 'float | None', 'old_pos': 'float | None', 'monitoring': 'str', 'monitoring_why': 'str', 'travel': 'list[tuple[str, float, float]]'}, (False, True, False, False), ('channel', 'index', 'zeros', 'modulo_range', 'old_neg', 'old_pos', 'monitoring', 'monitoring_why', 'travel'), ((2, (False, True, True, True)), (8, (False, True, True, True))), ('name', 'log_nr', 'unit', 'rotary', 'modulo', 'swe_neg', 'swe_pos', 'tolerance', 'ref'), ('name', 'log_nr', 'unit', 'rotary', 'modulo', 'swe_neg', 'swe_pos', 'tolerance', 'ref', 'channel', 'index', 'zeros', 'modulo_range', 'old_neg', 'old_pos', 'monitoring', 'monitoring_why', 'travel'), ('name', 'log_nr', 'unit', 'rotary', 'modulo', 'swe_neg', 'swe_pos', 'tolerance', 'ref', 'channel', 'index', 'zeros', 'modulo_range', 'old_neg', 'old_pos', 'monitoring', 'monitoring_why', 'travel'), ('name', 'log_nr', 'unit', 'rotary', 'modulo', 'swe_neg', 'swe_pos', 'tolerance', 'ref', 'channel', 'index', 'zeros', 'modulo_range', 'old_neg', 'old_pos', 'monitoring', 'monitoring_why', 'travel'), _67),
        'Scale': ({'lo': 'float', 'hi': 'float', 'x0': 'float', 'x1': 'float'}, (False, True, False, False), ('x0', 'x1'), (), ('lo', 'hi'), ('lo', 'hi', 'x0', 'x1'), ('lo', 'hi', 'x0', 'x1'), ('lo', 'hi', 'x0', 'x1'), _68),
        'ZeroPoint': ({'group': 'int', 'offset': 'float', 'pcs_neg': 'float | None', 'pcs_pos': 'float | None', 'note': 'str'}, (False, True, False, False), ('note',), (), ('group', 'offset', 'pcs_neg', 'pcs_pos'), ('group', 'offset', 'pcs_neg', 'pcs_pos', 'note'), ('group', 'offset', 'pcs_neg', 'pcs_pos', 'note'), ('group', 'offset', 'pcs_neg', 'pcs_pos', 'note'), _66),
    },
    'zero.rules.program': {
        '_AxisFacts': ({'name': 'str', 'unit': 'str', 'code': 'str', 'behaviour': 'str', 'path': 'str', 'neg': 'tuple[str, int | None]', 'pos': 'tuple[str, int | None]', 'kernel_error': 'str | None'}, (False, True, False, False), ('kernel_error',), (), ('name', 'unit', 'code', 'behaviour', 'path', 'neg', 'pos'), ('name', 'unit', 'code', 'behaviour', 'path', 'neg', 'pos', 'kernel_error'), ('name', 'unit', 'code', 'behaviour', 'path', 'neg', 'pos', 'kernel_error'), ('name', 'unit', 'code', 'behaviour', 'path', 'neg', 'pos', 'kernel_error'), _75),
    },
    'zero.server.documents': {
        'Analysis': ({'uri': 'str', 'version': 'int | None', 'path': 'Path | None', 'name': 'str', 'form': 'str', 'text': 'Text', 'data': 'bytes', 'saved': 'bool', 'registry': 'Registry', 'config': 'Config', 'options': 'LintOptions', 'result': 'LintResult | None', 'notes': 'list[Note]', 'machine': 'Machine | None', 'references': 'dict[str, Path]', 'cache': 'dict[str, object]', '_values': 'ListValues | None', '_lists': 'list[tuple[str, ListValues]] | None', '_rows': 'dict[int, list[tuple[ListValues, int]]] | None'}, (False, False, False, False), ('result', 'notes', 'machine', 'references', 'cache', '_values', '_lists', '_rows'), ((1, (False, True, True, True)), (3, (False, True, True, True)), (4, (False, True, True, True))), ('uri', 'version', 'path', 'name', 'form', 'text', 'data', 'saved', 'registry', 'config', 'options'), ('uri', 'version', 'path', 'name', 'form', 'text', 'data', 'saved', 'registry', 'config', 'options', 'result', 'notes', 'machine', 'references', 'cache', '_values', '_lists', '_rows'), ('uri', 'version', 'path', 'name', 'form', 'text', 'data', 'saved', 'registry', 'config', 'options', 'result', 'notes', 'machine', 'references', 'cache', '_values', '_lists', '_rows'), ('uri', 'version', 'path', 'name', 'form', 'text', 'data', 'saved', 'registry', 'config', 'options', 'result', 'notes', 'machine', 'references', 'cache', '_values', '_lists', '_rows'), _79),
        'Note': ({'message': 'str', 'line': 'int', 'column': 'int', 'severity': 'Severity', 'elsewhere': 'tuple[Path, int, int] | None'}, (False, True, False, False), ('line', 'column', 'severity', 'elsewhere'), (), ('message',), ('message', 'line', 'column', 'severity', 'elsewhere'), ('message', 'line', 'column', 'severity', 'elsewhere'), ('message', 'line', 'column', 'severity', 'elsewhere'), _77),
        'Place': ({'values': 'ListValues', 'line': 'int', 'column': 'int', 'shift': 'int', 'element': 'bool'}, (False, False, False, False), ('shift', 'element'), (), ('values', 'line', 'column'), ('values', 'line', 'column', 'shift', 'element'), ('values', 'line', 'column', 'shift', 'element'), ('values', 'line', 'column', 'shift', 'element'), _78),
    },
    'zero.server.hover': {
        'Target': ({'spec': 'ParamSpec', 'key': 'str | None', 'indices': 'tuple[int, ...]', 'entry': 'Entry | None', 'alias': 'str | None', 'start': 'int', 'end': 'int', 'values': 'ListValues | None'}, (False, True, False, False), ('key', 'indices', 'entry', 'alias', 'start', 'end', 'values'), (), ('spec',), ('spec', 'key', 'indices', 'entry', 'alias', 'start', 'end', 'values'), ('spec', 'key', 'indices', 'entry', 'alias', 'start', 'end', 'values'), ('spec', 'key', 'indices', 'entry', 'alias', 'start', 'end', 'values'), _80),
    },
    'zero.server.outline': {
        '_Group': ({'name': 'str', 'detail': 'str | None', 'level': 'int', 'symbols': 'list[types.DocumentSymbol]', 'groups': 'dict[str, _Group]', 'order': 'list[_Group | types.DocumentSymbol]', 'first': 'int', 'last': 'int'}, (False, True, False, False), ('symbols', 'groups', 'order', 'first', 'last'), ((0, (False, True, True, True)), (1, (False, True, True, True)), (2, (False, True, True, True))), ('name', 'detail', 'level'), ('name', 'detail', 'level', 'symbols', 'groups', 'order', 'first', 'last'), ('name', 'detail', 'level', 'symbols', 'groups', 'order', 'first', 'last'), ('name', 'detail', 'level', 'symbols', 'groups', 'order', 'first', 'last'), _81),
    },
    'zero.server.settings': {
        'Settings': ({'debounce': 'float', 'rule_docs': 'str | None', 'structured': 'str', 'machine': 'bool', 'max_findings': 'int'}, (False, True, False, False), ('debounce', 'rule_docs', 'structured', 'machine', 'max_findings'), (), (), ('debounce', 'rule_docs', 'structured', 'machine', 'max_findings'), ('debounce', 'rule_docs', 'structured', 'machine', 'max_findings'), ('debounce', 'rule_docs', 'structured', 'machine', 'max_findings'), _76),
    },
    'zero.structured.common': {
        'Found': ({'line': 'int', 'column': 'int', 'after': 'str | None', 'before': 'list[str]', 'key_at': 'tuple[int, int, int, int] | None'}, (False, True, False, False), ('after', 'before', 'key_at'), ((1, (False, True, True, True)),), ('line', 'column'), ('line', 'column', 'after', 'before', 'key_at'), ('line', 'column', 'after', 'before', 'key_at'), ('line', 'column', 'after', 'before', 'key_at'), _9),
    },
    'zero.structured.tree': {
        'Leaf': ({'key': 'str', 'path': 'tuple[str, ...]', 'value': 'Scalar', 'before': 'list[str]', 'after': 'str | None', 'line': 'int | None', 'column': 'int | None', 'native': 'str', 'key_at': 'tuple[int, int, int, int] | None'}, (False, False, False, False), ('before', 'after', 'line', 'column', 'native', 'key_at'), ((0, (False, True, True, True)),), ('key', 'path', 'value'), ('key', 'path', 'value', 'before', 'after', 'line', 'column', 'native', 'key_at'), ('key', 'path', 'value', 'before', 'after', 'line', 'column', 'native', 'key_at'), ('key', 'path', 'value', 'before', 'after', 'line', 'column', 'native', 'key_at'), _4),
        'ListText': ({'text': 'str', 'lines_of': 'dict[int, Leaf]'}, (False, True, False, False), (), (), ('text', 'lines_of'), ('text', 'lines_of'), ('text', 'lines_of'), ('text', 'lines_of'), _7),
        'Tree': ({'leaves': 'list[Leaf]', 'meta': 'dict[str, Any]', 'tail': 'list[str]', 'path': 'str', 'notes': 'list[str]', '_nested': 'tuple[dict[str, Any], list[Leaf]] | None'}, (False, False, False, False), ('meta', 'tail', 'path', 'notes', '_nested'), ((0, (False, True, True, True)), (1, (False, True, True, True)), (3, (False, True, True, True)), (4, (True, False, False, True))), ('leaves',), ('leaves', 'meta', 'tail', 'path', 'notes', '_nested'), ('leaves', 'meta', 'tail', 'path', 'notes'), ('leaves', 'meta', 'tail', 'path', 'notes', '_nested'), _5),
        '_Node': ({'children': 'dict[str, _Node | Leaf]'}, (False, True, False, False), ('children',), ((0, (False, True, True, True)),), (), ('children',), ('children',), ('children',), _6),
    },
}
del __init__
