"""zero.records behaves as the dataclasses it replaces: each case is declared both ways and
compared, so a difference in semantics fails here rather than somewhere in a rule."""

from __future__ import annotations

import copy
import dataclasses
import pickle
import re
import subprocess
import sys
from pathlib import Path
from types import CodeType, FunctionType, ModuleType
from typing import Any, ClassVar

import pytest

from zero.records import field, fields, record, replace


@record
class Point:
    x: int
    y: int = 0
    tags: list[str] = field(default_factory=list)
    note: str | None = field(default=None, compare=False)
    hidden: int = field(default=0, repr=False)
    LIMIT: ClassVar[int] = 3


@dataclasses.dataclass(slots=True)
class PointDC:
    x: int
    y: int = 0
    tags: list[str] = dataclasses.field(default_factory=list)
    note: str | None = dataclasses.field(default=None, compare=False)
    hidden: int = dataclasses.field(default=0, repr=False)
    LIMIT: ClassVar[int] = 3


@record(frozen=True)
class Span:
    line: int
    column: int


@record(eq=False)
class Node:
    name: str


@record(unsafe_hash=True)
class Key:
    text: str
    indices: tuple[int, ...] = ()


@record
class Base:
    a: int
    b: int = 1


@record
class Child(Base):
    c: int = 2


@record
class Same(Base):
    """No field of its own: the base's fields, not its annotations read twice."""


@record
class Checked:
    low: int
    high: int
    width: int = 0

    def __post_init__(self) -> None:
        self.width = self.high - self.low


@record
class Custom:
    value: int

    def __repr__(self) -> str:
        return f"<{self.value}>"


def test_init_defaults_and_factories_as_dataclasses() -> None:
    ours, theirs = Point(1), PointDC(1)
    assert (ours.x, ours.y, ours.tags, ours.note, ours.hidden) == (theirs.x, theirs.y, theirs.tags, theirs.note,
                                                                     theirs.hidden)
    assert Point(1).tags is not Point(1).tags  # a fresh list each time
    assert Point(x=2, y=3, tags=["a"]).tags == ["a"]
    assert Point.LIMIT == 3 and "LIMIT" not in [f.name for f in fields(Point)]
    assert Point.__match_args__ == PointDC.__match_args__


def test_repr_and_equality_as_dataclasses() -> None:
    assert repr(Point(1, 2, ["t"], "n", 9)) == repr(PointDC(1, 2, ["t"], "n", 9)).replace("PointDC", "Point")
    assert Point(1, note="a") == Point(1, note="b")  # note does not compare
    assert Point(1) != Point(2)
    assert Point(1) != PointDC(1)  # type: ignore[comparison-overlap]  # another class never compares equal
    assert Point.__hash__ is None and PointDC.__hash__ is None  # mutable and compared: unhashable
    assert Node("a") != Node("a") and len({Node("a"), Node("a")}) == 2  # eq=False: identity
    assert Key("k", (1,)) == Key("k", (1,)) and len({Key("k", (1,)), Key("k", (1,))}) == 1
    assert repr(Custom(3)) == "<3>"  # a method the class writes is kept


def test_slots_and_no_dict() -> None:
    p = Point(1)
    assert not hasattr(p, "__dict__")
    with pytest.raises(AttributeError):
        p.other = 1  # type: ignore[attr-defined]


def test_frozen_refuses_assignment_hashes_and_pickles() -> None:
    s = Span(1, 2)
    with pytest.raises(AttributeError):
        s.line = 3  # type: ignore[misc]
    with pytest.raises(AttributeError):
        del s.line
    assert hash(s) == hash(Span(1, 2)) and {s: 1}[Span(1, 2)] == 1
    assert pickle.loads(pickle.dumps(s)) == s
    assert copy.deepcopy(s) == s and copy.copy(s) == s
    assert pickle.loads(pickle.dumps(Point(1, tags=["a"]))) == Point(1, tags=["a"])


def test_inheritance_post_init_and_replace() -> None:
    assert [f.name for f in fields(Child)] == ["a", "b", "c"]
    assert [f.name for f in fields(Same)] == ["a", "b"] and Same(1) == Same(1, 1) and Same(1) != Base(1)
    assert Child(5) == Child(5, 1, 2) and Child(5) != Base(5)
    assert repr(Child(5)) == "Child(a=5, b=1, c=2)"
    assert Checked(2, 7).width == 5
    moved = replace(Child(5), c=9)
    assert moved == Child(5, 1, 9)
    with pytest.raises(TypeError):
        fields(object())


