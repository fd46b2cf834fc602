"""The bead on a hoop spun at a fixed rate w, typed into the playground (issue 40, a professor's review): the
separatrix marks by the conserved h, not E, and the equilibria with where they exist and when they are stable."""

import html as html_lib
import math
import re
from urllib.parse import urlencode

import pytest

from app.web.pages.playground_form import form_of, query_of

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): over 1.5 s of work in all

R, G, W = 0.5, 9.81, 6.0
HOOP = {
    "coordinates": ["theta"],
    "parameters": [
        {"name": "m", "value": 1.0, "unit": "kg", "min": 1e-9},
        {"name": "R", "value": R, "unit": "m", "min": 1e-9},
        {"name": "g", "value": G, "unit": "m/s^2", "min": 1e-9},
        {"name": "w", "value": W, "unit": "1/s"},
    ],
    "kinetic": "1/2*m*R^2*(theta_dot^2 + w^2*sin(theta)^2)",
    "potential": "-m*g*R*cos(theta)",
}


def text_of(client, spec) -> str:
    page = client.get("/playground?" + urlencode({**query_of(form_of(spec)), "stage": "whole"}, doseq=True)).text
    return html_lib.unescape(page)


def u_eff(theta: float) -> float:
    """h at rest per unit mass: −g R cos θ − ½ R² w² sin²θ."""
    return -G * R * math.cos(theta) - 0.5 * R**2 * W**2 * math.sin(theta) ** 2


def test_the_separatrix_speed_is_that_of_the_conserved_h(client):
    page = text_of(client, HOOP)
    # h(θ₀, θ̇₀) = ½ m R² θ̇₀² + U_eff(θ₀) = U_eff(θ_top), from θ₀ = 1 to the top θ = π and to θ = 0 (unstable here)
    over = math.sqrt(2 * (u_eff(math.pi) - u_eff(1.0)) / R**2)
    across = math.sqrt(2 * (u_eff(0.0) - u_eff(1.0)) / R**2)
    assert over == pytest.approx(9.27, abs=0.01)
    note = re.search(r"The slider marks ([^<]*)\.</p>", page).group(1)
    assert f"±{over:.4g} rad/s (separatrix from θ(0) = 1 rad, by h (conserved here, not E): just reaches θ = π)" in note
    assert (
        f"±{across:.4g} rad/s (separatrix from θ(0) = 1 rad, by h (conserved here, not E): just reaches θ = 0)" in note
    )
    # E's value, ½ m R² θ̇₀² = m g R (1 + cos θ₀), is not marked
    assert f"{math.sqrt(2 * G / R * (1 + math.cos(1.0))):.4g}" not in note


def test_an_explicitly_time_dependent_hoop_marks_no_separatrix(client):
    # the rate ramps up with t: neither h nor E is conserved, so no level is reached and nothing is said
    ramped = {**HOOP, "kinetic": "1/2*m*R^2*(theta_dot^2 + (w*t)^2*sin(theta)^2)"}
    assert "separatrix" not in text_of(client, ramped).split('id="derivation"')[0]


def test_each_equilibrium_says_where_it_exists_and_when_it_is_stable(client):
    doc = client.post("/api/derive", json=HOOP).json()
    found = {e["position"]["sympy"]: e for e in doc["effective_potential"]["equilibria"]}
    bottom, top, side = found["0"], found["pi"], found["acos(g/(R*w**2))"]
    # ω² = g/R − w² at the bottom: stable when g > R w², unstable when R w² > g
    assert bottom["stable"] is None
    assert (bottom["stable_when"]["latex"], bottom["unstable_when"]["latex"]) == ("g > R w^{2}", "R w^{2} > g")
    assert top["stable"] is False
    # arccos(g/(R w²)) exists only when R w² > g, and is stable there: ω² = w² − g²/(R² w²) > 0
    assert side["exists"]["latex"] == "R w^{2} > g" and side["stable"] is True
    assert found["-acos(g/(R*w**2))"]["exists"]["latex"] == "R w^{2} > g"
    page = text_of(client, HOOP)
    results = page[page.index("Effective potential") :]
    assert 'stable when <span class="math" data-tex="g > R w^{2}">' in results
    assert 'unstable when <span class="math" data-tex="R w^{2} > g">' in results
    assert results.count("which exists only when") == 2 and results.count("(stable wherever it exists)") == 2


