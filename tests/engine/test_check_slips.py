"""The tutor against realistic slips (tests/engine/slip_corpus.py): nine in ten named, none misnamed,
and every correct answer in an unusual form accepted."""

from __future__ import annotations

import re
import unicodedata
from functools import cache
from typing import Any

import pytest

from app.engine.check import judge, problem
from app.engine.derive import Derivation, derive
from app.engine.mistakes import POINTERS
from app.scenes import SCENES
from app.scenes.types import Parameter, Particle, System
from tests.engine.slip_corpus import CORRECT, SLIPS, SYSTEMS


def system_of(spec: dict) -> System:
    """The engine's declaration of a system given in the API's request shape (with units)."""
    return System(
        coordinates=tuple(spec["coordinates"]),
        parameters=tuple(
            Parameter(p["name"], p["value"], unit=p.get("unit", ""), min=p["min"], max=p.get("max"))
            for p in spec["parameters"]
        ),
        particles=tuple(
            Particle(p["mass"], tuple(p["position"]), p.get("label", "")) for p in spec.get("particles", [])
        ),
        kinetic=spec.get("kinetic"),
        potential=spec.get("potential"),
        lagrangian=spec.get("lagrangian"),
        forces=dict(spec.get("forces", {})),
    )


@cache
def derivation(name: str) -> Derivation:
    return derive(system_of(SYSTEMS[name]) if name in SYSTEMS else SCENES[name].system)


@cache
def step_problem(name: str, step: str, coordinate: str | None):
    return problem(derivation(name), step, coordinate)


def words(result: dict[str, Any]) -> str:
    """The key, name and hint of a diagnosis, as one text to search."""
    m = result["mistake"] or {"key": "", "name": ""}
    return unicodedata.normalize("NFC", f"{m['key']} | {m['name']} | {result['hint']}")


def outcome(slip: tuple) -> tuple[str, dict[str, Any]]:
    """'named' (the mistake the teacher names), 'misnamed' (another one), or 'general' (the step's rule)."""
    system, step, coordinate, answer, named = slip
    result = judge(step_problem(system, step, coordinate), answer)
    assert result["verdict"] == "incorrect", (slip, result)
    if result["mistake"] is None and result["hint"] in POINTERS.values():
        return "general", result
    found = re.search(unicodedata.normalize("NFC", named), words(result), re.IGNORECASE)
    return ("named" if found else "misnamed"), result


def test_the_corpus_spans_every_scene_and_four_typed_systems():
    assert len(SLIPS) >= 80 and len(CORRECT) >= 40
    assert {s[0] for s in SLIPS} == set(SCENES) | set(SYSTEMS)
    assert {c[0] for c in CORRECT} == set(SCENES) | set(SYSTEMS)


@pytest.mark.parametrize(("system", "step", "coordinate", "answer"), CORRECT, ids=[f"{c[0]}-{c[1]}-{i}" for i, c in enumerate(CORRECT)])
def test_every_correct_answer_in_an_unusual_form_is_accepted(system, step, coordinate, answer):
    result = judge(step_problem(system, step, coordinate), answer)
    assert result["verdict"] in ("correct", "equivalent"), result


@pytest.mark.parametrize(
    ("system", "step", "coordinate", "answer"),
    [
        ("simple-pendulum", "equation", "theta", "theta_ddot + (g/R)*sin(theta)"),
        ("rod-pendulum", "equation", "theta", "theta_ddot + 3*g*sin(theta)/(2*l)"),
        ("pulley", "equation", "y1", "(4*m1 + M)*y1_ddot + M*y2_ddot + 4*g*m1 - 2*M*g"),
    ],
)
def test_the_pages_own_form_and_any_constant_multiple_is_correct(system, step, coordinate, answer):
    result = judge(step_problem(system, step, coordinate), answer)
    assert result["verdict"] == "correct" and result["message"].startswith("Correct:"), result


def test_an_equation_multiplied_by_a_coordinate_is_equivalent_and_says_where():
    result = judge(
        step_problem("spherical-pendulum", "equation", "phi"), "sin(theta)*phi_ddot + 2*cos(theta)*theta_dot*phi_dot"
    )
    assert result["verdict"] == "equivalent" and "depends on the coordinates" in result["message"]


@pytest.mark.parametrize("slip", SLIPS, ids=[f"{s[0]}-{s[1]}-{i}" for i, s in enumerate(SLIPS)])
def test_a_named_slip_is_named_rightly(slip):
    kind, result = outcome(slip)
    assert kind != "misnamed", (slip, words(result))


@pytest.mark.slow
def test_nine_slips_in_ten_are_named():
    kinds = [outcome(slip)[0] for slip in SLIPS]
    named = kinds.count("named")
    assert named >= 0.9 * len(SLIPS), f"{named}/{len(SLIPS)} named"
