"""Closed forms of the accelerations decided by their length, not by the number of coordinates (issue 42).

The double-double Atwood machine: a massless top pulley carries a massless pulley on each side, m₁ and m₂
hang from the left one, m₃ and m₄ from the right one.  x is how far the left pulley has gone down (the right
one goes up as much), y and z how far m₁ and m₃ have gone down relative to their pulleys.  By hand, each
lower pulley with its two masses falls like one mass μ = 4 m_a m_b / (m_a + m_b) in the top Atwood machine,
    ẍ = g (μ₁₂ − μ₃₄)/(μ₁₂ + μ₃₄) = g (m₁m₂m₃ + m₁m₂m₄ − m₁m₃m₄ − m₂m₃m₄)/D,
and each lower machine's relative acceleration ÿ = (g − ẍ)(m₁ − m₂)/(m₁ + m₂), z̈ = (g + ẍ)(m₃ − m₄)/(m₃ + m₄):
    ÿ = 2 g m₃m₄ (m₁ − m₂)/D,   z̈ = 2 g m₁m₂ (m₃ − m₄)/D,   D = m₁m₂m₃ + m₁m₂m₄ + m₁m₃m₄ + m₂m₃m₄.
"""

from __future__ import annotations

import re

import pytest
import sympy as sp

from app.engine.derivation.derive import derive
from app.engine.parser.user_system import UserSystem
from tests.reference import numerically_equal, reference_accelerations

ATWOOD = {
    "coordinates": ["x", "y", "z"],
    "parameters": [{"name": n, "value": v} for n, v in (("m1", 1), ("m2", 2), ("m3", 3), ("m4", 4), ("g", 9.81))],
    "kinetic": "m1*(x_dot + y_dot)**2/2 + m2*(x_dot - y_dot)**2/2 + m3*(z_dot - x_dot)**2/2 + m4*(x_dot + z_dot)**2/2",
    "potential": "-g*(m1*(x + y) + m2*(x - y) + m3*(z - x) - m4*(x + z))",
}
m1, m2, m3, m4, g = sp.symbols("m1 m2 m3 m4 g", real=True)
D = m1 * m2 * m3 + m1 * m2 * m4 + m1 * m3 * m4 + m2 * m3 * m4
BY_HAND = {
    "x": g * (m1 * m2 * m3 + m1 * m2 * m4 - m1 * m3 * m4 - m2 * m3 * m4) / D,
    "y": 2 * g * m3 * m4 * (m1 - m2) / D,
    "z": 2 * g * m1 * m2 * (m3 - m4) / D,
}


@pytest.mark.slow
def test_by_hand_agrees_with_lagranges_method():
    reference, _ = reference_accelerations(UserSystem.of(ATWOOD).system())
    symbols = (m1, m2, m3, m4, g)
    for name, acc in zip("xyz", reference, strict=True):
        assert numerically_equal(acc, BY_HAND[name], symbols)


@pytest.mark.slow
def test_three_coordinate_atwood_gets_its_short_closed_forms(client):
    r = client.post("/api/derive", json=ATWOOD)
    assert r.status_code == 200, r.text
    d = r.json()
    assert set(d["accelerations"]) == {"x", "y", "z"}
    names = {s.name: s for s in (m1, m2, m3, m4, g)}
    for name, shown in d["accelerations"].items():
        served = sp.sympify(shown["sympy"], locals=names)
        assert sp.simplify(served - BY_HAND[name]) == 0
    assert not any(s["member"] == "accelerations" for s in d["skipped"])
    step = next(s for s in d["steps"] if s.get("id", s.get("key")) == "accelerations")
    assert "M^{-1}" not in str(step)


def test_the_engine_keeps_the_short_forms_and_says_how_long_they_are():
    eqs = derive(UserSystem.of(ATWOOD).system()).equations
    assert eqs.closed_form
    lengths = [len(str(a)) for a in eqs.accelerations]
    assert max(lengths) <= 100  # by hand: 89, 63 and 63 characters
    assert eqs.closed_form_reason == f"the longest one is {max(lengths)} characters"


@pytest.mark.slow
def test_a_three_link_chain_is_left_out_with_its_measured_length(client):
    chain = {
        "coordinates": ["a", "b", "c"],
        "parameters": [{"name": "g", "value": 9.81}],
        "particles": [
            {"mass": "1", "position": ["sin(a)", "0", "-cos(a)"]},
            {"mass": "1", "position": ["sin(a) + sin(b)", "0", "-cos(a) - cos(b)"]},
            {"mass": "1", "position": ["sin(a) + sin(b) + sin(c)", "0", "-cos(a) - cos(b) - cos(c)"]},
        ],
        "potential": "-g*(3*cos(a) + 2*cos(b) + cos(c))",
    }
    d = client.post("/api/derive", json=chain).json()
    assert d["accelerations"] == {}
    reason = next(s["reason"] for s in d["skipped"] if s["member"] == "accelerations")
    longest = int(re.search(r"is (\d+) characters", reason).group(1))
    assert longest > 400 and "more than 400" in reason
