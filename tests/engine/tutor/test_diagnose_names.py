"""Every hint and reason of a scene speaks in the page's own letters (review student-f, 21): a length the page
calls R is never l in a hint, and no hint borrows another scene's coordinate (Ẋ ṡ cos α on the double pendulum)
or a program's name (r₀, U_eff)."""

from __future__ import annotations

import re

import pytest

from app.engine.display.names import unicode
from app.engine.document.notation import text
from app.engine.tutor.check import exercises
from app.scenes import SCENES
from tests.engine.declared import derivation, problem_of

# one letter standing alone as a symbol (Greek or Latin, with its dot and subscript digits): not part of a word,
# not the s of an apostrophe's "'s"
# (a square's ² may follow: it is no letter)
SYMBOL = re.compile(
    r"(?<![A-Za-zα-ωΑ-Ω0-9_'’\u0307\u0308])([A-Za-zα-ωΑ-Ω])[\u0307\u0308]?([₀-₉]*)(?![A-Za-zα-ωΑ-Ω0-9_\u0307\u0308₀-₉])"
)
# the letters of the rules every system shares, which name no quantity of the page: T, U, L and h; p, q, Q and
# the generalized velocity; ½ m v², m g × height, ½ k × stretch², ½ I ω²; d/dt, Σ; the figure's axes x, y, z (ξ, η, ζ
# where a coordinate takes an axis's name: notation.practice_axes, said in the positions' note);
# the r of a position vector (∂r/∂q); the article a and A; T₂, T₁, T₀, the parts of T of degree 2, 1 and 0 in the
# velocities (h = T₂ − T₀ + U where a constraint moves); the number π
GENERIC = frozenset("T U L h H E p q Q v m g k I ω d t Σ x y z ξ η ζ r a A T₀ T₁ T₂ π".split())


def _letters(text: str) -> set[str]:
    return {m.group(1) + m.group(2) for m in SYMBOL.finditer(text)}


def test_the_letter_reader_sees_symbols_and_not_words():
    said = "a pendulum's l² sin θ across, R φ̇² cos(θ) and m₁ where M₁ belongs"
    assert _letters(said) == {"a", "l", "θ", "R", "φ", "m₁", "M₁"}


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SCENES))
def test_every_hint_names_only_the_scenes_own_symbols(name):
    d = derivation(name)
    # and the page's letter for the frequency of small oscillations (Ω where ω is a parameter, as its Symbols
    # table defines it)
    own = {unicode(s.name) for s in (*d.table.params, *d.table.q)} | {text("frequency", d)}
    strays = {}
    for step, coordinate in exercises(d):
        for _, hint, _ in problem_of(name, step, coordinate).mistakes:
            for letter in _letters(hint) - own:
                if letter not in GENERIC:
                    strays.setdefault(letter, hint)
    assert strays == {}, strays
