"""The derivation's first step states Hamilton's principle (with the forces' work where forces act)."""

import sympy as sp

from app.engine.action_step import TITLE
from app.service.derivations import derivation_document


def test_first_step_is_the_action_with_L_in_it():
    doc = derivation_document("simple-pendulum")
    first = doc["steps"][0]
    assert first["title"] == TITLE and r"\delta S" in first["latex"]
    integral = sp.sympify(first["sympy"])
    assert isinstance(integral, sp.Integral)
    lagrangian = next(s for s in doc["steps"] if s["title"] == "Lagrangian")
    assert sp.simplify(integral.function - sp.sympify(lagrangian["sympy"])) == 0


def test_forces_join_the_principle_as_their_work():
    first = derivation_document("damped-pendulum")["steps"][0]
    assert r"Q\cdot\delta q" in first["latex"]
    # δS = −∫ Q·δq dt: both rows are "left side &= …", so their = signs line up (prof-c S12)
    rows = first["latex"].removeprefix(r"\begin{aligned}").removesuffix(r"\end{aligned}").split(r" \\ ")
    assert [r.split("&=")[0].strip() for r in rows] == ["S[q]", r"\delta S"]
    assert r"Q\cdot" not in derivation_document("simple-pendulum")["steps"][0]["latex"]
