"""Record classes: the part of :mod:`dataclasses` zero uses, built without importing it.

``dataclasses`` imports :mod:`inspect` (and with it ``ast``, ``dis`` and ``tokenize``: about
10 ms) and compiles each method of each class. ``zero lint`` declares some forty records
before it reads the first line, so a pre-commit run spent a third of its start-up there.
A record is declared as a class naming :class:`Record` among its bases, ``class Span(Record,
frozen=True):``, which makes the record of the class statement's body in one step; the
:func:`record` decorator (``@record(frozen=True)``) makes the same record of a class already made,
a second class (what zero's ``Rule`` needs: its K subclass is a plain class). Only ``__init__`` is
written per record (it must be as fast as a dataclass's: a big list builds one record per line);
``__repr__``, ``__eq__`` and ``__hash__`` are shared by all records.
For the records of zero, what the fields are and their ``__init__`` compiled are worked out ahead
of time (:mod:`zero.record_inits`, by ``tools/gen_record_inits.py``): declaring one checks that the
table still describes the class and takes the rest from there. Any other record (a test's, or one
with a record base) is worked out as it is declared, its ``__init__`` compiled at its first
instance. Both are marked ``dataclass_transform``, so type checkers read a record exactly as they
read a dataclass (a subclass of a Record is a record to them; at run time it is one where it names
``Record`` too, as a subclass of a decorated class is one where it is decorated).

What it builds, as ``@dataclass(slots=True, ...)`` does: ``__slots__`` (always),
``__init__`` (calling ``__post_init__`` when the class has one), ``__repr__``, ``__eq__``
(``eq=True``) over the fields that compare, ``__hash__`` (``frozen`` or ``unsafe_hash``;
``None`` for a mutable record that compares), ``__setattr__``/``__delattr__`` refusing
assignment with ``AttributeError`` (``frozen``, with pickle support), and
``__match_args__``. A method the class writes itself is kept. Fields of record base classes
come first, in order, as in dataclasses. :func:`replace` and :func:`fields` work on records.
"""

from __future__ import annotations

from collections.abc import Callable
from operator import attrgetter
from types import FunctionType

from zero.hints import dataclass_transform, overload
from zero.record_inits import INITS, RECORDS, REST_MODULES

__all__ = ["Field", "Record", "field", "fields", "record", "replace"]

# typing is imported for type checkers only (zero.hints: `overload` and `dataclass_transform` at run time)
TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from types import MappingProxyType
    from typing import Any, TypeVar

    _T = TypeVar("_T")
_FIELDS = "__record_fields__"


class _Missing:
    __slots__ = ()

    def __repr__(self) -> str:
        return "MISSING"


MISSING: Any = _Missing()


class Field:
    """A field's declaration: its default (or factory) and whether it shows and compares."""

    __slots__ = ("compare", "default", "default_factory", "name", "repr")

    def __init__(self, default: Any = MISSING, default_factory: Any = MISSING, repr: bool = True,
                 compare: bool = True) -> None:
        self.name = ""
        self.default = default
        self.default_factory = default_factory
        self.repr = repr
        self.compare = compare

    @property
    def required(self) -> bool:
        return self.default is MISSING and self.default_factory is MISSING

    def __repr__(self) -> str:
        return f"Field(name={self.name!r}, default={self.default!r}, factory={self.default_factory!r})"


@overload
def field(*, default: _T, repr: bool = ..., compare: bool = ...) -> _T: ...
@overload
def field(*, default_factory: Callable[[], _T], repr: bool = ..., compare: bool = ...) -> _T: ...
@overload
def field(*, repr: bool = ..., compare: bool = ...) -> Any: ...
def field(*, default: Any = MISSING, default_factory: Any = MISSING, repr: bool = True,
          compare: bool = True) -> Any:
    """A field with a default, a default factory, or one that does not show or compare."""
    if default is not MISSING and default_factory is not MISSING:
        raise ValueError("a field cannot have both a default and a default factory")
    return Field(default, default_factory, repr, compare)


def fields(obj_or_cls: Any) -> tuple[Field, ...]:
    """The fields of a record (class or instance), in ``__init__`` order."""
    got: tuple[Field, ...] | None = getattr(obj_or_cls, _FIELDS, None)
    if got is None:
        raise TypeError(f"{obj_or_cls!r} is no record")
    return got


def replace(obj: _T, /, **changes: Any) -> _T:
    """A copy of the record ``obj`` with ``changes`` applied, built through ``__init__``."""
    for f in fields(obj):
        if f.name not in changes:
            changes[f.name] = getattr(obj, f.name)
    return obj.__class__(**changes)


