"""The ``__init__`` of every record of the modules a list's lint loads, compiled with this module and keyed by its text:
written by tools/gen_record_inits.py (see :func:`zero.records._compiled_init`).

Generated: do not edit."""

# ruff: noqa
# mypy: ignore-errors
from __future__ import annotations

from types import CodeType

INITS: dict[str, CodeType] = {}

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

def __init__(self, files=None, clean=None, unreadable=None, by_severity=None, by_code=None, worst=None) -> None:
    self.files = files
    self.clean = clean
    self.unreadable = unreadable
    self.by_severity = __factory_by_severity() if by_severity is MISSING else by_severity
    self.by_code = __factory_by_code() if by_code is MISSING else by_code
    self.worst = worst
INITS['def __init__(self, files=__default_files, clean=__default_clean, unreadable=__default_unreadable, by_severity=MISSING, by_code=MISSING, worst=__default_worst) -> None:\n    self.files = files\n    self.clean = clean\n    self.unreadable = unreadable\n    self.by_severity = __factory_by_severity() if by_severity is MISSING else by_severity\n    self.by_code = __factory_by_code() if by_code is MISSING else by_code\n    self.worst = worst'] = __init__.__code__

def __init__(self, form, source, shift, final_newline=None, kind=None, update=None, default_list=None) -> None:
    self.form = form
    self.source = source
    self.shift = shift
    self.final_newline = final_newline
    self.kind = kind
    self.update = update
    self.default_list = default_list
INITS['def __init__(self, form, source, shift, final_newline=__default_final_newline, kind=__default_kind, update=__default_update, default_list=__default_default_list) -> None:\n    self.form = form\n    self.source = source\n    self.shift = shift\n    self.final_newline = final_newline\n    self.kind = kind\n    self.update = update\n    self.default_list = default_list'] = __init__.__code__

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

def __init__(self, kind, line, start, end, detail=None) -> None:
    __set(self, 'kind', kind)
    __set(self, 'line', line)
    __set(self, 'start', start)
    __set(self, 'end', end)
    __set(self, 'detail', detail)
INITS["def __init__(self, kind, line, start, end, detail=__default_detail) -> None:\n    __set(self, 'kind', kind)\n    __set(self, 'line', line)\n    __set(self, 'start', start)\n    __set(self, 'end', end)\n    __set(self, 'detail', detail)"] = __init__.__code__

def __init__(self, line) -> None:
    self.line = line
INITS['def __init__(self, line) -> None:\n    self.line = line'] = __init__.__code__

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

def __init__(self, line, start, end, codes, scope, target=None, used=None) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.codes = codes
    self.scope = scope
    self.target = target
    self.used = __factory_used() if used is MISSING else used
INITS['def __init__(self, line, start, end, codes, scope, target=__default_target, used=MISSING) -> None:\n    self.line = line\n    self.start = start\n    self.end = end\n    self.codes = codes\n    self.scope = scope\n    self.target = target\n    self.used = __factory_used() if used is MISSING else used'] = __init__.__code__

def __init__(self, line, text) -> None:
    self.line = line
    self.text = text
INITS['def __init__(self, line, text) -> None:\n    self.line = line\n    self.text = text'] = __init__.__code__

def __init__(self, line, text, commented_out=None) -> None:
    self.line = line
    self.text = text
    self.commented_out = commented_out
INITS['def __init__(self, line, text, commented_out=__default_commented_out) -> None:\n    self.line = line\n    self.text = text\n    self.commented_out = commented_out'] = __init__.__code__

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

def __init__(self, machine, registry, severities=None, path=None) -> None:
    self.machine = machine
    self.registry = registry
    self.severities = __factory_severities() if severities is MISSING else severities
    self.path = path
INITS['def __init__(self, machine, registry, severities=MISSING, path=__default_path) -> None:\n    self.machine = machine\n    self.registry = registry\n    self.severities = __factory_severities() if severities is MISSING else severities\n    self.path = path'] = __init__.__code__

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

def __init__(self, program, registry, machine=None, severities=None, path=None) -> None:
    self.program = program
    self.registry = registry
    self.machine = machine
    self.severities = __factory_severities() if severities is MISSING else severities
    self.path = path
INITS['def __init__(self, program, registry, machine=__default_machine, severities=MISSING, path=__default_path) -> None:\n    self.program = program\n    self.registry = registry\n    self.machine = machine\n    self.severities = __factory_severities() if severities is MISSING else severities\n    self.path = path'] = __init__.__code__

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

def __init__(self, span, message, path=None) -> None:
    __set(self, 'span', span)
    __set(self, 'message', message)
    __set(self, 'path', path)
INITS["def __init__(self, span, message, path=__default_path) -> None:\n    __set(self, 'span', span)\n    __set(self, 'message', message)\n    __set(self, 'path', path)"] = __init__.__code__

def __init__(self, span, replacement) -> None:
    __set(self, 'span', span)
    __set(self, 'replacement', replacement)
INITS["def __init__(self, span, replacement) -> None:\n    __set(self, 'span', span)\n    __set(self, 'replacement', replacement)"] = __init__.__code__

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

def __init__(self, value) -> None:
    __set(self, 'value', value)
INITS["def __init__(self, value) -> None:\n    __set(self, 'value', value)"] = __init__.__code__

def __init__(self, which, type) -> None:
    __set(self, 'which', which)
    __set(self, 'type', type)
INITS["def __init__(self, which, type) -> None:\n    __set(self, 'which', which)\n    __set(self, 'type', type)"] = __init__.__code__

del __init__
