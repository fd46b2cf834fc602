"""Conserved quantities from continuous symmetries of L beyond cyclic coordinates (Noether's theorem).

Move the coordinates by δq = ε ξ(q).  If L changes only by a total time derivative,

    X L = Σ_k (ξ_k ∂L/∂q_k + ξ̇_k ∂L/∂q̇_k) = dF/dt   with F = F(q),

then along the motion (d/dt p_k = ∂L/∂q_k + Q_k)

    d/dt (Σ_k p_k ξ_k − F) = X L − dF/dt + Σ_k Q_k ξ_k = Σ_k Q_k ξ_k,

so C = Σ p ξ − F is conserved when the generalized forces do no work along ξ.  The symmetries tried:

* a translation of one coordinate that is not cyclic (ξ = e_k), where ∂L/∂q_k is a total derivative
  dF/dt: a charge in a uniform magnetic field, L = ½m(ẋ² + ẏ²) + ½qB(xẏ − yẋ), has ∂L/∂x = ½qBẏ, so
  p_x − ½qBy = mẋ − qBy is conserved (and mẏ + qBx): the guiding centre;
* a rotation in the plane of two coordinates that are not angles (ξ_i = −q_j, ξ_j = q_i): the same
  charge has X L = 0, so x p_y − y p_x = m(xẏ − yẋ) + ½qB(x² + y²) is conserved.

F is found by integrating X L's coefficients of the velocities when they are polynomials in the
coordinates (nothing else is integrated, so nothing can hang), and X L = dF/dt is then checked.  Before a
quantity is kept it is checked once more on its own: its time derivative along the equations of motion
(q̈ from the accelerations, or the residuals where those stay M⁻¹f) is identically zero.  So nothing
false is printed; a symmetry the search does not know is simply not listed.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations

import sympy as sp

from app.engine.algebra.simplify import is_zero
from app.engine.display.names import unicode
from app.engine.display.textbook import unicode_text
from app.engine.equations.lagrange import Equations
from app.engine.equations.mechanics import Mechanics

# the most coordinates whose translations and rotations are tried (n + n(n − 1)/2 candidates)
NOETHER_MAX_COORDINATES = 4
# axes named by the plane they turn: a rotation of (x, y) is about z
_AXES = {frozenset("xy"): "z", frozenset("yz"): "x", frozenset("xz"): "y"}


@dataclass(frozen=True)
class Symmetry:
    """A conserved C = Σ p ξ − F from a symmetry of L, with its name and the sentence that says why."""

    name: str
    latex_name: str
    expr: sp.Expr
    reason: str
    kind: str  # "rotation" or "translation"


def _angles(mech: Mechanics) -> set[sp.Symbol]:
    """Coordinates that are angles: inside a sine, cosine or tangent of L or of a position."""
    exprs = [mech.L, *(c for r in mech.positions for c in r)]
    inside = {a for e in exprs for f in sp.sympify(e).atoms(sp.sin, sp.cos, sp.tan) for a in f.args}
    return {q for q in mech.table.q if any(a.has(q) for a in inside)}


def _potential_of(change: sp.Expr, mech: Mechanics) -> sp.Expr | None:
    """F(q) with dF/dt = change, or None when change is not such a total derivative of a polynomial in q."""
    table = mech.table
    coefficients = [sp.expand(sp.diff(change, v)) for v in table.qd]
    # X L must be linear in the velocities with coefficients free of velocities and time
    rest = sp.expand(change - sum(c * v for c, v in zip(coefficients, table.qd, strict=True)))
    if rest != 0 or any(c.has(*table.qd, table.t) for c in coefficients):
        return None
    if not all(c.is_polynomial(*table.q) for c in coefficients):
        return None
    # integrate ∂F/∂q_k = c_k one coordinate at a time, each time subtracting what F already gives
    F = sp.Integer(0)
    for q, c in zip(table.q, coefficients, strict=True):
        F += sp.integrate(sp.expand(c - sp.diff(F, q)), q)
    return F if is_zero(table.dt(F) - change) else None


def _conserved_along_motion(C: sp.Expr, xi: list[sp.Expr], mech: Mechanics, eqs: Equations) -> bool:
    """dC/dt = 0 along the equations of motion, checked independently of how C was found."""
    table = mech.table
    rate = table.dt(C)
    if eqs.closed_form:
        # q̈ from the solved equations of motion
        return is_zero(rate.xreplace(dict(zip(table.qdd, eqs.accelerations, strict=True))))
    # dC/dt − Σ ξ_k E_k with E_k the residuals (zero on the motion): identically zero
    return is_zero(rate - sp.Add(*(x * r for x, r in zip(xi, eqs.residuals, strict=True))))


def _candidates(mech: Mechanics, cyclic: tuple[str, ...]) -> list[tuple[str, tuple[sp.Symbol, ...], list[sp.Expr]]]:
    """(kind, the coordinates it moves, ξ) for each symmetry tried."""
    table = mech.table
    n = len(table.q)
    found: list[tuple[str, tuple[sp.Symbol, ...], list[sp.Expr]]] = []
    for k, q in enumerate(table.q):
        # a cyclic coordinate's translation gives its momentum, listed already
        if table.names[k] not in cyclic:
            found.append(("translation", (q,), [sp.Integer(1 if j == k else 0) for j in range(n)]))
    angles = _angles(mech)
    for i, j in combinations(range(n), 2):
        if table.q[i] in angles or table.q[j] in angles:
            continue
        # turning (q_i, q_j) by ε: δq_i = −ε q_j, δq_j = ε q_i
        xi = [sp.Integer(0)] * n
        xi[i], xi[j] = -table.q[j], table.q[i]
        found.append(("rotation", (table.q[i], table.q[j]), xi))
    return found


def _rotation_name(pair: tuple[sp.Symbol, ...], several: bool, latex_names: dict[sp.Symbol, str]) -> tuple[str, str]:
    axis = _AXES.get(frozenset(s.name for s in pair))
    if axis is not None:
        return f"J_{axis}", f"J_{{{axis}}}"
    if not several:
        return "J", "J"
    return f"J_{pair[0].name}{pair[1].name}", f"J_{{{latex_names[pair[0]]} {latex_names[pair[1]]}}}"


def _minus(left: str, right: str) -> str:
    """left − right in words, a leading minus of right folded in: p_y + qBx/2, not p_y − (−qBx/2)."""
    return f"{left} + {right[1:]}" if right.startswith("−") else f"{left} − {right}"


def symmetries(mech: Mechanics, eqs: Equations, cyclic: tuple[str, ...]) -> list[Symmetry]:
    """The conserved quantities of L's translations and rotations beyond its cyclic coordinates, each checked."""
    table = mech.table
    if len(table.q) > NOETHER_MAX_COORDINATES or mech.L.has(sp.Derivative):
        return []
    latex_names = table.latex_names()
    candidates = []
    for kind, moved, xi in _candidates(mech, cyclic):
        # the generalized forces must do no work along the symmetry
        if not is_zero(sp.Add(*(f * x for f, x in zip(mech.Q, xi, strict=True)))):
            continue
        # X L = Σ ξ ∂L/∂q + ξ̇ ∂L/∂q̇
        change = sp.Add(*(x * g + table.dt(x) * p for x, g, p in zip(xi, eqs.dL_dq, eqs.momenta, strict=True)))
        F = sp.Integer(0) if is_zero(change) else _potential_of(change, mech)
        if F is None:
            continue
        # C = Σ p ξ − F
        C = sp.expand(sp.Add(*(p * x for p, x in zip(eqs.momenta, xi, strict=True))) - F)
        if C.free_symbols.isdisjoint(table.qd) or not _conserved_along_motion(C, xi, mech, eqs):
            continue
        candidates.append((kind, moved, C, F))
    rotations = sum(1 for c in candidates if c[0] == "rotation")
    found = []
    for kind, moved, C, F in candidates:
        if kind == "rotation":
            name, tex = _rotation_name(moved, rotations > 1, latex_names)
            a, b = (unicode(s.name) for s in moved)
            why = (
                f"L is unchanged when {a} and {b} are turned together in their plane (δ{a} = −ε{b}, δ{b} = ε{a})"
                if F == 0
                else f"Turning {a} and {b} together in their plane (δ{a} = −ε{b}, δ{b} = ε{a}) changes L only by "
                f"ε d/dt({unicode_text(F)})"
            )
            # Σ p ξ − F = q_i p_j − q_j p_i − F
            pa, pb = (unicode(f"p_{s.name}") for s in moved)
            what = f"{a}{pb} − {b}{pa}" if F == 0 else _minus(f"{a}{pb} − {b}{pa}", unicode_text(F))
        else:
            (q,) = moved
            name, tex = f"P_{q.name}", f"P_{{{latex_names[q]}}}"
            a = unicode(q.name)
            why = (
                f"∂L/∂{a} = {unicode_text(table.dt(F))} = d/dt({unicode_text(F)}): moving {a} by ε changes L only by "
                "a total time derivative"
            )
            what = _minus(unicode(f"p_{q.name}"), unicode_text(F))
        found.append(
            Symmetry(
                name,
                tex,
                C,
                f"{why}, and no generalized force acts along that motion, so by Noether's theorem {what} is "
                "conserved (its time derivative along the equations of motion is zero).",
                kind,
            )
        )
    return found
