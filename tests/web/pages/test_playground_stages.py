"""/playground in two stages (issue 35): the equations first, then the whole document at ``stage=whole``."""

from __future__ import annotations

import json
import re
from urllib.parse import urlencode

import pytest

from app.engine.document.model import Equation, FirstStage, Pair, Pending
from app.service.users.user_checks import checked, spec_key
from app.web.pages.playground_form import form_of, query_of, spec_of
from app.web.pages.playground_stages import first_view, whole_href

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

TRIPLE = {
    "coordinates": ["a", "b", "c"],
    "parameters": [{"name": "m", "value": 1.0, "unit": "kg"}, {"name": "l", "value": 1.0, "unit": "m"},
                   {"name": "g", "value": 9.81, "unit": "m/s^2"}],
    "particles": [
        {"mass": "m", "position": ["l*sin(a)", "0", "-l*cos(a)"]},
        {"mass": "m", "position": ["l*sin(a) + l*sin(b)", "0", "-l*cos(a) - l*cos(b)"]},
        {"mass": "m", "position": ["l*sin(a) + l*sin(b) + l*sin(c)", "0", "-l*cos(a) - l*cos(b) - l*cos(c)"]},
    ],
    "potential": "-m*g*l*(3*cos(a) + 2*cos(b) + cos(c))",
}  # fmt: skip
# a spring no other test derives, so that no cache holds its whole document
SPRING = {
    "coordinates": ["x"],
    "parameters": [{"name": "m", "value": 1.25, "unit": "kg"}, {"name": "k", "value": 3.5, "unit": "N/m"}],
    "kinetic": "m*x_dot**2/2",
    "potential": "k*x**2/2",
}


def _address(spec, **extra) -> str:
    return "/playground?" + urlencode({**query_of(form_of(spec)), **extra}, doseq=True)


def test_the_page_shows_the_equations_first_then_the_whole_derivation(client, services):
    first = client.get(_address(TRIPLE))
    assert first.status_code == 200
    html = first.text
    # the equations and the mass matrix (the accelerations stay M⁻¹f for a chain), and what is still to come
    assert 'data-stage="equations"' in html and "Still working on:" in html
    assert "the step-by-step derivation" in html and "normal modes" in html
    assert html.count('<li><div class="math math-display"') >= 3 + 1 + 3  # three equations, M q̈ = f, three f
    assert "\\mathcal{M} = \\begin{pmatrix}" in html
    assert 'id="simulation"' not in html and '<li class="step' not in html
    # the address of the rest, and a link to it for a reader without JavaScript
    href = re.search(r'data-whole-url="([^"]+)"', html)[1].replace("&amp;", "&")
    assert href.endswith("&stage=whole#outcome") and "<noscript><a href=" in html
    whole = client.get(href.split("#")[0])
    assert whole.status_code == 200
    assert 'data-stage="whole"' in whole.text and 'id="simulation"' in whole.text
    assert whole.text.count('<li class="step') >= 8 and "Still working on" not in whole.text
    # once the whole document is cached, the page shows it at once
    assert services.users.derivations.get(spec_key(checked(spec_of(form_of(TRIPLE))))) is not None
    assert 'data-stage="whole"' in client.get(_address(TRIPLE)).text


def test_a_refusal_of_the_first_stage_stays_at_its_field(client):
    bad = {**SPRING, "potential": "k*x**2/2 + sin("}
    response = client.get(_address(bad))
    assert response.status_code == 422
    assert 'aria-invalid="true"' in response.text and 'id="f-U-error"' in response.text
    assert 'id="derived"' not in response.text


def test_the_whole_stage_answers_a_refusal_as_the_page_does(client):
    """What the page's script copies into the live page when the rest is refused: the box and the field's note."""
    bad = {**SPRING, "kinetic": "m*x_dot**2/2 + (("}
    refused = client.get(_address(bad, stage="whole"))
    assert refused.status_code == 422
    assert 'id="form-error"' in refused.text and 'id="f-T-error"' in refused.text and 'id="derived"' not in refused.text


def test_the_first_view_lists_what_is_pending_and_links_to_the_rest():
    doc = FirstStage.model_construct(
        coordinates=["x"],
        equations_of_motion=[Equation.model_construct(coordinate="x", latex="m \\ddot{x} + k x = 0", divided_by=None)],
        accelerations={"x": Pair.model_construct(latex="- \\frac{k x}{m}")},
        mass_matrix=[[Pair.model_construct(latex="m")]],
        forcing=[],
        skipped=[],
        pending=[Pending(member="steps", name="the steps"), Pending(member="hamilton", name="Hamilton's equations"),
                 Pending(member="normal_modes", name="the normal modes")],
    )  # fmt: skip
    view = first_view(doc, whole_href("q=x&stage=whole&T=m"), "ab" * 32)
    assert view["pending"] == "the steps, Hamilton's equations, the normal modes and the simulation"
    assert view["accelerations"] == ["\\ddot{x} = - \\frac{k x}{m}"] and view["mass_matrix"] is None
    assert view["whole_href"] == "/playground?q=x&T=m&stage=whole#outcome"
    # the whole derivation's progress and its stop, by its key
    assert view["progress_url"] == "/api/derive/progress/" + "ab" * 32
    assert view["cancel_url"] == "/api/derive/cancel/" + "ab" * 32


