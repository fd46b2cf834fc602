"""/playground on the server: the system in the query string, derivation rendered, refusals located."""

import json
import re
import unicodedata
from urllib.parse import urlencode

import pytest
from starlette.datastructures import QueryParams

from app.web.api.examples_user import DOUBLE_PENDULUM, FORCED_SPRING, SPINNING_HOOP
from app.web.pages.playground import MAX_QUERY
from app.web.pages.playground_form import (
    JUST_ABOVE_ZERO,
    Form,
    form_of,
    positive_by_nature,
    query_of,
    read_form,
    spec_of,
)
from app.web.schemas.user import SystemSpec


@pytest.mark.parametrize("spec", [FORCED_SPRING, DOUBLE_PENDULUM, SPINNING_HOOP], ids=["spring", "double", "hoop"])
def test_the_address_holds_the_whole_system(spec):
    """API request -> form -> query string -> form -> API request gives the request back."""
    query = QueryParams(urlencode(query_of(form_of(spec)), doseq=True))
    expected = SystemSpec.model_validate(spec).to_spec()
    again = spec_of(read_form(query))
    if "particles" in spec:  # the form always writes all three components
        for p in expected["particles"]:
            p["position"] = p["position"] + ["0"] * (3 - len(p["position"]))
    for p in expected["parameters"]:  # the form's lowest value of a positive quantity left empty
        if p.get("min") is None and positive_by_nature(p["name"], p.get("unit") or ""):
            p["min"] = JUST_ABOVE_ZERO
    assert again == expected


def test_positive_quantities_default_to_just_above_zero():
    form = Form(coordinates="x", parameters=[
        {"name": "m", "value": "1"}, {"name": "k", "value": "2", "unit": "N/m"}, {"name": "c", "value": "3", "unit": "kg"},
        {"name": "F", "value": "0.5", "unit": "N"}, {"name": "w", "value": "1"},
    ], kinetic="m*x_dot**2/2", potential="k*x**2/2")  # fmt: skip
    lowest = {p["name"]: p.get("min") for p in spec_of(form)["parameters"]}
    assert lowest == {"m": JUST_ABOVE_ZERO, "k": JUST_ABOVE_ZERO, "c": JUST_ABOVE_ZERO, "F": None, "w": None}


def test_an_empty_form_says_what_to_enter(client):
    html = client.get("/playground?q=&form=energies&T=&U=").text
    assert 'id="outcome"' in html and "Nothing to derive yet" in html and "generalized coordinates" in html
    assert 'action="/playground#outcome"' in html


@pytest.mark.slow
def test_derive_lands_on_the_result_and_labels_are_not_doubled(client):
    html = client.get("/playground?" + urlencode({**query_of(form_of(SPINNING_HOOP)), "stage": "whole"}, doseq=True)).text
    # the anchor "Derive" lands on sits just before the simulation
    assert html.index('id="outcome"') < html.index('id="simulation"')
    labels = re.findall(r'<span class="sym">([^<]*)</span> <span class="desc">([^<]*)</span>', html)
    assert labels and all(sym.strip() != desc.strip() for sym, desc in labels)


@pytest.mark.slow
def test_the_page_derives_and_renders_the_steps(client):
    response = client.get("/playground?" + urlencode({**query_of(form_of(SPINNING_HOOP)), "stage": "whole"}, doseq=True))
    assert response.status_code == 200
    html = response.text
    assert html.count('<li class="step') >= 8
    assert 'data-simulate-url="/api/simulate"' in html
    data = json.loads(re.search(r'<script type="application/json" id="scene-data">(.*?)</script>', html, re.S)[1])
    # given by L alone, with no particle positions: no invented picture, and the page says so
    assert data["coordinates"] == ["theta"] and data["mechanism"]["none"] and data["mechanism"]["points"] == []
    assert "No picture: this system is given by its Lagrangian or its energies alone" in html
    system = json.loads(re.search(r'id="playground-system">(.*?)</script>', html, re.S)[1])
    assert system["lagrangian"] == SPINNING_HOOP["lagrangian"]


