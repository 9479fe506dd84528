"""Conditions as Python source, written at build time: what :func:`~zero.catalog.conditions.compile_condition`
builds at run time, read from bytecode instead (issue 40: start-up).

``tools/gen_conditions.py`` writes each K rule's condition with :func:`source` into
``data/startup_compiled.py``; :mod:`zero.rules.startup` takes a function from there where the row's
condition text is the one it was written from, and compiles the text otherwise. A function written here
gives what the compiled closure gives for every lookup (``tests/rules/test_condition_source.py``
compares them): ``None`` where a value it needs is not known, ``and``/``or`` deciding without the
unknown side where the known side decides. The helpers the written functions call, the closures' bodies, are
:mod:`~zero.catalog.condition_helpers`'s.
"""

from __future__ import annotations

from zero.catalog.condition_helpers import ELSEWHERE, HELPERS, UNIQUE
from zero.catalog.conditions import Binary, Call, Member, Num, Ref, Str, Unary

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if TYPE_CHECKING:
    from zero.catalog.conditions import Node

__all__ = ["HELPERS", "source"]


def _expr(node: Node, fresh: list[int]) -> str:
    """``node`` as a Python expression of ``lookup`` (``fresh``: the count of names taken for and/or)."""
    if isinstance(node, Num | Str):
        return repr(node.value)
    if isinstance(node, Member):
        return f"_member({_expr(node.arg, fresh)}, {node.choices!r}, {node.negated!r})"
    if isinstance(node, Ref):
        return f"lookup({node.pid!r}, {node.index!r})"
    if isinstance(node, Unary):
        return f"{'_not' if node.op == 'not' else '_neg'}({_expr(node.arg, fresh)})"
    if isinstance(node, Call):
        if node.name == "supports":
            ref = node.args[0]
            assert isinstance(ref, Ref)
            return f"_supports({ref.pid!r}, lookup)"
        if node.name in ("unique", "elsewhere"):
            fact = UNIQUE if node.name == "unique" else ELSEWHERE
            key = fact + ",".join(a.pid for a in node.args if isinstance(a, Ref))
            return f"_fact(lookup({key!r}, None))"
        args = ", ".join(_expr(a, fresh) for a in node.args)
        return f"_{node.name}({args})"
    assert isinstance(node, Binary)
    if node.op in ("and", "or"):
        # the left side first; the right one only where the left does not decide (as the closures)
        fresh[0] += 1
        a = f"_v{fresh[0]}"
        decided = f"not {a}" if node.op == "and" else a
        return (f"({node.op == 'or'!r} if ({a} := {_expr(node.left, fresh)}) is not None and {decided} "
                f"else _both({a}, {_expr(node.right, fresh)}))")
    return f"_binary({node.op!r}, {_expr(node.left, fresh)}, {_expr(node.right, fresh)})"


def source(name: str, node: Node) -> str:
    """A ``def name(lookup)`` that evaluates ``node`` as its compiled closure does."""
    return f"def {name}(lookup):\n    return {_expr(node, [0])}\n"
