"""The bead on a hoop spun at a fixed rate w, typed into the playground (issue 40, a professor's review): the
separatrix marks by the conserved h, not E, and the equilibria with where they exist and when they are stable."""

import html as html_lib
import math
import re
from urllib.parse import urlencode

import pytest

from app.web.playground_form import form_of, query_of

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
