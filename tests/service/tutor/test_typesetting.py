"""The typesetting service on the shared corpus of answers (tests/data/expressions.json): the engine's gates decide."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from app.engine.tutor.answer_sides import read_answer
from app.engine.tutor.check import CheckError, check_answer
from app.service.tutor.typesetting import scene_kinds, system_kinds, typeset_job
from app.service.users.user_checks import InvalidSystem

CORPUS = json.loads((Path(__file__).parents[2] / "data" / "expressions.json").read_text())


@pytest.fixture(scope="module")
def kinds():
    return scene_kinds(CORPUS["scene"])


def read(text: str, kinds: dict[str, str]) -> str:
    """The LaTeX of an answer by the route's two stages (the web process's gates, then the worker job's)."""
    try:
        parsed = read_answer(text, CORPUS["step"], None, kinds)[0]
    except CheckError as exc:
        raise InvalidSystem(str(exc)) from None
    return json.loads(typeset_job(parsed))["latex"]


@pytest.mark.parametrize("text", CORPUS["accepted"])
def test_the_corpus_answers_it_accepts_are_typeset(text, kinds):
    latex = read(text, kinds)
    assert latex and "**" not in latex and "*" not in latex  # printed as a textbook prints it


@pytest.mark.parametrize("case", CORPUS["refused"], ids=lambda case: case["text"])
def test_the_corpus_answers_it_refuses_carry_the_parsers_message(case, kinds):
    with pytest.raises(InvalidSystem) as refused:
        read(case["text"], kinds)
    assert case["says"] in str(refused.value) and str(refused.value).startswith("answer: ")


def test_names_print_as_the_engine_writes_them(kinds):
    assert read("m1*l1**2*theta1_dot**2/2", kinds) == r"\frac{m_{1} l_{1}^{2} \dot{\theta}_{1}^{2}}{2}"


def test_the_preview_keeps_what_was_typed_never_distributing_a_half(kinds):
    # student-c's report, 18: ½(m₁ + m₂) was shown as (m₁/2 + m₂/2)
    assert read("1/2*(m1+m2)*l1**2*theta1_dot**2", kinds) == (
        r"\frac{1}{2} \left(m_{1} + m_{2}\right) l_{1}^{2} \dot{\theta}_{1}^{2}"
    )


def test_a_declared_systems_names_are_its_coordinates_and_parameters():
    kinds = system_kinds(("x", "phi"), ("m", "k"))
    assert kinds["x_dot"] == "velocity" and kinds["p_phi"] == "momentum" and kinds["k"] == "parameter"
    assert json.loads(typeset_job(check_answer("m*x_dot**2/2 + k*x**2/2", "lagrangian", kinds)))["latex"] == (
        r"\frac{m \dot{x}^{2}}{2} + \frac{k x^{2}}{2}"
    )
