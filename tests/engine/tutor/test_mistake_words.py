"""A named slip says what happened to its piece: a piece left out reads "… left out" (or "… missing"), a piece
added "… added" (or "… counted twice"), never the piece alone, which reads as one the student wrote (review
student-l, section 3 item 4: "The mistake: the cross term in Ẋ Ḋ" for a T with no cross term at all).

The rule has one home, ``app.engine.tutor.mistake_families.said``; these tests run every scene's generated slips through
the verdict's own words (``mistake_json``) and the review's six answers through the checker.
"""

from __future__ import annotations

import re
import unicodedata

import pytest
import sympy as sp

from app.engine.tutor.check import judge
from app.engine.tutor.check_problem import exercises
from app.engine.tutor.diagnose import mistake_json
from app.engine.tutor.mistake_families import ADDS, LEAVES_OUT
from app.scenes import SCENES
from tests.engine.tutor.test_check_slips import derivation, step_problem

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

OMITTED = re.compile(r"\b(left out|leaves out|missing)\b")
ADDED = re.compile(r"\b(added|counted twice)\b")


def _leaves_out(m, truth: sp.Expr) -> bool:
    """Whether a mistake is its step's answer less its piece (read from the expressions, not from its family)."""
    if m.piece is None or m.count != 1 or m.approximation:
        return False
    return sp.expand(m.expr - (truth - m.piece)) == 0


@pytest.mark.parametrize("name", sorted(SCENES))
def test_every_generated_slip_that_leaves_a_piece_out_says_so(name):
    omissions = 0
    for step, coordinate in exercises(derivation(name)):
        pb = step_problem(name, step, coordinate)
        for m, _, _ in pb.mistakes:
            words = mistake_json(m, str)["name"]
            if m.family in ADDS:
                assert ADDED.search(words), (step, coordinate, m.key, words)
            elif m.family in LEAVES_OUT or _leaves_out(m, pb.truths[0]):
                omissions += 1
                assert OMITTED.search(words), (step, coordinate, m.key, words)
    # every scene has something to leave out of T or U
    assert omissions, name


# (scene, step, coordinate, answer, the verdict's name): the review's six, each a piece the answer has not
REVIEWED = [
    ("movable-incline", "kinetic", None, "1/2*M*X_dot**2 + 1/2*m*(X_dot**2 + D_dot**2)", "the cross term in Ẋ Ḋ left out"),
    ("pulley", "kinetic", None, "1/2*m1*y1_dot**2 + 1/2*m2*y2_dot**2", "the kinetic energy of the middle mass left out"),
    ("helix-bead", "kinetic", None, "1/2*m*R**2*alpha**2*z_dot**2", "the z-component of the bead's velocity left out"),
    ("helix-bead", "kinetic", None, "1/2*m*z_dot**2", "the bead's motion in the x–y plane left out"),
    ("rail-two-body", "potential", None, "1/2*k*(x2-x1)**2", "the spring's natural length l₀ left out"),
    ("coupled-oscillators", "potential", None, "1/2*k*x1**2 + 1/2*k*x2**2",
     "the energy of the spring κ in x₁ and x₂ left out"),
]  # fmt: skip


@pytest.mark.parametrize(("scene", "step", "coordinate", "answer", "name"), REVIEWED)
def test_the_reviews_omissions_read_left_out(scene, step, coordinate, answer, name):
    result = judge(step_problem(scene, step, coordinate), answer)
    said = unicodedata.normalize("NFC", result["mistake"]["name"])
    assert result["verdict"] == "incorrect" and said == unicodedata.normalize("NFC", name), said


def test_an_acceleration_carried_from_an_equation_says_left_out_before_where():
    # the coupled oscillators' ẍ₁ without the coupling spring's force: said where the piece went, then which equation
    # (a force on x₁ alone moves x₁ alone: its name says the force over the mass, and no equation)
    name = judge(step_problem("coupled-oscillators", "acceleration", "x1"), "-k/m*x1")["mistake"]["name"]
    assert name == "the coupling spring's force κ (x₂ − x₁)/m left out", name
    for scene, coordinate, typed in [("coupled-oscillators", "x2", "-(k+kappa)/m*x2"), ("rail-two-body", "x1", "k*(x2-x1)/m1")]:
        name = judge(step_problem(scene, "acceleration", coordinate), typed)["mistake"]["name"]
        assert "left out" in name and ("(in the equation" not in name or "left out (in the equation" in name), name


def test_a_piece_added_says_added():
    # ½ m (ẋ₁ + ẋ₂)²: a cross term the correct T has none of
    result = judge(step_problem("coupled-oscillators", "kinetic", None), "m*(x1_dot+x2_dot)**2/2")
    assert ADDED.search(result["mistake"]["name"]) and not OMITTED.search(result["mistake"]["name"]), result["mistake"]