def test_the_derivation_prints_the_equilibria_as_the_results_do(client):
    doc = client.post("/api/derive", json=HOOP).json()
    (step,) = [s for s in doc["steps"] if s["title"] == "Equilibria"]
    assert r"\theta &= \arccos {\frac{g}{R w^{2}}}" in step["latex"] and "arctan" not in step["latex"]
    exact = [e["exact"]["theta"]["sympy"] for e in doc["normal_modes"]]
    assert sorted(exact) == sorted(e["position"]["sympy"] for e in doc["effective_potential"]["equilibria"])
    # ω² about it collapses once cos(arccos c) = c: no arctan inside
    about = [s for s in doc["steps"] if s["title"].startswith("Small oscillations about θ = arccos")]
    assert about and "arctan" not in about[0]["latex"]


def test_the_hoop_given_by_l_alone_names_h_and_no_e(client):
    from app.web.api.examples_user import SPINNING_HOOP

    page = text_of(client, SPINNING_HOOP)
    note = re.search(r"The slider marks ([^<]*)\.</p>", page).group(1)
    # with L alone E is not defined: the mark names h, conserved, and says nothing of E
    assert ", by h (conserved here): just reaches θ = π" in note and "not E" not in note


def _effective_potential_words(client, spec) -> str:
    doc = client.post("/api/derive", json=spec).json()
    (step,) = [s for s in doc["steps"] if s["key"] == "effective-potential"]
    return step["explanation"]


def test_the_effective_potential_says_it_comes_from_the_moving_constraint(client):
    # the hoop has no cyclic coordinate: U_eff = −L at θ̇ = 0 = U − T₀, T₀ = ½ m R² w² sin²θ (prof-l 5)
    spun = {key: value for key, value in HOOP.items() if key != "kinetic"} | {
        "particles": [{"mass": "m", "position": ["R*sin(theta)*cos(w*t)", "R*sin(theta)*sin(w*t)", "-R*cos(theta)"]}],
    }
    for spec, source in ((spun, "the moving constraint (the positions contain t)"), (HOOP, "as written")):
        words = _effective_potential_words(client, spec)
        assert "No coordinate is cyclic here" in words and source in words
        assert "U_eff = −L at θ̇ = 0 is U − T₀" in words and "cyclic motion" not in words


def test_the_effective_potential_of_a_cyclic_coordinate_says_the_momentum_is_held(client):
    # a particle on a frictionless table pulled by a spring from the centre: φ is cyclic, no constraint moves
    table = {
        "coordinates": ["r", "phi"],
        "parameters": [{"name": "m", "value": 1.0, "unit": "kg", "min": 1e-9}, {"name": "k", "value": 4.0}],
        "particles": [{"mass": "m", "position": ["r*cos(phi)", "r*sin(phi)", "0"]}],
        "potential": "1/2*k*r^2",
    }
    words = _effective_potential_words(client, table)
    assert words.startswith("With each conserved momentum held at its value") and "T₀" not in words
    # one coordinate on a fixed circle: U_eff is U itself
    pendulum = {
        "coordinates": ["theta"],
        "parameters": HOOP["parameters"][:3],
        "particles": [{"mass": "m", "position": ["R*sin(theta)", "0", "-R*cos(theta)"]}],
        "potential": "-m*g*R*cos(theta)",
    }
    words = _effective_potential_words(client, pendulum)
    assert words.startswith("One coordinate on fixed constraints: U_eff is the potential energy U itself")