def test_a_required_field_after_a_default_is_refused() -> None:
    with pytest.raises(TypeError, match="without a default"):
        @record
        class Bad:
            a: int = 0
            b: int  # type: ignore[misc]


def test_the_lint_path_imports_no_module_it_does_not_use() -> None:
    """Start-up: zero lint's import chain stays free of dataclasses and inspect (~10 ms), and of
    threading and signal (only a write needs them)."""
    code = ("import sys, zero.cli.lean, zero.cli.run, zero.engine.lint; print(sorted(m for m in "
            "('dataclasses', 'inspect', 'ast', 'threading', 'signal') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_init_is_compiled_at_the_first_instance_and_then_called_directly() -> None:
    @record
    class Late:
        a: int
        b: list[int] = field(default_factory=list)

    class Sub(Late):  # a plain subclass instantiated first compiles its record's __init__
        pass

    first = Late.__init__
    assert Sub(1).a == 1 and Late.__init__ is not first  # the compiled one took its place
    compiled = Late.__init__
    x, y = Late(2), Late(3, [4])
    assert (x.a, x.b, y.b) == (2, [], [4]) and x.b is not Late(5).b
    assert Late.__init__ is compiled and Sub.__init__ is compiled
    with pytest.raises(TypeError, match="missing 1 required positional argument: 'a'"):
        Late()  # type: ignore[call-arg]


ROOT = Path(__file__).resolve().parent.parent


def test_the_ahead_of_time_inits_are_current() -> None:
    """Run ``python tools/gen_record_inits.py`` after adding or changing a record's fields."""
    done = subprocess.run([sys.executable, str(ROOT / "tools" / "gen_record_inits.py"), "--check"],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stdout + done.stderr


def test_a_record_of_zero_takes_its_init_from_the_table_and_behaves_as_compiled() -> None:
    from zero.diagnostics import Span
    from zero.record_inits import RECORDS

    span = Span(3, 4, 3, 9)
    init = type(span).__init__
    assert init.__code__ is RECORDS["zero.diagnostics"]["Span"][-1]
    assert init.__code__.co_filename.endswith("record_inits.py")
    assert (span.line, span.column, span.end_line, span.end_column) == (3, 4, 3, 9)
    assert init.__globals__ is not vars(sys.modules["zero.record_inits"])  # its own scope, not the table's
    assert [f.name for f in fields(span)] == ["line", "column", "end_line", "end_column"]


def test_a_record_of_the_second_table_takes_its_init_from_there() -> None:
    """The records of modules a list's lint does not load are in ``record_inits_rest``, read at the first of them."""
    from zero.machine.limits import LimitRow
    from zero.record_inits import RECORDS, REST_MODULES
    from zero.record_inits_rest import RECORDS as REST

    limits = LimitRow(1, 2, 3, "X", 4, "mm", -1.0, 1.0, 0.0, False, -1.0, 1.0)
    code = type(limits).__init__.__code__
    assert code is REST["zero.machine.limits"]["LimitRow"][-1] and "zero.machine.limits" not in RECORDS
    assert "zero.machine.limits" in REST_MODULES
    assert (limits.axis_name, limits.pcs_pos, limits.note) == ("X", 1.0, "")


def test_a_lint_of_a_list_reads_the_first_table_only(tmp_path: Path) -> None:
    code = ("import sys, os; os.environ['ZERO_NO_CACHE'] = '1'; sys.argv = ['zero', 'lint', sys.argv[1]]\n"
            "import zero.cli.lean as lean\n"
            "def end(code):\n"
            "    print('REST' if 'zero.record_inits_rest' in sys.modules else 'FIRST'); raise SystemExit(code)\n"
            "lean.end = end\nlean.main()\n")
    target = tmp_path / "axis.lis"
    target.write_text("kenngr.achs_mode 1\nkenngr.no_such_key 1\nEnde\n", encoding="ascii")
    out = subprocess.run([sys.executable, "-c", code, str(target)], capture_output=True, text=True, check=False,
                         cwd=tmp_path)
    assert out.stdout.strip().endswith("FIRST"), out.stdout + out.stderr


def test_a_record_the_table_does_not_hold_is_compiled_with_its_defaults() -> None:
    @record(frozen=True)
    class Unlisted:
        a_field_no_zero_record_has: int
        with_default: str = "d"
        with_factory: list[int] = field(default_factory=lambda: [7])

    made = Unlisted(1)
    assert type(made).__init__.__code__.co_filename == "<string>"
    assert (made.a_field_no_zero_record_has, made.with_default, made.with_factory) == (1, "d", [7])
    assert Unlisted(2, "e", [1]).with_factory == [1]
    with pytest.raises(AttributeError):
        made.with_default = "x"  # type: ignore[misc]


def _tables() -> tuple[dict[str, dict[str, tuple[Any, ...]]], dict[str, Any]]:
    from zero.record_inits import INITS, RECORDS
    from zero.record_inits_rest import INITS as REST_INITS
    from zero.record_inits_rest import RECORDS as REST

    assert not RECORDS.keys() & REST.keys() and not INITS.keys() & REST_INITS.keys()
    return RECORDS | REST, INITS | REST_INITS


def test_every_ahead_of_time_record_is_what_its_class_declares() -> None:
    """Each entry of the tables is its record as worked out the slow way, its ``__init__`` the code its text
    compiles to (with its defaults replaced): taken from the table, a record of zero is the one it declares."""
    import importlib

    from zero.records import MISSING, init_source

    listed, by_text = _tables()
    assert sum(len(v) for v in listed.values()) > 100 and len(by_text) >= 1
    for module, records in listed.items():
        for qualname, (declared, flags, valued, given, without, names, shown, compared, code) in records.items():
            cls = importlib.import_module(module)
            for part in qualname.split("."):
                cls = getattr(cls, part)
            got = fields(cls)
            assert tuple(f.name for f in got) == names == cls.__match_args__, qualname
            ns = cls.__dict__
            assert ns.get("__annotations__") == declared
            assert tuple(f.name for f in got if f.repr) == shown == cls.__record_shown__
            assert tuple(f.name for f in got if f.compare) == compared
            assert valued + without == names or set(valued) | set(without) == set(names)
            kinds = dict(given)
            assert [f.name for f in got if f.default is MISSING and f.default_factory is MISSING] == [
                n for n in names if n in without or kinds.get(valued.index(n), (True, True))[:2] == (False, False)]
            source = init_source(got, flags[0], flags[3])[0]
            assert _same_code(code, _gen().code_of(source)), qualname
            if "__init__" not in vars(cls):
                continue
            assert vars(cls)["__init__"].__code__ is code, qualname  # what the record took
    for source, code in by_text.items():
        assert _same_code(code, _gen().code_of(source)), source


def _same_code(code: CodeType, ref: CodeType) -> bool:
    return bool((code.co_code, code.co_names, code.co_varnames, code.co_argcount, code.co_consts)
                == (ref.co_code, ref.co_names, ref.co_varnames, ref.co_argcount, ref.co_consts))


def _gen() -> ModuleType:
    from conftest import script_module

    return script_module(ROOT / "tools" / "gen_record_inits.py")


# Every case of this module, declared in one module of its own: the slow way, then from a table of them.
CASES = """
from __future__ import annotations
from typing import ClassVar
from zero.hints import Generic
from zero.records import field, record

@record
class Point:
    x: int
    y: int = 0
    tags: list[str] = field(default_factory=list)
    note: str | None = field(default=None, compare=False)
    hidden: int = field(default=0, repr=False)
    LIMIT: ClassVar[int] = 3

@record(frozen=True)
class Span:
    line: int
    column: int

@record(frozen=True, eq=False)
class Opaque:
    data: list[int] = field(default_factory=list)

@record(eq=False)
class Node:
    name: str

@record(unsafe_hash=True)
class Key:
    text: str
    indices: tuple[int, ...] = ()

@record
class Checked:
    low: int
    high: int
    width: int = 0

    def __post_init__(self) -> None:
        self.width = self.high - self.low

@record
class Custom:
    value: int

    def __repr__(self) -> str:
        return f"<{self.value}>"

class Plain:
    __slots__ = ("extra",)

@record
class OnPlain(Plain, Generic):
    first: int
    hidden: int = field(repr=False)
    later: str = ""

@record
class Empty:
    pass
"""


def _declare(table: dict[str, tuple[Any, ...]] | None, monkeypatch: pytest.MonkeyPatch,
             text: str = CASES) -> tuple[dict[str, Any], list[str]]:
    """The records of ``text``, declared in module ``zero_records_case`` with ``table`` as its entry in
    ``RECORDS``, and the records worked out the slow way."""
    import zero.record_inits as record_inits
    import zero.records as records

    slow: list[str] = []
    body_slow = records._body_slow

    def counted(shell: Any, frozen: bool, eq: bool, unsafe_hash: bool) -> tuple[dict[str, Any], list[type]]:
        slow.append(shell.qualname)
        return body_slow(shell, frozen, eq, unsafe_hash)

    scope: dict[str, Any] = {"__name__": "zero_records_case"}
    with monkeypatch.context() as patch:
        patch.setattr(records, "_body_slow", counted)
        if table is not None:
            patch.setitem(record_inits.RECORDS, "zero_records_case", table)  # the dict records reads
        exec(compile(text, "<cases>", "exec"), scope)
    return scope, slow


def _table_of(monkeypatch: pytest.MonkeyPatch, text: str = CASES) -> dict[str, tuple[Any, ...]]:
    """The table's entry for the records of ``text``, as the generator writes it."""
    import zero.records as records

    gen = _gen()
    seen: list[tuple[Any, dict[str, Any], bool, bool, bool]] = []
    body_slow = records._body_slow

    def capture(shell: Any, frozen: bool, eq: bool, unsafe_hash: bool) -> tuple[dict[str, Any], list[type]]:
        body, owner = body_slow(shell, frozen, eq, unsafe_hash)
        seen.append((shell, body, frozen, eq, unsafe_hash))
        return body, owner

    with monkeypatch.context() as patch:
        patch.setattr(records, "_body", capture)
        exec(compile(text, "<cases>", "exec"), {"__name__": "zero_records_case"})
    table = {}
    for shell, body, frozen, eq, unsafe_hash in seen:
        source, spec = gen.entry(shell, body, frozen, eq, unsafe_hash)
        table[shell.qualname] = (*spec, gen.code_of(source))
    return table


def _shape(cls: type) -> tuple[Any, ...]:
    """All a record class is made of (but its ``__init__``'s code and identities)."""
    from zero.records import init_source

    skip = {"__init__", "__record_fields__", "__record_key__", "__dict__", "__weakref__", "__module__", "__doc__"}
    own = {k: v for k, v in vars(cls).items() if k not in skip and not k.startswith("__record_fields")}
    own = {k: (f"{v.__module__}.{v.__qualname__}" if isinstance(v, FunctionType)
               else type(v).__name__ if type(v).__name__ == "member_descriptor" else v) for k, v in own.items()}
    init = cls.__dict__["__init__"]
    if init.__code__.co_flags & 0x04:  # not made yet (the slow way: at the first instance): what it will be
        _, scope, defaults = init_source(fields(cls), "__record_frozen__" in vars(cls), hasattr(cls, "__post_init__"))
        made: tuple[Any, ...] = (defaults or None, sorted(k for k in scope if k.startswith("__factory")))
    else:
        made = (init.__defaults__, sorted(k for k in init.__globals__ if k.startswith("__factory")))
    return (cls.__name__, cls.__qualname__, [b.__qualname__ for b in cls.__bases__],
            sorted(own.items(), key=lambda kv: kv[0]),
            [(f.name, f.default, f.default_factory, f.repr, f.compare) for f in fields(cls)], made,
            "__record_key__" in vars(cls))


def test_a_record_the_table_describes_is_the_one_worked_out_the_slow_way(monkeypatch: pytest.MonkeyPatch) -> None:
    slow_made, slow = _declare(None, monkeypatch)
    table = _table_of(monkeypatch)
    fast_made, fast_slow = _declare(table, monkeypatch)
    assert len(slow) == len(table) == 9 and fast_slow == []  # all taken from the table
    p, q = slow_made["Point"], fast_made["Point"]
    for made in (q(1), q(2, 3, ["a"], "n", 4)):
        twin = p(made.x, made.y, list(made.tags), made.note, made.hidden)
        assert repr(made) == repr(twin) and made.tags is not q(1).tags
    assert q(1) == q(1, note="b") and q(1) != q(2) and q.__hash__ is None and q.LIMIT == 3
    assert [f.name for f in fields(q)] == ["x", "y", "tags", "note", "hidden"] and q.__match_args__ == p.__match_args__
    assert not hasattr(q(1), "__dict__")
    s = fast_made["Span"](1, 2)
    with pytest.raises(AttributeError):
        s.line = 3
    with pytest.raises(AttributeError):
        del s.line
    assert hash(s) == hash(fast_made["Span"](1, 2)) and copy.deepcopy(s) == s and copy.copy(s) == s
    t = object.__new__(fast_made["Span"])
    t.__setstate__(s.__getstate__())  # what pickle does (the module here cannot be imported)
    assert t == s
    o = fast_made["Opaque"]()
    assert o.data == [] and o != fast_made["Opaque"]() and o.__hash__ is not None and repr(o) == "Opaque(data=[])"
    n = fast_made["Node"]
    assert n("a") != n("a") and len({n("a"), n("a")}) == 2
    k = fast_made["Key"]
    assert k("k", (1,)) == k("k", (1,)) and len({k("k", (1,)), k("k", (1,))}) == 1 and k("k").indices == ()
    assert fast_made["Checked"](2, 7).width == 5 and repr(fast_made["Custom"](3)) == "<3>"
    on = fast_made["OnPlain"](1, 2)
    assert (on.first, on.hidden, on.later) == (1, 2, "") and repr(on) == "OnPlain(first=1, later='')"
    assert fast_made["OnPlain"].__slots__ == ("first", "hidden", "later")
    assert on.__class__.__mro__[1].__name__ == "Plain"
    on.extra = 5
    assert repr(fast_made["Empty"]()) == "Empty()" and fast_made["Empty"]() == fast_made["Empty"]()
    for name in table:
        assert _shape(slow_made[name]) == _shape(fast_made[name]), name


@pytest.mark.parametrize(("old", "new"), [
    ("    y: int = 0\n", "    y: int\n    z: int = 0\n"),  # a field more (annotations)
    ("    x: int\n", "    x: int = 5\n"),  # a required field given a default
    ("    y: int = 0\n", "    y: int = field(default=0, compare=False)\n"),  # a plain default now a field()
    ("    note: str | None = field(default=None, compare=False)\n", "    note: str | None = None\n"),
    ("    hidden: int = field(default=0, repr=False)\n", "    hidden: int = field(default_factory=int, repr=False)\n"),
    ("    hidden: int = field(default=0, repr=False)\n", "    hidden: int = field(default=0)\n"),
    ("@record\nclass Point:", "@record(frozen=True)\nclass Point:"),
    ("@record\nclass Point:", "@record(unsafe_hash=True)\nclass Point:"),
    ("    LIMIT: ClassVar[int] = 3\n", "    LIMIT: ClassVar[int] = 3\n\n    def __post_init__(self) -> None:\n"
                                       "        self.y = 9\n"),
    ("    LIMIT: ClassVar[int] = 3\n", "    LIMIT: int = 3\n"),  # a class variable become a field
    ("class Point:", "class Point(Key):"),  # a record base
])
def test_a_record_the_table_no_longer_describes_is_worked_out_the_slow_way(
        monkeypatch: pytest.MonkeyPatch, old: str, new: str) -> None:
    """A table not regenerated after a record changed: the record is as declared, never the table's."""
    from zero.records import MISSING

    table = _table_of(monkeypatch)
    changed = CASES.replace(old, new, 1)
    if "(Key)" in new:  # the base must come first
        changed = changed.replace("@record(unsafe_hash=True)\nclass Key:", "@record(unsafe_hash=True)\nclass Key0:")
        changed = changed.replace("from zero.records import field, record\n",
                                  "from zero.records import field, record\n\n@record(unsafe_hash=True)\n"
                                  "class Key:\n    text: str\n")
    assert changed != CASES
    fast_made, slow = _declare(table, monkeypatch, changed)
    assert "Point" in slow
    reference, _ = _declare(None, monkeypatch, changed)
    assert _shape(fast_made["Point"]) == _shape(reference["Point"])
    args = [1] * sum(f.default is MISSING and f.default_factory is MISSING for f in fields(reference["Point"]))
    assert repr(fast_made["Point"](*args)) == repr(reference["Point"](*args))


# The class-statement form: `class X(..., Record, ARGS):` for `@record(ARGS)` and `class X(...):`.
_DECORATED = re.compile(r"^(?P<ind>[ \t]*)@record(?:\((?P<args>[^)]*)\))?\n(?P=ind)class (?P<name>\w+)"
                        r"(?:\((?P<bases>[^)]*)\))?:", re.M)


def _as_record_base(text: str) -> str:
    """``text`` with every ``@record`` declaration written as a class naming ``Record`` (what zero's source does)."""
    def written(m: re.Match[str]) -> str:
        parts = [p for p in ((m["bases"] or "").strip(), "Record", (m["args"] or "").strip()) if p]
        return f"{m['ind']}class {m['name']}({', '.join(parts)}):"

    out = _DECORATED.sub(written, text)
    return out.replace("from zero.records import field, record\n", "from zero.records import Record, field, record\n")


def test_a_record_base_makes_the_record_the_decorator_makes(monkeypatch: pytest.MonkeyPatch) -> None:
    """Each case declared as a class naming Record is made the same as with ``@record``, the slow way and from
    the table (whose entries do not depend on the form), and in one step: no class is made twice."""
    text = _as_record_base(CASES)
    assert "@record" not in text and len(re.findall(r"^class \w+\(.*\bRecord\b", text, re.M)) == CASES.count("@record")
    table = _table_of(monkeypatch)
    assert _table_of(monkeypatch, text) == table  # the generator reads both forms alike
    decorated, _ = _declare(None, monkeypatch)
    for which in (None, table):
        made, slow = _declare(which, monkeypatch, text)
        assert slow == ([] if which else list(table))
        for name in table:
            assert _shape(made[name]) == _shape(decorated[name]), name
            assert type(made[name]) is type and all(b.__name__ != "Record" for b in made[name].__mro__)
    made, _ = _declare(table, monkeypatch, text)
    p = made["Point"]
    assert repr(p(1, 2, ["a"], "n", 4)) == "Point(x=1, y=2, tags=['a'], note='n')" and p(1) == p(1, note="z")
    s = made["Span"](1, 2)
    with pytest.raises(AttributeError):
        s.line = 3
    assert hash(s) == hash(made["Span"](1, 2))


RECORD_CASES = """
from __future__ import annotations
from zero.hints import Generic, TypeVar
from zero.records import Record, field, fields

T = TypeVar("T")

class Base(Record, frozen=True):
    a: int
    b: int = 1

    def who(self) -> type:
        return __class__

    def plain_repr(self) -> str:
        return super().__repr__()

class Sub(Base, Record, frozen=True):
    c: str = ""

class Plain(Base):
    def label(self) -> str:
        return f"plain {self.a}"

class Boxed(Generic[T], Record):
    value: T
    notes: list[str] = field(default_factory=list)
"""


def test_a_record_names_record_to_be_one() -> None:
    """A subclass naming Record is a record (its base's fields first); one that does not is a plain subclass, as
    a class deriving from a ``@record`` class is. Methods see their own class (``__class__``, ``super()``), which
    a decorator's second class cannot give them."""
    scope: dict[str, Any] = {"__name__": "zero_records_base_case"}
    exec(compile(RECORD_CASES, "<record cases>", "exec"), scope)
    base, sub, plain, boxed = scope["Base"], scope["Sub"], scope["Plain"], scope["Boxed"]
    assert [f.name for f in fields(sub)] == ["a", "b", "c"] and sub.__slots__ == ("c",)
    assert repr(sub(1, 2, "x")) == "Sub(a=1, b=2, c='x')" and sub(1) == sub(1) and sub(1) != base(1)
    assert base(1).who() is base and base(1).plain_repr().startswith("<zero_records_base_case.Base object at ")
    assert "__slots__" not in vars(plain) and plain(3).label() == "plain 3" and repr(plain(3)) == "Plain(a=3, b=1)"
    assert boxed(5).notes == [] and boxed(5).notes is not boxed(5).notes and boxed[int] is boxed
    for cls in (base, sub, plain, boxed):
        assert type(cls) is type  # isinstance with it stays the interpreter's fast check
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        state = pickle.loads(pickle.dumps(sub(1, 2, "x").__getstate__(), protocol))
        again = object.__new__(sub)
        again.__setstate__(state)
        assert again == sub(1, 2, "x")
    with pytest.raises(TypeError, match="without a default follows one with a default"):
        exec(compile("from zero.records import Record\nclass Bad(Record):\n    a: int = 0\n    b: int\n",
                     "<bad>", "exec"), {"__name__": "zero_records_bad"})
