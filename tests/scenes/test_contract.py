"""The scene additions to the derivation JSON follow the contract."""

import pytest
import sympy as sp

from app.engine.parser.parse import parse_expression
from app.scenes import SCENES
from app.service.chapter.derivations import derivation, derivation_document
from tests.reference import numerically_equal
from tests.scenes.common import forces

SCENE_KEYS = {
    *("id", "title", "section", "summary", "statement", "figure", "coordinates", "parameters", "initial", "t_end"),
    *("panels", "beyond_chapter", "events", "family", "marks", "answers", "exact_frequency", "run_note"),
}


def state_names(doc):
    names = {f"{q}{s}": sp.Symbol(f"{q}{s}", real=True) for q in doc["coordinates"] for s in ("", "_dot")}
    names |= {p: sp.Symbol(p, real=True) for p in doc["parameters"]}
    names["t"] = sp.Symbol("t", real=True)
    return names


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_scene_block_and_errata(scene_id):
    doc = derivation_document(scene_id)
    s = SCENES[scene_id]
    assert set(doc["scene"]) == SCENE_KEYS
    assert doc["scene"]["panels"] == list(s.panels) and doc["scene"]["initial"] == s.initial
    # each answer the Results box states names steps the document has (issue 40)
    keys = [step["key"] for step in doc["steps"]]
    assert doc["scene"]["answers"] == list(s.answers)
    assert all(any(k == a or k.startswith(a + ":") for k in keys) for a in s.answers), (s.answers, keys)
    served = [{k: e[k] for k in ("chapter", "correct", "reason")} for e in doc["errata"]]
    assert served == [{"chapter": e.chapter, "correct": e.correct, "reason": e.reason} for e in s.errata]
    # every formula typeset; a quotation of the chapter's words (not a formula) is prose, never typeset
    assert all((e["chapter_words"] or e["chapter_latex"]) and e["correct_latex"] for e in doc["errata"])
    assert [e["chapter_words"] for e in doc["errata"]] == [e.words for e in s.errata]
    assert all(not e["chapter_latex"] for e in doc["errata"] if e["chapter_words"])


@pytest.mark.slow
@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_constraint_forces_are_functions_of_the_state(scene_id):
    doc = derivation_document(scene_id)
    served = doc["constraint_forces"]
    assert [f["name"] for f in served] == [c.name for c in SCENES[scene_id].system.constraints]
    names = state_names(doc)
    titles = [step["title"] for step in doc["steps"]]
    assert ("Forces of constraint" in titles) == bool(served)
    for f, engine in zip(served, forces(scene_id), strict=True):
        assert {"name", "sympy", "latex", "convention", "slack_when_negative"} <= set(f)
        assert isinstance(f["slack_when_negative"], bool) and f["convention"]
        # parses with the state names alone: no acceleration is left in it
        expr = sp.sympify(f["sympy"], locals=names)
        assert expr.free_symbols <= set(names.values())
        assert numerically_equal(expr, engine.force, sorted(expr.free_symbols | {names["t"]}, key=str))
        # and with the engine's safe parser, which is how the numerics reads it
        assert parse_expression(f["sympy"], derivation(scene_id).table.namespace()) == expr


@pytest.mark.parametrize("scene_id", sorted(SCENES))
def test_transformed_only_for_the_rail(scene_id):
    doc = derivation_document(scene_id)
    if scene_id != "rail-two-body":
        assert doc["transformed"] is None
        return
    tr = doc["transformed"]
    assert tr["coordinates"] == ["X", "x"] and tr["cyclic"] == ["X"]
    for key in ("definitions", "inverse", "lagrangian", "accelerations", "momenta", "conserved", "reduced_mass"):
        assert tr[key], key
    m1, m2 = sp.symbols("m1 m2", real=True)
    reduced = sp.sympify(tr["reduced_mass"]["sympy"], locals={"m1": m1, "m2": m2})
    assert sp.simplify(reduced - m1 * m2 / (m1 + m2)) == 0
    p_X = next(c for c in tr["conserved"] if c["name"] == "p_X")
    assert p_X["original"]["sympy"] == "m1*x1_dot + m2*x2_dot"
    titles = [step["title"] for step in doc["steps"]]
    assert {"Change of coordinates", "Inverse map", "Inertia of the new coordinates"} <= set(titles)
