"""What the ω² step's answer says beside its formula: whether the equilibrium asked about is stable, and the
system's other equilibria, each with where it exists and whether it is stable.

Sentences of plain Unicode (they wrap on a phone, as a formula does not): "θ = 0 is stable while g > Rw²; where
ω² is negative it is unstable…", "The other equilibria: θ = ±arccos(g/(Rw²)), which exist only when Rw² > g, with
ω² = w² − g²/(R²w²) (positive there: stable)".
"""

from __future__ import annotations

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.display.textbook import unicode_text
from app.engine.document.notation import text
from app.engine.equations.reduction import Equilibrium
from app.engine.tutor.check_problem import asked_equilibrium, equilibrium_text, where_asked


def _condition(relation: sp.Relational) -> str:
    """b > a as running text prints it: "Rw² > g"."""
    return f"{unicode_text(relation.lhs)} > {unicode_text(relation.rhs)}"


def _asked(at: str, e: Equilibrium, w2: str) -> str:
    """``w2``: the frequency's square in the document's letter (Ω² where ω is a parameter)."""
    if e.stable is True:
        return f"{at} is stable: {w2} is positive for every value of the parameters."
    if e.stable_when is not None:
        return (f"{at} is stable while {_condition(e.stable_when)}; where {w2} is negative it is unstable (a small "
                "displacement grows), and there are no small oscillations about it.")
    return f"Where {w2} is negative, {at} is unstable (a small displacement grows): no small oscillations about it."


def _exists(e: Equilibrium, plural: bool) -> str:
    """Where an equilibrium exists, when that depends on the parameters."""
    which = "which exist" if plural else "which exists"
    if e.exists is not None:
        return f", {which} only when {_condition(e.exists)},"
    inverse = list(e.position.atoms(sp.acos, sp.asin))
    if len(inverse) == 1:
        # arccos x and arcsin x are defined for −1 ≤ x ≤ 1 only
        return f", {which} only where −1 ≤ {unicode_text(inverse[0].args[0])} ≤ 1,"
    return ""


def _stability(e: Equilibrium) -> str:
    if e.stable is True:
        return " (positive there: stable)" if e.exists is not None else " (positive: stable)"
    if e.stable is False:
        return " (never positive: unstable, no small oscillations)"
    if e.stable_when is not None:
        return f" (stable while {_condition(e.stable_when)})"
    return ""


def _groups(others: list[Equilibrium]) -> list[tuple[list[sp.Expr], Equilibrium]]:
    """The equilibria with the same ω² at ±x taken together (θ = ±arccos(g/(Rw²)))."""
    out: list[tuple[list[sp.Expr], Equilibrium]] = []
    for e in others:
        twin = next((g for g in out if len(g[0]) == 1 and sp.simplify(g[0][0] + e.position) == 0
                     and g[1].omega_squared == e.omega_squared), None)
        if twin is not None:
            twin[0].append(e.position)
        else:
            out.append(([e.position], e))
    return out


def _other(d: Derivation, positions: list[sp.Expr], e: Equilibrium, w2: str) -> str:
    if len(positions) == 2:
        # the positive one after ±
        p = positions[0] if not positions[0].could_extract_minus_sign() else positions[1]
        at = equilibrium_text(d, p).replace(" = ", " = ±", 1)
    else:
        at = equilibrium_text(d, positions[0])
    return f"{at}{_exists(e, len(positions) == 2) or ','} with {w2} = {unicode_text(e.omega_squared)}{_stability(e)}"


def equilibria_notes(d: Derivation) -> list[str]:
    """The sentences under the ω² step's answer: the asked equilibrium's stability, then the other equilibria."""
    red = d.reduction
    if red is None or not red.equilibria:
        return []
    asked = asked_equilibrium(d)
    w2 = f"{text('frequency', d)}²"
    notes = [_asked(where_asked(d), asked, w2)]
    others = _groups([e for e in red.equilibria if e is not asked])
    if others:
        listed = "; ".join(_other(d, positions, e, w2) for positions, e in others)
        notes.append(f"{'The other equilibria' if len(others) > 1 or len(others[0][0]) > 1 else 'The other equilibrium'}: "
                     f"{listed}.")
    return notes