def test_the_api_answers_the_equations_first_then_the_same_members_from_the_whole_document(client):
    spec = {**TRIPLE, "parameters": [{**p, "value": 9.79} if p["name"] == "g" else p for p in TRIPLE["parameters"]]}
    first = client.post("/api/derive/equations", json=spec)
    assert first.status_code == 200
    doc = first.json()
    assert doc["stage"] == "equations" and len(doc["equations_of_motion"]) == 3
    assert {p["member"] for p in doc["pending"]} >= {"steps", "hamilton", "normal_modes"}
    # a chain's accelerations stay M⁻¹f: M and f instead, and the note saying why
    assert doc["accelerations"] == {} and len(doc["mass_matrix"]) == 3 and len(doc["forcing"]) == 3
    assert [s["member"] for s in doc["skipped"]] == ["accelerations"]
    whole = client.post("/api/derive", json=spec).json()
    # the first stage's equations are the whole document's (the same display budget's rows for a chain)
    assert [e["sympy"] for e in doc["equations_of_motion"]] == [e["sympy"] for e in whole["equations_of_motion"]]
    again = client.post("/api/derive/equations", json=spec).json()
    assert again["stage"] == "whole" and again["pending"] == [] and again["skipped"] == whole["skipped"]
    assert again["equations_of_motion"] == whole["equations_of_motion"]


def test_the_api_refuses_the_equations_of_a_bad_system_where_it_is_wrong(client):
    refused = client.post("/api/derive/equations", json={**SPRING, "potential": "k*x**2/2 + sin("})
    assert refused.status_code == 422
    assert refused.json()["loc"] == ["body", "potential"] and "sin(" in refused.json()["part"]


def test_the_rest_is_asked_for_with_the_forms_own_address(client):
    """A system given as ?system=JSON (or the default system, with no query at all) is asked for again by the
    form's fields, so that stage=whole derives the same system."""
    import json

    spec = {**SPRING, "parameters": [{**p, "value": 4.75} if p["name"] == "k" else p for p in SPRING["parameters"]]}
    html = client.get("/playground?" + urlencode({"system": json.dumps(spec)})).text
    href = re.search(r'data-whole-url="([^"]+)"', html)[1].replace("&amp;", "&")
    assert "system=" not in href and "q=x" in href and "pv=4.75" in href
    whole = client.get(href.split("#")[0])
    assert whole.status_code == 200 and 'data-stage="whole"' in whole.text


def _rows(equation: dict, coordinates: list[str]) -> tuple[list, object]:
    """An equation as the API prints it (its scaled residual = 0), times the factor it says it was divided by:
    its accelerations' coefficients and the rest, taken to the right (one row of M q̈ = f)."""
    import sympy as sp

    factor = sp.sympify(equation["divided_by"]["sympy"]) if equation["divided_by"] else sp.Integer(1)
    residual = sp.expand(factor * sp.sympify(equation["sympy"]))
    accelerations = [sp.Symbol(f"{q}_ddot") for q in coordinates]
    coefficients = [residual.coeff(a) for a in accelerations]
    rest = residual.subs({a: 0 for a in accelerations})
    return coefficients, -rest


def test_each_printed_equation_names_its_factor_and_times_it_gives_the_rows_of_m_and_f(client):
    import sympy as sp

    from app.web.api.examples_user import DOUBLE_PENDULUM

    # the double pendulum with its own masses and lengths: its equations are divided by different factors
    for spec, factors in (
        (DOUBLE_PENDULUM, {"theta1": "l1", "theta2": "l2*m2"}),
        (TRIPLE, dict.fromkeys("abc", "l*m")),
    ):
        answer = client.post("/api/derive", json=spec)
        assert answer.status_code == 200, answer.text
        doc = answer.json()
        q = doc["coordinates"]
        assert {e["coordinate"]: e["divided_by"]["sympy"] for e in doc["equations_of_motion"]} == factors
        for k, equation in enumerate(doc["equations_of_motion"]):
            coefficients, rest = _rows(equation, q)
            row = [sp.sympify(x["sympy"]) for x in doc["mass_matrix"][k]]
            assert all(sp.simplify(a - b) == 0 for a, b in zip(coefficients, row, strict=True)), (equation, row)
            assert sp.simplify(rest - sp.sympify(doc["forcing"][k]["sympy"])) == 0


def test_the_first_stage_says_how_the_equations_are_scaled_beside_the_mass_matrix(client):
    # the chain in coordinates of its own: no other test derives it, so no cache holds its whole document and the
    # page opens on its first stage (the triple's whole document is cached by the tests above)
    own = json.loads(json.dumps(TRIPLE).replace('"a"', '"u"').replace("(a)", "(u)").replace("cos(b)", "cos(v)")
                     .replace("sin(b)", "sin(v)").replace('"b"', '"v"').replace("cos(c)", "cos(w)")
                     .replace("sin(c)", "sin(w)").replace('"c"', '"w"'))
    assert own["coordinates"] == ["u", "v", "w"] and "a)" not in json.dumps(own)
    html = client.get(_address(own)).text
    words = re.sub(r"\s+", " ", re.sub(r"<[^>]+>", " ", html))
    scaled = re.search(r'<p class="reason" id="equations-scaled">(.*?)</p>', html, re.S)
    assert scaled is not None
    for coordinate in ("u", "v", "w"):
        assert f'the <span class="math" data-tex="{coordinate}">' in scaled[1]
    assert scaled[1].count('data-tex="m l"') == 3  # each factor typeset from the API's LaTeX
    assert "Each equation is shown divided by the factor common to its terms:" in words
    assert "are those of the equations undivided: each row is that equation as shown above times the factor" in words
