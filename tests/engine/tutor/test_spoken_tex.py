"""A formula the tutor's words quote is typeset as it is printed there (issue 41, student-l 6, 7): U_eff″/m_eff
with real subscripts, the student's own term in its own order, I and l in math italic, never code."""

from __future__ import annotations

import pytest

from app.engine.tutor.spoken_tex import formulas, latex, spans


@pytest.mark.parametrize(
    ("text", "tex"),
    [
        # the subscript a word (eff, centre) set upright, its primes as primes: no underscore left to read as code
        ("ω² = U_eff″/m_eff", r"\omega ^{2} = U_{\text{eff}}'' /m_{\text{eff}}"),
        ("½ m v_centre² + ½ I ω²", r"\tfrac{1}{2} m v_{\text{centre}} ^{2} + \tfrac{1}{2} I \omega ^{2}"),
        # the student's term in its own order, slashes and parentheses kept
        ("−m g cos(α) sin(α)/(M + m cos²(α))", r"-m g \cos (\alpha ) \sin (\alpha )/(M + m \cos^{2} (\alpha ))"),
        ("(x₁ − x₂) κ", r"(x_{1} - x_{2} ) \kappa"),
        ("M (ẏ₁ + ẏ₂)²/8", r"M (\dot{y}_{1} + \dot{y}_{2} )^{2}/8"),
        ("sqrt(g/R)", r"\sqrt{g /R }"),
        # words are no formula
        ("the x of", None),
        ("(moment", None),
    ],
)
def test_a_quoted_formula_reads_as_latex_in_its_own_order(text, tex):
    assert latex(text) == tex


def test_the_formulas_of_a_sentence_are_its_runs_of_symbols():
    words = (
        "the rod taken as a point mass at its end: I = M l² in place of a rod's I about its end, M l²/3 (moment of "
        "inertia). Your T is a force (kg·m/s²); T's units (1/s²)"
    )
    # I = M l² whole, and the lone I beside the l it looked like (student-l 7); a possessive and units are words
    assert spans(words) == ["I = M l²", "I", "M l²/3", "T"]
    assert [f["text"] for f in formulas([words, None])] == ["I = M l²", "M l²/3", "I", "T"]
    assert spans("This is ω, not ω²: square it (ω² = U_eff″/m_eff at the equilibrium).") == [
        "ω",
        "ω²",
        "ω² = U_eff″/m_eff",
    ]
    # a value with its unit is words too
    assert spans("g is 9.81 m/s² here, and m g R a product") == ["g", "m g R"]
    # a parenthesis opened by the words belongs to them
    assert spans("the correct ω² of small oscillations (at θ = 0).") == ["ω²", "θ = 0"]
