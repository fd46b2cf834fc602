"""The derivation's first step states Hamilton's principle (with the forces' work where forces act)."""

import sympy as sp

from app.engine.document.action_step import FORCED_TITLE, TITLE
from app.service.chapter.derivations import derivation_document


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
    # prof-e 10: the title does not claim S is stationary over a text that says S alone is not
    assert first["title"] == FORCED_TITLE and "stationary" not in first["title"]


def test_a_kinetic_focus_is_possible_only_where_the_jacobi_equation_can_turn_back():
    # L at most linear in the coordinates, no coordinate-velocity product, a constant mass matrix: the Jacobi
    # fields are η = a t and no focus exists (prof-c 19, 26: the panel promised one on the helix and the incline)
    never = {"helix-bead", "incline-block", "pulley", "movable-incline"}
    for scene in ("helix-bead", "incline-block", "pulley", "movable-incline", "simple-pendulum", "tabletop-spring",
                  "rail-two-body", "spherical-pendulum"):  # fmt: skip
        doc = derivation_document(scene)
        assert doc["kinetic_focus_possible"] is (scene not in never), scene
        # the derivation's first step says the same as the verdict the action panel reads
        said = doc["steps"][0]["explanation"]
        denies = any(w in said for w in ("no kinetic focus", "least for any time", "for every duration"))
        assert denies is (scene in never), (scene, said)