def _is_classvar(annotation: object) -> bool:
    text = annotation if isinstance(annotation, str) else getattr(annotation, "_name", "") or ""
    return text.startswith(("ClassVar", "typing.ClassVar"))


_CLASSVAR = ("ClassVar", "typing.ClassVar")


def _frozen_setattr(self: Any, name: str, value: Any) -> None:
    """``__setattr__`` of a frozen record: refuses its fields (and, on the record itself, any name)."""
    cls = self.__class__
    if "__record_frozen__" in cls.__dict__ or name in cls.__record_names__:
        raise AttributeError(f"cannot assign to field {name!r} of a frozen record")
    object.__setattr__(self, name, value)


def _frozen_delattr(self: Any, name: str) -> None:
    cls = self.__class__
    if "__record_frozen__" in cls.__dict__ or name in cls.__record_names__:
        raise AttributeError(f"cannot delete field {name!r} of a frozen record")
    object.__delattr__(self, name)


def _frozen_getstate(self: Any) -> tuple[Any, ...]:
    return tuple(getattr(self, f.name) for f in fields(self))


def _frozen_setstate(self: Any, state: tuple[Any, ...]) -> None:
    for f, value in zip(fields(self), state, strict=True):
        object.__setattr__(self, f.name, value)


# ``__repr__``, ``__eq__`` and ``__hash__`` are shared by every record and read what they need from the
# class (``__record_shown__``, ``__record_key__``): making them per class, as closures or compiled as
# dataclasses does, was most of what declaring a record cost at start-up (issue 40).
def _record_repr(self: Any) -> str:
    inner = ", ".join(f"{name}={getattr(self, name)!r}" for name in self.__record_shown__)
    return f"{self.__class__.__qualname__}({inner})"


def _record_eq(self: Any, other: object) -> bool:
    values = self.__record_key__
    if other.__class__ is self.__class__:
        return bool(values(self) == values(other))
    return NotImplemented  # type: ignore[no-any-return]  # (mypy allows it only in a method named __eq__)


def _record_hash(self: Any) -> int:
    return hash(self.__record_key__(self))


def _no_values(_: object) -> tuple[()]:
    return ()


_NO_VALUES = staticmethod(_no_values)  # a record comparing no field (a plain function would bind to self)


_SCOPE: dict[str, Any] = {"MISSING": MISSING, "__set": object.__setattr__}  # an __init__'s globals: no factory


class _LazyFields(tuple):  # type: ignore[type-arg]  # (Any is for type checkers only)
    """A listed record's ``__record_fields__`` until first read, ``(names, valued, values)`` (the table's
    names and those of the fields with values, the values the class body gave): then its :class:`Field`
    tuple, put in its place. Made by ``tuple`` (no ``__init__`` to run: declaring a record stays cheap);
    a run reads the fields of few records."""

    __slots__ = ()

    def __get__(self, obj: object, objtype: type | None = None) -> tuple[Field, ...]:
        names, valued, values = self
        given = dict(zip(valued, values, strict=True))
        made: list[Field] = []
        for name in names:
            declared = given.get(name, MISSING)
            f = declared if declared.__class__ is Field else Field(declared)
            f.name = name
            made.append(f)
        out = tuple(made)
        for owner in (objtype or obj.__class__).__mro__:
            if owner.__dict__.get(_FIELDS) is self:
                type.__setattr__(owner, _FIELDS, out)
                break
        return out


class _Shell:
    """What a record is made from: its name, module and qualified name, the classes its MRO will hold
    between it and ``object`` (less :class:`Record`), and its class body (``ns``: the class's dict, or
    the namespace its class statement built)."""

    __slots__ = ("ancestors", "module", "name", "ns", "qualname")

    def __init__(self, name: str, qualname: str, module: str, ancestors: tuple[type, ...],
                 ns: dict[str, Any] | MappingProxyType[str, Any]) -> None:
        self.name, self.qualname, self.module, self.ancestors, self.ns = name, qualname, module, ancestors, ns


