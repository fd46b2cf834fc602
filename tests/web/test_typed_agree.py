"""The corpus of expressions as students type them (tests/data/typed_expressions.json) through the three places
that read one: the checker (POST /api/check), the typeset preview (POST /api/typeset) and the playground
(POST /api/derive/equations, the playground's first stage, with the text as a generalized force).  All three
read each text as meant, or refuse it with the same words, the same span and the same two readings."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp

from app.engine.tutor.check import check_answer
from app.engine.tutor.typed_latex import typed_latex
from app.service.tutor.typesetting import system_kinds

DATA = json.loads((Path(__file__).parents[1] / "data" / "typed_expressions.json").read_text())
COORDINATES, PARAMETERS = DATA["coordinates"], DATA["parameters"]
# every name is a real symbol, as the engine declares them; the server's SymPy strings are ours to read
SYMBOLS = {n: sp.Symbol(n, real=True) for n in [*COORDINATES, *(f"{q}_dot" for q in COORDINATES), *PARAMETERS, "t"]}
KINETIC = "m (θ'^2 + x'^2 + θ1'^2 + φ'^2)/2"  # typed as a student types it too
SYSTEM = {
    "coordinates": COORDINATES,
    "parameters": [{"name": p, "value": 1.5 + i / 4} for i, p in enumerate(PARAMETERS)],
    "kinetic": KINETIC,
    "potential": "k x^2/2",
}
LAGRANGIAN = (
    SYMBOLS["m"] * sum(SYMBOLS[f"{q}_dot"] ** 2 for q in COORDINATES) / 2 - SYMBOLS["k"] * SYMBOLS["x"] ** 2 / 2
)


def meant(text: str) -> sp.Expr:
    return sp.sympify(text, locals=SYMBOLS)


def _id(case: dict) -> str:
    return case["typed"].encode("unicode_escape").decode()


def _refusal(answer) -> tuple:
    body = answer.json()
    detail = body["detail"].split(": ", 1)[1]  # without the field's name ("answer: ", "forces.x: ")
    readings = body.get("readings")
    return answer.status_code, detail, body.get("start"), body.get("end"), tuple(readings) if readings else None


@pytest.mark.slow
@pytest.mark.parametrize("case", DATA["corpus"], ids=_id)
def test_checker_preview_and_playground_read_alike(client, case):
    text = case["typed"]
    preview = client.post(
        "/api/typeset", json={"text": text, "step": "lagrangian", "coordinates": COORDINATES, "parameters": PARAMETERS}
    )
    checked = client.post("/api/check", json={"step": "lagrangian", "answer": text, "system": SYSTEM})
    playground = client.post("/api/derive/equations", json={**SYSTEM, "forces": {"x": text}})
    if "reads" not in case:
        refusals = {_refusal(preview), _refusal(checked), _refusal(playground)}
        says = case.get("refused") or f"could be read as {case['readings'][0]} or as {case['readings'][1]}"
        for status, detail, start, end, readings in refusals:
            assert status == 422 and says in detail, (status, detail)
            assert text[start:end] and readings == (tuple(case["readings"]) if "readings" in case else None)
        # the same part refused, at the same place, with the same readings; the tutor (the checker) says it in its
        # own words around the parser's, and a step's name rules and a declaration's differ in words only
        assert len({r[2:] for r in refusals}) == 1, refusals
        return
    expr = meant(case["reads"])
    assert preview.status_code == 200, preview.text
    # the preview: what it read, printed as typed (app/engine/tutor/typed_latex.py), never rewritten
    kinds = system_kinds(tuple(COORDINATES), tuple(PARAMETERS))
    assert preview.json()["latex"] == typed_latex(check_answer(text, "lagrangian", kinds))
    # the checker: its verdict on L, and the difference it shows, give back what it read
    assert checked.status_code == 200, checked.text
    # the checker: the difference it shows (answer − L, less an additive constant, which L may carry) gives
    # back what it read, up to that constant
    verdict = checked.json()
    read = LAGRANGIAN + (meant(verdict["reveal"]["difference"]["sympy"]) if verdict["verdict"] == "incorrect" else 0)
    moving = {SYMBOLS[n] for n in [*COORDINATES, *(f"{q}_dot" for q in COORDINATES), "t"]}
    assert not sp.simplify(read - expr).free_symbols & moving, (verdict, expr)
    # the playground: m x'' = Q, the generalized force as read
    assert playground.status_code == 200, playground.text
    ddot = playground.json()["accelerations"]["x"]["sympy"]
    acceleration = -SYMBOLS["k"] * SYMBOLS["x"] / SYMBOLS["m"] + expr / SYMBOLS["m"]
    assert sp.simplify(meant(ddot) - acceleration) == 0, (ddot, expr)
