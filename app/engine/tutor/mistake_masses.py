"""The wrong mass in one term: another body's mass, or the total mass, where one body's belongs.

A term of T, U, L, a momentum or an equation carries the mass of the body it comes from (the
wedge's U is −m g D sin α: only the block changes height; the cart's cross term m l Ẋ θ̇ cos θ is
the bob's).  Each mass parameter in a term is replaced by each other mass, and by the sum of all
masses, one term at a time; the answer that gives is named "the wrong mass in your … term".

Bounded by counts: the terms of the truth (at most ``MAX_TERMS``), the masses (at most
``MAX_MASSES``), never by time.
"""

from __future__ import annotations

from collections.abc import Iterator

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.display.names import unicode
from app.engine.display.spoken import spoken
from app.engine.tutor.mistake_families import Mistake, short_form, slug

MAX_TERMS = 12
MAX_MASSES = 4
STEPS = ("kinetic", "potential", "lagrangian", "momentum", "equation", "hamiltonian")


def _owner(d: Derivation, mass: sp.Symbol) -> str:
    """The body a mass belongs to, by its label ("the block"), or "" where no particle has it."""
    for p in d.system.particles:
        if p.mass == mass.name:
            return f"the {p.label}" if p.label else ""
    return ""


def _divided_by_another(d: Derivation, truth: sp.Expr, masses: list[sp.Symbol]) -> Iterator[Mistake]:
    """An acceleration is a force over the mass of the body it moves: that mass, written as another one."""
    whole = sp.factor_terms(truth)
    for s in [m for m in masses if whole.as_powers_dict().get(m, 0) == -1]:
        owner = _owner(d, s) or "this body"
        for r in (m for m in masses if m != s):
            yield Mistake(
                f"acceleration.wrong_mass.{s.name}.{r.name}",
                "wrong_mass",
                f"the wrong mass: {unicode(r.name)} where {unicode(s.name)} belongs",
                s,
                f"this is the acceleration of {owner}, so the force on it is divided by its own mass, {unicode(s.name)}",
                whole.xreplace({s: r}),
            )


def wrong_masses(d: Derivation, step: str, truth: sp.Expr, masses: list[sp.Symbol]) -> Iterator[Mistake]:
    """For each term of the truth and each mass in it: that mass replaced by another one, or by the total."""
    if step == "acceleration" and len(masses) >= 2:
        yield from _divided_by_another(d, truth, masses[:MAX_MASSES])
        return
    if step not in STEPS or len(masses) < 2:
        return
    masses = masses[:MAX_MASSES]
    terms = sp.Add.make_args(sp.expand(truth))
    if len(terms) > MAX_TERMS:
        return
    total = sp.Add(*masses)
    for term in terms:
        for s in [m for m in masses if term.as_powers_dict().get(m, 0) == 1]:
            for r in [*(m for m in masses if m != s), total]:
                wrong_term = sp.expand(term.xreplace({s: r}))
                wrong = sp.expand(truth - term + wrong_term)
                # a replaced term that merges with another term is no longer the student's one term to quote
                if len(sp.Add.make_args(wrong)) != len(terms) - 1 + len(sp.Add.make_args(wrong_term)):
                    continue
                # an equation may be typed scaled or rearranged: its term is not quoted, the masses are
                quoted = (
                    f"one of your terms ({spoken(r)} where {unicode(s.name)} belongs)"
                    if step == "equation"
                    else f"your term {spoken(short_form(term.xreplace({s: r})))}"
                )
                owner = _owner(d, s) or "one body"
                # the reason opens with words, never with a symbol: a page capitalises its first letter (m₁ is no M₁)
                if r == total:
                    why = f"this term belongs to {owner} alone (mass {unicode(s.name)}), and {spoken(total)} is the total mass"
                else:
                    why = (
                        f"this term comes from {owner} (mass {unicode(s.name)}), and {unicode(r.name)} belongs to "
                        f"{_owner(d, r) or 'another body'}"
                    )
                yield Mistake(
                    f"{step}.wrong_mass.{slug(sp.sstr(term))[:40]}.{s.name}.{slug(sp.sstr(r))}",
                    "wrong_mass",
                    f"the wrong mass in {quoted}",
                    term,
                    why,
                    wrong,
                )