@pytest.mark.slow
def test_the_double_pendulum_is_drawn_with_a_pivot_and_two_rods(client):
    response = client.get("/playground?" + urlencode({**query_of(form_of(DOUBLE_PENDULUM)), "stage": "whole"}, doseq=True))
    data = json.loads(
        re.search(r'<script type="application/json" id="scene-data">(.*?)</script>', response.text, re.S)[1]
    )
    mech = data["mechanism"]
    labels = [p["label"] for p in mech["points"]]
    assert labels == ["mass 1", "mass 2", "pivot"] and not mech["points"][2]["mass"]
    rods = sorted((link["from"], link["to"]) for link in mech["links"] if link["style"] == "rod")
    assert rods == [(0, 1), (2, 0)]  # mass 1 - mass 2 and pivot - mass 1 (indices of points)
    assert "each distance that stays fixed drawn as a rod (whatever holds it there" in mech["caption"]
    assert "hoop the bead rides on) and the fixed pivot" in mech["caption"]


@pytest.mark.slow
def test_system_json_in_the_address_works_too(client):
    response = client.get("/playground?" + urlencode({"system": json.dumps(FORCED_SPRING)}))
    assert response.status_code == 200 and 'value="x"' in response.text


def test_an_empty_form_derives_nothing(client):
    response = client.get("/playground?new")
    assert response.status_code == 200
    assert 'id="derivation"' not in response.text and 'id="form-error"' not in response.text


@pytest.mark.parametrize(
    ("query", "field", "words"),
    [
        ({"q": "x", "form": "energies", "T": "x_dot**2", "U": "2^x^2"}, "f-U", "2^(x^2)"),
        (
            {"q": "x", "form": "energies", "pn": "k", "pv": "lots", "T": "x_dot**2", "U": "k*x"},
            "f-param-0-value",
            "not a number",
        ),
        ({"q": "x", "form": "energies", "pn": "sin", "pv": "1", "T": "x_dot**2", "U": "0"}, "f-param-0-name", "reserved"),
        # a blank value is an error at its field, never a silent 1; a row without a name says so in the form's words
        ({"q": "x", "form": "energies", "pn": "k", "T": "x_dot**2", "U": "k*x"}, "f-param-0-value", "parameter 1 (k): a value is needed"),
        ({"q": "x", "form": "energies", "pv": "2", "T": "x_dot**2", "U": "x"}, "f-param-0-name", "parameter 1: a name is needed"),
        (
            {"q": "x", "form": "particles", "m": "1", "x": "x", "z": "__class__", "U": "0"},
            "f-particle-0-z",
            "unknown name",
        ),
        (
            {"q": "x", "form": "lagrangian", "L": "x_dot**2", "fq": "x", "fQ": "eval(x)"},
            "f-force-0-expression",
            "functions",
        ),
        ({"q": "x", "form": "lagrangian", "L": "x_dot*x"}, "f-L", "mass matrix"),
        ({"q": "", "form": "lagrangian", "L": "x_dot**2"}, "f-coordinates", "add at least one coordinate"),
        ({"system": "{not json"}, "f-coordinates", "not valid JSON"),
    ],
)
def test_refusals_point_at_the_field(client, query, field, words):
    response = client.get("/playground?" + urlencode(query))
    assert response.status_code == 422
    html = response.text
    assert f'data-field="{field}"' in html
    assert re.search(rf'id="{field}"[^>]*aria-invalid="true"', html)
    assert words in re.search(r'<div class="form-error".*?</div>', html, re.S)[0].replace("&#39;", "'")


def test_an_overlong_address_is_refused(client):
    response = client.get("/playground?" + urlencode({"q": "x", "L": "x" * (MAX_QUERY + 1)}))
    assert response.status_code == 422 and "longer than" in response.text


@pytest.mark.usefixtures("fresh_mint_budget")
def test_the_page_issues_a_session(client):
    client.cookies.clear()
    response = client.get("/playground?new")
    assert "lagrange_session" in response.cookies


