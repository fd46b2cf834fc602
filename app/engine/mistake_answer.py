"""Slips read from the answer itself, when no mistake of the step's catalogue matches.

The catalogue (app/engine/mistakes.py, mistake_pieces.py) builds each wrong answer from the derivation
and compares; two common slips cannot be built that way, because what goes wrong depends on what the
student wrote:

* **a square left out**: a velocity component a·q̇ enters v² as a²q̇², and students write a instead of
  a² (the helix's m(1 + Rα)ż²/2 for m(1 + R²α²)ż²/2, the parabola's 1 + 2αρ for 1 + 4α²ρ²).  Each
  product or symbol of the answer that holds no velocity is squared in turn; the one whose square
  turns the answer into the engine's is named;
* **an equation linearised**: the small-angle equation (sin θ ≈ θ, cos ≈ 1, products of small
  quantities dropped) where the full one is asked for.  The engine's equation is expanded to first
  order about the state where every coordinate, velocity and acceleration is zero (when that state
  is an equilibrium); an answer equal to it, or to a constant multiple of it, is named.

Both compare values at the checker's sample points (app/engine/compare.py), within a count of work.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy as sp

from app.engine.compare import Groups, Values, differ_by_factor, equal, factor_is_constant, usable, values
from app.engine.diagnose import MIN_POINTS  # the points a comparison needs: one home with the catalogue's
from app.engine.textbook import unicode_text

MAX_CANDIDATES = 24  # products and symbols of an answer tried as the one left unsquared

SQUARE_HINT = (
    "You wrote {part} where T needs its square {square}: a velocity component such as {part}·{rate} enters "
    "v² squared, as {square}·{rate}², so square each component before adding them."
)
LINEAR_HINT = (
    "This is the equation linearised for small displacements (sin θ ≈ θ, cos θ ≈ 1, products of small "
    "quantities such as θ̇² dropped): an approximation. The step asks for the full equation of motion: keep "
    "the sines, cosines and velocity-squared terms as d/dt(∂L/∂q̇) − ∂L/∂q gives them."
)


@dataclass(frozen=True)
class AnswerSlip:
    """A slip read from the answer: a named mistake (``approximation`` for the small-angle form) and its hint."""

    key: str
    name: str
    where: str
    hint: str
    approximation: bool = False

    def json(self) -> dict[str, Any]:
        """The API's ``mistake`` (as ``app.engine.diagnose.mistake_json`` gives a catalogue's)."""
        family = "small_angle" if self.approximation else self.key.split(".")[-1]
        return {"key": self.key, "family": family, "name": self.name, "latex": "",
                "where": self.where, "approximation": self.approximation, "count": 1}  # fmt: skip


def _same(a: Values, b: Values) -> bool:
    return usable(a, b) >= MIN_POINTS and equal(a, b)


def missing_square(answer: sp.Expr, truth: Values, groups: Groups) -> AnswerSlip | None:
    """The slip naming a part of the answer written where its square belongs, or None."""
    rates = set(groups.rates)
    seen: set[sp.Expr] = set()
    for part in sp.preorder_traversal(answer):
        if len(seen) >= MAX_CANDIDATES:
            break
        if not (part.is_Symbol or part.is_Mul) or part in seen or part.free_symbols & rates:
            continue
        if not part.free_symbols or part.could_extract_minus_sign():
            continue
        seen.add(part)
        squared = answer.xreplace({part: part**2})
        if squared != answer and _same(values(squared, groups), truth):
            rate = next((r for r in groups.rates if r in answer.free_symbols), None)
            shown, square = unicode_text(part), unicode_text(part**2)
            hint = SQUARE_HINT.format(part=shown, square=square, rate=unicode_text(rate) if rate is not None else "q̇")
            return AnswerSlip(
                "kinetic.square_left_out",
                f"{shown} where T needs its square {square}",
                hint.split(": ", 1)[1].removesuffix("."),
                hint,
            )
    return None


def linearised(answer: Values, truth: sp.Expr, groups: Groups) -> AnswerSlip | None:
    """The slip naming an equation linearised about rest at zero, or None (no such rest state, or not it)."""
    moving = (*groups.positions, *groups.rates)
    rest = dict.fromkeys(moving, sp.S.Zero)
    if sp.simplify(truth.xreplace(rest)) != 0:
        return None  # zero is not an equilibrium of this equation: no small-angle form about it
    first = sum((sp.diff(truth, v).xreplace(rest) * v for v in moving), sp.S.Zero)
    if first == 0 or sp.expand(first - truth) == 0:
        return None  # the equation is linear already (or has no first-order part)
    mine = values(first, groups)
    if usable(answer, mine) >= MIN_POINTS and differ_by_factor(answer, mine) and factor_is_constant(answer, mine):
        return AnswerSlip(
            "equation.linearised",
            "the equation linearised for small displacements (sin θ ≈ θ, cos θ ≈ 1, products of small quantities "
            "such as θ̇² dropped)",
            "the step asks for the full equation of motion: keep the sines, cosines and velocity-squared terms as "
            "d/dt(∂L/∂q̇) − ∂L/∂q gives them",
            LINEAR_HINT,
            approximation=True,
        )
    return None
