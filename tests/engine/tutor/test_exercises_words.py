"""A practice page's help fits its scene (issue 41, student-l 8, 9): a position's shift of origin is shown with a
length the scene has (never R where there is none), the pulley's y₁, y₂ are said to be heights, and every name a
step offers is one the problem statement defines."""

from __future__ import annotations

import re

import pytest

from app.engine.derivation.derive import derive
from app.engine.display.names import unicode
from app.engine.tutor.exercises import exercise_json, position_note
from app.scenes import SCENES

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


@pytest.mark.parametrize(
    ("scene_id", "example"),
    [
        ("double-pendulum", "such as + l₁,"),
        ("coupled-oscillators", "such as + d,"),
        ("physical-pendulum", "such as + l,"),
        ("rolling-cylinder-wedge", "such as + r,"),
        ("massive-pulley", "such as + R,"),
        ("simple-pendulum", "such as + R,"),
        # no length among the wedge's or the rotating wire's parameters: no example, and never an R
        ("movable-incline", "with its units,"),
        ("rotating-parabola", "with its units,"),
    ],
)
def test_the_shift_of_origin_is_shown_with_a_length_of_the_scene(scene_id, example):
    note = position_note(derive(SCENES[scene_id].system))
    assert example in note and "never a bare number" in note
    if scene_id not in ("simple-pendulum", "massive-pulley"):
        assert "+ R" not in note


def test_the_pulleys_coordinates_are_said_to_be_heights():
    note = position_note(derive(SCENES["pulley"].system))
    assert "Here y₁, y₂ are heights (measured up, along z), not the third direction." in note
    # the massive pulley's z, the height m₂ has risen, sits in the z slot it names: nothing to say
    assert "Here" not in position_note(derive(SCENES["massive-pulley"].system))
    # a scene whose coordinates are no heights named y says nothing of the kind
    assert "height" not in position_note(derive(SCENES["double-pendulum"].system))


# names every page defines once for all: g, the gravitational acceleration (its Symbols table), and t
STANDARD = {"g", "t", "pi"}


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_every_name_a_step_offers_is_defined_in_the_statement(scene_id):
    # student-l 9: the two masses' d was offered in every step's names, and said only under the figure
    scene = SCENES[scene_id]
    d = derive(scene.system)
    declared = {s.name for s in (*d.table.q, *d.table.params)}
    offered = {re.sub(r"_d?dot$", "", n) for e in exercise_json(d)["exercises"] for n in e["names"]}
    text = f"{scene.statement} {scene.figure}"
    for name in sorted((offered & declared) - STANDARD):
        said = (rf"(?<![\w\u0300-\u036f]){re.escape(f)}(?![\w\u0300-\u036f₀-₉])" for f in {name, unicode(name)})
        assert any(re.search(s, scene.statement) for s in said), (scene_id, name, text)


@pytest.mark.parametrize("scene_id", ["massive-pulley", "pulley"])
def test_a_position_steps_side_is_plain_latex(scene_id):
    # a body named by its mass (the massive pulley's "mass m₁") has the mass set as mathematics in the step's
    # subscript: KaTeX has no Unicode subscript ₁ in text
    sides = [e["lhs"] for e in exercise_json(derive(SCENES[scene_id].system))["exercises"] if e["step"] == "position"]
    assert sides and all(side.isascii() for side in sides), sides
    if scene_id == "massive-pulley":
        # the coordinate z is m₂'s height, so the heights asked are ζ (notation.practice_axes; prof-r 1)
        assert sides == [r"\zeta_{\text{mass } m_{1}}", r"\zeta_{\text{mass } m_{2}}"]
