"""A verdict names the place and the kind of slip in a final answer without printing the correct part (review
student-l, section 3 item 3: "the denominator M + 4 m₁, where the correct one is M m₁ + M m₂ + 4 m₁ m₂"); the
correct part travels in the verdict's own field, ``correct_part``, for the page to show when the student asks."""

from __future__ import annotations

import unicodedata

import pytest

from app.engine.tutor.check import judge
from tests.engine.tutor.test_check_giveaway import read
from tests.engine.tutor.test_check_slips import step_problem

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)


def nfc(text: str) -> str:
    return unicodedata.normalize("NFC", text)


# (scene, step, coordinate, answer, the name's start, the part in words, the correct part as text)
CASES = [
    ("pulley", "acceleration", "y1", "g*(M - 2*m1)/(M + 4*m1 + m2)", "the denominator M + m₂ + 4 m₁", "denominator",
     "Mm₁ + Mm₂ + 4m₁m₂"),
    ("helix-bead", "acceleration", "z", "-g*R**2*alpha**2/(1+R**2*alpha**2)", "the numerator −g R² α²", "numerator",
     "−g"),
    ("physical-pendulum", "kinetic", None, "M*l**2*theta_dot**2/2", "the rod taken as a point mass at its end",
     "moment of inertia about the end", "Ml²/3"),
    ("rolling-cylinder-wedge", "kinetic", None,
     "M*X_dot**2/2 + m*(X_dot**2 + s_dot**2 + 2*X_dot*s_dot*cos(alpha))/2 + m*s_dot**2/2",
     "the cylinder taken as a hoop", "moment of inertia about the axis", "mr²/2"),
    ("massive-pulley", "kinetic", None, "(m1 + m2)*z_dot**2/2", "the pulley's turning energy ½ I (ż/R)² left out",
     "moment of inertia of the pulley about its axle", "MR²/2"),
    ("rail-two-body", "potential", None, "k*(x2 - x1 + l0)**2/2", "x₂ − x₁ + l₀: the sign of l₀", "stretch",
     "x₂ − x₁ − l₀"),
    ("double-pendulum", "kinetic", None,
     "(m1 + m2)*l1**2*theta1_dot**2/2 + m2*l2**2*theta2_dot**2/2 + m2*l1*l2*theta1_dot*theta2_dot*cos(theta1 + theta2)",
     "θ₁ + θ₂: the sign of θ₂", "angle", "θ₁ − θ₂"),
]  # fmt: skip


@pytest.mark.parametrize(("scene", "step", "coordinate", "answer", "name", "what", "text"), CASES)
def test_the_correct_part_is_its_own_field_and_not_in_the_words(scene, step, coordinate, answer, name, what, text):
    result = judge(step_problem(scene, step, coordinate), answer)
    assert result["verdict"] == "incorrect" and nfc(result["mistake"]["name"]).startswith(nfc(name)), result
    part = result["correct_part"]
    assert part["what"] == what and nfc(part["text"]) == nfc(text) and part["latex"], part
    # what the student reads before asking for it never holds it (nor "where the correct one is"), the student's own
    # quoted part aside (−g R² α² holds −g)
    said = nfc(read(result)).replace(" ", "").replace(nfc(name).replace(" ", ""), "")
    assert nfc(text).replace(" ", "") not in said and "wherethecorrect" not in said, said


def test_a_denominator_up_to_a_constant_factor_says_so_beside_it():
    part = judge(step_problem("pulley", "acceleration", "y1"), "g*(M - 2*m1)/(M + 4*m1 + m2)")["correct_part"]
    assert part["note"] == "up to a constant factor"


def test_a_mistake_that_points_at_no_part_has_none():
    result = judge(step_problem("simple-pendulum", "kinetic", None), "m*R**2*theta_dot**2")
    assert result["mistake"]["name"] == "the ½ of ½ m v² left out" and result["correct_part"] is None
