"""ValueKind and CommentStyle: enumerations without enum's class machinery (issue 40, start-up), which behave
as the enum members they were wherever zero uses them: name, value, repr, str, identity through pickle and copy."""

from __future__ import annotations

import pickle

import pytest

from conftest import assert_stays_itself
from zero.lists.model import CommentStyle, Member, ValueKind
from zero.lists.tokenizer import tokenize

KINDS = {"INT": "int", "HEX": "hex", "REAL": "real", "REF": "ref", "FLAGS": "flags", "WORD": "word",
         "QUOTED": "quoted"}
STYLES = {"HASH": "#", "PAREN": "(", "BLOCK": "/*", "TEXT": "text"}


@pytest.mark.parametrize(("cls", "members"), [(ValueKind, KINDS), (CommentStyle, STYLES)])
def test_members_are_named_and_valued_as_the_enum_gave_them(cls: type[Member], members: dict[str, str]) -> None:
    for name, value in members.items():
        member = getattr(cls, name)
        assert type(member) is cls
        assert (member.name, member.value) == (name, value)
        assert repr(member) == f"<{cls.__name__}.{name}: {value!r}>"
        assert str(member) == f"{cls.__name__}.{name}"
    assert len({getattr(cls, name) for name in members}) == len(members)


MEMBERS = [*(getattr(ValueKind, n) for n in KINDS), *(getattr(CommentStyle, n) for n in STYLES)]


@pytest.mark.parametrize("member", MEMBERS)
def test_a_member_stays_itself_through_pickle_and_copy(member: Member) -> None:
    assert_stays_itself(member)


def test_a_member_cannot_be_changed() -> None:
    with pytest.raises(AttributeError):
        ValueKind.INT.value = "real"
    with pytest.raises(AttributeError):
        CommentStyle.HASH.name = "PAREN"
    assert (ValueKind.INT.name, ValueKind.INT.value) == ("INT", "int")


def test_a_tokenized_entry_carries_the_members_themselves() -> None:
    doc = tokenize(b"kopf.achs_nr 0x10 # hex\nkenngr.swe_pos 1.5 ( P-AXIS-00001 note\n", "a.lis")
    entries = list(doc.entries)
    assert [e.value_kind for e in entries] == [ValueKind.HEX, ValueKind.REAL]
    assert entries[0].value_kind is ValueKind.HEX and entries[1].value_kind is ValueKind.REAL
    assert entries[0].comment_style is CommentStyle.HASH and entries[1].comment_style is CommentStyle.PAREN
    restored = pickle.loads(pickle.dumps(doc))
    assert [e.value_kind for e in restored.entries] == [ValueKind.HEX, ValueKind.REAL]
