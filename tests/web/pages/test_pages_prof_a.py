"""What prof-a's review of six scene pages would not sign, pinned by what the pages serve: a forced system's action
panel, the separatrix mark, one glyph and one meaning per letter, the errata typeset as a textbook would."""

from __future__ import annotations

import re

import pytest


@pytest.fixture(scope="module")
def pages(client):
    ids = ("simple-pendulum", "damped-pendulum", "spherical-pendulum", "tabletop-spring", "incline-block")
    return {s: client.get(f"/scenes/{s}").text for s in ids}


def _panel_text(html: str, name: str) -> str:
    section = html.split(f'id="panel-{name}"', 1)[1]
    return re.search(r'<p class="panel-text">(.*?)</p>', section, re.S).group(1)


def test_the_damped_action_panel_states_the_principle_with_Q(pages):
    # δS + ∫ Q δq dt = 0 on the true path: the panel must not say S is stationary or talk of a kinetic focus
    damped = _panel_text(pages["damped-pendulum"], "action")
    assert "δS + ∫ Q δq dt = 0" in damped and "−∫ Q sin(nπt/τ) dt" in damped
    assert "makes the action S = ∫ L dt stationary" not in damped and "kinetic focus" not in damped
    # a conservative scene keeps Hamilton's principle as it is
    assert "stationary among paths with the same ends" in _panel_text(pages["simple-pendulum"], "action")


def test_the_separatrix_mark_is_for_the_start_it_names_and_absent_with_drag(pages):
    marks = re.search(r'<p class="ticks">The slider marks (.*?)</p>', pages["simple-pendulum"], re.S).group(1)
    # ½ m R² θ̇₀² = m g R (1 + cos θ₀) at θ₀ = 1 rad gives the marked ±5.497 rad/s (the scene's default start)
    assert "separatrix from θ(0) = 1 rad: just reaches θ = π" in marks
    # with drag the undamped value falls short of the top: no such mark
    assert "separatrix" not in pages["damped-pendulum"].split('id="derivation"')[0]


def test_one_glyph_for_phi_and_one_meaning_for_F(pages):
    spherical = pages["spherical-pendulum"]
    # prose and controls write φ (U+03C6); LaTeX's \phi would print the other glyph ϕ
    assert re.search(r"\\phi(?![A-Za-z])", spherical) is None and r"\varphi" in spherical
    assert "ϕ" not in spherical
    damped = pages["damped-pendulum"]
    # F₁ is the string tension (λ₁|∇𝒞₁|): the drag is not called F as well
    assert r"F_{1} = \lambda_{1}" in damped and "F = −(b/R" not in damped and "torque about the pivot is −b θ̇" in damped


def test_the_errata_have_no_program_words(pages):
    assert "r_hat" not in pages["tabletop-spring"] and r"\hat{r}" in pages["tabletop-spring"]
    incline = pages["incline-block"]
    assert "Ex." not in incline and "repeated)" not in incline
    assert "The statement of the helix bead problem, repeated word for word." in incline
