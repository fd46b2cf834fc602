"""A sign diagnosis quotes the student's own term, as it stands in what they typed.

The catalogue names a term of the wrong sign by the engine's piece (−m g l sin θ). A student who wrote the
equation divided through by m l, or with that term on the right of '=', finds no such term on the screen.
So an equation's term is quoted at the student's scale and without its sign (the sign is the slip, and a
term moved across '=' shows the other one): "the sign of your g sin(θ) term". Where the student's answer has
no term of that form (written factored, or merged with another), no term is quoted at all: a diagnosis
never names a term the answer does not have.  A term with sin and cos swapped is quoted the same way, at the
student's scale and with its own sign (θ̈ + (g/R) cos θ: "your term g cos(θ)/R", never m g R cos θ).
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Iterable

import sympy as sp

from app.engine.display.spoken import spoken
from app.engine.tutor.mistake_families import Mistake
from app.engine.tutor.mistake_pieces import sum_words, swap_sin_cos

# the families whose name quotes one of the answer's terms by its sign
_SIGN_FAMILIES = frozenset({"term_sign"})
MAX_TERMS = 12  # of an answer, tried for the constant it is a mistake times


def as_typed(
    mistake: Mistake, hint: str, answer: sp.Expr, scale: sp.Expr, step: str, coordinates: Iterable[sp.Symbol] = ()
) -> tuple[Mistake, str]:
    """``mistake`` and its ``hint`` with the term named as the student's answer holds it (an equation's)."""
    if mistake.family == "inner_sign" and mistake.piece is not None:
        return _inner_as_typed(mistake, hint, answer, scale, tuple(coordinates))
    if step != "equation" or mistake.piece is None:
        return mistake, hint
    terms = {sp.expand(t) for t in sp.Add.make_args(sp.expand(answer))}
    # the student's scale: the one the comparison used, else the constant the answer is the mistake times (a slip
    # in the acceleration's own term makes the coefficients' ratio no constant: the spherical pendulum's φ̈ cos² θ)
    scales = (scale, *_factor(answer, mistake.expr, terms))
    if mistake.family == "sin_cos" and mistake.name.startswith("sin and cos swapped in your term"):
        # the answer holds scale × (the piece with sin and cos exchanged), of either sign: quoted as typed
        swaps = [sp.expand(c * swap_sin_cos(mistake.piece)) for c in scales]
        mine = next((t for s in swaps for t in (s, -s) if t in terms), None)
        name = (
            f"sin and cos swapped in your term {spoken(mine)}"
            if mine is not None
            else "sin and cos swapped in one of your terms"
        )
        return dataclasses.replace(mistake, name=name), _renamed(hint, mistake.name, name)
    if mistake.family not in _SIGN_FAMILIES:
        return mistake, hint
    # the answer is scale × (truth − 2 p): the student's term is −scale·p
    mine = next((t for c in scales for t in (sp.expand(-c * mistake.piece),) if t in terms or -t in terms), None)
    if mine is not None:
        unsigned = -mine if mine.could_extract_minus_sign() else mine
        name = f"the sign of your {spoken(unsigned)} term"
    else:
        name = "the sign of one of your terms"
    return dataclasses.replace(mistake, name=name), _renamed(hint, mistake.name, name)


def _factor(answer: sp.Expr, wrong: sp.Expr | None, terms: set[sp.Expr]) -> tuple[sp.Expr, ...]:
    """The constant c with answer = c × wrong, found from one term of each (at most one check for each of the
    answer's first MAX_TERMS terms: bounded by work, never by time), or nothing."""
    if wrong is None:
        return ()
    theirs = sp.Add.make_args(sp.expand(wrong))
    for t in sorted(terms, key=sp.default_sort_key)[:MAX_TERMS]:
        c = sp.cancel(t / theirs[0])
        if c.is_number and c != 0 and sp.expand(answer - c * wrong) == 0:
            return (c,)
    return ()


def _inner_as_typed(
    mistake: Mistake, hint: str, answer: sp.Expr, scale: sp.Expr, coordinates: tuple[sp.Symbol, ...]
) -> tuple[Mistake, str]:
    """A sum with one sign changed (a stretch x₁ − x₂ − l₀), quoted as the answer holds it: the answer's sum
    whose square is that of the catalogue's changed sum (a stretch's sign as a whole does not matter); where
    the answer holds no such sum (it multiplied it out), the answer's own term whose sign is wrong."""
    right = mistake.piece
    if right is None:
        return mistake, hint
    content = right.primitive()[0] if isinstance(right, sp.Add) else sp.Integer(1)
    for typed in (a for a in sp.preorder_traversal(answer) if isinstance(a, sp.Add)):
        for term in right.args:
            changed = right - 2 * term
            if any(sp.expand(typed**2 - c**2) == 0 for c in (changed, changed / content)):
                written = sum_words(changed / content, coordinates)
                if not mistake.name.startswith(f"{written}: "):
                    return mistake, hint
                rest = mistake.name[len(written) :]
                name = sum_words(typed, coordinates) + rest
                return dataclasses.replace(mistake, name=name), _renamed(hint, mistake.name, name)
    return _inner_term_as_typed(mistake, hint, answer, scale, coordinates)


def _inner_term_as_typed(
    mistake: Mistake, hint: str, answer: sp.Expr, scale: sp.Expr, coordinates: tuple[sp.Symbol, ...]
) -> tuple[Mistake, str]:
    """The sum's term of the wrong sign as the answer holds it multiplied out: (k + κ) x₁ + κ x₂ for
    k x₁ + κ (x₁ − x₂) is "your term +κ x₂, which should be −κ x₂"."""
    right, wrong = mistake.piece, mistake.expr
    if right is None or wrong is None or " (" not in mistake.name:
        return mistake, hint
    terms = {sp.expand(t) for t in sp.Add.make_args(sp.expand(answer))}
    for term in right.args:
        changed = right - 2 * term
        # only a sum the answer holds to the first power (a force κ (x₁ − x₂)): a square's sign changes more than
        # one term once multiplied out, and is quoted as a sum or not at all
        marker = sp.Dummy()
        held = wrong.xreplace({changed: marker})
        if not held.has(marker) or sp.diff(held, marker, 2) != 0 or sp.diff(held, marker).has(marker):
            continue
        # the truth is the mistake with the sum put right; they differ by twice the term's part, with its sign
        truth = wrong.xreplace({changed: right})
        part = sp.expand(truth - wrong) / 2
        mine = sp.expand(-scale * part)
        if len(sp.Add.make_args(part)) != 1 or mine not in terms:
            continue
        why = mistake.name[mistake.name.index(" (") :]
        yours, should = _signed(mine, coordinates), _signed(-mine, coordinates)
        name = f"your term {yours}, which should be {should}{why}"
        return dataclasses.replace(mistake, name=name), hint.replace(
            mistake.name, f"the term {yours}, which should be {should}{why}"
        )
    return mistake, hint


def _signed(term: sp.Expr, coordinates: tuple[sp.Symbol, ...]) -> str:
    """A term with its sign written out, as it stands in a sum: +κ x₂, −κ x₂."""
    return f"−{spoken(-term, coordinates)}" if term.could_extract_minus_sign() else f"+{spoken(term, coordinates)}"


def _renamed(hint: str, old: str, new: str) -> str:
    """The hint with the mistake's old name replaced, as the hint says it ("your" said once there: the term)."""
    said = re.compile(r"\byour\b")
    return hint.replace(old, new).replace(said.sub("the", old), said.sub("the", new))
