"""typing's names that zero uses at run time, without importing typing.

Importing typing costs about a twentieth of a list's lint at start-up, and zero's annotations
are strings (``from __future__ import annotations``) that only type checkers read. What a
module needs while it runs is here: ``overload`` and ``dataclass_transform`` leave what they
decorate as it is, ``Generic[...]`` is ``Generic``, and a type variable is its name. Type
checkers read typing's own names: ``TYPE_CHECKING`` below is typing's for mypy and ruff, so they take the second branch.
Elsewhere, ``TYPE_CHECKING = False`` then ``if TYPE_CHECKING: from typing import ...`` for names
that appear in annotations only.
"""

from __future__ import annotations

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing (mypy and ruff read it alike)
if not TYPE_CHECKING:  # the run-time stand-ins come first, so that linters see typing's names where used
    def overload(function: object) -> object:
        return function

    def dataclass_transform(**_options: object) -> object:
        return lambda cls: cls

    class Generic:
        """A base class whose subscript is itself (``Check[C]`` is ``Check``)."""

        __slots__ = ()

        def __class_getitem__(cls, _item: object) -> type:
            return cls

    def TypeVar(name: str, *_constraints: object, **_options: object) -> str:
        return name
if TYPE_CHECKING:
    from typing import Generic, TypeVar, dataclass_transform, overload

__all__ = ["Generic", "TypeVar", "dataclass_transform", "overload"]