def _body(shell: _Shell, frozen: bool, eq: bool, unsafe_hash: bool) -> tuple[dict[str, Any], list[type] | None]:
    """The body of the record ``shell`` describes, from what ``tools/gen_record_inits.py`` worked out ahead of
    time for it, kept in :mod:`zero.record_inits` (or ``record_inits_rest``) by module and qualified name,
    where that still describes the class (its own annotations, flags, which fields have values and of which
    kind); else by :func:`_body_slow`. Working fields, defaults and ``__init__`` out was most of declaring a
    record (issue 40). The list returned (the slow way only) is to hold the class made of the body."""
    module = shell.module
    listed = RECORDS.get(module)
    if listed is None:
        if module not in REST_MODULES:
            return _body_slow(shell, frozen, eq, unsafe_hash)
        from zero.record_inits_rest import RECORDS as rest  # start-up: the records a list's lint does not load

        listed = rest.get(module)
        if listed is None:
            return _body_slow(shell, frozen, eq, unsafe_hash)
    spec = listed.get(shell.qualname)
    ns = shell.ns
    if spec is None:
        return _body_slow(shell, frozen, eq, unsafe_hash)
    annotations, flags, valued, declared, without, names, shown, compared, code = spec
    bases = shell.ancestors
    post_init = "__post_init__" in ns
    if bases:
        for base in bases:
            if _FIELDS in base.__dict__:  # fields of a record base: worked out as it is
                return _body_slow(shell, frozen, eq, unsafe_hash)
        post_init = post_init or any(hasattr(b, "__post_init__") for b in bases)
    if (ns.get("__annotations__") != annotations or flags != (frozen, eq, unsafe_hash, post_init)
            or not ns.keys().isdisjoint(without)):
        return _body_slow(shell, frozen, eq, unsafe_hash)
    body = ns.copy()  # the class dict itself, copied (dict(ns) reads a mappingproxy key by key)
    try:
        values = list(map(body.pop, valued))  # the fields' values, out of the body
    except KeyError:  # a field the table says has one has none
        return _body_slow(shell, frozen, eq, unsafe_hash)
    scope = _SCOPE
    if list(map(type, values)).count(Field) != len(declared):  # not the fields the table says are field()s
        return _body_slow(shell, frozen, eq, unsafe_hash)
    defaults = values
    if declared:
        defaults = values.copy()
        required = False
        for at, kind in declared:
            f = values[at]
            if f.__class__ is not Field or kind != (f.default is not MISSING, f.default_factory is not MISSING,
                                                     f.repr, f.compare):
                return _body_slow(shell, frozen, eq, unsafe_hash)
            if kind[1]:
                if scope is _SCOPE:
                    scope = dict(_SCOPE)
                scope["__factory_" + valued[at]] = f.default_factory
                defaults[at] = MISSING  # what the table's __init__ takes for "not given"
            elif kind[0]:
                defaults[at] = f.default
            else:  # a field() with neither: a parameter without a default
                defaults[at] = _Missing
                required = True
        if required:
            defaults = [d for d in defaults if d is not _Missing]
    init = ns.get("__init__") or FunctionType(code, scope, "__init__", tuple(defaults) or None)
    return _finish(shell, body, names, _LazyFields((names, valued, values)), init, shown, compared, frozen, eq,
                   unsafe_hash), None


def _finish(shell: _Shell, body: dict[str, Any], names: tuple[str, ...], fields: Any, init: Any,
            shown: tuple[str, ...], compared: tuple[str, ...], frozen: bool, eq: bool,
            unsafe_hash: bool) -> dict[str, Any]:
    """The record's ``body`` completed: its slots, fields, ``__init__`` and the shared methods, each where
    the class does not define its own (both ways of working a record out end here)."""
    ns = shell.ns
    bases = shell.ancestors
    body.pop("__dict__", None)
    body.pop("__weakref__", None)
    if bases:
        inherited = {s for base in bases for s in base.__dict__.get("__slots__", ())}
        body["__slots__"] = tuple(n for n in names if n not in inherited)
    else:
        body["__slots__"] = names
    body[_FIELDS] = fields
    body["__match_args__"] = names
    body["__init__"] = init
    body["__record_shown__"] = shown
    if "__repr__" not in ns:
        body["__repr__"] = _record_repr
    explicit_hash = "__hash__" in ns and not (ns["__hash__"] is None and "__eq__" in ns)
    hashed = not explicit_hash and (unsafe_hash or (eq and frozen))
    if eq or hashed:
        body["__record_key__"] = attrgetter(*compared) if compared else _NO_VALUES
    if eq and "__eq__" not in ns:
        body["__eq__"] = _record_eq
    if hashed:
        body["__hash__"] = _record_hash
    elif eq and not explicit_hash:
        body["__hash__"] = None
    if frozen:
        # in the body, not set on the class made: assigning a special method to a class updates its slots again
        if "__getstate__" not in ns:
            body["__getstate__"] = _frozen_getstate
        if "__setstate__" not in ns:
            body["__setstate__"] = _frozen_setstate
        if "__setattr__" not in ns:
            body["__setattr__"] = _frozen_setattr
        if "__delattr__" not in ns:
            body["__delattr__"] = _frozen_delattr
        body["__record_frozen__"] = True
        body["__record_names__"] = frozenset(names)
    body["__qualname__"] = shell.qualname
    return body


