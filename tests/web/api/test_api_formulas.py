"""A verdict lists the formulas its words quote, each with its LaTeX, so a page typesets them where they stand
(issue 41, student-l 6, 7): the student's own term, U_eff″/m_eff, and a follow-up's reply echoed as it was typed."""

from __future__ import annotations

import pytest

from app.engine.display.names import unicode

pytestmark = pytest.mark.slow  # out of the fast tier (scripts/test-fast.sh): each test over 0.3 s (docs/testing.md)


def test_the_quoted_term_comes_with_its_latex_in_the_students_order(client):
    body = client.post(
        "/api/scenes/movable-incline/check",
        json={"step": "acceleration", "coordinate": "X", "answer": "-m*g*sin(alpha)*cos(alpha)/(M + m*cos(alpha)**2)"},
    ).json()
    term = "−m g cos(α) sin(α)/(M + m cos²(α))"
    assert term in body["mistake"]["name"]
    shown = {f["text"]: f["latex"] for f in body["formulas"]}
    assert shown[term] == r"-m g \cos (\alpha ) \sin (\alpha )/(M + m \cos^{2} (\alpha ))"
    # the longest first: a page sets a formula whole before a symbol it holds
    assert [len(f["text"]) for f in body["formulas"]] == sorted(
        (len(f["text"]) for f in body["formulas"]), reverse=True
    )


def test_the_frequencys_rule_has_real_subscripts(client):
    body = client.post(
        "/api/scenes/simple-pendulum/check", json={"step": "omega_squared", "answer": "sqrt(g/R)"}
    ).json()
    # θ is an angle: its inertia is the moment of inertia I_eff (prof-n 5)
    assert "U_eff″/I_eff" in body["hint"]
    shown = {f["text"]: f["latex"] for f in body["formulas"]}
    assert shown["ω² = U_eff″/I_eff"] == r"\omega ^{2} = U_{\text{eff}}'' /I_{\text{eff}}"


def test_a_right_reply_to_a_follow_up_is_echoed_as_typed(client):
    url = "/api/scenes/pulley/check"
    wrong = client.post(url, json={"step": "kinetic", "answer": "1/2*m1*y1_dot**2 + 1/2*m2*y2_dot**2"}).json()
    asked = {"step": "kinetic", "follow_up": wrong["follow_up"]["key"]}
    reply = client.post(url, json={**asked, "answer": "M/8*(y1_dot+y2_dot)^2"}).json()
    assert reply["verdict"] == "correct"
    # student-l 6: the factored reply came back expanded, M (ẏ₁² + ẏ₂² + 2 ẏ₁ ẏ₂)/8
    echo = f"M ({unicode('y1_dot')} + {unicode('y2_dot')})²/8"
    assert reply["message"].startswith(f"Correct: {echo}. ")
    assert {"text": echo, "latex": r"M (\dot{y}_{1} + \dot{y}_{2} )^{2}/8"} in reply["formulas"]
