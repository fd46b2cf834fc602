"""Slips read from the answer itself: a square left out, an equation linearised (app/engine/tutor/mistake_answer.py)."""

from __future__ import annotations

import pytest

from app.engine.tutor.check import judge
from tests.engine.tutor.test_check_slips import step_problem

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


@pytest.mark.parametrize(
    ("scene", "answer", "part", "square"),
    [
        ("helix-bead", "m*(1 + R*alpha)*z_dot**2/2", "αR", "α²R²"),
        ("rotating-parabola", "m*(rho_dot**2*(1 + 2*alpha*rho) + omega**2*rho**2)/2", "2αρ", "4α²ρ²"),
    ],
)
def test_a_component_left_unsquared_is_named_with_its_square(scene, answer, part, square):
    result = judge(step_problem(scene, "kinetic", None), answer)
    assert result["verdict"] == "incorrect"
    assert f"You wrote {part} where T needs its square {square}" in result["hint"]
    assert result["mistake"]["name"] == f"{part} where T needs its square {square}" and not result["mistake"]["approximation"]


def test_another_wrong_factor_is_not_called_a_missing_square():
    result = judge(step_problem("helix-bead", "kinetic", None), "m*(1 + 3*R*alpha)*z_dot**2/2")
    assert "needs its square" not in result["hint"]


def test_the_small_angle_equation_is_named_as_linearised():
    answer = "m2*l2**2*theta2_ddot + m2*l1*l2*theta1_ddot + m2*g*l2*theta2"
    result = judge(step_problem("double-pendulum", "equation", "theta2"), answer)
    assert result["verdict"] == "incorrect" and "linearised for small displacements" in result["hint"]
    # named as an approximation, as the catalogue's small-angle forms are (student-e, 16)
    assert result["mistake"]["approximation"] and result["mistake"]["name"].startswith("the equation linearised"), result
    # divided through by m₂ l₂ it is the same slip
    scaled = judge(step_problem("double-pendulum", "equation", "theta2"), "l2*theta2_ddot + l1*theta1_ddot + g*theta2")
    assert "linearised" in scaled["hint"]


def test_a_linear_system_is_never_told_it_linearised():
    # the coupled oscillators' equations are linear: the full equation is its own first-order part
    result = judge(step_problem("coupled-oscillators", "equation", "x1"), "m*x1_ddot + k*x1")
    assert "linearised" not in (result["hint"] or "")
