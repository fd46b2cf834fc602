"""The positions step's own mistakes (app/engine/tutor/mistake_positions.py): every one typed back is named by its
own key, with its own hint; the components asked are the moving ones; another origin is accepted."""

from __future__ import annotations

import pytest
import sympy as sp

from app.engine.tutor.check import exercises, judge, problem
from app.scenes import SCENES
from tests.cases import case_list
from tests.engine import slip_corpus
from tests.engine.tutor.test_check_slips import derivation

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

# (system, component) for each position step (the list kept on disk between runs: tests/cases.py)
POSITION_STEPS = case_list(
    "position-steps",
    lambda: [
        (name, coordinate) for name in (*SCENES, "free-cart", "elastic-pendulum")
        for step, coordinate in exercises(derivation(name)) if step == "position"
    ],
    __file__,
    slip_corpus.__file__,
)  # fmt: skip


@pytest.mark.parametrize(("system", "coordinate"), POSITION_STEPS, ids=["-".join(c) for c in POSITION_STEPS])
def test_every_position_mistake_typed_back_is_named_by_its_own_key(system, coordinate):
    pb = problem(derivation(system), "position", coordinate)
    assert pb.mistakes, (system, coordinate)
    for mistake, hint, _ in pb.mistakes:
        # typed as a student would, with the figure's constant (another origin) added
        result = judge(pb, f"{sp.sstr(mistake.expr)} + 0")
        assert result["verdict"] == "incorrect", (mistake.key, result)
        assert result["mistake"]["key"] == mistake.key and result["hint"] == hint, (mistake.key, result["hint"])


def test_the_components_asked_are_the_moving_ones_in_the_bodies_order():
    asked = {name: [c for s, c in exercises(derivation(name)) if s == "position"] for name in SCENES}
    assert asked["simple-pendulum"] == ["x", "z"]  # a flat figure: y = 0 is not asked
    assert asked["spherical-pendulum"] == ["x", "y", "z"]
    assert asked["pulley"] == ["z1", "z2", "z3"]  # the end masses hang at fixed x
    # the wedge's x = X is no step: the block's x holds it, and is asked (review prof-q 3); a declared rigid body
    # carried by the wedge is asked by its centre
    assert asked["movable-incline"] == ["x2", "z2"]
    assert asked["rolling-cylinder-wedge"] == ["x2", "z2"]
    # a system given by its energies has no positions step
    assert [s for s, _ in exercises(derivation("rod-pendulum"))][0] == "kinetic"


def test_the_engines_own_position_and_another_origin_are_accepted():
    pb = problem(derivation("double-pendulum"), "position", "z2")
    assert judge(pb, "-l1*cos(theta1) - l2*cos(theta2)")["verdict"] == "correct"
    shifted = judge(pb, "l1 + l2 - l1*cos(theta1) - l2*cos(theta2)")
    assert shifted["verdict"] == "equivalent" and "another origin" in shifted["message"]
