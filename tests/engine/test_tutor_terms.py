"""The tutor says a left-out term as mathematics, never as a list of its letters (issue 41, review student-k 3):
the coupled oscillators' κ x₂/m, the rail's −k l₀/m₁, the wedge's m Ẍ."""

from __future__ import annotations

import unicodedata
from functools import cache

import pytest

from app.engine.check import judge, problem
from app.engine.derive import derive
from app.scenes import SCENES


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
