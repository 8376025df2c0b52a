"""Every AST node class behaves as the frozen slotted dataclass ``rapidmc.ast`` declares:
``==``, ``hash`` and ``repr`` (shared by the classes, ``ast.node``) give what
``dataclass`` would generate, and the classes stay immutable, replaceable, picklable
and matchable."""
from __future__ import annotations

import copy
import dataclasses
import pickle

import pytest

from rapidmc import ast
from rapidmc.syntax import parse_text
from rapidmc.syntax.construct import NODE_CLASSES

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

PROGRAM = """MODULE m
  RECORD rec num a; ENDRECORD
  ALIAS num length;
  LOCAL CONST num limit{2} := [1, 2.5];
  PROC main(VAR num x, \\switch s | num t)
    x := -limit{1} + 2 * (x DIV 3);
    MoveL Offs(p, 0, 0, x), v100 \\T:=1, fine, tool0;
    IF x > 1 AND NOT TRUE THEN RETURN; ELSEIF x < 0 THEN x := 0; ELSE GOTO l; ENDIF
    FOR i FROM 1 TO 3 STEP 1 DO x := x + i; ENDFOR
    TEST x CASE 1: Stop; DEFAULT: RAISE 3; ENDTEST
    l:
  ERROR (4)
    RETRY;
  ENDPROC
ENDMODULE
"""


def reference_class(cls: type) -> type:
    """The class ``@dataclass(frozen=True, slots=True)`` makes from ``cls``'s fields."""
    return dataclasses.make_dataclass(
        cls.__name__,
        [(f.name, f.type, dataclasses.field(default=f.default, compare=f.compare, hash=f.hash,
                                            repr=f.repr))
         for f in dataclasses.fields(cls)], frozen=True, slots=True)


def samples(cls: type) -> list[tuple]:
    """Field values for two nodes differing in each field in turn."""
    count = len(dataclasses.fields(cls))
    base = tuple(f"v{index}" for index in range(count))
    return [base] + [base[:index] + ((1, 2.5, None),) + base[index + 1:]
                     for index in range(count)]


@pytest.mark.parametrize("name", sorted(NODE_CLASSES))
def test_equality_hash_and_repr_are_the_dataclass_ones(name):
    cls = NODE_CLASSES[name]
    reference = reference_class(cls)
    rows = samples(cls)
    for left in rows:
        assert repr(cls(*left)) == repr(reference(*left))
        assert hash(cls(*left)) == hash(reference(*left))
        for right in rows:
            assert (cls(*left) == cls(*right)) == (reference(*left) == reference(*right))
            assert (cls(*left) != cls(*right)) == (reference(*left) != reference(*right))
    assert cls(*rows[0]).__eq__(reference(*rows[0])) is NotImplemented


@pytest.mark.parametrize("name", sorted(NODE_CLASSES))
def test_nodes_are_immutable_replaceable_picklable_and_matchable(name):
    cls = NODE_CLASSES[name]
    fields = dataclasses.fields(cls)
    node = cls(*samples(cls)[0])
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(node, fields[0].name, "other")
    assert not hasattr(node, "__dict__")           # slots: no field can be added
    changed = dataclasses.replace(node, **{fields[0].name: "other"})
    assert getattr(changed, fields[0].name) == "other" and type(changed) is cls
    assert pickle.loads(pickle.dumps(node)) == node and copy.deepcopy(node) == node
    assert cls.__match_args__ == tuple(f.name for f in fields if f.init)
    assert dataclasses.is_dataclass(node) and dataclasses.astuple(node)


def test_parsed_trees_compare_and_hash_by_value():
    first, second = parse_text(PROGRAM, "m.mod"), parse_text(PROGRAM, "m.mod")
    assert first == second and hash(first) == hash(second) and first[0] is not second[0]
    names = [node for node, _ in ast.walk(first[0]) if isinstance(node, ast.NameRef)]
    # a name's span is not compared: the same name elsewhere is equal
    assert names[0].name == ast.Name.of(names[0].name.text) or names[0].name.text != "limit"
    assert ast.Name("x", "X", ast.Span("a", 1, 1)) == ast.Name("x", "X", ast.Span("b", 2, 2))
    assert len({ast.Name("x", "X", ast.Span("a", 1, 1)), ast.Name("x", "X", ast.NO_SPAN)}) == 1
    assert parse_text(PROGRAM.replace("2.5", "3.5"), "m.mod") != first
