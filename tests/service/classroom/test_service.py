"""The pieces of a class's check: the named mistake of a verdict, the assignment's item, codes and keys."""

from __future__ import annotations

import pytest

from app.engine.tutor.mistakes import RULES
from app.errors import Refused
from app.service.classroom import keys
from app.service.classroom.assignments import find_item
from app.service.classroom.service import named_mistake

CROSS = next(r for r in RULES if r.mistake == "missing_cross_term")


@pytest.mark.parametrize(
    ("verdict", "named"),
    [
        ({"verdict": "incorrect", "mistake": "missing_half", "hint": CROSS.hint}, "missing_half"),  # its own field first
        ({"verdict": "incorrect", "mistake": {"name": "sign_of_u", "hint": "..."}}, "sign_of_u"),
        ({"verdict": "incorrect", "hint": CROSS.hint}, "missing_cross_term"),  # no field: the hint's mistake
        ({"verdict": "incorrect", "hint": "U depends on positions only"}, None),  # a pointer, not a named mistake
        ({"verdict": "incorrect", "mistake": None, "hint": None}, None),
        ({"verdict": "correct", "mistake": "missing_half"}, None),
    ],
)
def test_the_named_mistake_of_a_verdict(verdict, named):
    assert named_mistake(verdict) == named


ITEMS = [
    {"scene": "double-pendulum", "steps": [{"step": "kinetic", "coordinate": None},
                                            {"step": "equation", "coordinate": "theta1"}], "parameters": {}},
    {"name": "spring", "system": {"coordinates": ["x"]}, "steps": [{"step": "acceleration", "coordinate": "x"}],
     "parameters": {}},
]


def test_a_check_finds_its_item_and_step():
    assert find_item(ITEMS, {"scene": "double-pendulum", "system": None}, "kinetic", None) is ITEMS[0]
    assert find_item(ITEMS, {"scene": "double-pendulum", "system": None}, "equation", "theta1") is ITEMS[0]
    assert find_item(ITEMS, {"scene": None, "system": "spring"}, "acceleration", "x") is ITEMS[1]
    with pytest.raises(Refused, match="not in the assignment"):
        find_item(ITEMS, {"scene": "double-pendulum", "system": None}, "equation", "theta2")
    with pytest.raises(Refused, match="assigned: double-pendulum, spring"):
        find_item(ITEMS, {"scene": "simple-pendulum", "system": None}, "kinetic", None)
    with pytest.raises(Refused, match="'scene'"):
        find_item(ITEMS, {"scene": None, "system": None}, "kinetic", None)
    # no assignment: any scene, no declared system
    assert find_item([], {"scene": "pulley", "system": None}, "kinetic", None)["scene"] == "pulley"
    with pytest.raises(Refused, match="no system is assigned"):
        find_item([], {"scene": None, "system": "spring"}, "kinetic", None)


def test_codes_are_typed_forgivingly_and_keys_kept_as_digests():
    code = keys.new_code()
    assert len(code) == keys.CODE_LENGTH and set(code) <= set(keys.ALPHABET)
    assert keys.normal_code(f" {code[:3].lower()}-{code[3:]} ") == code
    assert keys.normal_code("0OIl12") is None and keys.normal_code("ACE") is None
    key = keys.new_key()
    assert len(key) == 43 and keys.digest(key) != key and len(keys.digest(key)) == 64