def _own_fields(cls: type) -> tuple[Field, ...]:
    """The fields ``cls`` itself holds (none for a class that is no record)."""
    got = cls.__dict__.get(_FIELDS, ())
    return got.__get__(None, cls) if got.__class__ is _LazyFields else got


def _body_slow(shell: _Shell, frozen: bool, eq: bool, unsafe_hash: bool) -> tuple[dict[str, Any], list[type]]:
    # The class's own annotations (strings: every zero module imports annotations from __future__;
    # 3.10 and later answer for the class alone); inspect is what this module avoids.
    ns = shell.ns
    own: dict[str, Any] = ns.get("__annotations__") or {}
    declared_here = [name for name, annotation in own.items()
                     if not (annotation.startswith(_CLASSVAR) if annotation.__class__ is str
                             else _is_classvar(annotation))]
    bases = shell.ancestors
    body = ns.copy()  # the class dict itself, copied (dict(ns) reads a mappingproxy key by key)
    if any(_FIELDS in base.__dict__ for base in bases):
        by_name: dict[str, Field] = {}
        for base in reversed(bases):
            for f in _own_fields(base):
                by_name[f.name] = f
    else:
        by_name = {}
    for name in declared_here:
        declared = body.pop(name, MISSING)
        f = declared if declared.__class__ is Field else Field(declared)
        f.name = name
        by_name.pop(name, None)
        by_name[name] = f
    all_fields = tuple(by_name.values())
    names = tuple(by_name)
    seen_default = False
    for f in all_fields:
        if f.default is MISSING and f.default_factory is MISSING:
            if seen_default:
                raise TypeError(f"{shell.name}: field {f.name!r} without a default follows one with a default")
        else:
            seen_default = True

    owner: list[type] = []  # the class made of the body, whose __init__ the first call makes
    post_init = "__post_init__" in body or any(hasattr(b, "__post_init__") for b in bases)
    init = ns.get("__init__") or _first_init(all_fields, frozen, post_init, owner)
    return _finish(shell, body, names, all_fields, init, tuple(f.name for f in all_fields if f.repr),
                   tuple(f.name for f in all_fields if f.compare), frozen, eq, unsafe_hash), owner


def _build(cls: type, frozen: bool, eq: bool, unsafe_hash: bool) -> type:
    """``cls`` made a record (``@record``): a second class, made of its body with slots."""
    shell = _Shell(cls.__name__, cls.__qualname__, cls.__module__, cls.__mro__[1:-1], cls.__dict__)
    body, owner = _body(shell, frozen, eq, unsafe_hash)
    made: type = type(cls)(cls.__name__, cls.__bases__, body)
    if owner is not None:
        owner.append(made)
    return made


def _linearized(bases: tuple[type, ...]) -> list[type]:
    """The MRO a class with ``bases`` gets, less the class itself (C3, as ``type`` works it out)."""
    seqs = [list(b.__mro__) for b in bases] + [list(bases)]
    out: list[type] = []
    while True:
        seqs = [q for q in seqs if q]
        if not seqs:
            return out
        for q in seqs:
            head = q[0]
            if not any(head in other[1:] for other in seqs):
                break
        else:
            raise TypeError(f"no consistent method resolution order for bases {bases}")
        out.append(head)
        for q in seqs:
            if q[0] is head:
                del q[0]


@dataclass_transform(field_specifiers=(field, Field))
class _RecordMeta(type):
    """The class of :class:`Record` alone: a class statement naming ``Record`` among its bases makes a record of
    its body in one step (a decorator is handed a class already made and has to make a second one with slots:
    issue 40, start-up). The record made is a plain class, ``Record`` left out of its bases: a class of another
    metaclass would make every ``isinstance`` with it take Python's slow way (``__instancecheck__``). A
    subclass of a record is thus a record only where it names ``Record`` too, as with ``@record``."""

    def __new__(mcls, name: str, bases: tuple[type, ...], ns: dict[str, Any], *, frozen: bool = False,
                eq: bool = True, unsafe_hash: bool = False) -> _RecordMeta:
        if not bases:  # Record itself
            return super().__new__(mcls, name, bases, ns)
        real = tuple(b for b in bases if b is not Record)
        ancestors = (real[0].__mro__[:-1] if len(real) == 1
                     else tuple(c for c in _linearized(real) if c is not object))
        shell = _Shell(name, ns.get("__qualname__", name), ns.get("__module__", ""), ancestors, ns)
        body, owner = _body(shell, frozen, eq, unsafe_hash)
        made: _RecordMeta = type.__new__(type, name, real, body)  # type: ignore[assignment]
        if owner is not None:
            owner.append(made)
        return made


