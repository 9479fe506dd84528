"""The records of the modules a list's lint loads, worked out ahead of time: written by tools/gen_record_inits.py
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

def __init__(self, line, column, end_line, end_column) -> None:
    __set(self, 'line', line)
    __set(self, 'column', column)
    __set(self, 'end_line', end_line)
    __set(self, 'end_column', end_column)
_0 = __init__.__code__

def __init__(self, span, replacement) -> None:
    __set(self, 'span', span)
    __set(self, 'replacement', replacement)
_1 = __init__.__code__

def __init__(self, title, edits=None, safe=None) -> None:
    __set(self, 'title', title)
    __set(self, 'edits', edits)
    __set(self, 'safe', safe)
_2 = __init__.__code__

def __init__(self, span, message, path=None) -> None:
    __set(self, 'span', span)
    __set(self, 'message', message)
    __set(self, 'path', path)
_3 = __init__.__code__

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
_4 = __init__.__code__

def __init__(self, name, consequence, severity, says, source, releases=None, kinds=None, kernel_error=None) -> None:
    __set(self, 'name', name)
    __set(self, 'consequence', consequence)
    __set(self, 'severity', severity)
    __set(self, 'says', says)
    __set(self, 'source', source)
    __set(self, 'releases', releases)
    __set(self, 'kinds', kinds)
    __set(self, 'kernel_error', kernel_error)
_5 = __init__.__code__

def __init__(self, value) -> None:
    __set(self, 'value', value)
_6 = __init__.__code__

def __init__(self, which, type) -> None:
    __set(self, 'which', which)
    __set(self, 'type', type)
_7 = __init__.__code__

def __init__(self, id, index=None) -> None:
    __set(self, 'id', id)
    __set(self, 'index', index)
_8 = __init__.__code__

def __init__(self, op, left, right) -> None:
    __set(self, 'op', op)
    __set(self, 'left', left)
    __set(self, 'right', right)
_9 = __init__.__code__

def __init__(self, operand) -> None:
    __set(self, 'operand', operand)
_10 = __init__.__code__

def __init__(self, low, low_strict, high, high_strict) -> None:
    __set(self, 'low', low)
    __set(self, 'low_strict', low_strict)
    __set(self, 'high', high)
    __set(self, 'high_strict', high_strict)
_11 = __init__.__code__

def __init__(self, low=None, low_strict=None, high=None, high_strict=None, allowed=None) -> None:
    __set(self, 'low', low)
    __set(self, 'low_strict', low_strict)
    __set(self, 'high', high)
    __set(self, 'high_strict', high_strict)
    __set(self, 'allowed', allowed)
_12 = __init__.__code__

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
_13 = __init__.__code__

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
_14 = __init__.__code__

def __init__(self, text, pattern, indices) -> None:
    self.text = text
    self.pattern = pattern
    self.indices = indices
_15 = __init__.__code__

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
_16 = __init__.__code__

def __init__(self, line, text, commented_out=None) -> None:
    self.line = line
    self.text = text
    self.commented_out = commented_out
_17 = __init__.__code__

def __init__(self, line) -> None:
    self.line = line
_18 = __init__.__code__

def __init__(self, line, start) -> None:
    self.line = line
    self.start = start
_19 = __init__.__code__

def __init__(self, line, text) -> None:
    self.line = line
    self.text = text
_20 = __init__.__code__

def __init__(self, kind, line, start, end, detail=None) -> None:
    __set(self, 'kind', kind)
    __set(self, 'line', line)
    __set(self, 'start', start)
    __set(self, 'end', end)
    __set(self, 'detail', detail)
_21 = __init__.__code__

def __init__(self, form, source, shift, final_newline=None, kind=None, update=None, default_list=None) -> None:
    self.form = form
    self.source = source
    self.shift = shift
    self.final_newline = final_newline
    self.kind = kind
    self.update = update
    self.default_list = default_list
_22 = __init__.__code__

def __init__(self, head, tail, pattern, indices, indexed) -> None:
    self.head = head
    self.tail = tail
    self.pattern = pattern
    self.indices = indices
    self.indexed = indexed
_23 = __init__.__code__

def __init__(self, old, kind, new, id, release, source, see=None) -> None:
    __set(self, 'old', old)
    __set(self, 'kind', kind)
    __set(self, 'new', new)
    __set(self, 'id', id)
    __set(self, 'release', release)
    __set(self, 'source', source)
    __set(self, 'see', see)
_24 = __init__.__code__

def __init__(self, old, kind, release, source, see=None) -> None:
    __set(self, 'old', old)
    __set(self, 'kind', kind)
    __set(self, 'release', release)
    __set(self, 'source', source)
    __set(self, 'see', see)
_25 = __init__.__code__

def __init__(self, old, kind, new, release, source, see=None) -> None:
    __set(self, 'old', old)
    __set(self, 'kind', kind)
    __set(self, 'new', new)
    __set(self, 'release', release)
    __set(self, 'source', source)
    __set(self, 'see', see)
_26 = __init__.__code__

def __init__(self, renames, removals, prefixes) -> None:
    __set(self, 'renames', renames)
    __set(self, 'removals', removals)
    __set(self, 'prefixes', prefixes)
_27 = __init__.__code__

def __init__(self, number=None, text=None, ref=None, problem=None, detail=None) -> None:
    self.number = number
    self.text = text
    self.ref = ref
    self.problem = problem
    self.detail = detail
_28 = __init__.__code__

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
_29 = __init__.__code__

def __init__(self, select=None, ignore=None, kind=None, severity=None, extend_select=None, encoding=None, kernel=None, ignore_noqa=None) -> None:
    self.select = select
    self.ignore = ignore
    self.kind = kind
    self.severity = __factory_severity() if severity is MISSING else severity
    self.extend_select = extend_select
    self.encoding = encoding
    self.kernel = kernel
    self.ignore_noqa = ignore_noqa
_30 = __init__.__code__

def __init__(self, path, document, kind, diagnostics=None, note=None) -> None:
    self.path = path
    self.document = document
    self.kind = kind
    self.diagnostics = __factory_diagnostics() if diagnostics is MISSING else diagnostics
    self.note = note
_31 = __init__.__code__

def __init__(self, files=None, clean=None, unreadable=None, by_severity=None, by_code=None, worst=None) -> None:
    self.files = files
    self.clean = clean
    self.unreadable = unreadable
    self.by_severity = __factory_by_severity() if by_severity is MISSING else by_severity
    self.by_code = __factory_by_code() if by_code is MISSING else by_code
    self.worst = worst
_32 = __init__.__code__

def __init__(self, name, module, function, note, streamed=None, fail_on=None, json_statistics=None, aliases=None) -> None:
    __set(self, 'name', name)
    __set(self, 'module', module)
    __set(self, 'function', function)
    __set(self, 'note', note)
    __set(self, 'streamed', streamed)
    __set(self, 'fail_on', fail_on)
    __set(self, 'json_statistics', json_statistics)
    __set(self, 'aliases', aliases)
_33 = __init__.__code__

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
_34 = __init__.__code__

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
_35 = __init__.__code__

def __init__(self, config=None, isolated=None, param_desc=None, kernel=None) -> None:
    __set(self, 'config', config)
    __set(self, 'isolated', isolated)
    __set(self, 'param_desc', param_desc)
    __set(self, 'kernel', kernel)
_36 = __init__.__code__

def __init__(self, path, config, options, param_desc, project) -> None:
    __set(self, 'path', path)
    __set(self, 'config', config)
    __set(self, 'options', options)
    __set(self, 'param_desc', param_desc)
    __set(self, 'project', project)
_37 = __init__.__code__

def __init__(self, out, err, out_bytes) -> None:
    self.out = out
    self.err = err
    self.out_bytes = out_bytes
_38 = __init__.__code__

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
_39 = __init__.__code__

def __init__(self, results=None, report=None, findings_to_stderr=None, changed=None, fixed=None) -> None:
    self.results = __factory_results() if results is MISSING else results
    self.report = report
    self.findings_to_stderr = findings_to_stderr
    self.changed = changed
    self.fixed = __factory_fixed() if fixed is MISSING else fixed
_40 = __init__.__code__

def __init__(self, code, name, severity, summary, explanation, scope=None, opt_in=None, reads=None) -> None:
    __set(self, 'code', code)
    __set(self, 'name', name)
    __set(self, 'severity', severity)
    __set(self, 'summary', summary)
    __set(self, 'explanation', explanation)
    __set(self, 'scope', scope)
    __set(self, 'opt_in', opt_in)
    __set(self, 'reads', reads)
_41 = __init__.__code__

def __init__(self, machine, registry, severities=None, path=None) -> None:
    self.machine = machine
    self.registry = registry
    self.severities = __factory_severities() if severities is MISSING else severities
    self.path = path
_42 = __init__.__code__

def __init__(self, program, registry, machine=None, severities=None, path=None) -> None:
    self.program = program
    self.registry = registry
    self.machine = machine
    self.severities = __factory_severities() if severities is MISSING else severities
    self.path = path
_43 = __init__.__code__

def __init__(self, codes, run) -> None:
    __set(self, 'codes', codes)
    __set(self, 'run', run)
_44 = __init__.__code__

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
_45 = __init__.__code__

def __init__(self, condition, when, read, shown) -> None:
    __set(self, 'condition', condition)
    __set(self, 'when', when)
    __set(self, 'read', read)
    __set(self, 'shown', shown)
_46 = __init__.__code__

def __init__(self, line, start, end, codes, scope, target=None, used=None) -> None:
    self.line = line
    self.start = start
    self.end = end
    self.codes = codes
    self.scope = scope
    self.target = target
    self.used = __factory_used() if used is MISSING else used
_47 = __init__.__code__

def __init__(self, doc, registry, kind, base=None, shape_rows=None, shape_keys=None, pattern_shapes=None, bound=None, valueless=None, _groups=None, _entries=None, _resolved=None, _by_id=None, severities=None, kernel=None, default_list=None, tally=None) -> None:
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
    self.tally = tally
INITS['def __init__(self, doc, registry, kind, base=__default_base, shape_rows=MISSING, shape_keys=MISSING, pattern_shapes=MISSING, bound=MISSING, valueless=__default_valueless, _groups=__default__groups, _entries=__default__entries, _resolved=__default__resolved, _by_id=__default__by_id, severities=MISSING, kernel=__default_kernel, default_list=__default_default_list, tally=__default_tally) -> None:\n    self.doc = doc\n    self.registry = registry\n    self.kind = kind\n    self.base = base\n    self.shape_rows = __factory_shape_rows() if shape_rows is MISSING else shape_rows\n    self.shape_keys = __factory_shape_keys() if shape_keys is MISSING else shape_keys\n    self.pattern_shapes = __factory_pattern_shapes() if pattern_shapes is MISSING else pattern_shapes\n    self.bound = __factory_bound() if bound is MISSING else bound\n    self.valueless = valueless\n    self._groups = _groups\n    self._entries = _entries\n    self._resolved = _resolved\n    self._by_id = _by_id\n    self.severities = __factory_severities() if severities is MISSING else severities\n    self.kernel = kernel\n    self.default_list = default_list\n    self.tally = tally'] = __init__.__code__

RECORDS: dict[str, dict[str, tuple]] = {
    'zero.catalog.evidence': {
        'Claim': ({'name': 'str', 'consequence': 'str', 'severity': 'Severity', 'says': 'str', 'source': 'str', 'releases': 'str', 'kinds': 'tuple[str, ...]', 'kernel_error': 'str | None'}, (True, True, False, False), ('releases', 'kinds', 'kernel_error'), (), ('name', 'consequence', 'severity', 'says', 'source'), ('name', 'consequence', 'severity', 'says', 'source', 'releases', 'kinds', 'kernel_error'), ('name', 'consequence', 'severity', 'says', 'source', 'releases', 'kinds', 'kernel_error'), ('name', 'consequence', 'severity', 'says', 'source', 'releases', 'kinds', 'kernel_error'), _5),
    },
    'zero.catalog.ranges': {
        'BinOp': ({'op': 'str', 'left': 'Expr', 'right': 'Expr'}, (True, True, False, False), (), (), ('op', 'left', 'right'), ('op', 'left', 'right'), ('op', 'left', 'right'), ('op', 'left', 'right'), _9),
        'Bounds': ({'low': 'Number | None', 'low_strict': 'bool', 'high': 'Number | None', 'high_strict': 'bool'}, (True, True, False, False), (), (), ('low', 'low_strict', 'high', 'high_strict'), ('low', 'low_strict', 'high', 'high_strict'), ('low', 'low_strict', 'high', 'high_strict'), ('low', 'low_strict', 'high', 'high_strict'), _11),
        'Limit': ({'which': 'str', 'type': 'str'}, (True, True, False, False), (), (), ('which', 'type'), ('which', 'type'), ('which', 'type'), ('which', 'type'), _7),
        'Neg': ({'operand': 'Expr'}, (True, True, False, False), (), (), ('operand',), ('operand',), ('operand',), ('operand',), _10),
        'Num': ({'value': 'Number'}, (True, True, False, False), (), (), ('value',), ('value',), ('value',), ('value',), _6),
        'Range': ({'low': 'Expr | None', 'low_strict': 'bool', 'high': 'Expr | None', 'high_strict': 'bool', 'allowed': 'tuple[Number, ...] | None'}, (True, True, False, False), ('low', 'low_strict', 'high', 'high_strict', 'allowed'), (), (), ('low', 'low_strict', 'high', 'high_strict', 'allowed'), ('low', 'low_strict', 'high', 'high_strict', 'allowed'), ('low', 'low_strict', 'high', 'high_strict', 'allowed'), _12),
        'Ref': ({'id': 'str', 'index': 'int | None'}, (True, True, False, False), ('index',), (), ('id',), ('id', 'index'), ('id', 'index'), ('id', 'index'), _8),
    },
    'zero.catalog.registry': {
        'ParamSpec': ({'id': 'str', 'kind': 'str', 'key': 'str | None', 'type': 'str', 'default': 'str | None', 'range_text': 'str | None', 'range_note': 'str | None', 'dims': 'tuple[int, ...]', 'symbols': 'tuple[tuple[str, int | None], ...]', 'units': 'tuple[str, ...]', 'quantity': 'str | None', 'max_len': 'int | None', 'restart': 'bool', 'description': 'str | None', 'source': 'str', 'index_base': 'int', 'enum': 'tuple[int, ...]', 'enum_flags': 'bool', 'bits': 'bool', 'enum_labels': 'tuple[str, ...]'}, (False, True, False, False), ('default', 'range_text', 'range_note', 'dims', 'symbols', 'units', 'quantity', 'max_len', 'restart', 'description', 'source', 'index_base', 'enum', 'enum_flags', 'bits', 'enum_labels'), (), ('id', 'kind', 'key', 'type'), ('id', 'kind', 'key', 'type', 'default', 'range_text', 'range_note', 'dims', 'symbols', 'units', 'quantity', 'max_len', 'restart', 'description', 'source', 'index_base', 'enum', 'enum_flags', 'bits', 'enum_labels'), ('id', 'kind', 'key', 'type', 'default', 'range_text', 'range_note', 'dims', 'symbols', 'units', 'quantity', 'max_len', 'restart', 'description', 'source', 'index_base', 'enum', 'enum_flags', 'bits', 'enum_labels'), ('id', 'kind', 'key', 'type', 'default', 'range_text', 'range_note', 'dims', 'symbols', 'units', 'quantity', 'max_len', 'restart', 'description', 'source', 'index_base', 'enum', 'enum_flags', 'bits', 'enum_labels'), _13),
        'Registry': ({'specs': 'Mapping[str, ParamSpec]', 'source': 'str', '_by_key': 'Mapping[tuple[str, str], str]', '_kinds_of': 'Mapping[str, Sequence[str]]', '_ranges': 'dict[str, Range | None]', 'aliases': 'dict[tuple[str, str], str]', 'vendor_keys': 'dict[tuple[str, str], tuple[str, str]]', '_suggestions': 'dict[tuple[str, str | None, int], list[str]]', '_machine_data': 'frozenset[str] | None', '_pattern_specs': 'dict[tuple[str | None, str], ParamSpec | None]', 'memo': 'dict[str, dict[Any, Any]]'}, (False, True, False, True), ('source', '_by_key', '_kinds_of', '_ranges', 'aliases', 'vendor_keys', '_suggestions', '_machine_data', '_pattern_specs', 'memo'), ((1, (False, True, True, True)), (2, (False, True, True, True)), (3, (False, True, True, True)), (4, (False, True, True, True)), (5, (False, True, True, True)), (6, (False, True, True, True)), (8, (False, True, True, True)), (9, (False, True, False, True))), ('specs',), ('specs', 'source', '_by_key', '_kinds_of', '_ranges', 'aliases', 'vendor_keys', '_suggestions', '_machine_data', '_pattern_specs', 'memo'), ('specs', 'source', '_by_key', '_kinds_of', '_ranges', 'aliases', 'vendor_keys', '_suggestions', '_machine_data', '_pattern_specs'), ('specs', 'source', '_by_key', '_kinds_of', '_ranges', 'aliases', 'vendor_keys', '_suggestions', '_machine_data', '_pattern_specs', 'memo'), _14),
    },
    'zero.catalog.releases': {
        'Prefix': ({'old': 'str', 'kind': 'str', 'new': 'str', 'release': 'str', 'source': 'str', 'see': 'tuple[str, ...]'}, (True, True, False, False), ('see',), (), ('old', 'kind', 'new', 'release', 'source'), ('old', 'kind', 'new', 'release', 'source', 'see'), ('old', 'kind', 'new', 'release', 'source', 'see'), ('old', 'kind', 'new', 'release', 'source', 'see'), _26),
        'ReleaseTable': ({'renames': 'tuple[Rename, ...]', 'removals': 'tuple[Removal, ...]', 'prefixes': 'tuple[Prefix, ...]'}, (True, True, False, False), (), (), ('renames', 'removals', 'prefixes'), ('renames', 'removals', 'prefixes'), ('renames', 'removals', 'prefixes'), ('renames', 'removals', 'prefixes'), _27),
        'Removal': ({'old': 'str', 'kind': 'str', 'release': 'str', 'source': 'str', 'see': 'tuple[str, ...]'}, (True, True, False, False), ('see',), (), ('old', 'kind', 'release', 'source'), ('old', 'kind', 'release', 'source', 'see'), ('old', 'kind', 'release', 'source', 'see'), ('old', 'kind', 'release', 'source', 'see'), _25),
        'Rename': ({'old': 'str', 'kind': 'str', 'new': 'str', 'id': 'str', 'release': 'str', 'source': 'str', 'see': 'tuple[str, ...]'}, (True, True, False, False), ('see',), (), ('old', 'kind', 'new', 'id', 'release', 'source'), ('old', 'kind', 'new', 'id', 'release', 'source', 'see'), ('old', 'kind', 'new', 'id', 'release', 'source', 'see'), ('old', 'kind', 'new', 'id', 'release', 'source', 'see'), _24),
    },
    'zero.catalog.values': {
        'ListValues': ({'doc': 'Document', 'registry': 'Registry', 'kind': 'str | None', 'base': 'ListValues | None', 'shape_rows': 'list[Sequence[int]]', 'shape_keys': 'list[tuple[str, tuple[int, ...], bool]]', 'pattern_shapes': 'dict[str, list[int]]', 'bound': 'dict[str, tuple[ParamSpec, bool] | None]', 'valueless': 'frozenset[int]', '_groups': 'dict[str, Sequence[int]] | None', '_entries': 'list[Entry] | None', '_resolved': '_Resolved | None', '_by_id': 'Mapping[str, dict[tuple[int, ...], Resolved]] | None'}, (False, True, False, False), ('base', 'shape_rows', 'shape_keys', 'pattern_shapes', 'bound', 'valueless', '_groups', '_entries', '_resolved', '_by_id'), ((1, (False, True, False, False)), (2, (False, True, False, False)), (3, (False, True, False, False)), (4, (False, True, False, False)), (5, (True, False, False, False)), (6, (True, False, False, False)), (7, (True, False, False, False)), (8, (True, False, False, False)), (9, (True, False, False, False))), ('doc', 'registry', 'kind'), ('doc', 'registry', 'kind', 'base', 'shape_rows', 'shape_keys', 'pattern_shapes', 'bound', 'valueless', '_groups', '_entries', '_resolved', '_by_id'), ('doc', 'registry', 'kind', 'base'), ('doc', 'registry', 'kind', 'base'), _29),
        'Value': ({'number': 'Number | None', 'text': 'str | None', 'ref': 'tuple[str, int | None] | None', 'problem': 'str | None', 'detail': 'str'}, (False, True, False, False), ('number', 'text', 'ref', 'problem', 'detail'), (), (), ('number', 'text', 'ref', 'problem', 'detail'), ('number', 'text', 'ref', 'problem', 'detail'), ('number', 'text', 'ref', 'problem', 'detail'), _28),
    },
    'zero.cli.options': {
        'Option': ({'dest': 'str', 'flags': 'tuple[str, ...]', 'help': 'str', 'kind': "Literal['flag', 'value', 'multi']", 'type': 'type', 'choices': 'tuple[str, ...]', 'minimum': 'int | None', 'negative': 'str | None', 'default': 'object', 'metavar': 'str | None', 'envvar': 'str | None'}, (True, True, False, False), ('kind', 'type', 'choices', 'minimum', 'negative', 'default', 'metavar', 'envvar'), (), ('dest', 'flags', 'help'), ('dest', 'flags', 'help', 'kind', 'type', 'choices', 'minimum', 'negative', 'default', 'metavar', 'envvar'), ('dest', 'flags', 'help', 'kind', 'type', 'choices', 'minimum', 'negative', 'default', 'metavar', 'envvar'), ('dest', 'flags', 'help', 'kind', 'type', 'choices', 'minimum', 'negative', 'default', 'metavar', 'envvar'), _34),
    },
    'zero.diagnostics': {
        'Diagnostic': ({'code': 'str', 'severity': 'Severity', 'message': 'str', 'span': 'Span', 'path': 'str', 'param_id': 'str | None', 'fix': 'Fix | None', 'hint': 'str | None', 'related': 'tuple[Related, ...]', 'kernel_error': 'str | None', 'consequence': 'str | None', 'source': 'str | None'}, (True, True, False, False), ('path', 'param_id', 'fix', 'hint', 'related', 'kernel_error', 'consequence', 'source'), ((3, (True, False, True, False)), (4, (True, False, True, False)), (6, (True, False, True, False)), (7, (True, False, True, False))), ('code', 'severity', 'message', 'span'), ('code', 'severity', 'message', 'span', 'path', 'param_id', 'fix', 'hint', 'related', 'kernel_error', 'consequence', 'source'), ('code', 'severity', 'message', 'span', 'path', 'param_id', 'fix', 'hint', 'related', 'kernel_error', 'consequence', 'source'), ('code', 'severity', 'message', 'span', 'path', 'param_id', 'fix', 'kernel_error'), _4),
        'Edit': ({'span': 'Span', 'replacement': 'str'}, (True, True, False, False), (), (), ('span', 'replacement'), ('span', 'replacement'), ('span', 'replacement'), ('span', 'replacement'), _1),
        'Fix': ({'title': 'str', 'edits': 'tuple[Edit, ...]', 'safe': 'bool'}, (True, True, False, False), ('edits', 'safe'), (), ('title',), ('title', 'edits', 'safe'), ('title', 'edits', 'safe'), ('title', 'edits', 'safe'), _2),
        'Related': ({'span': 'Span', 'message': 'str', 'path': 'str | None'}, (True, True, False, False), ('path',), (), ('span', 'message'), ('span', 'message', 'path'), ('span', 'message', 'path'), ('span', 'message', 'path'), _3),
        'Span': ({'line': 'int', 'column': 'int', 'end_line': 'int', 'end_column': 'int'}, (True, True, False, False), (), (), ('line', 'column', 'end_line', 'end_column'), ('line', 'column', 'end_line', 'end_column'), ('line', 'column', 'end_line', 'end_column'), ('line', 'column', 'end_line', 'end_column'), _0),
    },
    'zero.engine.commands': {
        'Echo': ({'out': 'Callable[[str], None]', 'err': 'Callable[[str], None]', 'out_bytes': 'Callable[[bytes], None]'}, (False, True, False, False), (), (), ('out', 'err', 'out_bytes'), ('out', 'err', 'out_bytes'), ('out', 'err', 'out_bytes'), ('out', 'err', 'out_bytes'), _38),
        'LintRequest': ({'paths': 'Sequence[str]', 'select': 'Sequence[str]', 'ignore': 'Sequence[str]', 'kind': 'str | None', 'param_desc': 'FileName | None', 'jobs': 'int | None', 'config': 'FileName | Sequence[str] | None', 'isolated': 'bool', 'fix': 'bool', 'show_diff': 'bool', 'unsafe_fixes': 'bool', 'stdin_filename': 'str | None', 'machine': 'FileName | None', 'extend_select': 'Sequence[str]', 'add_noqa': 'bool', 'force_exclude': 'bool', 'ignore_noqa': 'bool', 'stream': 'bool', 'cache': 'bool'}, (False, True, False, False), ('paths', 'select', 'ignore', 'kind', 'param_desc', 'jobs', 'config', 'isolated', 'fix', 'show_diff', 'unsafe_fixes', 'stdin_filename', 'machine', 'extend_select', 'add_noqa', 'force_exclude', 'ignore_noqa', 'stream', 'cache'), (), (), ('paths', 'select', 'ignore', 'kind', 'param_desc', 'jobs', 'config', 'isolated', 'fix', 'show_diff', 'unsafe_fixes', 'stdin_filename', 'machine', 'extend_select', 'add_noqa', 'force_exclude', 'ignore_noqa', 'stream', 'cache'), ('paths', 'select', 'ignore', 'kind', 'param_desc', 'jobs', 'config', 'isolated', 'fix', 'show_diff', 'unsafe_fixes', 'stdin_filename', 'machine', 'extend_select', 'add_noqa', 'force_exclude', 'ignore_noqa', 'stream', 'cache'), ('paths', 'select', 'ignore', 'kind', 'param_desc', 'jobs', 'config', 'isolated', 'fix', 'show_diff', 'unsafe_fixes', 'stdin_filename', 'machine', 'extend_select', 'add_noqa', 'force_exclude', 'ignore_noqa', 'stream', 'cache'), _39),
        'LintRun': ({'results': 'Iterable[LintResult]', 'report': 'bool', 'findings_to_stderr': 'bool', 'changed': 'int', 'fixed': 'list[tuple[str, dict[str, int]]]'}, (False, True, False, False), ('results', 'report', 'findings_to_stderr', 'changed', 'fixed'), ((0, (False, True, True, True)), (4, (False, True, True, True))), (), ('results', 'report', 'findings_to_stderr', 'changed', 'fixed'), ('results', 'report', 'findings_to_stderr', 'changed', 'fixed'), ('results', 'report', 'findings_to_stderr', 'changed', 'fixed'), _40),
    },
    'zero.engine.config': {
        'Config': ({'path': 'str | None', 'select': 'tuple[str, ...]', 'extend_select': 'tuple[str, ...]', 'ignore': 'tuple[str, ...]', 'per_file_ignores': 'tuple[tuple[str, tuple[str, ...]], ...]', 'severity': 'dict[str, Severity]', 'kind': 'tuple[tuple[str, str], ...]', 'encoding': 'tuple[tuple[str, str], ...]', 'include': 'tuple[str, ...]', 'exclude': 'tuple[str, ...]', 'param_desc': 'Path | None', 'kernel': 'str | None', 'machine': 'Path | None', 'machine_lists': 'dict[str, Path]', 'machine_workdir': 'Path | None', 'machine_roots': 'tuple[tuple[str, Path], ...]', 'extend_exclude': 'tuple[str, ...]', 'extend_per_file_ignores': 'tuple[tuple[str, tuple[str, ...]], ...]', 'respect_gitignore': 'bool', 'parent': 'Config | None', 'given': 'frozenset[str]'}, (False, True, False, False), ('path', 'select', 'extend_select', 'ignore', 'per_file_ignores', 'severity', 'kind', 'encoding', 'include', 'exclude', 'param_desc', 'kernel', 'machine', 'machine_lists', 'machine_workdir', 'machine_roots', 'extend_exclude', 'extend_per_file_ignores', 'respect_gitignore', 'parent', 'given'), ((5, (False, True, True, True)), (13, (False, True, True, True))), (), ('path', 'select', 'extend_select', 'ignore', 'per_file_ignores', 'severity', 'kind', 'encoding', 'include', 'exclude', 'param_desc', 'kernel', 'machine', 'machine_lists', 'machine_workdir', 'machine_roots', 'extend_exclude', 'extend_per_file_ignores', 'respect_gitignore', 'parent', 'given'), ('path', 'select', 'extend_select', 'ignore', 'per_file_ignores', 'severity', 'kind', 'encoding', 'include', 'exclude', 'param_desc', 'kernel', 'machine', 'machine_lists', 'machine_workdir', 'machine_roots', 'extend_exclude', 'extend_per_file_ignores', 'respect_gitignore', 'parent', 'given'), ('path', 'select', 'extend_select', 'ignore', 'per_file_ignores', 'severity', 'kind', 'encoding', 'include', 'exclude', 'param_desc', 'kernel', 'machine', 'machine_lists', 'machine_workdir', 'machine_roots', 'extend_exclude', 'extend_per_file_ignores', 'respect_gitignore', 'parent', 'given'), _35),
    },
    'zero.engine.project': {
        'Common': ({'config': 'tuple[str, ...]', 'isolated': 'bool', 'param_desc': 'str | Path | None', 'kernel': 'str | None'}, (True, True, False, False), ('config', 'isolated', 'param_desc', 'kernel'), (), (), ('config', 'isolated', 'param_desc', 'kernel'), ('config', 'isolated', 'param_desc', 'kernel'), ('config', 'isolated', 'param_desc', 'kernel'), _36),
        'Settings': ({'path': 'FileName | None', 'config': 'Config', 'options': 'LintOptions', 'param_desc': 'str | Path | None', 'project': 'Project'}, (True, False, False, False), ('project',), ((0, (False, False, False, True)),), ('path', 'config', 'options', 'param_desc'), ('path', 'config', 'options', 'param_desc', 'project'), ('path', 'config', 'options', 'param_desc'), ('path', 'config', 'options', 'param_desc', 'project'), _37),
    },
    'zero.engine.results': {
        'LintOptions': ({'select': 'tuple[str, ...]', 'ignore': 'tuple[str, ...]', 'kind': 'str | None', 'severity': 'dict[str, Severity]', 'extend_select': 'tuple[str, ...]', 'encoding': 'str | None', 'kernel': 'str | None', 'ignore_noqa': 'bool'}, (False, True, False, False), ('select', 'ignore', 'kind', 'severity', 'extend_select', 'encoding', 'kernel', 'ignore_noqa'), ((3, (False, True, True, True)),), (), ('select', 'ignore', 'kind', 'severity', 'extend_select', 'encoding', 'kernel', 'ignore_noqa'), ('select', 'ignore', 'kind', 'severity', 'extend_select', 'encoding', 'kernel', 'ignore_noqa'), ('select', 'ignore', 'kind', 'severity', 'extend_select', 'encoding', 'kernel', 'ignore_noqa'), _30),
        'LintResult': ({'path': 'str', 'document': 'Document', 'kind': 'str | None', 'diagnostics': 'list[Diagnostic]', 'note': 'str | None'}, (False, True, False, False), ('diagnostics', 'note'), ((0, (False, True, True, True)),), ('path', 'document', 'kind'), ('path', 'document', 'kind', 'diagnostics', 'note'), ('path', 'document', 'kind', 'diagnostics', 'note'), ('path', 'document', 'kind', 'diagnostics', 'note'), _31),
        'Totals': ({'files': 'int', 'clean': 'int', 'unreadable': 'int', 'by_severity': 'dict[Severity, int]', 'by_code': 'dict[str, int]', 'worst': 'Severity | None'}, (False, True, False, False), ('files', 'clean', 'unreadable', 'by_severity', 'by_code', 'worst'), ((3, (False, True, True, True)), (4, (False, True, True, True))), (), ('files', 'clean', 'unreadable', 'by_severity', 'by_code', 'worst'), ('files', 'clean', 'unreadable', 'by_severity', 'by_code', 'worst'), ('files', 'clean', 'unreadable', 'by_severity', 'by_code', 'worst'), _32),
    },
    'zero.lists.model': {
        'Blank': ({'line': 'int'}, (False, False, False, False), (), (), ('line',), ('line',), ('line',), ('line',), _18),
        'Comment': ({'line': 'int', 'text': 'str', 'commented_out': 'Entry | None'}, (False, False, False, False), ('commented_out',), (), ('line', 'text'), ('line', 'text', 'commented_out'), ('line', 'text', 'commented_out'), ('line', 'text', 'commented_out'), _17),
        'End': ({'line': 'int', 'start': 'int'}, (False, False, False, False), (), (), ('line', 'start'), ('line', 'start'), ('line', 'start'), ('line', 'start'), _19),
        'Entry': ({'line': 'int', 'key_raw': 'str', 'key_text': 'str', 'key': 'Key | None', 'key_start': 'int', 'key_end': 'int', 'value': 'str', 'value_kind': 'ValueKind | None', 'value_start': 'int', 'value_end': 'int', 'comment': 'str | None', 'comment_start': 'int', 'comment_style': 'CommentStyle | None', 'annotation': 'str | None', 'annotation_start': 'int', 'after_end': 'bool'}, (False, False, False, False), ('comment', 'comment_start', 'comment_style', 'annotation', 'annotation_start', 'after_end'), (), ('line', 'key_raw', 'key_text', 'key', 'key_start', 'key_end', 'value', 'value_kind', 'value_start', 'value_end'), ('line', 'key_raw', 'key_text', 'key', 'key_start', 'key_end', 'value', 'value_kind', 'value_start', 'value_end', 'comment', 'comment_start', 'comment_style', 'annotation', 'annotation_start', 'after_end'), ('line', 'key_raw', 'key_text', 'key', 'key_start', 'key_end', 'value', 'value_kind', 'value_start', 'value_end', 'comment', 'comment_start', 'comment_style', 'annotation', 'annotation_start', 'after_end'), ('line', 'key_raw', 'key_text', 'key', 'key_start', 'key_end', 'value', 'value_kind', 'value_start', 'value_end', 'comment', 'comment_start', 'comment_style', 'annotation', 'annotation_start', 'after_end'), _16),
        'Invalid': ({'line': 'int', 'text': 'str'}, (False, False, False, False), (), (), ('line', 'text'), ('line', 'text'), ('line', 'text'), ('line', 'text'), _20),
        'Key': ({'text': 'str', 'pattern': 'str', 'indices': 'tuple[int, ...]'}, (False, True, True, False), (), (), ('text', 'pattern', 'indices'), ('text', 'pattern', 'indices'), ('text', 'pattern', 'indices'), ('text', 'pattern', 'indices'), _15),
        'Origin': ({'form': 'str', 'source': 'list[str]', 'shift': 'dict[int, tuple[int, int, tuple[int, int, int, int, int] | None]]', 'final_newline': 'bool', 'kind': 'str | None', 'update': 'bool', 'default_list': 'bool'}, (False, False, False, False), ('final_newline', 'kind', 'update', 'default_list'), (), ('form', 'source', 'shift'), ('form', 'source', 'shift', 'final_newline', 'kind', 'update', 'default_list'), ('form', 'source', 'shift', 'final_newline', 'kind', 'update', 'default_list'), ('form', 'source', 'shift', 'final_newline', 'kind', 'update', 'default_list'), _22),
        'Problem': ({'kind': 'str', 'line': 'int', 'start': 'int', 'end': 'int', 'detail': 'str'}, (True, True, False, False), ('detail',), (), ('kind', 'line', 'start', 'end'), ('kind', 'line', 'start', 'end', 'detail'), ('kind', 'line', 'start', 'end', 'detail'), ('kind', 'line', 'start', 'end', 'detail'), _21),
        'Shape': ({'head': 'str', 'tail': 'str', 'pattern': 'int', 'indices': 'tuple[int, ...]', 'indexed': 'bool'}, (False, False, False, False), (), (), ('head', 'tail', 'pattern', 'indices', 'indexed'), ('head', 'tail', 'pattern', 'indices', 'indexed'), ('head', 'tail', 'pattern', 'indices', 'indexed'), ('head', 'tail', 'pattern', 'indices', 'indexed'), _23),
    },
    'zero.output.formats': {
        'Format': ({'name': 'str', 'module': 'str | None', 'function': 'str', 'note': 'str', 'streamed': 'bool', 'fail_on': 'bool', 'json_statistics': 'bool', 'aliases': 'tuple[str, ...]'}, (True, True, False, False), ('streamed', 'fail_on', 'json_statistics', 'aliases'), (), ('name', 'module', 'function', 'note'), ('name', 'module', 'function', 'note', 'streamed', 'fail_on', 'json_statistics', 'aliases'), ('name', 'module', 'function', 'note', 'streamed', 'fail_on', 'json_statistics', 'aliases'), ('name', 'module', 'function', 'note', 'streamed', 'fail_on', 'json_statistics', 'aliases'), _33),
    },
    'zero.rules.base': {
        'Check': ({'codes': 'tuple[str, ...]', 'run': 'Callable[[C], Iterator[Diagnostic | str]]'}, (True, True, False, False), (), (), ('codes', 'run'), ('codes', 'run'), ('codes', 'run'), ('codes', 'run'), _44),
        'MachineContext': ({'machine': 'Machine', 'registry': 'Registry', 'severities': 'dict[str, Severity]', 'path': 'str'}, (False, True, False, False), ('severities', 'path'), ((0, (False, True, True, True)),), ('machine', 'registry'), ('machine', 'registry', 'severities', 'path'), ('machine', 'registry', 'severities', 'path'), ('machine', 'registry', 'severities', 'path'), _42),
        'ProgramContext': ({'program': 'Program', 'registry': 'Registry', 'machine': 'Machine | None', 'severities': 'dict[str, Severity]', 'path': 'str'}, (False, True, False, False), ('machine', 'severities', 'path'), ((1, (False, True, True, True)),), ('program', 'registry'), ('program', 'registry', 'machine', 'severities', 'path'), ('program', 'registry', 'machine', 'severities', 'path'), ('program', 'registry', 'machine', 'severities', 'path'), _43),
        'Rule': ({'code': 'str', 'name': 'str', 'severity': 'Severity', 'summary': 'str', 'explanation': 'str', 'scope': 'Scope', 'opt_in': 'bool', 'reads': 'tuple[str, ...]'}, (True, True, False, False), ('scope', 'opt_in', 'reads'), (), ('code', 'name', 'severity', 'summary', 'explanation'), ('code', 'name', 'severity', 'summary', 'explanation', 'scope', 'opt_in', 'reads'), ('code', 'name', 'severity', 'summary', 'explanation', 'scope', 'opt_in', 'reads'), ('code', 'name', 'severity', 'summary', 'explanation', 'scope', 'opt_in', 'reads'), _41),
    },
    'zero.rules.startup': {
        'StartupError': ({'code': 'str', 'number': 'int', 'kind': 'str', 'params': 'tuple[str, ...]', 'condition_text': 'str', 'when_text': 'str', 'correction': 'str', 'title': 'str', 'source': 'str', 'written': 'bool', 'reported': 'str'}, (True, True, False, False), ('written', 'reported'), (), ('code', 'number', 'kind', 'params', 'condition_text', 'when_text', 'correction', 'title', 'source'), ('code', 'number', 'kind', 'params', 'condition_text', 'when_text', 'correction', 'title', 'source', 'written', 'reported'), ('code', 'number', 'kind', 'params', 'condition_text', 'when_text', 'correction', 'title', 'source', 'written', 'reported'), ('code', 'number', 'kind', 'params', 'condition_text', 'when_text', 'correction', 'title', 'source', 'written', 'reported'), _45),
        '_Compiled': ({'condition': 'Compiled', 'when': 'Compiled | None', 'read': 'tuple[str, ...]', 'shown': 'tuple[tuple[str, int | None], ...]'}, (True, True, False, False), (), (), ('condition', 'when', 'read', 'shown'), ('condition', 'when', 'read', 'shown'), ('condition', 'when', 'read', 'shown'), ('condition', 'when', 'read', 'shown'), _46),
    },
    'zero.rules.suppress': {
        'Directive': ({'line': 'int', 'start': 'int', 'end': 'int', 'codes': 'tuple[str, ...] | None', 'scope': 'str', 'target': 'int | None', 'used': 'set[str]'}, (False, False, False, False), ('target', 'used'), ((1, (False, True, True, True)),), ('line', 'start', 'end', 'codes', 'scope'), ('line', 'start', 'end', 'codes', 'scope', 'target', 'used'), ('line', 'start', 'end', 'codes', 'scope', 'target', 'used'), ('line', 'start', 'end', 'codes', 'scope', 'target', 'used'), _47),
    },
}
# the modules whose records are in record_inits_rest
REST_MODULES = frozenset(('zero.diff', 'zero.engine.baseline', 'zero.engine.config_file', 'zero.engine.convert', 'zero.engine.fixes', 'zero.engine.fleet', 'zero.engine.formatting', 'zero.engine.git', 'zero.engine.queries', 'zero.engine.report', 'zero.machine.effective', 'zero.machine.limits', 'zero.machine.model', 'zero.machine.tsproj', 'zero.markup.documents', 'zero.markup.safe', 'zero.markup.tsproj', 'zero.nc.motion', 'zero.nc.program', 'zero.output.docs', 'zero.output.report', 'zero.output.svg', 'zero.rules.program', 'zero.server.documents', 'zero.server.hover', 'zero.server.outline', 'zero.server.settings', 'zero.structured.common', 'zero.structured.tree'))
del __init__