@pytest.mark.slow
def test_parameter_ranges_read_as_a_reader_writes_them(client):
    """A positive quantity left without bounds is "more than 0, up to" a round power of ten, with its unit typeset
    (never "1e-09 to 11 kg" or "m/s^2"); a signed one a symmetric round range with a true minus sign."""
    form = Form(coordinates="x", parameters=[
        {"name": "m", "value": "1", "unit": "kg"}, {"name": "g", "value": "9.81", "unit": "m/s^2"},
        {"name": "w", "value": "1.5", "unit": "1/s"},
    ], kinetic="m*x_dot**2/2", potential="m*g*x + w*x**2")  # fmt: skip
    html = client.get("/playground?" + urlencode({**query_of(form), "stage": "whole"}, doseq=True)).text
    # the allowed range's words (the hint says them, after the slider's own range where that is narrower)
    hints = dict(re.findall(r'data-name="(\w+)"[^>]*?data-allowed="([^"]*)"', html))
    said = dict(re.findall(r'id="ctl-(\w+)-hint"[^>]*>([^<]*)</p>', html))
    assert all(said[name].endswith(hints[name]) for name in ("m", "g", "w")), said
    shown = {name: hints[name] for name in ("m", "g", "w")}
    assert shown == {"m": "more than 0, up to 10 kg", "g": "more than 0, up to 100 m/s²", "w": "−100 to 100 s⁻¹"}, hints
    assert not any("e-0" in text or "^" in text for text in hints.values()), hints


@pytest.mark.slow
def test_a_charge_in_a_uniform_field_starts_moving_and_the_page_says_why(client):
    """V ≡ 0: every configuration is an equilibrium, so a start at rest would show nothing; the playground starts
    x moving at 1 m/s and says so under the initial conditions, with the rate's unit (prof-f 35: "1 per second")."""
    spec = {
        "coordinates": ["x", "y"],
        "parameters": [
            {"name": "m", "value": 1.0, "unit": "kg"},
            {"name": "e", "value": 1.0, "unit": "C"},
            {"name": "B", "value": 2.0, "unit": "T"},
        ],
        "lagrangian": "m*(x_dot**2 + y_dot**2)/2 + e*B*(x*y_dot - y*x_dot)/2",
    }
    html = client.get("/playground?" + urlencode({**query_of(form_of(spec)), "stage": "whole"}, doseq=True)).text
    note = re.search(r'<p class="help" id="initial-note">([^<]*)</p>', html)
    assert note and "Every configuration is an equilibrium" in note[1]
    assert unicodedata.normalize("NFC", note[1]).endswith("starts with \u1e8b(0) = 1 m/s.")  # ẋ
    start = re.search(r'<input type="number" id="ctl-x_dot" name="x_dot"[^>]*value="([^"]*)"', html)
    assert start and float(start[1]) == 1.0


@pytest.mark.slow
def test_a_name_of_several_letters_is_one_upright_name_with_the_dot_over_all_of_it(client):
    # prof-g 56: a coordinate th was typeset as t·ḣ ("r² tḣ²", "cos th", "∂L/∂tḣ"); theta stays θ
    response = client.post(
        "/api/derive",
        json={
            "coordinates": ["r", "th"],
            "parameters": [{"name": "m", "value": 1, "unit": "kg"}, {"name": "g", "value": 9.81, "unit": "m/s^2"}],
            "kinetic": "m*(r_dot**2 + r**2*th_dot**2)/2",
            "potential": "-m*g*r*cos(th)",
        },
    )
    assert response.status_code == 200, response.text
    doc = response.json()
    assert doc["symbols"]["th"]["latex"] == r"\mathrm{th}" and doc["symbols"]["th_dot"]["latex"] == r"\dot{\mathrm{th}}"
    # every printed formula: the rate's dot over the whole name, the name upright inside cos
    printed = " ".join(s["latex"] for s in doc["steps"]) + doc["lagrangian"]["latex"]
    assert r"\dot{\mathrm{th}}" in printed and r"\ddot{\mathrm{th}}" in printed and r"\mathrm{th}" in printed
    assert r"\dot{h}" not in printed and r"\ddot{h}" not in printed and not re.search(r"(?<![{\\a-z])th(?![a-z}])", printed)
    # in running text the dot follows the whole name (th˙), never sits on its last letter (tḣ)
    assert doc["symbols"]["th_dot"]["unicode"] == "th˙" and "tḣ" not in response.text
