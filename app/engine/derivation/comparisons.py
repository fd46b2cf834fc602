"""The accelerations beside those a problem compares them with, read from the system: a declared rigid body that
rolls beside a body that slides without turning (the cylinder beside a block on the same wedge), and every
acceleration with a body that carries another held fixed (its mass → ∞: the fixed wedge's 2g sin α/3)."""

from __future__ import annotations

import sympy as sp

from app.engine.derivation.derive import Derivation
from app.engine.equations.lagrange import euler_lagrange_of

MAX_BODIES = 4  # bodies whose held-still limit is tried, per step (app/engine/tutor/mistake_other.py too)


def sliding(d: Derivation) -> list[sp.Expr] | None:
    """The accelerations with the turning energy ½ I_cm θ̇² of every declared body carried by another taken out of
    L, each body then sliding as a point at its centre; None where no carried body turns (a pendulum's rod turns
    about its pivot: taken as a point it is another problem, not a comparison the statement asks for)."""
    carried = set().union(*(c.free_symbols for r in d.mechanics.positions for c in r)) & set(d.table.q)
    turning = [
        b.rotation
        for b in d.mechanics.bodies
        if b.rotation != 0 and b.translation != 0 and set().union(*(c.free_symbols for c in b.centre)) & carried
    ]
    if not turning or not d.equations.closed_form:
        return None
    t = d.table
    # ΔL = −Σ ½ I_cm θ̇²: each equation changes by d/dt ∂ΔL/∂q̇ − ∂ΔL/∂q, and ℳ q̈ = f is solved anew
    dL = -sp.Add(*turning)
    wrong = [sp.expand(r + euler_lagrange_of(d.table, j, dL)) for j, r in enumerate(d.equations.residuals)]
    M = sp.Matrix([[sp.diff(r, a) for a in t.qdd] for r in wrong])
    if M.det() == 0:
        return None
    zero = dict.fromkeys(t.qdd, sp.Integer(0))
    # cos² written 1 − sin², as the page's own accelerations are (M + m sin² α, never M + m − m cos² α)
    squared = (lambda e: e.is_Pow and isinstance(e.base, sp.cos) and e.exp == 2, lambda e: 1 - sp.sin(e.base.args[0]) ** 2)
    return [sp.factor(sp.cancel(x.replace(*squared))) for x in M.LUsolve(sp.Matrix([-r.xreplace(zero) for r in wrong]))]


def held(d: Derivation) -> list[tuple[sp.Symbol, list[sp.Expr | None]]]:
    """(M, the accelerations as M → ∞) for each body that carries another and is held fixed as its mass M → ∞
    (its own acceleration then vanishes); a limit that is not finite is None."""
    out = []
    for M in held_fixed(d):
        out.append((M, [limit(a, M) for a in d.equations.accelerations]))
    return out


def stops_when_heavy(d: Derivation, i: int, M: sp.Symbol) -> bool:
    """Whether body i's position moves with one coordinate alone, whose acceleration vanishes as M → ∞."""
    moves = {s for c in d.mechanics.positions[i] for s in c.free_symbols if s in d.table.q}
    if len(moves) != 1:
        return False
    j = d.table.q.index(next(iter(moves)))
    return mass_limit(d.equations.accelerations[j], M, sp.oo, allow_zero=True) == 0


def mass_limit(expr: sp.Expr, M: sp.Symbol, to: sp.Expr, allow_zero: bool = False) -> sp.Expr | None:
    """lim_{M→to} of a rational function of M (to is 0 or ∞), or None where it is not finite, is zero (unless
    allowed) or still holds M."""
    num, den = sp.fraction(sp.cancel(sp.together(expr)))
    try:
        top, bottom = sp.Poly(num, M), sp.Poly(den, M)
    except sp.PolynomialError:
        return None
    if to == 0:
        # lim_{M→0} (a_0 + a_1 M + …)/(b_0 + b_1 M + …) = a_0 / b_0, finite where b_0 ≠ 0
        a0, b0 = top.eval(0), bottom.eval(0)
        limit = None if b0 == 0 else sp.factor(a0 / b0)
    elif top.degree() > bottom.degree():
        limit = None
    elif top.degree() < bottom.degree():
        limit = sp.Integer(0)
    else:
        # lim_{M→∞} (a_n Mⁿ + …)/(b_n Mⁿ + …) = a_n / b_n
        limit = sp.factor(top.LC() / bottom.LC())
    if limit is None or (limit == 0 and not allow_zero) or limit.has(M):
        return None
    return limit


def held_fixed(d: Derivation) -> list[sp.Symbol]:
    """The mass of each body that carries another and is held fixed as its mass → ∞ (its one coordinate's
    acceleration then vanishes), where the figure has another body: the wedge's M under the block or the cylinder."""
    namespace = d.table.namespace()
    bodies = [(i, namespace[p.mass]) for i, p in enumerate(d.system.particles) if p.mass in namespace][:MAX_BODIES]
    if len(bodies) + len(d.mechanics.bodies) < 2 or not d.equations.closed_form:
        return []
    return [M for i, M in bodies if stops_when_heavy(d, i, M)]


def limit(expr: sp.Expr, M: sp.Symbol) -> sp.Expr | None:
    """lim_{M→∞} of a rational function of M, zero included; None where it is not finite."""
    return mass_limit(expr, M, sp.oo, allow_zero=True)
