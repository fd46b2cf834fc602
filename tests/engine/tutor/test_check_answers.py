"""An answer read once (app/engine/tutor/check_answers.py): what the web process reads is what the worker builds, with the
refusals the worker's own reading would give."""

from __future__ import annotations

import pickle

import pytest

from app.engine.parser.parse import Parsed
from app.engine.tutor.check import CheckError, allowed_names, check_answer, name_kinds, parse_answer, problem
from tests.engine.declared import derivation


def outcome(work) -> tuple:
    try:
        return ("built", work())
    except CheckError as exc:
        return ("refused", str(exc), exc.field, exc.part, exc.start, exc.end)


def test_what_is_read_is_checked_against_the_steps_names():
    kinds = name_kinds(("theta",), ("m", "g", "R"), ("p_phi",))
    parsed = check_answer(" m*g*R*cos(theta)", "potential", kinds)
    assert isinstance(parsed, Parsed) and parsed.text == " m*g*R*cos(theta)"
    assert parsed.names == frozenset(allowed_names("potential", kinds)) == {"R", "g", "m", "t", "theta"}


@pytest.mark.slow
@pytest.mark.parametrize(
    ("step", "coordinate", "answer"),
    [
        ("kinetic", None, "m*R**2*(theta_dot**2 + sin(theta)**2*phi_dot**2)/2"),
        ("equation", "theta", "theta_ddot - sin(theta)*cos(theta)*phi_dot**2 + g*sin(theta)/R"),
        ("potential", None, "1/(theta - theta)"),
        ("kinetic", None, "sqrt(-1 - theta_dot**2)"),
    ],
)
def test_a_scene_answer_read_in_the_web_process_builds_as_reading_it_in_the_worker(step, coordinate, answer):
    pb = problem(derivation("spherical-pendulum"), step, coordinate, mistakes=False)
    sent = pickle.loads(pickle.dumps(check_answer(answer, step, pb.kinds)))
    assert outcome(lambda: parse_answer(pb, sent)) == outcome(lambda: parse_answer(pb, answer))


@pytest.mark.slow
def test_a_declared_systems_answer_is_held_to_the_momenta_the_derivation_finds_conserved():
    """Before deriving, the web process lets an ω² name the momentum of every coordinate; the spring rod's r is not
    cyclic, so the worker refuses p_r as reading the text against the problem's names does, word for word."""
    pb = problem(derivation("spring-rod"), "omega_squared", mistakes=False)
    web = name_kinds(("r",), ("m", "k", "a", "w"), ("p_r",))
    for answer in ("k/m - w**2 + 0*p_r", "  k/m - p_r**2"):
        refused = outcome(lambda a=answer: parse_answer(pb, check_answer(a, "omega_squared", web)))
        assert refused == outcome(lambda a=answer: parse_answer(pb, a))
        assert refused[0] == "refused" and refused[1].startswith("answer: unknown name (allowed here: a, k, m, r, w, pi)")
        assert refused[3] == "p_r" and answer[refused[4] : refused[5]] == "p_r"
    right = parse_answer(pb, check_answer("k/m - w**2", "omega_squared", web))
    assert outcome(lambda: right) == outcome(lambda: parse_answer(pb, "k/m - w**2"))
