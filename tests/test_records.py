"""zero.records behaves as the dataclasses it replaces: each case is declared both ways and
compared, so a difference in semantics fails here rather than somewhere in a rule."""

from __future__ import annotations

import copy
import dataclasses
import pickle
import subprocess
import sys
from pathlib import Path
from typing import ClassVar

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
    from zero.record_inits import INITS

    span = Span(3, 4, 3, 9)
    init = type(span).__init__
    assert init.__code__ in INITS.values()
    assert init.__code__.co_filename.endswith("record_inits.py")
    assert (span.line, span.column, span.end_line, span.end_column) == (3, 4, 3, 9)
    assert init.__globals__ is not vars(sys.modules["zero.record_inits"])  # its own scope, not the table's


def test_a_record_of_the_second_table_takes_its_init_from_there() -> None:
    """The records of modules a list's lint does not load are in ``record_inits_rest``, read at the first of them."""
    from zero.machine.limits import LimitRow
    from zero.record_inits import INITS
    from zero.record_inits_rest import INITS as REST

    limits = LimitRow(1, 2, 3, "X", 4, "mm", -1.0, 1.0, 0.0, False, -1.0, 1.0)
    code = type(limits).__init__.__code__
    assert code in REST.values() and code not in INITS.values()
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


def test_every_ahead_of_time_init_is_the_code_its_text_compiles_to() -> None:
    """The table's functions are compiled from the text with its defaults replaced: the code is the same."""
    from types import CodeType

    from zero.record_inits import INITS
    from zero.record_inits_rest import INITS as REST

    assert len(INITS) > 20 and len(REST) > 20 and not INITS.keys() & REST.keys()
    for source, code in (INITS | REST).items():
        assert isinstance(code, CodeType)
        ref = next(c for c in compile(source, "<string>", "exec").co_consts if isinstance(c, CodeType))
        assert (code.co_code, code.co_names, code.co_varnames, code.co_argcount, code.co_consts) == (
            ref.co_code, ref.co_names, ref.co_varnames, ref.co_argcount, ref.co_consts), source
