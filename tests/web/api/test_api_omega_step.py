"""The ω² step of a system with several equilibria (inst-b 10 and 21): it asks about one equilibrium, named in its
title; ω² at another is a named mistake; its answer says whether the equilibrium is stable and where the others
exist, printed as a textbook prints them (arccos, never acos or 2π − arccos)."""

from __future__ import annotations

import pytest

from app.web.api.examples_user import SPINNING_HOOP

# the same hoop with its parameters' signs undeclared: nothing is known about where ω² is positive
PLAIN_HOOP = {
    "coordinates": ["theta"],
    "parameters": ["m", "R", "g", "w"],
    "lagrangian": "m*R**2*(theta_dot**2 + w**2*sin(theta)**2)/2 + m*g*R*cos(theta)",
}

pytestmark = pytest.mark.slow  # each system is derived once in the worker pool (a few seconds)


def omega_exercise(client, system):
    r = client.post("/api/practice", json=system)
    assert r.status_code == 200, r.text
    return next(e for e in r.json()["exercises"] if e["step"] == "omega_squared")


def test_the_step_names_its_equilibrium_and_says_which_are_stable_and_where_they_exist(client):
    e = omega_exercise(client, SPINNING_HOOP)
    assert e["title"] == "ω² of small oscillations about θ = 0"
    assert e["answer"]["latex"] == r"\omega^2 = \frac{g}{R} - w^{2}\ \text{at}\ \theta = 0"
    assert e["answer"]["notes"] == [
        "θ = 0 is stable while g > Rw²; where ω² is negative it is unstable (a small displacement grows), and there "
        "are no small oscillations about it.",
        "The other equilibria: θ = π, with ω² = −w² − g/R (never positive: unstable, no small oscillations); "
        "θ = ±arccos(g/(Rw²)), which exist only when Rw² > g, with ω² = w² − g²/(R²w²) (positive there: stable).",
    ]


def test_undeclared_signs_still_say_where_an_inverse_cosine_exists_and_what_a_negative_omega_squared_means(client):
    notes = omega_exercise(client, PLAIN_HOOP)["answer"]["notes"]
    assert notes[0] == "Where ω² is negative, θ = 0 is unstable (a small displacement grows): no small oscillations about it."
    assert "θ = ±arccos(g/(Rw²)), which exist only where −1 ≤ g/(Rw²) ≤ 1, with ω² = w² − g²/(R²w²)" in notes[1]
    assert "acos" not in " ".join(notes).replace("arccos", "") and "2π" not in " ".join(notes)


@pytest.mark.parametrize("system", [SPINNING_HOOP, PLAIN_HOOP], ids=["declared", "plain"])
def test_only_the_equilibrium_asked_about_is_right(client, system):
    def check(answer):
        r = client.post("/api/check", json={"system": system, "step": "omega_squared", "answer": answer})
        assert r.status_code == 200, r.text
        return r.json()

    right = check("g/R - w**2")
    assert right["verdict"] == "correct" and right["message"] == "Correct: this is the ω² of small oscillations at θ = 0."
    # the tilted equilibria's ω² (right there, not here) and the top's (unstable: no small oscillations) are wrong
    tilted = check("w**2 - g**2/(R**2*w**2)")
    assert tilted["verdict"] == "incorrect", tilted
    assert tilted["mistake"]["key"].startswith("omega_squared.other_equilibrium."), tilted["mistake"]
    assert "arccos(g/(Rw²))" in tilted["mistake"]["name"]
    top = check("-w**2 - g/R")
    assert top["verdict"] == "incorrect" and top["mistake"]["name"] == "ω² at the other equilibrium θ = π"


def test_a_scene_asks_the_same_way(client):
    # one equilibrium named in the title, the others said under the answer, as for a typed system
    r = client.get("/api/scenes/simple-pendulum/practice")
    assert r.status_code == 200, r.text
    e = next(e for e in r.json()["exercises"] if e["step"] == "omega_squared")
    assert e["title"] == "ω² of small oscillations about θ = 0"
    assert e["answer"]["notes"] == [
        "θ = 0 is stable: ω² is positive for every value of the parameters.",
        "The other equilibrium: θ = π, with ω² = −g/R (never positive: unstable, no small oscillations).",
    ]