class Record(metaclass=_RecordMeta):
    """Names a record: ``class Span(Record, frozen=True):`` with fields as annotations, as
    ``@dataclass(slots=True, frozen=True)`` reads them (``frozen``, ``eq`` and ``unsafe_hash`` as there).
    The record is made in one step (the class statement's body made a record before the class is), a plain
    class with slots: ``Record`` is not among its bases once made."""

    __slots__ = ()


def init_source(all_fields: tuple[Field, ...], frozen: bool, post_init: bool) -> tuple[str, dict[str, Any],
                                                                                      tuple[Any, ...]]:
    """A record's ``__init__`` as Python text, the globals it runs with (its defaults and factories by
    name) and its parameters' defaults in order (what the ``def`` line names)."""
    scope: dict[str, Any] = {"MISSING": MISSING, "__set": object.__setattr__}
    params: list[str] = []
    lines: list[str] = []
    defaults: list[Any] = []
    for f in all_fields:
        n = f.name
        if f.default_factory is not MISSING:
            scope[f"__factory_{n}"] = f.default_factory
            params.append(f"{n}=MISSING")
            defaults.append(MISSING)
            value = f"__factory_{n}() if {n} is MISSING else {n}"
        elif f.default is not MISSING:
            scope[f"__default_{n}"] = f.default
            params.append(f"{n}=__default_{n}")
            defaults.append(f.default)
            value = n
        else:
            params.append(n)
            value = n
        lines.append(f"    __set(self, {n!r}, {value})" if frozen else f"    self.{n} = {value}")
    if post_init:
        lines.append("    self.__post_init__()")
    source = "\n".join([f"def __init__(self, {', '.join(params)}) -> None:", *(lines or ["    pass"])])
    return source, scope, tuple(defaults)


def _compiled_init(source: str, scope: dict[str, Any], defaults: tuple[Any, ...]) -> Callable[..., None]:
    """The record's ``__init__``: from the code compiled ahead of time (:mod:`zero.record_inits`,
    written by ``tools/gen_record_inits.py`` and keyed by its text) with ``scope`` as its globals and
    ``defaults`` as its parameters' defaults, which is what executing ``source`` in ``scope`` makes; or,
    for a record that table does not hold (a test's, or a table not yet regenerated), by compiling
    ``source``. Compiling Python text is the costly part (some forty records a run: 5 ms of ``zero lint``)."""
    code = INITS.get(source)
    if code is None:
        from zero.record_inits_rest import INITS as rest  # start-up: the records a list's lint does not load

        code = rest.get(source)
    if code is not None:
        made: Callable[..., None] = FunctionType(code, scope, "__init__", defaults or None)
        scope["__init__"] = made
        return made
    exec(source, scope)  # the text is built from field names only
    init: Callable[..., None] = scope["__init__"]
    return init


def _first_init(all_fields: tuple[Field, ...], frozen: bool, post_init: bool,
                owner: list[type]) -> Callable[..., None]:
    """An ``__init__`` that makes the record's own at its first call and puts it in its place.

    Writing and making it is most of what declaring a record would cost, and a run instantiates fewer
    than half of the records it imports (``zero lint`` of one list: issue 40, start-up), so each is
    made when its class is first instantiated; from then on the class calls its own directly."""
    made: list[Callable[..., None]] = []

    def __init__(self: Any, *args: Any, **kwargs: Any) -> None:
        if not made:
            made.append(_compiled_init(*init_source(all_fields, frozen, post_init)))
        init = made[0]
        if owner[0].__dict__.get("__init__") is __init__:
            type.__setattr__(owner[0], "__init__", init)
        init(self, *args, **kwargs)

    return __init__


@overload
def record(cls: type[_T], /) -> type[_T]: ...
@overload
def record(*, frozen: bool = ..., eq: bool = ..., unsafe_hash: bool = ...) -> Callable[[type[_T]], type[_T]]: ...
@dataclass_transform(field_specifiers=(field, Field))
def record(cls: type[_T] | None = None, /, *, frozen: bool = False, eq: bool = True,
           unsafe_hash: bool = False) -> type[_T] | Callable[[type[_T]], type[_T]]:
    """Make ``cls`` a record with slots: ``@record`` or ``@record(frozen=True, ...)``."""
    def wrap(c: type[_T]) -> type[_T]:
        return _build(c, frozen, eq, unsafe_hash)

    return wrap if cls is None else wrap(cls)
