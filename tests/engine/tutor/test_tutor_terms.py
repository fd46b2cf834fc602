"""The tutor says a left-out term as mathematics, never as a list of its letters (issue 41, review student-k 3):
the coupled oscillators' κ x₂/m, the rail's −k l₀/m₁, the wedge's m Ẍ."""

from __future__ import annotations

import unicodedata
from functools import cache

import pytest

from app.engine.derivation.derive import derive
from app.engine.tutor.check import judge, problem
from app.scenes import SCENES

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all


@cache
def _problem(scene: str, step: str, coordinate: str | None):
    return problem(derive(SCENES[scene].system), step, coordinate)


@pytest.mark.parametrize(
    ("scene", "step", "coordinate", "answer", "name"),
    [
        ("coupled-oscillators", "acceleration", "x1", "-(k+kappa)/m*x1", "the term κ x₂/m left out"),
        ("rail-two-body", "acceleration", "x1", "k*(x2-x1)/m1", "the term −k l₀/m₁ left out"),
        ("movable-incline", "equation", "X", "M*X_ddot + m*D_ddot*cos(alpha)", "the term m Ẍ left out"),
    ],
)
def test_a_term_left_out_is_said_as_the_term(scene, step, coordinate, answer, name):
    result = judge(_problem(scene, step, coordinate), answer)
    assert result["verdict"] == "incorrect"
    said = unicodedata.normalize("NFC", result["mistake"]["name"]), unicodedata.normalize("NFC", result["hint"])
    assert said[0] == name
    assert name in said[1]


def test_an_extra_term_typed_without_a_fraction_is_said_as_a_term():
    # student-k 3, #127: no fraction typed, so no "numerator" and no "the denominator is right"
    pb = _problem("simple-pendulum", "acceleration", "theta")
    result = judge(pb, "-g*sin(theta)/R + theta_dot^2")
    said = unicodedata.normalize("NFC", result["mistake"]["name"] + " " + result["hint"])
    assert result["mistake"]["name"] == "an extra term θ̇² added, which the correct answer does not have"
    assert "numerator" not in said and "denominator" not in said
    # typed as one fraction, its numerator is the student's own and is named so
    typed = judge(pb, "(-g*sin(theta) + R*theta_dot^2)/R")
    assert typed["mistake"]["name"].startswith("the numerator R θ̇² − g sin(θ)")


def test_a_students_sum_is_quoted_term_by_term_not_regrouped():
    # student-k 3, #103: "m (R θ̈ + g θ̇ sin(θ)) R adds a torque …" quoted the student's sum regrouped
    result = judge(_problem("simple-pendulum", "equation", "theta"), "m*R^2*theta_ddot + m*g*R*sin(theta)*theta_dot")
    assert unicodedata.normalize("NFC", result["hint"]).startswith(
        unicodedata.normalize("NFC", "Check the units. m R² θ̈ + m g R θ̇ sin(θ) adds a torque (m R² θ̈)")
    )
