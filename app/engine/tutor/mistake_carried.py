"""Slips of T and U carried on: an L built from a T and a U that each hold a slip, and the equation of motion
derived correctly from such an L.

A student who swapped sin and cos in T (or in U), or wrote one term of U with the wrong sign, and then goes on
with their own T and U, writes an L with the same slips and derives from it the right equations for that L.
The equation is then no slip of differentiating: it is the right equation for a wrong L, and is named so ("your
equation follows from an L with sin and cos swapped in the term … of T"), pointing back at the step where the slip
is.

The slips taken are those the T and U steps name themselves (``piece_mistakes``: sin and cos swapped in one
term, a term's sign) and sin and cos swapped throughout L; one slip of T, one of U, or one of each. The work is
bounded by counts (MAX_SLIPS of each step, so at most MAX_SLIPS² + 2 MAX_SLIPS + 1 changes of L), never by time,
and the changes of L are computed once per derivation.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.equations.lagrange import euler_lagrange_of
from app.engine.tutor.mistake_families import Mistake
from app.engine.tutor.mistake_pieces import piece_mistakes, swap_sin_cos

MAX_SLIPS = 4  # slips of T, and of U, carried on (each alone, and each of T with each of U)
_KINDS = ("sin_cos",)  # families of a step's own slips that are carried, besides a term's sign
_CACHE_KEY = ("mistake_carried", "lagrangian_changes")

_LETTER = {"kinetic": "T", "potential": "U"}
_CARRIED_WHY = "it is the right equation for that L, so the slip is in an earlier step; fix it there and derive again"
_PAIR_WHY = "L = T − U carries the slips of T and U into L: fix them in T and U, and L follows"


def _said(name: str) -> str:
    """A step's own mistake name as said of a term of that step: "your term" is "the term"."""
    return re.sub(r"\byour\b", "the", name)


def _slips(d: Derivation, step: str, truth: sp.Expr) -> list[tuple[str, str, sp.Expr]]:
    """(key, words, change of the step's expression) for the step's own sign and sin/cos slips, the first
    MAX_SLIPS of them, each change distinct."""
    out: list[tuple[str, str, sp.Expr]] = []
    seen: set[sp.Expr] = set()
    found = [m for m in piece_mistakes(d, step, None, truth) if m.family in _KINDS or ".piece.sign." in m.key]
    # a swap before a sign: of two slips that explain the same answer, the more common one is named
    for m in sorted(found, key=lambda m: m.family not in _KINDS):
        change = sp.expand(m.expr - truth)
        if change == 0 or change in seen:
            continue
        seen.add(change)
        out.append((m.key.removeprefix(f"{step}."), f"{_said(m.name)} of {_LETTER[step]}", change))
        if len(out) == MAX_SLIPS:
            break
    return out


def lagrangian_changes(d: Derivation) -> tuple[tuple[str, str, sp.Expr, int], ...]:
    """(key, words, ΔL, how many slips) for each L a student builds from a T and a U with their slips: one
    slip of T, one of U, both, and sin and cos swapped throughout; once per derivation."""
    cached = d._members.get(_CACHE_KEY)
    if cached is not None:
        return cached
    T, U = d.mechanics.T, d.mechanics.U
    out: list[tuple[str, str, sp.Expr, int]] = []
    if T is not None and U is not None and (T.has(sp.sin, sp.cos) or U.has(sp.sin, sp.cos)):
        kinetic, potential = _slips(d, "kinetic", T), _slips(d, "potential", U)
        # L = T − U: a change of T is a change of L, a change of U one of the opposite sign
        out += [(f"kinetic.{key}", words, dT, 1) for key, words, dT in kinetic]
        out += [(f"potential.{key}", words, -dU, 1) for key, words, dU in potential]
        L = T - U
        # the positions written with sine and cosine exchanged: every sine and cosine of L swapped
        throughout = sp.expand(swap_sin_cos(L) - L)
        if throughout != 0:
            out.append(("throughout", "sin and cos swapped throughout (the positions written with the sine and the "
                        "cosine exchanged)", throughout, 1))  # fmt: skip
        # two slips last: where one slip explains the same answer, the one slip is named
        out += [
            (f"kinetic.{kt}+potential.{ku}", f"{wt}, and {wu}", dT - dU, 2)
            for kt, wt, dT in kinetic
            for ku, wu, dU in potential
        ]
    result = tuple(out)
    d._members[_CACHE_KEY] = result
    return result


def lagrangian_pairs(d: Derivation, truth: sp.Expr) -> Iterator[Mistake]:
    """The L step: a slip of T together with a slip of U, both carried into L (one slip alone is the L step's
    own piece mistake)."""
    for key, words, dL, count in lagrangian_changes(d):
        if count == 2:
            yield Mistake(f"lagrangian.carried.{key}", "pair", words, None, _PAIR_WHY, truth + dL, count=2)


def carried_equations(d: Derivation, k: int, truth: sp.Expr) -> Iterator[Mistake]:
    """The equation of coordinate k derived correctly from an L with the slips of T and U: the right equation
    for that L (one mistake, in the earlier step, however many slips that L holds)."""
    for key, words, dL, _ in lagrangian_changes(d):
        change = euler_lagrange_of(d.table, k, dL)
        if change == 0:
            continue
        yield Mistake(f"equation.carried.{key}", "travelled", f"an L with {words}", None, _CARRIED_WHY,
                      truth + change)  # fmt: skip
